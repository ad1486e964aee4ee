"""#42 item 22: a result equal to a target given is that target. With --in-time the drive is found
that puts the wheel at --until-omega (or --until-angle) at that time, so ω there is the target, and
what follows from ω alone is written from it: KE = ½Iω², the drive's power τω, friction's τ_f|ω|,
the viscous bω², the drag k|ω|ⁿ⁺¹ (all exactly 0 at ω = 0, where the motion's rounding printed
ω = 1.42e−14 rad/s, power −5.95e−16 W, KE 1.0e−30 J)."""

from __future__ import annotations

import math

import pytest

import taucli

LOSSES = [{"friction": 1}, {"viscous": 0.01}, {"drag": 0.001}, {"friction": 1, "viscous": 0.01}, {"drag": 0.001, "drag_exponent": 1.5}, {}]


@pytest.mark.parametrize("losses", LOSSES)
def test_brought_to_rest_in_a_time_is_at_rest(losses):
    r = taucli.spin_down(inertia=2, omega0="300 rpm", until_omega=0, in_time="30 s", **losses).results
    assert r["omega"].value == 0
    assert r["KE"].value == 0
    for key in ("power", "power_friction", "power_viscous", "power_drag"):
        if key in r:
            assert r[key].value == 0 and math.copysign(1, r[key].value) == 1, (key, r[key].value)  # 0, not −0


@pytest.mark.parametrize("losses", LOSSES)
def test_a_speed_given_with_a_time_is_that_speed(losses):
    report = taucli.spin_down(inertia=2, omega0="300 rpm", until_omega="50 rpm", in_time="30 s", **losses)
    r, w = report.results, report.inputs["until_omega"].value  # the target as read: 50 rpm in rad/s
    assert w == pytest.approx(50 * 2 * math.pi / 60, rel=1e-15)
    assert r["omega"].value == w
    assert r["KE"].value == 2 * w * w / 2
    if "power_viscous" in r:
        assert r["power_viscous"].value == pytest.approx(0.01 * w * w, rel=1e-12)


@pytest.mark.parametrize("losses", LOSSES[:3])
def test_an_angle_given_with_a_time_is_that_angle(losses):
    r = taucli.spin_down(inertia=2, omega0="300 rpm", until_angle="10 rev", in_time="30 s", **losses).results
    assert r["theta"].value == 10 * 2 * math.pi
    assert r["revs"].value == 10


@pytest.mark.parametrize("losses", [{"viscous": 0.01}, {"drag": 0.01}])
def test_brought_to_rest_within_an_angle_is_at_rest(losses):
    """--until-omega 0 --in-angle: the drive that stops the wheel in 10 rev (from one side only: a
    little less drive and it stops short); at the target KE and the drive's power are 0, not −0."""
    r = taucli.spin_down(inertia=2, omega0="300 rpm", until_omega=0, in_angle="10 rev", **losses).results
    assert r["torque"].value < 0
    assert r["KE"].value == 0
    assert r["power"].value == 0 and math.copysign(1, r["power"].value) == 1


def test_a_drive_power_at_rest_is_0_not_minus_0():
    r = taucli.spin_down(inertia=2, omega0="300 rpm", until_omega=0, viscous=0.01, friction=0.1, torque="-1 N*m", energy=True).results
    assert r["power"].value == 0 and math.copysign(1, r["power"].value) == 1
