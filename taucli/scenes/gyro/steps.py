"""The steps of a top's precession: the spin's angular momentum, the torque turning it, the
gyroscopic rate, and the exact steady rates (top.py does the arithmetic; these write it out)."""

from __future__ import annotations

import math

from taucli.writing.report import Step, fmt, quantity_text, term
from taucli.scenes.gyro.roots import discriminant_ratio

def _degrees(theta: float) -> str:
    return f"{fmt(math.degrees(theta))}°"


def _common_steps(moment, spin, angular_momentum, body_steps) -> list[Step]:
    steps = list(body_steps)
    steps.append(
        Step(
            "Spin angular momentum",
            "L = Iω_s",
            f"{quantity_text(moment, 'kg*m**2')} × {quantity_text(spin, 'rad/s')}",
            quantity_text(angular_momentum, "kg*m**2/s"),
            "the body spins about its symmetry axis, so L points along that axis",
        )
    )
    return steps


def _turning_steps(angular_momentum, theta, sin_t, about: str = "the vertical") -> list[Step]:
    level = sin_t == 1.0
    across = "horizontal and at right angles to L" if about == "the vertical" else f"at right angles to L and to {about}"
    return [
        Step(
            "The torque changes L's direction, not its size",
            "τ = dL/dt",
            "",
            "",
            f"the torque is {across}, so in dt it adds dL = τ dt across L: "
            "L swings round without changing its size, and the axis follows it instead of falling",
        ),
        Step(
            "How far L turns",
            "|dL| = L dφ" if level else "|dL| = L sin θ dφ",
            "" if level else f"{quantity_text(angular_momentum, 'kg*m**2/s')} × sin {_degrees(theta)} × dφ",
            "" if level else f"{quantity_text(angular_momentum * sin_t, 'kg*m**2/s')} × dφ",
            f"the part of L across {about} (all of it at 90°) turns through dφ about {about}; the arc it sweeps is its length times dφ",
        ),
    ]


def torque_steps(moment, spin, angular_momentum, torque, theta, sin_t, rate, period, body_steps) -> list[Step]:
    steps = _common_steps(moment, spin, angular_momentum, body_steps)
    steps.append(
        Step(
            "The torque on the body (given)",
            f"τ = {quantity_text(torque, 'N*m')}",
            "",
            "",
            "the Sun's and Moon's pull on the Earth's equatorial bulge, or any torque across the spin axis, turning it about the axis it precesses round",
        )
    )
    steps += _turning_steps(angular_momentum, theta, sin_t, "the axis it precesses round")
    steps.append(
        Step(
            "Precession rate",
            "Ω = dφ/dt = τ/(L sin θ)",
            f"{quantity_text(torque, 'N*m')} / ({quantity_text(angular_momentum, 'kg*m**2/s')} × sin {_degrees(theta)})",
            "out of range" if rate is None else quantity_text(rate, "rad/s"),
            "divide |dL| = τ dt by L sin θ dt",
        )
    )
    if period is not None:
        steps.append(Step("Precession period", "T = 2π/Ω", f"2π / {quantity_text(rate, 'rad/s')}", _period_text(period), "one full turn of the spin axis round its cone"))
    return steps


def _period_text(period: float) -> str:
    text = quantity_text(period, "s")
    year = 365.25 * 86400.0
    if period >= 10 * year:
        text += f" ({fmt(period / year)} years)"
    return text


def top_steps(moment, spin, angular_momentum, mass, g, r, theta, sin_t, cos_t, rate, perp, roots, minimum, period, body_steps, perp_steps) -> list[Step]:
    steps = _common_steps(moment, spin, angular_momentum, body_steps)
    weight_torque = mass * g * r
    steps.append(
        Step(
            "Torque of the weight about the pivot",
            "τ = mgr sin θ",
            f"{quantity_text(mass, 'kg')} × {quantity_text(g, 'm/s**2')} × {quantity_text(r, 'm')}" + ("" if sin_t == 1.0 else f" × sin {_degrees(theta)}"),
            quantity_text(weight_torque * sin_t, "N*m"),
            "the weight acts at the centre of mass, r along the axis from the pivot; its lever arm is r sin θ",
        )
    )
    steps += _turning_steps(angular_momentum, theta, sin_t)
    steps.append(
        Step(
            "Precession rate (gyroscopic approximation)",
            "Ω = τ/(L sin θ) = mgr/(Iω_s)",
            f"{quantity_text(weight_torque, 'N*m')} / {quantity_text(angular_momentum, 'kg*m**2/s')}",
            "out of range" if rate is None else quantity_text(rate, "rad/s"),
            "sin θ cancels: the rate is the same at every tilt; this takes L to be the spin's alone",
        )
    )
    if perp is None:
        if period is not None:
            steps.append(Step("Precession period", "T = 2π/Ω", f"2π / {quantity_text(rate, 'rad/s')}", _period_text(period), "one full turn of the axis about the vertical"))
        return steps
    for write in perp_steps:
        steps += write()
    a = perp * cos_t
    steps.append(
        Step(
            "The exact steady precession",
            "mgr = Ω(Iω_s − I⊥Ω cos θ)",
            f"Ω({term(angular_momentum, 'kg*m**2/s')} − {term(a, 'kg*m**2')} × Ω)",
            quantity_text(weight_torque, "N*m"),
            "the precession turns the body too, adding I⊥Ω sin θ across the axis to L; the horizontal part of L is then "
            "(Iω_s − I⊥Ω cos θ) sin θ, and turning it at Ω takes τ = mgr sin θ: a quadratic, I⊥Ω²cos θ − Iω_sΩ + mgr = 0"
            + ("; at 90° cos θ = 0 and its one root is mgr/(Iω_s) exactly" if cos_t == 0 else ""),
        )
    )
    if roots is None:
        steps.append(
            Step(
                "No real root: the spin is too slow",
                "ω_min = √(4·I⊥·mgr·cos θ)/I",
                f"√(4 × {term(perp, 'kg*m**2')} × {term(weight_torque, 'N*m')} × {term(cos_t)}) / {term(moment, 'kg*m**2')}",
                quantity_text(minimum, "rad/s"),
                f"the discriminant (Iω_s)² − 4I⊥ cos θ·mgr is negative below ω_min; at ω_s = {fmt(spin)} rad/s no steady precession exists",
            )
        )
        return steps
    slow, fast = roots
    if cos_t == 0:
        if period is not None:
            steps.append(Step("Precession period", "T = 2π/Ω", f"2π / {quantity_text(slow, 'rad/s')}", _period_text(period), "one full turn of the axis about the vertical"))
        return steps
    root_d = angular_momentum * math.sqrt(1.0 - discriminant_ratio(a, weight_torque, angular_momentum))
    steps.append(
        Step(
            "The slow root, written without cancellation",
            "Ω_slow = 2mgr / (Iω_s + √D),  D = (Iω_s)² − 4I⊥ cos θ·mgr",
            f"2 × {term(weight_torque, 'N*m')} / ({term(angular_momentum, 'kg*m**2/s')} + {term(root_d, 'kg*m**2/s')})",
            quantity_text(slow, "rad/s"),
            "the usual (Iω_s − √D)/(2I⊥ cos θ) subtracts two nearly equal numbers when the spin is fast; this form adds them",
        )
    )
    if fast is not None:
        steps.append(
            Step(
                "The fast root",
                "Ω_fast = (Iω_s + √D) / (2I⊥ cos θ)",
                f"({term(angular_momentum, 'kg*m**2/s')} + {term(root_d, 'kg*m**2/s')}) / (2 × {term(a, 'kg*m**2')})",
                quantity_text(fast, "rad/s"),
                "the other steady motion: a precession so fast that I⊥Ω²cos θ carries the torque almost alone, "
                "Ω ≈ Iω_s/(I⊥ cos θ); a top seldom settles into it"
                if cos_t > 0
                else "negative: below the pivot the second steady motion goes round the other way",
            )
        )
    neglected = a * slow / angular_momentum
    steps.append(
        Step(
            "Why the approximation holds",
            "ε = I⊥Ω_slow cos θ / (Iω_s)",
            f"{term(a * slow, 'kg*m**2/s')} / {term(angular_momentum, 'kg*m**2/s')}",
            fmt(neglected),
            "in mgr = Ω(Iω_s − I⊥Ω cos θ), where Iω_s ≫ I⊥Ω cos θ (ε ≪ 1) the second term drops out and Ω ≈ mgr/(Iω_s); "
            "mgr/(Iω_s) = Ω_slow(1 − ε) exactly",
        )
    )
    if period is not None:
        steps.append(Step("Precession period", "T = 2π/Ω_slow", f"2π / {quantity_text(slow, 'rad/s')}", _period_text(period), "one full turn of the axis about the vertical"))
    return steps


def orbit_steps(mass, g, r, circle, rate, symbol, orbital, inward) -> list[Step]:
    """The centre of mass's orbit in steady precession, and the pivot's force that keeps it there."""
    return [
        Step(
            "Orbital angular momentum of the centre of mass",
            f"L_orb = m (r sin θ) {symbol} · r",
            f"{term(mass, 'kg')} × {term(circle, 'm')} × {term(abs(rate), 'rad/s')} × {term(r, 'm')}",
            quantity_text(orbital, "kg*m**2/s"),
            "the centre of mass goes round a horizontal circle of radius r sin θ at the precession rate; its velocity is at right angles "
            "to r, so the size of r × mv is r·m·v (the precession's own share of L, which the exact rates count in I⊥)",
        ),
        Step(
            "The pivot's force: vertical",
            "F_v = mg",
            f"{term(mass, 'kg')} × {term(g, 'm/s**2')}",
            quantity_text(mass * g, "N"),
            "in steady precession the centre of mass keeps its height, so the pivot holds up the whole weight",
        ),
        Step(
            "The pivot's force: horizontal",
            f"F_h = m{symbol}²(r sin θ)",
            f"{term(mass, 'kg')} × ({term(abs(rate), 'rad/s')})² × {term(circle, 'm')}",
            quantity_text(inward, "N"),
            "the centre of mass goes round its circle, so something pushes it towards the centre: the pivot, horizontally, towards "
            "the vertical through it",
        ),
    ]
