"""``--find NAME --want RESULT=VALUE``: solve a scene for one of its inputs (#22, #31).

NAME is a quantity option, one more value of a repeated one, or a key inside a spec
(taucli.answering.unknowns). Where the scene's model has an easy inverse it is used, checked by the forward
solve; otherwise the scene is solved forward (``pipeline.solve``, the input as an SI number) over
the input's whole range and every root is found (taucli.numerics.roots: a grid, each edge of where the
result has a value bisected, each turn toward the target refined, Brent's method in each
bracket). Every root is reported (``roots``) and the smallest in size is the result; where the
search cannot promise it saw every root, a note says which range it searched and that it may hold
more. Where no value reaches the target the run is refused with the range of the result that is
reachable (or with the scene's own refusal, where it refuses every value); where the target holds
over an interval (a = 0 while friction holds) it is refused, naming the interval.

With uncertain inputs, or an uncertain target, the solved input's uncertainty follows from the
implicit function theorem: f(x, p) = y, so δx = (δy − Σ ∂f/∂p δp) / (∂f/∂x), and every other
result moves with x as well as with p (the full Jacobian).
"""

from __future__ import annotations

import math

from taucli.numerics import roots
from taucli.quantities import units
from taucli.answering import unknowns
from taucli.core.errors import InputError, did_you_mean, spelled
from taucli.writing.report import Measured, Report, Step, Value, fmt, pretty_unit, quantity_text, term
from taucli.quantities.measurement import NUMBER_THEN_UNIT, split
from taucli.answering.propagate import FIND_SOLVES, Scene, combine, jacobian, linearity, monte_carlo, numeric
from taucli.numerics.roots import brent
from taucli.scenes.assumed import STANDARD_GRAVITY


def _target(scene: Scene, want: str) -> tuple[str, float, float, str | None, list[str]]:
    """(result key, target in SI, its σ, its unit, the notes its reading raised) from "a=4.0+/-0.1m/s^2"."""
    command = scene.command
    key, sep, text = str(want).partition("=")
    key, text = key.strip(), text.strip()
    names = ", ".join(r.key for r in command.results)
    if not sep or not text:
        raise InputError("want", "expected RESULT=VALUE", example="{want} a=4.0m/s^2", got=repr(want))
    result = command.result(key)
    if result is None:
        raise InputError("want", f"expected a result of {command.name}: {names}", got=repr(key), hint=did_you_mean(key, [r.key for r in command.results]))
    if result.unit is None:
        raise InputError("want", f"expected a result that is a number; {key} is yes or no", got=repr(want))
    kind = next((k.name for k in units.KINDS.values() if k.si_unit == result.unit), None)
    parts = split(text)
    value_text, spread_text = parts if parts else (text, None)
    option = "{want} " + key
    if kind is None:  # a unit no option takes (J, W): the number times the unit's SI factor
        value, notes = _in_si(value_text, result.unit, key)
        spread, spread_notes = _in_si(spread_text, result.unit, key) if spread_text else (0.0, [])
        return key, value, spread, result.unit, [*notes, *spread_notes]
    value = units.parse(value_text, option, kind, sign="any", gravity=scene.si.get("g"))
    spread = units.parse(spread_text, option + " (its uncertainty)", kind, sign="nonnegative", gravity=scene.si.get("g")) if spread_text else None
    notes = [parsed.note for parsed in (value, spread) if parsed is not None and parsed.note]
    return key, value.value, spread.value if spread else 0.0, result.unit, notes


def _in_si(text: str, si_unit: str, key: str) -> tuple[float, list[str]]:
    split_text = NUMBER_THEN_UNIT.fullmatch(text)
    if split_text is None:
        raise InputError("want", f"expected {key} as a number with a unit of {si_unit}", example=f"{{want}} {key}=4{si_unit}", got=repr(text))
    number, unit = float(split_text[1]), split_text[2]
    notes = []
    value = number
    if unit:
        one = units.converted(1.0, si_unit, unit, "{want} " + key)
        value = number / one.value
        notes = [one.note] if one.note else []
    if not math.isfinite(value):
        raise InputError("want", f"expected a finite {key}", got=repr(text))
    return value, notes


def unknown(command, name: str, given) -> unknowns.Unknown:
    """What ``--find NAME`` solves for, with the options ``given`` (a usage error where it cannot)."""
    return unknowns.resolve(command, name, given)


REDRAWN_SOLVES = 10  # about how many solves the value solved for takes again for one Monte Carlo draw, from near the first


def solve_for(scene: Scene, unknown: unknowns.Unknown, want: str, spreads: dict[str, float], notes: list[str], mc: int | None) -> Report:
    """The report at the value of the input ``unknown`` that meets ``want``, that value as a result."""
    command = scene.command
    name = unknown.name
    key, target, target_spread, unit, want_notes = _target(scene, want)
    si_unit = units.KINDS[unknown.kind].si_unit
    refusals: dict[str, Exception] = {}
    scene.plan(FIND_SOLVES, "find")

    def f(x: float) -> float | None:
        values = scene.results({name: x})
        if values is None:
            refusals.setdefault(str(scene.refusal), scene.refusal)
        return None if values is None or key not in values else values[key] - target

    closed = _closed_form(scene, name, key, target, f) if unknown.key is None and not unknown.option.repeatable else None
    extra = [*notes, *want_notes]
    if closed is not None:
        x, equation, numbers = closed
        found = [x]
        solution = Step(f"Solve for {name}: the inverse in closed form", equation, numbers, quantity_text(x, si_unit),
                        f"{key} is monotonic in {name} in this model, so this is the only root; the forward solve at it gives {key} = {fmt(target, 10)}")
        how = f"{name} by its closed-form inverse"
        complete = True
    else:
        search = roots.search(f, roots.grid(units.KINDS[unknown.kind].bounds, unknown.sign, angle=unknown.kind == "angle"), target,
                              angle=unknown.kind == "angle", say=lambda value: quantity_text(value, si_unit, 6))
        search.doubts = [doubt.replace("the result", key) for doubt in search.doubts]
        if search.interval is not None:
            _refuse_interval(unknown, key, target, unit, si_unit, search.interval)
        if not search.roots:
            _refuse_unreachable(unknown, key, target, unit, si_unit, search, refusals, scene.given.get(unknown.option.name) is not None)
        found = search.roots
        best = _best(scene, unknown, found)
        x = found[best]
        solution = _search_step(name, key, target, si_unit, unit, search, best)
        extra.extend(_search_notes(unknown, key, target, unit, si_unit, search, f))
        how = f"{name} by a search of its range and a bracketed root-finder (Brent's method) to full precision"
        complete = search.complete
    nominal = scene.report({name: x})
    point = {name: x, **{p: scene.si[p] for p in spreads}}
    scales = {**spreads, name: max(abs(x) * 1e-3, 1e-300)}
    slopes = jacobian(scene, point, scales)
    fx = slopes[name].get(key)
    results = {name: Value(x, si_unit, f"{unknown.label}, solved for {key} = {fmt(target, 6)} {_unit(unit)}".rstrip())}
    if len(found) > 1:
        every = "every" if complete else "each found"
        results["roots"] = Value(list(found), si_unit, f"{every} {name} that gives {key} = {fmt(target, 6)} {_unit(unit)}".rstrip())
    results.update(nominal.results)
    if len(found) > 1:
        extra.append(f"{len(found)} values of {unknown.spelled} {'give' if complete else 'found give'} {key} = {fmt(target, 6)}: "
                     + ", ".join(quantity_text(r, si_unit, 6) for r in found) + "; " + _chosen(unknown))
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
        extra.append(f"{key} does not change with {unknown.spelled} at the root, so no uncertainty follows for it")
    report = Measured(
        nominal.scene, nominal.model, method, results, [*steps, *nominal.steps],
        [spelled(n, scene.spell, command.option) if "{" in n else n for n in (*nominal.notes, *extra)],
        nominal.inputs, nominal.tables, nominal.trajectory,
        uncertainties=sigma, input_uncertainties=dict(spreads),
    )
    if mc and (spreads or target_spread):
        scene.plan(mc * REDRAWN_SOLVES, "mc")
        monte_carlo(scene, report, spread_all, mc, lambda draw: _redrawn(scene, name, key, target, x, draw, spreads), {"{want}": target})
    return report


def _best(scene: Scene, unknown: unknowns.Unknown, found: list[float]) -> int:
    """Which root is the result: the smallest in size (of ±x, the positive); for an angle the
    motion travels to (its table names the time it is reached and where it starts: a pendulum's
    --angle), the first the motion reaches: the least time, and where every time is infinite (a
    fall from a balance at the top) the nearest to the start along the turn; then as before."""
    size = lambda i: (abs(found[i]), found[i] < 0)  # noqa: E731
    first = unknown.option.first_reached if unknown.key is None else None
    if first is None or len(found) == 1:
        return min(range(len(found)), key=size)
    timed, start = first
    origin = scene.si.get(start) or 0.0
    reached = []
    for x in found:
        values = scene.results({unknown.name: x})
        time = values.get(timed) if values is not None else None
        apart = round(abs(math.remainder(x - origin, 2 * math.pi)), 9)  # ±x equally far: a tie, not rounding
        reached.append((time if isinstance(time, float) and math.isfinite(time) else math.inf, apart))
    return min(range(len(found)), key=lambda i: (*reached[i], *size(i)))


def _chosen(unknown: unknowns.Unknown) -> str:
    if unknown.option.first_reached and unknown.key is None:
        return "the first the motion reaches is the result"
    return "the smallest in size is the result"


def _span(search: roots.Search, si_unit: str) -> str:
    """The range the search covered, in words."""
    if search.period:
        return f"one turn, {fmt(math.degrees(search.low))}° to {fmt(math.degrees(search.high))}°"
    return f"{quantity_text(search.low, si_unit, 3)} to {quantity_text(search.high, si_unit, 3)}"


def _search_step(name: str, key: str, target: float, si_unit: str, unit, search: roots.Search, best: int) -> Step:
    x, (low, high), how = search.roots[best], search.brackets[best], search.found[best]
    samples = f"{roots.PER_DECADE} values a decade" + (f" and {roots.PER_TURN} a turn" if si_unit == "rad" else "")
    refined = [f"{len(search.edges)} edge{'s' if len(search.edges) != 1 else ''} of where {key} has a value bisected"] if search.edges else []
    refined += [f"{search.turns} place{'s' if search.turns != 1 else ''} where {key} turns toward the target refined"] if search.turns else []
    count = len(search.roots)
    if search.complete:
        outcome = (f"{count} roots in all" if count > 1 else "the only root") + f", as far as the samples resolve {key}: they show it turning at most once between neighbours"
    else:
        outcome = f"{count} root{'s' if count != 1 else ''} found; the range may hold more (a note says where)"
    where = f"in [{fmt(low, 6)}, {fmt(high, 6)}] {_unit(si_unit)}".rstrip() if low != high else f"at {fmt(x, 6)} {_unit(si_unit)}".rstrip()
    valued = [x for x, v in search.samples if v is not None]
    if valued and not search.period and (valued[0] > search.low or valued[-1] < search.high):
        refined.append(f"{key} has values only from {quantity_text(valued[0], si_unit, 6)} to {quantity_text(valued[-1], si_unit, 6)}")
    return Step(
        f"Solve for {name}",
        f"{name} = the root of {key}({name}) − {fmt(target, 6)} {where}",
        "",
        f"{quantity_text(x, si_unit, 10)} ({how.replace('the result', key)})",
        f"the search: {search.solves} forward solves over {name} from {_span(search, si_unit)} ({samples}"
        + "".join(f"; {part}" for part in refined) + f"); {outcome}",
    )


def _search_notes(unknown, key: str, target: float, unit, si_unit: str, search: roots.Search, f) -> list[str]:
    notes = []
    if search.period:
        notes.append(f"{key} repeats every turn of {unknown.spelled}: each root plus or minus whole turns (360°) gives it too; "
                     f"the roots listed are those of one turn")
    for x in search.at_edge:
        if x in search.roots:
            value = f(x)
            notes.append(f"{key} = {fmt(target, 6)} {_unit(unit)} is met at an edge of where {key} has a value: at {unknown.spelled} "
                         f"= {quantity_text(x, si_unit, 10)} ({key} there is {fmt(value + target, 3) if value is not None else 'none'}, "
                         f"reaching the target in the limit; just past it, {key} has no value)".replace("  ", " "))
    if search.jumps:
        notes.append(f"{key} jumps across the target at {search.jumps} place{'s' if search.jumps > 1 else ''} in the range of {unknown.spelled}; a jump is not a root")
    if not search.complete:
        notes.append(f"the search of {unknown.spelled} from {_span(search, si_unit)} may have missed roots: "
                     + "; ".join(search.doubts) + " (it may hold more roots than those found)")
    return notes


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
    loads = ("viscous", "drag", "torque", "force", "power", "alpha", "brake", "face", "band", "caliper")
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


def _unit(unit: str | None) -> str:
    return pretty_unit(unit)


def _refuse_interval(unknown, key, target, unit, si_unit, interval):
    low, high = interval
    where = f"from {quantity_text(low, si_unit, 6)} " + (f"to {quantity_text(high, si_unit, 6)}" if high is not None else "upward")
    raise InputError("want", f"holds for every {unknown.spelled} {where} ({key} = {fmt(target, 6)} {_unit(unit)} over an interval), so it picks no one value".replace("  ", " "),
                     hint="give a target outside that interval")


def _refuse_unreachable(unknown, key, target, unit, si_unit, search: roots.Search, refusals: dict, given: bool):
    values = [(x, v) for x, v in search.samples if v is not None]
    if not values:
        refusal = next(iter(refusals.values()), None)
        if len(refusals) == 1 and isinstance(refusal, InputError):  # the scene refuses the options given, whatever the value: its reason
            if unknown.option.repeatable and given:
                hint = f"{{find}} {unknown.name} solves for one more {{{unknown.option.name}}} after those given: leave that one out"
                raise InputError(refusal.option, refusal.expected, got=refusal.got, example=refusal.example,
                                 hint=f"{refusal.hint}; {hint}" if refusal.hint else hint)
            raise refusal
        raise InputError("find", f"gives no {key} anywhere in the range {unknown.spelled} may take with these options")
    reached = [v + target for _, v in values]
    raise InputError(
        "want",
        f"cannot be met: no {unknown.spelled} gives {key} = {fmt(target, 6)} {_unit(unit)}".rstrip()
        + f"; over {unknown.spelled} from {quantity_text(values[0][0], si_unit, 6)} to {quantity_text(values[-1][0], si_unit, 6)}, "
        + f"{key} reaches about {fmt(min(reached), 6)} to {fmt(max(reached), 6)} {_unit(unit)}".rstrip()
        + (f" (it jumps across the target {search.jumps} time{'s' if search.jumps > 1 else ''})" if search.jumps else ""),
    )
