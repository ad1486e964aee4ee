"""A yo-yo: a body falling as its string, fixed above and wound on its axle, unwinds."""

from __future__ import annotations

import math

from taucli.core.errors import InputError
from taucli.options.rolling import COMMAND as TABLE
from taucli.writing.report import DeferredSteps, Report, Step, Trajectory, deferred, fmt, quantity_text, term
from taucli.scenes.rolling.body import Roller
from taucli.options.table import Results


def solve_yoyo(
    roller: Roller, g: float, *, axle: float | None = None, height: float | None = None, v0: float = 0.0, about_axle: float | None = None
) -> Report:
    """A yo-yo: the string, fixed above, unwinds from the axle of radius r (default R):

        m a = m g − T,   I α = T r,   a = r α   ⇒   a = g / (1 + I/(m r²)),  T = m g · q/(1 + q)

    with q = I/(m r²) = k² (R/r)²: with r = R neither mass nor radius enters a. ``about_axle``: the
    body's k2 is already I/(m r²) for a string wound at that r (I given, the outer radius unknown).
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
    a = g / (1 + ratio)
    tension = None if mass is None else mass * g * ratio / (1 + ratio)
    results = Results(TABLE)
    results.put("a", a, ", downward")
    results.put("alpha", None if r is None else a / r)
    results.put("T", tension)
    if mass is None:
        notes.append("T: give --mass (a does not need it)")
    if r is None:
        notes.append("alpha: give --radius (a does not need it)")
    if height is not None:
        part = f" after a drop of {fmt(height)} m"
        speed = math.sqrt(v0 * v0 + 2 * a * height)
        duration = 2 * height / (v0 + speed) if v0 >= 0 else (speed - v0) / a  # sums of positive terms
        results.put("v", speed, part + ("" if v0 else ", from rest"))
        results.put("omega", None if r is None else speed / r, part)
        results.put("t", duration, f" to drop {fmt(height)} m")
        if mass is not None:
            results.put("KE_trans", 0.5 * mass * speed * speed, part)
            results.put("KE_rot", 0.5 * ratio * mass * speed * speed, part)
            results.put("KE", 0.5 * (1 + ratio) * mass * speed * speed, part)
    steps = DeferredSteps(_yoyo_steps, ratio, a, tension, results if height is not None else None, g, mass, v0, height, r)
    model = f"yo-yo: {roller.description} (k² = I/mR² = {fmt(k2)}) falling as its string unwinds" + ("" if axle is None else f" from an axle of radius {fmt(axle)} m")
    if about_axle is not None:
        model = f"yo-yo: body (I/(m r²) = {fmt(ratio)}) falling as its string unwinds from an axle of radius {fmt(about_axle)} m"
    trajectory = deferred(_yoyo_trajectory, a, v0, results)
    return Report("rolling", model, "closed form", results, steps, notes, trajectory=trajectory)


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


def _yoyo_trajectory(a: float, v0: float, results) -> Trajectory:
    curves = (("x", "m", "drop, downward"), ("v", "m/s", "velocity, downward"))
    end = results["t"].value if "t" in results else None
    if end is None:
        return Trajectory(curves, 1.0, lambda t: (v0 * t + a * t * t / 2, v0 + a * t), note="plotted for 1 s; --height to change")
    return Trajectory(curves, end, lambda t: (v0 * t + a * t * t / 2, v0 + a * t), marks=((end, "end of the drop"),))

