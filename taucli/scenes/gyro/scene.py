"""``taucli gyro``: read which model the options ask for, and run it.

A --precession given (the rate at which a vehicle turns the rotor's axis) is a rotor on a
machine (machine.py); otherwise the weight (or a given torque) turns the axis of a top on a
pivot (top.py).
"""

from __future__ import annotations

from collections.abc import Sequence

from taucli.core.errors import InputError
from taucli.writing.report import Report
from taucli.scenes.gyro.machine import machine
from taucli.scenes.assumed import Assumed
from taucli.scenes.gyro.top import top
from taucli.scenes.gyro.vehicle import vehicle_on_a_turn

_MACHINE_ONLY = ("spin_sense", "turn", "lean", "craft", "bearing_span", "rotor")
_TOP_ONLY = ("cm_distance", "torque", "inertia_perp")


def gyro(
    *,
    inertia: float | None = None,
    shape: str | None = None,
    mass: float | None = None,
    radius: float | None = None,
    inner_radius: float | None = None,
    outer_radius: float | None = None,
    length: float | None = None,
    width: float | None = None,
    height: float | None = None,
    depth: float | None = None,
    axis: str | None = None,
    offset: float | None = None,
    part: Sequence = (),
    gyration: float | None = None,
    density=None,
    spin: float | None = None,
    cm_distance: float | None = None,
    torque: float | None = None,
    tilt: float | None = None,
    inertia_perp: float | None = None,
    precession: float | None = None,
    spin_sense: str | None = None,
    turn: str | None = None,
    lean: float | None = None,
    craft: str | None = None,
    bearing_span: float | None = None,
    rotor: Sequence = (),
    g: float | None = None,
    vehicle: str | None = None,
    cg_height: float | None = None,
    track: float | None = None,
    speed: float | None = None,
    turn_radius: float | None = None,
    wheel_inertia: float | None = None,
    wheel_radius: float | None = None,
    engine_inertia: float | None = None,
    gear_ratio: float | None = None,
) -> Report:
    """``taucli gyro``: a top on a pivot (its weight at --cm-distance, or --torque), or with
    --precession a rotor whose axis a vehicle turns (the gyroscopic couple), or with --vehicle a
    vehicle on a turn (vehicle.py)."""
    on_a_turn = {"cg_height": cg_height, "track": track, "speed": speed, "turn_radius": turn_radius, "wheel_inertia": wheel_inertia,
                 "wheel_radius": wheel_radius, "engine_inertia": engine_inertia, "gear_ratio": gear_ratio}
    if vehicle is not None:
        others = {"inertia": inertia, "shape": shape, "spin": spin, "precession": precession, "cm_distance": cm_distance, "torque": torque,
                  "tilt": tilt, "spin_sense": spin_sense, "turn": turn, "lean": lean, "rotor": rotor or None, "bearing_span": bearing_span,
                  "part": part or None, "gyration": gyration}
        for name, value in others.items():
            if value is not None:
                raise InputError(name, "does not apply with {vehicle}: the vehicle's wheels and engine are the rotors "
                                 "({wheel_inertia}, {engine_inertia}), its speed and turn their rates")
        assumed = Assumed()
        return assumed.applied(vehicle_on_a_turn(vehicle, mass, cg_height, track, wheel_inertia, wheel_radius, engine_inertia, gear_ratio,
                                                 speed, turn_radius, assumed.gravity(g)))
    for name, value in on_a_turn.items():
        if value is not None:
            raise InputError(name, "goes with {vehicle}: a vehicle on a turn", example="{vehicle} four-wheeler")
    dims = {"radius": radius, "inner_radius": inner_radius, "outer_radius": outer_radius, "length": length, "width": width, "height": height, "depth": depth}
    given = {"spin_sense": spin_sense, "turn": turn, "lean": lean, "craft": craft, "bearing_span": bearing_span, "rotor": rotor or None,
             "cm_distance": cm_distance, "torque": torque, "inertia_perp": inertia_perp}
    if precession is None:
        for name in _MACHINE_ONLY:
            if given[name] is not None:
                raise InputError(name, "goes with {precession}: the rate at which the vehicle turns the rotor's axis", example="{precession} '(100 km/h)/(75 m)'")
        return top(inertia=inertia, shape=shape, mass=mass, axis=axis, offset=offset, part=part, gyration=gyration, density=density, spin=spin,
                   cm_distance=cm_distance, torque=torque, tilt=tilt, inertia_perp=inertia_perp, g=g, **dims)
    for name in _TOP_ONLY:
        if given[name] is not None:
            raise InputError(name, "conflicts with {precession}: with the turning rate given, the couple it takes is found, not a top's own precession")
    if shape is None and gyration is None and mass is not None:
        raise InputError("mass", "goes with {shape}: with {inertia} (or parts) the rotor's mass is not used", example="{inertia} '400kg*(0.3m)^2'")
    report = machine(inertia=inertia, shape=shape, mass=mass, axis=axis, offset=offset, part=part, gyration=gyration, density=density, spin=spin, tilt=tilt, precession=precession,
                     spin_sense=spin_sense, turn=turn, lean=lean, craft=craft, bearing_span=bearing_span, rotor=tuple(rotor or ()), **dims)
    if g is not None:
        report.notes.append("g plays no part: the vehicle turns the rotor's axis at the rate given")
    return report
