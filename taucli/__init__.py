"""taucli: rigid-body rotation about a fixed axis, tau_net = I alpha, at the terminal and in Python.

One function per scene, named like its command, its keywords the batch keys, its values unit
texts or SI numbers; each returns the Report the command line renders:

    >>> import taucli
    >>> taucli.atwood(m1="4 kg", m2=1, pulley_mass="2 kg").results["a"].value
    4.9033...

A value the scene cannot use raises taucli.InputError (a ValueError) naming the parameter.
"""

from __future__ import annotations

__version__ = "0.1.0"

from taucli.errors import InputError  # noqa: E402
from taucli.report import Report  # noqa: E402

__all__ = ["InputError", "Report", "atwood", "impulse", "inertia", "rolling", "spin_down"]
__all__ += ["pendulum"]


def __getattr__(name: str):
    """taucli.atwood and the other scenes, made from their tables when first asked for."""
    if name not in __all__:  # a submodule not imported yet, or no such name
        raise AttributeError(f"module 'taucli' has no attribute {name!r}")
    import importlib

    found = importlib.import_module("taucli.api").function(name)
    if found is None:
        raise AttributeError(f"module 'taucli' has no attribute {name!r}")
    globals()[name] = found
    return found


def __dir__() -> list[str]:
    return sorted({*globals(), *__all__})
