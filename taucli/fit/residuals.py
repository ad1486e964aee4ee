"""``--residuals FILE.csv``: each sample of a fit as a row of a spreadsheet, to look at or plot where
the report's numbers came from.

A row per sample, in the order fitted: the file and line it was read from, its inputs (each column
matched to an option: the time of a time series), the result measured yᵢ, the model at the fitted
inputs f(xᵢ; p), the residual rᵢ = yᵢ − f(xᵢ; p), and the sample's standard uncertainty σᵢ where one
was given (--sigma; the cell is empty where none was). Every number in SI, the unit in its column's
heading and at full precision (a double's repr, read back exactly), as --format csv writes
(taucli.writing.formats.csv_grid: a text that a spreadsheet would take for a formula, a file
named =x.csv, is written after a quote).
"""

from __future__ import annotations

import os

import numpy as np

from taucli.core.errors import InputError
from taucli.core.written import printable
from taucli.quantities import units
from taucli.fit.solve import Fit
from taucli.writing import files, formats

EXAMPLE = "--residuals residuals.csv"


def grid(found: Fit) -> formats.Grid:
    """The samples as a table: file, line, inputs, measured, fitted, residual, σ."""
    model = found.model
    samples = model.samples
    y = np.asarray(samples.y, dtype=float)
    fitted = model.predict(found.p)
    residual = y - fitted
    sigma = samples.sigma if samples.sigma is not None else [None] * samples.count
    names = list(samples.inputs)
    input_units = [units.KINDS[model.command.option(name).kind].si_unit for name in names]
    unit = samples.y_unit
    columns = (("file", None), ("line", None), *zip(names, input_units),
               (f"{samples.y_key} measured", unit), (f"{samples.y_key} fitted", unit), ("residual", unit), ("sigma", unit))
    rows = tuple(
        (source, line, *(float(samples.inputs[name][i]) for name in names), float(y[i]), _finite(fitted[i]), _finite(residual[i]),
         None if sigma[i] is None else float(sigma[i]))
        for i, (source, line) in enumerate(samples.places)
    )
    return formats.Grid(f"fit: {model.command.name}, the samples", found.method, columns, rows, ())


def _finite(x) -> float | None:
    x = float(x)
    return x if np.isfinite(x) else None  # (a sample the scene gives no value for: an empty cell)


def check(path: str, data: list = ()) -> None:
    """Before the fit: a .csv file that can be written (taucli.writing.files), and none of the
    fit's own data files (``data``: the files given), which it would overwrite."""
    files.check(path, "--residuals", (".csv",), EXAMPLE)
    for source in data:
        if isinstance(source, str) and source != "-" and os.path.exists(path) and os.path.exists(source) and os.path.samefile(path, source):
            raise InputError("residuals", f"names {source}, a data file of this fit: writing the residuals would overwrite the measurements",
                             example=EXAMPLE)


def write(found: Fit, path: str, said_to=None) -> None:
    """The samples' table to ``path`` (whole or not at all); where it went is said on ``said_to``."""
    text = formats.csv_grid(grid(found))

    def put(temporary: str) -> None:
        with open(temporary, "w", encoding="utf-8", newline="") as handle:
            handle.write(text)

    files.replace_atomically(path, put, "--residuals", EXAMPLE)
    if said_to is not None:
        said_to.write(f"taucli: wrote the residuals to {printable(path)}\n")  # a path's control characters escaped, as --out's
