"""An encoder's counts as the speed a scene gives (#44): ``--counts-per-rev N`` with
``--counts cumulative`` (the count since the recording started, as a rotary motion sensor's
position) or ``--counts interval`` (the counts in each row's interval, since the row before).
Each interval between two rows gives the mean speed over it, taken as the speed at its middle:

    ω(t_{i−½}) = 2π (C_i − C_{i−1}) / (N (t_i − t_{i−1})),   t_{i−½} = (t_{i−1} + t_i)/2,

with C the cumulative count (the interval counts summed). Differences, not positions: an
encoder's count is off from N·θ by where in a count it started (up to one count, the same in
every row), which no scene's θ(t) has a place for and which a fit of positions would take for
friction; a difference of two counts has no such offset, and its rounding (up to a count) is
noise of mean 0. The mean over an interval differs from the speed at its middle by ω''Δt²/24:
nothing where the torque is constant, and far below a count's noise at the rates loggers
sample a coast at otherwise. Each count is a whole number (else the column is no count, refused);
the rows go forward in time; a blank count leaves out the intervals it bounds (cumulative) or is
(interval); an interval count's first row, whose interval began before the table, is left out. The
counts of each run (taucli.fit.runs) are taken apart.

Plain Python: no numpy, no pint.
"""

from __future__ import annotations

import math
import re
from dataclasses import replace

from taucli.core.errors import InputError
from taucli.fit import columns
from taucli.fit.data import Column, DataTable, Numbers
from taucli.options.table import Command

OPTION = "counts_per_rev"
KINDS = ("cumulative", "interval")
RESULT = "omega"
NAMES = ("counts", "count", "ticks", "encoder")  # a column named so is the counts where --y names none


def per_rev(text) -> float:
    """N from --counts-per-rev: a whole number of counts in a revolution, 1 or more."""
    found = re.fullmatch(r"\s*(\d+(?:\.\d*)?)\s*(?:(?:counts?|cpr|ticks?)\s*(?:/|per)?\s*(?:rev|revolution|turn)?)?\s*", str(text), re.IGNORECASE)
    value = float(found[1]) if found else math.nan
    if not (value >= 1 and value == int(value) and value <= 1e9):
        raise InputError(OPTION, "expected the encoder's counts in one revolution, a whole number of 1 or more", example="{counts_per_rev} 360",
                         got=repr(text))
    return value


def kind(text, counts_per_rev) -> str | None:
    """--counts, which goes with --counts-per-rev: each refused without the other."""
    if counts_per_rev is None:
        if text is not None:
            raise InputError("counts", "says what an encoder's counts are, and goes with {counts_per_rev}", example="{counts_per_rev} 360 {counts} cumulative")
        return None
    if text not in KINDS:
        raise InputError("counts", "expected cumulative (the count since the start, a position) or interval (the counts since the row before)",
                         example="{counts_per_rev} 360 {counts} cumulative", got=None if text is None else repr(text))
    return text


def speeds(table: DataTable, header: str, time_header: str | None, n: float, how: str) -> DataTable:
    """``table`` with a row for each interval between two of its rows: the time its middle, the
    counts column the mean speed over it (rev per the time's unit)."""
    if time_header is None:
        raise InputError(OPTION, "reads an encoder's counts as speeds between the times of the rows, and no column is the time", hint='map one: {x} "Time (s)"')
    counts, time = table.column(header), table.column(time_header)
    for line, c in zip(table.lines, counts.values):
        if not math.isnan(c) and c != round(c):
            raise InputError(OPTION, f"reads column {header!r} as an encoder's counts, and {table.source} line {line} holds {c:g}, not a whole number",
                             hint="give the column that counts, or its unit in the header if it is an angle")
    c = counts.values
    turned = (lambda k: c[k]) if how == "interval" else (lambda k: c[k] - c[k - 1])  # counts in the interval before row k (NaN where blank)
    middles, rates, lines = Numbers("d"), Numbers("d"), Numbers("q")
    for k in range(1, len(table.lines)):
        t0, t1 = time.values[k - 1], time.values[k]
        if not t1 > t0 and not (math.isnan(t0) or math.isnan(t1)):
            raise InputError("data", f"{table.source} line {table.lines[k]}: an encoder's counts are read between rows that go forward in time, "
                             "and this one is not after the row above", hint="sort the rows by time")
        middles.append((t0 + t1) / 2)
        rates.append(turned(k) / n / (t1 - t0))
        lines.append(table.lines[k])
    unit = f"rev/{time.unit}" if time.unit else "rev/s"
    changed = {header: Column(counts.header, counts.name, unit, rates), time_header: replace(time, values=middles)}
    others = [replace(column, values=Numbers("d", column.values[1:])) for column in table.columns if column.header not in changed]
    kept = {column.header: column for column in others} | changed
    return replace(table, columns=tuple(kept[column.header] for column in table.columns), lines=lines)


def counted_column(command: Command, tables: list[DataTable], y: str | None, chosen: dict) -> None:
    """The column of an encoder's counts (--y, else one named counts), the measured revs."""
    if command.result(RESULT) is None:
        raise InputError(OPTION, f"reads an encoder's counts as revolutions, and {command.name} gives no {RESULT}",
                         hint="fit spin-down, or give the angle in a column with its unit")
    if y is not None:
        column, target, _ = columns.spec(y, "y")
        header = columns.find(tables, column, "y")
        if target not in (None, RESULT):
            raise InputError("y", f"names column {header!r} as {target}, and with {{counts_per_rev}} it holds counts, read as {RESULT}",
                             example=f'{{y}} {columns.quoted(header)}', got=repr(y))
    else:
        named = [column.header for column in tables[0].columns if columns.key(column.name) in NAMES]
        if len(named) != 1:
            raise InputError("y", "names the column of the encoder's counts ({counts_per_rev} reads it)", example='{y} "Counts"')
        header = named[0]
    chosen[header] = (RESULT, True, "")
