"""Internal expanding shoes (#48 item 5; Shigley ch. 16-2, Bhandari, Khurmi): a shoe inside the
drum, hinged on a pin at a distance a from the drum's centre, pushed out against the drum by an
actuating force F at c from the pin. θ is measured at the drum's centre from the line through the
pin; the lining runs from its heel θ₁ to its toe θ₂ = θ₁ + the shoe's arc, of face width b, on a
drum of radius r.

A rigid shoe turning a little about its pin presses the lining by an amount ∝ the distance from
the pin's line, so the pressure grows as sin θ:

    p = p_a·sin θ/sin θ_a        θ_a = θ₂ where θ₂ ≤ 90°, else 90° (p_a the largest pressure)

A strip dθ of lining presses the drum with dN = p·b·r·dθ and rubs along it with μ·dN. Their moments
about the pin (the normal force's arm a·sin θ, the friction's r − a·cos θ) and the friction's
moment about the drum's centre (arm r):

    M_N = ∫ dN·a·sin θ        = p_a·b·r·a/sin θ_a · ∫ sin²θ dθ
    M_f = ∫ μ·dN·(r − a·cos θ) = μ·p_a·b·r/sin θ_a · ∫ sin θ·(r − a·cos θ) dθ
    T   = ∫ μ·dN·r            = μ·p_a·b·r²·(cos θ₁ − cos θ₂)/sin θ_a

Moments about the pin balance the shoe: F·c = M_N − M_f on the leading shoe (its heel at the pin
the drum turns away from: the friction's moment turns it on, self-energizing) and F·c = M_N + M_f
on the trailing one. Where M_f ≥ M_N the leading shoe locks itself: the drum drags it on with no
force at all. Two shoes on one pin line, pushed apart by the same F (the books' usual brake), are
one leading and one trailing whichever way the drum turns; given the largest pressure, it is on the
leading shoe, and F follows from it.

The integrals are kept in forms that hold their digits for a short arc:
∫ sin θ dθ = cos θ₁ − cos θ₂ = 2·sin(Σ/2)·sin(Δ/2), ∫ sin θ cos θ dθ = sin Σ·sin Δ/2 and
∫ sin²θ dθ = (Δ − sin Δ·cos Σ)/2 = ((Δ − sin Δ) + 2·sin Δ·sin²(Σ/2))/2 with Σ = θ₁ + θ₂,
Δ = θ₂ − θ₁, and Δ − sin Δ by its series for Δ < 1.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from taucli.core.errors import InputError
from taucli.writing.report import Step, fmt, quantity_text, term
from taucli.scenes.given import Brake

EXAMPLE = '{brake} "expanding=yes pmax=1MPa mu=0.32 width=32mm radius=150mm hinge=123mm lever=212mm heel-angle=0deg shoe-angle=126deg"'


def _x_minus_sin(x: float) -> float:
    """x − sin x, by its series below 1 (where the difference would cancel)."""
    if x >= 1:
        return x - math.sin(x)
    total, term_, k = 0.0, x, 1
    while True:  # x³/3! − x⁵/5! + …
        term_ *= -x * x / ((2 * k) * (2 * k + 1)) if k > 1 else x * x / 6
        total += term_
        if abs(term_) < 1e-18 * abs(total):
            return total
        k += 1


@dataclass(frozen=True)
class Arc:
    """The lining's arc and what its integrals give: per unit p_a·b·r/sin θ_a."""

    heel: float
    toe: float
    sin_a: float  # sin θ_a
    sines: float  # ∫ sin θ dθ = cos θ₁ − cos θ₂
    sine_cosine: float  # ∫ sin θ·cos θ dθ
    squares: float  # ∫ sin²θ dθ

    @classmethod
    def of(cls, heel: float, arc: float) -> Arc:
        toe = heel + arc
        total = heel + toe
        sin_a = 1.0 if toe >= math.pi / 2 else math.sin(toe)
        sines = 2 * math.sin(total / 2) * math.sin(arc / 2)
        sine_cosine = math.sin(total) * math.sin(arc) / 2
        squares = (_x_minus_sin(arc) + 2 * math.sin(arc) * math.sin(total / 2) ** 2) / 2
        return cls(heel, toe, sin_a, sines, sine_cosine, squares)


@dataclass(frozen=True)
class Shoe:
    """One shoe at its largest pressure: its moments about the pin, the force they need, its torque."""

    name: str  # "leading" or "trailing"
    pressure: float  # p_a
    normal_moment: float  # M_N
    friction_moment: float  # M_f
    force: float  # F
    torque: float  # T


def _per_pressure(brake: Brake, arc: Arc, radius: float, mu: float) -> tuple[float, float, float]:
    """M_N, M_f and T at p_a = 1 Pa."""
    scale = brake.width * radius / arc.sin_a
    normal = scale * brake.hinge * arc.squares
    friction = mu * scale * (radius * arc.sines - brake.hinge * arc.sine_cosine)
    return normal, friction, mu * scale * radius * arc.sines


def _shoe(brake: Brake, arc: Arc, radius: float, mu: float, name: str, *, pressure: float | None = None, force: float | None = None) -> Shoe | None:
    """A shoe from its largest pressure or its actuating force; None where it locks itself (leading, M_f ≥ M_N)."""
    normal, friction, torque = _per_pressure(brake, arc, radius, mu)
    net = normal - friction if name == "leading" else normal + friction
    if net <= 0:
        return None
    if pressure is None:
        pressure = force * brake.lever / net
    return Shoe(name, pressure, normal * pressure, friction * pressure, pressure * net / brake.lever, torque * pressure)


def _locks(brake: Brake, what: str, arc: Arc, radius: float, mu: float) -> InputError:
    normal, friction, _ = _per_pressure(brake, arc, radius, mu)
    return InputError(brake.source, f"locks itself: on the leading shoe the friction's moment about the hinge pin is at least the normal force's "
                      f"(M_f ≥ M_N at {what}), so the drum drags the shoe on with no actuating force "
                      "(a smaller mu=, or hinge= further from the drum's centre)",
                      example=EXAMPLE, got=f"M_f/M_N = {fmt(friction / normal)}")


@dataclass(frozen=True)
class Expanding:
    """The shoes sliding (kinetic μ), the most torque they hold at rest (static μ; infinite where
    the leading shoe locks itself), the actuating force, the largest pressure, steps and notes."""

    shoes: tuple[Shoe, ...]
    torque: float
    holding: float
    force: float
    pressure: float
    steps: tuple[Step, ...]
    notes: tuple[str, ...]


def expanding_torques(brake: Brake, radius: float) -> Expanding:
    """The internal expanding brake's shoes (module docstring)."""
    name = brake.source.replace("{", "").replace("}", "")
    if brake.hinge >= radius:
        raise InputError(brake.source, "has hinge= at or beyond the drum's radius: the shoes' pin is inside the drum (a < r)",
                         example=EXAMPLE, got=f"a = {fmt(brake.hinge)} m, r = {fmt(radius)} m")
    arc = Arc.of(brake.heel_angle, brake.shoe_angle)
    kinds = ("leading", "trailing") if brake.shoes == "both" else (brake.shoes,)
    mu_s = brake.mu_s if brake.mu_s is not None else brake.mu_k
    if "leading" in kinds and _shoe(brake, arc, radius, brake.mu_k, "leading", pressure=1.0) is None:
        raise _locks(brake, "μ = " + fmt(brake.mu_k), arc, radius, brake.mu_k)
    if brake.force is None:  # the largest pressure is on the leading shoe where there is one
        first = _shoe(brake, arc, radius, brake.mu_k, kinds[0], pressure=brake.pmax)
        force = first.force
        shoes = (first, *(_shoe(brake, arc, radius, brake.mu_k, kind, force=force) for kind in kinds[1:]))
    else:
        force = brake.force
        shoes = tuple(_shoe(brake, arc, radius, brake.mu_k, kind, force=force) for kind in kinds)
    holding_shoes = [_shoe(brake, arc, radius, mu_s, kind, force=force) for kind in kinds]
    notes = []
    if any(shoe is None for shoe in holding_shoes):
        notes.append(f"{brake.source}: at rest its leading shoe locks itself (M_f ≥ M_N at μs = {fmt(mu_s)}): it holds the drum against any torque")
        holding = math.inf
    else:
        holding = sum(shoe.torque for shoe in holding_shoes)
    torque = sum(shoe.torque for shoe in shoes)
    steps = [Step(f"Pressure round the {name}'s internal shoes", "p = p_a·sin θ/sin θ_a  (θ_a = θ₂ up to 90°, else 90°)",
                  f"θ₁ = {fmt(math.degrees(arc.heel))}°, θ₂ = θ₁ + {fmt(math.degrees(brake.shoe_angle))}° = {fmt(math.degrees(arc.toe))}°",
                  f"θ_a = {fmt(math.degrees(min(arc.toe, math.pi / 2)))}°, sin θ_a = {fmt(arc.sin_a)}",
                  "each shoe turns a little about its hinge pin, so the lining is pressed in, and presses back, in proportion to its distance from "
                  "the pin's line: sin θ, largest at 90° from it (or at the toe, short of 90°)")]
    steps.extend(_shoe_steps(brake, arc, radius, shoes, name))
    if len(shoes) > 1:
        steps.append(Step(f"Braking torque of the {name}'s two shoes", "T = T_leading + T_trailing",
                          " + ".join(quantity_text(shoe.torque, "N*m") for shoe in shoes), quantity_text(torque, "N*m"),
                          "the same actuating force pushes both shoes; the leading one, helped by its friction, presses harder"))
    pressure = max(shoe.pressure for shoe in shoes)
    return Expanding(tuple(shoes), torque, holding, force, pressure, tuple(steps), tuple(notes))


def _shoe_steps(brake: Brake, arc: Arc, radius: float, shoes, name: str) -> list[Step]:
    """Each shoe's moments, its force or pressure, and its torque, in the order the books work them."""
    steps: list[Step] = []
    b, r, a, c, mu = term(brake.width, "m"), term(radius, "m"), term(brake.hinge, "m"), term(brake.lever, "m"), fmt(brake.mu_k)
    heel, toe, sin_a = f"{fmt(math.degrees(arc.heel))}°", f"{fmt(math.degrees(arc.toe))}°", fmt(arc.sin_a)
    for number, shoe in enumerate(shoes):
        sign = "−" if shoe.name == "leading" else "+"
        pa = term(shoe.pressure, "Pa")
        given_pressure = brake.force is None and number == 0
        steps.append(Step(f"Moments about the hinge pin of the {shoe.name} shoe",
                          "M_N = p_a·b·r·a/sin θ_a·∫sin²θ dθ;  M_f = μ·p_a·b·r/sin θ_a·∫sin θ·(r − a·cos θ) dθ  (θ₁ to θ₂)",
                          f"p_a = {pa}, b = {b}, r = {r}, a = {a}, μ = {mu}, θ from {heel} to {toe}, sin θ_a = {sin_a}" if given_pressure else
                          f"per unit p_a: b = {b}, r = {r}, a = {a}, μ = {mu}, θ from {heel} to {toe}, sin θ_a = {sin_a}",
                          f"M_N = {quantity_text(shoe.normal_moment, 'N*m')}, M_f = {quantity_text(shoe.friction_moment, 'N*m')}" if given_pressure else
                          f"M_N/p_a = {quantity_text(shoe.normal_moment / shoe.pressure, 'm**3')}, M_f/p_a = {quantity_text(shoe.friction_moment / shoe.pressure, 'm**3')}",
                          "each strip of lining pushes on the drum with p·b·r·dθ at the arm a·sin θ about the pin, and rubs along the drum with μ times "
                          "that at the arm r − a·cos θ"))
        why = ("the friction's moment about the pin turns the leading shoe on (self-energizing), so the force needs only M_N − M_f"
               if shoe.name == "leading" else "the friction's moment about the pin pushes the trailing shoe off, so the force must give M_N + M_f")
        if given_pressure:
            steps.append(Step(f"Actuating force from the {shoe.name} shoe's largest pressure", f"F = (M_N {sign} M_f)/c",
                              f"({term(shoe.normal_moment, 'N*m')} {sign} {term(shoe.friction_moment, 'N*m')}) / {c}", quantity_text(shoe.force, "N"), why))
        else:
            steps.append(Step(f"Largest pressure on the {shoe.name} shoe", f"F·c = M_N {sign} M_f  →  p_a = F·c/(M_N/p_a {sign} M_f/p_a)",
                              f"{term(shoe.force, 'N')} × {c} / ({term(shoe.normal_moment / shoe.pressure, 'm**3')} {sign} "
                              f"{term(shoe.friction_moment / shoe.pressure, 'm**3')})", quantity_text(shoe.pressure, "Pa"), why))
        steps.append(Step(f"Braking torque of the {shoe.name} shoe", "T = μ·p_a·b·r²·(cos θ₁ − cos θ₂)/sin θ_a",
                          f"{mu} × {pa} × {b} × ({r})² × (cos {heel} − cos {toe}) / {sin_a}", quantity_text(shoe.torque, "N*m"),
                          "each strip's friction μ·p·b·r·dθ acts along the drum at the arm r from its centre"))
    return steps
