"""Friction torques of contacts pressed against a turning body: brake shoes, flat faces (#24),
band brakes (#35, taucli.scenes.band), internal expanding shoes (#48, taucli.scenes.expanding) and caliper disc
brakes (#48, taucli.scenes.caliper).

A brake shoe pressed with force N at radius r takes τ = μ·N·r. On a lever (a block brake), the
force F acts at ℓ from the lever's pivot, the shoe at x from it, and the line of the shoe's
friction force μN passes at c from the pivot; moments about the pivot:

    F·ℓ = N·x − μN·c   →   N = F·ℓ/(x − μ·c)

c > 0 where the friction's moment turns the lever the way F does (self-energizing: the drum
pulls the shoe on), c < 0 where it pushes the shoe off, c = 0 where its line passes through the
pivot. Where x ≤ μ·c the brake locks itself.

A long shoe (shoe-angle= 2θ, the arc it covers, symmetrical about the line to its pivot) wears
so that the pressure is p_max·cos φ at φ from its middle. Its resultant normal force (along the
middle) and its friction moment about the axle, per unit width,

    N = ∫ p_max·cos φ·cos φ·r dφ = p_max·r·(2θ + sin 2θ)/2,   τ = ∫ μ·p_max·cos φ·r² dφ = 2μ·p_max·r²·sin θ

give τ = μ′·N·r with μ′ = 4μ·sin θ/(2θ + sin 2θ) (μ′ → μ as θ → 0: a short shoe); the lever's
equations then take μ′ for μ.

A flat annular face pressed with force F between radii Ri and Ro takes, per contact surface,

    uniform pressure:  τ = (2/3)·μ·F·(Ro³ − Ri³)/(Ro² − Ri²) = (2/3)·μ·F·(Ro² + Ro·Ri + Ri²)/(Ro + Ri)
                       F = p_max·π·(Ro² − Ri²)          (p the same everywhere)
    uniform wear:      τ = μ·F·(Ro + Ri)/2
                       F = 2π·p_max·Ri·(Ro − Ri)        (p·r the same everywhere, p_max at Ri)

(the second form of the first keeps its digits as Ri → Ro, where both tend to μ·F·R). Each is a
constant Coulomb torque: kinetic μ while the body turns, static μ (at least the kinetic) holding it.

A cone clutch (cone= α, the semi-cone angle) presses a conical face between the radii Ri and Ro
with an axial force F. A ring of the face between r and r + dr has the slant width dr/sin α, so
the area 2πr·dr/sin α; the normal pressure p on it pushes back along the axis with p·2πr·dr (the
normal's axial share sin α times the area), and rubs with μ·p·2πr·dr/sin α at the arm r:

    F = ∫ p·2πr·dr  (as a flat face's)        τ = (flat face's τ)/sin α

so the cone multiplies the flat face's torque by 1/sin α (α = 90° is the flat face) and the
pressures in F are the same as a flat face's.
"""

from __future__ import annotations

from collections.abc import Sequence
import math
from dataclasses import dataclass, replace

from taucli.core.errors import InputError
from taucli.writing.report import Step, fmt, quantity_text, term
from taucli.scenes.angles import sin_exact
from taucli.scenes.band import band_torques
from taucli.scenes.caliper import caliper_torque
from taucli.scenes.expanding import EXAMPLE as EXPANDING_EXAMPLE, expanding_torques
from taucli.scenes.given import Band, Brake, Caliper, Face

def face_radius_factor(inner: float, outer: float, pressure: str) -> float:
    """The effective radius of an annular face per unit μF: τ = μ·F·(this) per surface."""
    if pressure == "wear":
        return (outer + inner) / 2
    return 2 * (outer * outer + outer * inner + inner * inner) / (3 * (outer + inner))


def body_radii(body_options: dict) -> tuple[float | None, float | None]:
    """(Ri, Ro) of a body lying on its flat face, from its shape; (None, None) where it has none."""
    shape = body_options.get("shape")
    if shape in ("disc", "cone") and body_options.get("radius") is not None:
        return 0.0, body_options["radius"]
    if shape == "ring" and body_options.get("radius") is not None:
        return body_options["radius"], body_options["radius"]
    if shape == "tube" and body_options.get("outer_radius") is not None:
        return body_options.get("inner_radius") or 0.0, body_options["outer_radius"]
    return None, None


def body_rim(body_options: dict) -> float | None:
    """The body's radius (its outer radius), where it has one."""
    for name in ("radius", "outer_radius"):
        if body_options.get(name) is not None and body_options.get("shape") not in (None, "rod", "plate", "box", "point"):
            return body_options[name]
    return None


def _name(source: str) -> str:
    """A spec's name for a step's title: "{brake} 2" -> "brake 2"."""
    return source.replace("{", "").replace("}", "")


@dataclass(frozen=True)
class Contacts:
    """The brakes' and faces' torques: kinetic and holding sums, their steps and the model's words."""

    brake: float = 0.0
    brake_static: float = 0.0
    face: float = 0.0
    face_static: float = 0.0
    steps: tuple[Step, ...] = ()
    models: tuple[str, ...] = ()
    notes: tuple[str, ...] = ()
    band: float = 0.0
    band_static: float = 0.0
    details: tuple[tuple[str, float | None, str], ...] = ()  # (result key, value, label part): forces, tensions, pressures
    caliper: float = 0.0
    caliper_static: float = 0.0

    @property
    def kinetic(self) -> float:
        return self.brake + self.face + self.band + self.caliper

    @property
    def static(self) -> float:
        return self.brake_static + self.face_static + self.band_static + self.caliper_static

    @property
    def shares(self) -> tuple[tuple[str, str, float], ...]:
        """(name, symbol, torque) of each kind of contact present."""
        return tuple((name, symbol, torque) for name, symbol, torque in
                     (("brake", "τ_b", self.brake), ("face", "τ_face", self.face), ("band", "τ_band", self.band),
                      ("caliper", "τ_cal", self.caliper)) if torque)


def contacts(brakes: Sequence[Brake], faces: Sequence[Face], body_options: dict, mass: float | None, g: float | None,
             bands: Sequence[Band] = (), calipers: Sequence[Caliper] = ()) -> Contacts:
    """The torques of the brakes, faces, bands and calipers on a body (its radius, radii and weight where they are not given)."""
    steps: list[Step] = []
    models: list[str] = []
    notes: list[str] = []
    details: list[tuple[str, float | None, str]] = []
    brake = brake_static = face = face_static = band = band_static = caliper = caliper_static = 0.0
    rim = body_rim(body_options)
    for shoe in brakes:
        if shoe.expanding:
            radius = _radius(shoe, rim, notes)
            inside = expanding_torques(shoe, radius)
            brake += inside.torque
            brake_static += inside.holding
            steps.extend(inside.steps)
            notes.extend(inside.notes)
            if len(brakes) == 1:
                details.extend((("force_actuating", inside.force, ""), ("pressure_brake", inside.pressure, "")))
            continue
        if shoe.shoe_angle is not None:
            shoe = _long_shoe(shoe, steps)
        radius = _radius(shoe, rim, notes)
        normal, normal_static = shoe.force, shoe.force
        if shoe.lever is not None:
            normal, normal_static = _lever_normal(shoe, steps, notes)
            if len(brakes) == 1:
                details.append(("force_brake", normal, ""))
        torque = shoe.mu_k * normal * radius
        brake += torque
        brake_static += (shoe.mu_s if shoe.mu_s is not None else shoe.mu_k) * normal_static * radius
        steps.append(Step(f"Friction torque of the {_name(shoe.source)}", "τ_b = μ·N·r",
                          f"{fmt(shoe.mu_k)} × {quantity_text(normal, 'N')} × {quantity_text(radius, 'm')}", quantity_text(torque, "N*m"),
                          "the shoe's friction force μN acts along the rim, at lever arm r from the axle"))
    if any(not shoe.expanding for shoe in brakes):
        models.append("brake friction μNr")
    if any(shoe.expanding for shoe in brakes):
        models.append("internal expanding shoes, p = p_a·sin θ/sin θ_a")
    for plate in faces:
        inner, outer = plate.inner_radius, plate.outer_radius
        if outer is None:
            body_inner, outer = body_radii(body_options)
            if outer is None:
                raise InputError(plate.source, "needs outer-radius= (the body's shape gives no flat face)", example='{face} "mu=0.3 force=2kN outer-radius=12cm"')
            inner = body_inner if inner is None else inner
            notes.append(f"{plate.source}: the face's radii from the body, Ri = {quantity_text(inner, 'm')}, Ro = {quantity_text(outer, 'm')}")
        inner = inner or 0.0
        if inner > outer:
            raise InputError(plate.source, "has inner-radius= above outer-radius=", got=f"{fmt(inner)} m > {fmt(outer)} m")
        force = plate.force
        if plate.pmax is not None:
            force = _clamp_from_pressure(plate, inner, outer, steps)
        elif force is None:
            if mass is None or g is None:
                raise InputError(plate.source, "needs force= (or a body's mass, whose weight presses the face)", example='{face} "mu=0.2 force=50N"')
            force = mass * g
            steps.append(Step(f"Normal force on the {_name(plate.source)}", "F = m·g", f"{quantity_text(mass, 'kg')} × {quantity_text(g, 'm/s**2')}",
                              quantity_text(force, "N"), "the body lies on its face, so the surface carries its weight"))
        sine = 1.0 if plate.cone is None else sin_exact(plate.cone)
        lever = face_radius_factor(inner, outer, plate.pressure) / sine
        torque = plate.mu_k * force * lever * plate.surfaces
        face += torque
        face_static += (plate.mu_s if plate.mu_s is not None else plate.mu_k) * force * lever * plate.surfaces
        times = f"; {plate.surfaces} surfaces" if plate.surfaces != 1 else ""
        cone = "" if plate.cone is None else "/sin α"
        if plate.pressure == "wear":
            equation = f"τ = μ·F·(Ro + Ri)/2{cone}" + (" × surfaces" if times else "")
            why = "worn in, the pressure falls as 1/r so that p·r (the wear rate) is the same everywhere; each ring carries μ·p·2πr·dr·r"
        else:
            equation = (f"τ = (2/3)·μ·F·(Ro³ − Ri³)/(Ro² − Ri²){cone} = (2/3)·μ·F·(Ro² + RoRi + Ri²)/(Ro + Ri){cone}" + (" × surfaces" if times else ""))
            why = "the pressure F/(π(Ro² − Ri²)) is the same everywhere; each ring of radius r carries μ·p·2πr·dr at lever arm r"
        if plate.cone is not None:
            why += ("; on a cone of semi-angle α the ring's slant width is dr/sin α, so its friction is 1/sin α times a flat ring's "
                    "while its pressure's axial share is the same (F the axial force)")
        angle = "" if plate.cone is None else f", α = {fmt(math.degrees(plate.cone))}°"
        kind = "face" if plate.cone is None else "cone"
        steps.append(Step(f"Friction torque of the {_name(plate.source)} ({'cone, ' if plate.cone is not None else ''}uniform {'wear' if plate.pressure == 'wear' else 'pressure'})", equation,
                          f"μ = {fmt(plate.mu_k)}, F = {quantity_text(force, 'N')}, Ro = {quantity_text(outer, 'm')}, Ri = {quantity_text(inner, 'm')}{angle}{times}",
                          quantity_text(torque, "N*m"), why))
        models.append(f"{kind} friction under uniform {'wear' if plate.pressure == 'wear' else 'pressure'}")
        if len(faces) == 1:
            details.append(("force_face", force, ""))
            details.append(("pressure_face", _face_pressure(plate, force, inner, outer, steps, notes), ""))
    for strap in bands:
        radius = strap.radius if strap.radius is not None else rim
        if radius is None:
            raise InputError(strap.source, "needs radius= (the body has no radius to take)", example='{band} "mu=0.25 wrap=270deg radius=0.3m tension=500N"')
        if strap.radius is None:
            notes.append(f"{strap.source}: wrapped round the body's rim, r = {quantity_text(radius, 'm')}")
        sliding, holding, band_steps, band_notes = band_torques(strap, radius)
        band += sliding.torque
        band_static += holding
        steps.extend(band_steps)
        notes.extend(band_notes)
        if len(bands) == 1:
            details.extend((("tension_tight", sliding.tight, ""), ("tension_slack", sliding.slack, "")))
            details.append(("pressure_band", None if strap.width is None else sliding.tight / (radius * strap.width), ""))
            if strap.width is None:
                notes.append(f"pressure_band: null, because {strap.source} " + ("is lined with blocks, which press the drum, not the band"
                             if strap.blocks is not None else "has no width= (the lining pressure is T/(r·w))"))
    for pads in calipers:
        found = caliper_torque(pads, steps, notes)
        caliper += found.torque
        caliper_static += found.holding
        if len(calipers) == 1:
            details.extend((("radius_effective", found.radius, ""), ("pressure_caliper", found.pressure, "")))
    if calipers:
        models.append("caliper disc brake μF·R_eff per pad")
    if any(strap.blocks is None for strap in bands):
        models.append("band brake T₁/T₂ = e^(μθ)")
    if any(strap.blocks is not None for strap in bands):
        models.append("band-and-block brake T₁/T₂ = ((1 + μ tan θ)/(1 − μ tan θ))ⁿ")
    return Contacts(brake, brake_static, face, face_static, tuple(steps), tuple(dict.fromkeys(models)), tuple(notes), band, band_static, tuple(details),
                    caliper, caliper_static)


def _radius(shoe: Brake, rim: float | None, notes: list[str]) -> float:
    """The radius a shoe presses at: its radius=, else the body's (noted)."""
    radius = shoe.radius if shoe.radius is not None else rim
    if radius is None:
        raise InputError(shoe.source, "needs radius= (the body has no radius to take)",
                         example=EXPANDING_EXAMPLE if shoe.expanding else '{brake} "force=100N mu=0.4 radius=0.5m"')
    if shoe.radius is None:
        notes.append(f"{shoe.source}: pressed at the body's radius r = {quantity_text(radius, 'm')}")
    return radius


def long_shoe_factor(shoe_angle: float) -> float:
    """μ′/μ of a long shoe of arc 2θ: 4·sin θ/(2θ + sin 2θ) (module docstring); 1 as θ → 0."""
    half = shoe_angle / 2
    return 4 * math.sin(half) / (shoe_angle + math.sin(shoe_angle))


def _long_shoe(shoe: Brake, steps: list[Step]) -> Brake:
    """The shoe with its μ made the long shoe's equivalent μ′ (its normal force the resultant N)."""
    factor = long_shoe_factor(shoe.shoe_angle)
    equivalent = replace(shoe, mu_k=shoe.mu_k * factor, mu_s=None if shoe.mu_s is None else shoe.mu_s * factor)
    steps.append(Step(f"Equivalent friction coefficient of the long {_name(shoe.source)}", "μ′ = 4μ·sin θ/(2θ + sin 2θ)",
                      f"4 × {fmt(shoe.mu_k)} × sin {fmt(math.degrees(shoe.shoe_angle / 2))}° / ({term(shoe.shoe_angle, 'rad')} + sin {fmt(math.degrees(shoe.shoe_angle))}°)",
                      fmt(equivalent.mu_k),
                      "the pressure on a long shoe pivoted far from the drum is p_max·cos φ round its arc 2θ; its resultant normal force N is "
                      "∫ p·cos φ, its friction moment ∫ μ·p·r, so τ = μ′·N·r"))
    return equivalent


def _lever_normal(shoe: Brake, steps: list[Step], notes: list[str]) -> tuple[float, float]:
    """N on a shoe from the force on its lever, sliding and holding: N = F·ℓ/(x − μ·c) (module docstring)."""
    name = _name(shoe.source)
    margin = shoe.pivot - shoe.mu_k * shoe.offset
    if margin <= 0:
        raise InputError(shoe.source, "locks itself: with pivot= x ≤ μ × offset= c the friction alone holds the shoe on, so N is not set by force= "
                         "(move the shoe further from the pivot, or the friction's line nearer it)",
                         example='{brake} "force=200N lever=1m pivot=0.4m offset=0.05m mu=0.3 radius=0.2m"',
                         got=f"x = {fmt(shoe.pivot)} m, μc = {fmt(shoe.mu_k * shoe.offset)} m")
    normal = shoe.force * shoe.lever / margin
    mu_s = shoe.mu_s if shoe.mu_s is not None else shoe.mu_k
    margin_static = shoe.pivot - mu_s * shoe.offset
    normal_static = math.inf if margin_static <= 0 else shoe.force * shoe.lever / margin_static
    if margin_static <= 0:
        notes.append(f"{shoe.source}: at rest it locks itself (x ≤ μs·c): it holds the body against any torque")
    if shoe.offset:
        how = ("self-energizing: the friction's moment about the pivot turns the lever the way F does" if shoe.offset > 0 else
               "the friction's moment about the pivot works against F, pushing the shoe off")
        equation, numbers = "F·ℓ = N·x − μN·c  →  N = F·ℓ/(x − μ·c)", (
            f"{term(shoe.force, 'N')} × {term(shoe.lever, 'm')} / ({term(shoe.pivot, 'm')} − {fmt(shoe.mu_k)} × {term(shoe.offset, 'm')})")
    else:
        how = "the friction's line passes through the pivot: it has no moment about it"
        equation, numbers = "F·ℓ = N·x  →  N = F·ℓ/x", f"{term(shoe.force, 'N')} × {term(shoe.lever, 'm')} / {term(shoe.pivot, 'm')}"
    steps.append(Step(f"Normal force on the {name} from its lever", equation, numbers, quantity_text(normal, "N"), f"moments about the lever's pivot; {how}"))
    return normal, normal_static


def _clamp_from_pressure(plate: Face, inner: float, outer: float, steps: list[Step]) -> float:
    """The clamp force that gives the largest lining pressure pmax (module docstring)."""
    name = _name(plate.source)
    if plate.pressure == "wear":
        if inner <= 0:
            raise InputError(plate.source, "pmax= with model=wear needs inner-radius= above 0 (worn in, p·r is the same everywhere, so p_max is at Ri)",
                             example='{face} "mu=0.3 pmax=1MPa inner-radius=5cm outer-radius=12cm model=wear"')
        force = 2 * math.pi * plate.pmax * inner * (outer - inner)
        steps.append(Step(f"Clamp force of the {name} (uniform wear)", "F = 2π·p_max·Ri·(Ro − Ri)",
                          f"2π × {term(plate.pmax, 'Pa')} × {term(inner, 'm')} × ({term(outer, 'm')} − {term(inner, 'm')})", quantity_text(force, "N"),
                          "worn in, p = p_max·Ri/r; each ring carries p·2πr·dr = 2π·p_max·Ri·dr"))
    else:
        force = math.pi * plate.pmax * (outer - inner) * (outer + inner)
        steps.append(Step(f"Clamp force of the {name} (uniform pressure)", "F = p_max·π·(Ro² − Ri²)",
                          f"{term(plate.pmax, 'Pa')} × π × ({term(outer, 'm')}² − {term(inner, 'm')}²)", quantity_text(force, "N"),
                          "the same pressure over the whole annulus"))
    return force


def _face_pressure(plate: Face, force: float, inner: float, outer: float, steps: list[Step], notes: list[str]) -> float | None:
    """The largest lining pressure of a face pressed with ``force``; None where it is unbounded (noted)."""
    if plate.pmax is not None:
        return plate.pmax
    area_factor = (outer - inner) * (outer + inner)
    if plate.pressure == "wear" and inner <= 0 or area_factor <= 0:
        notes.append(f"pressure_face: null, because {plate.source} has " + (
            "Ri = 0: worn in, p = p_max·Ri/r grows without bound at the centre" if area_factor > 0 else "no area (Ri = Ro)"))
        return None
    if plate.pressure == "wear":
        pressure = force / (2 * math.pi * inner * (outer - inner))
        equation, numbers = "p_max = F/(2π·Ri·(Ro − Ri))", f"{term(force, 'N')} / (2π × {term(inner, 'm')} × ({term(outer, 'm')} − {term(inner, 'm')}))"
        why = "worn in, p·r is the same everywhere, so the pressure is largest at the inner radius"
    else:
        pressure = force / (math.pi * area_factor)
        equation, numbers = "p = F/(π·(Ro² − Ri²))", f"{term(force, 'N')} / (π × ({term(outer, 'm')}² − {term(inner, 'm')}²))"
        why = "the same pressure over the whole annulus"
    steps.append(Step(f"Largest lining pressure of the {_name(plate.source)}", equation, numbers, quantity_text(pressure, "Pa"), why))
    return pressure
