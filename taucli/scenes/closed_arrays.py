"""The closed forms of taucli.scenes.closed_forms on numpy arrays: many times, or many wheels.

I dω/dt = A − bω − kω², for ω ≥ 0, with the roots of kω² + bω − A = 0 (D = b² + 4kA, r₊ = 2A/(b + √D)):

    ω(t) = [ω₀E + (A + k r₊ ω₀) G/I] / [E + (kω₀ + β) G/I],  E = e^(−λt), G = (1 − E)/λ, λ = √D/I
    θ(t) = ω₀ G L(x) + r₊√D t² g2(λt)/I + t g1(λt) M(x) k r₊(ω₀ − r₊) G/I,  x = k(ω₀ − r₊)G/I
    t(ω₀ → 0) = I ω₀/s · L(y),  s = βω₀ − A,  y = −ω₀√D/s

with g1, g2, L, M the series-guarded fractions of closed_forms (complex where D < 0): the same
forms term for term, so that the arrays cannot drift from the scalar solver (tests/fit/
test_fit_arrays.py and tests/answering/test_mc_arrays.py hold them to it at 1e-12).

``phase_state`` takes one phase (ClosedFormPhase: scalar I, A, b, k, ω₀) at many times (taucli
fit: a recording's samples). ``Phases`` takes many phases at once (a Monte Carlo's draws: each
its own I, A, b, k, ω₀) at one time each, split where the form changes (b = k = 0, the sign of D).
Imported by taucli.fit.arrays and taucli.answering.mc_arrays only: numpy is needed here alone.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

SERIES = 64  # terms of the guarded series (|x| < 0.5: the last is below 1e-19 of the first)


def _horner(x: np.ndarray, coefficient) -> np.ndarray:
    """Σₙ coefficient(n) (−x)ⁿ, n < SERIES."""
    total = np.full_like(x, coefficient(SERIES - 1))
    for n in range(SERIES - 2, -1, -1):
        total = total * -x + coefficient(n)
    return total


def _guarded(x: np.ndarray, coefficient, outside) -> np.ndarray:
    """The series where |x| < 0.5, ``outside(x)`` elsewhere (as closed_forms does)."""
    near = np.abs(x) < 0.5
    out = np.empty_like(x)
    if np.any(near):
        out[near] = _horner(x[near], coefficient)
    far = ~near
    if np.any(far):
        out[far] = outside(x[far])
    return out


_FACTORIAL = [float(math.factorial(n)) for n in range(SERIES + 3)]


def exp_fraction(u: np.ndarray) -> np.ndarray:
    """g1(u) = (1 − e^(−u))/u."""
    if not np.iscomplexobj(u):
        return np.where(u == 0, 1.0, -np.expm1(-u) / np.where(u == 0, 1.0, u))
    return _guarded(u, lambda n: 1 / _FACTORIAL[n + 1], lambda v: (1 - np.exp(-v)) / v)


def exp_fraction2(u: np.ndarray) -> np.ndarray:
    """g2(u) = (1 − g1(u))/u."""
    return _guarded(u, lambda n: 1 / _FACTORIAL[n + 2], lambda v: (1 - exp_fraction(v)) / v)


def log_fraction(x: np.ndarray) -> np.ndarray:
    """L(x) = ln(1 + x)/x."""
    if not np.iscomplexobj(x):
        return np.where(x == 0, 1.0, np.log1p(x) / np.where(x == 0, 1.0, x))
    return _guarded(x, lambda n: 1 / (n + 1), lambda v: np.log(1 + v) / v)


def log_fraction2(x: np.ndarray) -> np.ndarray:
    """M(x) = (1 − L(x))/x."""
    return _guarded(x, lambda n: 1 / (n + 2), lambda v: (1 - log_fraction(v)) / v)


def phase_state(closed, t: np.ndarray, angle: bool = True) -> tuple[np.ndarray, np.ndarray]:
    """(ω(t), θ(t)) of a ClosedFormPhase at every t of the array (each within the phase); θ
    zeros where ``angle`` is False (a fit of ω does not need it)."""
    inertia, a, w0 = closed.inertia, closed.constant, closed.omega0
    if closed.uniform:
        return w0 + a / inertia * t, (w0 * t + a / inertia * t * t / 2 if angle else np.zeros_like(t))
    root, steady = closed._roots()
    k = closed.drag
    decay = root * t / inertia
    beta = (closed.viscous + root) / 2
    if not angle and not isinstance(root, complex) and root > 0:  # ω alone, D > 0: G/I = (1 − E)/√D, fewer passes over a million samples
        e = np.exp(-decay)
        g = -np.expm1(-decay) / root
        return (w0 * e + (a + k * steady * w0) * g) / (e + (k * w0 + beta) * g), np.zeros_like(t)
    g1 = exp_fraction(decay)
    g = t * g1 / inertia  # G/I
    e = np.exp(-decay)
    omega = (w0 * e + (a + k * steady * w0) * g) / (e + (k * w0 + beta) * g)
    if not angle:
        return np.real(omega), np.zeros_like(t)
    x = k * (w0 - steady) * g
    theta = (w0 * t * g1 * log_fraction(x) + steady * root * t * t * exp_fraction2(decay) / inertia
             + t * g1 * log_fraction2(x) * (k * steady * w0 - k * steady * steady) * g)
    return np.real(omega), np.real(theta)


class Phases(NamedTuple):
    """Many phases of motion with ω ≥ 0, one a draw: I dω/dt = A − bω − kω² from ω₀ (each field
    an array of one shape). Each method splits the draws where the closed form changes and
    evaluates each part as ClosedFormPhase does its one."""

    inertia: np.ndarray
    constant: np.ndarray  # A
    viscous: np.ndarray  # b
    drag: np.ndarray  # k
    omega0: np.ndarray

    def part(self, mask: np.ndarray) -> "Phases":
        return Phases(*(field[mask] for field in self))

    @property
    def uniform(self) -> bool:
        """b = k = 0 for every draw (``parts`` gives only parts that are all or none so)."""
        return bool(np.all((self.viscous == 0) & (self.drag == 0)))

    def _roots(self) -> tuple[np.ndarray, np.ndarray]:
        """(√D, r₊) of each draw, for a part whose D is all ≥ 0 (real) or all < 0 (imaginary √D)."""
        a, b, k = self.constant, self.viscous, self.drag
        discriminant = b * b + 4 * k * a
        root = np.sqrt(discriminant) if np.all(discriminant >= 0) else 1j * np.sqrt(-discriminant)
        with np.errstate(divide="ignore", invalid="ignore"):
            steady = np.where(a == 0, 0.0, 2 * a / (b + root))
        return root, steady

    def parts(self):
        """(mask, part) over the draws: uniform (b = k = 0), D ≥ 0, D < 0; the empty ones left out."""
        uniform = (self.viscous == 0) & (self.drag == 0)
        negative = ~uniform & (self.viscous * self.viscous + 4 * self.drag * self.constant < 0)
        for mask in (uniform, ~uniform & ~negative, negative):
            if np.any(mask):
                yield mask, self.part(mask)

    def state(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(ω, θ) of each draw at its own time t (an array of the same shape)."""
        omega, theta = np.empty_like(self.omega0), np.empty_like(self.omega0)
        for mask, part in self.parts():
            omega[mask], theta[mask] = phase_state(part, t[mask])
        return omega, theta

    def theta(self, t: np.ndarray) -> np.ndarray:
        return self.state(t)[1]

    def stop_time(self) -> np.ndarray:
        """The time from ω₀ > 0 to ω = 0 of each draw whose A < 0 (ClosedFormPhase.time_to(0)):
        NaN for the others, and where the scalar form would refuse (a logarithm of a negative)."""
        found = np.full_like(self.omega0, math.nan)
        with np.errstate(divide="ignore", invalid="ignore"):
            for mask, part in self.parts():
                found[mask] = part._stop_time()
        found[~(self.constant < 0)] = math.nan
        return found

    def _stop_time(self) -> np.ndarray:
        w0, a, inertia = self.omega0, self.constant, self.inertia
        if self.uniform:
            rate = a / inertia
            t = (0.0 - w0) / rate
            return np.where((rate != 0) & (t > 0), t, math.nan)
        root, steady = self._roots()
        k = self.drag
        beta = (self.viscous + root) / 2
        scale = beta * w0 - a
        y = (0.0 - w0) * root / scale
        near = np.abs(y) < 0.5
        log_ratio = np.empty_like(y)
        if np.any(near):
            log_ratio[near] = _horner(y[near], lambda n: 1 / (n + 1))
        far = ~near
        if np.any(far):  # 1 + y straight from the parameters (β − √D = −k r₊): near y = −1 it would cancel
            one_plus_y = (-k[far] * steady[far] * w0[far] - a[far]) / scale[far]
            log_ratio[far] = np.log(one_plus_y) / y[far]
        return np.real(inertia * w0 / scale * log_ratio)
