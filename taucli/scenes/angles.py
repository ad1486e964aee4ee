"""Sines and cosines that are exact where a problem's angle is a whole number of right angles.

An angle typed as 90deg is read as a float near π/2, whose math.cos is 6e-17, not 0: a lever at
right angles would keep a sliver of torque, a particle's line a sliver of offset. These give 0
and ±1 there.
"""

from __future__ import annotations

import math

_SLACK = 4e-16  # relative: how near a whole number of quarter turns counts as one


def sin_exact(angle: float) -> float:
    """sin θ, exactly 0 or ±1 at whole multiples of 90° (180deg read as π would give 1.2e-16)."""
    quarter = angle / (math.pi / 2)
    nearest = round(quarter)
    if abs(quarter - nearest) <= _SLACK * max(1.0, abs(quarter)):
        return (0.0, 1.0, 0.0, -1.0)[nearest % 4]
    return math.sin(angle)


def cos_exact(angle: float) -> float:
    """cos θ, exactly 0 or ±1 at whole multiples of 90°."""
    quarter = angle / (math.pi / 2)
    nearest = round(quarter)
    if abs(quarter - nearest) <= _SLACK * max(1.0, abs(quarter)):
        return (1.0, 0.0, -1.0, 0.0)[nearest % 4]
    return math.cos(angle)
