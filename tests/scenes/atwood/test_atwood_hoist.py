"""atwood as a hoist (#48 item 8): the drive's steady power and torque, its energy per trip, and
the energy the axle friction (a brake) takes. References written here from the physics: the
work of each force over the path, and the energy balance of the scene's own motion."""

from __future__ import annotations


import mpmath
import pytest

import taucli
from conftest import assert_usage_error

G = mpmath.mpf("9.80665")


def test_halliday_freight_elevator():
    """Halliday, Resnick & Walker, Fundamentals of Physics, ch. 7: a freight elevator's cab of 1200 kg
    travels up 54 m in 3.0 min, starting and ending at rest, with a counterweight of 950 kg: the
    average power of the motor's force on the cab is (1200 − 950)(9.8)(54)/180 = 735 W."""
    results = taucli.atwood(m1="1200 kg", counterweight="950 kg", hoist_height="54 m", trip_time="3 min", g="9.8 m/s^2").results
    assert results["energy_trip"].value == pytest.approx(float(mpmath.mpf(250) * mpmath.mpf("9.8") * 54), rel=1e-14)
    assert results["power_trip"].value == pytest.approx(735.0, rel=1e-13)


@pytest.mark.parametrize("speed", [0.3, -0.3])
def test_steady_power_is_force_times_speed(speed):
    """Lifting (V > 0): the drive pays (m1 − m2)gV and the axle friction τa V/r; lowering, the
    weights drive and friction still takes its share: P = (m1 − m2)gV + (τa/r)|V|."""
    m1, m2, r, axle = 1200, 950, mpmath.mpf("0.5"), 100
    results = taucli.atwood(m1=m1, counterweight=m2, hoist_speed=f"{speed} m/s", pulley_radius="0.5 m", pulley_mass="80 kg",
                            axle_friction=f"{axle} N*m").results
    v = mpmath.mpf(speed)
    power = (m1 - m2) * G * v + axle / r * abs(v)
    assert results["power_steady"].value == pytest.approx(float(power), rel=1e-14)
    assert results["torque_steady"].value == pytest.approx(float(power / (v / r)), rel=1e-14)  # P = τω, ω = V/r


def test_trip_on_a_slope_with_sliding_friction():
    """m2 (the counterweight) on a 30° slope with μk = 0.2: lifting m1 by H, m2 slides down the slope
    by H; gravity gives back m2 g H sin θ, and friction takes μk m2 g cos θ H and τa H/r."""
    m1, m2, h, mu, r, axle = 50, 120, 7, mpmath.mpf("0.2"), mpmath.mpf("0.25"), 3
    angle = mpmath.pi / 6
    results = taucli.atwood(m1=m1, m2=m2, incline="30 deg", mu_k=0.2, mu_s=0.3, pulley_radius="0.25 m", axle_friction=f"{axle} N*m",
                            hoist_height=f"{h} m").results
    work = m1 * G * h - m2 * G * h * mpmath.sin(angle) + mu * m2 * G * mpmath.cos(angle) * h + axle * h / r
    assert results["energy_trip"].value == pytest.approx(float(work), rel=1e-13)
    assert results["work_brake"].value == pytest.approx(float(axle * h / r), rel=1e-14)


def test_the_drive_energy_balances_the_scenes_own_motion():
    """A drive torque τ lifts m1 from rest through d: τ d/r = energy_trip(d) + ½(m1 + m2 + I/r²)v²,
    with v the scene's own speed there (the kinetic energy still held at d)."""
    kw = dict(m1="30 kg", m2="10 kg", pulley_mass="6 kg", pulley_radius="0.2 m", axle_friction="4 N*m")
    torque, d = 80.0, 3.0
    moving = taucli.atwood(**kw, torque=f"{torque} N*m", distance=f"{d} m").results
    assert moving["a"].value < 0  # the drive wins: m1 goes up
    v = moving["v"].value
    trip = taucli.atwood(**kw, hoist_height=f"{d} m").results["energy_trip"].value
    kinetic = 0.5 * (30 + 10 + 0.5 * 6) * v * v
    assert torque * d / 0.2 == pytest.approx(trip + kinetic, rel=1e-12)


def test_work_brake_over_a_distance_and_to_the_stop():
    """The brake takes τa|Δθ| = τa s/r: over --distance, and until masses thrown up with --v0 stop."""
    kw = dict(m1="2 kg", m2="1 kg", pulley_mass="1 kg", pulley_radius="0.1 m", axle_friction="0.2 N*m")
    assert taucli.atwood(**kw, distance="1.5 m").results["work_brake"].value == pytest.approx(0.2 * 1.5 / 0.1, rel=1e-14)
    stopping = taucli.atwood(**kw, v0="-2 m/s").results
    assert stopping["work_brake"].value == pytest.approx(0.2 * abs(stopping["distance_stop"].value) / 0.1, rel=1e-14)
    # the energy balance of the stop: ½Mv₀² = rise of m1 less fall of m2 + the brake's share
    moving_mass = 2 + 1 + 0.5
    rise = abs(stopping["distance_stop"].value)
    assert 0.5 * moving_mass * 4 == pytest.approx((2 - 1) * 9.80665 * rise + stopping["work_brake"].value, rel=1e-12)


def test_units_do_not_change_the_hoist():
    si = taucli.atwood(m1="1200 kg", counterweight="950 kg", hoist_height="54 m", trip_time="180 s", hoist_speed="0.3 m/s",
                       pulley_radius="0.5 m", axle_friction="100 N*m").results
    other = taucli.atwood(m1=f"{1200 / 0.45359237} lb", counterweight=f"{950 / 0.45359237} lb", hoist_height=f"{54 / 0.3048} ft",
                          trip_time="3 min", hoist_speed=f"{0.3 * 60 / 0.3048} ft/min", pulley_radius="50 cm",
                          axle_friction=f"{100 / 1.3558179483314004} lbf*ft").results
    for key in ("energy_trip", "power_trip", "power_steady", "torque_steady", "work_brake"):
        assert other[key].value == pytest.approx(si[key].value, rel=1e-12), key


def test_refusals(taucli):
    assert_usage_error(taucli("atwood", "--m1", "4kg", "--m2", "1kg", "--counterweight", "1kg"), "--counterweight", "--m2")
    assert_usage_error(taucli("atwood", "--m1", "4kg", "--m2", "1kg", "--trip-time", "3min"), "--trip-time", "--hoist-height")
    assert_usage_error(taucli("atwood", "--m1", "4kg", "--m2", "1kg", "--rim-mu", "0.3", "--hoist-speed", "1m/s"), "--hoist-speed")
    assert_usage_error(taucli("atwood", "--m1", "4kg", "--m2", "1kg", "--hoist-height", "3kg"), "--hoist-height")
    assert_usage_error(taucli("atwood", "--m1", "4kg", "--m2", "1kg", "--hoist-height", "3m", "--trip-time", "0s"), "--trip-time")
