"""spin-down --until-angle with a body and its torques, for every torque law and method.

Reference, from the physics at 40 digits: while the wheel slows, dθ = Iω dω/|τ(ω)| and
dt = I dω/|τ(ω)|; the speed ω₁ at which θ(ω₁) = the target is found by a root-finder on that
quadrature, and the time is the quadrature of dt from ω₀ down to ω₁.
"""

from __future__ import annotations

import mpmath
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import taucli
from taucli.scenes.spin import Torques, solve

mp = mpmath.mp


def values(report):
    return {name: value.value for name, value in report.results.items()}


def slowing_reference(inertia, friction, viscous, drag, omega0, theta, exponent=2):
    """(t, ω) when a wheel slowing from ω₀ has turned θ (before it stops)."""
    with mp.workdps(40):
        i, f, b, k, w0 = (mpmath.mpf(x) for x in (inertia, friction, viscous, drag, omega0))

        def resisting(w):
            return f + b * w + k * w**exponent

        def turned(w1):
            return i * mpmath.quad(lambda w: w / resisting(w), [w1, w0])

        w1 = mpmath.findroot(lambda w: turned(w) - theta, (mpmath.mpf(0), w0), solver="illinois")
        t = i * mpmath.quad(lambda w: 1 / resisting(w), [w1, w0])
        return float(t), float(w1)


CASES = [  # inertia, friction, viscous, drag, exponent, ω₀, θ
    (0.1, 0.3, 0.0, 0.0, 2, 30.0, 100.0),
    (0.1, 0.0, 0.01, 0.0, 2, 30.0, 100.0),
    (0.1, 0.3, 0.01, 0.0, 2, 30.0, 80.0),
    (0.1, 0.0, 0.0, 0.001, 2, 30.0, 60.0),
    (0.1, 0.3, 0.02, 0.001, 2, 30.0, 40.0),
    (0.1, 0.3, 0.0, 0.001, 1.5, 30.0, 100.0),
    (2.0, 1.0, 0.05, 0.002, 3, 100.0, 120.0),
]


@pytest.mark.parametrize("case", CASES)
@pytest.mark.parametrize("method", ["auto", "rk45"])
def test_until_angle_against_quadrature(case, method):
    inertia, friction, viscous, drag, exponent, omega0, theta = case
    if method == "auto" and exponent == 2:
        rel = 1e-12
    else:
        rel = 1e-8
    result = values(solve(inertia, Torques(0.0, friction, viscous, drag, exponent), omega0, until_angle=theta, method=method))
    t, w1 = slowing_reference(inertia, friction, viscous, drag, omega0, theta, exponent)
    assert result["t_until"] == pytest.approx(t, rel=rel)
    assert result["omega"] == pytest.approx(w1, rel=rel, abs=rel * omega0)


def test_stops_first():
    report = solve(0.1, Torques(friction=0.3), 30.0, until_angle=200.0)
    assert values(report)["t_until"] is None
    assert any("stops first" in note for note in report.notes)


def test_driven_wheel_reaches_an_angle_and_an_arc():
    """A drum of radius 0.1 m from rest under 1.5 N·m: 2 m of cord is θ = 20 rad."""
    by_angle = values(taucli.spin_down(inertia=0.25, torque=1.5, until_angle=20))
    by_arc = taucli.spin_down(inertia=0.25, radius=0.1, torque=1.5, until_arc="2 m")
    assert values(by_arc)["t_until"] == pytest.approx(by_angle["t_until"], rel=1e-15)
    assert by_angle["t_until"] == pytest.approx((2 * 20 / 6) ** 0.5, rel=1e-15)
    assert any("θ = s/R" in note for note in by_arc.notes)


def test_restarting_the_other_way():
    """A drive against the motion larger than friction: the wheel stops and turns back."""
    report = values(solve(1.0, Torques(drive=-2.0, friction=1.0), 3.0, until_angle=-1.0))
    # first phase: α = −3 from 3 rad/s: stops at 1 s after 1.5 rad; then α = −1: 2.5 rad back takes √5 s
    assert report["t_until"] == pytest.approx(1 + 5**0.5, rel=1e-14)
    assert report["omega"] == pytest.approx(-(5**0.5), rel=1e-14)


@settings(max_examples=60, deadline=None)
@given(
    inertia=st.floats(0.01, 10),
    friction=st.one_of(st.just(0.0), st.floats(1e-6, 1)),  # (the units layer refuses sizes below 1e-40)
    viscous=st.one_of(st.just(0.0), st.floats(1e-6, 0.1)),
    drag=st.one_of(st.just(0.0), st.floats(1e-6, 0.01)),
    omega0=st.floats(1, 100),
    fraction=st.floats(0.01, 0.99),
)
def test_until_angle_then_time_returns_the_angle(inertia, friction, viscous, drag, omega0, fraction):
    torques = Torques(0.0, friction, viscous, drag)
    assume(friction > 1e-6 or viscous > 1e-6 or drag > 1e-6)
    stop = values(solve(inertia, torques, omega0))
    total = stop["theta_stop"]
    assume(total is not None or viscous > 1e-6)
    theta = fraction * (total if total is not None else inertia * omega0 / max(viscous, 1e-300) / 2)
    t = values(solve(inertia, torques, omega0, until_angle=theta))["t_until"]
    assume(t is not None)
    back = values(solve(inertia, torques, omega0, time=t))["theta"]
    assert back == pytest.approx(theta, rel=1e-12)
