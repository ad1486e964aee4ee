"""A name a user gives (a data file's, an --out or --torque-profile path, an option, a column,
anything an error echoes) cannot drive the terminal or leave its place (#43 item 14).

Every command and path that shows a user's name is run with a hostile one: ESC[31m, OSC 8 (a
link) and OSC 52 (a clipboard write) sequences, a C1 CSI, a newline, a carriage return, a bidi
override, an HTML tag with onerror and LaTeX's \\end{align*}. No control character may reach
stdout or stderr (a line's own newline aside), an error stays one line, and a Markdown, HTML or
LaTeX document keeps the name inside its cell, code block or math (no HTML tag, no raw line,
a document that compiles).
"""

from __future__ import annotations

import io
import json
import re

import pytest

import taucli
import taucli.fit
from fit_synthetic import coast_down, csv
from test_formats import html_checked, latex_balanced, md_code_blocks, md_tokens
from test_latex_compiles import _needs_tex, failing
from taucli.front.cli import Environment, main
from taucli.writing import formats, latex
from taucli.writing.human import render_human
from taucli.writing.report import Report, Step, Table, Value

HOSTILE = "a\x1b[31mred\x1b]8;;mailto:x@x.example\x1b\\link\x1b]8;;\x1b\\ \x1b]52;c;aGk=\x07\x9b2J\nnext\rover\u202e<img src=x onerror=alert(1)>\\end{align*}"
# A control character on a line of output: every C0 but the newline that ends the line, DEL, C1,
# the line and paragraph separators, the bidi overrides and isolates.
CONTROL = re.compile("[\x00-\x09\x0b-\x1f\x7f-\x9f\u2028\u2029\u202a-\u202e\u2066-\u2069]")
COAST = csv("t (s),omega (rad/s)", coast_down([1.5 * i for i in range(12)], 0.05, 11), ("g", ".3f"))
FIT = ["fit", "spin-down", "{file}", "--inertia", "0.1 kg*m^2", "--fit", "friction,viscous,omega0"]
RUN = ["spin-down", "--inertia", "0.1kg*m^2", "--omega0", "30rad/s", "--friction", "0.2N*m"]


def clean(text: str, where: str) -> None:
    found = CONTROL.search(text)
    assert found is None, f"{where}: {found.group()!r} at {found.start()}: {text[max(found.start() - 40, 0):found.start() + 40]!r}"


def run(words: list[str], stdin: str = "") -> tuple[int, str, str]:
    env = Environment(stdin=io.StringIO(stdin), stdout=io.StringIO(), stderr=io.StringIO())
    code = main(words, env)
    return code, env.stdout.getvalue(), env.stderr.getvalue()


@pytest.fixture
def folder(tmp_path, monkeypatch):
    """A folder holding a data file, a torque profile and a bad table, each under the hostile name."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / f"{HOSTILE}.csv").write_text(COAST, encoding="utf-8")
    (tmp_path / f"bad{HOSTILE}.csv").write_text("t (s),omega (rad/s)\n1,x\n", encoding="utf-8")
    header = HOSTILE.replace("\n", "").replace("\r", "")  # a column's name (one line of the file): tabs separate the columns
    rows = [line.replace(",", "\t") + "\t1" for line in COAST.splitlines()[1:]]
    (tmp_path / f"extra{HOSTILE}.csv").write_text("\n".join([f"t (s)\tomega (rad/s)\t{header}", *rows]) + "\n", encoding="utf-8")
    (tmp_path / f"profile{HOSTILE}.csv").write_text("t [s], torque [N*m]\n0, 1\n1, x\n", encoding="utf-8")
    return tmp_path


def fit_words(file: str, *more: str) -> list[str]:
    return [word.replace("{file}", file) for word in FIT] + list(more)


# Each way a name reaches what taucli prints: (what it is, argv, stdin)
ANSWERS = [
    ("fit's steps name the file", fit_words(f"{HOSTILE}.csv"), ""),
    ("fit's JSON", fit_words(f"{HOSTILE}.csv", "--json"), ""),
    ("fit's unused column, in a note", fit_words(f"extra{HOSTILE}.csv"), ""),
    ("--out's path, said on stderr", [*RUN, "--out", f"{HOSTILE}.svg"], ""),
]
ERRORS = [
    ("a data file with a bad row", fit_words(f"bad{HOSTILE}.csv")),
    ("a data file that is not there", fit_words(f"missing{HOSTILE}.csv")),
    ("fit's --x naming no column", fit_words(f"{HOSTILE}.csv", "--x", HOSTILE)),
    ("--out in a folder that is not there", [*RUN, "--out", f"no/{HOSTILE}.svg"]),
    ("--torque-profile not there", ["impulse", "--inertia", "2kg*m^2", "--omega0", "0", "--torque-profile", f"missing{HOSTILE}.csv"]),
    ("--torque-profile with a bad row", ["impulse", "--inertia", "2kg*m^2", "--omega0", "0", "--torque-profile", f"profile{HOSTILE}.csv"]),
    ("a value", ["atwood", "--m1", HOSTILE, "--m2", "1kg"]),
    ("an option that is not one", ["atwood", "--m1", "4kg", f"--{HOSTILE}"]),
    ("a command that is not one", [HOSTILE]),
    ("help on a command that is not one", ["help", HOSTILE]),
    ("--get's name", [*RUN, "--get", HOSTILE]),
    ("--to's name", [*RUN, "--to", f"{HOSTILE}=rpm"]),
    ("--to's unit", [*RUN, "--to", f"t_stop={HOSTILE}"]),
    ("--format's name", [*RUN, "--format", HOSTILE]),
    ("a part's shape", ["inertia", "disc", "--mass", "1kg", "--radius", "1m", "--part", f"{HOSTILE} mass=1kg"]),
    ("a part's key", ["inertia", "disc", "--mass", "1kg", "--radius", "1m", "--part", f"point {HOSTILE}=1kg"]),
    ("--find's name", ["atwood", "--m1", "4kg", "--m2", "1kg", "--find", HOSTILE, "--want", "a=1m/s^2"]),
]


@pytest.mark.parametrize("what, words, stdin", ANSWERS, ids=[case[0] for case in ANSWERS])
def test_an_answer_shows_a_hostile_name_escaped(what, words, stdin, folder):
    code, out, err = run(words, stdin)
    assert code == 0, err
    clean(out, "stdout")
    clean(err, "stderr")
    if "--json" in words:
        assert "\\x1b[31mred" in json.dumps(json.loads(out)["steps"]) or "x1b" in out  # the name, escaped as a message quotes it


@pytest.mark.parametrize("what, words", ERRORS, ids=[case[0] for case in ERRORS])
def test_an_error_quotes_a_hostile_name_on_one_line(what, words, folder):
    code, out, err = run(words)
    assert code == 2 and out == "", (code, out, err)
    assert err.count("\n") == 1 and err.startswith("taucli: error: "), err
    clean(err, "stderr")


def test_a_batch_line_with_a_hostile_path_gets_an_error_object_of_one_line(folder):
    line = json.dumps({"inertia": "2kg*m^2", "omega0": "0", "torque_profile": f"missing{HOSTILE}.csv"})
    code, out, err = run(["impulse", "--batch"], stdin=line + "\n")
    assert code == 2
    clean(out, "stdout")
    clean(err, "stderr")
    message = json.loads(out)["error"]["message"]
    clean(message, "the error object's message")
    assert "\\x1b[31mred" in message and "\n" not in message


# --- the documents, from the Python API (a notebook's views) and every writer --------------------


def hostile_report() -> Report:
    """A report whose every text holds the hostile name."""
    return Report(
        scene="inertia", model=HOSTILE, method=HOSTILE,
        results={"I": Value(0.1, "kg*m**2", HOSTILE), "word": Value(HOSTILE, None, "a word")},
        steps=[Step(HOSTILE, f"n = {HOSTILE}", f"{HOSTILE} = 5 kg", HOSTILE, HOSTILE)],
        notes=[HOSTILE], tables={HOSTILE: Table((("k", None, HOSTILE), ("I", "kg*m**2", "I")), ((HOSTILE, 0.1),))},
    )  # fmt: skip


def reports(folder) -> list[Report]:
    return [hostile_report(), taucli.fit.fit("spin-down", f"{HOSTILE}.csv", fit="friction,viscous,omega0", inertia="0.1 kg*m^2")]


def test_a_reports_views_keep_a_hostile_name_in_its_block(folder):
    documents = []
    for report in reports(folder):
        for name, text in (("repr", repr(report)), ("md", report._repr_markdown_()), ("html", report._repr_html_()), ("latex", report._repr_latex_())):
            clean(text.replace("\n", " "), name)
            assert "\x1b" not in text and "\r" not in text
        assert "\n" not in repr(report)
        # Markdown: no HTML of any kind, every step's lines in its code block, one line each as written
        md = report._repr_markdown_()
        assert not [token.type for token in md_tokens(md) if token.type.startswith("html")], md
        blocks = md_code_blocks(md)
        assert len(blocks) == len([step for step in report.steps if step.equation])
        assert any("\\x1b[31mred" in block for block in blocks)
        # HTML: every tag closed, no <img> but as text
        html = report._repr_html_()
        html_checked(html)
        assert "<img" not in html and "&lt;img" in html
        latex_balanced(report._repr_latex_())
        documents.append((f"report {len(documents)}", report._repr_latex_()))
    _needs_tex()
    assert not failing(folder, documents)


def test_every_writer_escapes_a_hostile_name(folder):
    report = hostile_report()
    human = io.StringIO()
    render_human(report, human)
    sheet = formats.sheet(report)
    grid = formats.single_grid(report)
    texts = {"human": human.getvalue(), "md": formats.markdown(sheet), "html": formats.html_fragment(sheet), "latex": latex.document(sheet),
             "csv": formats.csv_grid(grid), "md sweep": formats.markdown_grid(grid), "html sweep": formats.html_grid(grid), "latex sweep": latex.grid(grid)}  # fmt: skip
    for name, text in texts.items():
        clean(text, name)
    assert "\\x1b[31mred" in texts["human"]
