"""#45: the fit's model on arrays (taucli.fit.arrays) is the scene's physics, and it lifts the
sample cap: held to pipeline.solve on random scenes, the same report as the per-sample path, and a
fit of 10⁵ samples accepted and right."""

from __future__ import annotations

import io
import math

import numpy as np
import pytest

import taucli.fit as api
from taucli.answering import pipeline
from taucli.options import SCENES
from taucli.core.errors import InputError
from taucli.fit import arrays, data, fast_rows, samples as samples_module, solve
from taucli.fit.data import Column, DataTable

SPIN = SCENES["spin-down"]


def _random_scene(rng) -> dict:
    """A wheel under every mix of the torque laws: a drive either way or none, friction, viscous,
    quadratic drag (or kω, a viscous torque), ω₀ either way or 0."""
    scene = {"inertia": float(10 ** rng.uniform(-2, 1)), "omega0": float(rng.choice([0.0, 1.0, -1.0]) * 10 ** rng.uniform(-1, 2))}
    for name, low, high in (("torque", -2, 1), ("friction", -2, 1), ("viscous", -3, 0), ("drag", -4, -1)):
        if rng.random() < 0.5:
            scene[name] = float(10 ** rng.uniform(low, high) * (rng.choice([1.0, -1.0]) if name == "torque" else 1.0))
    if "drag" in scene and rng.random() < 0.2:
        scene["drag_exponent"] = 1.0
    return scene


def test_the_arrays_agree_with_the_scene_on_random_scenes():
    """ω, θ and revs at every sample time from the arrays, against ``taucli spin-down`` solved at
    each (pipeline.solve), to 1e-12 relative: stops, holds, turns back, the tangent solution."""
    rng = np.random.default_rng(45)
    worst = 0.0
    for _ in range(120):
        scene = _random_scene(rng)
        times = np.concatenate([[0.0], np.sort(rng.uniform(0, 30, 5))])
        for result in ("omega", "theta", "revs"):
            found = arrays.SpinDown(result).values(dict(scene), times)
            for t, value in zip(times, found):
                expected = pipeline.solve(SPIN, {**scene, "time": float(t)}).results[result].value
                assert math.isfinite(value)
                worst = max(worst, abs(value - expected) / abs(expected) if expected else abs(value))
    assert worst <= 1e-12


@pytest.mark.parametrize("exponent", [0.5, 1.5, 3.0])
def test_a_drag_exponent_is_stepped_once_and_agrees_with_the_scene(exponent):
    """A power-law drag has no closed form: one run of the scene's stepper over the sample times
    (each read on from the one before), within the stepper's tolerance of a solve per sample."""
    scene = {"inertia": 0.2, "omega0": 40.0, "friction": 0.02, "drag": 0.003, "drag_exponent": exponent}
    times = np.linspace(0, 25, 40)
    found = arrays.SpinDown("omega").values(dict(scene), times)
    expected = np.array([pipeline.solve(SPIN, {**scene, "time": float(t)}).results["omega"].value for t in times])
    assert np.all(np.abs(found - expected) <= 1e-8 * np.max(np.abs(expected)))


def _table(t: np.ndarray, omega: np.ndarray) -> DataTable:
    columns = (Column("t (s)", "t", "s", t.tolist()), Column("omega (rad/s)", "omega", "rad/s", omega.tolist()))
    return DataTable("coast.csv", columns, list(range(2, len(t) + 2)), ",", False)


def _coast(n: int, seed: int, sigma: float = 0.05):
    """A coast-down under friction and viscous torque (I = 0.1 kg·m², τ_f = 0.05 N·m, b = 0.01
    N·m·s, ω₀ = 30 rad/s: it stops at 19.46 s), sampled to 18 s with normal noise σ."""
    t = np.linspace(0, 18, n)
    b, friction, inertia, omega0 = 0.01, 0.05, 0.1, 30.0
    omega = (omega0 + friction / b) * np.exp(-b * t / inertia) - friction / b  # ω(t) of I dω/dt = −τ_f − bω, before the stop
    return t, omega + np.random.default_rng(seed).normal(0, sigma, n)


def _model(t, omega, sigma="0.05 rad/s"):
    command = SPIN
    found = samples_module.build(command, [_table(t, omega)], sigma=sigma, fitted=["friction", "viscous", "omega0"], given={"inertia"})
    model, starts, _ = solve.model_of(command, {"inertia": "0.1 kg*m^2"}, ["friction", "viscous", "omega0"], found)
    return model, starts


def test_the_fit_on_arrays_gives_the_report_the_per_sample_path_gives():
    t, omega = _coast(200, 1)
    fast, starts = _model(t, omega)
    assert fast.arrays is not None
    slow, _ = _model(t, omega)
    slow.arrays = None  # the per-sample path, as before #45
    with np.errstate(all="ignore"):
        a, b = solve.fit(fast, dict(starts)), solve.fit(slow, dict(starts))
    assert np.allclose(a.p, b.p, rtol=1e-9, atol=0)
    assert np.allclose(a.covariance, b.covariance, rtol=1e-6, atol=0)
    assert a.steps[-1].why == b.steps[-1].why  # the steps and the solves per sample, as counted before


def test_a_fit_of_a_hundred_thousand_samples_is_taken_and_right(tmp_path):
    """Refused before #45 (at most 5000 samples); each input within 3σ of the truth."""
    t, omega = _coast(100_000, 2)
    path = tmp_path / "coast.csv"
    path.write_text("t (s),omega (rad/s)\n" + "".join(f"{a!r},{w!r}\n" for a, w in zip(t.tolist(), omega.tolist())))
    report = api.fit("spin-down", str(path), fit="friction,viscous,omega0", inertia="0.1 kg*m^2", sigma="0.05 rad/s")
    assert report.results["samples"].value == 100_000
    for name, truth in (("friction", 0.05), ("viscous", 0.01), ("omega0", 30.0)):
        value, spread = report.results[name].value, report.uncertainties[name]
        assert 0 < spread < 1e-2 * truth and abs(value - truth) <= 3 * spread, (name, value, spread)


TABLES = [
    "t (s),omega (rad/s)\n" + "".join(f"{t / 10},{30 - t / 7:.6g}\n" for t in range(20_000)),
    "t;w (rad/s)\n" + "".join(f"{t};{t / 3:.4f}\n" for t in range(9000)) + "9000;1,5\n",  # a comma late: a point beside it, refused
    "t\tw (rad/s)\n" + "".join(f" {t}\t{-t}e-3 \n" for t in range(9000)) + "\n# a comment\n9001\t\n9002\tNaN\n",
    "t,w (rad/s)\n" + "".join(f"{t},{t}\n" for t in range(9000)) + "9000,1e400\n",
    "t,w (rad/s)\n" + "".join(f"{t},{t}\n" for t in range(9000)) + "9000,1e-400\n",
    "t,w (rad/s)\n" + "".join(f"{t},{t}\n" for t in range(8190)) + "1,-nan\n1,2,3\n",
    "t,w (rad/s)\n" + "".join(f"{t},{t}\n" for t in range(8191)) + "1,2\n1\n",
    "t,w (rad/s)\n" + "".join(f"{t},.{t}e+1\n" for t in range(10)) + '"1",2\n1_0,3\n',
]


def _read(text: str):
    try:
        table = data.read(io.StringIO(text))
    except InputError as err:
        return str(err)
    return [(c.header, c.name, c.unit, [repr(v) for v in c.values]) for c in table.columns], list(table.lines), table.decimal_comma  # (repr: NaN is NaN)


@pytest.mark.parametrize("text", TABLES)
def test_rows_read_a_batch_at_a_time_are_the_rows_read_one_by_one(text, monkeypatch):
    """#45 item 3: plain numbers a batch at a time (fast_rows), the same table, or the same
    refusal with its line, as row by row (every batch refused to the row-by-row reading)."""
    fast = _read(text)
    monkeypatch.setattr(fast_rows, "_batch", lambda *args: (None, None))
    assert fast == _read(text)


def _fast_and_slow(scene: str, held: dict, fitted: list[str], p: list[float], times, y_key: str):
    """The fit's model at p for samples at ``times``: on arrays (or the trajectory), and solved per sample."""
    from taucli.fit.samples import Samples

    found = Samples(y_key, "", [0.0] * len(times), {"time": [float(t) for t in times]})
    model, _, _ = solve.model_of(SCENES[scene], dict(held), fitted, found)
    assert model.arrays is not None
    fast = model.predict(np.array(p))
    assert not model.arrays.failed, f"the arrays were refused: {scene} {held} {p}"
    model.arrays, model._cache = None, {}
    return fast, model.predict(np.array(p))


def test_a_pendulums_swing_read_from_its_own_state_agrees_with_the_scene():
    """θ(t) and ω(t) of a pendulum at every sample from the scene's own elliptic motion, set up
    once per trial (Traced), against a solve per sample: to the last bits."""
    rng = np.random.default_rng(7)
    for _ in range(12):
        held = {"shape": "point", "mass": "1 kg", "radius": f"{rng.uniform(0.2, 3)} m", "angle0": f"{rng.uniform(1, 179)} deg"}
        times = np.sort(rng.uniform(0, 8, 25))
        for y_key in ("theta", "omega"):
            fast, slow = _fast_and_slow("pendulum", held, ["g"], [rng.uniform(2, 20)], times, y_key)
            assert np.all(np.isfinite(slow)) and np.allclose(fast, slow, rtol=1e-12, atol=1e-12 * np.max(np.abs(slow)))


def test_an_atwood_machines_travel_read_from_its_own_state_agrees_with_the_scene():
    rng = np.random.default_rng(8)
    for _ in range(12):
        held = {"m2": f"{rng.uniform(0.1, 3)} kg", "pulley_mass": f"{rng.uniform(0, 1)} kg", "pulley_radius": "5 cm",
                "axle_friction": f"{rng.uniform(0, 0.05)} N*m"}
        times = np.sort(rng.uniform(0, 5, 20))
        for y_key in ("v", "distance"):
            fast, slow = _fast_and_slow("atwood", held, ["m1"], [rng.uniform(0.1, 3)], times, y_key)
            assert np.all(np.isfinite(slow)) and np.allclose(fast, slow, rtol=1e-12, atol=1e-12 * np.max(np.abs(slow)))


@pytest.mark.parametrize("method", ["rk45", "rk4", "auto"])
def test_spin_down_under_a_stepping_method_is_stepped_once_through_the_samples(method):
    """A drag exponent's motion stepped once through the sample times (rk45: SpinDown; a fixed
    step: the trajectory's sampler), within the stepper's own error of a solve per sample."""
    held = {"inertia": "0.2 kg*m^2", "friction": "0.02 N*m", "drag": "0.003 N*m*s^2", "drag_exponent": "1.5", "method": method}
    if method == "rk4":
        held["dt"] = "5 ms"
    fast, slow = _fast_and_slow("spin-down", held, ["omega0"], [40.0], np.linspace(0, 25, 30), "omega")
    assert np.allclose(fast, slow, rtol=0, atol=1e-8 * np.max(np.abs(slow)))


def _periods(held: dict, fitted: list[str], p: list[float], angles):
    from taucli.fit.samples import Samples

    found = Samples("period", "s", [1.0] * len(angles), {"angle0": [float(a) for a in angles]})
    model, _, _ = solve.model_of(SCENES["pendulum"], dict(held), fitted, found)
    fast = model.predict(np.array(p))
    used = model.arrays is not None and not model.arrays.failed
    model.arrays, model._cache = None, {}
    return used, fast, model.predict(np.array(p))


@pytest.mark.parametrize("method", ["auto", "small-angle"])
def test_a_pendulums_periods_at_every_amplitude_agree_with_the_scene(method):
    """T(θ₀ᵢ) = T(θ₀ₐ)·K(kᵢ)/K(kₐ) from one solve (and one check) per trial, against a solve per
    sample, for bodies of every kind; to 1e-12."""
    rng = np.random.default_rng(9)
    bodies = [{"shape": "point", "mass": "50 g", "radius": "0.8 m"}, {"shape": "rod", "mass": "1 kg", "length": "1 m", "cm_distance": "0.5 m"},
              {"shape": "disc", "mass": "2 kg", "radius": "0.2 m", "cm_distance": "0.5 m"}]
    for body in bodies:
        held = {**body, "method": method}
        angles = np.radians(rng.uniform(-170, 170, 15))
        used, fast, slow = _periods(held, ["g"], [rng.uniform(2, 20)], angles)
        assert used and np.allclose(fast, slow, rtol=1e-12, atol=0), (held, np.max(np.abs(fast / slow - 1)))


def test_a_period_not_of_that_form_is_solved_per_sample():
    """A torsion spring besides gravity: the period is not 4K(k)/ω₀ₙ, the check sees it."""
    held = {"shape": "point", "mass": "50 g", "radius": "1 m", "torsion": "0.3 N*m/rad"}
    used, fast, slow = _periods(held, ["g"], [9.8], np.radians([10, 40, 80, 120]))
    assert not used and np.array_equal(fast, slow)
