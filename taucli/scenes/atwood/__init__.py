"""The Atwood machine: two masses on a string over a pulley that has mass and axle friction.

m1 hangs; m2 hangs on the other side, or lies on a table or a slope (the modified machine).
Positive is m1 moving down. One equation per body, the string not slipping on the pulley:

    m1:      m1 g − T1 = m1 a
    m2:      T2 − m2 g sin θ − μ m2 g cos θ·sgn v = m2 a      (hanging: θ = 90°, no friction)
    pulley:  (T1 − T2) R − τ_a·sgn v = I α,  α = a / R

Adding them cancels the tensions: a = (m1 g − m2 g sin θ − friction) / (m1 + m2 + I/R²). The
radius cancels too, except where axle friction (τ_a/R) or a given I (I/R²) brings it in. The
motion under constant forces, stops and static friction included, is motion.evolve's.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import NamedTuple

from taucli.errors import InputError
from taucli.options.atwood import COMMAND as TABLE
from taucli.report import (
    DeferredSteps,
    Report,
    Step,
    Trajectory,
    Value,
    deferred,
    fmt,
    quantity_text,
    term,
)
from taucli.scenes.assumed import Assumed
from taucli.scenes.point import RIM, put_point, put_start, rim_radius
from taucli.scenes.friction import needs_kinetic, static_coefficient
from taucli.scenes.motion import (
    Evolver,
    Loads,
    Method,
    Motion,
    evolve,
    start_direction,
    start_rate,
)
from taucli.table import Results
from taucli.scenes.inertia import body_inertia

HANGING = math.pi / 2
EPSILON = 2.0**-52


class Pulley(NamedTuple):  # NamedTuples, as report.Value: made on every run (a batch line), at a third of a frozen dataclass's cost
    """The pulley: its mass and shape, or its moment of inertia; its radius; axle friction."""
    mass: float = 0.0
    radius: float | None = None
    shape: str | None = None  # "disc" or "ring"; None with a mass means a disc, with a note
    inertia: float | None = None
    axle_friction: float = 0.0

    SHAPE_FACTORS = {"disc": 0.5, "ring": 1.0}  # I = factor × M R²

    def effective_mass(self) -> float:
        """I/R², the mass the pulley adds to the moving system: M/2 for a disc, M for a ring."""
        if self.inertia is not None:
            assert self.radius is not None
            return self.inertia / self.radius**2
        return self.SHAPE_FACTORS[self.shape or "disc"] * self.mass

    def axle_force(self) -> float:
        """τ_a / R: the axle friction as a force on the string."""
        return 0.0 if not self.axle_friction else self.axle_friction / self.radius

    def symbol(self) -> str:
        if self.inertia is not None:
            return "I/R²"
        return "M/2" if (self.shape or "disc") == "disc" else "M"


class Slope(NamedTuple):
    """Where m2 is: hanging (θ = 90°), on a table (0°) or a slope; its friction coefficients."""
    angle: float = HANGING
    mu_k: float | None = 0.0  # None: not given (friction.py's rule: needed only if m2 slides)
    mu_s: float | None = None

    @property
    def hanging(self) -> bool:
        return self.angle == HANGING


def _check(m1: float, m2: float, pulley: Pulley, slope: Slope) -> None:
    if m1 + m2 == 0 and pulley.mass == 0 and pulley.inertia is None:
        raise InputError("m1", "and {m2} cannot both be zero (with a massless pulley nothing is there to move)", example="{m1} 4kg {m2} 1kg")
    if pulley.inertia is not None and (pulley.mass or pulley.shape):
        raise InputError("pulley_inertia", "conflicts with {pulley_mass} and {pulley_shape}: give one description of the pulley")
    if pulley.inertia is not None and pulley.radius is None:
        raise InputError("pulley_radius", "is required with {pulley_inertia} (the pulley adds I/R² to the moving mass)", example="{pulley_radius} 0.1m")
    if pulley.axle_friction and pulley.radius is None:
        raise InputError("pulley_radius", "is required with {axle_friction} (the friction torque acts on the string as τ/R)", example="{pulley_radius} 0.1m")
    if pulley.shape is not None and pulley.shape not in Pulley.SHAPE_FACTORS:
        raise InputError("pulley_shape", "expected disc or ring", example="{pulley_shape} ring", got=repr(pulley.shape))
    if not 0 <= slope.angle <= HANGING:
        raise InputError("incline", "expected an angle from 0 to 90 deg", example="{incline} 30deg", got=f"{fmt(math.degrees(slope.angle))} deg")
    if slope.mu_s is not None and slope.mu_k is not None and slope.mu_k > slope.mu_s:
        raise InputError("mu_k", "must not exceed {mu_s} (kinetic friction is at most static friction)", got=f"{fmt(slope.mu_k)} > {fmt(slope.mu_s)}")


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
    """Acceleration, tensions and the motion that follows, for the machine described."""
    _check(m1, m2, pulley, slope)
    notes: list[str] = []
    if pulley.mass and pulley.shape is None:
        notes.append("pulley taken as a uniform solid disc (I = ½MR²); --pulley-shape ring for a thin ring")
    if slope.hanging and (slope.mu_k or slope.mu_s):
        notes.append("m2 hangs (or slides along a vertical face): no normal force, so no friction; --mu-k and --mu-s play no part")
        slope = Slope()
    sin_angle = 1.0 if slope.hanging else math.sin(slope.angle)
    normal = 0.0 if slope.hanging else m2 * g * math.cos(slope.angle)
    mu_s = static_coefficient(slope.mu_s, slope.mu_k or None, notes) or 0.0
    kinetic = slope.mu_k or 0.0  # a placeholder where μk is not given: the motion then goes unreported

    pulley_mass = pulley.effective_mass()
    if pulley_mass:
        notes.append("the string taken not to slip on the pulley (a = αR): friction at the rim turns it")
    moving_mass = m1 + m2 + pulley_mass
    # (m1 − m2) is exact for near-equal masses (Sterbenz); m1·g − m2·g would lose the difference.
    drive = (m1 - m2) * g if slope.hanging else m1 * g - m2 * g * sin_angle
    axle = pulley.axle_force()
    loads = Loads(drive=drive, friction=kinetic * normal + axle, static=mu_s * normal + axle)
    direction = start_direction(loads, v0)
    held = direction == 0
    a = start_rate(moving_mass, loads, v0)
    # the motion that follows (stops, a second phase), worked out where a question needs it
    motion = evolve(moving_mass, loads, v0, Evolver(Method("exact"))) if distance is not None or time is not None else None

    massless = start_rate(m1 + m2, loads, v0) if m1 + m2 > 0 else None

    results = Results(TABLE)
    results.put("a", a)
    if held:
        tension_high, tension_low = _statics(m1, m2, g, sin_angle, mu_s * normal, pulley, notes)
        notes.append(
            "nothing moves: "
            + ("the masses balance" if drive == 0 and not loads.holding else "friction can hold the system")
            + f" (net pull {quantity_text(abs(drive), 'N')} against at most {quantity_text(loads.holding, 'N')} of friction)"
        )
    else:
        # T1 = m1(g − a) and T2 = m2(a + g sin θ) + s μk N, with g − a and a + g sin θ written out
        # from a's formula: sums of positive terms, where the differences cancel as a -> g or −g sin θ.
        sliding = direction * kinetic * normal
        g_less_a = (g * (m2 * (1 + sin_angle) + pulley_mass) + direction * loads.friction) / moving_mass
        tension_high = m1 * g_less_a
        if pulley_mass == 0 and axle == 0:
            tension_low = tension_high  # the pulley's equation with I = 0: (T1 − T2)R = 0
        else:  # m2(a + g sin θ) + s μk N over one denominator, so the μk N terms do not cancel
            tension_low = (m2 * g * (m1 * (1 + sin_angle) + sin_angle * pulley_mass) - direction * m2 * axle + sliding * (m1 + pulley_mass)) / moving_mass
    results.put("T1", tension_high)
    results.put("T2", tension_low)
    results.put("alpha", None if pulley.radius is None else a / pulley.radius)
    if pulley.radius is None:
        notes.append("alpha: give --pulley-radius for the pulley's angular acceleration (a and the tensions do not need it)")
    results.put("a_massless", massless)
    if motion is not None:
        _motion_results(results, motion, distance, time, notes)

    unknown = slope.mu_k is None and normal > 0 and not held
    if unknown:  # it slides, and the sliding friction is not known: only that it moves, and which way
        needs_kinetic(", ".join(name for name, value in results.items() if value.value is not None), notes)
        results = {name: value._replace(value=None) for name, value in results.items()}
        a = massless = None
    steps = DeferredSteps(_steps, m1, m2, pulley, g, slope, sin_angle, normal, a, massless, dict(results), held, direction)
    model = ("massless pulley" if not pulley_mass else f"massive pulley ({_pulley_words(pulley)})") + ", string does not slip"
    if not slope.hanging:
        model += f"; m2 on {'a table' if slope.angle == 0 else f'a {fmt(math.degrees(slope.angle))}° slope'}"
        if slope.mu_k or mu_s:
            model += " with friction"
    if held and loads.holding:
        model += "; friction holds it at rest"
    elif loads.friction:
        model += "; friction overcome"
    trajectory = None if unknown else deferred(_trajectory, motion or (moving_mass, loads, v0), distance, time, results)
    return Report("atwood", model, "closed form", results, steps, notes, trajectory=trajectory)


def _trajectory(motion, distance: float | None, time: float | None, results: dict[str, Value]) -> Trajectory:
    """Position and velocity of m1 (down positive): to --time, or to --distance, or past the stop.
    ``motion`` is the Motion, or (mass, loads, v0) to evolve it from."""
    if not isinstance(motion, Motion):
        motion = evolve(*motion, Evolver(Method("exact")))
    stop, note, marks = motion.stop, "", []
    reached = results["t"].value if distance is not None else None
    if time is not None and time > 0:
        t_end = time
    elif reached:
        t_end = reached
    elif stop is not None and stop[0] > 0:
        t_end = 1.25 * stop[0]
    else:
        t_end, note = 1.0, "plotted for 1 s; --time or --distance to change"
    if reached:
        marks.append((reached, f"has moved {fmt(distance)} m"))
    if stop is not None and stop[0] > 0:
        marks.append((stop[0], "stops"))
    curves = (("x", "m", "position of m1, down positive"), ("v", "m/s", "velocity of m1"))
    return Trajectory(curves, t_end, lambda t: motion.state_at(t)[::-1], marks=tuple(marks), note=note)


def _pulley_words(pulley: Pulley) -> str:
    if pulley.inertia is not None:
        return "given I"
    return "solid disc" if (pulley.shape or "disc") == "disc" else "thin ring"


def _statics(m1, m2, g, sin_angle, grip, pulley, notes) -> tuple[float, float | None]:
    """Tensions at rest. T1 = m1 g. T2 must balance the pulley, |T1 − T2| ≤ τ_a/R, and m2,
    |T2 − m2 g sin θ| ≤ μs N (``grip``): statics fixes it wherever one of the two frictions is
    absent, or where the two intervals meet in one point (both frictions at their limits, on
    the point of slipping). Otherwise any T2 in their overlap balances, and it is null with
    the bounds in a note."""
    tension_high = m1 * g
    along = m2 * g * sin_angle
    axle = pulley.axle_force()
    if not axle:
        return tension_high, tension_high  # no torque on the pulley at rest: equal tensions
    if not grip:
        return tension_high, along  # nothing along the surface but the string and gravity
    low, high = max(tension_high - axle, along - grip), min(tension_high + axle, along + grip)
    if high - low <= 16 * EPSILON * (tension_high + along + axle + grip):
        return tension_high, (low + high) / 2
    notes.append(
        "T2: statically indeterminate: friction at the axle and under m2 share the load in a way statics cannot fix; "
        f"it lies between {fmt(low, 6)} and {fmt(high, 6)} N"
    )
    return tension_high, None


def _travel(motion, distance: float) -> float | None:
    """The time at which the masses have moved a path length ``distance`` (uniform phases)."""
    if motion.held_from_start:
        return 0.0 if distance == 0 else None
    first, stop = motion.first.closed, motion.stop
    if stop is None or distance <= stop[1]:
        return _uniform_time(first.omega0, first.constant / first.inertia, distance)
    if motion.second is None:
        return None
    second = motion.second.closed
    return stop[0] + _uniform_time(0.0, second.constant / second.inertia, distance - stop[1])


def _uniform_time(speed: float, acceleration: float, distance: float) -> float:
    """The first t ≥ 0 with speed·t + ½at² = distance: 2d/(u + √(u² + 2ad)), free of cancellation."""
    if distance == 0:
        return 0.0
    return 2 * distance / (speed + math.sqrt(max(speed * speed + 2 * acceleration * distance, 0.0)))


def _steps(m1, m2, pulley, g, slope, sin_angle, normal, a, massless, results, held, direction) -> list[Step]:
    steps: list[Step] = []
    if pulley.mass and pulley.inertia is None:
        factor = "½" if (pulley.shape or "disc") == "disc" else ""
        steps.append(
            Step(
                "The pulley's rotational inertia as extra mass",
                f"I/R² = {factor}M" if factor else "I/R² = M",
                f"{factor} × {quantity_text(pulley.mass, 'kg')}" if factor else quantity_text(pulley.mass, "kg"),
                quantity_text(pulley.effective_mass(), "kg"),
                f"I = {factor}MR² and α = a/R, so the torque equation (T₁ − T₂)R = Iα becomes T₁ − T₂ = {factor}Ma: "
                "R cancels",
            )
        )
    steps.append(Step("For m₁ (moving down)", "m₁g − T₁ = m₁a", "", "", "the net downward force on m₁ is its weight minus the upward string tension"))
    if slope.hanging:
        steps.append(Step("For m₂ (moving up)", "T₂ − m₂g = m₂a", "", "", "the net upward force on m₂ is the string tension minus its weight"))
    else:
        friction_term = " − μₖm₂g cos θ" if slope.mu_k != 0 else ""  # None: not given, but acting
        steps.append(
            Step(
                f"For m₂ (pulled along the {'table' if slope.angle == 0 else 'slope'})",
                f"T₂ − m₂g sin θ{friction_term} = m₂a",
                "",
                "",
                "along the surface: the tension pulls m₂ on, gravity's component m₂g sin θ pulls it back, and "
                "kinetic friction μₖN opposes the sliding, N = m₂g cos θ",
            )
        )
    axle_term = " − τ_a/R" if pulley.axle_friction else ""
    steps.append(
        Step(
            "For the pulley (rotating; the string does not slip, α = a/R)",
            f"T₁ − T₂{axle_term} = ({pulley.symbol()})a",
            "",
            "",
            "the net torque on the pulley is (T₁ − T₂)R" + (" less the axle friction τ_a" if pulley.axle_friction else "")
            + "; dividing by R, the pulley acts on the string like extra mass",
        )
    )
    pulley_term = f" + {pulley.symbol()}" if pulley.effective_mass() else ""
    drive_text = "m₁g − m₂g" if slope.hanging else "m₁g − m₂g sin θ"
    resist = (" − μₖm₂g cos θ" if slope.mu_k != 0 and not slope.hanging else "") + (" − τ_a/R" if pulley.axle_friction else "")
    numbers = (
        f"({quantity_text(m1 * g, 'N')} − {quantity_text(m2 * g * sin_angle, 'N')}"
        + (f" − {quantity_text((slope.mu_k or 0.0) * normal + pulley.axle_force(), 'N')}" if resist and slope.mu_k is not None else " − friction" if resist else "")
        + f") / ({term(m1, 'kg')} + {term(m2, 'kg')}"
        + (f" + {term(pulley.effective_mass(), 'kg')}" if pulley_term else "")
        + ")"
    )
    steps.append(
        Step(
            "Add the three equations: the tensions cancel",
            f"a = ({drive_text}{resist}) / (m₁ + m₂{pulley_term})",
            numbers,
            "needs μₖ (--mu-k)" if a is None else quantity_text(a, "m/s**2") + ("  (held: static friction wins, a = 0)" if held else ""),
            "adding the equations eliminates T₁ and T₂; the pulley's "
            f"{pulley.symbol()} in the denominator slows the system, as extra mass would"
            if pulley_term
            else "adding the equations eliminates T₁ and T₂",
        )
    )
    if pulley_term and massless is not None:
        steps.append(
            Step(
                "Compare: the same machine with a massless pulley",
                f"a₀ = ({drive_text}{resist}) / (m₁ + m₂)",
                f"{term(m1 * g - m2 * g * sin_angle, 'N')}{' − friction' if resist else ''} / {term(m1 + m2, 'kg')}",
                quantity_text(massless, "m/s**2"),
                f"the massive pulley costs {fmt(abs(massless - a))} m/s² of acceleration: part of gravity's work goes into spinning it",
            )
        )
    tension_high, tension_low = results["T1"].value, results["T2"].value
    if not held and a is not None:
        steps.append(Step("Tension on m₁'s side", "T₁ = m₁(g − a)", f"{term(m1, 'kg')} × ({term(g, 'm/s**2')} − {term(a, 'm/s**2')})", quantity_text(tension_high, "N"), "from m₁'s equation"))
        if slope.hanging:
            steps.append(Step("Tension on m₂'s side", "T₂ = m₂(g + a)", f"{term(m2, 'kg')} × ({term(g, 'm/s**2')} + {term(a, 'm/s**2')})", quantity_text(tension_low, "N"), "from m₂'s equation"))
        else:
            steps.append(
                Step("Tension on m₂'s side", "T₂ = m₂(a + g sin θ) + μₖN", "", quantity_text(tension_low, "N"), "from m₂'s equation")
            )
        if pulley.effective_mass() or pulley.axle_friction:
            needed = pulley.effective_mass() * a + direction * pulley.axle_force()
            steps.append(
                Step(
                    "Check with the pulley's equation",
                    f"T₁ − T₂ = ({pulley.symbol()})a" + (" + τ_a/R" if pulley.axle_friction else ""),
                    f"{quantity_text(tension_high, 'N')} − {quantity_text(tension_low, 'N')}",
                    quantity_text(tension_high - tension_low, "N"),
                    f"and ({pulley.symbol()})a{' + τ_a/R' if pulley.axle_friction else ''} = {quantity_text(needed, 'N')}: the tension "
                    "difference is exactly the force needed to turn the pulley",
                )
            )
    if pulley.radius is not None and a is not None:
        steps.append(Step("Angular acceleration of the pulley", "α = a/R", f"{term(a, 'm/s**2')} / {term(pulley.radius, 'm')}", quantity_text(a / pulley.radius, "rad/s**2"), "the string does not slip on the rim"))
    return steps


def _motion_results(results: Results, motion, distance: float | None, time: float | None, notes: list[str]) -> None:
    """t and v after --distance, v and the displacement at --time: m1's, as solve gives them."""
    if distance is not None:
        reached = _travel(motion, distance)
        if reached is None:
            notes.append(f"the masses never travel {quantity_text(distance, 'm')}")
        results.put("t", reached, f" {fmt(distance)} m")
        results.put("v", None if reached is None else motion.state_at(reached)[0], f" after {fmt(distance)} m")
    if time is not None:
        speed, displacement = motion.state_at(time)
        if "v" not in results:
            results.put("v", speed, f" at t = {fmt(time)} s")
        results.put("distance", displacement, f" at t = {fmt(time)} s")
        if distance is not None:
            notes.append("v is given at the distance; distance at the time")


def solve_stepped(
    m1: float, m2: float, pulley: Pulley, g: float, r1: float, r2: float, *, v0: float = 0.0, distance: float | None = None, time: float | None = None
) -> Report:
    """A stepped pulley: m1's string wound at r1, m2's at r2 on the other side; one pulley of
    inertia I, its rotation α the one unknown (m1 down and the pulley turning positive):

        m1:      m1 g − T1 = m1 a1,     a1 = α r1
        m2:      T2 − m2 g = m2 a2,     a2 = α r2   (m2 up positive)
        pulley:  T1 r1 − T2 r2 − τ_a·sgn ω = I α

    so α = (m1 g r1 − m2 g r2 − τ_a)/(I + m1 r1² + m2 r2²). In m1's coordinate (÷ r1): the
    machine of ``solve`` with m2 → m2 ρ², ρ = r2/r1, a drive g(m1 − m2 ρ), axle friction τ_a/r1.
    """
    if m1 + m2 == 0 and pulley.mass == 0 and pulley.inertia is None:
        raise InputError("m1", "and {m2} cannot both be zero (with a massless pulley nothing is there to move)", example="{m1} 4kg {m2} 1kg")
    if pulley.inertia is not None and (pulley.mass or pulley.shape):
        raise InputError("pulley_inertia", "conflicts with {pulley_mass} and {pulley_shape}: give one description of the pulley")
    if pulley.shape is not None and pulley.shape not in Pulley.SHAPE_FACTORS:
        raise InputError("pulley_shape", "expected disc or ring", example="{pulley_shape} ring", got=repr(pulley.shape))
    notes: list[str] = []
    if pulley.inertia is not None:
        inertia = pulley.inertia
    else:
        rim = pulley.radius if pulley.radius is not None else max(r1, r2)
        if pulley.mass and pulley.shape is None:
            notes.append("pulley taken as a uniform solid disc (I = ½MR²); --pulley-shape ring for a thin ring")
        if pulley.mass and pulley.radius is None:
            notes.append(f"no --pulley-radius: the pulley's mass taken out to the larger step, R = {fmt(rim)} m; --pulley-radius or --pulley-inertia to change it")
        inertia = Pulley.SHAPE_FACTORS[pulley.shape or "disc"] * pulley.mass * rim * rim
    if inertia:
        notes.append("the strings taken not to slip on their steps (a1 = α r1, a2 = α r2)")
    ratio = r2 / r1
    own = inertia / (r1 * r1)  # I/r1²: the pulley's mass as seen by m1
    moving = m1 + m2 * ratio * ratio + own
    drive = g * _product_difference(m1, r1, m2, r2) / r1
    axle = pulley.axle_friction / r1
    loads = Loads(drive=drive, friction=axle, static=axle)
    motion = evolve(moving, loads, v0, Evolver(Method("exact")))
    a, direction = motion.initial_rate, motion.direction
    if motion.held_from_start:
        tension1, tension2 = m1 * g, m2 * g
        notes.append(
            "nothing moves: " + ("the torques balance, m1 g r1 = m2 g r2" if drive == 0 else "axle friction holds it")
            + f" (net torque {quantity_text(abs(drive) * r1, 'N*m')} against at most {quantity_text(pulley.axle_friction, 'N*m')} of friction)"
        )
    else:  # g − a1 and g + a2 from a's formula, as sums of positive terms
        tension1 = m1 * (g * (m2 * ratio * (ratio + 1) + own) + direction * axle) / moving
        tension2 = m2 * (g * (m1 * (1 + ratio) + own) - ratio * direction * axle) / moving
    massless = None if m1 + m2 == 0 else start_rate(m1 + m2 * ratio * ratio, loads, v0)
    results = Results(TABLE)
    results.put("a", a)
    results.put("a2", ratio * a)
    results.put("T1", tension1)
    results.put("T2", tension2)
    results.put("alpha", a / r1)
    results.put("a_massless", massless)
    _motion_results(results, motion, distance, time, notes)
    steps = DeferredSteps(_stepped_steps, m1, m2, inertia, g, r1, r2, pulley.axle_friction, a, dict(results), motion.held_from_start)
    model = f"stepped pulley (r1 = {fmt(r1)} m, r2 = {fmt(r2)} m), " + ("massless" if not inertia else f"I = {fmt(inertia)} kg·m²") + ", strings do not slip"
    if pulley.axle_friction:
        model += "; axle friction holds it" if motion.held_from_start else "; axle friction overcome"
    return Report("atwood", model, "closed form", results, steps, notes, trajectory=deferred(_trajectory, motion, distance, time, results))


def _product_difference(a: float, b: float, c: float, d: float) -> float:
    """a·b − c·d to within an ulp or so, also where the two products nearly cancel (a stepped
    pulley near balance, m1 r1 ≈ m2 r2): each product's rounding error is found exactly (Dekker's
    two-product, by Veltkamp's split) and added back after the difference."""
    first, second = a * b, c * d
    if not (math.isfinite(first) and math.isfinite(second)) or max(abs(a), abs(b), abs(c), abs(d)) > 1e150:
        return first - second  # the split would overflow; nothing near cancellation is that large here
    return (first - second) + (_product_error(a, b, first) - _product_error(c, d, second))


def _product_error(a: float, b: float, product: float) -> float:
    """The exact a·b − fl(a·b)."""
    a_high, a_low = _split(a)
    b_high, b_low = _split(b)
    return ((a_high * b_high - product) + a_high * b_low + a_low * b_high) + a_low * b_low


def _split(x: float) -> tuple[float, float]:
    c = 134217729.0 * x  # 2^27 + 1
    high = c - (c - x)
    return high, x - high


def _stepped_steps(m1, m2, inertia, g, r1, r2, axle, a, results, held) -> list[Step]:
    axle_term = " − τ_a" if axle else ""
    steps = [
        Step("For m₁ (moving down), wound at r₁", "m₁g − T₁ = m₁a₁,  a₁ = α r₁", "", "", "weight minus tension; its string unwinds from the step of radius r₁"),
        Step("For m₂ (moving up), wound at r₂ on the other side", "T₂ − m₂g = m₂a₂,  a₂ = α r₂", "", "", "tension minus weight; its string winds onto the step of radius r₂"),
        Step("For the pulley", f"T₁r₁ − T₂r₂{axle_term} = I α", "", "", "each string's torque is its tension times its own radius"),
        Step(
            "Put the tensions from the masses into the pulley's equation",
            f"α = (m₁g r₁ − m₂g r₂{axle_term}) / (I + m₁r₁² + m₂r₂²)",
            f"({term(m1 * g * r1, 'N*m')} − {term(m2 * g * r2, 'N*m')}{' − ' + term(axle, 'N*m') if axle else ''}) / ({term(inertia, 'kg*m**2')} + {term(m1 * r1 * r1, 'kg*m**2')} + {term(m2 * r2 * r2, 'kg*m**2')})",
            quantity_text(results["alpha"].value, "rad/s**2") + ("  (held: a = 0)" if held else ""),
            "each mass adds m r² at its own radius to the pulley's I; the larger torque wins",
        ),
        Step("Each mass's acceleration", "a₁ = α r₁,  a₂ = α r₂", "", f"{quantity_text(a, 'm/s**2')}, {quantity_text(results['a2'].value, 'm/s**2')}",
             "the two strings move at the speeds of their steps' rims"),
        Step("Tensions", "T₁ = m₁(g − a₁),  T₂ = m₂(g + a₂)", "", f"{quantity_text(results['T1'].value, 'N')}, {quantity_text(results['T2'].value, 'N')}",
             "from each mass's equation"),
    ]
    return steps


def solve_rim(
    m1: float, m2: float, pulley: Pulley, g: float, rim_mu: float, wrap: float, *, v0: float = 0.0, distance: float | None = None, time: float | None = None
) -> Report:
    """A string that may slide over the rim. The capstan limit T_high/T_low ≤ e^{μβ} decides:
    within it the string grips (``solve``'s answer); past it the string slides, the tensions are
    in the capstan ratio, and the pulley is turned by the friction alone (m1 moving down):

        m1:      m1 g − T1 = m1 a,     m2:  T2 − m2 g = m2 a,     T1 = e^{μβ} T2
        pulley:  (T1 − T2) R = I α     (the rim's own acceleration a_rim = α R < a)

    giving a = g (m1 − E m2)/(m1 + E m2), T2 = 2 m1 m2 g/(m1 + E m2), E = e^{μβ} (and the
    mirror image when m2 goes down). At μ = ln(T1/T2)/β the two answers meet.
    """
    grip = solve(m1, m2, pulley, g, v0=v0, distance=distance, time=time)  # its checks first
    tension1, tension2 = grip.results["T1"].value, grip.results["T2"].value
    high, low = max(tension1, tension2), min(tension1, tension2)
    # the least μ that grips: ln(T_high/T_low)/β, with T_high − T_low = (I/R²)|a| from the pulley's
    # equation rather than the difference of two near-equal tensions (near-equal masses)
    need = math.log1p(pulley.effective_mass() * abs(grip.results["a"].value) / low) / wrap
    results = Results(TABLE)
    notes = [note for note in grip.notes if not note.startswith("the string taken not to slip")]
    if not pulley.effective_mass():
        notes.append("{rim_mu}: a massless pulley needs no torque, so the tensions are equal and the string always grips")
    if rim_mu >= need:
        for key, value in grip.results.items():
            results[key] = value
        results.put("a_rim", grip.results["a"].value)
        results.put("grips", True)
        results.put("rim_mu_min", need)
        notes.append(
            f"the string grips the rim: T_high/T_low = {fmt(high / low, 6)} ≤ e^(μβ) = {_exp_text(rim_mu * wrap)} "
            f"(it would slide below μ = {fmt(need)})"
        )
        steps = DeferredSteps(lambda: [*grip.steps, _capstan_step(high, low, rim_mu, wrap, need, True)])
        model = grip.model.replace("string does not slip", "string grips the rim")
        return Report("atwood", model, "closed form", results, steps, notes, trajectory=grip.trajectory)
    ratio = math.exp(rim_mu * wrap)
    growth = math.expm1(rim_mu * wrap)  # E − 1, kept accurate for small μβ
    if tension1 > tension2:  # m1 goes down; the tension grows along the rim towards m1
        low_side = 2 * m1 * m2 * g / (m1 + ratio * m2)
        a = g * (m1 - ratio * m2) / (m1 + ratio * m2)
        tension1, tension2, sense = ratio * low_side, low_side, 1.0
    else:
        low_side = 2 * m1 * m2 * g / (ratio * m1 + m2)
        a = g * (ratio * m1 - m2) / (ratio * m1 + m2)
        tension1, tension2, sense = low_side, ratio * low_side, -1.0
    rim_a = sense * growth * low_side / pulley.effective_mass()  # (T1 − T2) R / I × R
    results.put("a", a)
    results.put("T1", tension1)
    results.put("T2", tension2)
    results.put("alpha", None if pulley.radius is None else rim_a / pulley.radius)
    results.put("a_massless", grip.results["a_massless"].value)
    results.put("a_rim", rim_a)
    results.put("grips", False)
    results.put("rim_mu_min", need)
    notes.append(
        f"the string slides over the rim: gripping would need T_high/T_low = {fmt(high / low, 6)}, more than e^(μβ) = {fmt(ratio, 6)} "
        f"(μ ≥ {fmt(need)}); the tensions take the capstan ratio, and the pulley is turned by the sliding friction alone: "
        "a is the masses', a_rim the rim's. One coefficient, {rim_mu}, for gripping and sliding"
    )
    if pulley.radius is None:
        notes.append("alpha: give --pulley-radius for the pulley's angular acceleration (a_rim does not need it)")
    motion = evolve(1.0, Loads(drive=a), v0, Evolver(Method("exact")))  # no friction that depends on the masses' speed: uniform a
    _motion_results(results, motion, distance, time, notes)
    steps = DeferredSteps(lambda: [
        Step("For m₁ and m₂", "m₁g − T₁ = m₁a,  T₂ − m₂g = m₂a", "", "", "each mass's weight and its string's tension"),
        _capstan_step(high, low, rim_mu, wrap, need, False),
        Step("The string slides: the tensions take the capstan ratio", "T₁ = e^(μβ) T₂" if sense > 0 else "T₂ = e^(μβ) T₁",
             f"e^({fmt(rim_mu)} × {term(wrap, 'rad')}) = {fmt(ratio)}", f"E = {fmt(ratio)}", "sliding friction along the wrap makes the tension grow by e^(μβ) towards the side the string moves to"),
        Step("Solve for the masses", "a = g (m₁ − E m₂)/(m₁ + E m₂)" if sense > 0 else "a = g (E m₁ − m₂)/(E m₁ + m₂)",
             f"{term(g, 'm/s**2')} × ({term(m1, 'kg')} − {fmt(ratio)} × {term(m2, 'kg')}) / ({term(m1, 'kg')} + {fmt(ratio)} × {term(m2, 'kg')})"
             if sense > 0 else
             f"{term(g, 'm/s**2')} × ({fmt(ratio)} × {term(m1, 'kg')} − {term(m2, 'kg')}) / ({fmt(ratio)} × {term(m1, 'kg')} + {term(m2, 'kg')})",
             quantity_text(a, "m/s**2"), "the tensions from the masses' equations, put into the capstan ratio"),
        Step("The pulley, turned by the friction alone", "I α = (T₁ − T₂) R,  a_rim = α R = (T₁ − T₂)/(I/R²)",
             f"({term(tension1, 'N')} − {term(tension2, 'N')}) / {term(pulley.effective_mass(), 'kg')}", quantity_text(rim_a, "m/s**2"),
             "the rim lags the string: the string slides over it"),
    ])  # written when read
    model = ("massive pulley (" + _pulley_words(pulley) + "), the string slides over the rim (capstan friction)")
    return Report("atwood", model, "closed form", results, steps, notes, trajectory=deferred(_trajectory, motion, distance, time, results))


def _exp_text(x: float) -> str:
    """e^x as a number, or as e^x where it is beyond a float (a long wrap of a rough rim)."""
    return fmt(math.exp(x), 6) if x < 700 else f"e^{fmt(x)}"


def _capstan_step(high, low, mu, wrap, need, grips) -> Step:
    return Step(
        "Does the string grip? The capstan limit",
        "T_high / T_low ≤ e^(μβ)",
        f"{term(high, 'N')} / {term(low, 'N')} against e^({fmt(mu)} × {term(wrap, 'rad')})",
        f"{fmt(high / low, 6)} {'≤' if grips else '>'} {_exp_text(mu * wrap)}",
        "friction over a wrap of β can change the tension by at most a factor e^(μβ); "
        + (f"so it grips (least μ = {fmt(need)})" if grips else f"so it slides (gripping needs μ ≥ {fmt(need)})"),
    )


def _on_the_pulley(report: Report, r: float, radius: float | None, v0: float, distance: float | None, time: float | None) -> Report:
    """A point at r on the pulley, which turns with m1's string: ω = v/R and α = a/R (R the
    radius m1's string leaves at; down positive turns it positive); after --distance (θ = d/R),
    else at --time (θ = x/R), else at the start."""
    if radius is None:
        raise InputError("at", "needs {pulley_radius} (a point on the pulley turns at ω = v/R)", example="{pulley_radius} 0.1m {at} 0.05m")
    values = {key: value.value for key, value in report.results.items()}
    alpha = values.get("alpha")
    results = Results(TABLE)
    results.update(report.results)
    notes, steps = list(report.notes), list(report.steps)
    if distance is not None:
        when, speed, travelled = f" after {fmt(distance)} m", values.get("v"), distance
    elif time is not None:
        when, speed, travelled = f" at t = {fmt(time)} s", values.get("v"), values.get("distance")
    else:
        when, speed, travelled = " at the start", v0, 0.0
    if values.get("a") is None:  # the motion is not known (μk not given): nor is the point's
        speed = None
    omega = None if speed is None else speed / radius
    steps += put_point(results, r, omega, alpha, None if travelled is None else travelled / radius, when, notes)
    if omega is not None and when != " at the start":
        put_start(results, r, v0 / radius, alpha)
    return Report(report.scene, report.model, report.method, results, steps, notes, report.inputs, report.tables, report.trajectory)


def _with_parts(pulley: Pulley, parts: Sequence, assumed: Assumed) -> Pulley:
    """The pulley with its parts: I = I of --pulley-inertia or of --pulley-mass (Σ over one axle adds),
    plus each part's moment about the axle (taucli.scenes.inertia, parallel axes included)."""
    if pulley.radius is None:
        raise InputError("pulley_radius", "is required with {part} (the pulley adds I/R² to the moving mass)", example="{pulley_radius} 0.1m")
    if pulley.inertia is not None and pulley.mass:
        raise InputError("pulley_inertia", "conflicts with {pulley_mass} and {pulley_shape}: give one description of the pulley")
    base = pulley.inertia if pulley.inertia is not None else Pulley.SHAPE_FACTORS[pulley.shape or "disc"] * pulley.mass * pulley.radius**2
    parts = body_inertia(parts)
    assumed.notes.append(f"pulley: I = {fmt(base + parts.inertia)} kg·m², {'the given pulley and ' if base else ''}{parts.description}")
    return Pulley(0.0, pulley.radius, None, base + parts.inertia, pulley.axle_friction)


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
    if at is not None:
        if rim_mu is not None:
            raise InputError("at", "does not apply with {rim_mu}: where the string slides the pulley's own turning is not followed in time")
        report = atwood(m1=m1, m2=m2, pulley_mass=pulley_mass, pulley_radius=pulley_radius, pulley_shape=pulley_shape, pulley_inertia=pulley_inertia,
                        axle_friction=axle_friction, incline=incline, mu_k=mu_k, mu_s=mu_s, g=g, v0=v0, distance=distance, time=time,
                        radius1=radius1, radius2=radius2, part=part)
        if at == RIM and (radius1 is not None or radius2 is not None):
            raise InputError("at", "rim: a stepped pulley has two radii; give the point's radius", example="{at} 0.1m")
        r, note = rim_radius(at, pulley_radius, "{pulley_radius}")
        report = _on_the_pulley(report, r, radius1 if radius1 is not None else pulley_radius, v0 or 0.0, distance, time)
        report.notes += [note] if note else []
        return report
    if m1 is None:
        raise InputError("m1", "is required", example="{m1} 4kg")
    assumed = Assumed()
    if m2 is None:
        assumed.notes.append("no --m2: a single mass on a string wound on the pulley")
    pulley = Pulley(pulley_mass or 0.0, pulley_radius, pulley_shape, pulley_inertia, axle_friction or 0.0)
    if part:
        pulley = _with_parts(pulley, part, assumed)
    if wrap is not None and rim_mu is None:
        raise InputError("wrap", "needs {rim_mu} (the wrap matters only where the string may slide)", example="{rim_mu} 0.3 {wrap} 180deg")
    if radius1 is not None or radius2 is not None:
        r1 = radius1 if radius1 is not None else pulley_radius
        r2 = radius2 if radius2 is not None else pulley_radius
        if r1 is None or r2 is None:
            missing = "radius1" if r1 is None else "radius2"
            raise InputError(missing, "is required with {" + ("radius2" if missing == "radius1" else "radius1") + "} (or {pulley_radius} for it)", example=f"{{{missing}}} 0.1m")
        for name, value in (("incline", incline), ("rim_mu", rim_mu), ("mu_k", mu_k), ("mu_s", mu_s)):
            if value is not None:
                raise InputError(name, "does not apply with a stepped pulley ({radius1}, {radius2}): both masses hang, their strings fixed to their steps")
        gravity = assumed.gravity(g)
        return assumed.applied(solve_stepped(m1, m2 or 0.0, pulley, gravity, r1, r2, v0=v0 or 0.0, distance=distance, time=time))
    if rim_mu is not None:
        for name, value in (("incline", incline), ("axle_friction", axle_friction), ("mu_k", mu_k), ("mu_s", mu_s)):
            if value is not None:
                raise InputError(name, "does not apply with {rim_mu} here: a string that may slide is solved for two hanging masses on a pulley free on its axle")
        if not m1 or not m2:
            raise InputError("m1" if not m1 else "m2", "must be more than 0 with {rim_mu}: a string with nothing on one end slides off (a string wound on the pulley is fixed to it)")
        gravity = assumed.gravity(g)
        return assumed.applied(solve_rim(m1, m2, pulley, gravity, rim_mu, math.pi if wrap is None else wrap, v0=v0 or 0.0, distance=distance, time=time))
    # friction.py's rule: neither coefficient given, a smooth surface (μk = 0); only μs, μk unknown
    slope = Slope(HANGING if incline is None else incline, 0.0 if mu_k is None and mu_s is None else mu_k, mu_s)
    gravity = assumed.gravity(g)
    report = solve(m1, m2 or 0.0, pulley, gravity, slope=slope, v0=v0 or 0.0, distance=distance, time=time)
    return assumed.applied(report)
