"""A yo-yo spun in place: its string pulled up just hard enough that its centre stays put.

    m a = T − m g = 0    ⇒  T = m g
    I α = T r            ⇒  α = m g r / I = g r / k²,    k² = I/m (the body's radius of gyration, squared)
    the hand:  a_hand = r α = g r² / k²

(the string leaves the axle at r, so its free end moves at r ω above the still centre). After the
hand has pulled a length L of string (θ = L/r): ω² = ω₀² + 2αθ = ω₀² + 2 g L / k²: the hand's
work T L = m g L all goes into spin, and r cancels. A uniform disc wound at its rim (k² = R²/2)
needs a_hand = 2g and turns at α = 2g/R.
"""

from __future__ import annotations

import math

from taucli.core.errors import InputError
from taucli.options.rolling import COMMAND as TABLE
from taucli.writing.report import DeferredSteps, Report, Step, fmt, quantity_text, term
from taucli.options.table import Results


def solve_in_place(
    description: str, gyration2: float, mass: float | None, axle: float | None, g: float, *, omega0: float = 0.0, length: float | None = None
) -> Report:
    """The pull that holds a yo-yo's centre still, and what it does to the spin. ``gyration2`` is
    I/m (m²), ``axle`` the radius r the string leaves from (None: unknown, so α and the hand's
    acceleration are too), ``length`` the string the hand pulls, ``omega0`` the spin at the start."""
    if omega0 < 0:
        raise InputError("omega0", "expected 0 or a spin that unwinds the string (a yo-yo spun in place turns one way)", example="{omega0} 14rad/s")
    notes: list[str] = []
    alpha = None if axle is None else g * axle / gyration2
    results = Results(TABLE)
    results.put("a", 0.0, ", downward")
    results.put("alpha", alpha)
    results.put("T", None if mass is None else mass * g)
    results.put("a_hand", None if axle is None else g * axle * axle / gyration2)
    if axle is None:
        notes.append("alpha, a_hand: give --axle-radius or --radius (where the string leaves the body); T and ω do not need it")
    if mass is None:
        notes.append("T: give --mass (the pull is the weight it holds up)")
    omega = None
    if length is not None:
        part = f" after the hand pulls {fmt(length)} m of string"
        omega = math.sqrt(omega0 * omega0 + 2 * g * length / gyration2)
        results.put("omega", omega, part)
        results.put("t", None if axle is None else 2 * length / (axle * (omega + omega0)), f" to pull {fmt(length)} m of string")
        if mass is not None:
            results.put("KE_rot", 0.5 * mass * gyration2 * omega * omega, part)
            results.put("KE", 0.5 * mass * gyration2 * omega * omega, part + " (all of it rotation)")
    steps = DeferredSteps(_steps, gyration2, mass, axle, g, omega0, length, omega, alpha)
    where = "" if axle is None else f" at r = {fmt(axle)} m"
    model = f"yo-yo spun in place: {description} (I/m = {fmt(gyration2)} m²), its string pulled up{where} so that its centre stays put"
    return Report("rolling", model, "closed form", results, steps, notes)


def _steps(gyration2, mass, axle, g, omega0, length, omega, alpha) -> list[Step]:
    steps = [
        Step("The centre stays put (up positive)", "m a = T − m g = 0  ⇒  T = m g",
             "" if mass is None else f"{term(mass, 'kg')} × {term(g, 'm/s**2')}", "" if mass is None else quantity_text(mass * g, "N"),
             "the string's pull is all that holds up the weight"),
        Step("Rotation about the centre", "I α = T r  ⇒  α = m g r / I = g r / k²,  k² = I/m",
             "" if axle is None else f"{term(g, 'm/s**2')} × {term(axle, 'm')} / {term(gyration2, 'm**2')}",
             "" if alpha is None else quantity_text(alpha, "rad/s**2"), "the string leaves the axle r from the centre"),
    ]
    if axle is not None:
        steps.append(Step("How fast the hand must pull", "a_hand = r α = g r² / k²", f"{term(axle, 'm')} × {term(alpha, 'rad/s**2')}",
                          quantity_text(axle * alpha, "m/s**2"), "the string unwinds at r ω above a centre at rest, so its end accelerates at r α"))
    if omega is not None:
        steps.append(Step("Spin after the hand pulls L of string", "ω² = ω₀² + 2 α (L/r) = ω₀² + 2 g L / k²",
                          f"√(({term(omega0, 'rad/s')})² + 2 × {term(g, 'm/s**2')} × {term(length, 'm')} / {term(gyration2, 'm**2')})",
                          quantity_text(omega, "rad/s"), "the hand's work T L = m g L all goes into spin: ½ I (ω² − ω₀²) = m g L"))
    return steps
