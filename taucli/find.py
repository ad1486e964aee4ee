"""``--find NAME --want RESULT=VALUE``: solve a scene for one of its inputs (#22).

The scene is solved forward (``pipeline.solve``, the input given as an SI number) over the
input's physical range, from its sign and its kind's bounds in taucli.units: a grid of a few
values a decade (and 0, and the negative side where the sign allows). Each cell of the grid where
the result crosses the target is a bracket, and Brent's method finds the root in it to full
precision; a crossing that is a jump, not a root, is left out. Every root is reported (``roots``)
and the smallest in size is the result. Where no value reaches the target the run is refused with
the range of the result that is reachable; where the target holds over an interval (a = 0 while
friction holds) it is refused, naming the interval.

With uncertain inputs, or an uncertain target, the solved input's uncertainty follows from the
implicit function theorem: f(x, p) = y, so δx = (δy − Σ ∂f/∂p δp) / (∂f/∂x), and every other
result moves with x as well as with p (the full Jacobian).
"""

from __future__ import annotations

import math

from taucli import units
from taucli.errors import InputError
from taucli.report import Measured, Report, Step, Value, fmt, pretty_unit, quantity_text, term
from taucli.table import spelled
from taucli.measurement import NUMBER_THEN_UNIT, split
from taucli.propagate import Scene, combine, jacobian, linearity, monte_carlo, numeric
from taucli.scenes.assumed import STANDARD_GRAVITY

PER_DECADE = 4
EPS = 2.0**-52


def _target(scene: Scene, want: str) -> tuple[str, float, float, str | None, str | None]:
    """(result key, target in SI, its σ, its unit, a note on how the value was read) from "a=4.0+/-0.1m/s^2"."""
    command = scene.command
    key, sep, text = str(want).partition("=")
    key, text = key.strip(), text.strip()
    names = ", ".join(r.key for r in command.results)
    if not sep or not text:
        raise InputError("want", "expected RESULT=VALUE", example="{want} a=4.0m/s^2", got=repr(want))
    result = command.result(key)
    if result is None:
        raise InputError("want", f"expected a result of {command.name}: {names}", got=repr(key))
    if result.unit is None:
        raise InputError("want", f"expected a result that is a number; {key} is yes or no", got=repr(want))
    kind = next((k.name for k in units.KINDS.values() if k.si_unit == result.unit), None)
    parts = split(text)
    value_text, spread_text = parts if parts else (text, None)
    option = "{want} " + key
    if kind is None:  # a unit no option takes (J, W): the number times the unit's SI factor
        return key, _in_si(value_text, result.unit, key), _in_si(spread_text, result.unit, key) if spread_text else 0.0, result.unit, None
    value = units.parse(value_text, option, kind, sign="any", gravity=scene.si.get("g"))
    spread = units.parse(spread_text, option + " (its uncertainty)", kind, sign="nonnegative").value if spread_text else 0.0
    return key, value.value, spread, result.unit, value.note


def _in_si(text: str, si_unit: str, key: str) -> float:
    split_text = NUMBER_THEN_UNIT.fullmatch(text)
    if split_text is None:
        raise InputError("want", f"expected {key} as a number with a unit of {si_unit}", example=f"{{want}} {key}=4{si_unit}", got=repr(text))
    number, unit = float(split_text[1]), split_text[2]
    value = number / units.convert(1.0, si_unit, unit, "{want}") if unit else number
    if not math.isfinite(value):
        raise InputError("want", f"expected a finite {key}", got=repr(text))
    return value


def _grid(scene: Scene, name: str) -> list[float]:
    option = scene.command.option(name)
    low, high = units.KINDS[option.kind].bounds
    first, last = math.floor(math.log10(low) * PER_DECADE), math.ceil(math.log10(high) * PER_DECADE)
    sizes = [10.0 ** (k / PER_DECADE) for k in range(first, last + 1)]
    if option.sign == "positive":
        return sizes
    if option.sign == "nonnegative":
        return [0.0, *sizes]
    return [-s for s in reversed(sizes)] + [0.0] + sizes


def brent(f, a: float, b: float, fa: float, fb: float, *, iterations: int = 200) -> tuple[float, int]:
    """A root of f in [a, b] (fa, fb of opposite signs) by Brent's method, to a few ulp of x."""
    if fa == 0:
        return a, 0
    if fb == 0:
        return b, 0
    c, fc, d = a, fa, b - a
    e = d
    for count in range(1, iterations + 1):
        if fb * fc > 0:
            c, fc = a, fa
            d = e = b - a
        if abs(fc) < abs(fb):
            a, b, c = b, c, b
            fa, fb, fc = fb, fc, fb
        tol = 2 * EPS * abs(b) + 1e-300
        m = (c - b) / 2
        if abs(m) <= tol or fb == 0:
            return b, count
        if abs(e) >= tol and abs(fa) > abs(fb):
            s = fb / fa
            if a == c:
                p, q = 2 * m * s, 1 - s
            else:
                q, r = fa / fc, fb / fc
                p = s * (2 * m * q * (q - r) - (b - a) * (r - 1))
                q = (q - 1) * (r - 1) * (s - 1)
            if p > 0:
                q = -q
            p = abs(p)
            if 2 * p < min(3 * m * q - abs(tol * q), abs(e * q)):
                e, d = d, p / q
            else:
                d = e = m
        else:
            d = e = m
        a, fa = b, fb
        b += d if abs(d) > tol else math.copysign(tol, m)
        fb = f(b)
        if fb is None:
            raise ArithmeticError("the scene has no value inside the bracket")
    return b, iterations


def solve_for(scene: Scene, name: str, want: str, spreads: dict[str, float], notes: list[str], mc: int | None) -> Report:
    """The report at the value of input ``name`` that meets ``want``, that value as a result."""
    command = scene.command
    name = str(name).strip().lstrip("-").replace("-", "_")  # pulley_inertia, pulley-inertia or --pulley-inertia
    option = command.option(name)
    if option is None or name not in command.input_names or not option.is_quantity or option.repeatable:
        quantities = ", ".join(o.name for o in command.options if o.is_quantity and not o.repeatable)
        raise InputError("find", f"expected a quantity option of {command.name}: {quantities}", got=repr(name))
    if scene.given.get(name) is not None:
        raise InputError(name, "is what {find} solves for: leave it out", example=f"{{find}} {name}")
    key, target, target_spread, unit, read_as = _target(scene, want)
    si_unit = units.KINDS[option.kind].si_unit

    def f(x: float) -> float | None:
        values = scene.results({name: x})
        return None if values is None or key not in values else values[key] - target

    closed = _closed_form(scene, name, key, target, f)
    if closed is not None:
        x, equation, numbers = closed
        roots, jumps = [x], 0
        solution = Step(f"Solve for {name}: the inverse in closed form", equation, numbers, quantity_text(x, si_unit),
                        f"{key} is monotonic in {name} in this model, so this is the only root; the forward solve at it gives {key} = {fmt(target, 10)}")
        how = f"{name} by its closed-form inverse"
    else:
        roots, brackets, jumps = _roots(scene, name, key, target, unit, f)
        best = min(range(len(roots)), key=lambda i: abs(roots[i]))
        x = roots[best]
        low, high, iterations = brackets[best]
        solution = Step(
            f"Solve for {name}",
            f"{name} = the root of {key}({name}) − {fmt(target, 6)} in [{fmt(low, 6)}, {fmt(high, 6)}] {_unit(si_unit)}".rstrip(),
            "",
            f"{quantity_text(x, si_unit, 10)} (Brent's method, {iterations} steps)",
            f"the bracket is where {key} crosses the target on a grid of {PER_DECADE} values a decade over the range {name} may take"
            + (f"; {len(roots)} roots in all" if len(roots) > 1 else "; the only root"),
        )
        how = f"{name} by a bracketed root-finder (Brent's method) to full precision"
    nominal = scene.report({name: x})
    point = {name: x, **{p: scene.si[p] for p in spreads}}
    scales = {**spreads, name: max(abs(x) * 1e-3, 1e-300)}
    slopes = jacobian(scene, point, scales)
    fx = slopes[name].get(key)
    results = {name: Value(x, si_unit, f"{option.help.split('(')[0].split(',')[0].rstrip('. ')}, solved for {key} = {fmt(target, 6)} {_unit(unit)}".rstrip())}
    if len(roots) > 1:
        results["roots"] = Value(list(roots), si_unit, f"every {name} that gives {key} = {fmt(target, 6)} {_unit(unit)}".rstrip())
    results.update(nominal.results)
    extra = [*notes, *([read_as] if read_as else [])]
    if len(roots) > 1:
        extra.append(f"{len(roots)} values of {{{name}}} give {key} = {fmt(target, 6)}: " + ", ".join(quantity_text(r, si_unit, 6) for r in roots) + "; the smallest in size is the result")
    if jumps:
        extra.append(f"{key} jumps across the target at {jumps} place{'s' if jumps > 1 else ''} in the range of {{{name}}}; a jump is not a root")
    steps = [
        Step(
            f"The forward equation: {key} as a function of {name}",
            f"{key}({name}) = {fmt(target, 6)} {_unit(unit)}".rstrip(),
            "",
            "",
            f"{key} as {command.name} gives it (the steps below) for each trial {name}; the inverse is the root of "
            f"{key}({name}) − {fmt(target, 6)} = 0" + (" (no closed-form inverse is used)" if closed is None else ""),
        ),
        solution,
    ]
    method = f"{nominal.method}; {how}"
    sigma: dict[str, float] = {}
    spread_all = dict(spreads)
    if (spreads or target_spread) and fx:
        # The implicit function theorem: x moves with the target y and with each input p.
        dx = {p: -slopes[p].get(key, 0.0) / fx for p in spreads}
        totals = {p: {r: slopes[p].get(r, 0.0) + slopes[name].get(r, 0.0) * dx[p] for r in numeric(nominal)} for p in spreads}
        for p in spreads:
            totals[p][name] = dx[p]
        if target_spread:
            totals["{want}"] = {r: slopes[name].get(r, 0.0) / fx for r in numeric(nominal)}
            totals["{want}"][name] = 1.0 / fx
            totals["{want}"][key] = 1.0
            spread_all["{want}"] = target_spread
        sigma = combine(totals, spread_all, {**numeric(nominal), name: x})
        extra.extend(linearity(scene, nominal, {**spreads, name: sigma.get(name, 0.0)} if sigma.get(name) else spreads, slopes, point))
        method += "; uncertainties to first order (full Jacobian, the implicit function theorem for the solved input)"
        steps.append(Step(
            f"The uncertainty of {name}",
            f"δ{name} = √(δ{key}² + Σ (∂{key}/∂p · δp)²) / |∂{key}/∂{name}|",
            f"√({' + '.join(f'({term(part, unit)})²' for part in [target_spread, *(slopes[p].get(key, 0.0) * spreads[p] for p in spreads)])})"
            f" / {term(abs(fx), _per(unit, si_unit))}",
            quantity_text(sigma.get(name, 0.0), si_unit),
            f"the implicit function theorem: {key} is held at its target while the target and each uncertain input p move; "
            f"∂{key}/∂{name} = {fmt(fx, 6)} by differences; independent changes add in quadrature",
        ))
    elif (spreads or target_spread) and not fx:
        extra.append(f"{key} does not change with {{{name}}} at the root, so no uncertainty follows for it")
    report = Measured(
        nominal.scene, nominal.model, method, results, [*steps, *nominal.steps],
        [spelled(n, scene.spell, command.option) if "{" in n else n for n in (*nominal.notes, *extra)],
        nominal.inputs, nominal.tables, nominal.trajectory,
        uncertainties=sigma, input_uncertainties=dict(spreads),
    )
    if mc and (spreads or target_spread):
        monte_carlo(scene, report, spread_all, mc, lambda draw: _redrawn(scene, name, key, target, x, draw, spreads), {"{want}": target})
    return report


def _roots(scene: Scene, name: str, key: str, target: float, unit, f) -> tuple[list[float], list[tuple], int]:
    """Every root of f over the input's range: (roots, their brackets and Brent's steps, jumps)."""
    grid = _grid(scene, name)
    values = [f(x) for x in grid]
    roots, brackets, jumps = [], [], 0
    holds = [i for i, v in enumerate(values) if v is not None and _meets(v, target)]
    if len(holds) >= 2 and any(j == i + 1 for i, j in zip(holds, holds[1:])):
        _refuse_interval(scene, name, key, target, unit, grid, values, holds, f)
    for i in range(len(grid) - 1):
        fa, fb = values[i], values[i + 1]
        if fa is None or fb is None:
            continue
        if fa == 0 and i > 0:
            continue  # counted as the right end of the cell before
        if fa * fb > 0:
            continue
        try:
            x, count = brent(f, grid[i], grid[i + 1], fa, fb)
        except ArithmeticError:
            continue
        fx = f(x)
        if fx is None or abs(fx) > 1e-9 * max(abs(target), abs(fx + target), 1e-300) and abs(fx) > 1e-12:
            jumps += 1  # a jump across the target, not a root
            continue
        if not roots or not math.isclose(x, roots[-1], rel_tol=1e-12, abs_tol=1e-300):
            roots.append(x)
            brackets.append((grid[i], grid[i + 1], count))
    if not roots:
        _refuse_unreachable(scene, name, key, target, unit, grid, values, jumps)
    return roots, brackets, jumps


# Closed-form inverses, where one is easy: (scene, input, result) -> the inverse. Each is used only
# where the scene's options are those of its model and the forward solve at its value meets the
# target to 1e-12; otherwise the root-finder is used.
PLAIN_ATWOOD = ("axle_friction", "incline", "mu_k", "mu_s", "rim_mu", "radius1", "radius2", "pulley_shape")


def _atwood_inverse(scene: Scene, name: str, target: float):
    si = scene.si
    if any(option in scene.given for option in PLAIN_ATWOOD) or target == 0 or "m1" not in si:
        return None
    m1, m2, g = si["m1"], si.get("m2", 0.0), si.get("g", STANDARD_GRAVITY)
    extra = (m1 - m2) * g / target - m1 - m2  # I/R², or M/2: (m1 − m2) g = (m1 + m2 + I/R²) a
    if name == "pulley_inertia":
        if "pulley_radius" not in si or "pulley_mass" in scene.given:
            return None
        r = si["pulley_radius"]
        return (extra * r * r, "I = R² ((m₁ − m₂) g / a − m₁ − m₂)",
                f"({term(r, 'm')})² × (({term(m1, 'kg')} − {term(m2, 'kg')}) × {term(g, 'm/s**2')} / {term(target, 'm/s**2')} − {term(m1, 'kg')} − {term(m2, 'kg')})")
    if "pulley_inertia" in scene.given:
        return None
    return 2 * extra, "M = 2 ((m₁ − m₂) g / a − m₁ − m₂)", f"2 × (({term(m1, 'kg')} − {term(m2, 'kg')}) × {term(g, 'm/s**2')} / {term(target, 'm/s**2')} − {term(m1, 'kg')} − {term(m2, 'kg')})"


def _stop_inverse(scene: Scene, name: str, target: float):
    loads = ("viscous", "drag", "torque", "force", "power", "alpha", "brake", "face")
    if any(option in scene.given for option in loads) or "omega0" not in scene.si or target <= 0:
        return None
    probe = scene.results({name: 1.0})  # I does not depend on the friction
    if probe is None or "I" not in probe:
        return None
    inertia, omega0 = probe["I"], abs(scene.si["omega0"])
    return inertia * omega0 / target, "τ = I ω₀ / t_stop", f"{term(inertia, 'kg*m**2')} × {term(omega0, 'rad/s')} / {term(target, 's')}"


CLOSED_FORMS = {
    ("atwood", "pulley_inertia", "a"): _atwood_inverse,
    ("atwood", "pulley_mass", "a"): _atwood_inverse,
    ("spin-down", "friction", "t_stop"): _stop_inverse,
}


def _closed_form(scene: Scene, name: str, key: str, target: float, f):
    inverse = CLOSED_FORMS.get((scene.command.name, name, key))
    found = inverse and inverse(scene, name, target)
    if not found or not math.isfinite(found[0]) or not scene.allowed(name, found[0]):
        return None
    residual = f(found[0])
    if residual is None or abs(residual) > 1e-12 * abs(target):
        return None
    return found


def _redrawn(scene: Scene, name: str, key: str, target: float, x0: float, draw: dict, spreads) -> dict | None:
    """One Monte Carlo draw with --find: the root near x0 for the drawn inputs and target."""
    y = draw.pop("{want}", target)
    moved = {p: draw[p] for p in spreads}

    def f(x: float) -> float | None:
        values = scene.results({**moved, name: x})
        return None if values is None or key not in values else values[key] - y

    step = max(abs(x0) * 0.05, 1e-12)
    for _ in range(60):
        a, b = x0 - step, x0 + step
        if not scene.allowed(name, a):
            a = x0 / 2 if x0 > 0 else 0.0
        fa, fb = f(a), f(b)
        if fa is not None and fb is not None and fa * fb <= 0:
            x, _ = brent(f, a, b, fa, fb)
            values = scene.results({**moved, name: x})
            return values and {**values, name: x}
        step *= 2
    return None


def _per(unit: str, by: str) -> str:
    """The unit of a derivative ∂y/∂x: m/s**2 per kg*m**2 -> m/s**2/(kg*m**2)."""
    return f"{unit}/({by})" if any(sign in by for sign in "*/") else f"{unit}/{by}"


def _meets(v: float, target: float) -> bool:
    return v == 0 or abs(v) <= 1e-13 * abs(target)


def _unit(unit: str | None) -> str:
    return pretty_unit(unit)


def _edge(f, inside: float, outside: float, target: float) -> float:
    """Where "the target holds" ends between ``inside`` (holds) and ``outside`` (does not)."""
    for _ in range(200):
        middle = (inside + outside) / 2
        if middle in (inside, outside):
            break
        v = f(middle)
        if v is not None and _meets(v, target):
            inside = middle
        else:
            outside = middle
    return inside


def _refuse_interval(scene, name, key, target, unit, grid, values, holds, f):
    first = holds[0]
    last = first
    while last + 1 < len(grid) and values[last + 1] is not None and _meets(values[last + 1], target):
        last += 1
    low = _edge(f, grid[first], grid[first - 1], target) if first > 0 else grid[first]
    high = _edge(f, grid[last], grid[last + 1], target) if last + 1 < len(grid) else None
    si_unit = units.KINDS[scene.command.option(name).kind].si_unit
    where = f"from {quantity_text(low, si_unit, 6)} " + (f"to {quantity_text(high, si_unit, 6)}" if high is not None else "upward")
    raise InputError("want", f"holds for every {{{name}}} {where} ({key} = {fmt(target, 6)} {_unit(unit)} over an interval), so it picks no one value".replace("  ", " "),
                     hint="give a target outside that interval")


def _refuse_unreachable(scene, name, key, target, unit, grid, values, jumps):
    reached = [v + target for v in values if v is not None]
    si_unit = units.KINDS[scene.command.option(name).kind].si_unit
    if not reached:
        raise InputError("find", f"gives no {key} anywhere in the range {{{name}}} may take with these options")
    where = [x for x, v in zip(grid, values) if v is not None]
    raise InputError(
        "want",
        f"cannot be met: no {{{name}}} gives {key} = {fmt(target, 6)} {_unit(unit)}".rstrip()
        + f"; over {{{name}}} from {quantity_text(where[0], si_unit, 3)} to {quantity_text(where[-1], si_unit, 3)}, {key} reaches about {fmt(min(reached), 6)} to {fmt(max(reached), 6)} {_unit(unit)}".rstrip()
        + (f" (it jumps across the target {jumps} time{'s' if jumps > 1 else ''})" if jumps else ""),
    )
