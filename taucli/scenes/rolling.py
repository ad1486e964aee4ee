"""A round body on an incline: rolling or slipping; and a skidding ball on the flat until it rolls.

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
from dataclasses import dataclass

from taucli.errors import InputError, did_you_mean
from taucli.options.rolling import COMMAND as TABLE
from taucli.report import DeferredSteps, Report, Step, Trajectory, Value, deferred, fmt, quantity_text
from taucli.scenes.assumed import Assumed
from taucli.scenes.friction import needs_kinetic, static_coefficient
from taucli.table import Results

K2 = {"sphere": 0.4, "shell": 2 / 3, "disc": 0.5, "cylinder": 0.5, "ring": 1.0, "hoop": 1.0}
RIGHT_ANGLE = math.pi / 2


@dataclass(frozen=True)
class Roller:
    """The rolling body: k2 = I/(mR²), and mass and radius where something asks for them."""

    k2: float
    description: str
    mass: float | None = None
    radius: float | None = None


def roller(shape: str | None, k2: float | None, inertia: float | None, mass: float | None, radius: float | None) -> Roller:
    """The body from exactly one of SHAPE, k2 = I/(mR²), or I with the mass and radius."""
    given = [name for name, value in (("shape", shape), ("k2", k2), ("inertia", inertia)) if value is not None]
    if len(given) != 1:
        raise InputError(
            "shape" if not given else given[1],
            "is required: {shape}, {k2} or {inertia} (one of them)" if not given else f"conflicts with {{{given[0]}}}: describe the body once",
            example="taucli rolling sphere {angle} 30deg",
        )
    if shape is not None:
        if shape not in K2:
            raise InputError("shape", f"expected one of {', '.join(K2)}", example="sphere", got=repr(shape), hint=did_you_mean(shape, K2))
        return Roller(K2[shape], shape, mass, radius)
    if k2 is not None:
        return Roller(k2, "body", mass, radius)
    if mass is None or radius is None:
        raise InputError("mass" if mass is None else "{radius}", "is required with {inertia} (k² = I/(mR²))", example="{mass} 2kg {radius} 0.1m")
    return Roller(inertia / (mass * radius**2), "body", mass, radius)


def _check_friction(mu_s: float | None, mu_k: float | None) -> None:
    if mu_s is not None and mu_k is not None and mu_k > mu_s:
        raise InputError("mu_k", "must not exceed {mu_s} (kinetic friction is at most static friction)", got=f"{fmt(mu_k)} > {fmt(mu_s)}")


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
    the bottom; with v0 > 0 (up the slope), how far it climbs.

    Friction coefficients follow friction.py's rule: only μk given, μs = μk; slipping with no μk,
    what needs it is null. On a vertical face (90°) there is no normal force and so no friction:
    it falls freely, a = g, and its spin does not change; no μs can make it roll.
    """
    if not 0 <= angle <= RIGHT_ANGLE:
        raise InputError("angle", "expected an angle from 0 to 90 deg", example="{angle} 30deg", got=f"{fmt(math.degrees(angle))} deg")
    _check_friction(mu_s, mu_k)
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
    angular = None
    if radius is not None and a is not None:
        if rolls:
            angular = a / radius
        elif k2 > 0:
            angular = friction_per_mass / (k2 * radius)
        else:  # no friction torque (the vertical face) on no rotational inertia: 0/0
            notes.append("alpha: no torque acts on a body with no rotational inertia (k² = 0), so its spin is not fixed")

    results = Results(TABLE)
    results.put("a", a)
    results.put("alpha", angular)
    results.put("friction", None if mass is None or friction_per_mass is None else mass * friction_per_mass)
    results.put("mu_min", mu_min)
    results.put("rolls", rolls)
    if a is not None and radius is None:
        notes.append("alpha: give --radius (a does not need it)")
    if a is not None and mass is None:
        notes.append("friction: give --mass (a does not need it)")

    run = length if length is not None else (None if height is None else height / sin_a)
    if run is not None:
        if a is None:
            results.put("v", None)
            results.put("t", None)
        elif a <= 0:
            if angle == 0:
                notes.append("on the flat nothing pulls it along: from rest it stays where it is")
            else:
                notes.append("kinetic friction exceeds gravity's pull along the slope: it does not slide down")
            results.put("v", None)
            results.put("t", None)
        else:
            speed = math.sqrt(2 * a * run)
            duration = 2 * run / speed
            results.put("v", speed, ", from rest")
            results.put("t", duration)
            spin_speed = speed if rolls else (friction_per_mass / k2 * duration if friction_per_mass else 0.0)  # R ω at the bottom
            if mass is not None:
                results.put("KE_trans", 0.5 * mass * speed**2)
                results.put("KE_rot", 0.5 * k2 * mass * spin_speed**2)
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
    if a is None:
        needs_kinetic(", ".join(name for name in ("a", "alpha", "friction", "v", "t", "d_climb", "h_climb", "t_climb") if name in results), notes)

    steps = DeferredSteps(_incline_steps, roller, angle, g, static, mu_k, mu_min, rolls, a, results)
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
    if v0 > 0 and "t_climb" in results:
        top = results["t_climb"].value
        return Trajectory(curves, top, lambda t: (v0 * t - a * t * t / 2, v0 - a * t), marks=((top, "highest point"),))
    if v0 > 0:  # up the slope, with nothing to stop it
        return Trajectory(curves, 1.0, lambda t: (v0 * t - a * t * t / 2, v0 - a * t), note="plotted for 1 s: it does not come back")
    if a <= 0:
        return Trajectory(curves, 1.0, lambda t: (0.0, 0.0), note="plotted for 1 s: it stays at rest")
    bottom = results["t"].value if "t" in results else None
    if bottom is None:
        return Trajectory(curves, 1.0, lambda t: (a * t * t / 2, a * t), note="plotted for 1 s; --length or --height to change")
    return Trajectory(curves, bottom, lambda t: (a * t * t / 2, a * t), marks=((bottom, "reaches the bottom"),))


def _incline_steps(roller, angle, g, mu_s, mu_k, mu_min, rolls, a, results) -> list[Step]:
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
                f"{fmt(g)} × sin {degrees}° / (1 + {fmt(k2)})",
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
                "" if mu_k is None else f"{fmt(g)} × (sin {degrees}° − {fmt(mu_k)} × cos {degrees}°)",
                "needs μₖ (--mu-k)" if a is None else quantity_text(a, "m/s**2"),
                "the contact slides, so friction takes its kinetic value and a no longer equals Rα",
            )
        )
    if "v" in results and results["v"].value is not None:
        steps.append(
            Step("Speed and time at the bottom (uniform acceleration from rest)", "v = √(2 a L),  t = 2L / v", "",
                 f"{quantity_text(results['v'].value, 'm/s')}, {quantity_text(results['t'].value, 's')}", "constant a along the slope")
        )
        if rolls:
            steps.append(
                Step("Energy check", "m g h = ½ m v² + ½ I ω² = ½ m v² (1 + k²)", "", "",
                     f"a share k²/(1 + k²) = {fmt(100 * k2 / (1 + k2), 3)}% of the kinetic energy is rotation; no energy is lost to static friction")
            )
    if "d_climb" in results and results["d_climb"].value is not None:
        steps.append(Step("How far it climbs", "d = v₀² / (2a)", "", quantity_text(results["d_climb"].value, "m"), "going up, the same a slows it"))
    return steps


def solve_flat(roller: Roller, g: float, *, mu_k: float | None, v0: float, omega0: float = 0.0, mu_s: float | None = None) -> Report:
    """A ball skidding on the flat: friction μk m g acts against the slip v − Rω until it vanishes.

    slip s(t) = s₀ − μk g (1 + 1/k2) t, so t_roll = |s₀| k2 / (μk g (1 + k2));
    v_roll = (v₀ + k2 R ω₀)/(1 + k2) (angular momentum about the contact point is conserved).
    """
    _check_friction(mu_s, mu_k)  # μs plays no part in skidding, but a μk above it is still a mistake
    k2, mass, radius = roller.k2, roller.mass, roller.radius
    if omega0 and radius is None:
        raise InputError("radius", "is required with {omega0} (the slip is v − Rω)", example="{radius} 0.11m")
    spin_speed = 0.0 if not omega0 else radius * omega0
    slip = v0 - spin_speed
    notes: list[str] = []
    if slip != 0 and mu_k is None:
        raise InputError("mu_k", "is required: the ball skids (v ≠ Rω) and kinetic friction brings it to rolling", example="{mu_k} 0.2")
    if slip != 0 and mu_k == 0:
        return _skids_forever(roller, v0, spin_speed)
    v_roll = (v0 + k2 * spin_speed) / (1 + k2)
    if slip == 0:
        t_roll = 0.0
        d_roll = 0.0
        notes.append("it already rolls (v = Rω): nothing changes on the flat")
    else:
        t_roll = abs(slip) * k2 / (mu_k * g * (1 + k2))
        d_roll = (v0 + v_roll) / 2 * t_roll  # uniform deceleration: the mean speed times the time
    # KE before − KE after = ½m(v₀² + k²u²) − ½m(1 + k²)v_roll², u = Rω₀, v_roll = (v₀ + k²u)/(1 + k²),
    # = ½m[(1 + k²)(v₀² + k²u²) − (v₀ + k²u)²]/(1 + k²) = ½m k²(v₀ − u)²/(1 + k²): the difference
    # cancels as the ball nearly rolls (it came out negative); this form is ≥ 0 and keeps its digits.
    energy_lost = None if mass is None else 0.5 * mass * k2 / (1 + k2) * slip * slip
    results = _skid_results(t_roll, d_roll, v_roll, None if radius is None else v_roll / radius, energy_lost)
    steps = [
        Step("While it skids, kinetic friction acts against the slip", "m dv/dt = −μₖ m g·sgn s,  I dω/dt = +μₖ m g R·sgn s,  s = v − Rω", "", "",
             "friction slows the centre and spins the ball up (or the reverse, for backspin)"),
        Step("The slip closes at a constant rate", "ds/dt = −μₖ g (1 + 1/k²)·sgn s  ⇒  t_roll = |s₀| k² / (μₖ g (1 + k²))",
             "" if slip == 0 else f"{fmt(abs(slip))} × {fmt(k2)} / ({fmt(mu_k)} × {fmt(g)} × (1 + {fmt(k2)}))", quantity_text(t_roll, "s"),
             "once s = 0 the contact is at rest and friction stops acting: it rolls"),
        Step("Speed once it rolls", "v_roll = (v₀ + k² R ω₀) / (1 + k²)", f"({fmt(v0)} + {fmt(k2)} × {fmt(spin_speed)}) / (1 + {fmt(k2)})",
             quantity_text(v_roll, "m/s"), "friction acts at the contact, so angular momentum about the contact point is conserved"),
    ]
    model = f"{roller.description} (k² = {fmt(k2)}) skidding on the flat until it rolls"
    return Report("rolling", model, "closed form", results, steps, notes, trajectory=deferred(_skid_trajectory, v0, v_roll, t_roll))


def _skid_results(t_roll, d_roll, v_roll, omega_roll, energy_lost: float | None) -> Results:
    """The skidding ball's results (energy_lost only when the mass is known)."""
    results = Results(TABLE)
    for name, value in (("t_roll", t_roll), ("d_roll", d_roll), ("v_roll", v_roll), ("omega_roll", omega_roll)):
        results.put(name, value)
    if energy_lost is not None:
        results.put("energy_lost", energy_lost)
    return results


def _skids_forever(roller: Roller, v0: float, spin_speed: float) -> Report:
    """μk = 0 with v ≠ Rω: no force at the contact, so v and ω never change and it never rolls."""
    results = _skid_results(None, None, None, None, None if roller.mass is None else 0.0)
    notes = [f"μk = 0: no friction at the contact, so it skids for ever at v = {quantity_text(v0, 'm/s')} with the slip it started with, and never rolls"]
    steps = [
        Step("With no friction nothing acts at the contact", "m dv/dt = 0,  I dω/dt = 0", "", "",
             f"the slip s = v − Rω = {fmt(v0 - spin_speed)} m/s stays as it is"),
    ]
    model = f"{roller.description} (k² = {fmt(roller.k2)}) skidding on a frictionless flat"
    return Report("rolling", model, "closed form", results, steps, notes, trajectory=deferred(_skid_trajectory, v0, v0, math.inf))


def _skid_trajectory(v0: float, v_roll: float, t_roll: float) -> Trajectory:
    """Distance and speed of the centre: uniform change while it skids, then steady rolling."""
    change = 0.0 if t_roll == 0 else (v_roll - v0) / t_roll  # ±μk g while it skids

    def state(t: float) -> tuple[float, float]:
        if t <= t_roll:
            return v0 * t + change * t * t / 2, v0 + change * t
        return (v0 + v_roll) / 2 * t_roll + v_roll * (t - t_roll), v_roll

    curves = (("x", "m", "distance travelled"), ("v", "m/s", "speed of the centre"))
    if math.isinf(t_roll):
        return Trajectory(curves, 1.0, lambda t: (v0 * t, v0), note="plotted for 1 s: it never rolls")
    if t_roll == 0:
        return Trajectory(curves, 1.0, state, note="plotted for 1 s: it rolls from the start")
    return Trajectory(curves, 1.5 * t_roll, state, marks=((t_roll, "rolls without slipping"),))


def rolling(
    *,
    shape: str | None = None,
    k2: float | None = None,
    inertia: float | None = None,
    mass: float | None = None,
    radius: float | None = None,
    angle: float | None = None,
    mu_s: float | None = None,
    mu_k: float | None = None,
    length: float | None = None,
    height: float | None = None,
    v0: float | None = None,
    omega0: float | None = None,
    g: float | None = None,
) -> Report:
    """``taucli rolling``: down (or up) an incline, or a ball skidding on the flat (--v0 or
    --omega0 with no slope, length or height) until it rolls."""
    body = roller(shape, k2, inertia, mass, radius)
    assumed = Assumed()
    gravity = assumed.gravity(g)
    on_the_flat = (angle is None or angle == 0) and (v0 is not None or omega0 is not None) and length is None and height is None
    if on_the_flat:
        report = solve_flat(body, gravity, mu_k=mu_k, v0=v0 or 0.0, omega0=omega0 or 0.0, mu_s=mu_s)
    else:
        if angle is None:
            raise InputError("angle", "is required on an incline", example="{angle} 30deg")
        if omega0 is not None:
            raise InputError("omega0", "applies on the flat ({angle} 0 with {v0}): a skidding ball")
        report = solve_incline(body, angle, gravity, mu_s=mu_s, mu_k=mu_k, length=length, height=height, v0=v0 or 0.0)
    return assumed.applied(report)
