"""How a fit is reported (#44 item 14): --format md|latex|html|csv as every scene answers, and
--residuals FILE.csv with each sample measured, fitted, its residual and σ.

The references are the physics: a coast under friction τ_f and viscous drag b,
ω(t) = (ω₀ + τ_f/b)·e^(−bt/I) − τ_f/b, evaluated with mpmath at the fitted values.
"""

from __future__ import annotations

import csv
import importlib.util
import io
from pathlib import Path

import mpmath
import pytest

from conftest import assert_usage_error, run_taucli
from fit_synthetic import coast_down, csv as table_text
from taucli.front.cli import Environment, main

INERTIA = 0.1
FIT = ("--inertia", "0.1 kg*m^2", "--fit", "friction,viscous,omega0")


def _formats_tests():
    """tests/writing/test_formats.py's checks (HTML well formed, LaTeX compiled), loaded by path."""
    spec = importlib.util.spec_from_file_location("formats_checks", Path(__file__).parents[1] / "writing" / "test_formats.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture
def coast(tmp_path):
    path = tmp_path / "coast.csv"
    path.write_text(table_text("t (s),omega (rad/s)", coast_down([0.75 * i for i in range(22)], 0.05, 5), ("g", ".4f")))
    return path


def _run(*args: str) -> tuple[int, str, str]:
    stdout, stderr = io.StringIO(), io.StringIO()
    code = main(list(args), Environment(stdin=None, stdout=stdout, stderr=stderr))
    return code, stdout.getvalue(), stderr.getvalue()


def _fitted(path) -> dict[str, float]:
    code, out, err = _run("fit", "spin-down", str(path), *FIT, "--get", "friction", "--get", "viscous", "--get", "omega0")
    assert code == 0, err
    return dict(zip(("friction", "viscous", "omega0"), map(float, out.split())))


def _omega(t: float, friction: float, viscous: float, omega0: float) -> float:
    """The coast's closed form, at 30 digits."""
    with mpmath.workdps(30):
        tau, b, w0 = mpmath.mpf(friction), mpmath.mpf(viscous), mpmath.mpf(omega0)
        return float((w0 + tau / b) * mpmath.exp(-b * mpmath.mpf(t) / INERTIA) - tau / b)


# --- --format ---------------------------------------------------------------------------------

def test_format_md_html_latex_are_documents_of_the_fit(coast, tmp_path):
    """Before: exit 2, "--format is an option of taucli spin-down's own runs, not of fit"."""
    checks = _formats_tests()
    got = _fitted(coast)
    friction = f"{got['friction']:.4f}"[:5]  # 0.060… as each document shows it, ± its σ
    pages = {}
    for fmt in ("md", "html", "latex"):
        code, out, err = _run("fit", "spin-down", str(coast), *FIT, "--format", fmt)
        assert code == 0 and err == "", err
        assert friction in out and "omega0" in out and "residual" in out, out[:400]
        pages[fmt] = out
    md = pages["md"].splitlines()
    assert "| result | value | unit | what it is |" in md
    assert any(line.startswith("| friction | 0.06") and " ± " in line for line in md), md
    assert "**correlation**" in md and not any(line.startswith("| correlation |") for line in md)  # a table of its own, once
    assert "### Steps" in md and "- *note:* no uncertainty given for the samples" in "\n".join(md)
    parsed = checks.html_checked(pages["html"])
    assert any("friction" in text for text in parsed.texts)
    assert "\\begin{tabular}" in pages["latex"] and "uncertainty-mode=separate" in pages["latex"]
    checks.latex_compiles(pages["latex"], tmp_path)


def test_format_csv_is_one_row_of_the_results_and_the_notes_on_stderr(coast):
    code, out, err = _run("fit", "spin-down", str(coast), *FIT, "--format", "csv")
    assert code == 0
    header, row = list(csv.reader(io.StringIO(out)))
    cells = dict(zip(header, row))
    got = _fitted(coast)
    assert float(cells["friction (N*m)"]) == pytest.approx(got["friction"], rel=1e-14) and float(cells["friction uncertainty (N*m)"]) > 0
    assert float(cells["omega0 (rad/s)"]) == pytest.approx(got["omega0"], rel=1e-14) and int(cells["samples"]) == 22
    assert err.startswith("taucli: note: no uncertainty given for the samples"), err


def test_format_refuses_what_it_does_not_combine_with_as_a_scene_does(coast):
    for other in (("--json",), ("--get", "friction"), ("--plot",)):
        done = run_taucli("fit", "spin-down", str(coast), *FIT, "--format", "md", *other)
        assert_usage_error(done, f"{other[0]} does not combine with --format")
    assert_usage_error(run_taucli("fit", "spin-down", str(coast), *FIT, "--format", "markdown"), "--format: expected one of md, latex, html, csv")


# --- --residuals --------------------------------------------------------------------------------

def test_residuals_are_the_samples_measured_fitted_residual_and_sigma(coast, tmp_path):
    """Before: exit 2, --residuals was not an option."""
    out = tmp_path / "r.csv"
    code, stdout, err = _run("fit", "spin-down", str(coast), *FIT, "--sigma", "0.05rad/s", "--residuals", str(out), "--get", "friction")
    assert code == 0 and err == f"taucli: wrote the residuals to {out}\n", err
    rows = list(csv.DictReader(io.StringIO(out.read_text(encoding="utf-8"))))
    assert list(rows[0]) == ["file", "line", "time (s)", "omega measured (rad/s)", "omega fitted (rad/s)", "residual (rad/s)", "sigma (rad/s)"]
    given = [line.split(",") for line in coast.read_text().splitlines()[1:]]
    assert len(rows) == len(given) == 22
    got = _fitted(coast)  # (with --sigma one value for all: the same best fit)
    for number, (row, (t, omega)) in enumerate(zip(rows, given)):
        assert row["file"] == str(coast) and int(row["line"]) == number + 2
        assert float(row["time (s)"]) == float(t) and float(row["omega measured (rad/s)"]) == float(omega)
        fitted = float(row["omega fitted (rad/s)"])
        assert fitted == pytest.approx(_omega(float(t), **got), rel=1e-9, abs=1e-9)
        assert float(row["residual (rad/s)"]) == float(omega) - fitted  # at full precision: exactly
        assert float(row["sigma (rad/s)"]) == 0.05


def test_residuals_leave_sigma_empty_where_none_was_given_and_quote_a_name_a_spreadsheet_would_run(tmp_path, monkeypatch):
    """A file named =cmd.csv: its name in the file column after a quote ('=cmd.csv), as text."""
    monkeypatch.chdir(tmp_path)
    Path("=cmd.csv").write_text(table_text("t (s),omega (rad/s)", coast_down([0.75 * i for i in range(22)], 0.05, 6), ("g", ".4f")))
    code, _, err = _run("fit", "spin-down", "=cmd.csv", *FIT, "--residuals", "r.csv", "--get", "r2")
    assert code == 0, err
    rows = list(csv.reader(io.StringIO(Path("r.csv").read_text(encoding="utf-8"))))[1:]
    assert len(rows) == 22 and {row[0] for row in rows} == {"'=cmd.csv"} and {row[-1] for row in rows} == {""}


def test_a_residuals_file_that_cannot_be_written_is_refused_before_the_fit(coast, tmp_path):
    for path, said in ((tmp_path / "nowhere" / "r.csv", "--residuals: expected a file that can be written"),
                       (tmp_path / "r.txt", "--residuals: expected a file name ending in .csv"),
                       (tmp_path, "--residuals: expected a file name ending in .csv")):
        assert_usage_error(run_taucli("fit", "spin-down", str(coast), *FIT, "--residuals", str(path)), said)
    link = tmp_path / "link.csv"
    link.symlink_to(tmp_path / "elsewhere.csv")
    assert_usage_error(run_taucli("fit", "spin-down", str(coast), *FIT, "--residuals", str(link)), "not a symbolic link")
    assert not (tmp_path / "elsewhere.csv").exists()
