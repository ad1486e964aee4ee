"""The mean angular velocity of a spin-down run, ω_mean = θ/t, at 50 digits.

θ is the net angle the wheel has turned in the time t of the run (to --time, to a target, else
to the stop). Where the losses alone slow it (ω > 0 throughout),

    I dω/dt = −L(ω),   L(ω) = τ_f + b ω + k ωⁿ

so time and angle are quadratures over ω (dt = −I dω / L, dθ = ω dt):

    t(ω) = ∫_ω^ω₀ I dω' / L(ω'),   θ(ω) = ∫_ω^ω₀ I ω' dω' / L(ω')

to the stop (ω = 0: finite where τ_f > 0, or n < 1 with drag alone; the pole ω'^−n is
integrable there), and at a time T, ω is the root of t(ω) = T. Under a constant α (a drive
against friction, or --alpha; through ω = 0 and back): θ = ω₀ t + ½ α t², so θ/t = ω₀ + ½ α t.

Irodov 1.247: a flywheel slowed by a torque k√ω stops at t = 2I√ω₀/k having turned
θ = 2Iω₀^{3/2}/(3k): ⟨ω⟩ = ω₀/3, whatever I and k.
"""

from __future__ import annotations

import mpmath

from references import DPS, mp, mpf

WORK = DPS + 15


def _loss(friction, viscous, drag, exponent):
    tf, b, k, n = (mpf(x) for x in (friction, viscous, drag, exponent))
    return lambda w: tf + b * w + (k * w**n if k else 0)


def stop(inertia, omega0, friction=0, viscous=0, drag=0, exponent=2):
    """(t_stop, θ_stop, θ/t) of a wheel from ω₀ > 0 slowed by the losses alone (they must stop it).
    Under drag with n < 1 the quadratures are over x, ω = ω₀ x^p with p = 1/(1 − n): the pole
    ω^−n of drag alone becomes a constant (dω = pω₀x^{p−1}dx), and no digit is lost near ω = 0."""
    with mp.workdps(WORK):
        I, w0, n = mpf(inertia), mpf(omega0), mpf(exponent)
        L = _loss(friction, viscous, drag, exponent)
        p = 1 / (1 - n) if drag and n < 1 else mpf(1)

        def over_x(f):
            return mpmath.quad(lambda x: f(w0 * x**p) * p * w0 * x ** (p - 1), [0, 1])

        t = over_x(lambda w: I / L(w))
        theta = over_x(lambda w: I * w / L(w))
    with mp.workdps(DPS):
        return +t, +theta, +(theta / t)


def at_time(inertia, omega0, T, friction=0, viscous=0, drag=0, exponent=2):
    """(ω, θ, θ/T) at time T (before the stop) of a wheel from ω₀ > 0 slowed by the losses alone."""
    with mp.workdps(WORK):
        I, w0, T = mpf(inertia), mpf(omega0), mpf(T)
        L = _loss(friction, viscous, drag, exponent)

        def elapsed(w):
            return mpmath.quad(lambda v: I / L(v), [w, w0])

        lo, hi = mpf(0), w0  # t falls as ω rises: bisect for t(ω) = T, then Newton (dt/dω = −I/L)
        for _ in range(40):
            mid = (lo + hi) / 2
            if elapsed(mid) > T:
                lo = mid
            else:
                hi = mid
        w = (lo + hi) / 2
        for _ in range(20):
            step = (elapsed(w) - T) * L(w) / I
            w += step
            if abs(step) <= abs(w) * mpf(10) ** (-WORK + 5):
                break
        theta = mpmath.quad(lambda v: I * v / L(v), [w, w0])
    with mp.workdps(DPS):
        return +w, +theta, +(theta / T)


def constant_alpha(omega0, alpha, t):
    """(θ, θ/t) at t under a constant α (through ω = 0 and back, θ the net angle)."""
    with mp.workdps(WORK):
        w0, a, t = mpf(omega0), mpf(alpha), mpf(t)
        theta = w0 * t + a * t * t / 2
        mean = theta / t if t else w0
    with mp.workdps(DPS):
        return +theta, +mean
