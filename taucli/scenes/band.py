"""A band brake (#35): a band wrapped an angle θ round a drum, its friction making the tension grow
from the slack end T₂ to the tight end T₁ (the end the drum drags the band towards):

    T₁/T₂ = e^{μθ}                     (belt friction, the capstan equation, while it slides)
    τ = (T₁ − T₂)·r = T₂·(e^{μθ} − 1)·r  (the band's net pull on the drum's rim)
    p = T/(r·w)                        (the lining pressure under the band: largest at the tight end)

The band is pulled by a tension T₂ on its slack end (tension=), or by a lever: a force F at ℓ
from the lever's pivot, the slack end fixed to the lever at b from the pivot and the tight end at
a (an end not on the lever is fixed at the pivot). Moments about the lever's pivot:

    slack end on the lever (simple):    F·ℓ = T₂·b
    tight end on the lever (simple):    F·ℓ = T₁·a
    both, on opposite sides (differential): F·ℓ = T₂·b − T₁·a = T₂·(b − e^{μθ}·a)

The differential brake locks itself (F ≤ 0 needed) where b ≤ a·e^{μθ}. The geometry is for the
sense the drum turns; the other sense swaps the tight and slack ends (the scenes refuse a turn back).

A band-and-block brake lines the band with n blocks, each covering an angle 2θ of the drum. A
block between the tensions T₀ (its slack side) and T (its tight side), pulled along the band at
the ends of its arc, presses the drum with N and rubs with μN at its middle; resolving along and
across the block's middle radius:

    (T + T₀)·sin θ = N,   (T − T₀)·cos θ = μN   →   T/T₀ = (1 + μ tan θ)/(1 − μ tan θ)

so over n blocks T₁/T₂ = ((1 + μ tan θ)/(1 − μ tan θ))ⁿ = e^{2n·artanh(μ tan θ)} (the form kept
here: its digits hold for a small μ tan θ), and as n → ∞ with 2nθ fixed it tends to the band's
e^{μ·2nθ}. The band lies a block's thickness t out from the drum, so its tensions' torque is
(T₁ − T₂)·(r + t). Where μ tan θ ≥ 1 a block would lock itself (no finite tension turns the drum).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from taucli.core.errors import InputError
from taucli.writing.report import Step, fmt, quantity_text, term
from taucli.scenes.given import Band

EXAMPLE = '{band} "mu=0.25 wrap=270deg radius=0.3m force=400N lever=750mm slack-arm=125mm"'


@dataclass(frozen=True)
class BandForces:
    """The band's tensions (N), its torque on the drum (N·m), at one coefficient."""

    tight: float
    slack: float
    torque: float


def band_forces(band: Band, mu: float, radius: float) -> BandForces | None:
    """T₁, T₂ and τ with coefficient μ; None where a differential brake locks itself (b ≤ a·e^{μθ}),
    or a block of a band-and-block brake does (μ tan θ ≥ 1). ``radius`` is the drum's."""
    exponent = log_ratio(band, mu)
    if exponent is None:
        return None
    growth = math.expm1(exponent)  # e^{μθ} − 1, its digits kept for a small μθ
    ratio = 1.0 + growth
    radius = radius + band.thickness
    if band.tension is not None:
        slack = band.tension
    elif band.tight_arm is None:
        slack = band.force * band.lever / band.slack_arm
    elif band.slack_arm is None:
        tight = band.force * band.lever / band.tight_arm
        return BandForces(tight, tight / ratio, tight * (-math.expm1(-exponent)) * radius)
    else:
        margin = band.slack_arm - ratio * band.tight_arm
        if margin <= 0:
            return None
        slack = band.force * band.lever / margin
    return BandForces(ratio * slack, slack, slack * growth * radius)


def log_ratio(band: Band, mu: float) -> float | None:
    """ln(T₁/T₂): μθ for a band, 2n·artanh(μ tan θ) for n blocks of angle 2θ (None: a block locks itself)."""
    if band.blocks is None:
        return mu * band.wrap
    lean = mu * math.tan(band.block_angle / 2)
    if lean >= 1:
        return None
    return 2 * band.blocks * math.atanh(lean)


def band_torques(band: Band, radius: float) -> tuple[BandForces, float, list[Step], list[str]]:
    """The band sliding (kinetic μ: its forces) and holding (static μ: the most torque it holds;
    infinite where it locks itself), with the steps and notes."""
    sliding = band_forces(band, band.mu_k, radius)
    name = band.source.replace("{", "").replace("}", "")
    if sliding is None and band.blocks is not None and log_ratio(band, band.mu_k) is None:
        raise InputError(band.source, "locks itself: with μ·tan θ ≥ 1 (θ half a block's angle) a block's friction alone would hold it on the drum, "
                         "so no tension sets the torque (shorter blocks, or a smaller μ)",
                         example='{band} "mu=0.3 blocks=12 block-angle=15deg radius=300mm tension=1kN"',
                         got=f"μ·tan θ = {fmt(band.mu_k * math.tan(band.block_angle / 2))}")
    if sliding is None:
        raise InputError(band.source, "locks itself: with slack-arm= b ≤ tight-arm= a × e^(μθ) the tight end's pull alone holds the lever down, "
                         "so the torque is not set by force= (make slack-arm= longer)",
                         example=EXAMPLE, got=f"b = {fmt(band.slack_arm)} m, a·e^(μθ) = {fmt(band.tight_arm * math.exp(log_ratio(band, band.mu_k)))} m")
    notes: list[str] = []
    mu_s = band.mu_s if band.mu_s is not None else band.mu_k
    holding = band_forces(band, mu_s, radius)
    static = math.inf if holding is None else holding.torque
    if holding is None:
        notes.append(f"{band.source}: at rest it locks itself (" + ("μs·tan θ ≥ 1" if log_ratio(band, mu_s) is None else "b ≤ a·e^(μs·θ)")
                     + "): it holds the drum against any torque")
    if band.blocks is None:
        steps = [Step(f"Tension ratio of the {name}", "T₁/T₂ = e^(μθ)", f"e^({fmt(band.mu_k)} × {term(band.wrap, 'rad')})", fmt(sliding.tight / sliding.slack),
                      "belt friction: each element of the band, sliding over the drum, adds μ times its pressure to the tension (the capstan equation)")]
    else:
        half = band.block_angle / 2
        steps = [Step(f"Tension ratio of the {name} ({band.blocks} blocks)", "T₁/T₂ = ((1 + μ·tan θ)/(1 − μ·tan θ))ⁿ",
                      f"((1 + {fmt(band.mu_k)} × tan {fmt(math.degrees(half))}°)/(1 − {fmt(band.mu_k)} × tan {fmt(math.degrees(half))}°))^{band.blocks}",
                      fmt(sliding.tight / sliding.slack),
                      "each block of angle 2θ, between the tensions T₀ and T at its ends, presses the drum with N = (T + T₀)·sin θ "
                      "and rubs with μN = (T − T₀)·cos θ, so T/T₀ = (1 + μ tan θ)/(1 − μ tan θ) per block")]
    if band.tension is not None:
        steps.append(Step(f"Tensions of the {name}", "T₂ = tension given;  T₁ = T₂·(T₁/T₂)", f"{term(sliding.slack, 'N')} × {fmt(sliding.tight / sliding.slack)}",
                          f"T₁ = {quantity_text(sliding.tight, 'N')}, T₂ = {quantity_text(sliding.slack, 'N')}", "the pull on the slack end, grown over the wrap"))
    else:
        force, lever = term(band.force, "N"), term(band.lever, "m")
        if band.tight_arm is None:
            equation, numbers = "F·ℓ = T₂·b  →  T₂ = F·ℓ/b", f"{force} × {lever} / {term(band.slack_arm, 'm')}"
            why = "moments about the lever's pivot: the tight end is fixed at the pivot, the slack end pulled by the lever at b"
        elif band.slack_arm is None:
            equation, numbers = "F·ℓ = T₁·a  →  T₁ = F·ℓ/a", f"{force} × {lever} / {term(band.tight_arm, 'm')}"
            why = "moments about the lever's pivot: the slack end is fixed at the pivot, the tight end pulled by the lever at a"
        else:
            grown = "e^(μθ)" if band.blocks is None else "(T₁/T₂)"
            equation = f"F·ℓ = T₂·b − T₁·a = T₂·(b − a·{grown})  →  T₂ = F·ℓ/(b − a·{grown})"
            numbers = f"{force} × {lever} / ({term(band.slack_arm, 'm')} − {term(band.tight_arm, 'm')} × {fmt(sliding.tight / sliding.slack)})"
            why = "moments about the lever's pivot of a differential band brake: the tight end's pull, on the other side, helps the force"
        steps.append(Step(f"Tensions of the {name} from the lever", equation, numbers,
                          f"T₁ = {quantity_text(sliding.tight, 'N')}, T₂ = {quantity_text(sliding.slack, 'N')}", why))
    if band.thickness:
        steps.append(Step(f"Braking torque of the {name}", "τ = (T₁ − T₂)·(r + t)",
                          f"({term(sliding.tight, 'N')} − {term(sliding.slack, 'N')}) × ({term(radius, 'm')} + {term(band.thickness, 'm')})",
                          quantity_text(sliding.torque, "N*m"), "the band's two ends pull opposite ways along its line, a block's thickness t out from the drum"))
    else:
        steps.append(Step(f"Braking torque of the {name}", "τ = (T₁ − T₂)·r", f"({term(sliding.tight, 'N')} − {term(sliding.slack, 'N')}) × {term(radius, 'm')}",
                          quantity_text(sliding.torque, "N*m"), "the band's two ends pull the drum's rim opposite ways, the tight end harder"))
    if band.width is not None:
        steps.append(Step(f"Largest lining pressure of the {name}", "p_max = T₁/(r·w)", f"{term(sliding.tight, 'N')} / ({term(radius, 'm')} × {term(band.width, 'm')})",
                          quantity_text(sliding.tight / (radius * band.width), "Pa"),
                          "a band under tension T presses the drum with T/r per unit length of rim; at the tight end T = T₁"))
    return sliding, static, steps, notes
