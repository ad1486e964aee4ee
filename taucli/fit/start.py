"""Where a nonlinear fit starts: from the scene's closed forms, never from 1.

In this order, for each fitted input:

1. a value given for it beside ``--fit`` (``--friction 0.2N*m --fit friction``);
2. the scene's own equations, rearranged to be linear in the inputs sought and regressed over
   the samples (``CLOSED``):
   - spin-down, a coast-down ω(t) (or θ(t)): I dω/dt = τ − τ_f − bω − kωⁿ integrated over the
     samples, ω(t) − ω(t₁) = ((τ − τ_f)/I)(t − t₁) − (b/I)∫ω dt − (k/I)∫ωⁿ dt, is linear in its
     coefficients (integrating smooths the noise that differentiating would raise);
   - atwood, each run's acceleration (a, or 2d/t², or v²/2d): the equations of the masses and the
     pulley added, (m₁ − m₂)g − (I/R²)a − τ_f/R = (m₁ + m₂)a, linear in g, I and τ_f;
   - rolling down an incline, each run's acceleration: g sin θ − a k² = a, linear in g and k²;
   - a pendulum's swing θ(t): the amplitude and the period from its spectrum, g from the scene's
     own period at one g (the period goes as 1/√g at a given amplitude); runs of periods at their
     amplitudes: T = √(g₀/g)·T₀ for each, linear in √(g₀/g) (taucli.fit.swing);
3. else the roots of a few samples, as ``--find`` finds them (taucli.numerics.steppers.roots), the others at their
   starts (or 0): the one that best meets the samples (least squares over up to 40 of them).

Where none gives a value, the fit is refused, asking for a start.

``starts`` gives the fit more than one start where one may mislead: the closed form beside the
values given (a start such as --viscous 3 may stop the wheel before the second sample), and a
scene's other closed forms (a swing's period from its zero crossings beside its spectrum's). The
fit searches from each and keeps the least χ² (taucli.fit.solve).
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from taucli.numerics import roots
from taucli.quantities import units
from taucli.core.errors import InputError
from taucli.fit import decay, swing
from taucli.fit.model import Model
from taucli.writing.report import Step, fmt, quantity_text
from taucli.scenes.assumed import STANDARD_GRAVITY

ROWS = 5  # samples a root is sought in, for the generic start
CHECKED = 40  # samples each root is tried on
CANDIDATES = 40  # roots tried, those nearest the median of all found
NEARLY_DEPENDENT = 1e-3  # singular values of a closed form's columns (unit length) below this of the largest are cut


def _regress(columns: dict[str, np.ndarray], rhs: np.ndarray) -> dict[str, float] | None:
    """Least squares (the least-norm one where the columns are dependent: a start all the same, and
    the fit then names the inputs the samples cannot tell apart)."""
    names = list(columns)
    A = np.column_stack([columns[name] for name in names])
    if not np.all(np.isfinite(A)) or not np.all(np.isfinite(rhs)) or not len(rhs):
        return None
    norms = np.linalg.norm(A, axis=0)
    norms = np.where(norms > 0, norms, 1.0)
    solution = np.linalg.lstsq(A / norms, rhs, rcond=NEARLY_DEPENDENT)[0] / norms  # columns to unit length: nearly dependent ones cut
    return dict(zip(names, (float(v) for v in solution)))


def _values(model: Model, i: int) -> dict[str, float]:
    """The SI inputs of sample i: those held and its own."""
    return {**model.si, **model.samples.row(i)}


def _accelerations(model: Model, along: Callable[[dict], float | None]) -> np.ndarray | None:
    """Each sample's acceleration from its measurement: a, 2d/t², v²/2d or v/t (None where the
    result measured gives none). ``along`` is the distance of a sample (its run's length)."""
    key, y = model.samples.y_key, np.asarray(model.samples.y)
    found = []
    for i, measured in enumerate(y):
        values = _values(model, i)
        d, t = along(values), values.get("time")
        if key == "a":
            found.append(measured)
        elif key == "t" and d:
            found.append(2 * d / measured**2)
        elif key == "v" and d:
            found.append(measured**2 / (2 * d))
        elif key == "v" and t:
            found.append(measured / t)
        elif key == "distance" and t:
            found.append(2 * measured / t**2)
        else:
            return None
    return np.array(found)


def _atwood(model: Model) -> tuple[dict[str, float], Step] | None:
    plain = ("incline", "mu_k", "mu_s", "rim_mu", "radius1", "radius2", "part", "v0", "torque", "side1", "side2", "pull", "fixed_drum")
    if any(name in model.held for name in plain) or not set(model.names) <= {"g", "pulley_inertia", "pulley_mass", "axle_friction"}:
        return None
    a = _accelerations(model, lambda v: v.get("distance"))
    if a is None:
        return None
    rows = [_values(model, i) for i in range(len(a))]
    m1, m2 = np.array([v.get("m1", math.nan) for v in rows]), np.array([v.get("m2", 0.0) for v in rows])
    radius = np.array([v.get("pulley_radius", math.nan) for v in rows])
    share = 1.0 if model.held.get("pulley_shape") == "ring" else 0.5
    columns, rhs = {}, (m1 + m2) * a
    g = np.array([v.get("g", STANDARD_GRAVITY) for v in rows])
    if "g" in model.names:
        columns["g"] = m1 - m2
    else:
        rhs = rhs - (m1 - m2) * g
    for name, column, known in (
        ("pulley_inertia", -a / radius**2, lambda v: v.get("pulley_inertia", 0.0) / v.get("pulley_radius", math.inf) ** 2),
        ("pulley_mass", -a * share, lambda v: share * v.get("pulley_mass", 0.0)),
        ("axle_friction", -1.0 / radius, lambda v: v.get("axle_friction", 0.0) / v.get("pulley_radius", math.inf)),
    ):
        if name in model.names:
            columns[name] = column
        else:
            rhs = rhs + np.array([known(v) for v in rows]) * (a if name != "axle_friction" else 1.0)
    found = _regress(columns, rhs)
    if found is None:
        return None
    return found, Step(
        "A start from the machine's equations, linear in the inputs sought",
        "(m₁ − m₂)g − (I/R²)a − τ_f/R = (m₁ + m₂)a",
        result=model.shown(found),
        why=f"each run's a from its measured {model.samples.y_key}" + (" (a = 2d/t²)" if model.samples.y_key == "t" else "")
        + f", least squares over {len(a)} runs: the equations of m₁, m₂ and the pulley added (the tensions cancel) are linear in g, I and "
        "τ_f once a is known; the fit below then matches the measured result itself",
    )


def _rolling(model: Model) -> tuple[dict[str, float], Step] | None:
    plain = ("pull", "yoyo", "v0", "omega0", "axle_radius", "mu_k", "hanging_mass")
    if any(name in model.held for name in plain) or not set(model.names) <= {"g", "k2"}:
        return None
    rows = [_values(model, i) for i in range(model.samples.count)]
    angle = np.array([v.get("angle", math.nan) for v in rows])

    def along(v: dict) -> float | None:
        return v.get("length") or (v["height"] / math.sin(v["angle"]) if v.get("height") and v.get("angle") else None)

    a = _accelerations(model, along)
    if a is None or not np.all(np.isfinite(angle)):
        return None
    columns, rhs = {}, a.copy()
    g = np.array([v.get("g", STANDARD_GRAVITY) for v in rows])
    k2 = np.array([v.get("k2", math.nan) for v in rows])
    if "g" in model.names:
        columns["g"] = np.sin(angle)
    else:
        rhs = rhs - g * np.sin(angle)
    if "k2" in model.names:
        columns["k2"] = -a
    else:
        rhs = rhs + a * k2
    found = _regress(columns, rhs)
    if found is None:
        return None
    return found, Step(
        "A start from rolling's equation, linear in the inputs sought",
        "g sin θ − a k² = a",
        result=model.shown(found),
        why=f"each run's a from its measured {model.samples.y_key}" + (" (a = 2L/t²)" if model.samples.y_key == "t" else "")
        + f", least squares over {len(a)} runs: a = g sin θ/(1 + k²) for a body rolling without slipping, rearranged; "
        "the fit below then matches the measured result itself",
    )


def _spin_down(model: Model) -> tuple[dict[str, float], Step] | None:
    plain = ("brake", "face", "power", "alpha", "ke0", "rim_speed", "force", "in_time", "until_omega", "until_angle", "until_arc")
    sought = set(model.names)
    if any(name in model.held for name in plain) or not sought <= {"friction", "viscous", "drag", "drag_exponent", "omega0", "torque", "inertia"}:
        return None
    if set(model.samples.inputs) != {"time"} or model.samples.y_key not in ("omega", "theta", "revs"):
        return None
    t = np.asarray(model.samples.inputs["time"])
    order = np.argsort(t)
    t, y = t[order], np.asarray(model.samples.y)[order]
    if len(t) < 4 or np.any(np.diff(t) <= 0):
        return None
    omega = y if model.samples.y_key == "omega" else np.gradient(y * (2 * math.pi if model.samples.y_key == "revs" else 1.0), t)
    moving = np.abs(omega) > 0.02 * np.max(np.abs(omega))
    t, omega = t[moving], omega[moving]
    if len(t) < 4:
        return None
    sign = 1.0 if np.median(omega) >= 0 else -1.0
    n = model.si.get("drag_exponent", 2.0)
    given = lambda name: model.si.get(name, 0.0)  # noqa: E731

    def integral(values: np.ndarray) -> np.ndarray:
        return np.concatenate([[0.0], np.cumsum((values[1:] + values[:-1]) / 2 * np.diff(t))])

    def regressed(n: float) -> dict[str, float] | None:
        columns = {"level": np.ones(len(t)), "rate": t - t[0]}
        if "viscous" in sought or given("viscous"):
            columns["viscous"] = integral(omega)
        if "drag" in sought or given("drag"):
            columns["drag"] = integral(sign * np.abs(omega) ** n)
        return _regress(columns, omega)

    if "drag_exponent" in sought:  # n itself is not linear: the n whose regression leaves the least squares
        n = _exponent(regressed, lambda c, n: omega - c["level"] - c["rate"] * (t - t[0]) - c.get("viscous", 0.0) * integral(omega)
                      - c.get("drag", 0.0) * integral(sign * np.abs(omega) ** n))
        if n is None:
            return None
    c = regressed(n)
    if c is None:
        return None
    inertia = model.si.get("inertia")
    if inertia is None and "inertia" not in sought:
        try:
            inertia = model.report(np.array([_neutral(model, j) for j in range(len(model.names))]), {"time": 0.0}).results["I"].value
        except (InputError, KeyError, ValueError, ZeroDivisionError, OverflowError):
            return None
    drive, friction = given("torque"), given("friction")
    found: dict[str, float] = {}
    if "inertia" in sought:
        if "viscous" not in sought and given("viscous") and c.get("viscous"):
            inertia = -given("viscous") / c["viscous"]
        elif not {"friction", "torque"} & sought and drive - sign * friction and c["rate"]:
            inertia = (drive - sign * friction) / c["rate"]
        else:
            return None
        found["inertia"] = inertia
    if "friction" in sought:
        found["friction"] = sign * (drive - inertia * c["rate"])
    if "torque" in sought:
        found["torque"] = inertia * c["rate"] + sign * found.get("friction", friction)
    if "viscous" in sought:
        found["viscous"] = -inertia * c["viscous"]
    if "drag" in sought:
        found["drag"] = -inertia * c["drag"]
    if "drag_exponent" in sought:
        found["drag_exponent"] = n
    if "omega0" in sought:
        slope = c["rate"] + c.get("viscous", 0.0) * omega[0] + c.get("drag", 0.0) * sign * abs(omega[0]) ** n
        found["omega0"] = c["level"] - slope * t[0]
    terms = "((τ − τ_f)/I)(t − t₁)" + (" − (b/I)∫ω dt" if "viscous" in c else "") + (" − (k/I)∫ωⁿ dt" if "drag" in c else "")
    return found, Step(
        "A start from the equation of motion, integrated over the samples",
        f"ω(t) − ω(t₁) = {terms}",
        f"(τ − τ_f)/I = {fmt(c['rate'])} rad/s²" + (f", b/I = {fmt(-c['viscous'])} 1/s" if "viscous" in c else "")
        + (f", k/I = {fmt(-c['drag'])}" if "drag" in c else "") + f", I = {quantity_text(inertia, 'kg*m**2')}",
        model.shown(found),
        "I dω/dt = τ − τ_f − bω − kωⁿ integrated from the first sample is linear in its coefficients: least squares over the "
        f"{len(t)} samples where it turns" + (" (ω from the differences of θ)" if model.samples.y_key != "omega" else "")
        + ", the integrals of ω by the trapezoid rule (integrating smooths the noise that differentiating would raise)"
        + ("; n, which enters otherwise, is the one of 0.1 to 10 whose least squares leaves the least residual" if "drag_exponent" in sought else ""),
    )


EXPONENTS = np.linspace(0.1, 10.0, 100)  # the drag exponents tried for a start (its option takes 0 < n ≤ 10), then refined about the best


def _exponent(regressed, residual) -> float | None:
    """The drag exponent n whose regression ``regressed(n)`` leaves the least sum of squares: on
    EXPONENTS, then on a grid a hundredth as fine about the best (each a least squares of the
    samples alone, no solve of the scene)."""
    def squares(n: float) -> float:
        c = regressed(n)
        if c is None or "drag" not in c:
            return math.inf
        r = residual(c, n)
        return float(np.sum(r**2)) if np.all(np.isfinite(r)) else math.inf

    best = min(EXPONENTS, key=squares)
    step = float(EXPONENTS[1] - EXPONENTS[0])
    best = min(np.linspace(max(best - step, 0.01), best + step, 41), key=squares)
    return float(best) if math.isfinite(squares(best)) else None


CLOSED: dict[str, Callable[[Model], tuple[dict[str, float], Step] | None]] = {
    "spin-down": _spin_down, "atwood": _atwood, "rolling": _rolling,
    "pendulum": lambda model: decay.start(model) if decay.damped(model) else swing.pendulum(model),  # a damped swing's, or a swing's
}
ALTERNATIVES: dict[str, Callable[[Model], list[tuple[dict[str, float], Step]]]] = {"pendulum": swing.alternatives}  # other closed-form starts


def _neutral(model: Model, j: int) -> float:
    """A value for an input not yet started: 0 where it may be, else 1 (SI)."""
    return 0.0 if model.sign(j) != "positive" else 1.0


def _root_start(model: Model, j: int, p: np.ndarray) -> float | None:
    """The value of input j alone that best meets the samples: each root of a few samples (as
    --find finds them) tried on up to CHECKED samples, the one with the least sum of squares (a
    sample may be met by many values, as a swing's angle at one time is by many g)."""
    unknown = model.unknowns[j]
    count = model.samples.count
    picks = sorted({round(k * (count - 1) / max(ROWS - 1, 1)) for k in range(min(ROWS, count))})
    found: list[float] = []
    for i in picks:
        target = model.samples.y[i]

        def f(x: float, i=i, target=target) -> float | None:
            q = np.array(p, dtype=float)
            q[j] = x
            value = model.value(q, i)
            return None if math.isnan(value) else value - target

        search = roots.search(f, roots.grid(units.KINDS[unknown.kind].bounds, unknown.sign, angle=unknown.kind == "angle"), target,
                              angle=unknown.kind == "angle")
        found += search.roots
    if not found:
        return None
    checked = sorted({round(k * (count - 1) / max(CHECKED - 1, 1)) for k in range(min(CHECKED, count))})
    y = np.asarray(model.samples.y)[checked]

    def squares(x: float) -> float:
        q = np.array(p, dtype=float)
        q[j] = x
        r = np.array([model.value(q, i) for i in checked]) - y
        return float(np.sum(r**2)) if np.all(np.isfinite(r)) else math.inf

    candidates = sorted(set(found), key=lambda x: abs(x - float(np.median(found))))[:CANDIDATES]
    best = min(candidates, key=squares)
    return best if math.isfinite(squares(best)) else float(np.median(found))


def start(model: Model, given: dict[str, float]) -> tuple[np.ndarray, list[Step], list[str]]:
    """(p₀, the steps that found it, how each input's start was found)."""
    names = model.names
    p = np.array([given.get(name, math.nan) for name in names], dtype=float)
    how = ["given" if name in given else "" for name in names]
    steps: list[Step] = []
    if any(not h for h in how):
        closed = CLOSED.get(model.command.name)
        made = closed(model) if closed is not None else None
        if made is not None:
            values, step = made
            for j, name in enumerate(names):
                if not how[j] and name in values and math.isfinite(values[name]):
                    p[j], how[j] = values[name], "closed form"
            steps.append(step)
    for j in range(len(names)):
        if not how[j]:
            p[j] = _neutral(model, j)
    waiting = [j for j in range(len(names)) if not how[j]]
    while waiting:  # an input with no root while another is at 0 (ω₀ not yet started) is tried again after the others
        later = []
        for j in waiting:
            root = _root_start(model, j, p)
            if root is None:
                later.append(j)
                continue
            p[j], how[j] = root, "root"
            steps.append(_root_step(model, j, root))
        if later == waiting:
            break
        waiting = later
    refused = model.refusal
    if waiting and isinstance(refused, InputError) and refused.option in model.held and refused.option not in names and refused.option not in model.samples.inputs:
        raise refused  # an option given that the scene refuses whatever the fit tries (--shape 19.8kg): said as the scene says it
    for j in waiting:
        name = names[j]
        first = model.value(p, 0)
        said = (f" (at {name} = {fmt(p[j])} the scene gives {model.samples.y_key} = {quantity_text(first, model.samples.y_unit)} "
                f"at the first sample, measured {quantity_text(model.samples.y[0], model.samples.y_unit)})") if math.isfinite(first) else ""
        raise InputError("fit", f"finds no start for {name}: no value of it alone meets the samples tried{said}",
                         hint=f"is an input missing? Else give a start beside --fit, e.g. --{name.replace('_', '-')} VALUE")
    for j in range(len(names)):  # a start outside a --bound is moved just inside it
        low, high = model.lower(j), model.upper(j)
        if names[j] in model.bounds and (p[j] < low or p[j] > high) and (p[j] > high or low > model.natural_lower(j)):
            width = high - low if math.isfinite(high - low) else max(abs(low if math.isfinite(low) else high), 1e-300)
            p[j] = low + 1e-3 * width if p[j] < low else high - 1e-3 * width
    for j in range(len(names)):  # a start at or past a bound is moved just inside it (the fit moves within the bounds)
        if not model.allowed(j, p[j]) or (model.sign(j) != "any" and p[j] <= 0):
            p[j] = _inside(model, j, p)
    return p, steps, how


def _root_step(model: Model, j: int, root: float) -> Step:
    name = model.names[j]
    return Step(f"A start for {name}: the value that alone best meets a few samples",
                f"{model.samples.y_key}(xᵢ; {name}) = {model.samples.y_key}ᵢ",
                result=f"{name} = {quantity_text(root, units.KINDS[model.unknowns[j].kind].si_unit)}",
                why=f"the roots in {min(ROWS, model.samples.count)} samples spread over the table, each found as --find finds them "
                "(a search of the input's range, then Brent's method), the other inputs at their starts: the one with the least "
                f"sum of squares over up to {CHECKED} samples")


def _inside(model: Model, j: int, p: np.ndarray) -> float:
    """A small positive start for an input whose closed form came out at or below 0: a hundredth of
    the size its root alone would have, or of 1 SI."""
    q = np.array(p, dtype=float)
    q[j] = math.nan
    others = np.where(np.isfinite(q), q, 0.0)
    root = _root_start(model, j, others)
    return abs(root) / 100 if root else 1e-6


def starts(model: Model, given: dict[str, float]) -> list[tuple[np.ndarray, list[Step], list[str]]]:
    """Each start the fit searches from, the first the one ``start`` gives: then the closed form
    without the values given (where some were), and the scene's other closed forms. A start that
    differs from an earlier one by less than SAME of each input is left out."""
    first = start(model, given)
    found = [first]
    if given:
        try:
            found.append(start(model, {}))
        except InputError:
            pass
    other = ALTERNATIVES.get(model.command.name)
    for values, step in (other(model) if other is not None and set(given) != set(model.names) else []):
        p = np.array(first[0], dtype=float)
        how = list(first[2])
        for j, name in enumerate(model.names):
            if name in values and name not in given and math.isfinite(values[name]) and model.allowed(j, values[name]):
                p[j], how[j] = values[name], "closed form"
        found.append((p, [step if s.title.startswith(swing.TITLE) else s for s in first[1]], how))
    kept: list[tuple[np.ndarray, list[Step], list[str]]] = []
    for candidate in found:
        if all(np.any(np.abs(candidate[0] - other[0]) > SAME * np.maximum(np.abs(other[0]), 1e-300)) for other in kept):
            kept.append(candidate)
    return kept


SAME = 0.01  # two starts within this of each input are one
