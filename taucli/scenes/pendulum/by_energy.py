"""Gravity and a torsion spring together: the motion from the energy integral.

    ½Iω² + U(θ) = E,   U(θ) = G(1 − cos θ) + ½κθ²,   ω(θ) = ±√(2(E − U(θ))/I),   t = ∫ dθ/ω

There is no closed form, but every time the motion asks for is an integral of the energy: each is
taken by tanh-sinh quadrature (taucli.numerics.quadrature) to full precision, the 1/√ of a turning point
included. The spring makes U grow without bound, so the body swings between two turning angles
θ₋ < θ₊ where U = E, found on each side of θ₀ by scanning outward (stopping at each top of U, so
that a barrier it cannot pass is never stepped over) and bisection. The period is 2∫ dθ/ω from θ₋
to θ₊; an angle outside [θ₋, θ₊] is never reached; θ(t) inverts t(θ) by bisection.

Near a turning point θₜ, E − U(θ) is written from U(θₜ) = E as a product,
U(θₜ) − U(θ) = 2G sin((θₜ + θ)/2) sin((θₜ − θ)/2) + ½κ(θₜ − θ)(θₜ + θ), with θₜ − θ from the
quadrature's own distance to its end: so a swing that turns just short of the top (where U′ is
small and the time there long) keeps its digits.
"""

from __future__ import annotations

import math

from taucli.numerics.quadrature import tanh_sinh
from taucli.scenes.pendulum.swing import Swing

SCAN = math.pi / 16  # the outward scan's step for the turning angles (a top of U is stopped at, never stepped over)
RTOL = 1e-14


def _drop_from(swing: Swing, anchor: float, theta: float, gap: float) -> float:
    """U(anchor) − U(θ), with gap = anchor − θ given exactly."""
    total = anchor + theta
    return 2 * swing.gravity_torque * math.sin(total / 2) * math.sin(gap / 2) + swing.torsion * gap * total / 2


class ByEnergy:
    """θ'' = −(G sin θ + κθ)/I with G, κ > 0, by the energy integral (see the module)."""

    def __init__(self, swing: Swing):
        self.swing = swing
        start = swing.accel(swing.theta0)
        self.sense = math.copysign(1.0, swing.omega0) if swing.omega0 else math.copysign(1.0, start) if start else 0.0
        if self.sense == 0:  # at rest where nothing turns it (the bottom): it stays
            self.low = self.high = self.ahead = self.behind = swing.theta0
            # #42 item 12: its period is the limit of a swing's as the amplitude goes to 0, that of
            # small swings about where it rests, 2π√(I/U″(θ₀)), U″ = G cos θ₀ + κ (none where U″ ≤ 0)
            stiffness = swing.gravity_torque * math.cos(swing.theta0) + swing.torsion
            self.period = 2 * math.pi * math.sqrt(swing.inertia / stiffness) if stiffness > 0 else None
            self.half = None if self.period is None else self.period / 2
            self.amplitude = abs(swing.theta0)
            self.resting = True
            return
        self.resting = False
        ahead = self._turning(self.sense)
        behind = swing.theta0 if swing.omega0 == 0 else self._turning(-self.sense)
        self.low, self.high = sorted((ahead, behind))
        self.ahead, self.behind = ahead, behind
        self.half = self.between(self.low, self.high)
        self.period = 2 * self.half
        self.amplitude = max(abs(self.low), abs(self.high))

    # --- the turning angles ---------------------------------------------------------------

    def _speed2(self, theta: float) -> float:
        s = self.swing
        return s.omega0 * s.omega0 + 2 * s.drop(theta) / s.inertia

    def _slope(self, theta: float) -> float:
        """U′(θ) = G sin θ + κθ."""
        return self.swing.gravity_torque * math.sin(theta) + self.swing.torsion * theta

    def _turning(self, sense: float) -> float:
        """The first angle from θ₀ in direction ``sense`` where ω = 0."""
        s = self.swing
        energy = 0.5 * s.inertia * s.omega0 * s.omega0 + s.potential(s.theta0)
        reach = abs(s.theta0) + math.sqrt(2 * energy / s.torsion) + SCAN  # ½κθ² ≤ U ≤ E beyond it
        scale = math.hypot(s.theta0, s.omega0 / math.sqrt((s.gravity_torque + s.torsion) / s.inertia))
        step = min(SCAN, scale / 8) if scale else SCAN
        previous = s.theta0
        while abs(previous - s.theta0) <= 2 * reach:
            current = previous + sense * step
            if self._speed2(current) < 0:
                return self._root(previous, current)
            # a top of U between them (U′ turns from uphill to downhill along the way): stop at it
            uphill_before, uphill_after = sense * self._slope(previous) > 0, sense * self._slope(current) > 0
            if uphill_before and not uphill_after:
                top = self._bisect(previous, current, lambda x: sense * self._slope(x) > 0)
                if self._speed2(top) < 0:
                    return self._root(previous, top)
            previous = current
            step = min(SCAN, step * 2)
        raise ArithmeticError("no turning angle found")  # the spring bounds the swing: not reached

    def _root(self, inside: float, outside: float) -> float:
        """Where ω² = 0 between an angle it reaches and one it does not, to the last bit."""
        return self._bisect(inside, outside, lambda x: self._speed2(x) >= 0)

    @staticmethod
    def _bisect(good: float, bad: float, holds) -> float:
        for _ in range(200):
            middle = (good + bad) / 2
            if middle in (good, bad):
                break
            good, bad = (middle, bad) if holds(middle) else (good, middle)
        return good

    # --- times ----------------------------------------------------------------------------

    def _speed(self, theta: float, near: float | None, gap: float) -> float:
        """|ω| at θ; ``near`` a turning angle at ``gap`` = near − θ from it, written from U(near) = E."""
        s = self.swing
        if near is not None:
            square = 2 * _drop_from(s, near, theta, gap) / s.inertia
        else:
            square = self._speed2(theta)
        return math.sqrt(max(square, 0.0))

    def _piece(self, start: float, end: float, lo: float, hi: float) -> float:
        """∫ dθ/|ω| over [start, end] ⊂ [lo, hi]; near lo or hi where they are turning points, |ω|
        from U there (see the module)."""
        turning = (self.low, self.high)
        left = start if start == lo and lo in turning else None
        right = end if end == hi and hi in turning else None

        def integrand(theta: float, from_start: float, to_end: float) -> float:
            # from a turning end's U (= E) wherever the piece has one: θ itself, rounded, would cost
            # the digits of a short piece's distances
            if left is not None and (right is None or from_start <= to_end):
                speed = self._speed(theta, left, -from_start)
            elif right is not None:
                speed = self._speed(theta, right, to_end)
            else:
                speed = self._speed(theta, None, 0.0)
            return 1 / speed if speed else 0.0

        value, error = tanh_sinh(integrand, start, end, rtol=RTOL)
        if error > 1e-9 * value:
            raise ArithmeticError(f"the energy integral did not converge: {value} ± {error} s")
        return value

    def _pieces(self, a: float, b: float) -> list[tuple[float, float, float]]:
        """[a, b] (either order) cut at each multiple of π inside it (a long swing crosses many tops,
        each a bump in 1/ω), with the time over each: (start, end, time) along the way from a to b."""
        lo, hi = min(a, b), max(a, b)
        first, last = math.floor(lo / math.pi) + 1, math.ceil(hi / math.pi) - 1
        cuts = [lo, *(k * math.pi for k in range(first, last + 1) if lo < k * math.pi < hi), hi]
        pieces = [(start, end, self._piece(start, end, lo, hi)) for start, end in zip(cuts, cuts[1:])]
        return pieces if a <= b else [(end, start, time) for start, end, time in reversed(pieces)]

    def between(self, a: float, b: float) -> float:
        """The time to go from angle a to angle b (one way, within the swing): ∫ dθ/|ω|."""
        return math.fsum(time for _, _, time in self._pieces(a, b))

    def reaches(self, theta: float) -> bool:
        if self.resting:  # at rest: only where it is
            return theta == self.swing.theta0
        return self.period is not None and self.low <= theta <= self.high

    def time_to(self, theta: float) -> float | None:
        """The first time the body is at θ: on the way out (ahead of θ₀ in its first sense), or
        after turning at θ_ahead; None where θ lies outside the swing."""
        s = self.swing
        if theta == s.theta0:
            return 0.0
        if not self.reaches(theta):
            return None
        if self.sense * (theta - s.theta0) > 0:
            return self.between(s.theta0, theta)
        return self.between(s.theta0, self.ahead) + self.between(self.ahead, theta)

    def sense_at_first(self, theta: float) -> float:
        """The sign of ω when the body first reaches θ."""
        return self.sense if self.sense * (theta - self.swing.theta0) > 0 else -self.sense

    def state(self, t: float) -> tuple[float, float]:
        """(θ, ω) at t: the leg it is on (θ₀ to θ_ahead, then between the turning angles back and
        forth), and θ on it where ∫ dθ/|ω| from the leg's start is the time into the leg."""
        s = self.swing
        if self.resting:
            return s.theta0, 0.0
        out = self.between(s.theta0, self.ahead)
        if t <= out:
            start, end, into = s.theta0, self.ahead, t
        else:
            into = math.fmod(t - out, self.period)
            start, end = self.ahead, self.behind
            if into > self.half:
                into -= self.half
                start, end = end, start
        sense = math.copysign(1.0, end - start)
        for piece_start, piece_end, spent in self._pieces(start, end):  # the piece of the leg that holds the time
            if into <= spent:
                break
            into -= spent
        low, high = piece_start, piece_end  # θ between them where ∫ dθ/|ω| from piece_start is ``into``
        for _ in range(200):
            middle = (low + high) / 2
            if middle in (low, high):
                break
            segment = sorted((piece_start, middle))
            spent = self._piece(segment[0], segment[1], segment[0], segment[1]) if middle != piece_start else 0.0
            if spent < into:
                low = middle
            else:
                high = middle
        theta = (low + high) / 2
        return theta, sense * self._speed(theta, None, 0.0)
