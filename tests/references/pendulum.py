"""A body on a pivot, I θ'' = −m g d sin θ − κ θ (θ from the downward vertical), at 50 digits.

Per unit of inertia, with λ = m g d / I and μ = κ / I:

    θ'' = −λ sin θ − μ θ
    U(θ) = λ (1 − cos θ) + ½ μ θ² = 2λ sin²(θ/2) + ½ μ θ²          (potential energy / I)
    ω(θ)² = ω₀² − 2 [U(θ) − U(θ₀)]                                    (energy is conserved)
    U(p + δ) − U(p) = 2λ sin(δ/2) sin(p + δ/2) + μ δ (p + δ/2)         (no cancellation as δ -> 0)

so E(θ) = ½Iω² + mgd(1 − cos θ) + ½κθ² is constant. Then:

- alpha0 = |λ sin θ₀ + μ θ₀| (the size of θ'' at the start).
- Turning angles: the first θ from θ₀ along the motion where ω = 0, i.e. U(θ) = E. They are
  bracketed between the critical points of U (U'(θ) = λ sin θ + μ θ = 0: the local maxima
  lie in ((2n−1)π, 2nπ) where λ sin θ + μ θ dips below zero) and found by bisection.
- Gravity alone (μ = 0): with k² = sin²(θ₀/2) + ω₀²/(4λ) (sin²(θ_max/2) for a swing),
  a swing (k < 1) has period 4K(k²)/√λ, and sin(θ/2) = k sn(√λ t + u₀ | k²), ω = 2k√λ cn(…);
  the time from the bottom to θ is F(φ | k²)/√λ with sin(θ/2) = k sin φ. Going over the top
  (k > 1, ω_b² = 4λk²): one turn takes 4K(1/k²)/ω_b, θ/2 = am(ω_b t/2 + F(θ₀/2 | 1/k²)), and
  ω = ω_b dn(…). Angles are positions there (θ and θ + 2π are the same place).
- A spring alone (λ = 0): harmonic, period 2π/√μ, θ = θ₀ cos √μ t + (ω₀/√μ) sin √μ t.
- Both: the period is 2∫ dθ/|ω| between the turning angles, and the time to an angle ∫ dθ/|ω|
  along the motion (through a turning angle and back where the angle lies behind). At a
  turning angle b the integrand is singular (ω ~ √|θ − b|): θ = b ± D v² removes it. The
  intervals are split at the critical points of U, where a slow passage makes a peak, and near
  a turning angle by the top (U'(b) small), geometrically. θ(t) comes from a Taylor-series
  solution of the equation of motion (60 terms, a step well inside the series' radius), over
  t modulo the period.
- omega0_over: the least |ω₀| that reaches θ = ±π; U rises from 0 to π on either side, so it is
  √(2[U(π) − U(θ₀)]) = √(4λ cos²(θ₀/2) + μ(π − |θ₀|)(π + |θ₀|)). goes_over: E > U(π).
- The pivot's force on the body, from Newton's second law for the centre of mass at
  r = d(sin θ, −cos θ): F + m g = m a, a = d θ'' t̂ − d ω² n̂ (t̂ = (cos θ, sin θ) along the
  motion of larger θ, n̂ = (−sin θ, cos θ) from the centre of mass towards the pivot):
      radial (towards the pivot)   F·n̂ = m d ω² + m g cos θ
      tangential (along +θ)        F·t̂ = m d θ'' + m g sin θ
                                        = [m g sin θ (I − m d²) − m d κ θ] / I
  and the size √(radial² + tangential²).
- The pivot's force as components (#34 item 6), from Newton's second law for the centre of mass
  written in x (horizontal, towards positive θ) and y (up), with no radial/tangential split:
      x = d sin θ, y = −d cos θ;  x'' = d(θ'' cos θ − ω² sin θ), y'' = d(θ'' sin θ + ω² cos θ)
      F_h = m x'',  F_v = m y'' + m g,  F_r = F·(−sin θ, cos θ),  F_t = F·(cos θ, sin θ)
  with θ'' from the equation of motion at that angle.
- The swing's reach (#34 item 5): amplitude = the first turning angle along the motion
  (turning(s)); rise = d(cos θ₀ − cos θₐ), the height the centre of mass climbs from the start;
  KE_bottom = ½ I ω_b² = ½ I ω₀² + mgd(1 − cos θ₀) + ½ κ θ₀².
- Angles from the upward vertical (Toppling, gravity alone): φ, the centre of mass at
  d(sin φ, cos φ) (x towards positive φ); energy ½Iω² + mgd cos φ is constant, θ'' = mgd sin φ/I.
- equivalent_length = centre_of_percussion = I/(m d); period_small = 2π √(I/(mgd + κ)).
- A point at r from the pivot: v_t = |ω| r, a_c = ω² r, a_t = r θ'' along the motion
  (r θ'' sgn ω; from rest, the sense θ'' starts it in), a_total = √(a_t² + a_c²).
"""

from __future__ import annotations

import mpmath

from references import DPS, mp, mpf

GUARD = 10  # guard digits inside; results are good to DPS digits


def _sign(x) -> int:
    return (x > 0) - (x < 0)


class Pendulum:
    """The motion from (θ₀, ω₀) of I θ'' = −m g d sin θ − κ θ; every answer at 50 digits."""

    def __init__(self, inertia, mass=0, d=0, g=9.80665, kappa=0, theta0=0, omega0=0):
        with mp.workdps(DPS + GUARD):
            self.I, self.m, self.d, self.g, self.kappa = (mpf(x) for x in (inertia, mass, d, g, kappa))
            self.theta0, self.omega0 = mpf(theta0), mpf(omega0)
            self.lam = self.m * self.g * self.d / self.I
            self.mu = self.kappa / self.I
            self.E = self.omega0**2 / 2 + self.U(self.theta0)
            if self.omega0 != 0:
                self.s = _sign(self.omega0)
            else:
                self.s = -_sign(self.dU1(self.theta0))
            self._turns = {}
            self._period = None
            self._crit_cache = {}

    # -- the potential (per unit inertia) ---------------------------------------------------
    def U(self, x):
        return 2 * self.lam * mpmath.sin(x / 2) ** 2 + self.mu * x**2 / 2

    def dU(self, p, delta):
        """U(p + δ) − U(p), keeping its digits as δ -> 0."""
        return 2 * self.lam * mpmath.sin(delta / 2) * mpmath.sin(p + delta / 2) + self.mu * delta * (p + delta / 2)

    def dU1(self, x):
        """U'(x) = λ sin x + μ x (minus the angular acceleration)."""
        return self.lam * mpmath.sin(x) + self.mu * x

    def dU2(self, x):
        return self.lam * mpmath.cos(x) + self.mu

    def w2(self, x):
        """ω² at θ = x from the start's energy."""
        return self.omega0**2 - 2 * self.dU(self.theta0, x - self.theta0)

    def alpha(self, x):
        return -self.dU1(x)

    # -- critical points of U: maxima (tops) and minima ------------------------------------
    def _positive_crits(self, n):
        """The local maximum and minimum of U in ((2n−1)π, 2nπ), or None."""
        if n in self._crit_cache:
            return self._crit_cache[n]
        lam, mu = self.lam, self.mu
        pi = mpmath.pi
        found = None
        if lam > 0 and mu == 0:
            found = ((2 * n - 1) * pi, 2 * n * pi)
        elif lam > 0 and mu < lam and (2 * n - 1) * pi < lam / mu:
            xm = 2 * n * pi - mpmath.acos(-mu / lam)  # where U' is least in the interval
            if self.dU1(xm) < 0:
                top = self._bisect(lambda x: -self.dU1(x), (2 * n - 1) * pi, xm)  # U' from + to −
                bottom = self._bisect(self.dU1, xm, 2 * n * pi)  # U' from − to +
                found = (top, bottom)
        self._crit_cache[n] = found
        return found

    def _no_more_crits(self, n) -> bool:
        """No critical point of U beyond (2n−1)π (U' > 0 for θ > λ/μ)."""
        if self.lam == 0:
            return True
        if self.mu == 0:
            return False
        return self.mu >= self.lam or (2 * n - 1) * mpmath.pi >= self.lam / self.mu

    def crits_between(self, lo, hi):
        """[(x, 'max'|'min')] of U strictly inside (lo, hi), in order."""
        out = []
        if lo < 0 < hi:
            out.append((mpf(0), "min"))
        limit = max(abs(lo), abs(hi))
        n = 1
        while (2 * n - 1) * mpmath.pi < limit and not self._no_more_crits(n):
            found = self._positive_crits(n)
            if found:
                for x, kind in ((found[0], "max"), (found[1], "min")):
                    for y in (x, -x):
                        if lo < y < hi:
                            out.append((y, kind))
            n += 1
        out.sort(key=lambda item: item[0])
        return out

    @staticmethod
    def _bisect(f, a, b):
        """The root of f in [a, b] (f(a) < 0 <= f(b)), by bisection to the working precision."""
        fa = f(a)
        if fa >= 0:
            return a
        for _ in range(mp.prec + 8):
            mid = (a + b) / 2
            if mid == a or mid == b:
                break
            if f(mid) < 0:
                a = mid
            else:
                b = mid
        return (a + b) / 2

    # -- turning angles ---------------------------------------------------------------------
    def turning(self, s):
        """The first angle along direction s (+1: larger θ) where ω = 0; None if there is none."""
        if s in self._turns:
            return self._turns[s]
        with mp.workdps(DPS + GUARD):
            result = self._turning(s)
        self._turns[s] = result
        return result

    def _turning(self, s):
        if self.omega0 == 0 and s != self.s:
            return self.theta0  # it starts at rest, turning here
        x0 = s * self.theta0  # reflect: U is even, so go towards larger x
        lam, mu, E = self.lam, self.mu, self.E
        if lam == 0 and mu == 0:
            return None
        if mu == 0:  # gravity alone: a swing within the well of x0, or over the top
            k2 = E / (2 * lam)
            if k2 >= 1:
                return None
            well = mpmath.nint(x0 / (2 * mpmath.pi))
            return s * (2 * mpmath.pi * well + 2 * mpmath.asin(mpmath.sqrt(k2)))

        def excess(x):  # U(x) − E, from the start
            return self.dU(x0, x - x0) - self.omega0**2 / 2

        # walk the critical points above x0, in order, until a top higher than E
        first = int(mpmath.ceil((abs(x0) + 1) / (2 * mpmath.pi)))  # intervals 1..first cover |x| < 2π·first
        points = [(x, kind) for x, kind in self.crits_between(x0, 2 * mpmath.pi * first) if x > x0]
        left = x0
        n = first + 1
        while True:
            for x, kind in points:
                if kind == "max" and self.U(x) > E:
                    return s * self._bisect(excess, left, x)
                left = max(left, x)
            if self._no_more_crits(n):
                hi = max(mpmath.sqrt(2 * E / mu) + 1, left + 1)  # U >= ½μx² > E beyond it
                while excess(hi) < 0:
                    hi *= 2
                return s * self._bisect(excess, left, hi)
            found = self._positive_crits(n)
            n += 1
            points = [(found[0], "max"), (found[1], "min")] if found else []

    def goes_over(self):
        """Whether it passes θ = ±π: E > U(π) (gravity alone: k² > 1)."""
        with mp.workdps(DPS + GUARD):
            return self.E > self.U(mpmath.pi)

    def omega0_over(self):
        """√(4λ cos²(θ₀/2) + μ(π − |θ₀|)(π + |θ₀|)), for |θ₀| <= π."""
        with mp.workdps(DPS + GUARD):
            a = abs(self.theta0)
            return mpmath.sqrt(4 * self.lam * mpmath.cos(self.theta0 / 2) ** 2 + self.mu * (mpmath.pi - a) * (mpmath.pi + a))

    # -- closed forms under gravity alone -----------------------------------------------------
    def _k2(self):
        return mpmath.sin(self.theta0 / 2) ** 2 + self.omega0**2 / (4 * self.lam)

    def _kc2(self):
        """1 − k², without the cancellation of 1 − k² itself."""
        return mpmath.cos(self.theta0 / 2) ** 2 - self.omega0**2 / (4 * self.lam)

    # -- time along the motion by quadrature ------------------------------------------------
    def _time_from_turn(self, b, sigma, D):
        """∫ dθ/|ω| from the turning angle b to b + σD (D > 0): θ = b + σ D v², v in [0, 1]."""

        def f(v):
            delta = sigma * D * v * v
            w2 = -2 * self.dU(b, delta)
            return 2 * D * v / mpmath.sqrt(w2)

        points = [mpf(0), mpf(1)]
        slope = abs(self.dU1(b))
        curve = abs(self.dU2(b)) + abs(self.lam) + abs(self.mu)
        width = mpmath.sqrt(slope / (curve * D)) if curve * D > 0 else mpf(1)
        if width < mpf("0.1"):  # near a top: a peak of this width in v at v = 0
            w = width / 100
            extra = []
            while w < mpf("0.1"):
                extra.append(w)
                w *= 10
            points = [mpf(0), *extra, mpf(1)]
        return mpmath.quad(f, points, maxdegree=10)

    def _time_plain(self, a, b):
        """∫ dθ/|ω| over [a, b] (a < b) where ω does not vanish, split at the tops inside."""

        def f(x):
            return 1 / mpmath.sqrt(self.w2(x))

        pts = [a]
        for x, kind in self.crits_between(a, b):
            if kind == "max":
                w = mpmath.sqrt(self.w2(x))
                width = w / mpmath.sqrt(abs(self.dU2(x)) + abs(self.mu) + abs(self.lam))
                y = width / 100
                while y < (b - a) / 10:
                    for z in (x - y, x + y):
                        if a < z < b:
                            pts.append(z)
                    y *= 10
            pts.append(x)
        pts.append(b)
        pts = sorted(set(pts))
        return mpmath.quad(f, pts, maxdegree=10)

    def time_between(self, a, b, turn_a=False, turn_b=False):
        """Time to go from a to b on a stretch where θ moves one way; a turning end is flagged."""
        with mp.workdps(DPS + GUARD):
            if a == b:
                return mpf(0)
            lo, hi = (a, b) if a < b else (b, a)
            turn_lo, turn_hi = (turn_a, turn_b) if a < b else (turn_b, turn_a)
            inner = [x for x, _ in self.crits_between(lo, hi)]
            cuts = [lo, *inner, hi]
            total = mpf(0)
            for i in range(len(cuts) - 1):
                p, q = cuts[i], cuts[i + 1]
                tp = turn_lo and i == 0
                tq = turn_hi and i == len(cuts) - 2
                if tp and tq:
                    mid = (p + q) / 2
                    total += self._time_from_turn(p, 1, mid - p) + self._time_from_turn(q, -1, q - mid)
                elif tp:
                    mid = (p + q) / 2
                    total += self._time_from_turn(p, 1, mid - p) + self._time_plain(mid, q)
                elif tq:
                    mid = (p + q) / 2
                    total += self._time_plain(p, mid) + self._time_from_turn(q, -1, q - mid)
                else:
                    total += self._time_plain(p, q)
            return total

    # -- the answers ------------------------------------------------------------------------
    def period(self, method="auto"):
        """The time between two passages in the same state; one turn where it goes over."""
        with mp.workdps(DPS + GUARD):
            lam, mu = self.lam, self.mu
            if method == "auto" and mu == 0 and lam > 0:
                k2 = self._k2()
                if k2 < 1:
                    return 4 * mpmath.ellipk(1 - self._kc2()) / mpmath.sqrt(lam)
                if k2 == 1:
                    return None
                wb = mpmath.sqrt(4 * lam * k2)
                return 4 * mpmath.ellipk(1 / k2) / wb
            if method == "auto" and lam == 0 and mu > 0:
                return 2 * mpmath.pi / mpmath.sqrt(mu)
            up, down = self.turning(1), self.turning(-1)
            if up is None or down is None:
                if mu == 0 and lam > 0 and self._k2() > 1:  # one turn by quadrature
                    return self._time_plain(self.theta0, self.theta0 + 2 * mpmath.pi)
                return None
            if self.dU1(up) == 0 or self.dU1(down) == 0:  # it creeps up to a top: no return
                return None
            return 2 * self.time_between(down, up, True, True)

    def reach(self, target, method="auto"):
        """(t, ω) the first time θ = target, following the motion; None if it never gets there."""
        with mp.workdps(DPS + GUARD):
            target = mpf(target)
            if target == self.theta0:
                return mpf(0), self.omega0
            s = self.s
            if s == 0:
                return None
            lam, mu = self.lam, self.mu
            if mu == 0 and lam > 0 and self._k2() > 1:
                # over the top: angles are positions; the first one along the motion
                span = mpmath.fmod(s * (target - self.theta0), 2 * mpmath.pi)
                if span < 0:
                    span += 2 * mpmath.pi
                end = self.theta0 + s * span
                if method == "auto":
                    t = abs(self._rotation_clock(end) - self._rotation_clock(self.theta0))
                else:
                    t = self.time_between(self.theta0, end)
                return t, s * mpmath.sqrt(self.w2(target))
            if lam == 0 and mu == 0:
                return None
            ahead, behind = self.turning(s), self.turning(-s)
            if ahead is None:
                return None
            lo, hi = sorted((self.theta0, ahead))
            if lo <= target <= hi:
                if method == "auto" and mu == 0:
                    t = abs(self._swing_clock(target, target == ahead) - self._swing_clock(self.theta0, self.omega0 == 0))
                else:
                    t = self.time_between(self.theta0, target, self.omega0 == 0, target == ahead)
                w = mpmath.sqrt(max(self.w2(target), 0))
                return t, s * w
            lo, hi = sorted((behind, ahead))
            if lo <= target <= hi:
                if method == "auto" and mu == 0:
                    t = abs(self._swing_clock(ahead, True) - self._swing_clock(self.theta0, self.omega0 == 0)) + abs(self._swing_clock(ahead, True) - self._swing_clock(target, target == behind))
                else:
                    t = self.time_between(self.theta0, ahead, self.omega0 == 0, True) + self.time_between(ahead, target, True, target == behind)
                w = mpmath.sqrt(max(self.w2(target), 0))
                return t, -s * w
            return None

    def _swing_clock(self, x, turn=False):
        """Time from the bottom of the well to x, under gravity alone in a swing: F(φ | k²)/√λ,
        sin φ = sin(x/2)/k, cos φ = |ω(x)|/(2k√λ) (so φ keeps its digits near a turning angle)."""
        m = 1 - self._kc2()
        root = mpmath.sqrt(self.lam)
        well = mpmath.nint(self.theta0 / (2 * mpmath.pi)) * 2 * mpmath.pi
        if turn:
            return _sign(x - well) * mpmath.ellipk(m) / root
        phi = mpmath.atan2(mpmath.sin((x - well) / 2), mpmath.sqrt(max(self.w2(x), 0)) / (2 * root))
        return mpmath.ellipf(phi, m) / root

    def _rotation_clock(self, x):
        """Time from θ = 0 to x along a motion over the top: 2F(x/2 | 1/k²)/ω_b (F quasi-periodic)."""
        k2 = self._k2()
        q = 1 / k2
        wb = mpmath.sqrt(4 * self.lam * k2)
        half = x / 2
        turns = mpmath.nint(half / mpmath.pi)
        rest = half - turns * mpmath.pi
        return 2 * (mpmath.ellipf(rest, q) + 2 * turns * mpmath.ellipk(q)) / wb

    def at_time(self, t, method="auto"):
        """(θ, ω) at time t."""
        with mp.workdps(DPS + GUARD):
            t = mpf(t)
            lam, mu = self.lam, self.mu
            if method == "auto" and lam == 0 and mu > 0:
                w = mpmath.sqrt(mu)
                return (self.theta0 * mpmath.cos(w * t) + self.omega0 / w * mpmath.sin(w * t),
                        -self.theta0 * w * mpmath.sin(w * t) + self.omega0 * mpmath.cos(w * t))
            if method == "auto" and mu == 0 and lam > 0:
                return self._gravity_at_time(t)
            period = self.period()
            shift = mpf(0)
            if period is not None:
                n = mpmath.floor(t / period)
                t = t - n * period
                if mu == 0 and self._k2() > 1:
                    shift = n * 2 * mpmath.pi * self.s
            theta, omega = _taylor_solve(self.lam, self.mu, self.theta0, self.omega0, t)
            return theta + shift, omega

    def _gravity_at_time(self, t):
        lam, k2 = self.lam, self._k2()
        if k2 < 1:
            m = 1 - self._kc2()
            k = mpmath.sqrt(k2)
            root = mpmath.sqrt(lam)
            well = mpmath.nint(self.theta0 / (2 * mpmath.pi)) * 2 * mpmath.pi
            phi0 = mpmath.atan2(mpmath.sin((self.theta0 - well) / 2), abs(self.omega0) / (2 * root))  # sin φ₀ = sin(θ₀/2)/k
            K = mpmath.ellipk(m)
            u0 = mpmath.ellipf(phi0, m)
            if self.s < 0:  # on the falling branch of sn: u in (K, 3K)
                u0 = 2 * K - u0
            u = u0 + root * t
            sn = mpmath.ellipfun("sn", u, m=m)
            cn = mpmath.ellipfun("cn", u, m=m)
            return well + 2 * mpmath.asin(k * sn), 2 * k * root * cn
        q = 1 / k2
        wb = mpmath.sqrt(4 * lam * k2)
        half0 = self.theta0 / 2
        turns0 = mpmath.nint(half0 / mpmath.pi)
        K = mpmath.ellipk(q)
        u0 = mpmath.ellipf(half0 - turns0 * mpmath.pi, q) + 2 * turns0 * K
        u = u0 + self.s * wb * t / 2
        turns = mpmath.nint(u / (2 * K))
        rest = u - turns * 2 * K
        sn = mpmath.ellipfun("sn", rest, m=q)
        dn = mpmath.ellipfun("dn", rest, m=q)
        return 2 * (mpmath.asin(sn) + turns * mpmath.pi), self.s * wb * dn

    def pivot(self, theta, omega):
        """(radial, tangential) force of the pivot on the body at θ with angular velocity ω."""
        with mp.workdps(DPS + GUARD):
            theta, omega = mpf(theta), mpf(omega)
            m, d, g, inertia = self.m, self.d, self.g, self.I
            radial = m * d * omega**2 + m * g * mpmath.cos(theta)
            tangential = (m * g * mpmath.sin(theta) * (inertia - m * d * d) - m * d * self.kappa * theta) / inertia
            return radial, tangential

    def components(self, theta, omega):
        """(radial, tangential, horizontal, vertical) force of the pivot, from x'' and y'' of the centre of mass."""
        with mp.workdps(DPS + GUARD):
            theta, omega = mpf(theta), mpf(omega)
            accel = -self.dU1(theta)
            x2 = self.d * (accel * mpmath.cos(theta) - omega**2 * mpmath.sin(theta))
            y2 = self.d * (accel * mpmath.sin(theta) + omega**2 * mpmath.cos(theta))
            fx, fy = self.m * x2, self.m * y2 + self.m * self.g
            radial = -fx * mpmath.sin(theta) + fy * mpmath.cos(theta)
            tangential = fx * mpmath.cos(theta) + fy * mpmath.sin(theta)
            return radial, tangential, fx, fy

    def amplitude(self):
        """The first turning angle along the motion (None: it never turns)."""
        if self.omega0 == 0 and self.dU1(self.theta0) == 0:
            return self.theta0
        return self.turning(self.s)

    def rise(self):
        """d(cos θ₀ − cos θₐ): how far the centre of mass climbs from the start to the turning angle."""
        turn = self.amplitude()
        if turn is None:
            return None
        with mp.workdps(DPS + GUARD):
            return self.d * (mpmath.cos(self.theta0) - mpmath.cos(turn))

    def pivot_size(self, theta, omega):
        radial, tangential = self.pivot(theta, omega)
        with mp.workdps(DPS + GUARD):
            return mpmath.hypot(radial, tangential)


class Toppling:
    """A body on a pivot under gravity alone, its angle φ from the upward vertical (a falling
    chimney or stick): the centre of mass at d(sin φ, cos φ), x towards positive φ, y up. Written
    from the physics in φ, with no use of the bottom's θ."""

    def __init__(self, inertia, mass, d, g=9.80665, phi0=0, omega0=0):
        with mp.workdps(DPS + GUARD):
            self.I, self.m, self.d, self.g = (mpf(x) for x in (inertia, mass, d, g))
            self.phi0, self.omega0 = mpf(phi0), mpf(omega0)
            self.G = self.m * self.g * self.d

    def omega2(self, phi):
        """ω² at φ: ½Iω² + mgd cos φ = ½Iω₀² + mgd cos φ₀."""
        with mp.workdps(DPS + GUARD):
            return self.omega0**2 + 2 * self.G * (mpmath.cos(self.phi0) - mpmath.cos(mpf(phi))) / self.I

    def alpha(self, phi):
        """φ'' = mgd sin φ / I: gravity tips it further from the top."""
        with mp.workdps(DPS + GUARD):
            return self.G * mpmath.sin(mpf(phi)) / self.I

    def pivot(self, phi, omega2):
        """(radial towards the pivot, tangential towards larger φ, horizontal towards positive φ, vertical up)."""
        with mp.workdps(DPS + GUARD):
            phi = mpf(phi)
            a = self.alpha(phi)
            x2 = self.d * (a * mpmath.cos(phi) - omega2 * mpmath.sin(phi))  # x = d sin φ
            y2 = self.d * (-a * mpmath.sin(phi) - omega2 * mpmath.cos(phi))  # y = d cos φ
            fx, fy = self.m * x2, self.m * y2 + self.m * self.g
            radial = -(fx * mpmath.sin(phi) + fy * mpmath.cos(phi))  # towards the pivot: −(sin φ, cos φ)
            tangential = fx * mpmath.cos(phi) - fy * mpmath.sin(phi)  # along larger φ: (cos φ, −sin φ)
            return radial, tangential, fx, fy

    def turning(self):
        """The first φ along the motion where ω = 0, None where it goes over the top. Turning angles
        are ±φₐ with cos φₐ = cos φ₀ + Iω₀²/(2mgd); the body swings through the bottom (φ = ±180°),
        so moving towards larger φ it turns at −φₐ, towards smaller at +φₐ."""
        with mp.workdps(DPS + GUARD):
            c = mpmath.cos(self.phi0) + self.I * self.omega0**2 / (2 * self.G)
            if c > 1:
                return None
            sense = _sign(self.omega0) or _sign(mpmath.sin(self.phi0))
            return -sense * mpmath.acos(c)


def _taylor_solve(lam, mu, theta0, omega0, t, order=60):
    """θ(t), ω(t) of θ'' = −λ sin θ − μ θ by Taylor series (sin, cos by their recurrences)."""
    theta, omega, done = mpf(theta0), mpf(omega0), mpf(0)
    tol = mpf(10) ** (-(mp.dps + 5))
    while done < t:
        a = [theta, omega]
        s = [mpmath.sin(theta)]
        c = [mpmath.cos(theta)]
        for k in range(order):
            a.append(-(lam * s[k] + mu * a[k]) / ((k + 2) * (k + 1)))
            ds = mpmath.fsum(c[j] * (k - j + 1) * a[k - j + 1] for j in range(k + 1)) / (k + 1)
            dc = -mpmath.fsum(s[j] * (k - j + 1) * a[k - j + 1] for j in range(k + 1)) / (k + 1)
            s.append(ds)
            c.append(dc)
        tail = max(abs(a[-1]), abs(a[-2]), tol * tol)
        radius = tail ** (-mpf(1) / (len(a) - 1))
        h = radius * tol ** (mpf(1) / (len(a) - 1)) / 2
        h = min(h, t - done)
        theta, omega = mpf(0), mpf(0)
        for k in range(len(a) - 1, -1, -1):  # Horner, for θ(h) and θ'(h)
            theta = theta * h + a[k]
            if k:
                omega = omega * h + k * a[k]
        done += h
    return theta, omega
