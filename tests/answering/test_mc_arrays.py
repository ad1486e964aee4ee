"""--mc on arrays (#45 item 4): the draws of a closed-form scene solved all at once with numpy
(taucli.answering.mc_arrays), each the number the scene itself gives for it; the scalar path
where numpy is not installed and where a scene has no array form; the time budget that refused
10⁵ draws of a scene they now take well under a second."""

from __future__ import annotations

import json
import math
import random
import subprocess
import sys

import numpy as np
import pytest

from conftest import run_taucli
from taucli.answering import answer, pipeline, propagate
from taucli.options import SCENES

SPIN = {"inertia": "2+/-0.1 kg*m^2", "omega0": "100+/-2 rad/s", "friction": "0.5 N*m", "viscous": "0.01", "time": "10s"}
ATWOOD = {"m1": "1.1+/-0.1kg", "m2": "1kg", "pulley_radius": "0.1m", "axle_friction": "0.05 N*m"}
ROLLING = {"shape": "sphere", "angle": "30+/-1deg", "length": "2+/-0.01m", "mass": "1kg", "radius": "0.1m", "mu_s": "0.17+/-0.01", "mu_k": "0.1"}
PENDULUM = {"shape": "point", "mass": "1kg", "radius": "1+/-0.01m", "angle0": "30+/-2deg"}
SPIN_UP = {"inertia": "0.5+/-0.02 kg*m^2", "torque": "2+/-0.1 N*m", "friction": "0.3 N*m", "viscous": "0.01", "time": "5s"}
CLOSED = [("spin-down", SPIN), ("spin-down", SPIN_UP), ("atwood", ATWOOD), ("rolling", ROLLING), ("pendulum", PENDULUM)]


def _spin_scenes(rng: random.Random):
    """spin-down under its torque laws, every combination the form takes: turning either way or
    set going from rest, a drive or none, friction, viscous, quadratic drag, a time or none;
    wheels that stop before the time, after it, never; steady speeds; D < 0 (friction with drag)."""
    for _ in range(40):
        given = {"inertia": 10 ** rng.uniform(-2, 1), "omega0": rng.choice((-1, 1)) * 10 ** rng.uniform(-1, 2.5)}
        if rng.random() < 0.2:  # from rest: set going by the drive (or held by friction)
            del given["omega0"]
        for name, low, high in (("torque", -1, 1), ("friction", -2, 0.5), ("viscous", -4, -1), ("drag", -5, -2)):
            if rng.random() < 0.5:
                given[name] = 10 ** rng.uniform(low, high) * (rng.choice((-1, 1)) if name == "torque" else 1)
        if rng.random() < 0.7:
            given["time"] = 10 ** rng.uniform(-1, 2.5)
        yield given


def _atwood_scenes(rng: random.Random):
    """The article's machine: massless, of a mass (disc or ring) or a given I, axle friction or
    none, g given or not; moving either way or held by the axle."""
    for _ in range(40):
        given = {"m1": 10 ** rng.uniform(-1, 1), "m2": 10 ** rng.uniform(-1, 1)}
        if rng.random() < 0.4:  # near balance: held by the axle in some draws, moving either way in others
            given["m2"] = given["m1"] * (1 + rng.uniform(-0.05, 0.05))
        pulley = rng.choice(("none", "mass", "ring", "inertia"))
        if pulley in ("mass", "ring"):
            given["pulley_mass"] = 10 ** rng.uniform(-1, 1)
        if pulley == "ring":
            given["pulley_shape"] = "ring"
        if pulley == "inertia":
            given["pulley_inertia"] = 10 ** rng.uniform(-4, -1)
        if pulley == "inertia" or rng.random() < 0.6:
            given["pulley_radius"] = 10 ** rng.uniform(-2, 0)
            if rng.random() < 0.6:
                given["axle_friction"] = 10 ** rng.uniform(-2, 1) * given["pulley_radius"]
        if rng.random() < 0.3:
            given["g"] = rng.uniform(1, 20)
        yield given


def _rolling_scenes(rng: random.Random):
    """A body let go on a slope: by its shape, k² or I with m and R; rolling, or slipping where
    μs is below μ_min (μk given, or μk alone taken as μs); to the bottom of a length or a height."""
    for _ in range(40):
        given = {"angle": rng.uniform(0.05, 1.5)}
        body = rng.choice(("shape", "k2", "inertia"))
        if body == "shape":
            given["shape"] = rng.choice(("sphere", "shell", "disc", "ring"))
        elif body == "k2":
            given["k2"] = rng.uniform(0.1, 1.5)
        else:
            given["mass"], given["radius"] = 10 ** rng.uniform(-1, 1), 10 ** rng.uniform(-2, 0)
            given["inertia"] = rng.uniform(0.1, 1) * given["mass"] * given["radius"] ** 2
        if body != "inertia" and rng.random() < 0.5:
            given["mass"] = 10 ** rng.uniform(-1, 1)
        if body != "inertia" and rng.random() < 0.5:
            given["radius"] = 10 ** rng.uniform(-2, 0)
        friction = rng.choice(("none", "both", "kinetic"))
        if friction != "none":
            given["mu_k"] = rng.uniform(0.05, 0.5)
        if friction == "both":
            given["mu_s"] = given["mu_k"] * rng.uniform(1, 1.5)
        if rng.random() < 0.6:
            given[rng.choice(("length", "height"))] = 10 ** rng.uniform(-1, 1)
        if rng.random() < 0.3:
            given["g"] = rng.uniform(1, 20)
        yield given


def _pendulum_scenes(rng: random.Random):
    """A pendulum let go from rest under gravity: a point mass at a radius, or a body by its I,
    mass and d; the exact period or the small-angle one; any amplitude short of the top."""
    for _ in range(30):
        mass, distance = 10 ** rng.uniform(-1, 1), 10 ** rng.uniform(-2, 0.5)
        given = {"mass": mass, "angle0": rng.choice((-1, 1)) * rng.uniform(0.01, 3.0)}
        if rng.random() < 0.5:
            given.update(shape="point", radius=distance)
        else:
            given.update(inertia=mass * distance * distance * rng.uniform(1, 3), cm_distance=distance)
        if rng.random() < 0.3:
            given["method"] = "small-angle"
        if rng.random() < 0.3:
            given["g"] = rng.uniform(1, 20)
        yield given


def _moved(given: dict, rng: random.Random, draws: int) -> dict[str, list[float]]:
    """Draws of each numeric input about its value (5 %), kept within the range it may take."""
    return {name: [rng.gauss(value, 0.05 * abs(value)) for _ in range(draws)] for name, value in given.items() if isinstance(value, float)}


@pytest.mark.parametrize("scene, scenes", [("spin-down", _spin_scenes), ("atwood", _atwood_scenes), ("rolling", _rolling_scenes),
                                            ("pendulum", _pendulum_scenes)])
def test_the_arrays_give_each_draw_the_numbers_the_scene_gives(scene, scenes):
    """Each draw the form takes, through the arrays and through pipeline.solve: the same results
    by name, each within 1e-12 (relative), over random scenes and every regime the form has."""
    from taucli.answering import mc_arrays

    command, rng = SCENES[scene], random.Random(45)
    form = __import__(mc_arrays.FORMS[scene], fromlist=["drawn"]).drawn
    compared, regimes = 0, set()
    for given in scenes(rng):
        columns = _moved(given, rng, 12)
        found = form({**given, **{name: np.asarray(values) for name, values in columns.items()}})
        assert found is not None, given
        results, regime, taken = found
        for i in np.flatnonzero(taken).tolist():
            draw = {**given, **{name: values[i] for name, values in columns.items()}}
            try:
                own = propagate.numeric(pipeline.solve(command, draw))
            except (ValueError, ArithmeticError) as err:
                pytest.fail(f"the form took a draw the scene refuses: {draw} ({err})")
            mine = {key: float(values[i]) for key, values in results.items() if math.isfinite(values[i])}
            assert set(mine) == set(own), (draw, set(mine) ^ set(own))
            for key, value in own.items():
                assert mine[key] == pytest.approx(value, rel=1e-12, abs=1e-300), (key, draw)
            compared += 1
            regimes.add(int(regime[i]))
    assert compared > 250 and len(regimes) >= {"rolling": 2, "pendulum": 1}.get(scene, 3), (compared, regimes)


def _counted(monkeypatch) -> list[int]:
    calls = [0]
    solve = pipeline.solve

    def counting(*args, **kwargs):
        calls[0] += 1
        return solve(*args, **kwargs)

    monkeypatch.setattr(propagate.pipeline, "solve", counting)
    return calls


@pytest.mark.parametrize("scene, given", CLOSED)
def test_mc_100000_solves_the_scene_a_handful_of_times(monkeypatch, scene, given):
    """10⁵ draws of a closed-form scene: the scene itself is solved for the nominal answer, its
    Jacobian, the ±1σ check and a few anchors of each regime, not once a draw (100,000 times)."""
    calls = _counted(monkeypatch)
    report = answer.solve(SCENES[scene], dict(given), mc=100_000)
    assert report.draws == 100_000 and report.monte_carlo
    assert calls[0] <= 40, calls[0]


def _one_by_one(scene: str, given: dict, draws: int) -> dict:
    """The Monte Carlo summaries from the scalar path: each draw solved by the scene."""
    command = SCENES[scene]
    central, spreads, _ = answer._read(command, given, propagate.readable(command, given))
    solved = propagate.Scene(command, central, None, answer._as_named)
    report = propagate.measured(solved.report({}), {}, spreads, [])
    propagate.monte_carlo(solved, report, spreads, draws, lambda draw: solved.report(draw))
    return report.monte_carlo


@pytest.mark.parametrize("scene, given", [*CLOSED,
                                          ("atwood", {"m1": "4+/-0.3kg", "m2": "3.8+/-0.2kg", "pulley_mass": "1+/-0.2kg",
                                                      "pulley_radius": "0.1m", "axle_friction": "0.05+/-0.02 N*m"})])
def test_the_same_draws_give_the_same_summaries_through_both_paths(scene, given):
    """The arrays' means and σ are the scalar path's, to rounding: the same draws, the same
    per-draw results (a machine held in some draws and moving either way in others)."""
    arrays = answer.solve(SCENES[scene], dict(given), mc=3000).monte_carlo
    scalar = _one_by_one(scene, dict(given), 3000)
    assert list(arrays) == list(scalar)
    for key, (mean, spread) in scalar.items():
        assert arrays[key][0] == pytest.approx(mean, rel=1e-11, abs=1e-12 * abs(spread)), key
        assert arrays[key][1] == pytest.approx(spread, rel=1e-9, abs=1e-300), key


HIDDEN = """
import json, sys
sys.modules["numpy"] = None
from taucli.answering import answer
from taucli.options import SCENES
try:
    from taucli.answering import mc_arrays
    print("numpy was importable", file=sys.stderr)
    sys.exit(1)
except ImportError:
    pass
report = answer.solve(SCENES[sys.argv[1]], json.loads(sys.argv[2]), mc=3000)
print(json.dumps(report.monte_carlo))
"""


@pytest.mark.parametrize("scene, given", [("spin-down", SPIN), ("atwood", ATWOOD)])
def test_without_numpy_the_scalar_path_gives_the_same_numbers(scene, given):
    done = subprocess.run([sys.executable, "-c", HIDDEN, scene, json.dumps(given)], capture_output=True, text=True, encoding="utf-8")
    assert done.returncode == 0, done.stderr
    scalar = json.loads(done.stdout)
    arrays = answer.solve(SCENES[scene], dict(given), mc=3000).monte_carlo
    assert list(scalar) == list(arrays)
    for key, (mean, spread) in arrays.items():
        assert scalar[key][0] == pytest.approx(mean, rel=1e-11, abs=1e-12 * abs(spread)), key
        assert scalar[key][1] == pytest.approx(spread, rel=1e-9, abs=1e-300), key


def test_a_scene_with_no_array_form_is_solved_draw_by_draw(monkeypatch):
    """A drag kω^2.5 is stepped (no closed form): each draw is the scene's, as before."""
    calls = _counted(monkeypatch)
    given = {"inertia": "1+/-0.1 kg*m^2", "omega0": "100rad/s", "drag": "0.01", "drag_exponent": "2.5", "time": "1s"}
    report = answer.solve(SCENES["spin-down"], given, mc=50)
    assert calls[0] >= 50 and report.draws == 50 and "omega" in report.monte_carlo


def test_mc_100000_of_a_closed_form_is_not_refused_by_the_time_budget():
    """The budget estimated 10⁵ solves of about 1.7 ms (171 s, refused); the arrays take them at once."""
    done = run_taucli("spin-down", "--inertia", "2+/-0.1 kg*m^2", "--omega0", "100+/-2 rad/s", "--friction", "0.5 N*m",
                      "--viscous", "0.01", "--time", "10s", "--mc", "100000", "--get", "omega", timeout=60)
    assert done.code == 0, done.err
    # ω(10 s) of the nominal wheel: I dω/dt = −τf − bω, ω = (ω₀ + τf/b) e^(−bt/I) − τf/b
    assert float(done.out) == pytest.approx((100 + 0.5 / 0.01) * math.exp(-0.01 * 10 / 2) - 0.5 / 0.01, rel=1e-12)


def test_the_draws_are_the_ones_the_seed_gave_before():
    """The draws come from the same generator in the same order: rng.gauss about each input in
    turn, redrawn outside its range (so a run's Monte Carlo numbers stay what they were)."""
    command = SCENES["atwood"]
    given = {"m1": "0.2+/-0.15kg", "m2": "1+/-0.1kg"}
    central, spreads, _ = answer._read(command, given, propagate.readable(command, given))
    scene = propagate.Scene(command, central, None, answer._as_named)
    columns, redrawn = propagate.draws_of(scene, spreads, 500, random.Random(propagate.MC_SEED))
    rng, expected, again = random.Random(propagate.MC_SEED), {"m1": [], "m2": []}, 0
    for _ in range(500):
        for name, (centre, sigma) in {"m1": (0.2, 0.15), "m2": (1.0, 0.1)}.items():
            x = rng.gauss(centre, sigma)
            while not x > 0:
                again += 1
                x = rng.gauss(centre, sigma)
            expected[name].append(x)
    assert columns == expected and redrawn == again > 0


def _clocked(monkeypatch, costs):
    """pipeline.solve that takes the given seconds (the first cold, the rest warm) on a clock of its own."""
    import time

    clock, each = [0.0], iter(costs)

    def solve(command, given, **kwargs):
        clock[0] += next(each)

    monkeypatch.setattr(time, "perf_counter", lambda: clock[0])
    monkeypatch.setattr(propagate.pipeline, "solve", solve)


@pytest.mark.parametrize("warm, refused", [(1e-4, False), (1e-3, True)])
def test_the_budget_estimates_from_the_planned_solves_not_the_first_cold_one(monkeypatch, warm, refused):
    """The first solve of a run imports its scene (0.3 s; a warm one 80 µs): averaged in, 10⁵
    draws were estimated at 171 s and refused, where draw by draw they take 8 s (numpy not
    installed, or a scene with no array form). 10⁵ solves of 1 ms (100 s) are still refused."""
    _clocked(monkeypatch, [0.3] + [warm] * 400)
    scene = propagate.Scene(SCENES["atwood"], {"m1": "4kg", "m2": "1kg"}, None, answer._as_named, limit=60.0)
    for _ in range(9):  # the nominal answer, its Jacobian, the ±1σ check
        scene.report({"m1": 4.0})
    scene.plan(100_000, "mc")
    if refused:
        with pytest.raises(propagate.OverBudget, match=r"about 100 s \(100,000 solves of about 1 ms each\).*mc 59\d\d\d fits"):
            for _ in range(300):
                scene.report({"m1": 4.0})
    else:
        for _ in range(300):
            scene.report({"m1": 4.0})
        assert scene.solves == 309


@pytest.mark.parametrize("args", [
    ("spin-down", "--inertia", "1kg*m^2", "--omega0", "100rad/s", "--friction", "2N*m", "--get", "t_stop"),
    ("spin-down", "--inertia", "1+/-0kg*m^2", "--omega0", "100rad/s", "--friction", "2N*m", "--get", "t_stop"),
    ("atwood", "--m1", "1.1kg", "--m2", "1kg", "--pulley-radius", "0.1m", "--get", "a"),
    ("rolling", "sphere", "--angle", "30deg", "--length", "2m", "--get", "a"),
    ("pendulum", "--shape", "point", "--mass", "1kg", "--radius", "1m", "--angle0", "10deg", "--get", "period"),
])
def test_mc_with_no_uncertain_input_gives_each_result_a_spread_of_zero(args):
    """No input moves: every draw is the nominal scene (before, the array forms returned one number
    for a result no draw moves, and --mc ended in an internal error, exit 1)."""
    from conftest import run_taucli
    run = run_taucli(*args, "--mc", "1000", "--uncertainty")
    assert run.code == 0, run.err
    value, spread = run.out.split()
    assert float(spread) == 0 and "Monte Carlo check, 1000 draws" in run.err


def test_mc_with_get_says_its_check_on_stderr():
    """--mc asked for a check: under --get the check is said beside the bare numbers, as the table says it."""
    from conftest import run_taucli
    run = run_taucli("atwood", "--m1", "1.1+/-0.1kg", "--m2", "1kg", "--pulley-radius", "0.1m", "--mc", "2000", "--get", "a")
    assert run.code == 0 and "taucli: note: Monte Carlo check, 2000 draws" in run.err
    mean, spread = (float(x) for x in run.err.split("a = ")[1].split(";")[0].split(" ± "))
    assert abs(mean - float(run.out)) < spread and spread == pytest.approx(2 * 9.80665 * 1 / 2.1**2 * 0.1, rel=0.3)  # σ_a ≈ ∂a/∂m1·σ = 2g·m2/(m1 + m2)²·σ
