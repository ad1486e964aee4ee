"""``taucli fit SCENE FILE…``: the inputs of a scene that make its results match measured samples.

One module per job: reading the tables (``data``), matching their columns to the scene
(``samples``), the model (``model``: the scene solved for each sample), the start (``start``), the
linear fit (``linear``), the nonlinear fit (``nonlinear``), the covariance and the diagnostics
(``quality``), the order of a fit (``solve``), the report (``results``), the chart (``chart``) and
the command line (``command``). numpy and scipy are imported by those modules alone, and this
package is imported only by ``taucli fit``: the other commands start as fast as before.

    taucli.fit.fit("spin-down", "coast.csv", fit="friction,viscous", inertia="0.1 kg*m^2")

returns the Report the command line renders.

May import: every layer below the front ends (core, numerics, quantities, writing, options,
scenes, answering).
"""

from __future__ import annotations

import importlib.util

from taucli.core.errors import InputError

EXTRA = "pip install 'taucli[fit]' (from a checkout: pip install '.[fit]')"


def _installed(name: str) -> bool:
    try:
        return importlib.util.find_spec(name) is not None
    except (ImportError, ValueError):  # a module blocked or half imported (sys.modules[name] is None)
        return False


def _needs_scipy() -> None:
    """A usage error naming the extra to install where numpy or scipy is missing or does not import."""
    missing = [name for name in ("numpy", "scipy") if not _installed(name)]
    if missing:
        raise InputError("", f"taucli fit needs {' and '.join(missing)} (not installed)", hint=EXTRA)
    try:
        import numpy  # noqa: F401  # deferred: numpy, only for taucli fit
        import scipy  # noqa: F401  # deferred: scipy's package alone (its optimize, ~200 ms, where a nonlinear fit needs it)
    except ImportError as err:  # installed, and broken (a numpy built for another Python, a partial install)
        raise InputError("", f"taucli fit needs numpy and scipy, and they do not import ({str(err).splitlines()[0][:120]})",
                         hint=EXTRA.replace("pip install", "pip install --force-reinstall")) from None


def run(*, env, **given) -> int:
    """The command line's taucli fit: see taucli.fit.command."""
    _needs_scipy()
    from taucli.fit import command  # deferred: numpy and scipy with it, only for taucli fit

    return command.run(env, given)


def fit(scene: str, *data: str, fit: str, x=(), y: str | None = None, sigma: str | None = None, range=(), every=None, stdin=None, **options):
    """The fit's Report: ``scene``'s inputs named in ``fit`` ("friction,viscous") fitted to the
    tables ``data`` (file names), the scene's other options as keywords (texts with units, or SI)."""
    _needs_scipy()
    from taucli.fit import command  # deferred: numpy and scipy with it, only for a fit

    return command.fitted(scene, list(data), options, fit=fit, x=tuple(x) if not isinstance(x, str) else (x,), y=y, sigma=sigma,
                          ranges=tuple(range) if not isinstance(range, str) else (range,), every=every, stdin=stdin, spell=lambda name: name)
