"""The samples of a table on arrays: the rows samples.py takes one by one, taken all at once.

The same rules in the same order (taucli.fit.samples._collected): a row with a blank or NaN cell
in a column the fit uses is no measurement; --range keeps the rows within its windows; --every N
keeps the 1st, (N+1)th, … of the rows kept, counted over all the tables; each value is converted
to SI by its column's factor and checked as a typed one is. The checks are made on arrays here;
where any row fails one, nothing is taken (``collect`` returns False) and the row-by-row reading
gives the refusal with its line, as before. A check of sign and bounds holds for every value when
it holds for the least and the largest, the nonzero ones nearest 0 either side, and 0: the values
a quantity may take are 0 (or not) and bands of magnitudes either side.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from taucli.core.errors import InputError
from taucli.quantities import units
from taucli.quantities.kinds import BOUNDS


class Places(Sequence):
    """(file, line) of each sample, as a list of them reads, kept as each file's array of lines:
    a million samples are 8 MB here, not a million tuples."""

    def __init__(self, parts: list[tuple[str, np.ndarray]]):
        self.parts = [(source, lines) for source, lines in parts if len(lines)]
        self.ends = np.cumsum([len(lines) for _, lines in self.parts])

    def __len__(self) -> int:
        return int(self.ends[-1]) if len(self.ends) else 0

    def __getitem__(self, i):
        if isinstance(i, slice):
            return [self[j] for j in range(*i.indices(len(self)))]
        i = i + len(self) if i < 0 else i
        if not 0 <= i < len(self):
            raise IndexError(i)
        part = int(np.searchsorted(self.ends, i, side="right"))
        source, lines = self.parts[part]
        return source, int(lines[i - (int(self.ends[part - 1]) if part else 0)])

    def __iter__(self):
        for source, lines in self.parts:
            for line in lines.tolist():
                yield source, line

    def __eq__(self, other):
        return list(self) == list(other) if isinstance(other, (list, tuple, Places)) else NotImplemented

    __hash__ = None

    def sources(self) -> list[str]:
        return list(dict.fromkeys(source for source, _ in self.parts))


def _extend(column, values: np.ndarray) -> None:
    """Append the doubles to a column of the samples (an array of doubles, or a list)."""
    if hasattr(column, "frombytes"):
        column.frombytes(np.ascontiguousarray(values, dtype=float).tobytes())
    else:
        column.extend(values.tolist())


def _extremes(values: np.ndarray) -> list[float]:
    """The values whose checks stand for all of them (see the module's docstring)."""
    if not values.size:
        return []
    found = {float(values.min()), float(values.max())}
    positive, negative = values[values > 0], values[values < 0]
    if positive.size:
        found.add(float(positive.min()))
    if negative.size:
        found.add(float(negative.max()))
    if np.any(values == 0):
        found.add(0.0)
    return sorted(found)


def _input_holds(option, values: np.ndarray) -> bool:
    try:
        for value in _extremes(values):
            units.si_number(value, option.name, option.kind, sign=option.sign)
    except InputError:
        return False
    return True


def _measured_holds(values: np.ndarray) -> bool:
    low, high = BOUNDS
    size = np.abs(values)
    return bool(np.all((values == 0) | ((size >= low) & (size <= high))))


def _unit_holds(values: np.ndarray, given: np.ndarray) -> bool:
    return bool(np.all(np.isfinite(values) & ~((values == 0) & (given != 0))))


def collect(command, tables, y_column, inputs_mapped, sigma_value, sigma_factor, sigma_header, windows, step, used, samples) -> bool:
    """Fill ``samples`` from ``tables`` (True), or leave it for the row-by-row reading (False)
    where some row is refused."""
    with np.errstate(over="ignore", invalid="ignore"):  # (a value its unit takes past a double is refused below, row by row)
        return _collect(command, tables, y_column, inputs_mapped, sigma_value, sigma_factor, sigma_header, windows, step, used, samples)


def _collect(command, tables, y_column, inputs_mapped, sigma_value, sigma_factor, sigma_header, windows, step, used, samples) -> bool:
    mapped = (y_column, *inputs_mapped)
    parts: dict[str, list[np.ndarray]] = {m.target: [] for m in mapped}
    spreads, places, kept_before = [], [], 0
    for table in tables:
        raw = {header: np.asarray(table.column(header).values, dtype=float) for header in used}
        lines = np.asarray(table.lines)
        empty = np.zeros(len(lines), dtype=bool)
        for header in used:
            empty |= np.isnan(raw[header])
        samples.empty.extend((table.source, int(line)) for line in lines[empty])
        cells = {m.target: raw[m.column.header] * m.factor for m in mapped}
        inside = ~empty
        for name, low, high in windows:
            inside &= (cells[name] >= low) & (cells[name] <= high)
        samples.outside += int(np.sum(~empty & ~inside))
        order = kept_before + np.cumsum(inside)  # the count of rows kept in the windows, up to each
        kept_before = int(order[-1]) if order.size else kept_before
        taken = inside & ((order - 1) % step == 0)
        samples.thinned += int(np.sum(inside & ~taken))
        for m in mapped:
            values, given = cells[m.target][taken], raw[m.column.header][taken]
            if not _unit_holds(values, given):
                return False
            if m is y_column:
                if not _measured_holds(values):
                    return False
            elif not _input_holds(command.option(m.target), values):
                return False
            parts[m.target].append(values)
        if sigma_header is not None:
            given = raw[sigma_header][taken]
            spread = given * sigma_factor
            if not (_unit_holds(spread, given) and _measured_holds(spread) and np.all(spread > 0)):
                return False
            spreads.append(spread)
        places.append((table.source, lines[taken]))
    joined = {name: np.concatenate(found) if found else np.zeros(0) for name, found in parts.items()}
    _extend(samples.y, joined[y_column.target])
    for m in inputs_mapped:
        _extend(samples.inputs[m.target], joined[m.target])
    if sigma_header is not None:
        _extend(samples.sigma, np.concatenate(spreads))
    elif sigma_value is not None:
        _extend(samples.sigma, np.full(len(samples.y), sigma_value))
    samples.places = Places(places)
    return True
