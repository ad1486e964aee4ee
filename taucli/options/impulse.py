"""taucli impulse: angular impulse and momentum, τΔt = IΔω."""

from taucli.core.names import QUADRATURE_NAMES
from taucli.options.common import ANSWER, BAND_OPTION, BODY_OPTIONS, BRAKE_OPTION, CALIPER_OPTION, CENTRIFUGAL_OPTION, CONTACT_RESULTS, FACE_OPTION, GRAVITY, POINT_RESULTS, PUSH, point_option
from taucli.options.table import CHOICE, COUPLE, FILE, PART, PARTICLE, Command, Option, Result

MEETS = "Particles and bodies that meet it (L conserved)"

# What makes the results the docs example (a torque for a time) does not (#42 item 18): a contact that takes
# energy, a particle or body that meets it, a clutch, a particle striking a body whose mass and centre are known.
CONTACTS = ("brake", "face", "band", "caliper")
MEETINGS = ("particle", "couple")
CLUTCH = "{couple} 'inertia=3kg*m^2 torque=50N*m'"
STRUCK_SHAPE = ("particle+shape",)
STRUCK_SHAPE_EXAMPLE = "{particle} 'mass=0.4kg speed=20m/s radius=0.6m' {shape} disc {mass} 2kg {radius} 0.5m"

COMMAND = Command(
    name="impulse",
    summary="Angular impulse: τΔt = IΔω, any four of I, ω₀, ω₁, τ, Δt giving the fifth; or L₀, L₁, J given as such; or I that changes.",
    example="taucli impulse --inertia '0.1kg*m^2' --omega0 0 --torque '2N*m' --duration 0.5s",
    options=(
        *BODY_OPTIONS,
        Option("omega0", "angular velocity", "Angular velocity before.", sign="any"),
        Option("omega1", "angular velocity", "Angular velocity after.", sign="any"),
        Option("momentum0", "angular momentum", "Angular momentum before, L₀ = Iω₀, given as such, e.g. '2.4kg*m^2/s' (needs no I or ω).", sign="any"),
        Option("momentum1", "angular momentum", "Angular momentum after, L₁, given as such, e.g. '3.6kg*m^2/s'.", sign="any"),
        Option("impulse", "angular momentum", "Angular impulse J = ΔL = ∫τ dt given as such (the area under a torque–time graph), e.g. '1.8N*m*s'.",
               sign="any", metavar="J"),
        Option("torque", "torque", "Constant torque while it acts; or a formula of the time t (J = ∫τ dt over --duration), e.g. '(10 N*m/s)*t'.",
               sign="any", of_time=True),
        *PUSH,
        Option("duration", "time", "How long the torque acts."),
        BRAKE_OPTION,
        FACE_OPTION,
        BAND_OPTION,
        CALIPER_OPTION,
        CENTRIFUGAL_OPTION,
        GRAVITY,
        Option("inertia_final", "moment of inertia", "Inertia after a change with no torque (the skater).", metavar="I"),
        Option("part_after", PART, 'The body after a change with no torque, by parts, in place of --part (the body\'s --shape or --inertia stays), '
               'e.g. --part-after "point mass=25kg offset=0.5m" (repeatable).', repeatable=True, metavar='"SHAPE key=value ..."'),
        Option("torque_profile", FILE, "CSV: a header ('t [ms], torque [N*m]'; tab, ; or , as fit reads), then rows; - for stdin.", metavar="FILE",
               example="torque.csv"),
        Option("particle", PARTICLE,
               'A particle that meets the body, e.g. "mass=30kg speed=4m/s radius=2m": speed signed (positive in the body\'s sense), '
               "radius the distance of its line from the axis (or with angle=, to where it meets the body, angle= between velocity and radius); "
               "it sticks, or leaves with speed-after= (negative: it rebounds), or rebounds with e= (restitution); "
               "no speed=: it rides on the body, radius-after= where it moves to; speed-relative= its speed along the rim after, relative to the body "
               '(a toy train on a free wheel, a person walking on a turntable: "mass=55kg radius=3.25m speed-relative=3.8m/s") (repeatable).',
               repeatable=True, metavar='"mass=… speed=… radius=…"', panel=MEETS, example="mass=0.4kg speed=20m/s radius=0.6m"),
        Option("couple", COUPLE, 'Another body on the same axis that locks to it, e.g. "inertia=3kg*m^2 omega0=0" or "disc mass=2kg radius=0.1m omega0=100rpm" '
               '(repeatable); with torque=, through a clutch that slips passing that torque until the speeds meet, e.g. "inertia=3kg*m^2 torque=50N*m".',
               repeatable=True, metavar='"inertia=… omega0=…"', panel=MEETS, example="inertia=3kg*m^2 omega0=0"),
        Option("method", CHOICE, "Quadrature for a profile: " + " | ".join(QUADRATURE_NAMES) + ".", choices=QUADRATURE_NAMES, default="auto", metavar="METHOD"),
        point_option("(at the start, and at the end of the impulse)"),
    ),
    results=(
        Result("J", "N*m*s", "angular impulse…"),
        Result("delta_omega", "rad/s", "change of angular velocity"),
        Result("inertia", "kg*m**2", "moment of inertia…"),
        Result("omega0", "rad/s", "angular velocity before…"),
        Result("omega1", "rad/s", "angular velocity after…"),
        Result("torque", "N*m", "constant torque…"),
        Result("duration", "s", "time…"),
        Result("L0", "kg*m**2/s", "angular momentum before"),
        Result("L1", "kg*m**2/s", "angular momentum after…"),
        Result("KE0", "J", "rotational kinetic energy before…"),
        Result("KE1", "J", "rotational kinetic energy after…"),
        Result("work", "J", "work the body does on itself (KE1 − KE0)", needs=("inertia_final", "part_after", *CONTACTS), example="{inertia_final} '0.05 kg*m^2'"),
        Result("peak_torque", "N*m", "largest torque…", needs=("torque_profile",)),
        Result("KE_lost", "J", "kinetic energy lost (KE0 − KE1)…", needs=MEETINGS),
        Result("KE_lost_fraction", "", "fraction of the kinetic energy lost", needs=MEETINGS),
        Result("J_net", "N*m*s", "net angular impulse, drive and friction (IΔω)", needs=CONTACTS),
        Result("t_slip", "s", "time the clutch slips", needs=("couple",), example=CLUTCH),
        Result("heat", "J", "energy the clutch turns to heat", needs=("couple",), example=CLUTCH),
        Result("period", "s", "period of a turn after, 2π/|ω₁|"),
        Result("omega_impact", "rad/s", "angular velocity just after the collision…", needs=("particle+torque+duration", "couple+torque+duration")),
        Result("p0", "kg*m/s", "linear momentum of the system before, across the radius to the particle", needs=STRUCK_SHAPE, example=STRUCK_SHAPE_EXAMPLE),
        Result("p1", "kg*m/s", "linear momentum of the system after, across the radius to the particle", needs=STRUCK_SHAPE, example=STRUCK_SHAPE_EXAMPLE),
        Result("pivot_impulse", "N*s", "impulse of the pivot (axle) on the system, p1 − p0", needs=STRUCK_SHAPE, example=STRUCK_SHAPE_EXAMPLE),
        Result("speed_after", "m/s", "speed of the particle after…", needs=("particle",), example="{particle} 'mass=0.4kg speed=20m/s radius=0.6m e=0.5'"),
        *CONTACT_RESULTS,
        *POINT_RESULTS,
    ),
    output=ANSWER,
    headline="omega1",
    library="taucli.scenes.impulse:impulse",
)
