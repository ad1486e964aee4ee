"""taucli gyro: a spinning top or gyroscope on a pivot, and the precession of its axis."""

from taucli.options.common import ANSWER, BODY, BODY_OPTIONS, GRAVITY
from taucli.table import Command, Option, Result

PIVOT = "Pivot and torque"

COMMAND = Command(
    name="gyro",
    summary="A spinning top or gyroscope on a pivot: its precession, Ω = mgr/(Iω_s), and the exact steady rates.",
    description=(
        "The body spins at --spin about its symmetry axis (--inertia about that axis, or --shape with its "
        "dimensions), its centre of mass --cm-distance from the pivot, the axis at --tilt from the upward "
        "vertical. The weight's torque turns the angular momentum, not the body: the axis precesses. "
        "--inertia-perp (taken from the shape where one is given) adds the exact steady precession rates, "
        "the roots of I⊥Ω²cos θ − Iω_sΩ + mgr = 0."
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
        GRAVITY,
    ),
    results=(
        Result("L", "kg*m**2/s", "spin angular momentum Iω_s"),
        Result("omega_p", "rad/s", "precession rate…"),
        Result("period_p", "s", "precession period…"),
        Result("omega_p_slow", "rad/s", "slow steady precession (exact)"),
        Result("omega_p_fast", "rad/s", "fast steady precession (exact)"),
        Result("spin_min", "rad/s", "least spin for a steady precession"),
    ),
    output=ANSWER,
    headline="omega_p",
    library="taucli.scenes.gyro:gyro",
)
