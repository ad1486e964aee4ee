"""#46 item 3: a spin-down run as a schedule of phases (--phase, in order). Cutnell & Johnson's ship
propeller: from rest 2.90e-3 rad/s² for 2.10e3 s, then 1.40e3 s at constant speed, then −2.30e-3
rad/s² until it slows to 4.00 rad/s: 1.95e4 rad in all. Before, --phase was not an option.

The reference is the physics in mpmath: α(t) piecewise constant, ω(t) = ω₀ + ∫α, θ = ∫ω by
mpmath's quadrature with the phase boundaries as break points, and each end that is a speed or
an angle found by mpmath.findroot on ω(t) or θ(t) (not by the solver's closed forms).
"""

from __future__ import annotations

import json
import random

import mpmath
import pytest

import taucli
from conftest import assert_usage_error, run_taucli

MP_DPS = 30
PROPELLER = ("alpha=2.90e-3rad/s^2 time=2.10e3s", "coast time=1.40e3s", "alpha=-2.30e-3rad/s^2 until-omega=4.00rad/s")


def run_of(alphas_and_ends, omega0):
    """(t_k, ω(t_k), θ(t_k)) at each phase's end: each α constant over its phase; an end given as
    a time is added, one given as a speed or an angle found by findroot on ω or θ within it."""
    t0, w0, th0, out = mpmath.mpf(0), mpmath.mpf(omega0), mpmath.mpf(0), []
    for alpha, kind, value in alphas_and_ends:
        alpha = mpmath.mpf(alpha)

        def omega(s, t0=t0, w0=w0, alpha=alpha):
            return w0 + mpmath.quad(lambda u: alpha, [t0, s])

        def theta(s, t0=t0, th0=th0, omega=omega):
            return th0 + mpmath.quad(omega, [t0, s])

        if kind == "time":
            t1 = t0 + value
        elif kind == "omega":
            t1 = mpmath.findroot(lambda s: omega(s) - value, t0 + (value - w0) / alpha * mpmath.mpf("1.001"))
        else:
            t1 = mpmath.findroot(lambda s: theta(s) - th0 - value, t0 + mpmath.mpf(1))
        out.append((t1, omega(t1), theta(t1)))
        t0, w0, th0 = t1, omega(t1), theta(t1)
    return out


def test_cutnell_johnsons_propeller():
    done = run_taucli("spin-down", *[arg for phase in PROPELLER for arg in ("--phase", phase)], "--json")
    assert done.code == 0, done.err
    doc = done.json()
    want = run_of([(2.90e-3, "time", 2100), (0, "time", 1400), (-2.30e-3, "omega", 4)], 0)
    res = doc["results"]
    assert abs(res["theta"]["value"] - float(want[-1][2])) < 1e-9 * 2e4 and f"{res['theta']['value']:.3g}" == "1.95e+04"
    assert res["omega"]["value"] == pytest.approx(4.0, rel=1e-14) and res["t_run"]["value"] == pytest.approx(float(want[-1][0]), rel=1e-12)
    assert [round(row["theta"], 1) for row in doc["phases"]] == [6394.5, 8526.0, 4584.4]  # each phase's θ, in the JSON document too
    assert doc["phases"][2]["omega_end"] == 4.0 and doc["phases"][1]["alpha"] == 0.0


def test_the_table_of_phases_holds_each_phases_numbers():
    report = taucli.spin_down(phase=list(PROPELLER))
    rows = report.tables["phases"].rows
    want = run_of([(2.90e-3, "time", 2100), (0, "time", 1400), (-2.30e-3, "omega", 4)], 0)
    before = mpmath.mpf(0)
    for row, (t1, w1, th1) in zip(rows, want):
        assert row[5] == pytest.approx(float(w1), rel=1e-12) and row[6] == pytest.approx(float(th1 - before), rel=1e-12)
        before = th1
    assert [round(row[6], 1) for row in rows] == [6394.5, 8526.0, 4584.4]


@pytest.mark.parametrize("seed", range(15))
def test_random_schedules_against_mpmath(seed):
    """Random rates and ends (a time, a speed reached, an angle) and the class's balances: ω is
    continuous across phases, ω₁² = ω_s² + 2αθ in each, Σθᵢ = θ, Σtᵢ = t_run, and with a body
    KE − KE₀ = Σ τᵢθᵢ (the work of each phase's torque)."""
    rng = random.Random(seed)
    omega0, w, specs, plan = rng.uniform(0, 5), None, [], []
    w = omega0
    inertia = 10 ** rng.uniform(-1, 1)
    for _ in range(rng.randint(1, 4)):
        alpha = rng.uniform(-2, 2)
        kind = rng.choice(("time", "omega", "angle"))
        if kind == "time":
            value = rng.uniform(0.1, 3)
            end = f"time={value!r}s"
        elif kind == "omega":
            value = w + alpha * rng.uniform(0.1, 3)
            end = f"until-omega={value!r}rad/s"
        else:
            alpha = abs(alpha)  # speeding up: every angle is reached
            t = rng.uniform(0.1, 3)
            value = w * t + alpha * t * t / 2
            end = f"angle={value!r}rad"
        rate = f"torque={alpha * inertia!r}N*m" if rng.random() < 0.4 else f"alpha={alpha!r}rad/s^2"
        specs.append(f"{rate} {end}")
        plan.append((alpha, kind, value))
        if kind == "time":
            w = w + alpha * value
        elif kind == "omega":
            w = value
        else:
            w = (w * w + 2 * alpha * value) ** 0.5
    report = taucli.spin_down(phase=specs, inertia=inertia, omega0=f"{omega0!r} rad/s")
    res, rows = report.results, report.tables["phases"].rows
    want = run_of(plan, omega0)
    scale = 10 + abs(omega0) * 12
    assert abs(res["theta"].value - float(want[-1][2])) <= 1e-11 * scale * 12 and abs(res["omega"].value - float(want[-1][1])) <= 1e-11 * scale
    assert res["t_run"].value == pytest.approx(sum(row[3] for row in rows), rel=1e-14, abs=1e-14)
    assert res["theta"].value == pytest.approx(sum(row[6] for row in rows), rel=1e-13, abs=1e-12)
    work = 0.0
    for previous, row in zip((None, *rows), rows):
        if previous is not None:
            assert row[4] == previous[5]  # continuous
        assert row[5] ** 2 == pytest.approx(row[4] ** 2 + 2 * row[2] * row[6], rel=1e-11, abs=1e-11 * scale * scale)
        work += inertia * row[2] * row[6]
    assert res["KE"].value - res["KE0"].value == pytest.approx(work, rel=1e-10, abs=1e-10 * inertia * scale * scale)


def test_the_same_in_other_units_and_by_batch():
    si = taucli.spin_down(phase=list(PROPELLER)).results
    other = taucli.spin_down(phase=[f"alpha={2.90e-3 * 60 / 6.283185307179586 * 60!r}rpm/min time=35min", "coast time=1.40e6ms",
                                     f"alpha={-2.30e-3 / 6.283185307179586!r}rev/s^2 until-omega={4 * 60 / 6.283185307179586!r}rpm"]).results
    for key in ("theta", "omega", "t_run"):
        assert other[key].value == pytest.approx(si[key].value, rel=1e-12), key
    line = json.dumps({"phase": list(PROPELLER)})
    batch = json.loads(run_taucli("spin-down", "--batch", stdin=line + "\n").out)
    assert batch["results"]["theta"]["value"] == si["theta"].value


def test_alpha_from_two_ends_and_time_within_the_run():
    """A phase given by two ends (time= until-omega=; angle= until-omega=; time= angle=), and --time inside the run."""
    report = taucli.spin_down(phase=["time=4s until-omega=8rad/s", "angle=12rad until-omega=0", "time=2s angle=-2rad"], time="5 s")
    rows = report.tables["phases"].rows
    assert rows[0][2] == 2.0 and rows[1][2] == pytest.approx(-64 / 24) and rows[1][3] == pytest.approx(3.0) and rows[2][2] == pytest.approx(-1.0)
    assert report.results["omega"].value == pytest.approx(8 - 64 / 24) and report.results["theta"].value == pytest.approx(16 + 8 - 32 / 24 / 1)


@pytest.mark.parametrize("phases, extra, fragments", [
    (("alpha=1rad/s^2",), (), ("--phase", "one end")),
    (("alpha=1rad/s^2 torque=1N*m time=1s",), (), ("--phase", "one rate")),
    (("alpha=-1rad/s^2 until-omega=5rad/s",), (), ("--phase", "never reaches")),
    (("torque=1N*m time=1s",), (), ("--phase", "needs the body")),
    (("alpha=1rad/s^2 time=1s speed=2",), (), ("--phase", "knows")),
    (("brake time=1s",), (), ("--phase", "coast")),
    (("alpha=1 time=1s",), (), ("--phase",)),
    (("alpha=1rad/s^2 time=1s",), ("--friction", "1N*m", "--inertia", "1kg*m^2"), ("--friction", "--phase")),
    (("alpha=1rad/s^2 time=1s",), ("--time", "2s"), ("--time", "after the run ends")),
    (("alpha=-1rad/s^2 angle=10rad",), (), ("--phase", "never turns")),
])
def test_refusals(phases, extra, fragments):
    assert_usage_error(run_taucli("spin-down", *[arg for phase in phases for arg in ("--phase", phase)], *extra), *fragments)
