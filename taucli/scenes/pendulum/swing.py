"""The pendulum itself, and what energy gives at any angle whatever the model of its motion.

    I d²θ/dt² = −G sin θ − κθ,   G = mgd (gravity's torque at 90°),   κ the torsion constant

½Iω² + U(θ) is constant, U(θ) = G(1 − cos θ) + ½κθ²: the speeds at every angle, the starting
speed that just reaches the top and whether it gets there are exact, for every method.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from taucli.report import fmt
from taucli.table import Results

TWO_PI = 2 * math.pi


@dataclass(frozen=True)
class Swing:
    """The pendulum: I about the pivot, G = mgd (gravity's torque at 90°), κ, and its start."""
    inertia: float
    gravity_torque: float  # G = m g d
    torsion: float  # κ
    theta0: float
    omega0: float

    def potential(self, theta: float) -> float:
        """U(θ) = 2G sin²(θ/2) + ½κθ² (1 − cos θ written without cancellation)."""
        half = math.sin(theta / 2)
        return 2 * self.gravity_torque * half * half + self.torsion * theta * theta / 2

    def drop(self, theta: float) -> float:
        """U(θ₀) − U(θ), in the product forms that keep digits when θ is near θ₀."""
        a, b = self.theta0, theta
        return 2 * self.gravity_torque * math.sin((a + b) / 2) * math.sin((a - b) / 2) + self.torsion * (a - b) * (a + b) / 2

    def speed_at(self, theta: float) -> float | None:
        """|ω| at θ from energy, None where the body never gets there."""
        square = self.omega0 * self.omega0 + 2 * self.drop(theta) / self.inertia
        return None if square < 0 else math.sqrt(square)

    def accel(self, theta: float) -> float:
        """α(θ) = −(G sin θ + κθ)/I."""
        return -(self.gravity_torque * sine(theta) + self.torsion * theta) / self.inertia

    def small_period(self) -> float:
        """T₀ = 2π√(I / (G + κ)), the period of small swings (sin θ ≈ θ)."""
        return TWO_PI * math.sqrt(self.inertia / (self.gravity_torque + self.torsion))


def sine(theta: float) -> float:
    """sin θ, with the double nearest 180° (math.pi) read as 180° itself: 0, not 1.2e-16."""
    return 0.0 if abs(theta) == math.pi else math.sin(theta)


def put_energy(results: Results, notes: list[str], swing: Swing, cm_distance: float, angle: float | None) -> None:
    """I (and d under gravity); α₀ = |τ₀|/I; ω at the bottom and at --angle from energy; T₀; and
    under gravity the starting speed that just reaches the top, ½Iω₀,over² = U(180°) − U(θ₀),
    and whether it goes over (under gravity alone: |ω₀| > ω₀,over; with a spring: ω ≠ 0 at ±180°)."""
    results.put("I", swing.inertia)
    if swing.gravity_torque:
        results.put("cm_distance", cm_distance)
    results.put("alpha0", abs(swing.accel(swing.theta0)))
    results.put("omega_bottom", swing.speed_at(0.0))
    if angle is not None:
        speed_at_angle = swing.speed_at(angle)
        results.put("omega", speed_at_angle, f" at θ = {fmt(math.degrees(angle))}°")
        if speed_at_angle is None:
            notes.append(f"the body never reaches θ = {fmt(math.degrees(angle))}°: it has too little energy")
    results.put("period_small", swing.small_period())
    if swing.gravity_torque:
        theta0, omega0 = swing.theta0, swing.omega0
        omega0_over = math.sqrt(2 * max(swing.potential(math.pi) - swing.potential(theta0), 0.0) / swing.inertia)
        if swing.torsion == 0:
            goes_over = abs(omega0) > omega0_over
        else:
            goes_over = swing.speed_at(math.copysign(math.pi, omega0 or theta0 or 1.0)) not in (None, 0.0)
        results.put("goes_over", goes_over)
        results.put("omega0_over", omega0_over)
