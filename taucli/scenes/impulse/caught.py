"""A collision, then a torque over a time, in one run (#34): catch a ball, then stop the arm.

Two stages, each with its own law. While the particle strikes (an instant) no external torque
acts about the axis, so L is conserved and the body with what stays on it turns at ω_c just
after (meeting.py). Then a constant torque τ acts on that whole, of inertia I₁, for Δt:
τΔt = I₁(ω₁ − ω_c) (balance.py), any two of τ, Δt, ω₁ giving the third (stop the arm in 0.3 s:
ω₁ = 0, Δt = 0.3 s, τ solved for). Since L just after the blow is L₀, J = τΔt = L₁ − L₀ still.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from taucli.core.errors import InputError
from taucli.options.impulse import COMMAND as TABLE
from taucli.writing.report import Report, Step, quantity_text
from taucli.scenes.given import Couple, Particle
from taucli.scenes.impulse.balance import solve_balance
from taucli.options.table import Results

# From the collision: what it alone decides. From the torque: the rest (J, τ, Δt, ω₁, L1, KE1).
FROM_COLLISION = ("inertia", "omega0", "L0", "KE0", "KE_lost", "KE_lost_fraction", "p0", "p1", "pivot_impulse")
FROM_TORQUE = ("J", "omega1", "torque", "duration", "L1", "KE1")


def inertia_after(inertia: float, particles: Sequence[Particle], couples: Sequence[Couple], couple_inertias: Sequence[float]) -> float:
    """I₁ of what turns together after the blow: the body, the couples, and each particle that
    stays (sticks or rides) as a point mass at its radius (after)."""
    staying = [p for p in particles if p.speed is None or (p.speed_after is None and p.e is None)]
    return math.fsum([inertia, *couple_inertias, *(p.mass * (p.radius if p.radius_after is None else p.radius_after) ** 2 for p in staying)])


def then_torque(collision: Report, inertia1: float, omega1: float | None, torque: float | None, duration: float | None,
                left: bool = False) -> Report:
    """The collision's report followed by a constant torque on I₁ from ω_c: τΔt = I₁(ω₁ − ω_c).
    A particle that ``left`` the body (it rebounds, or leaves at speed-after=) is no part of what the
    torque turns: its speed after is the collision's."""
    given = [name for name, value in (("omega1", omega1), ("torque", torque), ("duration", duration)) if value is not None]
    example = '{particle} "mass=0.4kg speed=20m/s radius=0.6m" {omega1} 0 {duration} 0.3s'
    if len(given) < 2:
        others = " or ".join(f"{{{name}}}" for name in ("torque", "duration", "omega1") if name not in given)
        raise InputError(given[0], f"needs {others} after the collision: two of {{torque}}, {{duration}}, {{omega1}} give the third", example=example)
    if len(given) > 2:
        raise InputError("omega1", "conflicts with {torque} and {duration} after the collision: two of them give the third; leave out the one to solve for",
                         example=example)
    impact = collision.results["omega1"].value
    stage = solve_balance(inertia1, impact, omega1, torque, duration)
    results = Results(TABLE)
    results.put("omega_impact", impact, " (the body and what stays on it)")
    for key in (*FROM_COLLISION, "speed_after") if left else FROM_COLLISION:
        if key in collision.results:
            results[key] = collision.results[key]
    for key in FROM_TORQUE:
        if key in stage.results:
            value = stage.results[key]
            results[key] = value
    w0 = collision.results["omega0"].value
    if omega1 is None and "delta_omega" in collision.results and "delta_omega" in stage.results:
        # the collision's change and the torque's τΔt/I₁, each from its exchange, not ω₁ − ω₀ of the totals (#42 item 8)
        results.put("delta_omega", collision.results["delta_omega"].value + stage.results["delta_omega"].value)
    else:
        results.put("delta_omega", stage.results["omega1"].value - w0)
    steps = [*collision.steps,
             Step("Then the torque acts on all that turns together", "I₁ = I + Σ m ρ² (+ Σ I_c)", "", quantity_text(inertia1, "kg*m**2"),
                  "what stays on the body after the blow turns with it, and the torque must turn it all"),
             *stage.steps]
    notes = [*collision.notes, *(note for note in stage.notes if "no --omega0" not in note),
             f"omega1, torque, duration, J, L1 and KE1 are of the torque after the collision, on I₁ = {quantity_text(inertia1, 'kg*m**2')} "
             f"from ω = {quantity_text(impact, 'rad/s')}; KE_lost is the collision's"]
    model = f"{collision.model}; then a constant torque over Δt on the body and what stays on it: τΔt = I₁(ω₁ − ω_c)"
    return Report("impulse", model, "closed form", results, steps, notes, {}, collision.tables)
