"""taucli pendulum against 50-digit references written from the physics (tests/references/pendulum.py).

Random scenes over many orders of magnitude, edges drawn on purpose (near the top, near the
speed that just reaches it, tiny swings, weak springs, a spring alone). Each result that has a
reference is held to a budget: 1e-13 for a closed form (elliptic functions under gravity alone,
energy for speeds and forces), widened by the condition of the problem where the inputs
themselves are ill-conditioned (a swing that turns near the top; a speed near a turning angle);
1e-8 for what rk45 (rtol 1e-10) integrates under gravity and a spring together (θ and ω at
a time: 1e-7 for each period run, as rk45's phase drifts).

Each disagreement this test found has its minimal call below; all are fixed, and the random test
checks every row (Row.known names a disagreement still open: none).
"""

from __future__ import annotations

import math
import random

import mpmath
import pytest

import taucli
from references import DPS, mp
from references.compare import rad, rad_s
from references.pendulum import Pendulum
from references.scenes_pendulum import check_pendulum, check_time, draw_pendulum


def _failures(rows):
    return [f"{r.name}: taucli {r.got!r}, reference {mpmath.nstr(r.exact, 17) if r.exact is not None and not isinstance(r.exact, bool) else r.exact}, "
            f"error {r.error:.3g} > {r.budget:.3g}" for r in rows if not r.known and not r.ok]


@pytest.mark.parametrize("seed", range(4))
def test_random_scenes_within_budget(seed):
    rng = random.Random(32_000 + seed)
    bad = []
    for _ in range(30):
        kw, ref, extra = draw_pendulum(rng)
        rows = check_pendulum(kw, ref, extra, with_time=not extra["stepped"])
        bad += [f"{kw}: {line}" for line in _failures(rows)]
    assert not bad, "\n".join(bad)


def test_theta_at_a_time_with_a_spring_and_gravity():
    """The Taylor-series solve is slow at 50 digits: a few scenes only (the benchmark draws more)."""
    rng = random.Random(32_100)
    bad = []
    for _ in range(3):
        kw, ref, extra = draw_pendulum(rng, kind="spring")
        extra["cycles"] = 0.6
        bad += [f"{kw}: {line}" for line in _failures(check_time(kw, ref, extra))]
    assert not bad, "\n".join(bad)


def test_the_reference_agrees_with_itself():
    """Elliptic forms, quadrature of dθ/ω and the Taylor solve give the same motion."""
    with mp.workdps(DPS):
        for theta0, omega0 in ((1.0, 0.3), (3.14159, 0.0), (0.5, -5.0)):
            ref = Pendulum(2.0, 1.0, 1.0, 9.80665, 0, theta0, omega0)
            assert abs(ref.period(method="quad") / ref.period() - 1) < mpmath.mpf(10) ** -45
            for target in (0.0, 0.3, -0.7):
                a, b = ref.reach(target), ref.reach(target, method="quad")
                assert abs(a[0] / b[0] - 1) < mpmath.mpf(10) ** -45 and a[1] == b[1]
            theta, omega = ref.at_time(2.7)
            theta2, omega2 = ref.at_time(2.7, method="taylor")
            assert abs(theta - theta2) < mpmath.mpf(10) ** -45 and abs(omega - omega2) < mpmath.mpf(10) ** -45


# -- disagreements found (and fixed): their minimal calls ------------------------------------------

ROD = dict(shape="rod", length="1m", mass="2kg", axis="end")


def test_omega_at_angle_is_signed():
    got = taucli.pendulum(**ROD, angle0="90deg", angle="30deg").results["omega"].value
    ref = Pendulum(2.0 / 3, 2.0, 0.5, 9.80665, 0, math.pi / 2, 0).reach(math.radians(30))
    assert got == pytest.approx(float(ref[1]), rel=1e-13, abs=0)  # −5.0476…, taucli +5.0476…


def test_point_tangential_acceleration_is_signed_along_the_motion():
    report = taucli.pendulum(**ROD, angle0="30deg", omega0="3 rad/s", at="1m")
    assert report.results["a_t0"].value == pytest.approx(-9.80665 * 0.5 * 2 * 0.5 / (2.0 / 3), rel=1e-13, abs=0)  # −7.354987…


def test_omega0_over_near_the_top():
    theta0 = math.pi - 1e-9
    got = taucli.pendulum(inertia=2.0, mass=1.0, cm_distance=1.0, angle0=rad(theta0)).results["omega0_over"].value
    with mp.workdps(DPS):
        exact = Pendulum(2.0, 1.0, 1.0, 9.80665, 0, theta0, 0).omega0_over()  # 2√λ cos(θ₀/2) ≈ 2.2e-9 rad/s
    assert got == pytest.approx(float(exact), rel=1e-13, abs=0)


def test_period_turning_near_the_top_with_a_weak_spring():
    omega0 = 3.892246642874735  # ω₀_over (1 + 1e-6): it passes θ = π and turns at 3.14278 rad
    got = taucli.pendulum(inertia=2.0, mass=1.0, cm_distance=1.0, torsion=0.01, angle0=rad(1.0), omega0=rad_s(omega0)).results["period"].value
    exact = Pendulum(2.0, 1.0, 1.0, 9.80665, 0.01, 1.0, omega0).period()  # 14.967647239159915 s
    assert got == pytest.approx(float(exact), rel=1e-8, abs=0)  # taucli 14.96761482920281 s


def test_an_angle_never_reached_has_no_omega():
    report = taucli.pendulum(inertia=2.0, mass=1.0, cm_distance=1.0, torsion=0.01, angle0="300deg", angle="-10deg")
    ref = Pendulum(2.0, 1.0, 1.0, 9.80665, 0.01, math.radians(300), 0)
    assert ref.reach(math.radians(-10)) is None and ref.reach(0) is None
    assert report.results["omega"].value is None and report.results["omega_bottom"].value is None


def test_a_long_period_is_not_null():
    omega0 = 4.275823304665028  # over the top, then ~6 turns each way before the weak spring brings it back
    got = taucli.pendulum(inertia=2.0, mass=1.0, cm_distance=1.0, torsion=1e-3, angle0=rad(1.0), omega0=rad_s(omega0)).results["period"].value
    exact = Pendulum(2.0, 1.0, 1.0, 9.80665, 1e-3, 1.0, omega0).period()  # 128.49199764302122863 s
    assert got is not None and got == pytest.approx(float(exact), rel=1e-8, abs=0)


@pytest.mark.xfail(strict=True, reason="a swing that turns within ~1e-6 of the top with a very weak spring: the energy integral's "
                   "period is 2.5e-8 off (budget 1e-8) and its own error estimate does not see it (found by the 1,000-scene benchmark)")
def test_a_period_turning_a_hair_short_of_the_top_keeps_its_digits():
    kw = dict(inertia=59.84011955553542, mass=2.390189791202276, cm_distance=0.49907442458024576, g=0.8671194369429736,
              torsion=1.5173761427181244e-06)
    angle0, omega0 = 0.5121694584949656, -0.2543748039812588  # E − U(π) ≈ −1e-9 of E: it turns just short of the top
    got = taucli.pendulum(**kw, angle0=rad(angle0), omega0=rad_s(omega0)).results["period"].value
    exact = Pendulum(kw["inertia"], kw["mass"], kw["cm_distance"], kw["g"], kw["torsion"], angle0, omega0).period()
    assert got == pytest.approx(float(exact), rel=1e-8, abs=0)
