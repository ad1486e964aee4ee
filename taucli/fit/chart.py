"""The chart of a fit: the samples and the fitted model against the samples' input, and the
residuals below, drawn as every chart is (taucli.writing.plot: plotille in the terminal, matplotlib for
--out). The x axis is the input that varies between the samples (the time of a time series, an
amplitude), in its column's unit; where it is the only one, the model is drawn as a curve over it,
else at the samples. (``--json --plot`` gives the same numbers in SI.)

With the samples' σ given (--sigma), each sample and its residual carry an error bar ±σᵢ. The
curve carries its ±1σ band from the fitted inputs' covariance C, to first order:
σ_f(x)² = g(x)ᵀ C g(x), g = ∂f/∂p by central differences (forward ones at a bound).
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


def _curve(found: Fit, key: str, xs: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """(x, f, σ_f) along the curve: the model at CURVE points over the samples' span, and its band."""
    samples = found.model.samples
    if samples.varying != [key] or any(hasattr(unknown, "run") for unknown in found.model.unknowns):
        return None  # (runs with inputs of their own: one curve would be one run's, so the fit is drawn at each sample)
    row = samples.row(0)
    grid = np.linspace(float(np.min(xs)), float(np.max(xs)), CURVE)
    model = found.model

    def at(p) -> np.ndarray:
        return np.array([model.at(p, {**row, key: float(x)}) for x in grid])

    values = at(found.p)
    return grid, values, band(found, at, values)


STEP = 1e-3  # of an input's σ: the step of the band's differences


def band(found: Fit, at, values: np.ndarray) -> np.ndarray:
    """σ_f at each point where ``at(p)`` gives f: √(gᵀCg), g by differences of STEP·σⱼ in each input."""
    model, p, covariance = found.model, np.asarray(found.p, dtype=float), np.asarray(found.covariance, dtype=float)
    slopes = np.zeros((len(values), len(p)))
    for j in range(len(p)):
        h = STEP * math.sqrt(max(float(covariance[j, j]), 0.0))
        if not h > 0:
            continue
        up, down = p.copy(), p.copy()
        up[j] += h
        down[j] -= h
        if model.allowed(j, float(down[j])):
            slopes[:, j] = (at(up) - at(down)) / (2 * h)
        else:  # at or near its bound: a forward difference
            slopes[:, j] = (at(up) - values) / h
    return np.sqrt(np.maximum(np.einsum("ij,jk,ik->i", slopes, covariance, slopes), 0.0))


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
    bars = tuple(float(s) for s in samples.sigma) if samples.sigma is not None else ()
    model_series = (Series("fitted", tuple(curve[0] / per), tuple(_none(curve[1])), spread=tuple(_none(curve[2])))
                    if curve is not None  # else the model at each sample, its σ_f as a bar
                    else Series("fitted", shown, tuple(_none(fitted)), points=True, spread=tuple(_none(band(found, found.model.predict, fitted)))))
    panels = (
        Panel(samples.y_key, "measured and fitted", samples.y_unit, (Series("measured", shown, tuple(y), points=True, spread=bars), model_series)),
        Panel("residual", f"{samples.y_key} measured − fitted", samples.y_unit,
              (Series("residual", shown, tuple(_none(y - fitted)), points=True, spread=bars),)),
    )
    return Chart(f"fit: {found.model.command.name}, {samples.y_key} against {key}", key, key, shown_unit, panels)


def _none(values: np.ndarray) -> list[float | None]:
    return [float(v) if math.isfinite(v) else None for v in values]


def document(found: Fit) -> dict:
    """The chart's numbers for --json --plot: each sample measured, fitted, its residual (and σ where
    given), and the curve with its band (σ_f)."""
    samples = found.model.samples
    key, unit, xs = _axis(found)
    y = np.asarray(samples.y, dtype=float)
    fitted = found.model.predict(found.p)
    curve = _curve(found, key, xs)
    return {
        "x": key,
        "y": samples.y_key,
        "units": {key: unit, samples.y_key: samples.y_unit},
        "samples": [{key: float(x), samples.y_key: float(v), "fitted": f, "residual": r, **({"sigma": s} if s is not None else {})}
                    for x, v, f, r, s in zip(xs, y, _none(fitted), _none(y - fitted), samples.sigma or [None] * samples.count)],
        "curve": [{key: float(x), samples.y_key: v, "band": b} for x, v, b in zip(curve[0], _none(curve[1]), _none(curve[2]))] if curve is not None else [],
    }
