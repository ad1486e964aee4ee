"""#34 item 3: a drag exponent between 0 and 1, I dω/dt = −τ_f − bω − kωⁿ.

The physics: with no constant torque the equation is a Bernoulli one, linear in u = ω^(1−n):
du/dt = −(1−n)(bu + k)/I, so ω reaches 0 in a finite time, t = I/((1−n)b)·ln(1 + bu₀/k)
(t = Iu₀/((1−n)k) without b), unlike n ≥ 1 where it only approaches rest; the angle to rest is
θ = ∫ω dt = I/(1−n) ∫₀^u₀ u^(1/(1−n)) du/(bu + k). With friction the time and angle to rest are
∫₀^ω₀ I dω/(τ_f + bω + kωⁿ) and ∫₀^ω₀ Iω dω/(τ_f + bω + kωⁿ). References in mpmath."""

from __future__ import annotations

import mpmath
import pytest
from conftest import assert_usage_error, run_taucli

import taucli

mpmath.mp.dps = 40


def values(report):
    return {key: value.value for key, value in report.results.items()}


@pytest.mark.parametrize("n", ["0.05", "0.2", "0.5", "0.9", "0.999"])
@pytest.mark.parametrize("b", ["0", "0.1"])
def test_drag_alone_stops_the_wheel_in_a_finite_time(n, b):
    I, w0, k, n, b = mpmath.mpf(2), mpmath.mpf(10), mpmath.mpf("0.5"), mpmath.mpf(n), mpmath.mpf(b)
    r = values(taucli.spin_down(inertia=2, omega0="10 rad/s", drag=0.5, viscous=float(b), drag_exponent=float(n), time="1 s"))
    u0 = w0 ** (1 - n)
    t_stop = I / ((1 - n) * b) * mpmath.log1p(b * u0 / k) if b else I * u0 / ((1 - n) * k)
    theta_stop = I / (1 - n) * mpmath.quad(lambda u: u ** (1 / (1 - n)) / (b * u + k), [0, u0])
    u1 = (u0 + k / b) * mpmath.exp(-(1 - n) * b / I) - k / b if b else u0 - (1 - n) * k / I
    assert r["t_stop"] == pytest.approx(float(t_stop), rel=1e-12)
    assert r["theta_stop"] == pytest.approx(float(theta_stop), rel=1e-11)
    assert r["omega"] == pytest.approx(float(u1 ** (1 / (1 - n))), rel=1e-11)


@pytest.mark.parametrize("n", ["0.05", "0.5", "0.95"])
def test_with_friction(n):
    I, w0, k, n, b, f = 2, 10, mpmath.mpf("0.5"), mpmath.mpf(n), mpmath.mpf("0.1"), mpmath.mpf("0.01")
    r = values(taucli.spin_down(inertia=2, omega0="10 rad/s", drag=0.5, viscous=0.1, friction=0.01, drag_exponent=float(n)))
    splits = [0, mpmath.mpf("1e-6"), mpmath.mpf("1e-3"), w0]
    assert r["t_stop"] == pytest.approx(float(mpmath.quad(lambda w: I / (f + b * w + k * w**n), splits)), rel=1e-11)
    assert r["theta_stop"] == pytest.approx(float(mpmath.quad(lambda w: I * w / (f + b * w + k * w**n), splits)), rel=1e-11)


def test_continuous_as_the_exponent_reaches_one():
    """ω at 1 s under kω^(1−ε) tends to that under kω (a viscous torque, e^(−kt/I))."""
    at_one = values(taucli.spin_down(inertia=2, omega0="10 rad/s", drag=0.5, drag_exponent=1.0, time="1 s"))["omega"]
    below = values(taucli.spin_down(inertia=2, omega0="10 rad/s", drag=0.5, drag_exponent=1 - 1e-7, time="1 s"))["omega"]
    assert below == pytest.approx(at_one, rel=1e-6)
    assert at_one == pytest.approx(10 * float(mpmath.exp(-0.25)), rel=1e-14)


def test_an_exponent_of_zero_or_less_is_refused():
    assert_usage_error(run_taucli("spin-down", "--inertia", "2", "--omega0", "10rad/s", "--drag", "0.5", "--drag-exponent", "0"), "--drag-exponent")
    assert_usage_error(run_taucli("spin-down", "--inertia", "2", "--omega0", "10rad/s", "--drag", "0.5", "--drag-exponent", "-0.5"), "--drag-exponent")
