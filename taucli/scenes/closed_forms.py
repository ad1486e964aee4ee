"""Closed-form motion of a wheel on an axle: I dω/dt = A − bω − kω², for ω ≥ 0.

A is the constant part of the net torque (driving torque less kinetic friction), b the viscous
coefficient, k the quadratic drag coefficient. With the roots of kω² + bω − A = 0 written as

    r₊ = 2A / (b + √D),  β = (b + √D)/2 = −k r₋,  D = b² + 4kA,

the solution is, with λ = √D/I, E = e^(−λt) and G = (1 − E)/λ:

    ω(t) = r₊ + (ω₀ − r₊) E / (E + (kω₀ + β) G / I)
    θ(t) = r₊ t + (ω₀ − r₊) G · L(k (ω₀ − r₊) G / I),   L(x) = ln(1 + x)/x
    t(ω₀ → ω₁) = I (ω₀ − ω₁) / ((kω₁ + β)(ω₀ − r₊)) · L(y),  y = (ω₁ − ω₀) √D / ((kω₁ + β)(ω₀ − r₊))

This one form covers viscous decay (k = 0: r₊ = A/b, the exponential), quadratic drag (D > 0:
tanh-like) and friction with quadratic drag (D < 0: √D imaginary, the tangent/arctangent
solution, evaluated in complex arithmetic whose imaginary parts cancel). It never divides by
k or by √D, so it keeps full precision as k -> 0 and D -> 0; G and L are evaluated by series
near zero. Uniform acceleration (b = k = 0) is the one case it leaves out.
"""

from __future__ import annotations

import cmath
import math
from typing import NamedTuple

Scalar = float | complex


def _series(x: Scalar, coefficient) -> Scalar:
    """Σ coefficient(n) (−x)^n for n ≥ 0, summed until the terms no longer count."""
    total: Scalar = 0.0
    power: Scalar = 1.0
    n = 0
    while True:
        term = coefficient(n) * power
        total += term
        if abs(term) <= 1e-17 * abs(total) or n > 80:
            return total
        power *= -x
        n += 1


def exp_fraction(u: Scalar) -> Scalar:
    """g1(u) = (1 − e^(−u))/u = Σ (−u)^n/(n+1)!, with g1(0) = 1."""
    if abs(u) < 0.5:
        return _series(u, lambda n: 1 / math.factorial(n + 1))
    if isinstance(u, complex):
        return (1 - cmath.exp(-u)) / u
    return -math.expm1(-u) / u


def exp_fraction2(u: Scalar) -> Scalar:
    """g2(u) = (1 − g1(u))/u = (u − 1 + e^(−u))/u² = Σ (−u)^n/(n+2)!, with g2(0) = ½."""
    if abs(u) < 0.5:
        return _series(u, lambda n: 1 / math.factorial(n + 2))
    return (1 - exp_fraction(u)) / u


def log_fraction(x: Scalar) -> Scalar:
    """L(x) = ln(1 + x)/x = Σ (−x)^n/(n+1), with L(0) = 1."""
    if abs(x) < 0.5:
        return _series(x, lambda n: 1 / (n + 1))
    if isinstance(x, complex):
        return cmath.log(1 + x) / x
    return math.log1p(x) / x


def log_fraction2(x: Scalar) -> Scalar:
    """M(x) = (1 − L(x))/x = (x − ln(1 + x))/x² = Σ (−x)^n/(n+2), with M(0) = ½.

    The series runs to |x| < 0.5; beyond it 1 − L(x) > 0.18, so the difference costs < 3 bits.
    """
    if abs(x) < 0.5:
        return _series(x, lambda n: 1 / (n + 2))
    return (1 - log_fraction(x)) / x


def _real(value: Scalar) -> float:
    return float(value.real) if isinstance(value, complex) else float(value)


class ClosedFormPhase(NamedTuple):  # NamedTuples, as report.Value: made on every run (a batch line), at a third of a frozen dataclass's cost
    """One phase of motion with ω ≥ 0: I dω/dt = A − bω − kω², from ω₀ at t = 0."""

    inertia: float
    constant: float  # A: driving torque less kinetic friction, in this phase's direction
    viscous: float  # b
    drag: float  # k
    omega0: float

    @property
    def uniform(self) -> bool:
        return self.viscous == 0 and self.drag == 0

    def _roots(self) -> tuple[Scalar, Scalar]:
        """(√D, r₊): √D imaginary when D < 0; r₊ the steady speed when it is real and positive."""
        a, b, k = self.constant, self.viscous, self.drag
        discriminant = b * b + 4 * k * a
        root = math.sqrt(discriminant) if discriminant >= 0 else complex(0.0, math.sqrt(-discriminant))
        steady = 0.0 if a == 0 else 2 * a / (b + root)
        return root, steady

    @property
    def stops(self) -> bool:
        """The wheel reaches ω = 0 in finite time exactly when the constant torque opposes it."""
        return self.constant < 0

    @property
    def steady_speed(self) -> float | None:
        """ω as t -> ∞ within this phase (None: grows without bound or reaches zero first)."""
        if self.stops:
            return None
        if self.uniform:
            return self.omega0 if self.constant == 0 else None
        root, steady = self._roots()
        return float(steady.real) if isinstance(steady, complex) else steady

    def omega(self, t: float) -> float:
        """ω(t) = [ω₀E + (A + k r₊ ω₀) G/I] / [E + (kω₀ + β) G/I], valid for 0 ≤ t ≤ t_stop.

        The same as r₊ + (ω₀ − r₊)E/(E + (kω₀ + β)G/I), rearranged with r₊β = A so that no
        term grows as k -> 0 (where r₊ ~ √(A/k) is large and imaginary under friction).
        """
        if self.uniform:
            return self.omega0 + self.constant / self.inertia * t
        root, steady = self._roots()
        k, w0, inertia = self.drag, self.omega0, self.inertia
        decay = root * t / inertia
        e = cmath.exp(-decay) if isinstance(decay, complex) else math.exp(-decay)
        g = t * exp_fraction(decay) / inertia
        beta = (self.viscous + root) / 2
        return _real((w0 * e + (self.constant + k * steady * w0) * g) / (e + (k * w0 + beta) * g))

    def change(self, t: float) -> float:
        """Δω = ω(t) − ω₀ from what makes it, not as the difference of two speeds (which, for a
        heavy wheel a small torque hardly moves, loses every digit of it; #42 item 8):

            Δω = N₀ (G/I) / (E + (kω₀ + β) G/I),   N₀ = A − bω₀ − kω₀²  (the net torque at the start),

        ω(t) − ω₀ of the form in ``omega``, since (ω₀ − r₊)(kω₀ + β) = −N₀ (kr₊ = β − b, βr₊ = A).
        """
        if self.uniform:
            return self.constant / self.inertia * t
        root, _ = self._roots()
        k, w0, inertia = self.drag, self.omega0, self.inertia
        decay = root * t / inertia
        e = cmath.exp(-decay) if isinstance(decay, complex) else math.exp(-decay)
        g = t * exp_fraction(decay) / inertia  # G/I
        start = self.constant - self.viscous * w0 - k * w0 * w0
        return _real(start * g / (e + (k * w0 + (self.viscous + root) / 2) * g))

    def rate(self, t: float) -> float:
        """dω/dt at t, from the phase variable rather than from ω(t), which near the steady speed
        would leave A − bω − kω² a difference of near-equal numbers:

            dω/dt = −(ω₀ − r₊) c E / (E + c G)²,   c = (kω₀ + β)/I,

        the derivative of ω(t) = r₊ + (ω₀ − r₊) E/(E + cG), with dE/dt = −λE and dG/dt = E.
        """
        if self.uniform:
            return self.constant / self.inertia
        root, steady = self._roots()
        k, w0, inertia = self.drag, self.omega0, self.inertia
        decay = root * t / inertia
        e = cmath.exp(-decay) if isinstance(decay, complex) else math.exp(-decay)
        g = t * exp_fraction(decay) / inertia  # G/I
        c = k * w0 + (self.viscous + root) / 2  # c·I
        denominator = e + c * g
        return _real(-(w0 - steady) * c * e / (inertia * denominator * denominator))

    def theta(self, t: float) -> float:
        """θ(t) = ω₀ G L(x) + r₊√D t² g2(λt)/I + t g1(λt) M(x) k r₊(ω₀ − r₊) G/I, x = k(ω₀ − r₊)G/I.

        The same as r₊t + (ω₀ − r₊) G L(x), with the two large r₊ terms cancelled analytically.
        """
        if self.uniform:
            return self.omega0 * t + self.constant / self.inertia * t * t / 2
        root, steady = self._roots()
        k, w0, inertia = self.drag, self.omega0, self.inertia
        decay = root * t / inertia
        g1 = exp_fraction(decay)
        g = t * g1
        x = k * (w0 - steady) * g / inertia
        value = (
            w0 * g * log_fraction(x)
            + steady * root * t * t * exp_fraction2(decay) / inertia
            + t * g1 * log_fraction2(x) * (k * steady * w0 - k * steady * steady) * g / inertia
        )
        return _real(value)

    def time_to(self, target: float) -> float | None:
        """The time from ω₀ to ω = target ≥ 0 (None if this phase never gets there):

        t = I(ω₀ − ω₁)/s · L((ω₁ − ω₀)√D/s),  s = (kω₁ + β)(ω₀ − r₊) = kω₁ω₀ − kω₁r₊ + βω₀ − A.
        """
        if target == self.omega0:
            return 0.0
        if self.uniform:
            rate = self.constant / self.inertia
            t = (target - self.omega0) / rate if rate else -1.0
            return t if t > 0 else None
        root, steady = self._roots()
        limit = 0.0 if self.stops else _real(steady)
        low, high = sorted((self.omega0, limit))
        if not (low <= target <= high) or (target == limit and not self.stops):
            return None
        k, w0 = self.drag, self.omega0
        beta = (self.viscous + root) / 2
        scale = k * target * w0 - k * target * steady + beta * w0 - self.constant
        y = (target - w0) * root / scale
        if abs(y) < 0.5:
            log_ratio = log_fraction(y)
        else:  # 1 + y straight from the parameters (β − √D = −k r₊): near y = −1 it would cancel
            one_plus_y = (k * target * w0 - k * steady * (target + w0) - self.constant + target * root) / scale
            log_ratio = (cmath.log(one_plus_y) if isinstance(one_plus_y, complex) else math.log(one_plus_y)) / y
        return _real(self.inertia * (w0 - target) / scale * log_ratio)

    def stop_time(self) -> float | None:
        return self.time_to(0.0) if self.stops else None
