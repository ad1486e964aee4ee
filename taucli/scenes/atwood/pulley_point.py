"""--at r: a point on the pulley, which turns with m1's string (taucli.scenes.point puts its
speed, its accelerations and the path it has travelled).

    ω = v/R,   α = a/R,   θ = x/R   (R the radius m1's string leaves at)
"""

from __future__ import annotations

from collections.abc import Callable

from taucli.core.errors import InputError
from taucli.options.atwood import COMMAND as TABLE
from taucli.writing.report import Report, fmt
from taucli.scenes.point import RIM, put_point, put_start, rim_radius
from taucli.options.table import Results


def on_the_pulley(
    report: Report, at: float | str, pulley_radius: float | None, radius1: float | None, radius2: float | None,
    v0: float, distance: float | None, time: float | None, from_rest: Callable[[], float | None],
) -> Report:
    """The machine's report with the point at ``at`` (a radius, or "rim") on its pulley;
    ``from_rest`` gives the pulley's α once the masses have stopped (the machine's from rest)."""
    if at == RIM and (radius1 is not None or radius2 is not None):
        raise InputError("at", "rim: a stepped pulley has two radii; give the point's radius", example="{at} 0.1m")
    r, note = rim_radius(at, pulley_radius, "{pulley_radius}")
    report = _point(report, r, radius1 if radius1 is not None else pulley_radius, v0, distance, time, from_rest)
    report.notes += [note] if note else []
    return report


def _point(report: Report, r: float, string_radius: float | None, v0: float, distance: float | None, time: float | None,
           from_rest: Callable[[], float | None]) -> Report:
    """A point at r on the pulley, which turns with m1's string: ω = v/R and α = a/R (R the
    radius m1's string leaves at; down positive turns it positive); after --distance (θ = d/R),
    else at --time (θ = x/R), else at the start. Where the masses were thrown against the
    acceleration and have stopped by then (at t = −v₀/a), α is the one after the stop: 0 where
    static friction holds them, the machine's from rest where they come back."""
    if string_radius is None:
        raise InputError("at", "needs {pulley_radius} (a point on the pulley turns at ω = v/R)", example="{pulley_radius} 0.1m {at} 0.05m")
    values = {key: value.value for key, value in report.results.items()}
    alpha = start_alpha = values.get("alpha")
    a = values.get("a")
    instant = values.get("t") if distance is not None else time
    stopped = alpha is not None and a and v0 * a < 0 and instant is not None and instant > -v0 / a
    if stopped:
        alpha = from_rest()
    results = Results(TABLE)
    results.update(report.results)
    notes, steps = list(report.notes), list(report.steps)
    if distance is not None:
        when, speed, travelled = f" after {fmt(distance)} m", values.get("v"), distance
    elif time is not None:
        when, speed, travelled = f" at t = {fmt(time)} s", values.get("v"), values.get("distance")
    else:
        when, speed, travelled = " at the start", v0, 0.0
    if values.get("a") is None:  # the motion is not known (μk not given): nor is the point's
        speed = None
    omega = None if speed is None else speed / string_radius
    # a point at the string's radius moves with the string: its v_t, a_t and s are the string's v, a
    # and distance (the distance given, exactly: #42 item 22)
    string = (string_radius, speed, None if stopped else a, travelled)
    steps += put_point(results, r, omega, alpha, None if travelled is None else travelled / string_radius, when, notes, string)
    if omega is not None and when != " at the start":
        put_start(results, r, v0 / string_radius, start_alpha, (string_radius, v0))
    return Report(report.scene, report.model, report.method, results, steps, notes, report.inputs, report.tables, report.trajectory)
