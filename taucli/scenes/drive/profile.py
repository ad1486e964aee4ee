"""A move profile: accelerate, run, decelerate, dwell; the motor's torque in each, its peak and RMS.

The motor's speed climbs uniformly to ω in t_a, holds it for t_r, falls to rest in t_d and rests
for t_w. The motor torque in each phase (train.py, with the efficiency on the power's way):

    τ_a = (J_m + J_g)α_a + G(Jα_a/N + T)/N,   τ_r = G(T)/N,   τ_d = −(J_m + J_g)α_d + G(−Jα_d/N + T)/N,
    τ_w = T_g/N   (gravity's hold at rest),     G(x) = x/η for x ≥ 0, ηx for x < 0,

constant within each phase, so

    τ_rms = √((τ_a² t_a + τ_r² t_r + τ_d² t_d + τ_w² t_w)/t_cycle),   P̄ = ω(τ_a t_a/2 + τ_r t_r + τ_d t_d/2)/t_cycle.

A trapezoid from a travel θ, a top speed ω and an acceleration α (the same down): t_a = t_d = ω/α
and t_r = θ/ω − ω/α where θ ≥ ω²/α; a shorter move is a triangle that peaks at √(αθ). The two
meet at θ = ω²/α, where t_r = 0 and the peak is ω.
"""

from __future__ import annotations

import math
from typing import NamedTuple

from taucli.writing.report import Step, Trajectory, fmt, quantity_text, term
from taucli.scenes.drive.train import Train, torque_step
from taucli.options.table import Results


class Move(NamedTuple):
    """One cycle: the motor's top speed and the four phases' times."""

    top: float
    accel: float
    run: float
    decel: float
    dwell: float

    @property
    def cycle(self) -> float:
        return self.accel + self.run + self.decel + self.dwell

    @property
    def angle(self) -> float:
        """θ = ω(t_a/2 + t_r + t_d/2): the area under the speed."""
        return self.top * (self.accel / 2 + self.run + self.decel / 2)


def trapezoid(angle: float, top: float | None, alpha: float, dwell: float, notes: list[str], steps: list[Step]) -> Move:
    """The move of ``angle`` at ``alpha`` up and down, held at ``top`` where it gets there (None: a triangle)."""
    if top is not None and top * top <= alpha * angle:
        ramp = top / alpha
        run = angle / top - ramp
        steps.append(Step("Times of the trapezoid", "t_a = t_d = ω/α,  t_r = θ/ω − ω/α",
                          f"{quantity_text(top, 'rad/s')} / {quantity_text(alpha, 'rad/s**2')};  "
                          f"{quantity_text(angle, 'rad')} / {quantity_text(top, 'rad/s')} − {quantity_text(ramp, 's')}",
                          f"t_a = {quantity_text(ramp, 's')}, t_r = {quantity_text(run, 's')}",
                          "the ramps cover ω²/α between them; the rest of the travel is at the top speed"))
        return Move(top, ramp, max(run, 0.0), ramp, dwell)
    peak = math.sqrt(alpha) * math.sqrt(angle)
    ramp = math.sqrt(angle) / math.sqrt(alpha)
    if top is not None:
        notes.append(f"the move is too short to reach the top speed ({quantity_text(top, 'rad/s')} needs θ ≥ ω²/α = "
                     f"{quantity_text(top * top / alpha, 'rad')}): a triangle that peaks at {quantity_text(peak, 'rad/s')}")
    steps.append(Step("A triangular move", "ω_peak = √(αθ),  t_a = t_d = √(θ/α)",
                      f"√({quantity_text(alpha, 'rad/s**2')} × {quantity_text(angle, 'rad')})", f"ω_peak = {quantity_text(peak, 'rad/s')}, "
                      f"t_a = {quantity_text(ramp, 's')}", "half the travel speeding up, half slowing down, with no time at a top speed"))
    return Move(peak, ramp, 0.0, ramp, dwell)


class Phase(NamedTuple):
    name: str
    torque: float
    time: float
    power_start: float
    power_end: float


def phases(train: Train, move: Move) -> list[Phase]:
    """Each phase's motor torque, time, and power at its ends (with the load moving, or held)."""
    w = move.top
    alpha_up = w / move.accel if move.accel else 0.0
    alpha_down = w / move.decel if move.decel else 0.0
    up = train.motor_torque(alpha_up)
    run = train.running
    down = train.motor_torque(-alpha_down)
    return [Phase("accelerate", up, move.accel, 0.0, up * w), Phase("run", run, move.run, run * w, run * w),
            Phase("decelerate", down, move.decel, down * w, 0.0), Phase("dwell", train.hold, move.dwell, 0.0, 0.0)]


def rms(parts: list[Phase], cycle: float) -> float:
    """√(Σ τᵢ² tᵢ / t_cycle), scaled by the largest |τᵢ| so that no square overflows."""
    scale = max((abs(p.torque) for p in parts if p.time > 0), default=0.0)
    if scale == 0:
        return 0.0
    return scale * math.sqrt(math.fsum((p.torque / scale) ** 2 * p.time for p in parts) / cycle)


def solve_profile(train: Train, move: Move, limits: dict, results: Results, notes: list[str], steps: list[Step]) -> Trajectory:
    """The cycle's torques, peak, RMS and power; ``limits``: rated, peak and the motor's law, where given."""
    parts = phases(train, move)
    alpha_up = move.top / move.accel
    alpha_down = move.top / move.decel
    results.put("omega_top", move.top)
    speed = train.speed_of(move.top)
    if speed is not None:
        results.put("speed_top", speed)
    results.put("alpha", alpha_up)
    results.put("alpha_decel", alpha_down)
    results.put("t_accel", move.accel, " to the top speed")
    results.put("t_run", move.run)
    results.put("t_decel", move.decel)
    results.put("t_cycle", move.cycle)
    results.put("theta_move", move.angle)
    if train.lever is not None:
        results.put("travel", move.angle * train.lever / train.ratio)
    results.put("torque_accel", parts[0].torque)
    results.put("torque_decel", parts[2].torque)
    if train.gravity:
        results.put("torque_hold", train.hold)
    counted = [p for p in parts if p.time > 0]
    peak = max(abs(p.torque) for p in counted)
    torque_rms = rms(parts, move.cycle)
    results.put("torque_peak", peak)
    results.put("torque_rms", torque_rms)
    powers = [power for p in counted for power in (p.power_start, p.power_end)]
    power_mean = move.top * math.fsum((parts[0].torque * move.accel / 2, parts[1].torque * move.run, parts[2].torque * move.decel / 2)) / move.cycle
    results.put("power_peak", max(0.0, *powers))
    results.put("power_regen", max(0.0, -min(powers)))
    results.put("power_mean", power_mean)
    results.put("power_run", parts[1].torque * move.top, " at the top speed, running")
    # each phase's torque is constant and ω ramps (mean ω/2) or holds: what flows back where τ < 0
    regen = move.top * math.fsum((max(-parts[0].torque, 0.0) * move.accel / 2, max(-parts[1].torque, 0.0) * move.run,
                                  max(-parts[2].torque, 0.0) * move.decel / 2))
    results.put("energy_regen", regen)
    results.put("power_resistor", regen / move.cycle)
    steps.extend(_steps(train, move, parts, alpha_up, alpha_down, torque_rms, power_mean))
    if regen:
        steps.append(Step("Energy the load gives back per cycle, and a braking resistor's power", "E_r = ω(|τ_d| t_d/2 + …),  P_R = E_r/t_cycle",
                          f"{quantity_text(move.top, 'rad/s')} × {quantity_text(-parts[2].torque if parts[2].torque < 0 else 0.0, 'N*m')} × "
                          f"{quantity_text(move.decel, 's')}/2" + (" + …" if parts[0].torque < 0 or parts[1].torque < 0 else ""),
                          f"E_r = {quantity_text(regen, 'J')}, P_R = {quantity_text(regen / move.cycle, 'W')}",
                          "while the motor's torque is against its motion the load drives it: that energy goes back to the drive, "
                          "and a braking resistor takes it as heat, on average over the cycle"))
    steps.extend(_limits(move, parts, peak, torque_rms, limits, results, notes))
    return _curves(move, parts)


def _steps(train: Train, move: Move, parts: list[Phase], alpha_up: float, alpha_down: float, torque_rms: float, power_mean: float) -> list[Step]:
    up, run, down, dwell = parts
    steps = [
        Step("The motor's acceleration and deceleration", "α_a = ω/t_a,  α_d = ω/t_d",
             f"{quantity_text(move.top, 'rad/s')} / {quantity_text(move.accel, 's')};  {quantity_text(move.top, 'rad/s')} / {quantity_text(move.decel, 's')}",
             f"α_a = {quantity_text(alpha_up, 'rad/s**2')}, α_d = {quantity_text(alpha_down, 'rad/s**2')}", "uniform ramps of speed"),
        torque_step("Motor torque while accelerating", train, alpha_up, up.torque),
        torque_step("Motor torque while decelerating", train, -alpha_down, down.torque),
    ]
    terms = [(p, s) for p, s in ((up, "τ_a² t_a"), (run, "τ_r² t_r"), (down, "τ_d² t_d"), (dwell, "τ_w² t_w")) if p.time > 0]
    squares = " + ".join(f"{_squared(p.torque)} × {quantity_text(p.time, 's')}" for p, _ in terms)
    steps.append(Step("RMS torque over the cycle", f"τ_rms = √(({' + '.join(s for _, s in terms)}) / t_cycle)",
                      f"√(({squares}) / {quantity_text(move.cycle, 's')})",
                      quantity_text(torque_rms, "N*m"),
                      "the motor heats as the square of its current, so of its torque: the RMS is the steady torque that heats it as much"))
    steps.append(Step("Mean power over the cycle", "P̄ = ω(τ_a t_a/2 + τ_r t_r + τ_d t_d/2) / t_cycle",
                      f"{quantity_text(move.top, 'rad/s')} × ({term(up.torque, 'N*m')} × {quantity_text(move.accel, 's')}/2 + {term(run.torque, 'N*m')} × "
                      f"{quantity_text(move.run, 's')} + {term(down.torque, 'N*m')} × {quantity_text(move.decel, 's')}/2) / {quantity_text(move.cycle, 's')}",
                      quantity_text(power_mean, "W"), "the ramps run at half the top speed on average; what the load gives back while braking counts against it"))
    return steps


def _squared(torque: float) -> str:
    """(1.3 N·m)² or (−0.4 N·m)²: one pair of parentheses either way."""
    text = term(torque, "N*m")
    return (text if text.startswith("(") else f"({text})") + "²"


def _limits(move: Move, parts: list[Phase], peak: float, torque_rms: float, limits: dict, results: Results, notes: list[str]) -> list[Step]:
    """RMS against the rated torque, the peak against the peak torque, and the motor's law against each driving phase."""
    rated, most, motor = limits.get("rated"), limits.get("peak"), limits.get("motor")
    if rated is None and most is None and motor is None:
        return []
    steps, within = [], True
    if rated is not None:
        ratio = torque_rms / rated
        results.put("rms_to_rated", ratio)
        within = within and ratio <= 1
        steps.append(Step("RMS torque against the rated torque", "τ_rms / τ_rated", f"{quantity_text(torque_rms, 'N*m')} / {quantity_text(rated, 'N*m')}",
                          fmt(ratio), "at or under 1 the motor runs no hotter than at its rating; vendors leave a margin of 20% or so"))
    if most is not None:
        within = within and peak <= most
        if peak > most:
            notes.append(f"the peak torque {quantity_text(peak, 'N*m')} is over the motor's peak torque {quantity_text(most, 'N*m')}")
    if motor is not None:
        for phase in parts[:2]:
            if phase.time > 0 and phase.torque > motor.torque(move.top):
                within = False
                notes.append(f"the motor cannot follow the move: it needs {quantity_text(phase.torque, 'N*m')} to {phase.name} at "
                             f"{quantity_text(move.top, 'rad/s')}, where it gives {quantity_text(motor.torque(move.top), 'N*m')}")
    results.put("within_rating", within)
    return steps


def _curves(move: Move, parts: list[Phase]) -> Trajectory:
    ends = [move.accel, move.accel + move.run, move.accel + move.run + move.decel, move.cycle]

    def state(t: float) -> tuple[float, float]:
        if t < ends[0]:
            return move.top * t / move.accel, parts[0].torque
        if t < ends[1]:
            return move.top, parts[1].torque
        if t < ends[2]:
            return move.top * (ends[2] - t) / move.decel, parts[2].torque
        return 0.0, parts[3].torque

    curves = (("omega", "rad/s", "motor speed ω"), ("torque", "N*m", "motor torque τ"))
    marks = tuple((t, name) for t, name in zip(ends[:3], ("top speed", "decelerate", "at rest")) if 0 < t < move.cycle)
    return Trajectory(curves, move.cycle, state, marks=marks)
