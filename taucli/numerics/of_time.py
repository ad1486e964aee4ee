"""A quantity given as a formula of time, f(t) in SI, and its first and second integrals from 0:

    F₁(t) = ∫₀ᵗ f(s) ds,    F₂(t) = ∫₀ᵗ ∫₀ˢ f(u) du ds = ∫₀ᵗ (t − s) f(s) ds

so that an angular acceleration α(t) gives ω(t) = ω₀ + F₁(t) and θ(t) = ω₀ t + F₂(t), and a
torque τ(t) the angular impulse J = F₁(t). A polynomial Σ cₖ tᵏ is integrated exactly,
F₁ = Σ cₖ tᵏ⁺¹/(k + 1) and F₂ = Σ cₖ tᵏ⁺²/((k + 1)(k + 2)), each by Horner's rule; any other
formula by adaptive Gauss–Legendre quadrature (taucli.numerics.quadrature), F₂ as the one
integral of (t − s) f(s). Built by taucli.quantities.formula from the text a user typed.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from taucli.numerics.quadrature import gauss_legendre

MAX_PANELS = 4096


class FormulaFailed(ArithmeticError):
    """The formula has no finite value at a time it is needed (a division by zero, an overflow,
    the square root of a negative number): ``at`` is that time."""

    def __init__(self, at: float, why: str):
        super().__init__(f"no finite value at t = {at!r} s ({why})")
        self.at, self.why = at, why


@dataclass(frozen=True)
class OfTime:
    """f(t) in SI: ``coefficients`` (c₀, c₁, …) of a polynomial in t (seconds), or None and
    ``function`` (any other formula); ``text`` as typed, ``si_unit`` the unit f is in;
    ``variable`` its name (t, or theta: a turning moment's crank angle, in radians)."""

    text: str
    si_unit: str
    coefficients: tuple[float, ...] | None = None
    function: Callable[[float], float] | None = None
    variable: str = "t"
    waves: tuple | None = None  # ((c₀, c₁, …), ((w, s, c), …)): f = Σcₖxᵏ + Σ(s sin wx + c cos wx), beside ``function``

    @property
    def exact(self) -> bool:
        """Integrated in closed form (a polynomial, or a polynomial and its waves)."""
        return self.coefficients is not None or self.waves is not None

    def at(self, t: float) -> float:
        if self.coefficients is not None:
            return _horner(self.coefficients, t)
        return self._value(t)

    def first(self, t: float) -> float:
        """∫₀ᵗ f(s) ds."""
        if self.coefficients is not None:
            return t * _horner([c / (k + 1) for k, c in enumerate(self.coefficients)], t)
        if self.waves is not None:  # ∫₀ᵗ s sin ws + c cos ws = s(1 − cos wt)/w + c sin(wt)/w, 1 − cos x as 2 sin²(x/2)
            poly, terms = self.waves
            return math.fsum([t * _horner([c / (k + 1) for k, c in enumerate(poly)], t),
                              *(s * 2 * math.sin(w * t / 2) ** 2 / w + c * math.sin(w * t) / w for w, s, c in terms)])
        return self._integral(self._value, t)

    def second(self, t: float) -> float:
        """∫₀ᵗ (t − s) f(s) ds = ∫₀ᵗ ∫₀ˢ f."""
        if self.coefficients is not None:
            return t * t * _horner([c / ((k + 1) * (k + 2)) for k, c in enumerate(self.coefficients)], t)
        if self.waves is not None:  # ∫₀ᵗ of the first: s(t − sin(wt)/w)/w + c·2 sin²(wt/2)/w²
            poly, terms = self.waves
            return math.fsum([t * t * _horner([c / ((k + 1) * (k + 2)) for k, c in enumerate(poly)], t),
                              *(s * t * _less_sine(w * t) / w + c * 2 * math.sin(w * t / 2) ** 2 / (w * w) for w, s, c in terms)])
        return self._integral(lambda s: (t - s) * self._value(s), t)

    def describe(self) -> str:
        """The formula in SI, as a step shows it: "2 − 3 t" (a polynomial), else as typed."""
        if self.coefficients is None:
            return self.text
        terms = []
        for k, c in enumerate(self.coefficients):
            if c == 0:
                continue
            power = "" if k == 0 else f" {self.variable}" if k == 1 else f" {self.variable}^{k}"
            size = f"{abs(c):.6g}"
            body = (size if k == 0 or abs(c) != 1 else "") + power
            sign = "−" if c < 0 else "+"
            terms.append((sign, body.strip()))
        if not terms:
            return "0"
        first_sign, first = terms[0]
        return ("−" if first_sign == "−" else "") + first + "".join(f" {sign} {body}" for sign, body in terms[1:])

    def _value(self, t: float) -> float:
        try:
            value = self.function(t)
        except ZeroDivisionError:
            raise FormulaFailed(t, "a division by zero") from None
        except OverflowError:
            raise FormulaFailed(t, "too large a number") from None
        except ValueError:
            raise FormulaFailed(t, "the square root of a negative number") from None
        if not math.isfinite(value):
            raise FormulaFailed(t, "not a finite number")
        return value

    @staticmethod
    def _integral(f: Callable[[float], float], t: float) -> float:
        """∫₀ᵗ f by 8-point Gauss–Legendre on 16 panels, each halved while it and its halves
        disagree by more than 1e-13 of the whole; an integrand that will not settle (a pole
        within the run) raises FormulaFailed rather than give a number."""
        if t == 0:
            return 0.0

        def panel(lo: float, hi: float) -> float:
            return gauss_legendre(f, lo, hi, panels=1)

        edges = [t * i / 16 for i in range(17)]
        pending = [(lo, hi, panel(lo, hi)) for lo, hi in zip(edges, edges[1:])]
        scale = abs(math.fsum(p[2] for p in pending))
        done: list[float] = []
        while pending:
            lo, hi, whole = pending.pop()
            middle = (lo + hi) / 2
            left, right = panel(lo, middle), panel(middle, hi)
            error = abs(left + right - whole)
            if error <= 1e-13 * scale or error <= 1e-300:
                done.append(left + right)
            elif len(done) + len(pending) >= MAX_PANELS or middle in (lo, hi):
                raise FormulaFailed(middle, "its integral does not settle there: a pole, or a jump too sharp to integrate")
            else:
                pending += [(lo, middle, left), (middle, hi, right)]
        return math.fsum(done)


def _less_sine(u: float) -> float:
    """1 − sin(u)/u, by its series where u is small (the difference would lose its digits)."""
    if abs(u) > 0.1:
        return 1 - math.sin(u) / u
    total, term = 0.0, u * u / 6
    for k in range(1, 12):  # u²/3! − u⁴/5! + …: each term −u²/((2k + 2)(2k + 3)) of the one before
        total += term
        term *= -u * u / ((2 * k + 2) * (2 * k + 3))
    return total


def _horner(coefficients, t: float) -> float:
    total = 0.0
    for c in reversed(coefficients):
        total = total * t + c
    return total
