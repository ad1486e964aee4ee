"""The Atwood machine: two blocks on a string whose ends are wound on (or pass over) a pulley
that has mass, axle friction and perhaps a drive; the string grips the pulley.

Each block hangs, lies on a table or on its own incline (the pulley at the top); a constant pull
may act on either. Positive is m1 moving away from the pulley (down, hanging), the pulley
turning with it; m2 then moves towards the pulley (up), or, with its string wound on m1's side
(``same_side``), away from it too. One equation per body, G the pull of gravity and of the pulls
along each block's path away from the pulley, N the surface's push, s the sense of motion:

    m1:      G1 − T1 − μk1 N1 s = m1 a,          G1 = m1 g sin θ1 + P1 cos φ1
    m2:      T2 − G2 − μk2 N2 s σ = m2 a2,        G2 = m2 g sin θ2 + P2 cos φ2,  a2 = ρ a
    pulley:  T1 r1 − σ T2 r2 − τd − τa s = I α,   α = a / r1

with ρ = σ r2/r1 (σ = +1 on opposite sides, −1 on the same side; r1 = r2 = R but on a stepped
pulley), N = m g cos θ − P sin φ, τd the drive (positive lifting m1), τa the axle friction.
m1's equation, ρ times m2's and the pulley's over r1 add to one along the string:

    (m1 + m2 ρ² + I/r1²) a = G1 − ρ G2 − τd/r1 − s (μk1 N1 + |ρ| μk2 N2 + τa/r1)

a constant drive against constant Coulomb friction: motion.evolve's stops, static friction
holding and a second phase the other way. Each string can only pull: a tension the equations
make negative is a slack string, which is not modelled (refused, saying which).
"""

from __future__ import annotations

import math
from typing import NamedTuple

from taucli.core.errors import InputError
from taucli.numerics.exact import product_difference, product_terms
from taucli.options.atwood import COMMAND as TABLE
from taucli.writing.report import DeferredSteps, Report, deferred, fmt, quantity_text
from taucli.scenes.atwood.hoist import Hoist, put_hoist, put_work_brake
from taucli.scenes.atwood.pulley import DISC_NOTE, Pulley, check_pulley
from taucli.scenes.atwood.slope import HANGING, Slope, check_slope, side_static
from taucli.scenes.atwood.statics import held_tensions
from taucli.scenes.atwood.steps import general_steps, machine_steps, stepped_steps
from taucli.scenes.atwood.travel import evolve_exact, put_motion, trajectory
from taucli.scenes.friction import needs_kinetic
from taucli.scenes.motion import Loads, start_direction, start_rate
from taucli.options.table import Results

EPSILON = 2.0**-52


class Machine(NamedTuple):
    """The machine: the blocks, where each is, the pulls on them, the pulley and its drive."""
    m1: float
    m2: float
    pulley: Pulley
    g: float
    side1: Slope = Slope()
    side2: Slope = Slope()
    pull1: tuple[float, float] = (0.0, 0.0)  # the pulls on m1: (along its path away from the pulley, lifting it off its surface)
    pull2: tuple[float, float] = (0.0, 0.0)
    torque: float = 0.0  # a drive on the pulley, positive lifting m1
    radii: tuple[float, float] | None = None  # a stepped pulley's (r1, r2); None: both strings at the pulley's radius
    same_side: bool = False
    options: tuple[str, str] = ("side1", "incline")  # the options that placed each block, for messages
    kind: str = ""  # CLASSIC, STEPPED or GENERAL: solve_machine sorts it once (its steps and its last-bit forms)

    @property
    def pulled(self) -> bool:
        return self.pull1 != (0.0, 0.0) or self.pull2 != (0.0, 0.0)


CLASSIC, STEPPED, GENERAL = "classic", "stepped", "general"


def _kind(machine: Machine, side1: Slope, side2: Slope) -> str:
    """CLASSIC: m1 hangs on the far side of one radius from m2, nothing pulls, nothing drives (the
    article's machine and its modified one, m2 on a table or a slope); STEPPED: both hang on a
    stepped pulley, on opposite sides, nothing pulls or drives; GENERAL: the rest."""
    plain = side1.angle == HANGING and machine.pull1 == (0.0, 0.0) and machine.pull2 == (0.0, 0.0) and not machine.torque and not machine.same_side
    if plain and machine.radii is None:
        return CLASSIC
    if plain and side2.angle == HANGING:
        return STEPPED
    return GENERAL


class Forces(NamedTuple):
    """The machine reduced to the string's one coordinate (m1's displacement): what drives it,
    what friction resists, and each block's share, for the tensions."""
    mass1: float
    mass2: float
    r1: float | None  # the radius m1's string leaves at (None: not given, where nothing needs it)
    rho: float  # a2/a: r2/r1, negative where m2 is on m1's side
    added_mass: float  # I/r1²
    along1: float  # G1
    along2: float  # G2
    normal1: float
    normal2: float
    drive_force: float  # τd/r1
    axle_force: float  # τa/r1
    inertia: float | None = None  # a stepped pulley's I

    @property
    def moving_mass(self) -> float:
        return self.mass1 + self.mass2 * self.rho * self.rho + self.added_mass


def forces(machine: Machine, notes: list[str]) -> Forces:
    """The machine's forces along the string, checked: something to move, the pulley described
    once, a radius where a torque or a given I reaches the string through it, a block left on
    its surface by the pull on it."""
    m1, m2, pulley, g = machine.m1, machine.m2, machine.pulley, machine.g
    stepped = machine.radii is not None
    check_pulley(m1, m2, pulley, radius_needed=not stepped)
    if machine.torque and not stepped and pulley.radius is None:
        raise InputError("pulley_radius", "is required with {torque} (the drive acts on the string as τ/R)", example="{pulley_radius} 0.1m")
    if pulley.mass and pulley.shape is None and pulley.inertia is None:
        notes.append(DISC_NOTE)
    if stepped:
        r1, r2 = machine.radii
        if pulley.inertia is not None:
            inertia = pulley.inertia
        else:
            rim = pulley.radius if pulley.radius is not None else max(r1, r2)
            if pulley.mass and pulley.radius is None:
                notes.append(f"no --pulley-radius: the pulley's mass taken out to the larger step, R = {fmt(rim)} m; --pulley-radius or --pulley-inertia to change it")
            inertia = Pulley.SHAPE_FACTORS[pulley.shape or "disc"] * pulley.mass * rim * rim
        ratio, added_mass = r2 / r1, inertia / (r1 * r1)
    else:
        r1, ratio, added_mass, inertia = pulley.radius, 1.0, pulley.effective_mass(), None
    rho = -ratio if machine.same_side else ratio
    normal1 = _normal(machine.side1, m1, g, machine.pull1[1], "1")
    normal2 = _normal(machine.side2, m2, g, machine.pull2[1], "2")
    along1 = m1 * g * machine.side1.sin_angle + machine.pull1[0]
    along2 = m2 * g * machine.side2.sin_angle + machine.pull2[0]
    drive_force = machine.torque / r1 if machine.torque else 0.0
    axle_force = pulley.axle_friction / r1 if pulley.axle_friction else 0.0
    found = Forces(m1, m2, r1, rho, added_mass, along1, along2, normal1, normal2, drive_force, axle_force, inertia)
    if not found.moving_mass > 0:
        raise InputError("m1", "and {m2} cannot both be zero with a pulley of no inertia: nothing is there to move "
                         "(a pull or a drive would set a massless string going without bound)", example="{m1} 4kg {m2} 1kg")
    return found


def _normal(side: Slope, mass: float, g: float, lift: float, number: str) -> float:
    """N = m g cos θ − P sin φ: the surface's push (hanging: none, and no pull off the vertical)."""
    if side.hanging:
        if lift:
            raise InputError("pull", f"on m{number}: a hanging block is pulled along its string (angle= 0); pulled aside it would swing",
                             example='{pull} "force=20N on=' + number + '"')
        return 0.0
    normal = side.normal(mass, g) - lift
    if normal < 0:
        raise InputError("pull", f"on m{number} lifts it off its surface: its lift P sin φ = {fmt(lift)} N is more than m g cos θ = "
                         f"{fmt(side.normal(mass, g))} N (a block that leaves its surface is not modelled)")
    return normal


def solve(
    m1: float,
    m2: float,
    pulley: Pulley,
    g: float,
    *,
    slope: Slope = Slope(),
    v0: float = 0.0,
    distance: float | None = None,
    time: float | None = None,
) -> Report:
    """The article's machine, and m2 on a table or a slope: ``solve_machine`` of those."""
    return solve_machine(Machine(m1, m2, pulley, g, side2=slope), v0=v0, distance=distance, time=time)


def solve_machine(
    machine: Machine, *, v0: float = 0.0, distance: float | None = None, time: float | None = None, stop: bool = False,
    hoist: Hoist = Hoist(),
) -> Report:
    """Acceleration, tensions and the motion that follows, for the machine described (``stop``:
    report when the masses first stop, t_stop and distance_stop); a hoist's drive and the energy
    its brake takes (hoist.py)."""
    notes: list[str] = []
    side1, side2 = _hung(machine.side1, machine.options[0], "1", notes), _hung(machine.side2, machine.options[1], "2", notes)
    m1, m2, pulley, g, _, _, *others, _ = machine  # (made anew, not _replace'd: a third of the cost, on every batch line)
    machine = Machine(m1, m2, pulley, g, side1, side2, *others, _kind(machine, side1, side2))
    f = forces(machine, notes)
    mu_s1 = side_static(side1, machine.options[0], notes) or 0.0
    mu_s2 = side_static(side2, machine.options[1], notes) or 0.0
    mu_k1, mu_k2 = side1.mu_k or 0.0, side2.mu_k or 0.0  # placeholders where μk is not given: the motion then goes unreported
    moving_mass = f.moving_mass
    if f.added_mass and not machine.radii:
        notes.append("the string taken not to slip on the pulley (a = αR): friction at the rim turns it")
    elif f.added_mass:
        notes.append("the strings taken not to slip on their steps (a1 = α r1, a2 = α r2)")

    spread = abs(f.rho)
    loads = Loads(
        drive=_drive(machine, f),
        friction=mu_k1 * f.normal1 + spread * mu_k2 * f.normal2 + f.axle_force,
        static=mu_s1 * f.normal1 + spread * mu_s2 * f.normal2 + f.axle_force,
    )
    direction = start_direction(loads, v0)
    held = direction == 0
    a = start_rate(moving_mass, loads, v0)
    asked = distance is not None or time is not None or stop
    motion = evolve_exact(moving_mass, loads, v0) if asked else None

    results = Results(TABLE)
    results.put("a", a)
    if machine.radii is not None or machine.same_side:
        results.put("a2", f.rho * a)
    kinetic = (mu_k1 * f.normal1, mu_k2 * f.normal2)
    # it slides where the sliding friction is not known: only that it moves, and which way (so no tension to check either)
    unknown = not held and ((side1.mu_k is None and f.normal1 > 0) or (side2.mu_k is None and f.normal2 > 0))
    if held:
        tension1, tension2 = held_tensions(f, (mu_s1 * f.normal1, mu_s2 * f.normal2), notes)
        notes.append(_held_note(machine, f, loads))
    else:
        tension1, tension2 = tensions(f, kinetic, direction, machine)
        if not unknown:
            _taut(tension1, tension2, f, a, "")
    results.put("T1", tension1)
    results.put("T2", tension2)
    results.put("alpha", None if f.r1 is None else a / f.r1)
    if f.r1 is None:
        notes.append("alpha: give --pulley-radius for the pulley's angular acceleration (a and the tensions do not need it)")
    results.put("a_massless", _massless(machine, f, kinetic, loads, v0, notes))
    if motion is not None:
        if not unknown:
            _second_phase(motion, f, kinetic, machine, distance, time, notes)
        put_motion(results, motion, distance, time, [] if unknown else notes, stop=stop)  # (unknown: its values go null below, and its notes)

    sliding_known = not ((side1.mu_k is None and f.normal1 > 0) or (side2.mu_k is None and f.normal2 > 0))
    hoist_steps = put_hoist(results, notes, hoist, loads.drive + f.drive_force, loads.friction if sliding_known else None, f.r1, bool(machine.torque))
    if machine.pulley.axle_friction and (distance is not None or stop or hoist.height is not None):
        if distance is not None:
            put_work_brake(results, f.axle_force, distance if results["t"].value is not None else None, f" over {fmt(distance)} m")
        elif stop:
            put_work_brake(results, f.axle_force, results["distance_stop"].value, " until the masses stop")
        else:
            put_work_brake(results, f.axle_force, hoist.height, " over the trip")
    if unknown:
        said: list[str] = []
        needs_kinetic(", ".join(name for name, value in results.items() if value.value is not None), said)
        wanting = [option for option, side, normal in zip(machine.options, (side1, side2), (f.normal1, f.normal2)) if side.mu_k is None and normal > 0]
        if wanting != ["incline"]:  # friction.py's note names --mu-k; a side's μk is its spec's mu-k=
            where = " and ".join("--mu-k" if option == "incline" else f"mu-k= in --{option}" for option in wanting)
            said = [note.replace("needs --mu-k, which was not given", f"needs {where}, which {'was' if len(wanting) == 1 else 'were'} not given") for note in said]
        notes.extend(said)
        results = {name: value._replace(value=None) for name, value in results.items()}
        a = None
    if machine.kind == CLASSIC:
        steps = DeferredSteps(machine_steps, machine.m1, machine.m2, machine.pulley, machine.g, side2, side2.sin_angle, f.normal2,
                              a, results["a_massless"].value, dict(results), held, direction)
    elif machine.kind == STEPPED:
        steps = DeferredSteps(stepped_steps, machine.m1, machine.m2, f.inertia, machine.g, *machine.radii,
                              machine.pulley.axle_friction, a, dict(results), held)
    else:
        steps = DeferredSteps(general_steps, machine, f, (side1.mu_k, side2.mu_k), a, dict(results), held, direction)
    if hoist_steps:
        steps = DeferredSteps(lambda first, more: [*first, *more], steps, hoist_steps)
    path = None if unknown else deferred(trajectory, motion or (moving_mass, loads, v0), distance, time, results)
    return Report("atwood", _model(machine, f, loads, held), "closed form", results, steps, notes, trajectory=path)


def _held_note(machine: Machine, f: Forces, loads: Loads) -> str:
    if machine.kind == STEPPED:
        return ("nothing moves: " + ("the torques balance, m1 g r1 = m2 g r2" if loads.drive == 0 else "axle friction holds it")
                + f" (net torque {quantity_text(abs(loads.drive) * f.r1, 'N*m')} against at most {quantity_text(machine.pulley.axle_friction, 'N*m')} of friction)")
    balance = loads.drive == 0 and not loads.holding
    return ("nothing moves: " + ("the " + ("torques" if machine.radii else "forces along the string") + " balance" if balance and machine.kind != CLASSIC
                                 else "the masses balance" if balance else "friction can hold the system")
            + f" (net pull {quantity_text(abs(loads.drive), 'N')} against at most {quantity_text(loads.holding, 'N')} of friction)")


def _hung(side: Slope, option: str, number: str, notes: list[str]) -> Slope:
    """The block's place, checked; a block along a vertical face hangs: no normal force, so no friction."""
    if side.angle == HANGING and side.mu_k == 0.0 and side.mu_s is None:
        return side  # hangs (the usual case, first)
    check_slope(side, option)
    if not side.hanging:
        return side
    if side.mu_k or side.mu_s:
        said = "--mu-k and --mu-s play" if option == "incline" else f"the coefficients of --{option} play"
        notes.append(f"m{number} hangs (or slides along a vertical face): no normal force, so no friction; {said} no part")
    return Slope()


def _drive(machine: Machine, f: Forces) -> float:
    """G1 − ρ G2 − τd/r1, each product's rounding added back (math.fsum of exact products): near
    balance (m1 ≈ m2 hanging, m1 r1 ≈ m2 r2 on a stepped pulley) the difference keeps its digits.
    The classic machine and the plain stepped pulley keep the forms they had, to the last bit."""
    g = machine.g
    if machine.kind == CLASSIC:  # (m1 − m2) is exact for near-equal masses (Sterbenz); m1·g − m2·g would lose the difference
        return (machine.m1 - machine.m2) * g if machine.side2.hanging else machine.m1 * g - machine.m2 * g * machine.side2.sin_angle
    if machine.kind == STEPPED:
        r1, r2 = machine.radii
        return g * product_difference(machine.m1, r1, machine.m2, r2) / r1
    if machine.radii is not None:  # in torques, over r1: g (m1 r1 − m2 r2)/r1 as the stepped pulley's balance is written
        r1, r2 = machine.radii
        sign = -1.0 if machine.same_side else 1.0
        torque = math.fsum([
            *product_terms(machine.m1 * machine.side1.sin_angle, r1, g), *product_terms(-sign * machine.m2 * machine.side2.sin_angle, r2, g),
            machine.pull1[0] * r1, -sign * machine.pull2[0] * r2, -machine.torque,
        ])
        return torque / r1
    return math.fsum([
        *product_terms(machine.m1, g * machine.side1.sin_angle), *product_terms(-f.rho * machine.m2, g * machine.side2.sin_angle),
        machine.pull1[0], -f.rho * machine.pull2[0], -f.drive_force,
    ])


def tensions(f: Forces, kinetic: tuple[float, float], direction: int, machine: Machine | None = None,
             added_mass: float | None = None) -> tuple[float, float]:
    """T1 and T2 while moving in sense ``direction``, from each block's equation with a put in,
    over one denominator so that no difference of near-equal numbers is left where the classic
    machine has none (T1 = m1(g − a) with g − a written out as a sum of positive terms):

        M T1 = G1 (m2ρ² + J) + m1 ρ G2 + m1 τd/r1 − s f1 (m2ρ² + J) + s m1 (|ρ| f2 + τa/r1)
        M T2 = G2 (m1 + J) + m2 ρ G1 − m2 ρ τd/r1 + s sgn ρ f2 (m1 + J) − s m2 ρ (f1 + τa/r1)

    (f = μk N each block's kinetic friction, J = I/r1², M = m1 + m2ρ² + J)."""
    if machine is not None and added_mass is None and machine.kind == CLASSIC:
        return _classic_tensions(machine, f, kinetic[1], direction)
    if machine is not None and added_mass is None and machine.kind == STEPPED:
        return _stepped_tensions(machine, f, direction)
    m1, m2, rho = f.mass1, f.mass2, f.rho
    added = f.added_mass if added_mass is None else added_mass
    moving = m1 + m2 * rho * rho + added
    f1, f2 = kinetic
    s = direction
    others1 = m2 * rho * rho + added  # what m1 drags besides itself
    tension1 = (f.along1 * others1 + m1 * rho * f.along2 + m1 * f.drive_force - s * f1 * others1
                + s * m1 * (abs(rho) * f2 + f.axle_force)) / moving
    if added == 0 and f.axle_force == 0 and f.drive_force == 0 and rho == 1.0:
        return tension1, tension1  # the pulley's equation with I = 0: (T1 − T2)R = 0
    sign = 1.0 if rho > 0 else -1.0
    tension2 = (f.along2 * (m1 + added) + m2 * rho * f.along1 - m2 * rho * f.drive_force + s * sign * f2 * (m1 + added)
                - s * m2 * rho * (f1 + f.axle_force)) / moving
    return tension1, tension2


def _classic_tensions(machine: Machine, f: Forces, sliding: float, direction: int) -> tuple[float, float]:
    """The article's machine (m2 hanging or on its slope): T1 = m1(g − a) and T2 = m2(a + g sin θ)
    + s μk N, with g − a and a + g sin θ written out from a's formula as sums of positive terms,
    where the differences cancel as a -> g or −g sin θ."""
    m1, m2, g, sin = machine.m1, machine.m2, machine.g, machine.side2.sin_angle
    added, moving = f.added_mass, f.moving_mass
    g_less_a = (g * (m2 * (1 + sin) + added) + direction * (sliding + f.axle_force)) / moving
    tension1 = m1 * g_less_a
    if added == 0 and f.axle_force == 0:
        return tension1, tension1  # the pulley's equation with I = 0: (T1 − T2)R = 0
    # m2(a + g sin θ) + s μk N over one denominator, so the μk N terms do not cancel
    tension2 = (m2 * g * (m1 * (1 + sin) + sin * added) - direction * m2 * f.axle_force + direction * sliding * (m1 + added)) / moving
    return tension1, tension2


def _stepped_tensions(machine: Machine, f: Forces, direction: int) -> tuple[float, float]:
    """Both hanging on a stepped pulley: g − a1 and g + a2 from a's formula, as sums of positive terms."""
    m1, m2, g, ratio = machine.m1, machine.m2, machine.g, f.rho
    added, moving = f.added_mass, f.moving_mass
    tension1 = m1 * (g * (m2 * ratio * (ratio + 1) + added) + direction * f.axle_force) / moving
    tension2 = m2 * (g * (m1 * (1 + ratio) + added) - ratio * direction * f.axle_force) / moving
    return tension1, tension2


def _scale(f: Forces, kinetic=(0.0, 0.0)) -> float:
    """The size of the forces along the string, against which a tension is zero to rounding."""
    return abs(f.along1) + abs(f.along2) + kinetic[0] + kinetic[1] + abs(f.drive_force) + f.axle_force


def _taut(tension1: float, tension2: float | None, f: Forces, a: float, when: str) -> None:
    """Refuse a string that would have to push: a slack string is not modelled."""
    limit = -64 * EPSILON * _scale(f)
    for number, tension in (("1", tension1), ("2", tension2)):
        if tension is not None and tension < limit:
            own = a if number == "1" else f.rho * a
            raise InputError(
                "the string",
                f"goes slack on m{number}'s side{when}: the machine as one would need T{number} = {fmt(tension, 4)} N, a string that pushes "
                f"(m{number}'s own forces cannot give it the machine's {fmt(own, 4)} m/s², {'down' if number == '1' else 'up'} positive); "
                "a slack string is not modelled",
                hint="a lighter brake or drive, or a smaller --v0 against them" if f.axle_force or f.drive_force else None,
            )


def _massless(machine: Machine, f: Forces, kinetic, loads: Loads, v0: float, notes: list[str]) -> float | None:
    """The same machine with a massless pulley, for comparison (None where nothing is left to
    move, or where its string would go slack)."""
    light = f.mass1 + f.mass2 * f.rho * f.rho
    if not light > 0:
        if machine.pulled or machine.torque:  # (no masses at all: the classic machine's null, as it always was)
            notes.append("a_massless: null, because with a massless pulley nothing would be left to move but a massless string")
        return None
    a = start_rate(light, loads, v0)
    direction = start_direction(loads, v0)
    if direction:
        tension1, tension2 = tensions(f, kinetic, direction, added_mass=0.0)
        if min(tension1, tension2) < -64 * EPSILON * _scale(f, kinetic):
            if f.added_mass:
                notes.append("a_massless: null, because with a massless pulley the string would go slack")
            return None
    return a


def _second_phase(motion, f: Forces, kinetic, machine: Machine, distance, time, notes: list[str]) -> None:
    """After a stop the masses may set off the other way: that phase's string must stay taut too
    (refused where a result reaches into it, else said in a note)."""
    second, stop = motion.second, motion.stop
    if second is None or stop is None or motion.held_from_start:
        return
    a = second.direction * second.rate(0.0)
    tension1, tension2 = tensions(f, kinetic, second.direction, machine)
    if min(tension1, tension2) >= -64 * EPSILON * _scale(f, kinetic):
        return
    reached = time is not None and time > stop[0]  # (--distance is along the first way: never past the stop)
    if reached:
        _taut(tension1, tension2, f, a, " after the stop")
    notes.append("after the stop the string would go slack as the masses set off the other way (not modelled): the motion is given up to the stop")


def _model(machine: Machine, f: Forces, loads: Loads, held: bool) -> str:
    """The model in words."""
    if machine.radii is not None:
        r1, r2 = machine.radii
        inertia = f.inertia
        model = (f"stepped pulley (r1 = {fmt(r1)} m, r2 = {fmt(r2)} m{', both on one side' if machine.same_side else ''}), "
                 + ("massless" if not inertia else f"I = {fmt(inertia)} kg·m²") + ", strings do not slip")
    else:
        model = ("massless pulley" if not f.added_mass else f"massive pulley ({machine.pulley.words()})")
        model += ", strings wound on one side, not slipping" if machine.same_side else ", string does not slip"
    if machine.kind == CLASSIC:
        if not machine.side2.hanging:
            model += f"; m2 on {machine.side2.surface()}"
            if machine.side2.mu_k or machine.side2.mu_s:
                model += " with friction"
    else:
        where = [f"m{n} on {side.surface()}" + (" (a positive: m1 away from the pulley)" if n == "1" else "")
                 for n, side in (("1", machine.side1), ("2", machine.side2)) if not side.hanging]
        if where:
            model += "; " + ", ".join(where)
        pulled = [n for n, pull in (("1", machine.pull1), ("2", machine.pull2)) if pull != (0.0, 0.0)]
        if pulled:
            model += "; a pull on " + " and ".join(f"m{n}" for n in pulled)
        if machine.torque:
            model += "; a drive torque on the pulley"
    if machine.kind == STEPPED and machine.pulley.axle_friction:
        model += "; axle friction holds it" if held else "; axle friction overcome"
    elif held and loads.holding:
        model += "; friction holds it at rest"
    elif loads.friction:
        model += "; friction overcome"
    return model
