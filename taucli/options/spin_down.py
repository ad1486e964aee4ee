"""taucli spin-down: a wheel on a fixed axle, slowing or spun up."""

from taucli.options.common import ANSWER, BAND_OPTION, BODY_OPTIONS, BRAKE_OPTION, CALIPER_OPTION, CENTRIFUGAL_OPTION, CONTACT_RESULTS, DT, FACE_OPTION, GRAVITY, METHOD, MOTION, POINT_RESULTS, PUSH, RTOL, point_option
from taucli.options.table import FLAG, PHASE, Command, Option, Result

ENERGY = "Energy added, taken or put to use"

# What makes the results a run without them lacks (#42 item 18): a turn back by --time (a constant α, or a
# drive, against ω₀); a constant α to a target; the stored energy put to a load.
TURNS_BACK = ("time+alpha", "time+torque")
TURNS_BACK_EXAMPLE = "{time} 10s {alpha} '-6 rad/s^2'"
TO_A_TARGET = ("in_time+until_omega", "in_angle+until_omega")
TO_A_LOAD = ("lift_mass", "vehicle_mass")

COMMAND = Command(
    name="spin-down",
    summary="A wheel on a fixed axle, slowing or spun up: I dω/dt = τ_drive − τ_f − bω − kω².",
    example="taucli spin-down --shape disc --mass 5kg --radius 0.2m --omega0 30rad/s --friction '0.3N*m'",
    options=(
        *BODY_OPTIONS,
        Option("omega0", "angular velocity", "Initial angular velocity, e.g. 300rpm.", sign="any", default="0", panel=MOTION),
        Option("torque", "torque", "Driving torque along +ω (negative: against it), e.g. '1.5N*m'; or a formula of the time t, e.g. '(10 N*m/s)*t'.",
               sign="any", of_time=True),
        *PUSH,
        Option("friction", "torque", "Constant friction torque at the axle (also holds it at rest), e.g. '0.3N*m'.", sign="nonnegative"),
        BRAKE_OPTION,
        FACE_OPTION,
        BAND_OPTION,
        CALIPER_OPTION,
        CENTRIFUGAL_OPTION,
        GRAVITY,
        Option("viscous", "viscous coefficient", "Viscous coefficient b (torque bω), e.g. '0.01N*m*s'.", sign="nonnegative"),
        Option("corner", "dimensionless", "The body set down spinning in a corner, its rim on the floor and the wall, with this friction "
               "coefficient at both (the floor's friction pushing it into the wall): their friction torque, from its mass and radius, e.g. 0.3.",
               sign="nonnegative"),
        Option("drive_slope", "viscous coefficient", "How the drive torque rises with speed, dτ/dω (a motor's line T = T₀ + sω; negative: it falls "
               "with speed), e.g. '0.05N*m*s'; with no body: the speeds where the torques balance, and whether they are stable.", sign="any"),
        Option("drag", "drag coefficient", "Drag coefficient k (torque kωⁿ), e.g. '0.001N*m*s^2'.", sign="nonnegative"),
        Option("drag_exponent", "dimensionless", "Exponent n of the drag torque kωⁿ, above 0 and at most 10 (below 1 drag alone stops the wheel in a finite time).",
               default="2", metavar="N"),
        Option("time", "time", "Report ω, θ and revolutions at this time, e.g. 4s.", sign="nonnegative", panel=MOTION),
        Option("until_omega", "angular velocity", "Report the time and angle to reach this speed.", sign="any", panel=MOTION),
        Option("until_angle", "angle", "Report the time and ω when the wheel has turned this far, e.g. 10rev.", sign="any", panel=MOTION),
        Option("until_arc", "length", "The same for a length at the rim (cord off a drum): θ = s/R, e.g. 2m.", sign="any", panel=MOTION),
        Option(
            "alpha", "angular acceleration",
            "Constant angular acceleration, standing in for the body and its torques (any three of ω₀, ω₁, α, t, θ give the rest); "
            "or a formula of the time t, e.g. '(2 - 3*t/s) rad/s^2'.",
            sign="any", panel=MOTION, of_time=True,
        ),
        Option(
            "in_time", "time",
            "Reach the target (--until-omega or --until-angle) in this time: the constant α, and with a body the torque, that does it.",
            panel=MOTION,
        ),
        Option(
            "in_angle", "angle",
            "Reach --until-omega within this angle, e.g. 20rev: the constant α, and with a body the drive torque, that does it (stop a wheel in 10 rev: --until-omega 0).",
            sign="any", panel=MOTION,
        ),
        Option("phase", PHASE, 'One phase of the run, in order (repeatable): a rate, alpha=, torque= (with the body) or the word coast, and '
               'how it ends, time=, angle= or until-omega=; or two of those ends and no rate, e.g. "alpha=2.9e-3rad/s^2 time=2100s". Each '
               "phase's α, time, θ and ω in a table, the whole run's in the results.", repeatable=True, panel=MOTION,
               metavar='"alpha=… time=…"', example="alpha=2rad/s^2 time=3s"),
        Option("power", "power", "A motor of constant power P (τ = P/ω; negative: a load draining the wheel), e.g. 1kW.", sign="any"),
        Option("ke0", "energy", "Initial kinetic energy, giving ω₀ = √(2E/I), e.g. 1MJ.", sign="nonnegative", panel=MOTION),
        Option("work", "energy", "Work done on the wheel (positive: added; negative: taken, as water takes it from a propeller), giving ω after: "
               "½Iω₁² = ½Iω₀² + W, e.g. -50kJ.", sign="any", panel=ENERGY),
        Option("lift_mass", "mass", "A mass the wheel's stored energy lifts as the wheel comes to rest (or slows to --until-omega): the height, "
               "mgh = ηE, e.g. 50kg.", panel=ENERGY),
        Option("vehicle_mass", "mass", "A vehicle the wheel's stored energy sets moving from rest as the wheel comes to rest (or slows to --until-omega): "
               "its speed, ½mv² = ηE, e.g. 1200kg.", panel=ENERGY),
        Option("heat_mass", "mass", "The mass that takes the heat of the brakes, faces and bands (else of --friction) with --specific-heat: "
               "its temperature rise ΔT = E/(m·c), E the energy they take to --time, the target or the stop, e.g. 12kg.", panel=ENERGY),
        Option("specific_heat", "specific heat", "Specific heat c of --heat-mass, e.g. '460 J/(kg*K)' (steel).", panel=ENERGY),
        Option("efficiency", "dimensionless", "Efficiency η, 0 to 1, with which the stored energy reaches --lift-mass or --vehicle-mass.", default="1", panel=ENERGY),
        Option("rim_accel", "acceleration", "Tangential acceleration of the rim, giving α = a_t/R (R the body's radius, or --radius), e.g. '0.5m/s^2'.", sign="any", panel=MOTION),
        Option("rim_speed", "velocity", "Initial speed of the rim, giving ω₀ = v/R (R the body's radius, or --radius with --inertia).", sign="any", panel=MOTION),
        point_option("(at --time or the target, else the start)"),
        Option(
            "energy", FLAG,
            "Also report the kinetic energy, the work of the drive and of each loss (to --time, else the target, else the stop) and their power "
            "(always with --alpha, --in-time, --power or --ke0; --get KE and the like turn it on).",
            panel=MOTION,
            makes=("KE0", "KE", "work_drive", "work_friction", "work_viscous", "work_drag", "work_brake", "work_face", "work_band", "work_caliper",
                   "power", "power_mean", "power_friction", "power_viscous", "power_drag", "power_brake", "power_face", "power_band", "power_caliper"),
        ),
        METHOD,
        DT,
        RTOL,
    ),
    results=(
        Result("I", "kg*m**2", "moment of inertia about the axle"),
        Result("alpha0", "rad/s**2", "angular acceleration at the start"),
        Result("t_stop", "s", "time until the wheel stops"),
        Result("theta_stop", "rad", "angle turned until it stops"),
        Result("revs_stop", "rev", "revolutions until it stops"),
        Result("omega_inf", "rad/s", "steady speed as t -> ∞"),
        Result("normal_floor", "N", "the floor's push on the body in the corner", needs=("corner",), example="{corner} 0.3"),
        Result("normal_wall", "N", "the wall's push on the body in the corner", needs=("corner",), example="{corner} 0.3"),
        Result("stable", None, "whether the steady speed is a stable balance (a little faster, the net torque slows it back)", needs=("drive_slope",),
               example="{torque} '20N*m' {friction} '5N*m' {viscous} '0.1N*m*s' {drive_slope} '0.05N*m*s'"),
        Result("omega_unstable", "rad/s", "speed of an unstable balance: below it the wheel runs down, above it runs up", needs=("drive_slope",),
               example="{torque} '5N*m' {friction} '20N*m' {drive_slope} '0.05N*m*s'"),
        Result("omega", "rad/s", "angular velocity…", needs=("time", "until_omega", "until_angle", "phase")),
        Result("theta", "rad", "net angle turned…", needs=("time", "until_omega", "until_angle", "phase")),
        Result("revs", "rev", "net revolutions…", needs=("time", "until_omega", "until_angle", "phase")),
        Result("L", "kg*m**2/s", "angular momentum Iω…", needs=("time", "until_omega", "until_angle", "phase+inertia")),
        Result("theta_total", "rad", "total angle turned, both ways,…", needs=TURNS_BACK, example=TURNS_BACK_EXAMPLE),
        Result("revs_total", "rev", "total revolutions, both ways,…", needs=TURNS_BACK, example=TURNS_BACK_EXAMPLE),
        Result("t_until", "s", "time to reach…", needs=("until_omega", "until_angle"), example="{until_omega} 100rpm"),
        Result("theta_until", "rad", "angle turned until…", needs=("until_omega",), example="{until_omega} 100rpm"),
        Result("revs_until", "rev", "revolutions until…", needs=("until_omega",), example="{until_omega} 100rpm"),
        Result("omega_mean", "rad/s", "mean angular velocity θ/t…"),
        Result("t_run", "s", "duration of the whole run, all its phases", needs=("phase",)),
        Result("alpha_end", "rad/s**2", "angular acceleration…", needs=("time",), example="{alpha} '(2 - 3*t/s) rad/s^2' {time} 2s"),
        Result("alpha", "rad/s**2", "angular acceleration (constant)", needs=("alpha", "rim_accel", *TO_A_TARGET)),
        Result("omega0", "rad/s", "initial angular velocity…", needs=("rim_speed", "ke0")),
        Result("torque_net", "N*m", "net torque…", needs=("alpha", *TO_A_TARGET)),
        Result("torque", "N*m", "drive torque…", needs=("alpha", "power", *TO_A_TARGET)),
        Result("KE0", "J", "kinetic energy at the start"),
        Result("KE", "J", "kinetic energy…"),
        Result("work_drive", "J", "work done by the drive…"),
        Result("work_friction", "J", "energy friction takes…"),
        Result("work_viscous", "J", "energy the viscous torque takes…"),
        Result("work_drag", "J", "energy drag takes…"),
        Result("power", "W", "drive power…"),
        Result("power_mean", "W", "mean drive power…"),
        Result("power_friction", "W", "power friction takes…"),
        Result("power_viscous", "W", "power the viscous torque takes…"),
        Result("power_drag", "W", "power drag takes…"),
        Result("KE_after", "J", "kinetic energy after…", needs=("work", *TO_A_LOAD)),
        Result("omega_after", "rad/s", "angular velocity after…", needs=("work", *TO_A_LOAD)),
        Result("energy_delivered", "J", "energy that reaches the load (η × the energy the wheel gives up)", needs=TO_A_LOAD),
        Result("temperature_rise", "K", "temperature rise of the mass that takes the heat, ΔT = E/(m·c)", needs=("heat_mass",),
               example="{brake} 'force=100N mu=0.4 radius=0.5m' {heat_mass} 12kg {specific_heat} '460 J/(kg*K)'"),
        Result("lift_height", "m", "height the mass is lifted", needs=("lift_mass",)),
        Result("vehicle_speed", "m/s", "speed the vehicle reaches from rest", needs=("vehicle_mass",)),
        *POINT_RESULTS,
        *CONTACT_RESULTS,
    ),
    output=ANSWER,
    headline="alpha0",
    library="taucli.scenes.spin:spin_down",
)
