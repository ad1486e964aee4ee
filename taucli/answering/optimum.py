"""--find NAME --minimize RESULT (or --maximize): the value of an input, within its range, that
gives the least (or most) of a result (#47 item 6: the gear ratio with the least RMS torque).

The result is sampled over the input's range as --find's root search samples it (a few values a
decade, numerics.roots.grid), the best sample taken, and the extremum then found to full
precision between its neighbours by golden-section search (the result only needs to be
continuous there, not smooth). An extremum on the edge of the range searched is no extremum
(the result goes on falling, or rising, past it): refused, saying which way. Other local
extrema the samples show are named in a note.
"""

from __future__ import annotations

import math

from taucli.answering import unknowns
from taucli.answering.propagate import FIND_SOLVES, Scene
from taucli.core.errors import InputError, did_you_mean
from taucli.numerics import roots
from taucli.quantities import units
from taucli.writing.report import Report, Step, Value, quantity_text

GOLDEN = (math.sqrt(5) - 1) / 2
CURVE_CELLS = 3  # --plot draws the result over so many of the search grid's cells either side of the optimum
CURVE_POINTS = 61


def optimize(scene: Scene, unknown: unknowns.Unknown, key: str, sense: float, notes: list[str]) -> Report:
    """The report at the value of ``unknown`` where ``key`` is least (sense +1) or most (−1)."""
    command, name = scene.command, unknown.name
    option = "minimize" if sense > 0 else "maximize"
    result = command.result(key)
    if result is None:
        raise InputError(option, f"expected a result of {command.name}: {', '.join(r.key for r in command.results)}", got=repr(key),
                         hint=did_you_mean(key, [r.key for r in command.results]))
    if result.unit is None:
        raise InputError(option, f"expected a result that is a number; {key} is yes or no", got=repr(key))
    si_unit = units.KINDS[unknown.kind].si_unit
    scene.plan(FIND_SOLVES, "find")

    def f(x: float) -> float | None:
        values = scene.results({name: x})
        value = None if values is None else values.get(key)
        return None if value is None or not math.isfinite(value) else sense * value

    xs = roots.grid(units.KINDS[unknown.kind].bounds, unknown.sign, angle=unknown.kind == "angle")
    sampled = [(x, f(x)) for x in xs]
    made = [(x, y) for x, y in sampled if y is not None]
    if len(made) < 3:
        raise InputError(option, f"{key} is not made over the range {unknown.spelled} may take (it is made at {len(made)} of {len(sampled)} values tried)",
                         hint=str(scene.refusal) if scene.refusal else None)
    values = [y for _, y in made]
    if max(values) - min(values) <= 1e-12 * max(abs(v) for v in values):
        raise InputError(option, f"finds no {'least' if sense > 0 else 'most'} {key}: it does not change with {unknown.spelled} "
                         f"(it is {quantity_text(sense * values[0], result.unit, 6)} at each of the {len(made)} values tried)",
                         hint=f"{option} a result that {unknown.spelled} moves")
    best = min(range(len(made)), key=lambda i: made[i][1])
    if best in (0, len(made) - 1):
        edge = made[best][0]
        way = "least" if sense > 0 else "most"
        raise InputError(option, f"finds no {way} {key} within the range {unknown.spelled} may take: it goes on {'falling' if sense > 0 else 'rising'} "
                         f"toward {unknown.spelled} = {quantity_text(edge, si_unit, 6)}, the end of the range searched")
    low, high = made[best - 1][0], made[best + 1][0]
    x, y, steps_taken = _golden(f, low, high, made[best])
    others = [made[i][0] for i in range(1, len(made) - 1) if i != best and made[i][1] <= made[i - 1][1] and made[i][1] <= made[i + 1][1]]
    nominal = scene.report({name: x})
    extreme = sense * y
    way = "least" if sense > 0 else "most"
    results = {name: Value(x, si_unit, f"{unknown.label}, at the {way} {key}")}
    results.update(nominal.results)
    extra = list(notes)
    if others:
        extra.append(f"{key} has other local {'minima' if sense > 0 else 'maxima'} among the values tried, at {unknown.spelled} = "
                     + ", ".join(quantity_text(value, si_unit, 4) for value in others) + f"; the {way} of them all is given")
    steps = [
        Step(f"The {way} {key} over {name}", f"{'min' if sense > 0 else 'max'} {key}({name})",
             f"{len(made)} values of {name} from {quantity_text(made[0][0], si_unit, 3)} to {quantity_text(made[-1][0], si_unit, 3)}, "
             f"then golden-section search between {quantity_text(low, si_unit, 6)} and {quantity_text(high, si_unit, 6)} ({steps_taken} steps)",
             f"{name} = {quantity_text(x, si_unit, 8)}, {key} = {quantity_text(extreme, result.unit, 8)}",
             f"{key} as {command.name} gives it for each trial {name}; the sampled best and its neighbours bracket the "
             f"{'minimum' if sense > 0 else 'maximum'}, narrowed to where {key} no longer tells the trials apart: at an extremum "
             f"{key} changes as the square of the distance, so {name} is known to about 1e-8 of itself where {key} is to 1e-16"),
    ]
    method = f"{nominal.method}; {name} by a search of its range and golden-section search for the {way} {key}"
    window = (made[max(best - CURVE_CELLS, 0)][0], made[min(best + CURVE_CELLS, len(made) - 1)][0])
    report = Report(nominal.scene, nominal.model, method, results, [*steps, *nominal.steps], [*nominal.notes, *extra],
                    nominal.inputs, nominal.tables, nominal.trajectory)
    label = nominal.results[key].label if key in nominal.results else result.label
    report.chart = lambda: _curve(scene, unknown, result, label, f, sense, window, x)
    return report


def _curve(scene: Scene, unknown: unknowns.Unknown, result, label: str, f, sense: float, window: tuple[float, float], optimum: float):
    """--plot's chart of an optimum: the result against the input evenly either side of the
    optimum, as far as the nearer end of the search grid's cells about it (CURVE_POINTS solves,
    made only when the chart is drawn), the optimum marked; ``f`` is the search's own sense × result."""
    from taucli.writing import plot  # deferred: charts, only when one is drawn

    reach = min(optimum - window[0], window[1] - optimum)  # evenly either side, on the chart's linear axis: the optimum in the middle
    low, high = optimum - reach, optimum + reach
    xs = sorted({optimum, *(low + (high - low) * i / (CURVE_POINTS - 1) for i in range(CURVE_POINTS))})
    scene.plan(len(xs), "find")
    ys = [None if (y := f(trial)) is None else sense * y for trial in xs]
    si_unit = units.KINDS[unknown.kind].si_unit
    way = "least" if sense > 0 else "most"
    panel = plot.Panel(result.key, label or result.key, result.unit or "", (plot.Series("", tuple(xs), tuple(ys)),))
    note = (f"{unknown.name} from {quantity_text(low, si_unit, 4)} to {quantity_text(high, si_unit, 4)}, "
            f"evenly either side of the {way} {result.key}")
    return plot.Chart(f"{scene.command.name}: {result.key} against {unknown.name}", unknown.name, unknown.label or unknown.name,
                      si_unit, (panel,), ((optimum, f"the {way} {result.key}"),), (note,))


def _golden(f, low: float, high: float, best: tuple[float, float]) -> tuple[float, float, int]:
    """The least of f between low and high by golden-section search, to a relative 1e-12 of x
    (on a log scale where both ends are positive: the grid's cells span a decade's quarter)."""
    logged = low > 0 and high > 0
    to, back = (math.log, math.exp) if logged else ((lambda v: v), (lambda v: v))
    a, b = to(low), to(high)
    g = lambda u: f(back(u))  # noqa: E731
    c, d = b - GOLDEN * (b - a), a + GOLDEN * (b - a)
    fc, fd = g(c), g(d)
    steps = 0
    while abs(b - a) > 1e-12 * max(abs(a), abs(b), 1e-300 if not logged else 1.0) and steps < 200:
        steps += 1
        if fd is None or (fc is not None and fc <= fd):
            b, d, fd = d, c, fc
            c = b - GOLDEN * (b - a)
            fc = g(c)
        else:
            a, c, fc = c, d, fd
            d = a + GOLDEN * (b - a)
            fd = g(d)
    x = back((a + b) / 2)
    y = f(x)
    if y is None or y > best[1]:
        return best[0], best[1], steps
    return x, y, steps
