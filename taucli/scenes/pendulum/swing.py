"""The pendulum itself, and what energy gives at any angle whatever the model of its motion.

    I d²θ/dt² = −G sin θ − κθ,   G = mgd (gravity's torque at 90°),   κ the torsion constant

½Iω² + U(θ) is constant, U(θ) = G(1 − cos θ) + ½κθ²: the speeds at every angle, the starting
speed that just reaches the top and whether it gets there are exact, for every method.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from taucli.options.table import Results

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


def first_sense(exact, angle: float, arrives: float) -> float:
    """+1 or −1: the sign of ω when the body first reaches ``angle`` (at time ``arrives``), in the
    sense of --omega0 (toward larger angles)."""
    if hasattr(exact, "sense_at_first"):
        return exact.sense_at_first(angle)
    omega = exact.state(arrives)[1]
    if omega == 0:  # a turning point: ω is 0 either way; the sense it had on the way there
        omega = exact.state(max(arrives * (1 - 1e-9), 0.0))[1]
    return -1.0 if omega < 0 else 1.0


def fall_sense(angle: float | None) -> float:
    """The sign of ω of a body balanced on the top once it falls (#42 item 6: one way, said in a
    note): toward --angle (θ decreasing from +180° to a positive angle, increasing from −180° to a
    negative one), else the way θ decreases."""
    return 1.0 if angle is not None and angle < 0 else -1.0


def reached_speed(swing: Swing, exact, theta: float) -> float | None:
    """|ω| at θ from energy where the exact motion gets there; None where it never does, for too
    little energy or for a top it cannot pass between (a spring's well beyond the bottom)."""
    speed = swing.speed_at(theta)
    if speed is None or getattr(exact, "balanced", False):
        return speed
    reaches = exact.reaches(theta) if hasattr(exact, "reaches") else exact.time_to(theta) is not None
    return speed if reaches else None


def sine(theta: float) -> float:
    """sin θ, with the double nearest 180° (math.pi) read as 180° itself: 0, not 1.2e-16."""
    return 0.0 if abs(theta) == math.pi else math.sin(theta)


def put_energy(results: Results, notes: list[str], swing: Swing, cm_distance: float, angle: float | None, exact, zero) -> None:
    """I (and d under gravity); α₀ = |τ₀|/I; ω at the bottom from energy, and at --angle from
    energy with the sign it has when the body first gets there (from the exact motion, which also
    says whether it gets there: energy at the angle is not enough where a top lies between); T₀;
    under gravity the starting speed that just reaches the top, ½Iω₀,over² = U(180°) − U(θ₀) =
    2G cos²(θ₀/2) + ½κ(π − |θ₀|)(π + |θ₀|) (no difference of near-equal energies near the top),
    and whether it goes over (under gravity alone: |ω₀| > ω₀,over; with a spring: ω ≠ 0 at ±180°)."""
    results.put("I", swing.inertia)
    if swing.gravity_torque:
        results.put("cm_distance", cm_distance)
    results.put("alpha0", abs(swing.accel(swing.theta0)))
    bottom = reached_speed(swing, exact, 0.0)
    results.put("omega_bottom", bottom)
    if bottom is None and swing.speed_at(0.0) is not None:
        notes.append("omega_bottom: the body never reaches the bottom (θ = 0): a top it cannot pass lies between")
    if angle is not None:
        speed_at_angle = swing.speed_at(angle)
        balanced = getattr(exact, "balanced", False)  # at rest on the top: the speeds of a body that has just left it, either way
        arrives = exact.time_to(angle) if speed_at_angle is not None and not balanced else None
        if balanced:  # it falls toward --angle and first gets there before the bottom, speeding up
            speed_at_angle = fall_sense(angle) * speed_at_angle if speed_at_angle else 0.0
        elif speed_at_angle is not None and arrives is None:
            speed_at_angle = None
            notes.append(f"the body never reaches {zero.text(angle)}: a top it cannot pass lies between")
        elif speed_at_angle is None:
            notes.append(f"the body never reaches {zero.text(angle)}: it has too little energy")
        else:
            speed_at_angle = speed_at_angle * first_sense(exact, angle, arrives) if speed_at_angle else 0.0  # at rest there: 0, not −0
        results.put("omega", speed_at_angle, f" at {zero.text(angle)}, when it first gets there")
    results.put("period_small", swing.small_period())
    if swing.gravity_torque:
        theta0, omega0 = swing.theta0, swing.omega0
        half = 0.0 if abs(theta0) == math.pi else math.cos(theta0 / 2)  # correctly rounded for the double θ₀, near the top too; the double nearest 180° is the top
        rise = 2 * swing.gravity_torque * half * half + swing.torsion * (math.pi - abs(theta0)) * (math.pi + abs(theta0)) / 2
        omega0_over = math.sqrt(2 * max(rise, 0.0) / swing.inertia)
        if swing.torsion == 0:
            goes_over = abs(omega0) > omega0_over
        else:
            goes_over = swing.speed_at(math.copysign(math.pi, omega0 or theta0 or 1.0)) not in (None, 0.0)
        results.put("goes_over", goes_over)
        results.put("omega0_over", omega0_over)
