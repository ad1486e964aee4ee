"""A round body on an incline: rolling or slipping, down to the bottom or up to where it stops.

The article's three equations, with I = k² m R² (k2 = I/(mR²), the shape's only number):

    translation:  m a = m g sin θ − f
    rotation:     I α = f R
    no slip:      a = R α

give a = g sin θ / (1 + k2) and f = m g sin θ · k2/(1 + k2): neither mass nor radius enters a.
Rolling needs f ≤ μs N, N = m g cos θ, that is μs ≥ μ_min = tan θ · k2/(1 + k2). Below that the
body slips: f = μk N, a = g (sin θ − μk cos θ), α = μk g cos θ / (k2 R). Both are continuous at
μs = μk = μ_min.
"""

from __future__ import annotations

import math

from taucli.core.errors import InputError
from taucli.options.rolling import COMMAND as TABLE
from taucli.writing.report import DeferredSteps, Report, Step, Trajectory, Value, deferred, fmt, quantity_text, term
from taucli.scenes.friction import needs_kinetic, static_coefficient
from taucli.scenes.rolling.body import RIGHT_ANGLE, Roller, check_friction
from taucli.options.table import Results


def solve_incline(
    roller: Roller,
    angle: float,
    g: float,
    *,
    mu_s: float | None = None,
    mu_k: float | None = None,
    length: float | None = None,
    height: float | None = None,
    v0: float = 0.0,
) -> Report:
    """Roll or slip on a slope of ``angle`` (0 to 90°); with --length or --height, the state at
    the bottom; with v0 > 0 (set rolling up the slope, ω₀ = v₀/R), how far it climbs, and with a
    length too, the bottom after it rolls back: v = √(v₀² + 2aL), L = −v₀t + ½at² (v0 < 0: set
    rolling down it). The climb and the way back share a: rolling, and sliding too, for a body
    set rolling slides with its contact moving down the slope, so friction points up it both ways.

    Friction coefficients follow friction.py's rule: only μk given, μs = μk; slipping with no μk,
    what needs it is null. On a vertical face (90°) there is no normal force and so no friction:
    it falls freely, a = g, and its spin does not change; no μs can make it roll.
    """
    if not 0 <= angle <= RIGHT_ANGLE:
        raise InputError("angle", "expected an angle from 0 to 90 deg", example="{angle} 30deg", got=f"{fmt(math.degrees(angle))} deg")
    check_friction(mu_s, mu_k)
    if length is not None and height is not None:
        raise InputError("length", "conflicts with {height}: give the distance along the slope or the height, not both")
    if height is not None and angle == 0:
        raise InputError("height", "needs a slope: on the flat there is no height to roll down", example="{angle} 30deg {height} 1m")
    k2, mass, radius = roller.k2, roller.mass, roller.radius
    notes: list[str] = []
    vertical = angle == RIGHT_ANGLE
    sin_a, cos_a = (1.0, 0.0) if vertical else (math.sin(angle), math.cos(angle))
    mu_min = None if vertical else math.tan(angle) * k2 / (1 + k2)
    static = None
    if vertical:
        rolls = False
        notes.append(
            "a vertical face: no normal force, so no friction: it falls freely (a = g) and its spin does not change; "
            "mu_min: none, no μs makes it roll (μ_min = tan θ · k²/(1 + k²) grows without bound as θ -> 90°)"
        )
    else:
        static = static_coefficient(mu_s, mu_k, notes)
        rolls = True if static is None else static >= mu_min
        if static is None:
            notes.append(f"no --mu-s: assumed to roll without slipping, which needs μs ≥ μ_min = {fmt(mu_min)}")

    a: float | None
    friction_per_mass: float | None
    if rolls:
        a = g * sin_a / (1 + k2)
        friction_per_mass = g * sin_a * k2 / (1 + k2)
    elif vertical:
        a, friction_per_mass = g, 0.0
    elif mu_k is None:
        a = friction_per_mass = None
    else:
        a = g * (sin_a - mu_k * cos_a)
        friction_per_mass = mu_k * g * cos_a
    alpha = None
    if radius is not None and a is not None:
        if rolls:
            alpha = a / radius
        elif k2 > 0:
            alpha = friction_per_mass / (k2 * radius)
        else:  # no friction torque (the vertical face) on no rotational inertia: 0/0
            notes.append("alpha: no torque acts on a body with no rotational inertia (k² = 0), so its spin is not fixed")

    results = Results(TABLE)
    results.put("a", a, ", down the slope")
    results.put("alpha", alpha)
    results.put("friction", None if mass is None or friction_per_mass is None else mass * friction_per_mass, ", up the slope")
    results.put("mu_min", mu_min)
    results.put("rolls", rolls)
    if a is not None and radius is None:
        notes.append("alpha: give --radius (a does not need it)")
    if a is not None and mass is None:
        notes.append("friction: give --mass (a does not need it)")

    slope_length = length if length is not None else (None if height is None else height / sin_a)
    if slope_length is not None:
        if a is None:
            results.put("v", None, " at the bottom")
            results.put("t", None, " to the bottom")
        elif a <= 0:
            if angle == 0:
                notes.append("on the flat nothing pulls it along: from rest it stays where it is")
            else:
                notes.append("kinetic friction exceeds gravity's pull along the slope: it does not slide down")
            results.put("v", None, " at the bottom")
            results.put("t", None, " to the bottom")
        else:
            # set off at v₀ up the slope (or −v₀ down it), it climbs, comes back past its start under
            # the same a (rolling; or sliding, friction up the slope throughout), and reaches the bottom:
            # L = −v₀t + ½at², v = √(v₀² + 2aL); t as a sum of positive terms either way
            speed = math.sqrt(v0 * v0 + 2 * a * slope_length)
            duration = (speed + v0) / a if v0 > 0 else 2 * slope_length / (speed - v0)
            after = ", from rest" if not v0 else ", after its climb" if v0 > 0 else ", set rolling down it at v₀"
            results.put("v", speed, " at the bottom" + after)
            results.put("t", duration, " to the bottom")
            if v0:
                notes.append(f"{{v0}} with {{length}} or {{height}}: set rolling at {fmt(abs(v0))} m/s {'up' if v0 > 0 else 'down'} the slope "
                             f"{fmt(slope_length)} m from the bottom{', it climbs, stops, and rolls back past its start' if v0 > 0 else ''}: "
                             "v and t are at the bottom")
            spin_up = friction_per_mass / k2 * duration if friction_per_mass else 0.0  # R α t while it slides
            rim_speed = speed if rolls else spin_up - v0  # R ω at the bottom, set rolling at R ω₀ = v₀ up the slope
            if radius is not None:
                results.put("omega", rim_speed / radius, " at the bottom")  # ω = Rω/R, in the rolling sense (#48 item 1)
            if mass is not None:
                results.put("KE_trans", 0.5 * mass * speed**2, " at the bottom")
                results.put("KE_rot", 0.5 * k2 * mass * rim_speed**2, " at the bottom")
    if v0 > 0:
        deceleration = a
        if deceleration is None:
            for name in ("d_climb", "h_climb", "t_climb"):
                results.put(name, None)
        elif deceleration <= 0:
            notes.append("going up, friction never lets gravity stop it: it does not come back")
        else:
            climb = v0 * v0 / (2 * deceleration)
            results.put("d_climb", climb)
            results.put("h_climb", climb * sin_a)
            results.put("t_climb", v0 / deceleration)
    elif v0 < 0 and slope_length is None:
        notes.append("{v0} negative: set rolling down the slope, it does not climb; {length} or {height} for the bottom")
    if a is None:
        needs_kinetic(", ".join(name for name in ("a", "alpha", "friction", "v", "t", "d_climb", "h_climb", "t_climb") if name in results), notes)

    steps = DeferredSteps(_incline_steps, roller, angle, g, static, mu_k, mu_min, rolls, a, results, slope_length, v0)
    model = f"{roller.description} (k² = I/mR² = {fmt(k2)}) on a {fmt(math.degrees(angle))}° slope, "
    if vertical:
        model = f"{roller.description} (k² = I/mR² = {fmt(k2)}) falling along a vertical face (no normal force, no friction)"
    else:
        model += "rolling without slipping" if rolls else "slipping (kinetic friction)" if mu_k is not None else "slipping (μk not given)"
    trajectory = None if a is None else deferred(_incline_trajectory, a, v0, results)
    return Report("rolling", model, "closed form", results, steps, notes, trajectory=trajectory)


def _incline_trajectory(a: float, v0: float, results: dict[str, Value]) -> Trajectory:
    """Distance and speed along the slope: down it from rest to the bottom, or up it to the highest point."""
    curves = (("x", "m", "distance along the slope"), ("v", "m/s", "speed along the slope"))
    bottom = results["t"].value if "t" in results else None
    if v0 and (bottom is not None or v0 < 0):  # set off up (or down) the slope, to the bottom: x and v down the slope
        curves = (("x", "m", "distance down the slope from the start"), ("v", "m/s", "velocity down the slope"))
        if bottom is None:
            return Trajectory(curves, 1.0, lambda t: (-v0 * t + a * t * t / 2, -v0 + a * t), note="plotted for 1 s; --length or --height to change")
        marks = (((results["t_climb"].value, "highest point"),) if v0 > 0 and "t_climb" in results else ()) + ((bottom, "reaches the bottom"),)
        return Trajectory(curves, bottom, lambda t: (-v0 * t + a * t * t / 2, -v0 + a * t), marks=marks)
    if v0 > 0 and "t_climb" in results:
        top = results["t_climb"].value
        return Trajectory(curves, top, lambda t: (v0 * t - a * t * t / 2, v0 - a * t), marks=((top, "highest point"),))
    if v0 > 0:  # up the slope, with nothing to stop it
        return Trajectory(curves, 1.0, lambda t: (v0 * t - a * t * t / 2, v0 - a * t), note="plotted for 1 s: it does not come back")
    if a <= 0:
        return Trajectory(curves, 1.0, lambda t: (0.0, 0.0), note="plotted for 1 s: it stays at rest")
    if bottom is None:
        return Trajectory(curves, 1.0, lambda t: (a * t * t / 2, a * t), note="plotted for 1 s; --length or --height to change")
    return Trajectory(curves, bottom, lambda t: (a * t * t / 2, a * t), marks=((bottom, "reaches the bottom"),))


def _incline_steps(roller, angle, g, mu_s, mu_k, mu_min, rolls, a, results, slope_length=None, v0=0.0) -> list[Step]:
    k2 = roller.k2
    degrees = fmt(math.degrees(angle))
    steps = [
        Step("Translation of the centre (along the slope)", "m a = m g sin θ − f", "", "", "gravity's component pulls it down the slope; friction f at the contact acts up the slope"),
        Step("Rotation about the centre", "I α = f R,  I = k² m R²", f"k² = {fmt(k2)} for a {roller.description}", "", "only friction has a lever arm about the centre"),
    ]
    if mu_min is None:  # the vertical face
        steps.append(
            Step("No normal force on a vertical face, so no friction", "N = m g cos 90° = 0  ⇒  f = 0,  a = g,  α = 0", "",
                 quantity_text(a, "m/s**2"), "friction can be at most μN, and N = 0: nothing at the contact acts on it")
        )
    if rolls:
        steps.append(Step("No slip", "a = R α", "", "", "the contact point is instantaneously at rest"))
        steps.append(
            Step(
                "Solve the three equations",
                "a = g sin θ / (1 + k²)",
                f"{term(g, 'm/s**2')} × sin {degrees}° / (1 + {fmt(k2)})",
                quantity_text(a, "m/s**2"),
                "f = k² m a from the rotation and no-slip equations; put into the translation equation, m cancels and so does R",
            )
        )
    if mu_min is not None:
        steps.append(
            Step(
                "Friction needed to roll, and the least μs that supplies it",
                "f = m g sin θ · k²/(1 + k²),  μ_min = tan θ · k²/(1 + k²)",
                f"tan {degrees}° × {fmt(k2)} / (1 + {fmt(k2)})",
                fmt(mu_min),
                "static friction can give at most μs N = μs m g cos θ"
                + ("" if mu_s is None else f"; here μs = {fmt(mu_s)} {'≥' if rolls else '<'} μ_min, so it {'rolls' if rolls else 'slips'}"),
            )
        )
    if not rolls and mu_min is not None:
        steps.append(
            Step(
                "Slipping: kinetic friction instead of the no-slip condition",
                "f = μₖ m g cos θ,  a = g (sin θ − μₖ cos θ),  α = μₖ g cos θ / (k² R)",
                "" if mu_k is None else f"{term(g, 'm/s**2')} × (sin {degrees}° − {fmt(mu_k)} × cos {degrees}°)",
                "needs μₖ (--mu-k)" if a is None else quantity_text(a, "m/s**2"),
                "the contact slides, so friction takes its kinetic value and a no longer equals Rα",
            )
        )
    if "v" in results and results["v"].value is not None and not v0:
        steps.append(
            Step("Speed and time at the bottom (uniform acceleration from rest)", "v = √(2 a L),  t = 2L / v",
                 f"√(2 × {term(a, 'm/s**2')} × {term(slope_length, 'm')}),  2 × {term(slope_length, 'm')} / {term(results['v'].value, 'm/s')}",
                 f"{quantity_text(results['v'].value, 'm/s')}, {quantity_text(results['t'].value, 's')}", "constant a along the slope")
        )
    elif "v" in results and results["v"].value is not None:
        equation = "v = √(v₀² + 2 a L),  t = (v + v₀) / a" if v0 > 0 else "v = √(v₀² + 2 a L),  t = 2L / (v + |v₀|)"
        steps.append(
            Step("Speed and time at the bottom (uniform acceleration from v₀ up the slope)", equation,
                 f"√(({term(abs(v0), 'm/s')})² + 2 × {term(a, 'm/s**2')} × {term(slope_length, 'm')})",
                 f"{quantity_text(results['v'].value, 'm/s')}, {quantity_text(results['t'].value, 's')}",
                 "the same a down the slope going up and coming back (friction up the slope throughout): L = −v₀t + ½at², v₀ up the slope positive")
        )
    if "v" in results and results["v"].value is not None and rolls:
        steps.append(
            Step("Energy check", "m g h = ½ m v² + ½ I ω² = ½ m v² (1 + k²)" if not v0 else "m g h = ½ m (v² − v₀²) (1 + k²)", "", "",
                 f"a share k²/(1 + k²) = {fmt(100 * k2 / (1 + k2), 3)}% of the kinetic energy is rotation; no energy is lost to static friction")
        )
    if "d_climb" in results and results["d_climb"].value is not None:
        steps.append(Step("How far it climbs", "d = v₀² / (2a)", "", quantity_text(results["d_climb"].value, "m"), "going up, the same a slows it"))
    return steps

