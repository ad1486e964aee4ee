"""What the impulse models share: the brief blow, the plot's curves, L and KE before and after."""

from __future__ import annotations

from taucli.options.table import Results

BRIEF_BLOW = 0.1  # s: a blow this short is remembered by its impulse alone
CURVES = (("torque", "N*m", "torque τ"), ("omega", "rad/s", "angular velocity ω"))  # what a plot of the impulse shows


def put_momentum(results: Results, inertia: float | None, omega0: float | None, omega1: float | None) -> None:
    """L = Iω and KE = ½Iω² before (ω₀) and after (ω₁), each where I and that ω are known (else null)."""
    known0 = inertia is not None and omega0 is not None
    known1 = inertia is not None and omega1 is not None
    results.put("L0", inertia * omega0 if known0 else None)
    results.put("L1", inertia * omega1 if known1 else None)
    results.put("KE0", 0.5 * inertia * omega0 * omega0 if known0 else None)
    results.put("KE1", 0.5 * inertia * omega1 * omega1 if known1 else None)
