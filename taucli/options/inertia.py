"""taucli inertia: the moment of inertia of a shape, shifted, or of a body of several parts."""

from dataclasses import replace

from taucli.options.common import ANSWER, AXIS, BODY, DENSITY, DIMENSIONS, GRAVITY_FOR_WEIGHTS, GYRATION, MASS, OFFSET, PARTS, SHAPE_WORDS
from taucli.options.table import CHOICE, Command, Option, Result
from taucli.core.names import SHAPE_NAMES

COMMAND = Command(
    name="inertia",
    summary="Moment of inertia of a standard shape: shifted (--offset), or a body of several parts.",
    example="taucli inertia disc --mass 5kg --radius 0.2m",
    options=(
        Option("shape", CHOICE, f"One of: {SHAPE_WORDS} (none with --gyration).", choices=SHAPE_NAMES, positional=True, metavar="SHAPE"),
        MASS,
        DENSITY,
        GYRATION,
        *DIMENSIONS,
        AXIS,
        OFFSET,
        replace(PARTS, help=PARTS.help.replace(" (repeatable)", "; angle= where its centre lies round the axis, for --body-offset (repeatable)")),
        Option("body_offset", "length", "Distance from the body's centre of mass to the parallel axis it turns about: I = I_cm + Md² on the "
               "total mass, I_cm from the parts where they lie (two or more off the axis: each with angle=; --offset moves the shape alone).",
               sign="nonnegative", panel=BODY),
        GRAVITY_FOR_WEIGHTS,
    ),
    results=(
        Result("I", "kg*m**2", "moment of inertia about the rotation axis"),
        Result("k", "m", "radius of gyration, √(I/M)"),
        Result("I_cm", "kg*m**2", "moment of inertia about the parallel axis through the centre of mass", needs=("offset", "body_offset")),
        Result("mass", "kg", "total mass", needs=("part", "density")),
    ),
    output=ANSWER,
    headline="I",
    library="taucli.scenes.inertia:inertia",
)
