"""taucli balance: balancing of rotating masses, in one plane or in two planes along a shaft."""

from taucli.options.common import ANSWER, GRAVITY
from taucli.options.table import FLAG, REVOLVING, Command, Option, Result

MASSES = "The masses turning with the shaft"
BALANCING = "Balancing planes"
RUNNING = "Speed and bearings"

TWO_PLANES = ("plane+plane",)
BEARINGS = ("speed+bearing+bearing",)
TWO_PLANES_EXAMPLE = ("{mass} 'mass=2kg radius=0.3m angle=0deg plane=0.2m' {mass} 'mass=3kg radius=0.2m angle=90deg plane=0.5m' "
                      "{plane} 0m {plane} 0.8m")
BEARINGS_EXAMPLE = "{speed} 300rpm {bearing} -0.5m {bearing} 1m"

COMMAND = Command(
    name="balance",
    summary="Balancing of rotating masses: the balancing mass·radius and its angle in one plane or two, the unbalanced force and couple, the bearing loads.",
    description=(
        "Each mass turning with the shaft is --mass \"mass=… radius=… angle=… plane=…\" (repeatable): m at radius r, at angle θ "
        "counter-clockwise from a reference line, in the plane at plane= along the shaft. Their vectors m·r add to the unbalance "
        "U = Σ m r e^(iθ); the balancing mass in one plane is the vector that closes the polygon, −U. With two balancing planes "
        "(--plane twice) the couples m·r·l about the first close too, Σ m r l e^(iθ) + m_B r_B l_B = 0, and the masses in the two planes "
        "balance both the force and the couple. At a --speed ω the unbalanced force is ω²|U| and the couple ω²|Σ m r l e^(iθ)|; "
        "between two --bearing the loads each carries."
    ),
    example="taucli balance --mass 'mass=2kg radius=0.2m' --mass 'mass=3kg radius=15cm' --balance-radius 0.2m",
    options=(
        Option("mass", REVOLVING, 'A mass turning with the shaft: "mass=2kg radius=0.3m angle=45deg", with plane=0.5m its position along the shaft; '
               "length= in place of radius= for a uniform rod along the radius from the axis (or from radius=), its centre at r + L/2; "
               "angle= counter-clockwise from the reference line, default 0 (repeatable).",
               repeatable=True, metavar='"mass=… radius=… angle=… [plane=…]"', example="mass=2kg radius=0.3m angle=45deg", panel=MASSES),
        Option("plane", "length", "A balancing plane's position along the shaft, from where plane= is measured: once for one plane, "
               "twice for two (A, then B); the couples are taken about the first (repeatable).", sign="any", repeatable=True, panel=BALANCING),
        Option("balance_radius", "length", "The radius the balancing mass is put at: its mass m·r/r (once for both planes, or once for each).",
               repeatable=True, panel=BALANCING),
        Option("speed", "angular velocity", "The shaft's speed ω, for the unbalanced force ω²Σm·r and couple and the bearing loads, e.g. 300rpm.",
               sign="nonnegative", panel=RUNNING),
        Option("bearing", "length", "A bearing's position along the shaft (twice: A, then B), for the load each carries at --speed.",
               sign="any", repeatable=True, panel=RUNNING),
        Option("vertical", FLAG, "The shaft is vertical, positions along it measured upward: each mass's weight, at its radius, adds the moment "
               "m·g·r that turns with the shaft to the bearings' loads (else weights are left out, as balancing does).", panel=RUNNING),
        GRAVITY,
    ),
    results=(
        Result("unbalance", "kg*m", "unbalance, the size of Σ m·r"),
        Result("unbalance_angle", "rad", "angle of the unbalance Σ m·r"),
        Result("unbalance_couple", "kg*m**2", "couple unbalance, the size of Σ m·r·l…", needs=("plane", "bearing"),
               example=TWO_PLANES_EXAMPLE),
        Result("balance_mr", "kg*m", "balancing mass × radius (one plane)"),
        Result("balance_angle", "rad", "angle of the balancing mass (one plane)"),
        Result("balance_mass", "kg", "balancing mass at --balance-radius (one plane)"),
        Result("balance_mr_A", "kg*m", "balancing mass × radius in plane A", needs=TWO_PLANES, example=TWO_PLANES_EXAMPLE),
        Result("balance_angle_A", "rad", "angle of the balancing mass in plane A", needs=TWO_PLANES, example=TWO_PLANES_EXAMPLE),
        Result("balance_mass_A", "kg", "balancing mass in plane A at its radius", needs=("plane+plane+balance_radius",),
               example=TWO_PLANES_EXAMPLE + " {balance_radius} 0.25m"),
        Result("balance_mr_B", "kg*m", "balancing mass × radius in plane B", needs=TWO_PLANES, example=TWO_PLANES_EXAMPLE),
        Result("balance_angle_B", "rad", "angle of the balancing mass in plane B", needs=TWO_PLANES, example=TWO_PLANES_EXAMPLE),
        Result("balance_mass_B", "kg", "balancing mass in plane B at its radius", needs=("plane+plane+balance_radius",),
               example=TWO_PLANES_EXAMPLE + " {balance_radius} 0.25m"),
        Result("force_unbalanced", "N", "unbalanced force, ω² times the size of Σ m·r", needs=("speed",)),
        Result("couple_unbalanced", "N*m", "unbalanced couple, ω² times the size of Σ m·r·l…", needs=("speed+plane", "speed+bearing"),
               example=TWO_PLANES_EXAMPLE + " {speed} 300rpm"),
        Result("bearing_force_A", "N", "load on bearing A…", needs=BEARINGS, example=BEARINGS_EXAMPLE),
        Result("bearing_angle_A", "rad", "angle of the load on bearing A", needs=BEARINGS, example=BEARINGS_EXAMPLE),
        Result("bearing_force_B", "N", "load on bearing B…", needs=BEARINGS, example=BEARINGS_EXAMPLE),
        Result("bearing_angle_B", "rad", "angle of the load on bearing B", needs=BEARINGS, example=BEARINGS_EXAMPLE),
    ),
    output=ANSWER,
    headline="balance_mr",
    library="taucli.scenes.balance:balance",
)
