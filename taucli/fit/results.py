"""The report of a fit: the fitted inputs with their uncertainties, the fit's quality, and the
scene solved at the fitted values, its results carrying the fitted inputs' uncertainties.

Each fitted input is a result under its option's name (``friction``, ``brake.mu``), its standard
uncertainty from the covariance; ``correlation`` (two or more inputs), ``residual_rms``, ``r2``,
``chi2_dof`` (uncertainties given), ``samples`` and ``dropped`` follow (taucli.options.fit). Then
every result of the scene at the fitted values, with the options held and, for a table of runs,
the first sample's own inputs (a time series' time is left out: the scene's whole motion). Its
uncertainties are first order, through the full covariance of the fitted inputs (they are
correlated) and each held input's own: σᵣ² = gᵀCg + Σ_q (∂r/∂q + gᵀ∂p/∂q)² σ_q², g = ∂r/∂p.
"""

from __future__ import annotations

import math

import numpy as np

from taucli.quantities import units
from taucli.core.errors import InputError, spelled
from taucli.fit import quality, solve
from taucli.fit.model import REFUSALS
from taucli.fit.solve import Fit
from taucli.options.fit import COMMAND as FIT
from taucli.answering.propagate import derivative, numeric
from taucli.writing.report import Measured, Report, Step, Table, Value, fmt, pretty_unit, quantity_text

FEW = 5  # degrees of freedom below which the residual variance is a rough stand-in (a note)
EXACT = 1e-9  # residual RMS, of the largest measurement, at or below which the samples are exact values (computed, not measured)


def _label(key: str) -> str:
    return FIT.result(key).label


def label(unknown) -> str:
    """What a fitted input is, from its option's help: "Viscous coefficient b"."""
    said = unknown.label
    if said.count("(") == said.count(")") and len(said) > 5:
        return said
    return unknown.option.help.split(", ")[0].split(". ")[0].rstrip(".")


def scene_inputs(found: Fit) -> dict[str, float]:
    """The sample inputs the scene is solved with at the fitted values: the first sample's, its time
    left out."""
    samples = found.model.samples
    return {name: values[0] for name, values in samples.inputs.items() if name != "time"}


def written(found: Fit) -> Measured:
    model, samples, fitted = found.model, found.model.samples, found.quality
    units_of = [units.KINDS[u.kind].si_unit for u in model.unknowns]
    sigma = np.sqrt(np.diag(found.covariance))
    results: dict[str, Value] = {}
    spreads: dict[str, float] = {}
    for j, unknown in enumerate(model.unknowns):
        results[unknown.name] = Value(float(found.p[j]), units_of[j], f"{label(unknown)}, fitted" + (" (at its bound)" if j in found.bounded else ""))
        spreads[unknown.name] = float(sigma[j])
    for j in found.bounded:  # at its bound: the one-sided 95 % upper limit, bound + 1.645σ
        name = model.names[j]
        results[f"{name}_upper95"] = Value(float(found.p[j] + solve.UPPER * sigma[j]), units_of[j],
                                           f"one-sided 95 % upper limit of {name}, at its bound: bound + {solve.UPPER:.3f}σ")
    if fitted.scaled or fitted.rescaled:  # σ from the residuals' scatter: a 95 % interval from Student's t beside ±1σ
        for j, unknown in enumerate(model.unknowns):
            if j not in found.bounded and j not in found.on_bound:
                results[f"{unknown.name}_ci95"] = _interval(found, j, float(sigma[j]), units_of[j])
    results = {key: results[key] for name in model.names for key in (name, f"{name}_ci95", f"{name}_upper95") if key in results}  # each beside its input
    tables = {}
    if len(model.unknowns) > 1:
        rho = [[round(float(x), 6) for x in row] for row in fitted.correlation]
        results["correlation"] = Value(rho, None, f"correlation of {', '.join(model.names)} (rows and columns in that order)")
        tables["correlation"] = Table((("input", None, ""), *((name, "", name) for name in model.names)),
                                      tuple((name, *(round(x, 3) for x in row)) for name, row in zip(model.names, rho)))
    results["residual_rms"] = Value(fitted.rms, samples.y_unit, f"root mean square of the residuals ({samples.y_key} measured − fitted)")
    results["r2"] = Value(fitted.r2, "", _label("r2"))
    if fitted.chi2_dof is not None:
        results["chi2_dof"] = Value(fitted.chi2_dof, "", f"χ²/ν with the uncertainties given, ν = {fitted.dof} (near 1 for a model that fits)")
    results["samples"] = Value(samples.count, "", _label("samples"))
    results["dropped"] = Value(samples.dropped, "", _label("dropped"))
    notes = list(samples.notes)
    steps = [_samples_step(found), _model_step(found), *found.steps, _uncertainty_step(found, sigma), _quality_step(found)]
    notes += _warnings(found, sigma)
    scene, scene_notes = _scene(found, results, spreads)
    method = found.method + ("; uncertainties from the covariance scaled by the residual variance (no uncertainty given for the samples)"
                             if fitted.scaled else f"; uncertainties from the covariance with the samples' uncertainties ({samples.sigma_source})"
                             + (f" scaled by χ²/ν = {fmt(fitted.chi2_dof, 4)} (--scale-covariance)" if fitted.rescaled else ""))
    if scene is None:
        return Measured("fit", f"{model.command.name}: fitted", method, results, steps, [*notes, *scene_notes], {}, tables, None,
                        uncertainties=spreads, input_uncertainties=dict(model.spreads))
    steps += list(scene.steps)
    return Measured(
        "fit", f"{model.command.name}, {scene.model}", method + "; the scene's results to first order through them", results, steps,
        [*notes, *scene_notes, *scene.notes], scene.inputs, {**tables, **scene.tables}, None,
        uncertainties=spreads, input_uncertainties=dict(model.spreads),
    )


def _interval(found: Fit, j: int, spread: float, unit: str) -> Value:
    """The half-width of input j's 95 % interval, t·σ: Student's t for the residuals' ν = n − m, or
    where held inputs' uncertainties (known, ν = ∞) add to σ, for Welch–Satterthwaite's ν_eff."""
    fitted, name = found.quality, found.model.names[j]
    dof = quality.effective_dof(fitted.dof, math.sqrt(max(fitted.covariance[j, j], 0.0)), spread)
    t = quality.student_t(dof)
    shown = f"ν = {fitted.dof}" if dof == fitted.dof else f"ν_eff = {fmt(dof, 3)}, Welch–Satterthwaite"
    return Value(t * spread, unit, f"95 % interval: {name} ± this (Student's t, {shown}: {t:.3f}σ)")


def _scene(found: Fit, results: dict[str, Value], spreads: dict[str, float]) -> tuple[Report | None, list[str]]:
    """The scene at the fitted values, its results added to ``results`` with their uncertainties."""
    model = found.model
    row = scene_inputs(found)
    try:
        scene = model.report(found.p, row)
    except REFUSALS as err:
        said = err.spelled(model.spell) if isinstance(err, InputError) else str(err)
        return None, [f"the scene at the fitted values is not solved ({said})"]
    notes = []
    if row:
        notes.append("the scene's results are at the fitted values with the first sample's " + ", ".join(
            f"{name} = {quantity_text(value, units.KINDS[model.command.option(name).kind].si_unit)}" for name, value in row.items()))
    base = numeric(scene)
    slopes_p = [_slopes(model, found.p, row, j=j) for j in range(len(found.p))]
    slopes_q = {name: _slopes(model, found.p, row, held=name) for name in model.spreads}
    for key, value in scene.results.items():
        if key in results:
            continue
        results[key] = value
        if key not in base:
            continue
        g = np.array([slopes.get(key, math.nan) for slopes in slopes_p])
        if not np.all(np.isfinite(g)):
            continue
        variance = float(g @ found.quality.covariance @ g)
        for name, spread in model.spreads.items():
            direct = slopes_q[name].get(key, math.nan)
            variance += (direct + float(g @ found.from_held.get(name, np.zeros(len(g))))) ** 2 * spread**2
        if math.isfinite(variance):
            spreads[key] = math.sqrt(max(variance, 0.0))
    return scene, notes


def _slopes(model, p: np.ndarray, row: dict, *, j: int | None = None, held: str | None = None) -> dict[str, float]:
    """∂(each numeric result of the scene)/∂(fitted input j, or the held input ``held``)."""
    def results(x: float) -> dict | None:
        q, moved = np.array(p, dtype=float), None
        if held is None:
            q[j] = x
        else:
            moved = {held: x}
        try:
            return numeric(model.report(q, row, moved))
        except REFUSALS:
            return None

    if held is None:
        x, sign = float(p[j]), model.sign(j)
        h = max(1e-4 * abs(x), 1e-300)
    else:
        x, sign = model.si[held], model.command.option(held).sign
        h = max(1e-3 * model.spreads[held], 1e-7 * abs(x)) or 1e-7
    low = -math.inf if sign == "any" else 0.0
    slopes, _ = derivative(results, x, h, lambda z: z > low if sign == "positive" else z >= low)
    return slopes


def _samples_step(found: Fit) -> Step:
    samples = found.model.samples
    inputs = ", ".join(f"{m.target} (column {m.column.header!r})" for m in samples.columns)
    files = ", ".join(samples.sources())
    left = []
    if samples.outside:
        left.append(f"{samples.outside} outside --range")
    if samples.thinned:
        left.append(f"{samples.thinned} between --every")
    return Step(
        "The samples",
        f"{samples.count} samples of {samples.y_key} (column {samples.y_column.column.header!r}) from {files}",
        why=(f"each sample's own inputs: {inputs}; " if inputs else "") + (f"left out: {', '.join(left)}; " if left else "")
        + "each row is a run of the scene with its own inputs and the options held, in SI from each column's unit",
    )


def _model_step(found: Fit) -> Step:
    model = found.model
    command = model.command
    held = ", ".join(f"{command.flag(name)} = {quantity_text(model.si[name], units.KINDS[command.option(name).kind].si_unit)}" if name in model.si
                     else f"{command.flag(name)} {value}" for name, value in model.held.items() if not isinstance(value, (list, tuple)))
    shown = command.summary.split(":", 1)[-1].strip().rstrip(".")
    return Step(
        f"The model: {command.name}'s {model.samples.y_key} for each sample, with {', '.join(model.names)} to fit",
        f"yᵢ = f(xᵢ; p) + εᵢ,  f = {model.samples.y_key} as taucli {command.name} gives it,  p = ({', '.join(model.names)})",
        why=f"the scene's own model ({shown}) solved for every sample, no curve assumed in its place" + (f"; held: {held}" if held else ""),
    )


def _uncertainty_step(found: Fit, sigma: np.ndarray) -> Step:
    model, fitted = found.model, found.quality
    names = model.names
    shown = ", ".join(f"δ{name} = {quantity_text(s, units.KINDS[u.kind].si_unit)}" for name, s, u in zip(names, sigma, model.unknowns))
    held = "; ".join(f"{model.command.flag(name)} ± {fmt(spread)} moves " + ", ".join(
        f"{n} by ± {fmt(abs(d) * spread)}" for n, d in zip(names, found.from_held.get(name, []))) for name, spread in model.spreads.items())
    unit = pretty_unit(model.samples.y_unit)
    if fitted.scaled:
        equation = "C = s²(JᵀJ)⁻¹,  s² = Σrᵢ²/(n − m)"
        numbers = f"s² = {fmt(fitted.s2)} {squared(unit)}, n = {fitted.n}, m = {fitted.m}".replace(" ,", ",")
        why = "no uncertainty was given for the samples: the scatter of the residuals about the fit stands in for it"
    elif fitted.rescaled:
        equation = "C = (χ²/ν)(JᵀWJ)⁻¹,  W = diag(1/σᵢ²),  χ²/ν = Σ(rᵢ/σᵢ)²/(n − m)"
        numbers = f"σᵢ from {model.samples.sigma_source}, χ²/ν = {fmt(fitted.s2, 4)}, n = {fitted.n}, m = {fitted.m}"
        why = ("--scale-covariance: the uncertainties given weigh the samples, and the scatter of the residuals sets the size "
               "(as lmfit does by default)")
    else:
        equation = "C = (JᵀWJ)⁻¹,  W = diag(1/σᵢ²)"
        numbers = f"σᵢ from {model.samples.sigma_source}, n = {fitted.n}, m = {fitted.m}"
        why = "the uncertainties given for the samples; χ²/ν below says whether they match the scatter"
    if held:
        why += f"; each input held with an uncertainty moves the fit, δp = −(JᵀWJ)⁻¹JᵀW (∂f/∂q) δq, added in quadrature: {held}"
    return Step("The uncertainties: the covariance of the fitted inputs", equation, numbers, shown, why + "; J = ∂f/∂p by differences at the solution")


def squared(unit: str) -> str:
    """A unit squared, as shown: s², (rad/s)²."""
    return "" if not unit else f"({unit})²" if any(sign in unit for sign in "/·*") else f"{unit}²"


def _quality_step(found: Fit) -> Step:
    fitted = found.quality
    parts = [f"RMS = {quantity_text(fitted.rms, found.model.samples.y_unit)}", f"R² = {fmt(fitted.r2) if fitted.r2 is not None else '—'}"]
    equation = "r = y − f(x; p):  RMS = √(Σrᵢ²/n),  R² = 1 − Σrᵢ²/Σ(yᵢ − ȳ)²"
    if fitted.chi2_dof is not None:
        equation += ",  χ²/ν = Σ(rᵢ/σᵢ)²/(n − m)"
        low = fitted.chi2_low is not None and fitted.chi2_low < fitted.chi2_p  # the nearer tail
        p = fitted.chi2_low if low else fitted.chi2_p
        chance = f"P = {p:.2g}" if p > 1e-300 else "P below 1e-300"
        parts.append(f"χ²/ν = {fmt(fitted.chi2, 4)}/{fitted.dof} = {fmt(fitted.chi2_dof, 4)} (a χ² this {'small or smaller' if low else 'large or larger'}: {chance})")
    return Step("The fit's quality", equation, ", ".join(parts), "", _shape(fitted))


def _shape(fitted: quality.Quality) -> str:
    """What the two tests of the residuals' shape say, and which of them these samples are too few for."""
    if not fitted.shape_tested:
        return (f"too few samples ({fitted.n}) for a test of the residuals' shape to reach a chance of {_percent(quality.SHAPE_P)}: "
                "the runs test of their signs needs about 15, their lag-1 autocorrelation 10; not tested")
    verdict = "structured: the model does not describe the samples" if fitted.structured else "no shape seen beyond chance"
    return f"{_tested(fitted)}: {verdict}"


def _percent(p: float) -> str:
    return f"{fmt(100 * p, 2)} %"


def _tested(fitted: quality.Quality) -> str:
    runs, lag = fitted.runs, fitted.lag
    if fitted.runs_weak:
        said = (f"the runs test of their signs cannot reach a chance of {_percent(quality.SHAPE_P)} with {fitted.n} samples "
                + (f"({runs.plus} above, {runs.minus} below the fit: its least is {_percent(runs.least)}), left out" if runs is not None else "(left out)"))
    elif math.isinf(runs.z):
        said = f"every residual has one sign (chance {fmt(runs.p, 2)})"
    else:
        said = (f"{runs.runs} runs of one sign among the residuals, {fmt(runs.expected, 3)} ± {fmt(runs.spread, 2)} expected by chance "
                f"(z = {runs.z:.1f}, chance {fmt(runs.p, 2)} both ways)")
    if not fitted.lag_weak:
        said += f"; their lag-1 autocorrelation r₁ = {lag[0]:.2f} (z = {lag[1]:.1f})"
    else:
        said += f"; their lag-1 autocorrelation cannot reach |z| = {quality.SHAPE_Z:.1f} with {fitted.n} samples, left out"
    return said


SHELL_SPECIAL = set(" *^()[]{}?;&|<>$\\\"'`!#~")  # a text that bash, zsh or fish would read otherwise: quoted in an example


def _range_hint(found: Fit) -> str:
    """Where a model holds over part of the samples only (a coast before the bearing warms, a swing
    while its amplitude is small): --range fits that part alone. The example is the first half of
    the samples' span of their varying input, in its column's unit, as it can be typed."""
    samples = found.model.samples
    if not samples.varying:
        return "where the model holds over part of the samples only, --range COLUMN=FROM..TO fits that part alone"
    key = samples.varying[0]
    values = np.asarray(samples.inputs[key], dtype=float)
    column = next((m for m in samples.columns if m.target == key), None)
    unit, per = ((column.column.unit, column.factor) if column is not None and column.column.unit and column.factor > 0
                 else (units.KINDS[found.model.command.option(key).kind].si_unit, 1.0))
    low, high = float(np.min(values)) / per, float(np.max(values)) / per
    window = f"{'t' if key == 'time' else key}={_typed(low)}{unit}..{_typed((low + high) / 2)}{unit}"
    shown = f"'{window}'" if SHELL_SPECIAL & set(window) else window
    return (f"where the model holds over part of the samples only, --range fits that part alone: the first half of their "
            f"{_typed(low)} to {_typed(high)} {pretty_unit(unit)} is --range {shown}")


def _typed(x: float) -> str:
    """x to 3 significant digits as a person types it: 7380, 0.25, 1.5e-05 (no exponent between 1e-4 and 1e7)."""
    rounded = float(f"{x:.3g}")
    return f"{rounded:f}".rstrip("0").rstrip(".") if rounded == 0 or 1e-4 <= abs(rounded) < 1e7 else f"{rounded:.3g}"


def _warnings(found: Fit, sigma: np.ndarray) -> list[str]:
    model, fitted = found.model, found.quality
    notes = []
    if fitted.scaled:
        notes.append("no uncertainty given for the samples: each fitted input's uncertainty is from the covariance scaled by the residual "
                     "variance (--sigma gives the samples' own, and then χ²/ν)")
    largest = float(np.max(np.abs(model.samples.y))) if model.samples.count else 0.0
    if fitted.scaled and fitted.rms <= EXACT * largest:
        notes.append(f"the samples lie on the model to rounding (residual RMS at most {fmt(EXACT, 1)} of the largest measured, {fmt(largest, 3)}): "
                     "the uncertainties from their scatter are of rounding size, not a measurement's (--sigma gives the samples' own)")
    elif fitted.structured:
        how = (" (they alternate in sign more often than chance: samples of two runs or more, interleaved and fitted as one?)"
               if fitted.alternating else "")
        notes.append(f"warning: the residuals have a shape ({_tested(fitted)}){how}: the model does not describe these samples, "
                     f"and the uncertainties assume that it does (--plot shows the residuals; {_range_hint(found)})")
    elif not fitted.shape_tested:
        notes.append(f"the residuals are not tested for a shape: {fitted.n} samples are too few for the runs test or the autocorrelation "
                     f"to reach a chance of {_percent(quality.SHAPE_P)}, so a model that does not describe them would not be seen here")
    if fitted.r2 is not None and fitted.r2 < 0:
        notes.append(f"warning: R² = {fmt(fitted.r2, 3)} is below 0: the model describes the samples worse than their mean does "
                     "(the wrong scene, the wrong inputs held, or a search that ended far from the samples)")
    flag = fitted.chi2_flag
    if flag is not None:
        p = fitted.chi2_p if flag == "high" else fitted.chi2_low
        chance = f"P = {p:.1g}" if p > 1e-300 else "P below 1e-300"
        scale = math.sqrt(fitted.chi2 / fitted.n)  # the residuals' RMS in units of each sample's σ
        notes.append(f"warning: χ²/ν = {fmt(fitted.chi2_dof, 3)} is unlikely for a model that fits with the uncertainties given ({chance}, "
                     f"{'this large or larger' if flag == 'high' else 'this small or smaller'}): "
                     + (f"the residuals are larger than the uncertainties (their RMS is {fmt(scale, 2)} σ)" if flag == "high"
                        else f"the uncertainties given are larger than the scatter (the residuals' RMS is {fmt(scale, 2)} σ)"))
    if fitted.degeneracy.ratio < quality.NEARLY:
        notes.append(f"warning: {', '.join(fitted.degeneracy.involved)} are barely told apart by these samples (correlation near ±1): "
                     "their uncertainties are large and their values move together")
    for q, chi2 in found.rivals:
        best = float(np.sum((fitted.residuals / (model.samples.sigma if model.samples.sigma is not None else 1.0)) ** 2)) / (1.0 if not fitted.scaled else fitted.s2)
        notes.append(f"warning: another minimum fits about as well ({'χ²' if not fitted.scaled else 'Σr²/s²'} = {fmt(chi2, 4)} against {fmt(best, 4)}, "
                     f"within {fmt(solve.AMBIGUOUS, 3)}) at " + model.shown(dict(zip(model.names, (float(x) for x in q))))
                     + ": the samples do not pick one clearly (another start beside --fit, or samples over more of the motion, may)")
    for j in found.bounded:
        name, unit = model.names[j], units.KINDS[model.unknowns[j].kind].si_unit
        notes.append(f"warning: {name} is at its least value, {quantity_text(float(found.p[j]), unit)}: the samples ask for no more (their best "
                     f"lies at or past it, within noise), so it is given there with its one-sided 95 % upper limit, {name} ≤ "
                     f"{quantity_text(float(found.p[j] + solve.UPPER * sigma[j]), unit, 3)} (bound + {solve.UPPER:.3f}σ, σ = {fmt(sigma[j], 2)}); "
                     "the other inputs are fitted with it there")
    for j in found.on_bound:
        name, unit = model.names[j], units.KINDS[model.unknowns[j].kind].si_unit
        notes.append(f"warning: {name} ends on the bound given (--bound), {quantity_text(float(found.p[j]), unit)}: the samples ask for a value "
                     "past it, so the fit is the best within it, and its uncertainty is the curvature's there, not an interval about the samples' best")
    for j, (name, value, s) in enumerate(zip(model.names, found.p, sigma)):
        if s > abs(value) and j not in found.bounded:
            notes.append(f"{name} is not determined better than its own size ({fmt(value, 3)} ± {fmt(s, 2)}): the samples barely depend on it")
    if fitted.dof < FEW and fitted.scaled:
        notes.append(f"only {fitted.dof} degree{'s' if fitted.dof != 1 else ''} of freedom: the residual variance is a rough stand-in for the samples' own uncertainty")
    return [spelled(note, model.spell, model.command.option) if "{" in note else note for note in notes]
