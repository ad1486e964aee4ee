"""A rope over a drum that cannot turn (--fixed-drum, #35): a rod, a bollard, a capstan. The rope's
tension changes along the wrap β only through friction, by at most a factor e^{μβ} (the capstan
equation, each element adding μ times its pressure T·dφ):

    held:     e^{−μs β} ≤ m₁/m₂ ≤ e^{μs β}   (a = 0, T₁ = m₁g, T₂ = m₂g)
    sliding:  T_tight = e^{μk β}·T_slack, the tight side the one the rope moves towards:

    m₁ down:  m₁g − T₁ = m₁a,  T₂ − m₂g = m₂a,  T₁ = E·T₂   →  a = g(m₁ − E m₂)/(m₁ + E m₂),  T₂ = 2m₁m₂g/(m₁ + E m₂)
    m₁ up:    T₂ = E·T₁                        →  a = g(E m₁ − m₂)/(E m₁ + m₂),  T₁ = 2m₁m₂g/(E m₁ + m₂)

(a positive with m₁ moving down, E = e^{μk β}). Set moving (--v0), the rope slides with the
acceleration of its sense of motion, may stop, and then holds or slides back as from rest.
"""

from __future__ import annotations

import math

from taucli.core.errors import InputError
from taucli.options.atwood import COMMAND as TABLE
from taucli.writing.report import DeferredSteps, Report, Step, deferred, fmt, quantity_text, term
from taucli.scenes.atwood.travel import evolve_exact, put_motion, trajectory
from taucli.scenes.friction import needs_kinetic, static_coefficient
from taucli.scenes.motion import Loads
from taucli.options.table import Results


def sliding(m1: float, m2: float, g: float, mu: float, wrap: float, sense: int) -> tuple[float, float, float]:
    """(a, T₁, T₂) while the rope slides with m₁ moving down (sense +1) or up (−1)."""
    ratio = math.exp(mu * wrap)
    if sense > 0:
        slack = 2 * m1 * m2 * g / (m1 + ratio * m2)
        return g * (m1 - ratio * m2) / (m1 + ratio * m2), ratio * slack, slack
    slack = 2 * m1 * m2 * g / (ratio * m1 + m2)
    return g * (ratio * m1 - m2) / (ratio * m1 + m2), slack, ratio * slack


def solve_fixed_drum(m1: float, m2: float, g: float, mu_k: float | None, mu_s: float | None, wrap: float, *, v0: float = 0.0,
                     distance: float | None = None, time: float | None = None, stop: bool = False) -> Report:
    """Two hanging masses on a rope over a fixed drum (module docstring)."""
    if not m1 or not m2:
        raise InputError("m1" if not m1 else "m2", "must be more than 0 with {fixed_drum}: a rope with nothing on one end slides off the drum",
                         example="{m1} 250kg {m2} 100kg {fixed_drum} {rim_mu} 0.2")
    notes: list[str] = []
    mu_hold = static_coefficient(mu_s, mu_k, notes)
    log_ratio = math.log(m1 / m2)
    mu_min = abs(log_ratio) / wrap  # the least μs that holds the rope at rest
    holds = mu_min <= mu_hold
    results = Results(TABLE)
    gravity_a = g * (m1 - m2) / (m1 + m2)
    hold_steps = [Step("Does the rope hold? The capstan limit", "e^(−μs·β) ≤ m₁/m₂ ≤ e^(μs·β),  i.e.  |ln(m₁/m₂)|/β ≤ μs",
                  f"|ln({term(m1, 'kg')} / {term(m2, 'kg')})| / {term(wrap, 'rad')} against μs = {fmt(mu_hold)}",
                  f"{fmt(mu_min)} {'≤' if holds else '>'} {fmt(mu_hold)}",
                  "friction over a wrap β can change the tension by at most a factor e^(μβ); held, each side's tension is its weight")]
    if v0 == 0 and holds:
        results.put("a", 0.0)
        results.put("T1", m1 * g)
        results.put("T2", m2 * g)
        results.put("holds", True)
        results.put("rim_mu_min", mu_min)
        results.put("a_massless", gravity_a)
        notes.append(f"the rope holds on the drum: m₁/m₂ = {fmt(m1 / m2, 6)} is within e^(±μs·β) = e^(±{fmt(mu_hold * wrap)}) "
                     f"(it would slide below μs = {fmt(mu_min)})")
        motion = evolve_exact(1.0, Loads(drive=0.0), 0.0)
        put_motion(results, motion, distance, time, notes, stop=stop)
        model = "rope over a fixed drum (capstan friction): it holds"
        return Report("atwood", model, "closed form", results, hold_steps, notes, trajectory=deferred(trajectory, motion, distance, time, results))
    sense = (v0 > 0) - (v0 < 0) or (1 if log_ratio > 0 else -1)
    if mu_k is None:
        needs_kinetic("a, T1, T2", notes)
        for key in ("a", "T1", "T2"):
            results.put(key, None)
        results.put("holds", False)
        results.put("rim_mu_min", mu_min)
        results.put("a_massless", gravity_a)
        return Report("atwood", "rope over a fixed drum (capstan friction): it slides", "closed form", results, hold_steps, notes)
    a, tension1, tension2 = sliding(m1, m2, g, mu_k, wrap, sense)
    down, up = sliding(m1, m2, g, mu_k, wrap, 1)[0], sliding(m1, m2, g, mu_k, wrap, -1)[0]
    # the rope's motion as a unit mass under a drive and a friction: a = drive − friction·sgn v in
    # each sense; at rest it holds where μs does (a holding force at least the drive's)
    drive, friction = (down + up) / 2, (up - down) / 2
    loads = Loads(drive=drive, friction=friction, static=max(friction, abs(drive)) if holds else friction)
    motion = evolve_exact(1.0, loads, v0)
    results.put("a", a)
    results.put("T1", tension1)
    results.put("T2", tension2)
    results.put("holds", False)
    results.put("rim_mu_min", mu_min)
    results.put("a_massless", gravity_a)
    put_motion(results, motion, distance, time, notes, stop=stop)
    ratio = math.exp(mu_k * wrap)
    where = "set moving" if v0 else "from rest"
    notes.append(f"the rope slides over the drum ({where}, m₁ moving {'down' if sense > 0 else 'up'}): the tensions take the capstan ratio "
                 f"e^(μk·β) = {fmt(ratio, 6)}, the tight side the one it moves towards" + (" (held: a is the start's)" if v0 and holds else ""))
    if v0 and stop and motion.stop is not None:
        notes.append("once the rope stops it " + ("holds (μs)" if holds else "slides back the other way"))
    tight = "T₁ = E·T₂" if sense > 0 else "T₂ = E·T₁"
    formula = "a = g(m₁ − E m₂)/(m₁ + E m₂)" if sense > 0 else "a = g(E m₁ − m₂)/(E m₁ + m₂)"
    numbers = (f"{term(g, 'm/s**2')} × ({term(m1, 'kg')} − {fmt(ratio)} × {term(m2, 'kg')}) / ({term(m1, 'kg')} + {fmt(ratio)} × {term(m2, 'kg')})" if sense > 0 else
               f"{term(g, 'm/s**2')} × ({fmt(ratio)} × {term(m1, 'kg')} − {term(m2, 'kg')}) / ({fmt(ratio)} × {term(m1, 'kg')} + {term(m2, 'kg')})")
    steps = DeferredSteps(lambda: [
        *hold_steps,
        Step("For m₁ and m₂", "m₁g − T₁ = m₁a,  T₂ − m₂g = m₂a", "", "", "each mass's weight and its side's tension (a positive with m₁ moving down)"),
        Step("The rope slides: the tensions take the capstan ratio", f"{tight},  E = e^(μk·β)", f"e^({fmt(mu_k)} × {term(wrap, 'rad')})", fmt(ratio),
             "kinetic friction along the wrap makes the tension grow by e^(μk·β) towards the side the rope moves to"),
        Step("Solve for the masses", formula, numbers, quantity_text(a, "m/s**2"), "the tensions from the masses' equations, put into the capstan ratio"),
        Step("The tensions", "T₁ = m₁(g − a),  T₂ = m₂(g + a)", f"{term(m1, 'kg')} × ({term(g, 'm/s**2')} − {term(a, 'm/s**2')});  "
             f"{term(m2, 'kg')} × ({term(g, 'm/s**2')} + {term(a, 'm/s**2')})", f"T₁ = {quantity_text(tension1, 'N')}, T₂ = {quantity_text(tension2, 'N')}",
             "each mass's own equation"),
    ])
    model = "rope over a fixed drum (capstan friction): it slides"
    return Report("atwood", model, "closed form", results, steps, notes, trajectory=deferred(trajectory, motion, distance, time, results))
