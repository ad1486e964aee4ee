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

from taucli.options.atwood import COMMAND as TABLE
from taucli.report import DeferredSteps, Report, deferred, fmt, quantity_text
from taucli.scenes.atwood.pulley import DISC_NOTE, Pulley, check_pulley
from taucli.scenes.atwood.slope import Slope, check_slope
from taucli.scenes.atwood.steps import machine_steps
from taucli.scenes.atwood.travel import evolve_exact, put_motion, trajectory
from taucli.scenes.friction import needs_kinetic, static_coefficient
from taucli.scenes.motion import Loads, start_direction, start_rate
from taucli.table import Results

EPSILON = 2.0**-52


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
    check_pulley(m1, m2, pulley)
    check_slope(slope)
    notes: list[str] = []
    if pulley.mass and pulley.shape is None:
        notes.append(DISC_NOTE)
    if slope.hanging and (slope.mu_k or slope.mu_s):
        notes.append("m2 hangs (or slides along a vertical face): no normal force, so no friction; --mu-k and --mu-s play no part")
        slope = Slope()
    sin_angle = slope.sin_angle
    normal = slope.normal(m2, g)
    mu_s = static_coefficient(slope.mu_s, slope.mu_k or None, notes) or 0.0
    mu_k = slope.mu_k or 0.0  # a placeholder where μk is not given: the motion then goes unreported

    pulley_added_mass = pulley.effective_mass()
    if pulley_added_mass:
        notes.append("the string taken not to slip on the pulley (a = αR): friction at the rim turns it")
    moving_mass = m1 + m2 + pulley_added_mass
    # (m1 − m2) is exact for near-equal masses (Sterbenz); m1·g − m2·g would lose the difference.
    drive = (m1 - m2) * g if slope.hanging else m1 * g - m2 * g * sin_angle
    axle_force = pulley.axle_force()
    loads = Loads(drive=drive, friction=mu_k * normal + axle_force, static=mu_s * normal + axle_force)
    direction = start_direction(loads, v0)
    held = direction == 0
    a = start_rate(moving_mass, loads, v0)
    # the motion that follows (stops, a second phase), worked out where a question needs it
    motion = evolve_exact(moving_mass, loads, v0) if distance is not None or time is not None else None

    a_massless = start_rate(m1 + m2, loads, v0) if m1 + m2 > 0 else None

    results = Results(TABLE)
    results.put("a", a)
    if held:
        tension1, tension2 = _statics(m1, m2, g, sin_angle, mu_s * normal, pulley, notes)
        notes.append(
            "nothing moves: "
            + ("the masses balance" if drive == 0 and not loads.holding else "friction can hold the system")
            + f" (net pull {quantity_text(abs(drive), 'N')} against at most {quantity_text(loads.holding, 'N')} of friction)"
        )
    else:
        # T1 = m1(g − a) and T2 = m2(a + g sin θ) + s μk N, with g − a and a + g sin θ written out
        # from a's formula: sums of positive terms, where the differences cancel as a -> g or −g sin θ.
        sliding = direction * mu_k * normal
        g_less_a = (g * (m2 * (1 + sin_angle) + pulley_added_mass) + direction * loads.friction) / moving_mass
        tension1 = m1 * g_less_a
        if pulley_added_mass == 0 and axle_force == 0:
            tension2 = tension1  # the pulley's equation with I = 0: (T1 − T2)R = 0
        else:  # m2(a + g sin θ) + s μk N over one denominator, so the μk N terms do not cancel
            tension2 = (
                m2 * g * (m1 * (1 + sin_angle) + sin_angle * pulley_added_mass) - direction * m2 * axle_force + sliding * (m1 + pulley_added_mass)
            ) / moving_mass
    results.put("T1", tension1)
    results.put("T2", tension2)
    results.put("alpha", None if pulley.radius is None else a / pulley.radius)
    if pulley.radius is None:
        notes.append("alpha: give --pulley-radius for the pulley's angular acceleration (a and the tensions do not need it)")
    results.put("a_massless", a_massless)
    if motion is not None:
        put_motion(results, motion, distance, time, notes)

    unknown = slope.mu_k is None and normal > 0 and not held
    if unknown:  # it slides, and the sliding friction is not known: only that it moves, and which way
        needs_kinetic(", ".join(name for name, value in results.items() if value.value is not None), notes)
        results = {name: value._replace(value=None) for name, value in results.items()}
        a = a_massless = None
    steps = DeferredSteps(machine_steps, m1, m2, pulley, g, slope, sin_angle, normal, a, a_massless, dict(results), held, direction)
    model = ("massless pulley" if not pulley_added_mass else f"massive pulley ({pulley.words()})") + ", string does not slip"
    if not slope.hanging:
        model += f"; m2 on {slope.surface()}"
        if slope.mu_k or mu_s:
            model += " with friction"
    if held and loads.holding:
        model += "; friction holds it at rest"
    elif loads.friction:
        model += "; friction overcome"
    path = None if unknown else deferred(trajectory, motion or (moving_mass, loads, v0), distance, time, results)
    return Report("atwood", model, "closed form", results, steps, notes, trajectory=path)


def _statics(m1, m2, g, sin_angle, grip, pulley, notes) -> tuple[float, float | None]:
    """Tensions at rest. T1 = m1 g. T2 must balance the pulley, |T1 − T2| ≤ τ_a/R, and m2,
    |T2 − m2 g sin θ| ≤ μs N (``grip``): statics fixes it wherever one of the two frictions is
    absent, or where the two intervals meet in one point (both frictions at their limits, on
    the point of slipping). Otherwise any T2 in their overlap balances, and it is null with
    the bounds in a note."""
    tension1 = m1 * g
    weight_along = m2 * g * sin_angle
    axle_force = pulley.axle_force()
    if not axle_force:
        return tension1, tension1  # no torque on the pulley at rest: equal tensions
    if not grip:
        return tension1, weight_along  # nothing along the surface but the string and gravity
    low, high = max(tension1 - axle_force, weight_along - grip), min(tension1 + axle_force, weight_along + grip)
    if high - low <= 16 * EPSILON * (tension1 + weight_along + axle_force + grip):
        return tension1, (low + high) / 2
    notes.append(
        "T2: statically indeterminate: friction at the axle and under m2 share the load in a way statics cannot fix; "
        f"it lies between {fmt(low, 6)} and {fmt(high, 6)} N"
    )
    return tension1, None
