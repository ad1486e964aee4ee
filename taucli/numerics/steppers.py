"""Time steppers with event location, for motion that has no closed form (or when asked for).

The state is (ω, θ) with dω/dt = f(ω), dθ/dt = ω. Every method locates events (the wheel
reaching ω = 0, or a requested speed) by re-stepping from the start of the step that crosses
it, with the step size found by the Illinois method, so a stop is never stepped over and
Coulomb friction never chatters. Fixed-step methods report when their step leaves the stable
region of the linearised equation (|h λ| above the method's limit on the negative real axis).
"""

from __future__ import annotations

import math
from collections import deque
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


def _locate(tableau: Tableau, f: Rate, omega: float, h: float, target: float) -> tuple[float, float, float]:
    """The step size h* in (0, h] at which the step from ω lands on ω = target (Illinois method)."""
    low, high = 0.0, h
    f_low, f_high = omega - target, omega + _step(tableau, f, omega, h)[0] - target
    if f_high == 0:
        return h, target, _step(tableau, f, omega, h)[1]
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
    return high, target, _step(tableau, f, omega, high)[1]


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
            h_event, landed, d_theta = _locate(tableau, f, omega, step, event_at)
            return Solution(t + h_event, landed, theta + d_theta, True, steps, _unstable(tableau, worst), worst)
        if not math.isfinite(landed):
            return Solution(t + step, math.nan, math.nan, False, steps, True, worst)
        t, omega, theta = t + step, landed, theta + d_theta
        if settled is not None and t < t_end and settled(omega):
            return Solution(t, omega, theta, False, steps, _unstable(tableau, worst), worst, settled=True)
    return Solution(t, omega, theta, False, steps, _unstable(tableau, worst), worst)


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


# Quadrature of sampled data -----------------------------------------------------------------


class StreamingQuadrature:
    """∫ f dt over samples fed one at a time, by the trapezoid rule and by composite Simpson.

    Simpson's rule for uneven spacing takes the intervals in pairs,
        ∫ over [t0, t2] ≈ (h0 + h1)/6 · [(2 − h1/h0) f0 + (h0 + h1)²/(h0 h1) f1 + (2 − h0/h1) f2],
    exact for quadratics; an odd last interval takes the three-point formula exact for quadratics
    too. Only the last three samples are kept, so memory stays flat however long the data.
    """

    RULES = ("trapezoid", "simpson")

    def __init__(self) -> None:
        self.count = 0
        self.trapezoid = 0.0
        self._paired = 0.0  # Simpson over the even number of intervals closed so far
        self._window: deque[tuple[float, float]] = deque(maxlen=3)
        self.peak = (0.0, 0.0)  # (t, f) where |f| is largest
        self.low = self.high = 0.0  # the least and the largest f
        self.uneven = 1.0  # the largest ratio of two neighbouring intervals Simpson takes together

    def add(self, t: float, f: float) -> None:
        if self._window:
            t_prev, f_prev = self._window[-1]
            self.trapezoid += (t - t_prev) * (f + f_prev) / 2
        self._window.append((t, f))
        self.count += 1
        if self.count == 1 or abs(f) > abs(self.peak[1]):
            self.peak = (t, f)
        self.low, self.high = (f, f) if self.count == 1 else (min(self.low, f), max(self.high, f))
        if self.count >= 3:
            (t0, f0), (t1, f1), (t2, f2) = self._window
            h0, h1 = t1 - t0, t2 - t1
            self.uneven = max(self.uneven, h1 / h0, h0 / h1)
        if self.count >= 3 and (self.count - 1) % 2 == 0:
            self._paired += (h0 + h1) / 6 * ((2 - h1 / h0) * f0 + (h0 + h1) ** 2 / (h0 * h1) * f1 + (2 - h0 / h1) * f2)

    def simpson(self) -> float:
        """Composite Simpson over all samples so far (the trapezoid rule for two samples)."""
        if self.count < 3:
            return self.trapezoid
        if (self.count - 1) % 2 == 0:
            return self._paired
        (t0, f0), (t1, f1), (t2, f2) = self._window  # the odd last interval is [t1, t2]
        h0, h1 = t1 - t0, t2 - t1
        last = (2 * h1 * h1 + 3 * h0 * h1) / (6 * (h0 + h1)) * f2 + (h1 * h1 + 3 * h0 * h1) / (6 * h0) * f1 - h1**3 / (6 * h0 * (h0 + h1)) * f0
        return self._paired + last

    def result(self, rule: str) -> float:
        return self.trapezoid if rule == "trapezoid" else self.simpson()


# Gauss-Legendre quadrature of a function evaluated in increasing order --------------------------

# The 8-point Gauss-Legendre nodes on [-1, 1] (positive half) and their weights: exact for
# polynomials of degree 15.
_GL8_NODES = (0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363)
_GL8_WEIGHTS = (0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763)


def gauss_legendre(f: Callable[[float], float], a: float, b: float, panels: int = 128) -> float:
    """∫ f dt over [a, b] by 8-point Gauss-Legendre on ``panels`` equal panels.

    The nodes are visited in increasing t, so ``f`` may be a sampler that steps on from the
    last time it was asked (a stepping method's motion) rather than from the start.
    """
    if b <= a:
        return 0.0
    width = (b - a) / panels
    offsets = sorted([-x for x in _GL8_NODES] + list(_GL8_NODES))
    weights = {x: w for x, w in zip(_GL8_NODES, _GL8_WEIGHTS, strict=True)}
    terms = []
    for panel in range(panels):
        middle = a + (panel + 0.5) * width
        for x in offsets:
            terms.append(weights[abs(x)] * f(middle + x * width / 2))
    return fsum(terms) * width / 2


def adaptive_gauss(f: Callable[[float], float], a: float, b: float, rtol: float = 1e-13, max_panels: int = 4096) -> float:
    """∫ f over [a, b] (b < a gives the negative), by 8-point Gauss-Legendre on panels halved
    where a panel and its two halves disagree by more than rtol of the whole: an integrand that
    changes fast near one end (a log-like rise) gets small panels there and nowhere else."""
    if a == b:
        return 0.0
    if b < a:
        return -adaptive_gauss(f, b, a, rtol, max_panels)

    def panel(lo: float, hi: float) -> float:
        return gauss_legendre(f, lo, hi, panels=1)

    edges = [a + (b - a) * i / 16 for i in range(17)]
    pending = [(lo, hi, panel(lo, hi)) for lo, hi in zip(edges, edges[1:])]
    scale = abs(fsum(p[2] for p in pending))
    done: list[float] = []
    while pending:
        lo, hi, whole = pending.pop()
        middle = (lo + hi) / 2
        left, right = panel(lo, middle), panel(middle, hi)
        if abs(left + right - whole) <= rtol * scale or len(done) + len(pending) >= max_panels or middle in (lo, hi):
            done.append(left + right)
        else:
            pending += [(lo, middle, left), (middle, hi, right)]
    return fsum(done)


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


def falling_root(rate: Callable[[float], float]) -> float:
    """The speed u > 0 where ``rate`` (positive at 0, falling) crosses zero: bracketed by doubling
    from 1, then bisected until the bracket holds no float between its ends."""
    low, high = 0.0, 1.0
    while rate(high) > 0:
        low, high = high, 2 * high
    for _ in range(200):
        mid = (low + high) / 2
        if mid in (low, high):
            break
        low, high = (mid, high) if rate(mid) > 0 else (low, mid)
    return (low + high) / 2
