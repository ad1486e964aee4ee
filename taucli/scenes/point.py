"""A point at radius r on a body turning about a fixed axis (#24): how fast it moves, how it
accelerates (along its path and toward the axis) and how far it has travelled.

    v = ωr,   a_t = αr,   a_c = ω²r,   a = √(a_t² + a_c²),   φ = atan2(a_t, a_c),   s = rθ,
    chord = 2r·|sin(Δθ/2)|

a_t is taken along the motion (negative while the body slows); φ is the angle of the total
acceleration from the radius pointing to the axis, positive toward the motion. The chord is the
straight line from where the point started to where it is: the start, the end and the axis make
an isosceles triangle of apex Δθ, the net angle (whole turns bring the point back; a body that
turned back has undone part of its arc). Every scene with
ω and α (spin-down, atwood's pulley, rolling, impulse) puts these results the same way.
"""

from __future__ import annotations

import math

from taucli.core.errors import InputError
from taucli.writing.report import Step, quantity_text, term
from taucli.options.table import Results

KEYS = ("v_t", "a_t", "a_c", "a_total", "a_angle", "s", "chord")
RIM = "rim"


def rim_radius(at: float | str, radius: float | None, what: str) -> tuple[float, str | None]:
    """The point's radius: ``at``, or for "rim" the body's one radius (``what`` names where it
    comes from), with the note that says so; refused where the body has no one radius."""
    if at != RIM:
        return at, None
    if radius is None:
        raise InputError("at", f"expected a radius for the point, or {what} for its rim", example="{at} 0.2m")
    return radius, f"{{at}} rim: the point is on the rim, r = {quantity_text(radius, 'm')}"


def along(alpha: float, omega: float) -> float:
    """α taken along the motion: positive while the body speeds up, negative while it slows; from
    rest, along the motion α starts (a body set turning either way speeds up)."""
    return alpha if omega > 0 else -alpha if omega < 0 else abs(alpha)


def point_set(r: float, omega: float, alpha: float | None) -> tuple[float, float | None, float, float | None, float | None]:
    """v_t, a_t (along the motion: negative while slowing), a_c, a_total and a_angle of a point at r."""
    v = abs(omega) * r
    a_c = omega * omega * r
    if alpha is None:
        return v, None, a_c, None, None
    a_t = along(alpha, omega) * r
    total = math.hypot(a_t, a_c)
    angle = math.atan2(a_t, a_c) if total else None
    return v, a_t, a_c, total, angle


def put_point(results: Results, r: float, omega: float | None, alpha: float | None, theta: float | None, when: str, notes: list[str],
              string: tuple[float, float, float | None, float | None] | None = None) -> list[Step]:
    """The point's results at one instant (``when``: " at t = 2 s"), and the steps that give them.
    ``omega`` None: the instant never comes, so each result is null with a note. ``string`` =
    (R, v, a, x): ω, α and θ are a string's v/R, a/R and x/R, which a point at r = R moves with, so
    its v_t, a_t and s there are the string's own v, a and x (2 m of string given, s = 2 m, not
    (2/R)·R: #42 item 22); a None where α is not the string's a/R."""
    if omega is None:
        for key in KEYS:
            results.put(key, None, when)
        notes.append(f"{', '.join(KEYS)}: there is no such instant")
        return []
    v, a_t, a_c, total, angle = point_set(r, omega, alpha)
    if string is not None and r == string[0]:
        _, speed, accel, travelled = string
        v, arc = abs(speed), travelled
        if accel is not None and alpha is not None:
            a_t = along(accel, speed)
            total = math.hypot(a_t, a_c)
            angle = math.atan2(a_t, a_c) if total else None
    else:
        arc = None if theta is None else r * theta
    results.put("v_t", v, when)
    results.put("a_t", a_t, when)
    results.put("a_c", a_c, when)
    results.put("a_total", total, when)
    results.put("a_angle", angle, when)
    since = " by then" if when != " at the start" else " at the start"
    results.put("s", arc, since)
    results.put("chord", None if theta is None else chord(r, theta), since)
    if alpha is None:
        notes.append("a_t, a_total, a_angle: α is not defined at this instant")
    elif angle is None:
        notes.append("a_angle: the point has no acceleration at this instant, so no direction")
    return point_steps(r, omega, alpha, theta, v, a_t, a_c, total, angle, when, arc)


def chord(r: float, theta: float) -> float:
    """The straight line from the point's start to its place after the net angle θ: 2r·|sin(θ/2)|
    (θ/2 is exact in binary, and sin keeps its digits for θ of many turns)."""
    return 2 * r * abs(math.sin(theta / 2))


def put_start(results: Results, r: float, omega0: float, alpha0: float | None, string: tuple[float, float] | None = None) -> None:
    """v_t0, a_c0, a_total0 and a_angle0: the point at the start, where the first set is later;
    ``string`` = (R, v₀): ω₀ is a string's v₀/R, and a point at r = R moves at v₀ itself (see put_point)."""
    v0, _, a_c0, total0, angle0 = point_set(r, omega0, alpha0)
    if string is not None and r == string[0]:
        v0 = abs(string[1])
    results.put("v_t0", v0)
    results.put("a_c0", a_c0)
    results.put("a_total0", total0)
    results.put("a_angle0", angle0)


def point_steps(r, omega, alpha, theta, v, a_t, a_c, total, angle, when, arc=None) -> list[Step]:
    """v = ωr, a_c = ω²r, a_t = αr, a = √(a_t² + a_c²) with φ, s = rθ: each with its numbers."""
    radius = term(r, "m")
    steps = [
        Step(f"Speed of the point{when}", "v = ωr", f"{term(abs(omega), 'rad/s')} × {radius}", quantity_text(v, "m/s"),
             "every point of a rigid body turns through the same angle, so a point at radius r covers r per radian"),
        Step(f"Centripetal acceleration{when}", "a_c = ω²r", f"({term(abs(omega), 'rad/s')})² × {radius}", quantity_text(a_c, "m/s**2"),
             "the velocity turns at rate ω, so the point accelerates toward the axis by ωv = ω²r"),
    ]
    if alpha is not None:
        steps.append(Step(f"Tangential acceleration{when}", "a_t = αr", f"{term(along(alpha, omega), 'rad/s**2')} × {radius}",
                          quantity_text(a_t, "m/s**2"), "the speed ωr changes at αr; taken along the motion, negative while the body slows"))
        steps.append(Step(f"Total acceleration{when}", "a = √(a_t² + a_c²), φ = atan2(a_t, a_c)",
                          f"√(({term(a_t, 'm/s**2').strip('()')})² + ({term(a_c, 'm/s**2')})²)",
                          quantity_text(total, "m/s**2") + ("" if angle is None else f", φ = {quantity_text(angle, 'rad')}"),
                          "the two components are at right angles; φ is measured from the radius pointing to the axis, positive toward the motion"))
    if theta:
        steps.append(Step("Arc the point has travelled", "s = rθ", f"{radius} × {term(theta, 'rad')}", quantity_text(r * theta if arc is None else arc, "m"),
                          "an arc is its radius times the angle it spans (the string a drum winds, the tread a tyre moves)"))
        steps.append(Step("Straight-line distance from the start (chord)", "chord = 2r·|sin(Δθ/2)|",
                          f"2 × {radius} × |sin({term(theta, 'rad')} / 2)|", quantity_text(chord(r, theta), "m"),
                          "the start, the end and the axis make an isosceles triangle of apex Δθ, the net angle: "
                          "whole turns bring the point back to where it started"))
    return steps
