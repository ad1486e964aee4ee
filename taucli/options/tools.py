"""The commands that are not scenes: taucli bench, taucli completions and taucli convert."""

from taucli.core.names import BENCH_SCENES, SHELLS
from taucli.options.table import CHOICE, FILE, FLAG, TEXT, Command, Option

BENCH = Command(
    name="bench",
    summary="Speed against accuracy: time per solve and error of every method, charted (log-log).",
    description=(
        "Each point is one method at one step, tolerance or sample count on a fixed problem (the "
        "article's potter's wheel, a friction + viscous + drag coast, a power-law drag, a stiff brake, "
        "a half-sine torque pulse), its error against a 50-digit reference. '!' marks a run that "
        "diverged. scipy's solve_ivp is charted too when scipy is installed."
    ),
    example="taucli bench --quick",
    options=(
        Option("scene", CHOICE, " or ".join(BENCH_SCENES) + " (repeatable; default all " + str(len(BENCH_SCENES)) + ").", choices=BENCH_SCENES, repeatable=True, metavar="SCENE"),
        Option("quick", FLAG, "Fewer settings and repeats: a few seconds."),
        Option("out", FILE, "Also draw the charts to FILE.svg or FILE.png (needs matplotlib).", metavar="FILE"),
        Option("json", FLAG, "Print one strict JSON document on stdout."),
    ),
    handler="taucli.front.tools:bench",
)

COMPLETIONS = Command(
    name="completions",
    summary="Print the completion script for SHELL: commands, options, shapes, methods, and units after a number.",
    description="The scripts are static: pressing TAB never starts Python. For bash, save it and source it from ~/.bashrc (source ~/.taucli.bash); docs/shell.md says where zsh's and fish's go.",
    example="taucli completions bash > ~/.taucli.bash",
    options=(Option("shell", CHOICE, "bash, zsh or fish.", choices=SHELLS, positional=True, metavar="SHELL"),),
    handler="taucli.front.tools:completions",
)

CONVERT_RESULTS = ("value", "uncertainty", "unit", "kind", "si_value", "si_uncertainty", "si_unit")

CONVERT = Command(
    name="convert",
    summary="A quantity in another unit: QUANTITY read as every option reads it, written in UNIT (else SI).",
    description=(
        "QUANTITY is a number and its unit, as any option takes it ('3000 rpm', '2 lb*ft^2', '0.01 N*m/Hz'), "
        "with the same notes where the reading is not plain (Hz is revolutions per second, lb in an inertia "
        "a pound of mass). Its kind comes from its unit: mass, length, angle, time, angular velocity and "
        "acceleration, torque, moment of inertia, force, acceleration, velocity, momentum, viscous and drag "
        "coefficients, power, energy, density (and per area, per length), pressure, stress, torsion constant, "
        "lead. A unit that fits two kinds is read as the plainer (N*m: a torque; mm: a length)."
    ),
    example="taucli convert '3000 rpm' rad/s",
    options=(
        Option("quantity", TEXT, "A number and its unit: '3000 rpm', '2 lb*ft^2' (quoted where it holds * ^ or a space; a negative one after --: "
               "taucli convert -- '-40 N*m' 'lbf*ft').", positional=True, metavar="QUANTITY"),
        Option("unit", TEXT, "The unit to write it in.", default="the SI unit of its kind", positional=True, metavar="UNIT"),
        Option("json", FLAG, "Print one strict JSON document on stdout."),
        Option("get", CHOICE, "Print only this, bare (repeatable): " + ", ".join(CONVERT_RESULTS) + "; notes go to stderr.", choices=CONVERT_RESULTS,
               repeatable=True, metavar="NAME"),
    ),
    handler="taucli.front.tools:convert",
)

EXIT_STATUSES = (
    "Exit status: 0 success; 1 internal error (a bug in taucli: please report it, and --debug shows "
    "the traceback); 2 bad input (one line on stderr names the option); 130 interrupted (Ctrl-C)."
)

ROOT = Command(
    name="taucli",
    summary="Rigid-body rotation about a fixed axis: τ_net = Iα and what follows from it.",
    description="Quantities take units: 4kg, 300rpm, '0.3 N*m', 30deg. A bare number is SI, except for an angle, an angular velocity or an angular acceleration, which need their unit.",
    example="taucli atwood --m1 4kg --m2 1kg --pulley-mass 2kg",
    options=(
        Option("version", FLAG, "Print the version and exit."),
        Option("debug", FLAG, "On an internal error (exit 1), print the traceback (or set TAUCLI_DEBUG=1)."),
    ),
)
