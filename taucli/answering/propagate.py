"""How uncertainties travel through a scene: the full Jacobian, and the Monte Carlo check (#22).

Every result gets a first-order standard uncertainty from the full Jacobian of the scene (each
uncertain input moves every result; the inputs are taken as independent). The Jacobian is formed
by central differences with Richardson extrapolation: the scene is re-solved through
``pipeline.solve`` with changed SI inputs (a number given for an option is SI). Complex steps are
not used: the solvers call ``math`` functions, which refuse complex numbers. Near a physical bound
(a mass near 0) the differences are one-sided. Each uncertain input is also moved by ±1σ: where
the scene changes its regime there (a stop, roll or slip, friction that holds) or a result bends
away from its tangent, a note says that first order is rough, and ``--mc N`` (Monte Carlo, N
draws) gives a check: draw by draw, or all at once on numpy arrays where the scene has an array
form (taucli.answering.mc_arrays; the same draws, the same numbers to rounding).

taucli.answering.answer decides when this is asked for; taucli.answering.find uses the same pieces for the solved
input. Neither is imported here.
"""

from __future__ import annotations

import math
import re
import time
from collections.abc import Callable, Mapping

from taucli.answering import pipeline
from taucli.core.errors import InputError, spelled
from taucli.answering.inputs import read
from taucli.quantities.measurement import with_uncertainty
from taucli.writing.report import Measured, Report, fmt
from taucli.options.table import Command

_NUMBERS = re.compile(r"\d+(?:[.,]\d+)?(?:[eE][-+−]?\d+)?")  # the numbers in a model's text: the inputs it names
MC_SEED = 22  # Monte Carlo draws are seeded: the same run gives the same check
MC_MAX = 100_000


FIND_SOLVES = 450  # about how many solves a --find search takes: a grid over the unknown's range, then refined
ESTIMATES = frozenset({5, 10, 20, 40, 80, 160, 320})  # after so many solves the cost of all is estimated (first after 5)


class OverBudget(InputError):
    """Work estimated to take longer than the limit: refused before most of it is done."""


class Scene:
    """The scene with its options fixed but for the SI values a caller moves.

    ``limit`` (seconds, or None) bounds the work: a caller says how many solves it plans
    (``plan``), and after the first few are timed, the rest is estimated and refused where it
    would pass the limit (OverBudget), saying the setting that would fit."""

    def __init__(self, command: Command, given: dict, stdin, spell, unknown=None, limit: float | None = None):
        self.command, self.given, self.stdin, self.spell = command, given, stdin, spell
        self.limit = limit
        self.spent = 0.0  # seconds in solves
        self.planned: tuple[int, int, str] | None = None  # (solves so far when planned, solves planned, what asked for them)
        self.spent_before = 0.0  # seconds in solves when the work was planned
        self.progress = None  # called with (done, planned) after each planned solve: a progress bar
        arguments, _ = read(command, readable(command, given, unknown))
        self.si = {name: value for name, value in arguments.items() if isinstance(value, float)}
        self.solves = 0
        # What --find solves for: name -> an object whose given_with(given, x) puts x in its place
        # (an option, one more value of a repeated one, a key of a spec), and whose sign is the sign
        # x may take (taucli.answering.unknowns.Unknown).
        self.unknowns: dict[str, object] = {unknown.name: unknown} if unknown is not None else {}
        self.refusal: Exception | None = None  # why the scene last refused the inputs moved (results)

    def plan(self, solves: int, setting: str) -> None:
        """``solves`` more solves are to come, asked for by ``setting`` ("mc", "find")."""
        self.planned = (self.solves, solves, setting)
        self.spent_before = self.spent

    def _spend(self, seconds: float) -> None:
        self.spent += seconds
        if self.planned is None:
            return
        start, planned, setting = self.planned
        done = self.solves - start
        if self.progress is not None:
            self.progress(done, planned)
        if self.limit is None or planned <= done:
            return
        if done in ESTIMATES or self.spent > self.limit:  # estimated again as it goes: solves differ in cost across a --find's range
            # from the planned solves done so far: the first solve of a run (its modules imported,
            # its caches filled) took 20 times a warm one, and 10⁵ draws of 80 µs were estimated at 171 s
            each = (self.spent - self.spent_before) / done if done else self.spent / max(self.solves, 1)
            estimate = max(self.spent_before + each * planned, self.spent)
            if estimate > self.limit:
                raise _over_budget(setting, planned, each, estimate, self.limit)

    def report(self, moved: Mapping[str, float]) -> Report:
        started = time.perf_counter()
        try:
            return self._report(moved)
        finally:
            self._spend(time.perf_counter() - started)

    def _report(self, moved: Mapping[str, float]) -> Report:
        self.solves += 1
        if self.unknowns:
            given = {**self.given, **{name: x for name, x in moved.items() if name not in self.unknowns}}
            for name in self.unknowns.keys() & moved.keys():
                given = self.unknowns[name].given_with(given, moved[name])
        else:
            given = {**self.given, **moved}
        return pipeline.solve(self.command, given, stdin=self.stdin, spell=self.spell)

    def results(self, moved: Mapping[str, float]) -> dict[str, float] | None:
        """The numeric results with these inputs moved, or None where the scene refuses them
        (the reason kept in ``refusal``)."""
        try:
            return numeric(self.report(moved))
        except OverBudget:
            raise
        except (InputError, OverflowError, ZeroDivisionError, ValueError) as err:
            self.refusal = err
            return None

    def sign(self, name: str) -> str:
        unknown = self.unknowns.get(name)
        return unknown.sign if unknown is not None else self.command.option(name).sign

    def domain(self, name: str) -> tuple[float, float]:
        """The values option ``name`` may take, from its sign."""
        return (-math.inf if self.sign(name) == "any" else 0.0, math.inf)

    def allowed(self, name: str, x: float) -> bool:
        low, high = self.domain(name)
        return low < x < high if self.sign(name) == "positive" else low <= x < high


def _over_budget(setting: str, planned: int, each: float, estimate: float, limit: float) -> OverBudget:
    """The refusal of work estimated past ``limit``, with the setting that would fit."""
    took = f"is estimated to take about {estimate:,.0f} s ({planned:,} solves of about {solve_time(each)} each), over the {limit:.0f} s limit"
    if setting == "mc":
        fits = int(limit / each)
        hint = (f"{{mc}} {fits} fits" if fits >= 2 else "no number of draws fits") + "; {no_limit} runs it as asked"
    else:
        hint = "a faster solve fits (a larger {dt}, or {method} auto where a closed form exists); {no_limit} runs it as asked"
    return OverBudget(setting, took, hint=hint)


def solve_time(each: float) -> str:
    milliseconds = each * 1000
    return f"{milliseconds:.2g} ms" if milliseconds < 10 else f"{milliseconds:,.0f} ms" if milliseconds < 1000 else f"{each:.3g} s"


def readable(command: Command, given: Mapping[str, object], unknown=None) -> dict:
    """The options ``given`` as they can be read with ``unknown`` left out: a spec whose key is
    the unknown with a stand-in value there (0, or 1 where it must be positive), so that the
    spec's other keys are read (a spec without a key it needs is refused), or without that spec
    where even that is refused."""
    if unknown is None or unknown.key is None:
        return dict(given)
    probe = unknown.given_with(given, 1.0 if unknown.sign == "positive" else 0.0)
    try:
        read(command, probe)
    except InputError:
        return {name: value for name, value in given.items() if name != unknown.option.name}
    return probe


def numeric(report: Report) -> dict[str, float]:
    """The results that are numbers (not yes/no, not words, not None)."""
    return {key: float(v.value) for key, v in report.results.items()
            if isinstance(v.value, (float, int)) and not isinstance(v.value, bool) and math.isfinite(v.value)}


def derivative(f: Callable[[float], dict | None], x: float, h: float, allowed: Callable[[float], bool]) -> tuple[dict[str, float], dict[str, float]]:
    """d(each result)/dx by differences with Richardson extrapolation (central where x ± 2h is
    allowed, else one-sided, second order), and an error estimate for each."""
    central = allowed(x - 2 * h) and allowed(x + 2 * h)
    if not central and not allowed(x + 2 * h):
        h = -h  # near the top of the range: difference downward
    if central:
        points = {k: f(x + k * h) for k in (-2, -1, 1, 2)}
    else:
        points = {k: f(x + k * h) for k in (0, 1, 2, 4)}
    if any(value is None for value in points.values()):
        return {}, {}
    slopes, errors = {}, {}
    for key in set.intersection(*(set(p) for p in points.values())):
        v = {k: p[key] for k, p in points.items()}
        if central:
            coarse = (v[2] - v[-2]) / (4 * h)
            fine = (v[1] - v[-1]) / (2 * h)
        else:
            coarse = (-3 * v[0] + 4 * v[2] - v[4]) / (4 * h)
            fine = (-3 * v[0] + 4 * v[1] - v[2]) / (2 * h)
        slopes[key] = (4 * fine - coarse) / 3
        errors[key] = abs(fine - coarse)
    return slopes, errors


def jacobian(scene: Scene, point: Mapping[str, float], scales: Mapping[str, float]) -> dict[str, dict[str, float]]:
    """∂(each result)/∂(each input in ``point``), the others held: {input: {result: slope}}."""
    slopes = {}
    for name, x in point.items():
        h = max(1e-3 * scales[name], 1e-7 * abs(x)) or 1e-7
        slopes[name], _ = derivative(lambda moved, name=name: scene.results({**point, name: moved}), x, h, lambda z, name=name: scene.allowed(name, z))
    return slopes


def combine(slopes: Mapping[str, Mapping[str, float]], spreads: Mapping[str, float], results: Mapping[str, float]) -> dict[str, float]:
    """First-order σ of each numeric result: √Σ (∂r/∂x σx)² over independent inputs."""
    sigma = {}
    for key in results:
        terms = [slopes[name].get(key) for name in spreads]
        if any(term is None for term in terms) and any(spreads[name] for name, term in zip(spreads, terms) if term is None):
            continue  # a result the differences could not reach: no uncertainty claimed
        sigma[key] = math.sqrt(math.fsum((term * spreads[name]) ** 2 for name, term in zip(spreads, terms) if term is not None))
    return sigma


def linearity(scene: Scene, nominal: Report, spreads: Mapping[str, float], slopes: Mapping[str, Mapping[str, float]], point: Mapping[str, float] | None = None) -> list[str]:
    """Notes where the scene is far from linear within ±1σ of an input."""
    point = dict(point or {name: scene.si[name] for name in spreads})
    base = numeric(nominal)
    notes = []
    for name, sigma in spreads.items():
        flag = scene.unknowns[name].spelled if name in scene.unknowns else "{" + name + "}"  # "{particle} 2 speed="
        changes, bent = [], []
        for step in (-sigma, sigma):
            x = point[name] + step
            if not scene.allowed(name, x):
                changes.append(f"{fmt(x)} is outside the range {flag} may take")
                continue
            try:
                moved = scene.report({**point, name: x})
            except (InputError, OverflowError, ZeroDivisionError, ValueError) as err:
                changes.append(f"the scene is refused at {fmt(x)} ({err.expected if isinstance(err, InputError) else err})")
                continue
            if _NUMBERS.sub("#", moved.model) != _NUMBERS.sub("#", nominal.model):  # "29° slope" for "30° slope" is no other model
                changes.append(f"the model becomes “{moved.model}”")
            for key, value in moved.results.items():
                before = nominal.results.get(key)
                if before is not None and (isinstance(value.value, (bool, str)) or value.value is None or before.value is None) and value.value != before.value:
                    changes.append(f"{key} becomes {value.value}")
        if not changes:
            up, down = scene.results({**point, name: point[name] + sigma}), scene.results({**point, name: point[name] - sigma})
            for key, r0 in base.items():
                if up is None or down is None or key not in up or key not in down:
                    continue
                curve = abs(up[key] + down[key] - 2 * r0) / 2  # the second-order term over ±1σ
                if curve > 0.25 * abs(slopes[name].get(key, 0.0)) * sigma and curve > 1e-9 * abs(r0):
                    bent.append(key)
        if changes:
            notes.append(f"within ±1σ of {flag} the scene is far from linear: " + "; ".join(dict.fromkeys(changes)) + " (first-order uncertainties are rough here; --mc N checks them)")
        elif bent:
            notes.append(f"within ±1σ of {flag}, {', '.join(bent)} bend{'s' if len(bent) == 1 else ''} away from first order (the uncertainties are rough; --mc N checks them)")
    return [spelled(note, scene.spell, scene.command.option) for note in notes]


def measured(nominal: Report, sigma: dict[str, float], spreads: Mapping[str, float], notes: list[str]) -> Measured:
    return Measured(
        nominal.scene, nominal.model, nominal.method + "; uncertainties to first order (full Jacobian by differences)",
        nominal.results, list(nominal.steps), [*nominal.notes, *notes], nominal.inputs, nominal.tables, nominal.trajectory,
        uncertainties=sigma, input_uncertainties=dict(spreads),
    )


def monte_carlo(scene: Scene, report: Measured, spreads: Mapping[str, float], draws: int, solve_draw: Callable[[dict], Report | dict | None],
                centres: Mapping[str, float] | None = None, arrays: bool = False) -> None:
    """Draw each uncertain input from its normal distribution (redrawn outside its physical range),
    solve, and keep each numeric result's mean and standard deviation, with a note. ``centres``
    holds the centre of a draw that is not an input (--want's target). ``arrays``: the scene's
    draws may be solved all at once on numpy arrays where it has an array form
    (taucli.answering.mc_arrays: the same draws, the same results to rounding)."""
    import random  # deferred: only --mc draws

    columns, redrawn = draws_of(scene, spreads, draws, random.Random(MC_SEED), centres)
    found = None
    if arrays:
        try:
            from taucli.answering import mc_arrays  # deferred: numpy, only for --mc (and the scalar path where numpy is not installed)
        except ImportError:
            mc_arrays = None
        found = mc_arrays.solved(scene, columns, draws) if mc_arrays is not None else None
    if found is None:
        summaries, failed = _one_by_one(columns, draws, solve_draw, report)
    else:
        results, gave_none = found
        failed = int(gave_none.sum())
        summaries = mc_arrays.summaries(results, gave_none, report.results)
    kept = draws - failed
    report.draws = draws
    report.monte_carlo.update(summaries)
    said = f"Monte Carlo check, {draws} draws (seeded; each uncertain input normal"
    said += ", redrawn outside its physical range)" if redrawn else ")"
    if failed:
        said += f"; {failed} draws gave no scene"
    shown = "; ".join(f"{key} = {with_uncertainty(mean, spread)}" for key, (mean, spread) in report.monte_carlo.items() if key in report.uncertainties)
    report.notes.append(f"{said}: {shown}" if kept else said)


def draws_of(scene: Scene, spreads: Mapping[str, float], draws: int, rng, centres: Mapping[str, float] | None = None) -> tuple[dict[str, list[float]], int]:
    """The draws, input by input (name -> its N values), and how many were redrawn: each draw's
    inputs in the order of ``spreads``, each from rng.gauss about its value (or its ``centres``),
    redrawn (up to 100 times) while outside the range the input may take."""
    gauss = rng.gauss
    plan = []
    for name, sigma in spreads.items():
        if centres and name in centres:
            plan.append((name, centres[name], sigma, None))
        else:
            low, high = scene.domain(name)
            plan.append((name, scene.si[name], sigma, (low, high, scene.sign(name) == "positive")))
    columns: dict[str, list[float]] = {name: [] for name in spreads}
    redrawn = 0
    for _ in range(draws):
        for name, centre, sigma, bounds in plan:
            if bounds is None:
                columns[name].append(gauss(centre, sigma))
                continue
            low, high, strict = bounds
            for _attempt in range(100):  # as Scene.allowed
                x = gauss(centre, sigma)
                if (low < x < high) if strict else (low <= x < high):
                    break
                redrawn += 1
            columns[name].append(x)
    return columns, redrawn


def _one_by_one(columns: Mapping[str, list[float]], draws: int, solve_draw, report: Measured) -> tuple[dict[str, tuple[float, float]], int]:
    """Each draw solved alone: (mean, σ) of each numeric result that two or more draws give, and
    how many draws gave no scene."""
    import statistics  # deferred: 6 ms (it imports fractions and decimal), only for --mc

    samples: dict[str, list[float]] = {}
    failed = 0
    for i in range(draws):
        draw = {name: values[i] for name, values in columns.items()}
        try:
            solved = solve_draw(draw)
        except OverBudget:
            raise
        except (InputError, OverflowError, ZeroDivisionError, ValueError):
            solved = None
        values = numeric(solved) if isinstance(solved, Report) else solved
        if values is None:
            failed += 1
            continue
        for key, value in values.items():
            samples.setdefault(key, []).append(value)
    return {key: (statistics.fmean(values), statistics.stdev(values)) for key, values in samples.items()
            if len(values) >= 2 and key in report.results}, failed
