"""A torque profile from CSV text: "t [ms], torque [N*m]" then rows of numbers, streamed; or a
turning-moment diagram's samples, "theta [deg], torque [N*m]" (flywheel's --turning-moment: the
same rules, the first column an angle, whose unit must be written).

The header names the columns and, in brackets or parentheses, their units (none: SI, with a
note); tabs, semicolons or commas separate the columns, and cells may be quoted: the rules
``taucli fit`` reads its data by (csv_text.py). Rows are
read one at a time and yielded as SI (t, τ), so a file of any length is never held in memory.
Every defect (a missing header, a cell that is not a number, time that does not increase, too
few rows) is an InputError naming the line.
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field

from taucli.answering.csv_text import MAX_BYTES, cells as _cells, delimiter as _delimiter, split_header, too_large
from taucli.quantities import units
from taucli.core.errors import InputError
from taucli.quantities.kinds import BOUNDS, check_bounds, out_of_bounds

OPTION = "--torque-profile"


@dataclass
class Profile:
    """The samples of a torque profile, in SI, and the notes its reading raised."""

    samples: Iterator[tuple[float, float]]
    notes: list[str] = field(default_factory=list)


def _unit_factor(text: str | None, kind: str, column: str, notes: list[str], option: str = OPTION) -> float:
    if text is None or not text.strip():
        if kind == "angle":  # a number alone is no angle (degrees, as books tabulate, or radians?)
            raise InputError(option, "expected the angle column's unit in the header (deg or rad)", example="'theta [deg], torque [N*m]'", got="no unit")
        notes.append(f"{option}: no unit for the {column} column in the header: read as SI ({units.KINDS[kind].si_unit})")
        return 1.0
    if option.startswith("--"):
        parsed = units.parse(f"1 {text}", f"{option} header, {column} column", kind)
    else:  # a name, spelled per surface (--turning-moment, turning_moment): the header named in the message
        try:
            parsed = units.parse(f"1 {text}", option, kind)
        except InputError as err:
            raise InputError(option, f"the header's {column} column: {err.expected}", example=err.example, got=err.got) from None
    if parsed.note:  # "lb*ft": pound-force
        notes.append(parsed.note)
    return parsed.value


MAX_LINE = 4096  # characters in one line: a row is two numbers; a file with no newline (/dev/zero) is not CSV


def _lines(source: Iterable[str], name: str, option: str = OPTION, across: str = "time") -> Iterator[str]:
    """The lines of ``source``, each read at most MAX_LINE characters at a time, so that a file
    with no line end is refused rather than read into memory without end, and at most MAX_BYTES
    in all (csv_text's cap on any table: an endless FIFO or stdin is refused, not integrated forever)."""
    readline = getattr(source, "readline", None)
    if readline is None:
        yield from source
        return
    number = total = 0
    while line := readline(MAX_LINE + 1):
        number += 1
        total += len(line)
        if total > MAX_BYTES:
            raise too_large(option, name)
        if len(line) > MAX_LINE:
            raise InputError(option, f"line {number}: longer than {MAX_LINE} characters; expected CSV rows of two numbers, {across} and torque",
                             example=_HEADERS[across], got=repr(line[:20] + "…"))
        yield line


_HEADERS = {"time": "'t [ms], torque [N*m]'", "angle": "'theta [deg], torque [N*m]'"}


def read_profile(lines: Iterable[str], name: str = "the profile", *, option: str = OPTION, across: str = "time", least: int = 2) -> Profile:
    """A Profile over CSV lines: a header "t [ms], torque [N*m]", then "time, torque" rows
    (``name``: the file's, as the messages say it); with ``across="angle"``, a turning-moment
    diagram's "theta [deg], torque [N*m]" (``option`` as the messages name it; ``least`` rows)."""
    numbered = ((number, line.strip()) for number, line in enumerate(_lines(lines, name, option, across), start=1))
    rows = ((number, line) for number, line in numbered if line and not line.startswith("#"))
    try:
        header_number, header = next(rows)
    except StopIteration:
        raise InputError(option, f"is empty: expected a header such as {_HEADERS[across]} and at least {least} rows") from None
    separator = _delimiter(header)
    named = [split_header(cell) for cell in _cells(header, separator)]
    if len(named) != 2 or not all(name and not _NUMBER.fullmatch(name) for name, _ in named):
        raise InputError(option, f"line {header_number}: expected a header of two columns, {across} and torque, with units", example=_HEADERS[across], got=repr(header))
    notes: list[str] = []
    across_factor = _unit_factor(named[0][1], across, across, notes, option)
    torque_factor = _unit_factor(named[1][1], "torque", "torque", notes, option)
    return Profile(_samples(rows, across_factor, torque_factor, separator, option, across, least), notes)


_NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")


def _samples(rows: Iterator[tuple[int, str]], time_factor: float, torque_factor: float, separator: str = ",", option: str = OPTION, across: str = "time",
             least: int = 2) -> Iterator[tuple[float, float]]:
    previous = -math.inf
    count = 0
    symbol, unit = ("t", "s") if across == "time" else ("θ", "rad")
    for number, line in rows:
        cells = _cells(line, separator)
        if len(cells) != 2:
            raise InputError(option, f"line {number}: expected two numbers, {across} and torque", got=repr(line))
        try:
            if not line.isascii() or "_" in line:  # one rule with quantities: no 1_000, no fullwidth ５
                raise ValueError(line)
            t, torque = float(cells[0]) * time_factor, float(cells[1]) * torque_factor
        except ValueError:
            raise InputError(option, f"line {number}: expected numbers", got=repr(line)) from None
        if not (math.isfinite(t) and math.isfinite(torque)):
            raise InputError(option, f"line {number}: expected finite numbers", got=repr(line))
        for value, cell, kind in ((t, cells[0], across), (torque, cells[1], "torque")):
            if value == 0 and units.underflowed(cell):  # 1e-400: bounded as written, not as the 0 a double rounds it to
                raise out_of_bounds(kind, option, sign="any", got=f"{cell.strip()!r} on line {number}, nonzero but below what a double holds")
        if t <= previous:
            raise InputError(option, f"line {number}: {'time' if across == 'time' else 'the angle'} must increase from row to row", got=repr(line))
        # Held to the bounds a typed --torque or --duration is held to, a step between rows too
        # (steps of 1e-200 s would underflow Simpson's weights to a zero divisor).
        check_bounds(t, across, option, sign="any", got=f"{symbol} = {t:g} {unit} on line {number} ({line!r})")
        check_bounds(torque, "torque", option, sign="any", got=f"τ = {torque:g} N*m on line {number} ({line!r})")
        if t - previous < BOUNDS[0]:
            raise InputError(option, f"line {number}: expected {across} steps of at least {BOUNDS[0]:g} {unit}", got=f"a step of {t - previous:g} {unit} to {line!r}")
        previous = t
        count += 1
        yield t, torque
    if count < least:
        raise InputError(option, f"has {count} row{'s' if count != 1 else ''} of data: at least {'two are' if least == 2 else f'{least} are'} needed"
                         + (" for an integral" if across == "time" else " for a diagram over a cycle"))
