"""taucli pendulum: a body on a pivot under gravity or a torsion spring."""

from taucli.options.common import ANSWER, BODY_OPTIONS, DT, GRAVITY, MOTION, PARTS, RTOL, SIGNED_PARTS
from taucli.table import CHOICE, Command, Option, Result

METHODS = ("auto", "exact", "small-angle", "euler", "rk4", "rk45", "verlet")

COMMAND = Command(
    name="pendulum",
    summary="A body on a pivot under gravity or a torsion spring: I d²θ/dt² = −mgd sin θ − κθ.",
    example="taucli pendulum --shape rod --length 1m --mass 2kg --axis end --angle0 90deg",
    options=(
        *(SIGNED_PARTS if option is PARTS else option for option in BODY_OPTIONS),
        Option("cm_distance", "length", "Distance d from the pivot to the centre of mass (else from the shape and --offset).", sign="nonnegative"),
        Option("angle0", "angle", "Starting angle from the downward vertical (90deg: horizontal).", sign="any", default="0", panel=MOTION),
        Option("omega0", "angular velocity", "Starting angular velocity, positive toward larger angles.", sign="any", default="0", panel=MOTION),
        Option("torsion", "torsion constant", "Torsion constant κ of a spring or wire (torque κθ), e.g. '0.5N*m/rad'.", sign="nonnegative"),
        GRAVITY,
        Option("angle", "angle", "Report ω and the time to reach this angle, e.g. 0deg.", sign="any", panel=MOTION),
        Option("time", "time", "Report θ and ω at this time, e.g. 2s.", sign="nonnegative", panel=MOTION),
        Option("at", "length", "A point this far from the pivot: its tangential acceleration at the start, and its speed and accelerations at --angle.", sign="nonnegative", panel=MOTION),
        Option("method", CHOICE, " | ".join(METHODS) + ".", panel=MOTION, choices=METHODS, default="auto", metavar="METHOD"),
        DT,
        RTOL,
    ),
    results=(
        Result("I", "kg*m**2", "moment of inertia about the pivot"),
        Result("cm_distance", "m", "distance from the pivot to the centre of mass"),
        Result("alpha0", "rad/s**2", "angular acceleration at the start (size)"),
        Result("omega_bottom", "rad/s", "angular speed at the bottom (θ = 0)"),
        Result("omega", "rad/s", "angular velocity…"),
        Result("t_angle", "s", "time to reach…"),
        Result("t_bottom", "s", "time to reach the bottom (θ = 0)"),
        Result("period_small", "s", "period of small swings, 2π√(I/(mgd + κ))"),
        Result("period", "s", "period…"),
        Result("pivot_force0", "N", "force of the pivot on the body at the start (size)"),
        Result("pivot_force_bottom", "N", "force of the pivot on the body at the bottom (size)"),
        Result("equivalent_length", "m", "length of the simple pendulum with the same period, I/(md)"),
        Result("centre_of_percussion", "m", "centre of percussion, from the pivot, I/(md)"),
        Result("goes_over", None, "whether it goes over the top (θ = 180°)"),
        Result("omega0_over", "rad/s", "starting speed that just reaches the top"),
        Result("theta", "rad", "angle from the downward vertical…"),
        Result("a_t0", "m/s**2", "tangential acceleration at the start of the point…"),
        Result("v_t", "m/s", "speed of the point…"),
        Result("a_t", "m/s**2", "tangential acceleration of the point…"),
        Result("a_c", "m/s**2", "centripetal acceleration of the point…"),
    ),
    output=ANSWER,
    headline="period",
    library="taucli.scenes.pendulum:pendulum",
)
