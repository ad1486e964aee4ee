"""Every command's one table, in the order ``taucli --help`` lists them.

The scenes' tables (one module each) and the tools'. Plain data: importing this module loads
no solver, no typer, no rich and no pint, so ``--help`` and completion can read it at once.
The vocabulary of a table (Command, Option, Result, Results) is ``taucli.options.table``.

May import: taucli.core, taucli.writing.report (a result's Value); never a solver.
"""

from taucli.options import atwood, balance, drive, fit, flywheel, gyro, impulse, inertia, pendulum, rolling, spin_down, tools, torque
from taucli.options.table import Command

SCENES: dict[str, Command] = {
    module.COMMAND.name: module.COMMAND for module in (inertia, spin_down, atwood, rolling, impulse, pendulum, torque, gyro, drive, flywheel, balance)
}
COMMANDS: dict[str, Command] = {**SCENES, "fit": fit.COMMAND, "bench": tools.BENCH, "completions": tools.COMPLETIONS, "convert": tools.CONVERT}


def scene(name: str) -> Command:
    """The table of scene ``name`` ("spin-down" or "spin_down")."""
    return SCENES[name.replace("_", "-")]
