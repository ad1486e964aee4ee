"""The spin-down scene: a wheel on a fixed axle under driving torque, friction and drag.

    I dω/dt = τ_drive − τ_f·sgn(ω) − bω − k|ω|ⁿ·sgn(ω)

Coulomb friction τ_f is physics, not sgn(ω): the wheel stops at t_stop and stays stopped
while |τ_drive| ≤ τ_f (static friction holds it); only a larger driving torque starts it again,
the other way. Each stretch of motion in one direction is a phase with ω ≥ 0 in its own frame.
Closed forms (closed_forms.py) serve every combination with n = 2; a power-law drag with another
exponent has none and is integrated (numerics.py), with the stop located as an event.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace

from taucli.errors import InputError
from taucli.numerics import METHODS, falling_root
from taucli.options.spin_down import COMMAND as TABLE
from taucli.report import (
    Report,
    Step,
    Table,
    Trajectory,
    Value,
    deferred,
    fmt,
    quantity_text,
    term,
)
from taucli.scenes.point import KEYS, RIM, put_point, put_start, rim_radius
from taucli.scenes.assumed import Assumed
from taucli.scenes.motion import (
    DEFAULT_DT,
    DEFAULT_RTOL,
    Evolver,
    Loads,
    Method,
    Phase,
    evolve,
)
from taucli.table import Results
from taucli import numerics
from taucli.numerics import gauss_legendre
from taucli.scenes.contact import body_rim, contacts
from taucli.scenes.inertia import body, body_table
from taucli.scenes.uniform import Uniform, solve_unknowns

TWO_PI = 2 * math.pi
Torques = Loads  # for a wheel the loads are torques: drive, friction, viscous b, drag k

# A fixed step's answers are checked against a reference: the closed form where there is one,
# else rk45 at REFERENCE_RTOL (within 0.33 of it, tests/benchmarks/accuracy_rk45.py). Step
# doubling or Richardson extrapolation would be the method estimating itself, and it misses
# the worst case: a stop inside the first step is the same at dt, dt/2 and 2dt (Euler's one
# linear step from ω₀, located), so it would call an answer 88% off exact.
REFERENCE_RTOL = 1e-11
WITHHELD_ABOVE = 1e-3  # relative: a fixed-step answer estimated further off is withheld (null)
DERIVED = {"revs_stop": "theta_stop", "revs": "theta"}  # results that follow another by θ/2π


@dataclass(frozen=True)
class Push:
    """A tangential push that makes the driving torque: τ = F r sin φ."""
    force: float
    lever: float
    angle: float = math.pi / 2

    @property
    def torque(self) -> float:
        return self.force * self.lever * math.sin(self.angle)


def _net_torque_step(torques: Torques, omega0: float, alpha0: float, inertia: float, held: bool) -> tuple[Step, Step]:
    """τ_net at the start, term by term with its sign, then α = τ_net/I."""
    moving = 1.0 if omega0 > 0 else -1.0 if omega0 < 0 else math.copysign(1.0, torques.drive)
    power = "²" if torques.drag_exponent == 2 else f"^{fmt(torques.drag_exponent)}"
    terms = [  # (symbol, value of the term at the start)
        ("τ_drive", torques.drive),
        ("τ_f", -moving * torques.friction),
        ("bω", -torques.viscous * omega0),
        (f"k|ω|{power}", -moving * torques.drag * abs(omega0) ** torques.drag_exponent),
    ]
    present = [(symbol, value) for symbol, value in terms if value or (symbol == "τ_f" and torques.friction)]
    # the drive is signed as given (its term shows its sign: (−3 N·m)); each loss shows the sign it acts with
    equation = "τ_net = " + " ".join(
        "+ τ_drive" if symbol == "τ_drive" else f"{'−' if value <= 0 else '+'} {symbol}" for symbol, value in present
    ).removeprefix("+ ")
    numbers = " ".join(
        f"+ {term(value, 'N*m')}" if symbol == "τ_drive" else f"{'−' if value < 0 else '+'} {quantity_text(abs(value), 'N*m')}"
        for symbol, value in present
    ).removeprefix("+ ")
    if held:
        why = "at rest, static friction matches the driving torque up to τ_f, so nothing turns"
    elif omega0:
        why = "friction and drag oppose the motion, so they take the sign opposite to ω; the driving torque keeps its own sign (positive along +ω)"
    elif torques.friction:
        why = "from rest, the driving torque beats static friction, and kinetic friction opposes the motion it starts"
    else:
        why = "from rest, the driving torque is the only torque"
    net = alpha0 * inertia
    step_torque = Step("Net torque at the start", equation if present else "τ_net = 0", numbers, quantity_text(net, "N*m"), why)
    step_alpha = Step(
        "Angular acceleration (Newton's second law for rotation)",
        "α = τ_net / I",
        f"{term(net, 'N*m')} / {term(inertia, 'kg*m**2')}",
        quantity_text(alpha0, "rad/s**2"),
        "the negative sign means α opposes ω: the wheel slows"
        if alpha0 * omega0 < 0
        else "the same torque on a larger I would give a smaller α",
    )
    return step_torque, step_alpha


def _model(torques: Torques, method: Method) -> str:
    if torques.drag and torques.drag_exponent != 2:
        return f"power-law drag kω^{fmt(torques.drag_exponent)}: no closed form"
    if torques.drag:
        extra = " and viscous torque" if torques.viscous else ""
        constant = " with constant torque (tangent/arctangent solution)" if torques.drive or torques.friction else ""
        return f"quadratic drag kω²{extra}{constant}"
    if torques.viscous:
        return "exponential approach to a steady speed (viscous torque bω)"
    if torques.drive:
        return "uniform angular acceleration (constant torques)"
    return "uniform deceleration (constant friction torque)"


def solve(
    inertia: float,
    torques: Torques,
    omega0: float = 0.0,
    *,
    time: float | None = None,
    until_omega: float | None = None,
    until_angle: float | None = None,
    method: str = "auto",
    dt: float | None = None,
    rtol: float | None = None,
    push: Push | None = None,
    inertia_steps: Sequence[Step] = (),
    estimate_error: bool = True,
    energy: bool = False,
) -> Report:
    """Spin-down or spin-up of a wheel on a fixed axle; see the module docstring for the model.

    A fixed-step method (euler, rk4) has each answer's error estimated against a reference (the
    ``error_estimate`` table); an answer estimated more than 1e-3 off is withheld, null, with a
    note. ``estimate_error=False`` leaves that out (the bench times the method alone). ``energy``
    adds KE, the work of each torque and the power."""
    if torques.drag and not 1 <= torques.drag_exponent <= 10:
        raise InputError("drag_exponent", "expected a number from 1 to 10", example="{drag_exponent} 1.5", got=fmt(torques.drag_exponent))
    if torques.drag and torques.drag_exponent == 1:
        torques = Torques(torques.drive, torques.friction, torques.viscous + torques.drag, 0.0, 2.0, torques.static)
    if until_angle is not None and (time is not None or until_omega is not None):
        raise InputError("until_angle", "conflicts with {time} and {until_omega}: ask for one target at a time (a run each)")
    closed_form = torques.drag == 0 or torques.drag_exponent == 2
    chosen = _choose_method(method, closed_form, dt, rtol)
    evolver = Evolver(chosen)
    notes: list[str] = []
    motion = evolve(inertia, torques, omega0, evolver)
    first, second, held_from_start, stop = motion.first, motion.second, motion.held_from_start, motion.stop
    alpha0 = motion.initial_rate

    results = Results(TABLE)
    results.put("I", inertia)
    results.put("alpha0", alpha0)
    if held_from_start and not torques.drive:
        notes.append("no initial speed and no driving torque: the wheel stays at rest")
    elif held_from_start:
        notes.append(
            f"static friction holds the wheel at rest: |τ_drive| = {quantity_text(abs(torques.drive), 'N*m')} "
            f"does not exceed τ_f = {quantity_text(torques.holding, 'N*m')}"
        )
    elif stop is None and not first.stops:  # (a stop that a stepper blew up before finding is said below)
        notes.append(_never_stops_note(torques, first))
    answers = _answers(motion, time, until_omega, until_angle)
    results.put("t_stop", answers["t_stop"])
    results.put("theta_stop", answers["theta_stop"])
    results.put("revs_stop", None if answers["theta_stop"] is None else answers["theta_stop"] / TWO_PI)

    omega_inf = motion.final_speed()
    if omega_inf is None:
        notes.append("omega_inf: no steady speed; the driving torque is not balanced by drag, so ω grows without bound")
    results.put("omega_inf", omega_inf)

    if time is not None:
        omega_t, theta_t = answers["omega"], answers["theta"]
        results.put("omega", omega_t, f" at t = {fmt(time)} s")
        _put_angles(results, theta_t, answers["theta_stop"] if second is not None and stop is not None and time > stop[0] else None, time)
    if until_omega is not None:
        if answers["t_until"] is None and not evolver.unstable:
            notes.append(f"the wheel never reaches ω = {quantity_text(until_omega, 'rad/s')}")
        results.put("t_until", answers["t_until"], f" ω = {fmt(until_omega)} rad/s")
        results.put("theta_until", answers["theta_until"], f" ω = {fmt(until_omega)} rad/s")
    if until_angle is not None:
        where = f"θ = {fmt(until_angle)} rad ({fmt(until_angle / TWO_PI)} rev)"
        if answers["t_until"] is None and not evolver.unstable:
            turned = answers["theta_stop"]
            notes.append(f"the wheel stops first, after {fmt(turned)} rad ({fmt(turned / TWO_PI)} rev), and never reaches {where}"
                         if turned is not None and second is None else f"the wheel never reaches {where}")
        results.put("t_until", answers["t_until"], f" θ = {fmt(until_angle)} rad")
        results.put("omega", answers["omega"], f" at θ = {fmt(until_angle)} rad")

    tables, described = {}, chosen.describe(evolver.steps)
    if energy and not evolver.unstable:
        _energy(motion, inertia, torques, omega0, time, results, notes)
    if evolver.unstable:
        notes.extend(dict.fromkeys(evolver.unstable))
        for name in results:
            if name not in ("I", "alpha0"):
                results[name] = Value(None, results[name].unit, results[name].label)
    elif chosen.name in ("euler", "rk4") and estimate_error:
        estimate = _error_estimate(inertia, torques, omega0, closed_form, time, until_omega, until_angle, chosen, results, notes)
        if estimate is not None:
            tables["error_estimate"], worst = estimate
            described += f"; estimated error at most {fmt(worst, 2)} relative" if worst is not None else ""

    steps = list(inertia_steps)
    if push is not None:
        steps.append(_push_step(push))
    steps.extend(_net_torque_step(torques, omega0, alpha0, inertia, held_from_start))
    if not held_from_start:
        steps.extend(_kinematics_steps(torques, first, second, stop, results, time, chosen, omega0))
        if until_angle is not None and results["t_until"].value is not None:
            steps.append(Step("Time to turn θ", "θ(t) = θ_target, solved for t", f"θ_target = {quantity_text(until_angle, 'rad')}",
                              f"t = {quantity_text(results['t_until'].value, 's')}, ω = {quantity_text(results['omega'].value, 'rad/s')}",
                              "θ grows with t while the wheel turns one way, so the time is bracketed and found by bisection on θ(t)"))
    steps.extend(_energy_steps(results, inertia, torques.friction))
    if chosen.name != "exact" and method == "auto":
        notes.append(f"no closed form for drag kω^{fmt(torques.drag_exponent)} with these torques: integrated numerically")
    model = _model(torques, chosen)
    if held_from_start or (stop is not None and second is None):
        model += "; static friction holds it once stopped" if not held_from_start else "; held at rest by static friction"
    trajectory = None if evolver.unstable else deferred(_trajectory, motion, time, omega_inf)
    return Report("spin-down", model, described, results, steps, notes, tables=tables, trajectory=trajectory)


def _put_angles(results: Results, theta: float, turned_back_at: float | None, time: float) -> None:
    """theta and revs by ``time``: the net angle, signed. Where the wheel stopped at the angle
    ``turned_back_at`` and turned back before then, also the total it turned both ways:
    |θ_stop| + |θ − θ_stop|."""
    label = f" by t = {fmt(time)} s"
    results.put("theta", theta, label)
    results.put("revs", theta / TWO_PI, label)
    if turned_back_at is not None:
        total = abs(turned_back_at) + abs(theta - turned_back_at)
        results.put("theta_total", total, label)
        results.put("revs_total", total / TWO_PI, label)


def _energy(motion, inertia: float, torques: Torques, omega0: float, time: float | None, results: Results, notes: list[str]) -> None:
    """KE0, and KE with the work of the drive and of each loss up to --time (or the stop), and
    the power of each at --time (or the start).

    In each stretch of motion one way (a phase, ω ≥ 0 in its frame) I dω/dt = A − bω − kωⁿ with
    A = ±τ_drive − τ_f; times ω and integrated, ½I(ω_b² − ω_a²) = A·d − W_viscous − W_drag over
    the distance d. So the drive does ±τ_drive·d, friction takes τ_f·d, and the viscous and drag
    losses together take the rest; where both act, the viscous one is integrated (b∫ω²dt by
    8-point Gauss-Legendre on the motion) and drag takes what remains.
    """
    n = torques.drag_exponent
    results.put("KE0", inertia * omega0 * omega0 / 2)
    stop = motion.stop
    end = time if time is not None else (stop[0] if stop is not None and not motion.held_from_start else None)
    if end is not None:
        omega_end = motion.state_at(end)[0] if time is not None else 0.0
        results.put("KE", inertia * omega_end * omega_end / 2, " at the stop" if time is None else f" at t = {fmt(end)} s")
    at = 0.0 if time is None else time
    omega_at = motion.state_at(at)[0]
    when = " at the start" if time is None else f" at t = {fmt(at)} s"
    if torques.drive:
        results.put("power", torques.drive * omega_at, when)
    if torques.friction:
        results.put("power_friction", torques.friction * abs(omega_at), when)
    if torques.viscous:
        results.put("power_viscous", torques.viscous * omega_at * omega_at, when)
    if torques.drag:
        results.put("power_drag", torques.drag * abs(omega_at) ** (n + 1), when)
    if end is None:
        if not motion.held_from_start:
            notes.append("KE and work: the wheel never stops, so give {time} to say up to when")
        return
    by = f" by t = {fmt(end)} s" if time is not None else " until it stops"
    work = {"drive": 0.0, "friction": 0.0, "viscous": 0.0, "drag": 0.0}
    segments = []
    if not motion.held_from_start:
        first_end = end if stop is None else min(end, stop[0])
        segments.append((motion.first, first_end, stop is not None and end >= stop[0]))
        if motion.second is not None and stop is not None and end > stop[0]:
            segments.append((motion.second, end - stop[0], False))
    for phase, duration, to_stop in segments:
        start = phase.closed.omega0
        if to_stop:
            finish, distance = 0.0, stop[1]
        else:
            finish, distance = motion.evolver.state(phase, duration)
        drive = phase.direction * torques.drive
        work["drive"] += drive * distance
        work["friction"] += torques.friction * distance
        rest = (drive - torques.friction) * distance - inertia * (finish - start) * (finish + start) / 2
        if torques.viscous and torques.drag:
            sampler = _phase_sampler(motion.evolver, phase)
            viscous = torques.viscous * numerics_gauss(lambda t: sampler(t) ** 2, duration)
            work["viscous"] += viscous
            work["drag"] += max(0.0, rest - viscous)
        elif torques.viscous:
            work["viscous"] += max(0.0, rest)
        elif torques.drag:
            work["drag"] += max(0.0, rest)
    if torques.drive:
        results.put("work_drive", work["drive"], by)
        if end > 0:
            results.put("power_mean", work["drive"] / end, by)
    for name in ("friction", "viscous", "drag"):
        if getattr(torques, name):
            results.put("work_" + name, work[name], by)


def _phase_sampler(evolver: Evolver, phase: Phase):
    """ω(t) within a phase, for times asked in increasing order (a stepper steps on)."""
    last = [None]

    def omega(t: float) -> float:
        state = evolver.state(phase, t, last[0])
        last[0] = (t, *state)
        return state[0]

    return omega


def numerics_gauss(f, duration: float) -> float:

    return gauss_legendre(f, 0.0, duration)


def _answers(motion, time: float | None, until_omega: float | None, until_angle: float | None = None) -> dict[str, float | None]:
    """What a method's motion answers (the results a step size changes), by name."""
    stop, signed_stop = motion.stop, motion.signed_stop
    answers: dict[str, float | None] = {"t_stop": None if stop is None else stop[0], "theta_stop": None if signed_stop is None else signed_stop[1]}
    if time is not None:
        answers["omega"], answers["theta"] = motion.state_at(time)
    if until_omega is not None:
        reached = motion.reach(until_omega)
        answers["t_until"], answers["theta_until"] = (None, None) if reached is None else reached
    if until_angle is not None:
        reached = motion.reach_angle(until_angle)
        answers["t_until"], answers["omega"] = (None, None) if reached is None else reached
    return answers


def _error_estimate(inertia, torques, omega0, closed_form, time, until_omega, until_angle, chosen: Method, results, notes) -> tuple[Table, float | None] | None:
    """The error of each of a fixed step's answers, against the closed form or a tight rk45
    run: the table of them, and the largest relative error. Answers off by more than
    WITHHELD_ABOVE are withheld (null) with one note that gives them and a step that would do."""
    reference_method = Method("exact") if closed_form else Method("rk45", None, REFERENCE_RTOL)
    against = "the closed form" if closed_form else f"rk45 at rtol {REFERENCE_RTOL:g}"
    try:
        reference = _answers(evolve(inertia, torques, omega0, Evolver(reference_method)), time, until_omega, until_angle)
    except InputError:
        notes.append(f"no error estimate: the reference run ({against}) would take too many steps; the {chosen.name} answers are unchecked")
        return None
    rows, off, worst = [], [], 0.0
    for name, exact in reference.items():
        got, unit = results[name].value, results[name].unit
        if got is None and exact is None:
            continue
        error = relative = None
        if got is not None and exact is not None:
            error = abs(got - exact)
            relative = error / abs(exact) if exact else (0.0 if error == 0 else None)
        rows.append((name, got, error, unit, relative))
        if relative is not None and relative <= WITHHELD_ABOVE:
            worst = max(worst, relative)
            continue
        worst = math.inf if relative is None else max(worst, relative)
        shown = "none" if got is None else quantity_text(got, unit)
        gap = "" if relative is None else f", {_percent(relative)} off"
        off.append(f"{name} = {shown}{gap} ({'none' if exact is None else quantity_text(exact, unit)})")
        for withheld in (name, *(derived for derived, source in DERIVED.items() if source == name)):
            if withheld in results:
                results[withheld] = results[withheld]._replace(value=None)
    if off:
        order = METHODS[chosen.name].order
        advice = "--method auto"
        if math.isfinite(worst) and worst > 0:
            advice = f"--dt {fmt(chosen.dt * (WITHHELD_ABOVE / worst) ** (1 / order) / 2, 1)} s or less (its error goes as dt{'' if order == 1 else _SUPERSCRIPT[order]}), or {advice}"
        notes.append(
            f"{chosen.name} at dt = {fmt(chosen.dt)} s is off by more than {WITHHELD_ABOVE:g} here, estimated against {against} "
            f"(in brackets): {'; '.join(off)}; withheld. Try {advice}"
        )
    columns = (("result", None, "result"), ("value", None, "value"), ("error", None, "estimated error"), ("unit", None, "unit"), ("relative", None, "relative error"))
    return Table(columns, tuple(rows)), (worst if math.isfinite(worst) else None)


_SUPERSCRIPT = {2: "²", 3: "³", 4: "⁴", 5: "⁵"}


def _percent(relative: float) -> str:
    return f"{round(100 * relative)}%" if relative >= 0.01 else f"{fmt(100 * relative, 2)}%"


def _trajectory(motion, time: float | None, omega_inf: float | None) -> Trajectory:
    """ω(t) and θ(t): to --time, else a quarter past the stop, else 99% of the way to the steady speed."""
    stop, note = motion.stop, ""
    if time is not None and time > 0:
        t_end = time
    elif stop is not None and stop[0] > 0:
        t_end = (2.0 if motion.second is not None else 1.25) * stop[0]
    else:
        omega0 = motion.state_at(0.0)[0]
        near = None if omega_inf is None or omega_inf == omega0 else motion.reach(omega0 + 0.99 * (omega_inf - omega0))
        t_end = near[0] if near is not None and near[0] > 0 else 1.0
        note = "plotted until ω is 99% of the way to its steady speed; --time to change" if near else "plotted for 1 s; --time to change"
    marks = ((stop[0], "stops"),) if stop is not None and stop[0] > 0 else ()
    curves = (("omega", "rad/s", "angular velocity ω"), ("theta", "rad", "angle turned θ"))
    return Trajectory(curves, t_end, motion.sampler(), marks=marks, note=note)


def _choose_method(method: str, closed_form: bool, dt: float | None, rtol: float | None) -> Method:
    if method == "auto":
        return Method("exact") if closed_form else Method("rk45", None, rtol or DEFAULT_RTOL)
    if method == "exact":
        if not closed_form:
            raise InputError("method", "exact has no closed form for a drag exponent other than 1 or 2", hint="use {method} auto or rk45")
        return Method("exact")
    if method in ("euler", "rk4"):
        return Method(method, dt or DEFAULT_DT)
    if method == "rk45":
        return Method("rk45", dt, rtol or DEFAULT_RTOL)
    raise InputError("method", f"expected one of auto, exact, {', '.join(METHODS)}", example="{method} rk4 {dt} 1ms", got=repr(method))


def _never_stops_note(torques: Torques, phase: Phase) -> str:
    if phase.closed.constant > 0:
        return "t_stop: the driving torque exceeds friction, so the wheel never stops" if torques.friction else "t_stop: the driving torque keeps it turning, so the wheel never stops"
    if torques.viscous or torques.drag:
        return "t_stop: drag alone slows the wheel ever more gently and never quite stops it"
    return "t_stop: no net torque, so ω stays constant and the wheel never stops"


def _push_step(push: Push) -> Step:
    at_right_angle = math.isclose(push.angle, math.pi / 2)
    return Step(
        "Torque of the push",
        "τ = F r" if at_right_angle else "τ = F r sin φ",
        f"{quantity_text(push.force, 'N')} × {quantity_text(push.lever, 'm')}"
        + ("" if at_right_angle else f" × sin {fmt(math.degrees(push.angle))}°"),
        quantity_text(push.torque, "N*m"),
        "the force is tangential, perpendicular to the radius, so all of it turns the wheel"
        if at_right_angle
        else "only the part of the force perpendicular to the lever arm makes torque",
    )


def _stop_steps(w0: float, alpha: float, stop: tuple[float, float]) -> list[Step]:
    """t_stop = ω₀/|α| and θ_stop = ω₀²/(2|α|): constant α against the motion."""
    return [
        Step("Time to stop", "ω = ω₀ + αt = 0  ⇒  t = ω₀/|α|", f"{term(abs(w0), 'rad/s')} / {term(abs(alpha), 'rad/s**2')}",
             quantity_text(stop[0], "s"), "constant torque gives constant α, so ω falls linearly to zero"),
        Step("Angle turned while stopping", "θ = ω₀²/(2|α|)", f"({term(abs(w0), 'rad/s')})² / (2 × {term(abs(alpha), 'rad/s**2')})",
             quantity_text(abs(stop[1]), "rad") + f" = {fmt(abs(stop[1]) / TWO_PI)} rev", "the rotational analogue of v² = 2as"),
    ]


def _angle_step(title: str, omega0: float, alpha: float, time: float, theta: float) -> Step:
    """θ = ω₀t + ½αt²: the net angle, which holds through a turn back at constant α."""
    return Step(title, "θ = ω₀t + ½αt²", f"{term(omega0, 'rad/s')} × {term(time, 's')} + ½ × {term(alpha, 'rad/s**2')} × ({term(time, 's')})²",
                quantity_text(theta, "rad"), "the rotational analogue of s = ut + ½at²")


def _after_time_steps(omega0: float, alpha: float, time: float, results: Results) -> list[Step]:
    """ω = ω₀ + αt and θ = ω₀t + ½αt² at t."""
    return [
        Step("Angular velocity after t", "ω = ω₀ + αt", f"{term(omega0, 'rad/s')} + {term(alpha, 'rad/s**2')} × {term(time, 's')}",
             quantity_text(results["omega"].value, "rad/s"), "constant α: ω changes by the same amount every second"),
        _angle_step("Angle turned in t", omega0, alpha, time, results["theta"].value),
    ]


def _revolutions_step(results: Results) -> Step:
    return Step("Convert to revolutions", "revs = θ / 2π", f"{term(results['theta'].value, 'rad')} / 2π",
                f"{fmt(results['revs'].value)} rev", "one full revolution is 2π radians")


def _kinematics_steps(torques, first, second, stop, results, time, method, omega0) -> list[Step]:
    steps: list[Step] = []
    closed = first.closed
    alpha = results["alpha0"].value
    w0 = abs(omega0)
    if method.name != "exact":
        steps.append(
            Step(
                "Integrate the equation of motion",
                "I dω/dt = τ_net(ω),  dθ/dt = ω",
                method.describe(0).split(",")[0],
                "",
                "no closed form exists for this drag law; the stop is located as an event so friction cannot chatter",
            )
        )
    elif closed.uniform:
        if stop is not None and stop[0] > 0:
            steps.extend(_stop_steps(w0, alpha, stop))
        back = second is not None and stop is not None and time is not None and time > stop[0]
        if time is not None and results["theta"].value is not None and not back:
            steps.extend(_after_time_steps(omega0, alpha, time, results))
        elif back and results["theta"].value is not None:
            steps.extend(_turned_back_steps(torques, results['I'].value, second, stop, results, time))
        if time is not None and results["theta"].value is not None:
            steps.append(_revolutions_step(results))
    else:
        discriminant = closed.viscous**2 + 4 * closed.drag * closed.constant
        steps.append(
            Step(
                "The constants of I dω/dt = A − bω − kω²",
                f"D = b² + 4kA,  with A = τ_drive − τ_f = {quantity_text(closed.constant, 'N*m')}",
                f"({term(closed.viscous, 'N*m*s')})² + 4 × {term(closed.drag, 'N*m*s**2')} × {term(closed.constant, 'N*m')}",
                quantity_text(discriminant, "N**2*m**2*s**2")
                + (" (D < 0: the tangent form)" if discriminant < 0 else " (D > 0: the tanh form)" if closed.drag else " (k = 0: exponential)"),
                "the sign of D decides which of the log, arctangent or artanh integrals the separable equation gives",
            )
        )
        steps.append(
            Step(
                "Solve it (separable)",
                "ω(t) = r₊ + (ω₀ − r₊)E/(E + (kω₀ + β)(1 − E)/√D),  E = e^(−√D t/I),  r₊ = 2A/(b + √D),  β = (b + √D)/2",
                "",
                "",
                "r₊ is the steady speed when D > 0 and A > 0; for D < 0 the same form is the tangent solution, "
                "evaluated so that it stays exact as k -> 0 (exponential decay) and D -> 0",
            )
        )
        if stop is not None and stop[0] > 0:
            steps.append(Step("Time and angle to stop", "t_stop from ω(t) = 0;  θ_stop = ∫ω dt",
                              "", f"{quantity_text(stop[0], 's')}, {quantity_text(abs(stop[1]), 'rad')} = {fmt(abs(stop[1]) / TWO_PI)} rev",
                              "friction keeps a constant torque against the motion, so the wheel stops in a finite time"))
    return steps


def _turned_back_steps(torques, inertia: float, second, stop, results, time: float) -> list[Step]:
    """The drive outlasts the stop: the wheel starts back from rest at t_stop with the second
    phase's constant α₂ = (τ_drive ∓ τ_f)/I (friction now on the other side), so ω and θ are
    taken from there."""
    alpha2 = second.direction * second.rate(0.0)
    since = time - stop[0]
    theta, theta_stop = results["theta"].value, stop[1] if results["theta_stop"].value is None else results["theta_stop"].value
    friction = f" {'+' if second.direction < 0 else '−'} {term(torques.friction, 'N*m')}" if torques.friction else ""
    return [
        Step("Angular acceleration after the stop", f"α₂ = (τ_drive {'+' if second.direction < 0 else '−'} τ_f)/I" if torques.friction else "α₂ = τ_drive/I",
             f"({term(torques.drive, 'N*m')}{friction}) / {term(inertia, 'kg*m**2')}", quantity_text(alpha2, "rad/s**2"),
             "the drive is larger than static friction, so the wheel starts back the other way; friction turns with the motion, against it"),
        Step("Angular velocity after t", "ω = α₂(t − t_stop)", f"{term(alpha2, 'rad/s**2')} × ({term(time, 's')} − {term(stop[0], 's')})",
             quantity_text(results["omega"].value, "rad/s"), "from rest at t_stop, ω grows at the constant α₂"),
        Step("Net angle turned in t", "θ = θ_stop + ½α₂(t − t_stop)²",
             f"{term(theta_stop, 'rad')} + ½ × {term(alpha2, 'rad/s**2')} × ({term(since, 's')})²",
             quantity_text(theta, "rad"), "θ is where the wheel is, net of the turn back"),
        Step("Total angle turned, both ways", "θ_total = |θ_stop| + |θ − θ_stop|",
             f"{term(abs(theta_stop), 'rad')} + {term(abs(theta - theta_stop), 'rad')}",
             quantity_text(results["theta_total"].value, "rad") + f" = {fmt(results['revs_total'].value)} rev",
             "the wheel turned θ_stop one way, then back: the total counts both"),
    ]


def spin_down(
    *,
    omega0: float | None = None,
    torque: float | None = None,
    force: float | None = None,
    lever: float | None = None,
    push_angle: float | None = None,
    friction: float | None = None,
    brake: Sequence | None = None,
    face: Sequence | None = None,
    g: float | None = None,
    at: float | None = None,
    viscous: float | None = None,
    drag: float | None = None,
    drag_exponent: float | None = None,
    time: float | None = None,
    until_omega: float | None = None,
    until_angle: float | None = None,
    until_arc: float | None = None,
    alpha: float | None = None,
    in_time: float | None = None,
    power: float | None = None,
    ke0: float | None = None,
    rim_speed: float | None = None,
    energy: bool = False,
    method: str = "auto",
    dt: float | None = None,
    rtol: float | None = None,
    **body_options,
) -> Report:
    """``taucli spin-down``: the body (--inertia or --shape ...), its torques, and what to report.

    The drive is --torque, or the push --force at --lever (at --push-angle, default 90°) that
    makes it, or a motor of constant --power; the losses left out are zero; the wheel starts at
    ω₀ = 0 unless --omega0 (or --rim-speed, or --ke0) says. --alpha, or no body at all, is
    rotation at constant α: any three of ω₀, ω₁, α, t, θ give the rest.
    """
    if power == 0:
        power = None  # a motor of no power is no motor
    if g is not None and not any(plate.force is None for plate in face or ()):
        raise InputError("g", "is used only for the weight on a {face} with no force=")
    has_body = body_options.get("inertia") is not None or body_options.get("shape") is not None or bool(body_options.get("part"))
    rim = None
    if body_options.get("inertia") is not None and body_options.get("shape") is None and body_options.get("radius") is not None:
        if rim_speed is None and until_arc is None and at != RIM:
            raise InputError("radius", "goes with {shape}; with {inertia} it is the rim's radius, for {rim_speed}, {until_arc} or {at} rim")
        rim = body_options.pop("radius")
    moment, body_steps = body(**body_options) if has_body else (None, ())
    parts = None
    if body_options.get("part"):

        parts = body_table(**body_options)
    results = Results(TABLE)
    front_steps: list[Step] = []
    notes: list[str] = []
    if rim_speed is not None or until_arc is not None:
        rim = rim if rim is not None else _rim_radius(body_options, "rim_speed" if rim_speed is not None else "until_arc")
    given = [name for name, value in (("omega0", omega0), ("rim_speed", rim_speed), ("ke0", ke0)) if value is not None]
    if len(given) > 1:
        raise InputError(given[1], f"conflicts with {{{given[0]}}}: give the initial speed one way")
    if rim_speed is not None:
        omega0 = rim_speed / rim
        front_steps.append(Step("Angular velocity from the rim speed", "ω₀ = v/R", f"{quantity_text(rim_speed, 'm/s')} / {quantity_text(rim, 'm')}",
                                quantity_text(omega0, "rad/s"), "a point at radius R moves at v = ωR"))
        notes.append(f"ω₀ = v/R = {quantity_text(omega0, 'rad/s')}: the rim speed {quantity_text(rim_speed, 'm/s')} at R = {quantity_text(rim, 'm')}")
        results.put("omega0", omega0, " (from the rim speed)")
    if ke0 is not None:
        if moment is None:
            raise InputError("ke0", "needs a body ({inertia} or {shape}): ω₀ = √(2E/I)")
        omega0 = math.sqrt(2 * ke0 / moment)
        front_steps.append(Step("Angular velocity from the stored energy", "KE = ½Iω²  ⇒  ω₀ = √(2KE/I)",
                                f"√(2 × {quantity_text(ke0, 'J')} / {quantity_text(moment, 'kg*m**2')})", quantity_text(omega0, "rad/s"),
                                "all the energy of a wheel on a fixed axle is its rotational kinetic energy"))
        results.put("omega0", omega0, " (from KE0)")
    if until_arc is not None:
        if until_angle is not None:
            raise InputError("until_arc", "conflicts with {until_angle}: give the target one way")
        until_angle = until_arc / rim
        notes.append(f"θ = s/R = {quantity_text(until_angle, 'rad')}: the arc {quantity_text(until_arc, 'm')} at R = {quantity_text(rim, 'm')}")
    push = None
    if force is not None or lever is not None or push_angle is not None:
        if torque is not None:
            raise InputError("torque", "conflicts with {force} and {lever}: give the torque, or the push that makes it")
        if force is None:
            raise InputError("force", "is required with {lever}", example="{force} 6N")
        if lever is None:
            raise InputError("lever", "is required with {force}", example="{lever} 0.2m")
        push = Push(force, lever) if push_angle is None else Push(force, lever, push_angle)
        drive = push.torque
    else:
        drive = torque or 0.0
    contact, assumed = None, Assumed()
    axle = friction or 0.0
    if brake or face:
        contact = _contacts(brake or (), face or (), body_options, rim, assumed, g, results, front_steps, notes, axle)
        friction = axle + contact.kinetic
    static = None if contact is None or contact.static == contact.kinetic else axle + contact.static
    torques = Torques(drive, friction or 0.0, viscous or 0.0, drag or 0.0, 2.0 if drag_exponent is None else drag_exponent, static)

    def finish(report: Report, parts: Table | None) -> Report:
        """The report with the parts table, the contacts' shares of the friction, and what was assumed."""
        report = assumed.applied(_with_contacts(_split_contacts(_with_parts(report, parts), axle, contact), contact))
        if at is None:
            return report
        r, note = rim_radius(at, rim if rim is not None else body_options.get("radius", body_options.get("outer_radius")), "a body with {radius}")
        report = _point(report, r, torques, moment, power, omega0, time=time, until_omega=until_omega, until_angle=until_angle)
        report.notes += [note] if note else []
        return report

    if push is not None:
        front_steps.append(_push_step(push))
    if alpha is not None or not has_body:
        if power is not None:
            raise InputError("power", "conflicts with {alpha}: a constant power gives a changing α" if alpha is not None else "needs a body ({inertia} or {shape})")
        if in_time is not None:
            if time is not None:
                raise InputError("in_time", "conflicts with {time}: without a body they say the same")
            time = in_time
        return finish(_with_front(_uniform_report(moment, body_steps, torques, omega0, alpha, time=time, until_omega=until_omega,
                                           until_angle=until_angle, front=(front_steps, notes, results)), results), parts)
    if power is not None:
        if in_time is not None:
            raise InputError("in_time", "conflicts with {power}: the drive is the motor's")
        if push is not None:
            raise InputError("power", "conflicts with {force}: give the motor's power or the push")
        return finish(_with_front(_power_report(moment, body_steps, power, torques, omega0 or 0.0, time=time, until_omega=until_omega,
                                         until_angle=until_angle, method=method, dt=dt, rtol=rtol), results, notes, front_steps), parts)
    if in_time is not None:
        if torque is not None or push is not None or power is not None:
            raise InputError("in_time", "asks for the drive torque that meets the target, so it conflicts with a drive ({torque}, {force}, {power})")
        if (until_omega is None) == (until_angle is None):
            raise InputError("in_time", "needs one target: {until_omega} or {until_angle}", example="{until_omega} 1000rpm {in_time} 3s")
        if time is not None:
            raise InputError("time", "conflicts with {in_time}: ask for the target's time one way")
        if not torques.viscous and not torques.drag:
            return finish(_with_front(_uniform_report(moment, body_steps, torques, omega0, None, time=in_time, until_omega=until_omega,
                                               until_angle=until_angle, front=(front_steps, notes, results)), results), parts)
        torques = _drive_for_target(moment, torques, omega0 or 0.0, in_time, until_omega, until_angle, method, dt, rtol)
        time, until_omega, until_angle = in_time, None, None
        notes.append(f"the constant drive torque that meets the target in t = {fmt(in_time)} s, found by bisection on the motion: "
                     f"τ = {quantity_text(torques.drive, 'N*m')}")
        results.put("torque", torques.drive, " that meets the target")
    report = solve(
        moment, torques, omega0 or 0.0, time=time, until_omega=until_omega, until_angle=until_angle, method=method, dt=dt, rtol=rtol,
        push=push, inertia_steps=body_steps, energy=energy or ke0 is not None or power is not None or in_time is not None,
    )
    if "torque" in results:
        results.put("torque_net", report.results["alpha0"].value * moment, " at the start")
    return finish(_with_front(report, results, notes, front_steps), parts)


def _drive_for_target(inertia, torques: Torques, omega0, in_time, until_omega, until_angle, method, dt, rtol) -> Torques:
    """The constant drive with which the wheel is at ω₁ (or has turned θ) at t: ω(t) and θ(t) grow
    with the drive, so bisection brackets it; to the last bit of a double."""
    closed_form = torques.drag == 0 or torques.drag_exponent == 2
    evolver_method = _choose_method(method, closed_form, dt, rtol)

    def miss(drive: float) -> float:
        trial = Torques(drive, torques.friction, torques.viscous, torques.drag, torques.drag_exponent)
        omega, theta = evolve(inertia, trial, omega0, Evolver(evolver_method)).state_at(in_time)
        return omega - until_omega if until_omega is not None else theta - until_angle

    target = until_omega if until_omega is not None else until_angle
    scale = max(abs(target) / in_time, abs(omega0), 1.0)
    size = inertia * scale / in_time + torques.friction + torques.viscous * scale + torques.drag * scale**torques.drag_exponent
    low, high = -size, size
    for _ in range(200):
        if miss(high) >= 0:
            break
        low, high = high, 2 * high
    for _ in range(200):
        if miss(low) <= 0:
            break
        low, high = 2 * low, low
    for _ in range(200):
        mid = (low + high) / 2
        if mid in (low, high):
            break
        low, high = (mid, high) if miss(mid) < 0 else (low, mid)
    return Torques((low + high) / 2, torques.friction, torques.viscous, torques.drag, torques.drag_exponent)


def _with_parts(report: Report, parts: Table | None) -> Report:
    """The report with the parts table of a body of parts."""
    if parts is None:
        return report
    return Report(report.scene, report.model, report.method, report.results, report.steps, report.notes, report.inputs,
                  {"parts": parts, **report.tables}, report.trajectory)


def _rim_radius(body_options: dict, option: str) -> float:
    """The radius of the body's rim: its radius, or its outer radius."""
    for name in ("radius", "outer_radius"):
        if body_options.get(name) is not None:
            return body_options[name]
    raise InputError(option, "needs a radius: the body's ({shape} with {radius}), or {radius} beside {inertia}")


def _with_front(report: Report, front: Results, notes: Sequence[str] = (), steps: Sequence[Step] = ()) -> Report:
    """The report with what was worked out before the motion (ω₀ from a rim speed or KE0) first."""
    if not front and not notes and not steps:
        return report
    results = Results(TABLE)
    results.update(front)
    results.update(report.results)
    merged_steps = list(report.steps)
    if steps:
        body_count = next((i for i, step in enumerate(merged_steps) if step.title.startswith(("Torque of the push", "Net torque"))), 0)
        merged_steps[body_count:body_count] = [s for s in steps if s.title != "Torque of the push"]
    return Report(report.scene, report.model, report.method, results, merged_steps, [*notes, *report.notes], report.inputs, report.tables, report.trajectory)


# ---------------------------------------------------------------------------------------------
# Constant angular acceleration (--alpha, or no body): kinematics, and with a body the torque.


def _uniform_report(
    inertia: float | None,
    inertia_steps: Sequence[Step],
    torques: Torques,
    omega0: float | None,
    alpha: float | None,
    *,
    time: float | None,
    until_omega: float | None,
    until_angle: float | None,
    front: tuple[list[Step], list[str], Results],
) -> Report:
    """Rotation at constant α: from --alpha, or from the targets (any three of ω₀, ω₁, α, t, θ)."""
    front_steps, notes, results = front
    given_alpha = alpha is not None
    if torques.drive:
        raise InputError("torque", "conflicts with {alpha}: the drive is what a constant α asks for (reported as torque)" if given_alpha else "needs a body ({inertia} or {shape})")
    losses = [name for name, value in (("friction", torques.friction), ("viscous", torques.viscous), ("drag", torques.drag)) if value]
    if inertia is None and not given_alpha and until_omega is None and until_angle is None and losses:
        alpha, given_alpha = 0.0, True  # losses and no body: a wheel held at a constant speed
        notes.append("no body and no α: the wheel is held at a constant speed, and torque is the drive that balances the losses")
    if inertia is None and losses and not (given_alpha and alpha == 0):
        raise InputError(losses[0], "needs a body ({inertia} or {shape}), or {alpha} 0 for a wheel held at a constant speed")
    w0_given = omega0
    w0, alpha, solved_notes = solve_unknowns(omega0, alpha, time, until_omega, until_angle)
    notes.extend(solved_notes)
    if alpha != 0 and (torques.viscous or torques.drag):
        raise InputError("viscous" if torques.viscous else "drag", "makes α change with ω, so it cannot be constant: leave out {alpha}, or give it as 0")
    motion = Uniform(w0, alpha)
    targets = sum(x is not None for x in (time, until_omega, until_angle))
    pair = not given_alpha or (w0_given is None and targets >= 2)  # the targets fixed α or ω₀
    steps = list(inertia_steps) + front_steps
    if not given_alpha:  # the steps that found α; a given α's come once the results are in
        steps.extend(_uniform_alpha_steps(w0, alpha, time, until_omega, until_angle))
    if w0_given is None and pair and given_alpha:
        results.put("omega0", w0, " (from the targets)")
    if inertia is not None:
        results.put("I", inertia)
    results.put("alpha0", alpha)
    results.put("alpha", alpha)

    stop = motion.stop()
    if stop is not None:
        results.put("t_stop", stop[0])
        results.put("theta_stop", stop[1])
        results.put("revs_stop", stop[1] / TWO_PI)
        notes.append(
            f"a constant α carries the wheel on through ω = 0: it stops at t = {fmt(stop[0])} s, "
            f"after {fmt(abs(stop[1]) / TWO_PI)} rev, and turns back (t_stop, theta_stop give the first stop)"
        )

    end: float | None = None  # the time the energy, power and work are given at
    if pair:
        if time is not None:
            end = time
        elif until_omega is not None and until_angle is not None:
            end = 2 * until_angle / (w0 + until_omega)
        elif until_omega is not None:
            end = motion.time_to_omega(until_omega)
        else:
            end = _first_time_at_angle(motion, until_angle, notes)
        if end is None:
            raise InputError("until_omega", "is never reached at this α", got=f"α = {alpha:g} rad/s²")
        label = f" at t = {fmt(end)} s"
        results.put("omega", motion.omega(end), label)
        _put_angles(results, motion.theta(end), stop[1] if stop is not None and end > stop[0] else None, end)
        if time is None:
            results.put("t_until", end, " the target")
    else:
        if until_omega is not None and until_angle is not None:
            raise InputError("until_angle", "conflicts with {until_omega}: ask for one target at a time")
        if time is not None:
            end = time
            results.put("omega", motion.omega(time), f" at t = {fmt(time)} s")
            _put_angles(results, motion.theta(time), stop[1] if stop is not None and time > stop[0] else None, time)
        if until_omega is not None:
            t = motion.time_to_omega(until_omega)
            if t is None:
                notes.append(f"the wheel never reaches ω = {quantity_text(until_omega, 'rad/s')} at this α")
            elif stop is not None and t > stop[0]:
                notes.append(f"ω = {quantity_text(until_omega, 'rad/s')} is reached only after the wheel has stopped and turned back")
            results.put("t_until", t, f" ω = {fmt(until_omega)} rad/s")
            results.put("theta_until", None if t is None else motion.theta(t), f" ω = {fmt(until_omega)} rad/s")
        if until_angle is not None:
            t = _first_time_at_angle(motion, until_angle, notes)
            part = f" θ = {fmt(until_angle)} rad"
            results.put("t_until", t, part)
            if time is None:
                results.put("omega", None if t is None else motion.omega(t), f" at θ = {fmt(until_angle)} rad")
                end = t
    if given_alpha:
        steps.extend(_given_alpha_steps(motion, w0_given, time, until_omega, until_angle, results))
    if inertia is not None or losses:
        _uniform_torque(inertia, torques, motion, end, results, steps, notes)
    model = "uniform angular acceleration (constant α)" + ("" if given_alpha else ", from the targets")
    if inertia is not None:
        steps.extend(_energy_steps(results, inertia, torques.friction))
    trajectory = deferred(_curves, lambda t: (motion.omega(t), motion.theta(t)), end, stop)
    return Report("spin-down", model, "closed form", results, steps, notes, trajectory=trajectory)


def _curves(state, end: float | None, stop: tuple[float, float] | None) -> Trajectory:
    """ω(t) and θ(t) to the end asked for, else past the first stop, else for 10 s."""
    note = ""
    if end is not None and end > 0:
        t_end = end
    elif stop is not None and stop[0] > 0:
        t_end = 1.25 * stop[0]
    else:
        t_end, note = 10.0, "plotted for 10 s; --time to change"
    marks = ((stop[0], "stops"),) if stop is not None and 0 < stop[0] <= t_end else ()
    curves = (("omega", "rad/s", "angular velocity ω"), ("theta", "rad", "angle turned θ"))
    return Trajectory(curves, t_end, state, marks=marks, note=note)


def _first_time_at_angle(motion, theta: float, notes: list[str]) -> float | None:
    """The first time the wheel is at θ, with notes on the second root and on turning back."""
    times = motion.times_at_angle(theta)
    stop = motion.stop()
    where = f"θ = {fmt(theta)} rad ({fmt(theta / TWO_PI)} rev)"
    if not times:
        turn = f"it stops after {fmt(abs(stop[1]) / TWO_PI)} rev and turns back" if stop else "it turns the other way"
        notes.append(f"the wheel never reaches {where}: {turn}")
        return None
    if stop is not None and times[0] > stop[0]:
        notes.append(f"the wheel turns back first (it stops at t = {fmt(stop[0])} s, {fmt(stop[1])} rad) and reaches {where} on the way back")
    elif len(times) == 2:
        notes.append(f"the other root, t = {fmt(times[1])} s, is when the wheel, turned back, passes {where} again")
    return times[0]


def _uniform_alpha_steps(w0, alpha, time, w1, theta) -> list[Step]:
    """α (and the time where it is not given) from the targets: any three of ω₀, ω₁, α, t, θ."""
    steps: list[Step] = []
    if time is not None and w1 is not None:
        steps.append(Step("Angular acceleration from the change of speed", "α = (ω₁ − ω₀)/t", f"({term(w1, 'rad/s')} − {term(w0, 'rad/s')}) / {term(time, 's')}",
                          quantity_text(alpha, "rad/s**2"), "constant α: ω changes by the same amount every second"))
        steps.append(Step("Angle turned", "θ = ½(ω₀ + ω₁)t", f"½ × ({term(w0, 'rad/s')} + {term(w1, 'rad/s')}) × {term(time, 's')}",
                          quantity_text((w0 + w1) * time / 2, "rad") + f" = {fmt((w0 + w1) * time / 2 / TWO_PI)} rev",
                          "at constant α the mean speed is the average of the first and the last"))
    elif time is not None and theta is not None:
        steps.append(Step("Angular acceleration from the angle and the time", "θ = ω₀t + ½αt²  ⇒  α = 2(θ − ω₀t)/t²",
                          f"2 × ({term(theta, 'rad')} − {term(w0, 'rad/s')} × {term(time, 's')}) / ({term(time, 's')})²", quantity_text(alpha, "rad/s**2"),
                          "the rotational analogue of s = ut + ½at², solved for the acceleration"))
    elif w1 is not None and theta is not None:
        steps.append(Step("Angular acceleration from the speeds and the angle", "ω₁² = ω₀² + 2αθ  ⇒  α = (ω₁² − ω₀²)/(2θ)",
                          f"(({term(w1, 'rad/s')})² − ({term(w0, 'rad/s')})²) / (2 × {term(theta, 'rad')})", quantity_text(alpha, "rad/s**2"),
                          "the rotational analogue of v² = u² + 2as"))
        steps.append(Step("Time taken", "t = 2θ/(ω₀ + ω₁)", f"2 × {term(theta, 'rad')} / ({term(w0, 'rad/s')} + {term(w1, 'rad/s')})",
                          quantity_text(2 * theta / (w0 + w1), "s"), "the angle is the mean speed times the time"))
    return steps


def _given_alpha_steps(motion, w0_given: float | None, time: float | None, until_omega: float | None, until_angle: float | None,
                       results: Results) -> list[Step]:
    """The worked kinematics at a given constant α: ω₀ where the targets fix it, the stop, then
    ω and θ at t, or the time (and the angle or speed) at the target."""
    w0, alpha = motion.omega0, motion.alpha
    a = term(alpha, "rad/s**2")
    steps: list[Step] = []
    if w0_given is None and "omega0" in results:  # two targets and α fixed ω₀
        if time is not None and until_omega is not None:
            equation, numbers = "ω₀ = ω₁ − αt", f"{term(until_omega, 'rad/s')} − {a} × {term(time, 's')}"
        elif time is not None:
            equation, numbers = "ω₀ = θ/t − ½αt", f"{term(until_angle, 'rad')} / {term(time, 's')} − ½ × {a} × {term(time, 's')}"
        else:
            equation, numbers = "ω₁² = ω₀² + 2αθ  ⇒  ω₀ = ±√(ω₁² − 2αθ)", f"√(({term(until_omega, 'rad/s')})² − 2 × {a} × {term(until_angle, 'rad')})"
        steps.append(Step("Initial angular velocity from the targets", equation, numbers, quantity_text(w0, "rad/s"),
                          "at constant α any three of ω₀, ω₁, α, t, θ give the rest"))
    stop = motion.stop()
    if stop is not None and stop[0] > 0:
        steps.extend(_stop_steps(w0, alpha, stop))
    if time is not None and "theta" in results:
        steps.extend(_after_time_steps(w0, alpha, time, results))
        if "theta_total" in results:
            steps.append(Step("Total angle turned, both ways", "θ_total = |θ_stop| + |θ − θ_stop|",
                              f"{term(abs(stop[1]), 'rad')} + |{term(results['theta'].value, 'rad')} − {term(stop[1], 'rad')}|",
                              quantity_text(results["theta_total"].value, "rad"), "θ is the net angle; after the stop the wheel turns back over part of it"))
        steps.append(_revolutions_step(results))
    elif "t_until" in results and results["t_until"].value is not None:
        t = results["t_until"].value
        if until_omega is not None:
            steps.append(Step("Time to reach ω₁", "t = (ω₁ − ω₀)/α", f"({term(until_omega, 'rad/s')} − {term(w0, 'rad/s')}) / {a}",
                              quantity_text(t, "s"), "constant α: ω changes by the same amount every second"))
            if "theta_until" in results:
                steps.append(_angle_step("Angle turned by then", w0, alpha, t, results["theta_until"].value))
        elif until_angle is not None and "omega" in results:
            omega = results["omega"].value
            steps.append(Step("Angular velocity at the angle", "ω₁² = ω₀² + 2αθ  ⇒  ω₁ = ±√(ω₀² + 2αθ)", f"√(({term(w0, 'rad/s')})² + 2 × {a} × {term(until_angle, 'rad')})",
                              quantity_text(omega, "rad/s"), "the rotational analogue of v² = u² + 2as; its sign is the way the wheel turns then"))
            if w0 + omega:
                steps.append(Step("Time to turn it", "t = 2θ/(ω₀ + ω₁)", f"2 × {term(until_angle, 'rad')} / ({term(w0, 'rad/s')} + {term(omega, 'rad/s')})",
                                  quantity_text(t, "s"), "at constant α the mean speed is the average of the first and the last"))
    return steps


def _uniform_torque(inertia, torques: Torques, motion, end: float | None, results: Results, steps: list[Step], notes: list[str]) -> None:
    """The torque that keeps α constant against the losses, and the energy, work and power."""
    alpha, w0 = motion.alpha, motion.omega0
    sense = 1.0 if w0 > 0 else -1.0 if w0 < 0 else math.copysign(1.0, alpha) if alpha else 0.0
    n = torques.drag_exponent
    f = torques.friction if sense else 0.0

    def losses(omega: float, s: float) -> float:  # the torque of the losses against +ω, moving in sense s
        return s * f + torques.viscous * omega + s * torques.drag * abs(omega) ** n

    net = 0.0 if inertia is None else inertia * alpha
    drive = net + losses(w0, sense)
    if inertia is not None:
        results.put("torque_net", net, "")
        steps.append(Step("Net torque (Newton's second law for rotation)", "τ_net = Iα",
                          f"{quantity_text(inertia, 'kg*m**2')} × {quantity_text(alpha, 'rad/s**2')}", quantity_text(net, "N*m"),
                          "the net torque a constant α takes"))
    held = alpha == 0
    results.put("torque", drive, " that holds ω steady" if held else " that gives this α")
    if f or torques.viscous or torques.drag:
        steps.append(Step("Drive torque", "τ = τ_net + τ_f + bω + kωⁿ" if held else "τ = τ_net + τ_f",
                          f"{quantity_text(net, 'N*m')} + {quantity_text(drive - net, 'N*m')}", quantity_text(drive, "N*m"),
                          "the drive must also overcome the losses, which oppose the motion"))
    stop = motion.stop()
    at = end if end is not None else 0.0
    omega_at = motion.omega(at)
    after = stop is not None and at > stop[0]
    drive_at = net + losses(omega_at, -sense) if after else drive
    if after and f:
        notes.append(f"past the stop friction turns round: holding α takes τ = {quantity_text(drive_at, 'N*m')} from t = {fmt(stop[0])} s on")
    when = f" at t = {fmt(at)} s" if end is not None else " at the start"
    results.put("power", drive_at * omega_at, when)
    if f:
        results.put("power_friction", f * abs(omega_at), when)
    if torques.viscous:
        results.put("power_viscous", torques.viscous * omega_at * omega_at, when)
    if torques.drag:
        results.put("power_drag", torques.drag * abs(omega_at) ** (n + 1), when)
    if inertia is not None:
        results.put("KE0", inertia * w0 * w0 / 2)
    if end is None:
        return
    by = f" by t = {fmt(end)} s"
    if inertia is not None:
        results.put("KE", inertia * omega_at * omega_at / 2, f" at t = {fmt(end)} s")
    theta = motion.theta(end)
    if after:
        work = drive * stop[1] + drive_at * (theta - stop[1])
    else:
        work = drive * theta
    results.put("work_drive", work, by)
    if end > 0:
        results.put("power_mean", work / end, by)
    if f:
        results.put("work_friction", f * motion.path(end), by)
    if torques.viscous:
        results.put("work_viscous", torques.viscous * w0 * w0 * end, by)
    if torques.drag:
        results.put("work_drag", torques.drag * abs(w0) ** (n + 1) * end, by)


# ---------------------------------------------------------------------------------------------
# A motor of constant power (--power): I dω/dt = P/ω − τ_f − bω − kωⁿ.


@dataclass(frozen=True)
class PowerMotion:
    """The motion under a constant power P, in the frame where u = |ω| ≥ 0 (``sense`` = ±1).

    Without losses, ½Iu² grows (or, for P < 0, falls) at the rate P: u² = u₀² + 2Pt/I and
    θ = 2t(u² + uu₀ + u₀²)/(3(u + u₀)), which has no difference of near-equal numbers. With
    losses there is no closed form: u is stepped by the method, from a start just off rest where
    P/u dominates (so the lossless law carries the first ~1e-12 of the energy exactly enough),
    and a load (P < 0) is stopped the same way just before rest.
    """
    inertia: float
    power: float
    torques: Torques
    u0: float
    method: Method
    sense: float

    @property
    def lossless(self) -> bool:
        t = self.torques
        return not (t.friction or t.viscous or t.drag)

    def rate(self, u: float) -> float:
        t = self.torques
        drag = t.drag * u**t.drag_exponent if t.drag and u > 0 else 0.0
        u = max(u, 1e-300)  # finite below rest, so that a trial step past it is rejected, not accepted as NaN
        return (self.power / u - t.friction - t.viscous * u - drag) / self.inertia

    def stiffness(self, u: float) -> float:
        t = self.torques
        drag = t.drag_exponent * t.drag * u ** (t.drag_exponent - 1) if t.drag else 0.0
        return (abs(self.power) / (u * u) + t.viscous + drag) / self.inertia

    def _edge(self) -> float:
        """A speed near rest below which the losses are under 1e-7 of P/u."""
        t, p = self.torques, abs(self.power)
        scales = [p / t.friction if t.friction else math.inf, math.sqrt(p / t.viscous) if t.viscous else math.inf,
                  (p / t.drag) ** (1 / (t.drag_exponent + 1)) if t.drag else math.inf]
        return 1e-7 * min(scales)

    def lossless_state(self, t: float) -> tuple[float, float]:
        u0 = self.u0
        square = u0 * u0 + 2 * self.power * t / self.inertia
        u = math.sqrt(max(square, 0.0))
        return u, (2 * t * (u * u + u * u0 + u0 * u0) / (3 * (u + u0)) if u + u0 else 0.0)

    def stop(self) -> tuple[float, float] | None:
        """(t, θ) where a load brings the wheel to rest (None while P > 0)."""
        if self.power >= 0 or self.u0 == 0:
            return None if self.u0 or self.power >= 0 else (0.0, 0.0)
        if self.lossless:
            t = self.inertia * self.u0 * self.u0 / (2 * -self.power)
            return t, 2 * t * self.u0 / 3
        edge = self._edge()
        if self.u0 <= 2 * edge:  # already where the losses are under 1e-7 of P/ω: the lossless law
            return PowerMotion(self.inertia, self.power, Torques(), self.u0, self.method, self.sense).stop()
        solution = self._run(self.u0, math.inf, edge)
        tail = self.inertia * edge * edge / (2 * -self.power)
        return solution.t + tail, solution.theta + 2 * tail * edge / 3

    def _start(self) -> tuple[float, float, float]:
        """(t, u, θ) to step from: the start, or just off rest on the lossless law."""
        if self.u0 > 0 or self.power <= 0:
            return 0.0, self.u0, 0.0
        edge = self._edge()
        t = self.inertia * edge * edge / (2 * self.power)
        return t, edge, 2 * t * edge / 3

    def _run(self, u: float, t_end: float, event: float | None):

        method = self.method
        name = "rk45" if method.name == "exact" else method.name
        if t_end == math.inf:  # a bound on the time to the event: the energy to go, over the least net power on the way
            span = abs(self.inertia * (event - u) * (event + u) / 2)
            if self.power < 0:
                net = -self.power  # a load drains at least P; the losses only add to it
            else:
                steady = self.steady_speed()
                if steady is not None and event >= steady:
                    return None
                net = event * self.inertia * self.rate(event)  # P − ω·losses(ω), least at the event
            t_end = 1.01 * span / net
        try:
            return numerics.integrate(
                self.rate, u, t_end, name, dt=method.dt, rtol=method.rtol / 20, event_at=event, stiffness=self.stiffness,
            )
        except numerics.TooManySteps:
            raise InputError("rtol" if name == "rk45" else "dt", f"this run needs more than {numerics.MAX_STEPS[name]:,} {name} steps",
                             hint="use a looser --rtol, or a larger --dt") from None

    def state(self, t: float) -> tuple[float, float]:
        """(ω, θ) at t, signed."""
        if self.lossless:
            stop = self.stop()
            if stop is not None and t >= stop[0]:
                return 0.0, self.sense * stop[1]
            u, theta = self.lossless_state(t)
            return self.sense * u, self.sense * theta
        stop = self.stop()
        if stop is not None and t >= stop[0]:
            return 0.0, self.sense * stop[1]
        t0, u0, theta0 = self._start()
        if t <= t0:
            u, theta = PowerMotion(self.inertia, self.power, Torques(), self.u0, self.method, self.sense).lossless_state(t)
            return self.sense * u, self.sense * theta
        solution = self._run(u0, t - t0, None)
        return self.sense * solution.omega, self.sense * (theta0 + solution.theta)

    def time_to(self, target: float) -> tuple[float, float] | None:
        """(t, θ) when |ω| = target, or None."""
        u1 = target * self.sense
        if u1 < 0 or (u1 > self.u0) != (self.power > 0) or u1 == self.u0:
            return (0.0, 0.0) if u1 == self.u0 else None
        if self.lossless:
            t = self.inertia * (u1 - self.u0) * (u1 + self.u0) / (2 * self.power)
            return t, self.sense * self.lossless_state(t)[1]
        if u1 == 0:
            stop = self.stop()
            return None if stop is None else (stop[0], self.sense * stop[1])
        t0, u0, theta0 = self._start()
        solution = self._run(u0, math.inf, u1)
        if solution is None or not solution.event:
            return None
        return t0 + solution.t, self.sense * (theta0 + solution.theta)

    def steady_speed(self) -> float | None:
        """Where P/u balances the losses (P > 0 with losses), by bisection; None otherwise."""
        if self.power <= 0 or self.lossless:
            return None
        return falling_root(self.rate)


def _power_report(inertia, inertia_steps, power, torques: Torques, omega0, *, time, until_omega, until_angle, method, dt, rtol) -> Report:
    """spin-down under a motor of constant power."""
    if torques.drive:
        raise InputError("power", "conflicts with {torque}: the motor's torque is P/ω")
    if until_angle is not None and (time is not None or until_omega is not None):
        raise InputError("until_angle", "conflicts with {time} and {until_omega}: ask for one target at a time (a run each)")
    lossless = not (torques.friction or torques.viscous or torques.drag)
    if method == "exact" and not lossless:
        raise InputError("method", "exact has no closed form for a constant power against losses", hint="use {method} auto or rk45")
    if method in ("euler", "rk4") or method == "rk45":
        chosen = Method(method, dt or (DEFAULT_DT if method != "rk45" else None), rtol or DEFAULT_RTOL)
    else:
        chosen = Method("exact" if lossless else "rk45", None, rtol or DEFAULT_RTOL)
    sense = -1.0 if omega0 < 0 else 1.0
    motion = PowerMotion(inertia, power, torques, abs(omega0), chosen, sense)
    results, notes = Results(TABLE), []
    results.put("I", inertia)
    rate = motion.rate(abs(omega0)) if omega0 else None
    results.put("alpha0", None if rate is None or not math.isfinite(rate) else sense * rate)
    if omega0 == 0:
        notes.append("alpha0 and the torque at the start: none, a constant power from rest asks for an unbounded torque P/ω at ω = 0")
    if power < 0 and omega0 == 0:
        notes.append("a load with the wheel at rest: nothing turns")
    stop = motion.stop()
    results.put("t_stop", None if stop is None else stop[0])
    results.put("theta_stop", None if stop is None else sense * stop[1])
    results.put("revs_stop", None if stop is None else sense * stop[1] / TWO_PI)
    steady = motion.steady_speed()
    results.put("omega_inf", 0.0 if power < 0 else None if steady is None else sense * steady)
    if power > 0 and steady is None:
        notes.append("omega_inf: no steady speed; with no losses the motor's power all goes into the wheel, so ω grows without bound")
    omega_at = omega0
    at = None
    if time is not None:
        omega_at, theta = motion.state(time)
        at = time
        results.put("omega", omega_at, f" at t = {fmt(time)} s")
        results.put("theta", theta, f" by t = {fmt(time)} s")
        results.put("revs", theta / TWO_PI, f" by t = {fmt(time)} s")
    if until_omega is not None:
        reached = motion.time_to(until_omega)
        if reached is None:
            notes.append(f"the wheel never reaches ω = {quantity_text(until_omega, 'rad/s')}")
        results.put("t_until", None if reached is None else reached[0], f" ω = {fmt(until_omega)} rad/s")
        results.put("theta_until", None if reached is None else reached[1], f" ω = {fmt(until_omega)} rad/s")
        if reached is not None:
            at, omega_at = reached[0], until_omega
    if until_angle is not None:
        reached = _power_time_at_angle(motion, until_angle)
        if reached is None:
            notes.append(f"the wheel never reaches θ = {fmt(until_angle)} rad")
        results.put("t_until", None if reached is None else reached[0], f" θ = {fmt(until_angle)} rad")
        results.put("omega", None if reached is None else reached[1], f" at θ = {fmt(until_angle)} rad")
        if reached is not None:
            at, omega_at = reached
    when = " at the start" if at is None else f" at t = {fmt(at)} s"
    results.put("torque", power / omega_at if omega_at else None, when)
    results.put("power", power if omega_at or power > 0 else 0.0, when)
    results.put("KE0", inertia * omega0 * omega0 / 2)
    end = at if at is not None else (stop[0] if stop is not None else None)
    if end is not None:
        omega_end = motion.state(end)[0] if at is None else omega_at
        theta_end = motion.state(end)[1]
        ke = inertia * omega_end * omega_end / 2
        results.put("KE", ke, f" at t = {fmt(end)} s" if at is not None else " at the stop")
        driving_time = min(end, stop[0]) if stop is not None else end
        work = power * driving_time
        by = f" by t = {fmt(end)} s" if at is not None else " until it stops"
        results.put("work_drive", work, by)
        if end > 0:
            results.put("power_mean", work / end, by)
        friction = torques.friction * abs(theta_end)
        if torques.friction:
            results.put("work_friction", friction, by)
        rest = inertia * omega0 * omega0 / 2 - ke + work - friction
        if torques.viscous and torques.drag:

            viscous = torques.viscous * gauss_legendre(lambda t: motion.state(t)[0] ** 2, 0.0, end, panels=16)
            results.put("work_viscous", viscous, by)
            results.put("work_drag", max(0.0, rest - viscous), by)
        elif torques.viscous:
            results.put("work_viscous", max(0.0, rest), by)
        elif torques.drag:
            results.put("work_drag", max(0.0, rest), by)
    steps = list(inertia_steps)
    if lossless:
        steps.append(Step("Energy from a constant power", "½Iω² = ½Iω₀² + Pt  ⇒  t = I(ω₁² − ω₀²)/(2P)", "", "",
                          "a motor of constant power adds energy at the rate P; with no losses it all goes into the wheel"))
        if until_omega is not None and results["t_until"].value is not None:
            steps.append(Step("Time to reach ω₁", "t = I(ω₁ − ω₀)(ω₁ + ω₀)/(2P)",
                              f"{term(inertia, 'kg*m**2')} × ({term(until_omega, 'rad/s')} − {term(omega0, 'rad/s')}) × ({term(until_omega, 'rad/s')} + {term(omega0, 'rad/s')}) / (2 × {term(power, 'W')})",
                              quantity_text(results["t_until"].value, "s"), "the energy ½I(ω₁² − ω₀²) delivered at the rate P"))
        model = "constant power P (τ = P/ω), no losses: ½Iω² grows linearly in time"
    else:
        steps.append(Step("Integrate the equation of motion", "I dω/dt = P/ω − τ_f − bω − kωⁿ,  dθ/dt = ω", chosen.name, "",
                          "no closed form exists for a constant power against these losses"))
        model = "constant power P (τ = P/ω) against losses: no closed form"
    described = {"exact": "closed form", "rk45": f"rk45 (Dormand-Prince, adaptive), rtol = {chosen.rtol:g}"}.get(
        chosen.name, f"{chosen.name}, dt = {fmt(chosen.dt or 0.0)} s"
    )
    steps.extend(_energy_steps(results, inertia, torques.friction, power=power))
    return Report("spin-down", model, described, results, steps, notes, trajectory=deferred(_curves, motion.state, end, stop))


def _power_time_at_angle(motion: PowerMotion, theta: float) -> tuple[float, float] | None:
    """(t, ω) when the wheel under constant power has turned θ: bisection on the motion."""
    distance = theta * motion.sense
    if distance < 0:
        return None
    if distance == 0:
        return 0.0, motion.sense * motion.u0
    stop = motion.stop()
    if stop is not None and distance > stop[1]:
        return None
    low, high = 0.0, None
    if stop is not None:
        high = stop[0]
    else:
        guess = max(distance / motion.u0 if motion.u0 else 0.0, math.sqrt(distance * motion.inertia / max(motion.power, 1e-300)), 1e-9)
        for _ in range(200):
            if abs(motion.state(guess)[1]) >= distance:
                high = guess
                break
            low, guess = guess, 2 * guess
        if high is None:
            return None
    for _ in range(200):
        mid = (low + high) / 2
        if mid in (low, high):
            break
        if abs(motion.state(mid)[1]) < distance:
            low = mid
        else:
            high = mid
    return high, motion.state(high)[0]


def _energy_steps(results: Results, inertia: float, friction: float, power: float | None = None) -> list[Step]:
    """The worked steps of the energy results a run gave (KE, the work of each torque)."""
    steps: list[Step] = []
    value = {name: results[name].value for name in results}
    if value.get("KE0") is not None:
        w0 = math.sqrt(2 * value["KE0"] / inertia)
        steps.append(Step("Kinetic energy at the start", "KE₀ = ½Iω₀²", f"½ × {quantity_text(inertia, 'kg*m**2')} × ({quantity_text(w0, 'rad/s')})²",
                          quantity_text(value["KE0"], "J"), "a wheel on a fixed axle has only rotational kinetic energy"))
    if value.get("KE") is not None:
        w = math.sqrt(2 * value["KE"] / inertia)
        steps.append(Step("Kinetic energy" + results["KE"].label.removeprefix("kinetic energy"), "KE = ½Iω²",
                          f"½ × {quantity_text(inertia, 'kg*m**2')} × ({quantity_text(w, 'rad/s')})²", quantity_text(value["KE"], "J"),
                          "the same, at the end"))
    if value.get("work_drive") is not None:
        if power is not None:
            steps.append(Step("Work of the motor", "W_drive = P·t (while it turns)", f"{quantity_text(power, 'W')} × t", quantity_text(value["work_drive"], "J"),
                              "a constant power delivers the same energy every second"))
        else:
            steps.append(Step("Work of the drive", "W_drive = τθ (the torque times the angle it turns through)", "",
                              quantity_text(value["work_drive"], "J"), "a constant torque does τ of work for every radian turned along it"))
    if value.get("work_friction") is not None and friction:
        steps.append(Step("Energy friction takes", "W_f = τ_f × angle swept", f"{quantity_text(friction, 'N*m')} × {quantity_text(value['work_friction'] / friction, 'rad')}",
                          quantity_text(value["work_friction"], "J"), "friction opposes the motion whichever way it turns, so every radian swept costs τ_f"))
    rest = [name for name in ("work_viscous", "work_drag") if value.get(name) is not None]
    if rest:
        total = sum(value[name] for name in rest)
        steps.append(Step("Energy the viscous torque and drag take", "W_b + W_k = KE₀ − KE + W_drive − W_f", "", quantity_text(total, "J"),
                          "the energy balance: what the wheel had and the drive gave, less what it keeps and what friction took; "
                          "where both act, the viscous share b∫ω²dt is integrated and drag has the rest"))
    return steps


# ---------------------------------------------------------------------------------------------
# Brakes and pressed faces (#24): constant Coulomb torques added to the axle's friction.


def _split_contacts(report: Report, axle: float, contact) -> Report:
    """The report with the friction's work and power shared out by torque among the axle, the
    brakes and the faces: each is a constant torque against the motion, so each takes its
    torque times the same angle swept (and times the same |ω|)."""
    if contact is None or not contact.kinetic:
        return report
    total = axle + contact.kinetic
    results = Results(TABLE)
    steps = list(report.steps)
    for key, value in report.results.items():
        if key not in ("work_friction", "power_friction"):
            results[key] = value
            continue
        kind = key.partition("_")[0]
        part = value.label.partition("takes")[2]
        share = value.value / total  # the angle swept, or |ω|
        if axle:
            results.put(key, axle * share, part)
        for name, torque in (("brake", contact.brake), ("face", contact.face)):
            if torque:
                results.put(f"{kind}_{name}", torque * share, part)
                symbol = "τ_b" if name == "brake" else "τ_face"
                if kind == "work":
                    steps.append(Step(f"Energy the {name}s take", f"W_{name} = {symbol} × angle swept",
                                      f"{quantity_text(torque, 'N*m')} × {quantity_text(share, 'rad')}", quantity_text(torque * share, "J"),
                                      "a constant friction torque against the motion takes its torque for every radian swept"))
                else:
                    steps.append(Step(f"Power the {name}s take", f"P_{name} = {symbol}·|ω|",
                                      f"{quantity_text(torque, 'N*m')} × {quantity_text(share, 'rad/s')}", quantity_text(torque * share, "W"),
                                      "power is torque times angular speed"))
    steps = [replace(step, title="Energy all friction takes (axle, brakes, faces)") if step.title == "Energy friction takes" else step for step in steps]
    return Report(report.scene, report.model, report.method, results, steps, report.notes, report.inputs, report.tables, report.trajectory)


def _contacts(brakes, faces, body_options: dict, rim: float | None, assumed: Assumed, g: float | None, results: Results, steps: list[Step], notes: list[str], axle: float):
    """The brakes' and faces' torques (contact.py), put among the results, steps and notes before the motion."""
    shape_rim = body_rim(body_options)
    options = body_options if shape_rim is not None or rim is None else {**body_options, "shape": "disc", "radius": rim}
    g = assumed.gravity(g) if any(face.force is None for face in faces) else None
    contact = contacts(brakes, faces, options, body_options.get("mass"), g)
    if brakes:
        results.put("torque_brake", contact.brake)
    if faces:
        results.put("torque_face", contact.face)
    steps.extend(contact.steps)
    notes.extend(contact.notes)
    terms = [(symbol, value) for symbol, value in (("τ_axle", axle), ("τ_b", contact.brake), ("τ_face", contact.face)) if value]
    if terms:
        steps.append(Step("Friction torques add", "τ_f = " + " + ".join(symbol for symbol, _ in terms),
                          " + ".join(quantity_text(value, "N*m") for _, value in terms), quantity_text(axle + contact.kinetic, "N*m"),
                          "each is a constant torque against the motion, so together they act as one friction torque τ_f"))
    return contact


def _with_contacts(report: Report, contact) -> Report:
    """The model line names the brakes' and faces' friction models."""
    if contact is None or not contact.models:
        return report
    return Report(report.scene, f"{report.model}; {', '.join(contact.models)}", report.method, report.results, report.steps,
                  report.notes, report.inputs, report.tables, report.trajectory)


# ---------------------------------------------------------------------------------------------
# A point at radius r (--at, #24): its speed, accelerations and the arc it has travelled.


def _alpha_at(report: Report, torques: Torques, inertia: float | None, power: float | None, omega: float) -> float | None:
    """α at angular velocity ω: the constant α where there is one, else Newton's second law with
    the torques at that ω (friction against the motion; at rest, static friction holds what it can)."""
    if "alpha" in report.results and report.results["alpha"].value is not None and power is None:
        return report.results["alpha"].value
    if inertia is None:
        return None
    sense = (omega > 0) - (omega < 0)
    if power is not None:
        if omega == 0:
            return None
        drive = power / omega
    else:
        drive = torques.drive
    if sense == 0:
        if abs(drive) <= torques.holding:
            return 0.0
        return (drive - math.copysign(torques.friction, drive)) / inertia
    losses = sense * torques.friction + torques.viscous * omega + sense * torques.drag * abs(omega) ** torques.drag_exponent
    return (drive - losses) / inertia


def _point(report: Report, r: float, torques: Torques, inertia, power, omega0, *, time, until_omega, until_angle) -> Report:
    """The report with the results of a point at radius r, at --time or the target, else the start."""
    values = {key: value.value for key, value in report.results.items()}
    results = Results(TABLE)
    results.update(report.results)
    notes = list(report.notes)
    w0 = values.get("omega0")
    w0 = w0 if w0 is not None else (omega0 or 0.0)
    alpha0 = values.get("alpha0")
    if alpha0 is None:
        alpha0 = _alpha_at(report, torques, inertia, power, w0)
    if time is not None:
        when, omega, theta = f" at t = {fmt(time)} s", values.get("omega"), values.get("theta")
    elif until_angle is not None:
        when, omega, theta = " at the target angle", values.get("omega"), until_angle if values.get("omega") is not None else None
    elif until_omega is not None:
        when, omega, theta = " at the target speed", until_omega if values.get("theta_until") is not None else None, values.get("theta_until")
    else:
        when, omega, theta = " at the start", w0, 0.0
    later = when != " at the start"
    steps = list(report.steps)
    if omega is None:
        steps += put_point(results, r, None, None, None, when, notes)
        notes[-1] = f"{', '.join(KEYS)}: the wheel does not reach the target, so there is no such instant"
    else:
        alpha = _alpha_at(report, torques, inertia, power, omega) if later else alpha0
        steps += put_point(results, r, omega, alpha, theta, when, notes)
        if alpha is None:
            notes[-1] = "a_t, a_total, a_angle: α is not defined at this instant (a constant power at rest)"
    if later:
        put_start(results, r, w0, alpha0)
    return Report(report.scene, report.model, report.method, results, steps, notes, report.inputs, report.tables, report.trajectory)
