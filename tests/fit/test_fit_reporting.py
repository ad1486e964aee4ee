"""How a fit is reported (#44 item 14): --format md|latex|html|csv as every scene answers, and
--residuals FILE.csv with each sample measured, fitted, its residual and σ.

The references are the physics: a coast under friction τ_f and viscous drag b,
ω(t) = (ω₀ + τ_f/b)·e^(−bt/I) − τ_f/b, evaluated with mpmath at the fitted values.
"""

from __future__ import annotations

import csv
import json
import re
import shlex
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


# --- the chart ----------------------------------------------------------------------------------

BRAILLE = set(chr(c) for c in range(0x2801, 0x2900))  # a drawn braille cell (not the blank U+2800)


def _panel(text: str, title: str) -> list[str]:
    """The canvas rows of the panel titled ``title`` in a terminal chart."""
    lines = text.splitlines()
    start = lines.index(title) + 2
    rows = []
    for line in lines[start:]:
        if line.startswith("---"):
            break
        rows.append(line.split(" | ", 1)[1] if " | " in line else "")
    return rows


def test_the_fitted_line_is_drawn_over_the_samples_in_the_terminal(tmp_path, monkeypatch):
    """300 samples along the curve: before, the markers hid the line in every cell it passed
    (a handful of braille cells drawn in the panel); now the line is the last layer, whole, and the
    samples under it are counted."""
    monkeypatch.setenv("COLUMNS", "80")
    path = tmp_path / "dense.csv"
    path.write_text(table_text("t (s),omega (rad/s)", coast_down([0.05 * i for i in range(300)], 0.002, 3), ("g", ".4f")))
    code, out, err = _run("fit", "spin-down", str(path), *FIT, "--no-steps", "--plot")
    assert code == 0, err
    panel = _panel(out, "omega: measured and fitted")
    line_cells = sum(char in BRAILLE for row in panel for char in row)
    assert line_cells >= 64, "\n".join(panel)  # the curve crosses the 64 columns of the canvas, each seen
    assert re.search(r"^• \d+ of 300 measured lie under the fitted line, drawn over them$", out, re.M), out[-600:]


def test_the_terminal_draws_the_line_last(coast, monkeypatch):
    """What plotille is asked to draw, in order: the band, the error bars, the samples, then the line."""
    import plotille

    calls = []
    for name in ("plot", "scatter"):
        original = getattr(plotille.Figure, name)
        monkeypatch.setattr(plotille.Figure, name, lambda self, *a, _name=name, _original=original, **k: (calls.append((_name, k.get("marker"))), _original(self, *a, **k))[1])
    monkeypatch.setattr(plotille.Figure, "show", lambda self, legend=False, _show=plotille.Figure.show: (calls.append(("show", None)), _show(self, legend))[1])
    code, out, err = _run("fit", "spin-down", str(coast), *FIT, "--sigma", "0.05rad/s", "--no-steps", "--plot")
    assert code == 0, err
    first = calls[:calls.index(("show", None))]
    assert first[-1] == ("plot", None) and ("scatter", "•") in first, first  # the line after the samples
    assert first.index(("scatter", "·")) < first.index(("plot", None)) < first.index(("scatter", "•"))  # band, error bars, samples
    assert sum(call == ("plot", None) for call in first) == 22 + 1  # an error bar per sample, and the line


def test_error_bars_and_the_band_of_the_curve(coast, tmp_path, monkeypatch):
    """The band is σ_f(t)² = gᵀCg with g = ∂ω/∂(τ_f, b, ω₀) of the closed form, at the fitted values;
    the error bars are the σ given. The file draws both (matplotlib: errorbar, fill_between)."""
    from taucli.fit import chart, command

    report, found = command.fit_of("spin-down", [str(coast)], {"inertia": "0.1kg*m^2"}, fit="friction,viscous,omega0", sigma="0.05rad/s")
    drawn = chart.chart(found)
    measured, fitted = drawn.panels[0].series
    assert measured.spread == (0.05,) * 22 and drawn.panels[1].series[0].spread == (0.05,) * 22
    p = [float(x) for x in found.p]
    covariance = found.covariance
    for t, sigma in list(zip(fitted.xs, fitted.spread))[::20]:
        with mpmath.workdps(30):
            g = [mpmath.diff(lambda x: _omega_mp(t, *(p[:j] + [x] + p[j + 1:])), p[j]) for j in range(3)]
            reference = float(mpmath.sqrt(sum(g[i] * covariance[i][k] * g[k] for i in range(3) for k in range(3))))
        assert sigma == pytest.approx(reference, rel=1e-4), t
    monkeypatch.setenv("COLUMNS", "80")
    out = tmp_path / "chart.svg"
    code, text, err = _run("fit", "spin-down", str(coast), *FIT, "--sigma", "0.05rad/s", "--no-steps", "--plot", "--out", str(out))
    assert code == 0 and err == f"taucli: wrote the chart to {out}\n", err
    assert "• measured ± σ  ⠤ fitted  · fitted ± 1σ (band)" in text
    svg = out.read_text()
    assert 'id="FillBetweenPolyCollection_1"' in svg and svg.count('id="LineCollection_') >= 2  # the band, and a panel's error bars each
    code, text, _ = _run("fit", "spin-down", str(coast), *FIT, "--sigma", "0.05rad/s", "--json", "--plot")
    plotted = json.loads(text)["plot"]
    assert {s["sigma"] for s in plotted["samples"]} == {0.05} and all(point["band"] > 0 for point in plotted["curve"])


def _omega_mp(t, friction, viscous, omega0):
    tau, b, w0 = mpmath.mpf(friction), mpmath.mpf(viscous), mpmath.mpf(omega0)
    return (w0 + tau / b) * mpmath.exp(-b * mpmath.mpf(t) / INERTIA) - tau / b


# --- a shape in the residuals ---------------------------------------------------------------------

def test_a_shape_in_the_residuals_suggests_a_range_that_works_as_typed(tmp_path):
    """A viscous coast fitted with friction alone (a straight line through an exponential): the
    shape warning names --range with a window of the samples' own time, in their column's unit
    (ms here), and that window, typed as shown, is a fit that runs."""
    path = tmp_path / "coast.csv"
    rows = coast_down([0.25 * i for i in range(60)], 0.02, 9, friction=0.0)
    path.write_text(table_text("t (ms),omega (rad/s)", [(1000 * t, w) for t, w in rows], (".0f", ".4f")))
    args = ("fit", "spin-down", str(path), "--inertia", "0.1 kg*m^2", "--fit", "friction,omega0")
    code, out, err = _run(*args, "--get", "friction")
    assert code == 0
    said = [line for line in err.splitlines() if line.startswith("taucli: warning: the residuals have a shape")]
    assert len(said) == 1, err
    window = re.search(r"the first half of their 0 to 14800 ms is --range (\S+?)\)*$", said[0].strip())
    assert window and window.group(1) == "t=0ms..7380ms", said[0]
    code, out, err = _run(*args, "--range", *shlex.split(window.group(1)), "--get", "samples")
    assert code == 0 and int(out) == 30, err


# --- the progress bar -----------------------------------------------------------------------------

class _Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_a_fit_shows_its_progress_bar_on_a_terminal_only_once_it_has_run_a_second(coast, monkeypatch):
    """Before: the bar flashed on every fit, a quick one too. Now a quick fit (a clock that stands
    still) shows none, and one that runs past a second (a clock that moves 0.1 s a reading) shows
    it; never where stderr is not a terminal."""
    from taucli.writing import render

    args = ["fit", "spin-down", str(coast), *FIT, "--get", "friction"]
    monkeypatch.setattr(render.time, "monotonic", lambda: 0.0)  # a fit that takes no time (this machine's may take a second)
    stderr = _Terminal()
    assert main(args, Environment(stdin=None, stdout=io.StringIO(), stderr=stderr)) == 0
    assert "solving" not in stderr.getvalue() and stderr.getvalue() == "", stderr.getvalue()[:200]
    clock = iter(0.1 * k for k in range(10**6))
    monkeypatch.setattr(render.time, "monotonic", lambda: next(clock))
    for stream, shown in ((_Terminal(), True), (io.StringIO(), False)):
        assert main(args, Environment(stdin=None, stdout=io.StringIO(), stderr=stream)) == 0
        assert ("solving" in stream.getvalue()) is shown, stream.getvalue()[:200]


def test_the_residuals_docs_fit_md_shows_are_what_its_command_writes(tmp_path, monkeypatch):
    page = (Path(__file__).parents[2] / "docs" / "fit.md").read_text(encoding="utf-8")
    command = re.search(r"^\$ (taucli fit spin-down coast\.csv .*--residuals residuals\.csv.*)$", page, re.M).group(1)
    shown = re.search(r"residuals\.csv begins.*?```csv\n(.*?)```", page, re.S).group(1)
    coast = re.search(r"^\$ cat coast\.csv\n(.*?)(?=^\$ )", page, re.S | re.M).group(1)
    monkeypatch.chdir(tmp_path)
    Path("coast.csv").write_text(coast)
    code, _, err = _run(*shlex.split(command)[1:])
    assert code == 0, err
    written = list(csv.reader(io.StringIO(Path("residuals.csv").read_text(encoding="utf-8"))))
    rows = list(csv.reader(io.StringIO(shown)))
    assert rows[0] == written[0] and len(rows) == 5
    for row, got in zip(rows[1:], written[1:]):
        assert row[:2] == got[:2] and [float(x) for x in row[2:]] == pytest.approx([float(x) for x in got[2:]], rel=1e-9, abs=1e-12)


def _small_files():
    import resource

    resource.setrlimit(resource.RLIMIT_FSIZE, (4096, 4096))  # the residuals (about 25 KB) cannot be written: EFBIG, as on a full disk


def test_residuals_that_cannot_be_written_are_refused_before_any_answer(tmp_path):
    """As --out's chart: the file first, so a full disk is a refusal, not an answer then exit 2."""
    import subprocess
    import sys

    path = tmp_path / "dense.csv"
    path.write_text(table_text("t (s),omega (rad/s)", coast_down([0.05 * i for i in range(300)], 0.01, 4), ("g", ".4f")))
    done = subprocess.run([sys.executable, "-m", "taucli", "fit", "spin-down", str(path), *FIT, "--get", "friction", "--residuals", str(tmp_path / "r.csv")],
                          capture_output=True, text=True, preexec_fn=_small_files, timeout=120)
    assert done.returncode == 2 and done.stdout == "", (done.stdout, done.stderr)
    assert done.stderr.startswith("taucli: error: --residuals: expected a file that can be written") and "File too large" in done.stderr
    assert not (tmp_path / "r.csv").exists() and [p.name for p in tmp_path.iterdir()] == ["dense.csv"]  # (no temporary left)


def test_where_the_model_is_drawn_at_the_samples_each_fitted_point_carries_its_sigma(tmp_path):
    """Atwood runs at several m1 and m2 (docs/fit.md): no one input varies alone, so no curve; each
    fitted point carries σ_f,i = √(gᵢᵀCgᵢ). With C = s²(JᵀJ)⁻¹ (no σ given) the σ_f,i² add up to
    s²·tr(J(JᵀJ)⁻¹Jᵀ) = s²·m, m the inputs fitted (the hat matrix's trace)."""
    from taucli.fit import chart, command

    page = (Path(__file__).parents[2] / "docs" / "fit.md").read_text(encoding="utf-8")
    path = tmp_path / "atwood.csv"
    path.write_text(re.search(r"^\$ cat atwood\.csv\n(.*?)(?=^\$ )", page, re.S | re.M).group(1))
    report, found = command.fit_of("atwood", [str(path)], {"distance": "98cm", "pulley_radius": "2.5cm"}, fit="pulley_inertia,axle_friction")
    fitted = chart.chart(found).panels[0].series[1]
    assert fitted.points and len(fitted.spread) == found.model.samples.count and all(s > 0 for s in fitted.spread)
    n, m = found.model.samples.count, 2
    s2 = sum(r * r for r in found.quality.residuals) / (n - m)
    assert sum(s * s for s in fitted.spread) == pytest.approx(s2 * m, rel=1e-3)


def test_residuals_never_overwrite_the_data(tmp_path, monkeypatch):
    """--residuals naming the fit's own data file (as given, or as ./name) is refused before the fit: it would overwrite the measurements."""
    import shutil
    from pathlib import Path
    monkeypatch.chdir(tmp_path)
    shutil.copy(Path(__file__).resolve().parents[2] / "docs" / "data" / "vernier-two-runs.csv", "runs.csv")
    before = Path("runs.csv").read_bytes()
    for named in ("runs.csv", "./runs.csv"):
        code, out, err = _run("fit", "spin-down", "runs.csv", "--y", "Angular Velocity (rad/s)=omega", "--inertia", "0.05 kg*m^2", "--fit", "friction,viscous,omega0",
                              "--per-run", "omega0", "--residuals", named)
        assert code == 2 and out == "" and "would overwrite the measurements" in err, (code, err)
    assert Path("runs.csv").read_bytes() == before
