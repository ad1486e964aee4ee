"""taucli pendulum: a body on a pivot under gravity or a torsion spring."""

from taucli.options.common import ANSWER, BODY_OPTIONS, DT, GRAVITY, MOTION, PARTS, RTOL, SIGNED_PARTS
from taucli.options.table import CHOICE, FLAG, Command, Option, Result

COMPONENTS = tuple(f"pivot_{name}{where}" for where in ("0", "_bottom", "") for name in ("radial", "tangential", "horizontal", "vertical"))
METHODS = ("auto", "exact", "small-angle", "euler", "rk4", "rk45", "verlet")

COMMAND = Command(
    name="pendulum",
    summary="A body on a pivot under gravity or a torsion spring: I d²θ/dt² = −mgd sin θ − κθ.",
    example="taucli pendulum --shape rod --length 1m --mass 2kg --axis end --angle0 90deg",
    options=(
        *(SIGNED_PARTS if option is PARTS else option for option in BODY_OPTIONS),
        Option("cm_distance", "length", "Distance d from the pivot to the centre of mass (else from the shape and --offset).", sign="nonnegative"),
        Option("length_offset", "length", "Added to the distance from the pivot to the centre of mass, the body moved along that line (a length "
               "measured to the top of a bob is short by its radius), e.g. 1.9cm; fit it with --fit length_offset.", sign="any"),
        Option("angle0", "angle", "Starting angle from the downward vertical (90deg: horizontal; with --from-top, from the upward one).", sign="any", default="0", panel=MOTION),
        Option("omega0", "angular velocity", "Starting angular velocity, positive toward larger angles.", sign="any", default="0", panel=MOTION),
        Option("omega_bottom", "angular velocity", "Angular velocity at the bottom, where it starts (instead of --angle0 and --omega0): how far it swings.", sign="any", panel=MOTION),
        Option("from_top", FLAG, "Every angle in and out from the upward vertical, in the same sense (a toppling chimney, a falling stick; gravity alone).", panel=MOTION),
        Option("torsion", "torsion constant", "Torsion constant κ of a spring or wire (torque κθ), e.g. '0.5N*m/rad'.", sign="nonnegative"),
        Option("viscous", "viscous coefficient", "Damping torque bω against the swing (air, a pivot's grease), e.g. '2e-4N*m*s': θ and ω at "
               "--time by rk45 (or --method small-angle), and the decay; the answers energy gives do not hold.", sign="nonnegative"),
        Option("pivot_friction", "torque", "A friction couple at the pivot: a constant torque against the motion (a rough axle), e.g. '4.8N*m'.", sign="nonnegative"),
        GRAVITY,
        Option("start_time", "time", "Clock time of the start (θ = --angle0, ω = --omega0 there): --time is read on the same clock, and before "
               "the start the body is held at --angle0, e.g. 0.35s (a recording started before the release).", sign="any", panel=MOTION),
        Option("angle", "angle", "Report ω and the time to reach this angle, e.g. 0deg.", sign="any", panel=MOTION, first_reached=("t_angle", "angle0")),
        Option("time", "time", "Report θ and ω at this time, e.g. 2s.", sign="nonnegative", panel=MOTION),
        Option("at", "length", "A point this far from the pivot: its tangential acceleration at the start, and its speed and accelerations at --angle.", sign="nonnegative", panel=MOTION),
        Option("components", FLAG, "The pivot's force as components (along and across the line to the centre of mass; horizontal and vertical) "
               "at the start, the bottom and --angle (--get pivot_radial0 and the like turn it on).", panel=MOTION, makes=COMPONENTS),
        Option("method", CHOICE, " | ".join(METHODS) + ".", panel=MOTION, choices=METHODS, default="auto", metavar="METHOD"),
        DT,
        RTOL,
    ),
    results=(
        Result("I", "kg*m**2", "moment of inertia about the pivot"),
        Result("cm_distance", "m", "distance from the pivot to the centre of mass"),
        Result("alpha0", "rad/s**2", "angular acceleration at the start (size)"),
        Result("omega_bottom", "rad/s", "angular speed at the bottom"),
        Result("KE_bottom", "J", "kinetic energy at the bottom, ½Iω_b²"),
        Result("amplitude", "rad", "turning angle: where the swing first comes to rest…"),
        Result("rise", "m", "rise of the centre of mass from the start to the turning angle"),
        Result("omega", "rad/s", "angular velocity…", needs=("angle", "time")),
        Result("t_angle", "s", "time to reach…", needs=("angle",)),
        Result("t_bottom", "s", "time to reach the bottom"),
        Result("period_small", "s", "period of small swings, 2π√(I/(mgd + κ))"),
        Result("period", "s", "period…"),
        Result("pivot_force0", "N", "force of the pivot on the body at the start (size)"),
        Result("pivot_force_bottom", "N", "force of the pivot on the body at the bottom (size)"),
        Result("pivot_force", "N", "force of the pivot on the body (size)…", needs=("angle",)),
        Result("pivot_radial0", "N", "pivot's force along the line to the centre of mass, towards the pivot, at the start"),
        Result("pivot_tangential0", "N", "pivot's force across that line, towards larger angles, at the start"),
        Result("pivot_horizontal0", "N", "pivot's force, horizontal (towards positive angles), at the start"),
        Result("pivot_vertical0", "N", "pivot's force, vertical (up), at the start"),
        Result("pivot_radial_bottom", "N", "pivot's force along the line to the centre of mass, towards the pivot, at the bottom"),
        Result("pivot_tangential_bottom", "N", "pivot's force across that line, towards larger angles, at the bottom"),
        Result("pivot_horizontal_bottom", "N", "pivot's force, horizontal (towards positive angles), at the bottom"),
        Result("pivot_vertical_bottom", "N", "pivot's force, vertical (up), at the bottom"),
        Result("pivot_radial", "N", "pivot's force along the line to the centre of mass, towards the pivot…"),
        Result("pivot_tangential", "N", "pivot's force across that line, towards larger angles…"),
        Result("pivot_horizontal", "N", "pivot's force, horizontal (towards positive angles)…"),
        Result("pivot_vertical", "N", "pivot's force, vertical (up)…"),
        Result("equivalent_length", "m", "length of the simple pendulum with the same period, I/(md)"),
        Result("centre_of_percussion", "m", "centre of percussion, from the pivot, I/(md)"),
        Result("goes_over", None, "whether it goes over the top"),
        Result("omega0_over", "rad/s", "starting speed that just reaches the top"),
        Result("theta", "rad", "angle…", needs=("time",)),
        Result("decay_time", "s", "decay time of small swings' amplitude, τ = 2I/b (e^(−t/τ))", needs=("viscous",)),
        Result("quality_factor", "", "quality factor of small swings, Q = Ω₀I/b", needs=("viscous",)),
        Result("a_t0", "m/s**2", "tangential acceleration at the start of the point…", needs=("at",)),
        Result("v_t", "m/s", "speed of the point…"),
        Result("a_t", "m/s**2", "tangential acceleration of the point…"),
        Result("a_c", "m/s**2", "centripetal acceleration of the point…"),
    ),
    output=ANSWER,
    headline="period",
    library="taucli.scenes.pendulum:pendulum",
)
