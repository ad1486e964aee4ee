"""Where the angles are measured from: the downward vertical (the default), or the upward one
(--from-top: a toppling chimney, a falling stick), in the same sense either way.

    θ (from the bottom) = φ − 180°  for φ > 0,   φ + 180°  for φ ≤ 0     (φ from the top)

so φ = 0 is the top (θ = 180°) and φ = ±180° the bottom; angular velocities and accelerations are
the same in both (a positive ω turns toward larger angles). Every angle in (--angle0, --angle)
and out (amplitude, theta, the plot) is in the one the user chose; the solver works in θ.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from taucli.writing.report import fmt


@dataclass(frozen=True)
class Zero:
    """The zero of the user's angles: the bottom (θ itself) or the top (φ = θ ∓ 180°)."""
    top: bool = False

    def inward(self, angle: float | None) -> float | None:
        """θ from the bottom, for the user's angle (None stays None)."""
        if angle is None or not self.top:
            return angle
        return angle - math.pi if angle > 0 else angle + math.pi

    def outward(self, theta: float | None) -> float | None:
        """The user's angle for θ from the bottom (the bottom itself, from the top: +180°)."""
        if theta is None or not self.top:
            return theta
        return theta - math.pi if theta > 0 else theta + math.pi

    def text(self, theta: float) -> str:
        """θ as the user reads it: "θ = 30°", or "φ = 10° from the top"."""
        if not self.top:
            return f"θ = {fmt(math.degrees(theta))}°"
        return f"φ = {fmt(math.degrees(self.outward(theta)))}° from the top"
