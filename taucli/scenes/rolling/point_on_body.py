"""A point of the rolling body (--at): its motion about the body's centre, at the start and at
the end of the run the model reports.
"""

from __future__ import annotations

from taucli.errors import InputError
from taucli.options.rolling import COMMAND as TABLE
from taucli.report import Report
from taucli.scenes.point import put_point, put_start, rim_radius
from taucli.table import Results


def point_on_body(
    report: Report, at: float | str, radius: float | None, v0: float, omega0: float | None, rolling_radius: float | None
) -> Report:
    """A point of the body at r from its centre, turning with the body's ω and α about the
    centre (its motion relative to the centre; the centre's own velocity adds to it), at the
    start and at the end of the run the scene reports (the bottom, a drop, a pulled distance:
    ω = ω₀ + αt, θ = ω₀t + ½αt², α constant; a skid: α = (ω_roll − ω₀)/t_roll while it slides,
    θ = ½(ω₀ + ω_roll)t_roll, then α = 0 once it rolls on the flat). ω₀ is --omega0 (a skid
    without it starts with no spin), or v₀/R for a body set rolling (a yo-yo thrown down: R its
    axle). ``at`` is r, or "rim" for the body's radius (``radius``)."""
    r, rim_note = rim_radius(at, radius, "{radius}")
    values = {key: value.value for key, value in report.results.items()}
    results = Results(TABLE)
    results.update(report.results)
    notes, steps = list(report.notes), list(report.steps)
    skid = values.get("omega_roll") is not None and values.get("t_roll") is not None
    if omega0 is None:  # a skid starts without spin; a body set rolling (or a yo-yo thrown down) at v₀/R
        omega0 = 0.0 if skid or not v0 else (None if rolling_radius is None else v0 / rolling_radius)
    if omega0 is None:
        raise InputError("at", "needs {radius}: the body's ω₀ = v₀/R", example="{radius} 0.1m {at} 0.05m")
    if skid and values["t_roll"] > 0:  # a skid, until it rolls
        omega, duration = values["omega_roll"], values["t_roll"]
        alpha0, alpha, theta, when = (omega - omega0) / duration, 0.0, (omega0 + omega) * duration / 2, " once it rolls"
    else:
        alpha0 = alpha = values.get("alpha")
        duration = values.get("t")
        omega = theta = None
        if alpha is not None and duration is not None:
            omega, theta = omega0 + alpha * duration, omega0 * duration + alpha * duration * duration / 2
        label = report.results["v"].label if "v" in report.results else ""
        when = " " + label.removeprefix("speed").split(",")[0].strip() if label else ""
    if omega is None:
        steps += put_point(results, r, omega0, alpha0, 0.0, " at the start", notes)
    else:
        steps += put_point(results, r, omega, alpha, theta, when, notes)
        put_start(results, r, omega0, alpha0)
    notes.append("the point's motion about the centre of the body (v_t = ωr relative to the centre; the centre's own velocity adds to it)")
    notes += [rim_note] if rim_note else []
    return Report(report.scene, report.model, report.method, results, steps, notes, report.inputs, report.tables, report.trajectory)
