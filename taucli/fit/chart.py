"""The chart of a fit: the samples and the fitted model against the samples' input, and the
residuals below, drawn as every chart is (taucli.writing.plot: plotille in the terminal, matplotlib for
--out). The x axis is the input that varies between the samples (the time of a time series, an
amplitude), in its column's unit; where it is the only one, the model is drawn as a curve over it,
else at the samples. (``--json --plot`` gives the same numbers in SI.)
"""

from __future__ import annotations

import math

import numpy as np

from taucli.quantities import units
from taucli.fit.solve import Fit
from taucli.writing.plot import Chart, Panel, Series

CURVE = 121  # points of the fitted curve


def _axis(found: Fit) -> tuple[str, str, np.ndarray]:
    """(key, SI unit, value per sample) of the chart's x axis."""
    samples = found.model.samples
    varying = samples.varying
    if varying:
        name = varying[0]
        return name, units.KINDS[found.model.command.option(name).kind].si_unit, np.asarray(samples.inputs[name], dtype=float)
    return "sample", "", np.arange(1, samples.count + 1, dtype=float)


def _curve(found: Fit, key: str, xs: np.ndarray) -> tuple[np.ndarray, np.ndarray] | None:
    samples = found.model.samples
    if samples.varying != [key] or any(hasattr(unknown, "run") for unknown in found.model.unknowns):
        return None  # (runs with inputs of their own: one curve would be one run's, so the fit is drawn at each sample)
    row = samples.row(0)
    grid = np.linspace(float(np.min(xs)), float(np.max(xs)), CURVE)
    return grid, np.array([found.model.at(found.p, {**row, key: float(x)}) for x in grid])


def _shown(found: Fit, key: str, unit: str) -> tuple[str, float]:
    """(the unit the x axis is drawn in, SI per that unit): the column's own, as its header writes
    it (an amplitude in degrees), where it has one; else SI."""
    column = next((m for m in found.model.samples.columns if m.target == key), None)
    if column is None or not column.column.unit or not column.factor > 0:
        return unit, 1.0
    return column.column.unit, column.factor


def chart(found: Fit) -> Chart:
    samples = found.model.samples
    key, unit, xs = _axis(found)
    y = np.asarray(samples.y, dtype=float)
    fitted = found.model.predict(found.p)
    curve = _curve(found, key, xs)
    shown_unit, per = _shown(found, key, unit)
    shown = tuple(xs / per)
    model_series = (Series("fitted", tuple(curve[0] / per), tuple(_none(curve[1])))
                    if curve is not None else Series("fitted", shown, tuple(_none(fitted)), points=True))
    panels = (
        Panel(samples.y_key, "measured and fitted", samples.y_unit, (Series("measured", shown, tuple(y), points=True), model_series)),
        Panel("residual", f"{samples.y_key} measured − fitted", samples.y_unit, (Series("residual", shown, tuple(_none(y - fitted)), points=True),)),
    )
    return Chart(f"fit: {found.model.command.name}, {samples.y_key} against {key}", key, key, shown_unit, panels)


def _none(values: np.ndarray) -> list[float | None]:
    return [float(v) if math.isfinite(v) else None for v in values]


def document(found: Fit) -> dict:
    """The chart's numbers for --json --plot: each sample measured, fitted and its residual, and the curve."""
    samples = found.model.samples
    key, unit, xs = _axis(found)
    y = np.asarray(samples.y, dtype=float)
    fitted = found.model.predict(found.p)
    curve = _curve(found, key, xs)
    return {
        "x": key,
        "y": samples.y_key,
        "units": {key: unit, samples.y_key: samples.y_unit},
        "samples": [{key: float(x), samples.y_key: float(v), "fitted": f, "residual": r}
                    for x, v, f, r in zip(xs, y, _none(fitted), _none(y - fitted))],
        "curve": [{key: float(x), samples.y_key: v} for x, v in zip(curve[0], _none(curve[1]))] if curve is not None else [],
    }
