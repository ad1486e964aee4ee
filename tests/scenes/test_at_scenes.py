"""--at r on atwood's pulley, on a rolling body and on a body given an impulse (#24).

Each is checked against the motion worked here from the physics in mpmath (not taucli's
formulas): the scene's own ω and α at the instant, then v = ωr, a_t = αr (along the motion),
a_c = ω²r, a = √(a_t² + a_c²), φ = atan2(a_t, a_c), s = rθ. A length written in other units
gives the same point.
"""

from __future__ import annotations

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taucli
from taucli.core.errors import InputError

MP_DPS = 40  # the references' precision, set for each test by conftest


def _values(report) -> dict:
    return {key: value.value for key, value in report.results.items()}


def _expect_point(found: dict, r, omega, alpha, theta, rel=1e-12):
    r, omega, alpha = mpmath.mpf(r), mpmath.mpf(omega), mpmath.mpf(alpha)
    a_t = (alpha if omega >= 0 else -alpha) * r
    a_c = omega**2 * r
    expected = {"v_t": abs(omega) * r, "a_t": a_t, "a_c": a_c, "a_total": mpmath.sqrt(a_t**2 + a_c**2)}
    if a_t or a_c:
        expected["a_angle"] = mpmath.atan2(a_t, a_c)
    if theta is not None:
        expected["s"] = r * mpmath.mpf(theta)
    for key, value in expected.items():
        assert found[key] == pytest.approx(float(value), rel=rel, abs=1e-300), key


@settings(max_examples=60, deadline=None)
@given(m1=st.floats(0.5, 10), m2=st.floats(0.1, 10), pulley_mass=st.one_of(st.just(0.0), st.floats(0.1, 5)), radius=st.floats(0.02, 0.5),
       at=st.floats(0.001, 1), t=st.floats(0.01, 3))
def test_a_point_on_atwoods_pulley(m1, m2, pulley_mass, radius, at, t):
    """From rest, a = (m1 − m2)g/(m1 + m2 + M/2) (a solid disc); at t: v = at, x = ½at²; the pulley
    turns with the string, ω = v/R, α = a/R, θ = x/R."""
    g = mpmath.mpf("9.80665")
    a = (mpmath.mpf(m1) - m2) * g / (mpmath.mpf(m1) + m2 + mpmath.mpf(pulley_mass) / 2)
    found = _values(taucli.atwood(m1=m1, m2=m2, pulley_mass=pulley_mass, pulley_radius=radius, time=t, at=at))
    _expect_point(found, at, a * t / radius, a / radius, a * t * t / 2 / radius, rel=1e-11)
    assert found["v_t0"] == 0 and found["a_total0"] == pytest.approx(float(abs(a) / radius * at), rel=1e-12)


def test_a_point_on_atwoods_pulley_after_the_masses_stop():
    """Past the stop the pulley's α is the motion's then, not the one the masses started with:
    0 where static friction holds them, the other phase's (the machine's from rest) where they
    turn back. Worked here: m1 4 kg, m2 1 kg, a 2 kg disc (M/2 = 1 kg) of radius 0.1 m, 0.5 N·m
    of axle friction (5 N at the rim); m1 thrown up at 1 m/s decelerates at (3g + 5 N)/6 kg, stops,
    and comes down at (3g − 5 N)/6 kg."""
    g = mpmath.mpf("9.80665")
    first, second = (3 * g + 5) / 6, (3 * g - 5) / 6
    stop = 1 / first
    t = 1
    found = _values(taucli.atwood(m1="4kg", m2="1kg", pulley_mass="2kg", pulley_radius="0.1m", axle_friction="0.5N*m", v0="-1m/s", time="1s", at="0.05m"))
    radius = mpmath.mpf("0.1")
    _expect_point(found, "0.05", second * (t - stop) / radius, second / radius, None)
    # m2 on a slope with μs 0.6 holds the masses once they stop: no tangential acceleration
    held = _values(taucli.atwood(m1="0.5kg", m2="5kg", pulley_radius="0.1m", incline="0.2rad", mu_k=0.5, mu_s=0.6, v0="1m/s", time="2s", at="0.1m"))
    assert held["v"] == 0 and held["v_t"] == 0 and held["a_t"] == 0 and held["a_total"] == 0 and held["a_angle"] is None


def test_atwoods_rim_moves_with_the_string_and_winds_what_the_masses_travel():
    found = _values(taucli.atwood(m1="4kg", m2="1kg", pulley_mass="2kg", pulley_radius="10cm", distance="1.5m", at="10cm"))
    assert found["v_t"] == pytest.approx(found["v"], rel=1e-14)
    assert found["a_t"] == pytest.approx(found["a"], rel=1e-14)
    assert found["s"] == pytest.approx(1.5, rel=1e-14)


def test_the_same_point_in_other_units():
    metres = _values(taucli.atwood(m1="4kg", m2="1kg", pulley_mass="2kg", pulley_radius="0.1m", time="1s", at="0.05m"))
    other = _values(taucli.atwood(m1="4000g", m2="1kg", pulley_mass="2kg", pulley_radius="10cm", time="1000ms", at="5cm"))
    for key in ("v_t", "a_t", "a_c", "a_total", "a_angle", "s"):
        assert other[key] == pytest.approx(metres[key], rel=1e-14)


def test_atwood_at_needs_the_pulleys_radius():
    with pytest.raises(InputError) as caught:
        taucli.atwood(m1="4kg", m2="1kg", at="5cm")
    assert caught.value.option == "at" and "pulley_radius" in str(caught.value)


@settings(max_examples=60, deadline=None)
@given(k2=st.sampled_from([0.4, 0.5, 1.0, 2 / 3]), angle=st.floats(0.1, 1.2), length=st.floats(0.1, 10), radius=st.floats(0.01, 1),
       at=st.floats(0.001, 1))
def test_a_point_of_a_body_rolling_down_a_slope(k2, angle, length, radius, at):
    """Rolling from rest: a = g sin θ/(1 + k²), v = √(2aL) at the bottom; ω = v/R, α = a/R, θ = L/R."""
    shape = {0.4: "sphere", 0.5: "disc", 1.0: "ring", 2 / 3: "shell"}[k2]
    g = mpmath.mpf("9.80665")
    a = g * mpmath.sin(angle) / (1 + mpmath.mpf(k2))
    v = mpmath.sqrt(2 * a * length)
    found = _values(taucli.rolling(shape, angle=angle, length=length, radius=radius, at=at))
    _expect_point(found, at, v / radius, a / radius, mpmath.mpf(length) / radius, rel=1e-11)


def test_a_point_of_a_skidding_ball_until_it_rolls():
    """A ball thrown along the floor with no spin: friction μk m g spins it up at α = μk g/(k²R) and
    slows it, until v = Rω at t = v0 k²/(μk g (1 + k²)), v = v0/(1 + k²); then it rolls (α = 0)."""
    v0, mu, radius, k2, g = mpmath.mpf(7), mpmath.mpf("0.2"), mpmath.mpf("0.1"), mpmath.mpf("0.4"), mpmath.mpf("9.80665")
    t_roll = v0 * k2 / (mu * g * (1 + k2))
    omega_roll = v0 / (1 + k2) / radius
    found = _values(taucli.rolling("sphere", v0="7m/s", mu_k=0.2, radius="10cm", at="10cm"))
    _expect_point(found, radius, omega_roll, 0, omega_roll * t_roll / 2)
    assert found["a_total0"] == pytest.approx(float(mu * g / (k2 * radius) * radius), rel=1e-12)
    assert found["v_t0"] == 0


def test_a_yo_yo_winds_off_its_string_at_the_axle():
    """A yo-yo dropped h: its axle's rim moves with the string, so s at r = axle is h."""
    found = _values(taucli.rolling("disc", yoyo=True, mass="0.1kg", radius="3cm", axle_radius="5mm", height="1m", at="5mm"))
    assert found["s"] == pytest.approx(1.0, rel=1e-14)
    assert found["v_t"] == pytest.approx(found["v"], rel=1e-14)


@settings(max_examples=60, deadline=None)
@given(inertia=st.floats(0.01, 10), omega0=st.one_of(st.just(0.0), st.floats(0.1, 20), st.floats(-20, -0.1)), torque=st.one_of(st.floats(0.1, 10), st.floats(-10, -0.1)), duration=st.floats(0.01, 2), at=st.floats(0.01, 1))
def test_a_point_of_a_body_given_a_constant_torque(inertia, omega0, torque, duration, at):
    """ω₁ = ω₀ + τΔt/I with α = τ/I still acting at the end; θ = ω₀Δt + ½αΔt²."""
    alpha = mpmath.mpf(torque) / inertia
    omega1 = omega0 + alpha * duration
    theta = omega0 * mpmath.mpf(duration) + alpha * mpmath.mpf(duration) ** 2 / 2
    found = _values(taucli.impulse(inertia=inertia, omega0=omega0, torque=torque, duration=duration, at=at))
    _expect_point(found, at, omega1, alpha, theta, rel=1e-9)
    assert found["v_t0"] == pytest.approx(abs(omega0) * at, rel=1e-14)


def test_a_skaters_hand_after_she_pulls_in_her_arms():
    """No torque: I₀ω₀ = I₁ω₁, and afterwards α = 0: a hand at 0.5 m only accelerates inward."""
    found = _values(taucli.impulse(inertia="4kg*m^2", inertia_final="1.5kg*m^2", omega0="1rev/s", at="50cm"))
    omega1 = 2 * mpmath.pi * 4 / mpmath.mpf("1.5")
    assert found["v_t"] == pytest.approx(float(omega1 / 2), rel=1e-14)
    assert found["a_t"] == 0 and found["a_c"] == pytest.approx(float(omega1**2 / 2), rel=1e-14)
    assert found["s"] is None


def test_the_rim_is_the_point_where_a_points_result_is_asked_with_no_at(taucli):
    """The issue's flywheel: 0.5 m rim, from rest at 3 rad/s², 2 s later: v = 3 m/s, a_t = 1.5,
    a_c = 18, a = 18.1 m/s² (√(1.5² + 18²)); --get a_total with no --at takes the rim."""
    wheel = ("spin-down", "--shape", "disc", "--mass", "5kg", "--radius", "0.5m", "--alpha", "3rad/s^2", "--time", "2s")
    asked = float(taucli(*wheel, "--get", "a_total").out)
    assert asked == pytest.approx(float(mpmath.sqrt(mpmath.mpf("1.5") ** 2 + 18**2)), rel=1e-14)
    document = taucli(*wheel, "--at", "rim", "--json").json()
    assert document["results"]["v_t"]["value"] == pytest.approx(3.0, rel=1e-14)
    assert any("rim, r = 0.5 m" in note for note in document["notes"])
    assert float(taucli("atwood", "--m1", "4kg", "--m2", "1kg", "--pulley-radius", "10cm", "--time", "1s", "--get", "v_t").out) == pytest.approx(
        float(taucli("atwood", "--m1", "4kg", "--m2", "1kg", "--pulley-radius", "10cm", "--time", "1s", "--get", "v").out), rel=1e-14)


@pytest.mark.parametrize("args", [
    ("spin-down", "--inertia", "2", "--omega0", "10rad/s", "--get", "v_t"),  # no radius
    ("atwood", "--m1", "4kg", "--m2", "1kg", "--get", "v_t"),  # no pulley radius
    ("atwood", "--m1", "4kg", "--m2", "1kg", "--radius1", "5cm", "--radius2", "10cm", "--at", "rim"),  # two radii
    ("rolling", "sphere", "--angle", "30deg", "--length", "1m", "--get", "v_t"),
])
def test_no_rim_without_one_radius(taucli, args):
    from conftest import assert_usage_error

    assert_usage_error(taucli(*args), "--at")
