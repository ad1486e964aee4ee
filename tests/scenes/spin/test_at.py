"""spin-down --at r (#24): a point's speed, accelerations and arc, against references written from
the kinematics of a point on a rigid body (v = ωr, a_t = αr, a_c = ω²r) with ω(t) and θ(t) from
the equation of motion solved by hand at 50 digits."""

from __future__ import annotations

import math

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taucli

MP_DPS = 50  # the references' precision, set for each test by conftest


def values(report):
    return {name: value.value for name, value in report.results.items()}


def test_point_on_a_flywheel_rim_two_seconds_after_starting():
    """A 0.5 m flywheel rim, from rest at α = 3 rad/s²: after 2 s, ω = 6 rad/s, v = 3 m/s,
    a_t = 1.5 m/s², a_c = 18 m/s², a = √(1.5² + 18²) = 18.06 m/s² at atan(1.5/18) from the radius."""
    result = values(taucli.spin_down(alpha="3rad/s^2", time="2s", at="0.5m"))
    r, alpha, t = mpmath.mpf("0.5"), mpmath.mpf(3), mpmath.mpf(2)
    omega = alpha * t
    assert result["v_t"] == pytest.approx(float(omega * r), rel=1e-15)
    assert result["a_t"] == pytest.approx(float(alpha * r), rel=1e-15)
    assert result["a_c"] == pytest.approx(float(omega**2 * r), rel=1e-15)
    assert result["a_total"] == pytest.approx(float(mpmath.sqrt((alpha * r) ** 2 + (omega**2 * r) ** 2)), rel=1e-15)
    assert result["a_angle"] == pytest.approx(float(mpmath.atan(alpha / omega**2)), rel=1e-15)
    assert result["s"] == pytest.approx(float(alpha * t**2 / 2 * r), rel=1e-15)
    # at the start, from rest: all the acceleration is tangential, a quarter turn from the radius
    assert result["v_t0"] == 0 and result["a_c0"] == 0
    assert result["a_total0"] == pytest.approx(1.5, rel=1e-15)
    assert result["a_angle0"] == pytest.approx(math.pi / 2, rel=1e-15)


def test_string_a_drum_winds_in_ten_turns():
    """A drum of radius 10 cm turning ten times winds s = 2π·r·10 = 6.283 m of string."""
    result = values(taucli.spin_down(omega0="30rpm", alpha=0, until_angle="10rev", at="10cm"))
    assert result["s"] == pytest.approx(float(2 * mpmath.pi * mpmath.mpf("0.1") * 10), rel=1e-15)


def test_friction_and_viscous_slowing_at_a_time():
    """I dω/dt = −τ_f − bω: ω(t) = (ω₀ + τ_f/b)·e^(−bt/I) − τ_f/b; the point slows, so a_t < 0 and
    the acceleration leans back from the radius (a_angle < 0)."""
    inertia, w0, tf, b, t, r = (mpmath.mpf(x) for x in ("2", "40", "0.5", "0.1", "3", "0.3"))
    result = values(taucli.spin_down(inertia=2, omega0=40, friction=0.5, viscous=0.1, time=3, at="30cm"))
    omega = (w0 + tf / b) * mpmath.exp(-b * t / inertia) - tf / b
    theta = mpmath.quad(lambda u: (w0 + tf / b) * mpmath.exp(-b * u / inertia) - tf / b, [0, t])
    a_t = -(tf + b * omega) / inertia * r
    assert result["v_t"] == pytest.approx(float(omega * r), rel=1e-12)
    assert result["a_t"] == pytest.approx(float(a_t), rel=1e-12)
    assert result["a_c"] == pytest.approx(float(omega**2 * r), rel=1e-12)
    assert result["a_angle"] == pytest.approx(float(mpmath.atan2(a_t, omega**2 * r)), rel=1e-12)
    assert result["a_angle"] < 0
    assert result["s"] == pytest.approx(float(theta * r), rel=1e-12)
    assert result["a_c0"] == pytest.approx(float(w0**2 * r), rel=1e-15)
    assert result["a_total0"] == pytest.approx(float(mpmath.hypot(-(tf + b * w0) / inertia * r, w0**2 * r)), rel=1e-15)


def test_turning_the_other_way_a_t_is_along_the_motion():
    """ω₀ < 0 and slowing: the speed is a size, a_t is still negative (it slows)."""
    result = values(taucli.spin_down(inertia=1, omega0=-10, friction=1, at="1m"))
    assert result["v_t"] == pytest.approx(10, rel=1e-15)
    assert result["a_t"] == pytest.approx(-1, rel=1e-15)


@settings(max_examples=40, deadline=None)
@given(
    inertia=st.floats(0.01, 100), omega0=st.floats(0.01, 500), friction=st.floats(0.01, 100), time=st.floats(0.01, 50),
    r=st.floats(0.001, 10), brake=st.booleans(),
)
def test_s_is_r_theta(inertia, omega0, friction, time, r, brake):
    """Property: s = r·θ, v_t = |ω|·r and a_c = ω²r at --time, with friction or the same brake."""
    losses = {"brake": f"force={friction!r}N mu=1 radius=1m"} if brake else {"friction": friction}
    result = values(taucli.spin_down(inertia=inertia, omega0=omega0, time=time, at=f"{r!r}m", **losses))
    assert result["s"] == pytest.approx(r * result["theta"], rel=1e-15)
    assert result["v_t"] == pytest.approx(r * abs(result["omega"]), rel=1e-15)
    assert result["a_c"] == pytest.approx(r * result["omega"] ** 2, rel=1e-15)


def test_units_do_not_matter():
    a = values(taucli.spin_down(inertia=1, omega0="300rpm", friction=2, time=1, at="50cm"))
    b = values(taucli.spin_down(inertia=1, omega0=10 * math.pi, friction=2, time=1, at="0.5m"))
    for key in a:
        assert a[key] == pytest.approx(b[key], rel=1e-14), key


def test_a_target_never_reached_gives_no_instant():
    report = taucli.spin_down(inertia=1, omega0=10, friction=1, until_omega=20, at="1m")
    assert report.results["v_t"].value is None and report.results["s"].value is None
    assert report.results["v_t0"].value == pytest.approx(10, rel=1e-15)
    assert any("does not reach" in note for note in report.notes)


def test_a_point_at_the_target_reached_in_a_given_time():
    """#32 item 3: --in-time with --until-omega and --at gave null ("the wheel does not reach the
    target"), though it does: α = (ω₁ − ω₀)/t = 5 rad/s², v_t = ω₁r at the target."""
    result = values(taucli.spin_down(inertia=1, friction="1 N*m", until_omega="10 rad/s", in_time="2 s", at="1 m"))
    assert result["v_t"] == pytest.approx(10.0, rel=1e-15)
    assert result["a_t"] == pytest.approx(5.0, rel=1e-15)
    assert result["a_c"] == pytest.approx(100.0, rel=1e-15)


@pytest.mark.parametrize("sign", [1, -1])
def test_a_point_from_rest_speeds_up_either_way(sign):
    """#32 item 3: from rest under a negative torque a_t was −1 and a_angle −π/2, where the wheel
    speeds up in the negative sense: a_t is along the motion, +1, at +π/2, as for a positive torque."""
    result = values(taucli.spin_down(inertia=1, torque=sign * 1.0, at="1 m"))
    assert result["a_t"] == 1.0
    assert result["a_angle"] == pytest.approx(math.pi / 2, rel=1e-15)


@pytest.mark.parametrize("t", [1.0, 10.0, 40.0, 200.0, 700.0])
def test_the_tangential_acceleration_near_a_steady_speed_keeps_its_digits(t):
    """#32 item 3: I = 1, τ = 1 N·m, b = 1 N·m·s: ω(t) = 1 − e^(−t), α(t) = e^(−t). a_t was
    (τ − bω(t))/I from a rounded ω(t): 0 at 40 s where it is e^(−40) = 4.25e-18, and of either sign
    later. Now within a few ulp of e^(−t) at r = 1 m."""
    got = values(taucli.spin_down(inertia=1, torque="1 N*m", viscous="1 N*m*s", time=t, at="1 m"))["a_t"]
    exact = mpmath.exp(-mpmath.mpf(t))
    assert got == pytest.approx(float(exact), rel=1e-14, abs=0)
