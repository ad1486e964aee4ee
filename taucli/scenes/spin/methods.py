"""The choice of a method for the torque laws, and a fixed step's error against a reference.

auto is the closed form where one exists, else rk45. A fixed-step method (euler, rk4) has each
answer's error estimated against the closed form or a tight rk45 run; an answer estimated more
than WITHHELD_ABOVE off is withheld (null), with a note that gives it and a step that would do.
"""

from __future__ import annotations

import math

from taucli.core.errors import InputError
from taucli.numerics.steppers import METHODS
from taucli.writing.report import Table, fmt, quantity_text
from taucli.scenes.motion import DEFAULT_DT, DEFAULT_RTOL, Method

# A fixed step's answers are checked against a reference: the closed form where there is one,
# else rk45 at REFERENCE_RTOL (within 0.33 of it, tests/benchmarks/accuracy_rk45.py). Step
# doubling or Richardson extrapolation would be the method estimating itself, and it misses
# the worst case: a stop inside the first step is the same at dt, dt/2 and 2dt (Euler's one
# linear step from ω₀, located), so it would call an answer 88% off exact.
REFERENCE_RTOL = 1e-11


WITHHELD_ABOVE = 1e-3  # relative: a fixed-step answer estimated further off is withheld (null)


def error_estimate(results, reference: dict | None, against: str, chosen: Method, notes: list[str]) -> tuple[Table, float | None] | None:
    """The error of each of a fixed step's results against ``reference`` (the same run by the
    closed form or a tight rk45, its results by key; None: the reference could not be run): the
    table of them, and the largest relative error. Every numeric result is checked, so a result
    built from another (revs from θ, the works from the angles turned, the energy) is judged on
    its own value. Results off by more than WITHHELD_ABOVE are withheld (null), with one note that
    gives them and a step that would do.

    A result whose reference is 0 (KE at the stop) is judged against the largest reference
    value in its unit, so that round-off in a zero does not withhold it."""
    if reference is None:
        notes.append(f"no error estimate: the reference run ({against}) would take too many steps; the {chosen.name} answers are unchecked")
        return None
    scale: dict[str | None, float] = {}
    for value in reference.values():
        if _number(value.value):
            scale[value.unit] = max(scale.get(value.unit, 0.0), abs(value.value))
    rows, off, worst = [], [], 0.0
    for name, mine in list(results.items()):
        theirs = reference.get(name)
        if theirs is None or not (_number(mine.value) or _number(theirs.value)) or mine.value == theirs.value:
            continue
        got, exact, unit = mine.value, theirs.value, mine.unit
        error = relative = None
        if _number(got) and _number(exact):
            error = abs(got - exact)
            floor = 1e-9 * scale.get(unit, 0.0)
            relative = error / abs(exact) if abs(exact) > floor else (error / scale[unit] if scale.get(unit) else None)
        rows.append((name, got, error, unit, relative))
        if relative is not None and relative <= WITHHELD_ABOVE:
            worst = max(worst, relative)
            continue
        worst = math.inf if relative is None else max(worst, relative)
        shown = "none" if got is None else quantity_text(got, unit)
        gap = "" if relative is None else f", {_percent(relative)} off"
        off.append(f"{name} = {shown}{gap} ({'none' if exact is None else quantity_text(exact, unit)})")
        results[name] = mine._replace(value=None)
    if off:
        order = METHODS[chosen.name].order
        advice = "--method auto"
        if math.isfinite(worst) and 0 < worst <= 1:
            advice = f"--dt {fmt(chosen.dt * (WITHHELD_ABOVE / worst) ** (1 / order) / 2, 1)} s or less (its error goes as dt{'' if order == 1 else _SUPERSCRIPT[order]}), or {advice}"
        else:  # off by more than the answer itself: the step is past the method's stability limit, not merely coarse
            advice = f"{advice} (rk45 picks its own steps), or a much smaller --dt: at dt = {fmt(chosen.dt)} s the {chosen.name} steps run away"
        notes.append(
            f"{chosen.name} at dt = {fmt(chosen.dt)} s is off by more than {WITHHELD_ABOVE:g} here, estimated against {against} "
            f"(in brackets): {'; '.join(off)}; withheld. Try {advice}"
        )
    columns = (("result", None, "result"), ("value", None, "value"), ("error", None, "estimated error"), ("unit", None, "unit"), ("relative", None, "relative error"))
    return Table(columns, tuple(rows)), (worst if math.isfinite(worst) else None)


def _number(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


_SUPERSCRIPT = {2: "²", 3: "³", 4: "⁴", 5: "⁵"}


def _percent(relative: float) -> str:
    if relative >= 100:
        return f"{fmt(relative, 2)} times the answer"
    return f"{round(100 * relative)}%" if relative >= 0.01 else f"{fmt(100 * relative, 2)}%"


def choose_method(method: str, closed_form: bool, dt: float | None, rtol: float | None) -> Method:
    if method == "auto":
        return Method("exact") if closed_form else Method("rk45", None, rtol or DEFAULT_RTOL)
    if method == "exact":
        if not closed_form:
            raise InputError("method", "exact has no closed form for a drag exponent other than 1 or 2", hint="use {method} auto or rk45")
        return Method("exact")
    if method in ("euler", "rk4"):
        return Method(method, dt or DEFAULT_DT)
    if method == "rk45":
        return Method("rk45", dt, rtol or DEFAULT_RTOL)
    raise InputError("method", f"expected one of auto, exact, {', '.join(METHODS)}", example="{method} rk4 {dt} 1ms", got=repr(method))


def method_answers(motion, time: float | None, until_omega: float | None, until_angle: float | None = None) -> dict[str, float | None]:
    """What a method's motion answers (the results a step size changes), by name."""
    stop, signed_stop = motion.stop, motion.signed_stop
    answers: dict[str, float | None] = {"t_stop": None if stop is None else stop[0], "theta_stop": None if signed_stop is None else signed_stop[1]}
    if time is not None:
        answers["omega"], answers["theta"] = motion.state_at(time)
    if until_omega is not None:
        reached = motion.reach(until_omega)
        answers["t_until"], answers["theta_until"] = (None, None) if reached is None else reached
    if until_angle is not None:
        reached = motion.reach_angle(until_angle)
        answers["t_until"], answers["omega"] = (None, None) if reached is None else reached
    return answers
