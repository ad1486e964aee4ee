"""spin-down with --power and --in-time against 50-digit references (tests/references/spin.py).

A constant power P against τ_f + bω + kω² by quadrature over ω (the steady speed's pole taken
away by ω = ω∞ − (ω∞ − ω₀)e^{−s}); the drive torque of --in-time by solving
T = ∫ I dω/(τ − L(ω)) for τ. taucli integrates these with rk45 (rtol 1e-10): budget 1e-8,
times the slowness of the approach to a steady speed (an error rtol·ω in ω moves the time by
rtol·ω/|dω/dt|); each work is held relative to the scene's whole energy, as the stepper's
norm holds it. Closed forms (no losses; friction alone) are held to 1e-13.
"""

from __future__ import annotations

import random

import mpmath
import pytest

import taucli
from references.spin import PowerMotion

from references.scenes_spin import check_spin, draw_spin

COUNTS = {"power_until": 12, "power_time": 8, "power_near_steady": 10, "load_stop": 10, "power_lossless": 20, "in_time": 3, "in_time_friction": 30}


@pytest.mark.parametrize("kind", sorted(COUNTS))
def test_random_scenes_within_budget(kind):
    rng = random.Random(f"spin-{kind}")
    bad = []
    for _ in range(COUNTS[kind]):
        kw, extra = draw_spin(rng, kind)
        bad += [f"{kw}: {r.name}: taucli {r.got!r}, reference {mpmath.nstr(r.exact, 17)}, error {r.error:.3g} > {r.budget:.3g}"
                for r in check_spin(kw, extra) if not r.known and not r.ok]
    assert not bad, "\n".join(bad)


def test_the_works_of_viscous_and_drag_under_a_load():
    kw = dict(inertia=1.7599471323725313, power=-0.16652331956453104, viscous=0.014962693871135892, drag=0.0030283791411783215)
    report = taucli.spin_down(**kw, omega0="927.0286450082666 rad/s")
    exact = PowerMotion(kw["inertia"], kw["power"], 0, kw["viscous"], kw["drag"], 927.0286450082666).to_omega(0)
    assert report.results["work_viscous"].value == pytest.approx(float(exact["work_viscous"]), rel=1e-8, abs=0)
    assert report.results["work_drag"].value == pytest.approx(float(exact["work_drag"]), rel=1e-8, abs=0)


@pytest.mark.parametrize("omega0, time", [
    (0.0, 40.0),  # from rest to within e^-… of the steady speed (ω* ≈ 9.9 rad/s): the approach is taken in time
    (0.0, 0.5),  # from rest, far from the steady speed
    (30.0, 3.0),  # from above the steady speed, down toward it
    (5000.0, 2.0),  # a fast fall from a high speed, where drag dominates, then near the steady speed
])
def test_the_works_of_viscous_and_drag_under_a_drive(omega0, time):
    kw = dict(inertia=0.5, power=10.0, viscous=0.02, drag=0.1, friction=0.05)
    report = taucli.spin_down(**kw, omega0=f"{omega0} rad/s", time=f"{time} s", energy=True)
    exact = PowerMotion(kw["inertia"], kw["power"], kw["friction"], kw["viscous"], kw["drag"], omega0).at_time(time)
    energy = max(float(exact["work_drive"]), kw["inertia"] * omega0**2 / 2)
    for name in ("work_viscous", "work_drag"):  # held to the stepper's budget of the whole energy (rtol 1e-10)
        assert abs(report.results[name].value - float(exact[name])) <= 1e-8 * energy, name


def test_a_motor_above_its_steady_speed_slows_to_a_target():
    kw = dict(inertia=0.5, power=10.0, viscous=0.02, drag=0.1, friction=0.05)
    motion = PowerMotion(kw["inertia"], kw["power"], kw["friction"], kw["viscous"], kw["drag"], 30.0)
    exact = motion.to_omega(15)  # ω* ≈ 4.5 rad/s: from 30 rad/s the wheel slows through 15
    report = taucli.spin_down(**kw, omega0="30 rad/s", until_omega="15 rad/s")
    assert report.results["t_until"].value == pytest.approx(float(exact["t"]), rel=1e-8, abs=0)
    assert report.results["theta_until"].value == pytest.approx(float(exact["theta"]), rel=1e-8, abs=0)
