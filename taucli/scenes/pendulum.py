"""A body on a pivot under gravity, a torsion spring, or both: the physical pendulum.

    I d²θ/dt² = −mgd sin θ − κθ        (θ from the downward vertical, d pivot to centre of mass)

Energy gives the speeds and the pivot's forces at any angle, exactly, for every method:
½Iω² + mgd(1 − cos θ) + ½κθ² is constant. The motion in time is

- gravity alone (κ = 0): exact, with k = sin(θ_max/2): sin(θ/2) = k sn(ω₀t + u₀, k), ω = 2kω₀ cn,
  period 4K(k)/ω₀, ω₀ = √(mgd/I); over the top (k > 1) it circulates with modulus 1/k
  (taucli/elliptic.py, every function from k' = cos(θ_max/2) so that 179.999° keeps its digits);
- torsion alone (d = 0): exact, harmonic, period 2π√(I/κ);
- both: no closed form; rk45 (or the method asked for) steps θ'' = α(θ), events located;
- small-angle: the harmonic model sin θ ≈ θ at any amplitude, its period error stated.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from taucli import elliptic, numerics
from taucli.errors import InputError
from taucli.options.pendulum import COMMAND as TABLE
from taucli.report import DeferredSteps, Report, Step, Trajectory, deferred, fmt, quantity_text
from taucli.scenes.assumed import Assumed
from taucli.table import Results
from taucli.scenes.inertia import body_inertia, main_part

TWO_PI = 2 * math.pi
DEFAULT_DT = 1e-3
DEFAULT_RTOL = 1e-10
STEPPERS = ("euler", "rk4", "rk45", "verlet")
REFERENCE_RTOL = 1e-11  # rk45's, for a stepper's error where there is no closed form
WITHHELD_ABOVE = 1e-3  # a stepper's answers are withheld when its period is further off, relative (as in spin-down)


@dataclass(frozen=True)
class Swing:
    """The pendulum: I about the pivot, G = mgd (gravity's torque at 90°), κ, and its start."""
    inertia: float
    gravity_torque: float  # G = m g d
    torsion: float  # κ
    theta0: float
    omega0: float

    def potential(self, theta: float) -> float:
        """U(θ) = 2G sin²(θ/2) + ½κθ² (1 − cos θ written without cancellation)."""
        half = math.sin(theta / 2)
        return 2 * self.gravity_torque * half * half + self.torsion * theta * theta / 2

    def drop(self, theta: float) -> float:
        """U(θ₀) − U(θ), in the product forms that keep digits when θ is near θ₀."""
        a, b = self.theta0, theta
        return 2 * self.gravity_torque * math.sin((a + b) / 2) * math.sin((a - b) / 2) + self.torsion * (a - b) * (a + b) / 2

    def speed_at(self, theta: float) -> float | None:
        """|ω| at θ from energy, None where the body never gets there."""
        square = self.omega0 * self.omega0 + 2 * self.drop(theta) / self.inertia
        return None if square < 0 else math.sqrt(square)

    def accel(self, theta: float) -> float:
        return -(self.gravity_torque * sine(theta) + self.torsion * theta) / self.inertia


def sine(theta: float) -> float:
    """sin θ, with the double nearest 180° (math.pi) read as 180° itself: 0, not 1.2e-16."""
    return 0.0 if abs(theta) == math.pi else math.sin(theta)


# The motion in time: each model gives state(t) and the first time it reaches an angle. ---------


class Harmonic:
    """θ'' = −Ω²θ: θ = θ₀ cos Ωt + (ω₀/Ω) sin Ωt = A cos(Ωt − δ)."""
    def __init__(self, rate: float, theta0: float, omega0: float):
        self.rate, self.theta0, self.omega0 = rate, theta0, omega0
        self.amplitude = math.hypot(theta0, omega0 / rate)
        self.phase = math.atan2(omega0 / rate, theta0)
        self.period = TWO_PI / rate

    def state(self, t: float) -> tuple[float, float]:
        c, s = math.cos(self.rate * t), math.sin(self.rate * t)
        return self.theta0 * c + self.omega0 / self.rate * s, self.omega0 * c - self.theta0 * self.rate * s

    def time_to(self, theta: float) -> float | None:
        if theta == self.theta0:
            return 0.0
        if abs(theta) > self.amplitude:
            return None
        turn = math.acos(theta / self.amplitude)
        return min(((self.phase + sign * turn) % TWO_PI) / self.rate for sign in (1, -1))


class Libration:
    """Gravity alone, swinging: sin(θ/2) = k sn(u, k), ω = 2kω₀ cn(u, k), u = u₀ + ω₀t."""
    def __init__(self, swing: Swing, rate: float, k: float, kc: float):
        self.swing, self.rate, self.k, self.kc = swing, rate, k, kc
        self.quarter = elliptic.complete_k(kc)
        self.period = 4 * self.quarter / rate
        self.amplitude = 2 * math.atan2(k, kc)
        if k == 0:
            self.u0 = 0.0
        else:
            self.u0 = elliptic.incomplete_f(math.sin(swing.theta0 / 2) / k, swing.omega0 / (2 * rate * k), kc)

    def state(self, t: float) -> tuple[float, float]:
        if self.k == 0:
            return 0.0, 0.0
        sn, cn, dn = elliptic.jacobi(self.u0 + self.rate * t, self.kc)
        return 2 * math.atan2(self.k * sn, dn), 2 * self.k * self.rate * cn

    def time_to(self, theta: float) -> float | None:
        if theta == self.swing.theta0:
            return 0.0
        speed = self.swing.speed_at(theta)
        if speed is None or self.k == 0:
            return None
        first = elliptic.incomplete_f(math.sin(theta / 2) / self.k, speed / (2 * self.rate * self.k), self.kc)
        period = 4 * self.quarter
        return min(((u - self.u0) % period) / self.rate for u in (first, 2 * self.quarter - first))


class Circulation:
    """Gravity alone, over the top: sin(θ/2) = sn(v, 1/k), v = ±v₀ + kω₀t, once round in 2K(1/k)/(kω₀)."""
    def __init__(self, swing: Swing, rate: float, k: float, kc: float):
        self.swing, self.rate, self.k, self.kc = swing, rate, k, kc  # kc: of the modulus 1/k
        self.sign = 1.0 if swing.omega0 > 0 else -1.0
        self.half_turn = elliptic.complete_k(kc)
        self.period = 2 * self.half_turn / (k * rate)
        self.v0 = self._v(swing.theta0)

    def _v(self, theta: float) -> float:
        return elliptic.incomplete_f(math.sin(theta / 2), math.cos(theta / 2), self.kc)

    def state(self, t: float) -> tuple[float, float]:
        v = self.sign * self.v0 + self.k * self.rate * t
        half = elliptic.amplitude(v, self.kc)
        _, _, dn = elliptic.jacobi(v, self.kc)
        return self.sign * 2 * half, self.sign * 2 * self.k * self.rate * dn

    def time_to(self, theta: float) -> float | None:
        if abs(theta) > math.pi:
            theta = math.remainder(theta, TWO_PI)
        gap = (self.sign * (self._v(theta) - self.v0)) % (2 * self.half_turn)
        return gap / (self.k * self.rate)


class Separatrix:
    """Gravity alone with just the energy to reach the top: sin(θ/2) = tanh(v), v = ±v₀ + ω₀t; it
    takes forever to get there (or, balanced at the top, stays)."""
    def __init__(self, swing: Swing, rate: float):
        self.swing, self.rate = swing, rate
        self.sign = 1.0 if swing.omega0 > 0 else -1.0
        self.balanced = swing.omega0 == 0
        self.v0 = self._v(swing.theta0) if not self.balanced else 0.0
        self.period = None

    @staticmethod
    def _v(theta: float) -> float:
        return math.asinh(math.tan(theta / 2))

    def state(self, t: float) -> tuple[float, float]:
        if self.balanced:
            return self.swing.theta0, 0.0
        v = self.sign * self.v0 + self.rate * t
        return self.sign * 2 * math.atan(math.sinh(v)), self.sign * 2 * self.rate / math.cosh(v)

    def time_to(self, theta: float) -> float | None:
        if theta == self.swing.theta0:
            return 0.0
        if self.balanced or abs(theta) >= math.pi:
            return None
        gap = self.sign * self._v(theta) - self.sign * self.v0
        return gap / self.rate if gap >= 0 else None


class BlewUp(Exception):
    """A stepped run left the finite numbers: the step is far outside the method's stable range."""


class Stepped:
    """θ'' = α(θ) stepped by a method of numerics.integrate_angle, each answer from t = 0, all of
    them within one budget of steps (numerics.MAX_ANGLE_STEPS)."""
    def __init__(self, swing: Swing, method: str, dt: float, rtol: float, horizon: float):
        self.swing, self.method, self.dt, self.rtol, self.horizon = swing, method, dt, rtol, horizon
        natural = math.sqrt((swing.gravity_torque + swing.torsion) / swing.inertia)
        size = max(abs(swing.theta0), abs(swing.omega0) / natural, 1e-3)
        self.scale = (size, size * natural + abs(swing.omega0))
        self.steps = 0
        self.budget = numerics.MAX_ANGLE_STEPS[method]
        self._last = (0.0, swing.theta0, swing.omega0)  # where state() got to, to carry on from

    def _run(self, t_end: float, event=None, theta0=None, omega0=None) -> numerics.AngleSolution:
        start = (self.swing.theta0 if theta0 is None else theta0, self.swing.omega0 if omega0 is None else omega0)
        solution = numerics.integrate_angle(
            self.swing.accel, *start, t_end, self.method, dt=self.dt, rtol=self.rtol, scale=self.scale, event=event,
            max_steps=max(self.budget - self.steps, 1),
        )
        self.steps += solution.steps
        if not (math.isfinite(solution.theta) and math.isfinite(solution.omega)):
            raise BlewUp()
        return solution

    def state(self, t: float) -> tuple[float, float]:
        """(θ, ω) at t, carried on from the last time asked for when t is later (a plot's samples)."""
        t_last, theta, omega = self._last
        if t < t_last:
            t_last, theta, omega = 0.0, self.swing.theta0, self.swing.omega0
        if t > t_last:
            solution = self._run(t - t_last, theta0=theta, omega0=omega)
            theta, omega = solution.theta, solution.omega
        self._last = (t, theta, omega)
        return theta, omega

    def time_to(self, theta: float) -> float | None:
        if theta == self.swing.theta0:
            return 0.0
        if self.swing.speed_at(theta) is None:
            return None
        if self.swing.torsion:
            solution = self._run(self.horizon, lambda angle, _: angle - theta)
        else:  # under gravity alone θ and θ ± 2π are the same place (it may have gone over the top)
            solution = self._run(self.horizon, lambda angle, _: math.sin((angle - theta) / 2))
        return solution.t if solution.event else None

    def period(self, circulates: bool) -> float | None:
        if circulates:
            target = self.swing.theta0 + math.copysign(TWO_PI, self.swing.omega0)
            solution = self._run(self.horizon, lambda angle, _: angle - target)
            return solution.t if solution.event else None
        if self.swing.theta0 == 0 and self.swing.omega0 == 0:  # at rest at the bottom: the limit of small swings
            return TWO_PI * math.sqrt(self.swing.inertia / (self.swing.gravity_torque + self.swing.torsion))
        first = self._run(self.horizon, lambda _, speed: speed)
        if not first.event:
            return None
        second = self._run(self.horizon, lambda _, speed: speed, first.theta, first.omega)
        return 2 * second.t if second.event else None


# The library function ----------------------------------------------------------------------


def _body(inertia, shape, mass, axis, offset, part, cm_distance, dims) -> tuple[float, float | None, float | None, Sequence[Step], str]:
    """(I about the pivot, mass, d, the steps, words for the model) from the body's options."""
    if inertia is not None:
        if shape is not None:
            raise InputError("inertia", "conflicts with {shape}: give one of them")
        given = [name for name, value in (("axis", axis), ("offset", offset), *dims.items()) if value is not None]
        if given or part:
            raise InputError(given[0] if given else "part", "goes with {shape}; with {inertia} give {cm_distance} and {mass}")
        return inertia, mass, cm_distance, (), "a body of given I"
    if shape is None:
        raise InputError("inertia", "or {shape} is required", example="{shape} rod {length} 1m {mass} 2kg {axis} end, or {inertia} 0.5kg*m^2 {mass} 2kg {cm_distance} 0.5m")
    found = body_inertia([main_part(shape, mass, axis, offset, dims), *part])
    steps = list(found.steps)
    total = found.mass
    if cm_distance is None:
        cm_distance = math.fsum(p.part.mass * p.offset for p in found.parts) / total
        if len(found.parts) > 1:
            steps.append(
                Step(
                    "Distance from the pivot to the centre of mass",
                    "d = Σmᵢdᵢ / M",
                    " + ".join(f"{fmt(p.part.mass)} kg × {fmt(p.offset)} m" for p in found.parts) + f" / {quantity_text(total, 'kg')}",
                    quantity_text(cm_distance, "m"),
                    "the parts' centres are taken on one line, on the same side of the pivot",
                )
            )
    return found.inertia, total, cm_distance, steps, found.description


def _choose(method: str, gravity: bool, torsion: bool) -> str:
    if method == "auto":
        return "rk45" if gravity and torsion else "exact"
    if method == "exact" and gravity and torsion:
        raise InputError("method", "exact has no closed form with both gravity and {torsion}", hint="use {method} auto (rk45) or small-angle")
    if method not in ("exact", "small-angle", *STEPPERS):
        raise InputError("method", f"expected one of {', '.join(TABLE.option('method').choices)}", got=repr(method))
    return method


def pendulum(
    *,
    inertia: float | None = None,
    shape: str | None = None,
    mass: float | None = None,
    axis: str | None = None,
    offset: float | None = None,
    part: Sequence = (),
    cm_distance: float | None = None,
    angle0: float | None = None,
    omega0: float | None = None,
    torsion: float | None = None,
    g: float | None = None,
    angle: float | None = None,
    time: float | None = None,
    at: float | None = None,
    method: str | None = None,
    dt: float | None = None,
    rtol: float | None = None,
    **dims: float | None,
) -> Report:
    """``taucli pendulum``: the body (--inertia with --mass and --cm-distance, or --shape ...), its
    start (--angle0 from the downward vertical, --omega0), gravity and --torsion, what to report."""
    assumed = Assumed()
    moment, body_mass, distance, body_steps, body_words = _body(inertia, shape, mass, axis, offset, part, cm_distance, dims)
    kappa = torsion or 0.0
    if distance is None:
        if not kappa:
            raise InputError("cm_distance", "is required with {inertia} (gravity's torque is mgd)", example="{cm_distance} 0.5m")
        distance = 0.0
        assumed.notes.append("no --cm-distance: d = 0, gravity turns nothing (a torsion pendulum on a vertical wire)")
    if distance > 0 and body_mass is None:
        raise InputError("mass", "is required with {inertia} and {cm_distance} (gravity's torque is mgd)", example="{mass} 2kg")
    gravity = assumed.gravity(g) if distance > 0 or body_mass is not None else (g or 0.0)
    big_g = (body_mass or 0.0) * gravity * distance
    if big_g == 0 and kappa == 0:
        raise InputError(
            "cm_distance" if distance == 0 else "g",
            "leaves nothing to swing the body: its centre of mass is on the pivot and there is no {torsion}" if distance == 0
            else "is zero and there is no {torsion}: nothing swings the body",
        )
    theta0 = angle0 or 0.0
    if not kappa and abs(theta0) > math.pi:
        raise InputError("angle0", "expected an angle from −180 to 180 deg under gravity alone", got=f"{fmt(math.degrees(theta0))} deg")
    if angle is not None and not kappa and abs(angle) > math.pi:
        raise InputError("angle", "expected an angle from −180 to 180 deg under gravity alone", got=f"{fmt(math.degrees(angle))} deg")
    chosen = _choose(method or "auto", big_g > 0, kappa > 0)
    swing = Swing(moment, big_g, kappa, theta0, omega0 or 0.0)
    report = _solve(swing, body_mass, distance, gravity, chosen, dt or DEFAULT_DT, rtol or DEFAULT_RTOL, angle, time, body_steps, body_words)
    if at is not None:
        _point(report, swing, at, angle, gravity)
    return assumed.applied(report)


def _point(report: Report, swing: Swing, r: float, angle: float | None, gravity: float) -> None:
    """A point at r from the pivot: a_t = rα (sizes), v_t = rω, a_c = rω², at the start and at
    --angle; with a step that says why a rod's far end falls faster than g."""
    results = Results(TABLE)
    where = f" {fmt(r)} m from the pivot"
    alpha0 = abs(swing.accel(swing.theta0))
    results.put("a_t0", r * alpha0, where)
    steps = [
        Step(
            f"Tangential acceleration at the start of the point{where}",
            "a_t = rα₀",
            f"{quantity_text(r, 'm')} × {quantity_text(alpha0, 'rad/s**2')}",
            quantity_text(r * alpha0, "m/s**2"),
            (
                f"every point of a rigid body has the same α; a point beyond I/(md) = {fmt(swing.inertia * gravity / swing.gravity_torque)} m "
                f"falls faster than a free body's g sin θ₀ = {quantity_text(gravity * abs(sine(swing.theta0)), 'm/s**2')}: the rest of the body, "
                "nearer the pivot, pulls it along (a rod's tip from the horizontal: a_t = 3g/2)"
            )
            if swing.gravity_torque and not swing.torsion
            else "every point of a rigid body has the same α, so a_t grows with r",
        )
    ]
    if angle is not None:
        speed = swing.speed_at(angle)
        part = f"{where} at θ = {fmt(math.degrees(angle))}°"
        alpha = abs(swing.accel(angle))
        results.put("v_t", None if speed is None else r * speed, part)
        results.put("a_t", None if speed is None else r * alpha, part)
        results.put("a_c", None if speed is None else r * speed * speed, part)
        if speed is not None:
            steps.append(
                Step(
                    f"The point{part}",
                    "v_t = rω, a_t = rα, a_c = rω²",
                    f"{quantity_text(r, 'm')} × {quantity_text(speed, 'rad/s')}; α = {quantity_text(alpha, 'rad/s**2')}",
                    f"v_t = {quantity_text(r * speed, 'm/s')}, a_t = {quantity_text(r * alpha, 'm/s**2')}, a_c = {quantity_text(r * speed * speed, 'm/s**2')}",
                    "ω from energy at that angle, α from the torque there",
                )
            )
    report.results.update(results)
    report.steps = _Appended(report.steps, steps)


class _Appended(DeferredSteps):
    """A report's steps (written when first read) and more after them."""
    def __init__(self, first, more):
        super().__init__(lambda: [*first, *more])


def _exact_model(swing: Swing):
    """The closed-form motion: harmonic under torsion alone, elliptic under gravity alone."""
    if swing.gravity_torque == 0:
        return Harmonic(math.sqrt(swing.torsion / swing.inertia), swing.theta0, swing.omega0)
    rate = math.sqrt(swing.gravity_torque / swing.inertia)
    # cos(θ₀/2) is correctly rounded near the top too (math.cos reduces its argument exactly); the
    # double nearest 180° (math.pi) is read as the top itself, so that 180deg is the balance.
    s0 = math.copysign(1.0, swing.theta0) if abs(swing.theta0) == math.pi else math.sin(swing.theta0 / 2)
    c0 = 0.0 if abs(swing.theta0) == math.pi else math.cos(swing.theta0 / 2)
    w = swing.omega0 / (2 * rate)
    kc2 = (c0 - abs(w)) * (c0 + abs(w))  # k'² = cos²(θ₀/2) − (ω₀/2ω₀ₙ)², as a product
    k = math.hypot(s0, w)
    if kc2 > 0:
        return Libration(swing, rate, k, math.sqrt(kc2))
    if kc2 < 0:
        return Circulation(swing, rate, k, math.sqrt(-kc2) / k)
    return Separatrix(swing, rate)


def _solve(swing, body_mass, distance, gravity, method, dt, rtol, angle, time, body_steps, body_words) -> Report:
    notes: list[str] = []
    results = Results(TABLE)
    inertia, big_g, kappa = swing.inertia, swing.gravity_torque, swing.torsion
    theta0, omega0 = swing.theta0, swing.omega0
    results.put("I", inertia)
    if big_g:
        results.put("cm_distance", distance)

    alpha0 = abs(swing.accel(theta0))
    results.put("alpha0", alpha0)
    omega_bottom = swing.speed_at(0.0)
    results.put("omega_bottom", omega_bottom)
    speed_at_angle = swing.speed_at(angle) if angle is not None else None
    if angle is not None:
        results.put("omega", speed_at_angle, f" at θ = {fmt(math.degrees(angle))}°")
        if speed_at_angle is None:
            notes.append(f"the body never reaches θ = {fmt(math.degrees(angle))}°: it has too little energy")

    small = TWO_PI * math.sqrt(inertia / (big_g + kappa))
    results.put("period_small", small)

    exact = None if (big_g and kappa) else _exact_model(swing)
    over_needed = None
    goes_over = None
    if big_g:
        over_needed = math.sqrt(2 * max(swing.potential(math.pi) - swing.potential(theta0), 0.0) / inertia)
        goes_over = abs(omega0) > over_needed if kappa == 0 else swing.speed_at(math.copysign(math.pi, omega0 or theta0 or 1.0)) not in (None, 0.0)
        if kappa == 0 and abs(omega0) == over_needed:
            goes_over = False
        results.put("goes_over", goes_over)
        results.put("omega0_over", over_needed)

    if method == "small-angle":
        model = Harmonic(math.sqrt((big_g + kappa) / inertia), theta0, omega0)
    elif method == "exact":
        model = exact
    else:
        horizon = 20 * small if exact is None or exact.period is None else 3 * exact.period
        model = Stepped(swing, method, dt, rtol, horizon)

    try:
        if isinstance(model, Stepped):
            period = model.period(isinstance(exact, Circulation))
            if period is None:
                notes.append(f"period: {method} found no full swing within {fmt(model.horizon)} s")
        else:
            period = model.period
        t_bottom = model.time_to(0.0)
        t_angle = model.time_to(angle) if angle is not None else None
        state = model.state(time) if time is not None else None
    except numerics.TooManySteps:
        limit = numerics.MAX_ANGLE_STEPS[method]
        step = f"rtol = {fmt(rtol)}" if method == "rk45" else f"dt = {fmt(dt)} s"
        notes.append(f"--method {method} would take more than {limit} steps at {step}; its answers are left out (a larger {{dt}}, or rk45)")
        period = t_bottom = t_angle = state = None
    except BlewUp:
        notes.append(f"--method {method} blew up at dt = {fmt(dt)} s (the step is far too large for it): its answers are left out")
        period = t_bottom = t_angle = state = None

    circulating = isinstance(exact, Circulation)
    label = " of one turn (it goes over the top)" if circulating else " of the swing" + (" at this amplitude" if method != "small-angle" else ", small-angle model")
    if isinstance(exact, Separatrix) and method != "small-angle":
        period = None
        notes.append(
            "period: none: the body is balanced at the top, an unstable balance: it stays there unless disturbed"
            if exact.balanced
            else "period: none: the body has just the energy to reach the top, and takes forever to get there"
        )
    results.put("period", period, label)
    results.put("t_bottom", t_bottom)
    if t_bottom is None and not (isinstance(exact, Separatrix) and exact.balanced) and swing.speed_at(0.0) is not None and period is not None:
        notes.append("t_bottom: not found")
    if isinstance(exact, Separatrix) and exact.balanced:
        notes.append("balanced at the top: speeds at an angle are those of a body that has just left the top; it takes forever to leave")
    if angle is not None:
        results.put("t_angle", t_angle, f" θ = {fmt(math.degrees(angle))}°")

    # the pivot's force on the body: F − mg = m a_cm, a_cm = (dω² toward the pivot, dα along the swing)
    pivot_start = pivot_bottom = None
    if body_mass is not None:
        pivot_start = _pivot_force(swing, body_mass, distance, gravity, theta0, abs(omega0))
        pivot_bottom = _pivot_force(swing, body_mass, distance, gravity, 0.0, omega_bottom)
        results.put("pivot_force0", pivot_start)
        results.put("pivot_force_bottom", pivot_bottom)
    if body_mass and distance:
        length = inertia / (body_mass * distance)
        results.put("equivalent_length", length)
        results.put("centre_of_percussion", length)

    if time is not None:
        theta_t, omega_t = state if state is not None else (None, None)
        results.put("theta", theta_t, f" at t = {fmt(time)} s")
        if angle is None:
            results.put("omega", omega_t, f" at t = {fmt(time)} s")
        else:
            notes.append("omega is given at --angle; theta at --time (run without --angle for ω at the time)")

    amplitude = getattr(exact, "amplitude", None)
    if method == "small-angle" and big_g:
        if isinstance(exact, Libration):
            error = 1 - small / exact.period if not kappa else None
            notes.append(
                f"small-angle model (sin θ ≈ θ): at an amplitude of {fmt(math.degrees(amplitude))}° its period is "
                f"{fmt(100 * error, 3)}% short of the exact {fmt(exact.period, 6)} s (about θ₀²/16 = {fmt(100 * amplitude**2 / 16, 3)}%)"
            )
        elif exact is None:
            notes.append("small-angle model (sin θ ≈ θ): its error grows as about θ₀²/16 of the period (1% near 23°, 18% at 90°)")
        else:
            notes.append("small-angle model (sin θ ≈ θ): the body goes over the top, which no small-angle swing does: its times are meaningless here")
    # rk45 with no closed form to check it against is the reference itself: its tolerance holds
    if isinstance(model, Stepped) and (period is not None or t_bottom is not None or state is not None) and (exact is not None or method != "rk45"):
        error = _period_error(swing, exact, model, period, notes)
        if state is not None and error is not None and error <= WITHHELD_ABOVE:
            error = max(error, _state_error(swing, exact, model, time, state, notes))
        if error is not None and error > WITHHELD_ABOVE:
            order = {"euler": 1, "verlet": 2, "rk4": 4}.get(method)
            shown = "no full swing" if period is None else f"a period of {fmt(period, 6)} s"
            shown += f" and θ = {fmt(state[0], 6)} rad at t = {fmt(time)} s" if state is not None else ""
            better = f"; --dt {fmt(dt * (WITHHELD_ABOVE / 10 / error) ** (1 / order), 2)}s would do" if order and math.isfinite(error) else ""
            notes.append(
                f"{method}'s answers are withheld: it gave {shown}, {fmt(error, 2) if math.isfinite(error) else 'far'} off the "
                f"{'exact' if exact is not None else 'rk45 (rtol 1e-11)'} one (more than {fmt(WITHHELD_ABOVE)}){better}"
            )
            for key in ("period", "t_bottom", "t_angle", "theta"):
                if key in results:
                    results[key] = results[key]._replace(value=None)
            if time is not None and angle is None:
                results["omega"] = results["omega"]._replace(value=None)

    model_words = _model_words(swing, method, exact, body_words)
    method_words = {"exact": "closed form (elliptic integrals)" if big_g else "closed form (harmonic)", "small-angle": "closed form (harmonic, small-angle)"}.get(
        method, f"{method} (dt = {fmt(dt)} s)" if method != "rk45" else f"rk45 (rtol = {fmt(rtol)})"
    )
    steps = DeferredSteps(_steps, swing, body_mass, distance, gravity, body_steps, dict(results), exact, method, angle)
    trajectory = deferred(_trajectory, model, time, period, t_bottom)
    return Report("pendulum", model_words, method_words, results, steps, notes, trajectory=trajectory)


def _period_error(swing: Swing, exact, model: Stepped, period: float | None, notes: list[str]) -> float | None:
    """How far a stepper's period is from the exact one (or rk45's at rtol 1e-11 where there is
    none), relative; inf where it found no swing and the reference did; None with no reference."""
    if exact is not None:
        reference = exact.period
    else:
        try:
            reference = Stepped(swing, "rk45", model.dt, REFERENCE_RTOL, model.horizon).period(False)
        except (numerics.TooManySteps, BlewUp):
            reference = None
    if reference is None:
        notes.append(f"{model.method}'s error is not estimated: there is no reference period here")
        return None
    if period is None:
        return math.inf
    error = abs(period / reference - 1)
    against = "the exact one" if exact is not None else "rk45's at rtol 1e-11"
    step = f"rtol = {fmt(model.rtol)}" if model.method == "rk45" else f"dt = {fmt(model.dt)} s"
    notes.append(f"{model.method} at {step}: period {fmt(error, 2)} off {against} (relative)")
    return error


def _state_error(swing: Swing, exact, model: Stepped, time: float, state: tuple[float, float], notes: list[str]) -> float:
    """How far a stepper's (θ, ω) at --time is from the exact one (or rk45's), as a fraction of
    the sizes the motion reaches (model.scale); 0 where there is no reference."""
    try:
        reference = exact.state(time) if exact is not None else Stepped(swing, "rk45", model.dt, REFERENCE_RTOL, model.horizon).state(time)
    except (numerics.TooManySteps, BlewUp):
        return 0.0
    error = max(abs(state[0] - reference[0]) / model.scale[0], abs(state[1] - reference[1]) / model.scale[1])
    notes.append(f"{model.method}: θ and ω at t = {fmt(time)} s {fmt(error, 2)} off {'the exact ones' if exact is not None else 'rk45' + chr(39) + 's'} (relative to the swing's size)")
    return error


def _pivot_force(swing: Swing, mass: float, distance: float, gravity: float, theta: float, speed: float | None) -> float | None:
    if speed is None:
        return None
    toward_pivot = mass * (distance * speed * speed + gravity * math.cos(theta))
    # along the swing: m d α + m g sin θ = m g sin θ (I − md²)/I − m d κθ/I (no cancellation for a bob)
    along = mass * gravity * sine(theta) * (swing.inertia - mass * distance * distance) / swing.inertia - mass * distance * swing.torsion * theta / swing.inertia
    return math.hypot(toward_pivot, along)


def _model_words(swing: Swing, method: str, exact, body_words: str) -> str:
    if swing.gravity_torque and swing.torsion:
        drive = "gravity and a torsion spring"
    elif swing.gravity_torque:
        drive = "gravity"
    else:
        drive = "a torsion spring"
    kind = {Circulation: "goes over the top", Separatrix: "just reaches the top", Libration: "swings", Harmonic: "swings"}.get(type(exact), "swings or goes over")
    if method == "small-angle":
        return f"{body_words} on a pivot under {drive}: small-angle model (harmonic, sin θ ≈ θ)"
    return f"{body_words} on a pivot under {drive}; it {kind}"


def _trajectory(model, time: float | None, period: float | None, t_bottom: float | None) -> Trajectory:
    if time:
        t_end, note = time, ""
    elif period:
        t_end, note = 2 * period, "plotted for two periods; --time to change"
    else:
        t_end, note = 10.0, "plotted for 10 s; --time to change"
    curves = (("theta", "rad", "angle θ from the downward vertical"), ("omega", "rad/s", "angular velocity ω"))
    if isinstance(model, Stepped):  # stepped once through the samples, within a budget of its own
        model = Stepped(model.swing, model.method, model.dt, model.rtol, model.horizon)
        points = [(0.0, model.swing.theta0, model.swing.omega0)]
        for i in range(1, 201):
            t = t_end * i / 200
            try:
                points.append((t, *model.state(t)))
            except (numerics.TooManySteps, BlewUp):
                t_end, note = points[-1][0], f"plotted for {fmt(points[-1][0])} s: {model.method} cannot go further"
                break
        marks = ((t_bottom, "at the bottom"),) if t_bottom and t_bottom <= t_end else ()
        return Trajectory(curves, t_end, None, points=tuple(points), marks=marks, note=note)
    marks = ((t_bottom, "at the bottom"),) if t_bottom else ()
    return Trajectory(curves, t_end, model.state, marks=marks, note=note)


def _steps(swing: Swing, mass, distance, gravity, body_steps, results, exact, method, angle) -> list[Step]:
    value = lambda key: results[key].value if key in results else None  # noqa: E731
    inertia, big_g, kappa, theta0, omega0 = swing.inertia, swing.gravity_torque, swing.torsion, swing.theta0, swing.omega0
    steps = list(body_steps)
    deg0 = f"{fmt(math.degrees(theta0))}°"
    terms, numbers = [], []
    if big_g:
        terms.append("mgd sin θ₀")
        numbers.append(f"{fmt(mass)} kg × {fmt(gravity)} m/s² × {fmt(distance)} m × sin {deg0}")
    if kappa:
        terms.append("κθ₀")
        numbers.append(f"{fmt(kappa)} N·m/rad × {fmt(theta0)} rad")
    steps.append(
        Step(
            "Restoring torque at the start",
            "τ₀ = −(" + " + ".join(terms) + ")",
            "−(" + " + ".join(numbers) + ")",
            quantity_text(-(big_g * sine(theta0) + kappa * theta0), "N*m"),
            "; ".join(
                ["gravity acts at the centre of mass, a distance d from the pivot; its lever arm is d sin θ"] * bool(big_g)
                + ["the spring twists back in proportion to the angle"] * bool(kappa)
            ),
        )
    )
    steps.append(
        Step(
            "Angular acceleration at the start (τ = Iα about the pivot)",
            "α₀ = |τ₀| / I",
            f"{quantity_text(abs(big_g * sine(theta0) + kappa * theta0), 'N*m')} / {quantity_text(inertia, 'kg*m**2')}",
            quantity_text(value("alpha0"), "rad/s**2"),
            "I is about the pivot, not the centre of mass: the body turns about the pivot"
            + (f"; a point at r moves with a_t = rα₀, faster than g sin θ₀ beyond r = I/(md) = {fmt(inertia / (mass * distance))} m"
               if big_g and theta0 else ""),
        )
    )
    potential = ("mgd(1 − cos θ₀)" if big_g else "") + (" + " if big_g and kappa else "") + ("½κθ₀²" if kappa else "")
    steps.append(
        Step(
            "Speed at the bottom (energy is conserved)",
            f"½Iω_b² = ½Iω₀² + {potential}",
            f"√(({fmt(omega0)} rad/s)² + 2 × {quantity_text(swing.potential(theta0), 'J')} / {quantity_text(inertia, 'kg*m**2')})",
            quantity_text(value("omega_bottom"), "rad/s"),
            "the pivot does no work (it does not move), so the potential energy lost becomes kinetic energy ½Iω²",
        )
    )
    if angle is not None and "omega" in results:
        speed = value("omega")
        steps.append(
            Step(
                f"Speed at θ = {fmt(math.degrees(angle))}° (energy)",
                "½Iω² = ½Iω₀² + U(θ₀) − U(θ)",
                f"√(({fmt(omega0)} rad/s)² + 2 × {quantity_text(swing.drop(angle), 'J')} / {quantity_text(inertia, 'kg*m**2')})",
                "never reached" if speed is None else quantity_text(speed, "rad/s"),
                "U(θ) = mgd(1 − cos θ) + ½κθ², the potential energy of gravity and the spring",
            )
        )
    steps.append(
        Step(
            "Period of small swings",
            "T₀ = 2π√(I / (mgd + κ))",
            f"2π√({quantity_text(inertia, 'kg*m**2')} / {quantity_text(big_g + kappa, 'N*m')})",
            quantity_text(value("period_small"), "s"),
            "for small angles sin θ ≈ θ, so I θ'' = −(mgd + κ)θ: simple harmonic motion",
        )
    )
    if isinstance(exact, Libration) and method == "exact":
        k = exact.k
        steps.append(
            Step(
                "Exact period at this amplitude (complete elliptic integral)",
                "T = 4K(k)/ω₀ₙ, k = sin(θ_max/2), ω₀ₙ = √(mgd/I)",
                f"4 × {fmt(exact.quarter, 10)} / {quantity_text(exact.rate, 'rad/s')}",
                quantity_text(value("period"), "s") if value("period") is not None else "none",
                f"θ_max = {fmt(math.degrees(exact.amplitude), 6)}°, k = {fmt(k, 8)}, and K(k) = π/(2·AGM(1, cos(θ_max/2))); energy gives dθ/dt at each θ; the time for a quarter swing is ∫dθ/ω, which sin(θ/2) = k sin φ turns into K(k); "
                f"the exact period is {fmt(100 * (exact.period / value('period_small') - 1), 4)}% longer than the small-angle one",
            )
        )
        if value("t_bottom") is not None:
            steps.append(
                Step(
                    "Time to reach the bottom",
                    "t = (F(φ, k) measured from the start to the bottom) / ω₀ₙ",
                    "released from rest: a quarter period, K(k)/ω₀ₙ" if omega0 == 0 else "",
                    quantity_text(value("t_bottom"), "s"),
                    "sin(θ/2) = k sn(ω₀ₙt + u₀, k): the Jacobi elliptic function gives θ(t) exactly; it is at the bottom where sn = 0",
                )
            )
    elif isinstance(exact, Circulation) and method == "exact":
        steps.append(
            Step(
                "It goes over the top: time for one turn",
                "T = 2K(1/k)/(kω₀ₙ), k² = E/(2mgd) > 1",
                f"k = {fmt(exact.k, 8)}",
                quantity_text(value("period"), "s"),
                "with more energy than the top needs, θ keeps growing; sin(θ/2) = sn(kω₀ₙt, 1/k)",
            )
        )
    elif isinstance(exact, Harmonic) and method == "exact":
        steps.append(
            Step(
                "Period (exact at any amplitude)",
                "T = 2π√(I/κ)",
                f"2π√({quantity_text(inertia, 'kg*m**2')} / {fmt(kappa)} N·m/rad)",
                quantity_text(value("period"), "s"),
                "the spring's torque κθ is linear in θ, so the motion is simple harmonic however far it swings; "
                "the time to the bottom from rest is a quarter of it",
            )
        )
    elif method in STEPPERS:
        how = {
            "euler": "explicit Euler: θ += hω, ω += hα(θ) (first order; it gains energy every step)",
            "rk4": "classical Runge-Kutta, four stages (fourth order; it loses energy slowly)",
            "rk45": "Dormand-Prince 5(4), its step held to the tolerance",
            "verlet": "velocity Verlet: a half kick, a drift, a half kick (second order, symplectic: its energy stays bounded)",
        }[method]
        steps.append(
            Step(
                f"Period by stepping the motion ({method})",
                "θ' = ω, ω' = α(θ) = −(mgd sin θ + κθ)/I; T = 2 × (time between two turning points, ω = 0)",
                "",
                "withheld (see the notes)" if value("period") is None else quantity_text(value("period"), "s"),
                how + "; each turning point, the bottom and --angle are located by re-stepping the step that crosses them",
            )
        )
    elif method == "small-angle":
        steps.append(
            Step(
                "Small-angle model: the period at every amplitude",
                "T = T₀ = 2π√(I / (mgd + κ)), θ(t) = θ₀ cos Ωt + (ω₀/Ω) sin Ωt",
                "",
                quantity_text(value("period"), "s"),
                "sin θ ≈ θ makes the motion harmonic; the real period is longer, by about θ₀²/16 (see the note)",
            )
        )
    if mass is not None and value("pivot_force0") is not None:
        steps.append(
            Step(
                "Force of the pivot on the body at the start",
                "F_r = m(dω² + g cos θ), F_t = m(dα + g sin θ), F = √(F_r² + F_t²)",
                f"√(({fmt(mass * (distance * omega0 * omega0 + gravity * math.cos(theta0)))} N)² + ({fmt(mass * (distance * swing.accel(theta0) + gravity * sine(theta0)))} N)²)",
                quantity_text(value("pivot_force0"), "N"),
                f"with m = {fmt(mass)} kg, d = {fmt(distance)} m, ω = {fmt(abs(omega0))} rad/s, θ = {deg0}; Newton's second law for the centre of mass, which moves on a circle of radius d: F + mg = m a_cm",
            )
        )
        if value("pivot_force_bottom") is not None:
            steps.append(
                Step(
                    "Force of the pivot at the bottom",
                    "F = m(dω_b² + g)",
                    f"{fmt(mass)} kg × ({fmt(distance)} m × ({fmt(value('omega_bottom'))} rad/s)² + {fmt(gravity)} m/s²)",
                    quantity_text(value("pivot_force_bottom"), "N"),
                    "at the bottom α = 0 (gravity has no lever arm), so the pivot holds up the weight and supplies the centripetal force",
                )
            )
    if value("equivalent_length") is not None:
        steps.append(
            Step(
                "Equivalent simple pendulum and centre of percussion",
                "L = I / (md)",
                f"{quantity_text(inertia, 'kg*m**2')} / ({fmt(mass)} kg × {fmt(distance)} m)",
                quantity_text(value("equivalent_length"), "m"),
                "a bob at L has the same period; struck there, the body turns about the pivot with no jolt at the pivot",
            )
        )
    if value("omega0_over") is not None:
        steps.append(
            Step(
                "Does it go over the top?",
                "½Iω₀,over² = U(180°) − U(θ₀)",
                f"ω₀,over = √(2 × {quantity_text(max(swing.potential(math.pi) - swing.potential(theta0), 0.0), 'J')} / {quantity_text(inertia, 'kg*m**2')})",
                quantity_text(value("omega0_over"), "rad/s") + (": it goes over the top" if value("goes_over") else ": it swings back"),
                f"against |ω₀| = {fmt(abs(omega0))} rad/s: it passes the top only with more kinetic energy at the start than the climb takes",
            )
        )
    return steps
