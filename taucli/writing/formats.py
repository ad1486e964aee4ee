"""--format md, html and csv (taucli.writing.latex writes latex): an answer as text for a report, a
notebook or a spreadsheet.

Pure string building, no dependency: a run is first put in a ``Sheet`` (its model line, the
results table as shown, its tables, the steps, the notes: every number as the human view shows
it), a sweep in a ``Grid`` (a column per swept option and per result, a row per point); each
writer turns one of them into a document of its format, escaping every text it did not write
itself (a part's name, a unit typed with --to, a note). ``Report._repr_html_`` and the other
notebook views write the same documents.
"""

from __future__ import annotations

import csv
import html
import io
import re
from collections.abc import Sequence
from typing import NamedTuple

from taucli.quantities.measurement import with_uncertainty
from taucli.core.names import FORMATS as FORMATS  # --format's choices
from taucli.core.written import pretty_unit, printable, shown
from taucli.writing.display import equation_text, minus_signs

class Row(NamedTuple):
    """One result as a person is shown it: its value already written (6 digits, or with ± σ)."""

    name: str
    value: str
    unit: str | None  # as the unit parser reads it (kg*m**2), for siunitx and csv
    label: str

class Part(NamedTuple):
    """A small table of the report (the parts of a body): headings (text, unit) and the cells as shown."""

    title: str
    columns: tuple[tuple[str, str | None], ...]
    rows: tuple[tuple[str, ...], ...]

class Sheet(NamedTuple):
    """A run as every written format shows it."""

    scene: str
    model: str
    method: str
    results: tuple[Row, ...]
    tables: tuple[Part, ...]
    steps: tuple  # of report.Step (title, equation, numbers, result, why)
    notes: tuple[str, ...]

class Grid(NamedTuple):
    """A sweep: a column per swept option and per result, a row per point (values as solved)."""

    title: str  # "spin-down: --inertia 0.5..4kg*m^2 (5 values)"
    model: str
    columns: tuple[tuple[str, str | None], ...]  # (name, unit)
    rows: tuple[tuple, ...]  # floats, bools, words or None
    notes: tuple[str, ...]
    spreads: tuple[tuple, ...] = ()  # each cell's standard uncertainty (SI, as the value) or None; () where none has one (#42 item 7)

def grid_cells(grid: Grid) -> list[list[str]]:
    """Each cell as a person reads it: 4.90 ± 0.08 where it has an uncertainty (as --json keeps it)."""
    spreads = grid.spreads or [()] * len(grid.rows)
    return [[with_uncertainty(cell, sigma) if sigma is not None else shown(cell) for cell, sigma in zip(row, (*spread, *[None] * len(row))[:len(row)])]
            for row, spread in zip(grid.rows, spreads)]

def sheet(report, *, steps: bool = True) -> Sheet:
    """The report as the written formats show it (a Report, or a Measured one: values with ± σ)."""
    spreads = getattr(report, "uncertainties", None) or {}
    results = tuple(
        Row(name, with_uncertainty(v.value, spreads[name]) if name in spreads else shown(v.value), v.unit, v.label)
        for name, v in report.results.items()
        if name not in report.tables and (v.value is not None or not v.moot)  # (a result the scene cannot have, NotApplicable: its note
    )  # says why; a result shown as a table of its own, a fit's correlation, is that table alone, as the human view has it)
    tables = tuple(
        Part(title, tuple((heading, unit) for _, unit, heading in table.columns), tuple(tuple(shown(cell) for cell in row) for row in table.rows))
        for title, table in report.tables.items()
    )
    return Sheet(report.scene, report.model, report.method, results, tables, tuple(report.steps) if steps else (), tuple(report.notes))

def heading(name: str, unit: str | None) -> str:
    """A column's heading with its unit as a person reads it: "alpha0 (rad/s²)"."""
    return f"{name} ({pretty_unit(unit)})" if unit else name

def step_lines(step) -> list[str]:
    """A step's equation, then "= numbers" and "= result" under its "=", as the human view sets
    them: each one line, its control characters escaped (a newline in a file's name cannot end a
    code block, #43 item 14)."""
    equation = printable(step.equation)
    lines = [equation_text(equation)] if equation else []  # one minus, −, as the human view writes (#42)
    align = max(equation.find("="), 0)
    for line in (step.numbers, step.result if step.result != step.numbers else ""):
        if line:
            lines.append(" " * align + "= " + equation_text(printable(line)))
    return lines

def one_line(text: str) -> str:
    """A text on one line, each control character escaped (printable), runs of spaces one."""
    return " ".join(printable(str(text)).split())

# Markdown (GitHub's): every text a cell or a paragraph holds is escaped, so that no name or note
# can open a link, a table cell, an emphasis, an HTML tag, an entity or a math span.
_MD_SPECIAL = re.compile(r"([\\`*_\[\]{}<>|#~!$^])")
_MD_LINE_START = re.compile(r"^(\d+)([.)])(\s)|^([-+=])(\s|$)")

def md_text(text: str) -> str:
    text = _MD_SPECIAL.sub(r"\\\1", one_line(text).replace("&", "&amp;"))
    return _MD_LINE_START.sub(lambda m: f"{m[1]}\\{m[2]}{m[3]}" if m[1] else f"\\{m[4]}{m[5]}", text)

def _md_table(headings: Sequence[str], rows: Sequence[Sequence[str]], right: Sequence[bool]) -> list[str]:
    lines = ["| " + " | ".join(md_text(h) for h in headings) + " |", "| " + " | ".join("--:" if r else ":--" for r in right) + " |"]
    lines += ["| " + " | ".join(md_text(cell) for cell in row) + " |" for row in rows]
    return lines

def _fence(lines: Sequence[str]) -> str:
    """A code fence longer than any run of backticks in the block."""
    longest = max((len(run) for line in lines for run in re.findall(r"`+", line)), default=0)
    return "`" * max(3, longest + 1)

def markdown(sheet: Sheet) -> str:
    """The run as GitHub Markdown: the model line, the results table, tables, steps, notes."""
    out = [f"**{md_text(sheet.scene)}**: {md_text(sheet.model)}\\", f"*method: {md_text(sheet.method)}*", ""]
    out += _md_table(("result", "value", "unit", "what it is"), [(r.name, r.value, pretty_unit(r.unit), minus_signs(r.label)) for r in sheet.results], (False, True, False, False))
    for part in sheet.tables:
        out += ["", f"**{md_text(minus_signs(part.title))}**", ""]
        out += _md_table([heading(*column) for column in part.columns], part.rows, [unit is not None for _, unit in part.columns])
    if sheet.steps:
        out += ["", "### Steps", ""]
        for number, step in enumerate(sheet.steps, start=1):
            marker = f"{number}. "
            pad = " " * len(marker)
            out.append(f"{marker}**{md_text(minus_signs(step.title))}**")
            lines = step_lines(step)
            if lines:
                fence = _fence(lines)
                out += ["", pad + fence + "text", *(pad + line for line in lines), pad + fence]
            if step.why:
                out += ["", f"{pad}*why:* {md_text(step.why)}"]
            out.append("")
        out.pop()
    out += _md_notes(sheet.notes)
    return "\n".join(out) + "\n"

def _md_notes(notes: Sequence[str]) -> list[str]:
    return ["", *(f"- *note:* {md_text(note)}" for note in notes)] if notes else []

def markdown_grid(grid: Grid) -> str:
    """A sweep as GitHub Markdown: the title, the model, one row per point."""
    out = [f"**{md_text(grid.title)}**\\", f"*model: {md_text(grid.model)}*", ""]
    out += _md_table([heading(*column) for column in grid.columns], grid_cells(grid), [True] * len(grid.columns))
    return "\n".join(out + _md_notes(grid.notes)) + "\n"

# HTML: a fragment to put in a page or a notebook; every text through html.escape.
def _h(text) -> str:
    return html.escape(printable(str(text)), quote=True)

def _html_table(headings: Sequence[str], rows: Sequence[Sequence[str]], right: Sequence[bool], caption: str = "") -> list[str]:
    out = ["<table>"] + ([f"<caption>{_h(caption)}</caption>"] if caption else [])
    out.append("<thead><tr>" + "".join(f"<th>{_h(h)}</th>" for h in headings) + "</tr></thead>")
    out.append("<tbody>")
    for row in rows:
        cells = "".join(f'<td style="text-align:right">{_h(c)}</td>' if r else f"<td>{_h(c)}</td>" for c, r in zip(row, right))
        out.append(f"<tr>{cells}</tr>")
    return out + ["</tbody>", "</table>"]

def _html_notes(notes: Sequence[str]) -> list[str]:
    return ['<ul class="notes">', *(f"<li><em>note:</em> {_h(note)}</li>" for note in notes), "</ul>"] if notes else []

def html_fragment(sheet: Sheet) -> str:
    """The run as an HTML fragment: every tag closed, every text escaped."""
    out = ['<div class="taucli">', f"<p><strong>{_h(sheet.scene)}</strong>: {_h(sheet.model)}<br>", f"<em>method: {_h(sheet.method)}</em></p>"]
    out += _html_table(("result", "value", "unit", "what it is"), [(r.name, r.value, pretty_unit(r.unit), minus_signs(r.label)) for r in sheet.results], (False, True, False, False))
    for part in sheet.tables:
        out += _html_table([heading(*column) for column in part.columns], part.rows, [unit is not None for _, unit in part.columns], caption=minus_signs(part.title))
    if sheet.steps:
        out += ["<p><strong>Steps</strong></p>", "<ol>"]
        for step in sheet.steps:
            out.append(f"<li><strong>{_h(minus_signs(step.title))}</strong>")
            lines = step_lines(step)
            if lines:
                out.append("<pre>" + "\n".join(_h(line) for line in lines) + "</pre>")
            if step.why:
                out.append(f"<p><em>why:</em> {_h(step.why)}</p>")
            out.append("</li>")
        out.append("</ol>")
    return "\n".join(out + _html_notes(sheet.notes) + ["</div>"]) + "\n"

def html_grid(grid: Grid) -> str:
    out = ['<div class="taucli">', f"<p><strong>{_h(grid.title)}</strong><br>", f"<em>model: {_h(grid.model)}</em></p>"]
    out += _html_table([heading(*column) for column in grid.columns], grid_cells(grid), [True] * len(grid.columns))
    return "\n".join(out + _html_notes(grid.notes) + ["</div>"]) + "\n"

# CSV: for a spreadsheet. A header of "name (unit)", the unit as the unit parser reads it (as
# --json gives it), then one row per point at full precision (repr: the double read back exactly).
# A cell that is not a number and starts with =, +, - or @ (--find's roots, "-2.0 2.0"; a word)
# would be read by a spreadsheet as a formula (OWASP's CSV injection): it is written after a single
# quote, '-2.0 2.0, which a spreadsheet shows as text and does not keep (docs/output.md). A number,
# -2.5 or 1e-05, is written as it is.
_FORMULA_START = ("=", "+", "-", "@", "\t", "\r")
_CSV_NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def spreadsheet_text(text: str) -> str:
    """A cell's text as a spreadsheet takes it for what it is: a number as it is, any other text
    that starts as a formula would after a single quote."""
    return "'" + text if text.startswith(_FORMULA_START) and not _CSV_NUMBER.fullmatch(text) else text


def _csv_cell(value) -> str:
    if value is None:
        return ""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)
    if isinstance(value, list):
        return " ".join(_csv_cell(item) for item in value)
    return printable(str(value))

def csv_grid(grid: Grid) -> str:
    """A header, then a row per point; a column with an uncertainty anywhere is followed by its
    own, "a uncertainty (m/s**2)", at full precision as --json gives it (#42 item 7)."""
    spreads = grid.spreads or [()] * len(grid.rows)
    width = len(grid.columns)
    spreads = [(*spread, *[None] * width)[:width] for spread in spreads]
    uncertain = [any(spread[column] is not None for spread in spreads) for column in range(width)]
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    header = []
    for (name, unit), has in zip(grid.columns, uncertain):
        name, unit = printable(name), unit and printable(unit)
        header.append(f"{name} ({unit})" if unit else name)
        if has:
            header.append(f"{name} uncertainty ({unit})" if unit else f"{name} uncertainty")
    writer.writerow(map(spreadsheet_text, header))
    for row, spread in zip(grid.rows, spreads):
        cells = []
        for cell, sigma, has in zip(row, spread, uncertain):
            cells.append(_csv_cell(cell))
            if has:
                cells.append(_csv_cell(sigma))
        writer.writerow(map(spreadsheet_text, cells))
    return buffer.getvalue()

def single_grid(report) -> Grid:
    """One run as a sweep of one point: its results, one row (--format csv without a sweep)."""
    names = list(report.results)
    spreads = getattr(report, "uncertainties", None) or {}
    return Grid(f"{report.scene}", report.model, tuple((name, report.results[name].unit) for name in names),
                (tuple(report.results[name].value for name in names),), tuple(report.notes),
                (tuple(spreads.get(name) for name in names),) if spreads else ())
