"""Spin-down with a motor of constant power, and the drive torque of --in-time, at 50 digits.

A motor of constant power P against friction τ_f, viscous b and drag k (ω > 0):

    I dω/dt = P/ω − L(ω),   L(ω) = τ_f + b ω + k ω²          (P < 0: a load draining the wheel)

ω moves monotonically (towards the steady speed ω∞ where P = ω∞ L(ω∞), the one positive root
of kω³ + bω² + τ_f ω − P; or down to a stop when P < 0), so time, angle and each loss's work
are quadratures over ω:

    t(ω₁)  = ∫ I ω dω / (P − ω L(ω))          θ(ω₁) = ∫ I ω² dω / (P − ω L(ω))
    W_f = τ_f θ,   W_b = ∫ b ω² dt = ∫ b I ω³ dω / (P − ω L),   W_k = ∫ k I ω⁴ dω / (P − ω L)
    W_drive = P t,  the torque P/ω,  α₀ = (P/ω₀ − L(ω₀))/I,  KE = ½ I ω²

and ω at a time T is the root of t(ω) = T (bisection, then Newton with dt/dω = Iω/(P − ωL)).
Towards the steady speed the substitution ω = ω∞ − (ω∞ − ω₀)e^{−s} removes the pole:
P − ωL(ω) = (ω∞ − ω) Q(ω), Q = τ_f + b(ω∞ + ω) + k(ω∞² + ω∞ω + ω²), so dω/(P − ωL) = ds/Q.

--in-time: the constant drive τ that takes the wheel from ω₀ to ω₁ (> ω₀ >= 0) in a time T
against L:  T = ∫ I dω / (τ − L(ω)), solved for τ (t falls as τ grows; τ lies between L(ω₁)
and L(ω₁) + I(ω₁ − ω₀)/T); then θ = ∫ I ω dω / (τ − L(ω)), W_drive = τ θ, torque_net = τ − L(ω₀).
"""

from __future__ import annotations

import mpmath

from references import DPS, mp, mpf

WORK = DPS + 10


class PowerMotion:
    def __init__(self, inertia, power, friction=0, viscous=0, drag=0, omega0=0):
        with mp.workdps(WORK):
            self.I, self.P, self.tf, self.b, self.k, self.w0 = (mpf(x) for x in (inertia, power, friction, viscous, drag, omega0))

    def loss(self, w):
        return self.tf + self.b * w + self.k * w * w

    def rate(self, w):
        """dω/dt."""
        return (self.P / w - self.loss(w)) / self.I

    def omega_inf(self):
        """The positive root of k ω³ + b ω² + τ_f ω − P (P > 0); 0 for a load."""
        with mp.workdps(WORK):
            if self.P <= 0:
                return mpf(0)
            if self.tf == 0 and self.b == 0 and self.k == 0:
                return None
            f = lambda w: w * self.loss(w) - self.P  # noqa: E731  (increasing for w > 0)
            hi = mpf(1)
            while f(hi) < 0:
                hi *= 2
            lo = mpf(0)
            for _ in range(mp.prec + 10):
                mid = (lo + hi) / 2
                if f(mid) < 0:
                    lo = mid
                else:
                    hi = mid
            return (lo + hi) / 2

    def _q(self, w, steady):
        """(P − ω L(ω)) / (ω∞ − ω) = τ_f + b(ω∞ + ω) + k(ω∞² + ω∞ω + ω²), as P = ω∞ L(ω∞)."""
        return self.tf + self.b * (steady + w) + self.k * (steady * steady + steady * w + w * w)

    def _integral(self, w1, power):
        """∫ from ω₀ to ω₁ of I ωⁿ dω / (P − ω L(ω)).

        Towards a steady speed, ω = ω∞ − (ω∞ − ω₀) e^{−s} takes the pole away:
        dω / (P − ωL) = ds / Q(ω), so the integral is ∫₀^S I ωⁿ⁻¹ … smooth in s."""
        steady = self.omega_inf() if self.P > 0 else None
        if steady is None:
            return mpmath.quad(lambda w: self.I * w**power / (self.P - w * self.loss(w)), [self.w0, mpf(w1)], maxdegree=10)
        end = mpmath.log((steady - self.w0) / (steady - mpf(w1)))
        return self._s_integral(end, power, steady)

    def _s_integral(self, end, power, steady):
        def f(s):
            w = steady - (steady - self.w0) * mpmath.exp(-s)
            return self.I * w ** (power - 1) * w / self._q(w, steady)

        return mpmath.quad(f, [0, end], maxdegree=10)

    def to_omega(self, w1):
        """dict: t, theta, work_* and the rest on reaching ω₁ (w1 = 0: the stop of a load)."""
        with mp.workdps(WORK):
            w1 = mpf(w1)
            t = self._integral(w1, 1)
            theta = self._integral(w1, 2)
            out = dict(t=t, theta=theta, work_drive=self.P * t, work_friction=self.tf * theta,
                       work_viscous=self.b * self._integral(w1, 3), work_drag=self.k * self._integral(w1, 4),
                       KE=self.I * w1 * w1 / 2, omega=w1)
        with mp.workdps(DPS):
            return {k: +v for k, v in out.items()}

    def omega_at(self, T):
        """ω at time T (before any stop): the root of t(ω) = T."""
        with mp.workdps(WORK):
            T = mpf(T)
            steady = self.omega_inf() if self.P > 0 else mpf(0)
            if steady is None:  # no losses: ½Iω² = ½Iω₀² + P t
                return mpmath.sqrt(self.w0**2 + 2 * self.P * T / self.I)
            if self.P > 0:  # solve for s: T = ∫₀^s I ω/Q ds, dT/ds = I ω/Q
                def omega(s):
                    return steady - (steady - self.w0) * mpmath.exp(-s)

                s = mpf(0)
                while self._s_integral(s + 1, 1, steady) < T:
                    s += 1
                lo, hi = s, s + 1
                with mp.workdps(30):
                    for _ in range(50):
                        mid = (lo + hi) / 2
                        if self._s_integral(mid, 1, steady) < T:
                            lo = mid
                        else:
                            hi = mid
                s = (lo + hi) / 2
                for _ in range(8):
                    w = omega(s)
                    step = (self._s_integral(s, 1, steady) - T) * self._q(w, steady) / (self.I * w)
                    s -= step
                    if abs(step) < mpf(10) ** (-WORK + 2) * max(1, abs(s)):
                        break
                return omega(s)
            lo, hi = self.w0, steady
            with mp.workdps(30):
                for _ in range(60):
                    mid = (lo + hi) / 2
                    if abs(self._integral(mid, 1)) < T:
                        lo = mid
                    else:
                        hi = mid
            w = (lo + hi) / 2
            for _ in range(8):
                step = (self._integral(w, 1) - T) * (self.P - w * self.loss(w)) / (self.I * w)
                w -= step
                if abs(step) < abs(w) * mpf(10) ** (-WORK + 2):
                    break
            return w

    def at_time(self, T):
        w = self.omega_at(T)
        out = self.to_omega(w)
        return out


def in_time_torque(inertia, omega0, omega1, T, friction=0, viscous=0, drag=0):
    """dict: torque, torque_net (at the start), theta, work_drive, KE for --in-time.

    With the margin g = τ − L(ω₁) and x = ω₁ − ω, τ − L(ω) = g + x c(ω), c = b + k(ω₁ + ω), so
    nothing cancels near ω₁; x = (ω₁ − ω₀) e^{−s} turns dω/(τ − L) into x ds/(g + x c), smooth
    in s, which a long approach to ω₁ (a margin g of e^{−100}) does not trouble."""
    with mp.workdps(WORK):
        I, w0, w1, T, tf, b, k = (mpf(x) for x in (inertia, omega0, omega1, T, friction, viscous, drag))
        loss = lambda w: tf + b * w + k * w * w  # noqa: E731
        span = w1 - w0
        if b == 0 and k == 0:
            tau = tf + I * span / T
            theta = (w0 + w1) / 2 * T
            out = dict(torque=tau, torque_net=tau - loss(w0), theta=theta, work_drive=tau * theta, KE=I * w1 * w1 / 2,
                       work_friction=tf * theta, alpha0=(tau - loss(w0)) / I)
            with mp.workdps(DPS):
                return {key: +v for key, v in out.items()}

        def integral(g, power=0, square=False):
            c1 = b + 2 * k * w1
            end = max(mpmath.log(span * c1 / g), mpf(0)) + 80  # past it the integrand is below e^−80

            def f(s):
                x = span * mpmath.exp(-s)
                w = w1 - x
                den = g + x * (b + k * (w1 + w))
                return I * w**power * x / den ** (2 if square else 1)

            pts = [mpf(0)]
            while pts[-1] + 10 < end:
                pts.append(pts[-1] + 10)
            pts.append(end)
            return mpmath.quad(f, pts, maxdegree=8)

        top = mpmath.log(I * span / T)  # log of a margin at which t <= T; t grows as g falls
        with mp.workdps(30):
            lo = top - 1
            while integral(mpmath.exp(lo)) <= T:
                lo = top - 2 * (top - lo)
            hi = top
            for _ in range(25):  # then Newton
                mid = (lo + hi) / 2
                if integral(mpmath.exp(mid)) > T:
                    lo = mid
                else:
                    hi = mid
        u = (lo + hi) / 2  # Newton on u = log g: dt/du = −g ∫ I x /(τ − L)² ds
        for _ in range(20):
            g = mpmath.exp(u)
            step = (integral(g) - T) / (-g * integral(g, square=True))
            u -= step
            if abs(step) < mpf(10) ** (-WORK + 2) * max(1, abs(u)):
                break
        g = mpmath.exp(u)
        tau = loss(w1) + g
        theta = integral(g, power=1)
        out = dict(torque=tau, torque_net=tau - loss(w0), theta=theta, work_drive=tau * theta, KE=I * w1 * w1 / 2,
                   work_friction=tf * theta, alpha0=(tau - loss(w0)) / I)
    with mp.workdps(DPS):
        return {key: +v for key, v in out.items()}
