"""--format latex compiles, with pdflatex and the real siunitx (#43 item 15): the LaTeX of every
example of README and docs/, and of results named as a user or a scene may name them.

All the examples go into one document, a section each, compiled once (a compile of each alone
took about 0.5 s, 80 s in all); where it fails, the document is halved until each failing example
is named with TeX's error. Like the other compile tests (test_formats.latex_compiles), these are
skipped where pdflatex or siunitx is missing, and fail under CI, which installs them.
"""

from __future__ import annotations

import os
import subprocess

import pytest
from hypothesis import given, settings, strategies as st

from pages import examples_as
from test_formats import TEX, _TEX_MISSING
from taucli.writing import formats, latex
from taucli.writing.report import Report, Step, Table, Value

PREAMBLE = "\\documentclass{article}\n\\usepackage[T1]{fontenc}\n\\usepackage{amsmath}\n\\usepackage{siunitx}\n\\begin{document}\n"


def _needs_tex() -> None:
    if _TEX_MISSING:
        why = f"LaTeX cannot be compiled here: {', '.join(_TEX_MISSING)} not found (apt-get install texlive-latex-base texlive-science)"
        if os.environ.get("CI"):
            pytest.fail(why + ": .ci/run installs them")
        pytest.skip(why)


def _errors(folder, sections: list[tuple[str, str]]) -> list[str] | None:
    """TeX's error lines for one document of these (title, fragment) sections, or None when it compiles."""
    body = "".join(f"\\section*{{{latex.text(title)}}}\n{fragment}\n" for title, fragment in sections)
    (folder / "all.tex").write_text(PREAMBLE + body + "\\end{document}\n", encoding="utf-8")
    done = subprocess.run([TEX, "-draftmode", "-interaction=nonstopmode", "-halt-on-error", "all.tex"], cwd=folder,
                          capture_output=True, text=True, timeout=600)  # fmt: skip
    if done.returncode == 0:
        return None
    return [line for line in done.stdout.splitlines() if line.startswith(("!", "l."))][:4] or [done.stdout[-800:]]


def failing(folder, sections: list[tuple[str, str]]) -> list[tuple[str, list[str]]]:
    """Each section whose LaTeX does not compile, with TeX's error: the whole document first, then
    halves of a failing one, down to single sections."""
    errors = _errors(folder, sections)
    if errors is None:
        return []
    if len(sections) == 1:
        return [(sections[0][0], errors)]
    half = len(sections) // 2
    return failing(folder, sections[:half]) + failing(folder, sections[half:])


def test_every_docs_example_compiles_as_latex(tmp_path, monkeypatch):
    """Each `$ taucli SCENE ...` of README and docs/ that answers (an error shown on its page
    aside), asked for as --format latex, compiles; before #43, 3 of them did not ("Double
    subscript" in rim_mu_min and in gyro's --rotor steps)."""
    _needs_tex()
    work = tmp_path / "work"
    work.mkdir()
    monkeypatch.chdir(work)  # (put back after the test)
    sections, refused = [], []
    for command, printed, code, out, err in examples_as("latex", work):
        if code == 0:
            sections.append((command, out))
        elif not printed.lstrip().startswith("taucli: error:"):  # (fit's too, since #44 item 14)
            refused.append((command, err.strip()))
    assert not refused, f"examples that answer on their page and refuse --format latex: {refused}"
    assert len(sections) >= 150, len(sections)
    bad = failing(tmp_path, sections)
    assert not bad, "\n".join(f"{command}\n    {' / '.join(errors)}" for command, errors in bad)


# --- names as a user or a scene writes them ---------------------------------------------------

GREEK = "αβγδθλμπρστφωΔΘΣΩ"
NAME = st.text(st.sampled_from("abcxyzIMT_0123456789" + GREEK + "₀₁₂ᵢ²³"), min_size=1, max_size=14)


def named_report(names: list[str]) -> Report:
    """A report whose results, labels, steps, table and notes are named ``names``."""
    results = {name: Value(0.25 * (i + 1), "kg*m**2", f"{name} of part_{i}") for i, name in enumerate(names)}
    steps = [Step(f"The {name}", f"{name} = {names[0]}_rms + ω_{name}", f"{name} = 0.2 in [1, 2] kg", f"{i} kg·m²", f"from {name}") for i, name in enumerate(names)]
    table = Table(tuple((f"k{i}", "kg*m**2", name) for i, name in enumerate(names)), ((*(0.5 for _ in names),),))
    return Report(scene="inertia", model=" + ".join(names), method="closed form", results=results, steps=steps,
                  notes=[f"note on {name}" for name in names], tables={"parts": table})  # fmt: skip


@settings(max_examples=8, deadline=None)
@given(st.lists(NAME, min_size=1, max_size=12, unique=True))
def test_names_with_underscores_digits_and_greek_letters_compile(tmp_path_factory, names):
    """Result names and labels of underscores, digits, Greek letters and sub- and superscripts,
    in every place the writer puts a name (the results table, a step's equation, numbers and
    why, a table's heading, a note), compile."""
    _needs_tex()
    folder = tmp_path_factory.mktemp("names")
    fragment = latex.document(formats.sheet(named_report(names)))
    errors = _errors(folder, [("names", fragment)])
    assert errors is None, (names, errors)


def test_names_that_broke_the_document_compile(tmp_path):
    """Names as the scenes write them that broke a document before #43 (a subscript of a
    subscript: rim_mu_min, ω_sᵢ), and their kin."""
    _needs_tex()
    names = ["rim_mu_min", "rms_to_rated", "a_b_c_d", "ω_sᵢ", "x₀²³", "T_1_2", "_x_", "I__a", "τ_rms_2", "Iᵢω_sᵢ"]
    assert not failing(tmp_path, [(name, latex.document(formats.sheet(named_report([name, "I"])))) for name in names])
