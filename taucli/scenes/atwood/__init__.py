"""``taucli atwood``: two masses on a string over a pulley. One module per model, and here the
function that reads the options, picks the model and solves it:

    pulley.py         the pulley: I from a mass and a shape, a given I or parts; axle friction
    slope.py          where m2 is: hanging, on a table or a slope; the friction under it
    machine.py        the machine, the string gripping the pulley: a, T1, T2, statics (solve)
    steps.py          the machine's worked steps
    stepped.py        a stepped pulley, each string on its own step (solve_stepped)
    capstan.py        a string that may slide over the rim (solve_rim)
    travel.py         the motion after --distance or at --time, and the trajectory
    pulley_point.py   --at r: a point on the pulley
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from taucli.errors import InputError
from taucli.report import Report
from taucli.scenes.assumed import Assumed
from taucli.scenes.atwood.capstan import solve_rim
from taucli.scenes.atwood.machine import solve
from taucli.scenes.atwood.pulley import Pulley, with_parts
from taucli.scenes.atwood.pulley_point import on_the_pulley
from taucli.scenes.atwood.slope import HANGING, Slope
from taucli.scenes.atwood.stepped import solve_stepped, step_radii

__all__ = ["HANGING", "Pulley", "Slope", "atwood", "solve", "solve_rim", "solve_stepped"]


def atwood(
    *,
    m1: float | None = None,
    m2: float | None = None,
    pulley_mass: float | None = None,
    pulley_radius: float | None = None,
    pulley_shape: str | None = None,
    pulley_inertia: float | None = None,
    axle_friction: float | None = None,
    incline: float | None = None,
    mu_k: float | None = None,
    mu_s: float | None = None,
    g: float | None = None,
    v0: float | None = None,
    distance: float | None = None,
    time: float | None = None,
    radius1: float | None = None,
    radius2: float | None = None,
    rim_mu: float | None = None,
    wrap: float | None = None,
    part: Sequence = (),
    at: float | None = None,
) -> Report:
    """``taucli atwood``: m2 hangs unless --incline puts it on a slope; the pulley is massless
    unless given a mass (a solid disc unless --pulley-shape says) or a moment of inertia; a
    stepped pulley with --radius1/--radius2; a string that may slide with --rim-mu; --at r, a
    point on the pulley."""
    if at is not None:  # the machine, then the point on its pulley
        if rim_mu is not None:
            raise InputError("at", "does not apply with {rim_mu}: where the string slides the pulley's own turning is not followed in time")
        machine = dict(m1=m1, m2=m2, pulley_mass=pulley_mass, pulley_radius=pulley_radius, pulley_shape=pulley_shape, pulley_inertia=pulley_inertia,
                       axle_friction=axle_friction, incline=incline, mu_k=mu_k, mu_s=mu_s, g=g, radius1=radius1, radius2=radius2, part=part)
        report = atwood(**machine, v0=v0, distance=distance, time=time)

        def from_rest() -> float | None:  # once the masses have stopped: held (α = 0), or the other way at the machine's α from rest
            return atwood(**machine).results["alpha"].value

        return on_the_pulley(report, at, pulley_radius, radius1, radius2, v0 or 0.0, distance, time, from_rest)

    if m1 is None:
        raise InputError("m1", "is required", example="{m1} 4kg")
    assumed = Assumed()
    if m2 is None:
        assumed.notes.append("no --m2: a single mass on a string wound on the pulley")
    pulley = Pulley(pulley_mass or 0.0, pulley_radius, pulley_shape, pulley_inertia, axle_friction or 0.0)
    if part:
        pulley = with_parts(pulley, part, assumed)
    if wrap is not None and rim_mu is None:
        raise InputError("wrap", "needs {rim_mu} (the wrap matters only where the string may slide)", example="{rim_mu} 0.3 {wrap} 180deg")

    if radius1 is not None or radius2 is not None:  # a stepped pulley
        r1, r2 = step_radii(radius1, radius2, pulley_radius)
        _refuse("does not apply with a stepped pulley ({radius1}, {radius2}): both masses hang, their strings fixed to their steps",
                incline=incline, rim_mu=rim_mu, mu_k=mu_k, mu_s=mu_s)
        gravity = assumed.gravity(g)
        return assumed.applied(solve_stepped(m1, m2 or 0.0, pulley, gravity, r1, r2, v0=v0 or 0.0, distance=distance, time=time))

    if rim_mu is not None:  # a string that may slide over the rim
        _refuse("does not apply with {rim_mu} here: a string that may slide is solved for two hanging masses on a pulley free on its axle",
                incline=incline, axle_friction=axle_friction, mu_k=mu_k, mu_s=mu_s)
        if not m1 or not m2:
            raise InputError("m1" if not m1 else "m2", "must be more than 0 with {rim_mu}: a string with nothing on one end slides off (a string wound on the pulley is fixed to it)")
        gravity = assumed.gravity(g)
        return assumed.applied(solve_rim(m1, m2, pulley, gravity, rim_mu, math.pi if wrap is None else wrap, v0=v0 or 0.0, distance=distance, time=time))

    # the machine. friction.py's rule: neither coefficient given, a smooth surface (μk = 0); only μs, μk unknown
    slope = Slope(HANGING if incline is None else incline, 0.0 if mu_k is None and mu_s is None else mu_k, mu_s)
    gravity = assumed.gravity(g)
    return assumed.applied(solve(m1, m2 or 0.0, pulley, gravity, slope=slope, v0=v0 or 0.0, distance=distance, time=time))


def _refuse(why: str, **options: float | None) -> None:
    """An InputError for the first of ``options`` given (in the order named): it does not apply, ``why``."""
    for name, value in options.items():
        if value is not None:
            raise InputError(name, why)
