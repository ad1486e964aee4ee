"""``taucli fit SCENE FILE…``: the inputs of a scene that make its results match measured samples.

One module per job: reading the tables (``data``), matching their columns to the scene
(``samples``), the model (``model``: the scene solved for each sample), the start (``start``), the
linear fit (``linear``), the nonlinear fit (``nonlinear``), the covariance and the diagnostics
(``quality``), the order of a fit (``solve``), the report (``results``), the chart (``chart``) and
the command line (``command``). numpy and scipy are imported by those modules alone, and this
package is imported only by ``taucli fit``: the other commands start as fast as before.

    taucli.fit.fit("spin-down", "coast.csv", fit="friction,viscous", inertia="0.1 kg*m^2")

returns the Report the command line renders.
"""

from __future__ import annotations

import importlib.util

from taucli.errors import InputError

EXTRA = "pip install 'taucli[fit]'"


def _needs_scipy() -> None:
    missing = [name for name in ("numpy", "scipy") if importlib.util.find_spec(name) is None]
    if missing:
        raise InputError("", f"taucli fit needs {' and '.join(missing)} (not installed)", hint=EXTRA)


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
