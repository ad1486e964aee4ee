"""Renderers: the human view (rich table and steps), --json, --get and --format (md, latex, html,
csv: written by taucli.writing.formats and taucli.writing.latex); --to converts units.

JSON, --get and --format print nothing on stdout but the answer. rich is imported by the human view only.
"""

from __future__ import annotations

import io
import json
import re
import math
import os
import shutil
from collections.abc import Mapping, Sequence
from contextlib import contextmanager
from dataclasses import replace
from typing import NamedTuple, TextIO

from taucli.quantities import units
from taucli.core.version import __version__
from taucli.core.errors import InputError, did_you_mean
from taucli.writing.display import equation_text, minus_signs, wrap_expression
from taucli.quantities.measurement import with_uncertainty
from taucli.core.written import DIGITS, shown as written_shown
from taucli.writing.report import Report, Table, Value, pretty_unit


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
    uncertainty: bool = False  # --get: each result's standard uncertainty in a second column (#22)
    format: str | None = None  # --format md|latex|html|csv (#36): a document of that format

    @property
    def charted(self) -> bool:
        return self.plot or self.out is not None

    @property
    def drawn(self) -> bool:
        """A chart is drawn: in the terminal, or to a file. (--json --plot gives the samples only.)"""
        return self.out is not None or (self.plot and not self.json)


# The widths charts and tables are drawn at, whatever COLUMNS or the terminal says: COLUMNS=100000
# took 5 s and 434 MB for one chart, and 10**7 was killed for memory.
WIDTHS = (20, 400)


def clamped(columns: int) -> int:
    """``columns`` within WIDTHS."""
    return min(max(columns, WIDTHS[0]), WIDTHS[1])


def terminal_style(stream: TextIO) -> tuple[int, bool]:
    """(columns, colour) for text drawn on ``stream``: no colour under NO_COLOR, TERM=dumb or a pipe."""
    columns = shutil.get_terminal_size((80, 24)).columns  # in a pipe, 80: the width tables are drawn at
    colour = stream.isatty() and not os.environ.get("NO_COLOR") and os.environ.get("TERM") != "dumb"
    return clamped(columns), colour


def chart_units(report: Report, to: Sequence[str]) -> dict[str, tuple[str, float]]:
    """For each curve of the report's motion named in --to: (unit, SI value of one of it)."""
    curves = {key: unit for key, unit, _ in report.trajectory().curves} if report.trajectory else {}
    return {name: (unit, 1.0 / units.convert(1.0, curves[name], unit, "--to")) for name, unit in conversions(to) if name in curves}


def prepared(report: Report, output: Output) -> Report:
    """The report as shown: non-finite results as None, and in the units --to asks for."""
    return apply_conversions(finite_only(report), output.to)


def _finite(x) -> bool:
    return not isinstance(x, float) or math.isfinite(x)


def finite_only(report: Report) -> Report:
    """Replace any non-finite result or table cell with None and a note, so JSON stays strict."""
    for v in report.results.values():  # a loop, not all(...): this runs on every batch line
        x = v.value
        if x.__class__ is float and x - x != 0:  # (x − x is 0 for a finite float, NaN otherwise)
            break
    else:
        if not report.tables or all(_finite(cell) for table in report.tables.values() for row in table.rows for cell in row):
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
    results = dict(report.results)
    notes = list(report.notes)
    for name, unit in conversions(to):
        value = named_result(report, name, "--to")
        if value.unit is None or not isinstance(value.value, (float, int)) or isinstance(value.value, bool):
            if value.value is None:
                continue
            raise InputError("--to", f"expected a result with a unit; {name} has none", example="--to 'I=g*cm^2'")
        converted, note = units.converted(float(value.value), value.unit, unit, "--to")[:2]
        results[name] = value._replace(value=converted, unit=unit)
        spreads = getattr(report, "uncertainties", None)
        if spreads and name in spreads:  # #22: the uncertainty in the same unit (units scale, none is offset)
            report = replace(report, uncertainties={**spreads, name: abs(units.convert(spreads[name], value.unit, unit, "--to"))})
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
        "steps": document_steps(report.steps) if steps else [],
        "notes": list(report.notes),
    }
    for name, table in report.tables.items():
        if name not in report.results:  # a result that is also a table (fit's correlation): its value in JSON, the table to a person
            doc[name] = _json_table(table)
    if getattr(report, "uncertainties", None) is not None:
        _json_uncertain(doc, report)
    return doc


_ENCODED: dict[object, str] = {}  # a text, or a result's (name, unit, label), -> its JSON, as written before
_ENCODE_TEXT = json.encoder.encode_basestring  # a str's JSON as STRICT_JSON writes it (not ASCII-only)


def _text(text: str | None) -> str:
    found = _ENCODED.get(text)
    if found is None:
        found = "null" if text is None else _ENCODE_TEXT(text)
        if len(_ENCODED) < 4096:  # texts repeat (units, labels, notes); numbers in notes make some new each time
            _ENCODED[text] = found
    return found


def _number(value) -> str:
    """A value's JSON as STRICT_JSON writes it: float repr, null, true/false; NaN and ±inf refused."""
    kind = value.__class__
    if kind is float:
        if value != value or value in (math.inf, -math.inf):
            raise ValueError(f"{value!r} is not a number strict JSON allows")
        return float.__repr__(value)
    if value is None:
        return "null"
    if kind is bool:
        return "true" if value else "false"
    return STRICT_JSON.encode(value)


def _entry(key: tuple[str, str | None, str]) -> tuple[str, str]:
    """The JSON around a value: '"name":{"value":' and ',"unit":…,"label":…}' (after the uncertainty)."""
    name, unit, label = key
    found = (_text(name) + ':{"value":', ',"unit":' + _text(unit) + (',"label":' + _text(label) if label else "") + "}")
    if len(_ENCODED) < 4096:
        _ENCODED[key] = found
    return found


def _values(values: Mapping[str, Value], labelled: bool, spreads: Mapping[str, float]) -> str:
    parts = []
    for name, v in values.items():
        value = v.value
        # a finite float (x − x is 0 only then) written at once: most values of most documents
        number = float.__repr__(value) if value.__class__ is float and value - value == 0.0 else _number(value)
        if spreads and name in spreads:
            number += ',"uncertainty":' + _number(spreads[name])
        key = (name, v.unit, v.label if labelled else "")
        ends = _ENCODED.get(key) or _entry(key)
        parts.append(ends[0] + number + ends[1])
    return "{" + ",".join(parts) + "}"


def document_text(report: Report, *, steps: bool = True, plot: dict | None = None) -> str:
    """``document(report)`` as strict, compact JSON: the text STRICT_JSON.encode gives for it,
    written from the JSON of each unit, label and note as first written (a batch writes the
    same texts on every line; only the numbers change). ``plot`` is added under "plot"."""
    uncertain = getattr(report, "uncertainties", None) is not None
    parts = [
        '{"taucli":', _text(__version__), ',"scene":', _text(report.scene), ',"model":', _text(report.model),
        ',"method":', _text(report.method),
        ',"inputs":', _values(report.inputs, False, report.input_uncertainties if uncertain else {}),
        ',"results":', _values(report.results, True, report.uncertainties if uncertain else {}),
        ',"steps":', STRICT_JSON.encode(document_steps(report.steps)) if steps and report.steps else "[]",
        ',"notes":[', ",".join(map(_text, report.notes)), "]",
    ]  # fmt: skip
    for name, table in report.tables.items():
        if name not in report.results:  # (as in document)
            parts += [",", _text(name), ":", STRICT_JSON.encode(_json_table(table))]
    if uncertain and report.draws:
        parts += [',"monte_carlo":', STRICT_JSON.encode(_monte_carlo(report))]
    if plot is not None:
        parts += [',"plot":', STRICT_JSON.encode(plot)]
    parts.append("}")
    return "".join(parts)


def _json_uncertain(doc: dict, report) -> None:
    """#22: "uncertainty" beside "value" in each result (and input) that has one; --mc's check."""
    for part, spreads in (("results", report.uncertainties), ("inputs", report.input_uncertainties)):
        for name, entry in doc[part].items():
            if name in spreads:
                doc[part][name] = {"value": entry["value"], "uncertainty": spreads[name], **entry}
    if report.draws:
        doc["monte_carlo"] = _monte_carlo(report)


def _monte_carlo(report) -> dict:
    return {"draws": report.draws, "results": {name: {"mean": mean, "uncertainty": spread} for name, (mean, spread) in report.monte_carlo.items()}}


def document_steps(steps) -> list[dict]:
    return [{"title": s.title, "equation": s.equation, "numbers": s.numbers, "result": s.result, "why": s.why} for s in steps]


def render(report: Report, output: Output, stream: TextIO, notes_to: TextIO | None = None) -> None:
    """Write the report in the format the user asked for. A result --get prints as null has its
    reason (the notes that name it, else every note) written to ``notes_to``."""
    report = prepared(report, output)
    if output.charted:
        from taucli.writing import plot  # deferred: charts (2 ms, and plotille or matplotlib when drawn), only for --plot or --out
    chart = plot.motion_chart([("", report)], chart_units(report, output.to)) if output.drawn else None
    if output.out is not None:  # the file first: one that cannot be written (a full disk) is refused before any answer
        plot.write_file(chart, output.out, said_to=notes_to)
    if output.get:
        if output.uncertainty:  # #22: a second column, the result's standard uncertainty
            spreads = getattr(report, "uncertainties", None) or {}
            stream.write("".join(bare(named_result(report, name, "--get").value) + " " + get_spread(report, name, spreads) + "\n" for name in output.get))
        else:
            stream.write("".join(bare(named_result(report, name, "--get").value) + "\n" for name in output.get))
        if notes_to is not None:
            _why_null(report, output.get, notes_to)
    elif output.json:
        stream.write(document_text(report, steps=output.steps, plot=plot.plot_document(report) if output.charted else None) + "\n")
    elif output.format:
        stream.write(written(report, output.format, steps=output.steps))
        if output.format == "csv" and notes_to is not None:  # a spreadsheet's rows hold no notes: said beside them
            stream.flush()
            notes_to.write("".join(f"taucli: note: {' '.join(note.split())}\n" for note in report.notes))
    else:
        render_human(report, stream, show_steps=output.steps)
        if output.plot:
            columns, colour = terminal_style(stream)
            stream.write("\n" + plot.terminal(chart, columns, colour=colour))
    stream.flush()


def written(report: Report, format: str, *, steps: bool = True) -> str:
    """--format md|latex|html|csv (#36): the run as a Markdown, LaTeX or HTML document, or a CSV
    of one row (a header of its results with their units)."""
    from taucli.writing import formats  # deferred: the writers of documents (5 ms), only for --format

    if format == "csv":
        return formats.csv_grid(formats.single_grid(report))
    if format == "latex":
        from taucli.writing import latex  # deferred: LaTeX's tables of symbols, only for --format latex

        return latex.document(formats.sheet(report, steps=steps))
    return {"md": formats.markdown, "html": formats.html_fragment}[format](formats.sheet(report, steps=steps))


def _why_null(report: Report, names, stream: TextIO) -> None:
    """For each result --get printed as null, the notes that say why: those that name it, else all."""
    missing = [name for name in dict.fromkeys(names) if report.results[name].value is None]
    said: list[str] = []
    for name in missing:
        naming = [note for note in report.notes if re.search(rf"(?<![\w.]){re.escape(name)}(?![\w])", note)]
        said += [note for note in (naming or report.notes) if note not in said]
        if not naming and not report.notes:
            said.append(f"{name}: no value with these inputs")
    if said:
        stream.write("".join(f"taucli: note: {' '.join(note.split())}\n" for note in said))


def get_spread(report: Report, name: str, spreads: Mapping[str, float]) -> str:
    """A result's uncertainty for --get --uncertainty: 0.0 for a number no uncertain input moves."""
    if name in spreads:
        return bare(spreads[name])
    value = report.results[name].value
    return "0" if isinstance(value, (int, float)) and not isinstance(value, bool) else "null"


GET_DIGITS = 15  # --get: the digits a double holds for sure; --json keeps the repr, every digit


def bare(value) -> str:
    """A value as --get prints it, for a person and a script alike: at most 15 significant digits
    (``10``, not ``10.000000000000002``: the last digits of a double are rounding), no trailing
    ``.0``; ``null``, ``true``, ``false``. ``--json`` keeps every digit (the repr round-trips)."""
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return format(value, f".{GET_DIGITS}g")
    return str(value)


def shown(value, digits: int = DIGITS) -> str:
    """A value as the human view shows it (the tables, the sweep's table): as taucli.core.written
    writes it for every format, with one minus sign, − (taucli.writing.display). md, LaTeX and HTML keep
    written's ASCII."""
    return minus_signs(written_shown(value, digits))


NARROW = 60  # columns below which results are listed rather than tabled
LABEL_MIN = 12  # the least width a folding text column ("what it is") is given before a table gives way to a list


@contextmanager
def drawing(stream: TextIO):
    """A rich Console that draws for ``stream``: in colour on a terminal (or with FORCE_COLOR);
    elsewhere (a file, a pipe) plain, into a buffer whose lines are written without the trailing
    spaces rich pads them with."""
    from rich.console import Console  # deferred: rich (about 30 ms), only for the human view

    plain = bool(os.environ.get("NO_COLOR")) or os.environ.get("TERM") == "dumb"
    # rich takes a dumb terminal to be 80 columns; it has a width as any other (help uses it too)
    width = shutil.get_terminal_size((80, 24)).columns if os.environ.get("TERM") == "dumb" and stream.isatty() else None
    console = Console(file=stream, highlight=False, emoji=False, color_system=None if plain else "auto", width=width)
    if console.width != clamped(console.width):
        console.width = clamped(console.width)
    if console.is_terminal:  # a terminal, or FORCE_COLOR
        yield console
        return
    buffer = io.StringIO()
    yield Console(file=buffer, width=console.width, highlight=False, emoji=False, color_system=None)
    stream.write("\n".join(line.rstrip() for line in buffer.getvalue().split("\n")))


def draw_table(console, headings: Sequence[str], rows: Sequence[Sequence[str]], *, title: str | None = None,
               folding: Sequence[bool] | None = None, right: Sequence[bool] | None = None, bold_first: bool = False) -> None:
    """A table whose numbers are never split: a column of numbers keeps each cell whole (and its
    heading wraps to it); where even so the table is wider than the terminal, each row is listed
    instead, one "heading = value" to a line."""
    from rich import box  # deferred: rich, as in drawing()
    from rich.measure import Measurement
    from rich.padding import Padding
    from rich.table import Table as RichTable
    from rich.text import Text

    folding = folding or [False] * len(headings)
    right = right or [index > 0 for index in range(len(headings))]
    cells = [max((len(row[i]) for row in rows), default=0) for i in range(len(headings))]

    def table_of(shown_headings: Sequence[str]):
        least = [max(LABEL_MIN if fold else width, *(len(line) for line in heading.split("\n"))) for heading, width, fold in zip(shown_headings, cells, folding)]
        table = RichTable(title=title, box=box.SIMPLE_HEAD, pad_edge=False)
        for index, (heading, fold) in enumerate(zip(shown_headings, folding)):
            style = "bold" if bold_first and index == 0 else ("dim" if fold else None)
            if fold:
                table.add_column(heading, style=style, overflow="fold", justify="right" if right[index] else "left")
            else:
                table.add_column(heading, style=style, justify="right" if right[index] else "left", no_wrap=True, min_width=least[index])
        for row in rows:
            table.add_row(*(Text(cell) for cell in row))
        return table

    # As it is; else each unit under its name; else, too wide even so, a list
    stacked = [heading.replace(" (", "\n(", 1) if not fold else heading for heading, fold in zip(headings, folding)]
    for shown_headings in (headings, stacked):
        table = table_of(shown_headings)
        if Measurement.get(console, console.options.update(max_width=10**4), table).minimum <= console.width:
            console.print(table)
            return
    if title:
        console.print(Text(title, style="bold"))
    for row in rows:
        console.print(Text.assemble((f"{headings[0]} {row[0]}", "bold" if bold_first else "")))
        for heading, cell in zip(headings[1:], row[1:]):
            if cell:
                console.print(Padding(Text(f"{heading} = {cell}"), (0, 0, 0, 2)))


def render_human(report: Report, stream: TextIO, *, show_steps: bool = True) -> None:
    """The rich table of results, then the steps (equation, numbers, result, why) and notes."""
    with drawing(stream) as console:
        _draw_report(report, console, show_steps)


def _draw_report(report: Report, console, show_steps: bool) -> None:
    from rich.padding import Padding  # deferred: rich, as in drawing()
    from rich.text import Text

    console.print(Text.assemble((f"{report.scene}", "bold"), f": {minus_signs(report.model)}"))
    console.print(Text(f"method: {report.method}", style="dim"))

    rows = [(name, shown(value.value), pretty_unit(value.unit), value.label) for name, value in report.results.items() if name not in report.tables]
    spreads = getattr(report, "uncertainties", None)
    if spreads:  # #22: 4.90 ± 0.08, digits matched to the uncertainty
        rows = [(name, minus_signs(with_uncertainty(report.results[name].value, spreads[name])) if name in spreads else value, unit, label) for name, value, unit, label in rows]
    widths = [max((len(row[i]) for row in rows), default=0) for i in range(3)]
    if console.width < NARROW or sum(widths) + LABEL_MIN + 6 > console.width:  # one result to a line, numbers whole
        for name, value, unit, label in rows:
            console.print(Text.assemble((name, "bold"), f" = {value} {unit}".rstrip()))
            if label:
                console.print(Padding(Text(label, style="dim"), (0, 0, 0, 2)))
    else:
        worded = any(isinstance(value.value, str) for value in report.results.values())  # words may fold, numbers not
        draw_table(console, ("result", "value", "unit", "what it is"), rows, folding=(False, worded, False, True), right=(False, True, False, False), bold_first=True)

    for name, table in report.tables.items():
        headings = [f"{heading} ({pretty_unit(unit)})" if unit else heading for _, unit, heading in table.columns]
        right = [unit is not None for _, unit, _ in table.columns]
        draw_table(console, headings, [[shown(cell) for cell in row] for row in table.rows], title=name, right=right)

    if show_steps and report.steps:
        console.print(Text("Steps", style="bold underline"))
        for number, step in enumerate(report.steps, start=1):
            console.print(Text.assemble((f"{number}. ", "bold"), (minus_signs(step.title), "bold")))
            indent = 4
            equation = equation_text(step.equation)
            _expression(console, equation, indent)
            align = indent + max(equation.find("="), 0)
            if align + 20 > console.width:  # a long left-hand side: the numbers under its start
                align = indent + 2
            if step.numbers:
                _expression(console, f"= {equation_text(step.numbers)}", align)
            if step.result and step.result != step.numbers:
                _expression(console, f"= {equation_text(step.result)}", align)
            if step.why:
                console.print(Padding(Text.assemble(("why: ", "italic"), minus_signs(step.why), style="dim"), (0, 0, 0, indent), expand=False))
    for note in report.notes:
        console.print(Text.assemble(("note: ", "yellow"), minus_signs(note)))


def _expression(console, text: str, indent: int) -> None:
    """An equation's line at ``indent``, broken between its terms where it does not fit (taucli.writing.display)."""
    from rich.text import Text  # deferred: rich, as in drawing()

    for line in wrap_expression(text, console.width, indent):
        console.print(Text(line), soft_wrap=True)


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
