"""How far the swing reaches: the turning angle, the rise of the centre of mass, KE at the bottom.

Energy is conserved, ½Iω² + U(θ) = ½Iω₀² + U(θ₀), U(θ) = mgd(1 − cos θ) + ½κθ², so the body
turns (ω = 0) at the first angle θₐ along its motion where U(θₐ) = E:

- gravity alone, swinging: sin(θₐ/2) = ±k, k² = sin²(θ₀/2) + Iω₀²/(4mgd) (the exact model's
  amplitude, from k and k' = cos(θₐ/2)); from rest it turns at −θ₀;
- a spring alone: θₐ = ±√(θ₀² + Iω₀²/κ);
- both: the turning angle ahead, found by the energy model (by_energy.py);
- with the energy to pass the top (gravity alone) it never turns; with just that energy it
  creeps up to the top (±180°) and takes forever to get there.

The centre of mass rises h = d(cos θ₀ − cos θₐ) from the start: under gravity alone all the
kinetic energy goes into it, h = Iω₀²/(2mgd)·d, written so (no difference of near cosines);
with a spring, 2d sin((θ₀ + θₐ)/2) sin((θₐ − θ₀)/2). KE at the bottom is ½Iω_b².
"""

from __future__ import annotations

import math

from taucli.scenes.pendulum.by_energy import ByEnergy
from taucli.scenes.pendulum.exact import Circulation, Libration, Separatrix
from taucli.scenes.pendulum.harmonic import Harmonic
from taucli.scenes.pendulum.swing import Swing
from taucli.scenes.pendulum.zero import Zero
from taucli.options.table import Results


def _sense(swing: Swing) -> float:
    """+1 or −1, the way the body sets off (from rest: the way α pushes it); 0 at rest where nothing turns it."""
    if swing.omega0:
        return math.copysign(1.0, swing.omega0)
    alpha = swing.accel(swing.theta0)
    return math.copysign(1.0, alpha) if alpha else 0.0


def turning_angle(swing: Swing, exact) -> float | None:
    """θₐ, the first angle along the motion where ω = 0 (from the bottom); None where it goes over the top."""
    sense = _sense(swing)
    if sense == 0:
        return swing.theta0  # at rest where nothing turns it: it stays
    if isinstance(exact, Circulation):
        return None
    if isinstance(exact, Separatrix):
        return swing.theta0 if exact.balanced else math.copysign(math.pi, sense)
    if swing.omega0 == 0 and swing.torsion == 0:
        return -swing.theta0  # gravity alone is even in θ: from rest it turns at the mirror angle
    if isinstance(exact, ByEnergy):
        return exact.ahead
    if isinstance(exact, (Libration, Harmonic)):
        return sense * exact.amplitude
    return None


def put_reach(results: Results, notes: list[str], swing: Swing, cm_distance: float, exact, zero: Zero) -> None:
    """amplitude (in the user's angles), rise (under gravity) and KE_bottom, with a note where one is missing."""
    theta_a = turning_angle(swing, exact)
    results.put("amplitude", zero.outward(theta_a), ", from the top" if zero.top else "")
    if theta_a is None:
        notes.append("amplitude, rise: none: it goes over the top and never turns")
    elif isinstance(exact, Separatrix) and not exact.balanced:
        notes.append("amplitude: it has just the energy to reach the top, and creeps up to it forever")
    if swing.gravity_torque:
        if theta_a is None:
            rise = None
        elif swing.torsion == 0:
            rise = swing.inertia * swing.omega0 * swing.omega0 * cm_distance / (2 * swing.gravity_torque)
        else:
            rise = 2 * cm_distance * math.sin((swing.theta0 + theta_a) / 2) * math.sin((theta_a - swing.theta0) / 2)
        results.put("rise", rise)
    speed = results["omega_bottom"].value  # None where a top it cannot pass lies between
    results.put("KE_bottom", None if speed is None else swing.inertia * speed * speed / 2)
