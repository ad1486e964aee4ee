"""A yo-yo whose string is wound at its top end on a drum that turns on a fixed horizontal axle
(Irodov 1.258: two identical solid cylinders, the lower one hanging from threads wound on both;
Kleppner & Kolenkow 7.24, two drums): the body's fall is shared between its own unwinding and the
drum's.

The body (mass m, I about its centre, the string leaving it r from the centre), the drum (I_d, the
string leaving it R from its axle, a friction torque τ_f at the axle while it turns), a vertical
pull F on the body whose line passes d from the centre on the far side from the string (#46 item
1); a down positive, α and α_d positive as the string unwinds from each:

    m a = m g − T − F,   I α = T r − F d,   I_d α_d = T R − τ_f,   a = r α + R α_d

With q = I/(m r²), Q = I_d/(m R²), f = F/m, δ = d/r, φ = τ_f/(m R) and D = q Q + q + Q:

    T/m = (q Q (g − f) + Q f δ + q φ) / D
    a   = (Q (g − f (1 + δ)) + q (g − f − φ)) / D
    r α = (Q (g − f (1 + δ)) + φ − f δ) / D          (the body's share of a)
    R α_d = (q (g − f − φ) + f δ − φ) / D            (the drum's share)

each a numerator over D (no difference of the solved values). Q → ∞ gives back the plain yo-yo,
a = (g − f (1 + δ))/(1 + q). A string only pulls (T ≥ 0), so the drum, at rest at the start, is
only ever turned one way: it stays put while the plain yo-yo's T R ≤ τ_f (its axle friction holds
it), and then the plain yo-yo is the answer.

From rest, after a time t: v = a t, ω = α t, ω_d = α_d t; energy:
½ m v² + ½ I ω² + ½ I_d ω_d² = m g x − F (x + d θ) − τ_f θ_d.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from taucli.core.errors import InputError
from taucli.options.rolling import COMMAND as TABLE
from taucli.options.table import Results
from taucli.scenes.rolling.body import Roller
from taucli.writing.report import DeferredSteps, Report, Step, Trajectory, deferred, fmt, quantity_text, term


@dataclass(frozen=True)
class Drum:
    """The drum the yo-yo's string is wound on: its moment of inertia about its axle (or its mass,
    a uniform solid cylinder, I_d = M R²/2, with ``by_mass``), the radius R the string leaves it
    at (None where not given: a uniform drum's share of a needs no R), and the friction torque at
    its axle."""

    inertia: float | None = None
    mass: float | None = None
    radius: float | None = None
    friction: float = 0.0

    def relative(self, body_mass: float) -> float:
        """Q = I_d/(m R²): the drum's inertia as a mass at its rim, over the body's mass."""
        if self.mass is not None:
            return self.mass / (2 * body_mass)
        return self.inertia / (body_mass * self.radius**2)

    @property
    def description(self) -> str:
        return "a drum (a uniform solid cylinder)" if self.mass is not None else "a drum"


def given_drum(drum_mass: float | None, drum_inertia: float | None, drum_radius: float | None, drum_friction: float | None) -> Drum | None:
    """The drum from its options, or None where none is given; what each form needs."""
    if drum_mass is None and drum_inertia is None:
        for name, value in (("drum_radius", drum_radius), ("drum_friction", drum_friction)):
            if value is not None:
                raise InputError(name, "needs {drum_mass} or {drum_inertia} (the drum the yo-yo's string is wound on)", example="{drum_mass} 1kg")
        return None
    if drum_mass is not None and drum_inertia is not None:
        raise InputError("drum_inertia", "conflicts with {drum_mass}: give the drum by its mass (a uniform cylinder) or by its moment of inertia",
                         example="{drum_inertia} '0.005 kg*m^2' {drum_radius} 0.1m")
    if drum_inertia is not None and drum_radius is None:
        raise InputError("drum_radius", "is required with {drum_inertia} (the drum's share of the fall is T R²/I_d)", example="{drum_radius} 0.1m")
    if drum_friction is not None and drum_radius is None:
        raise InputError("drum_radius", "is required with {drum_friction} (the string's pull T R against the friction torque)", example="{drum_radius} 0.1m")
    return Drum(drum_inertia, drum_mass, drum_radius, drum_friction or 0.0)


def solve_yoyo_on_drum(
    roller: Roller, g: float, drum: Drum, *, ratio: float, r: float | None, height: float | None = None, time: float | None = None,
    force: float = 0.0, at: float = 0.0, pulled: bool = False, model: str = "", notes: list[str] | None = None,
) -> Report:
    """The yo-yo of body ``roller`` (q = I/(m r²) = ``ratio``, the string leaving it at ``r``, None
    where no radius is given) on ``drum``: a, T, the body's and the drum's α (and after ``height``
    or ``time``, from rest: v, ω, ω_d, the energies). ``force`` and ``at``: a pull F on the body,
    its line d from the centre (the module's docstring); ``notes``: the yo-yo's own, to keep."""
    mass = roller.mass
    if mass is None:
        raise InputError("mass", "is required with a drum: the drum's share of the fall is I_d/(m R²), against the body's mass", example="{mass} 1kg")
    if height is not None and time is not None:
        raise InputError("time", "conflicts with {height}: the run ends after a drop or after a time, not both", example="{time} 3s, or {height} 1m")
    if at != 0 and r is None:
        raise InputError("radius", "is required with {pull_at} (the pull's torque F d against the string's T r)", example="{radius} 0.1m")
    q, big_q = ratio, drum.relative(mass)
    f, delta = force / mass, (0.0 if at == 0 else at / r)
    phi = 0.0 if drum.friction == 0 else drum.friction / (mass * drum.radius)
    held = phi > 0 and (q * (g - f) + f * delta) <= phi * (1 + q)  # the plain yo-yo's T R ≤ τ_f: the drum's friction holds it
    if held:
        a = (g - f * (1 + delta)) / (1 + q)
        per_mass, a_body, a_drum = (q * (g - f) + f * delta) / (1 + q), a, 0.0
    else:
        d = q * big_q + q + big_q
        per_mass = (q * big_q * (g - f) + big_q * f * delta + q * phi) / d
        a = (big_q * (g - f * (1 + delta)) + q * (g - f - phi)) / d
        a_body = (big_q * (g - f * (1 + delta)) + phi - f * delta) / d
        a_drum = (q * (g - f - phi) + f * delta - phi) / d
    tension = mass * per_mass
    if tension < -1e-12 * (mass * g + abs(force)):
        raise InputError("pull", f"would leave the yo-yo's string slack (a string only pulls: its tension would be {fmt(tension)} N); "
                         "a smaller pull, or its line on the far side from the string ({pull_at} positive)", example="{pull} 5N")
    tension = max(tension, 0.0)
    results = Results(TABLE)
    results.put("a", a, ", downward")
    results.put("alpha", None if r is None else a_body / r, " of the body, unwinding")
    results.put("T", tension)
    results.put("alpha_drum", None if drum.radius is None else a_drum / drum.radius)
    if pulled:
        results.put("a_hand", -(a + a_body * delta), " (where the pull acts)")
    notes = list(notes or []) + ([] if drum.radius is not None else ["alpha_drum: give --drum-radius (a does not need it for a uniform drum)"])
    if r is None:
        notes.append("alpha: give --radius (a does not need it)")
    if held:
        notes.append(f"the drum's axle friction ({fmt(drum.friction)} N·m) holds it: the string's pull T R = {fmt(tension * drum.radius)} N·m is no more")
    end = _the_end(results, a, a_body, a_drum, height, time, r, drum, mass, q, big_q, force, delta, phi)
    steps = DeferredSteps(_steps, q, big_q, f, delta, phi, g, a, per_mass, a_body, a_drum, mass, held, results, end, pulled)
    # no input's value in the model's words: a value moved within its uncertainty is no change of model
    shown = f"{model}; its string's top end wound on {drum.description} turning on a fixed axle"
    if drum.friction:
        shown += ", against a friction torque at its axle" + (" that holds it" if held else "")
    trajectory = deferred(_trajectory, a, end, "end of the drop" if height is not None else "the time asked")
    return Report("rolling", shown, "closed form", results, steps, notes, trajectory=trajectory)


def _the_end(results, a, a_body, a_drum, height, time, r, drum, mass, q, big_q, force, delta, phi) -> float | None:
    """After a drop ``height`` or a ``time`` from rest: v, ω, ω_d, t or the drop, the energies."""
    if height is not None:
        if a <= 0:
            raise InputError("height", f"is never reached: the yo-yo's acceleration is {fmt(a)} m/s² (downward) from rest, so it does not drop "
                             f"{fmt(height)} m", example="{time} 1s, or a smaller {pull}")
        end, part = math.sqrt(2 * height / a), f" after a drop of {fmt(height)} m"
        results.put("v", math.sqrt(2 * a * height), part + ", from rest")
    elif time is not None:
        end, part = time, f" after {fmt(time)} s"
        speed = a * time
        results.put("v", speed, part + ", downward" + ("" if speed >= 0 else " (negative: rising)"))
    else:
        return None
    results.put("omega", None if r is None else a_body * end / r, part + ", the body's")
    results.put("omega_drum", None if drum.radius is None else a_drum * end / drum.radius, part)
    if height is not None:
        results.put("t", end, f" to drop {fmt(height)} m")
        drop = height
    else:
        drop = a * end * end / 2
        results.put("drop", drop, part + ("" if drop >= 0 else " (negative: risen)"))
    speed, rim_body, rim_drum = results["v"].value, a_body * end, a_drum * end  # r ω and R ω_d
    results.put("KE_trans", 0.5 * mass * speed * speed, part)
    results.put("KE_rot", 0.5 * q * mass * rim_body * rim_body, part + ", the body's spin")
    results.put("KE_drum", 0.5 * big_q * mass * rim_drum * rim_drum, part)
    results.put("KE", results["KE_trans"].value + results["KE_rot"].value + results["KE_drum"].value, part + ", body and drum")
    if force:
        results.put("work_pull", -force * (drop + delta * rim_body * end / 2), part)  # −F (x + d θ), d θ = δ (r θ)
    if phi:
        results.put("work_drum_friction", mass * phi * rim_drum * end / 2, part)  # τ_f θ_d = m φ (R θ_d)
    return end


def _steps(q, big_q, f, delta, phi, g, a, per_mass, a_body, a_drum, mass, held, results, end, pulled) -> list[Step]:
    pull = " − F" if pulled else ""
    steps = [
        Step("For the body's centre (down positive)", f"m a = m g − T{pull}", "", "", "gravity down, the string's tension up" + (", the pull F up" if pulled else "")),
        Step("The body's spin about its centre", "I α = T r" + (" − F d" if pulled else ""), "", "", "the string leaves the body r from its centre"),
        Step("The drum's spin about its axle", "I_d α_d = T R" + (" − τ_f" if phi else ""), f"I_d/(m R²) = Q = {fmt(big_q)}"
             + (f", τ_f/(m R) = φ = {term(phi, 'm/s**2')}" if phi else ""), "",
             "the string leaves the drum R from its axle" + ("; the axle's friction opposes its turning" if phi else "")),
        Step("The string does not stretch", "a = r α + R α_d", "", "", "the string unwound from the body and from the drum together is the drop"),
    ]
    if held:
        plain = "a = (g − f (1 + d/r)) / (1 + q),  f = F/m" if pulled else "a = g / (1 + q),  T = m g q / (1 + q)"
        steps.append(Step("The drum holds", f"T R ≤ τ_f with α_d = 0:  {plain}", f"q = I/(m r²) = {fmt(q)}",
                          quantity_text(a, "m/s**2") + f", T = {quantity_text(mass * per_mass, 'N')}",
                          "the plain yo-yo's tension cannot beat the axle's friction, so the drum stays put"))
    else:
        numbers = f"q = I/(m r²) = {fmt(q)}, Q = I_d/(m R²) = {fmt(big_q)}, D = q Q + q + Q = {fmt(q * big_q + q + big_q)}"
        if pulled:
            numbers += f", f = {term(f, 'm/s**2')}, d/r = {fmt(delta)}"
        if phi:
            numbers += f", φ = {term(phi, 'm/s**2')}"
        if pulled or phi:
            numbers += f", g = {term(g, 'm/s**2')}"
        if pulled or phi:
            equation = "T = m (q Q (g − f) + Q f d/r + q φ) / D,  a = (Q (g − f (1 + d/r)) + q (g − f − φ)) / D,  f = F/m, φ = τ_f/(m R)"
            why = "α = (T r − F d)/I and α_d = (T R − τ_f)/I_d put into the string's condition, then into the centre's equation"
        else:
            equation = "T = m g q Q / D,  a = g (q + Q) / D"
            numbers += f":  T = {term(mass, 'kg')} × {term(g, 'm/s**2')} × {fmt(q)} × {fmt(big_q)} / {fmt(q * big_q + q + big_q)}"
            why = "α = T r/I and α_d = T R/I_d put into the string's condition, then into the centre's equation"
        steps.append(Step("Solve the four together", equation, numbers, f"T = {quantity_text(mass * per_mass, 'N')}, a = {quantity_text(a, 'm/s**2')}", why))
        steps.append(Step("Each one's share of the drop", "r α = (T − F d/r)/(m q),  R α_d = (T − τ_f/R)/(m Q)", "",
                          f"r α = {quantity_text(a_body, 'm/s**2')}, R α_d = {quantity_text(a_drum, 'm/s**2')}",
                          "the body's spin is no longer a/r: the drum unwinds its share"))
    if end is not None and "KE" in results:
        losses = (" − F (x + d θ)" if pulled else "") + (" − τ_f θ_d" if phi else "")
        steps.append(Step("Energy", f"½ m v² + ½ I ω² + ½ I_d ω_d² = m g x{losses}",
                          f"{term(results['KE_trans'].value, 'J')} + {term(results['KE_rot'].value, 'J')} + {term(results['KE_drum'].value, 'J')}",
                          quantity_text(results["KE"].value, "J"), "from rest, constant a, α and α_d: v = a t, ω = α t, ω_d = α_d t"))
    return steps


def _trajectory(a, end, mark) -> Trajectory:
    curves = (("x", "m", "drop, downward"), ("v", "m/s", "velocity, downward"))
    motion = lambda t: (a * t * t / 2, a * t)  # noqa: E731
    if end is None:
        return Trajectory(curves, 1.0, motion, note="plotted for 1 s; --height or --time to change")
    return Trajectory(curves, end, motion, marks=((end, mark),))
