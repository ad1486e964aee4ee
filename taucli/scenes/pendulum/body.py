"""The body on its pivot, from the options: I about the pivot, the mass m and the distance d from
the pivot to the centre of mass (--inertia with --mass and --cm-distance, or --shape and its
parts), and what swings it: gravity's torque mgd and a torsion spring's κθ.

    d = |Σmᵢdᵢ| / M   (the parts' centres on one line through the pivot, offset= negative on the
                      other side; θ is measured to the centre of mass)
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import NamedTuple

from taucli.core.errors import InputError
from taucli.writing.report import Step, fmt, quantity_text
from taucli.scenes.assumed import Assumed
from taucli.scenes.inertia import body_inertia, main_part
from taucli.scenes.pendulum.swing import Swing


class Body(NamedTuple):
    """I about the pivot, the mass (None where not given), d, the steps that found them, and words for the model."""
    inertia: float
    mass: float | None
    cm_distance: float
    steps: Sequence[Step]
    words: str


def read_body(inertia, shape, mass, axis, offset, part, cm_distance, dims, torsion: float | None, assumed: Assumed,
              gyration: float | None = None, density=None) -> Body:
    """The body from its options; with --inertia and a spring but no --cm-distance, d = 0 (a
    torsion pendulum on a vertical wire), with a note. --gyration with --mass is k about the pivot
    (with --cm-distance), or with --offset about the centre of mass, --offset from the pivot."""
    if gyration is not None:
        if inertia is not None:
            raise InputError("gyration", "conflicts with {inertia}: give the body's I one way")
        if offset is None and cm_distance is None and not torsion:
            raise InputError("gyration", "needs {cm_distance} when k is about the pivot (gravity's torque is mgd); or give {offset}: k about the centre of mass, "
                             "the centre that far from the pivot", example="{gyration} 0.3m {mass} 2kg {cm_distance} 0.5m")
        if offset is not None and cm_distance is not None:
            raise InputError("cm_distance", "conflicts with {offset}: with {gyration} the offset is the centre of mass's distance from the pivot")
    if inertia is not None:
        if shape is not None:
            raise InputError("inertia", "conflicts with {shape}: give one of them")
        given = [name for name, value in (("axis", axis), ("offset", offset), *dims.items()) if value is not None]
        if given or part:
            raise InputError(given[0] if given else "part", "goes with {shape}; with {inertia} give {cm_distance} and {mass}")
        if cm_distance is None:
            if not torsion:
                raise InputError("cm_distance", "is required with {inertia} (gravity's torque is mgd)", example="{cm_distance} 0.5m")
            cm_distance = 0.0
            assumed.notes.append("no --cm-distance: d = 0, gravity turns nothing (a torsion pendulum on a vertical wire)")
        if mass is not None and inertia < mass * cm_distance * cm_distance * (1 - 1e-12):
            raise InputError("inertia", f"expected at least M d² = {fmt(mass * cm_distance * cm_distance)} kg·m² about the pivot: "
                             "I = I_cm + Md², and I_cm is never negative", example="{inertia} '0.5kg*m^2' {mass} 1kg {cm_distance} 0.5m",
                             got=f"{fmt(inertia)} kg·m²")
        return Body(inertia, mass, cm_distance, (), "a body of given I")
    if shape is None and gyration is None:
        raise InputError("inertia", "or {shape} is required", example="{shape} rod {length} 1m {mass} 2kg {axis} end, or {inertia} '0.5kg*m^2' {mass} 2kg {cm_distance} 0.5m")
    found = body_inertia([main_part(shape, mass, axis, offset, dims, gyration, density), *part])
    assumed.notes.extend(found.notes)  # a thin disc about a diameter, said (#42 item 3)
    steps = list(found.steps)
    total = found.mass
    unknown = next((p.part for p in found.parts if p.part.mass is None), None)
    if unknown is not None and cm_distance != 0:  # gravity's torque Mgd needs every part's mass (a part of I alone crashed: #48 item 2); a torsion pendulum centred on its axis does not
        raise InputError(unknown.option("mass") if unknown.source else "mass", "is needed for each part of a pendulum: gravity's torque and the "
                         "pivot's force take every part's mass, and a part given by its inertia alone has none",
                         example=unknown.example("mass", "1kg") if unknown.source else "{mass} 1kg")
    if cm_distance is None:
        moment = math.fsum(p.part.mass * p.offset for p in found.parts)  # offsets signed: the other side of the pivot negative
        cm_distance = abs(moment) / total
        if moment < 0:
            assumed.notes.append("the centre of mass is on the side of the parts with negative offset=: θ is measured to it")
        if len(found.parts) > 1:
            steps.append(
                Step(
                    "Distance from the pivot to the centre of mass",
                    "d = Σmᵢdᵢ / M",
                    " + ".join(f"{fmt(p.part.mass)} kg × {fmt(p.offset)} m" for p in found.parts) + f" / {quantity_text(total, 'kg')}",
                    quantity_text(cm_distance, "m"),
                    "the parts' centres are taken on one line through the pivot, an offset= on the other side negative",
                )
            )
    return Body(found.inertia, total, cm_distance, steps, found.description)


def on_pivot(body: Body, torsion: float | None, g: float | None, angle0: float | None, omega0: float | None, angle: float | None,
             assumed: Assumed) -> tuple[Swing, float]:
    """The pendulum, I θ'' = −mgd sin θ − κθ from θ₀ and ω₀, and g (standard gravity where the body
    has a mass or d > 0 and --g is not given): refused where nothing swings it, and under gravity
    alone for angles beyond ±180°."""
    kappa = torsion or 0.0
    if body.cm_distance > 0 and body.mass is None:
        raise InputError("mass", "is required with {inertia} and {cm_distance} (gravity's torque is mgd)", example="{mass} 2kg")
    gravity = assumed.gravity(g) if body.cm_distance > 0 or body.mass is not None else (g or 0.0)
    gravity_torque = (body.mass or 0.0) * gravity * body.cm_distance
    if gravity_torque == 0 and kappa == 0:
        raise InputError(
            "cm_distance" if body.cm_distance == 0 else "g",
            "leaves nothing to swing the body: its centre of mass is on the pivot and there is no {torsion}" if body.cm_distance == 0
            else "is zero and there is no {torsion}: nothing swings the body",
        )
    theta0 = angle0 or 0.0
    if not kappa and abs(theta0) > math.pi:
        raise InputError("angle0", "expected an angle from −180 to 180 deg under gravity alone", got=_past_half_turn(theta0))
    if angle is not None and not kappa and abs(angle) > math.pi:
        raise InputError("angle", "expected an angle from −180 to 180 deg under gravity alone", got=_past_half_turn(angle))
    return Swing(body.inertia, gravity_torque, kappa, theta0, omega0 or 0.0), gravity


def _past_half_turn(angle: float) -> str:
    """An angle just past ±180° in degrees, with the digits that show it is past (fmt's six
    significant digits would print 180.00000001° as "180")."""
    degrees = math.degrees(angle)
    shown = fmt(degrees)
    return f"{shown if abs(float(shown.replace('−', '-'))) > 180 else repr(degrees)} deg"


def moved(body: Body, length_offset: float | None) -> Body:
    """The body moved away from the pivot by δ = --length-offset along the line to its centre of
    mass (a length measured to the top of a bob is short by the bob's radius): d = d₀ + δ and, by
    the parallel-axis theorem (I = I_cm + md²), I = I₀ + m((d₀ + δ)² − d₀²) = I₀ + mδ(2d₀ + δ)."""
    if not length_offset:
        return body
    if body.mass is None:
        raise InputError("length_offset", "moves the body's centre of mass, which needs its {mass} (I = I_cm + md²)", example="{mass} 50g {length_offset} 1.9cm")
    distance = body.cm_distance + length_offset
    if distance < 0:
        raise InputError("length_offset", f"would put the centre of mass on the other side of the pivot (d = {fmt(body.cm_distance)} m "
                         f"+ {fmt(length_offset)} m < 0)", got=f"{fmt(length_offset)} m")
    inertia = body.inertia + body.mass * length_offset * (2 * body.cm_distance + length_offset)
    step = Step("The body moved along the line to its centre of mass by the length offset",
                "d = d₀ + δ,  I = I₀ + mδ(2d₀ + δ)  (parallel axes: I = I_cm + md²)",
                f"d₀ = {quantity_text(body.cm_distance, 'm')}, δ = {quantity_text(length_offset, 'm')}, m = {quantity_text(body.mass, 'kg')}, "
                f"I₀ = {quantity_text(body.inertia, 'kg*m**2')}",
                f"d = {quantity_text(distance, 'm')}, I = {quantity_text(inertia, 'kg*m**2')}",
                "a length measured to the top of a bob is short of its centre by the bob's radius")
    return Body(inertia, body.mass, distance, (*body.steps, step), body.words + f", its centre of mass {fmt(length_offset)} m further from the pivot")
