"""A yo-yo: a body falling as its string, fixed above and wound on its axle, unwinds; and one
pulled or held besides by a second force (a hand, a second string, a rope run under the body).

With a vertical pull F (up positive) whose line passes d from the centre on the far side from the
string (d < 0: the string's side), a down positive, α positive as the string unwinds:

    m a = m g − T − F,   I α = T r − F d,   a = r α
    ⇒  a = (g − F (1 + d/r)/m) / (1 + q),   T = q m a + F d/r,   q = I/(m r²)

The string only pulls (T ≥ 0); the pulled point moves up at −a (1 + d/r) (a rope run under the
body and up the far side, d = r: twice the centre's speed), so the pull does the work
W = −F (1 + d/r) x over a drop x, and KE − KE₀ = m g x + W (the fixed string does none).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from taucli.core.errors import InputError
from taucli.options.rolling import COMMAND as TABLE
from taucli.writing.report import DeferredSteps, Report, Step, Trajectory, deferred, fmt, quantity_text, term
from taucli.scenes.rolling.body import Roller
from taucli.scenes.rolling.drum import Drum, solve_yoyo_on_drum
from taucli.options.table import Results


@dataclass(frozen=True)
class YoyoPull:
    """A vertical force F on the yo-yo besides its string (up positive), its line ``at`` d from the
    centre on the far side from the string (negative: the string's side)."""

    force: float
    at: float = 0.0

    def gearing(self, r: float | None) -> float:
        """1 + d/r: how far the pulled point moves for each metre the centre drops (upward)."""
        if self.at == 0:
            return 1.0
        if r is None:
            raise InputError("radius", "is required with {pull_at} (the pulled point moves 1 + d/r times as far as the centre)", example="{radius} 0.1m")
        return 1.0 + self.at / r


def solve_yoyo(
    roller: Roller, g: float, *, axle: float | None = None, height: float | None = None, v0: float = 0.0, about_axle: float | None = None,
    pull: YoyoPull | None = None, time: float | None = None, drum: Drum | None = None,
) -> Report:
    """A yo-yo: the string, fixed above, unwinds from the axle of radius r (default R):

        m a = m g − T,   I α = T r,   a = r α   ⇒   a = g / (1 + I/(m r²)),  T = m g · q/(1 + q)

    with q = I/(m r²) = k² (R/r)²: with r = R neither mass nor radius enters a. ``about_axle``: the
    body's k2 is already I/(m r²) for a string wound at that r (I given, the outer radius unknown).
    ``pull``: a second force on the body (the module's docstring); ``time``: the state after it;
    ``drum``: the string's top end wound on a drum that turns (drum.py).
    """
    k2, mass, radius = roller.k2, roller.mass, roller.radius
    notes: list[str] = []
    if about_axle is not None:
        ratio, r = k2, about_axle
    elif axle is not None and radius is None:
        raise InputError("radius", "is required with {axle_radius} (I/(m r²) = k² R²/r²)", example="{radius} 0.03m")
    elif axle is not None and axle > radius:
        raise InputError("axle_radius", "must lie within the body's radius", example="{axle_radius} 0.005m", got=f"{fmt(axle)} m > R = {fmt(radius)} m")
    if about_axle is None:
        if axle is None:
            notes.append("no --axle-radius: the string is wound at the body's own radius (r = R)")
        ratio = k2 if axle is None else k2 * (radius / axle) ** 2  # q = I/(m r²)
        r = axle if axle is not None else radius
    if height is not None and time is not None:
        raise InputError("time", "conflicts with {height}: the run ends after a drop or after a time, not both", example="{time} 3s, or {height} 1m")
    if drum is not None:
        if v0:
            raise InputError("v0", "does not apply with a drum: a yo-yo thrown down on a turning drum has its speed shared between its own spin and "
                             "the drum's in a way the throw does not say (it starts from rest)", example="{height} 1m")
        return solve_yoyo_on_drum(roller, g, drum, ratio=ratio, r=r, height=height, time=time, force=0.0 if pull is None else pull.force,
                                  at=0.0 if pull is None else pull.at, pulled=pull is not None, model=_model(roller, k2, ratio, axle, about_axle, pull), notes=notes)
    gearing = 1.0
    if pull is None:
        a = g / (1 + ratio)
        tension = None if mass is None else mass * g * ratio / (1 + ratio)
    else:
        if mass is None:
            raise InputError("mass", "is required with {pull} on a yo-yo: the pull's share of the acceleration is F/m", example="{mass} 2kg")
        gearing = pull.gearing(r)
        a = (g - pull.force * gearing / mass) / (1 + ratio)
        tension = ratio * mass * a + (0.0 if pull.at == 0 else pull.force * pull.at / r)
        if tension < -1e-12 * (mass * g + abs(pull.force)):
            raise InputError("pull", f"would leave the yo-yo's string slack (a string only pulls: its tension would be {fmt(tension)} N); "
                             "a smaller pull, or its line on the far side from the string ({pull_at} positive)", example="{pull} 5N")
        tension = max(tension, 0.0)
    results = Results(TABLE)
    results.put("a", a, ", downward")
    results.put("alpha", None if r is None else a / r)
    results.put("T", tension)
    if pull is not None:
        results.put("a_hand", -a * gearing, " (where the pull acts)")
    if mass is None:
        notes.append("T: give --mass (a does not need it)")
    if r is None:
        notes.append("alpha: give --radius (a does not need it)")
    end = None
    if height is not None:
        end = _after_drop(results, a, v0, height, r, mass, ratio, pull, gearing)
    elif time is not None:
        end = time
        part = f" after {fmt(time)} s"
        speed, drop = v0 + a * time, v0 * time + a * time * time / 2
        results.put("v", speed, part + ", downward" + ("" if speed >= 0 else " (negative: rising)"))
        results.put("omega", None if r is None else speed / r, part + (", unwinding" if speed >= 0 else " (negative: winding up the string)"))
        results.put("drop", drop, part + ("" if drop >= 0 else " (negative: risen)"))
        _energies(results, part, mass, ratio, speed, pull, gearing, drop)
    if pull is None:
        steps = DeferredSteps(_yoyo_steps, ratio, a, tension, results if height is not None else None, g, mass, v0, height, r)
    else:
        steps = DeferredSteps(_pulled_steps, ratio, a, tension, g, mass, r, pull, gearing, results, v0, end)
    model = _model(roller, k2, ratio, axle, about_axle, pull)
    trajectory = deferred(_yoyo_trajectory, a, v0, end, "end of the drop" if height is not None else "the time asked")
    return Report("rolling", model, "closed form", results, steps, notes, trajectory=trajectory)


def _model(roller: Roller, k2: float, ratio: float, axle: float | None, about_axle: float | None, pull: YoyoPull | None) -> str:
    model = f"yo-yo: {roller.description} (k² = I/mR² = {fmt(k2)}) falling as its string unwinds" + ("" if axle is None else f" from an axle of radius {fmt(axle)} m")
    if about_axle is not None:
        model = f"yo-yo: body (I/(m r²) = {fmt(ratio)}) falling as its string unwinds from an axle of radius {fmt(about_axle)} m"
    if pull is not None:
        where = "through the centre" if pull.at == 0 else f"{fmt(abs(pull.at))} m from the centre on the {'far' if pull.at > 0 else 'string'}'s side"
        model += f", pulled up by {fmt(pull.force)} N {where}".replace("far's", "far")
    return model


def _after_drop(results, a, v0, height, r, mass, ratio, pull, gearing) -> float:
    """v, ω, t (and the energies) after a drop h from v0; the drop must be reached."""
    square = v0 * v0 + 2 * a * height
    if square < 0 or (v0 <= 0 and a <= 0 and height > 0):
        raise InputError("height", f"is never reached: the yo-yo's acceleration is {fmt(a)} m/s² (downward) from {fmt(v0)} m/s, so it does not drop "
                         f"{fmt(height)} m", example="{time} 1s, or a smaller {pull}")
    part = f" after a drop of {fmt(height)} m"
    speed = math.sqrt(square)
    duration = 2 * height / (v0 + speed) if v0 > 0 or (v0 == 0 and a > 0) else (speed - v0) / a  # sums of positive terms
    results.put("v", speed, part + ("" if v0 else ", from rest"))
    results.put("omega", None if r is None else speed / r, part)
    results.put("t", duration, f" to drop {fmt(height)} m")
    _energies(results, part, mass, ratio, speed, pull, gearing, height)
    return duration


def _energies(results, part, mass, ratio, speed, pull, gearing, drop) -> None:
    if mass is None:
        return
    results.put("KE_trans", 0.5 * mass * speed * speed, part)
    results.put("KE_rot", 0.5 * ratio * mass * speed * speed, part)
    results.put("KE", 0.5 * (1 + ratio) * mass * speed * speed, part)
    if pull is not None:
        results.put("work_pull", -pull.force * gearing * drop, part)


def _yoyo_steps(ratio, a, tension, results, g=None, mass=None, v0=0.0, height=None, r=None) -> list[Step]:
    steps = [
        Step("For the yo-yo's centre (down positive)", "m a = m g − T", "", "", "gravity down, the string's tension up"),
        Step("Rotation about the centre", "I α = T r", "", "", "the string leaves the axle at r from the centre"),
        Step("The string unwinds without slipping", "a = r α", "", "", "the point where the string leaves is momentarily at rest"),
        Step("Solve", "a = g / (1 + I/(m r²)),  T = m g (I/(m r²)) / (1 + I/(m r²))",
             f"I/(m r²) = {fmt(ratio)}:  a = {term(g, 'm/s**2')} / (1 + {fmt(ratio)})"
             + ("" if mass is None else f",  T = {term(mass, 'kg')} × {term(g, 'm/s**2')} × {fmt(ratio)} / (1 + {fmt(ratio)})"),
             quantity_text(a, "m/s**2") + ("" if tension is None else f", T = {quantity_text(tension, 'N')}"),
             "T r = I a / r from the rotation; put into the translation equation"),
    ]
    if results is not None:
        speed = results["v"].value
        numbers = f"√(({term(v0, 'm/s')})² + 2 × {term(a, 'm/s**2')} × {term(height, 'm')})" + ("" if r is None else f",  {term(speed, 'm/s')} / {term(r, 'm')}")
        shown = quantity_text(speed, "m/s") + ("" if r is None else f", ω = {quantity_text(results['omega'].value, 'rad/s')}")
        steps.append(Step("After the drop", "v = √(v₀² + 2 a h),  ω = v / r", numbers, shown,
                          "constant a; energy: m g h = ½ m v² (1 + I/(m r²)) − ½ m v₀² (1 + I/(m r²))"))
    return steps


def _pulled_steps(ratio, a, tension, g, mass, r, pull, gearing, results, v0, end) -> list[Step]:
    force = pull.force
    steps = [
        Step("For the yo-yo's centre (down positive)", "m a = m g − T − F", "", "", "gravity down; the string's tension and the pull F up"),
        Step("Rotation about the centre (the unwinding sense)", "I α = T r − F d", "", "",
             "the string leaves the axle r from the centre; the pull's line passes d from it on the far side"),
        Step("The string unwinds without slipping", "a = r α", "", "", "the point where the string leaves is momentarily at rest"),
        Step("Solve", "a = (g − F (1 + d/r)/m) / (1 + I/(m r²)),  T = (I/(m r²)) m a + F d/r",
             f"I/(m r²) = {fmt(ratio)}, 1 + d/r = {fmt(gearing)}:  a = ({term(g, 'm/s**2')} − {term(force, 'N')} × {fmt(gearing)} / {term(mass, 'kg')})"
             f" / (1 + {fmt(ratio)})", quantity_text(a, "m/s**2") + f", T = {quantity_text(tension, 'N')}",
             "T from the rotation, put into the translation equation; a negative a: the yo-yo climbs its string"),
        Step("Where the pull acts", "a_hand = −a (1 + d/r)  (upward)", f"−{term(a, 'm/s**2')} × {fmt(gearing)}", quantity_text(-a * gearing, "m/s**2"),
             "the body turns about the point where the string leaves it, r + d from the pulled point"),
    ]
    if end is not None and "v" in results:
        speed = results["v"].value
        drop = results["drop"].value if "drop" in results else None
        if drop is not None:
            steps.append(Step("After the time", "v = v₀ + a t,  x = v₀ t + ½ a t²,  ω = v / r",
                              f"{term(v0, 'm/s')} + {term(a, 'm/s**2')} × {term(end, 's')}" + ("" if r is None else f",  {term(speed, 'm/s')} / {term(r, 'm')}"),
                              quantity_text(speed, "m/s") + f", x = {quantity_text(drop, 'm')}"
                              + ("" if r is None else f", ω = {quantity_text(results['omega'].value, 'rad/s')}"), "constant a: the forces do not change"))
        if "work_pull" in results:
            steps.append(Step("Energy", "KE − KE₀ = m g x + W_pull,  W_pull = −F (1 + d/r) x", "", quantity_text(results["work_pull"].value, "J"),
                              "the fixed string does no work: the point where it leaves the body is at rest"))
    return steps


def _yoyo_trajectory(a: float, v0: float, end: float | None, mark: str) -> Trajectory:
    curves = (("x", "m", "drop, downward"), ("v", "m/s", "velocity, downward"))
    if end is None:
        return Trajectory(curves, 1.0, lambda t: (v0 * t + a * t * t / 2, v0 + a * t), note="plotted for 1 s; --height or --time to change")
    return Trajectory(curves, end, lambda t: (v0 * t + a * t * t / 2, v0 + a * t), marks=((end, mark),))
