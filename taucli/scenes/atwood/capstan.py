"""A string that may slide over the pulley's rim: the capstan limit on the ratio of the tensions
either side of a wrap, T_high/T_low ≤ e^{μβ}, decides whether it grips or slides.
"""

from __future__ import annotations

import math

from taucli.options.atwood import COMMAND as TABLE
from taucli.writing.report import DeferredSteps, Report, Step, deferred, fmt, quantity_text, term
from taucli.scenes.atwood.machine import Machine, solve_machine
from taucli.scenes.atwood.pulley import Pulley
from taucli.scenes.atwood.travel import evolve_exact, put_motion, trajectory
from taucli.scenes.motion import Loads
from taucli.options.table import Results


def solve_rim(
    m1: float, m2: float, pulley: Pulley, g: float, rim_mu: float, wrap: float, *, v0: float = 0.0, distance: float | None = None,
    time: float | None = None, stop: bool = False,
) -> Report:
    """A string that may slide over the rim. The capstan limit T_high/T_low ≤ e^{μβ} decides:
    within it the string grips (``solve``'s answer); past it the string slides, the tensions are
    in the capstan ratio, and the pulley is turned by the friction alone (m1 moving down):

        m1:      m1 g − T1 = m1 a,     m2:  T2 − m2 g = m2 a,     T1 = e^{μβ} T2
        pulley:  (T1 − T2) R = I α     (the rim's own acceleration a_rim = α R < a)

    giving a = g (m1 − E m2)/(m1 + E m2), T2 = 2 m1 m2 g/(m1 + E m2), E = e^{μβ} (and the
    mirror image when m2 goes down). At μ = ln(T1/T2)/β the two answers meet.
    """
    grip = solve_machine(Machine(m1, m2, pulley, g), v0=v0, distance=distance, time=time, stop=stop)  # its checks first
    grip_tension1, grip_tension2 = grip.results["T1"].value, grip.results["T2"].value
    high, low = max(grip_tension1, grip_tension2), min(grip_tension1, grip_tension2)
    # the least μ that grips: ln(T_high/T_low)/β, with T_high − T_low = (I/R²)|a| from the pulley's
    # equation rather than the difference of two near-equal tensions (near-equal masses)
    rim_mu_min = math.log1p(pulley.effective_mass() * abs(grip.results["a"].value) / low) / wrap
    results = Results(TABLE)
    notes = [note for note in grip.notes if not note.startswith("the string taken not to slip")]
    if not pulley.effective_mass():
        notes.append("{rim_mu}: a massless pulley needs no torque, so the tensions are equal and the string always grips")
    if rim_mu >= rim_mu_min:
        for key, value in grip.results.items():
            results[key] = value
        results.put("a_rim", grip.results["a"].value)
        results.put("grips", True)
        results.put("rim_mu_min", rim_mu_min)
        notes.append(
            f"the string grips the rim: T_high/T_low = {fmt(high / low, 6)} ≤ e^(μβ) = {_exp_text(rim_mu * wrap)} "
            f"(it would slide below μ = {fmt(rim_mu_min)})"
        )
        steps = DeferredSteps(lambda: [*grip.steps, _capstan_step(high, low, rim_mu, wrap, rim_mu_min, True)])
        model = grip.model.replace("string does not slip", "string grips the rim")
        return Report("atwood", model, "closed form", results, steps, notes, trajectory=grip.trajectory)
    capstan_ratio = math.exp(rim_mu * wrap)
    growth = math.expm1(rim_mu * wrap)  # E − 1, kept accurate for small μβ
    if grip_tension1 > grip_tension2:  # m1 goes down; the tension grows along the rim towards m1
        low_side = 2 * m1 * m2 * g / (m1 + capstan_ratio * m2)
        a = g * (m1 - capstan_ratio * m2) / (m1 + capstan_ratio * m2)
        tension1, tension2, sense = capstan_ratio * low_side, low_side, 1.0
    else:
        low_side = 2 * m1 * m2 * g / (capstan_ratio * m1 + m2)
        a = g * (capstan_ratio * m1 - m2) / (capstan_ratio * m1 + m2)
        tension1, tension2, sense = low_side, capstan_ratio * low_side, -1.0
    rim_a = sense * growth * low_side / pulley.effective_mass()  # (T1 − T2) R / I × R
    results.put("a", a)
    results.put("T1", tension1)
    results.put("T2", tension2)
    results.put("alpha", None if pulley.radius is None else rim_a / pulley.radius)
    results.put("a_massless", grip.results["a_massless"].value)
    results.put("a_rim", rim_a)
    results.put("grips", False)
    results.put("rim_mu_min", rim_mu_min)
    notes.append(
        f"the string slides over the rim: gripping would need T_high/T_low = {fmt(high / low, 6)}, more than e^(μβ) = {fmt(capstan_ratio, 6)} "
        f"(μ ≥ {fmt(rim_mu_min)}); the tensions take the capstan ratio, and the pulley is turned by the sliding friction alone: "
        "a is the masses', a_rim the rim's. One coefficient, {rim_mu}, for gripping and sliding"
    )
    if pulley.radius is None:
        notes.append("alpha: give --pulley-radius for the pulley's angular acceleration (a_rim does not need it)")
    motion = evolve_exact(1.0, Loads(drive=a), v0)  # no friction that depends on the masses' speed: uniform a
    put_motion(results, motion, distance, time, notes, stop=stop)
    steps = DeferredSteps(lambda: [
        Step("For m₁ and m₂", "m₁g − T₁ = m₁a,  T₂ − m₂g = m₂a", "", "", "each mass's weight and its string's tension"),
        _capstan_step(high, low, rim_mu, wrap, rim_mu_min, False),
        Step("The string slides: the tensions take the capstan ratio", "T₁ = e^(μβ) T₂" if sense > 0 else "T₂ = e^(μβ) T₁",
             f"e^({fmt(rim_mu)} × {term(wrap, 'rad')}) = {fmt(capstan_ratio)}", f"E = {fmt(capstan_ratio)}", "sliding friction along the wrap makes the tension grow by e^(μβ) towards the side the string moves to"),
        Step("Solve for the masses", "a = g (m₁ − E m₂)/(m₁ + E m₂)" if sense > 0 else "a = g (E m₁ − m₂)/(E m₁ + m₂)",
             f"{term(g, 'm/s**2')} × ({term(m1, 'kg')} − {fmt(capstan_ratio)} × {term(m2, 'kg')}) / ({term(m1, 'kg')} + {fmt(capstan_ratio)} × {term(m2, 'kg')})"
             if sense > 0 else
             f"{term(g, 'm/s**2')} × ({fmt(capstan_ratio)} × {term(m1, 'kg')} − {term(m2, 'kg')}) / ({fmt(capstan_ratio)} × {term(m1, 'kg')} + {term(m2, 'kg')})",
             quantity_text(a, "m/s**2"), "the tensions from the masses' equations, put into the capstan ratio"),
        Step("The pulley, turned by the friction alone", "I α = (T₁ − T₂) R,  a_rim = α R = (T₁ − T₂)/(I/R²)",
             f"({term(tension1, 'N')} − {term(tension2, 'N')}) / {term(pulley.effective_mass(), 'kg')}", quantity_text(rim_a, "m/s**2"),
             "the rim lags the string: the string slides over it"),
    ])  # written when read
    model = ("massive pulley (" + pulley.words() + "), the string slides over the rim (capstan friction)")
    return Report("atwood", model, "closed form", results, steps, notes, trajectory=deferred(trajectory, motion, distance, time, results))


def _exp_text(x: float) -> str:
    """e^x as a number, or as e^x where it is beyond a float (a long wrap of a rough rim)."""
    return fmt(math.exp(x), 6) if x < 700 else f"e^{fmt(x)}"


def _capstan_step(high, low, mu, wrap, rim_mu_min, grips) -> Step:
    return Step(
        "Does the string grip? The capstan limit",
        "T_high / T_low ≤ e^(μβ)",
        f"{term(high, 'N')} / {term(low, 'N')} against e^({fmt(mu)} × {term(wrap, 'rad')})",
        f"{fmt(high / low, 6)} {'≤' if grips else '>'} {_exp_text(mu * wrap)}",
        "friction over a wrap of β can change the tension by at most a factor e^(μβ); "
        + (f"so it grips (least μ = {fmt(rim_mu_min)})" if grips else f"so it slides (gripping needs μ ≥ {fmt(rim_mu_min)})"),
    )
