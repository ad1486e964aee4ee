"""``taucli atwood``: two masses on a string over a pulley. One module per model, and here the
function that reads the options, picks the model and solves it:

    pulley.py         the pulley: I from a mass and a shape, a given I or parts; axle friction
    slope.py          where each block is: hanging, on a table or a slope; the friction under it
    machine.py        the machine, the strings gripping the pulley: a, T1, T2 (solve_machine)
    statics.py        the tensions at rest: what statics fixes, and bounds where it does not
    steps.py          the machine's worked steps
    stepped.py        a stepped pulley, each string on its own step (solve_stepped)
    capstan.py        a string that may slide over the rim (solve_rim)
    fixed_drum.py     a rope over a drum that cannot turn (solve_fixed_drum)
    travel.py         the motion after --distance or at --time, and the trajectory
    pulley_point.py   --at r: a point on the pulley
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from taucli.core.errors import InputError
from taucli.writing.report import Report, fmt
from taucli.scenes.assumed import Assumed
from taucli.scenes.atwood.capstan import solve_rim
from taucli.scenes.atwood.fixed_drum import solve_fixed_drum
from taucli.scenes.atwood.hoist import Hoist, check_hoist
from taucli.scenes.atwood.machine import Machine, solve, solve_machine
from taucli.scenes.atwood.pulley import Pulley, with_parts
from taucli.scenes.atwood.pulley_point import on_the_pulley
from taucli.scenes.atwood.slope import HANGING, Slope, side_of
from taucli.scenes.atwood.stepped import solve_stepped, step_radii

__all__ = ["HANGING", "Machine", "Pulley", "Slope", "atwood", "solve", "solve_machine", "solve_rim", "solve_stepped"]


def atwood(
    *,
    m1: float | None = None,
    m2: float | None = None,
    pulley_mass: float | None = None,
    pulley_radius: float | None = None,
    pulley_shape: str | None = None,
    pulley_inertia: float | None = None,
    pulley_gyration: float | None = None,
    axle_friction: float | None = None,
    side1=None,
    side2=None,
    incline: float | None = None,
    mu_k: float | None = None,
    mu_s: float | None = None,
    pull: Sequence = (),
    torque: float | None = None,
    g: float | None = None,
    v0: float | None = None,
    distance: float | None = None,
    time: float | None = None,
    radius1: float | None = None,
    radius2: float | None = None,
    same_side: bool = False,
    rim_mu: float | None = None,
    wrap: float | None = None,
    fixed_drum: bool = False,
    part: Sequence = (),
    at: float | None = None,
    counterweight: float | None = None,
    hoist_speed: float | None = None,
    hoist_height: float | None = None,
    trip_time: float | None = None,
) -> Report:
    """``taucli atwood``: m1 and m2 hang unless --side1/--side2 (or --incline for m2) put them on a
    table or a slope; pulls on them (--pull) and a drive on the pulley (--torque); the pulley is
    massless unless given a mass (a solid disc unless --pulley-shape says) or a moment of inertia;
    a stepped pulley with --radius1/--radius2, both strings on one side with --same-side; a
    string that may slide with --rim-mu; a rope over a drum that cannot turn with --fixed-drum;
    --at r, a point on the pulley; t_stop and distance_stop with --v0; --pulley-gyration k with
    --pulley-mass M, a pulley of I = Mk²; a hoist (--counterweight, --hoist-speed, --hoist-height,
    --trip-time: hoist.py)."""
    if counterweight is not None:
        if m2 is not None:
            raise InputError("counterweight", "conflicts with {m2}: a hoist's counterweight is m2, give it once", example="{m1} 1200kg {counterweight} 950kg")
        m2 = counterweight
    hoist = Hoist(hoist_speed, hoist_height, trip_time)
    check_hoist(hoist)
    if pulley_gyration is not None:  # #42 item 15: the pulley by its radius of gyration
        given = {name: value for name, value in locals().items() if name not in ("pulley_gyration", "hoist", "counterweight")}
        return _by_gyration(given, pulley_gyration)
    if fixed_drum or rim_mu is not None:
        _refuse("does not apply with {fixed_drum}: a hoist drives a pulley that turns with its string" if fixed_drum
                else "does not apply with {rim_mu}: a hoist's string grips its drum", hoist_speed=hoist_speed, hoist_height=hoist_height)
    if fixed_drum:
        return _over_a_fixed_drum(m1, m2, g, rim_mu, mu_k, mu_s, wrap, v0, distance, time, at=at, pulley_mass=pulley_mass, pulley_radius=pulley_radius,
                                  pulley_inertia=pulley_inertia,
                                  axle_friction=axle_friction, part=part or None, radius1=radius1, radius2=radius2, same_side=same_side or None,
                                  torque=torque, side1=side1, side2=side2, incline=incline, pull=pull or None)
    if at is not None:  # the machine, then the point on its pulley (#34: every option passed on, --wrap was left out)
        machine = dict(m1=m1, m2=m2, pulley_mass=pulley_mass, pulley_radius=pulley_radius, pulley_shape=pulley_shape, pulley_inertia=pulley_inertia,
                       axle_friction=axle_friction, side1=side1, side2=side2, incline=incline, mu_k=mu_k, mu_s=mu_s, pull=pull, torque=torque, g=g,
                       radius1=radius1, radius2=radius2, same_side=same_side, rim_mu=rim_mu, wrap=wrap, part=part,
                       hoist_speed=hoist_speed, hoist_height=hoist_height, trip_time=trip_time)
        if rim_mu is not None:
            raise InputError("at", "does not apply with {rim_mu}: where the string slides the pulley's own turning is not followed in time")
        report = atwood(**machine, v0=v0, distance=distance, time=time)

        def from_rest() -> float | None:  # once the masses have stopped: held (α = 0), or the other way at the machine's α from rest
            return atwood(**machine).results["alpha"].value

        return on_the_pulley(report, at, pulley_radius, radius1, radius2, v0 or 0.0, distance, time, from_rest)

    assumed = Assumed()
    pulled = {number: [p for p in pull if p.on == number] for number in (1, 2)} if pull else {1: (), 2: ()}
    if m1 is None:
        if not pulled[1]:
            raise InputError("m1", "is required", example="{m1} 4kg", hint='or a {pull} "force=… on=1" on the string\'s end in its place')
        assumed.notes.append("no --m1: the string's end on side 1 pulled by hand (--pull), nothing hanging there")
    if m2 is None:
        if side2 is not None:
            raise InputError("side2", "needs {m2} (the block it places)", example='{m2} 1kg {side2} "table mu-k=0.2"')
        surface = next((name for name, value in (("incline", incline), ("mu_k", mu_k), ("mu_s", mu_s)) if value is not None), None)
        if surface is not None:  # #42 item 13: m2's slope or friction with no m2 was ignored
            raise InputError(surface, "needs {m2} (the block on the slope or table it describes)", example="{m2} 1kg {incline} 30deg {mu_k} 0.2")
        assumed.notes.append("no --m2: the string's end on side 2 pulled by hand (--pull)" if pulled[2] else "no --m2: a single mass on a string wound on the pulley")
    if side2 is not None and (incline is not None or mu_k is not None or mu_s is not None):
        given = next(name for name, value in (("incline", incline), ("mu_k", mu_k), ("mu_s", mu_s)) if value is not None)
        raise InputError(given, "conflicts with {side2}: give m2's surface once (--incline, --mu-k and --mu-s say what --side2 does)",
                         example='{side2} "incline angle=30deg mu-k=0.2"')
    if wrap is not None and rim_mu is None:
        raise InputError("wrap", "needs {rim_mu} (the wrap matters only where the string may slide)", example="{rim_mu} 0.3 {wrap} 180deg")
    stepped = radius1 is not None or radius2 is not None
    r1, r2 = step_radii(radius1, radius2, pulley_radius) if stepped else (None, None)
    pulley = Pulley(pulley_mass or 0.0, pulley_radius, pulley_shape, pulley_inertia, axle_friction or 0.0)
    if part:
        pulley = with_parts(pulley, part, assumed, None if not stepped else max(r1, r2))

    if rim_mu is not None:  # a string that may slide over the rim
        _refuse("does not apply with {rim_mu} here: a string that may slide is solved for two hanging masses on a pulley free on its axle",
                incline=incline, axle_friction=axle_friction, mu_k=mu_k, mu_s=mu_s, side1=side1, side2=side2, pull=pull or None, torque=torque,
                radius1=radius1, radius2=radius2, same_side=same_side or None)
        if not m1 or not m2:
            raise InputError("m1" if not m1 else "m2", "must be more than 0 with {rim_mu}: a string with nothing on one end slides off (a string wound on the pulley is fixed to it)")
        gravity = assumed.gravity(g)
        return assumed.applied(solve_rim(m1, m2, pulley, gravity, rim_mu, math.pi if wrap is None else wrap, v0=v0 or 0.0, distance=distance, time=time,
                                           stop=v0 is not None))

    # friction.py's rule under each block: neither coefficient given, a smooth surface (μk = 0); only μs, μk unknown
    if side2 is not None:
        place2, option2 = side_of(side2, "side2"), "side2"
    else:
        place2, option2 = Slope(HANGING if incline is None else incline, 0.0 if mu_k is None and mu_s is None else mu_k, mu_s), "incline"
    gravity = assumed.gravity(g)
    built = Machine(
        m1 or 0.0, m2 or 0.0, pulley, gravity, side_of(side1, "side1"), place2, _pulls(pulled[1]), _pulls(pulled[2]), torque or 0.0,
        None if not stepped else (r1, r2), same_side, ("side1", option2),
    )
    return assumed.applied(solve_machine(built, v0=v0 or 0.0, distance=distance, time=time, stop=v0 is not None, hoist=hoist))


def _over_a_fixed_drum(m1, m2, g, rim_mu, mu_k, mu_s, wrap, v0, distance, time, **others) -> Report:
    """Two hanging masses on a rope over a drum that cannot turn (fixed_drum.py): the coefficient
    from --rim-mu (static and kinetic alike) or --mu-s and --mu-k; nothing of a pulley that turns."""
    _refuse("does not apply with {fixed_drum}: the drum does not turn, and the rope's two hanging masses are the whole machine", **others)
    if rim_mu is not None and (mu_k is not None or mu_s is not None):
        raise InputError("mu_k" if mu_k is not None else "mu_s", "conflicts with {rim_mu}: give the drum's coefficient once (--rim-mu, or --mu-s and --mu-k)",
                         example="{fixed_drum} {mu_s} 0.3 {mu_k} 0.25")
    if rim_mu is None and mu_k is None and mu_s is None:
        raise InputError("fixed_drum", "needs the rope's friction on the drum: {rim_mu}, or {mu_s} and {mu_k}", example="{fixed_drum} {rim_mu} 0.2")
    if m1 is None or m2 is None:
        raise InputError("m1" if m1 is None else "m2", "is required with {fixed_drum}", example="{m1} 250kg {m2} 100kg")
    assumed = Assumed()
    gravity = assumed.gravity(g)
    kinetic, static = (rim_mu, rim_mu) if rim_mu is not None else (mu_k, mu_s)
    return assumed.applied(solve_fixed_drum(m1, m2, gravity, kinetic, static, math.pi if wrap is None else wrap, v0=v0 or 0.0, distance=distance,
                                            time=time, stop=v0 is not None))


def _pulls(pulls) -> tuple[float, float]:
    """The pulls on one block, summed: along its path away from the pulley, and lifting it off its surface."""
    if not pulls:
        return 0.0, 0.0
    along = math.fsum(p.force * (1.0 if p.angle == 0 else math.cos(p.angle)) for p in pulls)
    lift = math.fsum(p.force * math.sin(p.angle) for p in pulls)
    return along + 0.0, lift + 0.0


def _refuse(why: str, **options) -> None:
    """An InputError for the first of ``options`` given (in the order named): it does not apply, ``why``."""
    for name, value in options.items():
        if value is not None:
            raise InputError(name, why)


def _by_gyration(given: dict, gyration: float) -> Report:
    """The machine with a pulley of radius of gyration k and mass M: I = Mk² about its axle."""
    for name in ("pulley_inertia", "pulley_shape"):
        if given.get(name) is not None:
            raise InputError(name, "conflicts with {pulley_gyration}: give the pulley's I one way")
    mass = given.get("pulley_mass")
    if not mass:
        raise InputError("pulley_mass", "is required with {pulley_gyration} (I = Mk²)", example="{pulley_mass} 2kg {pulley_gyration} 0.08m")
    if given.get("pulley_radius") is None and given.get("radius1") is None and given.get("radius2") is None:
        raise InputError("pulley_radius", "is required with {pulley_gyration} (the pulley adds Mk²/R² to the moving mass)", example="{pulley_radius} 0.1m")
    inertia = mass * gyration**2
    report = atwood(**{**given, "pulley_mass": None, "pulley_inertia": inertia})
    report.notes.append(f"pulley: I = Mk² = {fmt(mass)} kg × ({fmt(gyration)} m)² = {fmt(inertia)} kg·m² (its radius of gyration)")
    return report
