"""taucli rolling: a round body on an incline, or a skidding ball on the flat; pulled, a spool, a
yo-yo; joined to a hanging mass over a pulley; a point of it seen from the ground."""

from taucli.core.names import ROLLING_BODIES
from taucli.options.common import ANSWER, BODY, GRAVITY, MOTION, POINT_RESULTS
from taucli.options.table import CHOICE, FLAG, Command, Option, Result

PULL = "Pull, spool and yo-yo"
HANGING = "Hanging mass over a pulley"
DRUM = "A yo-yo's drum"
RIM_POSITIONS = ("top", "bottom", "front", "back")  # scenes.rolling.ground_point.POSITIONS
STRING_ENDS = ("centre", "top")  # scenes.rolling.hanging: where the string leaves the body

# What makes the results of a mode the docs example (a sphere down a slope) is not in (#42 item 18): a
# hanging mass (forces need the body's mass), a skid on the flat, a point of the rim seen from the ground.
HANGING = "hanging_mass+mass"
ON_THE_FLAT = "{angle} 0deg {v0} '2 m/s'"
SKIDS = ("v0+mu_k", "omega0+mu_k+radius")
SKIDS_EXAMPLE = ON_THE_FLAT + " {mu_k} 0.5"
ON_THE_RIM = ("at+radius",)
ON_THE_RIM_EXAMPLE = "{at} top {radius} 0.2m"

def _on_a_drum(*more: str, ends: bool = False) -> tuple[str, ...]:
    """What makes a drum's result: a yo-yo with a mass on a drum given by its mass or its I (with its
    radius), ``more`` options beside, and after a drop or a time where ``ends``."""
    drums = [("drum_mass", *more), ("drum_inertia", "drum_radius", *(name for name in more if name != "drum_radius"))]
    return tuple("+".join(("yoyo", *drum, "mass", *((end,) if ends else ()))) for end in (("height", "time") if ends else ("",)) for drum in drums)


COMMAND = Command(
    name="rolling",
    summary="A round body on an incline: does it roll or slip, and how fast; a skidding ball; a pulled body, a spool, a yo-yo; a body joined to a hanging mass.",
    example="taucli rolling sphere --angle 30deg --length 2m",
    options=(
        Option("shape", CHOICE, f"{', '.join(ROLLING_BODIES)} (or give --k2 or --inertia).", choices=ROLLING_BODIES, positional=True, metavar="SHAPE"),
        Option("k2", "dimensionless", "I/(mR²) of the body, instead of SHAPE.", sign="nonnegative", panel=BODY),
        Option("inertia", "moment of inertia", "Moment of inertia about the centre (with --mass and --radius).", sign="nonnegative", panel=BODY),
        Option("gyration", "length", "The body's radius of gyration k about its centre, with --radius, instead of SHAPE: I/(mR²) = (k/R)², e.g. 0.07m.", panel=BODY),
        Option("mass", "mass", "Mass (needed only for forces and energies).", panel=BODY),
        Option("radius", "length", "Radius (needed only for α and ω).", panel=BODY),
        Option("angle", "angle", "Slope of the incline, 0 to 90deg.", sign="any"),
        Option("mu_s", "dimensionless", "Static friction coefficient (decides roll or slip).", sign="nonnegative"),
        Option("mu_k", "dimensionless", "Kinetic friction coefficient (when it slips or skids).", sign="nonnegative"),
        Option("length", "length", "Distance down the slope to the bottom; with --pull or --hanging-mass, the distance the body moves; "
               "with --in-place, the string the hand pulls.", panel=MOTION),
        Option("height", "length", "Height of the slope, instead of --length; a yo-yo's drop.", panel=MOTION),
        Option("v0", "velocity", "Speed up the slope, set rolling (negative: down it), from --length above the bottom; on the flat, "
               "rolling at v0 (alone) or skidding (with --mu-k or --omega0); a yo-yo thrown down.", sign="any", panel=MOTION),
        Option("omega0", "angular velocity", "Spin on the flat, in the rolling sense (skid to roll); a yo-yo spun in place: its spin at the start.",
               sign="any", panel=MOTION),
        Option("pull", "force", "A steady pull on the body (on an incline along the slope, up it; on a yo-yo upward, with --pull-at), e.g. 10N.", panel=PULL),
        Option("pull_height", "length", "Where the pull acts: height above the centre (negative below; R: the top).", sign="any", default="0", panel=PULL),
        Option("pull_angle", "angle", "Angle of the pull above the surface (on an incline, from the slope).", sign="any", default="0deg", panel=PULL),
        Option("axle_radius", "length", "A spool: the string is wound at this radius (below R) and leaves from below unless --pull-height is positive; a yo-yo's axle.", panel=PULL),
        Option("pull_at", "length", "A yo-yo's --pull (upward): where its line passes, this far from the centre on the far side "
               "from the string it unwinds from (negative: the string's side; R: a rope that runs under the body and up the far side), e.g. 0.1m.",
               sign="any", default="0", panel=PULL),
        Option("yoyo", FLAG, "A yo-yo: the body falls as its string, fixed above and wound at --axle-radius, unwinds.", panel=PULL),
        Option("in_place", FLAG, "A yo-yo spun in place: its string pulled up just hard enough that its centre stays put.", panel=PULL),
        Option("time", "time", "A yo-yo's state after this time (instead of --height): its velocity, spin and drop, e.g. 3s.", sign="nonnegative", panel=MOTION),
        Option("hanging_mass", "mass", "A mass hanging from a string that runs from the body along the surface and over a pulley "
               "(at the edge of the flat, or the top of the slope), e.g. 2kg.", panel=HANGING),
        Option("string", CHOICE, "Where that string leaves the body: centre (an axle in a frame) or top (wound on the body).",
               choices=STRING_ENDS, default="centre", panel=HANGING, metavar="centre|top"),
        Option("pulley_mass", "mass", "Mass of the pulley, a uniform disc (0: massless).", sign="nonnegative", default="0", panel=HANGING),
        Option("pulley_radius", "length", "Radius of the pulley (needed only for its angular acceleration).", panel=HANGING),
        Option("drum_mass", "mass", "A yo-yo whose string is wound at its top on a drum that turns on a fixed axle: the drum's mass, "
               "a uniform solid cylinder (I = M R²/2), e.g. 1kg.", panel=DRUM),
        Option("drum_inertia", "moment of inertia", "The drum's moment of inertia about its axle, instead of --drum-mass (with --drum-radius).", panel=DRUM),
        Option("drum_radius", "length", "The radius the string is wound at on the drum (needed only for its α and ω, and with --drum-inertia), e.g. 0.1m.",
               panel=DRUM),
        Option("drum_friction", "torque", "A constant friction torque at the drum's axle, opposing its turning (it holds the drum while "
               "the string's pull T R is no more), e.g. '0.05 N*m'.", sign="nonnegative", panel=DRUM),
        GRAVITY,
        Option("at", "length", "A point of the body: at this radius from the centre, turning with the body (v_t, a_t, a_c, a_total, a_angle, s "
               "about the centre), e.g. 0.05m, or rim (the body's radius; taken when one of those is asked for with no --at); or on the rim "
               "seen from the ground: top, bottom, front, back, or an angle from the top, forward positive, e.g. 45deg (v_ground, "
               "v_ground_angle, a_ground, a_ground_angle). At the end: the bottom, the distance, rolling at last; else the start.",
               panel=MOTION, words=("rim", *RIM_POSITIONS), also="angle"),
    ),
    results=(
        Result("a", "m/s**2", "acceleration of the centre…"),
        Result("alpha", "rad/s**2", "angular acceleration…"),
        Result("friction", "N", "friction force at the contact…"),
        Result("mu_min", "", "least static coefficient for rolling"),
        Result("rolls", None, "rolls without slipping"),
        Result("critical_angle", "rad", "pull angle at which the spool stays put", needs=("pull+axle_radius+radius",), example="{angle} 0deg {pull} 6N {axle_radius} 0.05m {radius} 0.2m"),
        Result("T", "N", "tension in the string…", needs=("hanging_mass+mass", "yoyo+mass", "in_place+mass+radius")),
        Result("T2", "N", "tension in the hanging part of the string", needs=(HANGING,)),
        Result("a_hanging", "m/s**2", "acceleration of the hanging mass, downward", needs=(HANGING,)),
        Result("alpha_pulley", "rad/s**2", "angular acceleration of the pulley", needs=(HANGING + "+pulley_radius",)),
        Result("a_hand", "m/s**2", "acceleration of the string's free end (the hand), upward", needs=("in_place+radius", "yoyo+pull+mass+radius")),
        Result("alpha_drum", "rad/s**2", "angular acceleration of the yo-yo's drum, unwinding", needs=_on_a_drum("drum_radius"),
               example="{yoyo} {mass} 1kg {drum_mass} 1kg {drum_radius} 0.1m"),
        Result("v", "m/s", "speed…"),
        Result("v_hanging", "m/s", "velocity of the hanging mass, downward…", needs=(HANGING + "+length",)),
        Result("omega", "rad/s", "angular velocity…", needs=("length+radius", "height+radius", "v0+radius", "yoyo+height+radius", "yoyo+time+radius", HANGING + "+length+radius"), example="{length} 2m {radius} 0.1m"),
        Result("omega_drum", "rad/s", "angular velocity of the yo-yo's drum…", needs=_on_a_drum("drum_radius", ends=True),
               example="{yoyo} {mass} 1kg {drum_mass} 1kg {drum_radius} 0.1m {height} 1m"),
        Result("t", "s", "time…"),
        Result("drop", "m", "distance the centre has dropped…", needs=("yoyo+time",), example="{yoyo} {time} 1s"),
        Result("work_pull", "J", "work done by the pull…", needs=("yoyo+pull+mass+time", "yoyo+pull+mass+height"), example="{yoyo} {mass} 2kg {pull} 5N {time} 1s"),
        Result("KE_trans", "J", "kinetic energy of translation…", needs=("mass",)),
        Result("KE_rot", "J", "kinetic energy of rotation…", needs=("mass",)),
        Result("KE_drum", "J", "kinetic energy of the yo-yo's drum…", needs=_on_a_drum(ends=True), example="{yoyo} {mass} 1kg {drum_mass} 1kg {height} 1m"),
        Result("work_drum_friction", "J", "energy the drum's axle friction takes…", needs=_on_a_drum("drum_radius", "drum_friction", ends=True),
               example="{yoyo} {mass} 1kg {drum_mass} 1kg {drum_radius} 0.1m {drum_friction} '0.1 N*m' {height} 1m"),
        Result("KE", "J", "kinetic energy, translation and rotation…", needs=("v0+mass", "yoyo+mass+height", HANGING + "+length+radius"), example=ON_THE_FLAT + " {mass} 4kg"),
        Result("d_climb", "m", "distance it climbs up the slope", needs=("v0",)),
        Result("h_climb", "m", "height it climbs", needs=("v0",)),
        Result("t_climb", "s", "time to the highest point", needs=("v0",)),
        Result("t_roll", "s", "time until it rolls without slipping", needs=SKIDS, example=SKIDS_EXAMPLE),
        Result("d_roll", "m", "distance skidded until then", needs=SKIDS, example=SKIDS_EXAMPLE),
        Result("v_roll", "m/s", "speed once it rolls", needs=SKIDS, example=SKIDS_EXAMPLE),
        Result("omega_roll", "rad/s", "angular velocity once it rolls", needs=("v0+mu_k+radius", "omega0+mu_k+radius"), example=SKIDS_EXAMPLE + " {radius} 0.2m"),
        Result("energy_lost", "J", "kinetic energy turned to heat by sliding friction", needs=("v0+mu_k+mass", "omega0+mu_k+radius+mass"), example=SKIDS_EXAMPLE + " {mass} 4kg"),
        *POINT_RESULTS,
        Result("v_ground", "m/s", "speed of the point relative to the ground…", needs=ON_THE_RIM, example=ON_THE_RIM_EXAMPLE),
        Result("v_ground_angle", "rad", "direction of that velocity…", needs=ON_THE_RIM, example=ON_THE_RIM_EXAMPLE),
        Result("a_ground", "m/s**2", "acceleration of the point relative to the ground…", needs=ON_THE_RIM, example=ON_THE_RIM_EXAMPLE),
        Result("a_ground_angle", "rad", "direction of that acceleration…", needs=ON_THE_RIM, example=ON_THE_RIM_EXAMPLE),
    ),
    output=ANSWER,
    headline="a",
    library="taucli.scenes.rolling:rolling",
)
