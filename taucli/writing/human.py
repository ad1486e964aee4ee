"""The human view: the rich table of results, then the worked steps and the notes, at any width
(numbers never split: a table too wide for the terminal becomes a list). rich is imported here
alone, and only when a view is drawn.
"""

from __future__ import annotations

import io
import os
import shutil
from collections.abc import Sequence
from contextlib import contextmanager
from typing import TextIO

from dataclasses import replace

from taucli.core.written import DIGITS, printable, shown as written_shown
from taucli.quantities.measurement import with_uncertainty
from taucli.writing.display import equation_text, minus_signs, wrap_expression
from taucli.writing.report import Report, Step, Table, pretty_unit

# The widths charts and tables are drawn at, whatever COLUMNS or the terminal says: COLUMNS=100000
# took 5 s and 434 MB for one chart, and 10**7 was killed for memory.
WIDTHS = (20, 400)


def clamped(columns: int) -> int:
    """``columns`` within WIDTHS."""
    return min(max(columns, WIDTHS[0]), WIDTHS[1])


def shown(value, digits: int = DIGITS) -> str:
    """A value as the human view shows it (the tables, the sweep's table): as taucli.core.written
    writes it for every format, with one minus sign, − (taucli.writing.display). md, LaTeX and HTML keep
    written's ASCII."""
    return minus_signs(written_shown(value, digits))


NARROW = 60  # columns below which results are listed rather than tabled
LABEL_MIN = 12  # the least width a folding text column ("what it is") is given before a table gives way to a list


def plain() -> bool:
    """No colour whatever the stream: NO_COLOR set (no-color.org), or TERM=dumb."""
    return bool(os.environ.get("NO_COLOR")) or os.environ.get("TERM") == "dumb"


def coloured(stream: TextIO) -> bool:
    """Whether the human view (its tables, steps and --plot's chart) is drawn in colour on
    ``stream``: on a terminal, or where FORCE_COLOR is set and not empty (force-color.org: a CI
    log or ``less -R`` that shows colour from a pipe); never under NO_COLOR or TERM=dumb
    (docs/running.md). Only the human view: --json, --get, --format and --batch never hold an
    escape code, whatever the environment says."""
    return not plain() and (stream.isatty() or bool(os.environ.get("FORCE_COLOR")))


@contextmanager
def drawing(stream: TextIO):
    """A rich Console that draws for ``stream``: in colour where ``coloured`` says so; elsewhere
    (a file, a pipe) plain, into a buffer whose lines are written without the trailing spaces
    rich pads them with. rich's own reading of the environment (TTY_COMPATIBLE, FORCE_COLOR) is
    not asked: ``coloured`` is the one rule."""
    from rich.console import Console  # deferred: rich (about 30 ms), only for the human view

    # rich takes a dumb terminal to be 80 columns; it has a width as any other (help uses it too)
    width = shutil.get_terminal_size((80, 24)).columns if os.environ.get("TERM") == "dumb" and stream.isatty() else None
    console = Console(file=stream, highlight=False, emoji=False, color_system=None if plain() else "auto", width=width,
                      force_terminal=coloured(stream) or stream.isatty())  # fmt: skip
    if console.width != clamped(console.width):
        console.width = clamped(console.width)
    if console.is_terminal:  # a terminal, or FORCE_COLOR (where not plain)
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
        _draw_report(printable_report(report, show_steps), console, show_steps)


def printable_report(report: Report, steps: bool = True) -> Report:
    """The report with every text in it printable (taucli.core.written.printable): a file's name
    in a fit's steps, a part's name, a note that quotes what was typed, shown with its control
    characters escaped (\\x1b, \\n), never sent to the terminal raw (#43 item 14)."""

    def p(text):
        return printable(text) if isinstance(text, str) else text

    return replace(
        report, scene=p(report.scene), model=p(report.model), method=p(report.method), notes=[p(note) for note in report.notes],
        results={p(name): v._replace(value=p(v.value), unit=p(v.unit), label=p(v.label)) for name, v in report.results.items()},  # its class kept (NotApplicable)
        steps=[Step(*map(p, (s.title, s.equation, s.numbers, s.result, s.why))) for s in report.steps] if steps else report.steps,
        tables={p(name): Table(tuple((key, p(unit), p(heading)) for key, unit, heading in table.columns), tuple(tuple(map(p, row)) for row in table.rows))
                for name, table in report.tables.items()},
    )  # fmt: skip


def _draw_report(report: Report, console, show_steps: bool) -> None:
    from rich.padding import Padding  # deferred: rich, as in drawing()
    from rich.text import Text

    console.print(Text.assemble((f"{report.scene}", "bold"), f": {minus_signs(report.model)}"))
    console.print(Text(f"method: {report.method}", style="dim"))

    rows = [(name, shown(value.value), pretty_unit(value.unit), value.label) for name, value in report.results.items()
            if name not in report.tables and (value.value is not None or not value.moot)]  # (a result the scene cannot have: its note says why)
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
