"""--at r: a point of the body at radius r, at the start (ω₀) and at the end of the impulse (ω₁).

    v = ωr,   a_t = αr,   a_c = ω²r,   s = rθ   (scenes.point puts them)
"""

from __future__ import annotations

from taucli.options.impulse import COMMAND as TABLE
from taucli.writing.report import Report
from taucli.scenes.point import put_point, put_start, rim_radius
from taucli.options.table import Results


def point_after(report: Report, at: float | str, radius: float | None, given: dict) -> Report:
    """The report with the point at ``at`` (a radius, or "rim": the body's ``radius``) put after
    its results and steps; ``given`` holds what the user gave, for what the report does not echo."""
    r, note = rim_radius(at, radius, "a body with {radius}")
    report = _point_after(report, r, given)
    report.notes += [note] if note else []
    return report


def _point_after(report: Report, r: float, given: dict) -> Report:
    """A point of the body at r: at the start (ω₀) and at the end of the impulse (ω₁). A constant
    torque still acts at the end (α = τ/I) and the body has turned θ = ½(ω₀ + ω₁)Δt; after a
    meeting or a change of shape no torque acts (α = 0) and the angle is not followed; a sampled
    torque's α at its end is not kept (null, with a note)."""
    values = {**given, **{key: value.value for key, value in (*report.inputs.items(), *report.results.items()) if value.value is not None}}
    omega0, omega1 = values.get("omega0"), values.get("omega1")
    torque, inertia, duration = values.get("torque"), values.get("inertia"), values.get("duration")
    results = Results(TABLE)
    results.update(report.results)
    notes, steps = list(report.notes), list(report.steps)
    if "alpha" in given:  # a braked impulse: α and the net angle from its motion (friction against it; it may stop)
        alpha, alpha0, theta, when = given["alpha"], given["alpha0"], given["theta"], " at the end of the impulse"
    elif torque is not None and inertia:
        alpha, theta = torque / inertia, None if duration is None or omega0 is None or omega1 is None else (omega0 + omega1) * duration / 2
        alpha0, when = alpha, " at the end of the impulse"
    elif report.model.startswith("sampled"):
        alpha = alpha0 = theta = None
        when = " after the impulse"
    else:
        alpha = alpha0 = 0.0
        theta, when = None, " after"
    if omega0 is None or omega1 is None:
        steps += put_point(results, r, None, None, None, when, notes)
        notes[-1] = "v_t, a_t, a_c, a_total, a_angle, s, chord: ω before or after is not determined by what is given"
    else:
        steps += put_point(results, r, omega1, alpha, theta, when, notes)
        put_start(results, r, omega0, alpha0)
        if theta is None:
            notes.append("s, chord: the angle turned while it changes is not followed here")
    return Report(report.scene, report.model, report.method, results, steps, notes, report.inputs, report.tables, report.trajectory)
