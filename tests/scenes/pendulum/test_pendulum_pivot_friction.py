"""pendulum --pivot-friction: a constant couple τ_f at the pivot against the motion (#48 item 7).

The reference is written here from the physics, in mpmath, without the solver's legs or rk45:
the couple does work τ_f|Δθ|, so along a stretch of motion in one sense s from (θ_s, ω_s)

    ½Iω² = ½Iω_s² + U(θ_s) − U(θ) − τ_f s(θ − θ_s),   U = mgd(1 − cos θ) + ½κθ²

it comes to rest at the first zero of that (a root bracketed by a scan, then bisection), stays
there if |mgd sin θ + κθ| ≤ τ_f, and the time to an angle is t = ∫dθ/|ω| by tanh-sinh quadrature
(which takes the square-root ends at rest in its stride).
"""

from __future__ import annotations

import math
import random

import mpmath
import pytest

import taucli
from conftest import assert_usage_error

MP_DPS = 20


class RoughReference:
    def __init__(self, inertia, big_g, kappa, friction, theta0, omega0):
        mp = mpmath.mpf
        self.I, self.G, self.k, self.f = mp(inertia), mp(big_g), mp(kappa), mp(friction)
        self.legs = []  # (t0, θ_s, ω_s, s, t_end, θ_end)
        self.rest = None
        theta, omega, t = mp(theta0), mp(omega0), mp(0)
        for _ in range(40):
            drive = -(self.G * mpmath.sin(theta) + self.k * theta)
            if omega == 0 and abs(drive) <= self.f:
                self.rest = theta
                return
            sense = mpmath.sign(omega) if omega else mpmath.sign(drive)
            end = self._turning(theta, omega, sense)
            duration = self._time(theta, omega, sense, end)
            self.legs.append((t, theta, omega, sense, t + duration, end))
            t, theta, omega = t + duration, end, mp(0)

    def U(self, theta):
        return self.G * (1 - mpmath.cos(theta)) + self.k * theta**2 / 2

    def energy(self, theta_s, omega_s, sense, theta):
        return self.I * omega_s**2 / 2 + self.U(theta_s) - self.U(theta) - self.f * sense * (theta - theta_s)

    def _turning(self, theta_s, omega_s, sense):
        step = mpmath.mpf("0.01")
        a = theta_s
        for _ in range(5000):
            b = a + sense * step
            if self.energy(theta_s, omega_s, sense, b) < 0:
                return mpmath.findroot(lambda x: self.energy(theta_s, omega_s, sense, x), (a, b), solver="anderson")
            a = b
        raise AssertionError("the reference found no turning angle")

    def _time(self, theta_s, omega_s, sense, theta):
        speed = lambda x: mpmath.sqrt(2 * max(self.energy(theta_s, omega_s, sense, x), 0) / self.I)  # noqa: E731
        return mpmath.quad(lambda x: 1 / speed(x) if speed(x) else 0, [theta_s, theta]) * sense  # an end node rounded onto a rest

    def first_leg_at(self, theta):
        for i, (t0, ts, ws, s, t1, te) in enumerate(self.legs):
            low, high = sorted((ts, te))
            if low <= theta <= high and (theta != ts or i == 0):
                return self.legs[i]
        return None

    def velocity_at(self, theta):
        leg = self.first_leg_at(theta)
        if leg is None:
            return None
        t0, ts, ws, s, t1, te = leg
        return s * mpmath.sqrt(2 * max(self.energy(ts, ws, s, theta), 0) / self.I)

    def time_to(self, theta):
        leg = self.first_leg_at(theta)
        if leg is None:
            return None
        t0, ts, ws, s, t1, te = leg
        return t0 + self._time(ts, ws, s, theta)

    def theta_at(self, t):
        for t0, ts, ws, s, t1, te in self.legs:
            if t < t1:
                return mpmath.findroot(lambda x: t0 + self._time(ts, ws, s, x) - t, (ts, te), solver="anderson")
        return self.rest

    def alpha0(self, theta0, omega0):
        drive = -(self.G * mpmath.sin(theta0) + self.k * theta0)
        if omega0:
            return abs(drive - mpmath.sign(omega0) * self.f) / self.I
        return max(abs(drive) - self.f, 0) / self.I


def _close(got, exact, rel, what):
    assert got is not None and exact is not None, (what, got, exact)
    assert abs(got - float(exact)) <= rel * max(abs(float(exact)), 1e-300), (what, got, float(exact))


def test_ocr_disc_on_a_rough_axle():
    """A published problem (OCR M4): a uniform disc, 4 kg, radius 0.6 m, turns about a horizontal
    axis through A with AC = 0.4 m; a frictional couple of 4.8 N·m opposes the motion; released
    from rest with AC horizontal. The mark scheme: I = 1.36 kg·m², α = 8.0 rad/s², ω = 3.46 rad/s."""
    report = taucli.pendulum(shape="disc", mass="4 kg", radius="0.6 m", offset="0.4 m", angle0="90 deg", g="9.8 m/s^2", pivot_friction="4.8 N*m")
    values = {key: value.value for key, value in report.results.items()}
    inertia = mpmath.mpf("0.5") * 4 * mpmath.mpf("0.36") + 4 * mpmath.mpf("0.16")
    big_g = 4 * mpmath.mpf("9.8") * mpmath.mpf("0.4")
    _close(values["I"], inertia, 1e-15, "I")
    _close(values["alpha0"], (big_g - mpmath.mpf("4.8")) / inertia, 1e-14, "alpha0")
    _close(values["omega_bottom"], mpmath.sqrt(2 * (big_g - mpmath.mpf("4.8") * mpmath.pi / 2) / inertia), 1e-14, "omega_bottom")
    assert round(values["alpha0"], 1) == 8.0 and round(values["omega_bottom"], 2) == 3.46
    assert values["period"] is None


def _draw(rng):
    inertia = 10 ** rng.uniform(-2, 1)
    big_g = 10 ** rng.uniform(-1, 2)
    kappa = rng.choice([0.0, 0.0, big_g * rng.uniform(0.1, 2)])
    theta0 = math.radians(rng.uniform(20, 170)) * rng.choice([-1, 1])
    omega0 = rng.choice([0.0, 0.0, rng.uniform(-1, 1) * math.sqrt(big_g / inertia)])
    holding = abs(big_g * math.sin(theta0) + kappa * theta0)
    friction = holding * rng.uniform(0.02, 0.8)
    return inertia, big_g, kappa, friction, theta0, omega0


@pytest.mark.parametrize("seed", range(3))
def test_random_rough_swings_against_the_reference(seed):
    rng = random.Random(4800 + seed)
    for _ in range(6):
        inertia, big_g, kappa, friction, theta0, omega0 = _draw(rng)
        angle, time = theta0 * rng.uniform(-0.5, 0.9), rng.uniform(0.1, 3) * 2 * math.pi * math.sqrt(inertia / (big_g + kappa))
        ref = RoughReference(inertia, big_g, kappa, friction, theta0, omega0)
        d = 0.5 * inertia * 9.80665 / big_g  # so that md² = I/2 ≤ I
        kw = dict(inertia=inertia, mass=big_g / (9.80665 * d), cm_distance=d, torsion=kappa or None, pivot_friction=friction,
                  angle0=f"{theta0} rad", omega0=f"{omega0} rad/s")
        values = {k: v.value for k, v in taucli.pendulum(**kw, angle=f"{angle} rad").results.items()}
        case = (inertia, big_g, kappa, friction, theta0, omega0, angle)
        _close(values["alpha0"], ref.alpha0(mpmath.mpf(theta0), mpmath.mpf(omega0)), 1e-12, ("alpha0", case))
        _close(values["amplitude"], ref.legs[0][5], 1e-9, ("amplitude", case))
        for key, theta, rel in (("omega_bottom", 0, 1e-9), ("omega", angle, 1e-9)):
            exact = ref.velocity_at(mpmath.mpf(theta))
            if exact is None:
                assert values[key] is None, (key, case, values[key])
            else:
                _close(abs(values[key]) if key == "omega_bottom" else values[key], abs(exact) if key == "omega_bottom" else exact, rel, (key, case))
        for key, theta in (("t_bottom", 0), ("t_angle", angle)):
            exact = ref.time_to(mpmath.mpf(theta))
            if exact is None:
                assert values[key] is None, (key, case)
            else:
                _close(values[key], exact, 1e-8, (key, case))
        theta_t = taucli.pendulum(**kw, time=f"{time} s").results["theta"].value
        exact_theta = ref.theta_at(mpmath.mpf(time))
        assert abs(theta_t - float(exact_theta)) <= 1e-8 * max(abs(theta0), 1e-3), ("theta", case, time, theta_t, exact_theta)


def test_a_vanishing_couple_is_the_smooth_pivot():
    """τ_f → 0 is continuous with no couple: the same speeds, turning angle and times."""
    kw = dict(shape="rod", mass="2 kg", length="1 m", axis="end", angle0="70 deg", angle="-20 deg")
    smooth = taucli.pendulum(**kw).results
    rough = taucli.pendulum(**kw, pivot_friction="1e-9 N*m").results
    for key in ("alpha0", "omega_bottom", "amplitude", "t_bottom", "omega", "t_angle", "pivot_force0", "pivot_force_bottom"):
        assert rough[key].value == pytest.approx(smooth[key].value, rel=1e-7), key


def test_holding_is_continuous_at_the_couple_that_just_holds():
    """Just below the torque at the start the body sets off with α₀ ≈ 0; just above, it is held: α₀ = 0."""
    holding = 2 * 9.80665 * 0.5 * math.sin(math.radians(30))
    kw = dict(shape="rod", mass="2 kg", length="1 m", axis="end", angle0="30 deg")
    below = taucli.pendulum(**kw, pivot_friction=holding * (1 - 1e-9)).results
    above = taucli.pendulum(**kw, pivot_friction=holding * (1 + 1e-9)).results
    assert 0 < below["alpha0"].value < 1e-7 and above["alpha0"].value == 0
    assert above["omega_bottom"].value is None and above["t_bottom"].value is None


def test_the_couple_in_other_units_gives_the_same_answers():
    kw = dict(shape="disc", mass="4 kg", radius="0.6 m", offset="0.4 m", angle0="90 deg", time="1.5 s")
    si = taucli.pendulum(**kw, pivot_friction="4.8 N*m").results
    other = taucli.pendulum(**kw, pivot_friction=f"{4.8 / 1.3558179483314004} lbf*ft").results
    for key in ("alpha0", "omega_bottom", "amplitude", "t_bottom", "theta"):
        assert other[key].value == pytest.approx(si[key].value, rel=1e-12), key


def test_pivot_force_at_the_start_is_newtons_law_with_the_couple():
    """F_t = m(dα + g sin θ) with α = −(mgd sin θ₀ − τ_f)/I from rest at θ₀ > 0 (the couple slows the fall)."""
    m, d, g, f = 4, 0.4, 9.8, 4.8
    inertia = 0.5 * 4 * 0.36 + 4 * 0.16
    theta0 = math.radians(60)
    values = taucli.pendulum(shape="disc", mass="4 kg", radius="0.6 m", offset="0.4 m", angle0="60 deg", g="9.8 m/s^2",
                             pivot_friction="4.8 N*m", components=True).results
    alpha = -(m * g * d * math.sin(theta0) - f) / inertia
    assert values["pivot_tangential0"].value == pytest.approx(m * (d * alpha + g * math.sin(theta0)), rel=1e-13)
    assert values["pivot_radial0"].value == pytest.approx(m * g * math.cos(theta0), rel=1e-13)


def test_refusals(taucli):
    base = ("pendulum", "--shape", "rod", "--mass", "2kg", "--length", "1m", "--axis", "end", "--angle0", "30deg")
    assert_usage_error(taucli(*base, "--pivot-friction", "1N*m", "--method", "exact"), "--method", "rk45")
    assert_usage_error(taucli(*base, "--pivot-friction", "-1N*m"), "--pivot-friction")
    assert_usage_error(taucli(*base, "--pivot-friction", "1m"), "--pivot-friction")
