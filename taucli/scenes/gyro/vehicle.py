"""A vehicle on a turn (--vehicle): the gyroscopic and centrifugal couples against the weight.

A vehicle of mass m, its centre of gravity h above the road, runs at v round a curve of radius R:
it turns at Ω = v/R, and its road wheels (each I_w, radius r_w) spin at ω_w = v/r_w, the engine's
rotating parts (I_e) at Gω_w (G the gear ratio; negative: the engine turns against the wheels).
The vehicle turns their angular momentum, which takes the gyroscopic couple

    C_g = (n I_w + G I_e) ω_w Ω          (n road wheels)

and the centrifugal force mv²/R at height h makes the couple C_c = mv²h/R, both tending to tip
it outward (C_g with the engine turning with the wheels; against them it may oppose C_c):

- four wheels, track x: each outer wheel carries mg/4 + (C_g + C_c)/(2x), each inner one
  mg/4 − (C_g + C_c)/(2x); the inner wheels lift (it overturns) where that is 0:
  v² = (mgxR/2) / ((4I_w + GI_e)/r_w + mh);
- two wheels: it leans into the turn until the weight's couple mgh sin θ balances
  (C_g + C_c) cos θ: tan θ = (v²/(Rg)) ((2I_w + GI_e)/r_w + mh)/(mh).
"""

from __future__ import annotations

import math

from taucli.core.errors import InputError
from taucli.options.gyro import COMMAND as TABLE
from taucli.options.table import Results
from taucli.writing.report import Report, Step, fmt, quantity_text

WHEELS = {"four-wheeler": 4, "two-wheeler": 2}


def vehicle_on_a_turn(kind: str, mass: float | None, cg_height: float | None, track: float | None, wheel_inertia: float | None,
                      wheel_radius: float | None, engine_inertia: float | None, gear_ratio: float | None, speed: float | None,
                      turn_radius: float | None, g: float) -> Report:
    """The couples, the wheels' loads and the overturning speed (four wheels), or the lean (two)."""
    if kind not in WHEELS:
        raise InputError("vehicle", "expected four-wheeler or two-wheeler", example="{vehicle} four-wheeler", got=repr(kind))
    for name, value in (("mass", mass), ("cg_height", cg_height), ("speed", speed), ("turn_radius", turn_radius)):
        if value is None:
            raise InputError(name, "is required with {vehicle}", example={"mass": "{mass} 2000kg", "cg_height": "{cg_height} 0.6m",
                                                                           "speed": "{speed} 90km/h", "turn_radius": "{turn_radius} 50m"}[name])
    if kind == "four-wheeler" and track is None:
        raise InputError("track", "is required for a four-wheeler (the distance between its inner and outer wheels)", example="{track} 1.5m")
    if kind == "two-wheeler" and track is not None:
        raise InputError("track", "is for a four-wheeler: a two-wheeler leans instead", example="{vehicle} four-wheeler {track} 1.5m")
    rotating = wheel_inertia is not None or engine_inertia is not None
    if rotating and wheel_radius is None:
        raise InputError("wheel_radius", "is required with {wheel_inertia} or {engine_inertia} (the wheels spin at v/r)", example="{wheel_radius} 0.3m")
    if gear_ratio is not None and engine_inertia is None:
        raise InputError("gear_ratio", "needs {engine_inertia} (the engine's rotating parts it turns)", example="{engine_inertia} '1kg*m^2' {gear_ratio} 4")
    wheels = WHEELS[kind]
    ratio = 1.0 if gear_ratio is None else gear_ratio
    spinning = wheels * (wheel_inertia or 0.0) + ratio * (engine_inertia or 0.0)  # n I_w + G I_e
    omega_wheel = speed / wheel_radius if rotating else 0.0
    omega_turn = speed / turn_radius
    gyroscopic = spinning * omega_wheel * omega_turn
    centrifugal = mass * speed * speed * cg_height / turn_radius
    results, notes = Results(TABLE), []
    steps = [Step("Rates", "ω_w = v/r_w,  Ω = v/R", f"{quantity_text(speed, 'm/s')} / {quantity_text(wheel_radius, 'm')}, {quantity_text(speed, 'm/s')} / {quantity_text(turn_radius, 'm')}"
                  if rotating else f"{quantity_text(speed, 'm/s')} / {quantity_text(turn_radius, 'm')}",
                  (f"ω_w = {quantity_text(omega_wheel, 'rad/s')}, " if rotating else "") + f"Ω = {quantity_text(omega_turn, 'rad/s')}",
                  "the wheels roll, so they spin at v/r_w; the vehicle's heading turns at v/R")]
    if kind == "four-wheeler":
        results.put("couple_gyro", gyroscopic)
        results.put("couple_centrifugal", centrifugal)
        share = (gyroscopic + centrifugal) / (2 * track)
        weight_share = mass * g / 4
        inner, outer = weight_share - share, weight_share + share
        lifts = "inner" if inner < 0 else "outer" if outer < 0 else None
        results.put("reaction_outer", None if lifts else outer)
        results.put("reaction_inner", None if lifts else inner)
        if lifts:
            notes.append(f"reaction_inner, reaction_outer: none: the {lifts} wheels lift at this speed, and the vehicle overturns "
                         f"{'outward' if lifts == 'inner' else 'inward'} (they would take {quantity_text(-min(inner, outer), 'N')} pulling down)")
        tipping = spinning / wheel_radius if rotating else 0.0
        tipping += mass * cg_height  # the couples are v²/R times this: outward where positive, inward where negative
        overturn = math.sqrt(mass * g * track * turn_radius / 2 / abs(tipping)) if tipping else None
        results.put("speed_overturn", overturn)
        if overturn is None:
            notes.append("speed_overturn: none: the engine's couple against the wheels cancels the centrifugal couple at every speed")
        elif tipping < 0:
            notes.append("speed_overturn: inward: the engine's couple against the wheels outweighs the centrifugal couple, so the outer wheels "
                         "unload at this speed")
        steps += [
            Step("Gyroscopic couple", "C_g = (4I_w + G·I_e) ω_w Ω", f"{quantity_text(spinning, 'kg*m**2')} × {quantity_text(omega_wheel, 'rad/s')} × {quantity_text(omega_turn, 'rad/s')}",
                 quantity_text(gyroscopic, "N*m"), "turning the spinning wheels' and engine's angular momentum takes this couple; its reaction on the "
                 "vehicle presses the outer wheels (the engine turning against the wheels subtracts)"),
            Step("Centrifugal couple", "C_c = m v² h / R", f"{fmt(mass)} kg × ({quantity_text(speed, 'm/s')})² × {quantity_text(cg_height, 'm')} / {quantity_text(turn_radius, 'm')}",
                 quantity_text(centrifugal, "N*m"), "the road's grip turns the vehicle at the ground; the centre of gravity, h above it, tips outward"),
            Step("Load on each wheel", "mg/4 ± (C_g + C_c)/(2x)", f"{quantity_text(weight_share, 'N')} ± {quantity_text(share, 'N')}",
                 f"outer {quantity_text(outer, 'N')}, inner {quantity_text(inner, 'N')}" + (" (a negative load: those wheels lift)" if lifts else ""),
                 "the couples are carried by the wheels' loads across the track x"),
        ]
        if overturn is not None:
            steps.append(Step(f"Speed at which it overturns ({'inner' if tipping > 0 else 'outer'} wheels unloaded)",
                              "v = √((mgxR/2) / |(4I_w + GI_e)/r_w + mh|)",
                              f"√(({fmt(mass)} kg × {quantity_text(g, 'm/s**2')} × {quantity_text(track, 'm')} × {quantity_text(turn_radius, 'm')} / 2) / "
                              f"{fmt(abs(tipping))} kg·m)", quantity_text(overturn, "m/s"),
                              "both couples grow as v², the weight's share does not"))
    else:
        tangent = speed * speed / (turn_radius * g) * ((spinning / wheel_radius if rotating else 0.0) + mass * cg_height) / (mass * cg_height)
        lean = math.atan(tangent)
        results.put("lean_balance", lean)
        results.put("couple_gyro", gyroscopic * math.cos(lean))
        results.put("couple_centrifugal", centrifugal * math.cos(lean))
        steps.append(Step("Lean that balances (the weight against both couples)", "tan θ = (v²/(Rg)) ((2I_w + GI_e)/r_w + mh)/(mh)",
                          f"({quantity_text(speed, 'm/s')})² / ({quantity_text(turn_radius, 'm')} × {quantity_text(g, 'm/s**2')}) × …",
                          f"θ = {fmt(math.degrees(lean))}°",
                          "leaning at θ, the weight's couple mgh sin θ balances (C_g + C_c) cos θ: the spinning wheels ask for more lean than the speed alone"))
    report = Report("gyro", f"a {kind} on a turn: gyroscopic and centrifugal couples", "closed form", results, steps, notes)
    return report
