"""The mean angular velocity of a run (#46 item 5): the net angle turned over the time it took,

    ω_mean = θ/t

to --time, else to the target (--until-omega, --until-angle), else to the stop. It is the
steady speed that turns the same angle in the same time (Irodov 1.247: a flywheel slowed by a
torque ∝ √ω stops at ⟨ω⟩ = ω₀/3). θ is the net angle, so a wheel that turned back counts the
way back against the way out. At t = 0 it is ω₀, the limit of θ/t. At one constant α
throughout it is ½(ω₀ + ω), written so (θ and t each carry a rounding that θ/t would keep, and
an uncertainty propagated by differences would read it as a dependence).
"""

from __future__ import annotations

from collections.abc import Sequence

from taucli.writing.report import DeferredSteps, Report, Step, fmt, quantity_text


def with_omega_mean(report: Report, omega0: float | None, *, time: float | None, until_omega: float | None, until_angle: float | None) -> Report:
    """The report with omega_mean put (and its step) where the run has an end: at --time, at the
    target, or at the stop; null with a note where the wheel never stops and no end was asked."""
    results = report.results
    values = {key: value.value for key, value in results.items()}
    if time is not None:
        theta, elapsed, when, last = values.get("theta"), time, f" by t = {fmt(time)} s", values.get("omega")
    elif until_omega is not None or until_angle is not None:
        if "t_until" not in results:
            return report
        theta = values.get("theta_until") if values.get("theta_until") is not None else values.get("theta")
        elapsed, when, last = values.get("t_until"), " until" + results["t_until"].label.removeprefix("time to reach"), values.get("omega")
    elif "t_stop" in results:
        theta, elapsed, when, last = values.get("theta_stop"), values.get("t_stop"), " until it stops", 0.0
    else:
        return report
    if theta is None or elapsed is None:
        results.put("omega_mean", None, when)
        if when == " until it stops" and getattr(results["t_stop"], "moot", False):
            results.not_applicable("omega_mean")  # a spin-up: beside t_stop's rows, which its own note explains (#42 item 23)
        else:
            report.notes.append("omega_mean: the wheel does not stop (or reach the target), so the run has no end to average over; {time} gives one")
        return report
    start = values.get("omega0", omega0)
    mean = theta / elapsed if elapsed else start
    if elapsed and start is not None and last is not None and _uniform(theta, elapsed, start, last):
        mean = (start + last) / 2  # its exact form at constant α: no rounding of θ and t left to move with an input
    results.put("omega_mean", mean, when)
    if elapsed:
        report.steps = DeferredSteps(_with_step, report.steps, theta, elapsed, mean)
    return report


def _uniform(theta: float, elapsed: float, start: float, last: float) -> bool:
    """Whether the run was at one constant α throughout (θ = ½(ω₀ + ω)t to rounding), so that
    θ/t is ½(ω₀ + ω): not where friction held the wheel at rest after it stopped."""
    return abs(theta - (start + last) / 2 * elapsed) <= 1e-12 * (abs(start) + abs(last)) * elapsed


def _with_step(steps: Sequence[Step], theta: float, elapsed: float, mean: float) -> list[Step]:
    """The run's steps and then ω_mean = θ/t (written only when the steps are read)."""
    return [*steps, Step("Mean angular velocity", "ω_mean = θ/t", f"{quantity_text(theta, 'rad')} / {quantity_text(elapsed, 's')}",
                         quantity_text(mean, "rad/s"),
                         "the net angle turned over the time it took: the steady speed that would turn the same angle in the same time")]
