"""spin-down with no body: where a drive's line meets its load's, and whether that is stable (#48 item 4).

Reference from the physics, in mpmath: a motor T_m = T₀ + sω driving a load T_L = F + bω + kω²
balances at the roots of kω² + (b − s)ω + (F − T₀) = 0 (the quadratic formula, in mpmath); a balance is stable
where the load's slope exceeds the motor's, b + 2kω > s. From ω₀ the speed moves the way
T_m − T_L pushes it, to the first balance on that side (a one-dimensional flow has no other way).
"""

from __future__ import annotations

import random

import mpmath
import pytest

import taucli
from conftest import assert_usage_error


def _reference(torque, slope, friction, viscous, drag, omega0):
    net = lambda w: torque + slope * w - friction - viscous * w - drag * w * w  # noqa: E731
    if drag:
        line, discriminant = slope - viscous, (slope - viscous) ** 2 + 4 * drag * (torque - friction)
        roots = [] if discriminant < 0 else [(line + sign * mpmath.sqrt(discriminant)) / (2 * drag) for sign in (1, -1)]
    else:
        roots = [(friction - torque) / (slope - viscous)] if slope != viscous else []
    roots = sorted(float(mpmath.re(r)) for r in roots if abs(mpmath.im(r)) < 1e-20 and mpmath.re(r) > 0)
    stable = {r: viscous + 2 * drag * r > slope for r in roots}
    push = net(omega0) if omega0 > 0 else torque - friction
    if push > 0:
        ahead = [r for r in roots if r > omega0]
        settles = ahead[0] if ahead else None
    else:
        behind = [r for r in roots if r < omega0]
        settles = behind[-1] if behind else 0.0
    unstable = next((r for r in roots if not stable[r]), None)
    return settles, (True if settles == 0.0 else stable.get(settles)), unstable


@pytest.mark.parametrize("seed", range(4))
def test_random_motor_and_load_lines(seed):
    rng = random.Random(480 + seed)
    for _ in range(25):
        torque, friction = rng.uniform(1, 50), rng.uniform(0, 60)
        slope, viscous, drag = rng.uniform(-0.2, 0.6), rng.uniform(0, 0.3), rng.choice([0.0, rng.uniform(1e-4, 1e-2)])
        if not drag and slope == viscous:
            continue
        omega0 = rng.choice([0.0, rng.uniform(0, 600)])
        settles, stable, unstable = _reference(mpmath.mpf(torque), mpmath.mpf(slope), mpmath.mpf(friction), mpmath.mpf(viscous), mpmath.mpf(drag), mpmath.mpf(omega0))
        kw = dict(torque=f"{torque} N*m", friction=f"{friction} N*m", viscous=f"{viscous} N*m*s", drive_slope=f"{slope} N*m*s",
                  omega0=f"{omega0} rad/s")
        if drag:
            kw["drag"] = f"{drag} N*m*s^2"
        values = {k: v.value for k, v in taucli.spin_down(**kw).results.items()}
        case = (torque, slope, friction, viscous, drag, omega0)
        if settles is None:
            assert values["omega_inf"] is None and values["stable"] is None, case
        else:
            assert values["omega_inf"] == pytest.approx(settles, rel=1e-12, abs=1e-12), case
            assert values["stable"] is stable, case
        if unstable is None:
            assert values["omega_unstable"] is None, case
        else:
            assert values["omega_unstable"] == pytest.approx(unstable, rel=1e-11), case


def test_a_rising_drive_steeper_than_its_load_is_unstable():
    """T_m = 5 + 0.05ω against a load of 20 N·m: they balance at 300 rad/s, and there a little faster
    gives more drive than load: unstable; from rest the drive cannot start it (5 < 20 N·m)."""
    values = {k: v.value for k, v in taucli.spin_down(torque="5 N*m", drive_slope="0.05 N*m*s", friction="20 N*m").results.items()}
    assert values["omega_unstable"] == pytest.approx(300, rel=1e-14)
    assert values["omega_inf"] == 0 and values["stable"] is True
    above = taucli.spin_down(torque="5 N*m", drive_slope="0.05 N*m*s", friction="20 N*m", omega0="301 rad/s").results
    assert above["omega_inf"].value is None  # it runs away


def test_the_steady_speed_needs_no_body():
    """The body changes how fast the wheel gets there, not where: with a body, omega_inf is the same."""
    kw = dict(torque="10 N*m", viscous="0.1 N*m*s", drag="0.001 N*m*s^2", friction="1 N*m")
    alone = taucli.spin_down(**kw).results
    with_body = taucli.spin_down(**kw, inertia="3 kg*m^2").results
    assert alone["omega_inf"].value == pytest.approx(with_body["omega_inf"].value, rel=1e-12)
    assert alone["stable"].value is True and with_body["stable"].value is True


def test_units_do_not_move_the_balance():
    si = taucli.spin_down(torque="20 N*m", friction="5 N*m", viscous="0.1 N*m*s", drive_slope="0.05 N*m*s").results
    other = taucli.spin_down(torque=f"{20 / 1.3558179483314004} lbf*ft", friction="500 N*cm", viscous="0.1 N*m/(rad/s)",
                             drive_slope=f"{0.05 * 2 * 3.141592653589793 / 60} N*m/rpm").results
    for key in ("omega_inf", "torque", "power"):
        assert other[key].value == pytest.approx(si[key].value, rel=1e-12), key


def test_refusals(taucli):
    assert_usage_error(taucli("spin-down", "--torque", "10N*m", "--viscous", "0.1N*m*s", "--time", "3s"), "--time", "--inertia")
    assert_usage_error(taucli("spin-down", "--inertia", "1kg*m^2", "--torque", "10N*m", "--viscous", "0.1N*m*s", "--drive-slope", "0.05N*m*s"), "--drive-slope")
    assert_usage_error(taucli("spin-down", "--torque", "10N*m", "--viscous", "0.1N*m*s", "--omega0", "-5rad/s"), "--omega0")
