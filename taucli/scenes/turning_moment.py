"""The energy a flywheel must give and take, from a turning-moment diagram's loops.

A turning-moment diagram plots the engine's torque T against the crank angle θ over a cycle;
the mean torque is a horizontal line across it, and the loops between the curve and that line
are the energy the flywheel takes (above the line: the engine gives more than the load takes)
and gives back (below). Taken in order, their areas a₁, a₂, … (signed: + above, − below), times
the diagram's scales (torque per mm × angle per mm, in radians), are the changes of the
flywheel's energy; its energy at the end of each loop is E + Σ aᵢ. The maximum fluctuation of
energy is the greatest of those less the least:

    ΔE = max_k Σᵢ≤ₖ aᵢ − min_k Σᵢ≤ₖ aᵢ      (k = 0 … n, the empty sum 0 among them)

Over a whole cycle the loops balance (Σ aᵢ = 0); where the areas given do not, a note says so.
"""

from __future__ import annotations

import math

from taucli.core.errors import InputError
from taucli.writing.report import Step, fmt, quantity_text

LOOPS_EXAMPLE = "{loops} '295,-685,40,-340,960,-270' {scale_torque} '5N*m' {scale_angle} 1deg"


def read_loops(text: str) -> list[float]:
    """The signed areas, in mm² of the diagram: numbers separated by commas or spaces."""
    items = [item for item in str(text).replace(",", " ").split() if item]
    try:
        areas = [float(item) for item in items]
    except ValueError:
        areas = []
    if not areas or not all(math.isfinite(a) for a in areas):
        raise InputError("loops", "expected the loops' areas in order, in mm² of the diagram, + above the mean torque line and − below",
                         example=LOOPS_EXAMPLE, got=repr(text))
    return areas


def swing_from_loops(areas: list[float], scale_torque: float | None, scale_angle: float | None, steps: list[Step], notes: list[str]) -> float:
    """ΔE from the loops and the diagram's scales (torque per mm, angle per mm)."""
    if scale_torque is None or scale_angle is None:
        raise InputError("scale_torque" if scale_torque is None else "scale_angle",
                         "is required with {loops}: the diagram's scales turn its areas into energy (torque per mm × angle per mm)", example=LOOPS_EXAMPLE)
    per_area = scale_torque * scale_angle  # J per mm² (the angle in radians)
    energies = [math.fsum(areas[:k]) * per_area for k in range(len(areas) + 1)]
    highest, lowest = max(energies), min(energies)
    swing = highest - lowest
    closing = energies[-1]
    if abs(closing) > 1e-9 * math.fsum(abs(a) for a in areas) * per_area:
        notes.append(f"--loops add to {fmt(math.fsum(areas))} mm², not 0: over a cycle the areas above and below the mean torque line balance; "
                     "ΔE is taken from the energies at the loops' ends as given")
    at = lambda value: energies.index(value)  # noqa: E731
    steps.append(Step("Energy of one mm² of the diagram", "e = (torque per mm) × (angle per mm)",
                      f"{quantity_text(scale_torque, 'N*m')} × {fmt(scale_angle)} rad", quantity_text(per_area, "J"),
                      "an area under a torque–angle curve is work: ∫T dθ"))
    steps.append(Step("The flywheel's energy at the end of each loop", "E + Σ aᵢ e",
                      ", ".join(("E" if value == 0 else f"E {'+' if value > 0 else '−'} {fmt(abs(value / per_area))}e") for value in energies),
                      f"greatest at the end of loop {at(highest)}, least at the end of loop {at(lowest)}" if at(highest) and at(lowest) else
                      f"greatest {'at the start' if not at(highest) else f'at the end of loop {at(highest)}'}, least "
                      f"{'at the start' if not at(lowest) else f'at the end of loop {at(lowest)}'}",
                      "the loops above the mean line speed the flywheel up, those below slow it down"))
    steps.append(Step("Maximum fluctuation of energy", "ΔE = E_max − E_min", f"({fmt((highest - lowest) / per_area)} mm²) × {quantity_text(per_area, 'J')}",
                      quantity_text(swing, "J"), "between its greatest and least energy the flywheel goes from its top to its least speed"))
    return swing
