"""One degree of freedom under Coulomb friction, evolved phase by phase.

    m dv/dt = F − f·sgn(v) − b v − k|v|ⁿ·sgn(v)

The wheel of spin-down (m = I, v = ω, F a torque) and the string of the Atwood machine (m the
effective mass, v its speed, F a force) are both this. Friction is physics, not sgn(v): the body
stops at t_stop and stays stopped while |F| does not exceed the static friction; only a larger
F starts it again, the other way. Each stretch in one direction is a Phase with v ≥ 0 in its own
frame, evolved by the closed form (closed_forms.py) or by a stepper (numerics.steppers).

Kept whole: a Phase, the Evolver that carries it (closed form or stepper) and the Motion strung
from phases are one model read top to bottom; apart, each module would need the other.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import NamedTuple

from taucli.numerics import steppers as numerics
from taucli.numerics.roots import falling_root
from taucli.core.errors import InputError
from taucli.writing.report import fmt
from taucli.scenes.closed_forms import ClosedFormPhase, exp_fraction2

DEFAULT_RTOL = 1e-10
DEFAULT_DT = 1e-3
# rk45 holds each step's error to rtol/RTOL_MARGIN, so that what it reports (ω and θ at a time, a
# stop, a time to reach a speed) is within rtol of the truth: errors of steps add up along the
# way, most in a long decay, where each step's relative error in ω adds to the next. Measured
# over 300 random scenes against quadrature (tests/benchmarks/accuracy_rk45.py): the worst
# reported error was 4.3 rtol at rtol 1e-10 and 8.8 rtol at 1e-4 with a margin of 1; with 20, at
# most 0.33 rtol at any rtol, for 1.8 times the steps.
RTOL_MARGIN = 20.0


class Loads(NamedTuple):  # NamedTuples, as report.Value: made on every run (a batch line), at a third of a frozen dataclass's cost
    """What drives and resists: drive along +v; kinetic friction, viscous, drag (all ≥ 0).

    ``static`` is the most static friction can hold (None: the same as the kinetic friction).
    """

    drive: float = 0.0
    friction: float = 0.0
    viscous: float = 0.0
    drag: float = 0.0
    drag_exponent: float = 2.0
    static: float | None = None

    @property
    def holding(self) -> float:
        return self.friction if self.static is None else self.static


class Phase(NamedTuple):
    """A stretch of motion in one direction (v ≥ 0 in its frame): the closed form, and how to integrate it."""

    closed: ClosedFormPhase
    exponent: float  # of the drag term kωⁿ
    direction: int  # +1 or −1: this phase's ω ≥ 0 is direction·ω in the user's frame

    @property
    def stops(self) -> bool:
        """It reaches ω = 0 in finite time: where the constant torque opposes it, and under a drag
        kωⁿ with n < 1 with nothing driving it on (near rest kωⁿ outweighs bω, and dω/dt = −kωⁿ/I
        gives ω^(1−n) falling linearly to 0 at t = Iω₀^(1−n)/((1−n)k))."""
        c = self.closed
        return c.stops or (bool(c.drag) and self.exponent < 1 and c.constant <= 0)

    def rate(self, omega: float) -> float:
        """dω/dt in this phase's frame, extended oddly below zero for the event search."""
        c = self.closed
        drag = c.drag * math.copysign(abs(omega) ** self.exponent, omega) if c.drag else 0.0
        return (c.constant - c.viscous * omega - drag) / c.inertia

    def stiffness(self, omega: float) -> float:
        """|∂(dω/dt)/∂ω| = (b + n k ωⁿ⁻¹)/I, which sets a fixed step's stability."""
        c = self.closed
        if c.drag and self.exponent < 1 and omega == 0:
            return math.inf  # ∂(kωⁿ)/∂ω = nkωⁿ⁻¹ grows without bound at rest when n < 1
        drag = self.exponent * c.drag * abs(omega) ** (self.exponent - 1) if c.drag else 0.0
        return (c.viscous + drag) / c.inertia

    def asymptote(self) -> tuple[float, float, float] | None:
        """(ω∞, λ, m) where the phase settles exponentially, δ = ω − ω∞ ~ e^(−λt): λ = |∂(dω/dt)/∂ω|
        at ω∞, and m the order in δ of the part of dω/dt the linear law leaves out (1 about a
        steady speed; n − 1 about rest, where drag kωⁿ is all of it, taken no more than 1).
        None where the phase stops, grows without bound, or settles slower than exponentially."""
        if self.stops:
            return None
        steady = self.steady_speed()
        if steady is None:
            return None
        rate = self.stiffness(steady)
        if not rate > 0 or not math.isfinite(rate):
            return None
        return steady, rate, 1.0 if steady > 0 else min(1.0, self.exponent - 1)

    def settled(self, rtol: float) -> Callable[[float], bool] | None:
        """Whether, from ω on, the linear law δ(t) = δ e^(−λt) stays within rtol/10 of the motion.

        What it leaves out, r(ω) = dω/dt + λδ, moves ln δ by |r/δ| per unit time; that fraction
        q = |r/(λδ)| shrinks as δ^m, so it adds up to at most q/m over the whole approach, an
        error of (q/m)·|δ| in ω (and in θ the same over a time 1/λ). Settled when that is within
        rtol/10 of ω: of ω∞ near a steady speed, of δ itself near rest."""
        asymptote = self.asymptote()
        if asymptote is None:
            return None
        steady, rate, order = asymptote

        def check(omega: float) -> bool:
            gap = omega - steady
            linear = -rate * gap
            if gap == 0 or linear == 0:  # (λ·δ can underflow where δ is already below a double's reach)
                return True
            excess = abs(self.rate(omega) - linear) / abs(linear) / order
            return excess * abs(gap) <= 0.1 * rtol * max(steady, abs(gap))

        return check

    def carry(self, omega: float, dt: float) -> tuple[float, float, float]:
        """(ω, Δθ, Δω) after dt more on the settled exponential approach from ω (see ``settled``):
        δ = ω − ω∞ goes as e^(−λt), so Δω = δ(e^(−λdt) − 1) and Δθ = ω dt − δλdt²·g2(λdt), each
        from ω rather than from ω∞, which may be far larger than ω and the change (a heavy wheel
        driven towards a high steady speed: #42 item 8)."""
        steady, rate, _ = self.asymptote()
        gap = omega - steady
        change = gap * math.expm1(-rate * dt)
        return omega + change, omega * dt - gap * rate * dt * dt * exp_fraction2(rate * dt), change

    def steady_speed(self) -> float | None:
        if self.exponent == 2 or self.closed.drag == 0:
            return self.closed.steady_speed
        if self.stops or self.closed.constant == 0:
            return None if self.stops else 0.0
        return falling_root(self.rate)  # rate(ω) falls from A/I > 0


def _bernoulli_stop(phase: Phase) -> float:
    """The time to rest under I dω/dt = −bω − kωⁿ with n < 1 (no constant torque): a Bernoulli
    equation, linear in u = ω^(1−n): du/dt = −(1−n)(bu + k)/I, so u reaches 0 at
    t = I/((1−n)b) · ln(1 + bu₀/k) (t = Iu₀/((1−n)k) without b). A stepper finds the angle to
    full precision, but not this time: ω falls below any double long before it, and the last
    step overshoots to a crossing that is not there."""
    c, n = phase.closed, phase.exponent
    u0 = c.omega0 ** (1 - n)
    if c.viscous:
        return c.inertia / ((1 - n) * c.viscous) * math.log1p(c.viscous * u0 / c.drag)
    return c.inertia * u0 / ((1 - n) * c.drag)


class Method(NamedTuple):
    """How a phase is evolved: the closed form, or a stepper with its step or tolerance."""

    name: str  # "exact", "euler", "rk4", "rk45"
    dt: float | None = None
    rtol: float = DEFAULT_RTOL

    def describe(self, steps: int) -> str:
        if self.name == "exact":
            return "closed form"
        if self.name == "rk45":
            return f"rk45 (Dormand-Prince, adaptive), rtol = {self.rtol:g}, {steps} steps, stop located as an event"
        return f"{self.name}, dt = {fmt(self.dt)} s, {steps} steps, stop located as an event"


class Evolver:
    """Answers the questions a phase is asked (state at t, stop, reaching a speed) by a method."""

    def __init__(self, method: Method) -> None:
        self.method = method
        self.steps = 0
        self.unstable: list[str] = []

    def _run(self, phase: Phase, t_end: float, event_at: float | None, omega_start: float | None = None) -> numerics.Solution:
        """Step the phase to t_end or the event; rk45 stops early where the motion has settled on
        its exponential approach to a steady speed (the callers carry it on in closed form)."""
        name = self.method.name
        try:
            solution = numerics.integrate(
                phase.rate,
                phase.closed.omega0 if omega_start is None else omega_start,
                t_end,
                name,
                dt=self.method.dt,
                rtol=self.method.rtol / RTOL_MARGIN,
                event_at=event_at,
                stiffness=phase.stiffness,
                max_steps=numerics.MAX_STEPS[name] - self.steps,
                settled=phase.settled(self.method.rtol) if name == "rk45" else None,
            )
        except numerics.TooManySteps:
            self._refuse()
        self.steps += solution.steps
        if solution.unstable and not math.isfinite(solution.omega) and self.method.dt is None:
            self.unstable.append(f"{self.method.name}: ω left the range of a double (it is not finite); results withheld")
        elif solution.unstable:
            limit = numerics.METHODS[self.method.name].stability_limit
            # Where ω blew up past a double (the rate is inf), the step that would have held is set
            # by the stiffness at the start, which the step first left the stable region from.
            start_rate = phase.stiffness(phase.closed.omega0 if omega_start is None else omega_start) * self.method.dt
            rate = solution.worst_rate if math.isfinite(solution.worst_rate) else start_rate
            reached = fmt(solution.worst_rate, 3) if math.isfinite(solution.worst_rate) else "past the largest double (ω blew up)"
            self.unstable.append(
                f"{self.method.name} went unstable: dt·|∂α/∂ω| reached {reached}, above its limit "
                f"{fmt(limit, 4)}; results withheld. "
                + (f"Use --dt below {fmt(self.method.dt * limit / rate, 2)} s, " if 0 < rate < math.inf else "Use a smaller --dt, ")
                + "or --method auto"
            )
        return solution

    def _refuse(self):
        name = self.method.name
        option, hint = ("--rtol", "use a looser --rtol, or --method auto") if name == "rk45" else ("--dt", "use a larger --dt, or --method rk45 or auto")
        raise InputError(option, f"this run needs more than {numerics.MAX_STEPS[name]:,} {name} steps in all (answers and plot)", hint=hint) from None

    def state(self, phase: Phase, t: float, start: tuple[float, float, float] | None = None) -> tuple[float, float]:
        """(ω, θ) at time t within the phase (before its stop); a stepping method steps from the
        phase's start, or on from ``start`` = (t₀, ω, θ) with t₀ ≤ t."""
        if self.method.name == "exact":
            return phase.closed.omega(t), phase.closed.theta(t)
        return self._stepped(phase, t, start)[:2]

    def advance(self, phase: Phase, t: float) -> tuple[float, float, float]:
        """(ω, θ, Δω) at time t within the phase (before its stop), Δω = ω − ω₀ formed from what
        makes it (the closed form's N₀G/(I(E + cG)), or the sum of the steps' increments), not as
        the difference of two speeds, which for a heavy wheel loses every digit of it (#42 item 8)."""
        if self.method.name == "exact":
            closed = phase.closed
            return closed.omega(t), closed.theta(t), closed.change(t)
        return self._stepped(phase, t, None)

    def _stepped(self, phase: Phase, t: float, start: tuple[float, float, float] | None) -> tuple[float, float, float]:
        """(ω, θ, ω − ω at the start) by stepping: ``state``'s stepping half, Δω as in ``advance``."""
        t0, omega0, theta0 = start or (0.0, phase.closed.omega0, 0.0)
        if t == t0:
            return omega0, theta0, 0.0
        solution = self._run(phase, t - t0, None, omega_start=omega0)
        if solution.settled:
            omega, theta, change = phase.carry(solution.omega, t - t0 - solution.t)
            return omega, theta0 + solution.theta + theta, solution.change + change
        return solution.omega, theta0 + solution.theta, solution.change

    def reach(self, phase: Phase, target: float) -> tuple[float, float] | None:
        """(t, θ) when the phase first reaches ω = target, or None if it never does."""
        if self.method.name == "exact":
            t = phase.closed.time_to(target)
            return None if t is None else (t, phase.closed.theta(t))
        if target == phase.closed.omega0:
            return 0.0, 0.0
        rate = phase.rate(target)
        heading_up = phase.rate(phase.closed.omega0) > 0
        c = phase.closed
        gap = abs(c.omega0 - target)
        if rate == 0 and target == 0 and phase.stops and not heading_up:
            # drag kωⁿ with n < 1: dω/dt → 0 at rest, yet ω gets there in finite time; under drag
            # alone at t = Iω₀^(1−n)/((1−n)k), and the other losses only make it sooner
            bound = 1.01 * c.inertia * c.omega0 ** (1 - phase.exponent) / ((1 - phase.exponent) * c.drag)
        elif rate == 0 or (rate > 0) != heading_up or (target > c.omega0) != heading_up or target < 0:
            return None
        else:
            # |dω/dt| only grows from the target back to ω₀, so this bounds the time to get there,
            # and its value at ω₀ bounds the time from below: a fixed step that cannot get there
            # within the budget even at that pace is refused at once, not after a second of stepping.
            bound = 1.01 * gap / abs(rate)
        least = gap / abs(phase.rate(phase.closed.omega0))
        if self.method.dt is not None and self.method.name != "rk45" and least / self.method.dt > numerics.MAX_STEPS[self.method.name] - self.steps:
            self._refuse()
        solution = self._run(phase, bound, target)
        if solution.settled:  # the rest of the way on the exponential approach
            steady, rate, _ = phase.asymptote()
            gap, remaining = solution.omega - steady, target - steady
            if remaining == 0 or (remaining > 0) != (gap > 0) or abs(remaining) > abs(gap):
                return None
            dt = math.log(gap / remaining) / rate
            return solution.t + dt, solution.theta + phase.carry(solution.omega, dt)[1]
        if not solution.event:
            return None
        if target == 0 and c.drag and phase.exponent < 1 and c.constant == 0:
            return _bernoulli_stop(phase), solution.theta
        return solution.t, solution.theta


    def reach_angle(self, phase: Phase, distance: float, t_limit: float | None = None) -> tuple[float, float] | None:
        """(t, ω) when the phase has covered ``distance`` > 0 (None: it never does, or not
        before t_limit). θ grows with t while the phase moves, so doubling steps bracket the time
        and bisection finds it to the last bit; a stepping method steps on from the bracket's
        lower end each time, so the whole search costs a few runs over the bracket."""
        closed = phase.closed
        if distance == 0:
            return 0.0, closed.omega0
        speed = closed.omega0
        if speed > 0:
            guess = distance / speed
        elif closed.constant > 0:
            guess = math.sqrt(2 * distance * closed.inertia / closed.constant)
        else:
            return None
        if t_limit is not None:
            guess = min(guess, t_limit)
        low = (0.0, closed.omega0, 0.0)
        width = guess
        for _ in range(80):
            t_high = low[0] + width if t_limit is None else min(low[0] + width, t_limit)
            omega, theta = self.state(phase, t_high, low)
            if theta >= distance:
                high = (t_high, omega, theta)
                break
            if t_limit is not None and t_high >= t_limit:
                return None
            low, width = (t_high, omega, theta), 2 * width
        else:
            return None
        for _ in range(200):
            mid = (low[0] + high[0]) / 2
            if mid in (low[0], high[0]):
                break
            omega, theta = self.state(phase, mid, low)
            if theta < distance:
                low = (mid, omega, theta)
            else:
                high = (mid, omega, theta)
        return high[0], high[1]


class Motion(NamedTuple):
    """The whole motion: a first phase, a stop perhaps, and perhaps a second phase the other way.

    Positions and speeds from its methods are signed in the user's frame.
    """

    evolver: Evolver
    first: Phase
    second: Phase | None
    direction: int  # of the first phase; 0 when static friction holds the body from the start
    stop: tuple[float, float] | None  # (t_stop, distance in the first phase's frame)

    @property
    def held_from_start(self) -> bool:
        return self.direction == 0

    @property
    def initial_rate(self) -> float:
        return 0.0 if self.held_from_start else self.direction * self.first.rate(self.first.closed.omega0)

    @property
    def signed_stop(self) -> tuple[float, float] | None:
        return None if self.stop is None else (self.stop[0], (self.direction or 1) * self.stop[1])

    def final_speed(self) -> float | None:
        """The speed as t -> ∞ (None where it grows without bound)."""
        final = self.second or (None if self.first.stops or self.held_from_start else self.first)
        if final is None:
            return 0.0
        steady = final.steady_speed()
        return None if steady is None else final.direction * steady

    def state_at(self, t: float, resume: dict[int, tuple[float, float, float]] | None = None) -> tuple[float, float]:
        """(v, x) at time t.

        With ``resume`` (see ``sampler``), a stepping method steps on from the (t, ω, θ) kept
        there for the phase, when t is not before it, and keeps where it got to.
        """
        if self.held_from_start:
            return 0.0, 0.0
        direction, stop, second = self.direction, self.stop, self.second
        number, phase, offset = (1, self.first, 0.0) if stop is None or t <= stop[0] else (2, second, stop[0])
        if phase is None:
            return 0.0, direction * stop[1]
        if resume is None:
            speed, distance = self.evolver.state(phase, t - offset)
        else:
            start = resume.get(number)
            speed, distance = self.evolver.state(phase, t - offset, start if start and start[0] <= t - offset else None)
            resume[number] = (t - offset, speed, distance)
        if number == 1:
            return direction * speed, direction * distance
        return second.direction * speed, direction * stop[1] + second.direction * distance

    def rate_at(self, t: float) -> float | None:
        """dω/dt at time t, signed, from the closed form's phase variable (see ClosedFormPhase.rate);
        None where the motion is stepped (the caller takes it from the torques at ω(t))."""
        if self.evolver.method.name != "exact":
            return None
        if self.held_from_start:
            return 0.0
        stop, second = self.stop, self.second
        if stop is None or t < stop[0]:
            return self.direction * self.first.closed.rate(t)
        if second is None:
            return 0.0  # held by static friction once stopped
        return second.direction * second.closed.rate(t - stop[0])

    def sampler(self) -> Callable[[float], tuple[float, float]]:
        """``state_at`` for times asked in increasing order, as a plot asks them: a stepping method
        steps on from the last time asked instead of from 0, so 201 samples cost one run, not 201.
        Each sample then lies on a grid restarted at the previous one; a plot cannot tell."""
        resume: dict[int, tuple[float, float, float]] = {}  # phase number: (t, ω, θ) in its own frame
        return lambda t: self.state_at(t, resume)

    def reach(self, target: float) -> tuple[float, float] | None:
        """(t, x) when the speed first equals target, or None if it never does."""
        if self.held_from_start:
            return (0.0, 0.0) if target == 0 else None
        direction, stop, second = self.direction, self.stop, self.second
        if target * direction >= 0:
            reached = self.evolver.reach(self.first, abs(target))
            if reached is not None:
                return reached[0], direction * reached[1]
        if second is not None and stop is not None and target * second.direction > 0:
            reached = self.evolver.reach(second, abs(target))
            if reached is not None:
                return stop[0] + reached[0], direction * stop[1] + second.direction * reached[1]
        return None


    def reach_angle(self, target: float) -> tuple[float, float] | None:
        """(t, v) when the position first equals target, or None if it never does."""
        if target == 0:
            return 0.0, self.state_at(0.0)[0]
        if self.held_from_start:
            return None
        direction, stop, second = self.direction, self.stop, self.second
        if target * direction > 0 and (stop is None or abs(target) <= stop[1]):
            reached = self.evolver.reach_angle(self.first, abs(target), None if stop is None else stop[0])
            if reached is not None:
                return reached[0], direction * reached[1]
        if second is not None and stop is not None:
            distance = (target - direction * stop[1]) * second.direction
            if distance > 0:
                reached = self.evolver.reach_angle(second, distance)
                if reached is not None:
                    return stop[0] + reached[0], second.direction * reached[1]
        return None


def start_direction(loads: Loads, v0: float) -> int:
    """The sense of the first motion: v0's, or where the drive exceeds what static friction can
    hold, the drive's; 0 when static friction holds the body from the start."""
    if v0 != 0:
        return 1 if v0 > 0 else -1
    return (1 if loads.drive > 0 else -1) if abs(loads.drive) > loads.holding else 0


def start_rate(mass: float, loads: Loads, v0: float) -> float:
    """dv/dt at the start: ``evolve(...).initial_rate``, without setting up the phases.

    Moving (v0 ≠ 0) or set going (|drive| above what static friction holds), in direction s:
    (s·drive − friction − b|v0| − k|v0|ⁿ)/m, times s; held: 0.
    """
    direction = start_direction(loads, v0)
    if direction == 0:
        return 0.0
    speed = abs(v0)
    drag = loads.drag * speed**loads.drag_exponent if loads.drag else 0.0
    return direction * ((direction * loads.drive - loads.friction - loads.viscous * speed - drag) / mass)


def evolve(mass: float, loads: Loads, v0: float, evolver: Evolver) -> Motion:
    """Set up the phases of the motion from v0 under these loads."""
    holding = loads.holding
    direction = start_direction(loads, v0)

    def phase(sign: int, start: float) -> Phase:
        constant = sign * loads.drive - loads.friction
        return Phase(ClosedFormPhase(mass, constant, loads.viscous, loads.drag, start), loads.drag_exponent, sign)

    first = phase(direction or 1, abs(v0))
    # After a stop, a drive larger than static friction starts the body the other way.
    restarts = abs(loads.drive) > holding
    second = phase(1 if loads.drive > 0 else -1, 0.0) if restarts and first.stops else None
    if direction == 0:
        stop: tuple[float, float] | None = (0.0, 0.0)
    elif first.stops:
        stop = evolver.reach(first, 0.0)
    else:
        stop = None
    return Motion(evolver, first, second, direction, stop)
