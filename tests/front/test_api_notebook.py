"""In a notebook (#46 item 10): a list for one keyword is a sweep of reports, each the report of
the single call (with .to_pandas() where pandas is installed); two lists in one call are refused;
report.plot() draws the scene's trajectory as a matplotlib Figure, line for line."""

from __future__ import annotations

import importlib.util
import os
import re
import sys

import pytest

import taucli
from conftest import example_keys
from taucli.options import SCENES
from taucli.writing.document import document
from taucli.writing.plot import SAMPLES

SCENE_NAMES = sorted(name for name in SCENES if name.replace("-", "_") in taucli.__all__)
NUMBER_UNIT = re.compile(r"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*)")


def _needed(module: str):
    """The module, or a skip where it is not installed (a failure under CI, which installs it)."""
    try:
        return __import__(module)
    except ImportError:
        if os.environ.get("CI"):
            raise
        pytest.skip(f"{module} is not installed")


def _call(command, given: dict):
    """The Python call of the scene, a report or the InputError it raised."""
    try:
        return getattr(taucli, command.function_name)(**given)
    except taucli.InputError as err:
        return err


def _others(text: str) -> list:
    """Values beside a quantity's text: it, 1.5 times it, half of it (in its unit), and its SI number."""
    found = NUMBER_UNIT.fullmatch(text)
    if found is None:
        return [text]
    number, unit = float(found[1]), found[2]
    return [text, f"{number * 1.5!r} {unit}".strip(), f"{number / 2!r} {unit}".strip()]


def _sweepable(command, given: dict) -> list[str]:
    return [name for name, value in given.items() if isinstance(value, str) and (option := command.option(name)) is not None and option.sweepable]


@pytest.mark.parametrize("scene", SCENE_NAMES)
def test_a_sweeps_rows_are_the_single_calls(scene):
    """Every scene, every keyword its example gives one quantity: a list of values gives, row
    for row, what one call per value gives (or the InputError the first refused value gives)."""
    command = SCENES[scene]
    given = example_keys(command)
    swept_any = False
    for name in _sweepable(command, given):
        values = _others(given[name])
        singles = [_call(command, {**given, name: value}) for value in values]
        sweep = _call(command, {**given, name: values})
        refused = [single for single in singles if isinstance(single, taucli.InputError)]
        if refused:  # the sweep stops at the first value refused, with that value's message
            assert isinstance(sweep, taucli.InputError) and str(sweep) == str(refused[0])
            continue
        assert isinstance(sweep, taucli.Sweep), sweep
        assert sweep.name == name and sweep.values == tuple(values) and len(sweep) == len(values)
        assert [document(row) for row in sweep] == [document(single) for single in singles]
        swept_any = True
    assert swept_any or not _sweepable(command, given), f"{scene}: no value of its example could be swept"


def test_a_numpy_array_is_a_sweep_too():
    numpy = _needed("numpy")
    sweep = taucli.atwood(m1="4 kg", m2=numpy.array([0.5, 1.0, 2.0]), pulley_mass="2 kg")
    assert [row.results["a"].value for row in sweep] == [taucli.atwood(m1="4 kg", m2=m2, pulley_mass="2 kg").results["a"].value for m2 in (0.5, 1.0, 2.0)]
    assert [row.results["a"].value for row in sweep] == pytest.approx([(4 - m2) * 9.80665 / (4 + m2 + 1) for m2 in (0.5, 1.0, 2.0)], rel=1e-15)


def test_lists_for_two_keywords_are_refused_naming_both():
    with pytest.raises(taucli.InputError, match=r"^m2 is a list, and so is m1: a call sweeps one keyword") as raised:
        taucli.atwood(m1=["4 kg", "5 kg"], m2=["1 kg", "2 kg"])
    assert raised.value.option == "m2" and "[taucli.atwood(..., m1=x, m2=[...]) for x in (...)]" in str(raised.value)


def test_an_empty_list_and_a_range_text_are_refused():
    with pytest.raises(taucli.InputError, match=r"^m2 is an empty list: a sweep takes one value or more"):
        taucli.atwood(m1="4 kg", m2=[])
    with pytest.raises(taucli.InputError, match=r"^m2: takes one value, or a list of values for a sweep"):
        taucli.atwood(m1="4 kg", m2="1..3 kg")


def test_a_repeatable_keyword_takes_its_list_as_its_values_not_a_sweep():
    report = taucli.drive(motor_inertia="1.2 kg*cm^2", ratio=[10], load_inertia=0.05)
    assert isinstance(report, taucli.Report)
    assert report.results["inertia_ratio"].value == pytest.approx(0.05 / 100 / 1.2e-4, rel=1e-12)


def test_to_pandas_has_the_keyword_then_the_results_with_their_units():
    pandas = _needed("pandas")
    sweep = taucli.atwood(m1="4 kg", m2=["500 g", 1, "2 kg"], pulley_mass="2 kg", pulley_radius="10 cm", distance="1 m")
    frame = sweep.to_pandas()
    assert isinstance(frame, pandas.DataFrame)
    results = list(sweep[0].results)
    assert list(frame.columns) == ["m2", *results]
    assert frame.attrs["units"] == {"m2": "kg", **{key: value.unit for key, value in sweep[0].results.items()}}
    assert frame["m2"].tolist() == [0.5, 1.0, 2.0]  # in SI, as read
    for key in results:
        assert frame[key].tolist() == [row.results[key].value for row in sweep]
    assert frame["a"].tolist() == pytest.approx([(4 - m2) * 9.80665 / (4 + m2 + 1) for m2 in (0.5, 1.0, 2.0)], rel=1e-15)


def test_to_pandas_without_pandas_says_how_to_get_it(monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)  # import pandas then raises ImportError
    sweep = taucli.atwood(m1="4 kg", m2=[1, 2])
    with pytest.raises(ImportError, match=r"needs pandas: pip install pandas"):
        sweep.to_pandas()
    assert sweep.records() == [{"m2": m2, **{key: value.value for key, value in row.results.items()}} for m2, row in zip((1.0, 2.0), sweep)]


def _drawn(axes) -> list[tuple[float, float]]:
    """The (t, y) points of an axes' first line: the curve (the lines after it mark moments)."""
    return [tuple(point) for point in axes.lines[0].get_xydata().tolist()]


@pytest.mark.parametrize("scene", SCENE_NAMES)
def test_plot_draws_the_scenes_trajectory_line_for_line(scene):
    """Every scene's example: report.plot() is a Figure with one panel per curve of its
    trajectory, each line the trajectory's samples (t, value) in SI, labelled with its unit."""
    _needed("matplotlib")
    from matplotlib.figure import Figure

    command = SCENES[scene]
    report = getattr(taucli, command.function_name)(**example_keys(command))
    if report.trajectory is None:
        with pytest.raises(ValueError, match=rf"^plot\(\) draws a motion in time, and this {scene} report has none"):
            report.plot()
        return
    trajectory = report.trajectory()
    samples = trajectory.sample(SAMPLES)
    figure = report.plot()
    assert isinstance(figure, Figure)
    assert len(figure.axes) == len(trajectory.curves)
    for column, (axes, (key, unit, label)) in enumerate(zip(figure.axes, trajectory.curves), start=1):
        assert _drawn(axes) == [(point[0], point[column]) for point in samples], key
        assert axes.get_ylabel().startswith(label)
    assert figure.axes[-1].get_xlabel() == "time (s)"


def test_a_spin_downs_plot_is_omega_and_theta_of_t():
    """The issue's chart: ω(t) falls at α = −τ/I to the stop, θ(t) = ω0 t + α t²/2 until then."""
    _needed("matplotlib")
    report = taucli.spin_down(shape="disc", mass=5, radius="20 cm", omega0="30 rad/s", friction="0.3 N*m")
    omega, theta = report.plot().axes
    alpha = -0.3 / 0.1
    for t, w in _drawn(omega):
        assert w == pytest.approx(max(30 + alpha * t, 0.0), rel=1e-12, abs=1e-12)
    for t, angle in _drawn(theta):
        t = min(t, 10.0)
        assert angle == pytest.approx(30 * t + alpha * t * t / 2, rel=1e-12, abs=1e-12)
    assert omega.get_ylabel() == "angular velocity ω (rad/s)" and theta.get_ylabel() == "angle turned θ (rad)"


def test_a_sweeps_plot_overlays_one_curve_per_value():
    _needed("matplotlib")
    sweep = taucli.spin_down(shape="disc", mass=5, radius="20 cm", omega0="30 rad/s", friction=["0.3 N*m", "0.5 N*m"])
    figure = sweep.plot()
    curves = [line for line in figure.axes[0].lines if not line.get_label().startswith("_")]
    assert [line.get_label() for line in curves] == ["friction = 0.3 N*m", "friction = 0.5 N*m"]


def test_plot_without_matplotlib_says_how_to_get_it(monkeypatch):
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    monkeypatch.setitem(sys.modules, "matplotlib.figure", None)
    with pytest.raises(ImportError, match=r"plot\(\) needs matplotlib: pip install 'taucli\[plot\]'"):
        taucli.spin_down(inertia=0.1, omega0="30 rad/s", friction="0.3 N*m").plot()


def test_the_examples_of_docs_python_md_are_what_python_shows():
    from conftest import ROOT

    page = (ROOT / "docs" / "python.md").read_text(encoding="utf-8")
    sweep = taucli.atwood(m1="4 kg", m2=["0.5 kg", "1 kg", "2 kg"], pulley_mass="2 kg", pulley_radius="10 cm")
    assert repr(sweep) + "\n" in page
    assert repr({name: unit for name, unit in sweep.columns()[1].items()}) + "\n" in page
    for m2, a, t1, t2 in [line.split()[1:] for line in page.splitlines() if re.fullmatch(r"\d  \d\.\d  .*", line)]:
        row = sweep[[0.5, 1.0, 2.0].index(float(m2))].results
        assert [float(a), float(t1), float(t2)] == pytest.approx([row["a"].value, row["T1"].value, row["T2"].value], abs=5e-7)
    if importlib.util.find_spec("matplotlib") is None and not os.environ.get("CI"):
        return  # (the sweep's lines are checked above; the figure's where matplotlib is)
    figure = taucli.spin_down(shape="disc", mass=5, radius="20 cm", omega0="30 rad/s", friction="0.3 N*m").plot()
    assert repr(figure) + "\n" in page and repr([ax.get_ylabel() for ax in figure.axes]) + "\n" in page
