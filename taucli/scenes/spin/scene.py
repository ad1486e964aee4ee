"""``taucli spin-down``: read the wheel, its start and its torques, pick the model, solve.

The models (one module each): constant α (--alpha, or kinematics with no body), a motor of
constant power (--power), the drive that meets a target in a time (--in-time), and the torque
laws (the rest). Before any of them: the body, ω₀ (given, from a rim speed or from the stored
energy), a target given as an arc at the rim, the push that makes the drive, and the brakes' and
faces' friction added to the axle's. After: the parts table, the contacts' shares of the work,
what was assumed, and a point on the body (--at).

Kept whole: the one reader of spin-down's fifty-odd options, each family read in the order the
models need it (the models, the corner, the balance with no body and the phases are modules of
their own); split further, the order would be spread over files that each need the others.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

from taucli.core.errors import InputError, Unused
from taucli.options.spin_down import COMMAND as TABLE
from taucli.writing.report import Report, Step, Table, fmt, quantity_text, term
from taucli.scenes.assumed import Assumed
from taucli.scenes.centrifugal import with_centrifugal
from taucli.scenes.inertia import body, body_table
from taucli.scenes.point import RIM, rim_radius
from taucli.scenes.push import Push, drive_steps
from taucli.numerics.of_time import OfTime
from taucli.scenes.spin.constant_alpha import constant_alpha_report
from taucli.scenes.spin.of_time import formula_run
from taucli.scenes.spin.phases import phases_run
from taucli.scenes.spin.targets import as_given, with_momentum, with_revs_until
from taucli.scenes.spin.corner import corner_torque
from taucli.scenes.spin.contacts import put_contacts, split_contacts, with_contacts
from taucli.scenes.heating import with_temperature_rise
from taucli.scenes.spin.mean import with_omega_mean
from taucli.scenes.spin.point import with_point
from taucli.scenes.spin.power import power_report
from taucli.scenes.spin.steady import steady_report
from taucli.scenes.spin.steps import Torques
from taucli.scenes.spin.torque_laws import drive_for_target, solve
from taucli.scenes.spin.transfer import transfer_report
from taucli.options.table import Results


@dataclass
class Wheel:
    """The turning body: its moment of inertia (None: no body, kinematics only), the steps that
    found it, its parts table, and the radius of its rim where one is known."""

    inertia: float | None
    steps: Sequence[Step]
    parts: Table | None
    rim: float | None


@dataclass
class Front:
    """What is worked out before the motion (ω₀ from a rim speed or KE0, the contacts' torques):
    its results, steps and notes go first in the report."""

    results: Results = field(default_factory=lambda: Results(TABLE))
    steps: list[Step] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)


@with_centrifugal(TABLE)
def spin_down(
    *,
    omega0: float | None = None,
    torque: float | None = None,
    force: float | None = None,
    lever: float | None = None,
    push_angle: float | None = None,
    friction: float | None = None,
    brake: Sequence | None = None,
    face: Sequence | None = None,
    band: Sequence | None = None,
    caliper: Sequence | None = None,
    g: float | None = None,
    at: float | None = None,
    viscous: float | None = None,
    corner: float | None = None,
    drive_slope: float | None = None,
    drag: float | None = None,
    drag_exponent: float | None = None,
    time: float | None = None,
    until_omega: float | None = None,
    until_angle: float | None = None,
    until_arc: float | None = None,
    alpha: float | None = None,
    in_time: float | None = None,
    in_angle: float | None = None,
    power: float | None = None,
    ke0: float | None = None,
    rim_speed: float | None = None,
    rim_accel: float | None = None,
    work: float | None = None,
    lift_mass: float | None = None,
    vehicle_mass: float | None = None,
    efficiency: float | None = None,
    energy: bool = False,
    heat_mass: float | None = None,
    specific_heat: float | None = None,
    method: str = "auto",
    dt: float | None = None,
    rtol: float | None = None,
    phase: Sequence | None = None,
    **body_options,
) -> Report:
    """``taucli spin-down``: the body (--inertia or --shape ...), its torques, and what to report.

    The drive is --torque, or the push --force at --lever (at --push-angle, default 90°) that
    makes it, or a motor of constant --power; the losses left out are zero; the wheel starts at
    ω₀ = 0 unless --omega0 (or --rim-speed, or --ke0) says. --alpha, or no body at all, is
    rotation at constant α: any three of ω₀, ω₁, α, t, θ give the rest.
    """
    if phase:
        others = {"torque": torque, "force": force, "lever": lever, "friction": friction, "brake": brake or None, "face": face or None,
                  "band": band or None, "caliper": caliper or None, "viscous": viscous, "drag": drag, "until_omega": until_omega, "until_angle": until_angle,
                  "until_arc": until_arc, "alpha": alpha, "in_time": in_time, "in_angle": in_angle, "power": power, "ke0": ke0,
                  "rim_speed": rim_speed, "rim_accel": rim_accel, "work": work, "lift_mass": lift_mass, "vehicle_mass": vehicle_mass,
                  "efficiency": efficiency, "at": at, "dt": dt, "rtol": rtol, "g": g}
        return phases_run(others, method, phase, omega0, time, body_options)
    if isinstance(torque, OfTime) or isinstance(alpha, OfTime):
        others = {"force": force, "lever": lever, "friction": friction, "brake": brake or None, "face": face or None, "band": band or None,
                  "caliper": caliper or None, "viscous": viscous, "drag": drag, "until_angle": until_angle, "until_arc": until_arc, "in_time": in_time, "in_angle": in_angle,
                  "power": power, "ke0": ke0, "rim_speed": rim_speed, "rim_accel": rim_accel, "work": work, "lift_mass": lift_mass,
                  "vehicle_mass": vehicle_mass, "efficiency": efficiency, "at": at, "dt": dt, "rtol": rtol, "g": g,
                  "torque" if isinstance(alpha, OfTime) else "alpha": torque if isinstance(alpha, OfTime) else alpha}
        return formula_run(others, method, torque, alpha, omega0, time, until_omega, body_options)
    if power == 0:
        power = None  # a motor of no power is no motor
    if g is not None and lift_mass is None and corner is None and not any(plate.by_weight for plate in face or ()):
        raise Unused("g", "is used only for the weight on a {face} with no force=, a {lift_mass}, a body in a {corner}, or to read a weight given for a mass")
    front = Front()
    wheel = _wheel(body_options, rim_speed, until_arc, at, rim_accel, front.notes)
    omega0 = _initial_speed(wheel, omega0, rim_speed, ke0, front)
    uses = {"work": work, "lift_mass": lift_mass, "vehicle_mass": vehicle_mass}
    if efficiency is not None or any(value is not None for value in uses.values()):
        others = {"torque": torque, "force": force, "friction": friction, "brake": brake or None, "face": face or None, "caliper": caliper or None, "viscous": viscous,
                  "drag": drag, "time": time, "until_angle": until_angle, "until_arc": until_arc, "alpha": alpha, "in_time": in_time,
                  "in_angle": in_angle, "power": power, "rim_accel": rim_accel, "at": at}
        return _transfer(wheel, omega0, uses, efficiency, until_omega, g, others, front)
    if rim_accel is not None:
        alpha = _alpha_of_rim(rim_accel, alpha, wheel.rim, front)
    if until_arc is not None:
        until_angle = _angle_of_arc(until_arc, until_angle, wheel.rim, front)
    push = _push(force, lever, push_angle)
    drive = (torque or 0.0) + (push.torque if push is not None else 0.0)
    assumed, axle = Assumed(), friction or 0.0
    _one_sense(brake, band, omega0, drive, in_time, in_angle)
    contact = (put_contacts(brake or (), face or (), body_options, wheel.rim, assumed, g, front.results, front.steps, front.notes, axle, band or (),
                            caliper or ()) if brake or face or band or caliper else None)
    friction = axle + contact.kinetic if contact is not None else friction
    if corner is not None:
        radius = body_options.get("radius", body_options.get("outer_radius")) if body_options.get("shape") is not None else wheel.rim
        friction = (friction or 0.0) + corner_torque(body_options.get("mass"), radius, corner, assumed.gravity(g), front.results, front.steps)
    static = None if contact is None or contact.static == contact.kinetic else axle + contact.static
    torques = Torques(drive, friction or 0.0, viscous or 0.0, drag or 0.0, 2.0 if drag_exponent is None else drag_exponent, static)
    targets = {"time": time, "until_omega": until_omega, "until_angle": until_angle}

    if in_angle is not None:  # ω₁ within an angle: the target angle is given, and the drive (or α) is what meets it
        in_angle = _within_angle(in_angle, until_omega, targets, in_time, alpha, torque, push, power)
        targets = {**targets, "until_angle": in_angle}

    if wheel.inertia is None and alpha is None and power is None and in_time is None and in_angle is None and (viscous or drag or drive_slope):
        asked = next((name for name, value in (*targets.items(), ("at", at)) if value is not None), None)
        if asked is not None:
            raise InputError(asked, "needs a body ({inertia} or {shape}): with no body spin-down gives only where the torques balance",
                             example="{inertia} '2kg*m^2'")
        return assumed.applied(steady_report(torques, drive_slope or 0.0, omega0, front))
    if drive_slope is not None:
        raise InputError("drive_slope", "is read with no body, for the speeds where the torques balance; the motion in time with a drive "
                         "that changes with speed is not modelled yet (leave out --inertia and --shape)")

    # The model: constant α, a motor of constant power, the drive that meets a target in a time or
    # an angle, or the torque laws.
    if (alpha is not None or wheel.inertia is None) and in_angle is None:
        report, targets = _at_constant_alpha(wheel, torques, omega0, alpha, power, in_time, targets, front)
    elif power is not None:
        if in_time is not None:
            raise InputError("in_time", "conflicts with {power}: the drive is the motor's")
        if push is not None:
            raise InputError("power", "conflicts with {force}: give the motor's power or the push")
        report = power_report(wheel.inertia, wheel.steps, power, torques, omega0 or 0.0, **targets, method=method, dt=dt, rtol=rtol)
        report = _with_front(report, front.results, front.notes, front.steps)
    elif in_angle is not None:
        report, targets, torques = _in_angle(wheel, torques, omega0, in_angle, targets, front, method, dt, rtol)
    elif in_time is not None:
        if torque is not None or push is not None:
            raise InputError("in_time", "asks for the drive torque that meets the target, so it conflicts with a drive ({torque}, {force}, {power})")
        report, targets, torques = _in_time(wheel, torques, omega0, in_time, targets, front, method, dt, rtol)
    else:
        report = _under_torques(wheel, torques, omega0, targets, front, drive_steps(push, torque), method, dt, rtol,
                                energy or ke0 is not None or heat_mass is not None)

    report = assumed.applied(with_contacts(split_contacts(_with_parts(report, wheel.parts), axle, contact), contact))
    report = with_temperature_rise(report, heat_mass, specific_heat)
    with_revs_until(report.results)
    with_momentum(report.results, wheel.inertia)
    report = with_omega_mean(report, omega0, **targets)
    if at is None:
        return report
    r, note = rim_radius(at, wheel.rim if wheel.rim is not None else body_options.get("radius", body_options.get("outer_radius")), "a body with {radius}")
    report = with_point(report, r, torques, wheel.inertia, power, omega0, **targets, rim=(wheel.rim, rim_speed, rim_accel, until_arc))
    report.notes += [note] if note else []
    return report


def _transfer(wheel: Wheel, omega0: float | None, uses: dict, efficiency: float | None, until_omega: float | None, g: float | None,
              others: dict, front: Front) -> Report:
    """Energy added or taken (--work), or the stored energy put to a load (--lift-mass,
    --vehicle-mass at --efficiency): an energy balance, with no motion in time."""
    given = [name for name, value in uses.items() if value is not None]
    if not given:
        raise InputError("efficiency", "goes with {lift_mass} or {vehicle_mass}: the share of the stored energy that reaches the load",
                         example="{lift_mass} 50kg {efficiency} 0.8")
    if uses["work"] is not None and len(given) > 1:
        raise InputError(given[1], "conflicts with {work}: give the work done on the wheel, or the load its energy goes to")
    if uses["work"] is not None and efficiency is not None:
        raise InputError("efficiency", "goes with {lift_mass} or {vehicle_mass}; {work} is the work done on the wheel itself")
    if uses["work"] is not None and until_omega is not None:
        raise InputError("until_omega", "conflicts with {work}: the work fixes the speed after")
    for name, value in others.items():
        if value is not None:
            raise InputError(name, f"conflicts with {{{given[0]}}}: an energy balance, from the speed before to the speed after, takes no torques, times or targets")
    if wheel.inertia is None:
        raise InputError(given[0], "needs a body ({inertia} or {shape}): its energy is ½Iω²", example="{inertia} '2kg*m^2' {omega0} 300rpm")
    if efficiency is not None and not 0 < efficiency <= 1:
        raise InputError("efficiency", "expected a number above 0 and at most 1", example="{efficiency} 0.8", got=f"{efficiency:g}")
    assumed = Assumed()
    gravity = assumed.gravity(g) if uses["lift_mass"] is not None else 0.0
    report = transfer_report(wheel.inertia, wheel.steps, omega0 or 0.0, work=uses["work"], lift_mass=uses["lift_mass"], vehicle_mass=uses["vehicle_mass"],
                             efficiency=efficiency, until_omega=until_omega, g=gravity, front=(front.steps, front.notes, front.results))
    return assumed.applied(_with_parts(report, wheel.parts))


def _alpha_of_rim(rim_accel: float, alpha: float | None, rim: float, front: Front) -> float:
    """α from the tangential acceleration of the rim: a_t = αR."""
    if alpha is not None:
        raise InputError("rim_accel", "conflicts with {alpha}: give the angular acceleration one way")
    alpha = rim_accel / rim
    front.steps.append(Step("Angular acceleration from the rim's tangential acceleration", "a_t = αR  ⇒  α = a_t/R",
                            f"{term(rim_accel, 'm/s**2')} / {quantity_text(rim, 'm')}", quantity_text(alpha, "rad/s**2"),
                            "every point of a rigid wheel turns with the same α; at radius R its speed changes at a_t = αR"))
    front.notes.append(f"α = a_t/R = {quantity_text(alpha, 'rad/s**2')}: the rim's tangential acceleration {quantity_text(rim_accel, 'm/s**2')} at R = {quantity_text(rim, 'm')}")
    return alpha


def _wheel(body_options: dict, rim_speed: float | None, until_arc: float | None, at, rim_accel: float | None = None, notes: list[str] | None = None) -> Wheel:
    """The body (--inertia, or --shape and its dimensions, or parts), and its rim: --radius beside
    --inertia is the rim's (for a rim speed, an arc or a point at the rim), else the shape's radius."""
    has_body = any(body_options.get(name) is not None for name in ("inertia", "shape", "gyration")) or bool(body_options.get("part"))
    rim = None
    if body_options.get("inertia") is not None and body_options.get("shape") is None and body_options.get("radius") is not None:
        if rim_speed is None and until_arc is None and rim_accel is None and at != RIM:
            raise InputError("radius", "goes with {shape}; with {inertia} it is the rim's radius, for {rim_speed}, {rim_accel}, {until_arc} or {at} rim")
        rim = body_options.pop("radius")
    moment, body_steps = body(**body_options, notes=notes) if has_body else (None, ())
    parts = body_table(**body_options) if body_options.get("part") else None
    if rim is None and (rim_speed is not None or until_arc is not None or rim_accel is not None):
        rim = _rim_radius(body_options, "rim_speed" if rim_speed is not None else "until_arc" if until_arc is not None else "rim_accel")
    return Wheel(moment, body_steps, parts, rim)


def _initial_speed(wheel: Wheel, omega0: float | None, rim_speed: float | None, ke0: float | None, front: Front) -> float | None:
    """ω₀ as given, or from the rim speed (ω₀ = v/R), or from the stored energy (ω₀ = √(2KE/I))."""
    given = [name for name, value in (("omega0", omega0), ("rim_speed", rim_speed), ("ke0", ke0)) if value is not None]
    if len(given) > 1:
        raise InputError(given[1], f"conflicts with {{{given[0]}}}: give the initial speed one way")
    if rim_speed is not None:
        rim = wheel.rim
        omega0 = rim_speed / rim
        front.steps.append(Step("Angular velocity from the rim speed", "ω₀ = v/R", f"{quantity_text(rim_speed, 'm/s')} / {quantity_text(rim, 'm')}",
                                quantity_text(omega0, "rad/s"), "a point at radius R moves at v = ωR"))
        front.notes.append(f"ω₀ = v/R = {quantity_text(omega0, 'rad/s')}: the rim speed {quantity_text(rim_speed, 'm/s')} at R = {quantity_text(rim, 'm')}")
        front.results.put("omega0", omega0, " (from the rim speed)")
    if ke0 is not None:
        if wheel.inertia is None:
            raise InputError("ke0", "needs a body ({inertia} or {shape}): ω₀ = √(2E/I)")
        omega0 = math.sqrt(2 * ke0 / wheel.inertia)
        front.steps.append(Step("Angular velocity from the stored energy", "KE = ½Iω²  ⇒  ω₀ = √(2KE/I)",
                                f"√(2 × {quantity_text(ke0, 'J')} / {quantity_text(wheel.inertia, 'kg*m**2')})", quantity_text(omega0, "rad/s"),
                                "all the energy of a wheel on a fixed axle is its rotational kinetic energy"))
        front.results.put("omega0", omega0, " (from KE0)")
    return omega0


def _angle_of_arc(until_arc: float, until_angle: float | None, rim: float, front: Front) -> float:
    """The target angle of an arc at the rim: θ = s/R (a cord off a drum)."""
    if until_angle is not None:
        raise InputError("until_arc", "conflicts with {until_angle}: give the target one way")
    until_angle = until_arc / rim
    front.results.put("theta_until", until_angle, f" the arc s = {fmt(until_arc)} m is off (θ = s/R)")
    front.steps.append(Step("Angle of the arc", "θ = s/R", f"{term(until_arc, 'm')} / {quantity_text(rim, 'm')}", quantity_text(until_angle, "rad"),
                            "an arc s at radius R subtends the angle s/R (in radians)"))
    front.notes.append(f"θ = s/R = {quantity_text(until_angle, 'rad')}: the arc {quantity_text(until_arc, 'm')} at R = {quantity_text(rim, 'm')}")
    return until_angle


def _push(force: float | None, lever: float | None, push_angle: float | None) -> Push | None:
    """The push --force at --lever (--push-angle), where one is given: its torque adds to --torque's."""
    if force is None and lever is None and push_angle is None:
        return None
    if force is None:
        raise InputError("force", "is required with {lever}", example="{force} 6N")
    if lever is None:
        raise InputError("lever", "is required with {force}", example="{lever} 0.2m")
    return Push(force, lever) if push_angle is None else Push(force, lever, push_angle)


def _at_constant_alpha(wheel: Wheel, torques: Torques, omega0, alpha, power, in_time, targets: dict, front: Front) -> tuple[Report, dict]:
    """A constant α given (--alpha), or no body: kinematics, and with a body the torque it takes;
    and the targets it answers (without a body, --in-time is the time)."""
    if power is not None and (wheel.inertia is not None or alpha):
        raise InputError("power", "conflicts with {alpha}: a constant power gives a changing α" if alpha else "needs a body ({inertia} or {shape})")
    if power is not None:
        return _steady_power(power, omega0, torques, targets, in_time, front), targets
    if in_time is not None:
        if targets["time"] is not None:
            raise InputError("in_time", "conflicts with {time}: without a body they say the same")
        targets = {**targets, "time": in_time}
    report = constant_alpha_report(wheel.inertia, wheel.steps, torques, omega0, alpha, **targets, front=(front.steps, front.notes, front.results))
    return _with_front(report, front.results), targets


def _steady_power(power: float, omega0: float | None, torques: Torques, targets: dict, in_time, front: Front) -> Report:
    """A power at a steady speed with no body (kinematics): the torque τ = P/ω that carries it, and
    by --time the angle turned and the work done, W = Pt."""
    for name, value in (("until_omega", targets["until_omega"]), ("until_angle", targets["until_angle"]), ("in_time", in_time),
                        ("friction", torques.friction or None), ("viscous", torques.viscous or None), ("drag", torques.drag or None)):
        if value is not None:
            raise InputError(name, "conflicts with {power} with no body: the speed is steady, so the power and the speed fix the torque (give a body for a motor that speeds it up)")
    if not omega0:
        raise InputError("power", "needs the steady speed it is carried at when there is no body: {omega0} or {rim_speed}", example="{power} 1kW {omega0} 300rpm")
    results = Results(TABLE)
    results.update(front.results)
    torque = power / omega0
    results.put("alpha0", 0.0)
    results.put("alpha", 0.0)
    results.put("torque", torque, " that carries the power at this speed")
    results.put("power", power, "")
    steps = [*front.steps, Step("Torque at a steady speed", "P = τω  ⇒  τ = P/ω", f"{term(power, 'W')} / {term(omega0, 'rad/s')}", quantity_text(torque, "N*m"),
                                "the power a torque delivers to a shaft turning at ω is τω")]
    time = targets["time"]
    if time is not None:
        theta = omega0 * time
        results.put("omega", omega0, f" at t = {fmt(time)} s")
        results.put("theta", theta, f" by t = {fmt(time)} s")
        results.put("revs", theta / (2 * math.pi), f" by t = {fmt(time)} s")
        results.put("work_drive", power * time, f" by t = {fmt(time)} s")
        steps.append(Step("Angle turned at the steady speed", "θ = ωt", f"{term(omega0, 'rad/s')} × {term(time, 's')}", quantity_text(theta, "rad"),
                          "the speed does not change"))
        steps.append(Step("Work done", "W = Pt = τθ", f"{term(power, 'W')} × {term(time, 's')}", quantity_text(power * time, "J"),
                          "a constant power for a time"))
    return Report("spin-down", "a power at a steady speed, no body (kinematics): τ = P/ω", "closed form", results, steps, list(front.notes))


def _in_time(wheel: Wheel, torques: Torques, omega0, in_time: float, targets: dict, front: Front, method, dt, rtol) -> tuple[Report, dict, Torques]:
    """The constant drive that brings the wheel to the target (--until-omega or --until-angle) in
    the time --in-time: at constant α where the losses do not change with ω, else by bisection on
    the motion, which is then solved as usual (to the time --in-time); the targets answered, and
    the torques with that drive."""
    until_omega, until_angle = targets["until_omega"], targets["until_angle"]
    if (until_omega is None) == (until_angle is None):
        raise InputError("in_time", "needs one target: {until_omega} or {until_angle}", example="{until_omega} 1000rpm {in_time} 3s")
    if targets["time"] is not None:
        raise InputError("time", "conflicts with {in_time}: ask for the target's time one way")
    if not torques.viscous and not torques.drag:
        report = constant_alpha_report(wheel.inertia, wheel.steps, torques, omega0, None, time=in_time, until_omega=until_omega,
                                       until_angle=until_angle, front=(front.steps, front.notes, front.results))
        report = as_given(_with_front(report, front.results), wheel.inertia, until_omega, until_angle)
        return report, {"time": in_time, "until_omega": None, "until_angle": None}, torques
    torques = drive_for_target(wheel.inertia, torques, omega0 or 0.0, in_time, until_omega, until_angle, method, dt, rtol)
    front.notes.append(f"the constant drive torque that meets the target in t = {fmt(in_time)} s, found by bisection on the motion: "
                       f"τ = {quantity_text(torques.drive, 'N*m')}")
    front.results.put("torque", torques.drive, " that meets the target")
    targets = {"time": in_time, "until_omega": None, "until_angle": None}
    report = _under_torques(wheel, torques, omega0, targets, front, (), method, dt, rtol, True)
    return as_given(report, wheel.inertia, until_omega, until_angle), targets, torques


def _within_angle(in_angle: float, until_omega, targets: dict, in_time, alpha, torque, push, power) -> float:
    """--in-angle asks for the α (and with a body the drive) that brings the wheel to --until-omega
    within the angle: it needs that target and no other, and no drive of its own."""
    if until_omega is None:
        raise InputError("in_angle", "needs {until_omega}: the speed to reach within the angle", example="{until_omega} 120rpm {in_angle} 20rev")
    for name, value in (("until_angle", targets["until_angle"]), ("time", targets["time"]), ("in_time", in_time), ("alpha", alpha)):
        if value is not None:
            raise InputError(name, "conflicts with {in_angle}: the angle and the speed fix α (and the time)")
    for name, value in (("torque", torque), ("force", push), ("power", power)):
        if value is not None:
            raise InputError("in_angle", f"asks for the drive torque that meets the target, so it conflicts with {{{name}}}")
    return in_angle


def _in_angle(wheel: Wheel, torques: Torques, omega0, in_angle: float, targets: dict, front: Front, method, dt, rtol) -> tuple[Report, dict, Torques]:
    """The constant drive that brings the wheel to --until-omega once it has turned --in-angle: at
    constant α where the losses do not change with ω (ω₁² = ω₀² + 2αθ, α = (ω₁² − ω₀²)/(2θ)),
    else by bisection on the motion; without a body, the kinematics alone."""
    until_omega = targets["until_omega"]
    if wheel.inertia is None or (not torques.viscous and not torques.drag):
        report = constant_alpha_report(wheel.inertia, wheel.steps, torques, omega0, None, time=None, until_omega=until_omega,
                                       until_angle=in_angle, front=(front.steps, front.notes, front.results))
        return _with_front(report, front.results), targets, torques
    w0 = omega0 or 0.0
    if w0 * until_omega >= 0 and (in_angle == 0 or (w0 + until_omega) * in_angle <= 0):
        # ω(t) is monotonic under a constant drive and these losses: with ω₀ and ω₁ on one side of 0 the wheel turns only that way
        raise InputError("in_angle", "cannot be reached with these speeds: the mean speed must turn the wheel that way (ω₀ and ω₁ are on one side of 0, "
                         "and under a constant drive the speed does not turn back on the way)",
                         got=f"θ = {in_angle:g} rad, ω₀ = {w0:g} rad/s, ω₁ = {until_omega:g} rad/s", example="{omega0} -300rpm {until_omega} -100rpm {in_angle} -10rev")
    torques = drive_for_target(wheel.inertia, torques, omega0 or 0.0, None, until_omega, None, method, dt, rtol, in_angle=in_angle)
    front.notes.append(f"the constant drive torque that brings the wheel to ω = {quantity_text(until_omega, 'rad/s')} within θ = "
                       f"{quantity_text(in_angle, 'rad')}, found by bisection on the motion: τ = {quantity_text(torques.drive, 'N*m')}")
    front.results.put("torque", torques.drive, " that meets the target")
    # Timed to the speed, not the angle: at a stop dθ/dt = 0, and a time to an angle would keep half the digits.
    targets = {"time": None, "until_omega": until_omega, "until_angle": None}
    return as_given(_under_torques(wheel, torques, omega0, targets, front, (), method, dt, rtol, True), wheel.inertia, until_omega, None), targets, torques


def _under_torques(wheel: Wheel, torques: Torques, omega0, targets: dict, front: Front, formed: list, method, dt, rtol, energy: bool) -> Report:
    """The torque laws: the wheel's motion under its drive (``formed``: the steps that formed it),
    friction and drag (torque_laws.solve)."""
    report = solve(wheel.inertia, torques, omega0 or 0.0, **targets, method=method, dt=dt, rtol=rtol, drive_steps=formed, inertia_steps=wheel.steps, energy=energy)
    if "torque" in front.results:
        front.results.put("torque_net", report.results["alpha0"].value * wheel.inertia, " at the start")
    return _with_front(report, front.results, front.notes, front.steps)


def _one_sense(brakes, bands, omega0: float | None, drive: float, in_time, in_angle) -> None:
    """A band brake, or a shoe whose friction has a moment about its lever's pivot, takes another
    torque when the wheel turns the other way: refuse where it might turn back."""
    sided = [spec.source for spec in (*(bands or ()), *(shoe for shoe in brakes or () if shoe.sided))]
    if not sided:
        return
    if in_time is not None or in_angle is not None:
        raise InputError("in_time" if in_time is not None else "in_angle", f"does not combine with {sided[0]}: its torque depends on the sense the wheel turns, "
                         "and the drive this solves for may turn it back")
    if omega0 and drive and (omega0 > 0) != (drive > 0):
        raise InputError(sided[0], "takes the torque for the sense the wheel turns, and a drive against ω₀ would stop it and turn it back "
                         "(the tight and slack ends, or the friction's moment, change over): give a drive along ω₀, or work the turn back in a second run",
                         example="{torque} '5N*m' {omega0} 100rpm")


def _with_parts(report: Report, parts: Table | None) -> Report:
    """The report with the parts table of a body of parts."""
    if parts is None:
        return report
    return Report(report.scene, report.model, report.method, report.results, report.steps, report.notes, report.inputs,
                  {"parts": parts, **report.tables}, report.trajectory)


def _rim_radius(body_options: dict, option: str) -> float:
    """The radius of the body's rim: its radius, or its outer radius."""
    for name in ("radius", "outer_radius"):
        if body_options.get(name) is not None:
            return body_options[name]
    raise InputError(option, "needs a radius: the body's ({shape} with {radius}), or {radius} beside {inertia} or with no body")


def _with_front(report: Report, front: Results, notes: Sequence[str] = (), steps: Sequence[Step] = ()) -> Report:
    """The report with what was worked out before the motion (ω₀ from a rim speed or KE0) first."""
    if not front and not notes and not steps:
        return report
    results = Results(TABLE)
    results.update(front)
    results.update(report.results)
    merged_steps = list(report.steps)
    if steps:
        body_count = next((i for i, step in enumerate(merged_steps) if step.title.startswith(("Torque of the push", "Net torque"))), 0)
        merged_steps[body_count:body_count] = steps
    return Report(report.scene, report.model, report.method, results, merged_steps, [*notes, *report.notes], report.inputs, report.tables, report.trajectory)
