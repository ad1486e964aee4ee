"""A rolling body joined to a hanging mass: a string leaves the body at its centre (an axle in a
frame) or its top (wound on it), runs along the surface to a pulley at the edge of the flat or at
the top of the slope, and down to the hanging mass m.

x along the surface towards the pulley (up the slope), c = 0 (centre) or 1 (top) the string's
lever arm about the centre over R, u = 1 + c how fast the string runs for the centre's speed
while the body rolls; the pulley a uniform disc, I_p = ½ m_p r_p², W = m + I_p/r_p²:

    body:          M a = T − M g sin θ − f,    I α = f R + c T R        (I = k² M R²)
    hanging mass:  m a_h = m g − T₂,           a_h = a + c R α         (the string moves with the point it leaves)
    pulley:        I_p α_p = (T₂ − T) r_p,     a_h = r_p α_p

f is the friction at the contact, positive away from the pulley; α is in the rolling sense of x.
Rolling (a = R α):

    a = g (u m − M sin θ) / (M (1 + k²) + u² W),   T = m g − W u a,   f = k² M a − c T

which needs |f| ≤ μs N, N = M g cos θ (the string runs along the surface). Otherwise the contact
slides the way that friction would have held it, f = ±μk N, and with b = R α:

    centre:  a = (m g − M g sin θ − f) / (M + W),   b = f / (k² M)
    top:     b = (m g + f + W (g sin θ + 2f/M)) / (W (1 + k²) + k² M),   T = k² M b − f,
             a = (T − M g sin θ − f) / M
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
ENDS = {"centre": 0, "center": 0, "top": 1}  # the string's lever arm about the centre, over R


@dataclass(frozen=True)
class Hanging:
    """The hanging mass, where the string leaves the body (c: 0 the centre, 1 the top), and the
    pulley (a uniform disc: its mass, and its radius where its α is asked for)."""

    mass: float
    lever: int = 0
    pulley_mass: float = 0.0
    pulley_radius: float | None = None

    @property
    def end(self) -> str:
        return "top" if self.lever else "centre"


def given_hanging(mass: float, string: str | None, pulley_mass: float | None, pulley_radius: float | None) -> Hanging:
    """The hanging mass as given; the string from the centre unless --string says the top."""
    end = (string or "centre").strip().lower()
    if end not in ENDS:
        raise InputError("string", "expected centre or top (where the string leaves the body)", example="{string} top", got=repr(string))
    return Hanging(mass, ENDS[end], pulley_mass or 0.0, pulley_radius)


def solve_hanging(
    roller: Roller, slope: float, g: float, hanging: Hanging, *, mu_s: float | None = None, mu_k: float | None = None, length: float | None = None
) -> Report:
    """The body and the hanging mass from rest: roll or slip, a, α, the tensions, friction and
    μ_min (the equations above); after ``length`` (the distance the body moves), v, ω and t."""
    k2, mass, radius = roller.k2, roller.mass, roller.radius
    if mass is None:
        raise InputError("mass", "is required with {hanging_mass} (the body's mass against the hanging one)", example="{mass} 2kg")
    if not 0 <= slope <= RIGHT_ANGLE:
        raise InputError("angle", "expected an angle from 0 to 90 deg (the pulley at the top of the slope)", example="{angle} 30deg",
                         got=f"{fmt(math.degrees(slope))} deg")
    check_friction(mu_s, mu_k)
    notes: list[str] = []
    m, c = hanging.mass, hanging.lever
    u = 1 + c
    moving = m + hanging.pulley_mass / 2  # W = m + I_p/r_p²: the hanging mass and the pulley, carried by the string
    vertical = slope == RIGHT_ANGLE
    sin_a, cos_a = (1.0, 0.0) if vertical else (math.sin(slope), math.cos(slope))
    normal = mass * g * cos_a

    rolling_a = g * (u * m - mass * sin_a) / (mass * (1 + k2) + u * u * moving)
    rolling_tension = m * (g - u * rolling_a) - hanging.pulley_mass / 2 * u * rolling_a
    friction_needed = k2 * mass * rolling_a - c * rolling_tension
    mu_min = None if vertical else abs(friction_needed) / normal
    static = static_coefficient(mu_s, mu_k, notes)
    if vertical:
        rolls = friction_needed == 0
        notes.append("a vertical face: no normal force, so no friction; mu_min: none, no μs makes it roll (it rolls only if it needs no friction)")
    elif static is None:
        rolls = True
        notes.append(f"no --mu-s: assumed to roll without slipping, which needs μs ≥ μ_min = {fmt(mu_min)}")
    else:
        rolls = abs(friction_needed) <= static * normal

    a = b = tension = friction = None  # b = R α
    spin_note = None
    if rolls:
        a, b, friction = rolling_a, rolling_a, friction_needed
    elif vertical or mu_k is not None:
        friction = 0.0 if vertical else math.copysign(mu_k * normal, friction_needed)
        if c == 0:
            a = (m * g - mass * g * sin_a - friction) / (mass + moving)
            if k2 > 0:
                b = friction / (k2 * mass)
            elif friction == 0:
                b = 0.0
            else:
                spin_note = "alpha: friction's torque on a body with no rotational inertia (k² = 0) has no finite answer"
        else:
            b = (m * g + friction + moving * (g * sin_a + 2 * friction / mass)) / (moving * (1 + k2) + k2 * mass)
            a = (k2 * mass * b - 2 * friction - mass * g * sin_a) / mass
    a_hanging = None if a is None else (u * a if rolls else a + c * b)
    if a_hanging is not None:
        tension2 = m * (g - a_hanging)
        tension = tension2 - hanging.pulley_mass / 2 * a_hanging
        scale = m * g + abs(hanging.pulley_mass * a_hanging)
        if min(tension, tension2) < -16 * EPSILON * scale:
            raise InputError("hanging_mass", "leaves the string slack: the body would run towards the pulley faster than the string lets the mass fall "
                             "(a slack string is not modelled)", got=f"T = {quantity_text(min(tension, tension2), 'N')}")
    alpha = None if b is None or radius is None else b / radius
    if spin_note:
        notes.append(spin_note)
    if radius is None and a is not None:
        notes.append("alpha: give --radius (a does not need it)")

    results = Results(TABLE)
    results.put("a", a, ", towards the pulley")
    results.put("alpha", alpha, ", in the rolling sense of a")
    results.put("T", tension, ", from the body to the pulley")
    results.put("T2", None if a_hanging is None else tension2)
    results.put("a_hanging", a_hanging)
    if hanging.pulley_radius is not None:
        results.put("alpha_pulley", None if a_hanging is None else a_hanging / hanging.pulley_radius)
    results.put("friction", friction, ", away from the pulley (negative: towards it)")
    results.put("mu_min", mu_min)
    results.put("rolls", rolls)
    if a is None:
        needs_kinetic("a, alpha, T, T2, a_hanging, friction", notes)
    else:
        notes.append(_which_way(a, slope, rolls, friction))
    if length is not None:
        _after_distance(results, length, a, alpha, a_hanging, k2, mass, radius, notes)
    steps = DeferredSteps(_hanging_steps, roller, slope, g, hanging, normal, rolling_a, friction_needed, mu_min, static, rolls, dict(results))
    where = "on the flat" if slope == 0 else f"on a {fmt(math.degrees(slope))}° slope"
    pulley = f"a pulley of {fmt(hanging.pulley_mass)} kg (a uniform disc)" if hanging.pulley_mass else "a massless pulley"
    model = (f"{roller.description} (k² = I/mR² = {fmt(k2)}) {where}, its string from the {hanging.end} over {pulley} to a hanging mass "
             f"of {fmt(m)} kg, " + ("rolling without slipping" if rolls else "slipping (kinetic friction)" if a is not None else "slipping (μk not given)"))
    trajectory = None if a is None else deferred(_trajectory, a, a_hanging, length)
    return Report("rolling", model, "closed form", results, steps, notes, trajectory=trajectory)


def _which_way(a: float, slope: float, rolls: bool, friction: float | None) -> str:
    verb = "rolls" if rolls else "slides"
    if a == 0:
        return "a = 0: the hanging mass and gravity along the slope balance, and it stays put"
    way = ("towards the pulley" + ("" if slope == 0 else ", up the slope")) if a > 0 else "away from the pulley, down the slope"
    if not friction:
        return f"it {verb} {way}" + ("" if friction is None else "; no friction acts")
    helps = (friction > 0) != (a > 0)  # friction along the acceleration
    return f"it {verb} {way}; friction points " + ("away from the pulley" if friction > 0 else "towards the pulley") + (
        ", the way it accelerates: it helps" if helps else "")


def _after_distance(results: Results, distance: float, a, alpha, a_hanging, k2, mass, radius, notes) -> None:
    """From rest, the state once the body has moved ``distance`` (whichever way a points)."""
    part = f" after {fmt(distance)} m"
    if not a:
        for key in ("v", "v_hanging", "t"):
            results.put(key, None, part if key != "t" else f" to move {fmt(distance)} m")
        if a == 0:
            notes.append(f"v, v_hanging, t: null: the body stays put, so it never moves {fmt(distance)} m")
        return
    duration = math.sqrt(2 * distance / abs(a))
    speed = a * duration
    results.put("v", speed, part + ", from rest")
    results.put("v_hanging", a_hanging * duration, part)
    results.put("t", duration, f" to move {fmt(distance)} m")
    omega = None if alpha is None else alpha * duration
    if radius is not None:
        results.put("omega", omega, part)
    ke_trans = 0.5 * mass * speed * speed
    ke_rot = None if omega is None else 0.5 * k2 * mass * (radius * omega) ** 2
    results.put("KE_trans", ke_trans, part + " (the body)")
    results.put("KE_rot", ke_rot, part + " (the body)")
    results.put("KE", None if ke_rot is None else ke_trans + ke_rot, part + " (the body)")


def _trajectory(a: float, a_hanging: float, length: float | None) -> Trajectory:
    curves = (("x", "m", "distance of the centre towards the pulley"), ("v", "m/s", "velocity of the centre"))
    if length is None or a == 0:
        return Trajectory(curves, 1.0, lambda t: (a * t * t / 2, a * t), note="plotted for 1 s; --length to change")
    end = math.sqrt(2 * length / abs(a))
    return Trajectory(curves, end, lambda t: (a * t * t / 2, a * t), marks=((end, f"has moved {fmt(length)} m"),))


def _hanging_steps(roller, slope, g, hanging, normal, rolling_a, friction_needed, mu_min, static, rolls, results) -> list[Step]:
    k2, mass, m, c = roller.k2, roller.mass, hanging.mass, hanging.lever
    u, degrees = 1 + c, fmt(math.degrees(slope))
    pulley = hanging.pulley_mass / 2
    value = {key: found.value for key, found in results.items()}
    steps = [
        Step("The body along the surface (towards the pulley)", "M a = T − M g sin θ − f", "", "",
             "the string pulls it towards the pulley" + ("" if slope == 0 else ", gravity down the slope")
             + "; friction f at the contact, positive away from the pulley"),
        Step("The body's rotation about its centre (in the rolling sense of a)", "I α = f R + T R,  I = k² M R²" if c else "I α = f R,  I = k² M R²",
             f"k² = {fmt(k2)}", "", "friction acts R from the centre; " + ("the string leaves the top, R from it" if c else "the string pulls at the centre: no torque")),
        Step("The hanging mass (down positive)", "m a_h = m g − T₂", "", "", "its weight down, the string up"),
        Step("The pulley, a uniform disc" if hanging.pulley_mass else "A massless pulley",
             "I_p α_p = (T₂ − T) r_p,  I_p = ½ m_p r_p²,  a_h = r_p α_p  ⇒  T₂ − T = ½ m_p a_h" if hanging.pulley_mass else "T₂ = T",
             "", "", "the string does not slip on the pulley: its rim moves with the string" if hanging.pulley_mass else "nothing to turn: the tension is the same on both sides"),
        Step("The string", "a_h = a + R α" if c else "a_h = a", "", "",
             "it leaves the body at the top, whose speed is v + Rω (2v while it rolls)" if c else "it is tied to the centre, which it moves with"),
        Step("Rolling (a = R α): solve", "a = g (u m − M sin θ) / (M (1 + k²) + u² (m + ½ m_p)),  u = " + ("2" if c else "1"),
             f"{term(g, 'm/s**2')} × ({u} × {term(m, 'kg')} − {term(mass, 'kg')} × sin {degrees}°) / "
             f"({term(mass, 'kg')} × (1 + {fmt(k2)}) + {u * u} × ({term(m, 'kg')} + {term(pulley, 'kg')}))",
             quantity_text(rolling_a, "m/s**2"),
             "f from the rotation with α = a/R, T from the hanging mass and the pulley, put into the body's translation"),
    ]
    if value.get("T") is not None:
        steps.append(Step("The tensions", "T₂ = m (g − a_h),  T = T₂ − ½ m_p a_h",
                          f"{term(m, 'kg')} × ({term(g, 'm/s**2')} − {term(value['a_hanging'], 'm/s**2')})",
                          f"T₂ = {quantity_text(value['T2'], 'N')}, T = {quantity_text(value['T'], 'N')}", "the hanging mass's equation, then the pulley's"))
    if mu_min is not None:
        steps.append(Step("Friction rolling needs, and the least μs that gives it", "f = k² M a − T,  μ_min = |f| / N" if c else "f = k² M a,  μ_min = |f| / N",
                          f"{term(abs(friction_needed), 'N')} / {term(normal, 'N')}", fmt(mu_min),
                          "N = M g cos θ (the string runs along the surface); static friction gives at most μs N"
                          + ("" if static is None else f"; here μs = {fmt(static)} {'≥' if rolls else '<'} μ_min, so it {'rolls' if rolls else 'slips'}")))
    if not rolls:
        equation = ("b = R α = (m g + f + W (g sin θ + 2f/M)) / (W (1 + k²) + k² M),  T = k² M b − f,  a = (T − M g sin θ − f)/M" if c
                    else "a = (m g − M g sin θ − f) / (M + m + ½ m_p),  R α = f / (k² M)")
        shown = "needs μₖ (--mu-k)" if value.get("a") is None else f"{quantity_text(value['a'], 'm/s**2')};  f = {quantity_text(value['friction'], 'N')}"
        steps.append(Step("Slipping: kinetic friction, the way the needed friction points", "f = ±μₖ N;  " + equation, "", shown,
                          "the contact slides, so friction takes its kinetic value and a no longer equals Rα (W = m + ½ m_p)"))
    if value.get("v") is not None:
        steps.append(Step("After the distance (uniform acceleration from rest)", "t = √(2d/|a|),  v = a t,  v_h = a_h t,  ω = α t", "",
                          f"{quantity_text(value['v'], 'm/s')}, {quantity_text(value['t'], 's')}", "a, a_h and α are constant"))
    return steps
