"""Energy and work on a wheel: KE = ½Iω², the work of the drive and of each loss, and their power.

In each stretch of motion one way, I dω/dt = A − bω − kωⁿ with A = ±τ_drive − τ_f; times ω and
integrated, ½I(ω_b² − ω_a²) = A·d − W_viscous − W_drag over the distance d turned.
"""

from __future__ import annotations

import math

from taucli.numerics.quadrature import gauss_legendre
from taucli.writing.report import Step, fmt, quantity_text
from taucli.scenes.motion import Evolver, Phase
from taucli.scenes.spin.steps import Torques
from taucli.options.table import Results


def put_energy(motion, inertia: float, torques: Torques, omega0: float, time: float | None, results: Results, notes: list[str],
               target: tuple[float | None, float | None, str] | None = None) -> None:
    """KE0, and KE with the work of the drive and of each loss up to --time, else up to the target
    (--until-omega, --until-angle), else to the stop; and the power of each then (else at the start).
    ``target`` is (the time it is reached, or None; ω there where it is given exactly; its words).

    In each stretch of motion one way (a phase, ω ≥ 0 in its frame) I dω/dt = A − bω − kωⁿ with
    A = ±τ_drive − τ_f; times ω and integrated, ½I(ω_b² − ω_a²) = A·d − W_viscous − W_drag over
    the distance d. So the drive does ±τ_drive·d, friction takes τ_f·d, and the viscous and drag
    losses together take the rest; where both act, the viscous one is integrated (b∫ω²dt by
    8-point Gauss-Legendre on the motion) and drag takes what remains. ω_b − ω_a is the motion's
    own change (Evolver.advance), and each loss is its own integral where the rest would be a
    difference of far larger terms, or the motion is stepped at a fixed step (#42 item 8).
    """
    n = torques.drag_exponent
    results.put("KE0", inertia * omega0 * omega0 / 2)
    stop = motion.stop
    if time is None and target is not None:
        reached, omega_there, words = target
        if reached is None:
            notes.append(f"KE, work and power at the target: the wheel never reaches {words}")
            return
        time, at_words, by_words = reached, f" at {words}", f" until {words}"
    else:
        omega_there, at_words, by_words = None, (None if time is None else f" at t = {fmt(time)} s"), (None if time is None else f" by t = {fmt(time)} s")
    end = time if time is not None else (stop[0] if stop is not None and not motion.held_from_start else None)
    if end is not None:
        omega_end = (omega_there if omega_there is not None else motion.state_at(end)[0]) if time is not None else 0.0
        results.put("KE", inertia * omega_end * omega_end / 2, " at the stop" if time is None else at_words)
    at = 0.0 if time is None else time
    omega_at = omega_there if omega_there is not None else motion.state_at(at)[0]
    when = " at the start" if time is None else at_words
    if torques.drive:
        results.put("power", torques.drive * omega_at + 0.0, when)  # + 0.0: at rest 0, not −0
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
    by = by_words if time is not None else " until it stops"
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
            finish, distance, speed_change = 0.0, stop[1], -start
        else:
            finish, distance, speed_change = motion.evolver.advance(phase, duration)
        drive = phase.direction * torques.drive
        work["drive"] += drive * distance
        work["friction"] += torques.friction * distance
        gained = (drive - torques.friction) * distance
        # ½I(ω_b² − ω_a²) with ω_b − ω_a the motion's own change, not the difference of two speeds
        # that a heavy wheel's small torque hardly parts (#42 item 8)
        change = inertia * speed_change * (finish + start) / 2
        rest = gained - change
        # a loss much smaller than the work and the change of KE it is the difference of loses its
        # digits there (#42 item 8): it is then its own integral, b∫ω²dt or k∫|ω|ⁿ⁺¹dt, over the motion;
        # so is every loss of a fixed step's motion, whose θ carries the method's own error (euler's
        # ½hΔω, unchecked by any tolerance), which the balance would hand to the loss magnified by
        # the drive's work over it (rk45 holds θ to its rtol; the closed form's θ is exact)
        cancels = motion.evolver.method.name in ("euler", "rk4") or abs(rest) < 1e-2 * max(abs(gained), abs(change))
        if torques.viscous and torques.drag:
            sampler = _phase_sampler(motion.evolver, phase)
            viscous = torques.viscous * gauss_legendre(lambda t: sampler(t) ** 2, 0.0, duration)
            work["viscous"] += viscous
            if cancels:
                sampler = _phase_sampler(motion.evolver, phase)
                work["drag"] += torques.drag * gauss_legendre(lambda t: abs(sampler(t)) ** (n + 1), 0.0, duration)
            else:
                work["drag"] += max(0.0, rest - viscous)
        elif torques.viscous:
            work["viscous"] += _loss_integral(motion.evolver, phase, duration, torques.viscous, 2.0) if cancels else max(0.0, rest)
        elif torques.drag:
            work["drag"] += _loss_integral(motion.evolver, phase, duration, torques.drag, n + 1) if cancels else max(0.0, rest)
    if torques.drive:
        results.put("work_drive", work["drive"], by)
        if end > 0:
            results.put("power_mean", work["drive"] / end, by)
    for name in ("friction", "viscous", "drag"):
        if getattr(torques, name):
            results.put("work_" + name, work[name], by)


def _loss_integral(evolver: Evolver, phase: Phase, duration: float, coefficient: float, power: float) -> float:
    """The work a speed-law loss c|ω|ᵖ takes over a phase, c∫|ω|ᵖ dt on the motion (≥ 0)."""
    sampler = _phase_sampler(evolver, phase)
    return coefficient * gauss_legendre(lambda t: abs(sampler(t)) ** power, 0.0, duration)


def _phase_sampler(evolver: Evolver, phase: Phase):
    """ω(t) within a phase, for times asked in increasing order (a stepper steps on)."""
    last = [None]

    def omega(t: float) -> float:
        state = evolver.state(phase, t, last[0])
        last[0] = (t, *state)
        return state[0]

    return omega


def energy_steps(results: Results, inertia: float, friction: float, power: float | None = None) -> list[Step]:
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
