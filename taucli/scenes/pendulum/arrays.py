"""A pendulum let go from rest under gravity alone, on arrays: many at once, one a Monte Carlo draw (#45 item 4).

The body is a point mass at --radius (I = mr², d = r) or --inertia with --mass and --cm-distance;
it starts at rest at 0 < |θ₀| < 180°; each draw its own. As the scene writes them (swing.py,
reach.py, exact.py, pivot.py), with G = mgd and c = cos(θ₀/2), s = sin(θ₀/2):

    α₀ = |G sin θ₀|/I,   ω_b = √(2·2G s²/I),   T₀ = 2π√(I/G),   ω₀,over = √(2·2G c²/I),   amplitude = −θ₀,
    rise = 0,   KE_b = ½Iω_b²,   T = 4K(k)/√(G/I), k' = c (exact)  or  T₀ (small-angle),   t_bottom = T/4,
    pivot force at the start m√(g² cos² θ₀ + (g sin θ₀ (I − md²)/I)²), at the bottom m(dω_b² + g),   L = I/(md)

with K(k) = π/(2 AGM(1, k')) iterated as taucli.numerics.elliptic.agm does, each draw until it
converges. ``drawn`` gives each result as an array, one regime (a swing from rest) and the draws
it takes; taucli.answering.mc_arrays holds it to the scene's own solve at a few draws first.
"""

from __future__ import annotations

import math

import numpy as np

from taucli.numerics.elliptic import EPSILON
from taucli.scenes.assumed import STANDARD_GRAVITY
from taucli.scenes.pendulum.swing import TWO_PI

POINT = {"shape", "mass", "radius", "angle0", "g", "method"}
GIVEN_I = {"inertia", "mass", "cm_distance", "angle0", "g", "method"}


def complete_k(kc: np.ndarray) -> np.ndarray:
    """K(k) from k' > 0 of each draw: elliptic.complete_k, the AGM stepped for each draw until it
    has converged (and no further), so each is the scalar's to the bit."""
    a, b = np.ones_like(kc), kc.copy()
    for _ in range(64):
        going = ~(np.abs(a - b) <= 2 * EPSILON * a)
        if not np.any(going):
            break
        a[going], b[going] = (a[going] + b[going]) / 2, np.sqrt(a[going] * b[going])
    return math.pi / (2 * ((a + b) / 2))


def drawn(arguments: dict) -> tuple[dict[str, np.ndarray], np.ndarray, np.ndarray] | None:
    """(results, regime, taken) for the draws in ``arguments`` (pendulum's keywords, the drawn ones
    arrays), or None where the form does not take these options at all."""
    given = {name: value for name, value in arguments.items() if value is not None}
    point = given.get("shape") == "point"
    if not (point and set(given) <= POINT and "radius" in given and "mass" in given) and not (set(given) <= GIVEN_I and {"inertia", "mass", "cm_distance"} <= set(given)):
        return None
    method = str(given.get("method", "auto")).replace("_", "-")
    if method not in ("auto", "exact", "small-angle") or "angle0" not in given:
        return None
    numbers = [np.asarray(value, dtype=float) for name, value in given.items() if name not in ("shape", "method")]
    shape = np.broadcast(*numbers).shape

    def field(name: str, default: float = math.nan) -> np.ndarray:
        return np.broadcast_to(np.asarray(given.get(name, default), dtype=float), shape)

    mass, g, theta0 = field("mass"), field("g", STANDARD_GRAVITY), field("angle0")
    if point:
        distance = field("radius")
        inertia = mass * distance**2
    else:
        distance, inertia = field("cm_distance"), field("inertia")
    with np.errstate(all="ignore"):
        torque = mass * g * distance  # G
        half_sin, half_cos = np.sin(theta0 / 2), np.cos(theta0 / 2)
        bottom = np.sqrt(0.0 * 0.0 + 2 * (2 * torque * half_sin * half_sin) / inertia)
        small = TWO_PI * np.sqrt(inertia / (torque + 0.0))
        rate = np.sqrt(torque / inertia)
        period = small if method == "small-angle" else 4 * complete_k(np.sqrt(half_cos * half_cos)) / rate
        sin0, cos0 = np.sin(theta0), np.cos(theta0)
        radial0 = mass * (distance * 0.0 * 0.0 + g * cos0)
        tangential0 = mass * g * sin0 * (inertia - mass * distance * distance) / inertia - mass * distance * 0.0 * theta0 / inertia
        found = {
            "I": inertia.copy(), "cm_distance": distance.copy(),
            "alpha0": np.abs(-(torque * sin0 + 0.0 * theta0) / inertia),
            "omega_bottom": bottom,
            "period_small": small,
            "omega0_over": np.sqrt(2 * np.maximum(2 * torque * half_cos * half_cos + 0.0, 0.0) / inertia),
            "amplitude": -theta0,
            "rise": inertia * 0.0 * 0.0 * distance / (2 * torque),
            "KE_bottom": inertia * bottom * bottom / 2,
            "period": period,
            "t_bottom": period / 4,
            "pivot_force0": np.hypot(radial0, tangential0),
            "pivot_force_bottom": np.abs(mass * (distance * bottom * bottom + g * 1.0)),
            "equivalent_length": inertia / (mass * distance),
        }
        found["centre_of_percussion"] = found["equivalent_length"].copy()
    taken = (mass > 0) & (distance > 0) & (inertia > 0) & (g > 0) & (theta0 != 0) & (np.abs(theta0) < math.pi)
    if not point:  # I = I_cm + md² ≥ md² (the scene refuses less; near it, the scene's to say)
        taken &= inertia > mass * distance * distance * (1 + 1e-9)
    for values in found.values():
        taken &= np.isfinite(values)
    return found, np.zeros(shape, dtype=int), taken
