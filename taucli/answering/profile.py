"""A torque profile from CSV text: "t [ms], torque [N*m]" then rows of numbers, streamed.

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


def _unit_factor(text: str | None, kind: str, column: str, notes: list[str]) -> float:
    if text is None or not text.strip():
        notes.append(f"{OPTION}: no unit for the {column} column in the header: read as SI ({units.KINDS[kind].si_unit})")
        return 1.0
    parsed = units.parse(f"1 {text}", f"{OPTION} header, {column} column", kind)
    if parsed.note:  # "lb*ft": pound-force
        notes.append(parsed.note)
    return parsed.value


MAX_LINE = 4096  # characters in one line: a row is two numbers; a file with no newline (/dev/zero) is not CSV


def _lines(source: Iterable[str], name: str) -> Iterator[str]:
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
            raise too_large(OPTION, name)
        if len(line) > MAX_LINE:
            raise InputError(OPTION, f"line {number}: longer than {MAX_LINE} characters; expected CSV rows of two numbers, time and torque",
                             example="t [ms], torque [N*m]", got=repr(line[:20] + "…"))
        yield line


def read_profile(lines: Iterable[str], name: str = "the profile") -> Profile:
    """A Profile over CSV lines: a header "t [ms], torque [N*m]", then "time, torque" rows
    (``name``: the file's, as the messages say it)."""
    numbered = ((number, line.strip()) for number, line in enumerate(_lines(lines, name), start=1))
    rows = ((number, line) for number, line in numbered if line and not line.startswith("#"))
    try:
        header_number, header = next(rows)
    except StopIteration:
        raise InputError(OPTION, "is empty: expected a header such as 't [s], torque [N*m]' and at least two rows") from None
    separator = _delimiter(header)
    named = [split_header(cell) for cell in _cells(header, separator)]
    if len(named) != 2 or not all(name and not _NUMBER.fullmatch(name) for name, _ in named):
        raise InputError(OPTION, f"line {header_number}: expected a header of two columns, time and torque, with units", example="'t [ms], torque [N*m]'", got=repr(header))
    notes: list[str] = []
    time_factor = _unit_factor(named[0][1], "time", "time", notes)
    torque_factor = _unit_factor(named[1][1], "torque", "torque", notes)
    return Profile(_samples(rows, time_factor, torque_factor, separator), notes)


_NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")


def _samples(rows: Iterator[tuple[int, str]], time_factor: float, torque_factor: float, separator: str = ",") -> Iterator[tuple[float, float]]:
    previous = -math.inf
    count = 0
    for number, line in rows:
        cells = _cells(line, separator)
        if len(cells) != 2:
            raise InputError(OPTION, f"line {number}: expected two numbers, time and torque", got=repr(line))
        try:
            if not line.isascii() or "_" in line:  # one rule with quantities: no 1_000, no fullwidth ５
                raise ValueError(line)
            t, torque = float(cells[0]) * time_factor, float(cells[1]) * torque_factor
        except ValueError:
            raise InputError(OPTION, f"line {number}: expected numbers", got=repr(line)) from None
        if not (math.isfinite(t) and math.isfinite(torque)):
            raise InputError(OPTION, f"line {number}: expected finite numbers", got=repr(line))
        for value, cell, kind in ((t, cells[0], "time"), (torque, cells[1], "torque")):
            if value == 0 and units.underflowed(cell):  # 1e-400: bounded as written, not as the 0 a double rounds it to
                raise out_of_bounds(kind, OPTION, sign="any", got=f"{cell.strip()!r} on line {number}, nonzero but below what a double holds")
        if t <= previous:
            raise InputError(OPTION, f"line {number}: time must increase from row to row", got=repr(line))
        # Held to the bounds a typed --torque or --duration is held to, a step between rows too
        # (steps of 1e-200 s would underflow Simpson's weights to a zero divisor).
        check_bounds(t, "time", OPTION, sign="any", got=f"t = {t:g} s on line {number} ({line!r})")
        check_bounds(torque, "torque", OPTION, sign="any", got=f"τ = {torque:g} N*m on line {number} ({line!r})")
        if t - previous < BOUNDS[0]:
            raise InputError(OPTION, f"line {number}: expected time steps of at least {BOUNDS[0]:g} s", got=f"a step of {t - previous:g} s to {line!r}")
        previous = t
        count += 1
        yield t, torque
    if count < 2:
        raise InputError(OPTION, f"has {count} row{'s' if count != 1 else ''} of data: at least two are needed for an integral")
