"""Renderers: the human view (rich table and steps), --json, and --get; --to converts units.

JSON and --get print nothing on stdout but the answer. rich is imported by the human view only.
"""

from __future__ import annotations

import json
import math
import os
from collections.abc import Mapping, Sequence
from dataclasses import replace
from typing import NamedTuple, TextIO

from taucli import __version__
from taucli.errors import InputError, did_you_mean
from taucli.report import Report, Table, Value, fmt, pretty_unit


# Compact, and strict: NaN or Infinity raise rather than print (finite_only keeps them out).
STRICT_JSON = json.JSONEncoder(ensure_ascii=False, allow_nan=False, separators=(",", ":"))


class Output(NamedTuple):
    """How the user asked for the answer: the format and unit conversions.

    A NamedTuple, as Value is: made twice on every run, batch lines included.
    """

    json: bool = False
    get: Sequence[str] = ()
    to: Sequence[str] = ()
    steps: bool = True
    plot: bool = False  # draw the motion in time (or, in --json, include its samples)
    out: str | None = None  # also draw the chart to this .svg or .png file
    json_lines: bool = False  # a sweep's documents one per line rather than one array

    @property
    def charted(self) -> bool:
        return self.plot or self.out is not None

    @property
    def drawn(self) -> bool:
        """A chart is drawn: in the terminal, or to a file. (--json --plot gives the samples only.)"""
        return self.out is not None or (self.plot and not self.json)


def terminal_style(stream: TextIO) -> tuple[int, bool]:
    """(columns, colour) for text drawn on ``stream``: no colour under NO_COLOR, TERM=dumb or a pipe."""
    import shutil

    columns = shutil.get_terminal_size((100, 24)).columns
    colour = stream.isatty() and not os.environ.get("NO_COLOR") and os.environ.get("TERM") != "dumb"
    return max(columns, 20), colour


def chart_units(report: Report, to: Sequence[str]) -> dict[str, tuple[str, float]]:
    """For each curve of the report's motion named in --to: (unit, SI value of one of it)."""
    from taucli import units

    curves = {key: unit for key, unit, _ in report.trajectory().curves} if report.trajectory else {}
    return {name: (unit, 1.0 / units.convert(1.0, curves[name], unit, "--to")) for name, unit in conversions(to) if name in curves}


def prepared(report: Report, output: Output) -> Report:
    """The report as shown: non-finite results as None, and in the units --to asks for."""
    return apply_conversions(finite_only(report), output.to)


def _finite(x) -> bool:
    return not isinstance(x, float) or math.isfinite(x)


def finite_only(report: Report) -> Report:
    """Replace any non-finite result or table cell with None and a note, so JSON stays strict."""
    tables_finite = all(_finite(cell) for table in report.tables.values() for row in table.rows for cell in row)
    if tables_finite and all(_finite(v.value) for v in report.results.values()):
        return report
    results = dict(report.results)
    notes = list(report.notes)
    for name, value in report.results.items():
        if not _finite(value.value):
            results[name] = value._replace(value=None)
            notes.append(f"{name} has no finite value here")
    tables = dict(report.tables)
    for name, table in report.tables.items():
        rows = tuple(tuple(cell if _finite(cell) else None for cell in row) for row in table.rows)
        if rows != table.rows:
            tables[name] = replace(table, rows=rows)
            notes.append(f"the {name} table has values that are not finite here, shown as null")
    return replace(report, results=results, notes=notes, tables=tables)


def conversions(to: Sequence[str]) -> list[tuple[str, str]]:
    """The (name, unit) of each --to NAME=UNIT."""
    pairs = []
    for request in to:
        name, sep, unit = request.partition("=")
        name, unit = name.strip(), unit.strip()
        if not sep or not name or not unit:
            raise InputError("--to", "expected NAME=UNIT", example="--to omega=rpm", got=repr(request))
        pairs.append((name, unit))
    return pairs


def apply_conversions(report: Report, to: Sequence[str]) -> Report:
    """Express the results named in --to NAME=UNIT in those units."""
    if not to:
        return report
    from taucli import units

    results = dict(report.results)
    notes = list(report.notes)
    for name, unit in conversions(to):
        value = named_result(report, name, "--to")
        if value.unit is None or not isinstance(value.value, (float, int)) or isinstance(value.value, bool):
            if value.value is None:
                continue
            raise InputError("--to", f"expected a result with a unit; {name} has none", example="--to I=g*cm^2")
        converted, note = units.converted(float(value.value), value.unit, unit, "--to")
        results[name] = value._replace(value=converted, unit=unit)
        if note and note not in notes:
            notes.append(note)
    return replace(report, results=results, notes=notes)


def named_result(report: Report, name: str, option: str) -> Value:
    try:
        return report.results[name]
    except KeyError:
        raise InputError(
            option,
            f"expected the name of a result of {report.scene}: {', '.join(report.results)}",
            got=repr(name),
            hint=did_you_mean(name, report.results),
        ) from None


def _json_value(value: Value) -> dict:
    entry = {"value": value.value, "unit": value.unit}
    if value.label:
        entry["label"] = value.label
    return entry


def _json_table(table: Table) -> list[dict]:
    return [{key: cell for (key, _, _), cell in zip(table.columns, row)} for row in table.rows]


def document(report: Report, *, steps: bool = True) -> dict:
    """The JSON document of DESIGN.md: taucli, scene, model, method, inputs, results, steps, notes.

    Without ``steps`` (--no-steps) the key stays, an empty list, so the shape does not change.
    """
    doc = {
        "taucli": __version__,
        "scene": report.scene,
        "model": report.model,
        "method": report.method,
        "inputs": {name: {"value": v.value, "unit": v.unit} for name, v in report.inputs.items()},
        "results": {name: _json_value(v) for name, v in report.results.items()},
        "steps": [
            {"title": s.title, "equation": s.equation, "numbers": s.numbers, "result": s.result, "why": s.why}
            for s in (report.steps if steps else ())
        ],
        "notes": list(report.notes),
    }
    for name, table in report.tables.items():
        doc[name] = _json_table(table)
    return doc


def render(report: Report, output: Output, stream: TextIO) -> None:
    """Write the report in the format the user asked for."""
    report = prepared(report, output)
    if output.charted:
        from taucli import plot
    chart = plot.motion_chart([("", report)], chart_units(report, output.to)) if output.drawn else None
    if output.get:
        stream.write("".join(bare(named_result(report, name, "--get").value) + "\n" for name in output.get))
    elif output.json:
        doc = document(report, steps=output.steps)
        if output.charted:
            doc["plot"] = plot.plot_document(report)
        stream.write(STRICT_JSON.encode(doc) + "\n")
    else:
        render_human(report, stream, show_steps=output.steps)
        if output.plot:
            columns, colour = terminal_style(stream)
            stream.write("\n" + plot.terminal(chart, columns, colour=colour))
    if output.out is not None:
        plot.write_file(chart, output.out)
    stream.flush()


def bare(value) -> str:
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)
    return str(value)


def shown(value, digits: int = 6) -> str:
    if value is None:
        return "—"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, (int, float)):
        return fmt(float(value), digits)
    return str(value)


NARROW = 60  # columns below which results are listed rather than tabled


def render_human(report: Report, stream: TextIO, *, show_steps: bool = True) -> None:
    """The rich table of results, then the steps (equation, numbers, result, why) and notes."""
    from rich import box
    from rich.console import Console
    from rich.padding import Padding
    from rich.table import Table as RichTable
    from rich.text import Text

    plain = bool(os.environ.get("NO_COLOR")) or os.environ.get("TERM") == "dumb"
    console = Console(file=stream, highlight=False, emoji=False, color_system=None if plain else "auto")
    console.print(Text.assemble((f"{report.scene}", "bold"), f": {report.model}"))
    console.print(Text(f"method: {report.method}", style="dim"))

    if console.width < NARROW:  # a table would cut its numbers short: one result to a line instead
        for name, value in report.results.items():
            console.print(Text.assemble((name, "bold"), f" = {shown(value.value)} {pretty_unit(value.unit)}".rstrip()))
            if value.label:
                console.print(Padding(Text(value.label, style="dim"), (0, 0, 0, 2)))
    else:
        results = RichTable(box=box.SIMPLE_HEAD, pad_edge=False)
        results.add_column("result", style="bold")
        results.add_column("value", justify="right")
        results.add_column("unit")
        results.add_column("what it is", style="dim", overflow="fold")
        for name, value in report.results.items():
            results.add_row(Text(name), Text(shown(value.value)), Text(pretty_unit(value.unit)), Text(value.label))
        console.print(results)

    for name, table in report.tables.items():
        drawn = RichTable(title=name, box=box.SIMPLE_HEAD, pad_edge=False)
        for _, unit, heading in table.columns:
            drawn.add_column(f"{heading} ({pretty_unit(unit)})" if unit else heading, justify="right" if unit else "left", overflow="fold")
        for row in table.rows:
            drawn.add_row(*(Text(shown(cell, 4)) for cell in row))
        console.print(drawn)

    if show_steps and report.steps:
        console.print(Text("Steps", style="bold underline"))
        for number, step in enumerate(report.steps, start=1):
            console.print(Text.assemble((f"{number}. ", "bold"), (step.title, "bold")))
            indent = " " * 4
            console.print(Padding(Text(step.equation), (0, 0, 0, len(indent)), expand=False))
            align = len(indent) + max(step.equation.find("="), 0)
            if step.numbers:
                console.print(Padding(Text(f"= {step.numbers}"), (0, 0, 0, align), expand=False))
            if step.result and step.result != step.numbers:
                console.print(Padding(Text(f"= {step.result}"), (0, 0, 0, align), expand=False))
            if step.why:
                console.print(Padding(Text.assemble(("why: ", "italic"), step.why, style="dim"), (0, 0, 0, len(indent)), expand=False))
    for note in report.notes:
        console.print(Text.assemble(("note: ", "yellow"), note))


def attach_inputs(report: Report, inputs: Mapping[str, Value], notes: Sequence[str]) -> Report:
    """The report with the inputs as parsed and the notes from reading them."""
    return Report(
        scene=report.scene,
        model=report.model,
        method=report.method,
        results=report.results,
        steps=report.steps,
        notes=[*notes, *report.notes],
        inputs=dict(inputs),
        tables=report.tables,
        trajectory=report.trajectory,
    )
