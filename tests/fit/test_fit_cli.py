"""taucli fit on the command line: what it prints, its refusals (exit 2, one line), its chart, and
that numpy and scipy stay out of every other command."""

from __future__ import annotations

import io
import os
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import modules_after_run, run_taucli
from fit_synthetic import coast_down, csv
from taucli.front import help as helptext
from taucli.options import COMMANDS, SCENES
from taucli.options.fit import COMMAND as FIT
from taucli.options.fit import SCENE_NAMES

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture
def coast(tmp_path):
    path = tmp_path / "coast.csv"
    path.write_text(csv("t (s),omega (rad/s)", coast_down([0.5 * i for i in range(30)], 0.05, 21), ("g", ".4f")))
    return str(path)


FIT_COAST = ("--inertia", "0.1kg*m^2", "--fit", "friction,viscous,omega0")


def test_fit_is_a_command_and_takes_every_scene():
    assert "fit" in COMMANDS and "fit" not in SCENES
    assert SCENE_NAMES == tuple(SCENES)


def test_fit_answers_with_the_fitted_inputs_their_quality_and_the_scene(coast):
    done = run_taucli("fit", "spin-down", coast, *FIT_COAST, "--no-steps", env={"COLUMNS": "80"})
    assert done.code == 0 and done.err == ""
    lines = done.out.splitlines()
    assert lines[0].startswith("fit: spin-down, exponential approach to a steady speed")
    for key in ("friction", "viscous", "omega0", "residual_rms", "r2", "samples", "dropped", "t_stop"):
        assert any(line.split() and line.split()[0] == key for line in lines), key
    assert "correlation" in [line.strip() for line in lines]


def test_fit_writes_strict_json_with_uncertainties_and_the_samples_for_a_plot(coast):
    document = run_taucli("fit", "spin-down", coast, *FIT_COAST, "--json", "--plot").json()
    assert document["scene"] == "fit"
    results = document["results"]
    assert results["friction"]["unit"] == "N*m" and results["friction"]["uncertainty"] > 0
    assert len(results["correlation"]["value"]) == 3 and results["samples"]["value"] == 30
    assert results["t_stop"]["uncertainty"] > 0
    assert "correlation" not in document  # the table the person sees is the result's value here
    plot = document["plot"]
    assert plot["x"] == "time" and plot["y"] == "omega" and len(plot["samples"]) == 30 and len(plot["curve"]) == 121
    assert set(plot["samples"][0]) == {"time", "omega", "fitted", "residual"}


def test_get_prints_the_numbers_and_with_uncertainty_their_sigma(coast):
    done = run_taucli("fit", "spin-down", coast, *FIT_COAST, "--get", "friction", "--get", "samples", "--uncertainty", "--to", "friction=mN*m")
    assert done.code == 0
    friction, samples = done.out.splitlines()
    value, sigma = (float(x) for x in friction.split())
    assert 40 < value < 80 and 0 < sigma < 5
    assert samples == "30 0"  # --get: no trailing .0 (#36 item 7)


def test_fit_repeated_adds_its_names(coast):
    """--fit friction --fit viscous,omega0 fits all three (the second --fit once replaced the first)."""
    once = run_taucli("fit", "spin-down", coast, *FIT_COAST, "--get", "friction", "--get", "viscous")
    twice = run_taucli("fit", "spin-down", coast, "--inertia", "0.1kg*m^2", "--fit", "friction", "--fit", "viscous,omega0", "--get", "friction", "--get", "viscous")
    assert twice.code == 0 and twice.out == once.out


def test_plot_draws_the_data_the_fit_and_the_residuals_and_out_writes_a_file(coast, tmp_path):
    done = run_taucli("fit", "spin-down", coast, *FIT_COAST, "--no-steps", "--plot", "--out", str(tmp_path / "fit.svg"), env={"COLUMNS": "80"})
    assert done.code == 0
    assert "fit: spin-down, omega against time" in done.out
    assert "omega: measured and fitted" in done.out and "residual: omega measured − fitted" in done.out
    assert "• measured  ⠤ fitted" in done.out
    assert (tmp_path / "fit.svg").read_text().lstrip().startswith("<?xml")


def test_the_charts_x_axis_is_in_its_columns_unit_and_the_json_in_si(tmp_path):
    path = tmp_path / "periods.csv"
    path.write_text("amplitude (deg),period (s)\n10,2.0123\n30,2.0382\n50,2.1057\n70,2.2107\n")
    args = ("fit", "pendulum", str(path), "--shape", "point", "--mass", "50g", "--radius", "1m", "--x", "amplitude (deg)=angle0", "--fit", "g")
    done = run_taucli(*args, "--no-steps", "--plot", env={"COLUMNS": "80"})
    assert done.code == 0 and "angle0 (deg)" in done.out and "angle0 (rad)" not in done.out
    plot = run_taucli(*args, "--json", "--plot").json()["plot"]
    assert plot["units"]["angle0"] == "rad" and plot["samples"][0]["angle0"] == pytest.approx(0.17453292519943295, rel=1e-15)


@pytest.mark.parametrize("args,said", [
    (("spin-down", "COAST", "--inertia", "0.1", "--fit", "friction", "--inertai", "3"),
     "--inertai is not an option of fit, nor an input of spin-down; did you mean '--inertia'?"),
    (("spin-down", "nothere.csv", "--fit", "friction"), "DATA: expected a readable data file (or - for stdin), got 'nothere.csv': No such file or directory"),
    (("spinn", "COAST"), "SCENE: expected a scene"),
    (("spin-down", "COAST", "--inertia", "0.1kg*m^2", "--fit", "frction"), "--fit: expected a quantity option of spin-down"),
    (("spin-down", "COAST", "--fit", "inertia,friction,viscous,omega0"), "--fit: the samples cannot tell inertia, friction and viscous apart"),
    (("spin-down", "COAST", "--inertia", "4m", "--fit", "friction"), "--inertia: expected a moment of inertia"),
    (("spin-down", "COAST", "--inertia", "0.1kg*m^2"), "--fit: expected the inputs to fit, by option name (e.g. --fit friction,viscous)"),
    (("spin-down", "--inertia", "0.1kg*m^2", "--fit", "friction"), "DATA: expected a data file (CSV) after the scene"),
    (("spin-down", "COAST", "--inertia", "0.1kg*m^2", "--fit", "friction,omega0", "--x", "tau"), "--x: expected a column of"),
    (("spin-down", "COAST", "--inertia", "0.1kg*m^2", "--fit", "friction,omega0", "--plot", "--get", "friction"), "--plot: draws a chart, and --get prints numbers only"),
    (("spin-down", "COAST", "--inertia", "0.1kg*m^2", "--fit", "friction,omega0", "--out", "chart.pdf"), "--out: expected a file name ending in .svg or .png"),
])  # fmt: skip
def test_a_fit_that_cannot_be_made_is_refused_in_one_line(args, said, coast):
    done = run_taucli("fit", *(coast if arg == "COAST" else arg for arg in args))
    assert done.code == 2 and done.out == ""
    assert done.err.startswith("taucli: error: " + said), done.err
    assert done.err.count("\n") == 1


def test_without_scipy_fit_says_which_extra_to_install(monkeypatch):
    import importlib.util

    import taucli.fit
    from taucli.front.cli import Environment, main

    real = importlib.util.find_spec
    monkeypatch.setattr(taucli.fit.importlib.util, "find_spec", lambda name, *a: None if name == "scipy" else real(name, *a))
    err = io.StringIO()
    assert main(["fit", "spin-down", "coast.csv", "--fit", "friction"], Environment(stdout=io.StringIO(), stderr=err)) == 2
    assert err.getvalue() == "taucli: error: taucli fit needs scipy (not installed); pip install 'taucli[fit]' (from a checkout: pip install '.[fit]')\n"


@pytest.mark.parametrize("blocked,said", [
    (("scipy",), "taucli: error: taucli fit needs scipy (not installed); pip install 'taucli[fit]' (from a checkout: pip install '.[fit]')\n"),
    (("numpy", "scipy"), "taucli: error: taucli fit needs numpy and scipy (not installed); pip install 'taucli[fit]' (from a checkout: pip install '.[fit]')\n"),
])
def test_the_command_line_without_the_fit_extra_exits_2_in_one_line_naming_it(blocked, said, coast):
    """The real entry point in a Python where numpy or scipy cannot be imported (as where the
    extra was not installed): exit 2, one line, no traceback."""
    code = (
        "import sys\n"
        f"for name in {blocked!r}:\n    sys.modules[name] = None\n"
        f"sys.argv = ['taucli', 'fit', 'spin-down', {coast!r}, '--inertia', '0.1kg*m^2', '--fit', 'friction,omega0']\n"
        "from taucli.__main__ import main\nsys.exit(main())\n"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=os.environ.copy())
    assert (done.returncode, done.stdout, done.stderr) == (2, "", said)


def _modules_after(argv: list[str]) -> set[str]:
    """The top-level packages a whole run of ``taucli ARGV`` loads."""
    return {name.split(".")[0] for name in modules_after_run(argv, {})}


@pytest.mark.parametrize("argv", [
    ["--help"], ["fit", "--help"], ["atwood", "--m1", "4kg", "--m2", "1kg", "--get", "a"],
    ["spin-down", "--inertia", "0.1", "--omega0", "3rad/s", "--friction", "0.1"],
    ["pendulum", "--shape", "point", "--mass", "50g", "--radius", "1m", "--angle0", "30deg", "--get", "period"],
    ["rolling", "sphere", "--angle", "30deg", "--get", "a"],
])
def test_numpy_and_scipy_stay_out_of_every_other_command(argv):
    """(pint imports numpy where it is installed, the first time a unit is read: the second run
    reads its units from taucli's cache.)"""
    _modules_after(argv)
    assert not _modules_after(argv) & {"numpy", "scipy"}


def test_the_python_api_fits_as_the_command_line_does(coast):
    import taucli.fit

    report = taucli.fit.fit("spin-down", coast, fit="friction,viscous,omega0", inertia="0.1 kg*m^2")
    document = run_taucli("fit", "spin-down", coast, *FIT_COAST, "--json").json()
    assert report.results["friction"].value == document["results"]["friction"]["value"]
    assert report.uncertainties["viscous"] == document["results"]["viscous"]["uncertainty"]


def test_fits_page_shows_its_options_and_results_as_its_table_has_them():
    text = (ROOT / "docs" / "fit.md").read_text(encoding="utf-8")
    start, end = helptext.TABLE_START.format(name="fit"), helptext.TABLE_END.format(name="fit")
    assert text.split(start, 1)[1].split(end, 1)[0].strip() == helptext.markdown(FIT), "docs/fit.md's table is stale: python -m taucli.front.help docs"
    assert "(docs/fit.md)" in (ROOT / "README.md").read_text(encoding="utf-8")


def test_the_tables_the_page_shows_are_the_synthetic_ones_its_text_states():
    """docs/fit.md's synthetic tables are made by tests/fit_synthetic.py at the parameters it names,
    and docs/data/phyphox-gyroscope.csv too."""
    import re

    from fit_synthetic import docs_tables, phyphox_gyroscope

    page = (ROOT / "docs" / "fit.md").read_text(encoding="utf-8")
    shown = dict(re.findall(r"^\$ cat (\S+)\n(.*?)(?=^\$ )", page, re.S | re.M))
    for name, text in docs_tables().items():
        assert shown[name] == text, name
    assert (ROOT / "docs" / "data" / "phyphox-gyroscope.csv").read_text(encoding="utf-8") == phyphox_gyroscope()
