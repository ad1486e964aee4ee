"""spin-down --corner μ: a spinning body set down in a corner, rubbing on floor and wall (#46 item 7).

Reference from the physics, in mpmath: the centre stays put, so the forces on it balance,
horizontally μN₁ = N₂ (the floor's friction into the wall, the wall's push back) and vertically
N₁ + μN₂ = mg (the wall's friction up); solved as a linear system (mpmath.lu_solve), then the
frictions' torque μ(N₁ + N₂)R slows I = ½mR² (a disc) to rest: t = Iω₀/τ, θ = Iω₀²/(2τ)."""

from __future__ import annotations

import random

import mpmath
import pytest

import taucli
from conftest import assert_usage_error

G = mpmath.mpf("9.80665")


def _reference(m, r, mu, omega0):
    m, r, mu, omega0 = (mpmath.mpf(q) for q in (m, r, mu, omega0))
    floor, wall = mpmath.lu_solve(mpmath.matrix([[mu, -1], [1, mu]]), mpmath.matrix([0, m * G]))
    torque = mu * (floor + wall) * r
    inertia = m * r * r / 2
    return floor, wall, inertia * omega0 / torque, inertia * omega0**2 / (2 * torque)


@pytest.mark.parametrize("seed", range(3))
def test_random_discs_in_a_corner(seed):
    rng = random.Random(4670 + seed)
    for _ in range(10):
        m, r, mu, omega0 = rng.uniform(0.1, 50), rng.uniform(0.01, 1), rng.uniform(0.01, 1.5), rng.uniform(1, 500)
        values = {k: v.value for k, v in taucli.spin_down(shape="disc", mass=m, radius=r, corner=mu, omega0=f"{omega0} rad/s").results.items()}
        floor, wall, t_stop, theta_stop = _reference(m, r, mu, omega0)
        assert values["normal_floor"] == pytest.approx(float(floor), rel=1e-13)
        assert values["normal_wall"] == pytest.approx(float(wall), rel=1e-13)
        assert values["t_stop"] == pytest.approx(float(t_stop), rel=1e-12)
        assert values["theta_stop"] == pytest.approx(float(theta_stop), rel=1e-12)


def test_the_textbook_time_to_stop():
    """The problem books' answer for a disc in a corner (Irodov's collection has it), t = ω₀R(1 + k²)/(2gk(1 + k)),
    for a disc of radius 0.1 m at 60 rad/s, k = 0.3, g = 9.8."""
    t = taucli.spin_down(shape="disc", mass="2 kg", radius="0.1 m", corner=0.3, omega0="60 rad/s", g="9.8 m/s^2").results["t_stop"].value
    assert t == pytest.approx(60 * 0.1 * (1 + 0.09) / (2 * 9.8 * 0.3 * 1.3), rel=1e-13)


def test_units_do_not_change_the_corner():
    si = taucli.spin_down(shape="disc", mass="2 kg", radius="0.1 m", corner=0.3, omega0="60 rad/s").results
    other = taucli.spin_down(shape="disc", mass=f"{2 / 0.45359237} lb", radius="10 cm", corner="30%", omega0=f"{60 * 60 / (2 * 3.141592653589793)} rpm").results
    for key in ("normal_floor", "normal_wall", "t_stop", "theta_stop"):
        assert other[key].value == pytest.approx(si[key].value, rel=1e-12), key


def test_refusals(taucli):
    assert_usage_error(taucli("spin-down", "--inertia", "0.01kg*m^2", "--omega0", "60rad/s", "--corner", "0.3"), "--corner", "mass")
    assert_usage_error(taucli("spin-down", "--shape", "disc", "--mass", "2kg", "--radius", "0.1m", "--omega0", "60rad/s", "--corner", "-0.3"), "--corner")
