"""A body pulled on the flat or up a slope by a steady force at a height above its centre, or a
spool pulled by a string wound on its axle: whether it rolls or slips, which way it goes, and
the spool's critical angle, at which it stays put.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from taucli.core.errors import InputError
from taucli.options.rolling import COMMAND as TABLE
from taucli.writing.report import DeferredSteps, Report, Step, Trajectory, deferred, fmt, quantity_text, term
from taucli.scenes.friction import needs_kinetic, static_coefficient
from taucli.scenes.rolling.body import RIGHT_ANGLE, Roller, check_friction
from taucli.options.table import Results

EPSILON = 2.0**-52


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


def given_pull(force: float, angle: float | None, height: float | None, axle: float | None, notes: list[str]) -> Pull:
    """The pull as given: along the surface and through the centre unless ``angle`` and
    ``height`` say otherwise. On a spool (``axle``) the string leaves the axle from below unless
    ``height`` is positive, and that side is all ``height`` says there (0 is refused)."""
    if axle is not None and height is not None and height == 0:
        raise InputError("pull_height", "cannot be 0 with {axle_radius}: the string leaves the axle from below (negative) or the top (positive)")
    side = 1 if height is not None and height > 0 else -1
    if axle is not None and height is not None and abs(height) != axle:
        notes.append("with {axle_radius}, {pull_height} says only which side the string leaves the axle from "
                     f"({'the top' if side > 0 else 'below'}): a string tangent to the axle has the lever arm r at any angle")
    return Pull(force, angle or 0.0, height or 0.0, axle, side)


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
    check_friction(mu_s, mu_k)
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
    pull_along = sigma * pull.force * cos_p  # the pull's component along +x
    normal = mass * g * cos_a - pull.force * sin_p
    scale = mass * g * cos_a + abs(pull.force * sin_p)
    if normal < -16 * EPSILON * scale:
        raise InputError("pull", "lifts the body off the surface: its part away from the surface, F sin φ, exceeds m g cos θ",
                         got=f"{quantity_text(pull.force * sin_p, 'N')} > {quantity_text(mass * g * cos_a, 'N')}")
    normal = max(normal, 0.0)
    turning = 0.0 if lever == 0 else sigma * pull.force * lever / radius  # σFℓ/R: the pull's torque over R
    drive = pull_along + mass * g * sin_a
    friction_needed = (k2 * drive - turning) / (1 + k2)  # the friction rolling needs
    rolling_a = (drive + turning) / (mass * (1 + k2))
    mu_min = (abs(friction_needed) / normal if normal > 0 else (0.0 if friction_needed == 0 else None))
    static = static_coefficient(mu_s, mu_k, notes)
    if normal == 0 and friction_needed != 0:
        rolls = False
        notes.append("the pull just balances the body's weight across the surface: no normal force, no friction, so it cannot roll")
    elif static is None:
        rolls = True
        notes.append(f"no --mu-s: assumed to roll without slipping, which needs μs ≥ μ_min = {fmt(mu_min)}")
    else:
        rolls = abs(friction_needed) <= static * normal
    a: float | None
    friction: float | None
    alpha: float | None = None
    if rolls:
        a, friction = rolling_a, friction_needed
        alpha = None if radius is None else a / radius
    elif normal == 0 or mu_k is not None:
        friction = math.copysign((mu_k or 0.0) * normal, friction_needed)
        a = (drive - friction) / mass
        torque_over_radius = friction + turning  # I α / R
        if radius is not None:
            if k2 > 0:
                alpha = torque_over_radius / (k2 * mass * radius)
            elif torque_over_radius == 0:
                alpha = 0.0
            else:
                notes.append("alpha: a torque on a body with no rotational inertia (k² = 0) has no finite answer")
    else:
        a = friction = None
    if radius is None and a is not None:
        notes.append("alpha: give --radius (a does not need it)")

    direction = ", along the pull" if flat else ", down the slope"
    results = Results(TABLE)
    results.put("a", a, direction)
    results.put("alpha", alpha, ", in the rolling sense of a")
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
        _after_distance(results, length, a, alpha, k2, mass, radius, notes)
    steps = DeferredSteps(_pull_steps, roller, slope, g, pull, sigma, normal, friction_needed, rolling_a, mu_min, static, rolls, a, friction, dict(results))
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


def _after_distance(results: Results, distance: float, a, alpha, k2, mass, radius, notes) -> None:
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
    omega = None if alpha is None else alpha * duration
    if radius is not None:
        results.put("omega", omega, part)
    ke_trans = 0.5 * mass * speed * speed
    ke_rot = None if omega is None or radius is None else 0.5 * k2 * mass * (radius * omega) ** 2
    results.put("KE_trans", ke_trans, part)
    results.put("KE_rot", ke_rot, part)
    results.put("KE", None if ke_rot is None else ke_trans + ke_rot, part)


def _pull_trajectory(a: float, length: float | None) -> Trajectory:
    curves = (("x", "m", "distance of the centre along a"), ("v", "m/s", "velocity of the centre"))
    if length is None or a == 0:
        return Trajectory(curves, 1.0, lambda t: (a * t * t / 2, a * t), note="plotted for 1 s; --length to change")
    end = math.sqrt(2 * length / abs(a))
    return Trajectory(curves, end, lambda t: (a * t * t / 2, a * t), marks=((end, f"has moved {fmt(length)} m"),))


def _pull_steps(roller, slope, g, pull, sigma, normal, friction_needed, rolling_a, mu_min, static, rolls, a, friction, results) -> list[Step]:
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
             f"{quantity_text(rolling_a, 'm/s**2')};  f = {quantity_text(friction_needed, 'N')}",
             "f from the rotation equation with α = a/R, put into the translation equation; f < 0 means friction must point along a"),
    ]
    if mu_min is not None:
        steps.append(Step("The least μs that rolls it", "μ_min = |f| / N", f"{term(abs(friction_needed), 'N')} / {term(normal, 'N')}", fmt(mu_min),
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

