"""The pendulum's answer with a friction couple at its pivot (--pivot-friction), as a worked
solution: the torque at the start less the couple gives α₀; energy less the couple's work τ_f|Δθ|
gives ω at the bottom and at --angle and where it turns; the times are stepped leg by leg
(rough.py). The pivot's force and a point at --at use α with the couple in it.
"""

from __future__ import annotations

import math

from taucli.core.errors import InputError
from taucli.numerics import steppers as numerics
from taucli.options.pendulum import COMMAND as TABLE
from taucli.options.pendulum import COMPONENTS
from taucli.options.table import Results
from taucli.scenes.pendulum.motion import put_state, trajectory
from taucli.scenes.pendulum.pivot import put_pivot
from taucli.scenes.pendulum.point import put_point
from taucli.scenes.pendulum.rough import RTOL, Rough
from taucli.scenes.pendulum.swing import Swing, sine
from taucli.scenes.pendulum.zero import Zero
from taucli.writing.report import DeferredSteps, Report, Step, deferred, fmt, quantity_text

TIMED = ("t_bottom", "t_angle", "theta")


def rough_report(body, swing: Swing, gravity: float, friction: float, method: str | None, rtol: float | None,
                 angle: float | None, time: float | None, at: float | None, components: bool, body_words: str, zero: Zero) -> Report:
    """Every result the couple leaves: α₀, ω at the bottom and at --angle, the turning angle and
    rise, the times, θ and ω at --time, the pivot's force; no period (the swing dies away)."""
    if method not in (None, "auto", "rk45"):
        raise InputError("method", "with {pivot_friction} the motion is stepped leg by leg by rk45: expected auto or rk45", example="{method} rk45")
    model = Rough(swing, friction, rtol or RTOL)
    results = Results(TABLE)
    notes: list[str] = []
    results.put("I", swing.inertia)
    if swing.gravity_torque:
        results.put("cm_distance", body.cm_distance)
    alpha0 = model.alpha(swing.theta0, swing.omega0)
    results.put("alpha0", abs(alpha0))
    if swing.omega0 == 0 and model.holds(swing.theta0):
        notes.append(f"the couple holds the body where it starts: the torque there, {quantity_text(abs(model.drive(swing.theta0)), 'N*m')}, "
                     f"is no more than τ_f = {quantity_text(friction, 'N*m')}; it does not move")
    try:
        _put_motion(results, notes, model, body.cm_distance, angle, time, zero)
    except numerics.TooManySteps:
        notes.append(f"rk45 at rtol = {fmt(model.rtol)} did not find where the body first comes to rest within its steps "
                     "(it creeps, or goes over the top many times): what comes after is left out")
        moving = ("omega_bottom", "KE_bottom", "amplitude", "t_bottom") + ("rise", "goes_over", "omega0_over") * bool(swing.gravity_torque)
        for key in moving + ("omega", "t_angle") * (angle is not None) + ("theta", "omega") * (time is not None):
            if key not in results or key in ("goes_over", "omega"):
                results.put(key, None)
    results.put("period_small", swing.small_period())
    results.not_applicable("period")
    notes.append("period: none: the couple takes τ_f|Δθ| of energy on every swing, so the swing dies away; "
                 "period_small is that of small swings without the couple")
    alphas = {"start": alpha0}
    bottom = results["omega_bottom"].value
    if bottom is not None:
        alphas["bottom"] = model.alpha(0.0, model.velocity_at(0.0))
    speed_at_angle = None
    if angle is not None and results["omega"].value is not None:
        speed_at_angle = abs(results["omega"].value)
        alphas["angle"] = model.alpha(angle, results["omega"].value)
    put_pivot(results, swing, body.mass, body.cm_distance, gravity, angle, speed_at_angle, zero, alphas=alphas)
    if not components:
        for key in COMPONENTS:
            results.pop(key, None)
    steps = DeferredSteps(_worked_steps, model, body.steps, body.mass, body.cm_distance, gravity, dict(results), zero)
    report = Report(
        "pendulum",
        f"{body_words} on a pivot under {_drive_words(swing)}, with a friction couple of {quantity_text(friction, 'N*m')} at the pivot",
        f"energy less the couple's work, leg by leg; times by rk45 (rtol = {fmt(model.rtol)})",
        results, steps, notes,
        trajectory=deferred(_trajectory, Rough(swing, friction, model.rtol), time, results["t_bottom"].value, zero),
    )
    if at is not None:
        put_point(report, swing, at, angle, gravity, zero, accel=model.alpha)
    return report


def _put_motion(results: Results, notes: list[str], model: Rough, cm_distance: float, angle, time, zero: Zero) -> None:
    swing = model.swing
    bottom = model.velocity_at(0.0)
    results.put("omega_bottom", None if bottom is None else abs(bottom))
    if bottom is None and not (swing.omega0 == 0 and model.holds(swing.theta0)):
        notes.append("omega_bottom: none: the body comes to rest before it reaches the bottom, and the couple holds it there")
    results.put("KE_bottom", None if bottom is None else swing.inertia * bottom * bottom / 2)
    theta_a = model.turning_angle()
    results.put("amplitude", None if theta_a is None else zero.outward(theta_a), ", from the top" if zero.top else "")
    if theta_a is None:
        notes.append("amplitude, rise: none: it goes over the top and turns beyond what rk45 stepped")
    if swing.gravity_torque:
        rise = None if theta_a is None else 2 * cm_distance * math.sin((swing.theta0 + theta_a) / 2) * math.sin((theta_a - swing.theta0) / 2)
        results.put("rise", rise)
        sense = math.copysign(1.0, swing.omega0 or swing.theta0 or 1.0)
        results.put("goes_over", model.goes_over())
        results.put("omega0_over", model.omega0_over(sense))
    if angle is not None:
        velocity = model.velocity_at(angle)
        results.put("omega", velocity, f" at {zero.text(angle)}, when it first gets there")
        if velocity is None:
            notes.append(f"the body never reaches {zero.text(angle)}: it comes to rest before, and the couple holds it")
    results.put("t_bottom", model.time_to(0.0) if bottom is not None else None)
    if angle is not None:
        results.put("t_angle", model.time_to(angle) if results["omega"].value is not None else None, f" {zero.text(angle)}")
    put_state(results, notes, model.state(time) if time is not None else None, angle, time, zero)


def _trajectory(model: Rough, time: float | None, t_bottom: float | None, zero: Zero):
    """θ(t), ω(t) to --time, else to where the body comes to rest for good (within 60 legs), else for 10 s."""
    if time is None:
        for i, _ in enumerate(model.each_leg()):
            if i >= 60:
                break
        if model.rest is not None and model.legs and model.legs[-1].t_end:
            time = model.legs[-1].t_end
    return trajectory(model, time, None, t_bottom, zero)


def _drive_words(swing: Swing) -> str:
    if swing.gravity_torque and swing.torsion:
        return "gravity and a torsion spring"
    return "gravity" if swing.gravity_torque else "a torsion spring"


def _worked_steps(model: Rough, body_steps, mass, cm_distance, gravity, results, zero: Zero) -> list[Step]:
    """The body's steps; α₀ with the couple against the torque; ω at the bottom from energy less the
    couple's work; where it turns."""
    swing, friction = model.swing, model.friction
    value = lambda key: results[key].value if key in results else None  # noqa: E731
    steps = list(body_steps)
    deg0 = f"{fmt(math.degrees(swing.theta0))}°"
    torque0 = abs(model.drive(swing.theta0))
    steps.append(
        Step(
            "Angular acceleration at the start (τ = Iα about the pivot, the couple against the motion)",
            "α₀ = (|mgd sin θ₀ + κθ₀| − τ_f) / I" if swing.omega0 == 0 else "α₀ = |−(mgd sin θ₀ + κθ₀) − τ_f sgn ω₀| / I",
            f"({quantity_text(torque0, 'N*m')} − {quantity_text(friction, 'N*m')}) / {quantity_text(swing.inertia, 'kg*m**2')}"
            if swing.omega0 == 0 and torque0 > friction else f"at θ₀ = {deg0}",
            quantity_text(value("alpha0"), "rad/s**2"),
            "the couple opposes the way the body turns (from rest, the way the torque would turn it); "
            "where the torque is no more than the couple, the couple holds the body",
        )
    )
    first = model.legs[0] if model.legs else None
    bottom = value("omega_bottom")
    if first is not None and bottom is not None and model.first_at(0.0)[0] is first:
        turned = abs(first.theta_start)
        steps.append(
            Step(
                "Speed at the bottom (energy less the couple's work)",
                "½Iω_b² = ½Iω₀² + U(θ₀) − U(0) − τ_f|θ₀|",
                f"√(({fmt(swing.omega0)} rad/s)² + 2 × ({quantity_text(swing.potential(swing.theta0), 'J')} − "
                f"{quantity_text(friction, 'N*m')} × {fmt(turned)} rad) / {quantity_text(swing.inertia, 'kg*m**2')})",
                quantity_text(bottom, "rad/s"),
                "the pivot does not move, so its force does no work; the couple takes τ_f for every radian turned",
            )
        )
    elif bottom is not None:
        steps.append(Step("Speed at the bottom", "½Iω² = ½Iω_s² + U(θ_s) − U(0) − τ_f|θ_s|, on the leg that gets there",
                          "", quantity_text(bottom, "rad/s"), "each leg starts where the one before came to rest"))
    theta_a = model.turning_angle() if value("amplitude") is not None else None
    if theta_a is not None and model.legs:
        start_energy = swing.inertia * swing.omega0**2 / 2 + swing.potential(swing.theta0)
        steps.append(
            Step(
                "Where it first comes to rest",
                "½Iω₀² + U(θ₀) − τ_f|θₐ − θ₀| = U(θₐ)",
                f"{quantity_text(start_energy, 'J')} − {quantity_text(friction, 'N*m')} × {fmt(abs(theta_a - swing.theta0))} rad "
                f"= {quantity_text(swing.potential(theta_a), 'J')}",
                f"{fmt(math.degrees(zero.outward(theta_a)))}°",
                "all the energy the swing had, less what the couple took, is potential energy where it turns "
                "(found by rk45 to ω = 0, then Newton's method on the energy)",
            )
        )
    if mass is not None and cm_distance and value("pivot_force0") is not None:
        steps.append(
            Step(
                "Pivot force at the start",
                "F = m√((dω₀² + g cos θ₀)² + (dα₀ + g sin θ₀)²)",
                f"{fmt(mass)} kg, d = {fmt(cm_distance)} m, θ₀ = {deg0}, g sin θ₀ = {quantity_text(gravity * sine(swing.theta0), 'm/s**2')}",
                quantity_text(value("pivot_force0"), "N"),
                "the centre of mass moves on a circle of radius d: its acceleration is dω² toward the pivot and dα along the swing, "
                "α₀ signed, with the couple in it",
            )
        )
    return steps
