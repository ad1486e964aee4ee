"""The samples a fit matches: which column is which input of the scene and which is the result
measured, in SI, with the window (--range) and thinning (--every) applied.

Each row of a table is a sample: the scene run with that row's inputs gives a result to compare
with the row's measurement. A column is matched to the scene:

- named by ``--x COLUMN[=OPTION]`` (OPTION defaults to ``time``) or ``--y COLUMN[=RESULT]``;
  either may carry a unit for a header that has none: ``--y "w=omega (rad/s)"``;
- else by its name (the header without its unit, and without a single run's mark): an option's
  name (``m1``, ``angle0``, ``pulley_mass`` or ``pulley-mass``) is an input; ``t`` or ``time``
  is ``--time`` where the scene has no result called so; a result's name (``period``,
  ``omega``) is what was measured, where ``--y`` does not say; two columns for one input are
  refused (columns.py);
- a column matched to nothing is left out, with a note.

A header's unit converts its column to SI with taucli's rules (``Time (ms)``; ``rpm`` is
revolutions, with a note). A used column with no unit is SI only where its name is the input's
or result's own, with a note; angles and angular speeds with no unit are refused, as a bare
number for ``--angle`` is (columns.py). A row with a blank or NaN cell in a column the fit uses
is no measurement: it is left out, and a note counts it.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field, replace

from taucli.quantities import units
from taucli.quantities.kinds import BOUNDS
from taucli.core.errors import InputError, did_you_mean
from taucli.fit import bulk, columns, encoder
from taucli.fit.data import Column, DataTable, Numbers
from taucli.fit.columns import TIME_NAMES, key as _key, quoted as _quoted
from taucli.writing.report import fmt, pretty_unit
from taucli.options.table import Command


@dataclass(frozen=True)
class Mapped:
    """A column matched to the scene: an input option (``is_result`` False) or the result measured."""

    column: Column
    target: str  # the option's name or the result's key
    is_result: bool
    factor: float  # SI per unit of the column
    si_unit: str


@dataclass
class Samples:
    """The samples, in SI: each row's inputs (``inputs``: option name -> one value per sample),
    the result measured, and its standard uncertainty where given."""

    y_key: str
    y_unit: str
    y: list[float]
    inputs: dict[str, list[float]]
    sigma: list[float] | None = None
    sigma_source: str = ""  # "column u (rad/s)", "0.05 rad/s"
    columns: list[Mapped] = field(default_factory=list)
    y_column: Mapped | None = None
    places: list[tuple[str, int]] = field(default_factory=list)  # (file, line) of each sample
    outside: int = 0  # left out by --range
    empty: list[tuple[str, int]] = field(default_factory=list)  # (file, line) of each row left out for a blank or NaN cell the fit uses
    thinned: int = 0  # left out by --every
    notes: list[str] = field(default_factory=list)
    runs: list[int] = field(default_factory=list)  # the run each sample is of (an index of run_names)
    run_names: list[str] = field(default_factory=list)  # each run's file (and its mark): "coast.csv", "lab.csv (run 2)"

    @property
    def count(self) -> int:
        return len(self.y)

    @property
    def dropped(self) -> int:
        return self.outside + self.thinned

    def of_runs(self, kept: set[int]) -> Samples:
        """These samples of the runs ``kept`` alone (a start for each run's own inputs)."""
        chosen = [i for i, run in enumerate(self.runs) if run in kept]
        pick = lambda values: [values[i] for i in chosen]  # noqa: E731
        return replace(self, y=pick(self.y), inputs={name: pick(values) for name, values in self.inputs.items()},
                       sigma=None if self.sigma is None else pick(self.sigma), places=pick(self.places), runs=pick(self.runs), notes=[])

    def row(self, i: int) -> dict[str, float]:
        return {name: values[i] for name, values in self.inputs.items()}

    @property
    def varying(self) -> list[str]:
        """The inputs that differ between samples, in the order of the columns."""
        return [name for name, values in self.inputs.items() if any(value != values[0] for value in values)]

    def sources(self) -> list[str]:
        """The files the samples come from, in order."""
        sources = getattr(self.places, "sources", None)
        return sources() if sources is not None else list(dict.fromkeys(place[0] for place in self.places))


_spec, _find = columns.spec, columns.find  # (named in columns.py, where a column's naming is)


def _factor(column: Column, unit: str, kind: str | None, si_unit: str, label: str, notes: list[str], target: str = "", is_result: bool = False) -> float:
    """SI per unit of the column (its header's unit, or the unit its mapping gives; with neither,
    columns.bare_factor's rule for the input or result ``target``)."""
    if not unit:
        return columns.bare_factor(column, target, is_result, kind, si_unit, label, notes)
    where = f"column {column.header!r}"
    if kind is not None:
        parsed = units.parse(f"1 {unit}", where, kind, sign="positive")
    else:
        one = units.converted(1.0, si_unit, unit, where)
        parsed = units.Parsed(1.0 / one.value, one.note)
    if parsed.note:
        notes.append(parsed.note.replace(f"{where} 1 {unit}:", f"{where}:"))
    return parsed.value


def _kind_of_result(si_unit: str) -> str | None:
    return next((kind.name for kind in units.KINDS.values() if kind.si_unit == si_unit), None)


def build(command: Command, tables: list[DataTable], *, x=(), y: str | None = None, sigma: str | None = None,
          ranges=(), every: str | None = None, fitted=(), given=(), gravity: float | None = None, counts_per_rev=None, counts=None) -> Samples:
    """The samples of ``tables`` for ``command``, every column matched and converted to SI; an
    encoder's counts (``counts_per_rev``, ``counts``) as revolutions (taucli.fit.encoder)."""
    notes: list[str] = []
    how = encoder.kind(counts, counts_per_rev)
    per_rev = encoder.per_rev(counts_per_rev) if how is not None else None
    headers = [column.header for column in tables[0].columns]
    for table in tables[1:]:
        if [column.header for column in table.columns] != headers:
            raise InputError("data", f"{table.source} names other columns than {tables[0].source}: every file of one fit has the same columns",
                             got=", ".join(repr(column.header) for column in table.columns))
    picked = {_spec(text, "x")[0] for text in x or ()} | ({_spec(y, "y")[0]} if y is not None else set())
    tables = [run for table in tables for run in columns.split_runs(table, picked)]  # each file, and each run side by side in one, a run
    chosen: dict[str, tuple[str, bool, str]] = {}  # header -> (target, is_result, unit given by the mapping)
    for text in x or ():
        column, target, unit = _spec(text, "x")
        header = _find(tables, column, "x")
        target = _option_target(command, target or "time", text)
        columns.refuse_a_column_mapped_twice(chosen, header, target, "x")
        chosen[header] = (target, False, unit)
    if per_rev is not None:
        encoder.counted_column(command, tables, y, chosen)
    elif y is not None:
        column, target, unit = _spec(y, "y")
        header = _find(tables, column, "y")
        columns.refuse_a_column_mapped_twice(chosen, header, target, "y")
        key = target or tables[0].column(header).name
        if command.result(_key(key)) is None and command.result(key) is None:
            keys = [result.key for result in command.results]
            close = did_you_mean(key, keys)  # a close name says enough; else the first few, not ~60 (#42)
            listed = "" if close else ": " + (", ".join(keys) if len(keys) <= 12 else ", ".join(keys[:10]) + f", … ({len(keys)} in all: docs/{command.name}.md)")
            raise InputError("y", f"expected a result of {command.name} for column {header!r}{listed}", got=repr(key),
                             example='{y} "w (rad/s)=omega"', hint=close)
        chosen[header] = (key if command.result(key) is not None else _key(key), True, unit)
    sigma_header = _sigma_column(tables, sigma)
    _refuse_sigma_of_a_used_column(command, tables[0], chosen, sigma_header, y is not None)
    unused = columns.match_by_name(command, tables[0], chosen, sigma_header, y is not None or per_rev is not None, notes)
    if per_rev is not None:
        counted = next(header for header, (_, is_result, _) in chosen.items() if is_result)
        time = next((header for header, (target, is_result, _) in chosen.items() if target == "time" and not is_result), None)
        tables = [encoder.speeds(table, counted, time, per_rev, how) for table in tables]
        notes.append(f"column {counted!r} read as an encoder's {'cumulative count' if how == 'cumulative' else 'counts in each interval'}, "
                     f"{per_rev:g} a revolution: each interval between two rows gives its mean speed, 2π·Δcount/({per_rev:g}·Δt), at its middle; "
                     "neighbouring intervals share a count's rounding, so their residuals alternate in sign (r₁ near −0.5) and the "
                     "uncertainties, which take them as independent, are larger than the counts' own")
    results = [header for header, (_, is_result, _) in chosen.items() if is_result]
    if not results:
        names = ", ".join(repr(h) for h in headers)
        raise InputError("y", f"names the column that was measured, and no column is named like a result of {command.name} ({names})",
                         example='{y} "Gyroscope z (rad/s)=omega"')
    if len(results) > 1:
        raise InputError("y", f"says which column was measured: {', '.join(repr(h) for h in results)} are each named like a result",
                         example=f"{{y}} {results[0]!r}")
    mapped = []
    for header, (target, is_result, unit) in chosen.items():
        mapped.append(_mapped(command, tables[0].column(header), target, is_result, unit, fitted, given, notes))
    y_column = next(m for m in mapped if m.is_result)
    inputs_mapped = [m for m in mapped if not m.is_result]
    found = _collected(command, tables, y_column, inputs_mapped, sigma, sigma_header, ranges, every, gravity, notes)
    _refuse_one_run_beside_unused(command, tables, found, unused)
    return found


def _refuse_sigma_of_a_used_column(command: Command, table: DataTable, chosen: dict, sigma_header: str | None, y_given: bool) -> None:
    """--sigma naming a column the fit uses otherwise: the measured one (its own σ: the fit then
    weighs each sample by its size) or an input's. A σ is a column of its own, or one value."""
    if sigma_header is None:
        return
    used = dict(chosen)
    if sigma_header not in used:
        columns.match_by_name(command, table, used, None, y_given, [])  # what the column would be, were it not σ
    others_measured = any(is_result for header, (_, is_result, _) in used.items() if header != sigma_header)
    if sigma_header in used and not (used[sigma_header][1] and others_measured):  # (named like a result beside the measured column: σ)
        target, is_result, _ = used[sigma_header]
        what = f"the measured {target}" if is_result else f"the input {target}"
        raise InputError("sigma", f"names column {sigma_header!r}, which is {what}: a sample's uncertainty is a column of its own, or one value for all",
                         example="{sigma} 0.05rad/s", got=repr(sigma_header))


def _refuse_one_run_beside_unused(command: Command, tables: list[DataTable], found: Samples, unused: list[str]) -> None:
    """Samples that are all one run of the scene (no input column, or none that varies) beside a
    column that varies and is not used: that column is most likely the input the runs differ by
    (an amplitude, a mass), and fitting the runs as repeats of one would give a wrong number."""
    if found.varying or found.count < 2:
        return
    varies = [header for header in unused if len({value for table in tables for value in table.column(header).values if not math.isnan(value)}) > 1]
    if varies:
        listed = ", ".join(repr(header) for header in varies)
        raise InputError("x", f"is needed: every sample is the same run of {command.name} (no column gives an input that differs between them), "
                         f"and {listed} differ{'s' if len(varies) == 1 else ''} between them but {'is' if len(varies) == 1 else 'are'} not used",
                         hint=f"say which input {'it is' if len(varies) == 1 else 'each is'}: {{x}} {_quoted(varies[0] + '=OPTION')}, "
                         "or leave the column out of the table")


def _option_target(command: Command, name: str, text: str) -> str:
    option = command.option(_key(name)) or command.option(name)
    if option is None or option.name not in command.input_names or not option.is_quantity or option.repeatable:
        quantities = [o.name for o in command.options if o.is_quantity and not o.repeatable and o.name in command.input_names]
        if name == "time" and command.option("time") is None:
            raise InputError("x", f"names the option a column is: {command.name} has no --time, so say which: {{x}} \"COLUMN=OPTION\"", got=repr(text))
        raise InputError("x", f"expected an input of {command.name} that takes one quantity: {', '.join(quantities)}", got=repr(name),
                         hint=did_you_mean(name, quantities))
    return option.name


def _sigma_column(tables: list[DataTable], sigma: str | None) -> str | None:
    if sigma is None:
        return None
    headers = [column.header for column in tables[0].columns]
    names = [column.name for column in tables[0].columns]
    return sigma.strip() if sigma.strip() in headers else headers[names.index(sigma.strip())] if sigma.strip() in names else None


def _mapped(command: Command, column: Column, target: str, is_result: bool, unit: str, fitted, given, notes: list[str]) -> Mapped:
    if column.unit and unit and column.unit != unit:
        raise InputError("x" if not is_result else "y", f"gives column {column.header!r} the unit {unit}, and its header says {column.unit}", got=repr(unit))
    unit = column.unit or unit
    if is_result:
        result = command.result(target)
        if result.unit is None:
            raise InputError("y", f"expected a result that is a number; {target} is yes or no", got=repr(column.header))
        kind = _kind_of_result(result.unit)
        try:
            factor = _factor(column, unit, kind, result.unit, f"the result {target}", notes, target, True)
        except InputError as err:
            if not unit or err.option != f"column {column.header!r}":
                raise
            raise InputError("y", f"reads column {column.header!r} as the result {target}, and its unit {unit} is not "
                             + (units.article(kind) if kind else f"one of {pretty_unit(result.unit)}"),
                             hint=f"say which result it is: {{y}} {_quoted(column.header + '=RESULT')}") from None
        return Mapped(column, target, True, factor, result.unit)
    if target in fitted:
        raise InputError("fit", f"fits {target}, and column {column.header!r} gives it for each sample: one or the other", got=repr(target))
    if target in given:
        raise InputError("data", f"column {column.header!r} gives {{{target}}} for each sample, and {{{target}}} is given as well: one or the other")
    option = command.option(target)
    try:
        factor = _factor(column, unit, option.kind, units.KINDS[option.kind].si_unit, f"--{target.replace('_', '-')}", notes, target)
    except InputError as err:
        if not unit or err.option != f"column {column.header!r}":
            raise
        said = " (--x COLUMN alone is the time)" if target == "time" else ""
        raise InputError("x", f"reads column {column.header!r} as {{{target}}}{said}, and its unit {unit} is not {units.article(option.kind)}",
                         hint=f"say which input it is: {{x}} {_quoted(column.header + '=OPTION')}") from None
    return Mapped(column, target, False, factor, units.KINDS[option.kind].si_unit)


def _collected(command: Command, tables, y_column: Mapped, inputs_mapped: list[Mapped], sigma, sigma_header, ranges, every, gravity, notes) -> Samples:
    windows = [_window(command, text, [y_column, *inputs_mapped], gravity) for text in ranges or ()]
    step = _every(every)
    sigma_value, sigma_factor, sigma_source = _sigma(tables[0], sigma, sigma_header, y_column, gravity)
    # each a compact array of doubles (data.Numbers, equal to a list of the same numbers): a million samples are 8 MB a column
    samples = Samples(y_column.target, y_column.si_unit, Numbers("d"), {m.target: Numbers("d") for m in inputs_mapped},
                      Numbers("d") if sigma is not None else None, sigma_source, inputs_mapped, y_column, notes=notes)
    kept_in_window = 0  # (no cap on the samples but the reader's: a fit past its time limit is refused by taucli.fit.budget, --every its way out)
    used = [m.column.header for m in (y_column, *inputs_mapped)] + ([sigma_header] if sigma_header is not None else [])
    samples.run_names = [table.source for table in tables]
    # one run: on arrays at once (bulk); several, or a row refused there: row by row, each sample's run and line kept
    if len(tables) == 1 and bulk.collect(command, tables, y_column, inputs_mapped, sigma_value, sigma_factor, sigma_header, windows, step, used, samples):
        _note_the_empty_rows(samples, used, False)
        return samples
    samples.empty, samples.outside, samples.thinned = [], 0, 0
    for run, table in enumerate(tables):
        for i, line in enumerate(table.lines):
            if any(math.isnan(table.column(header).values[i]) for header in used):
                samples.empty.append((table.source, line))  # no measurement: not a sample (data.py reads a blank or NaN cell so)
                continue
            cells = {m.target: table.column(m.column.header).values[i] * m.factor for m in (y_column, *inputs_mapped)}
            if any(not low <= cells[name] <= high for name, low, high in windows):
                samples.outside += 1
                continue
            kept_in_window += 1
            if (kept_in_window - 1) % step:
                samples.thinned += 1
                continue
            for m in (y_column, *inputs_mapped):  # in SI, a value its unit takes past a double's range, or to 0, is refused as a typed one is
                _check_unit_made(cells[m.target], table.column(m.column.header).values[i], table.source, line, m.column.header)
            for m in inputs_mapped:
                option = command.option(m.target)
                _check_input(option, cells[m.target], table.source, line, m.column.header)
                samples.inputs[m.target].append(cells[m.target])
            _check_measured(cells[y_column.target], y_column, table.source, line)
            samples.y.append(cells[y_column.target])
            if sigma_header is not None:
                spread = table.column(sigma_header).values[i] * sigma_factor
                _check_unit_made(spread, table.column(sigma_header).values[i], table.source, line, sigma_header)
                _check_measured(spread, y_column, table.source, line, sigma_header)
                if not spread > 0:
                    raise InputError("sigma", f"{table.source} line {line}: expected an uncertainty greater than 0 in column {sigma_header!r}", got=fmt(spread))
                samples.sigma.append(spread)
            elif sigma_value is not None:
                samples.sigma.append(sigma_value)
            samples.places.append((table.source, line))
            samples.runs.append(run)
    _note_the_empty_rows(samples, used, len(tables) > 1)
    return samples


def _note_the_empty_rows(samples: Samples, used: list[str], files: bool) -> None:
    """A note of the rows left out for a blank or NaN cell in a column the fit uses; a usage error
    where that leaves no sample."""
    if not samples.empty:
        return
    listed = ", ".join(repr(header) for header in used)
    if not samples.count and not samples.outside:
        raise InputError("data", f"has no row with a number in every column the fit uses ({listed}): each is blank or NaN in some row",
                         hint="fill the cells, or map other columns with --x and --y")
    count = len(samples.empty)
    shown = samples.empty[:3]
    places = ", ".join(f"{source} line {line}" if files else str(line) for source, line in shown)
    places = ("" if files else "line " if count == 1 else "lines ") + places + (f", … ({count} in all)" if count > len(shown) else "")
    samples.notes.append(f"{count} row{'s' if count != 1 else ''} left out ({places}): a column the fit uses ({listed}) is blank or NaN there, "
                         "no measurement")


def _check_unit_made(value: float, given: float, source: str, line: int, header: str) -> None:
    """A cell that its column's unit takes past a double (1e306 rad/ms) or to 0 (1e-320 ms)."""
    if not math.isfinite(value) or (value == 0 and given != 0):
        raise InputError("data", f"{source} line {line}: column {header!r} holds {fmt(given)}, which its unit makes {'too large' if value else 'too small'} "
                         "for a double in SI")


def _check_measured(value: float, measured: Mapped, source: str, line: int, header: str | None = None) -> None:
    """A measured value (or its σ) held to the bounds a typed quantity is (0, or 1e-40 to 1e40 in SI)."""
    low, high = BOUNDS
    if value and not low <= abs(value) <= high:
        header = header or measured.column.header
        unit = measured.si_unit
        raise InputError("data", f"{source} line {line}: column {header!r} (the measured {measured.target}{', its σ' if header != measured.column.header else ''}) "
                         f"expected a value of 0 or between 1e-40 and 1e40 {unit} in size".rstrip(), got=f"{fmt(value)} {unit}".rstrip())


def _check_input(option, value: float, source: str, line: int, header: str) -> None:
    try:
        units.si_number(value, option.name, option.kind, sign=option.sign)
    except InputError as err:
        raise InputError("data", f"{source} line {line}: column {header!r} ({option.flag}) {err.expected}", got=fmt(value)) from None


def _every(text: str | None) -> int:
    if text is None:
        return 1
    try:
        step = int(str(text).strip())
    except ValueError:
        step = 0
    if step < 1:
        raise InputError("every", "expected a whole number of 1 or more", example="{every} 10", got=repr(text))
    return step


def _sigma(table: DataTable, sigma: str | None, sigma_header: str | None, y_column: Mapped, gravity) -> tuple[float | None, float, str]:
    """(one σ for every sample, or None; SI per unit of a σ column; how the output names it)."""
    if sigma is None:
        return None, 1.0, ""
    unit = pretty_unit(y_column.si_unit)
    if sigma_header is not None:
        column = table.column(sigma_header)
        factor = y_column.factor if not column.unit else _factor(column, column.unit, _kind_of_result(y_column.si_unit), y_column.si_unit, "an uncertainty", [])
        return None, factor, f"column {sigma_header!r}" + ("" if column.unit else f" (in {y_column.column.unit or unit}, as {y_column.column.header!r})")
    try:
        value = _quantity(sigma, "sigma", y_column.si_unit, gravity)
    except InputError:
        if re.search(r"\d", sigma):
            raise
        # a word that is no value: a column that is not there ("u" read as a unit was "a mass")
        columns = ", ".join(repr(column.header) for column in table.columns[:8]) + (f", … {len(table.columns)} in all" if len(table.columns) > 8 else "")
        raise InputError("sigma", f"expected a column of {table.source} ({columns}) or one value for all", example=f"{{sigma}} 0.05{unit.replace('²', '^2')}",
                         got=f"{sigma!r}, which is no column of it" if sigma.strip() else repr(sigma)) from None
    if not value > 0:
        raise InputError("sigma", "expected an uncertainty greater than 0, or a column", example=f"{{sigma}} 0.05{unit.replace('²', '^2')}", got=repr(sigma))
    return value, 1.0, f"{fmt(value)} {unit}".rstrip()


def _quantity(text: str, option: str, si_unit: str, gravity) -> float:
    kind = _kind_of_result(si_unit)
    if kind is not None:
        return units.parse(text, f"{{{option}}}", kind, sign="any", gravity=gravity).value
    found = re.fullmatch(r"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*", text)
    if found is None:
        raise InputError(option, f"expected a number with a unit of {si_unit or 'no unit'}", got=repr(text))
    number, unit = float(found[1]), found[2]
    return number / units.converted(1.0, si_unit, unit, f"{{{option}}}").value if unit else number


def _window(command: Command, text: str, mapped: list[Mapped], gravity) -> tuple[str, float, float]:
    """(target, low, high) in SI from "NAME=FROM..TO" (either end may be left open)."""
    name, sep, span = str(text).partition("=")
    low_text, dots, high_text = span.partition("..")
    if not sep or not dots:
        raise InputError("range", "expected COLUMN=FROM..TO", example="{range} t=2s..30s", got=repr(text))
    name = name.strip()
    found = [m for m in mapped if name in (m.column.header, m.column.name, m.target) or (name in TIME_NAMES and m.target == "time")]
    if not found:
        names = sorted({m.column.name for m in mapped} | {m.target for m in mapped})
        raise InputError("range", f"expected a column of the fit: {', '.join(names)}", got=repr(name), example="{range} t=2s..30s")
    m = found[0]
    bounds = []
    for part, default in ((low_text, -math.inf), (high_text, math.inf)):
        if not part.strip():
            bounds.append(default)
        elif m.is_result:
            bounds.append(_quantity(part, "range", m.si_unit, gravity))
        else:
            bounds.append(units.parse(part, "{range}", command.option(m.target).kind, sign="any", gravity=gravity).value)
    if bounds[0] > bounds[1]:
        raise InputError("range", "expected FROM below TO", example="{range} t=2s..30s", got=repr(text))
    return m.target, bounds[0], bounds[1]
