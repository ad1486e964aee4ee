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
    bounded: list[int] = field(default_factory=list)  # the inputs held at their bound (0), the samples asking for no more
    rivals: list[tuple[np.ndarray, float]] = field(default_factory=list)  # other minima from other starts that fit as well: (p, χ²)
    on_bound: list[int] = field(default_factory=list)  # the inputs that ended on a --bound given (the samples ask for a value past it)


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


def fit(model: Model, starts: dict[str, float], *, rescale: bool = False) -> Fit:
    """The fit from the starts; ``rescale``: with σ given, the covariance scaled by χ²/ν (taucli.fit.quality.assess)."""
    samples = model.samples
    n, m = samples.count, len(model.unknowns)
    if n <= m:
        raise InputError("data", f"gives {n} sample{'s' if n != 1 else ''} for {m} input{'s' if m != 1 else ''} to fit: a fit needs more samples than inputs",
                         hint="give more samples, or fit fewer inputs")
    y = np.asarray(samples.y, dtype=float)
    sigma = np.asarray(samples.sigma, dtype=float) if samples.sigma is not None else None
    if model.budget is not None:  # the least the fit takes, estimated (and refused past the limit) before the work
        budget.before(model, np.array([starts.get(name, 0.0 if model.sign(j) != "positive" else 1.0) for j, name in enumerate(model.names)]))
    candidates = start.starts(model, starts)
    p0, steps, how = candidates[0]
    if not np.any(np.isfinite(model.predict(p0))):
        raise InputError("fit", f"the scene gives no {samples.y_key} for any sample at the start ({model.why_refused()})")
    natural = np.where(np.abs(p0) > 0, np.abs(p0), 1.0)  # each input's natural size: its start's (1 SI where that is 0)
    shape = linear.affine(model, p0, np.where(p0 != 0, linear.STEP * np.abs(p0), 1.0))
    # at the start: inputs the samples cannot tell apart, before a search that cannot end (one that does not act there may further on)
    flat = _refuse_degenerate(model, shape.X if shape is not None else quality.jacobian(model, p0, rough=True, scale=natural), sigma, p0, natural, start=True)
    if flat:  # an input that does not act at the start says nothing of the model's shape elsewhere: searched for, not solved as linear
        shape = None
    bounded: list[int] = []
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
            model.budget.plan(n, budget.nonlinear_evaluations(m), m, budget.per_evaluation(model))
        searches, refusals = [], []
        for number, (q0, q_steps, q_how) in enumerate(candidates):
            if number and not _worth(model, q0, [c[0] for c in candidates[:number]], y, sigma):
                continue
            try:
                searches.append((_search(model, y, sigma, q0, natural), q_steps, q_how))
            except InputError as err:
                refusals.append(err)
        if not searches:
            raise refusals[0]
        least = min(found.cost for found, _, _ in searches)
        best = next(k for k, (found, _, _) in enumerate(searches) if found.cost <= least * (1 + SAME_COST) + 1e-300)  # ties: the first start
        (search, steps, how), others = searches[best], [found for k, (found, _, _) in enumerate(searches) if k != best]
        steps = list(steps)
        p, bounded, J, outcome = search.p, search.bounded, search.J, search.outcome
        started = "a closed-form start" if "closed form" in how else "the starts given" if set(how) == {"given"} else "a start from single samples"
        method = f"bounded nonlinear least squares (trust region reflective, scipy.optimize.least_squares) from {started}"
    on_bound = [j for j in range(m) if model.on_user_bound(j, p[j], USER_BOUND * natural[j])]
    for j in on_bound:  # on it (the reflective search nears a bound without reaching it)
        p[j] = model.lower(j) if p[j] - model.lower(j) <= model.upper(j) - p[j] else model.upper(j)
    _refuse_not_finite(model, J / sigma[:, None] if sigma is not None else J, p)
    order = np.asarray(samples.inputs[samples.varying[0]] if samples.varying else np.arange(n), dtype=float)
    found = quality.assess(y, model.predict(p), J, sigma, order, model.names, p, natural, rescale=rescale)
    for j in range(m):  # nearer its bound than a millionth of its σ (the reflective search nears a bound without reaching it): on it
        if (j not in bounded and model.sign(j) == "nonnegative" and p[j] - model.natural_lower(j) <= NEAR_BOUND * math.sqrt(max(found.covariance[j, j], 0.0))
                and not model.on_user_bound(j, p[j], NEAR_BOUND * natural[j])):
            p, held = _at_bound(model, [*bounded, j], p, y, sigma, natural)
            bounded = held
    covariance, from_held = _with_held(model, p, J, sigma, found.covariance)
    rivals = _rivals(p, search.cost, others, found, sigma is None) if not is_linear else []
    if not is_linear:
        spread = np.sqrt(np.abs(np.diag(covariance)))
        steps.append(Step(
            "Minimise the squares of the residuals within the inputs' bounds",
            ("min Σᵢ ((yᵢ − f(xᵢ; p))/σᵢ)²" if sigma is not None else "min Σᵢ (yᵢ − f(xᵢ; p))²") + f" over {', '.join(_bound(model, j) for j in range(m))}",
            result=", ".join(f"{u.name} = {quantity_text(value, units.KINDS[u.kind].si_unit, digits_known(value, uncertainty))}"
                             for u, value, uncertainty in zip(model.unknowns, p, spread)),
            why=f"trust region reflective (scipy) from the start: {_count(outcome.iterations, 'step')}, "
            + (f"{_count(outcome.evaluations, 'run')} of the scene, each read at every sample's time" if model.series
               else f"{_count(outcome.evaluations, 'solve')} of the scene per sample")
            + f" (its Jacobian by differences); it stops where a step changes the sum or p by less than {nonlinear.TOLERANCE:g} of them; "
            f"shown to a thousandth of each one's uncertainty (the digits past that are the search's rounding)"
            + (f"; searched from {len(searches)} starts, this the least sum" if len(searches) > 1 else ""),
        ))
    return Fit(model, p, found, covariance, from_held, is_linear, method, steps, how, bounded, rivals, on_bound)


USER_BOUND = 1e-6  # of an input's natural size: this near a --bound, the fit ends on it


def bounds_of(model: Model, texts, gravity=None) -> None:
    """--bound NAME=FROM..TO for fitted inputs (either end open), read in the input's kind: model.bounds."""
    for text in texts or ():
        name, sep, span = str(text).partition("=")
        low_text, dots, high_text = span.partition("..")
        name = name.strip().lstrip("-").replace("-", "_")
        if not sep or not dots:
            raise InputError("bound", "expected NAME=FROM..TO, a fitted input and its range", example="{bound} 'viscous=0..0.01N*m*s'", got=repr(text))
        if name not in model.names:
            raise InputError("bound", f"expected an input named in {{fit}} ({', '.join(model.names)}); one held fixed is given as the scene's option",
                             example="{bound} 'viscous=0..0.01N*m*s'", got=repr(name))
        if name in model.bounds:
            raise InputError("bound", f"is given twice for {name}", got=repr(text))
        kind = model.unknowns[model.names.index(name)].kind
        ends = [default if not part.strip() else units.parse(part, "{bound}", kind, sign="any", gravity=gravity).value
                for part, default in ((low_text, -math.inf), (high_text, math.inf))]
        j = model.names.index(name)
        if not ends[0] < ends[1] or ends[1] <= model.natural_lower(j):
            raise InputError("bound", f"expected FROM below TO, and TO above {name}'s least value", example="{bound} 'viscous=0..0.01N*m*s'", got=repr(text))
        model.bounds[name] = (ends[0], ends[1])


SAME_COST = 1e-8  # two minima whose sums differ by less than this of them are one (the first start's is kept)
WORSE = 4.0  # a further start whose sum is more than this times an earlier start's is not searched from
AMBIGUOUS = 3.84  # χ² (in the residual variance where no σ is given) within which another minimum fits as well: χ²'s 95 % point for one degree of freedom
APART = 3.0  # σ apart: another minimum with an input this far from the best is another answer


@dataclass
class Search:
    p: np.ndarray
    bounded: list[int]
    J: np.ndarray
    outcome: nonlinear.Outcome
    cost: float  # Σ((yᵢ − f)/σᵢ)² at p


def _cost(model: Model, p: np.ndarray, y: np.ndarray, sigma) -> float:
    r = (y - model.predict(p)) / (sigma if sigma is not None else 1.0)
    return float(np.sum(r**2)) if np.all(np.isfinite(r)) else math.inf


def _worth(model: Model, q0: np.ndarray, earlier: list[np.ndarray], y: np.ndarray, sigma) -> bool:
    """A further start is searched from unless its sum is more than WORSE times an earlier one's."""
    return _cost(model, q0, y, sigma) <= WORSE * min(_cost(model, e, y, sigma) for e in earlier)


def _search(model: Model, y: np.ndarray, sigma, p0: np.ndarray, natural: np.ndarray) -> Search:
    """The bounded nonlinear least squares from p0, polished; refused where it does not converge,
    ends past a bound the samples ask for, or where the scene gives no value."""
    outcome = nonlinear.minimize(model, y, sigma, p0)
    if not outcome.converged:  # inputs the samples cannot tell apart leave a valley the search wanders in: say so first
        _refuse_degenerate(model, quality.jacobian(model, outcome.p, scale=natural), sigma, outcome.p, natural)
        raise InputError("fit", f"did not converge ({outcome.message.rstrip('.')}) after {outcome.iterations} steps from the start "
                         + ", ".join(f"{name} = {p:.6g}" for name, p in zip(model.names, p0)), hint="give a start beside --fit, or fit fewer inputs")
    p, bounded = outcome.p, []
    if outcome.at_bound:
        p, bounded = _at_bound(model, outcome.at_bound, p, y, sigma, natural)
    missing = nonlinear.stuck(model, p)
    if missing:
        raise InputError("fit", f"ends where the scene gives no {model.samples.y_key} for {missing} of the samples ({model.why_refused()})")
    polished = _polished(model, p, quality.jacobian(model, p, scale=natural), y, sigma, bounded)
    J = quality.jacobian(model, polished, scale=natural) if not np.array_equal(polished, p) else quality.jacobian(model, p, scale=natural)
    return Search(polished, bounded, J, outcome, _cost(model, polished, y, sigma))


def _rivals(p: np.ndarray, cost: float, others: list[Search], found: quality.Quality, scaled: bool) -> list[tuple[np.ndarray, float]]:
    """The other minima that fit about as well (χ² within AMBIGUOUS of the best, in the residual
    variance where no σ is given) with some input APART σ or more from the best: (p, χ²) each."""
    unit = found.s2 if scaled else 1.0
    spread = np.sqrt(np.abs(np.diag(found.covariance)))
    kept: list[tuple[np.ndarray, float]] = []
    for other in others:
        if math.isfinite(other.cost) and (other.cost - cost) / unit < AMBIGUOUS and np.any(np.abs(other.p - p) > APART * spread):
            if all(np.any(np.abs(other.p - q) > APART * spread) for q, _ in kept):
                kept.append((other.p, other.cost / unit))
    return kept


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


def _polished(model: Model, p: np.ndarray, J: np.ndarray, y: np.ndarray, sigma, held=()) -> np.ndarray:
    """Up to two Gauss–Newton steps with the accurate Jacobian from where the search stopped (within
    its tolerance of the least squares), each kept where it does not raise the sum (beyond rounding)
    and stays within the bounds: the solution does not depend on the search's path to its last digits.
    The inputs ``held`` at their bounds stay there."""
    weights = 1.0 / sigma if sigma is not None else np.ones(len(y))
    J = np.array(J, dtype=float)
    J[:, list(held)] = 0.0  # the least-norm step leaves them where they are
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


def _refuse_degenerate(model: Model, J: np.ndarray, sigma, p: np.ndarray, natural: np.ndarray, *, start: bool = False) -> list[str]:
    """Refused where the samples cannot tell the inputs apart (or do not depend on one). At the
    ``start``, an input the samples do not depend on there is left to the search (a start such as
    --viscous 3 stops the wheel before the second sample, where friction does not act), and the
    others are checked among themselves; the fit's end checks them all."""
    weighted = J / sigma[:, None] if sigma is not None else J
    if not np.all(np.isfinite(weighted)):
        return []  # some sample has no value here: the fit decides
    f = model.predict(p) / (sigma if sigma is not None else 1.0)
    found = quality.degeneracy(weighted, model.names, p, f, natural)
    flat = list(found.flat)
    if start and flat:
        acting = [j for j, name in enumerate(model.names) if name not in flat]
        if len(acting) < 2:
            return flat
        found = quality.degeneracy(weighted[:, acting], [model.names[j] for j in acting], p[acting], f, natural[acting])
    if found.flat or found.ratio < quality.DEGENERATE:
        quality.refuse_degenerate(found, model.samples.y_key, f" (the scene gives {_at_first(model, p)})")
    return flat


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
    if name in model.bounds:  # --bound
        low, high = model.lower(j), model.upper(j)
        return (f"{fmt(low)} ≤ " if math.isfinite(low) else "") + name + (f" ≤ {fmt(high)}" if math.isfinite(high) else "")
    return f"{name} {'> 0' if sign == 'positive' else '≥ 0' if sign == 'nonnegative' else 'free'}"


NEAR_BOUND = 1e-6  # of an input's σ: this near its bound it is on it
BOUND_P = 1e-3  # the chance of χ² falling this much past the bounds by noise alone: more, and the samples ask for a value past them
UPPER = 1.6449  # the normal's one-sided 95 % point: an input held at its bound is given as at most bound + UPPER·σ


def _at_bound(model: Model, at: list[int], p: np.ndarray, y: np.ndarray, sigma, natural: np.ndarray) -> tuple[np.ndarray, list[int]]:
    """The inputs the search left on their bounds, held there: each one that may be 0 (a friction
    torque, a drag), where the samples' best without the bounds lies within noise of them (the fit
    then reports it at the bound with a one-sided upper limit). The best without the bounds is one
    Gauss–Newton step from them, δ = (JᵀWJ)⁻¹JᵀWr, and it would lower χ² by |J δ|²_W (in units of
    the residual variance where no σ is given): more than χ²'s 0.1 % point for as many degrees of
    freedom as inputs held (10.8 for one), and the samples ask for a value far past
    the bounds: the model does not describe them, refused. An input that may not be 0 (a moment of
    inertia) is refused on its bound."""
    strict = [j for j in at if model.sign(j) == "positive"]
    if strict:
        _refuse_bound(model, strict, p)
    p = np.array(p, dtype=float)
    for j in at:
        p[j] = model.natural_lower(j)
    J = quality.jacobian(model, p, scale=natural)
    weights = 1.0 / sigma if sigma is not None else np.ones(len(y))
    r = (y - model.predict(p)) * weights
    Jw = J * weights[:, None]
    if not (np.all(np.isfinite(Jw)) and np.all(np.isfinite(r))):
        return p, list(at)
    step = np.linalg.lstsq(Jw, r, rcond=None)[0]
    n, m = Jw.shape
    s2 = 1.0 if sigma is not None else float(np.sum((r - Jw @ step) ** 2)) / max(n - m, 1)
    past = [j for j in at if step[j] < 0]
    if past:
        from scipy.special import chdtri  # deferred: χ²'s inverse tail as scipy.stats.chi2.isf works it, without importing scipy.stats

        gain = float(np.sum((Jw @ step) ** 2)) / s2 if s2 > 0 else math.inf
        if gain > float(chdtri(len(past), BOUND_P)):
            _refuse_bound(model, past, p, gain)
    return p, list(at)


def _refuse_bound(model: Model, at: list[int], p: np.ndarray, gain: float | None = None) -> None:
    names = [model.names[j] for j in at]
    shown = ", ".join(f"{model.names[j]} = {quantity_text(p[j], units.KINDS[model.unknowns[j].kind].si_unit, 3)}" for j in at)
    far = (f"; past the bound χ² would fall by {fmt(gain, 3)}, beyond what noise gives at {fmt(100 * BOUND_P, 1)} %" if gain is not None else "")
    raise InputError("fit", f"the samples ask for {' and '.join(names)} at or past {'its' if len(at) == 1 else 'their'} least value ({shown}{far}), "
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
