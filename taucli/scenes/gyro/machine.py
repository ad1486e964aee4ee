"""A rotor on a machine whose axis is turned: the gyroscopic couple and its effect.

A rotor of moment of inertia I spins at ω_s; the vehicle it is mounted in turns its axis at Ω
(a ship or aircraft turning at v/R, a ship pitching, a two-wheeler on a curve). The angular
momentum L = Iω_s ŝ then changes at dL/dt = Ω × L: the frame must apply that couple to the
rotor (the active gyroscopic couple), and the rotor pushes back on the frame with the opposite,
L × Ω (the reactive couple, whose effect on the vehicle the books describe). Its size is

    C = Iω_sΩ sin θ,

θ the angle between the spin axis and the axis the vehicle turns about (90° in the usual case:
a fore-and-aft rotor in a turn or a pitch). Carried by two bearings a span l apart, it is a
pair of equal and opposite forces C/l across the shaft; the bearing at the end the spin vector
points to is pushed along (L × Ω) × ŝ.

The vehicle's axes: x forward (bow, nose, front), y to the left (port), z up. A rotor turning
clockwise seen from the rear spins along +x (right-hand rule); a turn to the left is Ω along +z,
the front rising is Ω along −y, a roll with the right side going down Ω along +x. A lean φ (right
side down positive) turns the rotor's axis about x before the vehicle turns it.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from taucli.core.errors import InputError
from taucli.options.gyro import COMMAND as TABLE, SPIN_SENSES
from taucli.writing.report import Report, Step, fmt, quantity_text
from taucli.scenes.angles import cos_exact, sin_exact
from taucli.scenes.gyro.roots import finite
from taucli.scenes.inertia import body
from taucli.scenes.torque import cross, size
from taucli.options.table import Results

Vector = tuple[float, float, float]

# The direction a viewer stands in, from the rotor; a rotor clockwise seen from there spins away from them.
_VIEWPOINTS: dict[str, Vector] = {
    "rear": (-1.0, 0.0, 0.0), "front": (1.0, 0.0, 0.0), "left": (0.0, 1.0, 0.0),
    "right": (0.0, -1.0, 0.0), "above": (0.0, 0.0, 1.0), "below": (0.0, 0.0, -1.0),
}  # fmt: skip
# The axis each motion of the vehicle turns about (right-hand rule).
TURN_AXES: dict[str, Vector] = {
    "left": (0.0, 0.0, 1.0), "right": (0.0, 0.0, -1.0), "pitch-up": (0.0, -1.0, 0.0),
    "pitch-down": (0.0, 1.0, 0.0), "roll-right": (1.0, 0.0, 0.0), "roll-left": (-1.0, 0.0, 0.0),
}  # fmt: skip
# The words of each craft: front, rear, left, right, and the vehicle itself.
WORDS = {
    "vehicle": ("front", "rear", "left", "right", "vehicle"),
    "ship": ("bow", "stern", "port", "starboard", "ship"),
    "aircraft": ("nose", "tail", "left", "right", "aircraft"),
}
# How a book names each viewpoint, in a craft's words (front, rear, left, right, name).
_VIEW_WORDS = {
    "rear": lambda w: f"the {w[1]}", "front": lambda w: f"the {w[0]}", "left": lambda w: f"the {w[2]}",
    "right": lambda w: f"the {w[3]}", "above": lambda w: "above", "below": lambda w: "below",
}  # fmt: skip
_SHARE_SHOWN = 1e-12  # a component below this share of the couple is rounding, not an effect


def spin_direction(sense: str) -> Vector:
    """The unit vector of the spin in the vehicle's axes, from "cw-from-rear" and the like: a rotor
    turning clockwise seen from a viewpoint spins away from it (right-hand rule)."""
    turn, _, viewpoint = sense.split("-", 2)
    towards = _VIEWPOINTS[viewpoint]
    sign = -1.0 if turn == "cw" else 1.0
    return tuple(sign * c for c in towards)


def lean_turned(v: Vector, lean: float) -> Vector:
    """v turned about the forward axis x by the lean φ (right side down for φ > 0, that is about +x);
    exact at whole right angles, so that a spin axis leaned onto the turn's axis has no couple (#42 item 10)."""
    c, s = cos_exact(lean), sin_exact(lean)
    return (v[0], c * v[1] - s * v[2], s * v[1] + c * v[2])


def effect_words(couple: Vector, craft: str) -> str:
    """What the reactive couple does to the vehicle, as the books say it: raises the bow and lowers
    the stern, turns the ship towards port, rolls it to starboard; each share sized where there are several."""
    front, rear, left, right, name = WORDS[craft]
    total = size(couple)
    if total == 0:
        return "none"
    x, y, z = couple
    parts = []
    if abs(y) > _SHARE_SHOWN * total:
        lowers = "dips" if craft == "aircraft" else "lowers"
        parts.append((f"raises the {front} and {lowers} the {rear}" if y < 0 else f"lowers the {front} and raises the {rear}", abs(y)))
    if abs(z) > _SHARE_SHOWN * total:
        side = left if z > 0 else right
        parts.append((f"turns the {name} towards {side}" if craft == "ship" else f"turns the {name} to the {side}", abs(z)))
    if abs(x) > _SHARE_SHOWN * total:
        side = right if x > 0 else left
        parts.append((f"rolls the {name} to {side}" if craft == "ship" else f"rolls the {name} to the {side}", abs(x)))
    if len(parts) == 1:
        return parts[0][0]
    return "; ".join(f"{words} ({quantity_text(share, 'N*m')})" for words, share in parts)


def _direction_words(v: Vector, craft: str) -> str | None:
    """up, down, towards the bow, to port, ... for a vector along one of the vehicle's axes; None otherwise."""
    front, rear, left, right, _ = WORDS[craft]
    total = size(v)
    named = [(abs(c), i) for i, c in enumerate(v) if abs(c) > 1e-9 * total]
    if len(named) != 1:
        return None
    i = named[0][1]
    positive = v[i] > 0
    return [(f"towards the {front}", f"towards the {rear}"), (_to_side(left, craft), _to_side(right, craft)), ("up", "down")][i][0 if positive else 1]


def _to_side(side: str, craft: str) -> str:
    """ "to port" (a ship's sides are names), "to the left"."""
    return f"to {side}" if craft == "ship" else f"to the {side}"


def _end_words(s: Vector, craft: str) -> str | None:
    front, rear, left, right, _ = WORDS[craft]
    total = size(s)
    named = [i for i, c in enumerate(s) if abs(c) > 1e-9 * total]
    if len(named) != 1:
        return None
    i = named[0]
    return [(front, rear), (left, right), ("upper", "lower")][i][0 if s[i] > 0 else 1]


def machine(
    *,
    inertia: float | None = None,
    shape: str | None = None,
    mass: float | None = None,
    axis: str | None = None,
    offset: float | None = None,
    part: Sequence = (),
    gyration: float | None = None,
    density=None,
    spin: float | None = None,
    tilt: float | None = None,
    precession: float,
    spin_sense: str | None = None,
    turn: str | None = None,
    lean: float | None = None,
    craft: str | None = None,
    bearing_span: float | None = None,
    rotor: Sequence = (),
    **dims: float | None,
) -> Report:
    """The gyroscopic couple on a rotor whose axis the vehicle turns at --precession."""
    body_notes: list[str] = []
    moment, body_steps = body(inertia=inertia, shape=shape, mass=mass if shape is not None or gyration is not None else None, axis=axis, offset=offset, part=part,
                              gyration=gyration, density=density, notes=body_notes, **dims)  # a rotor by its radius of gyration, or its density (#42 item 15)
    if spin is None:
        raise InputError("spin", "is required: the rotor's spin about its axis", example="{spin} 2400rpm")
    craft = craft or "vehicle"
    sensed = spin_sense is not None and turn is not None
    if (spin_sense is None) != (turn is None):
        missing = "turn" if turn is None else "spin_sense"
        raise InputError(missing, "is required with {" + ("spin_sense" if turn is None else "turn") + "}: the couple's effect needs the rotor's sense and the vehicle's turn",
                         example="{spin_sense} cw-from-rear {turn} left")
    if sensed and tilt is not None:
        raise InputError("tilt", "conflicts with {spin_sense} and {turn}: they fix the angle between the spin axis and the turn's axis")
    if rotor and not sensed:
        raise InputError("rotor", "goes with {spin_sense} and {turn}: the rotors' angular momenta add as vectors, each with its sense",
                         example='{spin_sense} cw-from-right {turn} left {rotor} "inertia=0.3kg*m^2 spin=5000rpm sense=cw-from-right"')
    if rotor and bearing_span is not None:
        raise InputError("bearing_span", "is one rotor's: with {rotor} the couple is the rotors' together, carried by several shafts")
    for other in rotor:
        if other.sense not in SPIN_SENSES:
            raise InputError(other.source, "expected sense= one of " + ", ".join(SPIN_SENSES), example='{rotor} "inertia=0.3kg*m^2 spin=5000rpm sense=cw-from-right"',
                             got=repr(other.sense))
    if lean is not None and not sensed:
        raise InputError("lean", "goes with {spin_sense} and {turn}: the lean turns the rotor's axis, whose sense they give", example="{spin_sense} cw-from-left {turn} right {lean} 20deg")
    angular_momentum = moment * spin
    if not math.isfinite(angular_momentum):
        raise InputError("spin", "gives no usable angular momentum Iω_s with this body (out of range)", got=f"I = {fmt(moment)} kg·m², ω_s = {fmt(spin)} rad/s")
    notes: list[str] = [*body_notes]
    results = Results(TABLE)
    results.put("couple", None)  # first: the answer, and what a sweep charts (filled in below)
    results.put("L", finite(angular_momentum))
    steps = list(body_steps)
    steps.append(Step("Spin angular momentum of the rotor", "L = Iω_s", f"{quantity_text(moment, 'kg*m**2')} × {quantity_text(spin, 'rad/s')}",
                      quantity_text(angular_momentum, "kg*m**2/s"), "the rotor spins about its own axis, so L lies along it"))
    if sensed:
        spin_axis = spin_direction(spin_sense)
        if lean:
            spin_axis = lean_turned(spin_axis, lean)
        turn_axis = TURN_AXES[turn]
        momentum = tuple(angular_momentum * c for c in spin_axis)
        if rotor:
            momentum = _rotors_added(momentum, rotor, lean, steps)
        turning = tuple(precession * c for c in turn_axis)
        reactive = cross(momentum, turning)
        couple = size(reactive)
        sine = size(cross(momentum, turn_axis)) / size(momentum) if any(momentum) else 0.0
        results.put("couple", finite(couple), " on the vehicle, L × Ω")
        effect = effect_words(reactive, craft)
        results.put("effect", effect)
        turn_word, _, viewpoint = spin_sense.split("-", 2)
        spin_words = f"{'clockwise' if turn_word == 'cw' else 'counter-clockwise'} seen from {_VIEW_WORDS[viewpoint](WORDS[craft])}"
        steps.append(Step("The directions (right-hand rule)", f"ŝ = {_vec(spin_axis)},  Ω̂ = {_vec(turn_axis)}", "", "",
                          f"axes x forward (to the {WORDS[craft][0]}), y {_to_side(WORDS[craft][2], craft)}, z up; a rotor turning {spin_words} spins along ŝ"
                          + (f", turned by the lean of {fmt(math.degrees(lean))}° about x" if lean else "")
                          + f"; the turn ({turn}) is a rotation about Ω̂"))
        steps.append(Step("The couple the frame applies to turn L (active)", "C_active = dL/dt = Ω × L",
                          f"{quantity_text(precession, 'rad/s')} {_vec(turn_axis)} × "
                          + (f"{quantity_text(angular_momentum, 'kg*m**2/s')} {_vec(spin_axis)}" if not rotor else f"{_vec(momentum)} kg·m²/s"),
                          f"{_vec(tuple(-c for c in reactive))} N·m",
                          "L keeps its size but its direction turns at Ω, so it changes at Ω × L; the bearings must apply that couple to the rotor"))
        steps.append(Step("The reactive couple on the vehicle", "C = L × Ω,  |C| = Iω_sΩ sin θ",
                          f"{quantity_text(size(momentum), 'kg*m**2/s')} × {quantity_text(precession, 'rad/s')} × {fmt(sine)}",
                          f"{quantity_text(couple, 'N*m')}: {effect}",
                          "the rotor pushes back on its bearings with the opposite couple; θ is the angle between the spin axis and the turn's axis"))
        if couple == 0 and precession > 0:
            notes.append("no gyroscopic couple: the vehicle turns the rotor about its own spin axis, so L does not change direction")
    else:
        theta = math.pi / 2 if tilt is None else tilt
        if not 0 <= theta <= math.pi + 1e-15:
            raise InputError("tilt", "expected an angle from 0 to 180 deg between the spin axis and the axis it is turned about", example="{tilt} 90deg")
        sine = 1.0 if tilt is None else sin_exact(theta)
        couple = abs(angular_momentum) * precession * sine
        reactive = None
        results.put("couple", finite(couple), ", Iω_sΩ" + (" sin θ" if tilt is not None else ""))
        steps.append(Step("Gyroscopic couple", "C = Iω_sΩ" + (" sin θ" if tilt is not None else ""),
                          f"{quantity_text(angular_momentum, 'kg*m**2/s')} × {quantity_text(precession, 'rad/s')}" + (f" × sin {fmt(math.degrees(theta))}°" if tilt is not None else ""),
                          quantity_text(couple, "N*m"),
                          "L keeps its size but its direction turns at Ω, so it changes at Ω × L: the frame must apply this couple, and the rotor "
                          "pushes back on it with the same couple the other way" + ("; θ is the angle between the spin axis and the axis it is turned about" if tilt is not None else
                                                                                   " (the spin axis at right angles to the axis it is turned about: --tilt for another angle)")))
        notes.append("effect: give --spin-sense and --turn to have the couple's effect on the vehicle in words")
    if bearing_span is not None:
        force = couple / bearing_span
        results.put("bearing_force", finite(force), ", equal and opposite at the two bearings")
        where = "each bearing carries it across the shaft, the two forces opposite"
        if reactive is not None and couple > 0:
            push = cross(reactive, spin_axis)
            end, direction = _end_words(spin_axis, craft), _direction_words(push, craft)
            if end and direction:
                other = _direction_words(tuple(-c for c in push), craft)
                opposite_end = _end_words(tuple(-c for c in spin_axis), craft)
                where = f"the rotor pushes the bearing at its {end} end {direction} and the one at its {opposite_end} end {other}"
                notes.append(f"bearing_force: {where} (the gyroscopic part alone; the rotor's weight adds its share)")
        steps.append(Step("Bearing forces", "F = C/l", f"{quantity_text(couple, 'N*m')} / {quantity_text(bearing_span, 'm')}", quantity_text(force, "N"),
                          f"a couple carried by two bearings l apart is a pair of equal, opposite forces across the shaft: {where}"))
    model = "gyroscopic couple on a rotor whose axis is turned: C = Iω_sΩ" + (" sin θ" if sensed and sine != 1.0 or tilt is not None else "")
    return Report("gyro", model, "closed form", results, steps, notes)


def _rotors_added(momentum: Vector, rotors: Sequence, lean: float | None, steps: list[Step]) -> Vector:
    """The first rotor's L with each --rotor's Iω_s along its own sense (turned by the lean): angular momenta add as vectors."""
    terms = [momentum]
    for other in rotors:
        axis = spin_direction(other.sense)
        if lean:
            axis = lean_turned(axis, lean)
        terms.append(tuple(other.inertia * other.spin * c for c in axis))
    total = tuple(math.fsum(t[i] for t in terms) for i in range(3))
    steps.append(Step("The rotors' angular momenta add", "L = Σ Iᵢω_sᵢ ŝᵢ", " + ".join(f"{_vec(t)}" for t in terms), f"{_vec(total)} kg·m²/s",
                      "each rotor's L lies along its own axis, in its own sense; the vehicle turns them all at Ω, so the couple is Ω × ΣL "
                      "(a rotor the other way round takes away)"))
    return total


def _vec(v: Vector) -> str:
    """(0, −1, 0): a direction or a vector in a step, with true minus signs."""
    return "(" + ", ".join(fmt(0.0 if abs(c) < 1e-15 else c, 4).replace("-", "−", 1) for c in v) + ")"
