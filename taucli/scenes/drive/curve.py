"""Run-up of an induction motor on its torque–slip curve (--motor-curve): Kloss's formula

    T(s) = 2T_max / (s/s_m + s_m/s),   s = 1 − ω/ω_s

(T_max the breakdown torque, s_m the slip where it falls, ω_s the synchronous speed). The motor
drives a train (train.py, or several loads, loads.py) whose torque at an acceleration α is
τ(α) = (J_m + J_g)α + Σ G(Jα/N + T)/N + τ_mf, piecewise linear and rising in α; at each speed the
motor's T(s) fixes α(ω) as the root of τ(α) = T(s) (exact: a line between the corners where a
load's power turns round). Then

    t = ∫ dω/α(ω),   θ = ∫ ω dω/α(ω),   E_r = ∫ s T ω_s dt = ∫ T(s)(ω_s − ω) dω/α(ω)

from ω₀ (rest unless --omega0) to ω₁, by adaptive Gauss–Legendre split at those corners. E_r is
the energy the rotor dissipates (its copper loss: the slip's share s of the air-gap power Tω_s);
the motor takes Tω_s from the supply through the gap, E_r of it lost in the rotor, the rest work.
Unloaded (no torque at any speed), α = T/J_e with J_e the inertia through the losses, and

    t = (J_e ω_s / 2T_max)[(s₀² − s₁²)/(2s_m) + s_m ln(s₀/s₁)],   E_r = ½J_e ω_s²(s₀² − s₁²)
    θ = (J_e ω_s² / 2T_max)[(s₀² − s₁²)/(2s_m) − (s₀³ − s₁³)/(3s_m) + s_m(ln(s₀/s₁) − (s₀ − s₁))]

(from rest, ½J_e ω_s²(1 − s₁²): as much as the kinetic energy gained, in the limit s₁ → 0).

The motor reaches ω₁ only where T(s) beats the load's running torque T_run = τ(0) all the way:
T(s) rises from the start to T_max at s_m and then falls, so it fails at ω₀ (T(s₀) ≤ T_run: it
never starts) or where T falls to T_run past the peak, s_ss = s_m/(k + √(k² − 1)), k = T_max/T_run:
the motor settles at ω_ss = ω_s(1 − s_ss) and never passes it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from taucli.core.errors import InputError
from taucli.numerics.quadrature import adaptive_gauss
from taucli.writing.report import Step, fmt, quantity_text, term

TWO_PI = 2.0 * math.pi


@dataclass(frozen=True)
class Kloss:
    """An induction motor's torque–slip curve by its breakdown torque, the slip there and the synchronous speed."""

    source: str
    tmax: float
    slip_max: float
    sync: float

    def slip(self, omega: float) -> float:
        return 1.0 - omega / self.sync

    def torque(self, omega: float) -> float:
        """T = 2T_max/(s/s_m + s_m/s), written 2T_max s s_m/(s² + s_m²): exact at s = 0."""
        s = self.slip(omega)
        return 2.0 * self.tmax * s * self.slip_max / (s * s + self.slip_max * self.slip_max)

    def slips_at(self, torque: float) -> tuple[float, ...]:
        """The slips in (0, ∞) where T(s) = torque: s_m(k ∓ √(k² − 1)), k = T_max/T (none above T_max)."""
        if torque <= 0 or torque > self.tmax:
            return ()
        k = self.tmax / torque
        root = math.sqrt(max(k * k - 1.0, 0.0))
        return (self.slip_max / (k + root), self.slip_max * (k + root))


def _corners(train) -> list[float]:
    """The accelerations where a load's power through its train turns round (Jα/N + T = 0)."""
    branches = getattr(train, "branches", None)
    if branches is None:
        return [-train.torque * train.ratio / train.load] if train.load else []
    return sorted({-b.torque * b.ratio / b.inertia for b in branches if b.inertia})


def acceleration(train, torque: float) -> float:
    """α where the train asks the motor for ``torque``: τ(α) is a rising line between corners."""
    points = _corners(train) or [0.0]
    values = [train.motor_torque(a) for a in points]
    if torque <= values[0]:
        a, b = points[0] - 1.0, points[0]
    elif torque >= values[-1]:
        a, b = points[-1], points[-1] + 1.0
    else:
        i = next(i for i in range(1, len(points)) if torque <= values[i])
        a, b = points[i - 1], points[i]
    fa, fb = train.motor_torque(a), train.motor_torque(b)
    return a + (torque - fa) * (b - a) / (fb - fa)


def run_up(train, curve: Kloss, omega0: float, target: float | None, results, notes: list[str], steps: list[Step]) -> None:
    """t_accel, theta_accel and energy_accel from ω₀ to ``target`` on the curve, or a refusal naming where it stalls."""
    if curve.sync <= omega0:
        raise InputError("omega0", f"expected a speed below the synchronous speed sync={quantity_text(curve.sync, 'rad/s')}", example="{omega0} 0")
    slope = train.motor_torque(1.0) - train.motor_torque(0.0)
    if slope <= 0:
        raise InputError("motor_inertia", "or a load's inertia is required for a run-up: with none the motor would reach any speed at once",
                         example="{motor_inertia} '0.5kg*m^2'")
    running = train.motor_torque(0.0)
    start = curve.torque(omega0)
    steps.append(Step("The motor's torque on its curve (Kloss)", "T(s) = 2T_max/(s/s_m + s_m/s),  s = 1 − ω/ω_s",
                      f"2 × {quantity_text(curve.tmax, 'N*m')} / ({fmt(curve.slip(omega0))}/{fmt(curve.slip_max)} + {fmt(curve.slip_max)}/{fmt(curve.slip(omega0))})",
                      f"T = {quantity_text(start, 'N*m')} at {'rest' if omega0 == 0 else quantity_text(omega0, 'rad/s')}; T_max = {quantity_text(curve.tmax, 'N*m')} "
                      f"at ω = {quantity_text(curve.sync * (1 - curve.slip_max), 'rad/s')}",
                      "the torque rises from the start to its peak at the slip s_m, then falls to nothing at the synchronous speed"))
    alpha0 = acceleration(train, start)
    inertia = 1.0 / (acceleration(train, start + 1.0) - alpha0) if start > running else slope
    steps.append(Step("What the motor turns, through the losses", "J_e α = T(s) − T_run,  T_run = τ(α = 0)",
                      f"({quantity_text(start, 'N*m')} − {term(running, 'N*m')}) / {quantity_text(inertia, 'kg*m**2')}",
                      f"α₀ = {quantity_text(alpha0, 'rad/s**2')}" if start > running else "T(s₀) ≤ T_run",
                      "the load's torque and inertia reach the motor through the train and its losses, as in a run-up at a constant α"))
    if start <= running:
        raise InputError("motor_curve", f"cannot start the load: it gives {quantity_text(start, 'N*m')} at "
                         f"{'rest' if omega0 == 0 else quantity_text(omega0, 'rad/s')}, the load asks {quantity_text(running, 'N*m')} at the motor: it stalls there",
                         example=_stronger(curve, running / start if start > 0 else 2.0))
    results.put("alpha0", alpha0, "" if omega0 == 0 else f" at {fmt(omega0)} rad/s")
    stall = _steady(curve, running)
    if target is None:
        raise InputError("until_omega", "is required with {motor_curve}: the speed to reach, below the synchronous speed"
                         + (f" and below {quantity_text(stall, 'rad/s')}, where the motor's torque falls to the load's" if stall is not None else ""),
                         example="{until_omega} 1400rpm")
    if target <= omega0:
        top = min(curve.sync, stall) if stall is not None else curve.sync
        raise InputError("until_omega", f"expected a speed above the run-up's start {quantity_text(omega0, 'rad/s')}",
                         example=f"{{until_omega}} {fmt((omega0 + top) / 2 * 60 / TWO_PI, 4)}rpm")
    if stall is not None and target >= stall:
        raise InputError("until_omega", f"is never reached: the motor's torque falls to the load's {quantity_text(running, 'N*m')} at "
                         f"{quantity_text(stall, 'rad/s')} ({fmt(stall * 60 / TWO_PI)} rpm), where it settles", example=f"{{until_omega}} {fmt(0.95 * stall * 60 / TWO_PI)}rpm")
    if target >= curve.sync:
        raise InputError("until_omega", f"is never reached: an induction motor runs below its synchronous speed {quantity_text(curve.sync, 'rad/s')}",
                         example=f"{{until_omega}} {fmt(0.95 * curve.sync * 60 / TWO_PI)}rpm")
    if stall is not None:
        steps.append(Step("Where the motor's torque falls to the load's", "T(s) = T_run  ⇒  s = s_m/(k + √(k² − 1)),  k = T_max/T_run",
                          f"{fmt(curve.slip_max)} / (k + √(k² − 1)),  k = {quantity_text(curve.tmax, 'N*m')}/{quantity_text(running, 'N*m')}",
                          f"ω_ss = {quantity_text(stall, 'rad/s')}", "the run-up closes on this speed and never passes it: the speed asked is below it"))
    time, theta, loss = _integrals(train, curve, omega0, target, running)
    words = f" to {fmt(target)} rad/s" if omega0 == 0 else f" from {fmt(omega0)} to {fmt(target)} rad/s"
    results.put("t_accel", time, words)
    results.put("theta_accel", theta)
    results.put("revs_accel", theta / TWO_PI)
    results.put("energy_accel", loss)
    s0, s1 = curve.slip(omega0), curve.slip(target)
    if _unloaded(train):
        steps.append(Step("Time to reach the speed, unloaded", "t = (J_e ω_s/2T_max)[(s₀² − s₁²)/(2s_m) + s_m ln(s₀/s₁)]",
                          f"({quantity_text(inertia, 'kg*m**2')} × {quantity_text(curve.sync, 'rad/s')} / (2 × {quantity_text(curve.tmax, 'N*m')})) × "
                          f"[({fmt(s0)}² − {fmt(s1)}²)/(2 × {fmt(curve.slip_max)}) + {fmt(curve.slip_max)} × ln({fmt(s0)}/{fmt(s1)})]",
                          quantity_text(time, "s"), "J_e dω/dt = T(s) with dω = −ω_s ds: the integral of (s/s_m + s_m/s) ds/2T_max"))
        steps.append(Step("Energy dissipated in the rotor, unloaded", "E_r = ∫ s T ω_s dt = ½J_e ω_s²(s₀² − s₁²)",
                          f"½ × {quantity_text(inertia, 'kg*m**2')} × ({quantity_text(curve.sync, 'rad/s')})² × ({fmt(s0)}² − {fmt(s1)}²)",
                          quantity_text(loss, "J"), "the rotor's copper loss is the slip's share of the air-gap power T ω_s; from rest to near ω_s it is "
                          "as much as the kinetic energy gained (the stator's loss, R_s/R_r′ of it, comes on top)"))
    else:
        steps.append(Step("Time to reach the speed", "t = ∫ dω/α(ω),  J_e α = T(s) − T_run",
                          f"∫ from {quantity_text(omega0, 'rad/s')} to {quantity_text(target, 'rad/s')}", quantity_text(time, "s"),
                          "the motor's spare torque over the inertia sets the acceleration at each speed; integrated numerically (Gauss–Legendre)"))
        steps.append(Step("Energy dissipated in the rotor in the run-up", "E_r = ∫ s T ω_s dt = ∫ T(s)(ω_s − ω) dω/α(ω)",
                          f"∫ from {quantity_text(omega0, 'rad/s')} to {quantity_text(target, 'rad/s')}", quantity_text(loss, "J"),
                          "the rotor's copper loss is the slip's share s of the air-gap power T ω_s; a load torque lengthens the run-up and adds to it"))
    steps.append(Step("The motor's angle meanwhile", "θ = ∫ ω dω/α(ω)", f"∫ from {quantity_text(omega0, 'rad/s')} to {quantity_text(target, 'rad/s')}",
                      f"{quantity_text(theta, 'rad')} = {fmt(theta / TWO_PI)} rev", "the speed over the acceleration is the time per unit speed; times ω, the angle"))


def _unloaded(train) -> bool:
    """No torque at any speed and every train driven while the motor speeds up: α = T/J_e, the closed forms."""
    return train.motor_torque(0.0) == 0 and not any(a < 0 for a in _corners(train))


def method(train) -> str:
    return "closed form" if _unloaded(train) else "quadrature (adaptive Gauss–Legendre)"


def _steady(curve: Kloss, running: float) -> float | None:
    """The speed past the peak where T(s) falls to T_run (None: a load that drives, or none, never stops the motor short of ω_s)."""
    slips = curve.slips_at(running)
    return None if not slips else curve.sync * (1.0 - slips[0])


def _integrals(train, curve: Kloss, omega0: float, target: float, running: float) -> tuple[float, float, float]:
    """t, θ and E_r by adaptive Gauss–Legendre, the interval split where a load's power turns round."""
    if _unloaded(train):  # every train driven, α = T/J_e
        inertia = 1.0 / (acceleration(train, 1.0) - acceleration(train, 0.0))
        s0, s1, sm = curve.slip(omega0), curve.slip(target), curve.slip_max
        scale = inertia * curve.sync / (2 * curve.tmax)
        time = scale * ((s0 - s1) * (s0 + s1) / (2 * sm) + sm * math.log(s0 / s1))
        loss = inertia * curve.sync**2 * (s0 - s1) * (s0 + s1) / 2
        theta = scale * curve.sync * ((s0 - s1) * (s0 + s1) / (2 * sm) - (s0**3 - s1**3) / (3 * sm) + sm * (math.log(s0 / s1) - (s0 - s1)))
        return time, theta, loss
    edges = {omega0, target}
    for corner in _corners(train):
        for s in curve.slips_at(train.motor_torque(corner)):
            omega = curve.sync * (1.0 - s)
            if omega0 < omega < target:
                edges.add(omega)
    points = sorted(edges)

    def total(f) -> float:
        return math.fsum(adaptive_gauss(f, a, b) for a, b in zip(points, points[1:]))

    time = total(lambda w: 1.0 / acceleration(train, curve.torque(w)))
    theta = total(lambda w: w / acceleration(train, curve.torque(w)))
    loss = total(lambda w: curve.torque(w) * (curve.sync - w) / acceleration(train, curve.torque(w)))
    return time, theta, loss


def _stronger(curve, short: float) -> str:
    """The --motor-curve example for a motor that cannot start its load: the same curve with its
    T_max raised past the load (the torque at every slip scales with it), by half again."""
    return (f"{{motor_curve}} 'tmax={fmt(1.5 * short * curve.tmax, 3)}N*m slip-max={fmt(curve.slip_max)} "
            f"sync={fmt(curve.sync * 60 / TWO_PI, 6)}rpm'")
