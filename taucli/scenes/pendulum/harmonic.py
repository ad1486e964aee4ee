"""Harmonic motion, θ'' = −Ω²θ: exact under a torsion spring alone (Ω² = κ/I, the period 2π√(I/κ)
at any amplitude), and the small-angle model sin θ ≈ θ (Ω² = (mgd + κ)/I).

Like every model of the motion it gives state(t) = (θ, ω), time_to(θ), the first time it reaches
an angle, and its period.
"""

from __future__ import annotations

import math

from taucli.scenes.pendulum.swing import TWO_PI


class Harmonic:
    """θ'' = −Ω²θ: θ = θ₀ cos Ωt + (ω₀/Ω) sin Ωt = A cos(Ωt − δ)."""
    def __init__(self, rate: float, theta0: float, omega0: float):
        self.rate, self.theta0, self.omega0 = rate, theta0, omega0
        self.amplitude = math.hypot(theta0, omega0 / rate)
        self.phase = math.atan2(omega0 / rate, theta0)
        self.period = TWO_PI / rate

    def state(self, t: float) -> tuple[float, float]:
        c, s = math.cos(self.rate * t), math.sin(self.rate * t)
        return self.theta0 * c + self.omega0 / self.rate * s, self.omega0 * c - self.theta0 * self.rate * s

    def time_to(self, theta: float) -> float | None:
        if theta == self.theta0:
            return 0.0
        if abs(theta) > self.amplitude:
            return None
        turn = math.acos(theta / self.amplitude)
        return min(((self.phase + sign * turn) % TWO_PI) / self.rate for sign in (1, -1))
