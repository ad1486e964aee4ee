"""Reading a command's inputs: one loop over its table, from text (or SI numbers) to SI values.

Every way in (a command line, a sweep's point, a batch line, a Python call) arrives here as a
mapping of option names to what was given, and leaves as the keyword arguments of the scene's
library function, with the inputs echoed in SI for the report and any notes their reading raised.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import TextIO

from taucli import units
from taucli.errors import InputError, did_you_mean
from taucli.report import Value
from taucli.table import CHOICE, COUNT, FILE, FLAG, PART, TEXT, Command, Option


@dataclass
class Inputs:
    """What was read: each value as given, in SI, and any notes on reading it."""

    values: dict[str, Value] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)

    def quantity(self, name: str, given, kind: str, *, sign: str = "positive", key: str | None = None) -> float | None:
        """The SI value of ``given`` (text with a unit, or an SI number) read as ``kind``."""
        if given is None:
            return None
        text = _text(given, name)
        parsed = units.parse(text, name if name.startswith("{") else "{" + name + "}", kind, sign=sign)
        self.values[key or name] = Value(parsed.value, units.KINDS[kind].si_unit, "")
        if parsed.note:
            self.notes.append(parsed.note)
        return parsed.value


def _text(given, name: str) -> str:
    """An SI number as the text a bare number is (a bare number means the SI unit)."""
    if isinstance(given, str):
        return given
    if isinstance(given, (int, float)) and not isinstance(given, bool):
        if isinstance(given, float) and not math.isfinite(given):
            raise InputError(name, "expected a finite number", got=repr(given))
        return repr(float(given)) if isinstance(given, float) else str(given)
    raise InputError(name, "expected a number or a text with a unit", example='"4kg"', got=repr(given))


def read(command: Command, given: Mapping[str, object], *, stdin: TextIO | None = None) -> tuple[dict[str, object], Inputs]:
    """The keyword arguments of ``command``'s library function from the options ``given``.

    ``given`` holds option names (``pulley_mass``; ``pulley-mass`` reads too) and what was given
    for each (None: not given). Names that are not the command's options are refused.
    """
    inputs = Inputs()
    arguments: dict[str, object] = {}
    if not command.input_names.issuperset(given):
        name = next(name for name in given if name not in command.input_names)
        raise InputError(name, f"is not an option of {command.name}", hint=did_you_mean(name, sorted(command.input_names)))
    for option in command.options:
        value = given.get(option.name)
        if value is None or value == () or value == [] or value is False:
            continue
        arguments[option.name] = READERS[option.kind](option, value, inputs, stdin)
    return arguments, inputs


def _quantity(option: Option, given, inputs: Inputs, stdin) -> float | None:
    return inputs.quantity(option.name, given, option.kind, sign=option.sign)


def _choice(option: Option, given, inputs: Inputs, stdin):
    if option.repeatable:
        return tuple(_word(option, item) for item in (given if isinstance(given, (list, tuple)) else [given]))
    return _word(option, given)


def _word(option: Option, given) -> str:
    if not isinstance(given, str):
        raise InputError(option.name, f"expected one of {', '.join(option.choices)}", got=repr(given))
    return given.strip()


def _flag(option: Option, given, inputs: Inputs, stdin) -> bool:
    if not isinstance(given, bool):
        raise InputError(option.name, "expected true or false", got=repr(given))
    return given


def _parts(option: Option, given, inputs: Inputs, stdin) -> tuple:
    specs = given if isinstance(given, (list, tuple)) else [given]
    return tuple(parse_part_spec(_word(option, spec), number, inputs) for number, spec in enumerate(specs, start=2))


def _file(option: Option, given, inputs: Inputs, stdin):
    """A torque profile from its CSV file (or stdin for -), streamed: its samples as they are read."""
    from taucli.profile import read_profile

    source = _word(option, given)
    if source == "-":
        if stdin is None:
            raise InputError(option.name, "cannot be - here: no stdin to read it from", example='"torque_profile": "pulse.csv"')
        profile = read_profile(stdin)
    else:
        try:
            handle = open(source, encoding="utf-8")  # noqa: SIM115 (closed when its samples are read, or by the collector)
            profile = read_profile(handle)
        except OSError as err:
            raise InputError(option.name, "expected a readable CSV file (or - for stdin)", got=f"{source!r}: {err.strerror}") from None
        except UnicodeDecodeError:
            raise InputError(option.name, "expected a UTF-8 text file", got=repr(source)) from None
        profile.samples = _decoded(profile.samples, source, option.name)
    inputs.notes.extend(profile.notes)
    return profile.samples


def _decoded(samples, source: str, name: str):
    try:
        yield from samples
    except UnicodeDecodeError:
        raise InputError(name, "expected a UTF-8 text file", got=repr(source)) from None


def _count(option: Option, given, inputs: Inputs, stdin) -> int:
    try:
        return int(given)
    except (TypeError, ValueError):
        raise InputError(option.name, "expected a whole number", example=f"{{{option.name}}} 50", got=repr(given)) from None


def _as_given(option: Option, given, inputs: Inputs, stdin):
    return given


READERS = {FLAG: _flag, CHOICE: _choice, PART: _parts, FILE: _file, COUNT: _count, TEXT: _as_given}
READERS.update({kind: _quantity for kind in units.KINDS})


_PART_KEY = re.compile(r"\s+(?=[a-z][a-z_-]*=)")
PART_DIMENSIONS = ("radius", "inner_radius", "outer_radius", "length", "width", "height", "depth")


def parse_part_spec(spec: str, number: int, inputs: Inputs):
    """A ``--part`` value such as "point mass=100g offset=20cm" as an inertia Part.

    A part is a shape with mass= (or density=) and its dimensions, or its own I: inertia=
    (with mass= and offset=, I_cm moved by the parallel-axis theorem) or gyration= with mass=;
    those need no shape word. Keys read with - or _ (inner-radius=, inner_radius=).
    """
    from taucli.scenes.inertia import Part

    source = f"{{part}} {number}"
    words = _PART_KEY.split(spec.strip())
    shape, *pairs = words
    if shape and "=" in shape:
        shape, pairs = "", words
    if not words or not words[0]:
        raise InputError(source, "expected a shape then key=value pairs", example='{part} "point mass=100g offset=20cm"', got=repr(spec))
    fields: dict[str, str] = {}
    for pair in pairs:
        key, _, text = pair.partition("=")
        fields[key.replace("-", "_")] = text.strip()
    known = {"mass", "axis", "offset", "inertia", "gyration", "density", *PART_DIMENSIONS}
    for key in fields:
        if key not in known:
            raise InputError(source, f"knows {', '.join(sorted(k.replace('_', '-') for k in known))}", got=repr(key.replace("_", "-")))
    given_inertia = "inertia" in fields or "gyration" in fields
    if not shape and not given_inertia:
        raise InputError(source, "expected a shape then key=value pairs (or inertia= or gyration=)", example='{part} "point mass=100g offset=20cm"', got=repr(spec))
    if shape and given_inertia:
        raise InputError(source, "takes a shape or inertia=/gyration=, not both", got=repr(spec))
    if "mass" not in fields and "density" not in fields and "inertia" not in fields:
        raise InputError(source, "needs mass= (or density=, or inertia=)", example='{part} "point mass=100g offset=20cm"', got=repr(spec))

    def read_field(key: str, kind: str, sign: str = "positive") -> float:
        return inputs.quantity(f"{source} {key.replace('_', '-')}=", fields[key], kind, sign=sign, key=f"part{number}_{key}")

    dims = {key: read_field(key, "length", "nonnegative" if key == "inner_radius" else "positive") for key in PART_DIMENSIONS if key in fields}
    offset = read_field("offset", "length", "nonnegative") if "offset" in fields else None
    mass = read_field("mass", "mass") if "mass" in fields else None
    inertia = read_field("inertia", "moment of inertia") if "inertia" in fields else None
    gyration = read_field("gyration", "length") if "gyration" in fields else None
    density = _read_density(source, fields["density"], inputs, number) if "density" in fields else None
    return Part(shape, mass, dims, fields.get("axis"), offset, source, inertia, gyration, density)


def _read_density(source: str, text: str, inputs: Inputs, number: int) -> float:
    """A density in kg/m³: read as a mass of the text's numerator over a volume (no density kind yet)."""
    from taucli import units

    option = f"{source} density="
    number_unit = text.strip()
    try:
        quantity, _ = units.quantity(number_unit, option, "dimensionless")
        value = float(quantity.to("kg/m**3").magnitude) if not quantity.unitless else float(quantity.magnitude)
    except InputError:
        raise
    except Exception:
        raise InputError(option, "expected a density", example="7800kg/m^3", got=repr(text)) from None
    if not math.isfinite(value) or not 0 < value <= units.LARGEST:
        raise InputError(option, "expected a positive density", example="7800kg/m^3", got=repr(text))
    inputs.values[f"part{number}_density"] = Value(value, "kg/m**3", "")
    return value
