"""A round body down an incline from rest on arrays: many at once, one a Monte Carlo draw (#45 item 4).

incline.solve_incline for a body (a --shape, --k2, or --inertia with --mass and --radius) let go
on a slope of 0 < θ < 90°, each draw its own, written as it writes them:

    rolls (μs ≥ μ_min = tan θ · k²/(1 + k²), or no μs):  a = g sin θ/(1 + k²),  f/m = g sin θ · k²/(1 + k²),  α = a/R
    slips (μs < μ_min, μk given):                          a = g (sin θ − μk cos θ),  f/m = μk g cos θ,  α = (f/m)/(k² R)
    to the bottom (--length L, or --height h = L sin θ):   v = √(2aL),  t = 2L/v,  Rω = v (rolls) or (f/m)/k² · t (slips),
                                                           KE_trans = ½ m v²,  KE_rot = ½ k² m (Rω)²

``drawn`` gives each result as an array (NaN where the scene gives none), each draw's regime
(rolls or slips) and the draws it takes: one that slips with no μk, or that does not slide down
at all, is the scene's to solve. taucli.answering.mc_arrays holds every regime to the scene's
own solve at a few draws before it uses it.
"""

from __future__ import annotations

import math

import numpy as np

from taucli.scenes.assumed import STANDARD_GRAVITY
from taucli.scenes.rolling.body import K2, RIGHT_ANGLE

TAKES = {"shape", "k2", "inertia", "mass", "radius", "angle", "mu_s", "mu_k", "length", "height", "g"}


def drawn(arguments: dict) -> tuple[dict[str, np.ndarray], np.ndarray, np.ndarray] | None:
    """(results, regime, taken) for the draws in ``arguments`` (rolling's keywords, the drawn ones
    arrays), or None where the form does not take these options at all."""
    given = {name: value for name, value in arguments.items() if value is not None}
    bodies = [name for name in ("shape", "k2", "inertia") if name in given]
    if not set(given) <= TAKES or len(bodies) != 1 or "angle" not in given or ("length" in given and "height" in given):
        return None
    if given.get("shape", "sphere") not in K2 or ("inertia" in given and ("mass" not in given or "radius" not in given)):
        return None
    numbers = [np.asarray(value, dtype=float) for name, value in given.items() if name != "shape"]
    shape = np.broadcast(*numbers).shape

    def field(name: str, default: float = math.nan) -> np.ndarray:
        return np.broadcast_to(np.asarray(given.get(name, default), dtype=float), shape)

    angle, g, mass, radius = field("angle"), field("g", STANDARD_GRAVITY), field("mass"), field("radius")
    with np.errstate(all="ignore"):
        if "shape" in given:
            k2 = np.full(shape, K2[given["shape"]])
        elif "k2" in given:
            k2 = field("k2").copy()
        else:
            k2 = field("inertia") / (mass * radius**2)
        sin_a, cos_a = np.sin(angle), np.cos(angle)
        mu_min = np.tan(angle) * k2 / (1 + k2)
        static = field("mu_s") if "mu_s" in given else field("mu_k")
        mu_k = field("mu_k")
        rolls = np.isnan(static) | (static >= mu_min)
        a = np.where(rolls, g * sin_a / (1 + k2), g * (sin_a - mu_k * cos_a))
        per_mass = np.where(rolls, g * sin_a * k2 / (1 + k2), mu_k * g * cos_a)
        found = {
            "a": a,
            "alpha": np.where(rolls, a / radius, per_mass / (k2 * radius)),
            "friction": mass * per_mass,
            "mu_min": mu_min,
        }
        if "length" in given or "height" in given:
            slope_length = field("length") if "length" in given else field("height") / sin_a
            speed = np.sqrt(0.0 * 0.0 + 2 * a * slope_length)
            duration = 2 * slope_length / (speed - 0.0)
            spin_up = np.where(per_mass != 0, per_mass / k2 * duration, 0.0)
            rim_speed = np.where(rolls, speed, spin_up - 0.0)
            found.update({"v": speed, "t": duration, "omega": rim_speed / radius,
                          "KE_trans": 0.5 * mass * speed**2, "KE_rot": 0.5 * k2 * mass * rim_speed**2})
            taken_length = (a > 0) & (slope_length > 0)
        else:
            taken_length = np.ones(shape, dtype=bool)
    taken = ((angle > 0) & (angle < RIGHT_ANGLE) & (k2 > 0) & (g > 0) & (rolls | ~np.isnan(mu_k)) & taken_length
             & ~(~np.isnan(static) & ~np.isnan(mu_k) & (mu_k > static)) & np.isfinite(a))
    return found, (~rolls).astype(int), taken
