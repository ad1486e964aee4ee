"""taucli drive: a motor turning a load through a ratio: reflected inertia, torques, a move's RMS torque."""

from dataclasses import replace

from taucli.options.common import ANSWER, BODY_OPTIONS, GRAVITY, MOTION
from taucli.options.table import FLAG, LOAD as LOAD_SPEC, MOTOR_CURVE, SEGMENT, Command, Option, Result

MOTOR = "Motor"
TRAIN = "Drive train"
LOAD = "Load (a rotating body at the output, a mass moved in a line, what resists)"
PROFILE = "Move profile (accelerate, run, decelerate, dwell)"

# What makes the results the docs example (a run-up in a time) does not (#42 item 18): a move profile, beside
# the top speed (--until-omega or --speed) or the travel; a mass moved in a line, by a drum or a screw.
A_MOVE = ("accel_time", "distance+accel", "move_angle+alpha")
A_MASS = ("load_mass+drum_radius", "load_mass+lead")

# The rotating load at the output shaft: --load-inertia, or a shape and its dimensions, or parts.
LOAD_BODY = tuple(
    replace(option, panel=LOAD, help=option.help.replace("the body", "the rotating load").replace("The body", "The rotating load"))
    for option in BODY_OPTIONS
    if option.name != "inertia"
)

COMMAND = Command(
    name="drive",
    summary="A motor turning a load through a ratio: the inertia it sees, the torques it gives, a move's RMS torque.",
    description=(
        "The load (a rotating body at the output shaft; a mass moved by a drum, belt, pinion or screw) is "
        "reflected to the motor through the stages --ratio (N, motor speed over output speed): J/N², the "
        "torque T/(Nη) while the motor drives it and ηT/N when the load drives the motor back. With a "
        "speed and a time (or an acceleration) the torque to get there; with the motor's torque–speed line "
        "(--stall-torque, --no-load-speed) or a constant --motor-torque the time it takes; with a move "
        "profile the torque of each phase, the peak and RMS torque and the power."
    ),
    example="taucli drive --motor-inertia '1.2 kg*cm^2' --ratio 10 --load-inertia '0.05 kg*m^2' --until-omega 3000rpm --in-time 0.2s",
    options=(
        Option("motor_inertia", "moment of inertia", "Moment of inertia of the motor's rotor, e.g. '1.2kg*cm^2' or '0.0012lb*in*s^2'.",
               sign="nonnegative", panel=MOTOR),
        Option("stall_torque", "torque", "Torque at standstill of a motor whose torque falls on a line to zero at --no-load-speed, "
               "τ = τ_s(1 − ω/ω_nl), e.g. '2N*m'.", panel=MOTOR),
        Option("no_load_speed", "angular velocity", "Speed at which that line reaches zero torque, e.g. 3000rpm.", panel=MOTOR),
        Option("motor_torque", "torque", "A motor that gives a constant torque from rest (instead of the line), e.g. '1.5N*m'; "
               "0 for a load that runs down freely through the gears.", sign="nonnegative", panel=MOTOR),
        Option("motor_curve", MOTOR_CURVE, "An induction motor's torque–slip curve by Kloss's formula, T = 2T_max/(s/s_m + s_m/s), s = 1 − ω/ω_s: "
               "\"tmax=400N*m slip-max=0.2 sync=1500rpm\" (the breakdown torque, the slip where it falls, the synchronous speed); with "
               "--until-omega the run-up's time t_accel and the energy the rotor dissipates, energy_accel.", panel=MOTOR,
               metavar='"tmax=… slip-max=… sync=…"'),
        Option("rated_torque", "torque", "The motor's rated (continuous) torque, held against the RMS torque of a move.", panel=MOTOR),
        Option("rated_power", "power", "The motor's rated (continuous) power, held against the RMS power of a duty cycle (--segment by power=).", panel=MOTOR),
        Option("segment", SEGMENT, 'A segment of a duty cycle: "time=10min power=100kW" or "time=… torque=…", rest=yes where the motor stands '
               "still (repeatable, in order): the RMS torque or power over the cycle, e.g. --segment \"time=5min power=0\".", panel=MOTOR, repeatable=True,
               metavar='"time=… torque=…|power=… [rest=yes]"'),
        Option("rest_factor", "dimensionless", "How much more slowly the motor cools at a standstill: a rest segment's time counts 1/k of itself "
               "in the RMS (default 1; the duty class or the maker gives it, often 3 or 4).", panel=MOTOR),
        Option("peak_torque", "torque", "The most torque the motor and its drive give for a short time, held against the peak of a move.",
               panel=MOTOR),
        Option("ratio", "dimensionless", "Speed ratio N of a stage (gear, belt, pulley): motor speed over output speed, 10 for a 10:1 "
               "reducer; repeat for stages in series, e.g. --ratio 5 --ratio 3 (default 1, a direct drive).", panel=TRAIN, repeatable=True),
        Option("efficiency", "dimensionless", "Efficiency η of the whole train from the motor to the load (stages, belt, screw), "
               "above 0 and at most 1.", default="1", panel=TRAIN),
        Option("efficiency_back", "dimensionless", "Efficiency η′ of the train where the load drives the motor (lowering, braking), "
               "above 0 and at most 1 (default --efficiency): a worm or a screw drives back with less.", panel=TRAIN),
        Option("motor_friction", "torque", "A friction torque at the motor shaft, against the motion, that no efficiency divides "
               "(a ball nut's, the motor's bearings), e.g. '0.05N*m'.", sign="nonnegative", panel=TRAIN),
        Option("gear_inertia", "moment of inertia", "Moment of inertia of gearing and couplings referred to the motor shaft (as a "
               "gearhead's catalogue gives it), counted with the load.", sign="nonnegative", panel=TRAIN),
        Option("load_inertia", "moment of inertia", "Moment of inertia of the rotating load about the output shaft (or give --shape "
               "with its dimensions, or --part).", panel=LOAD),
        *LOAD_BODY,
        Option("load", LOAD_SPEC, 'One of several loads, each through its own train: "inertia=10kg*m^2 ratio=10 efficiency=0.9 torque=10N*m" '
               "(ratio= motor speed over the load's, the books' a = 1/N; efficiency-back= where the load drives the motor; torque= at its shaft), "
               'or a mass moved in a line, "mass=1000kg speed=1.5m/s force=9810N efficiency=0.85" (speed= at --motor-speed) or "mass=… radius=… ratio=…" '
               "(a drum at its shaft). Repeatable; instead of --ratio, --efficiency and the single load's options.",
               panel=LOAD, repeatable=True, metavar='"inertia=… ratio=… efficiency=… torque=…"'),
        Option("load_mass", "mass", "A mass moved in a straight line (a table, a belt's load, a hoisted mass), with --drum-radius or "
               "--lead, e.g. 250kg.", panel=LOAD),
        Option("drum_radius", "length", "Radius of the drum, pulley, sprocket or pinion that moves the mass (belt, hoist, rack and "
               "pinion): its inertia m·r² at the output shaft, e.g. 5cm.", panel=LOAD),
        Option("lead", "lead", "Lead of a screw that moves the mass, the travel per turn: its inertia m(p/2π)² at the output shaft, "
               "e.g. 10mm or 0.2in/rev.", panel=LOAD),
        Option("load_torque", "torque", "Torque the load resists with at the output shaft while it moves (friction, a process), "
               "against the motion; negative where it drives, e.g. '2N*m'.", sign="any", panel=LOAD),
        Option("load_force", "force", "Force on the moving mass against its motion while it moves (a cutting force, a seal's "
               "friction); negative where it pushes it along, e.g. 50N.", sign="any", panel=LOAD),
        Option("incline", "angle", "Angle of the mass's travel above the horizontal, gravity m·g·sin θ against it: 90deg lifts, "
               "-90deg lowers.", sign="any", default="0deg", panel=LOAD),
        Option("mu", "dimensionless", "Friction coefficient of the mass on its guides: μ·m·g·cos θ against the motion.",
               sign="nonnegative", panel=LOAD),
        GRAVITY,
        Option("motor_speed", "angular velocity", "The motor's running speed: the speed at which a --load's speed= is given, and the steady "
               "power there (power_run), e.g. 1420rpm.", panel=MOTION),
        Option("omega0", "angular velocity", "The motor's speed where a run-up on --motor-curve starts (default 0, rest), e.g. 500rpm.",
               sign="nonnegative", default="0rpm", panel=MOTION),
        Option("until_omega", "angular velocity", "Motor speed to reach from rest (a move's top speed), e.g. 3000rpm.", panel=MOTION),
        Option("speed", "velocity", "Speed of the moving mass to reach from rest (a move's top speed), instead of --until-omega, "
               "e.g. 15m/min.", panel=MOTION),
        Option("in_time", "time", "Reach --until-omega (or --speed) in this time: the acceleration and the torque that do it.",
               panel=MOTION),
        Option("alpha", "angular acceleration", "The motor's angular acceleration (a move's acceleration and deceleration), "
               "e.g. '3000rad/s^2'.", panel=MOTION),
        Option("accel", "acceleration", "Acceleration of the moving mass, instead of --alpha, e.g. '2.5m/s^2'.", panel=MOTION),
        Option("accel_time", "time", "Time to accelerate from rest to the top speed.", panel=PROFILE, example="0.1s"),
        Option("run_time", "time", "Time at the top speed.", sign="nonnegative", default="0s", panel=PROFILE),
        Option("decel_time", "time", "Time to decelerate to rest (default --accel-time).", panel=PROFILE),
        Option("dwell_time", "time", "Time at rest before the next move.", sign="nonnegative", default="0s", panel=PROFILE),
        Option("distance", "length", "Travel of the moving mass per move: with the times, the top speed; with --speed and --accel, "
               "the trapezoid (a triangle if it is too short to reach the speed).", panel=PROFILE),
        Option("move_angle", "angle", "The motor's turn per move, as --distance for a rotating load, e.g. 10rev.", panel=PROFILE),
        Option("energy", FLAG, "Also report the run-up's energy: the kinetic energy reached, the motor's work, the work against the "
               "load and the losses (--get KE and the like turn it on).", panel=MOTION, makes=("KE", "work_motor", "work_load", "work_loss")),
    ),
    results=(
        Result("ratio_total", "", "overall ratio, N₁ × N₂ × ⋯", needs=("ratio+ratio",), example="{ratio} 5 {ratio} 3"),
        Result("linear_inertia", "kg*m**2", "moving mass's inertia at its shaft…", needs=A_MASS),
        Result("reflected_inertia", "kg*m**2", "load inertia at the motor…"),
        Result("total_inertia", "kg*m**2", "inertia at the motor, rotor and load"),
        Result("inertia_ratio", "", "inertia ratio, load over rotor"),
        Result("ratio_optimal", "", "ratio matching load to rotor, √(J/J_m)"),
        Result("load_torque_motor", "N*m", "load torque at the motor, running", needs=("load_torque", "load_force", "motor_friction")),
        Result("torque_hold", "N*m", "motor torque holding the load at rest", needs=tuple(f"{way}+incline" for way in A_MASS)),
        Result("alpha", "rad/s**2", "motor's angular acceleration…"),
        Result("torque_accel", "N*m", "motor torque while accelerating"),
        Result("t_accel", "s", "time to accelerate…"),
        Result("theta_accel", "rad", "motor's angle while accelerating"),
        Result("revs_accel", "rev", "motor's revolutions while accelerating"),
        Result("omega_steady", "rad/s", "speed where the line meets the load", needs=("stall_torque+no_load_speed",)),
        Result("time_constant", "s", "mechanical time constant…", needs=("stall_torque+no_load_speed",)),
        Result("alpha0", "rad/s**2", "motor's angular acceleration from rest", needs=("stall_torque+no_load_speed", "motor_torque", "motor_curve")),
        Result("energy_accel", "J", "energy dissipated in the rotor in the run-up, ∫ s T ω_s dt", needs=("motor_curve+until_omega",),
               example="{motor_curve} 'tmax=2N*m slip-max=0.2 sync=3600rpm' {until_omega} 3000rpm"),
        Result("KE", "J", "kinetic energy reached, motor and load"),
        Result("work_motor", "J", "work of the motor in the run-up"),
        Result("work_load", "J", "work against the load in the run-up"),
        Result("work_loss", "J", "energy lost in the run-up: the train's, and the motor shaft's friction"),
        Result("omega_top", "rad/s", "motor's top speed", needs=A_MOVE),
        Result("speed_top", "m/s", "moving mass's top speed", needs=tuple(f"accel_time+{way}" for way in A_MASS)),
        Result("t_run", "s", "time at the top speed", needs=A_MOVE),
        Result("t_decel", "s", "time to decelerate", needs=A_MOVE),
        Result("t_cycle", "s", "time of a cycle, dwell included", needs=(*A_MOVE, "segment")),
        Result("theta_move", "rad", "motor's angle per move", needs=A_MOVE),
        Result("travel", "m", "moving mass's travel per move", needs=tuple(f"accel_time+{way}" for way in A_MASS)),
        Result("alpha_decel", "rad/s**2", "motor's deceleration (size)", needs=A_MOVE),
        Result("torque_decel", "N*m", "motor torque decelerating (< 0: braking)", needs=A_MOVE),
        Result("torque_peak", "N*m", "peak motor torque (size)", needs=(*A_MOVE, "segment")),
        Result("torque_rms", "N*m", "RMS motor torque over the cycle", needs=(*A_MOVE, "segment")),
        Result("power_rms", "W", "RMS motor power over the duty cycle", needs=("segment",), example="{segment} 'time=10min power=100kW' {segment} 'time=5min power=0'"),
        Result("power_peak", "W", "peak power the motor gives"),
        Result("power_regen", "W", "peak power the load gives back", needs=A_MOVE),
        Result("power_mean", "W", "mean motor power (net) over the cycle", needs=A_MOVE),
        Result("power_run", "W", "motor power…", needs=(*A_MOVE, "motor_speed")),
        Result("energy_regen", "J", "energy the load gives back per cycle (braking)", needs=A_MOVE),
        Result("power_resistor", "W", "mean power of a braking resistor that takes it, E/t_cycle", needs=A_MOVE),
        Result("rms_to_rated", "", "RMS torque (or power) over the rated one", needs=(*(f"{way}+rated_torque" for way in A_MOVE), "segment+rated_torque", "segment+rated_power")),
        Result("within_rating", None, "within the motor's ratings", needs=("accel_time+rated_torque", "accel_time+peak_torque")),
    ),
    output=ANSWER,
    headline="reflected_inertia",
    library="taucli.scenes.drive:drive",
)
