"""A whole body of parts moved to a parallel axis (inertia --body-offset, #35 item 6, #46 item 8).

The parts are placed about an axis O: each part's centre of mass at distance dᵢ from it, in the
direction aᵢ round it (angle=; the shape's own at 0°). The body's centre of mass is

    c = Σ mᵢ dᵢ (cos aᵢ, sin aᵢ) / M

and its moment of inertia about the parallel axis through c, each part's own I_cᵢ moved to it,

    I_cm = Σ (I_cᵢ + mᵢ |pᵢ − c|²)   ( = I_O − M|c|², without that difference's cancellation)

Moved so that it turns about a parallel axis D from its centre of mass: I = I_cm + M D².
Where no part is off O (or one alone is, when its direction does not matter), c needs no
direction; where two or more are, each needs its angle=.
"""

from __future__ import annotations

import math
from dataclasses import replace

from taucli.core.errors import InputError
from taucli.quantities.kinds import check_bounds
from taucli.scenes.angles import cos_exact, sin_exact
from taucli.writing.report import Step, fmt, quantity_text

EXAMPLE = 'taucli inertia ring {mass} 10kg {radius} 0.5m {part} "rod mass=2kg length=0.5m axis=end angle=0deg" {part} "rod mass=2kg length=0.5m axis=end angle=180deg" {body_offset} 0.5m'


def moved(body, distance: float) -> tuple:
    """The whole body (a taucli.scenes.inertia.BodyInertia, whose module calls this one) moved to
    a parallel axis ``distance`` from its centre of mass, and its I_cm."""
    for found in body.parts:
        if found.part.mass is None:
            raise InputError("body_offset", "needs the mass of every part (the parallel-axis theorem takes the total mass)", example='{part} "inertia=0.2kg*m^2 mass=3kg"')
    places = _places(body)
    mass = body.mass
    if not mass:
        raise InputError("body_offset", "needs a body with mass (the parallel-axis theorem takes the total mass)", example=EXAMPLE)
    cx = math.fsum(found.part.mass * x for found, (x, _) in zip(body.parts, places)) / mass
    cy = math.fsum(found.part.mass * y for found, (_, y) in zip(body.parts, places)) / mass
    about_cm = math.fsum(found.inertia_centre + found.part.mass * ((x - cx) ** 2 + (y - cy) ** 2) for found, (x, y) in zip(body.parts, places))
    result = about_cm + mass * distance**2
    check_bounds(result, "moment of inertia", "{body_offset}", got=f"I = {result:g} kg*m**2")
    steps = list(body.steps)
    if any(found.offset for found in body.parts):
        steps += _centre_steps(body, places, math.hypot(cx, cy), about_cm)
        why = "the axis through the centre of mass is the one the parallel-axis theorem starts from; a parallel axis d away adds the whole mass at d"
    else:
        why = ("the parts are centred on the axis they were built about, so it passes through the body's centre of mass; "
               "a parallel axis d away adds the whole mass at d")
    steps.append(Step("Move the whole body (parallel-axis theorem)", "I = I_cm + Md²",
                      f"{quantity_text(about_cm, 'kg*m**2')} + {quantity_text(mass, 'kg')} × ({quantity_text(distance, 'm')})²",
                      quantity_text(result, "kg*m**2"), why))
    description = f"{body.description}, the whole shifted {fmt(distance)} m from its centre of mass (parallel-axis theorem)"
    return replace(body, inertia=result, steps=tuple(steps), description=description), about_cm


def _places(body) -> list[tuple[float, float]]:
    """Each part's centre (x, y) about the axis the body was built on: at its distance, in the
    direction of its angle= (the shape's at 0°; one part alone off the axis: any)."""
    off = [number for number, found in enumerate(body.parts) if found.offset]
    places = []
    for number, found in enumerate(body.parts):
        angle = found.part.angle
        if angle is None and number > 0 and found.offset and len(off) > 1:
            raise InputError(found.part.option("angle"), "is needed with {body_offset} where two or more parts are off the axis: where each lies "
                             "round it (from the shape's direction, 0°) places the body's centre of mass", example=EXAMPLE)
        angle = angle or 0.0
        places.append((found.offset * cos_exact(angle), found.offset * sin_exact(angle)))
    return places


def _centre_steps(body, places: list[tuple[float, float]], centre: float, about_cm: float) -> list[Step]:
    """The body's centre of mass from its parts' places, and its I about the axis through it."""
    terms = " + ".join(f"{fmt(found.part.mass)} kg × ({fmt(x)}, {fmt(y)}) m" for found, (x, y) in zip(body.parts, places) if found.offset)
    return [
        Step("Centre of mass of the body", "c = Σ mᵢpᵢ / M", f"|{terms}| / {quantity_text(body.mass, 'kg')}", quantity_text(centre, "m") + " from the axis",
             "each part's mass acts at its centre pᵢ (its distance from the axis, in the direction of its angle=); the centred parts add nothing"),
        Step("Moment of inertia about the centre of mass", "I_cm = Σ (I_cᵢ + mᵢ|pᵢ − c|²) = I_O − M|c|²",
             f"{quantity_text(body.inertia, 'kg*m**2')} − {quantity_text(body.mass, 'kg')} × ({quantity_text(centre, 'm')})²",
             quantity_text(about_cm, "kg*m**2"),
             "each part's own I about its centre, moved to the body's centre of mass; the axis the parts were built about is not "
             "through it, so its I_O is not I_cm"),
    ]
