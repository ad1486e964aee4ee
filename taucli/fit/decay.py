"""Where a damped swing's fit starts (--viscous, --start-time): its frequency, decay and phase.

θ(t) ≈ A e^(−γ(t − t₁)) cos(2πf(t − tₛ)), from what noise does not fool:

- f from the spectrum (taucli.fit.swing.spectrum);
- the decay from windows of about two periods each: in each, the least squares of
  θ = a cos 2πft + b sin 2πft + c gives its amplitude Aₖ = √(a² + b²) at its mid-time tₖ, and
  ln Aₖ = ln A − γ(tₖ − t₁) is a straight line: γ its slope, b = 2Iγ (I the scene's own);
- the start: the first window's phase φ = atan2(b, a) puts the turning points at 2πft = φ + kπ;
  tₛ is the last of them at or before the first sample, θ₀ = ±A e^(γ(t₁ − tₛ)) there (the sign
  alternating with k);
- g from the damped frequency: Ω₀² = (2πf)² + γ², lengthened for the amplitude by the exact
  pendulum's 1 + θ²/16, and the scene's own small-swing period at one g (T₀ ∝ 1/√g).

A start only: the fit then matches θ(t) itself.
"""

from __future__ import annotations

import math

import numpy as np

from taucli.fit.swing import SCENE_ERRORS, spectrum
from taucli.scenes.assumed import STANDARD_GRAVITY
from taucli.writing.report import Step, fmt, quantity_text

SOUGHT = {"g", "angle0", "viscous", "start_time"}
WINDOW_PERIODS = 2.0  # periods in each window the amplitude is measured over


def damped(model) -> bool:
    """A swing θ(t) with a damping or a start time, held or fitted: the model this start is for."""
    names, held = set(model.names), set(model.held)
    return (bool(names & {"viscous", "start_time"}) or bool(held & {"viscous", "start_time"})) and names <= SOUGHT \
        and not held & {"torsion", "omega0", "omega_bottom"} and set(model.samples.inputs) == {"time"} and model.samples.y_key == "theta"


def _amplitude(t: np.ndarray, theta: np.ndarray, f: float) -> tuple[float, float, float] | None:
    """(a, b, mid-time) of θ = a cos 2πft + b sin 2πft + c over one window."""
    if len(t) < 4:
        return None
    A = np.column_stack([np.cos(2 * math.pi * f * t), np.sin(2 * math.pi * f * t), np.ones(len(t))])
    a, b, _ = np.linalg.lstsq(A, theta, rcond=None)[0]
    return float(a), float(b), float(np.mean(t))


def start(model) -> tuple[dict[str, float], Step] | None:
    t = np.asarray(model.samples.inputs["time"], dtype=float)
    order = np.argsort(t, kind="stable")
    t, theta = t[order], np.asarray(model.samples.y, dtype=float)[order]
    found_spectrum = spectrum(t, theta - np.mean(theta))
    if found_spectrum is None:
        return None
    f = found_spectrum[0]
    span = float(t[-1] - t[0])
    count = max(1, min(12, int(span * f / WINDOW_PERIODS)))
    edges = np.linspace(t[0], t[-1], count + 1)
    windows = [_amplitude(t[(t >= lo) & (t <= hi)], theta[(t >= lo) & (t <= hi)], f) for lo, hi in zip(edges[:-1], edges[1:])]
    windows = [w for w in windows if w is not None and math.hypot(w[0], w[1]) > 0]
    if not windows:
        return None
    mids = np.array([w[2] for w in windows])
    logs = np.log([math.hypot(w[0], w[1]) for w in windows])
    if len(windows) > 1:
        slope, level = np.polyfit(mids - t[0], logs, 1)
        gamma = max(-float(slope), 0.0)
    else:
        gamma, level = 0.0, float(logs[0])
    amplitude_first = math.exp(level)  # at the first sample
    a, b, _ = windows[0]
    phase = math.atan2(b, a)  # a cos ωt + b sin ωt = R cos(ωt − φ)
    omega_d = 2 * math.pi * f
    held_start = model.si.get("start_time", 0.0)
    if "start_time" in model.names:
        k = math.floor((omega_d * t[0] - phase) / math.pi + 1e-9)
        start_time = (phase + k * math.pi) / omega_d
    else:
        start_time, k = held_start, None
    size = amplitude_first * math.exp(gamma * (t[0] - start_time))
    if k is not None:
        angle0 = size * (1 if k % 2 == 0 else -1)
    else:
        angle0 = size * math.copysign(1.0, math.cos(omega_d * start_time - phase))
    found: dict[str, float] = {}
    if "angle0" in model.names:
        found["angle0"] = angle0
    if "start_time" in model.names:
        found["start_time"] = start_time
    reference = {"g": STANDARD_GRAVITY, "angle0": angle0, "viscous": 0.0, "start_time": start_time}
    try:
        scene = model.report(np.array([reference[name] for name in model.names]), {"time": float(t[0])}).results
        small_period, inertia = scene["period_small"].value, scene["I"].value
    except SCENE_ERRORS:
        return None
    if "viscous" in model.names:
        found["viscous"] = 2 * inertia * gamma
    if "g" in model.names:
        mean_amplitude = float(np.mean(np.exp(logs)))
        natural = math.sqrt(omega_d**2 + gamma**2) * (1 + mean_amplitude**2 / 16)  # Ω₀ of small swings
        found["g"] = STANDARD_GRAVITY * (small_period * natural / (2 * math.pi)) ** 2
    return found, Step(
        "A start from the swing: its frequency, decay and phase",
        "θ ≈ A e^(−γ(t − t₁)) cos 2πf(t − tₛ);  ln Aₖ = ln A − γ(tₖ − t₁);  b = 2Iγ,  Ω₀² = (2πf)² + γ²",
        f"f = {fmt(f)} Hz from the spectrum, γ = {fmt(gamma)} 1/s from {len(windows)} windows, I = {quantity_text(inertia, 'kg*m**2')}",
        model.shown(found),
        f"the strongest frequency of the {len(t)} samples, the amplitude's decay from the least squares in windows of about "
        f"{fmt(WINDOW_PERIODS)} periods, and the start at the last turning point before the first sample (a start only: the fit "
        "below matches θ(t) itself)",
    )
