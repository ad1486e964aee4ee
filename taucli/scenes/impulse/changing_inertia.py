"""A moment of inertia that changes with no external torque (the skater, the diver): I₀ω₀ = I₁ω₁.

τ = dL/dt = d(Iω)/dt, so with τ = 0 about the axis L = Iω stays constant while I changes
(τ = Iα does not hold then). The kinetic energy L²/(2I) changes: the body's own muscles do work.
"""

from __future__ import annotations

from collections.abc import Sequence

from taucli.options.impulse import COMMAND as TABLE
from taucli.writing.report import Report, Step, quantity_text, term
from taucli.options.table import Results


def solve_changing_inertia(inertia0: float, inertia1: float, omega0: float, *, inertia_steps: Sequence[Step] = (),
                           change: float | None = None) -> Report:
    """I₀ω₀ = I₁ω₁ (no external torque about the axis, L = Iω conserved while I changes):
    ω₁ = I₀ω₀/I₁; KE₁ = ½I₁ω₁² = KE₀·I₀/I₁, not conserved; the work the body does, KE₁ − KE₀.

    The changes are formed from ΔI = I₁ − I₀ (``change``: the parts that moved, where the body
    is given by parts; else I₁ − I₀ of the inputs), not as differences of near-equal totals:
    Δω = −ω₀ΔI/I₁, work = −KE₀ΔI/I₁."""
    if change is None:
        change = inertia1 - inertia0
    omega1 = inertia0 * omega0 / inertia1
    momentum = inertia0 * omega0
    energy0 = 0.5 * inertia0 * omega0 * omega0
    energy1 = 0.5 * momentum * omega1  # ½ I₁ω₁² = ½ L ω₁
    results = Results(TABLE)
    results.put("omega1", omega1, " the change")
    results.put("delta_omega", -omega0 * change / inertia1)
    results.put("J", 0.0, ": no external torque")
    results.put("L0", momentum)
    results.put("L1", inertia1 * omega1, " (the same)")
    results.put("KE0", energy0)
    results.put("KE1", energy1)
    results.put("work", -energy0 * change / inertia1)
    steps = [
        *inertia_steps,
        Step("No external torque: angular momentum is conserved", "τ = dL/dt = 0  ⇒  I₀ω₀ = I₁ω₁", "", "",
             "τ = Iα does not hold while I changes; τ = d(Iω)/dt does, and with τ = 0, Iω stays constant"),
        Step("Angular velocity after", "ω₁ = I₀ω₀ / I₁", f"{term(inertia0, 'kg*m**2')} × {term(omega0, 'rad/s')} / {term(inertia1, 'kg*m**2')}", quantity_text(omega1, "rad/s"),
             "less inertia, faster spin: the skater pulling in her arms"),
        Step("Kinetic energy is not conserved", "KE = L²/(2I)  ⇒  KE₁/KE₀ = I₀/I₁",
             f"{term(energy0, 'J')} × {term(inertia0, 'kg*m**2')} / {term(inertia1, 'kg*m**2')}", quantity_text(energy1, "J"),
             "pulling mass inward against the outward pull of the spin takes work, done by the body's own muscles; "
             "spreading out gives it back"),
    ]
    model = "changing moment of inertia, no external torque: L conserved"
    return Report("impulse", model, "closed form", results, steps, [])
