"""Gravity alone (κ = 0), exactly, in Jacobi elliptic functions; a torsion spring alone, harmonic.

    I d²θ/dt² = −mgd sin θ,   ω₀ₙ = √(mgd/I),   k = sin(θ_max/2)

- it swings (k < 1): sin(θ/2) = k sn(ω₀ₙt + u₀, k), ω = 2kω₀ₙ cn, period 4K(k)/ω₀ₙ;
- it goes over the top (k > 1): it circulates with modulus 1/k, once round in 2K(1/k)/(kω₀ₙ);
- it has just the energy to reach the top (k = 1): sin(θ/2) = tanh(v), and never gets there.

Every function is taken from k' = cos(θ_max/2) (taucli/numerics/elliptic.py), so that 179.999° keeps its
digits. Each model gives state(t) = (θ, ω), time_to(θ) (the first time it reaches an angle) and
its period.
"""

from __future__ import annotations

import math

from taucli.numerics import elliptic
from taucli.scenes.pendulum.by_energy import ByEnergy
from taucli.scenes.pendulum.harmonic import Harmonic
from taucli.scenes.pendulum.swing import TWO_PI, Swing


def exact_model(swing: Swing):
    """The exact motion: harmonic under torsion alone, elliptic under gravity alone, the energy
    integral by quadrature under both (by_energy.py)."""
    if swing.gravity_torque and swing.torsion:
        return ByEnergy(swing)
    if swing.gravity_torque == 0:
        return Harmonic(math.sqrt(swing.torsion / swing.inertia), swing.theta0, swing.omega0)
    rate = math.sqrt(swing.gravity_torque / swing.inertia)
    # cos(θ₀/2) is correctly rounded near the top too (math.cos reduces its argument exactly); the
    # double nearest 180° (math.pi) is read as the top itself, so that 180deg is the balance.
    s0 = math.copysign(1.0, swing.theta0) if abs(swing.theta0) == math.pi else math.sin(swing.theta0 / 2)
    c0 = 0.0 if abs(swing.theta0) == math.pi else math.cos(swing.theta0 / 2)
    w = swing.omega0 / (2 * rate)
    kc2 = (c0 - abs(w)) * (c0 + abs(w))  # k'² = cos²(θ₀/2) − (ω₀/2ω₀ₙ)², as a product
    k = math.hypot(s0, w)
    if kc2 > 0:
        return Libration(swing, rate, k, math.sqrt(kc2))
    if kc2 < 0:
        return Circulation(swing, rate, k, math.sqrt(-kc2) / k)
    return Separatrix(swing, rate)


class Libration:
    """Gravity alone, swinging: sin(θ/2) = k sn(u, k), ω = 2kω₀ cn(u, k), u = u₀ + ω₀t."""
    def __init__(self, swing: Swing, rate: float, k: float, kc: float):
        self.swing, self.rate, self.k, self.kc = swing, rate, k, kc
        self.quarter = elliptic.complete_k(kc)
        self.period = 4 * self.quarter / rate
        self.amplitude = 2 * math.atan2(k, kc)
        if k == 0:
            self.u0 = 0.0
        else:
            self.u0 = elliptic.incomplete_f(math.sin(swing.theta0 / 2) / k, swing.omega0 / (2 * rate * k), kc)

    def state(self, t: float) -> tuple[float, float]:
        if self.k == 0:
            return 0.0, 0.0
        sn, cn, dn = elliptic.jacobi(self.u0 + self.rate * t, self.kc)
        return 2 * math.atan2(self.k * sn, dn), 2 * self.k * self.rate * cn

    def time_to(self, theta: float) -> float | None:
        if theta == self.swing.theta0:
            return 0.0
        speed = self.swing.speed_at(theta)
        if speed is None or self.k == 0:
            return None
        first = elliptic.incomplete_f(math.sin(theta / 2) / self.k, speed / (2 * self.rate * self.k), self.kc)
        period = 4 * self.quarter
        return min(((u - self.u0) % period) / self.rate for u in (first, 2 * self.quarter - first))


class Circulation:
    """Gravity alone, over the top: sin(θ/2) = sn(v, 1/k), v = ±v₀ + kω₀t, once round in 2K(1/k)/(kω₀)."""
    def __init__(self, swing: Swing, rate: float, k: float, kc: float):
        self.swing, self.rate, self.k, self.kc = swing, rate, k, kc  # kc: of the modulus 1/k
        self.sign = 1.0 if swing.omega0 > 0 else -1.0
        self.half_turn = elliptic.complete_k(kc)
        self.period = 2 * self.half_turn / (k * rate)
        self.v0 = self._v(swing.theta0)

    def _v(self, theta: float) -> float:
        return elliptic.incomplete_f(math.sin(theta / 2), math.cos(theta / 2), self.kc)

    def state(self, t: float) -> tuple[float, float]:
        v = self.sign * self.v0 + self.k * self.rate * t
        half = elliptic.amplitude(v, self.kc)
        _, _, dn = elliptic.jacobi(v, self.kc)
        return self.sign * 2 * half, self.sign * 2 * self.k * self.rate * dn

    def time_to(self, theta: float) -> float | None:
        if abs(theta) > math.pi:
            theta = math.remainder(theta, TWO_PI)
        gap = (self.sign * (self._v(theta) - self.v0)) % (2 * self.half_turn)
        return gap / (self.k * self.rate)


class Separatrix:
    """Gravity alone with just the energy to reach the top: sin(θ/2) = tanh(v), v = ±v₀ + ω₀t; it
    takes forever to get there (or, balanced at the top, stays)."""
    def __init__(self, swing: Swing, rate: float):
        self.swing, self.rate = swing, rate
        self.sign = 1.0 if swing.omega0 > 0 else -1.0
        self.balanced = swing.omega0 == 0
        self.v0 = self._v(swing.theta0) if not self.balanced else 0.0
        self.period = None

    @staticmethod
    def _v(theta: float) -> float:
        return math.asinh(math.tan(theta / 2))

    def state(self, t: float) -> tuple[float, float]:
        if self.balanced:
            return self.swing.theta0, 0.0
        v = self.sign * self.v0 + self.rate * t
        return self.sign * 2 * math.atan(math.sinh(v)), self.sign * 2 * self.rate / math.cosh(v)

    def time_to(self, theta: float) -> float | None:
        if theta == self.swing.theta0:
            return 0.0
        if self.balanced or abs(theta) >= math.pi:
            return None
        gap = self.sign * self._v(theta) - self.sign * self.v0
        return gap / self.rate if gap >= 0 else None

