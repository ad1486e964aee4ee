"""Options several commands share: the body, gravity, the method, and how to answer."""

from __future__ import annotations

from taucli.core.names import FORMATS, METHOD_NAMES, SHAPE_AXES, SHAPE_NAMES
from dataclasses import replace

from taucli.options.table import BAND, BRAKE, CALIPER, CENTRIFUGAL, CHOICE, COUNT, FACE, FILE, FLAG, PART, TEXT, Option, Result

BODY = "Body (shape and dimensions)"
MOTION = "Motion and method"
OUTPUT = "Output"
SWEEP = "Sweep and plot (any quantity option takes a range FROM..TO or a list A,B)"

STANDARD_GRAVITY = 9.80665


def _length(name: str, help: str, sign: str = "positive") -> Option:
    return Option(name, "length", help, sign=sign, panel=BODY)


# The dimensions of a shape, as in ``taucli inertia`` and ``--shape`` (scenes.inertia.SHAPES).
DIMENSIONS = (
    _length("radius", "Radius (a point's distance from the axis), e.g. 0.2m."),
    _length("inner_radius", "Inner radius (tube, thick-shell).", sign="nonnegative"),
    _length("outer_radius", "Outer radius (tube, thick-shell)."),
    _length("length", "Length (rod; cylinder along its axis)."),
    _length("width", "Width (plate, box)."),
    _length("height", "Height (plate, box, cone)."),
    _length("depth", "Depth (box)."),
)
DIMENSION_NAMES = tuple(option.name for option in DIMENSIONS)

MASS = Option("mass", "mass", "Mass of the body, e.g. 5kg.", panel=BODY)
AXIS = Option(
    "axis",
    CHOICE,
    "Axis, where the shape has several: "
    + "; ".join(f"{'|'.join(axes)} ({name})" for name, axes in SHAPE_AXES.items() if len(axes) > 1)
    + " (default: the first).",
    panel=BODY,
    choices=tuple(dict.fromkeys(axis for axes in SHAPE_AXES.values() for axis in axes)),
    metavar="AXIS",
)
OFFSET = _length("offset", "Distance of the rotation axis from the parallel axis through the centre of mass.", sign="nonnegative")
PARTS = Option(
    "part",
    PART,
    'Another part of the same body about the same axis, e.g. --part "point mass=100g offset=0.2m"; '
    'a part may be given by inertia= (with mass= and offset=), gyration= with mass=, or density= with its dimensions (repeatable).',
    panel=BODY,
    repeatable=True,
    metavar='"SHAPE key=value ..."',
    example="point mass=100g offset=0.2m",
)
SHAPE_WORDS = ", ".join(SHAPE_NAMES)
# pendulum: a part may sit on the other side of the pivot, its offset= negative (d = Σmᵢdᵢ/M, signed)
SIGNED_PARTS = replace(PARTS, sign="any", help=PARTS.help.replace("(repeatable)", "offset= negative on the other side of the pivot (repeatable)"))

# A body by its density (read by its unit: per volume, area or length) or its radius of gyration (#34).
DENSITY = Option("density", "density", "The body's density instead of --mass, with its shape and dimensions, read by its unit: kg/m^3 for a solid, "
                 "kg/m^2 for a disc, plate, washer (tube) or thin shell, kg/m for a rod or ring, e.g. '7800kg/m^3'.", panel=BODY,
                 also=("areal density", "linear density"))
GYRATION = Option("gyration", "length", "The body's radius of gyration k, with --mass and no shape: I = Mk², e.g. 0.3m.", panel=BODY)

# A body on an axle: its moment of inertia, or a shape with its mass and dimensions.
BODY_OPTIONS = (
    Option("inertia", "moment of inertia", "Moment of inertia about the axle, e.g. '0.1kg*m^2' (or give --shape).", panel=BODY),
    Option("shape", CHOICE, f"The body's shape, with --mass and its dimensions: {SHAPE_WORDS}.", panel=BODY, choices=SHAPE_NAMES, metavar="SHAPE"),
    MASS,
    DENSITY,
    GYRATION,
    *DIMENSIONS,
    AXIS,
    OFFSET,
    PARTS,
)

# A push that makes (or adds to) the torque: spin-down and impulse. taucli.scenes.spin.steps.Push
PUSH = (
    Option("force", "force", "A push at --lever whose torque F·r·sin φ adds to --torque's (or is the torque), e.g. 6N.", sign="any"),
    Option("lever", "length", "Distance of the push from the axle, e.g. 0.25m."),
    Option("push_angle", "angle", "Angle between lever arm and force.", sign="any", default="90deg"),
)

GRAVITY = Option("g", "acceleration", "Gravity.", default="9.80665 m/s^2")
GRAVITY_FOR_WEIGHTS = Option("g", "acceleration", "Gravity, to read a weight given for a mass (--mass 490N).", default="9.80665 m/s^2")

METHOD = Option("method", CHOICE, " | ".join(METHOD_NAMES) + ".", panel=MOTION, choices=METHOD_NAMES, default="auto", metavar="METHOD")
DT = Option("dt", "time", "Fixed step for euler and rk4.", panel=MOTION, default="1 ms")
RTOL = Option("rtol", "dimensionless", "Relative tolerance for rk45.", panel=MOTION, default="1e-10")

# Solving for an input, and uncertainty (#22; taucli.answering.find, taucli.uncertain).
FIND = "Solve for an input, and uncertainty (any quantity may be given as 4.0+/-0.1kg)"
UNCERTAIN = (
    Option("find", TEXT, "Solve for this input so that --want holds: its option name, e.g. pulley_inertia, or a key of a spec, e.g. particle.speed.", panel=FIND, metavar="NAME"),
    Option("want", TEXT, "The target of --find, e.g. --want 'a=4.0m/s^2' (may carry an uncertainty).", panel=FIND, metavar="RESULT=VALUE"),
    Option("minimize", TEXT, "With --find NAME: the value of NAME, within its range, that gives the least of this result, e.g. --minimize torque_rms.",
           panel=FIND, metavar="RESULT"),
    Option("maximize", TEXT, "With --find NAME: the value of NAME that gives the most of this result, e.g. --maximize power.", panel=FIND, metavar="RESULT"),
    Option("uncertainty", FLAG, "With --get: each result's standard uncertainty in a second column.", panel=FIND),
    Option("mc", COUNT, "Check the uncertainties by Monte Carlo with N draws.", panel=FIND, metavar="N"),
    Option("no_limit", FLAG, "Run --find or --mc however long it is estimated to take (else refused past 60 s).", panel=FIND),
)

# How to answer: read by the command line, not by the scene.
ANSWER = (
    Option("json", FLAG, "Print one strict JSON document on stdout.", panel=OUTPUT),
    Option("get", TEXT, "Print only this result's number (repeatable, one per line).", panel=OUTPUT, repeatable=True, metavar="NAME"),
    Option("to", TEXT, "Show a result in this unit, e.g. --to 'I=g*cm^2' (repeatable).", panel=OUTPUT, repeatable=True, metavar="NAME=UNIT"),
    Option("no_steps", FLAG, "Leave out the worked steps (the human view, and --json's steps list).", panel=OUTPUT),
    Option(
        "batch",
        FLAG,
        "Many scenes: read JSON lines on stdin, keys the option names (m1, pulley_mass), and write one --json document per line.",
        panel=OUTPUT,
    ),
    Option("jsonl", FLAG, "Like --json, but a sweep's documents one per line rather than one array.", panel=OUTPUT),
    Option(
        "format",
        CHOICE,
        "Write the answer as a document: md (GitHub Markdown), latex (siunitx units, the steps in align*), html (a fragment), "
        "or csv (a header with units, a row per point of a sweep).",
        panel=OUTPUT,
        choices=FORMATS,
        metavar="md|latex|html|csv",
    ),
    Option(
        "plot",
        FLAG,
        "Draw the motion against time (a list: one curve per value; a range: its chart), leaving out a sweep's table. With --json: the samples.",
        panel=SWEEP,
    ),
    Option("out", FILE, "Also draw the chart to FILE.svg or FILE.png (needs matplotlib: pip install 'taucli[plot]').", panel=SWEEP, metavar="FILE"),
    Option("points", COUNT, "Values in a range FROM..TO, ends included.", panel=SWEEP, default="50", metavar="N"),
    Option("y", TEXT, "A result to chart against a range (repeatable; default the scene's main result).", panel=SWEEP, repeatable=True, metavar="NAME"),
    *UNCERTAIN,
)


def point_option(what: str) -> Option:
    """--at r (#24): a point at this radius of the turning body (``what`` says which body and when)."""
    return Option("at", "length", f"A point at this radius {what}: its speed v_t, accelerations a_t, a_c, a_total, a_angle, arc s and chord (straight from its start), "
                  "e.g. 0.5m, or rim (the body's radius; taken when a point's result is asked for with no --at).", panel=MOTION, words=("rim",))


POINT_RESULTS = (  # taucli.scenes.point
    Result("v_t", "m/s", "speed of the point…"),
    Result("a_t", "m/s**2", "tangential acceleration…"),
    Result("a_c", "m/s**2", "centripetal acceleration…"),
    Result("a_total", "m/s**2", "total acceleration…"),
    Result("a_angle", "rad", "angle of a from the radius…"),
    Result("s", "m", "arc travelled…"),
    Result("chord", "m", "distance in a straight line from its start (net angle)…"),
    Result("v_t0", "m/s", "speed of the point at the start"),
    Result("a_c0", "m/s**2", "centripetal acceleration at the start"),
    Result("a_total0", "m/s**2", "total acceleration at the start"),
    Result("a_angle0", "rad", "angle of a from the radius at the start"),
)


# Contacts pressed against the body (#24, #35): spin-down and impulse. taucli.scenes.contact
BRAKE_OPTION = Option(
    "brake", BRAKE,
    'A brake shoe (or a tool) pressed against the body, e.g. "force=100N mu=0.4 radius=0.5m": torque μ·N·r, like --friction; '
    "mu-s= and mu-k= for static and kinetic μ; radius= defaults to the body's radius. On a lever (a block brake): "
    '"force=200N lever=1m pivot=0.4m offset=0.05m mu=0.3": force= at lever= from the lever\'s pivot, the shoe at pivot= from it, '
    "the friction's line at offset= from it (positive: self-energizing), N = F·lever/(pivot − μ·offset); "
    "shoe-angle= the arc 2θ of a long shoe, μ′ = 4μ·sin θ/(2θ + sin 2θ) in place of μ. Internal expanding shoes: "
    '"expanding=yes force=2.3kN mu=0.32 width=32mm radius=150mm hinge=123mm lever=212mm heel-angle=0deg shoe-angle=126deg": '
    "each shoe hinged on a pin hinge= from the drum's centre, pushed by force= (or pmax=, the largest lining pressure) at lever= from the pin, "
    "its lining width= wide from heel-angle= to heel-angle= + shoe-angle= (from the pin's line), p = p_a·sin θ/sin θ_a; "
    "shoes=both (default: one leading, one trailing, the same force), leading (self-energizing: the rim runs past it from its toe towards its pin) or trailing (repeatable).",
    repeatable=True, metavar='"force=… mu=… radius=…"', example="force=100N mu=0.4 radius=0.5m",
)
FACE_OPTION = Option(
    "face", FACE,
    'A flat face pressed on a surface, e.g. "mu=0.2" (the body lying on its face: its weight, its radii) or '
    '"mu=0.3 force=2kN inner-radius=5cm outer-radius=12cm model=uniform|wear surfaces=2" (a clutch plate); '
    "pmax= (the largest lining pressure) in place of force=; cone= the semi-cone angle of a cone clutch "
    '("mu=0.2 force=5kN inner-radius=170mm outer-radius=205mm cone=20deg": force= the axial force, the torque the flat face\'s over sin α) (repeatable).',
    repeatable=True, metavar='"mu=… [force=…]"', example="mu=0.3 force=2kN inner-radius=5cm outer-radius=12cm",
)
BAND_OPTION = Option(
    "band", BAND,
    'A band brake round the body, T₁/T₂ = e^(μθ), torque (T₁ − T₂)·r, e.g. "mu=0.25 wrap=270deg radius=0.3m tension=500N" '
    "(tension= pulls the slack end) or \"mu=0.25 wrap=270deg force=400N lever=750mm slack-arm=125mm\" "
    "(a lever: force= at lever= from its pivot, the slack end at slack-arm=, the tight end at tight-arm=; both: differential); "
    "width= for the lining pressure; the tight end is the one the drum drags the band towards; "
    '"… blocks=12 block-angle=15deg thickness=75mm" (in place of wrap=): a band-and-block brake, T₁/T₂ = ((1 + μ tan θ)/(1 − μ tan θ))ⁿ '
    "with 2θ each block's angle, torque (T₁ − T₂)·(r + thickness) (repeatable).",
    repeatable=True, metavar='"mu=… wrap=… tension=…|force=… lever=…"', example="mu=0.25 wrap=270deg radius=0.3m tension=500N",
)
BRAKE_EXPANDING = "{brake} 'expanding=yes force=2.3kN mu=0.32 width=32mm radius=150mm hinge=123mm lever=212mm heel-angle=0deg shoe-angle=126deg'"
CALIPER_OPTION = Option(
    "caliper", CALIPER,
    'A caliper disc brake: pads pressed on the disc, each with force=, torque n·μ·F·R_eff (n = surfaces=, 2 unless given: a pad each side), like --friction; '
    'an annular-sector pad "mu=0.37 force=3748lbf inner-radius=3.875in outer-radius=5.5in angle=108deg model=uniform|wear" '
    "(R_eff = (2/3)(Ro³ − Ri³)/(Ro² − Ri²) new, (Ro + Ri)/2 worn in; angle= only for the pad pressure), or a circular (button) pad "
    '"mu=0.31 force=500N pad=circular pad-radius=12mm centre-distance=50mm" (its radius and its centre\'s distance from the axis; '
    "R_eff = δ·e from the pressure integrated over the circle); mu-s= and mu-k= for static and kinetic μ (repeatable).",
    repeatable=True, metavar='"mu=… force=… inner-radius=… outer-radius=…|pad=circular pad-radius=… centre-distance=…"',
    example="mu=0.37 force=3748lbf inner-radius=3.875in outer-radius=5.5in angle=108deg model=wear",
)
CENTRIFUGAL_OPTION = Option(
    "centrifugal", CENTRIFUGAL,
    'A centrifugal clutch, read at ω₀ (the spider\'s speed), e.g. "shoes=4 mass=6kg radius=160mm spring-force=1450N mu=0.35 drum-radius=250mm": '
    "n shoes of mass= each, their centre of mass at radius= when they touch the drum, each pulled in there by its spring with spring-force=; "
    "μ between shoe and drum of inner radius drum-radius=. Engagement at ω_e = √(S/(m·r)); above it the clutch passes τ = n·μ·(m·ω₀²·r − S)·R, "
    "reported beside the motion, not applied to it (alone with --omega0: the clutch only).",
    metavar='"shoes=… mass=… radius=… spring-force=… mu=… drum-radius=…"',
    example="shoes=4 mass=6kg radius=160mm spring-force=1450N mu=0.35 drum-radius=250mm",
)
BRAKE_ON_A_LEVER = "{brake} 'force=200N lever=1m pivot=0.4m offset=0.05m mu=0.3 radius=0.5m'"  # the shoe's force then comes from the lever
CONTACT_RESULTS = (
    Result("torque_brake", "N*m", "friction torque of the brakes", needs=("brake",)),
    Result("work_brake", "J", "energy the brakes take…", needs=("brake",)),
    Result("power_brake", "W", "power the brakes take…", needs=("brake",)),
    Result("torque_face", "N*m", "friction torque of the faces", needs=("face",)),
    Result("work_face", "J", "energy the faces take…", needs=("face",)),
    Result("power_face", "W", "power the faces take…", needs=("face",)),
    Result("force_brake", "N", "normal force on the brake shoe, from its lever", needs=("brake",), example=BRAKE_ON_A_LEVER),
    Result("force_actuating", "N", "actuating force on each internal expanding shoe, (M_N ∓ M_f)/c", needs=("brake",), example=BRAKE_EXPANDING),
    Result("pressure_brake", "Pa", "largest lining pressure of the internal expanding shoes (on the leading one, where there is one)", needs=("brake",), example=BRAKE_EXPANDING),
    Result("force_face", "N", "clamp force on the face", needs=("face",)),
    Result("pressure_face", "Pa", "largest lining pressure of the face", needs=("face",)),
    Result("torque_band", "N*m", "friction torque of the band brakes", needs=("band",)),
    Result("work_band", "J", "energy the band brakes take…", needs=("band",)),
    Result("power_band", "W", "power the band brakes take…", needs=("band",)),
    Result("tension_tight", "N", "band tension at its tight end, T₁", needs=("band",)),
    Result("tension_slack", "N", "band tension at its slack end, T₂", needs=("band",)),
    Result("pressure_band", "Pa", "largest lining pressure under the band, T₁/(r·w)", needs=("band",),
           example="{band} 'mu=0.25 wrap=270deg radius=0.3m tension=500N width=5cm'"),
    Result("torque_caliper", "N*m", "friction torque of the caliper disc brakes", needs=("caliper",)),
    Result("work_caliper", "J", "energy the caliper brakes take…", needs=("caliper",)),
    Result("power_caliper", "W", "power the caliper brakes take…", needs=("caliper",)),
    Result("radius_effective", "m", "effective (friction) radius of the caliper's pads, τ = n·μ·F·R_eff", needs=("caliper",)),
    Result("pressure_caliper", "Pa", "largest pad pressure of the caliper", needs=("caliper",)),
    Result("omega_engage", "rad/s", "speed at which the centrifugal clutch engages", needs=("centrifugal",)),
    Result("torque_centrifugal", "N*m", "torque the centrifugal clutch passes at ω₀", needs=("centrifugal+omega0",)),
    Result("power_centrifugal", "W", "power the centrifugal clutch passes at ω₀", needs=("centrifugal+omega0",)),
)
