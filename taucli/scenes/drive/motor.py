"""Run-up from rest: at a constant α (the torque it takes), or under the motor's own torque law
(the time it takes).

A motor given by its torque–speed line, τ(ω) = τ_s(1 − ω/ω_nl), or by a constant torque, drives
the train of train.py. While the motor drives the load (T_out ≥ 0),

    τ(ω) = (J_m + J_g)ω̇ + (J ω̇/N + T)/(Nη)   ⇒   J_e ω̇ = τ_s − T_e − (τ_s/ω_nl) ω,
    J_e = J_m + J_g + J/(N²η),   T_e = T/(Nη),

which is spin-down with a drive τ_s − T_e and a viscous torque bω, b = τ_s/ω_nl: from rest

    ω(t) = ω_ss (1 − e^(−t/τ_m)),   ω_ss = ω_nl (1 − T_e/τ_s),   τ_m = J_e ω_nl/τ_s,
    t(ω₁) = −τ_m ln(1 − ω₁/ω_ss),   θ(ω₁) = ω_ss t − τ_m ω₁

(unloaded: ω_ss = ω_nl and τ_m = J ω_nl/τ_s). Where the load drives the motor (an overhauling
load, T < 0, once the acceleration has fallen so far that J ω̇/N + T < 0) the same holds with
J_e = J_m + J_g + ηJ/N² and T_e = ηT/N, from the speed of the switch on: the two pieces meet with
the same ω and ω̇ (at the switch T_out = 0 and both read τ = (J_m + J_g)ω̇). The closed forms are
scenes.closed_forms' (ClosedFormPhase), each piece one phase.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import NamedTuple

from taucli.writing.report import Step, Trajectory, fmt, quantity_text, term
from taucli.scenes.closed_forms import ClosedFormPhase
from taucli.scenes.drive.train import TWO_PI, Train, torque_step
from taucli.options.table import Results


@dataclass(frozen=True)
class Motor:
    """A torque–speed line τ_s(1 − ω/ω_nl), or a constant torque (no_load None)."""

    stall: float
    no_load: float | None = None

    def torque(self, omega: float) -> float:
        return self.stall if self.no_load is None else self.stall * (1.0 - omega / self.no_load)

    @property
    def slope(self) -> float:
        """b = τ_s/ω_nl: the line's fall of torque per unit speed."""
        return 0.0 if self.no_load is None else self.stall / self.no_load


class Piece(NamedTuple):
    """One stretch of the run-up with the power flowing one way."""

    inertia: float  # J_e
    load: float  # T_e
    driving: bool  # True: the motor drives the load; False: the load drives the motor
    phase: ClosedFormPhase
    t0: float
    theta0: float


def effective(train: Train, driving: bool) -> tuple[float, float]:
    """(J_e, T_e): J_m + J_g + J/(N²η), T/(Nη) + τ_mf while driving; J_m + J_g + η′J/N², η′T/N + τ_mf while regenerating."""
    n2 = train.ratio * train.ratio
    if driving:
        return train.input_inertia + train.load / (n2 * train.efficiency), train.torque / (train.ratio * train.efficiency) + train.motor_friction
    return train.input_inertia + train.back * train.load / n2, train.back * train.torque / train.ratio + train.motor_friction


def switch_torque(train: Train) -> float | None:
    """The motor torque at which the power through the teeth turns round (T_out = 0: ω̇ = −TN/J),
    τ_sw = −(J_m + J_g)TN/J; None where it never does (no load inertia: T's sign decides)."""
    if train.load == 0:
        return None
    return -train.input_inertia * train.torque * train.ratio / train.load


def pieces(train: Train, motor: Motor) -> list[Piece]:
    """The run-up from rest: one piece, or two where the load starts to drive the motor on the way."""
    switch = switch_torque(train)
    driving = train.torque >= 0 if switch is None else motor.stall >= switch
    inertia, load = effective(train, driving)
    first = Piece(inertia, load, driving, ClosedFormPhase(inertia, motor.stall - load, motor.slope, 0.0, 0.0), 0.0, 0.0)
    if not driving or switch is None or switch <= 0 or motor.no_load is None:
        return [first]
    # the line falls to the switch's torque at ω_sw = ω_nl(1 − τ_sw/τ_s), below ω_ss of the first piece (T < 0 there)
    omega_switch = motor.no_load * (1.0 - switch / motor.stall)
    t_switch = first.phase.time_to(omega_switch)
    if t_switch is None:
        return [first]
    inertia, load = effective(train, False)
    phase = ClosedFormPhase(inertia, motor.stall - load, motor.slope, 0.0, omega_switch)
    return [first, Piece(inertia, load, False, phase, t_switch, first.phase.theta(t_switch))]


class RunUp(NamedTuple):
    time: float | None
    theta: float | None
    work_loss: float | None
    work_motor: float | None


def reach(train: Train, parts: list[Piece], target: float) -> RunUp:
    """Time, angle, loss and motor work from rest to ω = target (None where it is never reached)."""
    time = theta = None
    loss = work = 0.0
    omega_a = 0.0
    for index, piece in enumerate(parts):
        last = index == len(parts) - 1
        end = target if last else parts[index + 1].phase.omega0
        if not last and target < end:
            end, last = target, True
        dt = piece.phase.time_to(end)
        if dt is None:
            return RunUp(None, None, None, None)
        dtheta = piece.phase.theta(dt)
        time, theta = piece.t0 + dt, piece.theta0 + dtheta
        output = train.load * (end * end - omega_a * omega_a) / (2 * train.ratio * train.ratio) + train.torque * dtheta / train.ratio
        loss += train.train_loss(output, piece.driving) + train.motor_friction * dtheta
        work += piece.load * dtheta + piece.inertia * (end * end - omega_a * omega_a) / 2
        omega_a = end
        if last:
            break
    return RunUp(time, theta, loss, work)


def _overhauled(train: Train, torque: float) -> float | None:
    """The motor's α at the start (negative) where gravity on the load beats the motor's torque at
    rest and runs it backwards (#42 item 16: --motor-torque 0, a load that runs down freely
    through the gears); None where the load stays put. Running back, the load drives the motor:
    the train passes η of the output's torque, its friction T_f now against the descent."""
    pull = train.gravity - (train.torque - train.gravity)  # T_g − T_f at the output, down the slope
    back = train.back * pull / train.ratio
    if pull <= 0 or back <= torque + train.motor_friction:
        return None
    return (torque + train.motor_friction - back) / (train.input_inertia + train.back * train.load / (train.ratio * train.ratio))


def run_up(train: Train, motor: Motor, target: float | None, energy: bool, results: Results, notes: list[str], steps: list[Step]) -> Trajectory | None:
    """The motor's own run-up from rest: α at the start, the steady speed and time constant of a
    line, and the time, angle and energy to ``target``."""
    parts = pieces(train, motor)
    first = parts[0]
    alpha0 = first.phase.constant / first.inertia
    steps.extend(_law_steps(train, motor, first))
    if first.phase.constant <= 0 and _runs_back(train, motor, results, notes, steps, target, energy):
        return None
    if first.phase.constant <= 0:
        back = _overhauled(train, motor.stall)
        results.put("alpha0", 0.0 if back is None else back)
        notes.append(f"the motor cannot start the load: it gives {quantity_text(motor.stall, 'N*m')} at rest, the load asks "
                     f"{quantity_text(first.load, 'N*m')} at the motor" + ("" if back is None else
                     "; gravity runs the load down and the motor backwards: α₀ = (τ − η(T_g − T_f)/N)/(J_m + J_g + ηJ/N²), "
                     "the load driving the motor through the train"))
        if motor.no_load is not None:
            results.put("omega_steady", None)
        if target is not None:
            _put_target(results, target, None, train, energy)
            notes.append("t_accel, theta_accel: the motor never turns the load")
        return None
    results.put("alpha0", alpha0)
    if motor.no_load is not None:
        last = parts[-1]
        steady = last.phase.steady_speed
        results.put("omega_steady", steady)
        results.put("time_constant", first.inertia * motor.no_load / motor.stall, ", J_e ω_nl/τ_s")
        if len(parts) > 1:
            notes.append(f"from ω = {quantity_text(last.phase.omega0, 'rad/s')} the load drives the motor (its acceleration no longer "
                         "needs all of its pull): the run-up goes on with ηJ/N² and ηT/N, time constant "
                         f"{quantity_text(last.inertia * motor.no_load / motor.stall, 's')}")
        if steady is not None and steady > motor.no_load:
            notes.append("above the no-load speed the line's torque is negative: the motor holds the load back (a generator)")
    if target is None:
        return None
    found = reach(train, parts, target)
    _put_target(results, target, found, train, energy)
    if found.time is None:
        notes.append(f"t_accel, theta_accel: the motor never reaches {quantity_text(target, 'rad/s')}"
                     + (f"; it settles at {quantity_text(parts[-1].phase.steady_speed, 'rad/s')}" if motor.no_load is not None else ""))
        return None
    used = parts if len(parts) > 1 and target > parts[1].phase.omega0 else parts[:1]
    steps.extend(_target_steps(motor, used, target, found))
    return _curves(parts, found.time)


def _runs_back(train: Train, motor: Motor, results: Results, notes: list[str], steps: list[Step], target: float | None, energy: bool) -> bool:
    """A load whose weight beats the motor's stall torque runs the motor backwards (#42 item 11): going
    down, friction (the rest of T) turns to hold against gravity, and the load drives the motor
    through the teeth, which keep (1 − η): τ_s − ηT_down/N = (J_m + J_g + ηJ/N²)α, T_down = T_g − T_f.
    False where gravity's pull, less what friction can hold, does not beat the motor at rest."""
    friction = train.torque - train.gravity
    down = train.gravity - friction
    back = train.back * down / train.ratio
    if down <= 0 or back <= motor.stall + train.motor_friction:
        return False
    inertia = train.input_inertia + train.back * train.load / (train.ratio * train.ratio)
    alpha0 = (motor.stall + train.motor_friction - back) / inertia
    results.put("alpha0", alpha0, ": negative, the load runs the motor backwards")
    notes.append(f"the motor cannot hold the load: it gives {quantity_text(motor.stall, 'N*m')} at rest, gravity's pull less friction asks "
                 f"{quantity_text(back, 'N*m')} at the motor, so the load runs down and turns the motor backwards")
    steps.append(Step("The load runs the motor backwards", "α = (τ_s − ηT_down/N)/(J_m + J_g + ηJ/N²),  T_down = T_g − T_f",
                      f"({quantity_text(motor.stall, 'N*m')} − {term(back, 'N*m')}) / {quantity_text(inertia, 'kg*m**2')}", quantity_text(alpha0, "rad/s**2"),
                      "going down, friction turns to act against gravity, and the load drives the motor through the teeth, which keep (1 − η) of it"))
    if motor.no_load is not None:
        results.put("omega_steady", motor.no_load * (1 - back / motor.stall), ": negative, the load going down")
    if target is not None:
        _put_target(results, target, None, train, energy)
        notes.append("t_accel, theta_accel: the motor never turns the load forward")
    return True


def _put_target(results: Results, target: float, found: RunUp | None, train: Train, energy: bool) -> None:
    time = None if found is None else found.time
    theta = None if found is None else found.theta
    results.put("t_accel", time, f" to {fmt(target)} rad/s")
    results.put("theta_accel", theta)
    results.put("revs_accel", None if theta is None else theta / TWO_PI)
    if time is not None and energy:
        put_energy(results, train, target, theta, found.work_motor, found.work_loss)


def put_energy(results: Results, train: Train, omega: float, theta: float, work_motor: float, work_loss: float) -> None:
    """KE = ½(J_m + J_r)ω², the work against the load Tθ/N, the loss and the motor's work, to the speed reached."""
    results.put("KE", train.total * omega * omega / 2)
    results.put("work_load", train.torque * theta / train.ratio)
    results.put("work_loss", work_loss)
    results.put("work_motor", work_motor)


def _law_steps(train: Train, motor: Motor, first: Piece) -> list[Step]:
    driving = first.driving
    inertia_equation = "J_e = J_m + J_g + J/(N²η)" if driving else "J_e = J_m + J_g + ηJ/N²"
    load_equation = "T_e = T/(Nη)" if driving else "T_e = ηT/N"
    steps = [Step("Inertia and load the motor drives, through the losses" if driving else "Inertia and load, the load driving the motor",
                  f"{inertia_equation},  {load_equation}",
                  f"{quantity_text(train.input_inertia, 'kg*m**2')} + {quantity_text(train.load, 'kg*m**2')} × "
                  + (f"1/({fmt(train.ratio)}² × {fmt(train.efficiency)})" if driving else f"{fmt(train.back)}/{fmt(train.ratio)}²")
                  + f";  T_e = {quantity_text(first.load, 'N*m')}",
                  quantity_text(first.inertia, "kg*m**2"),
                  "τ = (J_m + J_g)ω̇ + (Jω̇/N + T)/(Nη): the output's torque, inertial and load alike, passes the teeth and pays their loss"
                  if driving else "the output gives power back (Jω̇/N + T < 0): the teeth keep (1 − η) of it, so the motor feels η of it")]
    if motor.no_load is None:
        steps.append(Step("Angular acceleration under a constant torque", "α = (τ − T_e)/J_e",
                          f"({quantity_text(motor.stall, 'N*m')} − {term(first.load, 'N*m')}) / {quantity_text(first.inertia, 'kg*m**2')}",
                          quantity_text(first.phase.constant / first.inertia, "rad/s**2"), "constant torques, constant α: ω = αt"))
        return steps
    steady = motor.no_load * (1 - first.load / motor.stall)
    constant = first.inertia * motor.no_load / motor.stall
    steps.append(Step("Speed where the line meets the load", "τ_s(1 − ω/ω_nl) = T_e  ⇒  ω_ss = ω_nl(1 − T_e/τ_s)",
                      f"{quantity_text(motor.no_load, 'rad/s')} × (1 − {term(first.load, 'N*m')}/{quantity_text(motor.stall, 'N*m')})",
                      quantity_text(steady, "rad/s"), "unloaded it is the no-load speed; a load torque lowers it along the line"))
    steps.append(Step("Mechanical time constant", "J_e dω/dt = (τ_s − T_e) − (τ_s/ω_nl)ω  ⇒  τ_m = J_e ω_nl/τ_s",
                      f"{quantity_text(first.inertia, 'kg*m**2')} × {quantity_text(motor.no_load, 'rad/s')} / {quantity_text(motor.stall, 'N*m')}",
                      quantity_text(constant, "s"),
                      "the line acts as a drive τ_s − T_e with a viscous torque (τ_s/ω_nl)ω: ω(t) = ω_ss(1 − e^(−t/τ_m)), unloaded ω_nl(1 − e^(−t/τ_m))"))
    return steps


def _target_steps(motor: Motor, parts: list[Piece], target: float, found: RunUp) -> list[Step]:
    if motor.no_load is None:
        alpha = parts[-1].phase.constant / parts[-1].inertia
        return [Step("Time to reach the speed", "t = ω₁/α", f"{quantity_text(target, 'rad/s')} / {quantity_text(alpha, 'rad/s**2')}",
                     quantity_text(found.time, "s"), "uniform acceleration from rest"),
                Step("The motor's angle meanwhile", "θ = ω₁t/2", f"{quantity_text(target, 'rad/s')} × {quantity_text(found.time, 's')} / 2",
                     f"{quantity_text(found.theta, 'rad')} = {fmt(found.theta / TWO_PI)} rev", "the mean speed of a uniform run-up is half the last")]
    if len(parts) == 1:
        piece = parts[0]
        steady = piece.phase.steady_speed
        constant = piece.inertia * motor.no_load / motor.stall
        return [Step("Time to reach the speed", "ω(t) = ω_ss(1 − e^(−t/τ_m))  ⇒  t = −τ_m ln(1 − ω₁/ω_ss)",
                     f"−{quantity_text(constant, 's')} × ln(1 − {quantity_text(target, 'rad/s')}/{quantity_text(steady, 'rad/s')})",
                     quantity_text(found.time, "s"), "the speed closes on ω_ss exponentially: the nearer ω₁ to ω_ss, the longer"),
                Step("The motor's angle meanwhile", "θ = ∫ω dt = ω_ss t − τ_m ω₁",
                     f"{quantity_text(steady, 'rad/s')} × {quantity_text(found.time, 's')} − {quantity_text(constant, 's')} × {quantity_text(target, 'rad/s')}",
                     f"{quantity_text(found.theta, 'rad')} = {fmt(found.theta / TWO_PI)} rev", "ω_ss t less what the lag behind ω_ss costs")]
    second = parts[1]
    steady = second.phase.steady_speed
    constant = second.inertia * motor.no_load / motor.stall
    dt = found.time - second.t0
    first = parts[0]
    switch = motor.stall * (1 - second.phase.omega0 / motor.no_load)
    return [Step("Where the load starts to drive the motor", "Jω̇/N + T = 0:  τ_sw = −(J_m + J_g)TN/J,  ω_sw = ω_nl(1 − τ_sw/τ_s)",
                 f"{quantity_text(motor.no_load, 'rad/s')} × (1 − {quantity_text(switch, 'N*m')}/{quantity_text(motor.stall, 'N*m')})",
                 quantity_text(second.phase.omega0, "rad/s"),
                 "past it the load's pull gives more than its acceleration takes: the power through the teeth turns round"),
            Step("Time to the switch", "t_sw = −τ_m ln(1 − ω_sw/ω_ss)",
                 f"−{quantity_text(first.inertia * motor.no_load / motor.stall, 's')} × ln(1 − {quantity_text(second.phase.omega0, 'rad/s')}/"
                 f"{quantity_text(first.phase.steady_speed, 'rad/s')})", quantity_text(second.t0, "s"),
                 f"the first piece, as above; the motor has turned θ_sw = {quantity_text(second.theta0, 'rad')} by then"),
            Step("Time to reach the speed, from the switch", "t = t_sw + τ₂ ln((ω_ss,2 − ω_sw)/(ω_ss,2 − ω₁)),  τ₂ = J_e,2 ω_nl/τ_s",
                 f"{quantity_text(second.t0, 's')} + {quantity_text(constant, 's')} × ln(({quantity_text(steady, 'rad/s')} − "
                 f"{quantity_text(second.phase.omega0, 'rad/s')})/({quantity_text(steady, 'rad/s')} − {quantity_text(target, 'rad/s')}))",
                 quantity_text(found.time, "s"), "the second piece starts where the first ends, with the same ω and ω̇, and closes on its own ω_ss"),
            Step("The motor's angle meanwhile", "θ = θ_sw + ω_ss,2(t − t_sw) − τ₂(ω₁ − ω_sw)",
                 f"{quantity_text(second.theta0, 'rad')} + {quantity_text(steady, 'rad/s')} × {quantity_text(dt, 's')} − "
                 f"{quantity_text(constant, 's')} × ({quantity_text(target, 'rad/s')} − {quantity_text(second.phase.omega0, 'rad/s')})",
                 f"{quantity_text(found.theta, 'rad')} = {fmt(found.theta / TWO_PI)} rev", "each piece as the first: ω_ss times the time, less the lag")]


def _curves(parts: list[Piece], t_end: float) -> Trajectory:
    def state(t: float) -> tuple[float, float]:
        piece = next((p for p in reversed(parts) if t >= p.t0), parts[0])
        return piece.phase.omega(t - piece.t0), piece.theta0 + piece.phase.theta(t - piece.t0)

    curves = (("omega", "rad/s", "motor speed ω"), ("theta", "rad", "motor angle θ"))
    marks = tuple((p.t0, "the load drives the motor") for p in parts[1:] if p.t0 <= t_end)
    return Trajectory(curves, t_end, state, marks=marks)


def uniform(train: Train, alpha: float, target: float | None, energy: bool, results: Results, steps: list[Step], words: str,
            in_time: float | None = None) -> None:
    """A constant α given (or ω₁/t): the torque it takes, and to the target its time, angle and
    energy; with --in-time the time is the one given (not ω₁/(ω₁/t), which may round off it: #42 item 22)."""
    torque = train.motor_torque(alpha)
    results.put("alpha", alpha, words)
    results.put("torque_accel", torque)
    steps.append(torque_step("Motor torque while accelerating", train, alpha, torque))
    if target is None:
        return
    time = target / alpha if in_time is None else in_time
    theta = target * time / 2
    results.put("t_accel", time, f" to {fmt(target)} rad/s")
    results.put("theta_accel", theta)
    results.put("revs_accel", theta / TWO_PI)
    if energy:
        loss = train.run_loss(alpha, target, theta)
        put_energy(results, train, target, theta, torque * theta, loss)
    results.put("power_peak", max(torque * target, 0.0))
    steps.append(Step("Peak power, at the end of the run-up", "P = τω₁", f"{quantity_text(torque, 'N*m')} × {quantity_text(target, 'rad/s')}",
                      quantity_text(torque * target, "W"), "a constant torque at a rising speed: the power is highest as the speed is reached"))
