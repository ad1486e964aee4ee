"""Time steppers with event location, for motion that has no closed form (or when asked for).

The state is (ω, θ) with dω/dt = f(ω), dθ/dt = ω; beside it each run keeps Δω, the sum of its
steps' increments (compensated), so that a change much smaller than ω (a heavy wheel a small
torque hardly moves) keeps its digits rather than being ω₁ − ω₀ of two near-equal speeds. Every
method locates events (the wheel reaching ω = 0, or a requested speed) by re-stepping from the
start of the step that crosses it, with the step size found by the Illinois method, so a stop
is never stepped over and Coulomb friction never chatters. Fixed-step methods report when their
step leaves the stable region of the linearised equation (|h λ| above the method's limit on the
negative real axis).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from math import fsum
from operator import mul, sub

Rate = Callable[[float], float]


@dataclass(frozen=True)
class Tableau:
    """An explicit Runge-Kutta method: stage matrix, weights, and embedded weights if adaptive."""

    name: str
    stages: tuple[tuple[float, ...], ...]
    weights: tuple[float, ...]
    embedded: tuple[float, ...] | None = None
    order: int = 1
    stability_limit: float = math.inf  # where the real stability interval ends, |h λ|


EULER = Tableau("euler", ((),), (1.0,), order=1, stability_limit=2.0)
RK4 = Tableau("rk4", ((), (0.5,), (0.0, 0.5), (0.0, 0.0, 1.0)), (1 / 6, 1 / 3, 1 / 3, 1 / 6), order=4, stability_limit=2.785293563405282)
RK45 = Tableau(  # Dormand-Prince 5(4)
    "rk45",
    (
        (),
        (1 / 5,),
        (3 / 40, 9 / 40),
        (44 / 45, -56 / 15, 32 / 9),
        (19372 / 6561, -25360 / 2187, 64448 / 6561, -212 / 729),
        (9017 / 3168, -355 / 33, 46732 / 5247, 49 / 176, -5103 / 18656),
        (35 / 384, 0.0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84),
    ),
    (35 / 384, 0.0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84, 0.0),
    (5179 / 57600, 0.0, 7571 / 16695, 393 / 640, -92097 / 339200, 187 / 2100, 1 / 40),
    order=5,
    stability_limit=3.3066,
)
METHODS: dict[str, Tableau] = {t.name: t for t in (EULER, RK4, RK45)}
# Steps one run may take in all (its answers and its plot): about 0.8 s of stepping each on a
# slow machine (3.1, 6.2 and 13.8 us a step), so that no input keeps the user waiting long.
MAX_STEPS = {"euler": 250_000, "rk4": 125_000, "rk45": 60_000}


class TooManySteps(Exception):
    """A run would take more steps than it was allowed."""


@dataclass(frozen=True)
class Solution:
    """Where a run ended: the time, speed and angle, whether an event ended it, and its cost."""

    t: float
    omega: float
    theta: float
    event: bool
    steps: int
    unstable: bool  # a fixed step left the method's stable region
    worst_rate: float  # the largest |h λ| met
    settled: bool = False  # ended early, before t_end, because ``settled`` said the state had settled
    change: float = 0.0  # ω − ω₀, the steps' increments summed (not the difference of the two speeds)


def _step(tableau: Tableau, f: Rate, omega: float, h: float) -> tuple[float, float, tuple[float, float]]:
    """One step: (Δω, Δθ, (error estimate of Δω, of Δθ)); (0, 0) without an embedded pair."""
    # fsum over map(mul, ...) rather than a generator: the same sums, bit for bit, in half the time.
    slopes: list[float] = []
    speeds: list[float] = []
    for row in tableau.stages:
        speed = omega + h * fsum(map(mul, row, slopes))
        speeds.append(speed)
        slopes.append(f(speed))
    d_omega = h * fsum(map(mul, tableau.weights, slopes))
    d_theta = h * fsum(map(mul, tableau.weights, speeds))
    if tableau.embedded is None:
        return d_omega, d_theta, (0.0, 0.0)
    differences = tuple(map(sub, tableau.weights, tableau.embedded))
    return d_omega, d_theta, (abs(h * fsum(map(mul, differences, slopes))), abs(h * fsum(map(mul, differences, speeds))))


def _locate(tableau: Tableau, f: Rate, omega: float, h: float, target: float) -> tuple[float, float, float, float]:
    """The step size h* in (0, h] at which the step from ω lands on ω = target (Illinois method):
    (h*, target, Δθ, Δω) of that step."""
    low, high = 0.0, h
    f_low, f_high = omega - target, omega + _step(tableau, f, omega, h)[0] - target
    if f_high == 0:
        d_omega, d_theta, _ = _step(tableau, f, omega, h)
        return h, target, d_theta, d_omega
    side = 0
    for _ in range(200):
        mid = (low * f_high - high * f_low) / (f_high - f_low)
        if not low < mid < high:
            mid = (low + high) / 2
        f_mid = omega + _step(tableau, f, omega, mid)[0] - target
        if f_mid == 0 or high - low <= 4e-16 * high:
            low = high = mid
            break
        if (f_mid > 0) == (f_low > 0):
            low, f_low = mid, f_mid
            if side == -1:
                f_high /= 2
            side = -1
        else:
            high, f_high = mid, f_mid
            if side == 1:
                f_low /= 2
            side = 1
    d_omega, d_theta, _ = _step(tableau, f, omega, high)
    return high, target, d_theta, d_omega


def integrate(
    f: Rate,
    omega0: float,
    t_end: float,
    method: str,
    *,
    dt: float | None = None,
    rtol: float = 1e-9,
    event_at: float | None = None,
    stiffness: Rate | None = None,
    max_steps: int | None = None,
    settled: Callable[[float], bool] | None = None,
) -> Solution:
    """Integrate dω/dt = f(ω), dθ/dt = ω from (ω₀, 0) until t_end or until ω reaches event_at.

    ``dt`` is the fixed step (euler, rk4) or the first step (rk45); ``rtol`` the relative
    tolerance of rk45. ``stiffness(ω)`` gives |∂f/∂ω|, to check fixed steps against the
    method's stability limit. More than ``max_steps`` steps (default MAX_STEPS) raise TooManySteps:
    at once for a fixed step with no event (t_end/dt is the count), as they are taken otherwise.
    ``settled(ω)``, checked at the start and after each step, ends the run early (Solution.settled)
    where the caller can carry the state on in closed form (an exponential approach to a steady speed).
    """
    tableau = METHODS[method]
    limit = MAX_STEPS[method] if max_steps is None else max_steps
    adaptive = tableau.embedded is not None
    t, omega, theta = 0.0, omega0, 0.0
    # ω, θ and Δω each summed with its rounding carried: a step's increment far below ω (a heavy
    # wheel) would otherwise lose its low digits to every addition, and Δω is their sum
    omega_lo = theta_lo = change = change_lo = 0.0
    if adaptive:
        slope = abs(f(omega0))
        h = dt or min(t_end, 0.01 * max(abs(omega0), 1.0) / slope if slope else t_end)
    else:
        assert dt is not None
        h = dt
        if event_at is None and t_end / h > limit:  # an event may end the run long before t_end
            raise TooManySteps()
    steps, worst = 0, 0.0
    if settled is not None and settled(omega):
        return Solution(t, omega, theta, False, 0, False, 0.0, settled=True)
    while t < t_end:
        if steps >= limit:
            raise TooManySteps()
        step = min(h, t_end - t)
        if stiffness is not None:
            try:
                worst = max(worst, step * stiffness(omega))
            except OverflowError:  # |ω|^(n−1) past a double: a fixed step has long left its stable region
                worst = math.inf
        try:
            d_omega, d_theta, error = _step(tableau, f, omega, step)
        except (ValueError, OverflowError):  # fsum met inf − inf or overflowed: the run has blown up
            return Solution(t + step, math.nan, math.nan, False, steps + 1, True, worst)
        if adaptive:
            # Each of ω and θ to rtol of its own size. One scale for both (the larger) let ω's
            # error grow with θ: at t = 1000 s, θ = 2700 rad let ω drift 5e-9 from its steady
            # speed at rtol 1e-10, and a decaying ω came out 1e5 times too large.
            ratio = max(
                error[0] / (rtol * max(abs(omega), abs(omega + d_omega)) + 1e-300),
                error[1] / (rtol * max(abs(theta), abs(theta + d_theta)) + 1e-300),
            )
            if ratio > 1:
                h = step * max(0.2, 0.9 * ratio ** (-1 / tableau.order))
                steps += 1
                continue
            h = step * min(5.0, 0.9 * ratio ** (-1 / tableau.order) if ratio else 5.0)
        steps += 1
        landed = omega + d_omega
        if event_at is not None and (landed - event_at) * (omega - event_at) <= 0 and omega != event_at:
            h_event, landed, d_theta, d_omega = _locate(tableau, f, omega, step, event_at)
            return Solution(t + h_event, landed, theta + (d_theta + theta_lo), True, steps, _unstable(tableau, worst), worst,
                            change=change + (d_omega + change_lo))
        if not math.isfinite(landed):
            return Solution(t + step, math.nan, math.nan, False, steps, True, worst)
        t = t + step
        # Kahan's summation, inline (a step costs ~2 us): each sum's rounding is carried into its
        # next increment, ω's too, so that its carry decays with a motion that decays
        added = d_omega + omega_lo
        total = omega + added
        omega_lo, omega = added - (total - omega), total
        added = d_theta + theta_lo
        total = theta + added
        theta_lo, theta = added - (total - theta), total
        added = d_omega + change_lo
        total = change + added
        change_lo, change = added - (total - change), total
        if settled is not None and t < t_end and settled(omega):
            return Solution(t, omega + omega_lo, theta + theta_lo, False, steps, _unstable(tableau, worst), worst, settled=True, change=change + change_lo)
    return Solution(t, omega + omega_lo, theta + theta_lo, False, steps, _unstable(tableau, worst), worst, change=change + change_lo)


def _unstable(tableau: Tableau, worst_rate: float) -> bool:
    """Whether a fixed step left the method's stable region. An adaptive step may pass the limit
    for a step: its error estimate then grows, and the step is rejected and shortened."""
    return tableau.embedded is None and worst_rate > tableau.stability_limit


def naive_coulomb_euler(torque: Callable[[float], float], inertia: float, omega0: float, t_end: float, dt: float) -> list[float]:
    """Explicit Euler on I dω/dt = τ(ω) with friction written as −c·sign(ω), no event location.

    Kept to show the failure that event location prevents: near ω = 0 the sign flips every
    step and ω chatters about zero instead of stopping. Returns ω at every step.
    """
    omegas = [omega0]
    omega = omega0
    for _ in range(int(round(t_end / dt))):
        omega += dt * torque(omega) / inertia
        omegas.append(omega)
    return omegas


# A body on a pivot: θ'' = α(θ), the state (θ, ω) ------------------------------------------

Accel = Callable[[float], float]
ANGLE_METHODS = ("euler", "rk4", "rk45", "verlet")
# Steps one pendulum run may take in all its answers (about 0.4 s of stepping on a slow shared
# machine: 4, 8, 20 and 1.6 us a step).
MAX_ANGLE_STEPS = {"euler": 100_000, "rk4": 50_000, "rk45": 20_000, "verlet": 250_000}


@dataclass(frozen=True)
class AngleSolution:
    """Where a run of θ'' = α(θ) ended: time, angle, speed, whether an event ended it, steps."""

    t: float
    theta: float
    omega: float
    event: bool
    steps: int


def angle_step(method: str, accel: Accel, theta: float, omega: float, h: float) -> tuple[float, float, tuple[float, float]]:
    """One step of θ' = ω, ω' = α(θ): (θ, ω) after it, and rk45's error estimates of each
    ((0, 0) for the fixed-step methods). verlet is velocity Verlet (symplectic, order 2):
    a half kick, a drift, a half kick."""
    if method == "verlet":
        half = omega + 0.5 * h * accel(theta)
        theta = theta + h * half
        return theta, half + 0.5 * h * accel(theta), (0.0, 0.0)
    tableau = METHODS[method]
    thetas: list[float] = []  # the stages' slopes of θ (speeds) and of ω (accelerations)
    alphas: list[float] = []
    for row in tableau.stages:
        speed = omega + h * fsum(map(mul, row, alphas))
        angle = theta + h * fsum(map(mul, row, thetas))
        thetas.append(speed)
        alphas.append(accel(angle))
    new_theta = theta + h * fsum(map(mul, tableau.weights, thetas))
    new_omega = omega + h * fsum(map(mul, tableau.weights, alphas))
    if tableau.embedded is None:
        return new_theta, new_omega, (0.0, 0.0)
    differences = tuple(map(sub, tableau.weights, tableau.embedded))
    return new_theta, new_omega, (abs(h * fsum(map(mul, differences, thetas))), abs(h * fsum(map(mul, differences, alphas))))


def _angle_step_or_nan(method: str, accel: Accel, theta: float, omega: float, h: float) -> tuple[float, float, tuple[float, float]]:
    """angle_step, or NaNs where the run has blown up (sin of an infinity, fsum of inf − inf)."""
    try:
        return angle_step(method, accel, theta, omega, h)
    except (ValueError, OverflowError):
        return math.nan, math.nan, (math.inf, math.inf)


def integrate_angle(
    accel: Accel,
    theta0: float,
    omega0: float,
    t_end: float,
    method: str,
    *,
    dt: float,
    rtol: float = 1e-10,
    scale: tuple[float, float] = (1.0, 1.0),
    event: Callable[[float, float], float] | None = None,
    max_steps: int | None = None,
) -> AngleSolution:
    """θ'' = α(θ) from (θ₀, ω₀) until t_end, or until ``event(θ, ω)`` changes sign.

    ``dt`` is the fixed step (euler, rk4, verlet) or the first step (rk45), which holds each
    step's error below rtol × ``scale`` (the sizes of θ and ω the motion reaches). An event is
    located by re-stepping from the start of the step that crosses it (bisection on the step),
    so it is never stepped over; a zero of the event at the start does not count. More than
    ``max_steps`` steps raise TooManySteps.
    """
    limit = MAX_ANGLE_STEPS[method] if max_steps is None else max_steps
    adaptive = method == "rk45"
    if not adaptive and event is None and t_end / dt > limit:
        raise TooManySteps()
    t, theta, omega, h, steps = 0.0, theta0, omega0, dt, 0
    tolerance = (rtol * scale[0], rtol * scale[1])
    before = event(theta, omega) if event is not None else 0.0
    while t < t_end:
        if steps >= limit:
            raise TooManySteps()
        step = min(h, t_end - t)
        new_theta, new_omega, error = _angle_step_or_nan(method, accel, theta, omega, step)
        steps += 1
        if adaptive:
            ratio = max(error[0] / tolerance[0], error[1] / tolerance[1])
            if ratio > 1:
                h = step * max(0.2, 0.9 * ratio**-0.2)
                continue
            h = step * min(5.0, 0.9 * ratio**-0.2 if ratio else 5.0)
        if not (math.isfinite(new_theta) and math.isfinite(new_omega)):
            return AngleSolution(t + step, math.nan, math.nan, False, steps)
        if event is not None:
            after = event(new_theta, new_omega)
            crossed = after == 0 or (after > 0) != (before > 0)
            end = step
            if not crossed and before != 0 and (new_omega > 0) != (omega > 0) and omega != 0:
                # the step holds a turning point: θ may go past a target and come back within it
                end = _bisect(lambda h: _angle_step_or_nan(method, accel, theta, omega, h)[1] > 0, omega > 0, step)
                turning = event(*_angle_step_or_nan(method, accel, theta, omega, end)[:2])
                crossed = turning == 0 or (turning > 0) != (before > 0)
            if before != 0 and crossed:
                high = _bisect(lambda h: event(*_angle_step_or_nan(method, accel, theta, omega, h)[:2]) > 0, before > 0, end)
                new_theta, new_omega, _ = _angle_step_or_nan(method, accel, theta, omega, high)
                return AngleSolution(t + high, new_theta, new_omega, True, steps)
            before = after if after != 0 else before
        t, theta, omega = t + step, new_theta, new_omega
    return AngleSolution(t, theta, omega, False, steps)


def _bisect(positive: Callable[[float], bool], start_positive: bool, high: float) -> float:
    """The least h in (0, high] where ``positive(h)`` differs from ``start_positive``, by
    bisection to the last double (the sign is all it needs); ``positive(high)`` differs."""
    low = 0.0
    for _ in range(200):
        mid = (low + high) / 2
        if not low < mid < high:
            break
        if positive(mid) == start_positive:
            low = mid
        else:
            high = mid
    return high
