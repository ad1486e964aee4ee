"""A spin-down run as a schedule of phases (--phase, in order), each at a constant α:

    ω = ω_s + α t,   θ = ω_s t + ½ α t²,   ω² = ω_s² + 2 α θ      (ω_s the speed the phase starts at)

A phase's α is given (alpha=, coast: 0), or τ/I (torque=, with the body), or follows from two of
its ends: time and until-omega, α = (ω₁ − ω_s)/t; angle and until-omega, α = (ω₁² − ω_s²)/(2θ);
time and angle, α = 2(θ − ω_s t)/t². With its rate it ends at time=, at a net angle= (the first
time θ gets there) or at until-omega= (reached going its way: t = (ω₁ − ω_s)/α ≥ 0). Each phase
starts where the last ended; the run's θ, revolutions, ω and time are the sums and the last end.
A propeller (Cutnell & Johnson): 2.90e-3 rad/s² for 2.10e3 s, coast 1.40e3 s, −2.30e-3 rad/s² to
4.00 rad/s: θ = 6394.5 + 8526 + 4584.4 = 1.95e4 rad.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from taucli.core.errors import InputError
from taucli.options.spin_down import COMMAND as TABLE
from taucli.options.table import Results
from taucli.scenes.given import Phase
from taucli.writing.report import DeferredSteps, Report, Step, Table, Trajectory, deferred, fmt, quantity_text, term

TWO_PI = 2 * math.pi


def solve_phases(inertia: float | None, omega0: float, phases: Sequence[Phase], time: float | None = None, inertia_steps=()) -> Report:
    """The run through ``phases`` from ω₀; --time: the state at that time within it."""
    rows, start_t, w, theta = [], 0.0, omega0, 0.0
    for number, phase in enumerate(phases, start=1):
        alpha = _rate(phase, inertia, w)
        duration = _duration(phase, alpha, w)
        angle = w * duration + 0.5 * alpha * duration * duration
        end_w = phase.until_omega if phase.until_omega is not None and phase.time is None else w + alpha * duration
        rows.append((number, start_t, alpha, duration, w, end_w, angle))
        start_t, w, theta = start_t + duration, end_w, theta + angle
    total = start_t
    results = Results(TABLE)
    if inertia is not None:
        results.put("I", inertia)
    results.put("alpha0", rows[0][2])
    part = " at the end of the run"
    if time is not None:
        if time > total:
            raise InputError("time", f"is after the run ends ({fmt(total)} s, its phases' times added)", example=f"{{time}} {fmt(total)}s")
        w, theta = _state(rows, time)
        part = f" at t = {fmt(time)} s"
    results.put("omega", w, part)
    results.put("theta", theta, part)
    results.put("revs", theta / TWO_PI, part)
    results.put("t_run", total)
    end = total if time is None else time
    if end > 0:
        results.put("omega_mean", theta / end, f" over {fmt(end)} s")
    if inertia is not None:
        results.put("L", inertia * w, part)
        results.put("KE0", 0.5 * inertia * omega0 * omega0)
        results.put("KE", 0.5 * inertia * w * w, part)
    table = Table((("phase", None, "phase"), ("t_start", "s", "starts at"), ("alpha", "rad/s**2", "α"), ("time", "s", "lasts"),
                   ("omega_start", "rad/s", "ω at its start"), ("omega_end", "rad/s", "ω at its end"), ("theta", "rad", "θ in it"),
                   ("revs", "rev", "revolutions in it")),
                  tuple((n, t0, a, dt, w0, w1, th, th / TWO_PI) for n, t0, a, dt, w0, w1, th in rows))
    steps = DeferredSteps(_steps, rows, phases, inertia, inertia_steps, total, theta if time is None else None)
    model = f"a run of {len(rows)} phases, each at constant α" if len(rows) > 1 else "a run of one phase at constant α"
    trajectory = deferred(_trajectory, rows, total)
    return Report("spin-down", model, "closed form", results, steps, [], tables={"phases": table}, trajectory=trajectory)


def phases_run(others: dict, method: str, phases: Sequence[Phase], omega0: float | None, time: float | None, body_options: dict) -> Report:
    """--phase: the run alone on the body (or with no body), from ω₀; the options of other models refused."""
    from taucli.scenes.inertia import body  # deferred: only a run of phases with a body needs it (and it imports this layer's peers)

    for name, value in others.items():
        if value is not None and value != () and value is not False:
            raise InputError(name, "does not combine with {phase}: each phase gives its own rate (alpha=, torque= or coast) and end",
                             example='{phase} "alpha=2rad/s^2 time=3s" {phase} "coast time=5s"')
    if method != "auto":
        raise InputError("method", "does not apply with {phase}: each phase at constant α has a closed form")
    given = any(body_options.get(name) not in (None, (), []) for name in ("inertia", "shape", "gyration", "part"))
    inertia, steps = body(**body_options) if given else (None, ())
    return solve_phases(inertia, omega0 or 0.0, phases, time, steps)


def _rate(phase: Phase, inertia: float | None, w: float) -> float:
    if phase.alpha is not None:
        return phase.alpha
    if phase.torque is not None:
        if inertia is None:
            raise InputError("phase", f"{phase.source} has torque=, which needs the body ({{inertia}} or a shape): α = τ/I", example="{inertia} '2kg*m^2'")
        return phase.torque / inertia
    t, angle, w1 = phase.time, phase.angle, phase.until_omega
    if t is not None and w1 is not None:
        if t == 0:
            raise InputError("phase", f"{phase.source}: time=0 cannot change the speed", example='{phase} "time=5s until-omega=100rpm"')
        return (w1 - w) / t
    if angle is not None and w1 is not None:
        if not (w + w1) * angle > 0:
            raise InputError("phase", f"{phase.source}: no constant α takes ω from {fmt(w)} to {fmt(w1)} rad/s within {fmt(angle)} rad "
                             "(the mean speed (ω_s + ω₁)/2 must turn it that way)", example='{phase} "angle=10rev until-omega=0"')
        return (w1 - w) * (w1 + w) / (2 * angle)
    if t == 0:
        raise InputError("phase", f"{phase.source}: time=0 turns no angle", example='{phase} "time=5s angle=20rev"')
    return 2 * (angle - w * t) / (t * t)


def _duration(phase: Phase, alpha: float, w: float) -> float:
    if phase.time is not None:
        return phase.time
    if phase.angle is not None and phase.until_omega is not None:  # α from these two: the time at the mean speed
        return 2 * phase.angle / (w + phase.until_omega)
    if phase.until_omega is not None:
        if phase.until_omega == w:
            return 0.0
        if alpha == 0 or (phase.until_omega - w) / alpha < 0:
            raise InputError("phase", f"{phase.source} never reaches until-omega={fmt(phase.until_omega)} rad/s: it starts at {fmt(w)} rad/s with "
                             f"α = {fmt(alpha)} rad/s²", example='{phase} "alpha=-2rad/s^2 until-omega=0"')
        return (phase.until_omega - w) / alpha
    return _time_to_angle(phase, alpha, w, phase.angle)


def _time_to_angle(phase: Phase, alpha: float, w: float, angle: float) -> float:
    """The first t ≥ 0 with w t + ½ α t² = angle (a stable root of the quadratic)."""
    if angle == 0:
        return 0.0
    square = w * w + 2 * alpha * angle
    roots = []
    if alpha == 0:
        roots = [angle / w] if w != 0 else []
    elif square >= 0:
        q = -(w + math.copysign(math.sqrt(square), w)) / 2
        roots = [r for r in ((q / (alpha / 2)) if q else None, (-angle / q) if q else None) if r is not None]
    found = [r for r in roots if r > 0]
    if not found:
        raise InputError("phase", f"{phase.source} never turns angle={fmt(angle)} rad: it starts at {fmt(w)} rad/s with α = {fmt(alpha)} rad/s²",
                         example='{phase} "alpha=2rad/s^2 angle=10rev"')
    return min(found)


def _state(rows, t: float) -> tuple[float, float]:
    """ω and the net θ at time t within the run."""
    theta = 0.0
    for number, t0, alpha, duration, w0, w1, angle in rows:
        if t <= t0 + duration or number == rows[-1][0]:
            s = t - t0
            return (w1 if s == duration else w0 + alpha * s), theta + w0 * s + 0.5 * alpha * s * s
        theta += angle
    return 0.0, theta


def _steps(rows, phases, inertia, inertia_steps, total, theta) -> list[Step]:
    steps = list(inertia_steps)
    for (number, t0, alpha, duration, w0, w1, angle), phase in zip(rows, phases):
        how = ("coast: α = 0" if phase.alpha == 0 and phase.torque is None else "α as given" if phase.alpha is not None
               else "α = τ/I" if phase.torque is not None else "α from its two ends")
        ends = "t as given" if phase.time is not None else "t = (ω₁ − ω_s)/α" if phase.until_omega is not None else "the first t with θ as given"
        steps.append(Step(f"Phase {number}, from t = {fmt(t0)} s", "ω₁ = ω_s + α t,  θ = ω_s t + ½ α t²",
                          f"α = {term(alpha, 'rad/s**2')}, t = {term(duration, 's')}:  {term(w0, 'rad/s')} + {term(alpha, 'rad/s**2')} × {term(duration, 's')}",
                          f"ω₁ = {quantity_text(w1, 'rad/s')}, θ = {quantity_text(angle, 'rad')} = {fmt(angle / TWO_PI)} rev", f"{how}; {ends}"))
    if theta is not None:
        steps.append(Step("The whole run", "θ = Σ θᵢ,  t = Σ tᵢ", " + ".join(fmt(r[6]) for r in rows) + " rad",
                          f"{quantity_text(theta, 'rad')} = {fmt(theta / TWO_PI)} rev in {quantity_text(total, 's')}", "each phase starts where the last ended"))
    return steps


def _trajectory(rows, total: float) -> Trajectory:
    curves = (("omega", "rad/s", "angular velocity"), ("theta", "rad", "angle turned"))
    marks = tuple((t0, f"phase {number}") for number, t0, *_ in rows[1:])
    end = total if total > 0 else 1.0
    return Trajectory(curves, end, lambda t: _state(rows, t), marks=(*marks, (total, "the end")))
