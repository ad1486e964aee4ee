"""spin-down under the torque laws on arrays: many wheels at once, one a Monte Carlo draw (#45 item 4).

The scene of torque_laws.solve, for a wheel given by --inertia, turning at ω₀ (or set going from
rest by a drive that beats friction), under a drive τ, axle friction τ_f, viscous b and quadratic
drag k (n = 2, or none), each draw its own, in the frame of its motion (s = ±1, ω ≥ 0):

    I dω/dt = A − bω − kω²,  A = sτ − τ_f  (taucli.scenes.closed_arrays.Phases: the same closed forms)
    α₀ = (A − bω₀ − kω₀²)/I;  A < 0: t_stop = t(ω₀ → 0), θ_stop = θ(t_stop), held there (|τ| ≤ τ_f)
    ω∞ = 0 after a stop, else r₊ (ω₀ where b = k = 0 and A = 0; none where ω grows without bound)
    at --time t: ω(t), θ(t) (ω = 0, θ = θ_stop past the stop), L = Iω, revs = θ/2π,
    ω_mean = θ/t (½(ω₀ + ω) where α was constant throughout, as taucli.scenes.spin.mean writes it)

``drawn`` gives each result as an array (NaN where the scene gives none), each draw's regime
(the scene's results differ between them: a stop, none, no steady speed) and which draws it
takes: the others (a wheel that friction holds from the start, one that turns back after its
stop) are the scene's to solve, one by one. taucli.answering.mc_arrays holds every regime to the
scene's own solve at a few draws before it uses it.
"""

from __future__ import annotations

import math

import numpy as np

from taucli.scenes.closed_arrays import Phases
from taucli.scenes.spin.steps import TWO_PI

TAKES = {"inertia", "omega0", "torque", "friction", "viscous", "drag", "drag_exponent", "time", "method"}
KEYS = ("I", "alpha0", "t_stop", "theta_stop", "revs_stop", "omega_inf", "omega", "L", "theta", "revs", "omega_mean")


def drawn(arguments: dict) -> tuple[dict[str, np.ndarray], np.ndarray, np.ndarray] | None:
    """(results, regime, taken) for the draws in ``arguments`` (spin_down's keywords, the drawn
    ones arrays), or None where the form does not take these options at all."""
    given = {name: value for name, value in arguments.items() if value is not None}
    if not set(given) <= TAKES or "inertia" not in given or str(given.get("method", "auto")) not in ("auto", "exact"):
        return None
    if given.get("drag_exponent", 2.0) != 2.0 and np.any(np.asarray(given.get("drag", 0.0)) != 0):
        return None
    shape = np.broadcast(*(np.asarray(given.get(name, 0.0)) for name in ("inertia", "omega0", "torque", "friction", "viscous", "drag", "time"))).shape

    def field(name: str) -> np.ndarray:
        return np.broadcast_to(np.asarray(given.get(name, 0.0), dtype=float), shape).copy()

    inertia, start, drive, friction, b, k = (field(name) for name in ("inertia", "omega0", "torque", "friction", "viscous", "drag"))
    # the sense of the motion (motion.start_direction): ω₀'s, or from rest the drive's where it beats friction
    sense = np.where(start > 0, 1.0, np.where(start < 0, -1.0, np.where(np.abs(drive) > friction, np.sign(drive), 0.0)))
    w0 = np.abs(start)  # each draw in its own frame, ω ≥ 0
    a = sense * drive - friction
    phases = Phases(inertia, a, b, k, w0)
    stops = a < 0
    taken = (sense != 0) & (inertia > 0) & (friction >= 0) & (b >= 0) & (k >= 0) & ~(stops & (np.abs(drive) > friction))  # (no turn back)
    found = {key: np.full(shape, math.nan) for key in KEYS}
    found["I"] = inertia.copy()
    with np.errstate(all="ignore"):
        found["alpha0"] = sense * ((a - b * w0 - k * (w0 * w0)) / inertia)  # (Phase.rate at ω₀ ≥ 0: kω₀ⁿ with n = 2)
        t_stop = phases.stop_time()
        turned = np.full(shape, math.nan)  # θ_stop in the draw's frame
        if np.any(stops):
            turned[stops] = phases.part(stops).theta(np.where(np.isfinite(t_stop), t_stop, 0.0)[stops])
        theta_stop = sense * turned
        found["t_stop"], found["theta_stop"], found["revs_stop"] = t_stop, theta_stop, theta_stop / TWO_PI
        uniform = (b == 0) & (k == 0)
        _, steady = _steady(phases)
        found["omega_inf"] = np.where(stops, 0.0, sense * np.where(uniform, np.where(a == 0, w0, math.nan), steady))
        time = given.get("time")
        if time is not None:
            t = field("time")
            before = ~stops | (t <= np.where(np.isnan(t_stop), np.inf, t_stop))
            omega, theta = np.zeros(shape), theta_stop.copy()
            if np.any(before):
                speed, angle = phases.part(before).state(t[before])
                omega[before], theta[before] = sense[before] * speed, sense[before] * angle
            found["omega"], found["L"], found["theta"], found["revs"] = omega, inertia * omega, theta, theta / TWO_PI
            elapsed, last = t, omega
        else:
            theta, elapsed, last = theta_stop, t_stop, np.zeros(shape)
        # ω_mean = θ/t, or ½(ω₀ + ω) at constant α where ω₀ was given (taucli.scenes.spin.mean)
        mean = theta / elapsed
        if "omega0" in given:
            constant = np.abs(theta - (start + last) / 2 * elapsed) <= 1e-12 * (np.abs(start) + np.abs(last)) * elapsed
            mean = np.where(elapsed == 0, start, np.where(constant, (start + last) / 2, mean))
        found["omega_mean"] = mean
    regime = stops.astype(int) + 2 * uniform + 4 * (a == 0) + 8 * np.isnan(found["omega_inf"]) + 16 * (sense < 0) + 32 * (start == 0)
    taken &= np.isfinite(found["alpha0"]) & (~stops | (np.isfinite(t_stop) & np.isfinite(theta_stop)))
    if time is not None:
        taken &= np.isfinite(found["omega"]) & np.isfinite(found["theta"]) & (t > 0)
    return found, regime, taken


def _steady(phases: Phases) -> tuple[np.ndarray, np.ndarray]:
    """(√D, r₊) of each draw (real: where A ≥ 0, the only draws that keep a steady speed)."""
    a, b, k = phases.constant, phases.viscous, phases.drag
    root = np.sqrt(np.maximum(b * b + 4 * k * a, 0.0))
    return root, np.where(a == 0, 0.0, 2 * a / (b + root))
