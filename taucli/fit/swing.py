"""Where a pendulum's fit starts: a swing's period and amplitude, and runs of periods.

- A swing θ(t) from rest: its period and amplitude from its spectrum, which noise does not fool:
  the power |Σᵢ (θᵢ − θ̄)e^(−2πif tᵢ)|² is largest at the swing's frequency (found on a zero-padded
  FFT of the samples on an even grid, then refined on a fine grid of f about it with the samples'
  own times), and the least squares of θ − θ̄ = a cos 2πft + b sin 2πft at that f gives its
  amplitude, ±√(a² + b²) with the sign of a (a swing from rest at t = 0 is θ₀ cos 2πft to first
  order). A dense recording's noise crosses θ̄ many times near each true crossing: the period from
  the zero crossings (the alternative start) then comes out far too short. g from the period the
  scene gives at a known g: T ∝ 1/√g at a given amplitude.
- Runs of periods at their amplitudes: T = T₀ √(g₀/g) for each, linear in √(g₀/g).
"""

from __future__ import annotations

import math

import numpy as np

from taucli.core.errors import InputError
from taucli.fit.model import Model
from taucli.scenes.assumed import STANDARD_GRAVITY
from taucli.writing.report import Step, fmt, quantity_text

TITLE = "A start from the swing"  # the start's step, replaced where another start is taken
PAD = 8  # the FFT's length over the samples': its bins an eighth of 1/span apart
FINE = 201  # frequencies the peak is refined on, over ± one padded bin
SCENE_ERRORS = (InputError, KeyError, ValueError, ZeroDivisionError, OverflowError)


def spectrum(t: np.ndarray, level: np.ndarray) -> tuple[float, float] | None:
    """(frequency, signed amplitude) of the strongest oscillation in ``level`` (its mean taken
    out) at times ``t`` (sorted): at least half a period within the samples, at most Nyquist."""
    n = len(t)
    span = float(t[-1] - t[0]) if n else 0.0
    if n < 8 or not span > 0:
        return None
    even = np.interp(np.linspace(t[0], t[-1], n), t, level)
    size = PAD * 2 ** math.ceil(math.log2(n))
    power = np.abs(np.fft.rfft(even, size)) ** 2
    frequencies = np.fft.rfftfreq(size, d=span / (n - 1))
    allowed = frequencies >= 0.5 / span
    if not np.any(allowed) or not np.any(power[allowed] > 0):
        return None
    peak = float(frequencies[allowed][np.argmax(power[allowed])])
    step = float(frequencies[1])
    fine = np.linspace(max(peak - step, 0.5 / span), peak + step, FINE)
    phases = np.exp(-2j * math.pi * np.outer(fine, t))
    f = float(fine[np.argmax(np.abs(phases @ level) ** 2)])
    A = np.column_stack([np.cos(2 * math.pi * f * t), np.sin(2 * math.pi * f * t)])
    a, b = np.linalg.lstsq(A, level, rcond=None)[0]
    return f, math.copysign(math.hypot(a, b), a if a != 0 else 1.0)


def _plain(model: Model) -> bool:
    """A pendulum from rest, g and θ₀ the inputs sought: the model these starts are for."""
    held = ("torsion", "omega0", "omega_bottom")
    return not any(name in model.held or name in model.samples.inputs for name in held) and set(model.names) <= {"g", "angle0"}


def _sorted_swing(model: Model) -> tuple[np.ndarray, np.ndarray] | None:
    if not _plain(model) or set(model.samples.inputs) != {"time"} or model.samples.y_key != "theta":
        return None
    t = np.asarray(model.samples.inputs["time"], dtype=float)
    order = np.argsort(t, kind="stable")
    return t[order], np.asarray(model.samples.y, dtype=float)[order]


def _values(model: Model, period: float, amplitude: float | None) -> dict[str, float] | None:
    """g and θ₀ (those fitted) from a period and an amplitude: g = g₀ (T₀/T)², T₀ the scene's period at g₀."""
    found: dict[str, float] = {}
    if "angle0" in model.names:
        found["angle0"] = amplitude
    else:
        amplitude = model.si.get("angle0")
    if "g" in model.names:
        reference = np.array([STANDARD_GRAVITY if name == "g" else amplitude for name in model.names])
        try:
            at_reference = model.report(reference, {"time": 0.0}).results["period"].value
        except SCENE_ERRORS:
            return None
        if not at_reference or not period > 0:
            return None
        found["g"] = STANDARD_GRAVITY * (at_reference / period) ** 2
    return found


def pendulum(model: Model) -> tuple[dict[str, float], Step] | None:
    """A swing's start from its spectrum (runs of periods: ``periods``)."""
    if _plain(model) and model.samples.y_key == "period" and model.names == ["g"]:
        return periods(model)
    swing = _sorted_swing(model)
    if swing is None:
        return None
    t, theta = swing
    found_spectrum = spectrum(t, theta - np.mean(theta))
    if found_spectrum is None:
        return None
    frequency, amplitude = found_spectrum
    found = _values(model, 1 / frequency, amplitude)
    if found is None:
        return None
    shown = amplitude if "angle0" in model.names else model.si.get("angle0")
    return found, Step(
        f"{TITLE}: its amplitude and period from its spectrum",
        "f = argmax |Σᵢ(θᵢ − θ̄)e^(−2πiftᵢ)|²,  θ − θ̄ ≈ a cos 2πft + b sin 2πft;  T = 1/f,  θ₀ = ±√(a² + b²);  g = g₀ (T₀/T)²",
        f"T = {quantity_text(1 / frequency, 's')}, T₀ = the scene's period at g₀ = {quantity_text(STANDARD_GRAVITY, 'm/s**2')}"
        + (f" and θ₀ = {quantity_text(shown, 'rad')}" if shown is not None else ""),
        model.shown(found),
        f"the strongest frequency of the {len(t)} samples (an FFT on an even grid, refined at their own times): noise, spread over "
        "every frequency, does not move it as it adds crossings of θ̄; at a given amplitude the period goes as 1/√g, so the scene's "
        "own period at one g gives g (a start only: the fit below matches θ(t) itself)",
    )


def alternatives(model: Model) -> list[tuple[dict[str, float], Step]]:
    """The swing's period from its zero crossings (T = 2 × the mean time between crossings of θ̄)
    and its amplitude as the largest |θ|: the fit searches from it too, and keeps the better."""
    swing = _sorted_swing(model)
    if swing is None:
        return []
    t, theta = swing
    level = theta - np.mean(theta)
    crossings = [t[i] - level[i] * (t[i + 1] - t[i]) / (level[i + 1] - level[i]) for i in range(len(t) - 1) if level[i] * level[i + 1] < 0]
    if len(crossings) < 2:
        return []
    period = 2 * float(np.mean(np.diff(crossings)))
    first = int(np.argmax(np.abs(theta) > 0.9 * np.max(np.abs(theta))))
    amplitude = float(np.sign(theta[first]) * np.max(np.abs(theta)))
    found = _values(model, period, amplitude)
    if found is None:
        return []
    return [(found, Step(
        f"{TITLE}: its amplitude, and its period from the zero crossings",
        "T = 2 × (mean time between crossings of θ's mean);  g = g₀ (T₀/T)²",
        f"T = {quantity_text(period, 's')}, T₀ = the scene's period at g₀ = {quantity_text(STANDARD_GRAVITY, 'm/s**2')}",
        model.shown(found),
        f"{len(crossings)} crossings (the start from the spectrum gave a greater χ² at its minimum); at a given amplitude the period "
        "goes as 1/√g, so the scene's own period at one g gives g (a start only: the fit below matches θ(t) itself)",
    ))]


def periods(model: Model) -> tuple[dict[str, float], Step] | None:
    """Runs of periods (at their amplitudes): T = T₀ √(g₀/g) with T₀ the scene's period at g₀ for
    each run, so T is c·T₀ with c = √(g₀/g), linear in c: c = ΣwTT₀/ΣwT₀² is the least squares,
    and g = g₀/c² the start (the fit then finds it again)."""
    y = np.asarray(model.samples.y)
    weights = 1.0 / np.asarray(model.samples.sigma) ** 2 if model.samples.sigma is not None else np.ones(len(y))
    at_standard = np.array([model.value(np.array([STANDARD_GRAVITY]), i) for i in range(len(y))])
    if not np.all(np.isfinite(at_standard)) or not np.all(at_standard > 0):
        return None
    c = float(np.sum(weights * y * at_standard) / np.sum(weights * at_standard**2))
    if not c > 0:
        return None
    found = {"g": STANDARD_GRAVITY / c**2}
    return found, Step(
        "A start from the periods: T ∝ 1/√g for each run",
        "Tᵢ = c·T₀ᵢ,  c = √(g₀/g)  ⇒  c = ΣwᵢTᵢT₀ᵢ/ΣwᵢT₀ᵢ²,  g = g₀/c²",
        f"T₀ᵢ = the scene's period of run i at g₀ = {quantity_text(STANDARD_GRAVITY, 'm/s**2')}; c = {fmt(c)}",
        model.shown(found),
        f"at a given amplitude (and body) the period goes as 1/√g exactly, so the {len(y)} runs are linear in c: its least squares "
        "is the start, and the fit below finds the same g",
    )
