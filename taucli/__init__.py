"""taucli: rigid-body rotation about a fixed axis, tau_net = I alpha, at the terminal and in Python.

One function per scene, named like its command, its keywords the batch keys, its values unit
texts or SI numbers; each returns the Report the command line renders:

    >>> import taucli
    >>> taucli.atwood(m1="4 kg", m2=1, pulley_mass="2 kg").results["a"].value
    4.9033...

A value the scene cannot use raises taucli.InputError (a ValueError) naming the parameter; a
result the run did not make, taucli.MissingResult (a KeyError) naming what makes it.
taucli.convert("3000 rpm", "rad/s") reads a quantity as the options do and writes it in a unit.
A list of values for one keyword gives a taucli.Sweep, the reports in order (.to_pandas() where
pandas is installed); report.plot() draws the motion in time as a matplotlib Figure.
"""

from __future__ import annotations

from taucli.core.errors import InputError
from taucli.options import SCENES  # plain data: no solver, typer, rich or pint
from taucli.writing.report import Report
from taucli.writing.swept import Sweep
from taucli.options.table import MissingResult
from taucli.core.version import __version__ as __version__  # taucli.__version__

__all__ = ["InputError", "MissingResult", "Report", "Sweep", "convert", *(command.function_name for command in SCENES.values())]


def __getattr__(name: str):
    """taucli.atwood and the other scenes, made from their tables when first asked for."""
    if name not in __all__:  # a submodule not imported yet, or no such name
        raise AttributeError(f"module 'taucli' has no attribute {name!r}")
    if name == "convert":
        from taucli.front.api import convert  # deferred: pint, only when converting

        globals()[name] = convert
        return convert
    from taucli.front import api  # deferred: the API's functions are made on first use, not by a plain import

    found = api.function(name)
    if found is None:
        raise AttributeError(f"module 'taucli' has no attribute {name!r}")
    globals()[name] = found
    return found


def __dir__() -> list[str]:
    return sorted({*globals(), *__all__})
