"""#42 item 22 beyond spin-down (tests/scenes/spin/test_spin_targets_given.py): in every scene
where a target is given, a result equal to that target is the target as read, and a result that
is 0 there is 0, never −0.

- atwood: --time 0 (v is v₀, the displacement 0: printed −0 before for a start from rest) and
  --distance 0 (t = 0, v = v₀);
- pendulum: ω at --angle equal to --angle0 or at the far end of the swing (0, not −0);
- impulse: --omega1 given, ω₁ is it, and L₁ = KE₁ = 0 at --omega1 0;
- drive: --in-time with --until-omega or --speed: t_accel is the time given (before: ω₁/(ω₁/t),
  0.6999999999999998 s for 0.7 s);
- flywheel: the mean speed given is ω_mean;
- a point on a pulley at its string's radius (atwood, every layout --at follows): after --distance
  its arc s is the distance given, its v_t and a_t the string's; at --time its arc is the
  distance printed; in spin-down a rim point's s is --until-arc, v_t0 --rim-speed, a_t --rim-accel."""

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


ATWOOD_LAYOUTS = {  # every layout a point on the pulley is followed in (rim_mu and fixed_drum take no --at)
    "hanging": {},
    "massive pulley with axle friction": {"pulley_mass": "2 kg", "axle_friction": "0.05 N*m"},
    "m2 on an incline": {"pulley_mass": "1.1 kg", "side2": "incline angle=30deg mu-s=0.3 mu-k=0.2"},
    "m1 on a table": {"pulley_inertia": "0.004 kg*m^2", "side1": "table mu-k=0.1", "m1": "1.3 kg", "m2": "3 kg"},
    "a string wound on the pulley": {"pulley_mass": "2 kg", "m2": "0 kg"},
    "a drive torque": {"pulley_mass": "2 kg", "torque": "1.5 N*m"},
    "a pull on m2": {"pulley_mass": "2 kg", "side2": "table mu-k=0.2", "pull": "force=5N angle=20deg on=2"},
    "a stepped pulley": {"pulley_inertia": "0.01 kg*m^2", "stepped": True},
}


@pytest.mark.parametrize("layout", ATWOOD_LAYOUTS)
def test_atwood_a_point_on_the_string_s_radius_moves_with_the_string(layout):
    """#42 item 22 in atwood mid-motion: the string's radius is where a pulley point moves with the
    string, so after --distance d its arc s is d as given (was (d/R)·R: 1.9980000000000002 m for
    --distance 1.998m --pulley-radius 0.1124m --at rim), its v_t and a_t are the string's |v| and a,
    v_t0 is |v₀|; at --time its arc is the distance printed. No atwood result echoes --time (t is
    the time to --distance) or --distance alone (distance is the displacement at --time)."""
    rng = random.Random(layout)
    for _ in range(25):
        options = {"m1": "3 kg", "m2": "1.3 kg", **ATWOOD_LAYOUTS[layout]}
        radius = round(rng.uniform(0.011, 0.5), rng.randint(2, 4))
        if options.pop("stepped", False):
            options.update(radius1=f"{radius!r} m", radius2=f"{round(rng.uniform(0.011, 0.5), 3)!r} m")
        else:
            options["pulley_radius"] = f"{radius!r} m"
        v0 = rng.choice([0.0, round(rng.uniform(0.1, 2), 2), -round(rng.uniform(0.1, 2), 2)])
        distance, time = round(rng.uniform(0.01, 5), rng.randint(1, 4)), round(rng.uniform(0.01, 3), rng.randint(1, 3))
        after = taucli.atwood(**options, v0=f"{v0!r} m/s", distance=f"{distance!r} m", at=f"{radius!r} m").results
        if after["t"].value is not None:
            assert after["s"].value == distance, (options, v0, distance)
            assert after["v_t"].value == abs(after["v"].value) and after["v_t0"].value == abs(v0)
            a, v = after["a"].value, after["v"].value
            if after["a_t"].value is not None and not v0 * a < 0:  # (thrown against a and stopped by then: α is the one after)
                assert after["a_t"].value == (a if v > 0 else -a if v < 0 else abs(a))  # along the motion
        at_time = taucli.atwood(**options, v0=f"{v0!r} m/s", time=f"{time!r} s", at=f"{radius!r} m").results
        assert at_time["s"].value == at_time["distance"].value, (options, v0, time)


def test_spin_down_a_point_at_the_rim_keeps_the_rim_s_values_given():
    """The same class in spin-down: --until-arc s with --at rim has run s (was (s/R)·R: 0.8999999999999999
    m for --radius 0.339m --until-arc 0.9m); --rim-speed v is the rim point's v_t0 (v_t at the start),
    --rim-accel its a_t."""
    rng = random.Random(2222)
    for _ in range(60):
        radius, arc = round(rng.uniform(0.011, 0.5), rng.randint(2, 4)), round(rng.uniform(0.01, 5), rng.randint(1, 4))
        speed, accel = round(rng.uniform(0.5, 9), rng.randint(1, 3)), round(rng.uniform(0.1, 3), 2)
        r = taucli.spin_down(inertia=2, radius=f"{radius!r} m", rim_speed=f"{speed!r} m/s", friction="0.3 N*m", until_arc=f"{arc!r} m", at="rim").results
        assert r["v_t0"].value == speed
        assert r["s"].value == arc or r["t_until"].value is None
        r = taucli.spin_down(radius=f"{radius!r} m", rim_speed=f"{speed!r} m/s", rim_accel=f"{accel!r} m/s^2", time="1.3 s", at="rim").results
        assert (r["v_t0"].value, r["a_t"].value) == (speed, accel)
        r = taucli.spin_down(radius=f"{radius!r} m", rim_speed=f"{speed!r} m/s", rim_accel=f"{accel!r} m/s^2", at="rim").results
        assert (r["v_t"].value, r["a_t"].value) == (speed, accel)
