"""Where each block is: hanging, on a table or on its own slope (the pulley at the top), and the
friction under it (--side1, --side2; --incline, --mu-k and --mu-s for m2).

Along the surface gravity pulls the block away from the pulley with m g sin θ and the surface
presses on it with N = m g cos θ; kinetic friction μk N opposes the sliding, static friction
holds up to μs N. Hanging (θ = 90°), the whole weight pulls and no normal force means no friction.
"""

from __future__ import annotations

import math
from typing import NamedTuple

from taucli.core.errors import InputError
from taucli.writing.report import fmt
from taucli.scenes.friction import static_coefficient

HANGING = math.pi / 2


class Slope(NamedTuple):
    """Where a block is: hanging (θ = 90°), on a table (0°) or a slope; its friction coefficients."""
    angle: float = HANGING
    mu_k: float | None = 0.0  # None: not given (friction.py's rule: needed only if m2 slides)
    mu_s: float | None = None

    @property
    def hanging(self) -> bool:
        return self.angle == HANGING

    @property
    def sin_angle(self) -> float:
        """sin θ, the share of m2's weight that pulls along the surface (hanging: exactly 1)."""
        return 1.0 if self.hanging else math.sin(self.angle)

    def normal(self, m2: float, g: float) -> float:
        """N = m2 g cos θ, the surface's push on m2 (hanging: exactly 0)."""
        return 0.0 if self.hanging else m2 * g * math.cos(self.angle)

    def surface(self) -> str:
        """What m2 lies on, in words: "a table" or "a 30° slope"."""
        return "a table" if self.angle == 0 else f"a {fmt(math.degrees(self.angle))}° slope"


def check_slope(slope: Slope, option: str = "incline") -> None:
    """The angle from 0 (a table) to 90° (hanging); μk at most μs. ``option`` names it: incline
    (with --mu-k and --mu-s), or side1, side2 (their keys)."""
    if not 0 <= slope.angle <= HANGING:
        example = "{incline} 30deg" if option == "incline" else "{" + option + '} "incline angle=30deg"'
        raise InputError(option if option == "incline" else "{" + option + "} angle=", "expected an angle from 0 to 90 deg", example=example,
                         got=f"{fmt(math.degrees(slope.angle))} deg")
    if slope.mu_s is not None and slope.mu_k is not None and slope.mu_k > slope.mu_s:
        if option == "incline":
            raise InputError("mu_k", "must not exceed {mu_s} (kinetic friction is at most static friction)", got=f"{fmt(slope.mu_k)} > {fmt(slope.mu_s)}")
        raise InputError("{" + option + "}", "has mu-s= below mu-k= (static friction is at least kinetic)", got=f"{fmt(slope.mu_s)} < {fmt(slope.mu_k)}")


def side_static(slope: Slope, option: str, notes: list[str]) -> float | None:
    """The static coefficient under a block, by friction.py's one rule (μs if given, else μk, with
    a note; neither: smooth), its note naming the block's option."""
    if slope.mu_s is not None or not slope.mu_k:  # μs given, or no μk to stand for it: no note
        return slope.mu_s
    said: list[str] = []
    mu_s = static_coefficient(slope.mu_s, slope.mu_k, said)
    if option != "incline":
        said = [note.replace("no --mu-s:", "{" + option + "} has no mu-s=:").replace("give --mu-s", "give mu-s=") for note in said]
    notes.extend(said)
    return mu_s


def side_of(side, option: str) -> Slope:
    """A block's place as --side1 or --side2 gave it (taucli.scenes.given.Side) as a Slope."""
    if side is None or side.surface == "hang":
        return Slope()
    angle = 0.0 if side.surface == "table" else side.angle
    return Slope(angle, 0.0 if side.mu_k is None and side.mu_s is None else side.mu_k, side.mu_s)
