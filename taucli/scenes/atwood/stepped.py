"""A stepped pulley: two radii on one axle, each mass's string wound on its own step; both masses
hang. One unknown, the pulley's rotation α; each mass moves at its own step's rim speed.
"""

from __future__ import annotations

import math

from taucli.errors import InputError
from taucli.options.atwood import COMMAND as TABLE
from taucli.report import DeferredSteps, Report, Step, deferred, fmt, quantity_text, term
from taucli.scenes.atwood.pulley import DISC_NOTE, Pulley, check_pulley
from taucli.scenes.atwood.travel import evolve_exact, put_motion, trajectory
from taucli.scenes.motion import Loads, start_rate
from taucli.table import Results


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
    machine of ``solve`` with m2 → m2 ρ², ρ = r2/r1, a drive g(m1 − m2 ρ), axle friction τ_a/r1.
    """
    check_pulley(m1, m2, pulley, radius_needed=False)
    notes: list[str] = []
    if pulley.inertia is not None:
        inertia = pulley.inertia
    else:
        rim = pulley.radius if pulley.radius is not None else max(r1, r2)
        if pulley.mass and pulley.shape is None:
            notes.append(DISC_NOTE)
        if pulley.mass and pulley.radius is None:
            notes.append(f"no --pulley-radius: the pulley's mass taken out to the larger step, R = {fmt(rim)} m; --pulley-radius or --pulley-inertia to change it")
        inertia = Pulley.SHAPE_FACTORS[pulley.shape or "disc"] * pulley.mass * rim * rim
    if inertia:
        notes.append("the strings taken not to slip on their steps (a1 = α r1, a2 = α r2)")
    ratio = r2 / r1
    pulley_added_mass = inertia / (r1 * r1)  # I/r1²: the pulley's mass as seen by m1
    moving_mass = m1 + m2 * ratio * ratio + pulley_added_mass
    drive = g * _product_difference(m1, r1, m2, r2) / r1
    axle_force = pulley.axle_friction / r1
    loads = Loads(drive=drive, friction=axle_force, static=axle_force)
    motion = evolve_exact(moving_mass, loads, v0)
    a, direction = motion.initial_rate, motion.direction
    if motion.held_from_start:
        tension1, tension2 = m1 * g, m2 * g
        notes.append(
            "nothing moves: " + ("the torques balance, m1 g r1 = m2 g r2" if drive == 0 else "axle friction holds it")
            + f" (net torque {quantity_text(abs(drive) * r1, 'N*m')} against at most {quantity_text(pulley.axle_friction, 'N*m')} of friction)"
        )
    else:  # g − a1 and g + a2 from a's formula, as sums of positive terms
        tension1 = m1 * (g * (m2 * ratio * (ratio + 1) + pulley_added_mass) + direction * axle_force) / moving_mass
        tension2 = m2 * (g * (m1 * (1 + ratio) + pulley_added_mass) - ratio * direction * axle_force) / moving_mass
    a_massless = None if m1 + m2 == 0 else start_rate(m1 + m2 * ratio * ratio, loads, v0)
    results = Results(TABLE)
    results.put("a", a)
    results.put("a2", ratio * a)
    results.put("T1", tension1)
    results.put("T2", tension2)
    results.put("alpha", a / r1)
    results.put("a_massless", a_massless)
    put_motion(results, motion, distance, time, notes)
    steps = DeferredSteps(_stepped_steps, m1, m2, inertia, g, r1, r2, pulley.axle_friction, a, dict(results), motion.held_from_start)
    model = f"stepped pulley (r1 = {fmt(r1)} m, r2 = {fmt(r2)} m), " + ("massless" if not inertia else f"I = {fmt(inertia)} kg·m²") + ", strings do not slip"
    if pulley.axle_friction:
        model += "; axle friction holds it" if motion.held_from_start else "; axle friction overcome"
    return Report("atwood", model, "closed form", results, steps, notes, trajectory=deferred(trajectory, motion, distance, time, results))


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


def _stepped_steps(m1, m2, inertia, g, r1, r2, axle_torque, a, results, held) -> list[Step]:
    axle_term = " − τ_a" if axle_torque else ""
    steps = [
        Step("For m₁ (moving down), wound at r₁", "m₁g − T₁ = m₁a₁,  a₁ = α r₁", "", "", "weight minus tension; its string unwinds from the step of radius r₁"),
        Step("For m₂ (moving up), wound at r₂ on the other side", "T₂ − m₂g = m₂a₂,  a₂ = α r₂", "", "", "tension minus weight; its string winds onto the step of radius r₂"),
        Step("For the pulley", f"T₁r₁ − T₂r₂{axle_term} = I α", "", "", "each string's torque is its tension times its own radius"),
        Step(
            "Put the tensions from the masses into the pulley's equation",
            f"α = (m₁g r₁ − m₂g r₂{axle_term}) / (I + m₁r₁² + m₂r₂²)",
            f"({term(m1 * g * r1, 'N*m')} − {term(m2 * g * r2, 'N*m')}{' − ' + term(axle_torque, 'N*m') if axle_torque else ''}) / ({term(inertia, 'kg*m**2')} + {term(m1 * r1 * r1, 'kg*m**2')} + {term(m2 * r2 * r2, 'kg*m**2')})",
            quantity_text(results["alpha"].value, "rad/s**2") + ("  (held: a = 0)" if held else ""),
            "each mass adds m r² at its own radius to the pulley's I; the larger torque wins",
        ),
        Step("Each mass's acceleration", "a₁ = α r₁,  a₂ = α r₂", "", f"{quantity_text(a, 'm/s**2')}, {quantity_text(results['a2'].value, 'm/s**2')}",
             "the two strings move at the speeds of their steps' rims"),
        Step("Tensions", "T₁ = m₁(g − a₁),  T₂ = m₂(g + a₂)", "", f"{quantity_text(results['T1'].value, 'N')}, {quantity_text(results['T2'].value, 'N')}",
             "from each mass's equation"),
    ]
    return steps
