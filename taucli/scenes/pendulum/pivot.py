"""The pivot's force on the body, and the equivalent simple pendulum.

The centre of mass moves on a circle of radius d, so F + mg = m a_cm with a_cm = (dω² toward the
pivot, dα along the swing):

    F_r = m(dω² + g cos θ)     along the line to the centre of mass, positive towards the pivot
    F_t = m(dα + g sin θ)      across it, positive towards larger angles
    F = √(F_r² + F_t²)
    F_h = F_t cos θ − F_r sin θ,   F_v = F_r cos θ + F_t sin θ

F_v is positive up; F_h is positive towards the side of positive angles (where sin of the
user's angle is positive: with --from-top that is the other side, so F_h changes sign with the
zero, as every angle does). ω from energy at that angle (exact for every method). A bob at
L = I/(md) has the same period; struck there (the centre of percussion) the body turns about
the pivot with no jolt at it.
"""

from __future__ import annotations

import math
from typing import NamedTuple

from taucli.scenes.angles import cos_exact, sin_exact
from taucli.scenes.pendulum.swing import Swing
from taucli.scenes.pendulum.zero import Zero
from taucli.options.table import Results


class PivotForce(NamedTuple):
    """The pivot's force on the body: along the line to the centre of mass (towards the pivot),
    across it (towards larger angles), horizontal and vertical (up), and its size."""
    radial: float
    tangential: float
    horizontal: float
    vertical: float
    size: float


def pivot_force(swing: Swing, mass: float, cm_distance: float, gravity: float, theta: float, speed: float | None,
                zero: Zero = Zero(), alpha: float | None = None) -> PivotForce | None:
    """The force at θ (from the bottom), the body turning at |ω| = speed there; None where it never
    gets there. ``alpha``: α there where more than gravity and the spring turn the body (a couple
    at the pivot), signed as θ."""
    if speed is None:
        return None
    sin, cos = sin_exact(theta), cos_exact(theta)
    radial = mass * (cm_distance * speed * speed + gravity * cos)
    if alpha is not None:
        tangential = mass * (cm_distance * alpha + gravity * sin)
    else:  # across: m d α + m g sin θ = m g sin θ (I − md²)/I − m d κθ/I (no cancellation for a bob)
        tangential = mass * gravity * sin * (swing.inertia - mass * cm_distance * cm_distance) / swing.inertia - mass * cm_distance * swing.torsion * theta / swing.inertia
    horizontal = tangential * cos - radial * sin
    vertical = radial * cos + tangential * sin
    return PivotForce(radial, tangential, -horizontal if zero.top else horizontal, vertical, math.hypot(radial, tangential))


_SUFFIXES = {"start": "0", "bottom": "_bottom", "angle": ""}


def put_pivot(results: Results, swing: Swing, mass: float | None, cm_distance: float, gravity: float, angle: float | None = None,
              speed_at_angle: float | None = None, zero: Zero = Zero(), alphas: dict[str, float] | None = None) -> None:
    """The pivot's force at the start, at the bottom and at --angle (with the body's mass): its size
    and its components; and L = I/(md) (with a mass and d > 0). ``alphas``: α at "start",
    "bottom", "angle" where a couple at the pivot turns the body too."""
    if mass is not None:
        where = {"start": (swing.theta0, abs(swing.omega0)), "bottom": (0.0, results["omega_bottom"].value)}
        if angle is not None:
            where["angle"] = (angle, speed_at_angle)
        for name, (theta, speed) in where.items():
            force = pivot_force(swing, mass, cm_distance, gravity, theta, speed, zero, None if alphas is None else alphas.get(name))
            suffix = _SUFFIXES[name]
            part = f" at {zero.text(theta)}" if name == "angle" else ""
            results.put("pivot_force" + suffix, None if force is None else force.size, part)
            for component in ("radial", "tangential", "horizontal", "vertical"):
                results.put(f"pivot_{component}{suffix}", None if force is None else getattr(force, component), part)
    if mass and cm_distance:
        equivalent_length = swing.inertia / (mass * cm_distance)
        results.put("equivalent_length", equivalent_length)
        results.put("centre_of_percussion", equivalent_length)
