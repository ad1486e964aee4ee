"""A swing with a damping torque bω against it (air, a pivot's grease):

    I θ'' = −mgd sin θ − κθ − bθ'        (γ = b/2I, Ω₀² = (mgd + κ)/I)

No energy is kept, so the answers the energy gives (the speeds at an angle, the pivot's forces,
the period at an amplitude, the turning angle) do not hold: this model gives θ and ω at --time,
and the decay of small swings:

- small-angle (sin θ ≈ θ): the damped harmonic oscillator, exactly. Under-damped (γ < Ω₀),
  θ = e^(−γt)(θ₀ cos Ω_d t + ((ω₀ + γθ₀)/Ω_d) sin Ω_d t), Ω_d = √(Ω₀² − γ²); critically damped,
  θ = e^(−γt)(θ₀ + (ω₀ + γθ₀)t); over-damped, θ = e^(−γt)(θ₀ cosh βt + ((ω₀ + γθ₀)/β) sinh βt),
  β = √(γ² − Ω₀²) (sinh βt/β and cosh βt formed so that β → 0 keeps its digits);
- auto, rk45: Dormand–Prince 5(4) steps of θ'' = α(θ, ω), each step's error within rtol of the
  swing's size; state(t) steps on from the last time asked for, so a plot's (or a fit's) samples
  in increasing time cost one run.

The amplitude of small swings falls as e^(−t/τ), τ = 2I/b (``decay_time``); the quality factor
Q = Ω₀/2γ = Ω₀I/b (``quality_factor``).
"""

from __future__ import annotations

import math
from math import fsum
from operator import mul, sub

from taucli.core.errors import InputError
from taucli.numerics import steppers as numerics
from taucli.scenes.pendulum.swing import Swing, sine
from taucli.writing.report import fmt

MAX_STEPS = numerics.MAX_ANGLE_STEPS["rk45"]  # in one run of the stepper (all its answers and its plot)


class Stepped:
    """θ'' = α(θ, ω) = −(G sin θ + κθ + bω)/I by Dormand–Prince 5(4), carried on from the last time asked."""

    def __init__(self, swing: Swing, viscous: float, rtol: float, dt: float):
        self.swing, self.viscous, self.rtol, self.dt = swing, viscous, rtol, dt
        natural = math.sqrt((swing.gravity_torque + swing.torsion) / swing.inertia) if swing.gravity_torque + swing.torsion > 0 else 1.0
        size = max(abs(swing.theta0), abs(swing.omega0) / natural, 1e-3)
        self.tolerance = (rtol * size, rtol * (size * natural + abs(swing.omega0)))
        self.steps = 0
        self._last = (0.0, swing.theta0, swing.omega0, dt)

    def accel(self, theta: float, omega: float) -> float:
        s = self.swing
        return -(s.gravity_torque * sine(theta) + s.torsion * theta + self.viscous * omega) / s.inertia

    def _step(self, theta: float, omega: float, h: float) -> tuple[float, float, float, float]:
        tableau = numerics.RK45
        speeds: list[float] = []
        alphas: list[float] = []
        for row in tableau.stages:
            speed = omega + h * fsum(map(mul, row, alphas))
            angle = theta + h * fsum(map(mul, row, speeds))
            speeds.append(speed)
            alphas.append(self.accel(angle, speed))
        differences = tuple(map(sub, tableau.weights, tableau.embedded))
        return (theta + h * fsum(map(mul, tableau.weights, speeds)), omega + h * fsum(map(mul, tableau.weights, alphas)),
                abs(h * fsum(map(mul, differences, speeds))), abs(h * fsum(map(mul, differences, alphas))))

    def state(self, t: float) -> tuple[float, float]:
        """(θ, ω) at t ≥ 0."""
        t_now, theta, omega, h = self._last
        if t < t_now:
            t_now, theta, omega, h = 0.0, self.swing.theta0, self.swing.omega0, self.dt
        while t_now < t:
            if self.steps >= MAX_STEPS:
                raise numerics.TooManySteps()
            step = min(h, t - t_now)
            new_theta, new_omega, error_theta, error_omega = self._step(theta, omega, step)
            self.steps += 1
            ratio = max(error_theta / self.tolerance[0], error_omega / self.tolerance[1])
            if not math.isfinite(ratio):
                raise numerics.TooManySteps()
            if ratio > 1:
                h = step * max(0.2, 0.9 * ratio**-0.2)
                continue
            grown = step * min(5.0, 0.9 * ratio**-0.2 if ratio else 5.0)
            h = max(h, grown) if step < h else grown  # (a step cut short to land on t leaves the step size as it was)
            t_now, theta, omega = t_now + step, new_theta, new_omega
        self._last = (t_now, theta, omega, h)
        return theta, omega


class SmallAngle:
    """The damped harmonic oscillator θ'' + 2γθ' + Ω₀²θ = 0, exactly (the forms in the docstring)."""

    def __init__(self, swing: Swing, viscous: float):
        self.gamma = viscous / (2 * swing.inertia)
        self.natural_squared = (swing.gravity_torque + swing.torsion) / swing.inertia
        self.theta0, self.omega0 = swing.theta0, swing.omega0

    def state(self, t: float) -> tuple[float, float]:
        gamma, theta0 = self.gamma, self.theta0
        drive = self.omega0 + gamma * theta0
        difference = self.natural_squared - gamma * gamma  # Ω_d² (> 0: under-damped), or −β²
        x = difference * t * t
        if abs(x) < 1e-4:  # near critical damping: cos and sin(Ω_d t)/Ω_d by their series in Ω_d² t²
            c = 1 - x / 2 + x * x / 24
            s = t * (1 - x / 6 + x * x / 120)
            c_rate = -difference * s  # d(c)/dt
        elif difference > 0:
            w = math.sqrt(difference)
            c, s, c_rate = math.cos(w * t), math.sin(w * t) / w, -w * math.sin(w * t)
        else:
            b = math.sqrt(-difference)
            c, s, c_rate = math.cosh(b * t), math.sinh(b * t) / b, b * math.sinh(b * t)
        decay = math.exp(-gamma * t)
        theta = decay * (theta0 * c + drive * s)
        omega = decay * (theta0 * c_rate + drive * c) - gamma * theta  # d/dt of e^(−γt)(θ₀c + Ds): s' = c
        return theta, omega


METHODS = ("auto", "rk45", "small-angle")


def model_of(swing: Swing, viscous: float, method: str, dt: float, rtol: float):
    """The damped swing's model for --method: rk45 (auto), or the small-angle closed form."""
    if method not in METHODS:
        raise InputError("method", "expected auto, rk45 or small-angle with {viscous} (a damped swing has no closed form "
                         "but the small-angle one, and the energy's exact methods do not hold)", got=repr(method),
                         example="{method} rk45")
    return SmallAngle(swing, viscous) if method == "small-angle" else Stepped(swing, viscous, rtol, dt)


def decay_results(swing: Swing, viscous: float) -> tuple[float | None, float | None]:
    """(τ = 2I/b, Q = Ω₀I/b): None where b = 0 (no decay) or Ω₀ = 0 (no swing)."""
    if not viscous > 0:
        return None, None
    natural = math.sqrt((swing.gravity_torque + swing.torsion) / swing.inertia)
    tau = 2 * swing.inertia / viscous
    return tau, (natural * tau / 2 if natural > 0 else None)


def words(method: str, viscous: float) -> str:
    if method == "small-angle":
        return f"damped harmonic oscillator, small-angle model (b = {fmt(viscous)} N·m·s/rad)"
    return f"damped swing, I θ'' = −mgd sin θ − κθ − bθ' stepped by rk45 (b = {fmt(viscous)} N·m·s/rad): no closed form"
