"""``taucli drive``: read the motor, the train and the load; reflect the load to the motor; then
the run-up (at a constant α, or under the motor's own law) or a move profile.

Every rotation in and out is the motor's (its speed, acceleration and angle); a moving mass's
speed, acceleration and travel are its own, turned into the motor's through the drum's radius or
the screw's lead and the ratio: ω = vN/r, α = aN/r, θ = sN/r (r = p/2π for a screw).
"""

from __future__ import annotations

import math
from dataclasses import replace
from collections.abc import Sequence

from taucli.core.errors import InputError, Unused
from taucli.quantities.kinds import check_bounds, out_of_bounds
from taucli.options.drive import COMMAND as TABLE
from taucli.writing.report import Report, Step, Table, fmt, quantity_text, term
from taucli.scenes.assumed import Assumed
from taucli.scenes.drive import curve as drive_curve
from taucli.scenes.drive import loads as drive_loads
from taucli.scenes.drive import train as drive_train
from taucli.scenes.drive.duty import duty_cycle
from taucli.scenes.drive.motor import Motor, run_up, uniform
from taucli.scenes.drive.profile import Move, solve_profile, trapezoid
from taucli.scenes.drive.train import TWO_PI, Train
from taucli.scenes.inertia import body, body_table
from taucli.options.table import Results

SHAPE_OPTIONS = ("mass", "density", "radius", "inner_radius", "outer_radius", "length", "width", "height", "depth", "axis", "offset")


def drive(
    *,
    motor_inertia: float | None = None,
    stall_torque: float | None = None,
    no_load_speed: float | None = None,
    motor_torque: float | None = None,
    rated_torque: float | None = None,
    peak_torque: float | None = None,
    ratio: Sequence[float] = (),
    efficiency: float | None = None,
    efficiency_back: float | None = None,
    motor_friction: float | None = None,
    gear_inertia: float | None = None,
    load_inertia: float | None = None,
    load_mass: float | None = None,
    drum_radius: float | None = None,
    lead: float | None = None,
    load_torque: float | None = None,
    load_force: float | None = None,
    incline: float | None = None,
    mu: float | None = None,
    g: float | None = None,
    until_omega: float | None = None,
    speed: float | None = None,
    in_time: float | None = None,
    alpha: float | None = None,
    accel: float | None = None,
    accel_time: float | None = None,
    run_time: float | None = None,
    decel_time: float | None = None,
    dwell_time: float | None = None,
    distance: float | None = None,
    move_angle: float | None = None,
    energy: bool = False,
    rated_power: float | None = None,
    segment: Sequence = (),
    rest_factor: float | None = None,
    load: Sequence = (),
    motor_speed: float | None = None,
    motor_curve=None,
    omega0: float | None = None,
    **body_options,
) -> Report:
    """``taucli drive``: the motor (--motor-inertia, its law), the train (--ratio, --efficiency),
    the load (a body at the output, a mass on a drum or screw, what resists), and the motion; or a
    duty cycle of segments (--segment: duty.py)."""
    if segment:
        given = {name: value for name, value in locals().items() if name not in ("segment", "rest_factor", "rated_torque", "rated_power", "body_options")}
        given.update(body_options)
        others = [name for name, value in given.items() if value not in (None, False, (), [])]
        if others:
            also = ", ".join("{" + name + "}" for name in others[1:])
            raise InputError(others[0], "does not apply with {segment}: a duty cycle is its segments' times and torques (or powers) alone"
                             + (f"; leave out {also} too" if also else ""))
        return duty_cycle(tuple(segment), rest_factor, rated_torque, rated_power)
    for name, value in (("rest_factor", rest_factor), ("rated_power", rated_power)):
        if value is not None:
            raise InputError(name, "goes with {segment}: a duty cycle's segments", example="{segment} 'time=10min power=100kW' {segment} 'time=5min power=0'")
    results, notes, steps, assumed = Results(TABLE), [], [], Assumed()
    profile = any(value is not None for value in (accel_time, run_time, decel_time, dwell_time, distance, move_angle))
    if load:
        single = {"ratio": ratio, "efficiency": efficiency, "efficiency_back": efficiency_back, "load_inertia": load_inertia, "load_mass": load_mass,
                  "drum_radius": drum_radius, "lead": lead, "load_torque": load_torque, "load_force": load_force, "incline": incline, "mu": mu, "g": g,
                  "speed": speed, "accel": accel, "distance": distance, **body_options}
        train = drive_loads.several(tuple(load), motor_inertia, gear_inertia, motor_friction, motor_speed, single, results, steps)
        stages, eta, moment, screw, torque, parts = (), 1.0, None, False, train.torque, None
        tables = {"loads": drive_loads.table(train)}
    else:
        stages = tuple(ratio or ())
        n = _ratio(stages)
        eta = 1.0 if efficiency is None else efficiency
        if eta > 1:
            raise InputError("efficiency", "expected a number above 0 and at most 1 (the whole train's, motor to load)", example="{efficiency} 0.9",
                             got=fmt(eta))
        if efficiency_back is not None and efficiency_back > 1:
            raise InputError("efficiency_back", "expected a number above 0 and at most 1 (the train's where the load drives the motor)",
                             example="{efficiency_back} 0.6", got=fmt(efficiency_back))
        moment, body_steps, parts = _load_body(load_inertia, body_options, notes)
        lever, screw = _lever(drum_radius, lead)
        linear = _linear(load_mass, lever, screw, steps)
        gravity_needed = load_mass is not None and (bool(incline) or bool(mu))
        if g is not None and not gravity_needed:
            raise Unused("g", "is used only for gravity on the moving mass ({incline}, {mu}), or to read a weight given for a mass")
        force, gravity_force, force_steps = _force(load_mass, load_force, incline or 0.0, mu, lever, assumed.gravity(g) if gravity_needed else None)
        torque = (load_torque or 0.0) + (force * lever if force else 0.0)
        if not any((moment, linear, torque, gear_inertia, load_mass is not None, motor_curve is not None)):
            raise InputError("load_inertia", "or another load is required: a rotating load ({load_inertia}, {shape}, {part}), a mass "
                             "({load_mass} with {drum_radius} or {lead}), {load_torque} or {load_force}",
                             example="{load_inertia} '0.05kg*m^2'")
        train = Train(n, eta, motor_inertia, gear_inertia or 0.0, (moment or 0.0) + linear, torque,
                      gravity_force * lever if gravity_force else 0.0, lever, efficiency_back, motor_friction or 0.0)
        steps[:0] = list(body_steps)
        _reflect(train, stages, moment or 0.0, linear, screw, results, notes, steps)
        steps.extend(force_steps)
        loaded = profile or any(value is not None for value in (load_torque, load_force, mu, motor_friction)) or bool(incline)
        _load_torque(train, load_torque, force, screw, loaded, results, steps)
        tables = {} if parts is None else {"parts": parts}

    top, top_words = _top(until_omega, speed, train)
    rate = _rate(alpha, accel, train)
    rate_name = "alpha" if alpha is not None else "accel"
    angle = _angle(distance, move_angle, train)
    law = _law(stall_torque, no_load_speed, motor_torque)
    regime, trajectory, method = "reflected to the motor", None, "closed form"
    if omega0 is not None and motor_curve is None:
        raise InputError("omega0", "goes with {motor_curve}: the speed where a run-up on the motor's curve starts",
                         example="{motor_curve} 'tmax=400N*m slip-max=0.2 sync=1500rpm' {omega0} 500rpm {until_omega} 1400rpm")
    if motor_curve is not None:
        others = [name for name, value in (("stall_torque", stall_torque), ("no_load_speed", no_load_speed), ("motor_torque", motor_torque),
                                           ("in_time", in_time), ("alpha", alpha), ("accel", accel), ("accel_time", accel_time),
                                           ("distance", distance), ("move_angle", move_angle), ("energy", energy or None)) if value is not None]
        if others:
            raise InputError(others[0], "conflicts with {motor_curve}: the motor's curve sets how fast it gets there"
                             + ("; a move profile's ramps are given, not the motor's" if others[0] in ("accel_time", "distance", "move_angle") else "")
                             + ("; its energy is energy_accel, the rotor's loss" if others[0] == "energy" else ""))
        train = _rotor(train, notes, "the run-up on the motor's curve")
        drive_curve.run_up(train, motor_curve, omega0 or 0.0, top, results, notes, steps)
        if omega0:
            notes.append(f"alpha0: at ω₀ = {fmt(omega0)} rad/s, where the run-up starts")
        regime = "run-up on the induction motor's torque–slip curve (Kloss)"
        method = drive_curve.method(train)
        if motor_speed is not None:
            drive_loads.put_power(train, motor_speed, results, steps)
    elif profile:
        if motor_speed is not None:
            raise InputError("motor_speed", "conflicts with a move profile: the move's top speed is the speed it runs at", example="{speed} 15m/min")
        angle_name = "distance" if distance is not None else "move_angle"
        move = _move(top, (rate, rate_name), (angle, angle_name), in_time, accel_time, run_time, decel_time, dwell_time, notes, steps)
        train = _rotor(train, notes, "the torques of a move")
        trajectory = solve_profile(train, move, {"rated": rated_torque, "peak": peak_torque, "motor": law}, results, notes, steps)
        regime = "move profile" + (" (a triangle)" if move.run == 0 and accel_time is None else "")
    else:
        for name, value in (("rated_torque", rated_torque), ("peak_torque", peak_torque)):
            if value is not None:
                raise InputError(name, "goes with a move profile: a cycle's RMS and peak torques are held against it",
                                 example="{accel_time} 0.1s {run_time} 1s {dwell_time} 0.3s")
        if motor_speed is not None:
            drive_loads.put_power(train, motor_speed, results, steps)
        if law is not None and load:
            raise InputError("load", "with the motor's torque–speed line or a constant {motor_torque} is not built: several loads take the run-up at a "
                             "constant α ({in_time} or {alpha}) or on an induction motor's {motor_curve}", example="{until_omega} 1420rpm {in_time} 2s")
        if law is not None:
            for name, value in (("in_time", in_time), ("alpha", alpha), ("accel", accel)):
                if value is not None:
                    raise InputError(name, "conflicts with the motor's law ({stall_torque} and {no_load_speed}, or {motor_torque}): "
                                     "the motor sets how fast it gets there")
            train = _rotor(train, notes, "the run-up under the motor's torque")
            trajectory = run_up(train, law, top, energy, results, notes, steps)
            regime = "run-up on the torque–speed line" if law.no_load is not None else "run-up under a constant motor torque"
        elif rate is not None or in_time is not None:
            rate, words = _uniform_rate(rate, top, in_time, alpha)
            train = _rotor(train, notes, "the torque to accelerate")
            uniform(train, rate, top, energy, results, steps, words, in_time)
            regime = "acceleration at a constant α"
        elif top is not None:
            raise InputError(top_words, "needs a way to get there: {in_time}, {alpha} (or {accel}), or the motor's law "
                             "({stall_torque} with {no_load_speed}, or {motor_torque})", example="{in_time} 0.2s")
    if energy and "KE" not in results and results.get("t_accel") is None or energy and profile:
        notes.append("KE, work_motor, work_load, work_loss: " + ("a move's energy over its cycle is power_mean × t_cycle" if profile else
                     "the energy is to a speed reached from rest ({until_omega} or {speed}, with {in_time}, {alpha} or the motor's law)"))
    if load:
        model = f"{len(train.branches)} load{'s' if len(train.branches) != 1 else ''}, each through its own train: {regime}"
    elif motor_curve is not None and not any((moment, load_mass is not None, torque, gear_inertia)):
        model = f"the motor alone: {regime}"
    else:
        model = f"{_load_words(moment, load_mass, screw, torque)} through {_train_words(stages, eta)}: {regime}"
    report = Report("drive", model, method, results, steps, notes)
    if trajectory is not None:
        report.trajectory = lambda: trajectory
    if tables:
        report.tables = tables
    return assumed.applied(report)


def _ratio(stages: tuple[float, ...]) -> float:
    """N = ΠNᵢ, held to a number's bounds as any typed quantity is."""
    n = math.prod(stages) if stages else 1.0
    got = f"N = {n:g} from the stages {', '.join(fmt(s) for s in stages)}"
    if n == 0:  # positive stages whose product is below what a double holds (1e-40 nine times): not 0, and not to divide by
        raise out_of_bounds("dimensionless", "ratio", sign="positive", got=got.replace("N = 0", "N below 1e-308", 1))
    check_bounds(n, "dimensionless", "ratio", sign="positive", got=got)
    return n


def _load_body(load_inertia: float | None, options: dict, notes: list[str]) -> tuple[float | None, Sequence[Step], Table | None]:
    """The rotating load at the output: --load-inertia, or a shape and its options, or parts (None: none)."""
    shape, part, gyration = options.get("shape"), options.get("part"), options.get("gyration")
    given = [name for name in SHAPE_OPTIONS if options.get(name) is not None]
    if load_inertia is not None:
        if shape is not None or gyration is not None:
            raise InputError("load_inertia", f"conflicts with {{{'shape' if shape is not None else 'gyration'}}}: give one of them")
        if given:
            raise InputError(given[0], "goes with {shape}; with {load_inertia} it is not used")
    elif shape is None and gyration is None and given and not part:
        raise InputError(given[0], "goes with {shape}: the rotating load's shape", example="{shape} disc {mass} 5kg {radius} 0.2m")
    if load_inertia is None and shape is None and gyration is None and not part:
        return None, (), None
    moment, steps = body(inertia=load_inertia, notes=notes, **options)
    return moment, steps, body_table(inertia=load_inertia, **options)


def _lever(drum_radius: float | None, lead: float | None) -> tuple[float | None, bool]:
    """The mass's travel per radian of its shaft: r, or p/2π for a screw."""
    if drum_radius is not None and lead is not None:
        raise InputError("lead", "conflicts with {drum_radius}: the mass is moved by a screw or by a drum, belt or pinion")
    if lead is not None:
        return lead / TWO_PI, True
    return drum_radius, False


def _linear(mass: float | None, lever: float | None, screw: bool, steps: list[Step]) -> float:
    if mass is None:
        return 0.0
    if lever is None:
        raise InputError("load_mass", "needs what moves it: {drum_radius} (a drum, belt, pinion) or {lead} (a screw)", example="{lead} 10mm")
    inertia = mass * lever * lever
    steps.append(drive_train.linear_step(mass, lever, screw, inertia))
    return inertia


def _force(mass: float | None, load_force: float | None, incline: float, mu: float | None, lever: float | None,
           g: float | None) -> tuple[float, float, list[Step]]:
    """F = F_ext + μmg cos θ + mg sin θ against the motion, its gravity part, and its step."""
    for name, value in (("incline", incline), ("mu", mu)):
        if value and mass is None:
            raise InputError(name, "goes with {load_mass}: it acts on the moving mass", example="{load_mass} 50kg {drum_radius} 5cm")
    if load_force is not None and lever is None:
        raise InputError("load_force", "needs what the mass's motion turns: {drum_radius} or {lead}", example="{lead} 10mm")
    if mass is not None and incline and not -math.pi / 2 - 1e-12 <= incline <= math.pi / 2 + 1e-12:
        raise InputError("incline", "expected an angle from -90 to 90 deg above the horizontal", example="{incline} 30deg", got=f"{fmt(math.degrees(incline))} deg")
    if g is None:
        return load_force or 0.0, 0.0, []
    parts: list[tuple[str, str, float]] = []
    if load_force:
        parts.append(("F_ext", term(load_force, "N"), load_force))
    cos, sin = _cos_sin(incline)
    if mu:
        normal = mass * g * cos
        parts.append(("μmg cos θ" if incline else "μmg", f"{fmt(mu)} × {quantity_text(mass, 'kg')} × {quantity_text(g, 'm/s**2')}"
                      + (f" × cos {fmt(math.degrees(incline))}°" if incline else ""), mu * normal))
    gravity = mass * g * sin
    if incline:
        parts.append(("mg sin θ", f"{quantity_text(mass, 'kg')} × {quantity_text(g, 'm/s**2')} × sin {fmt(math.degrees(incline))}°", gravity))
    force = math.fsum(value for _, _, value in parts)
    return force, gravity, [drive_train.force_step(parts, force)]


def _cos_sin(angle: float) -> tuple[float, float]:
    """cos θ and sin θ, exact at ±90° (a hoist: no normal force, all the weight along the travel)."""
    if abs(abs(angle) - math.pi / 2) <= 4.5e-16:
        return 0.0, math.copysign(1.0, angle)
    return math.cos(angle), math.sin(angle)


def _reflect(train: Train, stages: tuple[float, ...], moment: float, linear: float, screw: bool, results: Results, notes: list[str],
             steps: list[Step]) -> None:
    if len(stages) > 1:
        results.put("ratio_total", train.ratio)
        steps.append(drive_train.ratio_step(stages, train.ratio))
    if linear:
        results.put("linear_inertia", linear, ", m(p/2π)²" if screw else ", m r²")
    results.put("reflected_inertia", train.reflected, ", J_g + J/N²")
    steps.append(drive_train.reflected_step(train, moment, linear))
    if train.rotor is None:
        return
    results.put("total_inertia", train.total)
    if train.rotor == 0:
        results.put("inertia_ratio", None)
        notes.append("inertia_ratio: the rotor is given no inertia")
        return
    results.put("inertia_ratio", train.reflected / train.rotor)
    steps.append(drive_train.inertia_ratio_step(train))
    if train.load > 0:
        optimal = math.sqrt(train.load / train.rotor)
        results.put("ratio_optimal", optimal)
        steps.append(drive_train.optimal_step(train, optimal))


def _load_torque(train: Train, load_torque: float | None, force: float, screw: bool, loaded: bool, results: Results, steps: list[Step]) -> None:
    """T at the output shaft, and at the motor where a load torque is given (or a move runs against it)."""
    if force:
        steps.append(drive_train.load_torque_step(load_torque or 0.0, force, train.lever, screw, train.torque))
    if loaded:
        results.put("load_torque_motor", train.running)
    if train.torque or train.motor_friction:
        steps.append(drive_train.motor_load_step(train))
    if train.gravity:
        results.put("torque_hold", train.hold)
        steps.append(drive_train.hold_step(train))


def _top(until_omega: float | None, speed: float | None, train: Train) -> tuple[float | None, str]:
    """The motor speed to reach: --until-omega, or the mass's --speed as ω = vN/r."""
    if until_omega is not None and speed is not None:
        raise InputError("speed", "conflicts with {until_omega}: give the motor's speed or the mass's")
    if speed is None:
        return until_omega, "until_omega"
    if train.lever is None:
        raise InputError("speed", "needs what the mass's motion turns: {drum_radius} or {lead}", example="{lead} 10mm")
    return speed * train.ratio / train.lever, "speed"


def _rate(alpha: float | None, accel: float | None, train: Train) -> float | None:
    if alpha is not None and accel is not None:
        raise InputError("accel", "conflicts with {alpha}: give the motor's acceleration or the mass's")
    if accel is None:
        return alpha
    if train.lever is None:
        raise InputError("accel", "needs what the mass's motion turns: {drum_radius} or {lead}", example="{lead} 10mm")
    return accel * train.ratio / train.lever


def _angle(distance: float | None, move_angle: float | None, train: Train) -> float | None:
    if distance is not None and move_angle is not None:
        raise InputError("distance", "conflicts with {move_angle}: give the mass's travel or the motor's turn")
    if distance is None:
        return move_angle
    if train.lever is None:
        raise InputError("distance", "needs what the mass's motion turns: {drum_radius} or {lead}", example="{lead} 10mm")
    return distance * train.ratio / train.lever


def _law(stall: float | None, no_load: float | None, constant: float | None) -> Motor | None:
    if constant is not None:
        if stall is not None or no_load is not None:
            raise InputError("motor_torque", "conflicts with the torque–speed line ({stall_torque}, {no_load_speed}): give one law")
        return Motor(constant)
    if (stall is None) != (no_load is None):
        missing = "no_load_speed" if no_load is None else "stall_torque"
        raise InputError(missing, "is required: the line needs both ends, {stall_torque} and {no_load_speed}",
                         example="{stall_torque} '2N*m' {no_load_speed} 3000rpm")
    return None if stall is None else Motor(stall, no_load)


def _rotor(train: Train, notes: list[str], what: str) -> Train:
    """The train with its rotor's inertia; not given, neglected (0) with a note (#42 item 16)."""
    if train.rotor is not None:
        return train
    notes.append(f"no --motor-inertia: the motor's rotor neglected (J_m = 0) in {what}; give {{motor_inertia}} to count it")
    return replace(train, rotor=0.0)


def _uniform_rate(rate: float | None, top: float | None, in_time: float | None, alpha: float | None) -> tuple[float, str]:
    if in_time is None:
        return rate, ""
    if top is None:
        raise InputError("in_time", "needs the speed to reach: {until_omega} or {speed}", example="{until_omega} 3000rpm {in_time} 0.2s")
    if rate is not None:
        raise InputError("in_time", "conflicts with " + ("{alpha}" if alpha is not None else "{accel}") + ": the time and the speed set the acceleration")
    return top / in_time, " (ω₁/t)"


def _move(top, given_rate, given_angle, in_time, accel_time, run_time, decel_time, dwell_time, notes: list[str], steps: list[Step]) -> Move:
    """The cycle: from the phases' times (and the top speed or the travel), or a trapezoid from the travel."""
    rate, rate_name = given_rate
    angle, angle_name = given_angle
    if in_time is not None:
        raise InputError("in_time", "conflicts with a move profile: give its ramp as {accel_time}", example="{accel_time} 0.1s")
    dwell = dwell_time or 0.0
    if accel_time is None:
        for name, value in (("run_time", run_time), ("decel_time", decel_time)):
            if value is not None:
                raise InputError(name, "goes with {accel_time}; a move from its travel, top speed and acceleration sets its own times")
        if angle is None:
            raise InputError("distance", "or {move_angle} is required for a move without {accel_time}: its travel, with {speed} and {accel}",
                             example="{distance} 0.275m {speed} 15m/min {accel} 2.5m/s^2")
        if rate is None:
            raise InputError("accel", "or {alpha} is required with the travel: the ramps' acceleration", example="{accel} 2.5m/s^2")
        return trapezoid(angle, top, rate, dwell, notes, steps)
    if rate is not None:
        raise InputError(rate_name, "conflicts with {accel_time}: the ramp is given by its time")
    decel = accel_time if decel_time is None else decel_time
    if decel_time is None:
        notes.append("t_d = t_a: the deceleration takes as long as the acceleration ({decel_time} to change)")
    run = run_time or 0.0
    if top is not None and angle is not None:
        raise InputError(angle_name, "conflicts with the top speed ({until_omega} or {speed}) beside {accel_time}: with the times, "
                         "the travel sets the top speed and the top speed the travel",
                         hint="leave out one of them: the travel or the top speed", example="{distance} 1m {accel_time} 0.5s")
    if top is None:
        if angle is None:
            raise InputError("until_omega", "or {speed}, or the travel {distance}, is required with {accel_time}: the move's top speed",
                             example="{speed} 15m/min")
        top = angle / (accel_time / 2 + run + decel / 2)
        steps.append(Step("Top speed from the travel and the times", "θ = ω(t_a/2 + t_r + t_d/2)  ⇒  ω = θ/(t_a/2 + t_r + t_d/2)",
                          f"{quantity_text(angle, 'rad')} / ({quantity_text(accel_time, 's')}/2 + {quantity_text(run, 's')} + {quantity_text(decel, 's')}/2)",
                          quantity_text(top, "rad/s"), "the travel is the area under the speed: a trapezoid"))
    return Move(top, accel_time, run, decel, dwell)


def _load_words(moment: float | None, mass: float | None, screw: bool, torque: float) -> str:
    words = []
    if moment:
        words.append("a rotating load")
    if mass is not None:
        words.append("a mass on a screw" if screw else "a mass on a drum")
    if not words:
        words.append("a load torque" if torque else "the gearing alone")
    return " and ".join(words)


def _train_words(stages: tuple[float, ...], eta: float) -> str:
    ratio = " × ".join(fmt(s) for s in stages) if stages else "1 (direct)"
    return f"N = {ratio}" + (f", η = {fmt(eta)}" if eta != 1 else "")
