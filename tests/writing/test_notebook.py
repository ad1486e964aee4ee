"""A Report in Python and Jupyter (#36 item 2): a short repr, the documents of --format md, html
and latex as its notebook views, help() from the scene's table, and a missing result that says
which keyword makes it."""

from __future__ import annotations

import io
import pydoc
import shlex

import pytest

import taucli
from taucli.front.cli import Environment, main
from taucli.options import SCENES
from taucli.options.table import CHOICE, FLAG


def cli(command: str) -> str:
    env = Environment(stdin=io.StringIO(""), stdout=io.StringIO(), stderr=io.StringIO())
    assert main(shlex.split(command)[1:], env) == 0, env.stderr.getvalue()
    return env.stdout.getvalue()


ATWOOD = dict(m1="4 kg", m2="1 kg", pulley_mass="2 kg", pulley_radius="0.1 m")
ATWOOD_CLI = "taucli atwood --m1 4kg --m2 1kg --pulley-mass 2kg --pulley-radius 0.1m"


def test_a_report_repr_is_one_short_line_with_the_model_and_headline_results():
    shown = repr(taucli.atwood(**ATWOOD))
    assert shown == "<Report atwood: massive pulley (solid disc), string does not slip; a = 4.90332 m/s², T1 = 19.6133 N, T2 = 14.71 N, … (2 more)>"
    assert "\n" not in shown


def test_a_measured_report_repr_shows_each_value_with_its_uncertainty():
    shown = repr(taucli.atwood(m1="4.0+/-0.1 kg", m2="1 kg", pulley_mass="2 kg"))
    # a = (m1 − m2)g/S with S = m1 + m2 + M/2 = 6 kg: ∂a/∂m1 = g(S − (m1 − m2))/S² = g/12, σ_a = 0.1 g/12 = 0.082
    assert shown.startswith("<Measured atwood: ") and "a = 4.90 ± 0.08 m/s²" in shown


@pytest.mark.parametrize("view, fmt", [("_repr_markdown_", "md"), ("_repr_html_", "html"), ("_repr_latex_", "latex")])
def test_the_notebook_views_are_the_documents_of_format(view, fmt):
    """Jupyter shows the table and steps: the same document --format writes for the same run, but
    for its notes, which name options as Python does (pulley_shape, not --pulley-shape: #42 item 19)."""
    written = cli(f"{ATWOOD_CLI} --format {fmt}")
    shown = getattr(taucli.atwood(**ATWOOD), view)()
    apart = lambda text: [line for line in text.splitlines() if "note:" not in line]  # noqa: E731
    assert apart(shown) == apart(written)
    notes = [line for line in shown.splitlines() if "note:" in line]
    assert len(notes) == len([line for line in written.splitlines() if "note:" in line]) >= 2
    assert any("pulley_shape" in line or "pulley\\_shape" in line for line in notes) and not any("--" in line or "-{}-" in line for line in notes)


@pytest.mark.parametrize("name", sorted(SCENES))
def test_help_lists_every_keyword_with_its_kind_unit_default_and_help(name):
    command = SCENES[name]
    text = pydoc.render_doc(getattr(taucli, command.function_name), renderer=pydoc.plaintext)
    assert command.summary.split("\n")[0] in text
    for option in command.options:
        line = next((line for line in text.splitlines() if line.strip().startswith(f"{option.name} (")), None)
        assert line is not None, f"{option.name} is not listed"
        if option.kind == FLAG:
            assert "True or False" in line
        elif option.kind == CHOICE:
            assert "one of " + ", ".join(option.choices) in line
        if option.default:
            assert f"default {option.default}" in line
        first_words = " ".join(option.help.split()[:4])
        assert first_words in " ".join(text.split()), f"{option.name}'s help is not shown"


def test_help_gives_a_quantity_keywords_si_unit():
    text = taucli.spin_down.__doc__
    assert "    omega0 (angular velocity, a number in rad/s; default 0)" in text
    assert "    friction (torque, a number in N*m)" in text
    assert "    energy (True or False; makes KE0, KE, " in text


def test_a_missing_result_says_which_keyword_makes_it():
    report = taucli.spin_down(shape="disc", mass=5, radius="20 cm", omega0="30 rad/s", friction="0.3 N*m")
    with pytest.raises(taucli.MissingResult) as raised:
        report.results["KE0"]
    assert str(raised.value) == "KE0 is not among this run's results: energy=True turns it on (--energy on the command line)"
    assert isinstance(raised.value, KeyError)
    assert "KE0" not in report.results and report.results.get("KE0") is None  # a dict as before
    made = taucli.spin_down(shape="disc", mass=5, radius="20 cm", omega0="30 rad/s", friction="0.3 N*m", energy=True)
    assert made.results["KE0"].value == pytest.approx(0.5 * 0.1 * 30**2, rel=1e-15)  # ½Iω₀², I = ½MR² = 0.1 kg·m²


def test_a_result_no_keyword_turns_on_is_named_with_the_runs_results():
    report = taucli.atwood(**ATWOOD)
    with pytest.raises(KeyError, match=r"^v is not among this run's results: it needs distance= or time= \(--distance or --time on the command line\)$"):
        report.results["v"]
    with pytest.raises(KeyError, match=r"^acceleration is not a result of atwood; this run's results: a, "):
        report.results["acceleration"]


def test_the_notebook_example_of_docs_python_md_is_what_python_shows():
    from conftest import ROOT

    page = (ROOT / "docs" / "python.md").read_text(encoding="utf-8")
    shown = next(line for line in page.splitlines() if line.startswith("<Report spin-down"))
    report = taucli.spin_down(shape="disc", mass=5, radius="20 cm", omega0="30 rad/s", friction="0.3 N*m")
    assert repr(report) == shown
    assert "KE0 is not among this run's results: energy=True turns it on (--energy on the command line)" in page
    for line in ("    omega0 (angular velocity, a number in rad/s; default 0)", "    friction (torque, a number in N*m)"):
        assert line in page and line in taucli.spin_down.__doc__
