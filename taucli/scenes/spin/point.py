"""A point at radius r on the wheel (--at): its speed and accelerations at --time or the target,
else at the start (taucli.scenes.point), with α from the torques at that instant.
"""

from __future__ import annotations

import math

from taucli.options.spin_down import COMMAND as TABLE
from taucli.writing.report import Report, fmt
from taucli.scenes.motion import Evolver, Method, evolve
from taucli.scenes.point import KEYS, put_point, put_start
from taucli.scenes.spin.steps import Torques
from taucli.options.table import Results


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


def _alpha_at_time(report: Report, torques: Torques, inertia: float | None, power: float | None, omega0: float, t: float) -> float | None:
    """α at time t under the torque laws from the closed form's phase variable, exact to its last
    digits near a steady speed (where τ − bω(t) − kω(t)² would cancel); None elsewhere."""
    if inertia is None or power is not None or "alpha" in report.results or report.method != "closed form":
        return None
    if torques.drag and torques.drag_exponent == 1:  # kω is a viscous torque, as the torque laws take it
        torques = Torques(torques.drive, torques.friction, torques.viscous + torques.drag, 0.0, 2.0, torques.static)
    return evolve(inertia, torques, omega0, Evolver(Method("exact"))).rate_at(t)


def with_point(report: Report, r: float, torques: Torques, inertia, power, omega0, *, time, until_omega, until_angle,
               rim: tuple[float | None, float | None, float | None, float | None] = (None, None, None, None)) -> Report:
    """The report with the results of a point at radius r, at --time or the target, else the start.
    ``rim`` = (R, --rim-speed, --rim-accel, --until-arc), each None where not given: a point at the
    rim moves at the rim speed given, accelerates at the rim acceleration given and has run the arc
    given, exactly (not v/R times R: #42 item 22)."""
    rim_r, rim_speed, rim_accel, arc = rim
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
        reached = values.get("t_until") is not None
        theta = values.get("theta_until") if values.get("theta_until") is not None else values.get("theta")
        when, omega = " at the target speed", until_omega if reached else None
    else:
        when, omega, theta = " at the start", w0, 0.0
    later = when != " at the start"
    steps = list(report.steps)
    if omega is None:
        steps += put_point(results, r, None, None, None, when, notes)
        notes[-1] = f"{', '.join(KEYS)}: the wheel does not reach the target, so there is no such instant"
    else:
        alpha = _alpha_at_time(report, torques, inertia, power, w0, time) if time is not None else None
        if alpha is None:
            alpha = _alpha_at(report, torques, inertia, power, omega) if later else alpha0
        string = None  # the rim's own speed, acceleration and arc where they were given
        if rim_r is not None and (rim_speed is not None or rim_accel is not None or arc is not None):
            speed = rim_speed if not later and rim_speed is not None else omega * rim_r
            if later and until_angle is not None and arc is not None:
                run = arc
            else:
                run = None if theta is None else theta * rim_r
            string = (rim_r, speed, rim_accel, run)
        steps += put_point(results, r, omega, alpha, theta, when, notes, string)
        if alpha is None:
            notes[-1] = "a_t, a_total, a_angle: α is not defined at this instant (a constant power at rest)"
    if later:
        put_start(results, r, w0, alpha0, None if rim_r is None or rim_speed is None else (rim_r, rim_speed))
    return Report(report.scene, report.model, report.method, results, steps, notes, report.inputs, report.tables, report.trajectory)
