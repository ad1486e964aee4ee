"""Sweeps: one quantity option over a range, another over a list, a scene solved at each point.

    --inertia 0.5..4kg*m^2     a range: --points values from one end to the other, evenly spaced
    --torque 3N*m,6N*m         a list: each value in turn (a bare number takes the last one's unit)

At most one range and one list per run. Each point is an ordinary run of the command with those
options replaced by one value, so a sweep's documents are exactly the single runs' documents.
Output: a table (one row per point) and, for a range, a chart of results against it; --plot shows
the chart alone, and for a list without a range overlays the motions in time. --json gives an
array of the documents, --jsonl one per line; --get one line per point, the swept values (SI) then
the results, tab-separated.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass

from taucli.writing import formats
from taucli.writing import plot
from taucli.writing import render as renderer
from taucli.writing.document import document_text
from taucli.writing.human import draw_table, drawing
from taucli.writing.display import minus_signs
from taucli.core.errors import InputError, did_you_mean
from taucli.core.written import printable
from taucli.options import scene
from taucli.writing.report import Report, pretty_unit
from taucli.options.table import Command
from taucli.quantities.units import KINDS

DEFAULT_POINTS = 50
# Points in all, a range's points times a list's values: enough for any chart (a terminal has
# ~100 columns, a file 700 pixels). rich lays out a wide table at 1.6-2.8 ms a row here, so 200
# rows keep the slowest human view (impulse's) at 0.56 s. More scenes are what --batch is for.
MAX_POINTS = 200
MAX_NOTES = 8  # distinct notes shown under a sweep's table

_NUMBER_THEN_UNIT = re.compile(r"\s*(?P<number>[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(?P<unit>.*?)\s*")


@dataclass(frozen=True)
class Swept:
    """One option given as a range or a list, and the values (as text) it takes in turn."""

    name: str  # the parameter: "pulley_mass"
    given: str  # as the user typed it
    texts: tuple[str, ...]  # one value per point, each read by the command as usual
    numbers: tuple[float, ...] | None  # the values in ``unit`` when the items share one unit
    unit: str  # the unit text they share ("" when none or SI)
    is_range: bool

    @property
    def option(self) -> str:
        """The option's name as a message names it ({pulley_mass}: the surface spells it)."""
        return "{" + self.name + "}"

    def label(self, index: int) -> str:
        return f"{self.name} = {pretty_unit(self.texts[index])}"


def _split_number(text: str) -> tuple[float, str] | None:
    found = _NUMBER_THEN_UNIT.fullmatch(text)
    return None if found is None else (float(found["number"]), found["unit"])


def _shared(option: str, items: list[str], given: str, kind: str) -> tuple[list[str], tuple[float, ...] | None, str]:
    """The items with the last one's unit given to bare numbers before it; their numbers and unit."""
    if any(not item.strip() for item in items):
        raise InputError(option, "has an empty item in its list or range", example=_forms(option, kind), got=repr(given))
    split = [_split_number(item) for item in items]
    unit = split[-1][1] if split[-1] is not None else ""
    texts = [f"{item.strip()} {unit}" if unit and pair is not None and not pair[1] else item.strip() for item, pair in zip(items, split)]
    if all(pair is not None and pair[1] in ("", unit) for pair in split):
        return texts, tuple(pair[0] for pair in split), unit
    return texts, None, ""


def _forms(option: str, kind: str) -> str:
    """The two forms of a sweep, as typed in bash, zsh and fish: "{mass} 1..5kg or {mass} 1,5kg"."""
    unit = KINDS[kind].example.strip("'").partition(" ")[2] if kind in KINDS else ""
    quoted = (lambda words: f"'{words}'") if any(ch in unit for ch in "*^()") else (lambda words: words)
    return f"{option} {quoted('1..5' + unit)} or {option} {quoted('1,5' + unit)}"


def _range(name: str, text: str, points: int, kind: str) -> Swept:
    option = "{" + name + "}"
    ends = text.split("..")
    if len(ends) != 2 or "..." in text:  # "1...5kg" is no range: 1 to .5, or 1. to 5?
        raise InputError(option, "expected a range FROM..TO (two dots) or a list A,B", example=_forms(option, kind), got=repr(text))
    _, numbers, unit = _shared(option, ends, text, kind)
    if numbers is None:
        raise InputError(option, "expected a range of two numbers in one unit", example=_forms(option, kind), got=repr(text))
    low, high = numbers
    if not (math.isfinite(low) and math.isfinite(high)) or low == high:
        raise InputError(option, "expected a range between two different finite numbers", example=f"{option} 0.5..4", got=repr(text))
    values = tuple(low + (high - low) * i / (points - 1) for i in range(points - 1)) + (high,)
    texts = tuple(f"{value!r} {unit}".strip() for value in values)
    return Swept(name, text, texts, values, unit, True)


_DECIMAL_COMMA = re.compile(r"\s*[-+]?\d+,\d+(?:[eE][-+]?\d+)?\s*[^\d\s.,][^,]*|\s*[-+]?\d+,\d+\s*")
_THOUSANDS = re.compile(r"\s*[-+]?\d{1,3}(?:,\d{3})+(?:\.\d*)?\s*[^,]*")


def _list(name: str, text: str, kind: str) -> Swept:
    option = "{" + name + "}"
    if _DECIMAL_COMMA.fullmatch(text) or _THOUSANDS.fullmatch(text):
        first, second, *_ = text.split(",")
        number, unit = _NUMBER_THEN_UNIT.fullmatch(f"{first.strip()}.{second.strip()}").group("number", "unit")
        unit = unit or KINDS[kind].example.strip("'").partition(" ")[2]  # the unit typed, else the option's kind's
        if _THOUSANDS.fullmatch(text):  # 1,000 kg: a thousands separator is the likelier reading
            number = text.replace(",", "").strip().removesuffix(unit).strip()
        whole, part = first.strip(), _NUMBER_THEN_UNIT.fullmatch(second.strip()).group("number")
        quoted = (lambda words: f"'{words}'") if any(ch in unit for ch in "*^()") else (lambda words: words)
        raise InputError(
            option,
            "is ambiguous: a comma could be a decimal comma, a thousands separator or a list",
            example=f"{option} {quoted(number + unit)} for a number, {option} {quoted(f'{whole}{unit},{part}{unit}')} for a list",
            got=repr(text),
        )
    texts, numbers, unit = _shared(option, text.split(","), text, kind)
    return Swept(name, text, tuple(texts), numbers, unit, False)


def marked(command: Command, given: Mapping[str, object]) -> tuple[list[str], list[str]]:
    """The names of the quantity options ``given`` as a range (FROM..TO), and as a list (A,B)."""
    ranges, lists = [], []
    for name, value in given.items():
        option = command.option(name)
        if option is None or not option.sweepable or not isinstance(value, str):
            continue
        if ".." in value and "," in value:
            raise InputError(
                "{" + name + "}", "is a range and a list at once: give a range FROM..TO or a list A,B, and at most one of each per run",
                example="{" + name + "} 1..2kg", got=repr(value),
            )
        if ".." in value:
            ranges.append(name)
        elif "," in value:
            lists.append(name)
    return ranges, lists


def find(command: Command, given: Mapping[str, object], points: int | None) -> tuple[Swept | None, Swept | None]:
    """The range and the list among the options ``given`` (None where there is none)."""
    ranges, lists = marked(command, given)
    for found, what, example in ((ranges, "range", "--inertia 0.5..4kg*m^2"), (lists, "list", "--torque 3N*m,6N*m")):
        if len(found) > 1:
            options = " and ".join("{" + name + "}" for name in found)
            raise InputError(options, f"are each a {what}: a sweep takes at most one range and one list", example=example)
    count = DEFAULT_POINTS if points is None else points
    if not 2 <= count <= MAX_POINTS:
        raise InputError("points", f"expected a whole number from 2 to {MAX_POINTS:,}", example="{points} 50", got=str(count))
    if points is not None and not ranges:
        raise InputError("points", "applies to a range (FROM..TO)", example="--inertia '0.5..4kg*m^2' {points} 20")
    swept_range = _range(ranges[0], str(given[ranges[0]]), count, command.option(ranges[0]).kind) if ranges else None
    swept_list = _list(lists[0], str(given[lists[0]]), command.option(lists[0]).kind) if lists else None
    total = (len(swept_range.texts) if swept_range else 1) * (len(swept_list.texts) if swept_list else 1)
    if total > MAX_POINTS:  # a range times a list of as many values would otherwise run for hours
        option = (swept_list or swept_range).option
        raise InputError(option, f"makes a sweep of {total:,} points, more than {MAX_POINTS:,} in all", hint="use fewer {points} or a shorter list, or {batch} for many scenes")
    return swept_range, swept_list


@dataclass
class Point:
    """One solved point of the sweep: which value of the range and of the list, and its report."""

    range_index: int | None
    list_index: int | None
    report: Report


def solve_all(
    command: Command, swept_range: Swept | None, swept_list: Swept | None, given: Mapping[str, object], solve: Callable[[dict], Report]
) -> list[Point]:
    """Each combination of the range's and the list's values, list outermost; a bad point names itself."""
    outer = range(len(swept_list.texts)) if swept_list else [None]
    inner = range(len(swept_range.texts)) if swept_range else [None]
    points = []
    for list_index in outer:
        for range_index in inner:
            options = dict(given)
            for swept, index in ((swept_list, list_index), (swept_range, range_index)):
                if swept is not None:
                    options[swept.name] = swept.texts[index]
            try:
                report = solve(options)
            except InputError as err:
                where = [s.label(i) for s, i in ((swept_range, range_index), (swept_list, list_index)) if s is not None]
                err.expected += f" (at the sweep's point {', '.join(where)})"
                raise
            points.append(Point(range_index, list_index, report))
    return points




def _swept_columns(swept: Swept, points: list[Point]) -> tuple[str, list[float]]:
    """A swept option's heading and its value at each point: in the unit the user typed, else SI."""
    if swept.numbers is not None and swept.unit:
        return f"{swept.name} ({pretty_unit(swept.unit)})", [swept.numbers[point.range_index if swept.is_range else point.list_index] for point in points]
    value = points[0].report.inputs.get(swept.name)
    unit = pretty_unit(value.unit) if value is not None else ""
    return (f"{swept.name} ({unit})" if unit else swept.name), [point.report.inputs[swept.name].value for point in points]


def range_chart(points: list[Point], swept_range: Swept, swept_list: Swept | None, names: list[str]):
    """Each result named against the range, one series per value of the list."""
    first = points[0].report
    per_series = len(swept_range.texts)
    groups = [points[i : i + per_series] for i in range(0, len(points), per_series)]
    heading, xs = _swept_columns(swept_range, groups[0])
    x_unit = heading.partition(" (")[2].removesuffix(")")
    panels = []
    for name in names:
        value = first.results[name]
        series = tuple(
            plot.Series(
                swept_list.label(group[0].list_index) if swept_list else "",
                tuple(xs),
                tuple(None if isinstance(p.report.results[name].value, bool) else p.report.results[name].value for p in group),
            )
            for group in groups
        )
        panels.append(plot.Panel(name, value.label or name, value.unit or "", series))
    title = f"{first.scene}: {', '.join(names)} against {swept_range.name}"
    return plot.Chart(title, swept_range.name, swept_range.name, x_unit, tuple(panels))


def chart_names(points: list[Point], y: list[str]) -> list[str]:
    """The results a range's chart shows: --y, else the scene's headline result (where a model of
    the scene has no such result, as gyro's rotor on a machine has no precession rate: its first number)."""
    results = points[0].report.results
    headline = scene(points[0].report.scene).headline
    if headline not in results:
        headline = next((name for name, value in results.items() if isinstance(value.value, float)), headline)
    names = y or [headline]
    for name in names:
        if name not in results:
            raise InputError("y", f"expected the name of a result of {points[0].report.scene}: {', '.join(results)}", got=repr(name), hint=did_you_mean(name, results))
    return names


def render(points: list[Point], swept_range: Swept | None, swept_list: Swept | None, output, y: list[str], stream, notes_to=None) -> None:
    """The sweep in the format asked for: --get lines, a JSON array or lines, a --format document
    (#36), or a table and a chart."""
    points = [Point(p.range_index, p.list_index, renderer.prepared(p.report, output)) for p in points]
    swept = [s for s in (swept_list, swept_range) if s is not None]
    chart = None
    if swept_range is not None:
        chart = range_chart(points, swept_range, swept_list, chart_names(points, y))
    elif output.drawn:
        runs = [(swept_list.label(p.list_index), p.report) for p in points]
        chart = plot.motion_chart(runs, renderer.chart_units(points[0].report, output.to))
    if output.out is not None and chart is not None:  # the file first: one that cannot be written is refused before any answer
        plot.write_file(chart, output.out, said_to=notes_to)
    if output.get:
        for point in points:
            values = [point.report.inputs[s.name].value for s in swept]
            shown = [renderer.bare(value) for value in values]
            spreads = getattr(point.report, "uncertainties", None) or {}
            for name in output.get:
                shown.append(renderer.bare(renderer.named_result(point.report, name, "--get").value))
                if output.uncertainty:  # #42 item 7: each result's uncertainty in the column after it, as a single run's --get
                    shown.append(renderer.get_spread(point.report, name, spreads))
            stream.write("\t".join(shown) + "\n")
    elif output.json:
        plotted = output.charted and swept_range is None
        documents = [
            document_text(point.report, steps=output.steps, plot=plot.plot_document(point.report) if plotted else None)
            for point in points
        ]
        stream.write("".join(doc + "\n" for doc in documents) if output.json_lines else "[" + ",".join(documents) + "]\n")
    elif output.format:
        _write_format(grid(points, swept), output.format, stream, notes_to)
    else:
        if not output.plot:
            _render_table(points, swept, stream)
        if chart is not None and (swept_range is not None or output.plot):
            columns, colour = renderer.terminal_style(stream)
            stream.write(("" if output.plot else "\n") + plot.terminal(chart, columns, colour=colour))
    stream.flush()


def _notes_where(points: list[Point], swept: list[Swept]) -> list[str]:
    """Each distinct note of the points, once; a note not true at every point says where it is
    ("at m2 = 4 kg: nothing moves"), or at how many points and between which values."""
    where: dict[str, list[int]] = {}
    for row, point in enumerate(points):
        for note in point.report.notes:
            rows = where.setdefault(note, [])
            if not rows or rows[-1] != row:
                rows.append(row)
    if len(points) < 2:
        return list(where)

    def at(row: int) -> str:
        point = points[row]
        return ", ".join(pretty_unit(s.texts[point.range_index if s.is_range else point.list_index]).join((f"{s.name} = ", "")) for s in reversed(swept))

    said = []
    for note, rows in where.items():
        if len(rows) == len(points):
            said.append(note)
        elif len(rows) <= 3:
            said.append(f"at {'; '.join(at(row) for row in rows)}: {note}")
        else:
            said.append(f"at {len(rows)} of the {len(points)} points, {at(rows[0])} to {at(rows[-1])}: {note}")
    return said


def _swept_values(swept: Swept, points: list[Point]) -> tuple[str, str | None, list]:
    """A swept option's name, unit and value at each point: in the unit the user typed, else SI."""
    if swept.numbers is not None and swept.unit:
        return swept.name, swept.unit, [swept.numbers[point.range_index if swept.is_range else point.list_index] for point in points]
    value = points[0].report.inputs.get(swept.name)
    return swept.name, value.unit if value is not None else None, [point.report.inputs[swept.name].value for point in points]


def grid(points: list[Point], swept: list[Swept]) -> formats.Grid:
    """The sweep as one table: the swept values, then every result that has a value somewhere;
    the distinct notes of its points (at most MAX_NOTES, and how many more)."""
    first = points[0].report
    what = " × ".join(f"--{s.name.replace('_', '-')} {s.given} ({len(s.texts)} values)" for s in reversed(swept))
    models = dict.fromkeys(p.report.model for p in points)
    model = first.model if len(models) == 1 else f"varies ({len(models)} kinds; see --json)"
    names = [name for name in first.results if any(p.report.results.get(name) and p.report.results[name].value is not None for p in points)]
    swept_columns = [_swept_values(s, points) for s in swept]
    columns = tuple((name, unit) for name, unit, _ in swept_columns) + tuple((name, first.results[name].unit) for name in names)
    rows = tuple(
        tuple(values[row] for _, _, values in swept_columns)
        + tuple(point.report.results[name].value if name in point.report.results else None for name in names)
        for row, point in enumerate(points)
    )
    notes = _notes_where(points, swept)  # a note true at some points only says at which
    if len(notes) > MAX_NOTES:
        notes = notes[:MAX_NOTES] + [f"… and {len(notes) - MAX_NOTES} more notes that differ from point to point (see --json)"]
    spreads = [getattr(point.report, "uncertainties", None) or {} for point in points]  # #42 item 7: the ± --json keeps
    spread_rows = tuple(tuple([None] * len(swept_columns) + [spread.get(name) for name in names]) for spread in spreads) if any(spreads) else ()
    return formats.Grid(f"{first.scene}: {what}", model, columns, rows, tuple(notes), spread_rows)


def _write_format(table: formats.Grid, format: str, stream, notes_to) -> None:
    """--format md|latex|html|csv (#36): the sweep's table as a document; a CSV's notes to stderr."""
    if format == "csv":
        stream.write(formats.csv_grid(table))
        stream.flush()  # the rows, then the notes beside them
        if notes_to is not None:
            notes_to.write(renderer.said_notes(table.notes))
        return
    if format == "latex":
        from taucli.writing import latex  # deferred: LaTeX's tables of symbols, only for --format latex

        stream.write(latex.grid(table))
        return
    stream.write(formats.markdown_grid(table) if format == "md" else formats.html_grid(table))


def _render_table(points: list[Point], swept: list[Swept], stream) -> None:
    """One row per point: the swept values, then every result that has a value somewhere."""
    from rich.text import Text  # deferred: rich (about 30 ms), only for the human view

    table = grid(points, swept)
    with drawing(stream) as console:
        scene_name, _, what = printable(table.title).partition(": ")  # every text printable, as a single run's (#43 item 14)
        console.print(Text.assemble((scene_name, "bold"), f": {what}"))
        console.print(Text(f"model: {printable(table.model)}", style="dim"))
        headings = []
        for name, unit in table.columns:
            shown_unit = printable(pretty_unit(unit))
            headings.append(f"{printable(name)} ({shown_unit})" if shown_unit else printable(name))
        rows = [[minus_signs(printable(cell)) for cell in row] for row in formats.grid_cells(table)]  # 4.90 ± 0.08 where a value has one
        # numbers are never split: a table too wide for the terminal becomes a list, one point at a time
        draw_table(console, headings, rows, right=[True] * len(headings), bold_first=True)
        for note in map(printable, table.notes):
            if note.startswith("… and "):
                console.print(Text(note, style="dim"))
            else:
                console.print(Text.assemble(("note: ", "yellow"), minus_signs(note)))
        console.print(Text("steps: run one point alone to see its worked solution", style="dim"))
