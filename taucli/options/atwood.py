"""taucli atwood: two masses on a string over a pulley with mass."""

from taucli.core.names import PULLEY_SHAPES
from taucli.options.common import ANSWER, GRAVITY, MOTION, POINT_RESULTS, point_option
from taucli.options.table import CHOICE, FLAG, PART, PULL, SIDE, Command, Option, Result

PULLEY = "Pulley"
HOIST = "A hoist: its drive and its brake"
SIDES = "Where the blocks are, and what pulls them"

COMMAND = Command(
    name="atwood",
    summary="Two masses on a string over a pulley with mass: acceleration and tensions.",
    example="taucli atwood --m1 4kg --m2 1kg --pulley-mass 2kg --pulley-radius 0.1m",
    options=(
        Option("m1", "mass", "The mass on side 1 (hanging unless --side1 says); its motion away from the pulley (down, hanging) is positive "
               "(0, or left out with a --pull on it: the string's end pulled by hand).", sign="nonnegative"),
        Option("m2", "mass", "The other mass (0: one mass on a string wound on the pulley).", sign="nonnegative"),
        Option("pulley_mass", "mass", "Pulley mass (0: massless).", sign="nonnegative", default="0", panel=PULLEY),
        Option("pulley_radius", "length", "Pulley radius (needed only for alpha, axle friction, --torque or --pulley-inertia).", panel=PULLEY),
        Option("pulley_shape", CHOICE, "Pulley shape.", choices=PULLEY_SHAPES, default="disc", panel=PULLEY),
        Option("pulley_inertia", "moment of inertia", "Pulley moment of inertia, instead of mass and shape.", sign="nonnegative", panel=PULLEY),
        Option("pulley_gyration", "length", "The pulley's radius of gyration k, with --pulley-mass instead of --pulley-shape: I = Mk², e.g. 0.08m.", panel=PULLEY),
        Option("axle_friction", "torque", "Constant friction torque at the axle, a brake (holds at rest too).", sign="nonnegative", panel=PULLEY),
        Option(
            "part", PART,
            'A part of the pulley about its axle (a hub, a rim, spokes), as in taucli inertia, e.g. --part "ring mass=0.5kg radius=0.1m" '
            "(repeatable); the parts add to --pulley-inertia or to the inertia of --pulley-mass.",
            panel=PULLEY, repeatable=True, metavar='"SHAPE key=value ..."',
        ),
        Option("radius1", "length", "A stepped pulley: the radius m1's string is wound at (m2's on the other side at --radius2).", panel=PULLEY),
        Option("radius2", "length", "A stepped pulley: the radius m2's string is wound at.", panel=PULLEY),
        Option("same_side", FLAG, "m2's string wound on m1's side of the pulley, the same way: the two torques add and both blocks go down together "
               "(a stepped pulley, or one drum at --pulley-radius).", panel=PULLEY),
        Option("rim_mu", "dimensionless", "Friction coefficient between the string and the rim: past the capstan limit the string slides.", sign="nonnegative", panel=PULLEY),
        Option("wrap", "angle", "Angle of rim the string wraps, with --rim-mu (or of drum, with --fixed-drum).", default="180deg", panel=PULLEY),
        Option("fixed_drum", FLAG, "The rope passes over a drum that cannot turn (a rod, a bollard): held while m1/m2 is within e^(±μs·wrap), "
               "sliding with T_tight = e^(μk·wrap)·T_slack beyond; the coefficient from --rim-mu, or --mu-s and --mu-k.", panel=PULLEY),
        Option("side1", SIDE, 'Where m1 is: "hang" (the default), "table mu-s=… mu-k=…" or "incline angle=… mu-s=… mu-k=…" '
               "(its own slope, the pulley at the top; no coefficient: smooth).", panel=SIDES, metavar='"hang|table|incline key=value ..."'),
        Option("side2", SIDE, 'Where m2 is, as --side1 (--incline, --mu-s and --mu-k say the same for m2, and are not given beside it).',
               panel=SIDES, metavar='"hang|table|incline key=value ..."'),
        Option("incline", "angle", 'm2 on a slope at this angle (0deg: a table) instead of hanging: --side2 "incline angle=…".', sign="any", panel=SIDES),
        Option("mu_k", "dimensionless", "Kinetic friction coefficient under m2 (with --incline).", sign="nonnegative", panel=SIDES),
        Option("mu_s", "dimensionless", "Static friction coefficient under m2 (with --incline).", sign="nonnegative", panel=SIDES),
        Option("pull", PULL, 'A constant pull on a block, e.g. "force=20N angle=30deg on=2": along its path away from the pulley (negative: '
               "towards it), angle= tilted off its surface (positive lifting it; 0 on a hanging block), on= 1 or 2 (default 1); in place of "
               "a hanging mass or beside one (repeatable).", panel=SIDES, repeatable=True, metavar='"force=… [angle=…] [on=1|2]"'),
        Option("torque", "torque", "A drive torque on the pulley (a motor, a hoist drum), positive lifting m1 (winding m1's string in).",
               sign="any", panel=SIDES),
        Option("counterweight", "mass", "A hoist's counterweight, hanging on side 2 (the same as --m2): m1 is the cage or load the drive lifts.",
               sign="nonnegative", panel=HOIST),
        Option("hoist_speed", "velocity", "A hoist lifting m1 steadily at this speed (negative: lowering it): the drive's power_steady and torque_steady.",
               sign="any", panel=HOIST),
        Option("hoist_height", "length", "A hoist's trip: m1 lifted this far, from rest to rest (negative: lowered): energy_trip, the drive's work.",
               sign="any", panel=HOIST),
        Option("trip_time", "time", "The trip's time, with --hoist-height: power_trip, the drive's mean power over it.", panel=HOIST),
        GRAVITY,
        Option("v0", "velocity", "Initial speed of m1 (down positive).", sign="any", default="0", panel=MOTION),
        Option("distance", "length", "Report the time and speed after m1 has moved this far the way the masses first move (null where they stop short).", sign="nonnegative", panel=MOTION),
        Option("time", "time", "Report the speed and displacement at this time.", sign="nonnegative", panel=MOTION),
        point_option("on the pulley (after --distance, else at --time, else the start)"),
    ),
    results=(
        Result("a", "m/s**2", "acceleration of the masses (m1 downward positive)"),
        Result("T1", "N", "tension on m1's side"),
        Result("T2", "N", "tension on m2's side"),
        Result("alpha", "rad/s**2", "angular acceleration of the pulley"),
        Result("a2", "m/s**2", "acceleration of m2 (upward positive)", needs=("radius1", "radius2")),
        Result("a_rim", "m/s**2", "tangential acceleration of the rim (m1's side moving down positive)", needs=("rim_mu",)),
        Result("grips", None, "the string grips the rim (does not slide over it)", needs=("rim_mu",)),
        Result("rim_mu_min", "", "least rim coefficient for the string to grip", needs=("rim_mu",)),
        Result("holds", None, "the rope holds on the fixed drum (does not slide)", needs=("fixed_drum+rim_mu", "fixed_drum+mu_s+mu_k")),
        Result("a_massless", "m/s**2", "acceleration with a massless pulley, for comparison"),
        Result("t", "s", "time to travel…", needs=("distance", "time")),
        Result("v", "m/s", "velocity…", needs=("distance", "time")),
        Result("distance", "m", "displacement of m1 (down positive)…", needs=("time",)),
        Result("t_stop", "s", "time until the masses stop (with --v0)", needs=("v0",), example="{v0} '-2 m/s'"),
        Result("distance_stop", "m", "displacement of m1 until they stop (down positive)", needs=("v0",), example="{v0} '-2 m/s'"),
        Result("power_steady", "W", "power of the drive lifting m1 steadily at --hoist-speed", needs=("hoist_speed",)),
        Result("torque_steady", "N*m", "drive torque lifting m1 steadily at --hoist-speed", needs=("hoist_speed+pulley_radius",)),
        Result("energy_trip", "J", "energy the drive gives per trip (m1 lifted --hoist-height, from rest to rest)", needs=("hoist_height",)),
        Result("power_trip", "W", "mean power of the drive over the trip, energy_trip / --trip-time", needs=("hoist_height+trip_time",)),
        Result("work_brake", "J", "energy the axle friction (a brake) takes…",
               needs=("axle_friction+distance", "axle_friction+v0", "axle_friction+hoist_height"), example="{axle_friction} '0.5 N*m' {pulley_radius} 0.1m {distance} 1m"),
        *POINT_RESULTS,
    ),
    output=ANSWER,
    headline="a",
    library="taucli.scenes.atwood:atwood",
)
