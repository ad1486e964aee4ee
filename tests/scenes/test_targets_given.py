"""#42 item 22 beyond spin-down (tests/scenes/spin/test_spin_targets_given.py): in every scene
where a target is given, a result equal to that target is the target as read, and a result that
is 0 there is 0, never −0.

- atwood: --time 0 (v is v₀, the displacement 0: printed −0 before for a start from rest) and
  --distance 0 (t = 0, v = v₀);
- pendulum: ω at --angle equal to --angle0 or at the far end of the swing (0, not −0);
- impulse: --omega1 given, ω₁ is it, and L₁ = KE₁ = 0 at --omega1 0;
- drive: --in-time with --until-omega or --speed: t_accel is the time given (before: ω₁/(ω₁/t),
  0.6999999999999998 s for 0.7 s);
- flywheel: the mean speed given is ω_mean."""

from __future__ import annotations

import math
import random

import pytest

import taucli


def plus_zero(value):
    return value == 0 and math.copysign(1, value) == 1


@pytest.mark.parametrize("v0", ["0 m/s", "0.3 m/s", "-0.3 m/s"])
def test_atwood_at_time_zero_is_the_start(v0):
    report = taucli.atwood(m1="1.3 kg", m2="2.1 kg", v0=v0, time="0 s")
    r, u = report.results, report.inputs["v0"].value
    assert plus_zero(r["distance"].value)
    assert r["v"].value == u and (u != 0 or plus_zero(r["v"].value))


@pytest.mark.parametrize("v0", ["0 m/s", "0.3 m/s", "-0.3 m/s"])
def test_atwood_after_no_distance_is_the_start(v0):
    report = taucli.atwood(m1="2.1 kg", m2="1.3 kg", v0=v0, distance="0 m")
    r, u = report.results, report.inputs["v0"].value
    assert plus_zero(r["t"].value)
    assert r["v"].value == u and (u != 0 or plus_zero(r["v"].value))


@pytest.mark.parametrize("angle0, angle", [("70deg", "70deg"), ("70deg", "-70deg"), ("-70deg", "70deg"), ("-1.1rad", "-1.1rad")])
def test_pendulum_at_its_turning_angle_is_at_rest(angle0, angle):
    r = taucli.pendulum(shape="rod", axis="end", length="1.3 m", mass="1 kg", angle0=angle0, angle=angle).results
    assert plus_zero(r["omega"].value)


def test_impulse_omega1_given_is_omega1():
    rng = random.Random(22)
    for _ in range(30):
        w0, w1 = rng.uniform(-50, 50), rng.uniform(-50, 50)
        torque = math.copysign(rng.uniform(0.1, 5), w1 - w0)
        report = taucli.impulse(inertia=rng.uniform(0.1, 5), omega0=f"{w0!r} rad/s", omega1=f"{w1!r} rad/s", torque=f"{torque!r} N*m")
        assert report.results["omega1"].value == w1
    r = taucli.impulse(inertia=2, omega0="10 rad/s", omega1="0 rad/s", torque="-3 N*m").results
    for key in ("omega1", "L1", "KE1"):
        assert plus_zero(r[key].value), key


def test_drive_in_a_time_takes_that_time():
    rng = random.Random(221)
    for _ in range(30):
        in_time = round(rng.uniform(0.05, 3), rng.randint(1, 4))
        common = dict(motor_inertia="1e-4 kg*m^2", ratio=rng.choice([3, 7, 10, 12.5]), in_time=f"{in_time!r} s", energy=True)
        by_speed = taucli.drive(load_mass="30 kg", drum_radius="0.1 m", speed=f"{rng.uniform(0.1, 3)!r} m/s", **common).results
        by_omega = taucli.drive(load_inertia="0.05 kg*m^2", until_omega=f"{rng.uniform(100, 6000)!r} rpm", **common).results
        assert by_speed["t_accel"].value == in_time
        assert by_omega["t_accel"].value == in_time


def test_flywheel_mean_speed_given_is_the_mean():
    report = taucli.flywheel(inertia=20, omega_mean="300 rpm", fluctuation=0.02)
    assert report.results["omega_mean"].value == report.inputs["omega_mean"].value
