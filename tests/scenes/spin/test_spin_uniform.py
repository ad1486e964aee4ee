"""spin-down at constant α (--alpha, or no body) and the torque a target needs (--in-time).

References are written from the physics at 40 digits (mpmath): ω = ω₀ + αt, θ = ∫ω dt by
quadrature, and the time at an angle by a root-finder on that integral, never by the solver's
quadratic formula.
"""

from __future__ import annotations

import math

import mpmath
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import taucli
from taucli.core.errors import InputError
from taucli.scenes.spin.kinematics import Uniform

mp = mpmath.mp
TWO_PI = 2 * math.pi


def values(report):
    return {name: value.value for name, value in report.results.items()}


def theta_reference(w0, alpha, t):
    with mp.workdps(40):
        return mpmath.quad(lambda s: mpmath.mpf(w0) + mpmath.mpf(alpha) * s, [0, t])


def test_fan_from_100_to_500_rpm_in_10_s():
    """A fan from 100 to 500 rpm in 10 s: α = 4.19 rad/s², 50 revolutions (the book's answers)."""
    result = values(taucli.spin_down(omega0="100 rpm", until_omega="500 rpm", time="10 s"))
    assert result["alpha"] == pytest.approx(400 * TWO_PI / 60 / 10, rel=1e-14)
    assert result["revs"] == pytest.approx(50.0, rel=1e-14)
    assert round(result["alpha"], 2) == 4.19


def test_torque_to_bring_a_disc_to_1000_rpm_in_3_s():
    """20 kg, 0.5 m disc to 1000 rpm in 3 s: I = 2.5 kg·m², α = 34.9 rad/s², τ = 87.3 N·m."""
    result = values(taucli.spin_down(shape="disc", mass="20 kg", radius="0.5 m", until_omega="1000 rpm", in_time="3 s"))
    assert result["torque"] == pytest.approx(2.5 * 1000 * TWO_PI / 60 / 3, rel=1e-14)
    assert result["torque_net"] == result["torque"]
    assert round(result["torque"], 1) == 87.3
    with_friction = values(taucli.spin_down(shape="disc", mass=20, radius=0.5, until_omega="1000 rpm", in_time=3, friction=2))
    assert with_friction["torque"] == pytest.approx(result["torque"] + 2, rel=1e-14)
    assert with_friction["work_friction"] == pytest.approx(2 * with_friction["theta"], rel=1e-14)


def test_torque_with_viscous_loss_meets_the_target():
    """The drive found by bisection, run forward, reaches ω₁ at t (a reference from quadrature)."""
    result = values(taucli.spin_down(inertia=2.5, until_omega=100, in_time=3, viscous=0.05, friction=1))
    drive = result["torque"]
    with mp.workdps(40):
        a, b, i = mpmath.mpf(drive) - 1, mpmath.mpf("0.05"), mpmath.mpf("2.5")
        # I dω/dt = a − bω from rest: ω(t) = (a/b)(1 − e^(−bt/I))
        omega = a / b * -mpmath.expm1(-b * 3 / i)
    assert float(omega) == pytest.approx(100, rel=1e-13)


@pytest.mark.parametrize(
    ("given_", "unknown"),
    [
        (dict(omega0=3.0, alpha=2.0, time=4.0), None),
        (dict(omega0=3.0, until_omega=11.0, time=4.0), "alpha"),
        (dict(omega0=3.0, until_angle=28.0, time=4.0), "alpha"),
        (dict(omega0=3.0, until_omega=11.0, until_angle=28.0), "alpha"),
        (dict(alpha=2.0, until_omega=11.0, time=4.0), "omega0"),
        (dict(alpha=2.0, until_angle=28.0, time=4.0), "omega0"),
        (dict(alpha=2.0, until_omega=11.0, until_angle=28.0), "omega0"),
        (dict(until_omega=11.0, until_angle=28.0, time=4.0), "omega0 alpha"),
    ],
)
def test_any_three_give_the_rest(given_, unknown):
    """ω₀ = 3, α = 2, t = 4: ω₁ = 11, θ = 28; any three of the five give the others."""
    result = values(taucli.spin_down(**given_))
    assert result["alpha"] == pytest.approx(2.0, rel=1e-14)
    assert result["omega"] == pytest.approx(11.0, rel=1e-14)
    assert result["theta"] == pytest.approx(28.0, rel=1e-14)
    if "time" not in given_:
        assert result["t_until"] == pytest.approx(4.0, rel=1e-14)
    if unknown and "omega0" in unknown and "alpha" in given_:
        assert result["omega0"] == pytest.approx(3.0, rel=1e-14)


def test_four_of_five_is_refused():
    with pytest.raises(InputError, match="too many"):
        taucli.spin_down(omega0=3, until_omega=11, until_angle=28, time=4)


def test_turning_back_through_zero():
    """α = −2 from ω₀ = 10: the first stop at 5 s after 25 rad; at 8 s ω = −6, θ = 16 rad."""
    report = taucli.spin_down(alpha=-2, omega0=10, time=8)
    result = values(report)
    assert (result["t_stop"], result["theta_stop"]) == (5.0, 25.0)
    assert result["omega"] == -6.0 and result["theta"] == 16.0
    assert any("turns back" in note for note in report.notes)


def test_two_roots_the_earlier_answer_and_the_later_noted():
    report = taucli.spin_down(alpha=-2, omega0=10, until_angle=20)
    t = values(report)["t_until"]
    assert t == pytest.approx(5 - math.sqrt(5), rel=1e-15)
    assert any("7.236" in note for note in report.notes)
    never = taucli.spin_down(alpha=-2, omega0=10, until_angle=30)
    assert values(never)["t_until"] is None and any("never reaches" in note for note in never.notes)
    back = taucli.spin_down(alpha=-2, omega0=10, until_angle=-11)
    assert values(back)["t_until"] == pytest.approx(5 + 6, rel=1e-15)
    assert any("turns back first" in note for note in back.notes)


finite = st.floats(-1e3, 1e3, allow_nan=False).filter(lambda x: abs(x) > 1e-3)
speed = st.one_of(st.just(0.0), st.floats(-1e3, 1e3).filter(lambda x: abs(x) > 1e-6))


@settings(max_examples=300, deadline=None)
@given(w0=speed, alpha=finite, t=st.floats(1e-3, 1e3))
def test_until_angle_then_time_returns_the_angle(w0, alpha, t):
    """θ(t) from quadrature at 40 digits; --until-angle that θ gives a t at which the motion is
    at θ (the earliest such t), and --time at it returns θ."""
    theta = float(theta_reference(w0, alpha, t))
    assume(abs(theta) > 1e-6)
    motion = Uniform(w0, alpha)
    found = values(taucli.spin_down(alpha=alpha, omega0=w0, until_angle=theta))["t_until"]
    assert found is not None and found <= t * (1 + 1e-9)
    back = float(theta_reference(w0, alpha, found))
    assert back == pytest.approx(theta, rel=1e-9, abs=1e-9 * (abs(w0) * t + abs(alpha) * t * t))
    assert motion.theta(found) == pytest.approx(theta, rel=1e-9, abs=1e-9 * (abs(w0) * t + abs(alpha) * t * t))


@settings(max_examples=200, deadline=None)
@given(w0=speed, alpha=finite, theta=st.floats(-1e5, 1e5).filter(lambda x: abs(x) > 1e-3))
def test_both_roots_satisfy_the_angle_equation(w0, alpha, theta):
    """Each root t of ½αt² + ω₀t = θ, checked in 40-digit arithmetic; the earlier is first."""
    roots = Uniform(w0, alpha).times_at_angle(theta)
    with mp.workdps(40):
        for t in roots:
            residual = mpmath.mpf(w0) * t + mpmath.mpf(alpha) * t * t / 2 - theta
            assert abs(residual) <= 1e-12 * (abs(theta) + abs(w0 * t) + abs(alpha) * t * t)
    assert roots == sorted(roots)
    discriminant = w0 * w0 + 2 * alpha * theta
    if discriminant > 1e-9 * (w0 * w0 + abs(2 * alpha * theta)):
        expected = sum(1 for sign in (1, -1) if (-w0 + sign * math.sqrt(discriminant)) / alpha > 0)
        assert len(roots) == expected


@settings(max_examples=200, deadline=None)
@given(inertia=st.floats(1e-3, 1e3), w0=speed, alpha=finite, t=st.floats(1e-3, 100), friction=st.one_of(st.just(0.0), st.floats(1e-6, 100)))
def test_energy_balance_at_constant_alpha(inertia, w0, alpha, t, friction):
    """KE0 − KE = Σ losses − work_drive, to 1e-12 of the largest term."""
    result = values(taucli.spin_down(inertia=inertia, alpha=alpha, omega0=w0, time=t, friction=friction))
    losses = result.get("work_friction") or 0.0
    scale = max(result["KE0"], result["KE"], losses, abs(result["work_drive"]))
    assert result["KE0"] - result["KE"] == pytest.approx(losses - result["work_drive"], abs=1e-12 * scale)
    assert losses >= 0


def test_held_at_constant_speed():
    """--alpha 0 with losses: the drive balances them, τ = τ_f + bω, P = τω."""
    result = values(taucli.spin_down(inertia=2, alpha=0, omega0=100, friction=2, viscous=0.1, time=10))
    assert result["torque"] == pytest.approx(12.0, rel=1e-15)
    assert result["power"] == pytest.approx(1200.0, rel=1e-15)
    assert result["work_viscous"] == pytest.approx(0.1 * 100**2 * 10, rel=1e-15)
    assert result["work_drive"] == pytest.approx(result["work_viscous"] + result["work_friction"], rel=1e-15)


def test_units_do_not_change_the_answer():
    a = values(taucli.spin_down(omega0="100 rpm", until_omega="500 rpm", until_angle="50 rev"))
    b = values(taucli.spin_down(omega0=100 * TWO_PI / 60, until_omega=500 * TWO_PI / 60, until_angle=50 * TWO_PI))
    assert a["t_until"] == pytest.approx(b["t_until"], rel=1e-14) and a["t_until"] == pytest.approx(10, rel=1e-14)


def test_a_rim_speed_for_omega0():
    """A tyre of radius 0.3 m at 20 m/s: ω₀ = v/R = 66.7 rad/s, with a note; --radius beside --inertia too."""
    by_shape = taucli.spin_down(shape="ring", mass=1, radius="30 cm", rim_speed="20 m/s", friction=1)
    by_inertia = taucli.spin_down(inertia=0.09, radius=0.3, rim_speed=20, friction=1)
    for report in (by_shape, by_inertia):
        assert report.results["omega0"].value == pytest.approx(20 / 0.3, rel=1e-15)
        assert report.results["t_stop"].value == pytest.approx(0.09 * 20 / 0.3, rel=1e-14)
        assert any("v/R" in note for note in report.notes)
    with pytest.raises(InputError, match="needs a radius"):
        taucli.spin_down(inertia=0.09, rim_speed=20)
    with pytest.raises(InputError, match="conflicts"):
        taucli.spin_down(inertia=0.09, radius=0.3, rim_speed=20, omega0=3)


def test_omega0_from_stored_energy():
    """A flywheel of I = 2 kg·m² storing 1 MJ turns at √(2E/I) = 1000 rad/s."""
    report = taucli.spin_down(inertia=2, ke0="1 MJ", friction=1)
    assert report.results["omega0"].value == pytest.approx(1000, rel=1e-15)
    assert report.results["KE0"].value == pytest.approx(1e6, rel=1e-15)
    assert report.results["work_friction"].value == pytest.approx(1e6, rel=1e-13)


def test_in_time_to_an_angle_with_a_viscous_loss():
    """From rest, drive a against b: θ(t) = (a/b)(t − (I/b)(1 − e^(−bt/I))); the drive found meets θ at t."""
    result = values(taucli.spin_down(inertia=1, until_angle=3, in_time=2, viscous=1))
    with mp.workdps(40):
        a = mpmath.mpf(result["torque"])
        theta = a * (2 + mpmath.expm1(-2))
    assert float(theta) == pytest.approx(3, rel=1e-13)


def test_in_time_to_an_angle_at_constant_alpha_with_a_body():
    """10 rev in 5 s from rest: α = 2θ/t², τ = Iα + τ_f."""
    result = values(taucli.spin_down(inertia=0.5, until_angle="10 rev", in_time="5 s", friction=0.2))
    alpha = 2 * 10 * TWO_PI / 25
    assert result["alpha"] == pytest.approx(alpha, rel=1e-14)
    assert result["torque"] == pytest.approx(0.5 * alpha + 0.2, rel=1e-14)
