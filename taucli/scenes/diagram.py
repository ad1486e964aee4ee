"""The energy a flywheel gives and takes over a cycle, from the turning-moment diagram T(θ) itself:
its samples (crank angle and torque, as the books tabulate them) or a formula of θ.

Over one cycle of crank angle Θ (2π for a steam or two-stroke engine, 4π for a four-stroke) the
engine does the work W = ∫T dθ, and the load, taken as a constant torque, the same: the mean
torque is

    T_mean = W/Θ = (1/Θ) ∫₀^Θ T(θ) dθ,

and the mean power P = T_mean ω_mean. The flywheel's energy above its energy at the start is the
running integral of the torque in excess of the mean,

    E(θ) = ∫₀^θ (T − T_mean) dθ,        ΔE = max E − min E,

whose extremes lie where T crosses T_mean (the ends of the loops of turning_moment.py), and at
the ends of the cycle, where E returns to 0.

Samples are joined by straight lines, and integrated by the trapezoid rule: the samples may be
unevenly spaced, and the running integral of a polyline has its extremes exactly where a segment
crosses the mean line (found by linear interpolation), so the work, the mean and ΔE are those of
one curve; Simpson's parabolas would need even, paired intervals and can overshoot between
samples, with the crossings no longer on the curve the trapezoids integrate. A formula is
integrated exactly where it is a polynomial plus sines and cosines of multiples of θ (the books'
formulas: ∫ sin wθ = (1 − cos wθ)/w), else by adaptive Gauss–Legendre quadrature
(taucli.numerics.of_time, to about 1e-13), and the crossings are found by Brent's method between
the sign changes of T − T_mean on a grid of GRID points over the cycle.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import replace

from taucli.core.errors import InputError
from taucli.numerics.of_time import FormulaFailed, OfTime
from taucli.numerics.roots import brent
from taucli.writing.report import Step, fmt, quantity_text, term

GRID = 2880  # points over a cycle where T − T_mean is sampled for its sign changes (¼° over 720°), more for fast waves
MAX_GRID = 200_000
PERIODS = (2 * math.pi, 4 * math.pi)  # a formula's cycle where none is given: one turn, else two (a four-stroke's)
EXAMPLE = "{turning_moment} '(15000 + 10000*sin(2*theta) - 6000*cos(2*theta)) N*m'"


def degrees(angle: float) -> str:
    return f"{fmt(math.degrees(angle))}°"


def swing_from_curve(curve: OfTime | Sequence[tuple[float, float]], cycle: float | None, steps: list[Step], notes: list[str]) -> tuple[float, float, str]:
    """(ΔE, T_mean, the method) from the diagram: a formula of theta (an OfTime) or its SI samples (θ, T)."""
    if isinstance(curve, OfTime):
        try:
            swing, mean = _from_formula(curve, cycle, steps)
        except FormulaFailed as failed:
            raise InputError("turning_moment", f"has no finite value at θ = {degrees(failed.at)} ({failed.why})", example=EXAMPLE) from None
        return swing, mean, ("closed-form integral" if curve.exact else "Gauss–Legendre quadrature") + ", Brent's method for the crossings"
    swing, mean = _from_samples([(float(a), float(t)) for a, t in curve], cycle, steps, notes)
    return swing, mean, "trapezoid rule over the samples"


def _from_samples(samples: list[tuple[float, float]], cycle: float | None, steps: list[Step], notes: list[str]) -> tuple[float, float]:
    start, span = samples[0][0], samples[-1][0] - samples[0][0]
    if cycle is None:
        cycle = span
        if not any(abs(span - whole) <= 1e-9 * whole for whole in (math.pi, *PERIODS)):
            turn = next(whole for whole in (*PERIODS, math.inf) if whole > span)
            notes.append(f"--turning-moment: the samples span {degrees(span)}, taken as the cycle; where the diagram repeats after "
                         f"{degrees(turn) if math.isfinite(turn) else 'a whole number of turns'}, give --cycle-angle "
                         f"{'%gdeg' % math.degrees(turn) if math.isfinite(turn) else ''}".rstrip() + " (its last segment then runs back to the first torque)")
    elif cycle < span * (1 - 1e-9):
        raise InputError("cycle_angle", f"is shorter than the samples' span, {degrees(span)}: give the samples of one cycle", example="{cycle_angle} 720deg",
                         got=degrees(cycle))
    elif cycle > span * (1 + 1e-9):
        samples = [*samples, (start + cycle, samples[0][1])]
        steps.append(Step("Closing the cycle", "T(θ₀ + Θ) = T(θ₀)", f"θ₀ + Θ = {degrees(start + cycle)}", quantity_text(samples[0][1], "N*m"),
                          "the diagram repeats every cycle: its last segment runs back to the first sample's torque"))
    top = max(abs(t) for _, t in samples)
    if abs(samples[-1][1] - samples[0][1]) > 1e-6 * top:
        notes.append(f"--turning-moment: the diagram ends at {quantity_text(samples[-1][1], 'N*m')}, not at its first torque "
                     f"{quantity_text(samples[0][1], 'N*m')}: over a whole cycle a diagram closes on itself; the samples are taken as given")
    work = math.fsum((a[1] + b[1]) / 2 * (b[0] - a[0]) for a, b in zip(samples, samples[1:]))
    mean = work / cycle
    # E at each sample, and at each crossing of the mean line within a segment (a polyline's extremes)
    points: list[tuple[float, float]] = [(start, 0.0)]
    energy = 0.0
    for (a, ta), (b, tb) in zip(samples, samples[1:]):
        ga, gb, width = ta - mean, tb - mean, b - a
        if ga * gb < 0:
            share = ga / (ga - gb)
            points.append((a + share * width, energy + ga * share * width / 2))
        energy += (ga + gb) / 2 * width
        points.append((b, energy))
    steps.append(Step("Work over the cycle", "W = Σ ½(Tᵢ + Tᵢ₊₁)(θᵢ₊₁ − θᵢ)",
                      f"{len(samples)} samples over {degrees(cycle)} (the trapezoid rule)", quantity_text(work, "J"),
                      "the area under the diagram, its samples joined by straight lines (they may be unevenly spaced; the crossings of the mean line "
                      "below lie on the same lines)"))
    return _swing(points, mean, work, cycle, steps, "at the samples and where a segment crosses the mean line (by linear interpolation)")


def _from_formula(curve: OfTime, cycle: float | None, steps: list[Step]) -> tuple[float, float]:
    steps.append(Step("The turning moment as a formula of the crank angle", f"T(θ) = {curve.describe()}  (N·m, θ in rad)", "", "", "as given"))
    if cycle is None:
        cycle = _period(curve)
        steps.append(Step("The cycle", "T(θ + Θ) = T(θ)", "", f"Θ = {degrees(cycle)}",
                          "one turn (a steam or two-stroke engine), or two for a four-stroke; give --cycle-angle for another"))
    work = curve.first(cycle)
    mean = work / cycle
    if curve.exact:  # T − T_mean integrated in closed form as it stands: E(θ) keeps its digits where T_mean θ is far larger
        above = _less(curve, mean)
        energy, excess = above.first, above.at
    else:  # quadrature settles to a share of the integral, which for T − T_mean comes back to 0 at the cycle's end
        energy = lambda angle: curve.first(angle) - mean * angle  # noqa: E731
        excess = lambda angle: curve.at(angle) - mean  # noqa: E731
    count = GRID
    if curve.waves is not None and curve.waves[1]:  # 16 points to each period of its fastest wave, at the least
        count = max(GRID, math.ceil(16 * max(w for w, _, _ in curve.waves[1]) * cycle / (2 * math.pi)))
        if count > MAX_GRID:
            raise InputError("turning_moment", f"swings too fast to follow: more than {MAX_GRID // 16} periods over the cycle", example=EXAMPLE)
    grid = [cycle * i / count for i in range(count + 1)]
    values = [excess(angle) for angle in grid]
    points = [(0.0, 0.0)]
    for a, b, fa, fb in zip(grid, grid[1:], values, values[1:]):
        if fa == 0:
            points.append((a, energy(a)))
        elif fa * fb < 0:
            root, _ = brent(excess, a, b, fa, fb)
            points.append((root, energy(root)))
    points.append((cycle, energy(cycle)))
    how = ("exactly (a polynomial)" if curve.coefficients is not None else "exactly (sines and cosines of multiples of θ, and a polynomial)"
           if curve.exact else "by adaptive Gauss–Legendre quadrature")
    steps.append(Step("Work over the cycle", "W = ∫₀^Θ T dθ", f"over {degrees(cycle)}, {how}", quantity_text(work, "J"), "the area under the diagram"))
    return _swing(points, mean, work, cycle, steps, "where T(θ) = T_mean (Brent's method between the sign changes on a fine grid)")


def _less(curve: OfTime, mean: float) -> OfTime:
    """T − T_mean of a formula in closed form: its polynomial's constant term less the mean."""
    if curve.coefficients is not None:
        return replace(curve, coefficients=(curve.coefficients[0] - mean, *curve.coefficients[1:]))
    function, (poly, terms) = curve.function, curve.waves
    return replace(curve, function=lambda angle: function(angle) - mean, waves=((poly[0] - mean, *poly[1:]), terms))


def _period(curve: OfTime) -> float:
    """2π, else 4π, where the formula repeats over it (at 97 points, to 1e-9 of its size); else refused."""
    for period in PERIODS:
        probes = [period * (k + 0.37) / 97 for k in range(97)]
        here = [curve.at(angle) for angle in probes]
        size = max(abs(value) for value in here) or 1.0
        if all(abs(curve.at(angle + period) - value) <= 1e-9 * size for angle, value in zip(probes, here)):
            return period
    raise InputError("cycle_angle", "is required: the formula does not repeat over 360° or 720°, so the cycle is not known", example="{cycle_angle} 360deg")


def _swing(points: list[tuple[float, float]], mean: float, work: float, cycle: float, steps: list[Step], where: str) -> tuple[float, float]:
    highest = max(points, key=lambda point: point[1])
    lowest = min(points, key=lambda point: point[1])
    swing = highest[1] - lowest[1]
    steps.append(Step("Mean torque", "T_mean = W/Θ", f"{quantity_text(work, 'J')} / {fmt(cycle)} rad", quantity_text(mean, "N*m"),
                      "the load's steady torque that takes the engine's work over the cycle"))
    steps.append(Step("The flywheel's energy above its start", "E(θ) = ∫₀^θ (T − T_mean) dθ",
                      f"greatest at {degrees(highest[0])}, least at {degrees(lowest[0])}",
                      f"E_max = {quantity_text(highest[1], 'J')}, E_min = {quantity_text(lowest[1], 'J')}",
                      f"its extremes lie where the torque crosses the mean, or at the cycle's ends: {where}"))
    steps.append(Step("Maximum fluctuation of energy", "ΔE = E_max − E_min", f"{term(highest[1], 'J')} − {term(lowest[1], 'J')}",
                      quantity_text(swing, "J"), "between its greatest and least energy the flywheel goes from its top to its least speed"))
    return swing, mean
