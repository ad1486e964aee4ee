"""Quadrature: of samples fed one at a time (StreamingQuadrature: trapezoid and Simpson), of a
function by Gauss–Legendre (fixed panels, or panels halved where they disagree), and by
double-exponential (tanh-sinh) quadrature, for integrals with singular or near-singular ends.

    ∫ₐᵇ f dx = ∫ f(x(t)) x'(t) dt,   x(t) = a + (b − a)/(1 + e^(−2u)),   u = (π/2) sinh t

The weights fall off as exp(−(π/2)e^|t|), so a 1/√ singularity at an end (the time a pendulum
takes near a turning point, ∫dθ/ω) is integrated to full precision in a few dozen points. ``f``
is called as f(x, x − a, b − x), the distances to the ends computed from t without rounding x,
so that an integrand that needs them (ω near a turning point) keeps its digits there.
"""

from __future__ import annotations

import math
from collections import deque
from collections.abc import Callable
from math import fsum

LEVELS = 8  # halvings of the step, from h = 1 to h = 1/128
T_MAX = 4.6  # e^(−2u) at t = 4.6 is about 1e-109: beyond it the points are the ends themselves


def tanh_sinh(f: Callable[[float, float, float], float], a: float, b: float, *, rtol: float = 1e-14) -> tuple[float, float]:
    """∫ₐᵇ f dx and an error estimate (the change at the last halving), a < b."""
    width = b - a
    if width <= 0:
        return 0.0, 0.0

    def term(t: float) -> float:
        u = math.pi / 2 * math.sinh(t)
        near_a = width / (1 + math.exp(-2 * u))  # x − a, small where t < 0
        near_b = width / (1 + math.exp(2 * u))  # b − x, small where t > 0
        weight = width / 2 * (math.pi / 2) * math.cosh(t) / math.cosh(u) ** 2
        if weight == 0 or near_a == 0 or near_b == 0:
            return 0.0
        return weight * f(a + near_a if near_a <= near_b else b - near_b, near_a, near_b)

    h = 1.0
    total = term(0.0) + math.fsum(term(k * h) + term(-k * h) for k in range(1, int(T_MAX / h) + 1))
    estimate = h * total
    error = math.inf
    for _ in range(LEVELS):
        h /= 2
        total += math.fsum(term(k * h) + term(-k * h) for k in range(1, int(T_MAX / h) + 1, 2))
        better = h * total
        error = abs(better - estimate)
        estimate = better
        if error <= rtol * abs(estimate):
            break
    return estimate, error


# Quadrature of sampled data -----------------------------------------------------------------


class StreamingQuadrature:
    """∫ f dt over samples fed one at a time, by the trapezoid rule and by composite Simpson.

    Simpson's rule for uneven spacing takes the intervals in pairs,
        ∫ over [t0, t2] ≈ (h0 + h1)/6 · [(2 − h1/h0) f0 + (h0 + h1)²/(h0 h1) f1 + (2 − h0/h1) f2],
    exact for quadratics; an odd last interval takes the three-point formula exact for quadratics
    too. Only the last three samples are kept, so memory stays flat however long the data.
    """

    RULES = ("trapezoid", "simpson")

    def __init__(self) -> None:
        self.count = 0
        self.trapezoid = 0.0
        self._paired = 0.0  # Simpson over the even number of intervals closed so far
        self._window: deque[tuple[float, float]] = deque(maxlen=3)
        self.peak = (0.0, 0.0)  # (t, f) where |f| is largest
        self.low = self.high = 0.0  # the least and the largest f
        self.uneven = 1.0  # the largest ratio of two neighbouring intervals Simpson takes together

    def add(self, t: float, f: float) -> None:
        if self._window:
            t_prev, f_prev = self._window[-1]
            self.trapezoid += (t - t_prev) * (f + f_prev) / 2
        self._window.append((t, f))
        self.count += 1
        if self.count == 1 or abs(f) > abs(self.peak[1]):
            self.peak = (t, f)
        self.low, self.high = (f, f) if self.count == 1 else (min(self.low, f), max(self.high, f))
        if self.count >= 3:
            (t0, f0), (t1, f1), (t2, f2) = self._window
            h0, h1 = t1 - t0, t2 - t1
            self.uneven = max(self.uneven, h1 / h0, h0 / h1)
        if self.count >= 3 and (self.count - 1) % 2 == 0:
            self._paired += (h0 + h1) / 6 * ((2 - h1 / h0) * f0 + (h0 + h1) ** 2 / (h0 * h1) * f1 + (2 - h0 / h1) * f2)

    def simpson(self) -> float:
        """Composite Simpson over all samples so far (the trapezoid rule for two samples)."""
        if self.count < 3:
            return self.trapezoid
        if (self.count - 1) % 2 == 0:
            return self._paired
        (t0, f0), (t1, f1), (t2, f2) = self._window  # the odd last interval is [t1, t2]
        h0, h1 = t1 - t0, t2 - t1
        last = (2 * h1 * h1 + 3 * h0 * h1) / (6 * (h0 + h1)) * f2 + (h1 * h1 + 3 * h0 * h1) / (6 * h0) * f1 - h1**3 / (6 * h0 * (h0 + h1)) * f0
        return self._paired + last

    def result(self, rule: str) -> float:
        return self.trapezoid if rule == "trapezoid" else self.simpson()


# Gauss-Legendre quadrature of a function evaluated in increasing order --------------------------

# The 8-point Gauss-Legendre nodes on [-1, 1] (positive half) and their weights: exact for
# polynomials of degree 15.
_GL8_NODES = (0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363)
_GL8_WEIGHTS = (0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763)


def gauss_legendre(f: Callable[[float], float], a: float, b: float, panels: int = 128) -> float:
    """∫ f dt over [a, b] by 8-point Gauss-Legendre on ``panels`` equal panels.

    The nodes are visited in increasing t, so ``f`` may be a sampler that steps on from the
    last time it was asked (a stepping method's motion) rather than from the start.
    """
    if b <= a:
        return 0.0
    width = (b - a) / panels
    offsets = sorted([-x for x in _GL8_NODES] + list(_GL8_NODES))
    weights = {x: w for x, w in zip(_GL8_NODES, _GL8_WEIGHTS, strict=True)}
    terms = []
    for panel in range(panels):
        middle = a + (panel + 0.5) * width
        for x in offsets:
            terms.append(weights[abs(x)] * f(middle + x * width / 2))
    return fsum(terms) * width / 2


def adaptive_gauss(f: Callable[[float], float], a: float, b: float, rtol: float = 1e-13, max_panels: int = 4096) -> float:
    """∫ f over [a, b] (b < a gives the negative), by 8-point Gauss-Legendre on panels halved
    where a panel and its two halves disagree by more than rtol of the whole: an integrand that
    changes fast near one end (a log-like rise) gets small panels there and nowhere else."""
    if a == b:
        return 0.0
    if b < a:
        return -adaptive_gauss(f, b, a, rtol, max_panels)

    def panel(lo: float, hi: float) -> float:
        return gauss_legendre(f, lo, hi, panels=1)

    edges = [a + (b - a) * i / 16 for i in range(17)]
    pending = [(lo, hi, panel(lo, hi)) for lo, hi in zip(edges, edges[1:])]
    scale = abs(fsum(p[2] for p in pending))
    done: list[float] = []
    while pending:
        lo, hi, whole = pending.pop()
        middle = (lo + hi) / 2
        left, right = panel(lo, middle), panel(middle, hi)
        if abs(left + right - whole) <= rtol * scale or len(done) + len(pending) >= max_panels or middle in (lo, hi):
            done.append(left + right)
        else:
            pending += [(lo, middle, left), (middle, hi, right)]
    return fsum(done)
