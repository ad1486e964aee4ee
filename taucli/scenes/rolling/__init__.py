"""A round body on an incline: rolling or slipping; a skidding ball on the flat until it rolls;
a body pulled on the flat or a slope, a spool pulled by its string, a yo-yo (solve_pull,
solve_yoyo, and solve_rolling_flat for a body rolling at v0).

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
from taucli.report import (
    DeferredSteps,
    Report,
    Step,
    Trajectory,
    Value,
    deferred,
    fmt,
    quantity_text,
    term,
)
from taucli.scenes.point import put_point, put_start, rim_radius
from taucli.scenes.assumed import Assumed
from taucli.scenes.friction import needs_kinetic, static_coefficient
from taucli.table import Results

K2 = {"sphere": 0.4, "shell": 2 / 3, "disc": 0.5, "cylinder": 0.5, "ring": 1.0, "hoop": 1.0}
RIGHT_ANGLE = math.pi / 2
EPSILON = 2.0**-52


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
    results.put("a", a, ", down the slope")
    results.put("alpha", angular)
    results.put("friction", None if mass is None or friction_per_mass is None else mass * friction_per_mass, ", up the slope")
    results.put("mu_min", mu_min)
    results.put("rolls", rolls)
    if a is not None and radius is None:
        notes.append("alpha: give --radius (a does not need it)")
    if a is not None and mass is None:
        notes.append("friction: give --mass (a does not need it)")

    run = length if length is not None else (None if height is None else height / sin_a)
    if run is not None:
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
            speed = math.sqrt(2 * a * run)
            duration = 2 * run / speed
            results.put("v", speed, " at the bottom, from rest")
            results.put("t", duration, " to the bottom")
            spin_speed = speed if rolls else (friction_per_mass / k2 * duration if friction_per_mass else 0.0)  # R ω at the bottom
            if mass is not None:
                results.put("KE_trans", 0.5 * mass * speed**2, " at the bottom")
                results.put("KE_rot", 0.5 * k2 * mass * spin_speed**2, " at the bottom")
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

    steps = DeferredSteps(_incline_steps, roller, angle, g, static, mu_k, mu_min, rolls, a, results, run)
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


def _incline_steps(roller, angle, g, mu_s, mu_k, mu_min, rolls, a, results, run=None) -> list[Step]:
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
    if "v" in results and results["v"].value is not None:
        steps.append(
            Step("Speed and time at the bottom (uniform acceleration from rest)", "v = √(2 a L),  t = 2L / v",
                 f"√(2 × {term(a, 'm/s**2')} × {term(run, 'm')}),  2 × {term(run, 'm')} / {term(results['v'].value, 'm/s')}",
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
             "" if slip == 0 else f"{term(abs(slip), 'm/s')} × {fmt(k2)} / ({fmt(mu_k)} × {term(g, 'm/s**2')} × (1 + {fmt(k2)}))", quantity_text(t_roll, "s"),
             "once s = 0 the contact is at rest and friction stops acting: it rolls"),
        Step("Speed once it rolls", "v_roll = (v₀ + k² R ω₀) / (1 + k²)", f"({term(v0, 'm/s')} + {fmt(k2)} × {term(spin_speed, 'm/s')}) / (1 + {fmt(k2)})",
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


@dataclass(frozen=True)
class Pull:
    """A steady pull F at ``angle`` above the surface (on a slope: from it, pulling up it).

    It acts at a point ``height`` above the centre (lever arm h cos φ about the centre), or, for
    a spool, through a string wound at ``axle`` that leaves the axle tangentially from below
    (``side`` −1) or from the top (+1): its lever arm is r at any angle.
    """

    force: float
    angle: float = 0.0
    height: float = 0.0
    axle: float | None = None
    side: int = -1

    def lever(self) -> float:
        """The lever arm about the centre, signed: positive where the pull turns the body forward
        (in the sense that rolls it along the pull)."""
        return self.side * self.axle if self.axle is not None else self.height * self.cos_sin()[0]

    def cos_sin(self) -> tuple[float, float]:
        """cos φ and sin φ, exact at ±90° (straight up or down), where math.cos(π/2) is 6e-17."""
        if abs(self.angle) == RIGHT_ANGLE:
            return 0.0, math.copysign(1.0, self.angle)
        return math.cos(self.angle), math.sin(self.angle)


def solve_pull(
    roller: Roller,
    slope: float,
    g: float,
    pull: Pull,
    *,
    mu_s: float | None = None,
    mu_k: float | None = None,
    length: float | None = None,
) -> Report:
    """A body pulled on the flat or a slope, from rest (or rolling), x along a's positive sense
    (along the pull on the flat, down the slope on a slope), σ = +1 (flat) or −1 (slope):

        m a = σ F cos φ + m g sin θ − f          (f: friction, positive against +x)
        I α = f R + σ F ℓ                         (α positive in the rolling sense of +x)
        N   = m g cos θ − F sin φ

    Rolling (a = R α): a = (σF cos φ + m g sin θ + σFℓ/R) / (m(1 + k²)) and
    f = (k²(σF cos φ + m g sin θ) − σFℓ/R)/(1 + k²), which needs |f| ≤ μs N. Otherwise the
    contact slides the way the needed friction opposes: f = sgn(f) μk N.
    """
    k2, mass, radius = roller.k2, roller.mass, roller.radius
    if mass is None:
        raise InputError("mass", "is required with {pull} (a force gives an acceleration only with a mass)", example="{mass} 2kg")
    if not 0 <= slope <= RIGHT_ANGLE:
        raise InputError("angle", "expected an angle from 0 to 90 deg", example="{angle} 30deg", got=f"{fmt(math.degrees(slope))} deg")
    if not -RIGHT_ANGLE <= pull.angle <= RIGHT_ANGLE:
        raise InputError("pull_angle", "expected an angle from −90 to 90 deg (above the surface positive)", example="{pull_angle} 30deg",
                         got=f"{fmt(math.degrees(pull.angle))} deg")
    _check_friction(mu_s, mu_k)
    lever = pull.lever()
    if lever != 0 and radius is None:
        raise InputError("radius", "is required with {pull_height} or {axle_radius} (the pull's torque acts through ℓ/R)", example="{radius} 0.1m")
    if radius is not None and (abs(pull.height) > radius or (pull.axle is not None and pull.axle > radius)):
        name = "axle_radius" if pull.axle is not None else "pull_height"
        raise InputError(name, "must lie within the body's radius", example=f"{{{name}}} 0.05m", got=f"{fmt(pull.axle or abs(pull.height))} m > R = {fmt(radius)} m")
    notes: list[str] = []
    flat = slope == 0
    sigma = 1.0 if flat else -1.0
    sin_a, cos_a = (1.0, 0.0) if slope == RIGHT_ANGLE else (math.sin(slope), math.cos(slope))
    cos_p, sin_p = pull.cos_sin()
    along = sigma * pull.force * cos_p  # the pull's component along +x
    normal = mass * g * cos_a - pull.force * sin_p
    scale = mass * g * cos_a + abs(pull.force * sin_p)
    if normal < -16 * EPSILON * scale:
        raise InputError("pull", "lifts the body off the surface: its part away from the surface, F sin φ, exceeds m g cos θ",
                         got=f"{quantity_text(pull.force * sin_p, 'N')} > {quantity_text(mass * g * cos_a, 'N')}")
    normal = max(normal, 0.0)
    turning = 0.0 if lever == 0 else sigma * pull.force * lever / radius  # σFℓ/R: the pull's torque over R
    drive = along + mass * g * sin_a
    needed = (k2 * drive - turning) / (1 + k2)  # the friction rolling needs
    rolling_a = (drive + turning) / (mass * (1 + k2))
    mu_min = (abs(needed) / normal if normal > 0 else (0.0 if needed == 0 else None))
    static = static_coefficient(mu_s, mu_k, notes)
    if normal == 0 and needed != 0:
        rolls = False
        notes.append("the pull just balances the body's weight across the surface: no normal force, no friction, so it cannot roll")
    elif static is None:
        rolls = True
        notes.append(f"no --mu-s: assumed to roll without slipping, which needs μs ≥ μ_min = {fmt(mu_min)}")
    else:
        rolls = abs(needed) <= static * normal
    a: float | None
    friction: float | None
    angular: float | None = None
    if rolls:
        a, friction = rolling_a, needed
        angular = None if radius is None else a / radius
    elif normal == 0 or mu_k is not None:
        friction = math.copysign((mu_k or 0.0) * normal, needed)
        a = (drive - friction) / mass
        torque_over_radius = friction + turning  # I α / R
        if radius is not None:
            if k2 > 0:
                angular = torque_over_radius / (k2 * mass * radius)
            elif torque_over_radius == 0:
                angular = 0.0
            else:
                notes.append("alpha: a torque on a body with no rotational inertia (k² = 0) has no finite answer")
    else:
        a = friction = None
    if radius is None and a is not None:
        notes.append("alpha: give --radius (a does not need it)")

    direction = ", along the pull" if flat else ", down the slope"
    results = Results(TABLE)
    results.put("a", a, direction)
    results.put("alpha", angular, ", in the rolling sense of a")
    results.put("friction", friction, ", backward (negative: forward)" if flat else ", up the slope (negative: down it)")
    results.put("mu_min", mu_min)
    results.put("rolls", rolls)
    if pull.axle is not None:
        results.put("critical_angle", _critical_angle(pull, sigma, mass * g * sin_a, radius, notes))
    if a is None:
        needs_kinetic("a, alpha, friction", notes)
    elif a == 0:
        notes.append("a = 0: the pull, gravity and friction balance, and it stays put"
                     + (f"; friction points {_friction_way(friction, flat)}" if friction else ""))
    else:
        notes.append(_which_way(a, flat, rolls, friction))
    if length is not None:
        _after_distance(results, length, a, angular, k2, mass, radius, rolls, notes)
    steps = DeferredSteps(_pull_steps, roller, slope, g, pull, sigma, normal, needed, rolling_a, mu_min, static, rolls, a, friction, dict(results))
    where = "on the flat" if flat else f"on a {fmt(math.degrees(slope))}° slope"
    what = f"as a spool, pulled by its string wound at r = {fmt(pull.axle)} m," if pull.axle is not None else "pulled"
    model = f"{roller.description} (k² = I/mR² = {fmt(k2)}) {what} {where}, " + (
        "rolling without slipping" if rolls else "slipping (kinetic friction)" if a is not None else "slipping (μk not given)"
    )
    trajectory = None if a is None else deferred(_pull_trajectory, a, length)
    return Report("rolling", model, "closed form", results, steps, notes, trajectory=trajectory)



def _critical_angle(pull: Pull, sigma: float, weight_along: float, radius: float, notes: list[str]) -> float | None:
    """The pull angle at which a rolling spool stays put: σF cos φ + m g sin θ + σF ℓ/R = 0 with
    ℓ = ±r, so cos φc = −ℓ/R − σ m g sin θ/F: from below, r/R on the flat and r/R + m g sin θ/F
    on a slope (σ = −1)."""
    cosine = -(pull.side * pull.axle / radius) - sigma * weight_along / pull.force
    if 0 <= cosine <= 1:
        return math.acos(cosine)
    sense = "forward, along the pull" if sigma > 0 else "up the slope"
    if cosine < 0:
        notes.append(f"critical_angle: none: at every pull angle it rolls {sense} (the string's torque and the pull agree)")
    else:
        notes.append("critical_angle: none: at no pull angle can the string hold it" + ("" if sigma > 0 else " against the slope"))
    return None


def _which_way(a: float, flat: bool, rolls: bool, friction: float | None) -> str:
    if flat:
        way = "forward, the way it is pulled" if a > 0 else "backward, against the pull"
    else:
        way = "down the slope" if a > 0 else "up the slope"
    verb = "rolls" if rolls else "slides"
    if friction is None or friction == 0:
        return f"it {verb} {way}" + ("" if friction is None else "; no friction acts")
    helps = (friction > 0) != (a > 0)  # friction along the acceleration
    return f"it {verb} {way}; friction points {_friction_way(friction, flat)}" + (", the way it accelerates: it helps" if helps else "")


def _friction_way(friction: float, flat: bool) -> str:
    if flat:
        return "backward (against the pull)" if friction > 0 else "forward (along the pull)"
    return "up the slope" if friction > 0 else "down the slope"


def _after_distance(results: Results, distance: float, a, angular, k2, mass, radius, rolls, notes) -> None:
    """From rest, the state once the centre has moved ``distance`` (whichever way a points)."""
    part = f" after {fmt(distance)} m"
    if a is None or a == 0:
        results.put("v", None, part)
        results.put("t", None, f" to move {fmt(distance)} m")
        if a == 0:
            notes.append(f"v, t: null: it stays put, so it never moves {fmt(distance)} m")
        return
    duration = math.sqrt(2 * distance / abs(a))
    speed = a * duration
    results.put("v", speed, part + ", from rest")
    results.put("t", duration, f" to move {fmt(distance)} m")
    spin = None if angular is None else angular * duration
    if radius is not None:
        results.put("omega", spin, part)
    trans = 0.5 * mass * speed * speed
    rot = None if spin is None or radius is None else 0.5 * k2 * mass * (radius * spin) ** 2
    results.put("KE_trans", trans, part)
    results.put("KE_rot", rot, part)
    results.put("KE", None if rot is None else trans + rot, part)


def _pull_trajectory(a: float, length: float | None) -> Trajectory:
    curves = (("x", "m", "distance of the centre along a"), ("v", "m/s", "velocity of the centre"))
    if length is None or a == 0:
        return Trajectory(curves, 1.0, lambda t: (a * t * t / 2, a * t), note="plotted for 1 s; --length to change")
    end = math.sqrt(2 * length / abs(a))
    return Trajectory(curves, end, lambda t: (a * t * t / 2, a * t), marks=((end, f"has moved {fmt(length)} m"),))


def _pull_steps(roller, slope, g, pull, sigma, normal, needed, rolling_a, mu_min, static, rolls, a, friction, results) -> list[Step]:
    k2, mass = roller.k2, roller.mass
    flat = slope == 0
    along = "F cos φ" if flat else "m g sin θ − F cos φ"
    if pull.axle is None:
        lever = "ℓ = h cos φ"
    else:
        lever = "ℓ = −r (the string leaves the axle from below)" if pull.side < 0 else "ℓ = +r (the string leaves the axle from the top)"
    torque = "+ F ℓ" if flat else "− F ℓ"
    steps = [
        Step("Translation of the centre" + (" (along the pull)" if flat else " (down the slope)"), f"m a = {along} − f", "", "",
             "the pull's component along the surface" + ("" if flat else " (up the slope) and gravity's (down it)")
             + "; friction f at the contact, positive against a"),
        Step("Rotation about the centre (in the rolling sense of a)", f"I α = f R {torque},  {lever}", "", "",
             f"friction acts at the contact, R from the centre; the pull's line of action passes ℓ from it: here ℓ = {quantity_text(pull.lever(), 'm')}, "
             f"and I = k² m R² with k² = {fmt(k2)}"),
        Step("Normal force", "N = m g cos θ − F sin φ", f"{term(mass, 'kg')} × {term(g, 'm/s**2')} × cos {fmt(math.degrees(slope))}° − {term(pull.force, 'N')} × sin {fmt(math.degrees(pull.angle))}°",
             quantity_text(normal, "N"), "a pull above the surface lifts part of the weight off it"),
        Step("Rolling (a = R α): solve the three equations", f"a = ({along} {torque}/R) / (m (1 + k²)),  f = k² m a {'−' if flat else '+'} Fℓ/R", "",
             f"{quantity_text(rolling_a, 'm/s**2')};  f = {quantity_text(needed, 'N')}",
             "f from the rotation equation with α = a/R, put into the translation equation; f < 0 means friction must point along a"),
    ]
    if mu_min is not None:
        steps.append(Step("The least μs that rolls it", "μ_min = |f| / N", f"{term(abs(needed), 'N')} / {term(normal, 'N')}", fmt(mu_min),
                          "static friction can give at most μs N" + ("" if static is None else f"; here μs = {fmt(static)} {'≥' if rolls else '<'} μ_min, so it {'rolls' if rolls else 'slips'}")))
    if not rolls:
        steps.append(Step("Slipping: kinetic friction, the way the needed friction points", "f = ±μₖ N,  a = (… − f)/m,  α = (f R ± F ℓ)/I", "",
                          "needs μₖ (--mu-k)" if a is None else f"{quantity_text(a, 'm/s**2')};  f = {quantity_text(friction, 'N')}",
                          "the contact slides the way friction would have had to stop it, so kinetic friction opposes that"))
    if "critical_angle" in results and results["critical_angle"].value is not None:
        steps.append(Step("The spool's critical angle (a = 0)", "cos φc = r/R" if flat else "cos φc = r/R + m g sin θ / F",
                          f"{term(pull.axle, 'm')} / {term(roller.radius, 'm')}" if flat else "", f"{fmt(math.degrees(results['critical_angle'].value))}°",
                          "the pull's line of action passes through the contact point: it has no torque about it, so nothing turns the spool"
                          if flat else "the pull's torque about the contact point balances gravity's"))
    if "v" in results and results["v"].value is not None:
        steps.append(Step("After the distance (uniform acceleration from rest)", "t = √(2d/|a|),  v = a t,  ω = α t", "",
                          f"{quantity_text(results['v'].value, 'm/s')}, {quantity_text(results['t'].value, 's')}", "a and α are constant"))
    return steps


def solve_yoyo(
    roller: Roller, g: float, *, axle: float | None = None, height: float | None = None, v0: float = 0.0, about_axle: float | None = None
) -> Report:
    """A yo-yo: the string, fixed above, unwinds from the axle of radius r (default R):

        m a = m g − T,   I α = T r,   a = r α   ⇒   a = g / (1 + I/(m r²)),  T = m g · q/(1 + q)

    with q = I/(m r²) = k² (R/r)²: with r = R neither mass nor radius enters a. ``about_axle``: the
    body's k2 is already I/(m r²) for a string wound at that r (I given, the outer radius unknown).
    """
    k2, mass, radius = roller.k2, roller.mass, roller.radius
    notes: list[str] = []
    if about_axle is not None:
        ratio, r = k2, about_axle
    elif axle is not None and radius is None:
        raise InputError("radius", "is required with {axle_radius} (I/(m r²) = k² R²/r²)", example="{radius} 0.03m")
    elif axle is not None and axle > radius:
        raise InputError("axle_radius", "must lie within the body's radius", example="{axle_radius} 0.005m", got=f"{fmt(axle)} m > R = {fmt(radius)} m")
    if about_axle is None:
        if axle is None:
            notes.append("no --axle-radius: the string is wound at the body's own radius (r = R)")
        ratio = k2 if axle is None else k2 * (radius / axle) ** 2  # q = I/(m r²)
        r = axle if axle is not None else radius
    a = g / (1 + ratio)
    tension = None if mass is None else mass * g * ratio / (1 + ratio)
    results = Results(TABLE)
    results.put("a", a, ", downward")
    results.put("alpha", None if r is None else a / r)
    results.put("T", tension)
    if mass is None:
        notes.append("T: give --mass (a does not need it)")
    if r is None:
        notes.append("alpha: give --radius (a does not need it)")
    if height is not None:
        part = f" after a drop of {fmt(height)} m"
        speed = math.sqrt(v0 * v0 + 2 * a * height)
        duration = 2 * height / (v0 + speed) if v0 >= 0 else (speed - v0) / a  # sums of positive terms
        results.put("v", speed, part + ("" if v0 else ", from rest"))
        results.put("omega", None if r is None else speed / r, part)
        results.put("t", duration, f" to drop {fmt(height)} m")
        if mass is not None:
            results.put("KE_trans", 0.5 * mass * speed * speed, part)
            results.put("KE_rot", 0.5 * ratio * mass * speed * speed, part)
            results.put("KE", 0.5 * (1 + ratio) * mass * speed * speed, part)
    steps = DeferredSteps(_yoyo_steps, ratio, a, tension, results if height is not None else None, g, mass, v0, height, r)
    model = f"yo-yo: {roller.description} (k² = I/mR² = {fmt(k2)}) falling as its string unwinds" + ("" if axle is None else f" from an axle of radius {fmt(axle)} m")
    if about_axle is not None:
        model = f"yo-yo: body (I/(m r²) = {fmt(ratio)}) falling as its string unwinds from an axle of radius {fmt(about_axle)} m"
    trajectory = deferred(_yoyo_trajectory, a, v0, results)
    return Report("rolling", model, "closed form", results, steps, notes, trajectory=trajectory)


def _yoyo_steps(ratio, a, tension, results, g=None, mass=None, v0=0.0, height=None, r=None) -> list[Step]:
    steps = [
        Step("For the yo-yo's centre (down positive)", "m a = m g − T", "", "", "gravity down, the string's tension up"),
        Step("Rotation about the centre", "I α = T r", "", "", "the string leaves the axle at r from the centre"),
        Step("The string unwinds without slipping", "a = r α", "", "", "the point where the string leaves is momentarily at rest"),
        Step("Solve", "a = g / (1 + I/(m r²)),  T = m g (I/(m r²)) / (1 + I/(m r²))",
             f"I/(m r²) = {fmt(ratio)}:  a = {term(g, 'm/s**2')} / (1 + {fmt(ratio)})"
             + ("" if mass is None else f",  T = {term(mass, 'kg')} × {term(g, 'm/s**2')} × {fmt(ratio)} / (1 + {fmt(ratio)})"),
             quantity_text(a, "m/s**2") + ("" if tension is None else f", T = {quantity_text(tension, 'N')}"),
             "T r = I a / r from the rotation; put into the translation equation"),
    ]
    if results is not None:
        speed = results["v"].value
        numbers = f"√(({term(v0, 'm/s')})² + 2 × {term(a, 'm/s**2')} × {term(height, 'm')})" + ("" if r is None else f",  {term(speed, 'm/s')} / {term(r, 'm')}")
        shown = quantity_text(speed, "m/s") + ("" if r is None else f", ω = {quantity_text(results['omega'].value, 'rad/s')}")
        steps.append(Step("After the drop", "v = √(v₀² + 2 a h),  ω = v / r", numbers, shown,
                          "constant a; energy: m g h = ½ m v² (1 + I/(m r²)) − ½ m v₀² (1 + I/(m r²))"))
    return steps


def _yoyo_trajectory(a: float, v0: float, results) -> Trajectory:
    curves = (("x", "m", "drop, downward"), ("v", "m/s", "velocity, downward"))
    end = results["t"].value if "t" in results else None
    if end is None:
        return Trajectory(curves, 1.0, lambda t: (v0 * t + a * t * t / 2, v0 + a * t), note="plotted for 1 s; --height to change")
    return Trajectory(curves, end, lambda t: (v0 * t + a * t * t / 2, v0 + a * t), marks=((end, "end of the drop"),))


def solve_rolling_flat(roller: Roller, v0: float) -> Report:
    """A body rolling without slipping on the flat at v0: KE = ½ m v² (1 + k²), nothing changes."""
    k2, mass, radius = roller.k2, roller.mass, roller.radius
    if mass is None:
        raise InputError("mass", "is required: on the flat, {v0} alone is a body rolling at v0, and its kinetic energy needs the mass "
                         "(a ball skidding from no spin: give {mu_k})", example="{mass} 2kg")
    results = Results(TABLE)
    results.put("omega", None if radius is None else v0 / radius, ", rolling")
    trans = 0.5 * mass * v0 * v0
    results.put("KE_trans", trans, ", rolling")
    results.put("KE_rot", k2 * trans, ", rolling")
    results.put("KE", (1 + k2) * trans, ", rolling")
    notes = ["on the flat, {v0} alone: rolling without slipping (ω = v/R); with {mu_k} it skids from no spin ({omega0} for a spin)"]
    if radius is None:
        notes.append("omega: give --radius (the energies do not need it)")
    steps = [
        Step("Rolling without slipping", "ω = v / R", "", "" if radius is None else quantity_text(v0 / radius, "rad/s"), "the contact point is at rest"),
        Step("Kinetic energy", "KE = ½ m v² + ½ I ω² = ½ m v² (1 + k²)", f"½ × {term(mass, 'kg')} × ({term(v0, 'm/s')})² × (1 + {fmt(k2)})", quantity_text((1 + k2) * trans, "J"),
             f"I ω² = k² m R² (v/R)² = k² m v²: a share k²/(1 + k²) = {fmt(100 * k2 / (1 + k2), 3)}% is rotation"),
    ]
    model = f"{roller.description} (k² = {fmt(k2)}) rolling without slipping on the flat"
    return Report("rolling", model, "closed form", results, steps, notes)


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
    pull: float | None = None,
    pull_height: float | None = None,
    pull_angle: float | None = None,
    axle_radius: float | None = None,
    yoyo: bool | None = None,
    g: float | None = None,
    at: float | None = None,
) -> Report:
    """``taucli rolling``: down (or up) an incline, or a ball skidding on the flat (--v0 or
    --omega0 with no slope, length or height) until it rolls; a body pulled (--pull), a spool
    (--axle-radius), a yo-yo (--yoyo); --at r, a point of the body at r from its centre."""
    if at is not None:
        report = rolling(shape=shape, k2=k2, inertia=inertia, mass=mass, radius=radius, angle=angle, mu_s=mu_s, mu_k=mu_k, length=length,
                         height=height, v0=v0, omega0=omega0, pull=pull, pull_height=pull_height, pull_angle=pull_angle,
                         axle_radius=axle_radius, yoyo=yoyo, g=g)
        r, note = rim_radius(at, radius, "{radius}")
        report = _point_on_body(report, r, v0 or 0.0, omega0, radius if not yoyo else axle_radius)
        report.notes += [note] if note else []
        return report
    if yoyo and inertia is not None and radius is None and axle_radius is not None and mass is not None and shape is None and k2 is None:
        # a yo-yo needs only I/(m r²): its outer radius plays no part (Halliday's 950 g·cm², 120 g, r = 3.2 mm)
        assumed = Assumed()
        body = Roller(inertia / (mass * axle_radius**2), "body", mass, None)
        for name, value in (("angle", angle), ("pull", pull), ("pull_height", pull_height), ("pull_angle", pull_angle), ("mu_s", mu_s),
                            ("mu_k", mu_k), ("length", length), ("omega0", omega0)):
            if value is not None:
                raise InputError(name, "does not apply with {yoyo} (a yo-yo falls on its string: {height} for the drop, {v0} to throw it down)")
        report = solve_yoyo(body, assumed.gravity(g), height=height, v0=v0 or 0.0, about_axle=axle_radius)
        return assumed.applied(report)
    body = roller(shape, k2, inertia, mass, radius)
    assumed = Assumed()
    if not yoyo and pull is None and angle in (None, 0.0) and v0 is not None and omega0 is None and mu_k is None and length is None and height is None:
        return solve_rolling_flat(body, v0)  # rolling on the flat: gravity plays no part
    gravity = assumed.gravity(g)
    if yoyo:
        for name, value in (("angle", angle), ("pull", pull), ("pull_height", pull_height), ("pull_angle", pull_angle), ("mu_s", mu_s),
                            ("mu_k", mu_k), ("length", length), ("omega0", omega0)):
            if value is not None:
                raise InputError(name, "does not apply with {yoyo} (a yo-yo falls on its string: {height} for the drop, {v0} to throw it down)")
        return assumed.applied(solve_yoyo(body, gravity, axle=axle_radius, height=height, v0=v0 or 0.0))
    if pull is None:
        for name, value in (("pull_height", pull_height), ("pull_angle", pull_angle), ("axle_radius", axle_radius)):
            if value is not None:
                raise InputError(name, "needs {pull} (the force on the body" + (", or {yoyo}" if name == "axle_radius" else "") + ")", example="{pull} 10N")
    else:
        for name, value in (("v0", v0), ("omega0", omega0), ("height", height)):
            if value is not None:
                raise InputError(name, "does not apply with {pull}: the pulled body starts from rest ({length} for the distance it moves)")
        if axle_radius is not None and pull_height is not None and pull_height == 0:
            raise InputError("pull_height", "cannot be 0 with {axle_radius}: the string leaves the axle from below (negative) or the top (positive)")
        side = 1 if pull_height is not None and pull_height > 0 else -1
        if axle_radius is not None and pull_height is not None and abs(pull_height) != axle_radius:
            assumed.notes.append("with {axle_radius}, {pull_height} says only which side the string leaves the axle from "
                                 f"({'the top' if side > 0 else 'below'}): a string tangent to the axle has the lever arm r at any angle")
        pulled = Pull(pull, pull_angle or 0.0, pull_height or 0.0, axle_radius, side)
        report = solve_pull(body, angle or 0.0, gravity, pulled, mu_s=mu_s, mu_k=mu_k, length=length)
        return assumed.applied(report)
    flat = angle is None or angle == 0
    if flat and (v0 is not None or omega0 is not None) and (length is not None or height is not None):
        # #16 item 12: this once became a 0° incline from rest, silently setting --v0 aside
        raise InputError(
            "length" if length is not None else "height",
            "applies down a slope; on the flat a ball given {v0} or {omega0} skids (with {mu_k}) or rolls along, and no distance ends it",
            example="{angle} 10deg {length} 1m, or leave it out",
        )
    on_the_flat = flat and (v0 is not None or omega0 is not None)
    if on_the_flat:
        report = solve_flat(body, gravity, mu_k=mu_k, v0=v0 or 0.0, omega0=omega0 or 0.0, mu_s=mu_s)
    else:
        if angle is None:
            raise InputError("angle", "is required on an incline", example="{angle} 30deg")
        if omega0 is not None:
            raise InputError("omega0", "applies on the flat ({angle} 0 with {v0}): a skidding ball")
        report = solve_incline(body, angle, gravity, mu_s=mu_s, mu_k=mu_k, length=length, height=height, v0=v0 or 0.0)
    return assumed.applied(report)


def _point_on_body(report: Report, r: float, v0: float, omega0: float | None, radius: float | None) -> Report:
    """A point of the body at r from its centre, turning with the body's ω and α about the
    centre (its motion relative to the centre; the centre's own velocity adds to it), at the
    start and at the end of the run the scene reports (the bottom, a drop, a pulled distance:
    ω = ω₀ + αt, θ = ω₀t + ½αt², α constant; a skid: α = (ω_roll − ω₀)/t_roll while it slides,
    θ = ½(ω₀ + ω_roll)t_roll, then α = 0 once it rolls on the flat). ω₀ is --omega0 (a skid
    without it starts with no spin), or v₀/R for a body set rolling (a yo-yo thrown down: R its
    axle)."""
    values = {key: value.value for key, value in report.results.items()}
    results = Results(TABLE)
    results.update(report.results)
    notes, steps = list(report.notes), list(report.steps)
    skid = values.get("omega_roll") is not None and values.get("t_roll") is not None
    if omega0 is None:  # a skid starts without spin; a body set rolling (or a yo-yo thrown down) at v₀/R
        omega0 = 0.0 if skid or not v0 else (None if radius is None else v0 / radius)
    if omega0 is None:
        raise InputError("at", "needs {radius}: the body's ω₀ = v₀/R", example="{radius} 0.1m {at} 0.05m")
    if skid and values["t_roll"] > 0:  # a skid, until it rolls
        omega, duration = values["omega_roll"], values["t_roll"]
        alpha0, alpha, theta, when = (omega - omega0) / duration, 0.0, (omega0 + omega) * duration / 2, " once it rolls"
    else:
        alpha0 = alpha = values.get("alpha")
        duration = values.get("t")
        omega = theta = None
        if alpha is not None and duration is not None:
            omega, theta = omega0 + alpha * duration, omega0 * duration + alpha * duration * duration / 2
        label = report.results["v"].label if "v" in report.results else ""
        when = " " + label.removeprefix("speed").split(",")[0].strip() if label else ""
    if omega is None:
        steps += put_point(results, r, omega0, alpha0, 0.0, " at the start", notes)
    else:
        steps += put_point(results, r, omega, alpha, theta, when, notes)
        put_start(results, r, omega0, alpha0)
    notes.append("the point's motion about the centre of the body (v_t = ωr relative to the centre; the centre's own velocity adds to it)")
    return Report(report.scene, report.model, report.method, results, steps, notes, report.inputs, report.tables, report.trajectory)
