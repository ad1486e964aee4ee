"""--format md|latex|html|csv (#36 items 1 and 3), checked by rendering each document.

Markdown is parsed by markdown-it-py (a test extra) and its cells, code blocks and notes must
give back the texts the run shows; HTML is parsed by the standard library's html.parser, every
tag closed in order; LaTeX is compiled with pdflatex or lualatex where one is installed (and is
otherwise skipped, naming them), and always checked for balanced braces and environments; CSV is
read back by the csv module, to the last digit of --json's numbers.
"""

from __future__ import annotations

import csv
import io
import json
import os
import re
import shlex
import shutil
import subprocess
from html.parser import HTMLParser
from pathlib import Path

import pytest
from markdown_it import MarkdownIt

from conftest import ROOT
from taucli.writing import formats
from taucli.writing import latex
from taucli.front.cli import Environment, main
from taucli.options import SCENES
from taucli.writing.report import Report, Step, Table, Value

FORMATS = ("md", "latex", "html", "csv")
TEX = next((program for program in ("pdflatex", "lualatex") if shutil.which(program)), None)
TEX_FILES = ("siunitx.sty", "amsmath.sty", "fontenc.sty", "t1enc.def")  # what the test document below loads


def tex_missing() -> list[str]:
    """What compiling the LaTeX needs and this machine lacks: the program, then each file the
    document loads that kpsewhich cannot find (pdflatex comes without siunitx in texlive-latex-base)."""
    if TEX is None:
        return ["pdflatex or lualatex"]
    found = subprocess.run(["kpsewhich", *TEX_FILES], capture_output=True, text=True) if shutil.which("kpsewhich") else None
    if found is None:
        return ["kpsewhich"]
    seen = {Path(line).name for line in found.stdout.splitlines()}
    return [name for name in TEX_FILES if name not in seen]


_TEX_MISSING = tex_missing()


def _docs_example(scene: str) -> str:
    """The first command of the scene's page that runs it alone (no pipe, no file)."""
    page = (ROOT / "docs" / f"{scene}.md").read_text(encoding="utf-8")
    for block in re.findall(r"```console\n(.*?)```", page, re.S):
        for line in block.splitlines():
            if line.startswith(f"$ taucli {scene} ") and not re.search(r"[|<>]|--(plot|json|get|batch|out|jsonl|y)\b|\.\.|,\d", line):
                return line[2:]
    raise AssertionError(f"docs/{scene}.md has no plain example")


EXAMPLES = sorted({(name, command.example) for name, command in SCENES.items()} | {(name, _docs_example(name)) for name in SCENES})
EXAMPLES += [  # a body of parts (its parts table), a result solved for with an uncertainty (values with ± σ)
    ("inertia", 'taucli inertia disc --mass 5kg --radius 0.2m --part "point mass=100g offset=20cm" --part "point mass=100g offset=20cm"'),
    ("atwood", 'taucli atwood --m1 4kg --m2 1kg --pulley-radius 0.1m --find pulley_inertia --want "a=4.0+/-0.1m/s^2"'),
]


def run(command: str) -> tuple[int, str, str]:
    """taucli in this process, as typed (the shell's quoting read by shlex)."""
    env = Environment(stdin=io.StringIO(""), stdout=io.StringIO(), stderr=io.StringIO())
    code = main(shlex.split(command)[1:], env)
    return code, env.stdout.getvalue(), env.stderr.getvalue()


def answered(command: str, *more: str) -> str:
    code, out, err = run(" ".join((command, *more)))
    assert code == 0, err
    return out


def as_json(command: str) -> dict:
    return json.loads(answered(command, "--json"))


# --- what each format gives back when read -------------------------------------------------


def md_tokens(text: str):
    return MarkdownIt("commonmark").enable("table").parse(text)


def md_inline_text(token) -> str:
    """The text an inline token shows: its text, code and entities, without the markup."""
    breaks = {"softbreak": "\n", "hardbreak": "\n"}
    return "".join(breaks.get(child.type, child.content if child.type in ("text", "code_inline", "text_special") else "") for child in token.children or ())


def md_cells(text: str) -> list[list[str]]:
    """The cells of every table row (header rows included), in order."""
    rows, row, inside = [], None, False
    for token in md_tokens(text):
        if token.type == "tr_open":
            row = []
        elif token.type in ("th_open", "td_open"):
            inside = True
        elif token.type == "inline" and inside:
            row.append(md_inline_text(token))
            inside = False
        elif token.type == "tr_close":
            rows.append(row)
    return rows


def md_code_blocks(text: str) -> list[str]:
    return [token.content for token in md_tokens(text) if token.type == "fence"]


def md_paragraphs(text: str) -> list[str]:
    return [md_inline_text(token) for token in md_tokens(text) if token.type == "inline"]


class WellFormed(HTMLParser):
    """Every tag closed, in order; the text it shows collected."""

    VOID = {"br", "hr", "img", "meta", "input", "link", "wbr"}

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.open: list[str] = []
        self.texts: list[str] = []
        self.problems: list[str] = []

    def handle_starttag(self, tag, attrs):
        if tag not in self.VOID:
            self.open.append(tag)

    def handle_endtag(self, tag):
        if not self.open or self.open[-1] != tag:
            self.problems.append(f"</{tag}> closes {self.open[-1] if self.open else 'nothing'}")
        else:
            self.open.pop()

    def handle_data(self, data):
        self.texts.append(data)


def html_checked(text: str) -> WellFormed:
    parser = WellFormed()
    parser.feed(text)
    parser.close()
    assert not parser.problems, parser.problems
    assert not parser.open, f"tags never closed: {parser.open}"
    return parser


def html_cells(text: str) -> list[list[str]]:
    class Cells(HTMLParser):
        def __init__(self):
            super().__init__(convert_charrefs=True)
            self.rows, self.cell = [], None

        def handle_starttag(self, tag, attrs):
            if tag == "tr":
                self.rows.append([])
            elif tag in ("td", "th"):
                self.cell = ""

        def handle_endtag(self, tag):
            if tag in ("td", "th"):
                self.rows[-1].append(self.cell)
                self.cell = None

        def handle_data(self, data):
            if self.cell is not None:
                self.cell += data

    parser = Cells()
    parser.feed(text)
    return parser.rows


def latex_balanced(text: str) -> None:
    """Braces balance (escaped ones aside), and every \\begin{X} has its \\end{X} in order."""
    body = "\n".join(line for line in text.splitlines() if not line.startswith("%"))
    depth = 0
    for char in re.sub(r"\\[{}%$&#_]", "", body):
        depth += {"{": 1, "}": -1}.get(char, 0)
        assert depth >= 0, "a } closes nothing"
    assert depth == 0, "a { is never closed"
    stack = []
    for kind, name in re.findall(r"\\(begin|end)\{([^}]*)\}", body):
        if kind == "begin":
            stack.append(name)
        else:
            assert stack and stack.pop() == name, f"\\end{{{name}}} out of order"
    assert not stack
    assert not re.search(r"[^\x00-\x7f\u00c0-\u00ff]", body), "a character pdflatex may not set: " + repr(re.findall(r"[^\x00-\x7f\u00c0-\u00ff]", body)[:5])


def latex_compiles(fragment: str, tmp_path) -> None:
    missing = _TEX_MISSING
    if missing:
        why = f"LaTeX cannot be compiled here: {', '.join(missing)} not found (apt-get install texlive-latex-base texlive-science)"
        if os.environ.get("CI"):
            pytest.fail(why + ": .ci/run installs them")
        pytest.skip(why)
    (tmp_path / "body.tex").write_text(fragment, encoding="utf-8")
    (tmp_path / "doc.tex").write_text(
        "\\documentclass{article}\n\\usepackage[T1]{fontenc}\n\\usepackage{amsmath}\n\\usepackage{siunitx}\n"
        "\\begin{document}\n\\input{body}\n\\end{document}\n",
        encoding="utf-8",
    )
    done = subprocess.run([TEX, "-interaction=nonstopmode", "-halt-on-error", "doc.tex"], cwd=tmp_path, capture_output=True, text=True, timeout=120)
    errors = [line for line in done.stdout.splitlines() if line.startswith("!")]
    assert done.returncode == 0, f"{TEX} failed: {errors}\n{done.stdout[-1500:]}"


# --- every scene, every format --------------------------------------------------------------


def step_lines(step: dict) -> list[str]:
    return formats.step_lines(Step(**step))


@pytest.mark.parametrize("scene, command", EXAMPLES)
def test_markdown_round_trips_through_a_markdown_parser(scene, command):
    doc = as_json(command)
    text = answered(command, "--format md")
    cells = md_cells(text)
    assert cells[0] == ["result", "value", "unit", "what it is"]
    assert [row[0] for row in cells[1 : 1 + len(doc["results"])]] == list(doc["results"])
    for row, (name, result) in zip(cells[1:], doc["results"].items()):
        assert row[3] == " ".join(result["label"].split())
    blocks = md_code_blocks(text)
    assert blocks == ["\n".join(step_lines(step)) + "\n" for step in doc["steps"] if step_lines(step)]
    shown = md_paragraphs(text)
    for note in doc["notes"]:
        assert "note: " + " ".join(note.split()) in shown
    assert shown[0].startswith(f"{doc['scene']}: {doc['model']}")


@pytest.mark.parametrize("scene, command", EXAMPLES)
def test_html_parses_with_every_tag_closed_and_shows_the_same_texts(scene, command):
    doc = as_json(command)
    text = answered(command, "--format html")
    parser = html_checked(text)
    rows = html_cells(text)
    assert rows[0] == ["result", "value", "unit", "what it is"]
    assert [row[0] for row in rows[1 : 1 + len(doc["results"])]] == list(doc["results"])
    shown = "".join(parser.texts)
    for step in doc["steps"]:
        assert "\n".join(step_lines(step)) in shown
    for note in doc["notes"]:
        assert note in shown


@pytest.mark.parametrize("scene, command", EXAMPLES)
def test_latex_compiles_with_the_steps_in_an_align(scene, command, tmp_path):
    doc = as_json(command)
    text = answered(command, "--format latex")
    latex_balanced(text)
    assert ("\\begin{align*}" in text) == bool(doc["steps"])
    assert text.count("\\intertext{") >= len(doc["steps"])
    for name in doc["results"]:
        assert f"\\texttt{{{latex.text(name)}}}" in text
    latex_compiles(text, tmp_path)


@pytest.mark.parametrize("scene, command", EXAMPLES)
def test_csv_of_one_run_is_one_row_of_every_result_at_full_precision(scene, command):
    doc = as_json(command)
    rows = list(csv.reader(io.StringIO(answered(command, "--format csv"))))
    assert len(rows) == 2
    header, cells = [], []  # a result with an uncertainty has it in the next column, as --json keeps it (#42 item 7)
    for name, r in doc["results"].items():
        header.append(f"{name} ({r['unit']})" if r["unit"] else name)
        cells.append(r["value"])
        if "uncertainty" in r:
            header.append(f"{name} uncertainty ({r['unit']})" if r["unit"] else f"{name} uncertainty")
            cells.append(r["uncertainty"])
    assert rows[0] == header
    for cell, value in zip(rows[1], cells):
        if isinstance(value, float):
            assert float(cell) == value  # every digit of the double
        elif value is None:
            assert cell == ""


def test_the_completions_offer_the_formats():
    for path, offered in (("completions/taucli.fish", "-l format -x -a 'md latex html csv'"), ("completions/_taucli", "(md latex html csv)"), ("completions/taucli.bash", '--format) COMPREPLY=($(compgen -W "md latex html csv"')):
        assert offered in (ROOT / path).read_text(encoding="utf-8"), path


def test_no_steps_leaves_the_steps_out_of_each_format():
    command = SCENES["atwood"].example + " --no-steps"
    assert "### Steps" not in answered(command, "--format md")
    assert "<ol>" not in answered(command, "--format html")
    assert "align*" not in answered(command, "--format latex")


# --- escaping -------------------------------------------------------------------------------

NASTY = "A&B <b>x</b> my_part 50% #1 $5$ \\no {x} ~y^2 | *a* [l](u) `c` 1. &amp; ω₀²"


def nasty_report() -> Report:
    """A report whose every text holds what each format must escape."""
    return Report(
        scene="inertia",
        model=NASTY,
        method="closed form",
        results={"I": Value(0.1, "kg*m**2", NASTY), "name_x": Value(NASTY, None, "a word")},
        steps=[Step(NASTY, "I = ½MR²", "½ × 5 kg × (0.2 m)²", "0.1 kg·m²", NASTY)],
        notes=[NASTY, "- 1. # not a list"],
        tables={"parts": Table((("shape", None, "part & <name>"), ("I", "kg*m**2", "I_part %")), ((NASTY, 0.1),))},
    )


def test_a_markdown_document_gives_back_every_text_unchanged():
    text = formats.markdown(formats.sheet(nasty_report()))
    cells = md_cells(text)
    assert cells[1] == ["I", "0.1", "kg·m²", NASTY]
    assert cells[2] == ["name_x", NASTY, "", "a word"]
    assert cells[3] == ["part & <name>", "I_part % (kg·m²)"]
    assert cells[4] == [NASTY, "0.1"]
    shown = md_paragraphs(text)
    assert shown[0] == f"inertia: {NASTY}\nmethod: closed form"
    assert f"note: {NASTY}" in shown and "note: - 1. # not a list" in shown
    assert NASTY in shown  # the step's title
    assert f"why: {NASTY}" in shown
    assert [t.type for t in md_tokens(text) if t.type.startswith(("html", "heading", "link"))] == ["heading_open", "heading_close"]


def test_an_html_fragment_escapes_every_text():
    text = formats.html_fragment(formats.sheet(nasty_report()))
    parser = html_checked(text)
    rows = html_cells(text)
    assert rows[1] == ["I", "0.1", "kg·m²", NASTY]
    assert rows[4] == [NASTY, "0.1"]
    assert "<b>" not in text and NASTY in "".join(parser.texts)


def test_a_latex_document_escapes_every_text_and_compiles(tmp_path):
    text = latex.document(formats.sheet(nasty_report()))
    latex_balanced(text)
    latex_compiles(text, tmp_path)


def test_user_text_in_a_unit_of_to_is_escaped_in_every_format(tmp_path):
    command = "taucli inertia disc --mass 5kg --radius 0.2m --to 'I=g*cm^2'"
    assert md_cells(answered(command, "--format md"))[1][:3] == ["I", "1000000", "g·cm²"]
    html_checked(answered(command, "--format html"))
    text = answered(command, "--format latex")
    assert "\\unit{g.cm^{2}}" in text
    latex_compiles(text, tmp_path)


@pytest.mark.parametrize(
    "equation, expected",
    [
        ("θ = ω₀²/(2|α|)", "{\\theta} = {\\omega}_{0}^{2}/(2|{\\alpha}|)"),
        ("τ_rms = √(τ_a² t_a)", "{\\tau}_{\\mathrm{rms}} = \\sqrt{{\\tau}_{a}^{2} t_{a}}"),
        ("ω(t) = ω_ss(1 − e^(−t/τ_m))", "{\\omega}(t) = {\\omega}_{\\mathrm{ss}}(1 - e^{(-t/{\\tau}_{m})})"),
        ("a = g sin θ", "a = g \\sin  {\\theta}"),
        ("lost 799.6 J (100%)", "\\text{lost}\\ 799.6 J (100\\%)"),  # the space after a word kept: "lost 799.6", not "lost799.6"
        # #43 item 15: a name of two underscores is a name, not a subscript of a subscript ("Double subscript")
        ("rim_mu_min(m2) = 0.2", "\\text{rim\\_mu\\_min}(m2) = 0.2"),
        ("L = Σ Iᵢω_sᵢ sᵢ", "L = {\\Sigma} I_{i}{\\omega}_{s,i} s_{i}"),  # gyro's --rotor: ω_s of rotor i
        ("x₀²^2", "x_{0}^{2}{}^{2}"),
        ("the root of f(m) − 0.2 in [1, 2] kg", "\\text{the root of}\\ f(m) - 0.2\\ \\text{in}\\ [1, 2] kg"),
    ],
)
def test_unicode_math_becomes_latex_math(equation, expected):
    assert latex.math(equation) == expected


def test_a_numbers_line_sets_each_quantity_with_siunitx():
    assert latex.quantities("½ × 5 kg × (0.2 m)²") == "\\tfrac{1}{2} \\times  \\qty{5}{kg} \\times  (\\qty{0.2}{m})^{2}"
    assert latex.quantities("(−1.5 rad/s²) × 20 s") == "(\\qty{-1.5}{rad/s^{2}}) \\times  \\qty{20}{s}"
    assert latex.quantities("8e37 kg·m² × 7.29e-5 rad/s") == "\\qty{8e37}{kg.m^{2}} \\times  \\qty{7.29e-5}{rad/s}"
    assert latex.quantities("2 mass") == "2\\ \\text{mass}"  # a word is no unit
    assert latex.quantities("0.2 in [100, 177.828] kg") == "0.2\\ \\text{in}\\ [100, 177.828] kg"  # "in" after a number is the word (#43 item 15)
    assert latex.quantities("5 lbf·in") == "\\qty{5}{lbf.in}"  # an inch with another unit stays one


# --- sweeps -------------------------------------------------------------------------------

SWEEP = "taucli spin-down --inertia '0.5..2kg*m^2' --torque '3N*m,6N*m' --points 4"


def test_a_sweep_as_csv_has_a_header_with_units_and_a_row_per_point():
    code, out, err = run(SWEEP + " --format csv")
    assert code == 0
    rows = list(csv.reader(io.StringIO(out)))
    assert rows[0][:4] == ["torque (N*m)", "inertia (kg*m^2)", "I (kg*m**2)", "alpha0 (rad/s**2)"]
    assert len(rows) == 1 + 2 * 4
    for row in rows[1:]:
        torque, inertia, _, alpha0 = map(float, row[:4])
        assert alpha0 == pytest.approx(torque / inertia, rel=1e-15, abs=0)  # α = τ/I, each point
    assert [float(row[1]) for row in rows[1:5]] == [0.5, 1.0, 1.5, 2.0]
    assert "taucli: note:" in err  # the notes, which a spreadsheet's rows do not hold, beside them


def test_a_sweeps_csv_holds_the_numbers_get_prints():
    gets = [line.split("\t") for line in answered(SWEEP, "--get alpha0").splitlines()]
    rows = list(csv.reader(io.StringIO(answered(SWEEP, "--format csv"))))[1:]
    assert [float(row[3]) for row in rows] == [float(get[2]) for get in gets]


@pytest.mark.parametrize("fmt", ["md", "html", "latex"])
def test_a_sweep_in_each_format_is_one_table_with_a_row_per_point(fmt, tmp_path):
    text = answered(SWEEP, f"--format {fmt}")
    if fmt == "md":
        cells = md_cells(text)
        assert cells[0][:4] == ["torque (N·m)", "inertia (kg·m²)", "I (kg·m²)", "alpha0 (rad/s²)"]
        assert len(cells) == 1 + 8 and cells[1][3] == "6" and cells[8][3] == "3"
    elif fmt == "html":
        html_checked(text)
        assert len(html_cells(text)) == 1 + 8
    else:
        latex_balanced(text)
        assert text.count("\\\\\n") >= 9
        latex_compiles(text, tmp_path)


# --- what --format refuses -------------------------------------------------------------------


@pytest.mark.parametrize(
    "more, fragment",
    [
        ("--format pdf", "--format: expected one of md, latex, html, csv"),
        ("--format md --json", "--json does not combine with --format"),
        ("--format md --get a", "--get does not combine with --format"),
        ("--format html --plot", "--plot does not combine with --format"),
        ("--format md --batch", "--format does not combine with --batch"),
    ],
)
def test_format_mistakes_exit_2_with_one_line(more, fragment):
    code, out, err = run(SCENES["atwood"].example + " " + more)
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and fragment in err, err


# --- the textbook problem of docs/output.md ----------------------------------------------------


def test_halliday_sample_problem_10_08_in_markdown():
    """Halliday, Resnick and Walker, Fundamentals of Physics (10th ed.), Sample Problem 10.08: a
    1.2 kg block hangs from a cord wound on a 2.5 kg uniform disc of radius 20 cm (g = 9.8 m/s²).
    The book prints a = −4.8 m/s² (upward positive), T = 6.0 N, α = −24 rad/s²."""
    cells = md_cells(answered("taucli atwood --m1 1.2kg --pulley-mass 2.5kg --pulley-radius 20cm --g 9.8", "--format md"))
    values = {row[0]: (float(row[1]), row[2]) for row in cells[1:] if row[0] in ("a", "T1", "alpha")}
    assert values == {"a": (4.8, "m/s²"), "T1": (6.0, "N"), "alpha": (24.0, "rad/s²")}
