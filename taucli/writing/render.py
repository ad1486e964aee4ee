"""Which writer answers a run: the human view (taucli.writing.human), --json
(taucli.writing.document), --get, and --format (md, latex, html, csv: written by
taucli.writing.formats and taucli.writing.latex); --to converts units first.

JSON, --get and --format print nothing on stdout but the answer. rich is imported by the human view only.
"""

from __future__ import annotations

import re
import math
import shutil
import time
from contextlib import contextmanager
from collections.abc import Mapping, Sequence
from dataclasses import replace
from typing import NamedTuple, TextIO

from taucli.quantities import units
from taucli.core.errors import InputError, did_you_mean
from taucli.core.names import FORMATS
from taucli.core.written import printable
from taucli.writing.document import document_text
from taucli.writing.human import clamped, coloured, render_human
from taucli.writing.report import Report, Value


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


def chosen_format(chosen: str | None, others: Mapping[str, bool]) -> str | None:
    """--format (#36), as every command takes it (a scene, a sweep, a fit): one of md, latex,
    html, csv, alone among the ways to answer (``others``: which of json, get, plot… were given)."""
    if chosen is None:
        return None
    if chosen not in FORMATS:
        raise InputError("format", f"expected one of {', '.join(FORMATS)}", example="{format} md", got=repr(chosen), hint=did_you_mean(chosen, FORMATS))
    for name, given in others.items():
        if given:
            raise InputError(name, "does not combine with {format}: each writes the whole answer", example="{format} " + chosen)
    return chosen


def terminal_style(stream: TextIO) -> tuple[int, bool]:
    """(columns, colour) for a chart drawn on ``stream``: colour as the tables have it
    (human.coloured: a terminal or FORCE_COLOR, never NO_COLOR or TERM=dumb)."""
    columns = shutil.get_terminal_size((80, 24)).columns  # in a pipe, 80: the width tables are drawn at
    return clamped(columns), coloured(stream)


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


def render(report: Report, output: Output, stream: TextIO, notes_to: TextIO | None = None) -> None:
    """Write the report in the format the user asked for. A result --get prints as null has its
    reason (the notes that name it, else every note) written to ``notes_to``."""
    report = prepared(report, output)
    if output.charted:
        from taucli.writing import plot  # deferred: charts (2 ms, and plotille or matplotlib when drawn), only for --plot or --out
    chart = None
    if output.drawn:
        chart = report.chart() if report.chart is not None else plot.motion_chart([("", report)], chart_units(report, output.to))
    if output.out is not None:  # the file first: one that cannot be written (a full disk) is refused before any answer
        plot.write_file(chart, output.out, said_to=notes_to)
    if output.get:
        for name in output.get:
            if name in report.needs:  # a result this run could not give for want of an option (#42 item 14): refused, naming it
                option, expected = report.needs[name]
                raise InputError(option, expected, example=_NEEDED_EXAMPLES.get(option))
        if output.uncertainty:  # #22: a second column, the result's standard uncertainty
            spreads = getattr(report, "uncertainties", None) or {}
            stream.write("".join(bare(named_result(report, name, "--get").value) + " " + get_spread(report, name, spreads) + "\n" for name in output.get))
        else:
            stream.write("".join(bare(named_result(report, name, "--get").value) + "\n" for name in output.get))
        if notes_to is not None:
            _about_the_inputs(report, notes_to, _why_null(report, output.get, notes_to))
    elif output.json:
        stream.write(document_text(report, steps=output.steps, plot=plot.plot_document(report) if output.charted else None) + "\n")
    elif output.format:
        stream.write(written(report, output.format, steps=output.steps))
        if output.format == "csv" and notes_to is not None:  # a spreadsheet's rows hold no notes: said beside them
            stream.flush()
            notes_to.write(said_notes(report.notes))
    else:
        render_human(report, stream, show_steps=output.steps)
        if output.plot:
            columns, colour = terminal_style(stream)
            stream.write("\n" + plot.terminal(chart, columns, colour=colour))
    stream.flush()


_NEEDED_EXAMPLES = {"mass": "{mass} 5kg", "fluctuation": "{fluctuation} 0.02", "inertia": "{inertia} '150kg*m^2'", "band": '{band} "mu=0.25 wrap=270deg radius=0.3m tension=500N"'}


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


def _why_null(report: Report, names, stream: TextIO) -> list[str]:
    """For each result --get printed as null, the notes that say why: those that name it, else all
    (the notes said)."""
    missing = [name for name in dict.fromkeys(names) if report.results[name].value is None]
    said: list[str] = []
    for name in missing:
        naming = [note for note in report.notes if re.search(rf"(?<![\w.]){re.escape(name)}(?![\w])", note)]
        said += [note for note in (naming or report.notes) if note not in said]
        if not naming and not report.notes:
            said.append(f"{name}: no value with these inputs")
    if said:
        stream.write(said_notes(said))
    return said


def _about_the_inputs(report: Report, stream: TextIO, said: list[str]) -> None:
    """Beside --get's bare numbers, the notes that speak of an option the run was given (one that
    plays no part, or that looks wrong): a script reading the number alone must hear of them too,
    as the human view says them. (Notes _why_null wrote already are not said twice.)"""
    flags = tuple(f"--{name.replace('_', '-')}" for name in report.inputs)
    loud = [note for note in report.notes if note not in said and (
        note.startswith(MONTE_CARLO)  # --mc asked for it: its check is said, as the human view says it
        or _names_a_flag(note, flags) and not note.startswith("no --") and "to change it" not in note)]  # (not a default's note: nothing given there)
    if loud:
        stream.write(said_notes(loud))


MONTE_CARLO = "Monte Carlo check"  # how taucli.answering.propagate's note of --mc begins


def _names_a_flag(note: str, flags: tuple[str, ...]) -> bool:
    return any(re.search(rf"(?<![\w-]){re.escape(flag)}(?![\w-])", note) for flag in flags)


def said_notes(notes: Sequence[str]) -> str:
    """Notes as stderr says them beside a machine's answer: "taucli: note: ..." a line each, every
    control character escaped (taucli.core.written.printable), as an error's line is."""
    return "".join(f"taucli: note: {' '.join(printable(note).split())}\n" for note in notes)


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


@contextmanager
def progress_bar(stderr: TextIO, wanted: bool, *, after: float = 0.0):
    """A progress bar on ``stderr`` for --find, --mc and a fit, where stderr is a terminal (else
    None): told (done, planned) solves as they go, shown once the work has taken ``after`` seconds
    (a fit's bar: over a second; one that ends sooner does not flash one), and gone when the work is."""
    if not wanted or not getattr(stderr, "isatty", lambda: False)():
        yield None
        return
    started = time.monotonic()
    shown: list = []  # the bar and its task, once shown

    def told(done: int, planned: int) -> None:
        if not shown:
            if time.monotonic() - started < after:
                return
            from rich.console import Console  # deferred: rich, only for a bar on a terminal
            from rich.progress import Progress

            bar = Progress(console=Console(file=stderr), transient=True)
            bar.start()
            shown.extend((bar, bar.add_task("solving", total=None)))
        shown[0].update(shown[1], completed=done, total=planned)

    try:
        yield told
    finally:
        if shown:
            shown[0].stop()
