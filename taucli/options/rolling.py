"""taucli rolling: a round body on an incline, or a skidding ball on the flat; pulled, a spool, a yo-yo."""

from taucli.names import ROLLING_BODIES
from taucli.options.common import ANSWER, BODY, GRAVITY, MOTION, POINT_RESULTS, point_option
from taucli.table import CHOICE, FLAG, Command, Option, Result

PULL = "Pull, spool and yo-yo"

COMMAND = Command(
    name="rolling",
    summary="A round body on an incline: does it roll or slip, and how fast; a skidding ball; a pulled body, a spool, a yo-yo.",
    example="taucli rolling sphere --angle 30deg --length 2m",
    options=(
        Option("shape", CHOICE, f"{', '.join(ROLLING_BODIES)} (or give --k2 or --inertia).", choices=ROLLING_BODIES, positional=True, metavar="SHAPE"),
        Option("k2", "dimensionless", "I/(mR²) of the body, instead of SHAPE.", sign="nonnegative", panel=BODY),
        Option("inertia", "moment of inertia", "Moment of inertia about the centre (with --mass and --radius).", sign="nonnegative", panel=BODY),
        Option("mass", "mass", "Mass (needed only for forces and energies).", panel=BODY),
        Option("radius", "length", "Radius (needed only for α and ω).", panel=BODY),
        Option("angle", "angle", "Slope of the incline, 0 to 90deg.", sign="any"),
        Option("mu_s", "dimensionless", "Static friction coefficient (decides roll or slip).", sign="nonnegative"),
        Option("mu_k", "dimensionless", "Kinetic friction coefficient (when it slips or skids).", sign="nonnegative"),
        Option("length", "length", "Distance down the slope to the bottom.", panel=MOTION),
        Option("height", "length", "Height of the slope, instead of --length.", panel=MOTION),
        Option("v0", "velocity", "Speed up the slope (how far it climbs); on the flat, rolling at v0 (alone) or skidding (with --mu-k or --omega0); a yo-yo thrown down.", sign="any", panel=MOTION),
        Option("omega0", "angular velocity", "Spin on the flat, in the rolling sense (skid to roll).", sign="any", panel=MOTION),
        Option("pull", "force", "A steady pull on the body (on an incline along the slope, up it), e.g. 10N.", panel=PULL),
        Option("pull_height", "length", "Where the pull acts: height above the centre (negative below; R: the top).", sign="any", default="0", panel=PULL),
        Option("pull_angle", "angle", "Angle of the pull above the surface (on an incline, from the slope).", sign="any", default="0deg", panel=PULL),
        Option("axle_radius", "length", "A spool: the string is wound at this radius (below R) and leaves from below unless --pull-height is positive; a yo-yo's axle.", panel=PULL),
        Option("yoyo", FLAG, "A yo-yo: the body falls as its string, fixed above and wound at --axle-radius, unwinds.", panel=PULL),
        GRAVITY,
        point_option("from the centre, turning with the body (at the end: the bottom, the drop, rolling at last; else the start)"),
    ),
    results=(
        Result("a", "m/s**2", "acceleration of the centre…"),
        Result("alpha", "rad/s**2", "angular acceleration…"),
        Result("friction", "N", "friction force at the contact…"),
        Result("mu_min", "", "least static coefficient for rolling"),
        Result("rolls", None, "rolls without slipping"),
        Result("critical_angle", "rad", "pull angle at which the spool stays put"),
        Result("T", "N", "tension in the string"),
        Result("v", "m/s", "speed…"),
        Result("omega", "rad/s", "angular velocity…"),
        Result("t", "s", "time…"),
        Result("KE_trans", "J", "kinetic energy of translation…"),
        Result("KE_rot", "J", "kinetic energy of rotation…"),
        Result("KE", "J", "kinetic energy, translation and rotation…"),
        Result("d_climb", "m", "distance it climbs up the slope"),
        Result("h_climb", "m", "height it climbs"),
        Result("t_climb", "s", "time to the highest point"),
        Result("t_roll", "s", "time until it rolls without slipping"),
        Result("d_roll", "m", "distance skidded until then"),
        Result("v_roll", "m/s", "speed once it rolls"),
        Result("omega_roll", "rad/s", "angular velocity once it rolls"),
        Result("energy_lost", "J", "kinetic energy turned to heat by sliding friction"),
        *POINT_RESULTS,
    ),
    output=ANSWER,
    headline="a",
    library="taucli.scenes.rolling:rolling",
)
