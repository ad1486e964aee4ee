"""A spinning body set down in a corner (--corner μ): it rubs on the floor and on the wall.

Set down spinning so that the floor's friction pushes it into the wall (the usual problem), the
body's centre does not move: the wall's push N₂ balances the floor's friction μN₁, and the floor's
push with the wall's friction (upward, the way the rim slides past it) balances the weight:

    N₂ = μN₁,   N₁ + μN₂ = mg   ⇒   N₁ = mg/(1 + μ²),   N₂ = μmg/(1 + μ²)

and both frictions act at the rim against the spin: τ = μ(N₁ + N₂)R = μmgR(1 + μ)/(1 + μ²),
a constant friction torque (with the same μ at floor and wall).
"""

from __future__ import annotations

from taucli.core.errors import InputError
from taucli.writing.report import Step, fmt, quantity_text


def corner_torque(mass: float | None, radius: float | None, mu: float, g: float, results, steps: list[Step]) -> float:
    """The friction torque of the floor and the wall, with N₁ and N₂ put in ``results``."""
    if mass is None:
        raise InputError("corner", "needs the body's mass: its weight presses it on the floor", example="{shape} disc {mass} 2kg {radius} 0.1m {corner} 0.3")
    if radius is None:
        raise InputError("corner", "needs the body's radius: the floor and the wall touch its rim", example="{shape} disc {mass} 2kg {radius} 0.1m {corner} 0.3")
    weight = mass * g
    floor = weight / (1 + mu * mu)
    wall = mu * floor
    torque = mu * (floor + wall) * radius
    results.put("normal_floor", floor)
    results.put("normal_wall", wall)
    steps.append(Step("Forces in the corner", "N₁ = mg/(1 + μ²),  N₂ = μN₁", f"{quantity_text(weight, 'N')} / (1 + {fmt(mu)}²)",
                      f"N₁ = {quantity_text(floor, 'N')}, N₂ = {quantity_text(wall, 'N')}",
                      "the centre stays put: the wall's push balances the floor's friction, and the floor's push with the wall's friction "
                      "(up, the way the rim slides past it) carries the weight"))
    steps.append(Step("Friction torque of the floor and the wall", "τ_f = μ(N₁ + N₂)R", f"{fmt(mu)} × ({quantity_text(floor, 'N')} + {quantity_text(wall, 'N')}) × {quantity_text(radius, 'm')}",
                      quantity_text(torque, "N*m"), "both frictions act at the rim, against the spin"))
    return torque
