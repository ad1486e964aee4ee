"""The pivot's force on the body, and the equivalent simple pendulum.

The centre of mass moves on a circle of radius d, so F + mg = m a_cm with a_cm = (dω² toward the
pivot, dα along the swing):

    F_r = m(dω² + g cos θ),   F_t = m(dα + g sin θ),   F = √(F_r² + F_t²)

ω from energy at that angle (exact for every method). A bob at L = I/(md) has the same period;
struck there (the centre of percussion) the body turns about the pivot with no jolt at it.
"""

from __future__ import annotations

import math

from taucli.scenes.pendulum.swing import Swing, sine
from taucli.table import Results


def pivot_force(swing: Swing, mass: float, cm_distance: float, gravity: float, theta: float, speed: float | None) -> float | None:
    """F = √(F_r² + F_t²) at θ, the body turning at |ω| = speed there; None where it never gets there."""
    if speed is None:
        return None
    toward_pivot = mass * (cm_distance * speed * speed + gravity * math.cos(theta))
    # along the swing: m d α + m g sin θ = m g sin θ (I − md²)/I − m d κθ/I (no cancellation for a bob)
    along = mass * gravity * sine(theta) * (swing.inertia - mass * cm_distance * cm_distance) / swing.inertia - mass * cm_distance * swing.torsion * theta / swing.inertia
    return math.hypot(toward_pivot, along)


def put_pivot(results: Results, swing: Swing, mass: float | None, cm_distance: float, gravity: float) -> None:
    """The pivot's force at the start and at the bottom (with the body's mass), and L = I/(md)
    (with a mass and d > 0)."""
    if mass is not None:
        results.put("pivot_force0", pivot_force(swing, mass, cm_distance, gravity, swing.theta0, abs(swing.omega0)))
        results.put("pivot_force_bottom", pivot_force(swing, mass, cm_distance, gravity, 0.0, results["omega_bottom"].value))
    if mass and cm_distance:
        equivalent_length = swing.inertia / (mass * cm_distance)
        results.put("equivalent_length", equivalent_length)
        results.put("centre_of_percussion", equivalent_length)
