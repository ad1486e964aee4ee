"""Where m2 is: hanging, on a table or on a slope, and the friction under it.

Along the surface gravity pulls m2 back with m2 g sin θ and the surface presses on it with
N = m2 g cos θ; kinetic friction μk N opposes the sliding, static friction holds up to μs N.
Hanging (θ = 90°), the whole weight pulls and no normal force means no friction.
"""

from __future__ import annotations

import math
from typing import NamedTuple

from taucli.errors import InputError
from taucli.report import fmt

HANGING = math.pi / 2


class Slope(NamedTuple):
    """Where m2 is: hanging (θ = 90°), on a table (0°) or a slope; its friction coefficients."""
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


def check_slope(slope: Slope) -> None:
    """The angle from 0 (a table) to 90° (hanging); μk at most μs."""
    if not 0 <= slope.angle <= HANGING:
        raise InputError("incline", "expected an angle from 0 to 90 deg", example="{incline} 30deg", got=f"{fmt(math.degrees(slope.angle))} deg")
    if slope.mu_s is not None and slope.mu_k is not None and slope.mu_k > slope.mu_s:
        raise InputError("mu_k", "must not exceed {mu_s} (kinetic friction is at most static friction)", got=f"{fmt(slope.mu_k)} > {fmt(slope.mu_s)}")
