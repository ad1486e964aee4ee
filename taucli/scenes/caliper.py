"""Caliper disc brakes (#48 item 5): pads pressed on the faces of a disc, each with the normal
force F (a caliper squeezes both faces: 2 pads by default, surfaces=). The torque of one pad is
μ·F·R_eff, R_eff the pad's effective (friction) radius: ∫μ·p·r dA = μ·F·R_eff with F = ∫p dA.

An annular-sector pad between the radii Ri and Ro over the angle θ (dA = r·dr·dφ):

    uniform pressure p:     F = p·θ·(Ro² − Ri²)/2,       R_eff = (2/3)(Ro³ − Ri³)/(Ro² − Ri²)
                                                          = (2/3)(Ro² + Ro·Ri + Ri²)/(Ro + Ri)
    uniform wear (p·r = p_max·Ri, the wear rate the same everywhere):
                            F = p_max·θ·Ri·(Ro − Ri),    R_eff = (Ro + Ri)/2

(θ cancels from R_eff, but sets the pressure). A circular ("button") pad of radius R whose centre
is at e from the axis, a = R/e < 1: write a point of it as e·(1 + w), |w| ≤ a. For |w| < 1,
|1 + w|^s = (1 + w)^(s/2)·(1 + w̄)^(s/2) = Σⱼ Σₖ C(s/2, j)·C(s/2, k)·wʲ·w̄ᵏ; round a circle
|w| = ρ only j = k is left, ρ^(2k), whose mean over the disc |w| ≤ a is a^(2k)/(k + 1). So the
mean of (r/e)^s over the pad is

    M(s) = Σₖ C(s/2, k)²·a^(2k)/(k + 1),

    uniform pressure:   R_eff = ∫r dA/A = e·M(1) = e·(1 + a²/8 + a⁴/192 + …)      (above e)
    uniform wear (p = c/r):  F = c·∫dA/r, τ/μ = c·A, R_eff = e/M(−1) = e/(1 + a²/8 + 3a⁴/64 + …),
                        p_max = c/(e − R) = F/((e − R)·A·M(−1)/e)                 (below e)

δ = R_eff/e is the books' ratio. Shigley's table for button pads (after Fazekas: δ = 0.983,
0.969, 0.957, 0.947, 0.938 at R/e = 0.1 … 0.5) is neither of these models (at R/e = 0.5 uniform
pressure gives 1.0316 and p ∝ 1/r 0.9665); it is not used.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from taucli.scenes.given import Caliper
from taucli.writing.report import Step, fmt, quantity_text, term


def disc_mean_power(ratio: float, power: float) -> float:
    """M(s): the mean of (r/e)^s over a disc of radius a·e centred at e, a = ``ratio`` < 1 (module docstring)."""
    x = ratio * ratio
    half = power / 2
    coefficient, total, k, term_k = 1.0, 1.0, 0, 1.0
    while True:
        coefficient *= (half - k) / (k + 1)  # C(s/2, k + 1)
        k += 1
        term_k = coefficient * coefficient * x**k / (k + 1)
        total += term_k
        if term_k <= 1e-17 * total or k > 100000:
            return total


@dataclass(frozen=True)
class PadTorque:
    """One caliper's torques (all its surfaces), sliding and holding; its pads' R_eff and largest pressure (None: unknown)."""

    torque: float
    holding: float
    radius: float
    pressure: float | None


def caliper_torque(caliper: Caliper, steps: list[Step], notes: list[str]) -> PadTorque:
    """τ = surfaces·μ·F·R_eff, with the steps that find R_eff, the pressure and the torque."""
    name = caliper.source.replace("{", "").replace("}", "")
    wear = caliper.model == "wear"
    force = caliper.force
    pressure = None
    if caliper.pad == "circular":
        pad, centre = caliper.pad_radius, caliper.centre_distance
        ratio = pad / centre
        area = math.pi * pad * pad
        if wear:
            mean_inverse = disc_mean_power(ratio, -1.0)
            delta = 1 / mean_inverse
            equation = "R_eff = δ·e = e/M(−1),  M(−1) = mean of e/r = Σ C(−½,k)²·(R/e)^(2k)/(k+1)"
            why = ("worn in, the pressure falls as c/r (p·r, the wear rate, the same everywhere): F = c·∫dA/r and τ/μ = c·A, so "
                   "R_eff = A/∫dA/r; the mean of e/r over the circle is the series, from |1 + w|⁻¹ averaged over |w| ≤ R/e")
            pressure = force * centre / ((centre - pad) * area * mean_inverse)
        else:
            delta = disc_mean_power(ratio, 1.0)
            equation = "R_eff = δ·e = e·M(1),  M(1) = mean of r/e = Σ C(½,k)²·(R/e)^(2k)/(k+1)"
            why = ("the same pressure F/(πR²) over the whole pad: R_eff = ∫r dA/A, the mean distance of the pad from the axis "
                   "(a little beyond its centre's)")
            pressure = force / area
        radius = delta * centre
        steps.append(Step(f"Effective radius of the {name}'s circular pad (uniform {'wear' if wear else 'pressure'})", equation,
                          f"R = {quantity_text(pad, 'm')}, e = {quantity_text(centre, 'm')}, R/e = {fmt(ratio)}, δ = {fmt(delta)}",
                          quantity_text(radius, "m"), why))
        pressure_step = (("p_max = F·e/((e − R)·πR²·M(−1))", f"{term(force, 'N')} × {term(centre, 'm')} / (({term(centre, 'm')} − {term(pad, 'm')}) × "
                          f"π × ({term(pad, 'm')})² × {fmt(mean_inverse)})", "worn in, p = c/r is largest at the pad's edge nearest the axis, r = e − R")
                         if wear else ("p = F/(πR²)", f"{term(force, 'N')} / (π × ({term(pad, 'm')})²)", "the same pressure over the whole pad"))
    else:
        inner, outer = caliper.inner_radius, caliper.outer_radius
        if wear:
            radius = (outer + inner) / 2
            equation, numbers = "R_eff = (Ro + Ri)/2", f"({term(outer, 'm')} + {term(inner, 'm')}) / 2"
            why = "worn in, p·r is the same everywhere: F = p_max·θ·Ri·(Ro − Ri), τ = μ·p_max·θ·Ri·(Ro² − Ri²)/2 (θ cancels)"
        else:
            radius = 2 * (outer * outer + outer * inner + inner * inner) / (3 * (outer + inner))
            equation = "R_eff = (2/3)(Ro³ − Ri³)/(Ro² − Ri²) = (2/3)(Ro² + Ro·Ri + Ri²)/(Ro + Ri)"
            numbers = f"(2/3) × ({term(outer, 'm')}² + {term(outer, 'm')} × {term(inner, 'm')} + {term(inner, 'm')}²) / ({term(outer, 'm')} + {term(inner, 'm')})"
            why = "the same pressure everywhere: F = p·θ·(Ro² − Ri²)/2, τ = μ·p·θ·(Ro³ − Ri³)/3 (θ cancels)"
        steps.append(Step(f"Effective radius of the {name}'s annular pad (uniform {'wear' if wear else 'pressure'})", equation, numbers,
                          quantity_text(radius, "m"), why))
        angle = caliper.angle
        pressure_step = None
        if angle is None:
            notes.append(f"pressure_caliper: null, because {caliper.source} has no angle= (the pad's sector angle, which sets its area)")
        elif wear and inner <= 0 or outer <= inner:
            notes.append(f"pressure_caliper: null, because {caliper.source} has " + (
                "Ri = 0: worn in, p = p_max·Ri/r grows without bound at the centre" if outer > inner else "no area (Ri = Ro)"))
        elif wear:
            pressure = force / (angle * inner * (outer - inner))
            pressure_step = ("p_max = F/(θ·Ri·(Ro − Ri))", f"{term(force, 'N')} / ({term(angle, 'rad')} × {term(inner, 'm')} × ({term(outer, 'm')} − {term(inner, 'm')}))",
                             "worn in, p·r is the same everywhere, so the pressure is largest at the inner radius")
        else:
            pressure = force / (angle * (outer - inner) * (outer + inner) / 2)
            pressure_step = ("p = F/(θ·(Ro² − Ri²)/2)", f"{term(force, 'N')} / ({term(angle, 'rad')} × ({term(outer, 'm')}² − {term(inner, 'm')}²) / 2)",
                             "the same pressure over the pad's sector, of area θ·(Ro² − Ri²)/2")
    if pressure_step is not None:
        steps.append(Step(f"Largest pad pressure of the {name}", *pressure_step[:2], quantity_text(pressure, "Pa"), pressure_step[2]))
    torque = caliper.surfaces * caliper.mu_k * force * radius
    holding = caliper.surfaces * (caliper.mu_s if caliper.mu_s is not None else caliper.mu_k) * force * radius
    steps.append(Step(f"Friction torque of the {name}", "τ = n·μ·F·R_eff",
                      f"{caliper.surfaces} × {fmt(caliper.mu_k)} × {term(force, 'N')} × {term(radius, 'm')}", quantity_text(torque, "N*m"),
                      f"each of the n = {caliper.surfaces} pads (one on each face of the disc) is pressed with F and rubs with μF at R_eff"))
    return PadTorque(torque, holding, radius, pressure)
