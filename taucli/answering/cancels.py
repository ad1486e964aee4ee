"""An input a refusal asks for that some results do not use (#42 items 14, 16): a body given by
its shape without its mass, a band brake without its drum's radius. The results that do not
depend on it are given, the others null with the reason.

A shape's I is M times a function of its dimensions, so wherever the mass cancels (a pendulum's
period, a disc's precession rate, a radius of gyration) the answer exists without it. Rather than
teach every solver which of its results the mass cancels from, the scene is solved with two
stand-in masses, 1 kg and 4 kg (a power of two: a product or quotient of the mass scales exactly,
so a result free of it comes out bit for bit the same): a result, a step, a note or a table that
differs between the two depends on the mass and is left out (a result: null, with a note naming
--mass; asked for with --get: refused, naming --mass). The stand-in never reaches a number shown.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import replace

from taucli.core.errors import InputError
from taucli.writing.report import Report

STAND_INS = (1.0, 4.0)  # kg
TOLERANCE = 1e-13  # relative: a result that moves less than this between the two stand-ins is taken as free of the mass


def stand_ins(arguments: Mapping[str, object], error: InputError) -> tuple[list[dict], str, str, str] | None:
    """The two runs with stand-ins for what the refusal asked for, where it may cancel out; the
    option it belongs to; what it is, for the note; how a --get of a result that needs it is
    refused (%s: the result). None where the refusal stands.

    - a body given by a shape (not by its density or radius of gyration) with no --mass;
    - a band brake with no radius= round a body with none (#42 item 16): its tensions and μ do
      not depend on the drum's radius, only its torque does."""
    if (error.option == "mass" and arguments.get("mass") is None and arguments.get("shape") is not None
            and arguments.get("density") is None and arguments.get("gyration") is None):
        return [{**arguments, "mass": mass} for mass in STAND_INS], "mass", "{mass}", "is required for %s, which depends on the body's mass"
    bands = arguments.get("band") or ()
    if "radius=" in error.expected and any(error.option == band.source.strip("{}") for band in bands):
        runs = [{**arguments, "band": tuple(replace(band, radius=radius) if band.radius is None else band for band in bands)} for radius in STAND_INS]
        return runs, "band", "radius= in {band} (the drum's radius)", "needs radius= for %s, which depends on the drum's radius"
    return None


def without(solver: Callable[..., Report], runs: list[dict], option: str, what: str, refusal: str, error: InputError) -> Report:
    """The report with every result the stand-ins leave the same; the others null, named in
    ``needs``. Refuses (with the solver's own message) when no result is free of them."""
    first, second = (solver(**run) for run in runs)
    results, needs = {}, []
    for key, value in first.results.items():
        other = second.results.get(key)
        if other is not None and _same(value.value, other.value):
            results[key] = value
        else:
            results[key] = value._replace(value=None)
            if value.value is not None:
                needs.append(key)
    if all(value.value is None for value in results.values()):
        raise error
    steps = [step for step, other in zip(first.steps, second.steps) if step == other] if len(first.steps) == len(second.steps) else []
    notes = [note for note in first.notes if note in second.notes]
    if needs:
        notes.append(f"no {what}: {', '.join(needs)} {'depends' if len(needs) == 1 else 'depend'} on it and {'is' if len(needs) == 1 else 'are'} not given; "
                     "the other results do not")
    tables = {name: table for name, table in first.tables.items() if second.tables.get(name) == table}
    trajectory = first.trajectory if _same_motion(first, second) else None
    return replace(first, results=results, steps=steps, notes=notes, tables=tables, trajectory=trajectory,
                   needs={key: (option, refusal % key) for key in needs})


def _same(a, b) -> bool:
    if isinstance(a, float) and isinstance(b, float) and not isinstance(a, bool):
        if math.isnan(a) or math.isnan(b):
            return math.isnan(a) and math.isnan(b)
        return a == b or abs(a - b) <= TOLERANCE * max(abs(a), abs(b))
    return a == b


def _same_motion(first: Report, second: Report) -> bool:
    """Whether the two stand-ins move alike (a chart of the motion is then free of the mass)."""
    if first.trajectory is None or second.trajectory is None:
        return first.trajectory is None and second.trajectory is None
    try:
        one, two = first.trajectory(), second.trajectory()
        return all(len(p) == len(q) and all(_same(x, y) for x, y in zip(p, q)) for p, q in zip(one.sample(17), two.sample(17), strict=True))
    except (ValueError, ArithmeticError):
        return False
