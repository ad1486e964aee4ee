"""A torque that varies in time, sampled: J = ∫τ dt by quadrature, then ω₁ = ω₀ + J/I.

The samples are streamed (numerics.quadrature.StreamingQuadrature keeps three): ω at each sample is kept for
up to SAMPLES_SHOWN rows, and a thinned set of them for the plot, so memory stays flat.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence

from taucli.core.errors import InputError
from taucli.numerics.quadrature import StreamingQuadrature
from taucli.options.impulse import COMMAND as TABLE
from taucli.writing.report import Report, Step, Table, Trajectory, deferred, fmt, quantity_text, term
from taucli.scenes.impulse.common import BRIEF_BLOW, CURVES, put_momentum
from taucli.options.table import Results

SAMPLES_SHOWN = 10_000  # ω at the samples is reported for profiles up to this many rows
PLOTTED = 500  # a profile's plot keeps between this many and twice as many of its samples
UNEVEN = 2.0  # auto takes Simpson where no interval is more than this many times its neighbour


def solve_profile(
    inertia: float,
    omega0: float,
    samples: Iterable[tuple[float, float]],
    *,
    rule: str = "auto",
    inertia_steps: Sequence[Step] = (),
) -> Report:
    """J = ∫τ dt = I(ω₁ − ω₀) for a sampled torque τ(t) on a body of fixed I: J by quadrature
    (``rule``: trapezoid, or simpson, which auto takes unless there are only two samples),
    ω = ω₀ + ∫τ dt/I at the samples, ω₁ = ω₀ + J/I, the peak torque. Samples are (t, τ), t
    increasing; Δt runs from the first to the last."""
    if rule not in ("auto", *StreamingQuadrature.RULES):
        raise InputError("method", "expected auto, trapezoid or simpson for a torque profile", got=repr(rule))
    notes: list[str] = []
    quadrature = StreamingQuadrature()
    shown: list[tuple[float, float, float]] = []
    chosen = "simpson" if rule == "auto" else rule
    plotted: list[tuple[float, float, float]] = []  # every stride-th sample, so memory stays flat
    stride = 1
    start = None
    for t, torque in samples:
        if start is None:
            start = t
        quadrature.add(t, torque)
        if quadrature.count <= SAMPLES_SHOWN:
            shown.append((t, torque, omega0 + quadrature.trapezoid / inertia, omega0 + quadrature.simpson() / inertia))
        if (quadrature.count - 1) % stride == 0:
            plotted.append((t, torque, omega0 + quadrature.trapezoid / inertia, omega0 + quadrature.simpson() / inertia))
            if len(plotted) == 2 * PLOTTED:
                plotted, stride = plotted[::2], 2 * stride
    count = quadrature.count
    if count < 2:
        raise InputError("torque_profile", "needs at least two samples for an integral")
    duration = t - start
    if rule == "auto" and count < 3:
        chosen = "trapezoid"
    trapezoid, simpson = quadrature.trapezoid, quadrature.simpson()
    slack = 1e-12 * max(abs(quadrature.low), abs(quadrature.high)) * duration
    within = quadrature.low * duration - slack <= simpson <= quadrature.high * duration + slack  # the mean torque lies between its least and largest
    if rule == "auto" and chosen == "simpson" and (quadrature.uneven > UNEVEN or not within):
        chosen = "trapezoid"
        why = ("the samples are unevenly spaced (neighbouring intervals up to "
               f"{fmt(quadrature.uneven, 3)} times each other), where Simpson's parabolas through three samples can overshoot" if quadrature.uneven > UNEVEN
               else f"Simpson's rule gives J = {fmt(simpson)} N·m·s, outside what these samples allow")
        notes.append(f"method: trapezoid, not Simpson: {why}; the trapezoid rule takes τ straight between samples")
    impulse = trapezoid if chosen == "trapezoid" else simpson
    withheld = chosen == "simpson" and not within
    omega1 = omega0 + impulse / inertia
    results = Results(TABLE)
    results.put("J", impulse, f" ∫τ dt ({chosen})")
    results.put("delta_omega", impulse / inertia)
    results.put("omega1", omega1, " the last sample")
    results.put("duration", duration, " from the first sample to the last")
    results.put("peak_torque", quadrature.peak[1], f", at t = {fmt(quadrature.peak[0])} s")
    put_momentum(results, inertia, omega0, omega1)
    if rule == "auto" and chosen == "simpson":
        notes.append("method: simpson (composite Simpson, exact for quadratics, O(h⁴) on smooth data; --method trapezoid for data with corners, "
                     "where Simpson's higher order does not hold)")
    elif rule == "auto" and count < 3:
        notes.append("method: trapezoid (two samples: only the trapezoid rule applies)")
    if count >= 3 and trapezoid != simpson:
        other, value = ("Simpson's rule", simpson) if chosen == "trapezoid" else ("the trapezoid rule", trapezoid)
        notes.append(f"J: {other} gives {fmt(value)} N·m·s, {fmt(abs(simpson - trapezoid))} N·m·s from this; how far the two rules differ "
                     "is how far the samples leave J open")
    if withheld:
        for key in ("J", "delta_omega", "omega1", "L1", "KE1"):
            results[key] = results[key]._replace(value=None)
        notes.append(f"J withheld: Simpson's rule over these samples gives {fmt(simpson)} N·m·s, outside the least and largest torque times Δt "
                     f"({fmt(quadrature.low * duration)} to {fmt(quadrature.high * duration)} N·m·s); --method trapezoid reads them as straight lines")
    if duration <= BRIEF_BLOW:
        notes.append(f"a brief blow ({fmt(duration)} s): the motion remembers only the impulse J, not the shape of τ(t)")
    tables = {}
    pick = 2 if chosen == "trapezoid" else 3
    if count <= SAMPLES_SHOWN:
        columns = (("t", "s", "t"), ("torque", "N*m", "τ"), ("omega", "rad/s", "ω"))
        tables["samples"] = Table(columns, tuple((row[0], row[1], None if withheld else row[pick]) for row in shown))
    else:
        notes.append(f"ω at the samples is reported for up to {SAMPLES_SHOWN:,} rows; this profile has {count:,}")
    steps = [
        *inertia_steps,
        Step("Angular impulse of a varying torque", "J = ∫τ dt = ΔL = I(ω₁ − ω₀)", f"{count} samples over {fmt(duration)} s, {chosen} rule",
             quantity_text(impulse, "N*m*s"), "the torque changes in time, so its impulse is an integral, taken here from the samples"),
        Step("Angular velocity after", "ω₁ = ω₀ + J/I", f"{term(omega0, 'rad/s')} + {term(impulse, 'N*m*s')} / {term(inertia, 'kg*m**2')}", quantity_text(omega1, "rad/s"),
             "the impulse is all the motion remembers of the torque"),
    ]
    model = f"sampled torque profile ({count} samples), J by the {chosen} rule"
    if plotted[-1][0] != t:
        plotted.append((t, torque, omega1, omega1))
    points = tuple((row[0] - start, row[1], row[pick]) for row in plotted)
    note = "" if stride == 1 else f"plotted at every {stride}th sample"
    return Report("impulse", model, chosen, results, steps, notes, {}, tables, deferred(Trajectory, CURVES, duration, points=points, note=note))
