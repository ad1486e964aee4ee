"""Measurement uncertainty through a whole scene, and the entry for ``--find`` (#22).

A quantity text may carry a standard uncertainty: ``4.0+/-0.1 kg``, ``4.0 ± 0.1 kg``,
``(4.0 ± 0.1) kg``, ``4.0 kg ± 0.1 kg`` or the concise ``4.0(1) kg``. ``split`` reads the text
into the value's text and the uncertainty's (taucli.inputs reads both, in SI). ``solve`` is the
one entry for every surface (the command line, a sweep's point, a batch line, the Python API):
with no uncertainty, no ``--find`` and no ``--mc`` it is ``pipeline.solve`` and nothing else.

Otherwise every result gets a first-order standard uncertainty, from the full Jacobian of the
scene (each uncertain input moves every result; the inputs are taken as independent). The
Jacobian is formed by central differences with Richardson extrapolation: the scene is re-solved
through ``pipeline.solve`` with changed SI inputs (a number given for an option is SI). Complex
steps are not used: the solvers call ``math`` functions, which refuse complex numbers. Near a
physical bound (a mass near 0) the differences are one-sided. Each uncertain input is also moved
by ±1σ: where the scene changes its regime there (a stop, roll or slip, friction that holds) or
a result bends away from its tangent, a note says that first order is rough, and ``--mc N``
(Monte Carlo, N draws) gives a check.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

from taucli.errors import InputError
from taucli.report import Report, fmt
from taucli.table import FILE, Command

PLUS_MINUS = ("±", "+/-")
_NUMBER = r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?"
_LEADING = re.compile(rf"\s*({_NUMBER})\s*(.*?)\s*$")
_PARENTHESISED = re.compile(rf"\s*\(\s*({_NUMBER})\s*(?:±|\+/-)\s*({_NUMBER})\s*\)\s*(.*?)\s*$")
_CONCISE = re.compile(r"\s*([+-]?)(\d+)(?:\.(\d*))?\((\d+)\)((?:[eE][+-]?\d+)?)\s*(.*?)\s*$")
MC_SEED = 22  # Monte Carlo draws are seeded: the same run gives the same check
MC_MAX = 100_000


def marked(value) -> bool:
    """Whether ``value`` may carry an uncertainty (cheap: the plain path asks this of each value)."""
    return isinstance(value, str) and ("±" in value or "+/-" in value or ")" in value)


def split(text: str) -> tuple[str, str] | None:
    """("4.0 kg", "0.1 kg") for "4.0+/-0.1 kg", "4.0 ± 0.1 kg", "(4.0 ± 0.1) kg", "4.0 kg ± 0.1"
    or "4.0(1) kg"; None for a text with no uncertainty. The uncertainty takes the value's unit
    where it has none of its own."""
    concise = _CONCISE.fullmatch(text)
    if concise:
        sign, whole, decimals, digits, exponent, unit = concise.groups()
        decimals = decimals or ""
        places = len(decimals) - (int(exponent[1:]) if exponent else 0)
        spread = f"{int(digits)}e{-places}"
        return f"{sign}{whole}{'.' + decimals if decimals else ''}{exponent} {unit}".strip(), f"{spread} {unit}".strip()
    marker = next((m for m in PLUS_MINUS if m in text), None)
    if marker is None:
        return None
    bracketed = _PARENTHESISED.fullmatch(text)
    if bracketed:
        value, spread, unit = bracketed.groups()
        return f"{value} {unit}".strip(), f"{spread} {unit}".strip()
    left, _, right = text.partition(marker)
    value, spread = _LEADING.fullmatch(left), _LEADING.fullmatch(right)
    if value is None or spread is None:
        return None
    unit = value[2] or spread[2]
    return f"{value[1]} {value[2] or unit}".strip(), f"{spread[1]} {spread[2] or unit}".strip()


def _as_named(name: str) -> str:
    return name


@dataclass
class Measured(Report):
    """A report whose results carry standard uncertainties (SI, as the values)."""

    uncertainties: dict[str, float] = field(default_factory=dict)  # result key -> σ
    input_uncertainties: dict[str, float] = field(default_factory=dict)  # input name -> σ
    monte_carlo: dict[str, tuple[float, float]] = field(default_factory=dict)  # key -> (mean, σ)
    draws: int = 0


def solve(
    command: Command,
    given: Mapping[str, object],
    *,
    find: str | None = None,
    want: str | None = None,
    mc: int | None = None,
    stdin=None,
    spell: Callable[[str], str] = _as_named,
) -> Report:
    """The scene's report, as ``pipeline.solve`` gives it, with uncertainties where any input
    carries one, solved for the input ``find`` where ``want`` (RESULT=VALUE) says."""
    from taucli import pipeline

    if pipeline.plain(given, find, want, mc):
        return pipeline.solve(command, given, stdin=stdin, spell=spell)
    if (find is None) != (want is None):
        raise InputError("find" if find is None else "want", "goes with {" + ("want" if find is None else "find") + "}",
                         example="{find} pulley_inertia {want} a=4.0m/s^2")
    if mc is not None and not 2 <= mc <= MC_MAX:
        raise InputError("mc", f"expected a number of draws from 2 to {MC_MAX}", example="{mc} 2000", got=repr(mc))
    for name, value in given.items():
        option = command.option(name)
        if option is not None and option.kind == FILE and value is not None:
            raise InputError(name, "does not combine with an uncertainty, {find} or {mc}: the scene is solved many times, and a file is read once")
    central, spreads, notes = _read(command, given, spell)
    scene = Scene(command, central, stdin, spell)
    if find is not None:
        from taucli import find as finding

        return finding.solve_for(scene, find, want, spreads, notes, mc)
    nominal = scene.report({})
    if not spreads and not mc:
        return nominal
    slopes = jacobian(scene, {name: scene.si[name] for name in spreads}, spreads)
    sigma = combine(slopes, spreads, numeric(nominal))
    notes = [*notes, *linearity(scene, nominal, spreads, slopes)]
    report = measured(nominal, sigma, spreads, notes)
    if mc:
        monte_carlo(scene, report, spreads, mc, lambda draw: scene.report(draw))
    return report


def _read(command: Command, given: Mapping[str, object], spell) -> tuple[dict, dict[str, float], list[str]]:
    """The options with each value's text in place of "value ± σ", and each σ in SI."""
    from taucli.inputs import read
    from taucli.table import spelled

    _, inputs = read(command, given)
    spreads: dict[str, float] = {}
    notes: list[str] = []
    central = dict(given)
    for key, sigma in (inputs.uncertainties or {}).items():
        option = command.option(key)
        if option is None or not option.is_quantity or option.repeatable:
            notes.append(spelled(f"the uncertainty given in {key} is not carried through: only a scene's own single quantity options carry one", spell, command.option))
            continue
        central[key] = split(given[key])[0]
        if sigma > 0:
            spreads[key] = sigma
    return central, spreads, notes


class Scene:
    """The scene with its options fixed but for the SI values a caller moves."""

    def __init__(self, command: Command, given: dict, stdin, spell):
        from taucli.inputs import read

        self.command, self.given, self.stdin, self.spell = command, given, stdin, spell
        arguments, _ = read(command, given)
        self.si = {name: value for name, value in arguments.items() if isinstance(value, float)}
        self.solves = 0

    def report(self, moved: Mapping[str, float]) -> Report:
        from taucli import pipeline

        self.solves += 1
        return pipeline.solve(self.command, {**self.given, **moved}, stdin=self.stdin, spell=self.spell)

    def results(self, moved: Mapping[str, float]) -> dict[str, float] | None:
        """The numeric results with these inputs moved, or None where the scene refuses them."""
        try:
            return numeric(self.report(moved))
        except (InputError, OverflowError, ZeroDivisionError, ValueError):
            return None

    def domain(self, name: str) -> tuple[float, float]:
        """The values option ``name`` may take, from its sign."""
        sign = self.command.option(name).sign
        return (-math.inf if sign == "any" else 0.0, math.inf)

    def allowed(self, name: str, x: float) -> bool:
        low, high = self.domain(name)
        return low < x < high if self.command.option(name).sign == "positive" else low <= x < high


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
    from taucli.table import spelled

    point = dict(point or {name: scene.si[name] for name in spreads})
    base = numeric(nominal)
    notes = []
    for name, sigma in spreads.items():
        flag = "{" + name + "}"
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
            if moved.model != nominal.model:
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
                centres: Mapping[str, float] | None = None) -> None:
    """Draw each uncertain input from its normal distribution (redrawn outside its physical range),
    solve, and keep each numeric result's mean and standard deviation, with a note. ``centres``
    holds the centre of a draw that is not an input (--want's target)."""
    import random
    import statistics

    rng = random.Random(MC_SEED)
    samples: dict[str, list[float]] = {}
    redrawn = failed = 0
    for _ in range(draws):
        draw = {}
        for name, sigma in spreads.items():
            if centres and name in centres:
                draw[name] = rng.gauss(centres[name], sigma)
                continue
            for _attempt in range(100):
                x = rng.gauss(scene.si[name], sigma)
                if scene.allowed(name, x):
                    break
                redrawn += 1
            draw[name] = x
        try:
            solved = solve_draw(draw)
        except (InputError, OverflowError, ZeroDivisionError, ValueError):
            solved = None
        values = numeric(solved) if isinstance(solved, Report) else solved
        if values is None:
            failed += 1
            continue
        for key, value in values.items():
            samples.setdefault(key, []).append(value)
    kept = draws - failed
    report.draws = draws
    for key, values in samples.items():
        if len(values) >= 2 and key in report.results:
            report.monte_carlo[key] = (statistics.fmean(values), statistics.stdev(values))
    said = f"Monte Carlo check, {draws} draws (seeded; each uncertain input normal"
    said += ", redrawn outside its physical range)" if redrawn else ")"
    if failed:
        said += f"; {failed} draws gave no scene"
    shown = "; ".join(f"{key} = {with_uncertainty(mean, spread)}" for key, (mean, spread) in report.monte_carlo.items() if key in report.uncertainties)
    report.notes.append(f"{said}: {shown}" if kept else said)


def with_uncertainty(value: float, sigma: float | None) -> str:
    """``4.90 ± 0.08``: the uncertainty to one significant digit (two where they begin 10-35),
    the value to the same decimal place."""
    if sigma is None or not math.isfinite(sigma) or not math.isfinite(value):
        return fmt(value, 6)
    if sigma == 0:
        return f"{fmt(value, 6)} ± 0"
    place = math.floor(math.log10(sigma))
    leading = sigma / 10.0 ** (place - 1)
    digits = 2 if leading < 35.5 else 1
    last = place - digits + 1  # the decimal place of the last digit shown
    size = max(abs(value), sigma)
    top = math.floor(math.log10(size)) if size else 0
    if -5 <= last and top < 7:
        decimals = max(0, -last)
        return f"{round(value, -last):.{decimals}f} ± {round(sigma, -last):.{decimals}f}"
    scale = 10.0 ** top
    decimals = max(0, top - last)
    return f"({value / scale:.{decimals}f} ± {sigma / scale:.{decimals}f})e{top}"
