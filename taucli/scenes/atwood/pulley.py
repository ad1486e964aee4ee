"""The pulley: its rotational inertia from a mass and a shape, a given I, or parts about its
axle; its radius and axle friction, as the string feels them.

    I = k M R²   (k = ½ for a solid disc, 1 for a thin ring)
    α = a/R, so the torque equation (T1 − T2) R = I α reads T1 − T2 = (I/R²) a: the pulley
    adds I/R² to the moving mass (M/2 for a disc, M for a ring: R cancels)
    the axle friction torque τ_a acts on the string as a force τ_a/R
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import NamedTuple

from taucli.core.errors import InputError
from taucli.writing.report import fmt
from taucli.scenes.assumed import Assumed

DISC_NOTE = "pulley taken as a uniform solid disc (I = ½MR²); --pulley-shape ring for a thin ring"


class Pulley(NamedTuple):  # NamedTuples, as report.Value: made on every run (a batch line), at a third of a frozen dataclass's cost
    """The pulley: its mass and shape, or its moment of inertia; its radius; axle friction."""
    mass: float = 0.0
    radius: float | None = None
    shape: str | None = None  # "disc" or "ring"; None with a mass means a disc, with a note
    inertia: float | None = None
    axle_friction: float = 0.0

    SHAPE_FACTORS = {"disc": 0.5, "ring": 1.0}  # I = factor × M R²

    def effective_mass(self) -> float:
        """I/R², the mass the pulley adds to the moving system: M/2 for a disc, M for a ring."""
        if self.inertia is not None:
            assert self.radius is not None
            return self.inertia / self.radius**2
        return self.SHAPE_FACTORS[self.shape or "disc"] * self.mass

    def axle_force(self) -> float:
        """τ_a / R: the axle friction as a force on the string."""
        return 0.0 if not self.axle_friction else self.axle_friction / self.radius

    def symbol(self) -> str:
        if self.inertia is not None:
            return "I/R²"
        return "M/2" if (self.shape or "disc") == "disc" else "M"

    def words(self) -> str:
        """The pulley in the model's words: "given I", "solid disc" or "thin ring"."""
        if self.inertia is not None:
            return "given I"
        return "solid disc" if (self.shape or "disc") == "disc" else "thin ring"


def check_pulley(m1: float, m2: float, pulley: Pulley, *, radius_needed: bool = True) -> None:
    """Something to move; one description of the pulley; a radius where I or the axle friction
    reaches the string through it (``radius_needed``: not on a stepped pulley, whose strings
    leave at their steps' radii); a shape it knows."""
    if m1 + m2 == 0 and pulley.mass == 0 and pulley.inertia is None:
        raise InputError("m1", "and {m2} cannot both be zero (with a massless pulley nothing is there to move)", example="{m1} 4kg {m2} 1kg")
    if pulley.inertia is not None and (pulley.mass or pulley.shape):
        raise InputError("pulley_inertia", "conflicts with {pulley_mass} and {pulley_shape}: give one description of the pulley")
    if radius_needed:
        if pulley.inertia is not None and pulley.radius is None:
            raise InputError("pulley_radius", "is required with {pulley_inertia} (the pulley adds I/R² to the moving mass)", example="{pulley_radius} 0.1m")
        if pulley.axle_friction and pulley.radius is None:
            raise InputError("pulley_radius", "is required with {axle_friction} (the friction torque acts on the string as τ/R)", example="{pulley_radius} 0.1m")
    if pulley.shape is not None and pulley.shape not in Pulley.SHAPE_FACTORS:
        raise InputError("pulley_shape", "expected disc or ring", example="{pulley_shape} ring", got=repr(pulley.shape))


def with_parts(pulley: Pulley, parts: Sequence, assumed: Assumed, steps: float | None = None) -> Pulley:
    """The pulley with its parts: I = I of --pulley-inertia or of --pulley-mass (Σ over one axle adds),
    plus each part's moment about the axle (taucli.scenes.inertia, parallel axes included).

    A stepped pulley's strings leave at their steps (``steps``: the larger one's radius), so the
    parts' own I needs no --pulley-radius there; a mass given beside them is taken out to the
    pulley's radius, or to the larger step, as solve_stepped takes it."""
    rim = pulley.radius if pulley.radius is not None else steps
    if rim is None:
        raise InputError("pulley_radius", "is required with {part} (the pulley adds I/R² to the moving mass)", example="{pulley_radius} 0.1m")
    if pulley.inertia is not None and pulley.mass:
        raise InputError("pulley_inertia", "conflicts with {pulley_mass} and {pulley_shape}: give one description of the pulley")
    own_inertia = pulley.inertia if pulley.inertia is not None else Pulley.SHAPE_FACTORS[pulley.shape or "disc"] * pulley.mass * rim**2
    if pulley.mass and pulley.radius is None:
        assumed.notes.append(f"no --pulley-radius: the pulley's mass taken out to the larger step, R = {fmt(rim)} m; --pulley-radius or --pulley-inertia to change it")
    from taucli.scenes.inertia import body_inertia  # deferred: bodies and the shapes' table (6 ms), only for a pulley of parts

    added = body_inertia(parts)
    assumed.notes.extend(added.notes)
    assumed.notes.append(f"pulley: I = {fmt(own_inertia + added.inertia)} kg·m², {'the given pulley and ' if own_inertia else ''}{added.description}")
    return Pulley(0.0, pulley.radius, None, own_inertia + added.inertia, pulley.axle_friction)
