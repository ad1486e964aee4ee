"""A point at radius r on a body turning about a fixed axis, at 50 digits.

With the body's angular velocity ω, acceleration α and angle turned θ:

    v_t = |ω| r                      (speed)
    a_t = r α sgn ω                  (along the motion: negative while the body slows; from rest,
                                      the motion is the sense α starts it in, so a_t = |α| r)
    a_c = ω² r                       (towards the axis)
    a_total = √(a_t² + a_c²)
    a_angle = atan2(a_t, a_c)        (from the radius towards the motion)
    s = r θ                          (signed arc)
    chord = |r(cos θ, sin θ) − r(1, 0)| (straight from where the point started to where it is: the
                                      net angle θ decides it, whole turns drop out)

and the motions these are taken on:

    constant α:        ω = ω₀ + α t,  θ = ω₀ t + ½ α t²
    drive τ, viscous b: ω = ω∞ + (ω₀ − ω∞) e^{−bt/I}, ω∞ = τ/b,
                        α = (τ − b ω₀)/I · e^{−bt/I}           (never ω∞ − ω: it keeps its digits at large t)
                        θ = ω∞ t + (ω₀ − ω∞)(I/b)(−expm1(−bt/I))
    Atwood (hanging m₁, m₂, pulley I at radius R, no friction):
                        a = (m₁ − m₂) g / (m₁ + m₂ + I/R²),  α = a/R,  v = v₀ + a t,  x = v₀ t + ½ a t²
                        after a distance D downwards: v = √(v₀² + 2 a D), θ = D/R
"""

from __future__ import annotations

import mpmath

from references import DPS, mp, mpf


def point(omega, alpha, r, theta=None):
    """dict of v_t, a_t, a_c, a_total, a_angle and s (when θ is given) for a point at r."""
    with mp.workdps(DPS + 10):
        w, a, r = mpf(omega), mpf(alpha), mpf(r)
        sense = mpmath.sign(w) if w != 0 else mpmath.sign(a)
        a_t = r * a * sense
        a_c = w * w * r
        out = dict(v_t=abs(w) * r, a_t=a_t, a_c=a_c, a_total=mpmath.hypot(a_t, a_c), a_angle=mpmath.atan2(a_t, a_c))
        if theta is not None:
            out["s"] = r * mpf(theta)
    with mp.workdps(DPS):
        return {k: +v for k, v in out.items()}


def chord(r, theta):
    """The straight-line distance from the point's start, r(1, 0), to its place after turning θ
    about the axis, r(cos θ, sin θ): Pythagoras on the two positions, at 60 digits (θ of many
    turns loses none of them: θ is read exactly and mpmath reduces it; a small θ, where cos θ − 1
    cancels, gets twice its digits back)."""
    size = abs(mpf(theta))
    extra = 0 if size == 0 else int(abs(mpmath.log10(size))) * (2 if size < 1 else 1)
    with mp.workdps(DPS + 10 + extra):
        r, theta = mpf(r), mpf(theta)
        out = r * mpmath.hypot(mpmath.cos(theta) - 1, mpmath.sin(theta))
    with mp.workdps(DPS):
        return +out


def constant_alpha(omega0, alpha, t):
    """(ω, α, θ) at t under a constant α."""
    with mp.workdps(DPS + 10):
        w0, a, t = mpf(omega0), mpf(alpha), mpf(t)
        return w0 + a * t, a, w0 * t + a * t * t / 2


def viscous_drive(inertia, torque, viscous, omega0, t):
    """(ω, α, θ) at t of I ω' = τ − b ω."""
    with mp.workdps(DPS + 10):
        I, tau, b, w0, t = (mpf(x) for x in (inertia, torque, viscous, omega0, t))
        w_inf = tau / b
        decay = mpmath.exp(-b * t / I)
        omega = w_inf + (w0 - w_inf) * decay
        alpha = (tau - b * w0) / I * decay
        theta = w_inf * t + (w0 - w_inf) * (I / b) * -mpmath.expm1(-b * t / I)
        return omega, alpha, theta


def atwood(m1, m2, pulley_inertia, radius, g, v0=0, t=None, distance=None):
    """(ω, α, θ) of the pulley at t, or after m₁ has gone down by distance (v₀ >= 0, a > 0)."""
    with mp.workdps(DPS + 10):
        m1, m2, I, R, g, v0 = (mpf(x) for x in (m1, m2, pulley_inertia, radius, g, v0))
        a = (m1 - m2) * g / (m1 + m2 + I / (R * R))
        if distance is not None:
            D = mpf(distance)
            v = mpmath.sqrt(v0 * v0 + 2 * a * D)
            return v / R, a / R, D / R
        if t is None:
            return v0 / R, a / R, mpf(0)
        t = mpf(t)
        return (v0 + a * t) / R, a / R, (v0 * t + a * t * t / 2) / R
