"""--find NAME --minimize RESULT / --maximize RESULT (#47 item 6). References from the physics:
inertia matching (a gear ratio that moves a given load's motion with the least motor torque,
d/dN (J_m N + J/N) = 0: N = √(J/J_m)) and a rod pivoted off its centre with the least period
(T ∝ √((L²/12 + d²)/d), least at d = L/√12). An extremum is found to about √ε of itself."""

from __future__ import annotations

import json
import math
import random

import pytest

import taucli
from conftest import assert_usage_error

MOVE = dict(load_mass="10 kg", drum_radius="0.05 m", speed="1 m/s", accel_time="0.2 s", run_time="0.5 s", dwell_time="0.3 s")


@pytest.mark.parametrize("seed", range(2))
def test_inertia_matching_is_the_least_rms_torque(seed):
    rng = random.Random(4760 + seed)
    for _ in range(3):
        rotor, mass, radius = 10 ** rng.uniform(-5, -3), rng.uniform(1, 50), rng.uniform(0.01, 0.2)
        found = taucli.drive(motor_inertia=rotor, load_mass=mass, drum_radius=radius, speed="1 m/s", accel_time="0.2 s", run_time="0.5 s",
                             find="ratio", minimize="torque_rms").results
        assert found["ratio"].value == pytest.approx(math.sqrt(mass * radius**2 / rotor), rel=1e-6)
        assert found["ratio_optimal"].value == pytest.approx(found["ratio"].value, rel=1e-6)  # the scene's own check, √(J/J_m)


def test_a_rod_swings_fastest_pivoted_at_l_over_root_12():
    offset = taucli.pendulum(shape="rod", length="1 m", mass="1 kg", axis="center", find="offset", minimize="period_small").results["offset"].value
    assert offset == pytest.approx(1 / math.sqrt(12), rel=1e-6)


def test_maximize_is_minimize_of_the_negative():
    """The power a motor's line gives, P = τω = τ_s(1 − ω/ω_nl)ω, is most at ω = ω_nl/2: a drive's
    steady speed on a load of b ω (no body): the b that takes the most power from the line."""
    found = taucli.spin_down(torque="10 N*m", drive_slope="-0.1 N*m*s", find="viscous", maximize="power").results
    # the line τ = 10 − 0.1ω meets bω at ω = 10/(b + 0.1); P = bω² is most where b = 0.1 (ω = 50, half the no-load 100)
    assert found["viscous"].value == pytest.approx(0.1, rel=1e-6)
    assert found["omega_inf"].value == pytest.approx(50, rel=1e-6)


def test_batch_and_python_agree_with_the_command_line():
    from conftest import run_taucli
    line = json.dumps({"motor_inertia": "1e-4kg*m^2", **{k: v.replace(" ", "") for k, v in MOVE.items()}, "find": "ratio", "minimize": "torque_rms"})
    batch = json.loads(run_taucli("drive", "--batch", "--no-steps", stdin=line + "\n").out)
    cli = run_taucli("drive", "--motor-inertia", "1e-4kg*m^2", "--load-mass", "10kg", "--drum-radius", "0.05m", "--speed", "1m/s", "--accel-time", "0.2s",
                     "--run-time", "0.5s", "--dwell-time", "0.3s", "--find", "ratio", "--minimize", "torque_rms", "--get", "ratio")
    python = taucli.drive(motor_inertia="1e-4 kg*m^2", **MOVE, find="ratio", minimize="torque_rms").results["ratio"].value
    assert batch["results"]["ratio"]["value"] == pytest.approx(python, rel=1e-15)
    assert float(cli.out) == pytest.approx(python, rel=1e-14)


def test_refusals(taucli):
    base = ("spin-down", "--inertia", "1kg*m^2", "--omega0", "10rad/s")
    assert_usage_error(taucli(*base, "--find", "friction", "--minimize", "t_stop"), "--minimize", "falling")
    assert_usage_error(taucli(*base, "--find", "friction", "--minimize", "t_stop", "--want", "t_stop=3s"), "--minimize", "--want")
    assert_usage_error(taucli(*base, "--minimize", "t_stop"), "--minimize", "--find")
    # a result the input does not move has no least: said so, not "it goes on falling" toward an end of the range
    flat = taucli("drive", "--motor-inertia", "1e-4kg*m^2", "--load-mass", "10kg", "--drum-radius", "0.05m", "--speed", "1m/s", "--accel-time", "0.2s",
                  "--run-time", "0.5s", "--dwell-time", "0.3s", "--find", "ratio", "--minimize", "power_mean")
    assert_usage_error(flat, "--minimize", "does not change with --ratio")
    assert "falling" not in flat.err
    assert_usage_error(taucli(*base, "--find", "friction", "--minimize", "t_stop", "--maximize", "t_stop"), "--maximize")
    assert_usage_error(taucli(*base, "--find", "friction", "--minimize", "nothing"), "--minimize")
    assert_usage_error(taucli(*base, "--find", "friction", "--minimize", "t_stp"), "did you mean 't_stop'?")
    assert_usage_error(taucli(*base, "--find", "frction", "--minimize", "t_stop"), "--find", "did you mean 'friction'?")
    assert_usage_error(taucli(*base, "--find", "friction", "--want", "t_stp=3s"), "--want", "did you mean 't_stop'?")


def test_plot_draws_the_result_against_the_input_about_the_optimum():
    """#47 item 6: --plot charts the result against the input, the optimum marked. Each point is
    the RMS torque of the move at that ratio, from the physics: τ_a = (J_m N + J/N)·v/(r t_a) ... as
    (J_m + J/N²)·α with α = N v/(r t_a); τ_rms = τ_a √((t_a + t_d)/t_cycle)."""
    from conftest import run_taucli
    rotor, mass, radius = 1e-4, 10.0, 0.05
    args = ("drive", "--motor-inertia", "1e-4kg*m^2", "--load-mass", "10kg", "--drum-radius", "0.05m", "--speed", "1m/s", "--accel-time", "0.2s",
            "--run-time", "0.5s", "--dwell-time", "0.3s", "--find", "ratio", "--minimize", "torque_rms")
    document = json.loads(run_taucli(*args, "--json", "--plot").out)
    plot = document["plot"]
    assert plot["units"] == {"ratio": "", "torque_rms": "N*m"}
    points = plot["points"]
    assert len(points) >= 50
    ratios = [p["ratio"] for p in points]
    assert (min(ratios) + max(ratios)) / 2 == pytest.approx(math.sqrt(10 * 0.05**2 / 1e-4), rel=1e-9) and max(ratios) > 1.5 * min(ratios)  # evenly either side
    for p in points:
        ratio = p["ratio"]
        alpha = ratio * 1.0 / (radius * 0.2)
        torque_accel = (rotor + mass * radius**2 / ratio**2) * alpha
        assert p["torque_rms"] == pytest.approx(torque_accel * math.sqrt(0.4 / 1.2), rel=1e-9)
    least = min(points, key=lambda p: p["torque_rms"])
    assert least["ratio"] == pytest.approx(math.sqrt(mass * radius**2 / rotor), rel=1e-6)  # the optimum is one of the points
    assert plot["marks"] == [{"ratio": pytest.approx(least["ratio"], rel=1e-12), "what": "the least torque_rms"}]
    shown = run_taucli(*args, "--plot", env={"COLUMNS": "80"}).out
    assert "drive: torque_rms against ratio" in shown and "at ratio = 15.81: the least torque_rms" in shown


def test_report_plot_draws_the_optimum_curve():
    pytest.importorskip("matplotlib")
    report = taucli.drive(motor_inertia="1e-4 kg*m^2", **MOVE, find="ratio", minimize="torque_rms")
    figure = report.plot()
    axes = figure.axes[0]
    assert "ratio" in axes.get_xlabel() and "RMS motor torque" in axes.get_ylabel()
    xs, ys = axes.lines[0].get_xdata(), axes.lines[0].get_ydata()
    least = min(range(len(ys)), key=lambda i: ys[i])
    assert xs[least] == pytest.approx(math.sqrt(10 * 0.05**2 / 1e-4), rel=1e-6)
    assert ys[least] == pytest.approx(report.results["torque_rms"].value, rel=1e-12)
