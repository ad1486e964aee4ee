"""Angular momentum and impulse given as such (--momentum0, --momentum1, --impulse): ΔL = J = τΔt.

A body of fixed moment of inertia about a fixed axis, a torque τ acting for Δt:

    L₀ = Iω₀,   L₁ = Iω₁,   J = L₁ − L₀ = τΔt

four equations in L₀, L₁, J, τ, Δt, I, ω₀, ω₁: the givens fix what these equations reach from
them, each found once by the first equation that has all it needs, then every equation checked
against the rest (givens that disagree are refused, naming them). A book's "L from 2.4 to 3.6
kg·m²/s in 4 s" needs neither I nor ω: τ = ΔL/Δt. With I, ω₀ = L₀/I and ω₁ = L₁/I; the work the
torque does is KE₁ − KE₀ = J(ω₀ + ω₁)/2 = τθ.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import NamedTuple

from taucli.core.errors import InputError
from taucli.options.impulse import COMMAND as TABLE
from taucli.options.table import Results
from taucli.writing.report import Report, Step, fmt, quantity_text, term

AGREEMENT = 1e-9  # relative: givens that fix one quantity twice must agree this closely
UNITS = {"L0": "kg*m**2/s", "L1": "kg*m**2/s", "J": "N*m*s", "torque": "N*m", "duration": "s", "inertia": "kg*m**2", "omega0": "rad/s", "omega1": "rad/s"}
SYMBOLS = {"L0": "L₀", "L1": "L₁", "J": "J", "torque": "τ", "duration": "Δt", "inertia": "I", "omega0": "ω₀", "omega1": "ω₁"}
OPTIONS = {"L0": "momentum0", "L1": "momentum1", "J": "impulse", "torque": "torque", "duration": "duration", "inertia": "inertia", "omega0": "omega0", "omega1": "omega1"}


class Rule(NamedTuple):
    """``target`` from ``needs`` by ``equation``; ``form`` gives (value, the size of its terms), or None where it cannot."""

    target: str
    needs: tuple[str, ...]
    equation: str
    shown: str  # the equation's right side with the values, {0}, {1}, … in the order of ``needs``
    form: Callable[..., tuple[float, float] | None]
    why: str


def _quotient(a: float, b: float) -> tuple[float, float] | None:
    return None if b == 0 else (a / b, abs(a / b))


RULES = (
    Rule("L0", ("inertia", "omega0"), "L₀ = Iω₀", "{0} × {1}", lambda i, w: (i * w, abs(i * w)), "angular momentum of a body about its axis"),
    Rule("L1", ("inertia", "omega1"), "L₁ = Iω₁", "{0} × {1}", lambda i, w: (i * w, abs(i * w)), "angular momentum of a body about its axis"),
    Rule("J", ("L0", "L1"), "J = ΔL = L₁ − L₀", "{1} − {0}", lambda l0, l1: (l1 - l0, max(abs(l0), abs(l1))), "the angular impulse is the change of angular momentum"),
    Rule("J", ("torque", "duration"), "J = τΔt", "{0} × {1}", lambda tau, dt: (tau * dt, abs(tau * dt)), "a constant torque (or its mean) times the time it acts"),
    Rule("L1", ("L0", "J"), "L₁ = L₀ + J", "{0} + {1}", lambda l0, j: (l0 + j, max(abs(l0), abs(j))), "the impulse adds to the angular momentum"),
    Rule("L0", ("L1", "J"), "L₀ = L₁ − J", "{0} − {1}", lambda l1, j: (l1 - j, max(abs(l1), abs(j))), "the impulse added to the angular momentum"),
    Rule("torque", ("J", "duration"), "τ = J/Δt = ΔL/Δt", "{0} / {1}", _quotient, "the rate of change of angular momentum (the mean torque)"),
    Rule("duration", ("J", "torque"), "Δt = J/τ = ΔL/τ", "{0} / {1}", _quotient, "how long the torque takes to make the change"),
    Rule("omega0", ("L0", "inertia"), "ω₀ = L₀/I", "{0} / {1}", _quotient, "L = Iω"),
    Rule("omega1", ("L1", "inertia"), "ω₁ = L₁/I", "{0} / {1}", _quotient, "L = Iω"),
    Rule("inertia", ("L0", "omega0"), "I = L₀/ω₀", "{0} / {1}", _quotient, "L = Iω"),
    Rule("inertia", ("L1", "omega1"), "I = L₁/ω₁", "{0} / {1}", _quotient, "L = Iω"),
    Rule("inertia", ("J", "omega0", "omega1"), "I = J/(ω₁ − ω₀)", "{0} / ({2} − {1})", lambda j, w0, w1: _quotient(j, w1 - w0), "J = IΔω"),
    Rule("omega1", ("omega0", "J", "inertia"), "ω₁ = ω₀ + J/I", "{0} + {1} / {2}", lambda w0, j, i: (w0 + j / i, max(abs(w0), abs(j / i))), "J = IΔω"),
    Rule("omega0", ("omega1", "J", "inertia"), "ω₀ = ω₁ − J/I", "{0} − {1} / {2}", lambda w1, j, i: (w1 - j / i, max(abs(w1), abs(j / i))), "J = IΔω"),
)


def solve_momentum(inertia: float | None, omega0: float | None, omega1: float | None, torque: float | None, duration: float | None,
                   momentum0: float | None, momentum1: float | None, impulse: float | None, *, inertia_steps: Sequence[Step] = ()) -> Report:
    """What L₀ = Iω₀, L₁ = Iω₁, J = L₁ − L₀ = τΔt fix from the givens (see the module); a body
    given with an impulse and no state at all starts at rest (ω₀ = 0, with a note)."""
    known = {"L0": momentum0, "L1": momentum1, "J": impulse, "torque": torque, "duration": duration, "inertia": inertia, "omega0": omega0, "omega1": omega1}
    known = {name: value for name, value in known.items() if value is not None}
    rests_on = {name: {name} for name in known}  # the givens each value rests on, for a refusal's message
    notes: list[str] = []
    if "inertia" in known and not {"L0", "L1", "omega0", "omega1"} & set(known) and ("J" in known or {"torque", "duration"} <= set(known)):
        known["omega0"], rests_on["omega0"] = 0.0, set()
        notes.append("no --omega0 (nor --momentum0): the body starts at rest (ω₀ = 0); give --omega0 for another start")
    steps = list(inertia_steps)
    solved: list[str] = []
    changed = True
    while changed:
        changed = False
        for rule in RULES:
            if not all(name in known for name in rule.needs):
                continue
            formed = rule.form(*(known[name] for name in rule.needs))
            if formed is None:  # a quotient over zero: L ≠ 0 at ω = 0, J ≠ 0 under τ = 0 or with ω₁ = ω₀
                top, bottom = rests_on[rule.needs[0]], set().union(*(rests_on[name] for name in rule.needs[1:]))
                if known[rule.needs[0]] != 0 and not top & bottom:  # (from the same givens, a zero there is rounding's)
                    _refuse(rule, f"{rule.equation} divides {SYMBOLS[rule.needs[0]]} = {fmt(known[rule.needs[0]], 6)} {_plain(UNITS[rule.needs[0]])} by zero",
                            rests_on)
                continue
            value, size = formed
            if rule.target in known:
                if not rests_on[rule.target] <= set().union(*(rests_on[name] for name in rule.needs)):
                    _check(rule, value, size, known, rests_on)  # two ways from different givens (one way from the same ones agrees by itself)
                continue
            _check_sign(rule, value)
            known[rule.target] = value
            rests_on[rule.target] = set().union(*(rests_on[name] for name in rule.needs))
            solved.append(rule.target)
            changed = True
            numbers = rule.shown.format(*(term(known[name], UNITS[name]) for name in rule.needs))
            steps.append(Step(f"Solve for {SYMBOLS[rule.target]}", rule.equation, numbers, quantity_text(value, UNITS[rule.target]), rule.why))
    if not solved:
        raise InputError(" and ".join("{" + OPTIONS[name] + "}" for name in known), ("fix nothing more by themselves" if len(known) > 1 else
                         "fixes nothing more by itself") + ": give two of "
                         "{momentum0}, {momentum1}, {impulse} with a time or a torque, or a body with its state",
                         example="{momentum0} '2.4kg*m^2/s' {momentum1} '3.6kg*m^2/s' {duration} 4s")
    return _report(known, solved, notes, steps)


def _check(rule: Rule, value: float, size: float, known: dict, rests_on: dict) -> None:
    """A quantity fixed twice: the two must agree, else the givens behind them are named."""
    held = known[rule.target]
    if abs(value - held) <= AGREEMENT * max(size, abs(held), 1e-300):
        return
    unit = _plain(UNITS[rule.target])
    _refuse(rule, f"{SYMBOLS[rule.target]} = {fmt(held, 6)} {unit} but {rule.equation.split(' = ')[-1]} = {fmt(value, 6)} {unit}", rests_on)


def _refuse(rule: Rule, why: str, rests_on: dict) -> None:
    """The givens behind ``rule`` (its target's and its needs') disagree: named, with ``why``."""
    givens = sorted(rests_on.get(rule.target, set()).union(*(rests_on[name] for name in rule.needs)), key=list(OPTIONS).index)
    names = ["{" + OPTIONS[name] + "}" for name in givens]
    raise InputError(", ".join(names[:-1]) + " and " + names[-1] if len(names) > 1 else names[0], f"disagree: {why}; leave one of them out",
                     example="{momentum0} '2.4kg*m^2/s' {momentum1} '3.6kg*m^2/s' {duration} 4s")


def _check_sign(rule: Rule, value: float) -> None:
    """A time and a moment of inertia found from the others must be positive."""
    if rule.target == "duration" and value <= 0:
        raise InputError("torque", "must act in the sense of the change of angular momentum for a positive duration",
                         example="{momentum0} '2.4kg*m^2/s' {momentum1} '3.6kg*m^2/s' {torque} '0.3N*m'", got=f"Δt = J/τ = {fmt(value)} s")
    if rule.target == "inertia" and value <= 0:
        raise InputError("omega0", "and the angular momentum must have the same sense for a positive moment of inertia",
                         example="{momentum0} '2.4kg*m^2/s' {omega0} '12rad/s'", got=f"I = {fmt(value)} kg·m²")


def _plain(unit: str) -> str:
    return unit.replace("**2", "²").replace("*", "·")


def _report(known: dict, solved: list[str], notes: list[str], steps: list[Step]) -> Report:
    i, w0, w1, j = (known.get(name) for name in ("inertia", "omega0", "omega1", "J"))
    results = Results(TABLE)
    results.put("J", j, " ΔL = L₁ − L₀" + (" (solved for)" if "J" in solved else ""))
    results.put("delta_omega", j / i if j is not None and i is not None else None)
    for name in ("inertia", "omega0", "omega1", "torque", "duration", "L0", "L1"):
        results.put(name, known.get(name), " (solved for)" if name in solved else "")
    l0, l1 = known.get("L0"), known.get("L1")
    results.put("KE0", l0 * l0 / (2 * i) if l0 is not None and i is not None else None)
    results.put("KE1", l1 * l1 / (2 * i) if l1 is not None and i is not None else None)
    work = j * (w0 + w1) / 2 if None not in (j, w0, w1) else None  # KE₁ − KE₀ = (L₁ − L₀)(L₁ + L₀)/2I, the torque's τθ
    results.put("work", work)
    if work is not None:
        steps.append(Step("The torque's work", "W = KE₁ − KE₀ = J(ω₀ + ω₁)/2 = τθ", f"{term(j, 'N*m*s')} × ({term(w0, 'rad/s')} + {term(w1, 'rad/s')}) / 2",
                          quantity_text(work, "J"), "(L₁² − L₀²)/2I, as the impulse times the mean angular velocity"))
    unfixed = [name for name in ("J", "torque", "duration", "inertia", "omega0", "omega1", "L0", "L1") if name not in known]
    if unfixed:
        notes.append(f"{', '.join(unfixed)}: not fixed by what is given (L₀ = Iω₀, L₁ = Iω₁, J = L₁ − L₀ = τΔt)")
    reached = ", ".join(SYMBOLS[name] for name in solved)
    return Report("impulse", f"angular momentum given: ΔL = J = τΔt, L = Iω; solved for {reached}", "closed form", results, steps, notes)
