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
    """T₁, T₂ and τ with coefficient μ; None where a differential brake locks itself (b ≤ a·e^{μθ})."""
    growth = math.expm1(mu * band.wrap)  # e^{μθ} − 1, its digits kept for a small μθ
    ratio = 1.0 + growth
    if band.tension is not None:
        slack = band.tension
    elif band.tight_arm is None:
        slack = band.force * band.lever / band.slack_arm
    elif band.slack_arm is None:
        tight = band.force * band.lever / band.tight_arm
        return BandForces(tight, tight / ratio, tight * (-math.expm1(-mu * band.wrap)) * radius)
    else:
        margin = band.slack_arm - ratio * band.tight_arm
        if margin <= 0:
            return None
        slack = band.force * band.lever / margin
    return BandForces(ratio * slack, slack, slack * growth * radius)


def band_torques(band: Band, radius: float) -> tuple[BandForces, float, list[Step], list[str]]:
    """The band sliding (kinetic μ: its forces) and holding (static μ: the most torque it holds;
    infinite where it locks itself), with the steps and notes."""
    sliding = band_forces(band, band.mu_k, radius)
    name = band.source.replace("{", "").replace("}", "")
    if sliding is None:
        raise InputError(band.source, "locks itself: with slack-arm= b ≤ tight-arm= a × e^(μθ) the tight end's pull alone holds the lever down, "
                         "so the torque is not set by force= (make slack-arm= longer)",
                         example=EXAMPLE, got=f"b = {fmt(band.slack_arm)} m, a·e^(μθ) = {fmt(band.tight_arm * math.exp(band.mu_k * band.wrap))} m")
    notes: list[str] = []
    mu_s = band.mu_s if band.mu_s is not None else band.mu_k
    holding = band_forces(band, mu_s, radius)
    static = math.inf if holding is None else holding.torque
    if holding is None:
        notes.append(f"{band.source}: at rest it locks itself (b ≤ a·e^(μs·θ)): it holds the drum against any torque")
    ratio_text = f"e^({fmt(band.mu_k)} × {term(band.wrap, 'rad')})"
    steps = [Step(f"Tension ratio of the {name}", "T₁/T₂ = e^(μθ)", ratio_text, fmt(sliding.tight / sliding.slack),
                  "belt friction: each element of the band, sliding over the drum, adds μ times its pressure to the tension (the capstan equation)")]
    if band.tension is not None:
        steps.append(Step(f"Tensions of the {name}", "T₂ = tension given;  T₁ = T₂·e^(μθ)", f"{term(sliding.slack, 'N')} × {fmt(sliding.tight / sliding.slack)}",
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
            equation = "F·ℓ = T₂·b − T₁·a = T₂·(b − a·e^(μθ))  →  T₂ = F·ℓ/(b − a·e^(μθ))"
            numbers = f"{force} × {lever} / ({term(band.slack_arm, 'm')} − {term(band.tight_arm, 'm')} × {fmt(sliding.tight / sliding.slack)})"
            why = "moments about the lever's pivot of a differential band brake: the tight end's pull, on the other side, helps the force"
        steps.append(Step(f"Tensions of the {name} from the lever", equation, numbers,
                          f"T₁ = {quantity_text(sliding.tight, 'N')}, T₂ = {quantity_text(sliding.slack, 'N')}", why))
    steps.append(Step(f"Braking torque of the {name}", "τ = (T₁ − T₂)·r", f"({term(sliding.tight, 'N')} − {term(sliding.slack, 'N')}) × {term(radius, 'm')}",
                      quantity_text(sliding.torque, "N*m"), "the band's two ends pull the drum's rim opposite ways, the tight end harder"))
    if band.width is not None:
        steps.append(Step(f"Largest lining pressure of the {name}", "p_max = T₁/(r·w)", f"{term(sliding.tight, 'N')} / ({term(radius, 'm')} × {term(band.width, 'm')})",
                          quantity_text(sliding.tight / (radius * band.width), "Pa"),
                          "a band under tension T presses the drum with T/r per unit length of rim; at the tight end T = T₁"))
    return sliding, static, steps, notes
