"""A damped swing (--viscous) and a start on a clock (--start-time) (#44 item 12).

References from the physics in mpmath, not from taucli: I θ'' = −mgd sin θ − κθ − bθ' solved by
mpmath's Taylor-series ODE solver (30 digits), and the damped harmonic oscillator's closed forms
(under-, critically and over-damped) for the small-angle model.
"""

from __future__ import annotations

import math

import mpmath
import pytest

from taucli.answering import pipeline
from taucli.core.errors import InputError
from taucli.options import SCENES

PENDULUM = SCENES["pendulum"]


def solved(**options):
    return pipeline.solve(PENDULUM, options).results


def swing_reference(g_over_l, b_over_i, theta0, omega0, t, kappa_over_i=0):
    mpmath.mp.dps = 20
    f = mpmath.odefun(lambda _, y: [y[1], -g_over_l * mpmath.sin(y[0]) - kappa_over_i * y[0] - b_over_i * y[1]], 0, [mpmath.mpf(theta0), mpmath.mpf(omega0)])
    return [float(v) for v in f(t)]


@pytest.mark.parametrize("theta0, omega0, b, t", [(0.35, 0.0, 0.05, 3.0), (2.5, 0.0, 0.2, 4.1), (0.1, 1.5, 0.01, 2.5), (-1.0, -0.3, 1.5, 2.0)])
def test_damped_swing_follows_the_equation_of_motion(theta0, omega0, b, t):
    found = solved(shape="point", mass="2 kg", radius="0.75 m", angle0=theta0, omega0=omega0, viscous=b, time=t, g="9.81 m/s^2")
    inertia = 2 * 0.75**2
    theta, omega = swing_reference(mpmath.mpf("9.81") * 2 * mpmath.mpf("0.75") / inertia, mpmath.mpf(b) / inertia, theta0, omega0, t)
    assert found["theta"].value == pytest.approx(theta, abs=1e-8 * max(abs(theta0), 1e-3) + 1e-9)
    assert found["omega"].value == pytest.approx(omega, abs=1e-8 * (abs(omega0) + 5) + 1e-9)
    assert found["decay_time"].value == pytest.approx(2 * inertia / b, rel=1e-14)
    assert found["period"].value is None and found["omega_bottom"].value is None  # energy's answers do not hold with a loss


@pytest.mark.parametrize("b", [0.3, 2 * math.sqrt(9.81), 12.0, 2 * math.sqrt(9.81) * (1 + 1e-9)])  # under, critical, over, just over
def test_small_angle_damped_oscillator_has_its_closed_forms(b):
    mpmath.mp.dps = 40
    theta0, omega0, t = mpmath.mpf("0.2"), mpmath.mpf("-0.4"), mpmath.mpf("1.7")
    gamma, w0sq = mpmath.mpf(b) / 2, mpmath.mpf("9.81")
    d = w0sq - gamma**2

    def theta(t):
        if d == 0:
            return mpmath.exp(-gamma * t) * (theta0 + (omega0 + gamma * theta0) * t)
        w = mpmath.sqrt(d)  # imaginary when over-damped: cos and sin/w of an imaginary argument are cosh and sinh/β
        return mpmath.re(mpmath.exp(-gamma * t) * (theta0 * mpmath.cos(w * t) + (omega0 + gamma * theta0) * mpmath.sin(w * t) / w))

    found = solved(shape="point", mass="1 kg", radius="1 m", angle0=0.2, omega0=-0.4, viscous=b, time=1.7, g="9.81 m/s^2", method="small-angle")
    assert found["theta"].value == pytest.approx(float(theta(t)), rel=1e-12, abs=1e-15)
    assert found["omega"].value == pytest.approx(float(mpmath.diff(theta, t)), rel=1e-10, abs=1e-14)


def test_start_time_shifts_the_clock_and_holds_the_body_before_it():
    plain = solved(shape="point", mass="1 kg", radius="1 m", angle0="20 deg", time="1.3 s")
    shifted = solved(shape="point", mass="1 kg", radius="1 m", angle0="20 deg", time="2.0 s", start_time="0.7 s")
    assert shifted["theta"].value == pytest.approx(plain["theta"].value, rel=1e-12)
    assert shifted["omega"].value == pytest.approx(plain["omega"].value, rel=1e-12)
    held = solved(shape="point", mass="1 kg", radius="1 m", angle0="20 deg", time="0.5 s", start_time="0.7 s", viscous=0.01)
    assert held["theta"].value == pytest.approx(math.radians(20), rel=1e-15) and held["omega"].value == 0
    with pytest.raises(InputError):  # a start with a speed has no motion before it
        solved(shape="point", mass="1 kg", radius="1 m", angle0="20 deg", omega0="1 rad/s", time="0.5 s", start_time="0.7 s")


@pytest.mark.parametrize("option, value", [("angle", "0 deg"), ("at", "0.5 m"), ("method", "exact")])
def test_damped_swing_refuses_what_energy_answers(option, value):
    with pytest.raises(InputError) as caught:
        solved(shape="point", mass="1 kg", radius="1 m", angle0="20 deg", viscous=0.01, **{option: value})
    assert caught.value.option in (option, "method")
