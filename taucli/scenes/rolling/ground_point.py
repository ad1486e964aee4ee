"""A point on the rim of a rolling body seen from the ground (--at top, bottom, front, back, or an
angle from the top, forward positive): the velocity and acceleration of the centre added to the
point's motion about it.

    v_P = v + ω × r,   a_P = a + α × r − ω² r

With x forward along the surface (the sense the scene's a is positive in), y away from it, the
point at φ from the top (forward positive: the front is +90°, the bottom 180°), r = R (sin φ,
cos φ), and ω, α in the rolling sense of x (clockwise when x points to the right):

    v_P = (v + Rω cos φ,  −Rω sin φ)
    a_P = (a + Rα cos φ − Rω² sin φ,  −Rα sin φ − Rω² cos φ)

Rolling without slipping (v = Rω, a = Rα, taken exactly) the bottom is at rest, the top moves at
2v, the front at √2 v pointing 45° down; each is taken with its direction from x towards y.
"""

from __future__ import annotations

import math

from taucli.core.errors import InputError
from taucli.writing.report import Step, Value, fmt, quantity_text, term
from taucli.scenes.angles import cos_exact, sin_exact
from taucli.options.table import Results

# cos φ and sin φ of each named point, φ from the top, forward positive (options.rolling.RIM_POSITIONS)
POSITIONS = {"top": (1.0, 0.0), "front": (0.0, 1.0), "bottom": (-1.0, 0.0), "back": (0.0, -1.0)}


def is_position(at: object) -> bool:
    """Whether --at names a point on the rim (a word, or an angle read as a Value), not a radius."""
    return isinstance(at, Value) or at in POSITIONS


def position(at: str | Value) -> tuple[float, float, str]:
    """cos φ, sin φ and the words for the point: a named one, or φ from the top (radians)."""
    if isinstance(at, Value):
        angle = at.value
        return cos_exact(angle), sin_exact(angle), f"{fmt(math.degrees(angle))}° from the top"
    cos_p, sin_p = POSITIONS[at]
    return cos_p, sin_p, f"the {at}"


def put_ground_point(
    results: Results, at: str | Value, radius: float | None, instant, when: str, forward: str, up: str, notes: list[str]
) -> list[Step]:
    """v_ground, v_ground_angle, a_ground and a_ground_angle of the rim point ``at``, with the steps.

    ``instant`` holds the centre's v and a, the spin ω and α (None where the run does not fix
    them) and whether it rolls (then the rim speed Rω is v and Rα is a, exactly)."""
    if radius is None:
        raise InputError("at", "needs {radius} for a point on the rim (it lies R from the centre)", example="{radius} 0.1m {at} top")
    cos_p, sin_p, name = position(at)
    v, a = instant.v, instant.a
    rim_speed = v if instant.rolls else (None if instant.omega is None else radius * instant.omega)  # R ω
    rim_accel = a if instant.rolls else (None if instant.alpha is None else radius * instant.alpha)  # R α
    # + 0.0: a component of −0 would turn a direction of ±180° into −180°
    velocity = None if v is None or rim_speed is None else (v + rim_speed * cos_p + 0.0, -rim_speed * sin_p + 0.0)
    inward = None if rim_speed is None else rim_speed * rim_speed / radius  # ω²R
    accel = None
    if velocity is not None and a is not None and rim_accel is not None:
        accel = (a + rim_accel * cos_p - inward * sin_p + 0.0, -rim_accel * sin_p - inward * cos_p + 0.0)
    angle = f" (0 = {forward}, +90° = {up})"
    for key, vector, what in (("v_ground", velocity, "velocity"), ("a_ground", accel, "acceleration")):
        size = None if vector is None else math.hypot(*vector)
        results.put(key, size, when)
        results.put(key + "_angle", None if not size else math.atan2(vector[1], vector[0]), angle)
        if vector is None:
            notes.append(f"{key}, {key}_angle: the {what} of the body is not known at this instant")
        elif not size:
            notes.append(f"{key}_angle: the point has no {what} relative to the ground{when}, so no direction")
    shown = at if not isinstance(at, Value) else f"{fmt(math.degrees(at.value))}deg"
    notes.append(f"{{at}} {shown}: the point on the rim at {name}, seen from the ground (angles from the top, forward positive; forward: {forward})")
    return _ground_steps(name, radius, v, a, rim_speed, rim_accel, inward, cos_p, sin_p, velocity, accel, when, instant.rolls)


def _ground_steps(name, radius, v, a, rim_speed, rim_accel, inward, cos_p, sin_p, velocity, accel, when, rolls) -> list[Step]:
    if velocity is None:
        return []
    why = "rolling without slipping, R ω = v: the contact point is at rest" if rolls else "it slides: R ω and v differ"
    steps = [
        Step(f"Velocity of the point at {name} relative to the ground{when}", "v_P = v + ω × r = (v + Rω cos φ, −Rω sin φ)",
             f"v = {term(v, 'm/s')}, Rω = {term(rim_speed, 'm/s')}, cos φ = {fmt(cos_p)}, sin φ = {fmt(sin_p)}",
             f"({quantity_text(velocity[0], 'm/s')}, {quantity_text(velocity[1], 'm/s')})",
             f"the centre's velocity plus the point's turning about it; x forward along the surface, y away from it; {why}"),
    ]
    if accel is not None:
        steps.append(Step(f"Acceleration of the point relative to the ground{when}",
                          "a_P = a + α × r − ω² r = (a + Rα cos φ − Rω² sin φ, −Rα sin φ − Rω² cos φ)",
                          f"a = {term(a, 'm/s**2')}, Rα = {term(rim_accel, 'm/s**2')}, Rω² = {term(inward, 'm/s**2')}",
                          f"({quantity_text(accel[0], 'm/s**2')}, {quantity_text(accel[1], 'm/s**2')})",
                          "the centre's acceleration, the tangential αR and the centripetal ω²R towards the centre"))
    return steps
