"""A friction couple at the pivot (--pivot-friction): a constant torque τ_f against the motion.

    I d²θ/dt² = −G sin θ − κθ − τ_f sgn ω      while the body turns (G = mgd)
    it stays where it comes to rest if |G sin θ + κθ| ≤ τ_f there: the couple holds it

Between two rests (a leg) the sense s of ω does not change, so the couple is a constant torque
−sτ_f and energy gives the speed exactly, the couple's work being τ_f times the angle turned:

    ½Iω² = ½Iω_s² + U(θ_s) − U(θ) − τ_f·s(θ − θ_s)

A leg ends where that speed is 0 (the turning angle, found by rk45 and polished by Newton's
method on the energy, whose slope there is the torque Iα). Times (to the bottom, to --angle,
θ and ω at --time) step each leg by rk45, on which θ'' = (−G sin θ − κθ − sτ_f)/I is smooth.
The swing dies away, so there is no period.
"""

from __future__ import annotations

import dataclasses
import math
from typing import NamedTuple

from taucli.numerics import steppers as numerics
from taucli.scenes.pendulum.swing import Swing, sine

RTOL = 1e-11
MAX_LEGS = 2000  # half-swings stepped before the model says it cannot go further


class Leg(NamedTuple):
    """One stretch of motion in one sense: it starts at t0 from (θ_s, ω_s), turns with sense s,
    and comes to rest at θ_end at t_end (None: it goes on beyond what was stepped, which took it
    as far as θ_last)."""
    t0: float
    theta_start: float
    omega_start: float
    sense: float
    t_end: float | None
    theta_end: float | None
    theta_last: float


class Rough:
    """The pendulum with a couple τ_f at its pivot, leg by leg (see the module's docstring)."""

    period = None  # the swing dies away

    def __init__(self, swing: Swing, friction: float, rtol: float = RTOL):
        self.swing, self.friction, self.rtol = swing, friction, rtol
        natural = math.sqrt((swing.gravity_torque + swing.torsion) / swing.inertia)
        size = max(abs(swing.theta0), abs(swing.omega0) / natural, 1e-3)
        self.scale = (size, size * natural + abs(swing.omega0))
        self.chunk = 2 * math.pi / natural
        self.horizon = 1000 * self.chunk  # the longest leg stepped (it may go over the top many times)
        self.legs: list[Leg] = []
        self.rest: float | None = None  # where it stays, once it does
        self.cut_short = False  # MAX_LEGS or a leg's step budget reached before it stays

    # ── the torques ──────────────────────────────────────────────────────────────────────────
    def drive(self, theta: float) -> float:
        """−(G sin θ + κθ): the torque of gravity and the spring."""
        return -(self.swing.gravity_torque * sine(theta) + self.swing.torsion * theta)

    def holds(self, theta: float) -> bool:
        """At rest at θ, the couple holds the body: |G sin θ + κθ| ≤ τ_f."""
        return abs(self.drive(theta)) <= self.friction

    def alpha(self, theta: float, omega: float) -> float:
        """α at θ turning at ω; at rest, the way it sets off (0 where the couple holds it)."""
        drive = self.drive(theta)
        if omega == 0:
            if abs(drive) <= self.friction:
                return 0.0
            return (drive - math.copysign(self.friction, drive)) / self.swing.inertia
        return (drive - math.copysign(self.friction, omega)) / self.swing.inertia

    def energy_left(self, leg: Leg, theta: float) -> float:
        """½Iω² at θ on the leg: ½Iω_s² + U(θ_s) − U(θ) − τ_f s(θ − θ_s)."""
        on_leg = dataclasses.replace(self.swing, theta0=leg.theta_start)
        return self.swing.inertia * leg.omega_start**2 / 2 + on_leg.drop(theta) - self.friction * leg.sense * (theta - leg.theta_start)

    def speed_on(self, leg: Leg, theta: float) -> float:
        return math.sqrt(max(2 * self.energy_left(leg, theta) / self.swing.inertia, 0.0))

    # ── the legs ─────────────────────────────────────────────────────────────────────────────
    def _accel(self, sense: float):
        return lambda theta: (self.drive(theta) - sense * self.friction) / self.swing.inertia

    def _step(self, leg: Leg, duration: float, event=None, partial: bool = False) -> numerics.AngleSolution:
        """rk45 along the leg from its start for ``duration``, or to the event, a natural period at a
        time within one budget of steps for the leg: past it, TooManySteps, or with ``partial`` where
        the last whole period got to (event False)."""
        accel, budget = self._accel(leg.sense), numerics.MAX_ANGLE_STEPS["rk45"]
        t, theta, omega, steps = 0.0, leg.theta_start, leg.omega_start, 0
        while t < duration:
            try:
                run = numerics.integrate_angle(accel, theta, omega, min(self.chunk, duration - t), "rk45", dt=self.chunk / 1000,
                                               rtol=self.rtol, scale=self.scale, event=event, max_steps=max(budget - steps, 1))
            except numerics.TooManySteps:
                if partial:
                    return numerics.AngleSolution(t, theta, omega, False, steps)
                raise
            steps += run.steps
            t, theta, omega = t + run.t, run.theta, run.omega
            if run.event:
                return numerics.AngleSolution(t, theta, omega, True, steps)
        return numerics.AngleSolution(t, theta, omega, False, steps)

    def _next_leg(self) -> Leg | None:
        """The leg after the last one (the first from the start); None once the body stays."""
        if self.rest is not None or self.cut_short:
            return None
        if self.legs:
            last = self.legs[-1]
            if last.t_end is None:
                return None
            t0, theta, omega = last.t_end, last.theta_end, 0.0
        else:
            t0, theta, omega = 0.0, self.swing.theta0, self.swing.omega0
        if omega == 0 and self.holds(theta):
            self.rest = theta
            return None
        if len(self.legs) >= MAX_LEGS:
            self.cut_short = True
            return None
        sense = math.copysign(1.0, omega) if omega else math.copysign(1.0, self.drive(theta))
        leg = Leg(t0, theta, omega, sense, None, None, theta)
        end = self._step(leg, self.horizon, lambda _, speed: speed * sense, partial=True)
        if not end.event:
            self.cut_short = True
            self.legs.append(leg._replace(theta_last=end.theta))
            return self.legs[-1]
        theta_end = self._polish(leg, end.theta)
        leg = leg._replace(t_end=t0 + end.t, theta_end=theta_end, theta_last=theta_end)
        self.legs.append(leg)
        return leg

    def _polish(self, leg: Leg, theta: float) -> float:
        """The turning angle: Newton's method on ½Iω²(θ) = 0, whose slope is the torque there."""
        for _ in range(4):
            slope = self.drive(theta) - leg.sense * self.friction
            if slope == 0:
                break
            theta -= self.energy_left(leg, theta) / slope
        return theta

    def each_leg(self):
        """The legs in order, stepped as they are asked for."""
        i = 0
        while True:
            if i < len(self.legs):
                yield self.legs[i]
            elif self._next_leg() is None:
                return
            else:
                yield self.legs[i]
            i += 1

    # ── what the scene asks ──────────────────────────────────────────────────────────────────
    def _crossing(self, leg: Leg, theta: float) -> float | None:
        """Where on the leg (its unwrapped angle) the body first is at θ (or θ ± 2πk under gravity
        alone, the same place); None where the leg does not get there. A leg's start belongs to
        the leg before it, but for the first."""
        start, first, end = leg.theta_start, leg.t0 == 0, leg.theta_last
        if self.swing.torsion:
            reached = theta
        else:
            ahead = (leg.sense * (theta - start)) % (2 * math.pi)
            reached = start + leg.sense * (2 * math.pi if ahead == 0 and not first else ahead)
        low, high = sorted((start, end))
        if reached == start and not first:
            return None
        if not low <= reached <= high:
            if leg.t_end is None:  # beyond where the stepping got: not known
                raise numerics.TooManySteps()
            return None
        return reached

    def first_at(self, theta: float) -> tuple[Leg, float] | None:
        """(the leg, the unwrapped angle) where the body first reaches θ; None where it never does."""
        for leg in self.each_leg():
            reached = self._crossing(leg, theta)
            if reached is not None:
                return leg, reached
        return None

    def velocity_at(self, theta: float) -> float | None:
        """ω (signed) when the body first reaches θ; None where it never does."""
        found = self.first_at(theta)
        if found is None:
            return None
        leg, reached = found
        return leg.sense * self.speed_on(leg, reached) if reached != leg.theta_end else 0.0

    def time_to(self, theta: float) -> float | None:
        """The time the body first reaches θ; None where it never does."""
        if theta == self.swing.theta0:
            return 0.0
        found = self.first_at(theta)
        if found is None:
            return None
        leg, reached = found
        if reached == leg.theta_start:
            return leg.t0
        if reached == leg.theta_end:
            return leg.t_end
        solution = self._step(leg, self.horizon, lambda angle, _: (angle - reached) * leg.sense)
        return leg.t0 + solution.t if solution.event else None

    def state(self, t: float) -> tuple[float, float]:
        """(θ, ω) at t."""
        for leg in self.each_leg():
            if leg.t_end is not None and t >= leg.t_end:
                continue
            if t == leg.t0:
                return leg.theta_start, leg.omega_start
            solution = self._step(leg, t - leg.t0)
            return solution.theta, solution.omega
        if self.rest is not None:
            return self.rest, 0.0
        raise numerics.TooManySteps()

    def turning_angle(self) -> float | None:
        """The first angle where the body comes to rest (θ₀ where the couple holds it at the start);
        None where it goes on beyond what was stepped."""
        first = next(self.each_leg(), None)
        if first is None:
            return self.swing.theta0
        return first.theta_end

    def goes_over(self) -> bool:
        """The first leg passes the top (±180°)."""
        first = next(self.each_leg(), None)
        if first is None:
            return False
        low, high = sorted((first.theta_start, first.theta_last))
        return high > math.pi or low < -math.pi

    def omega0_over(self, sense: float) -> float:
        """The least |ω₀| (sense s) that takes the body to the top s·180° on its first leg:
        ½Iω₀² = max over the path of [U(θ) − U(θ₀) + τ_f|θ − θ₀|] (the hardest place to pass)."""
        top = sense * math.pi
        need = lambda theta: -self.swing.drop(theta) + self.friction * abs(theta - self.swing.theta0)  # noqa: E731
        grid = [self.swing.theta0 + (top - self.swing.theta0) * i / 2000 for i in range(2001)]
        best = max(range(len(grid)), key=lambda i: need(grid[i]))
        low, high = grid[max(best - 1, 0)], grid[min(best + 1, 2000)]
        for _ in range(100):  # golden-section on the bracket around the largest sample
            a, b = low + (high - low) * 0.382, low + (high - low) * 0.618
            if need(a) < need(b):
                low = a
            else:
                high = b
        most = max(need(grid[best]), need((low + high) / 2), need(top))
        return math.sqrt(2 * max(most, 0.0) / self.swing.inertia)

