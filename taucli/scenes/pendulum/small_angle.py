"""The small-angle model: sin θ ≈ θ at any amplitude, so I θ'' = −(mgd + κ)θ, harmonic with
Ω = √((mgd + κ)/I) (harmonic.py); and its period's error, stated in a note: under gravity its
period is short of the exact one by about θ₀²/16.
"""

from __future__ import annotations

import math

from taucli.writing.report import fmt
from taucli.scenes.pendulum.by_energy import ByEnergy
from taucli.scenes.pendulum.exact import Libration
from taucli.scenes.pendulum.harmonic import Harmonic
from taucli.scenes.pendulum.swing import Swing


def small_angle_model(swing: Swing) -> Harmonic:
    """θ = θ₀ cos Ωt + (ω₀/Ω) sin Ωt, Ω = √((mgd + κ)/I)."""
    return Harmonic(math.sqrt((swing.gravity_torque + swing.torsion) / swing.inertia), swing.theta0, swing.omega0)


def small_angle_note(swing: Swing, exact) -> str:
    """The note on the small-angle model under gravity: how far its period T₀ is short of the
    exact T at this amplitude, 1 − T₀/T (against θ₀²/16); with a spring too, how it grows; over
    the top, that it means nothing there."""
    if isinstance(exact, Libration):  # gravity alone (with a spring too there is no exact model)
        short = 1 - swing.small_period() / exact.period
        return (
            f"small-angle model (sin θ ≈ θ): at an amplitude of {fmt(math.degrees(exact.amplitude))}° its period is "
            f"{fmt(100 * short, 3)}% short of the exact {fmt(exact.period, 6)} s (about θ₀²/16 = {fmt(100 * exact.amplitude**2 / 16, 3)}%)"
        )
    if isinstance(exact, ByEnergy) and exact.period:  # a spring too: the exact period is the energy integral's (#42 item 12: at rest, not "over the top")
        off = 1 - swing.small_period() / exact.period
        return (
            f"small-angle model (sin θ ≈ θ): at an amplitude of {fmt(math.degrees(exact.amplitude))}° its period is "
            f"{fmt(100 * abs(off), 3)}% {'short of' if off >= 0 else 'longer than'} the exact {fmt(exact.period, 6)} s"
        )
    if exact is None or isinstance(exact, ByEnergy):
        return "small-angle model (sin θ ≈ θ): its error grows as about θ₀²/16 of the period (1% near 23°, 18% at 90°)"
    return "small-angle model (sin θ ≈ θ): the body goes over the top, which no small-angle swing does: its times are meaningless here"
