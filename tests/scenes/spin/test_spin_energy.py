"""spin-down energy, work and power: each against a 40-digit reference from the physics.

While a wheel moves one way, dt = I dω/τ(ω), so the work of a torque T(ω) over the motion is
∫T ω dt = I ∫ T(ω) ω/τ(ω) dω: quadrature over ω, independent of the solver's closed forms.
"""

from __future__ import annotations

import math

import mpmath
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import taucli
from taucli.scenes.spin import Torques, solve

mp = mpmath.mp


def values(report):
    return {name: value.value for name, value in report.results.items()}


def works_reference(inertia, drive, friction, viscous, drag, omega0, omega1, exponent=2):
    """Work of the drive and of each loss while ω goes from ω₀ to ω₁ (one way, ω ≥ 0)."""
    with mp.workdps(40):
        i, a, f, b, k = (mpmath.mpf(x) for x in (inertia, drive, friction, viscous, drag))

        def net(w):
            return a - f - b * w - k * w**exponent

        def work(torque):
            return i * mpmath.quad(lambda w: torque(w) * w / net(w), [omega0, omega1])

        return {
            "drive": float(work(lambda w: a)),
            "friction": float(work(lambda w: f)),
            "viscous": float(work(lambda w: b * w)),
            "drag": float(work(lambda w: k * w**exponent)),
        }


CASES = [  # inertia, friction, viscous, drag, exponent, ω₀
    (0.1, 0.3, 0.0, 0.0, 2, 30.0),
    (0.1, 0.3, 0.01, 0.0, 2, 30.0),
    (0.1, 0.0, 0.0, 0.001, 2, 30.0),
    (0.1, 0.3, 0.01, 0.001, 2, 30.0),
    (2.0, 1.0, 0.05, 0.002, 3, 100.0),
]


@pytest.mark.parametrize("case", CASES)
def test_work_of_each_loss_until_it_stops(case):
    inertia, friction, viscous, drag, exponent, omega0 = case
    result = values(solve(inertia, Torques(0.0, friction, viscous, drag, exponent), omega0, energy=True))
    if result["t_stop"] is None:  # drag alone never stops it: up to --time instead
        return
    ref = works_reference(inertia, 0.0, friction, viscous, drag, omega0, 0.0, exponent)
    rel = 1e-12 if exponent == 2 else 1e-8
    for name in ("friction", "viscous", "drag"):
        if getattr(Torques(0.0, friction, viscous, drag), name):
            assert result["work_" + name] == pytest.approx(ref[name], rel=rel)
    assert result["KE0"] == pytest.approx(inertia * omega0**2 / 2, rel=1e-15)


def test_work_up_to_a_time_against_quadrature():
    """Driven against viscous and quadratic drag, up to t = 2 s: ω₁ from the run, works from ω₀ to ω₁."""
    report = values(solve(0.5, Torques(3.0, 0.2, 0.01, 0.002), 5.0, time=2.0, energy=True))
    ref = works_reference(0.5, 3.0, 0.2, 0.01, 0.002, 5.0, report["omega"])
    for name in ("drive", "friction", "viscous", "drag"):
        assert report["work_" + name] == pytest.approx(ref[name], rel=1e-11)
    assert report["power"] == pytest.approx(3.0 * report["omega"], rel=1e-15)
    assert report["power_mean"] == pytest.approx(report["work_drive"] / 2, rel=1e-15)


def test_flywheel_energy_and_the_friction_that_takes_it():
    """A 4 kg·m² flywheel at 6000 rpm stores ½Iω² = 789.6 kJ; friction takes all of it."""
    result = values(taucli.spin_down(inertia="4 kg*m^2", omega0="6000 rpm", friction="0.5 N*m", energy=True))
    omega = 6000 * 2 * math.pi / 60
    assert result["KE0"] == pytest.approx(2 * omega**2, rel=1e-15)
    assert result["work_friction"] == pytest.approx(result["KE0"], rel=1e-14)
    assert result["KE"] == 0.0


small = st.one_of(st.just(0.0), st.floats(1e-4, 1.0))


@settings(max_examples=150, deadline=None)
@given(
    inertia=st.floats(1e-2, 10),
    drive=st.one_of(st.just(0.0), st.floats(-5, 5).filter(lambda x: abs(x) > 1e-4)),
    friction=small,
    viscous=small,
    drag=small,
    exponent=st.sampled_from([2.0, 1.5, 3.0]),
    omega0=st.one_of(st.just(0.0), st.floats(-50, 50).filter(lambda x: abs(x) > 1e-3)),
    time=st.one_of(st.none(), st.floats(1e-3, 20)),
)
def test_energy_balance(inertia, drive, friction, viscous, drag, exponent, omega0, time):
    """KE0 − KE = Σ losses − work_drive to 1e-12 of the largest term; each loss ≥ 0."""
    report = solve(inertia, Torques(drive, friction, viscous, drag, exponent), omega0, time=time, energy=True)
    result = values(report)
    assume("KE" in result and result["KE"] is not None)
    losses = [result.get("work_" + name) or 0.0 for name in ("friction", "viscous", "drag")]
    assert all(loss >= 0 for loss in losses)
    work_drive = result.get("work_drive") or 0.0
    scale = max(result["KE0"], result["KE"], *losses, abs(work_drive))
    tolerance = 1e-12 if exponent == 2 or not drag else 1e-8  # a method's own ω against its own θ
    assert result["KE0"] - result["KE"] == pytest.approx(sum(losses) - work_drive, abs=tolerance * scale)
