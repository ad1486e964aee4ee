"""taucli gyro: a spinning top or gyroscope on a pivot, and the precession of its axis."""

from taucli.options.common import ANSWER, BODY, BODY_OPTIONS, GRAVITY
from taucli.options.table import CHOICE, ROTOR, Command, Option, Result

PIVOT = "Pivot and torque"
MACHINE = "A rotor on a machine whose axis is turned (--precession)"

# How a book states a rotor's sense: clockwise or counter-clockwise seen from one end of the
# vehicle (rear: stern, tail; front: bow, nose). scenes.gyro.machine gives each its direction.
SPIN_SENSES = tuple(f"{turn}-from-{end}" for end in ("rear", "front", "left", "right", "above", "below") for turn in ("cw", "ccw"))
# How the vehicle turns the rotor's axis: a turn seen from above, a pitch of its front, a roll.
TURNS = ("left", "right", "pitch-up", "pitch-down", "roll-left", "roll-right")
CRAFTS = ("vehicle", "ship", "aircraft")
VEHICLE = "A vehicle on a turn (--vehicle)"
VEHICLES = ("four-wheeler", "two-wheeler")
ON_A_TURN = "{vehicle} four-wheeler {mass} 2000kg {cg_height} 0.6m {track} 1.5m {speed} 90km/h {turn_radius} 100m"  # the results' example

COMMAND = Command(
    name="gyro",
    summary="A spinning top or gyroscope on a pivot: its precession, Ω = mgr/(Iω_s), and the exact steady rates.",
    description=(
        "The body spins at --spin about its symmetry axis (--inertia about that axis, or --shape with its "
        "dimensions), its centre of mass --cm-distance from the pivot, the axis at --tilt from the upward "
        "vertical. The weight's torque turns the angular momentum, not the body: the axis precesses. "
        "--inertia-perp (taken from the shape where one is given) adds the exact steady precession rates, "
        "the roots of I⊥Ω²cos θ − Iω_sΩ + mgr = 0, the orbit of the centre of mass and the pivot's force. "
        "A rotor on a machine whose axis is turned at a given rate (--precession: a ship or aircraft in a turn, "
        "v/R on a curve, a pitching rate) feels the gyroscopic couple Iω_sΩ; --spin-sense and --turn give its effect "
        "in words, --bearing-span the bearings' forces."
    ),
    example="taucli gyro --shape disc --mass 0.3kg --radius 5cm --spin 4000rpm --cm-distance 5cm",
    options=(
        *BODY_OPTIONS,
        Option("spin", "angular velocity", "Spin ω_s: the angular velocity's component along the spin axis, e.g. 4000rpm."),
        Option("cm_distance", "length", "Distance r from the pivot to the centre of mass, along the spin axis, e.g. 5cm.", sign="nonnegative", panel=PIVOT),
        Option(
            "torque",
            "torque",
            "The torque on the body, instead of --mass and --cm-distance (the Earth's axis under the Sun and Moon): Ω = τ/(L sin θ).",
            sign="nonnegative",
            panel=PIVOT,
        ),
        Option(
            "tilt",
            "angle",
            "Angle of the spin axis from the upward vertical, 0 to 180deg (above 90deg the body hangs below the pivot; with --torque, from the axis it precesses round).",
            sign="nonnegative",
            default="90deg",
            panel=PIVOT,
        ),
        Option(
            "inertia_perp",
            "moment of inertia",
            "Moment of inertia about an axis through the pivot perpendicular to the spin axis (from the shape and --cm-distance where a shape is given).",
            panel=BODY,
        ),
        Option(
            "precession",
            "angular velocity",
            "The rate Ω at which the rotor's axis is turned (a rotor on a machine): a turn v/R, e.g. '(100 km/h)/(75 m)', or a pitching rate.",
            sign="nonnegative",
            panel=MACHINE,
        ),
        Option("spin_sense", CHOICE, "The rotor's sense as a book states it: clockwise (cw) or counter-clockwise (ccw) seen from the rear "
               "(stern, tail), front (bow, nose), left, right, above or below, e.g. cw-from-rear.", choices=SPIN_SENSES, panel=MACHINE, metavar="SENSE",
               example="cw-from-rear"),
        Option("turn", CHOICE, "How the vehicle turns the rotor's axis: left, right (seen from above), pitch-up, pitch-down (the front rising, "
               "falling), roll-left, roll-right (that side going down).", choices=TURNS, panel=MACHINE, metavar="TURN", example="left"),
        Option("lean", "angle", "The vehicle's lean (bank) about its fore-and-aft axis, positive with its right side down, e.g. 20deg "
               "(a two-wheeler leaning into a right-hand curve).", sign="any", panel=MACHINE),
        Option("craft", CHOICE, "The words for the effect: vehicle (front, rear, left, right), ship (bow, stern, port, starboard), "
               "aircraft (nose, tail, left, right).", choices=CRAFTS, default="vehicle", panel=MACHINE, metavar="vehicle|ship|aircraft"),
        Option("rotor", ROTOR, 'Another rotor the vehicle turns with the first, e.g. "inertia=0.3kg*m^2 spin=5000rpm sense=cw-from-right" '
               '(an engine beside the road wheels; repeatable): the angular momenta add as vectors.', repeatable=True, panel=MACHINE,
               metavar='"inertia=… spin=… sense=…"'),
        Option("bearing_span", "length", "The distance between the rotor shaft's two bearings: each carries the couple as a force C/l.", panel=MACHINE),
        Option("vehicle", CHOICE, "A vehicle on a turn: four-wheeler (its wheels' loads, the speed it overturns at) or two-wheeler (its lean), "
               "from --mass, --cg-height, --speed, --turn-radius and its spinning wheels and engine.", choices=VEHICLES, panel=VEHICLE,
               metavar="four-wheeler|two-wheeler", example="four-wheeler"),
        Option("cg_height", "length", "Height of the vehicle's centre of gravity above the road, e.g. 0.6m.", panel=VEHICLE),
        Option("track", "length", "A four-wheeler's track: the distance between its inner and outer wheels, e.g. 1.5m.", panel=VEHICLE),
        Option("speed", "velocity", "The vehicle's speed round the turn, e.g. 90km/h.", panel=VEHICLE),
        Option("turn_radius", "length", "Radius of the turn, e.g. 50m.", panel=VEHICLE),
        Option("wheel_inertia", "moment of inertia", "Each road wheel's moment of inertia about its axle (with its share of the axle), e.g. '0.8kg*m^2'.",
               sign="nonnegative", panel=VEHICLE),
        Option("wheel_radius", "length", "The road wheels' radius: they spin at v/r, e.g. 0.3m.", panel=VEHICLE),
        Option("engine_inertia", "moment of inertia", "The engine's (or motors') rotating parts, all together, about their axis across the vehicle, e.g. '1kg*m^2'.",
               sign="nonnegative", panel=VEHICLE),
        Option("gear_ratio", "dimensionless", "The engine's speed over the wheels' (negative: the engine turns against the wheels), e.g. 4.", sign="any", panel=VEHICLE),
        GRAVITY,
    ),
    results=(
        Result("L", "kg*m**2/s", "spin angular momentum Iω_s"),
        Result("omega_p", "rad/s", "precession rate…"),
        Result("period_p", "s", "precession period…"),
        Result("omega_p_slow", "rad/s", "slow steady precession (exact)"),
        Result("omega_p_fast", "rad/s", "fast steady precession (exact)"),
        Result("spin_min", "rad/s", "least spin for a steady precession", needs=("tilt",)),
        Result("L_orbital", "kg*m**2/s", "angular momentum of the centre of mass's orbit…"),
        Result("pivot_force_vertical", "N", "pivot's force on the body, vertical (up)"),
        Result("pivot_force_horizontal", "N", "pivot's force on the body, horizontal (towards the axis)…"),
        Result("couple", "N*m", "gyroscopic couple…", needs=("precession",)),
        Result("effect", None, "effect of the couple on the vehicle", needs=("precession+spin_sense+turn",)),
        Result("bearing_force", "N", "force on each bearing C/l…", needs=("precession+bearing_span",)),
        Result("couple_gyro", "N*m", "gyroscopic couple of the wheels and engine, (nI_w + GI_e)ω_wΩ", needs=("vehicle",),
               example=ON_A_TURN + " {wheel_inertia} '0.8kg*m^2' {wheel_radius} 0.3m"),
        Result("couple_centrifugal", "N*m", "centrifugal couple mv²h/R", needs=("vehicle",),
               example=ON_A_TURN),
        Result("reaction_outer", "N", "load on each outer wheel", needs=("vehicle+track",),
               example=ON_A_TURN),
        Result("reaction_inner", "N", "load on each inner wheel", needs=("vehicle+track",),
               example=ON_A_TURN),
        Result("speed_overturn", "m/s", "speed at which the inner wheels lift (it overturns)", needs=("vehicle+track",),
               example=ON_A_TURN),
        Result("lean_balance", "rad", "lean from the vertical at which a two-wheeler balances on the turn", needs=("vehicle",),
               example="{vehicle} two-wheeler {mass} 250kg {cg_height} 0.6m {speed} 90km/h {turn_radius} 100m"),
    ),
    output=ANSWER,
    headline="omega_p",
    library="taucli.scenes.gyro:gyro",
)
