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
import os

from taucli.answering.python import plain
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


def fit(scene: str, *data, fit, x=(), y: str | None = None, sigma: str | None = None, range=(), every=None, per_run=(), counts_per_rev=None, counts=None,
        stdin=None, scale_covariance: bool = False, bound=(), **options):
    """The fit's Report: ``scene``'s inputs named in ``fit`` ("friction,viscous") fitted to the
    tables ``data`` (file names, pathlib.Path, or open file objects), the scene's other options as
    keywords (texts with units, or SI numbers; numpy numbers too); ``scale_covariance=True`` with
    ``sigma`` scales the covariance by χ²/ν; ``bound="viscous=0..0.01N*m*s"`` (or a list) holds a
    fitted input within a range. Every bad argument raises InputError naming it."""
    _needs_scipy()
    from taucli.fit import command  # deferred: numpy and scipy with it, only for a fit

    if not isinstance(scene, str):
        raise InputError("scene", "expected a scene's name, a text", example='taucli.fit.fit("spin-down", "coast.csv", fit="friction")', got=_shown(scene))
    sources = [_source(item) for item in data]
    if not sources:
        raise InputError("data", "expected a data file (CSV) after the scene: a path, or an open file", example='taucli.fit.fit("spin-down", "coast.csv", fit="friction")')
    if stdin is not None and not callable(getattr(stdin, "read", None)):
        raise InputError("stdin", "expected a file object to read - from (or None)", got=_shown(stdin))
    every = _whole(every)
    options = {name.replace("-", "_"): plain(value, name) for name, value in options.items()}
    return command.fitted(scene, sources, options, fit=_texts(fit, "fit", "friction,viscous", alone=True), x=_texts(x, "x", "t (s)=time"),
                          y=_text(y, "y", "omega (rad/s)=omega"), sigma=_text(sigma, "sigma", "0.05 rad/s"),
                          ranges=_texts(range, "range", "time=0..10s"), every=every, per_run=_texts(per_run, "per_run", "omega0"),
                          counts_per_rev=_count(counts_per_rev), counts=_text(counts, "counts", "cumulative"), stdin=stdin,
                          spell=lambda name: name, scale_covariance=_flag(scale_covariance, "scale_covariance"), bounds=_texts(bound, "bound", "viscous=0..0.01N*m*s"))


def _count(value):
    """counts_per_rev=: a number or its text (taucli.fit.encoder reads it)."""
    if value is None or isinstance(value, str):
        return value
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return repr(value)
    raise InputError("counts_per_rev", "expected the encoder's counts in a revolution, a whole number", example="counts_per_rev=360", got=_shown(value))


def _flag(value, name: str) -> bool:
    if isinstance(value, bool):
        return value
    raise InputError(name, "expected True or False", example=f"{name}=True", got=_shown(value))


def _shown(value) -> str:
    text = repr(value) if not isinstance(value, int) or value.bit_length() < 200 else f"a whole number of {value.bit_length()} bits"
    return f"{text[:60]} ({type(value).__name__})"


def _source(item):
    """A data file as fit reads it: a path's text, or an open file object (text or bytes)."""
    if isinstance(item, str):
        return item
    if isinstance(item, os.PathLike):
        path = os.fspath(item)
        if isinstance(path, str):
            return path
    elif callable(getattr(item, "read", None)):
        return item
    raise InputError("data", "expected a file's path (a text or a pathlib.Path) or an open file", example='taucli.fit.fit("spin-down", "coast.csv", fit="friction")',
                     got=_shown(item))


def _text(value, name: str, example: str):
    if value is None or isinstance(value, str):
        return value
    raise InputError(name, "expected a text (a column, or a value with its unit)" if name == "sigma" else "expected a text", example=f'{name}="{example}"', got=_shown(value))


def _texts(value, name: str, example: str, *, alone: bool = False):
    """A text, or a list or tuple of texts (x=, range=; fit= as one text or a list)."""
    if isinstance(value, str):
        return value if alone else (value,)
    if value is None and not alone:
        return ()
    if isinstance(value, (list, tuple)) and value and all(isinstance(item, str) for item in value):
        return ",".join(value) if alone else tuple(value)
    if isinstance(value, (list, tuple)) and not value and not alone:
        return ()
    raise InputError(name, "expected a text or a list of texts", example=f'{name}="{example}"', got=_shown(value))


def _whole(every):
    """every=: a whole number (or its text), bounded before any text of it is made."""
    if every is None or isinstance(every, str):
        return every
    every = plain(every, "every")
    if isinstance(every, int) and not isinstance(every, bool) and every.bit_length() <= 64:
        return str(every)
    raise InputError("every", "expected a whole number of 1 or more", example="every=10", got=_shown(every))
