"""What an impulse leaves behind (#34): the body after a change given by parts, the period of a
turn after, and the linear momentum of a collision with a particle and the pivot's impulse.

Linear momentum: the system (body and particle) has p = Σ m v = M v_cm + m v. While the particle
strikes, the only external force that is impulsive is the pivot's (gravity's impulse over the
instant of the blow is nothing), so Newton's second law for the system, Σ F_ext = dp/dt,
integrated over the blow gives the pivot's impulse:

    J_pivot = p₁ − p₀ = (M d ω₁ + m v₁) − (M d ω₀ + m v₀),

all across the radius to the point struck, with the body's centre of mass on that radius at d
from the axis (v_cm = ωd). At the centre of percussion, r = I/(Md) from the axis, the pivot feels
no blow: there J_pivot = J(Mdr/I − 1) = 0 for the impulse J the particle gives.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from taucli.core.errors import InputError
from taucli.options.impulse import COMMAND as TABLE
from taucli.writing.report import Report, Step, quantity_text, term
from taucli.scenes.given import Part, Particle
from taucli.scenes.inertia import body, body_inertia, main_part, part_inertia
from taucli.options.table import Results

BODY_KEYS = ("inertia", "shape", "mass", "axis", "offset", "gyration", "density", "radius", "inner_radius", "outer_radius", "length", "width", "height", "depth")


def body_after(part_after: Sequence[Part], inertia_final: float | None, body_options: dict) -> tuple[float, list[Step]]:
    """I after a change: the body's --shape (or --inertia, or --gyration) with the parts after in
    place of --part; its steps under a heading that says so."""
    if inertia_final is not None:
        raise InputError("part_after", "conflicts with {inertia_final}: give the body after one way")
    options = {**body_options, "part": tuple(part_after)}
    has_main = any(options.get(name) is not None for name in ("inertia", "shape", "gyration"))
    if not has_main and not any(body_options.get(name) for name in ("part",)):
        raise InputError("part_after", "needs the body before: {inertia}, {shape} or {part}", example='{inertia} "3kg*m^2" {part_after} "point mass=5kg offset=0.2m"')
    moment, steps = body(**options)
    return moment, [Step(f"After: {s.title[0].lower()}{s.title[1:]}", s.equation, s.numbers, s.result, s.why) for s in steps]


def inertia_change(part_after: Sequence[Part], body_options: dict) -> float:
    """I₁ − I₀ where --part-after replaces the parts: the sum of the pieces after less those
    before, each piece's I as the body's sum has it (the unchanged ones cancel exactly), not the
    difference of the two totals, which loses a small part's change beside a large body."""
    def moments(parts: Sequence[Part]) -> list[float]:
        main = []
        if body_options.get("inertia") is not None:
            main = [body_options["inertia"]]
        elif body_options.get("shape") is not None or body_options.get("gyration") is not None:
            dims = {name: body_options.get(name) for name in ("radius", "inner_radius", "outer_radius", "length", "width", "height", "depth")}
            main = [part_inertia(main_part(body_options.get("shape"), body_options.get("mass"), body_options.get("axis"), body_options.get("offset"), dims,
                                           body_options.get("gyration"), body_options.get("density"))).inertia]
        return main + [part_inertia(p).inertia for p in parts]
    return math.fsum([*moments(part_after), *(-m for m in moments(body_options.get("part") or ()))])


def with_period(report: Report) -> Report:
    """The period of a turn after the impulse, T = 2π/|ω₁| (null where the body ends at rest)."""
    omega1 = report.results.get("omega1")
    if omega1 is None or omega1.value is None or "period" in report.results:
        return report
    results = Results(TABLE)
    results.update(report.results)
    if omega1.value == 0:
        results.put("period", None)
        report.notes.append("period: the body is at rest after, so it does not turn")
    else:
        period = 2 * math.pi / abs(omega1.value)
        results.put("period", period)
        report.steps = [*report.steps, Step("Period of a turn after", "T = 2π/|ω₁|", f"2π / {quantity_text(abs(omega1.value), 'rad/s')}",
                                            quantity_text(period, "s"), "one turn is 2π rad, at the speed after")]
    report.results = results
    return report


def body_centre(body_options: dict) -> tuple[float, float] | str:
    """(M, d): the body's mass and its centre's distance from the axis, or why they are not known."""
    if body_options.get("inertia") is not None:
        return "no body mass"  # a body of given I alone: no linear momentum is formed, nor said to be missing
    parts = list(body_options.get("part") or ())
    pieces = list(parts)
    if body_options.get("shape") is not None or body_options.get("gyration") is not None:
        dims = {name: body_options.get(name) for name in ("radius", "inner_radius", "outer_radius", "length", "width", "height", "depth")}
        pieces.insert(0, main_part(body_options.get("shape"), body_options.get("mass"), body_options.get("axis"), body_options.get("offset"), dims,
                                   body_options.get("gyration"), body_options.get("density")))
    found = body_inertia(pieces)
    if any(p.part.gyration is not None and p.part.offset is None for p in found.parts) or any(p.part.mass is None for p in found.parts):
        return "the body's centre of mass is not known from a radius of gyration or a part of given I: give it as a shape"
    if len(found.parts) > 1 and any(p.offset for p in found.parts):
        return "the directions of the parts' centres from the axis are not known: give the body as one shape"
    return found.mass, found.parts[0].offset if found.parts else 0.0


def put_momentum(results: Results, steps: list[Step], notes: list[str], centre: tuple[float, float] | str, particles: Sequence[Particle],
                 omega0: float, omega1: float, after: dict[str, float], impulses: dict[str, float]) -> None:
    """p0, p1 and pivot_impulse for one particle meeting the body across its radius (angle 90°);
    ``impulses``: the angular impulse each part receives (the body's IΔω, the particle's m r Δv),
    each formed from its exchange, so that p₁ − p₀ is too."""
    if not particles or centre == "no body mass":
        return
    why = None
    if len(particles) > 1:
        why = "one particle at a time"
    elif particles[0].speed is None:
        why = "a particle riding on the body strikes nothing"
    elif particles[0].angle is not None and abs(particles[0].angle - math.pi / 2) > 1e-12:
        why = "a particle meeting the body across its radius (angle= 90°): at another angle the axle also stops its motion along the radius"
    elif particles[0].radius_after is not None:
        why = "a particle that stays where it strikes (no radius-after=)"
    elif isinstance(centre, str):
        why = centre
    for key in ("p0", "p1", "pivot_impulse"):
        results.put(key, None)
    if why is not None:
        notes.append(f"p0, p1, pivot_impulse: given for {why}" if not why.startswith("the") else f"p0, p1, pivot_impulse: {why}")
        return
    p = particles[0]
    mass, d = centre
    v1 = after.get("particle", omega1 * p.radius)  # a particle that sticks moves with the body's point at r
    before = mass * d * omega0 + p.mass * p.speed
    after_p = mass * d * omega1 + p.mass * v1
    # the difference as the two exchanges, not p₁ − p₀ of near-equal totals
    pivot = math.fsum([mass * d * impulses["body"] / results["inertia"].value, impulses["particle"] / p.radius]) if p.radius else \
        mass * d * (omega1 - omega0) + p.mass * (v1 - p.speed)
    results.put("p0", before)
    results.put("p1", after_p)
    results.put("pivot_impulse", pivot)
    steps.append(Step("Linear momentum before and after", "p = M v_cm + m v,  v_cm = ω d",
                      f"{term(mass, 'kg')} × {term(omega0, 'rad/s')} × {term(d, 'm')} + {term(p.mass, 'kg')} × {term(p.speed, 'm/s')} → "
                      f"{term(mass, 'kg')} × {term(omega1, 'rad/s')} × {term(d, 'm')} + {term(p.mass, 'kg')} × {term(v1, 'm/s')}",
                      f"{quantity_text(before, 'kg*m/s')} → {quantity_text(after_p, 'kg*m/s')}",
                      "across the radius to the point struck; the body's centre of mass is on that radius, d from the axis"))
    steps.append(Step("Impulse of the pivot", "J_pivot = p₁ − p₀", f"{term(after_p, 'kg*m/s')} − {term(before, 'kg*m/s')}", quantity_text(pivot, "N*s"),
                      "the pivot's force is the only impulsive external force on the system, so it alone changes its linear momentum "
                      "(Newton's second law for the system, integrated over the blow)"))
    centre_of_percussion = None if not mass or not d else results["inertia"].value / (mass * d) if "inertia" in results else None
    if centre_of_percussion is not None:
        notes.append(f"the centre of percussion is {quantity_text(centre_of_percussion, 'm')} from the axis (I/(Md)): struck there, the pivot feels no blow")
