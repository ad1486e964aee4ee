"""#34 items 3 and 4 in spin-down: a rim's tangential acceleration for α (--rim-accel), a power at
a steady speed with no body (τ = P/ω), and the angle of an --until-arc as a result.

The physics: every point of a rigid wheel turns with the same α, so a point at R has a_t = αR;
the power a torque delivers to a shaft at ω is P = τω; an arc s at radius R subtends θ = s/R."""

from __future__ import annotations

import math

import mpmath
import pytest
from conftest import assert_usage_error, run_taucli

import taucli

mpmath.mp.dps = 40


def values(report):
    return {key: value.value for key, value in report.results.items()}


def test_serway_a_car_tyre_from_rest_to_22_m_s_in_9_s():
    """Serway & Jewett, Physics for Scientists and Engineers, ch. 10: a car accelerates uniformly from
    rest to 22.0 m/s in 9.00 s; the tyre's diameter is 58.0 cm. The book's answers: (a) 54.3 rev,
    (b) 12.1 rev/s. The rim's tangential acceleration is the car's, a_t = 22/9 m/s²."""
    r = values(taucli.spin_down(rim_accel="(22m/s)/(9s)", radius="29 cm", time="9 s"))
    assert r["revs"] == pytest.approx(54.3, abs=0.05)  # the book's 54.3 rev
    assert r["omega"] / (2 * math.pi) == pytest.approx(12.1, abs=0.05)  # the book's 12.1 rev/s
    alpha = mpmath.mpf(22) / 9 / mpmath.mpf("0.29")
    assert r["alpha"] == pytest.approx(float(alpha), rel=1e-14)
    assert r["theta"] == pytest.approx(float(alpha * 81 / 2), rel=1e-14)


def test_rim_accel_with_a_body_gives_the_torque():
    """A 5 kg, 0.2 m disc whose rim speeds up at 0.6 m/s²: α = 3 rad/s², τ = ½MR²α = 0.3 N·m."""
    r = values(taucli.spin_down(shape="disc", mass="5 kg", radius="0.2 m", rim_accel="0.6 m/s^2", time="2 s"))
    assert r["alpha"] == pytest.approx(3, rel=1e-14)
    assert r["torque"] == pytest.approx(0.3, rel=1e-14)
    same = values(taucli.spin_down(inertia="0.1 kg*m^2", radius="20 cm", rim_accel="60 cm/s^2", time="2 s"))
    assert same["torque"] == pytest.approx(r["torque"], rel=1e-14)


def test_rim_accel_needs_a_radius_and_is_one_way_of_giving_alpha():
    assert_usage_error(run_taucli("spin-down", "--rim-accel", "2m/s^2", "--time", "9s"), "--rim-accel needs a radius")
    assert_usage_error(run_taucli("spin-down", "--rim-accel", "2m/s^2", "--radius", "1m", "--alpha", "1rad/s^2", "--time", "9s"),
                       "--rim-accel conflicts with --alpha")


def test_young_and_freedman_the_torque_of_a_motor_at_2500_rpm():
    """Young & Freedman, University Physics, ch. 10: a motor uses 9.00 kJ in 1.00 min, a third of it
    lost as heat; the rest is its output at 2500 rpm. The torque? The book's answer: 0.382 N·m."""
    r = values(taucli.spin_down(power="(2/3)*9kJ/(1min)", omega0="2500 rpm"))
    assert r["torque"] == pytest.approx(0.382, abs=5e-4)
    assert r["torque"] == pytest.approx(float(mpmath.mpf(100) / (2500 * 2 * mpmath.pi / 60)), rel=1e-14)


def test_power_at_a_rim_speed_with_no_body_and_its_work():
    r = values(taucli.spin_down(power="1 kW", rim_speed="10 m/s", radius="0.5 m", time="1 min"))
    assert r["torque"] == pytest.approx(50, rel=1e-14)  # P/ω = 1000/(10/0.5)
    assert r["work_drive"] == pytest.approx(60000, rel=1e-14)
    assert r["theta"] == pytest.approx(1200, rel=1e-14)
    other = values(taucli.spin_down(power="1.341022 hp", rim_speed="36 km/h", radius="50 cm", time="60 s"))
    assert other["torque"] == pytest.approx(r["torque"], rel=1e-6)


def test_power_with_no_body_refuses_what_a_steady_speed_cannot_do():
    assert_usage_error(run_taucli("spin-down", "--power", "1kW"), "--power needs the steady speed it is carried at when there is no body")
    assert_usage_error(run_taucli("spin-down", "--power", "1kW", "--omega0", "300rpm", "--until-omega", "400rpm"), "--until-omega conflicts with --power")
    assert_usage_error(run_taucli("spin-down", "--power", "1kW", "--omega0", "300rpm", "--alpha", "1rad/s^2"), "--power conflicts with --alpha")


def test_the_angle_of_an_arc_is_a_result():
    """2 m of cord off a 0.2 m drum: θ = s/R = 10 rad, now under theta_until."""
    r = values(taucli.spin_down(shape="disc", mass="5 kg", radius="0.2 m", omega0="30 rad/s", until_arc="2 m", friction="0.3 N*m"))
    assert r["theta_until"] == pytest.approx(10, rel=1e-15)
    assert values(taucli.spin_down(inertia=0.1, radius="20 cm", omega0="30 rad/s", until_arc="200 cm", friction="0.3 N*m"))["theta_until"] == pytest.approx(10, rel=1e-15)
    result = run_taucli("spin-down", "--shape", "disc", "--mass", "5kg", "--radius", "0.2m", "--omega0", "30rad/s", "--until-arc", "2m", "--get", "theta_until")
    assert result.code == 0 and float(result.out) == pytest.approx(10, rel=1e-15)
