"""One fit, from the options and the samples to the report: the worked solution's order.

1. The model: the scene with the options held, each sample's own inputs, the inputs fitted
   (taucli.fit.model).
2. A start from the scene's closed forms (taucli.fit.start).
3. Linear in the fitted inputs? Then linear least squares, exactly (taucli.fit.linear); else
   bounded nonlinear least squares from the start (taucli.fit.nonlinear).
4. The covariance and the diagnostics; inputs the samples cannot tell apart are refused
   (taucli.fit.quality).
5. Each input held with an uncertainty moves the fit: δp = −(JᵀWJ)⁻¹JᵀW (∂f/∂q) δq, added in
   quadrature to the samples' own scatter.
6. The report: the fitted inputs, the fit's quality, and the scene at the fitted values with
   every result's uncertainty (taucli.fit.results).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from taucli.quantities import units
from taucli.answering import unknowns
from taucli.core.errors import InputError
from taucli.fit import budget, linear, nonlinear, quality, start
from taucli.fit.model import Model, held
from taucli.fit.samples import Samples
from taucli.answering.inputs import read
from taucli.writing.report import Step, fmt, quantity_text
from taucli.options.table import Command


@dataclass
class Fit:
    """What the fit found, for the report (taucli.fit.results) and the chart."""

    model: Model
    p: np.ndarray
    quality: quality.Quality
    covariance: np.ndarray  # of p: the samples' scatter and the held inputs' uncertainties
    from_held: dict[str, np.ndarray]  # held input -> dp/dq
    linear: bool
    method: str
    steps: list[Step] = field(default_factory=list)
    starts: list[str] = field(default_factory=list)  # how each input's start was found: "given", "closed form", "root"


def names_of(text) -> list[str]:
    """The inputs --fit names: "friction,viscous" (spaces allowed), or several such (--fit repeated)."""
    text = ",".join(str(part) for part in text) if isinstance(text, (list, tuple)) else text
    names = [name.strip() for name in str(text or "").replace(" ", ",").split(",") if name.strip()]
    if not names:
        raise InputError("fit", "expected the inputs to fit, by option name", example="{fit} friction,viscous", got=repr(text) if text else None)
    return names


def model_of(command: Command, given: dict, names: list[str], samples: Samples, *, stdin=None, spell=None) -> tuple[Model, dict[str, float], list[str]]:
    """The model, the starts given beside --fit (SI), and the notes reading the options raised."""
    spell = spell or command.flag
    given = dict(given)
    starts: dict[str, float] = {}
    for name in names:
        key = name.strip().lstrip("-").replace("-", "_").lower()
        option = command.option(key)
        if option is not None and not option.repeatable and given.get(key) is not None:
            arguments, _ = read(command, {key: given.pop(key)})
            if isinstance(arguments.get(key), float):
                starts[key] = arguments[key]
    found = []
    for name in names:
        try:
            unknown = unknowns.resolve(command, name, given)
        except InputError as err:  # said of --find, which names inputs as --fit does
            if err.option != "find":
                raise
            raise InputError("fit", err.expected.replace("{find}", "{fit}"), got=err.got, example=err.example and err.example.replace("{find}", "{fit}")) from None
        if unknown.name in {u.name for u in found}:
            raise InputError("fit", f"names {unknown.name} twice", got=repr(name))
        found.append(unknown)
    held_options, spreads, si, notes = held(command, given, spell, found)
    model = Model(command, held_options, found, samples, si=si, spreads=spreads, stdin=stdin, spell=spell)
    return model, starts, notes


def fit(model: Model, starts: dict[str, float]) -> Fit:
    samples = model.samples
    n, m = samples.count, len(model.unknowns)
    if n <= m:
        raise InputError("data", f"gives {n} sample{'s' if n != 1 else ''} for {m} input{'s' if m != 1 else ''} to fit: a fit needs more samples than inputs",
                         hint="give more samples, or fit fewer inputs")
    y = np.asarray(samples.y, dtype=float)
    sigma = np.asarray(samples.sigma, dtype=float) if samples.sigma is not None else None
    if model.budget is not None:  # the least the fit takes, estimated (and refused past the limit) before the work
        budget.before(model, np.array([starts.get(name, 0.0 if model.sign(j) != "positive" else 1.0) for j, name in enumerate(model.names)]))
    p0, steps, how = start.start(model, starts)
    if not np.any(np.isfinite(model.predict(p0))):
        raise InputError("fit", f"the scene gives no {samples.y_key} for any sample at the start ({model.why_refused()})")
    shape = linear.affine(model, p0, np.where(p0 != 0, linear.STEP * np.abs(p0), 1.0))
    _refuse_degenerate(model, shape.X if shape is not None else quality.jacobian(model, p0, rough=True), sigma, p0)  # at the start: before a search that cannot end
    is_linear = False
    if shape is not None:
        p = linear.solve(shape, y, sigma)
        # past a bound the scene has no value to check it by: the bounded search below decides (and refuses there)
        is_linear = all(model.allowed(j, p[j]) for j in range(m)) and linear.holds(model, shape, p)
    if is_linear:
        J = shape.X
        method = f"linear least squares (the model is linear in {', '.join(model.names)}: solved exactly, no iteration)"
        steps.append(_linear_step(model, shape, n))
    else:
        if model.budget is not None:
            model.budget.plan(n, budget.nonlinear_evaluations(m), m)
        outcome = nonlinear.minimize(model, y, sigma, p0)
        if not outcome.converged:  # inputs the samples cannot tell apart leave a valley the search wanders in: say so first
            _refuse_degenerate(model, quality.jacobian(model, outcome.p), sigma, outcome.p)
            raise InputError("fit", f"did not converge ({outcome.message.rstrip('.')}) after {outcome.iterations} steps from the start "
                             + ", ".join(f"{name} = {p:.6g}" for name, p in zip(model.names, p0)), hint="give a start beside --fit, or fit fewer inputs")
        p = outcome.p
        if outcome.at_bound:
            _refuse_bound(model, outcome.at_bound, p)
        missing = nonlinear.stuck(model, p)
        if missing:
            raise InputError("fit", f"ends where the scene gives no {samples.y_key} for {missing} of the samples ({model.why_refused()})")
        polished = _polished(model, p, quality.jacobian(model, p), y, sigma)
        J = quality.jacobian(model, polished) if not np.array_equal(polished, p) else quality.jacobian(model, p)
        p = polished
        started = "a closed-form start" if "closed form" in how else "the starts given" if set(how) == {"given"} else "a start from single samples"
        method = f"bounded nonlinear least squares (trust region reflective, scipy.optimize.least_squares) from {started}"
    _refuse_not_finite(model, J / sigma[:, None] if sigma is not None else J, p)
    order = np.asarray(samples.inputs[samples.varying[0]] if samples.varying else np.arange(n), dtype=float)
    found = quality.assess(y, model.predict(p), J, sigma, order, model.names, p)
    covariance, from_held = _with_held(model, p, J, sigma, found.covariance)
    if not is_linear:
        spread = np.sqrt(np.abs(np.diag(covariance)))
        steps.append(Step(
            "Minimise the squares of the residuals within the inputs' bounds",
            ("min Σᵢ ((yᵢ − f(xᵢ; p))/σᵢ)²" if sigma is not None else "min Σᵢ (yᵢ − f(xᵢ; p))²") + f" over {', '.join(_bound(model, j) for j in range(m))}",
            result=", ".join(f"{u.name} = {quantity_text(value, units.KINDS[u.kind].si_unit, digits_known(value, uncertainty))}"
                             for u, value, uncertainty in zip(model.unknowns, p, spread)),
            why=f"trust region reflective (scipy) from the start: {_count(outcome.iterations, 'step')}, {_count(outcome.evaluations, 'solve')} of the scene per sample "
            f"(its Jacobian by differences); it stops where a step changes the sum or p by less than {nonlinear.TOLERANCE:g} of them; "
            f"shown to a thousandth of each one's uncertainty (the digits past that are the search's rounding)",
        ))
    return Fit(model, p, found, covariance, from_held, is_linear, method, steps, how)


GUARD = 3  # decimal places shown past an uncertainty's leading digit: a thousandth of it
KNOWN_DIGITS = 8  # at most: the search stops at a relative 1e-10, and the last digits of a solve are rounding


def digits_known(value: float, uncertainty: float) -> int:
    """Significant figures of a fitted value that its uncertainty and the search's tolerance
    determine: down to a thousandth of the uncertainty, 3 to KNOWN_DIGITS of them. Past that the
    digits change with numpy's and scipy's versions and the search's path, not with the samples."""
    if not (value and math.isfinite(value) and uncertainty > 0 and math.isfinite(uncertainty)):
        return 6
    known = math.floor(math.log10(abs(value))) - math.floor(math.log10(uncertainty)) + GUARD + 1
    return max(3, min(KNOWN_DIGITS, known))


def _count(n: int, what: str) -> str:
    return f"{n} {what}{'' if n == 1 else 's'}"


def _polished(model: Model, p: np.ndarray, J: np.ndarray, y: np.ndarray, sigma) -> np.ndarray:
    """Up to two Gauss–Newton steps with the accurate Jacobian from where the search stopped (within
    its tolerance of the least squares), each kept where it does not raise the sum (beyond rounding)
    and stays within the bounds: the solution does not depend on the search's path to its last digits."""
    weights = 1.0 / sigma if sigma is not None else np.ones(len(y))
    for _ in range(2):
        before = (y - model.predict(p)) * weights
        if not (np.all(np.isfinite(J * weights[:, None])) and np.all(np.isfinite(before))):
            return p  # (numbers past a double's range: the fit is refused after, where its Jacobian is looked at)
        moved = p + np.linalg.lstsq(J * weights[:, None], before, rcond=None)[0]
        if not all(model.allowed(j, moved[j]) for j in range(len(p))):
            return p
        after = (y - model.predict(moved)) * weights
        if not (np.all(np.isfinite(after)) and np.sum(after**2) <= np.sum(before**2) * (1 + 1e-9)):  # (at the bottom the sums differ by rounding)
            return p
        p = moved
    return p


def _with_held(model: Model, p: np.ndarray, J: np.ndarray, sigma, covariance: np.ndarray) -> tuple[np.ndarray, dict[str, np.ndarray]]:
    """The covariance of p with each held input's uncertainty added: δp = −(JᵀWJ)⁻¹JᵀW (∂f/∂q) δq."""
    weights = 1.0 / sigma**2 if sigma is not None else np.ones(J.shape[0])
    normal = J.T @ (J * weights[:, None])
    total = covariance.copy()
    slopes: dict[str, np.ndarray] = {}
    for name, spread in model.spreads.items():
        x = model.si[name]
        h = max(1e-3 * spread, 1e-7 * abs(x)) or 1e-7
        option = model.command.option(name)
        low = -math.inf if option.sign == "any" else 0.0
        if x - h > low:
            df = (model.predict(p, {name: x + h}) - model.predict(p, {name: x - h})) / (2 * h)
        else:
            df = (model.predict(p, {name: x + h}) - model.predict(p)) / h
        if not np.all(np.isfinite(df)):
            continue
        dp = -np.linalg.solve(normal, J.T @ (df * weights))
        slopes[name] = dp
        total += np.outer(dp, dp) * spread**2
    return total, slopes


def _refuse_not_finite(model: Model, J: np.ndarray, p: np.ndarray) -> None:
    """The (weighted) Jacobian at the fitted inputs must be finite for the covariance: where the
    scene has no value just beside them (an input at its bound) or its result changes past what a
    double holds, the fit is refused (a linear algebra routine given a NaN fails, and LAPACK says
    so on stdout)."""
    if not np.all(np.isfinite(J)):
        at = ", ".join(f"{name} = {value:.6g}" for name, value in zip(model.names, p))
        why = model.why_refused() if model.refusal is not None else f"{model.samples.y_key} changes past what a double holds"
        raise InputError("fit", f"ends where the scene has no {model.samples.y_key}, or none a double holds, just beside the inputs fitted "
                         f"({at}: {why}), so the fit's uncertainties cannot be worked out there", hint="give magnitudes nearer everyday sizes, or fit fewer inputs")


def _refuse_degenerate(model: Model, J: np.ndarray, sigma, p: np.ndarray) -> None:
    weighted = J / sigma[:, None] if sigma is not None else J
    if not np.all(np.isfinite(weighted)):
        return  # some sample has no value here: the fit decides
    f = model.predict(p) / (sigma if sigma is not None else 1.0)
    found = quality.degeneracy(weighted, model.names, p, f)
    if found.flat or found.ratio < quality.DEGENERATE:
        quality.refuse_degenerate(found, model.samples.y_key, f" (the scene gives {_at_first(model, p)})")


def _at_first(model: Model, p: np.ndarray) -> str:
    """What the scene gives at the first sample, against what was measured there: "omega = 0 rad/s
    at the first sample (time = 0 s), measured 30.1 rad/s"."""
    samples = model.samples
    key, unit = samples.y_key, samples.y_unit
    row = ", ".join(f"{name} = {quantity_text(value, units.KINDS[model.command.option(name).kind].si_unit)}" for name, value in samples.row(0).items())
    return (f"{key} = {quantity_text(model.predict(p)[0], unit)} at the first sample" + (f" ({row})" if row else "")
            + f" with {', '.join(f'{n} = {v:.6g}' for n, v in zip(model.names, p))}; measured {quantity_text(samples.y[0], unit)}")


def _bound(model: Model, j: int) -> str:
    name = model.names[j]
    sign = model.sign(j)
    return f"{name} {'> 0' if sign == 'positive' else '≥ 0' if sign == 'nonnegative' else 'free'}"


def _refuse_bound(model: Model, at: list[int], p: np.ndarray) -> None:
    names = [model.names[j] for j in at]
    shown = ", ".join(f"{model.names[j]} = {quantity_text(p[j], units.KINDS[model.unknowns[j].kind].si_unit, 3)}" for j in at)
    raise InputError("fit", f"the samples ask for {' and '.join(names)} at or past {'its' if len(at) == 1 else 'their'} least value ({shown}), "
                     f"which the scene cannot take: the model does not describe these samples with {' and '.join(names)} free",
                     hint=f"leave {' and '.join(names)} out of --fit, or look at the samples (--range, the plot)")


def _linear_step(model: Model, shape: linear.Linear, n: int) -> Step:
    return Step(
        "The model is linear in the inputs fitted: linear least squares",
        linear.form(model.command.name, model.samples.y_key) + ",  so f(p) = f(p₀) + X(p − p₀) exactly",
        result="p − p₀ = the least-squares solution of (WX)δ = W(y − f(p₀)), by the SVD",
        why=f"checked on the scene, not assumed: f at p₀, at p₀ + Δ and p₀ + 2Δ along each input, and with all moved; every second "
        f"difference and cross term is below {fmt(linear.TOLERANCE)} of f (rounding), so X = ∂f/∂p is exact and the least squares over "
        f"the {n} samples has one solution, with no start nor iteration; the forward solve there gives f(p₀) + Xδ again",
    )
