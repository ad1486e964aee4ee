"""The roots of a top's steady precession, written to keep their digits (see top.py).

I⊥Ω² cos θ − Iω_sΩ + mgr = 0: the slow root 2c/(−b + √D), the fast (−b − √D)/2a, from ρ = 4ac/b²
formed from mantissas and exponents so that nothing overflows.
"""

from __future__ import annotations

import math

TWO_PI = 2.0 * math.pi
HALF_PI = 0.5 * math.pi
TILT_SLACK = 4.5e-16  # two ulps of π/2: "90deg" and "0.25rev" read as the float nearest π/2, or next to it
APPROXIMATION_NOTED = 1e-3  # the approximation's relative error is noted above this


def tilt_cos_sin(theta: float) -> tuple[float, float]:
    """cos θ and sin θ, exact at 0, 90 and 180 degrees (a float near π/2 has cos 6e-17, not 0:
    that would turn "one root at 90°" into a fast root of 1e16)."""
    if abs(theta - HALF_PI) <= TILT_SLACK:
        return 0.0, 1.0
    if abs(theta - math.pi) <= 2 * TILT_SLACK:
        return -1.0, 0.0
    if theta == 0:
        return 1.0, 0.0
    return math.cos(theta), math.sin(theta)


def discriminant_ratio(a: float, c: float, b: float) -> float:
    """ρ = 4ac/b², from mantissas and exponents: b² and ac are never formed, so nothing
    overflows or underflows on the way to a ρ that is in range (±inf and 0 where ρ is not)."""
    if a == 0 or c == 0:
        return 0.0
    ma, ea = math.frexp(a)
    mc, ec = math.frexp(c)
    mb, eb = math.frexp(b)
    try:
        return math.ldexp(4.0 * ma * mc / (mb * mb), ea + ec - 2 * eb)
    except OverflowError:
        return math.copysign(math.inf, a * c)


def precession_roots(inertia_perp_cos: float, angular_momentum: float, weight_torque: float) -> tuple[float, float | None] | None:
    """The roots (slow, fast) of I⊥cosθ·Ω² − LΩ + mgr = 0 for L > 0 and mgr ≥ 0; fast is None
    where the equation is linear (cos θ = 0) or the root is out of range; None where no real
    root exists (ρ > 1: no steady precession)."""
    rho = discriminant_ratio(inertia_perp_cos, weight_torque, angular_momentum)
    if rho > 1:
        return None
    s = math.sqrt(1.0 - rho)
    slow = (weight_torque / angular_momentum) * (2.0 / (1.0 + s))
    if inertia_perp_cos == 0:
        return slow, None
    fast = angular_momentum * (1.0 + s) / (2.0 * inertia_perp_cos)
    return slow, fast if math.isfinite(fast) else None


def approximation_error(inertia_perp_cos: float, angular_momentum: float, weight_torque: float) -> float:
    """mgr/(Iω_s) over the slow root, less 1: (s − 1)/2 = −ρ/(2(1 + s)), free of cancellation.
    It equals −I⊥Ω_slow cos θ/(Iω_s), the share of the term the approximation leaves out."""
    rho = discriminant_ratio(inertia_perp_cos, weight_torque, angular_momentum)
    return -rho / (2.0 * (1.0 + math.sqrt(1.0 - rho)))


def least_spin(inertia: float, inertia_perp_cos: float, weight_torque: float) -> float:
    """ω_min = √(4·I⊥·mgr·cos θ)/I (cos θ > 0), as a product of square roots (no overflow)."""
    return 2.0 * math.sqrt(inertia_perp_cos) * math.sqrt(weight_torque) / inertia


def finite(x: float | None) -> float | None:
    return x if x is not None and math.isfinite(x) else None


