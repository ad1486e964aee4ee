"""Reading flywheel's --turning-moment: a turning-moment diagram T(θ), as a formula of the crank
angle or as its samples in a CSV file.

A text that is no file's path and names ``theta`` (or θ), or has a formula's marks (parentheses,
* or ^, a number and a unit), is a formula of it (taucli.quantities.formula, θ in radians):
``'(15000 + 10000*sin(2*theta) - 6000*cos(2*theta)) N*m'``, read into an OfTime of theta. Any
other text is a file's path: a header "theta [deg], torque [N*m]" (the angle's unit written),
then rows of crank angle and torque, the angle increasing, read by the torque profile's rules
(profile.py, csv_text.py), at least MIN_SAMPLES rows. From Python, a sequence of (θ, T) pairs in
SI (radians, N·m) is taken as the samples. The scene gets an OfTime or a tuple of SI pairs.
"""

from __future__ import annotations

import math
import os
import re

from taucli.answering.profile import read_profile
from taucli.answering.reading import Inputs
from taucli.core.errors import InputError
from taucli.quantities import units
from taucli.writing.report import Value

_FORMULA = re.compile(r"[()*^]|\d\s+[A-Za-z]")  # a formula's marks (a path not found that has them is read as a formula, for its message)
MIN_SAMPLES = 3  # two points are a straight line: no swing to speak of
MAX_SAMPLES = 100_000  # a book's table has a few dozen rows; ¼° steps over 720° are 2881: more is a file of something else
EXAMPLE = "{turning_moment} '(15000 + 10000*sin(2*theta) - 6000*cos(2*theta)) N*m'"
FILE_EXAMPLE = "{turning_moment} diagram.csv"
WHAT = ("expected a CSV file of crank angle and torque (a header such as 'theta [deg], torque [N*m]', then rows) "
        "or a formula of theta giving a torque")


def turning_moment(option, given, inputs: Inputs, stdin):
    """The diagram ``given``: a formula of theta, a file's path, or (Python) SI pairs."""
    from taucli.quantities.formula import ANGLE, mentions_angle, read_formula  # deferred: the formula parser

    name = option.name
    if isinstance(given, str):
        if not os.path.isfile(given.strip()) and (mentions_angle(given) or _FORMULA.search(given)):
            formula = read_formula(given, name, units.KINDS["torque"], ANGLE)
            if formula.coefficients is not None and len(formula.coefficients) == 1:
                raise InputError(name, "expected a formula of theta: a constant torque has no fluctuation of energy", example=EXAMPLE, got=repr(given))
            inputs.values[name] = Value(given, None, "")
            return formula
        samples = _from_file(name, given.strip(), inputs)
        inputs.values[name] = Value(given, None, "")
        return samples
    if isinstance(given, (list, tuple)):
        pairs = _pairs(name, given)
        inputs.values[name] = Value(f"{len(pairs)} samples (θ in rad, T in N*m)", None, "")
        return pairs
    raise InputError(name, WHAT, example=EXAMPLE, got=f"{given!r} ({type(given).__name__})")


def _from_file(name: str, path: str, inputs: Inputs) -> tuple[tuple[float, float], ...]:
    if not path:
        raise InputError(name, WHAT, example=FILE_EXAMPLE, got="''")
    try:
        with open(path, encoding="utf-8") as handle:
            profile = read_profile(handle, path, option=name, across="angle", least=MIN_SAMPLES)
            samples = tuple(_at_most(profile.samples, name))
    except OSError as err:
        raise InputError(name, WHAT, example=FILE_EXAMPLE, got=f"{path!r}: {err.strerror}") from None
    except UnicodeDecodeError:
        raise InputError(name, "expected a UTF-8 text file", got=repr(path)) from None
    inputs.notes.extend(profile.notes)
    return samples


def _at_most(samples, name: str):
    for count, sample in enumerate(samples, start=1):
        if count > MAX_SAMPLES:
            raise InputError(name, f"has more than {MAX_SAMPLES} rows: expected a turning-moment diagram's table (a book's has a few dozen)", example=FILE_EXAMPLE)
        yield sample


def _pairs(name: str, given) -> tuple[tuple[float, float], ...]:
    """(θ, T) pairs in SI from Python: numbers, the angle increasing, at least MIN_SAMPLES."""
    example = "turning_moment=[(0, 100), (1.5708, 300), (3.1416, 100)]"
    if len(given) > MAX_SAMPLES:
        raise InputError(name, f"has more than {MAX_SAMPLES} samples: expected a turning-moment diagram's table (a book's has a few dozen)", example=example)
    try:
        pairs = tuple((float(theta), float(torque)) for theta, torque in given)
    except (TypeError, ValueError):
        raise InputError(name, "expected (angle in rad, torque in N*m) pairs", example=example, got=repr(given)[:80]) from None
    if len(pairs) < MIN_SAMPLES:
        raise InputError(name, f"has {len(pairs)} samples: at least {MIN_SAMPLES} are needed for a diagram over a cycle", example=example)
    for number, (theta, torque) in enumerate(pairs, start=1):
        if not (math.isfinite(theta) and math.isfinite(torque)):
            raise InputError(name, f"sample {number}: expected finite numbers", got=repr((theta, torque)))
        if number > 1 and theta <= pairs[number - 2][0]:
            raise InputError(name, f"sample {number}: the angle must increase from sample to sample", got=repr((theta, torque)))
    return pairs
