"""A stepped pulley: two radii on one axle, each mass's string wound on its own step (on opposite
sides, or both on one side with --same-side). One unknown, the pulley's rotation α; each mass
moves at its own step's rim speed. The machine's equations are machine.py's, with r1 ≠ r2.
"""

from __future__ import annotations

from taucli.core.errors import InputError
from taucli.writing.report import Report
from taucli.scenes.atwood.machine import Machine, solve_machine
from taucli.scenes.atwood.pulley import Pulley


def step_radii(radius1: float | None, radius2: float | None, pulley_radius: float | None) -> tuple[float, float]:
    """r1 and r2, the radii the strings are wound at: --radius1 and --radius2, either one not
    given taken from --pulley-radius."""
    r1 = radius1 if radius1 is not None else pulley_radius
    r2 = radius2 if radius2 is not None else pulley_radius
    if r1 is None or r2 is None:
        missing = "radius1" if r1 is None else "radius2"
        raise InputError(missing, "is required with {" + ("radius2" if missing == "radius1" else "radius1") + "} (or {pulley_radius} for it)", example=f"{{{missing}}} 0.1m")
    return r1, r2


def solve_stepped(
    m1: float, m2: float, pulley: Pulley, g: float, r1: float, r2: float, *, v0: float = 0.0, distance: float | None = None, time: float | None = None
) -> Report:
    """A stepped pulley: m1's string wound at r1, m2's at r2 on the other side; one pulley of
    inertia I, its rotation α the one unknown (m1 down and the pulley turning positive):

        m1:      m1 g − T1 = m1 a1,     a1 = α r1
        m2:      T2 − m2 g = m2 a2,     a2 = α r2   (m2 up positive)
        pulley:  T1 r1 − T2 r2 − τ_a·sgn ω = I α

    so α = (m1 g r1 − m2 g r2 − τ_a)/(I + m1 r1² + m2 r2²). In m1's coordinate (÷ r1): the
    machine with m2 → m2 ρ², ρ = r2/r1, a drive g(m1 − m2 ρ), axle friction τ_a/r1.
    """
    return solve_machine(Machine(m1, m2, pulley, g, radii=(r1, r2)), v0=v0, distance=distance, time=time)
