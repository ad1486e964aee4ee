"""Rotation at a constant α (--alpha, or targets with no body): the kinematics of kinematics.py,
and with a body the torque that holds α against the losses, with its energy, work and power.

    ω = ω₀ + αt,  θ = ω₀t + ½αt²,  ω₁² = ω₀² + 2αθ;  τ = Iα + τ_f (+ bω + kωⁿ where α = 0)
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from taucli.core.errors import InputError
from taucli.writing.report import Report, Step, deferred, fmt, quantity_text, term
from taucli.scenes.spin.energy import energy_steps
from taucli.scenes.spin.kinematics import Uniform, solve_unknowns
from taucli.scenes.spin.steps import (
    TWO_PI,
    Torques,
    after_time_steps,
    angle_step,
    curves,
    put_angles,
    revolutions_step,
    stop_steps,
)
from taucli.options.table import Results


def constant_alpha_report(
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
        put_angles(results, motion.theta(end), stop[1] if stop is not None and end > stop[0] else None, end)
        if time is None:
            results.put("t_until", end, " the target")
    else:
        if until_omega is not None and until_angle is not None:
            raise InputError("until_angle", "conflicts with {until_omega}: ask for one target at a time")
        if time is not None:
            end = time
            results.put("omega", motion.omega(time), f" at t = {fmt(time)} s")
            put_angles(results, motion.theta(time), stop[1] if stop is not None and time > stop[0] else None, time)
        if until_omega is not None:
            t = motion.time_to_omega(until_omega)
            if t is None:
                notes.append(f"the wheel never reaches ω = {quantity_text(until_omega, 'rad/s')} at this α")
            elif stop is not None and t > stop[0]:
                notes.append(f"ω = {quantity_text(until_omega, 'rad/s')} is reached only after the wheel has stopped and turned back")
            results.put("t_until", t, f" ω = {fmt(until_omega)} rad/s")
            results.put("theta_until", None if t is None else motion.theta(t), f" ω = {fmt(until_omega)} rad/s")
            if time is None:
                end = t  # the energy, power and work at the target
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
        steps.extend(energy_steps(results, inertia, torques.friction))
    trajectory = deferred(curves, lambda t: (motion.omega(t), motion.theta(t)), end, stop)
    return Report("spin-down", model, "closed form", results, steps, notes, trajectory=trajectory)


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
        steps.extend(stop_steps(w0, alpha, stop))
    if time is not None and "theta" in results:
        steps.extend(after_time_steps(w0, alpha, time, results))
        if "theta_total" in results:
            steps.append(Step("Total angle turned, both ways", "θ_total = |θ_stop| + |θ − θ_stop|",
                              f"{term(abs(stop[1]), 'rad')} + |{term(results['theta'].value, 'rad')} − {term(stop[1], 'rad')}|",
                              quantity_text(results["theta_total"].value, "rad"), "θ is the net angle; after the stop the wheel turns back over part of it"))
        steps.append(revolutions_step(results))
    elif "t_until" in results and results["t_until"].value is not None:
        t = results["t_until"].value
        if until_omega is not None:
            steps.append(Step("Time to reach ω₁", "t = (ω₁ − ω₀)/α", f"({term(until_omega, 'rad/s')} − {term(w0, 'rad/s')}) / {a}",
                              quantity_text(t, "s"), "constant α: ω changes by the same amount every second"))
            if "theta_until" in results:
                steps.append(angle_step("Angle turned by then", w0, alpha, t, results["theta_until"].value))
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
