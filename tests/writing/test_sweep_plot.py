"""Sweeps and charts: a sweep's points are single runs; a chart's data is the solver's.

References are written here from the physics (α = τ/I, a = g(m1 − m2)/(m1 + m2 + M/2), the
skidding ball's v_roll = 5/7 v₀), not taken from taucli's formulas.
"""

from __future__ import annotations

import json
import math
import re
import struct
import xml.etree.ElementTree as ElementTree
from pathlib import Path

import pytest

from conftest import assert_usage_error, documents_text, run_taucli

GOLDEN = Path(__file__).resolve().parents[1] / "golden"
G = 9.80665
ANSI = re.compile(r"\x1b\[")


def _documents(result) -> list[dict]:
    assert result.code == 0, result.err
    return json.loads(result.out)


SWEEPS = [
    ("inertia", ["disc", "--mass", "1kg..5kg", "--radius", "10cm,20cm"], "mass", "radius"),
    ("spin-down", ["--inertia", "0.5..4kg*m^2", "--torque", "3N*m,6N*m", "--friction", "0.5N*m", "--time", "2s"], "inertia", "torque"),
    ("atwood", ["--m1", "1..5kg", "--m2", "1kg", "--pulley-mass", "0kg,2kg", "--distance", "1m"], "m1", "pulley_mass"),
    ("rolling", ["sphere", "--angle", "10..40deg", "--mu-s", "0.1,0.3", "--mu-k", "0.08", "--length", "2m"], "angle", "mu_s"),
    ("impulse", ["--inertia", "0.1kg*m^2", "--omega0", "0", "--torque", "1..3N*m", "--duration", "0.5s,2s"], "torque", "duration"),
]


@pytest.mark.parametrize("scene, args, ranged, listed", SWEEPS)
def test_each_point_of_a_sweep_is_the_single_run_at_that_point(scene, args, ranged, listed):
    documents = _documents(run_taucli(scene, *args, "--points", "4", "--json"))
    assert len(documents) == 4 * 2
    single_args = list(args)
    range_at, list_at = single_args.index("--" + ranged.replace("_", "-")) + 1, single_args.index("--" + listed.replace("_", "-")) + 1
    low, high = args[range_at].split("..")
    unit = re.sub(r"^[-+.\d]+", "", high)
    low_value, high_value = float(re.match(r"[-+.\d]+", low)[0]), float(re.match(r"[-+.\d]+", high)[0])
    list_items = args[list_at].split(",")
    for index, document in enumerate(documents):
        item, step = divmod(index, 4)
        single_args[range_at] = f"{low_value + (high_value - low_value) * step / 3!r}{unit}"
        single_args[list_at] = list_items[item]
        single = run_taucli(scene, *single_args, "--json").json()
        assert document == single, (index, single_args)


def test_the_range_runs_end_to_end_in_the_unit_given_and_a_bare_number_takes_the_last_unit():
    documents = _documents(run_taucli("atwood", "--m1", "500..1500g", "--m2", "1kg", "--points", "3", "--json", "--no-steps"))
    assert [d["inputs"]["m1"]["value"] for d in documents] == [0.5, 1.0, 1.5]
    documents = _documents(run_taucli("spin-down", "--inertia", "1", "--torque", "1,2,3N*m", "--json", "--no-steps"))
    assert [d["results"]["alpha0"]["value"] for d in documents] == [1.0, 2.0, 3.0]


def test_alpha_against_inertia_for_two_torques_stays_a_factor_of_two_apart():
    """The article's first figure: α = τ/I, so the τ = 6 N·m curve is twice the τ = 3 N·m one."""
    lines = run_taucli("spin-down", "--inertia", "0.5..4kg*m^2", "--torque", "3N*m,6N*m", "--points", "50", "--get", "alpha0")
    assert lines.code == 0, lines.err
    rows = [[float(cell) for cell in line.split("\t")] for line in lines.out.splitlines()]
    assert len(rows) == 100
    for torque, inertia, alpha in rows:
        assert alpha == pytest.approx(torque / inertia, rel=1e-15)
    for (_, inertia3, alpha3), (_, inertia6, alpha6) in zip(rows[:50], rows[50:]):
        assert inertia3 == inertia6 and alpha6 == pytest.approx(2 * alpha3, rel=1e-15)


@pytest.mark.parametrize(
    "args, fragments",
    [
        (["spin-down", "--inertia", "1..2", "--torque", "1..2"], ("--inertia and --torque", "at most one range")),
        (["spin-down", "--inertia", "1,2", "--torque", "1,2", "--omega0", "1rad/s"], ("--inertia and --torque", "list")),
        (["spin-down", "--inertia", "1", "--torque", "1", "--points", "5"], ("--points", "range")),
        (["spin-down", "--inertia", "1..2", "--torque", "1", "--points", "1"], ("--points", "2 to 200")),
        (["spin-down", "--inertia", "1..2", "--torque", "1", "--points", "ten"], ("--points", "whole number")),
        (["spin-down", "--inertia", "2..2", "--torque", "1"], ("--inertia", "two different")),
        (["spin-down", "--inertia", "1..2..3", "--torque", "1"], ("--inertia", "FROM..TO")),
        (["spin-down", "--inertia", "1g..2kg", "--torque", "1"], ("--inertia", "one unit")),
        (["spin-down", "--inertia", "1", "--torque", "1,"], ("--torque", "empty item")),
        (["atwood", "--m1", "4,5 kg"], ("--m1", "ambiguous", "4.5kg")),
        (["atwood", "--m1", "1,500 kg"], ("--m1", "ambiguous")),
        (["atwood", "--m1", "4kg", "--y", "a"], ("--y", "range")),
        (["atwood", "--m1", "1..2kg", "--y", "alpah"], ("--y", "did you mean 'alpha'")),
        (["atwood", "--m1", "4kg", "--plot", "--get", "a"], ("--plot", "--get")),
        (["atwood", "--m1", "4kg", "--out", "chart.pdf"], ("--out", ".svg or .png")),
        (["atwood", "--m1", "1kg..2m"], ("--m1", "one unit")),
        (["atwood", "--m1", "0..2kg", "--m2", "0"], ("--m1", "point m1 = 0.0 kg")),
        (["atwood", "--m1", "1..2 m", "--points", "3"], ("--m1", "a mass", "point m1 = 1.0 m")),
        (["inertia", "disc", "--mass", "1kg", "--radius", "1m", "--plot"], ("--plot", "motion in time")),
        (["atwood", "--m1", "1..2kg", "--batch"], ("--m1", "--batch")),
        # a range times a list: 10,000 × 10,000 points would have run for hours (#9)
        (["atwood", "--m1", "1..2kg", "--points", "200", "--m2", "1kg,2kg"], ("--m2", "sweep of 400 points", "more than 200 in all", "--batch")),
        (["atwood", "--m1", ",".join(["1kg"] * 10001)], ("--m1", "sweep of 10,001 points")),
    ],
)
def test_sweep_mistakes_exit_2_with_one_line(args, fragments):
    assert_usage_error(run_taucli(*args, stdin=""), *fragments)


def test_a_batch_line_cannot_hold_a_range():
    result = run_taucli("atwood", "--batch", stdin='{"m1": "1..2kg"}\n{"m1": "4kg"}\n')
    lines = [json.loads(line) for line in result.out.splitlines()]
    assert result.code == 2 and "range or a list" in lines[0]["error"]["message"] and lines[1]["results"]["a"]["value"] == G


def test_the_table_has_a_row_per_point_and_a_column_per_result_and_the_chart_follows():
    result = run_taucli("atwood", "--m1", "1..4kg", "--m2", "1kg", "--points", "4", env={"COLUMNS": "100"})
    assert result.code == 0, result.err
    rows = [line.split() for line in result.out.splitlines() if re.match(r"\s+\d(\.\d+)?\s+\d", line)]
    assert [float(row[0]) for row in rows] == [1, 2, 3, 4]
    header = next(line for line in result.out.splitlines() if "m1 (kg)" in line)
    assert all(name in header for name in ("a (m/s²)", "T1 (N)", "T2 (N)", "a_massless (m/s²)"))
    assert "a: acceleration of the masses" in result.out
    assert "\n            m1 (kg)\n" in result.out


def _plot(result) -> dict:
    assert result.code == 0, result.err
    return result.json()["plot"]


def test_spin_down_plot_data_is_the_uniform_deceleration_and_marks_the_stop():
    """The article's potter's wheel: ω = 30 − 3t until it stops at 10 s, then held; θ = 30t − 1.5t²."""
    plot = _plot(run_taucli("spin-down", "--inertia", "0.1kg*m^2", "--omega0", "30rad/s", "--friction", "0.3N*m", "--plot", "--json"))
    assert plot["units"] == {"t": "s", "omega": "rad/s", "theta": "rad"}
    assert plot["marks"] == [{"t": pytest.approx(10.0, rel=1e-15), "what": "stops"}]
    assert plot["points"][-1]["t"] == pytest.approx(12.5)
    for point in plot["points"]:
        t = min(point["t"], 10.0)
        assert point["omega"] == pytest.approx(30 - 3 * t, abs=1e-12)
        assert point["theta"] == pytest.approx(30 * t - 1.5 * t * t, rel=1e-13, abs=1e-12)


def test_atwood_plot_data_is_uniform_acceleration_with_a_massive_disc():
    m1, m2, pulley = 4.0, 1.0, 2.0
    a = G * (m1 - m2) / (m1 + m2 + pulley / 2)
    plot = _plot(run_taucli("atwood", "--m1", "4kg", "--m2", "1kg", "--pulley-mass", "2kg", "--distance", "1m", "--plot", "--json"))
    t_end = math.sqrt(2 / a)
    assert plot["points"][-1]["t"] == pytest.approx(t_end, rel=1e-14)
    assert plot["marks"][0]["t"] == pytest.approx(t_end, rel=1e-14)
    for point in plot["points"]:
        assert point["x"] == pytest.approx(a * point["t"] ** 2 / 2, rel=1e-13, abs=1e-15)
        assert point["v"] == pytest.approx(a * point["t"], rel=1e-13, abs=1e-15)


def test_rolling_plot_marks_the_moment_rolling_begins():
    """A ball skidding at 7 m/s with μk = 0.2: v falls at μk g until v = 5/7 v₀ = 5 m/s, then stays."""
    plot = _plot(run_taucli("rolling", "sphere", "--v0", "7m/s", "--mu-k", "0.2", "--plot", "--json"))
    t_roll = (7 - 5) / (0.2 * G)
    assert plot["marks"] == [{"t": pytest.approx(t_roll, rel=1e-14), "what": "rolls without slipping"}]
    for point in plot["points"]:
        expected = 7 - 0.2 * G * point["t"] if point["t"] <= t_roll else 5.0
        assert point["v"] == pytest.approx(expected, rel=1e-13)


def test_a_torque_profile_plots_omega_at_its_samples_and_stays_small_for_long_profiles(tmp_path):
    """τ = 2 N·m for 1 s on I = 0.5: ω = 4t, at the samples kept (every k-th of 100,001)."""
    profile = tmp_path / "constant.csv"
    profile.write_text("t [s],torque [N*m]\n" + "".join(f"{i / 100000!r},2\n" for i in range(100001)))
    plot = _plot(run_taucli("impulse", "--inertia", "0.5kg*m^2", "--torque-profile", str(profile), "--plot", "--json", "--no-steps"))
    assert 500 <= len(plot["points"]) <= 1001
    assert plot["points"][-1]["t"] == 1.0
    for point in plot["points"]:
        assert point["omega"] == pytest.approx(4 * point["t"], rel=1e-12, abs=1e-12)
        assert point["torque"] == 2.0


def test_a_list_with_plot_overlays_free_fall_and_the_disc_on_one_horizon():
    """The article's second figure: free fall (massless pulley, no m2) beside a mass on a disc of
    twice its mass: a = g against g/2, so the gap ½(g − g/2)t² grows."""
    result = run_taucli("atwood", "--m1", "1kg", "--pulley-mass", "0kg,2kg", "--distance", "1m", "--plot", "--json", "--no-steps")
    free, disc = _documents(result)
    horizon = disc["plot"]["points"][-1]["t"]
    assert horizon == pytest.approx(math.sqrt(4 / G), rel=1e-14)
    assert free["plot"]["points"][-1]["t"] == pytest.approx(math.sqrt(2 / G), rel=1e-14)
    text = run_taucli("atwood", "--m1", "1kg", "--pulley-mass", "0kg,2kg", "--distance", "1m", "--plot", env={"COLUMNS": "80"}).out
    assert "• pulley_mass = 0kg  + pulley_mass = 2kg" in text
    assert "│ at t = 0.4516 s: has moved 1 m (pulley_mass = 0kg)" in text
    assert "│ at t = 0.6387 s: has moved 1 m (pulley_mass = 2kg)" in text


@pytest.mark.parametrize("columns", [40, 120])
def test_the_terminal_chart_fits_the_width_and_has_no_colour_codes_in_a_pipe(columns):
    result = run_taucli("spin-down", "--inertia", "0.5..4kg*m^2", "--torque", "3N*m,6N*m", env={"COLUMNS": str(columns)})
    assert result.code == 0, result.err
    chart = result.out[result.out.index("spin-down: alpha0 against inertia") :]
    assert not ANSI.search(result.out)
    assert max(len(line) for line in chart.splitlines()) <= columns + 2  # plotille's axis arrow
    canvas = [line for line in chart.splitlines() if re.match(r"\s*[-\d.e]+ \| ", line)]
    assert len(canvas) == 12 and "•" in chart and "+" in chart


def test_colour_only_on_a_terminal_and_never_under_no_color():
    import io

    from taucli.writing import plot

    chart = plot.Chart("t", "x", "x", "m", (plot.Panel("y", "y", "s", (plot.Series("a", (0.0, 1.0), (0.0, 1.0)), plot.Series("b", (0.0, 1.0), (1.0, 0.0)))),))
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("FORCE_COLOR", "1")  # plotille also asks whether sys.stdout is a terminal
        patch.delenv("NO_COLOR", raising=False)
        assert ANSI.search(plot.terminal(chart, 60, colour=True))
        assert not ANSI.search(plot.terminal(chart, 60, colour=False))

    class Terminal(io.StringIO):
        def isatty(self):
            return True

    from taucli.writing.render import terminal_style

    assert terminal_style(Terminal())[1] is True
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("NO_COLOR", "1")
        assert terminal_style(Terminal())[1] is False


def test_one_small_chart_matches_its_golden_text():
    result = run_taucli("spin-down", "--inertia", "0.5..4kg*m^2", "--torque", "3N*m,6N*m", "--points", "8", env={"COLUMNS": "60"})
    assert result.code == 0, result.err
    assert result.out == (GOLDEN / "alpha_against_inertia.txt").read_text(encoding="utf-8")


def test_out_writes_a_valid_svg_and_png(tmp_path):
    pytest.importorskip("matplotlib")
    svg, png = tmp_path / "alpha.svg", tmp_path / "fall.png"
    assert run_taucli("spin-down", "--inertia", "0.5..4kg*m^2", "--torque", "3N*m,6N*m", "--out", str(svg), "--json").code == 0
    root = ElementTree.parse(svg).getroot()
    assert root.tag == "{http://www.w3.org/2000/svg}svg"
    assert root.iter("{http://www.w3.org/2000/svg}path") is not None and len(list(root.iter("{http://www.w3.org/2000/svg}path"))) > 10
    result = run_taucli("atwood", "--m1", "1kg", "--pulley-mass", "0kg,2kg", "--distance", "1m", "--out", str(png), "--get", "a")
    assert result.code == 0 and result.out == f"0\t{G!r}\n2\t{G / 2!r}\n"  # the swept value (SI), then a
    data = png.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n" and data[12:16] == b"IHDR"
    width, height = struct.unpack(">II", data[16:24])
    assert (width, height) == (700, 580)  # 7 in × (2.6 in per panel × 2 + 0.6 in) at matplotlib's 100 dpi




def _readme_charts() -> list[tuple[str, str]]:
    """(command, output) of each chart block in README and docs/: ```text, then $ taucli ... --plot."""
    blocks = [block for _, text in documents_text() for block in re.findall(r"```text\n\$ taucli ([^\n]*--plot)\n(.*?)```", text, re.S)]
    assert len(blocks) >= 3, "the article's figures are missing from docs/output.md"
    return blocks


@pytest.mark.parametrize("command, shown", _readme_charts())
def test_the_readme_figures_are_what_their_commands_print_at_72_columns(command, shown):
    import shlex

    result = run_taucli(*shlex.split(command), env={"COLUMNS": "72"})
    assert result.code == 0, result.err
    assert result.out == shown


def test_a_horizon_taucli_chose_is_said_under_the_chart_and_in_the_json():
    """Uniform spin-up never ends: with no --time, the plot covers 1 s and says so."""
    text = run_taucli("spin-down", "--inertia", "1", "--torque", "1", "--plot", "--no-steps", env={"COLUMNS": "80"}).out
    assert text.rstrip().endswith("note: plotted for 1 s; --time to change")
    plot = _plot(run_taucli("spin-down", "--inertia", "1", "--torque", "1", "--plot", "--json"))
    assert plot["notes"] == ["plotted for 1 s; --time to change"] and plot["points"][-1]["t"] == 1.0
    assert plot["points"][-1]["omega"] == 1.0 and plot["points"][-1]["theta"] == 0.5  # ω = t, θ = t²/2 at τ/I = 1


def test_a_run_without_plot_does_no_work_for_one():
    """The plot's horizon (99% of the way to the steady speed) is found only when a plot asks:
    at rk4 dt = 0.1 ms it would take about 10 million steps, which a run that plots nothing must not
    try, or refuse."""
    args = ("spin-down", "--inertia", "1kg*m^2", "--torque", "1N*m", "--viscous", "0.1N*m*s", "--method", "rk4", "--dt", "0.1ms")
    result = run_taucli(*args, "--get", "omega_inf")
    assert result.code == 0, result.err
    assert float(result.out) == pytest.approx(10.0, rel=1e-12)  # ω∞ = τ/b
    assert_usage_error(run_taucli(*args, "--plot", "--json"), "--dt", "more than 125,000 rk4 steps in all")


def test_a_value_that_is_a_range_and_a_list_at_once_is_refused():
    """#16: --m1 1..2,3 dropped ..2, ran a sweep of 1.0 and 3 and exited 1."""
    from conftest import assert_usage_error

    assert_usage_error(run_taucli("atwood", "--m1", "1..2,3", "--m2", "1kg"), "--m1 is a range and a list at once")


def test_an_ambiguous_comma_is_answered_in_the_options_own_kind():
    """#15 item 7: --v0 1,5 suggested '4.5kg' for a speed."""
    from conftest import assert_usage_error

    assert_usage_error(run_taucli("rolling", "sphere", "--angle", "30deg", "--v0", "1,5"), "--v0 1.5m/s for a number", "--v0 1m/s,5m/s for a list")
    assert_usage_error(run_taucli("spin-down", "--inertia", "1", "--torque", "1,5"), "--torque '1.5N*m' for a number")
