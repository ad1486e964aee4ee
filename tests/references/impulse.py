"""Particles and bodies meeting a body on a fixed axis (impulse --particle, --couple), at 50 digits.

While they meet, no external torque acts about the axis (the axle's force passes through it),
so the angular momentum about the axis is conserved:

    L₀ = I ω₀ + Σ I_c ω_c + Σ m v r⊥ + Σ m r² ω₀          (body, couples, moving particles, riders)
    L₁ = I₁ ω₁ + Σ m v′ r⊥                                  (what turns together, particles that leave)
    I₁ = I + Σ I_c + Σ m r² (particles that stick at r) + Σ m r′² (riders moved to r′)

A particle's line passes the axis at r⊥ = r sin φ (φ the angle between its velocity and the
radius where it meets the body; r⊥ = r without one). Written so that small exchanges keep
their digits (every term a difference of inputs, never of large totals):

    I₁ Δω = Σ I_c (ω_c − ω₀) + Σ m r (v sin φ − ω₀ r) + Σ m (r² − r′²) ω₀ + Σ m r⊥ (v − v′)
    J = I Δω,  ω₁ = ω₀ + Δω

A particle that rebounds with restitution e along its line (one particle alone): the speeds
along the line separate at e times the speed they met with, v′ − ω₁ r⊥ = −e (v − ω₀ r⊥), so

    Δω = m r⊥ (1 + e)(v − ω₀ r⊥) / (I + m r⊥²)
    KE_lost = ½ (1 − e²) [I m / (I + m r⊥²)] (v − ω₀ r⊥)²

A particle given by its speed relative to the body after (speed-relative=, v_rel: a toy train
on a track on a free wheel, a person walking on a turntable) moves at the body's own speed there
plus v_rel, along the rim in the body's positive sense: v₁ = ω₁ r′ + v_rel (r′ = radius-after, else
r), so its L₁ = m r′ (ω₁ r′ + v_rel): it turns with the body (m r′² joins I₁) and takes m r′ v_rel
from the rest: I₁ Δω gains −m r′ v_rel. Before, it rides (no speed=) or moves at speed=. Where one
is given, KE₁ = ½ I₁ ω₁² + Σ ½ m v_rel (v_rel + 2 ω₁ r′) + …, and KE_lost = KE₀ − KE₁ directly
at 90 digits (the walker's legs, the train's motor do work: KE_lost < 0).

Otherwise, with δ_j = ω_j − ω₀ for each part that ends at ω₁ (a particle that sticks turns
at v sin φ / r about the axis and loses its radial motion ½ m (v cos φ)² to the axle):

    KE_lost = ½ Σ A_j δ_j² − ½ I₁ Δω² + ½ R ω₀² + Σ ½ m (v − v′)(v + v′ − 2 ω₀ r⊥) + Σ ½ m (v cos φ)²

(R = Σ m (r′² − r²) of the riders, A_j the inertias before), which is KE₀ − KE₁ expanded about
ω₀ so that nothing large cancels; KE₀ = ½Iω₀² + Σ ½I_c ω_c² + Σ ½ m v² + Σ ½ m r² ω₀²,
KE₁ = ½ I₁ ω₁² + Σ ½ m v′², KE_lost_fraction = KE_lost / KE₀ (system totals, particles included).
"""

from __future__ import annotations

from dataclasses import dataclass

import mpmath

from references import DPS, mp, mpf

WORK = DPS + 40  # the general sum may cancel by a large ratio of inertias: 40 guard digits


@dataclass
class Particle:
    mass: float
    radius: float
    speed: float | None = None  # None: it rides on the body
    angle: float | None = None  # between its velocity and the radius (rad); None: 90°
    speed_after: float | None = None  # it leaves along its line
    e: float | None = None  # it rebounds with restitution e
    radius_after: float | None = None  # a rider moves here
    speed_relative: float | None = None  # after, it moves at this speed relative to the body (along the rim)


@dataclass
class Couple:
    inertia: float
    omega0: float


def meet(inertia, omega0, particles=(), couples=()):
    """The results of impulse with --particle and --couple: a dict of mpf at 50 digits."""
    with mp.workdps(WORK):
        I, w0 = mpf(inertia), mpf(omega0)
        L0 = I * w0
        KE0 = I * w0**2 / 2
        I1 = I
        push = mpf(0)  # I₁ Δω
        spread = mpf(0)  # ½ Σ A δ²
        extra = mpf(0)  # the other terms of KE_lost
        leaving = mpf(0)  # Σ m v′ r⊥
        KE_leavers = mpf(0)
        bounce = None
        walkers = []
        for c in couples:
            ic, wc = mpf(c.inertia), mpf(c.omega0)
            L0 += ic * wc
            KE0 += ic * wc**2 / 2
            I1 += ic
            push += ic * (wc - w0)
            spread += ic * (wc - w0) ** 2 / 2
        for p in particles:
            m, r = mpf(p.mass), mpf(p.radius)
            if p.speed_relative is not None:
                r2 = mpf(p.radius_after) if p.radius_after is not None else r
                vr = mpf(p.speed_relative)
                if p.speed is None:  # it rode with the body before
                    before = m * r * r * w0
                    KE0 += m * r * r * w0**2 / 2
                else:
                    v = mpf(p.speed)
                    before = m * v * r * (mpmath.sin(mpf(p.angle)) if p.angle is not None else 1)
                    KE0 += m * v * v / 2
                L0 += before
                I1 += m * r2 * r2
                push += before - m * r2 * r2 * w0 - m * r2 * vr
                walkers.append((m, r2, vr))
                continue
            if p.speed is None:  # a rider
                r2 = mpf(p.radius_after) if p.radius_after is not None else r
                L0 += m * r * r * w0
                KE0 += m * r * r * w0**2 / 2
                I1 += m * r2 * r2
                push += m * (r - r2) * (r + r2) * w0
                extra += m * (r2 - r) * (r2 + r) * w0**2 / 2
                continue
            v = mpf(p.speed)
            sin = mpmath.sin(mpf(p.angle)) if p.angle is not None else mpf(1)
            cos = mpmath.cos(mpf(p.angle)) if p.angle is not None else mpf(0)
            perp = r * sin
            L0 += m * v * perp
            KE0 += m * v * v / 2
            if p.e is not None:
                bounce = (m, v, perp, mpf(p.e))
            elif p.speed_after is not None:
                v2 = mpf(p.speed_after)
                leaving += m * v2 * perp
                KE_leavers += m * v2 * v2 / 2
                push += m * perp * (v - v2)
                extra += m * (v - v2) * (v + v2 - 2 * w0 * perp) / 2
            else:  # it sticks at r
                I1 += m * r * r
                push += m * r * (v * sin - w0 * r)
                spread += m * (v * sin - w0 * r) ** 2 / 2
                extra += m * (v * cos) ** 2 / 2
        if bounce is not None:
            m, v, perp, e = bounce
            u = v - w0 * perp
            dw = m * perp * (1 + e) * u / (I + m * perp**2)
            lost = (1 - e * e) * I * m * u * u / (2 * (I + m * perp**2))
            v2 = w0 * perp + u * (m * perp**2 - e * I) / (I + m * perp**2)
            KE1 = I * (w0 + dw) ** 2 / 2 + m * v2 * v2 / 2
        else:
            dw = push / I1
            lost = spread - I1 * dw**2 / 2 + extra
            KE1 = I1 * (w0 + dw) ** 2 / 2 + KE_leavers
            if walkers:
                w1 = w0 + dw
                KE1 += sum(m * vr * (vr + 2 * w1 * r2) / 2 for m, r2, vr in walkers)
                lost = KE0 - KE1
        out = dict(J=I * dw, delta_omega=dw, omega1=w0 + dw, L0=L0, L1=L0, KE0=KE0, KE1=KE1, KE_lost=lost,
                   KE_lost_fraction=lost / KE0 if KE0 else None)
    with mp.workdps(DPS):
        return {k: (+v if v is not None else None) for k, v in out.items()}
