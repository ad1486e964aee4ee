"""What the models of spin-down share: the torques, and the worked
steps of constant-α kinematics (the stop, ω and θ at t, the turn back after a stop).

    τ_net = τ_drive − τ_f − bω − kωⁿ,  α = τ_net/I,  t_stop = ω₀/|α|,  θ = ω₀t + ½αt²
"""

from __future__ import annotations

import math

from taucli.writing.report import Step, Trajectory, fmt, quantity_text, term
from taucli.scenes.motion import Loads
from taucli.options.table import Results

Torques = Loads  # for a wheel the loads are torques: drive, friction, viscous b, drag k
TWO_PI = 2 * math.pi


def net_torque_steps(torques: Torques, omega0: float, alpha0: float, inertia: float, held: bool) -> tuple[Step, Step]:
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


def put_angles(results: Results, theta: float, turned_back_at: float | None, time: float) -> None:
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


def stop_steps(w0: float, alpha: float, stop: tuple[float, float]) -> list[Step]:
    """t_stop = ω₀/|α| and θ_stop = ω₀²/(2|α|): constant α against the motion."""
    return [
        Step("Time to stop", "ω = ω₀ + αt = 0  ⇒  t = ω₀/|α|", f"{term(abs(w0), 'rad/s')} / {term(abs(alpha), 'rad/s**2')}",
             quantity_text(stop[0], "s"), "constant torque gives constant α, so ω falls linearly to zero"),
        Step("Angle turned while stopping", "θ = ω₀²/(2|α|)", f"({term(abs(w0), 'rad/s')})² / (2 × {term(abs(alpha), 'rad/s**2')})",
             quantity_text(abs(stop[1]), "rad") + f" = {fmt(abs(stop[1]) / TWO_PI)} rev", "the rotational analogue of v² = 2as"),
    ]


def angle_step(title: str, omega0: float, alpha: float, time: float, theta: float) -> Step:
    """θ = ω₀t + ½αt²: the net angle, which holds through a turn back at constant α."""
    return Step(title, "θ = ω₀t + ½αt²", f"{term(omega0, 'rad/s')} × {term(time, 's')} + ½ × {term(alpha, 'rad/s**2')} × ({term(time, 's')})²",
                quantity_text(theta, "rad"), "the rotational analogue of s = ut + ½at²")


def after_time_steps(omega0: float, alpha: float, time: float, results: Results) -> list[Step]:
    """ω = ω₀ + αt and θ = ω₀t + ½αt² at t."""
    return [
        Step("Angular velocity after t", "ω = ω₀ + αt", f"{term(omega0, 'rad/s')} + {term(alpha, 'rad/s**2')} × {term(time, 's')}",
             quantity_text(results["omega"].value, "rad/s"), "constant α: ω changes by the same amount every second"),
        angle_step("Angle turned in t", omega0, alpha, time, results["theta"].value),
    ]


def revolutions_step(results: Results) -> Step:
    return Step("Convert to revolutions", "revs = θ / 2π", f"{term(results['theta'].value, 'rad')} / 2π",
                f"{fmt(results['revs'].value)} rev", "one full revolution is 2π radians")


def turned_back_steps(torques, inertia: float, second, stop, results, time: float) -> list[Step]:
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


def curves(state, end: float | None, stop: tuple[float, float] | None) -> Trajectory:
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
