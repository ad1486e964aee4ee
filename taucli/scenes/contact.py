"""Friction torques of contacts pressed against a turning body: brake shoes and flat faces (#24).

A brake shoe pressed with force N at radius r takes τ = μ·N·r; a flat annular face pressed
with force F between radii Ri and Ro takes, per contact surface,

    uniform pressure:  τ = (2/3)·μ·F·(Ro³ − Ri³)/(Ro² − Ri²) = (2/3)·μ·F·(Ro² + Ro·Ri + Ri²)/(Ro + Ri)
    uniform wear:      τ = μ·F·(Ro + Ri)/2

(the second form of the first keeps its digits as Ri → Ro, where both tend to μ·F·R). Each is a
constant Coulomb torque: kinetic μ while the body turns, static μ (at least the kinetic) holding it.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from taucli.errors import InputError
from taucli.report import Step, fmt, quantity_text
from taucli.scenes.given import Brake, Face

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

    @property
    def kinetic(self) -> float:
        return self.brake + self.face

    @property
    def static(self) -> float:
        return self.brake_static + self.face_static


def contacts(brakes: Sequence[Brake], faces: Sequence[Face], body_options: dict, mass: float | None, g: float | None) -> Contacts:
    """The torques of the brakes and faces on a body (its radius, radii and weight where they are not given)."""
    steps: list[Step] = []
    models: list[str] = []
    notes: list[str] = []
    brake = brake_static = face = face_static = 0.0
    rim = body_rim(body_options)
    for shoe in brakes:
        radius = shoe.radius if shoe.radius is not None else rim
        if radius is None:
            raise InputError(shoe.source, "needs radius= (the body has no radius to take)", example='{brake} "force=100N mu=0.4 radius=0.5m"')
        if shoe.radius is None:
            notes.append(f"{shoe.source}: pressed at the body's radius r = {quantity_text(radius, 'm')}")
        torque = shoe.mu_k * shoe.force * radius
        brake += torque
        brake_static += (shoe.mu_s if shoe.mu_s is not None else shoe.mu_k) * shoe.force * radius
        steps.append(Step(f"Friction torque of the {_name(shoe.source)}", "τ_b = μ·N·r",
                          f"{fmt(shoe.mu_k)} × {quantity_text(shoe.force, 'N')} × {quantity_text(radius, 'm')}", quantity_text(torque, "N*m"),
                          "the shoe's friction force μN acts along the rim, at lever arm r from the axle"))
    if brakes:
        models.append("brake friction μNr")
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
        if force is None:
            if mass is None or g is None:
                raise InputError(plate.source, "needs force= (or a body's mass, whose weight presses the face)", example='{face} "mu=0.2 force=50N"')
            force = mass * g
            steps.append(Step(f"Normal force on the {_name(plate.source)}", "F = m·g", f"{quantity_text(mass, 'kg')} × {quantity_text(g, 'm/s**2')}",
                              quantity_text(force, "N"), "the body lies on its face, so the surface carries its weight"))
        lever = face_radius_factor(inner, outer, plate.pressure)
        torque = plate.mu_k * force * lever * plate.surfaces
        face += torque
        face_static += (plate.mu_s if plate.mu_s is not None else plate.mu_k) * force * lever * plate.surfaces
        times = f"; {plate.surfaces} surfaces" if plate.surfaces != 1 else ""
        if plate.pressure == "wear":
            equation = "τ = μ·F·(Ro + Ri)/2" + (" × surfaces" if times else "")
            why = "worn in, the pressure falls as 1/r so that p·r (the wear rate) is the same everywhere; each ring carries μ·p·2πr·dr·r"
        else:
            equation = "τ = (2/3)·μ·F·(Ro³ − Ri³)/(Ro² − Ri²) = (2/3)·μ·F·(Ro² + RoRi + Ri²)/(Ro + Ri)" + (" × surfaces" if times else "")
            why = "the pressure F/(π(Ro² − Ri²)) is the same everywhere; each ring of radius r carries μ·p·2πr·dr at lever arm r"
        steps.append(Step(f"Friction torque of the {_name(plate.source)} (uniform {'wear' if plate.pressure == 'wear' else 'pressure'})", equation,
                          f"μ = {fmt(plate.mu_k)}, F = {quantity_text(force, 'N')}, Ro = {quantity_text(outer, 'm')}, Ri = {quantity_text(inner, 'm')}{times}",
                          quantity_text(torque, "N*m"), why))
        models.append(f"face friction under uniform {'wear' if plate.pressure == 'wear' else 'pressure'}")
    return Contacts(brake, brake_static, face, face_static, tuple(steps), tuple(dict.fromkeys(models)), tuple(notes))
