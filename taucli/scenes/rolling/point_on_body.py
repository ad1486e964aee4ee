"""A point of the rolling body (--at): at a radius, its motion about the centre (scenes/point.py);
on the rim at a named place or an angle, its motion seen from the ground (ground_point.py). Either
at the end of the run the model reports (the bottom, a distance, rolling at last), else its start.

``motion`` reads the body's motion from a model's report: its centre's v and a along x (forward:
the sense the model's a is positive in) and its spin ω and α in the rolling sense of x.
"""

from __future__ import annotations

from dataclasses import dataclass

from taucli.core.errors import InputError
from taucli.options.rolling import COMMAND as TABLE
from taucli.writing.report import Report
from taucli.scenes.point import put_point, put_start, rim_radius
from taucli.scenes.rolling.ground_point import is_position, put_ground_point
from taucli.options.table import Results


@dataclass(frozen=True)
class Instant:
    """The body at one instant: the centre's velocity v and acceleration a along x, the spin ω and
    α in the rolling sense of x (None where the run does not fix them); ``rolls``: v = Rω and
    a = Rα hold exactly (the contact is at rest)."""

    v: float | None
    omega: float | None
    a: float | None
    alpha: float | None
    rolls: bool = False


@dataclass(frozen=True)
class Motion:
    """The body's start and, where the run has one, its end with the angle turned by then (θ),
    the words for it (" at the bottom"), and what x and y are ("down the slope", "away from the slope")."""

    start: Instant
    end: Instant | None = None
    theta: float | None = None
    when: str = ""
    forward: str = "the way it rolls"
    up: str = "up"  # away from the surface
    on_a_surface: bool = True  # a yo-yo rolls down its string: no ground to see a rim point from
    at_start: str = " at the start"  # the words for a rim point's instant where the run has no end


def motion(
    model: str, report: Report, *, v0: float | None, omega0: float | None, radius: float | None, axle: float | None, slope: float | None = None
) -> Motion:
    """The motion of the body in the report of ``model`` (incline, flat, skid, pull, hanging,
    yoyo, in place), from rest unless v0 (a body set rolling: ω₀ = v₀/R, on a slope v₀ up it) or
    ω₀ (a skid; a yo-yo spun in place) say otherwise."""
    values = {key: value.value for key, value in report.results.items()}
    a, alpha, duration = values.get("a"), values.get("alpha"), values.get("t")
    rolls = bool(values.get("rolls"))
    label = report.results["v"].label if "v" in report.results else ""
    when = " " + label.removeprefix("speed").split(",")[0].strip() if label else ""
    v0 = v0 or 0.0
    if model == "skid":
        return _skid(values, v0, omega0 or 0.0)
    if model == "flat":  # rolling along: nothing changes
        return Motion(Instant(v0, None if radius is None else v0 / radius, 0.0, 0.0, rolls=True), at_start=" as it rolls")
    if model in ("yoyo", "in place"):
        rolling_radius = axle if axle is not None else radius  # the string leaves the axle
        if model == "in place":
            spin0 = omega0 or 0.0
        elif not v0:
            spin0 = 0.0
        elif rolling_radius is None:
            raise InputError("at", "needs {radius} or {axle_radius}: the yo-yo's ω₀ = v₀/r", example="{radius} 0.03m {at} rim")
        else:
            spin0 = v0 / rolling_radius
        centre = 0.0 if model == "in place" else v0
        return _uniform(Instant(centre, spin0, a, alpha, rolls=model == "yoyo"), duration, values, when, "down", on_a_surface=False)
    if model == "incline":  # x down the slope; v0 is up it, and the body is set rolling that way
        spin0 = 0.0 if not v0 else (None if radius is None else -v0 / radius)
        return _uniform(Instant(-v0, spin0, a, alpha, rolls=rolls), duration, values, when, "down the slope", up="away from the slope")
    forward = "towards the pulley" if model == "hanging" else "along the pull" if not slope else "down the slope"  # the sense a is positive in
    return _uniform(Instant(0.0, 0.0, a, alpha, rolls=rolls), duration, values, when, forward, up="away from the slope" if slope else "up")


def _uniform(start: Instant, duration: float | None, values: dict, when: str, forward: str, *, on_a_surface: bool = True, up: str = "up") -> Motion:
    """Constant a and α from ``start`` for ``duration`` (None: the start alone): v = v₀ + at (the
    model's own v where it gives one), ω = ω₀ + αt, θ = ω₀t + ½αt²."""
    if duration is None or start.a is None:
        return Motion(start, when=when, forward=forward, up=up, on_a_surface=on_a_surface)
    speed = values.get("v")
    v = speed if speed is not None else (None if start.v is None else start.v + start.a * duration)
    omega = theta = None
    if start.alpha is not None and start.omega is not None:
        omega = start.omega + start.alpha * duration
        theta = start.omega * duration + start.alpha * duration * duration / 2
    end = Instant(v, omega, start.a, start.alpha, start.rolls)
    return Motion(start, end, theta, when, forward, up, on_a_surface)


def _skid(values: dict, v0: float, omega0: float) -> Motion:
    """A ball skidding on the flat: a and α constant while it slides (from v₀, ω₀ to v_roll,
    ω_roll in t_roll), then it rolls on with a = α = 0; with no friction it skids on unchanged."""
    t_roll, v_roll, omega_roll = values.get("t_roll"), values.get("v_roll"), values.get("omega_roll")
    thrown = "the way it is thrown"
    if t_roll is None:  # μk = 0: nothing acts at the contact
        return Motion(Instant(v0, omega0, 0.0, 0.0), forward=thrown)
    if t_roll == 0:  # it already rolls
        return Motion(Instant(v0, omega0, 0.0, 0.0, rolls=True), forward=thrown)
    slowing = (v_roll - v0) / t_roll
    if omega_roll is None:  # no radius: its spin is not known, but for the start's (none, or --omega0)
        return Motion(Instant(v0, omega0, slowing, None), forward=thrown)
    start = Instant(v0, omega0, slowing, (omega_roll - omega0) / t_roll)
    end = Instant(v_roll, omega_roll, 0.0, 0.0, rolls=True)
    return Motion(start, end, (omega0 + omega_roll) * t_roll / 2, " once it rolls", thrown)


def point_on_body(report: Report, at: object, radius: float | None, body: Motion) -> Report:
    """The report with the point ``at`` put in: r (or "rim", the body's ``radius``) from the
    centre, turning with the body's ω and α about it (its motion relative to the centre: v_t = ωr,
    a_t = αr, a_c = ω²r, s = rθ), at the end (with the start's v_t0...) or at the start; or a
    point on the rim (top, bottom, front, back, an angle from the top) seen from the ground."""
    results = Results(TABLE)
    results.update(report.results)
    notes, steps = list(report.notes), list(report.steps)
    instant = body.end or body.start
    when = body.when if body.end is not None else body.at_start
    if is_position(at):
        if not body.on_a_surface:
            raise InputError("at", "takes a radius for a yo-yo (top, bottom, front, back and angles are points seen from the ground "
                             "a body rolls on)", example="{at} rim")
        steps += put_ground_point(results, at, radius, instant, when, body.forward, body.up, notes)
    else:
        r, rim_note = rim_radius(at, radius, "{radius}")
        if body.start.omega is None:
            raise InputError("at", "needs {radius}: the body's ω₀ = v₀/R", example="{radius} 0.1m {at} 0.05m")
        if body.end is None or body.end.omega is None:
            steps += put_point(results, r, body.start.omega, body.start.alpha, 0.0, " at the start", notes)
        else:
            steps += put_point(results, r, body.end.omega, body.end.alpha, body.theta, when, notes)
            put_start(results, r, body.start.omega, body.start.alpha)
        notes.append("the point's motion about the centre of the body (v_t = ωr relative to the centre; the centre's own velocity adds to it)")
        notes += [rim_note] if rim_note else []
    return Report(report.scene, report.model, report.method, results, steps, notes, report.inputs, report.tables, report.trajectory)
