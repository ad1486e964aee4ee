"""The torque laws: I dω/dt = τ_drive − τ_f·sgn(ω) − bω − k|ω|ⁿ·sgn(ω).

Each stretch of motion in one direction is a phase with ω ≥ 0 in its own frame (taucli.scenes.
motion). Closed forms (closed_forms.py) serve every combination with n = 2; a power-law drag with
another exponent has none and is integrated (numerics.py), with the stop located as an event, so
that Coulomb friction stops the wheel and holds it rather than chattering about ω = 0.
"""

from __future__ import annotations

import math

from collections.abc import Sequence

from taucli.core.errors import InputError
from taucli.options.spin_down import COMMAND as TABLE
from taucli.writing.report import (
    DeferredSteps,
    Report,
    Step,
    Trajectory,
    Value,
    deferred,
    fmt,
    quantity_text,
    term,
)
from taucli.scenes.motion import Evolver, Method, Phase, evolve
from taucli.scenes.spin.energy import energy_steps, put_energy
from taucli.scenes.spin.methods import (
    REFERENCE_RTOL,
    choose_method,
    error_estimate,
    method_answers,
)
from taucli.scenes.spin.steps import (
    TWO_PI,
    Torques,
    after_time_steps,
    net_torque_steps,
    put_angles,
    revolutions_step,
    stop_steps,
    turned_back_steps,
)
from taucli.options.table import Results


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
    if torques.friction:
        return "uniform deceleration (constant friction torque)"
    return "no torque: the wheel keeps its angular velocity (τ_net = 0, α = 0)"


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
    drive_steps: Sequence[Step] = (),
    inertia_steps: Sequence[Step] = (),
    estimate_error: bool = True,
    energy: bool = False,
) -> Report:
    """Spin-down or spin-up of a wheel on a fixed axle; see the module docstring for the model.

    A fixed-step method (euler, rk4) has each answer's error estimated against a reference (the
    ``error_estimate`` table); an answer estimated more than 1e-3 off is withheld, null, with a
    note. ``estimate_error=False`` leaves that out (the bench times the method alone). ``energy``
    adds KE, the work of each torque and the power."""
    if torques.drag and not 0 < torques.drag_exponent <= 10:
        raise InputError("drag_exponent", "expected a number above 0 and at most 10", example="{drag_exponent} 1.5", got=fmt(torques.drag_exponent))
    linear_drag = torques.drag if torques.drag and torques.drag_exponent == 1 else 0.0
    if linear_drag:  # kω is a viscous torque: the motion takes b + k together; the energy is shared back out below
        torques = Torques(torques.drive, torques.friction, torques.viscous + linear_drag, 0.0, 2.0, torques.static)
    if until_angle is not None and (time is not None or until_omega is not None):
        raise InputError("until_angle", "conflicts with {time} and {until_omega}: ask for one target at a time (a run each)")
    closed_form = torques.drag == 0 or torques.drag_exponent == 2
    chosen = choose_method(method, closed_form, dt, rtol)
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
    # a drive (or no torque at all) keeps it turning: nothing can stop it, so the stop does not apply
    kept_turning = not held_from_start and stop is None and not first.stops and (first.closed.constant > 0 or not (torques.viscous or torques.drag))
    omega_inf = motion.final_speed()
    if kept_turning:
        notes.append(_kept_turning_note(torques, first, motion.initial_rate * motion.direction > 0, omega_inf is None))
    elif stop is None and not first.stops and not held_from_start:  # (a stop that a stepper blew up before finding is said below)
        notes.append(_never_stops_note(torques, first))
    answers = method_answers(motion, time, until_omega, until_angle)
    if kept_turning:
        results.not_applicable("t_stop", "theta_stop", "revs_stop")
    else:
        results.put("t_stop", answers["t_stop"])
        results.put("theta_stop", answers["theta_stop"])
        results.put("revs_stop", None if answers["theta_stop"] is None else answers["theta_stop"] / TWO_PI)

    if omega_inf is None:  # ω grows without bound: no steady speed to have
        if not kept_turning:
            notes.append("omega_inf: no steady speed; the driving torque is not balanced by drag, so ω grows without bound")
        results.not_applicable("omega_inf")
    else:
        results.put("omega_inf", omega_inf)
    if torques.viscous or torques.drag:  # losses that grow with speed and a drive that does not: the net torque falls as ω rises
        results.put("stable", None if omega_inf is None else True)

    if time is not None:
        omega_t, theta_t = answers["omega"], answers["theta"]
        results.put("omega", omega_t, f" at t = {fmt(time)} s")
        put_angles(results, theta_t, answers["theta_stop"] if second is not None and stop is not None and time > stop[0] else None, time)
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
        target = None
        if until_omega is not None:
            target = (answers["t_until"], until_omega, f"ω = {fmt(until_omega)} rad/s")
        elif until_angle is not None:
            target = (answers["t_until"], None, f"θ = {fmt(until_angle)} rad")
        put_energy(motion, inertia, torques, omega0, time, results, notes, target)
        if linear_drag:
            _share_linear_drag(results, torques.viscous - linear_drag, linear_drag)
    if evolver.unstable:
        notes.extend(dict.fromkeys(evolver.unstable))
        for name in results:
            if name not in ("I", "alpha0"):
                results[name] = Value(None, results[name].unit, results[name].label)
    elif chosen.name in ("euler", "rk4") and estimate_error:
        against = "the closed form" if closed_form else f"rk45 at rtol {REFERENCE_RTOL:g}"
        try:
            reference = solve(inertia, torques, omega0, time=time, until_omega=until_omega, until_angle=until_angle, method="exact" if closed_form else "rk45",
                              rtol=REFERENCE_RTOL, estimate_error=False, energy=energy).results
        except InputError:
            reference = None
        estimate = error_estimate(results, reference, against, chosen, notes)
        if estimate is not None:
            tables["error_estimate"], worst = estimate
            described += f"; estimated error at most {fmt(worst, 2)} relative" if worst is not None else ""

    steps = DeferredSteps(_steps, inertia_steps, drive_steps, torques, omega0, alpha0, inertia, motion, dict(results), time, until_angle, chosen)
    if chosen.name != "exact" and method == "auto":
        notes.append(f"no closed form for drag kω^{fmt(torques.drag_exponent)} with these torques: integrated numerically")
    model = _model(torques, chosen)
    if held_from_start or (stop is not None and second is None):
        model += "; static friction holds it once stopped" if not held_from_start else "; held at rest by static friction"
    trajectory = None if evolver.unstable else deferred(_trajectory, motion, time, omega_inf)
    return Report("spin-down", model, described, results, steps, notes, tables=tables, trajectory=trajectory)


def _share_linear_drag(results: Results, viscous: float, drag: float) -> None:
    """The work and power of b + k together (a drag kω with n = 1 is a viscous torque) shared out
    between them by coefficient: both are the same ∫ω² dt and ω², times b or k."""
    for kind in ("work", "power"):
        joint = results.pop(f"{kind}_viscous", None)
        if joint is None:
            continue
        part = joint.label.partition("takes")[2]
        share = None if joint.value is None else joint.value / (viscous + drag)
        if viscous:
            results.put(f"{kind}_viscous", None if share is None else viscous * share, part)
        results.put(f"{kind}_drag", None if share is None else drag * share, part)


def _steps(inertia_steps, drive_steps: Sequence[Step], torques: Torques, omega0: float, alpha0: float, inertia: float, motion, results: dict,
           time: float | None, until_angle: float | None, chosen: Method) -> list[Step]:
    """The worked solution: the body, the drive (a push), τ_net and α at the start, then the motion's
    kinematics (the stop, ω and θ at t, the time to an angle) and the energy."""
    steps = [*inertia_steps, *drive_steps]
    steps.extend(net_torque_steps(torques, omega0, alpha0, inertia, motion.held_from_start))
    if not motion.held_from_start:
        steps.extend(_kinematics_steps(torques, motion.first, motion.second, motion.stop, results, time, chosen, omega0))
        if until_angle is not None and results["t_until"].value is not None:
            steps.append(Step("Time to turn θ", "θ(t) = θ_target, solved for t", f"θ_target = {quantity_text(until_angle, 'rad')}",
                              f"t = {quantity_text(results['t_until'].value, 's')}, ω = {quantity_text(results['omega'].value, 'rad/s')}",
                              "θ grows with t while the wheel turns one way, so the time is bracketed and found by bisection on θ(t)"))
    steps.extend(energy_steps(results, inertia, torques.friction))
    return steps


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


def _kept_turning_note(torques: Torques, phase: Phase, speeding_up: bool, unbounded: bool) -> str:
    """The one note for a wheel nothing can stop, in place of the rows of its stop (and of a
    steady speed it never reaches): JSON keeps them null, the human views leave them out."""
    if phase.closed.constant <= 0:
        why = "no net torque, so ω stays constant and the wheel never stops"
    else:
        drive = "the driving torque exceeds friction" if torques.friction else "the driving torque keeps it turning"
        why = f"{'it speeds up: ' if speeding_up else ''}{drive}, so the wheel never stops"
    words = f"{why} and t_stop, theta_stop, revs_stop do not apply"
    if unbounded:
        words += "; nor has it a steady speed (no drag balances the drive, so ω grows without bound): omega_inf does not apply either"
    return words


def _never_stops_note(torques: Torques, phase: Phase) -> str:
    if torques.viscous or torques.drag:
        return "t_stop: drag alone slows the wheel ever more gently and never quite stops it"
    return "t_stop: the wheel never stops"


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
            steps.extend(stop_steps(w0, alpha, stop))
        back = second is not None and stop is not None and time is not None and time > stop[0]
        if time is not None and results["theta"].value is not None and not back:
            steps.extend(after_time_steps(omega0, alpha, time, results))
        elif back and results["theta"].value is not None:
            steps.extend(turned_back_steps(torques, results['I'].value, second, stop, results, time))
        if time is not None and results["theta"].value is not None:
            steps.append(revolutions_step(results))
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


def drive_for_target(inertia, torques: Torques, omega0, in_time, until_omega, until_angle, method, dt, rtol, in_angle=None) -> Torques:
    """The constant drive with which the wheel is at ω₁ (or has turned θ) at t, or (``in_angle``)
    is at ω₁ when it has turned that angle: ω(t), θ(t) and ω(θ) grow with the drive (a wheel that
    stops short of the angle is below any ω₁ ≥ 0), so bisection brackets it; to the last bit."""
    closed_form = torques.drag == 0 or torques.drag_exponent == 2
    evolver_method = choose_method(method, closed_form, dt, rtol)

    def miss(drive: float) -> float:
        trial = Torques(drive, torques.friction, torques.viscous, torques.drag, torques.drag_exponent)
        motion = evolve(inertia, trial, omega0, Evolver(evolver_method))
        if in_angle is not None:
            reached = motion.reach_angle(in_angle)
            if reached is None:  # stopped short: too little drive turning forward, too much turning back
                return -math.inf if in_angle > 0 else math.inf
            return reached[1] - until_omega
        omega, theta = motion.state_at(in_time)
        return omega - until_omega if until_omega is not None else theta - until_angle

    if in_angle is not None:
        in_time = 2 * abs(in_angle) / max(abs(omega0) + abs(until_omega), 1e-300)  # the time at the mean speed, a scale
    target = until_omega if until_omega is not None else until_angle
    scale = max(abs(target) / in_time, abs(omega0), abs(until_omega or 0.0), 1.0)
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
    if in_angle is not None:  # a bracket across a jump (a wheel that never gets there on one side) is no answer
        missed = min(abs(miss(low)), abs(miss(high)))  # a target of rest is met from one side only (the other stops short)
        if not missed <= 1e-6 * max(abs(until_omega), abs(omega0)):
            raise InputError("in_angle", "cannot be reached by any constant drive with these losses: no drive brings the wheel to {until_omega} "
                             "once it has turned this angle", example="{omega0} -300rpm {until_omega} -100rpm {in_angle} -10rev")
    return Torques((low + high) / 2, torques.friction, torques.viscous, torques.drag, torques.drag_exponent)
