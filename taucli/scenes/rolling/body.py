"""The rolling body: its k² = I/(mR²), the shape's only number (I = k² m R²), from a shape's
table K2, a given k2, or a given I with the mass and radius; and the checks every model of
rolling makes of what it is given.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from taucli.core.errors import InputError, did_you_mean
from taucli.writing.report import fmt

K2 = {"sphere": 0.4, "shell": 2 / 3, "disc": 0.5, "cylinder": 0.5, "ring": 1.0, "hoop": 1.0}
RIGHT_ANGLE = math.pi / 2


@dataclass(frozen=True)
class Roller:
    """The rolling body: k2 = I/(mR²), and mass and radius where something asks for them."""

    k2: float
    description: str
    mass: float | None = None
    radius: float | None = None


def roller(shape: str | None, k2: float | None, inertia: float | None, mass: float | None, radius: float | None) -> Roller:
    """The body from exactly one of SHAPE, k2 = I/(mR²), or I with the mass and radius."""
    given = [name for name, value in (("shape", shape), ("k2", k2), ("inertia", inertia)) if value is not None]
    if len(given) != 1:
        raise InputError(
            "shape" if not given else given[1],
            "is required: {shape}, {k2} or {inertia} (one of them)" if not given else f"conflicts with {{{given[0]}}}: describe the body once",
            example="taucli rolling sphere {angle} 30deg",
        )
    if shape is not None:
        if shape not in K2:
            raise InputError("shape", f"expected one of {', '.join(K2)}", example="sphere", got=repr(shape), hint=did_you_mean(shape, K2))
        return Roller(K2[shape], shape, mass, radius)
    if k2 is not None:
        return Roller(k2, "body", mass, radius)
    if mass is None or radius is None:
        raise InputError("mass" if mass is None else "{radius}", "is required with {inertia} (k² = I/(mR²))", example="{mass} 2kg {radius} 0.1m")
    return Roller(inertia / (mass * radius**2), "body", mass, radius)


def check_friction(mu_s: float | None, mu_k: float | None) -> None:
    """μk ≤ μs, as for every real pair of surfaces: a μk above μs is refused."""
    if mu_s is not None and mu_k is not None and mu_k > mu_s:
        raise InputError("mu_k", "must not exceed {mu_s} (kinetic friction is at most static friction)", got=f"{fmt(mu_k)} > {fmt(mu_s)}")
