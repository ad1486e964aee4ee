"""taucli torque: torque τ = r × F and angular momentum L = r × p as vectors about a point."""

from taucli.options.common import ANSWER, GRAVITY_FOR_WEIGHTS
from taucli.options.table import VECTOR, Command, Option, Result

FORCES = "Forces (τ = r × F)"
PARTICLES = "Particles (L = r × p)"
A_PARTICLE = ("mass+velocity", "momentum")  # what makes L = r × p (#42 item 18)

COMMAND = Command(
    name="torque",
    summary="Torque τ = r × F and angular momentum L = r × mv about a point, as vectors; or a force at a lever arm in the plane.",
    description=(
        "Give each force as a vector with its point of application (--r then --force, repeated in pairs), "
        "or in the plane as a size with --lever and --angle (positive counter-clockwise). "
        "A particle is --r, --mass and --velocity, repeated in triples, or --r and --momentum in pairs. Where forces and particles share a run, "
        "the --r values go to the forces first, then to the particles (or, one each, to both). "
        "--about moves the point the torques and angular momenta are taken about: --r is then measured from the origin."
    ),
    example='taucli torque --r "0.3,0.4,0 m" --force "0,0,10 N"',
    options=(
        Option("r", VECTOR, 'Position from the point (or from the origin, with --about) to where the force acts (or of the particle), e.g. "0.3,0.4,0 m" (repeatable).',
               repeatable=True, of="length", metavar='"X,Y,Z UNIT"', sign="any"),
        Option("force", VECTOR, 'A force as a vector, e.g. "0,0,10 N"; or a size, e.g. 20N, with --lever and --angle (repeatable).',
               repeatable=True, of="force", metavar='"X,Y,Z UNIT"', sign="any", panel=FORCES),
        Option("lever", "length", "The distance from the axis to where a planar force acts (repeatable, one for each force given as a size).",
               repeatable=True, panel=FORCES),
        Option("angle", "angle", "The angle from the lever (r) to the force, counter-clockwise positive (repeatable).",
               sign="any", repeatable=True, default="90deg", panel=FORCES),
        Option("mass", "mass", "A particle's mass (repeatable, one for each --velocity).", repeatable=True, panel=PARTICLES),
        Option("velocity", VECTOR, 'A particle\'s velocity, e.g. "0,2,0 m/s" (repeatable).',
               repeatable=True, of="velocity", metavar='"X,Y,Z UNIT"', sign="any", panel=PARTICLES, example="0,2,0 m/s"),
        Option("momentum", VECTOR, 'A particle\'s momentum p, instead of --mass and --velocity, e.g. "2,0,0 kg*m/s" (repeatable).',
               repeatable=True, of="momentum", metavar='"X,Y,Z UNIT"', sign="any", panel=PARTICLES, example="2,0,0 kg*m/s"),
        Option("about", VECTOR, 'The point the torques and angular momenta are about, from the origin --r is measured from, e.g. "1,0,0 m" (default the origin).',
               of="length", metavar='"X,Y,Z UNIT"', sign="any"),
        GRAVITY_FOR_WEIGHTS,
    ),
    results=(
        Result("tau_x", "N*m", "torque, x component…"),
        Result("tau_y", "N*m", "torque, y component…"),
        Result("tau_z", "N*m", "torque, z component…"),
        Result("tau", "N*m", "size of the torque…"),
        Result("sense", None, "sense of the torque, seen from the tip of its axis"),
        Result("lever_arm", "m", "lever arm r⊥…"),
        Result("L_x", "kg*m**2/s", "angular momentum, x component…", needs=A_PARTICLE),
        Result("L_y", "kg*m**2/s", "angular momentum, y component…", needs=A_PARTICLE),
        Result("L_z", "kg*m**2/s", "angular momentum, z component…", needs=A_PARTICLE),
        Result("L", "kg*m**2/s", "size of the angular momentum…", needs=A_PARTICLE),
        Result("L_sense", None, "sense of the angular momentum, seen from the tip of its axis", needs=A_PARTICLE),
    ),
    output=ANSWER,
    headline="tau",
    library="taucli.scenes.torque:torque",
)
