"""taucli fit: the inputs of a scene that make its results match measured samples.

Not a scene of its own: SCENE names one, and the words after the data files are that scene's
options, read by its own table (taucli.fit.command). This table holds what fit itself takes.
"""

from taucli.options import atwood, balance, drive, flywheel, gyro, impulse, inertia, pendulum, rolling, spin_down, torque
from taucli.options.common import ANSWER, OUTPUT
from taucli.options.table import CHOICE, FILE, FLAG, TEXT, Command, Option, Result

SCENE_NAMES = tuple(module.COMMAND.name for module in (inertia, spin_down, atwood, rolling, impulse, pendulum, torque, gyro, drive, flywheel, balance))
DATA = "Data"
SHOWN = ("json", "get", "to", "no_steps", "format")  # of the scenes' answer options: no sweep, batch, --find or --mc

COMMAND = Command(
    name="fit",
    summary="Fit inputs of a scene to measured samples (least squares): each ± its uncertainty, the fit's quality, and the scene at the fitted values.",
    description=(
        "SCENE's options follow the data files, as that scene takes them (--inertia '0.1 kg*m^2'); those named in --fit are "
        "fitted (a value given for one is its start), the others held, with their uncertainties if they carry any. Each row "
        "of a table is a sample: columns named like the scene's options are its inputs in that row (a time column, t or time, "
        "is --time), a column named like a result is what was measured; a header may carry its unit, as Time (s) or t [ms]. "
        "Comma, semicolon or tab separated, or an .xlsx workbook; several runs side by side, or several files, are fitted together (--per-run). Needs scipy: pip install 'taucli[fit]'. More, with worked examples: docs/fit.md "
        "in taucli's source."
    ),
    example="taucli fit spin-down coast.csv --inertia '0.1 kg*m^2' --fit friction,viscous,omega0",
    options=(
        Option("scene", CHOICE, "The scene whose inputs are fitted: " + ", ".join(SCENE_NAMES) + ".", choices=SCENE_NAMES, positional=True, metavar="SCENE"),
        Option(
            "data", FILE,
            "The measured samples: CSV files, .xlsx workbooks or phyphox's zip (- for stdin), then the scene's own options, as it takes them.",
            positional=True, repeatable=True, metavar="FILE... [SCENE OPTIONS]",
        ),
        Option("fit", TEXT, "The inputs to fit, by option name (friction,viscous), or a key of a spec as --find takes it (brake.mu); repeatable.",
               repeatable=True, metavar="NAME,NAME", panel=DATA),
        Option("x", TEXT, "A column that is an input of each sample, and which (default time), e.g. \"Time (s)\" or \"amplitude (deg)=angle0\" (repeatable).",
               repeatable=True, metavar="COLUMN[=OPTION]", panel=DATA),
        Option("y", TEXT, "The column that was measured, and the result it is, e.g. \"Gyroscope z (rad/s)=omega\".", metavar="COLUMN[=RESULT]", panel=DATA),
        Option("sigma", TEXT, "Each sample's standard uncertainty: a column, or one value for all, e.g. 0.05rad/s.", metavar="COLUMN|VALUE", panel=DATA),
        Option("range", TEXT, "Fit only the samples with a column in this window, e.g. t=2s..30s (repeatable).", repeatable=True, metavar="COLUMN=FROM..TO", panel=DATA),
        Option("per_run", TEXT, "Inputs of --fit fitted for each run on its own (each file, and each run side by side in one), e.g. omega0; "
               "the others are shared by all runs (repeatable).", repeatable=True, metavar="NAME,NAME", panel=DATA),
        Option("counts_per_rev", TEXT, "The measured column is an encoder's counts, this many a revolution (each interval read as a mean speed, omega), e.g. 360; with --counts.",
               metavar="N", panel=DATA),
        Option("counts", CHOICE, "An encoder's counts: cumulative (since the start) or interval (in each row's interval, since the row before).",
               choices=("cumulative", "interval"), panel=DATA),
        Option("bound", TEXT, "A range a fitted input is held within, e.g. 'viscous=0..0.01N*m*s' or g=9.5..10.1 (repeatable; either end may be "
               "left open). An input held fixed is not fitted: give it as the scene's option instead.", repeatable=True, metavar="NAME=FROM..TO", panel=DATA),
        Option("scale_covariance", FLAG, "With --sigma: scale the covariance by χ²/ν (lmfit's default), so the σ given weigh the samples "
               "and their scatter sets the uncertainties.", panel=DATA),
        Option("every", TEXT, "Use every Nth sample only (a long export), e.g. 10.", metavar="N", panel=DATA),
        Option("no_limit", FLAG, "Run the fit however long it is estimated to take (else refused past 60 s).", panel=DATA),
    ),
    results=(
        Result("correlation", None, "correlation of the fitted inputs (rows and columns in --fit's order)"),
        Result("residual_rms", None, "root mean square of the residuals (measured − fitted)"),
        Result("r2", "", "coefficient of determination R²"),
        Result("chi2_dof", "", "χ²/ν, with the uncertainties given (near 1 for a model that fits)"),
        Result("samples", "", "samples fitted"),
        Result("dropped", "", "samples left out (outside --range, or between --every)"),
    ),
    output=(
        *(option for option in ANSWER if option.name in SHOWN),
        Option("uncertainty", FLAG, "With --get: each result's standard uncertainty in a second column.", panel=OUTPUT),
        Option("plot", FLAG, "Draw the data, the fit with its ±1σ band and the residuals in the terminal (with --sigma, each sample's error bar). "
               "With --json: the samples.", panel=OUTPUT),
        Option("out", FILE, "Also draw them to FILE.svg or FILE.png (needs matplotlib: pip install 'taucli[plot]').", panel=OUTPUT, metavar="FILE"),
        Option("residuals", FILE, "Also write each sample to FILE.csv: its inputs, measured, fitted, residual (measured − fitted) and σ, in SI "
               "with the units in the header.", panel=OUTPUT, metavar="FILE"),
    ),
    handler="taucli.fit:run",
)
