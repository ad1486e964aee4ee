"""The article's Atwood machine on arrays: many machines at once, one a Monte Carlo draw (#45 item 4).

Both blocks hang on one radius R, nothing pulls or drives; the pulley is massless or of mass M
(shape factor c: I = cMR²) or of a given I, its axle friction τ_a; each draw its own. As
machine.solve_machine writes them for this machine (the forms kept to the last bit):

    a = s (s (m1 − m2) g − τa/R)/(m1 + m2 + J),  J = I/R²,  s = sgn(m1 − m2) where |m1 − m2| g > τa/R, else 0
    moving:  T1 = m1 (g(2 m2 + J) + s τa/R)/(m1 + m2 + J),  T2 = (m2 g (2 m1 + J) − s m2 τa/R)/(m1 + m2 + J)
             (T2 = T1 where J = 0 and τa = 0: the pulley's equation with I = 0)
    held:    T1 = m1 g, T2 = m2 g;   α = a/R;   a_massless: a with J = 0

``drawn`` gives each result as an array (NaN where the scene gives none), each draw's regime
(s + 1) and the draws it takes: a held machine at the very edge of holding, where the scene's
statics meets its intervals by rounding, is the scene's to solve. taucli.answering.mc_arrays
holds every regime to the scene's own solve at a few draws before it uses it.
"""

from __future__ import annotations

import math

import numpy as np

from taucli.scenes.assumed import STANDARD_GRAVITY
from taucli.scenes.atwood.pulley import Pulley
from taucli.scenes.atwood.slope import Slope

TAKES = {"m1", "m2", "pulley_mass", "pulley_radius", "pulley_shape", "pulley_inertia", "axle_friction", "g"}


def drawn(arguments: dict) -> tuple[dict[str, np.ndarray], np.ndarray, np.ndarray] | None:
    """(results, regime, taken) for the draws in ``arguments`` (atwood's keywords, the drawn ones
    arrays), or None where the form does not take these options at all."""
    given = {name: value for name, value in arguments.items() if value is not None}
    if not set(given) <= TAKES or "m1" not in given or "m2" not in given:
        return None
    shape_name, radius = given.get("pulley_shape"), given.get("pulley_radius")
    if shape_name is not None and (shape_name not in Pulley.SHAPE_FACTORS or "pulley_inertia" in given):
        return None
    if ("pulley_inertia" in given or "axle_friction" in given) and radius is None or ("pulley_inertia" in given and "pulley_mass" in given):
        return None  # (the scene's refusals)
    numbers = [np.asarray(value, dtype=float) for name, value in given.items() if name != "pulley_shape"]
    shape = np.broadcast(*numbers).shape

    def field(name: str, default: float = 0.0) -> np.ndarray:
        return np.broadcast_to(np.asarray(given.get(name, default), dtype=float), shape)

    m1, m2, g = field("m1"), field("m2"), field("g", STANDARD_GRAVITY)
    sin = Slope().sin_angle  # m2 hangs: exactly 1
    with np.errstate(all="ignore"):
        if "pulley_inertia" in given:
            added = field("pulley_inertia") / field("pulley_radius") ** 2
        else:
            added = Pulley.SHAPE_FACTORS[shape_name or "disc"] * field("pulley_mass")
        r1 = field("pulley_radius", math.nan)
        axle = np.where(field("axle_friction") != 0, field("axle_friction") / r1, 0.0)
        drive = (m1 - m2) * g
        direction = np.where(np.abs(drive) > axle, np.where(drive > 0, 1.0, -1.0), 0.0)
        moving = m1 + m2 * 1.0 * 1.0 + added
        a = np.where(direction != 0, direction * ((direction * drive - axle) / moving), 0.0)
        tension1 = m1 * ((g * (m2 * (1 + sin) + added) + direction * (0.0 + axle)) / moving)
        tension2 = np.where((added == 0) & (axle == 0), tension1,
                            (m2 * g * (m1 * (1 + sin) + sin * added) - direction * m2 * axle + direction * 0.0 * (m1 + added)) / moving)
        held = direction == 0
        weight1, weight2 = m1 * g * sin + 0.0, m2 * g * sin + 0.0
        tension1 = np.where(held, weight1, tension1)
        tension2 = np.where(held, weight2, tension2)
        light = m1 + m2 * 1.0 * 1.0
        found = {
            "a": a, "T1": tension1, "T2": tension2,
            "alpha": a / r1,
            "a_massless": np.where(direction != 0, direction * ((direction * drive - axle) / light), 0.0),
        }
    # held: T1 = m1 g and T2 = m2 g where each lies within what the other side and the axle allow, as computed
    edge = held & ~((0.0 - axle + weight2 <= weight1) & (weight1 <= 0.0 + axle + weight2)
                    & (weight1 - 0.0 - axle <= weight2) & (weight2 <= weight1 - 0.0 + axle))
    taken = (m1 > 0) & (m2 > 0) & (added >= 0) & (g > 0) & ~edge & np.isfinite(a) & np.isfinite(tension1) & np.isfinite(tension2)
    return found, (direction + 1).astype(int), taken
