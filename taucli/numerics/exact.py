"""Products and differences of products without rounding error: Dekker's two-product by
Veltkamp's split. a·b is fl(a·b) plus an error that is itself a double, found exactly; summed with
math.fsum, terms such as m1·g − m2·g keep every digit where they nearly cancel (an Atwood machine
near balance, a stepped pulley with m1 r1 ≈ m2 r2).
"""

from __future__ import annotations

import math


def product_terms(a: float, b: float, c: float = 1.0) -> tuple[float, ...]:
    """a·b (·c) as floats that sum to it exactly: each product and its rounding error (Dekker's
    two-product by Veltkamp's split; the third factor, g, multiplies both)."""
    first = a * b
    if not math.isfinite(first) or max(abs(a), abs(b)) > 1e150:
        return (first * c,)
    error = product_error(a, b, first)
    if c == 1.0:
        return first, error
    return (*product_terms(first, c), *product_terms(error, c))


def product_difference(a: float, b: float, c: float, d: float) -> float:
    """a·b − c·d to within an ulp or so, also where the two products nearly cancel (a stepped
    pulley near balance, m1 r1 ≈ m2 r2): each product's rounding error is found exactly and added
    back after the difference."""
    first, second = a * b, c * d
    if not (math.isfinite(first) and math.isfinite(second)) or max(abs(a), abs(b), abs(c), abs(d)) > 1e150:
        return first - second  # the split would overflow; nothing near cancellation is that large here
    return (first - second) + (product_error(a, b, first) - product_error(c, d, second))


def product_error(a: float, b: float, product: float) -> float:
    """The exact a·b − fl(a·b)."""
    a_high, a_low = split(a)
    b_high, b_low = split(b)
    return ((a_high * b_high - product) + a_high * b_low + a_low * b_high) + a_low * b_low


def split(x: float) -> tuple[float, float]:
    """Veltkamp's split: x = high + low exactly, each with half of x's 53 bits."""
    c = 134217729.0 * x  # 2^27 + 1
    high = c - (c - x)
    return high, x - high
