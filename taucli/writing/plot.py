"""Charts: a sweep's results against its parameter, or a scene's motion against time.

A Chart is data: panels of series of (x, y) points, and moments to mark. ``terminal`` draws it
with plotille (braille canvas; each series its own marker, so it reads without colour) sized to
the terminal; ``write_file`` draws it with matplotlib, imported only then. Both are imported
only when a chart is drawn.
"""

from __future__ import annotations

import importlib.util
import math
import os
import textwrap
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Any

from taucli.quantities.cache import made
from taucli.core.errors import InputError
from taucli.core.written import fmt, pretty_unit, printable
from taucli.writing import files

# A Report and its Trajectory (taucli.writing.report), named here by what is read of them and not
# imported: report.py imports this module for Report.plot(), and the import graph has no loop.
Report = Any
Trajectory = Any

MARKERS = ("•", "+", "x", "o", "*", "#", "@", "%")  # one per series, so the series differ without colour
COLOURS = ("cyan", "magenta", "yellow", "green", "red", "blue", "white", "bright_black")
Y_AXIS_WIDTH = 16  # what plotille adds to the canvas: the y axis (a label and " | ") and the x axis arrow


@dataclass(frozen=True)
class Series:
    label: str
    xs: tuple[float, ...]
    ys: tuple[float | None, ...]  # None: no value at that x (the result does not exist there)
    points: bool = False  # drawn as markers alone (measured samples), not joined by a line
    spread: tuple[float | None, ...] = ()  # ±σ at each point: error bars on points, a band about a line (a fit's chart)


@dataclass(frozen=True)
class Panel:
    """One y quantity against the chart's x, with one series per value of a list."""

    key: str
    label: str
    unit: str
    series: tuple[Series, ...]


@dataclass(frozen=True)
class Chart:
    title: str
    x_key: str
    x_label: str
    x_unit: str
    panels: tuple[Panel, ...]
    marks: tuple[tuple[float, str], ...] = ()  # (x, what happens there)
    notes: tuple[str, ...] = ()  # how the chart was drawn, where the user did not say


SAMPLES = 201  # times at which a motion is sampled for a chart or for --json's "plot"


def trajectory_of(report: Report) -> Trajectory:
    """The report's motion in time, or the --plot error that says there is none."""
    if report.trajectory is None:
        raise InputError(
            "--plot",
            f"needs a motion in time, and {report.scene} has none here (a range, FROM..TO, is charted against its parameter)",
            example="taucli spin-down --inertia '0.1kg*m^2' --omega0 30rad/s --friction '0.3N*m' --plot",
        )
    return report.trajectory()


def motion_points(report: Report, t_end: float | None = None) -> list[tuple[float, ...]]:
    """(t, *curves) of the report's motion in SI, to ``t_end`` if given (a common horizon)."""
    trajectory = trajectory_of(report)
    if t_end is not None and trajectory.state is not None:
        trajectory = replace(trajectory, t_end=t_end)
    return trajectory.sample(SAMPLES)


def plot_document(report: Report) -> dict:
    """The sampled motion for --json: units, points as objects, and the marked moments (or, where
    --plot draws a chart of another kind, its points against its x: an optimum's curve)."""
    if report.chart is not None:
        return chart_document(report.chart())
    trajectory = trajectory_of(report)
    points = motion_points(report)
    keys = ["t", *(key for key, _, _ in trajectory.curves)]
    return {
        "units": {"t": "s", **{key: unit for key, unit, _ in trajectory.curves}},
        "points": [dict(zip(keys, (x if math.isfinite(x) else None for x in point))) for point in points],
        "marks": [{"t": t, "what": what} for t, what in trajectory.marks],
        "notes": [trajectory.note] if trajectory.note else [],
    }


def chart_document(chart: Chart) -> dict:
    """A chart of one series a panel as --json's "plot": its x and each panel's key per point."""
    keys = [chart.x_key, *(panel.key for panel in chart.panels)]
    xs = chart.panels[0].series[0].xs
    columns = [xs, *(panel.series[0].ys for panel in chart.panels)]
    return {
        "units": {chart.x_key: chart.x_unit, **{panel.key: panel.unit for panel in chart.panels}},
        "points": [dict(zip(keys, (x if x is not None and math.isfinite(x) else None for x in row))) for row in zip(*columns)],
        "marks": [{chart.x_key: x, "what": what} for x, what in chart.marks],
        "notes": list(chart.notes),
    }


def motion_chart(runs: Sequence[tuple[str, Report]], units: Mapping[str, tuple[str, float]] | None = None) -> Chart:
    """The curves of each run's motion against time, one series per run, on a common horizon.

    ``units`` maps a curve's key to the unit to show it in and the SI value of one of that unit.
    """
    units = units or {}
    first = runs[0][1]
    horizon = max(trajectory_of(report).t_end for _, report in runs)
    sampled = [(label, motion_points(report, horizon)) for label, report in runs]
    panels = []
    for column, (key, unit, label) in enumerate(trajectory_of(first).curves, start=1):
        shown_unit, factor = units.get(key, (unit, 1.0))
        series = tuple(
            Series(run_label, tuple(p[0] for p in points), tuple(p[column] / factor for p in points)) for run_label, points in sampled
        )
        panels.append(Panel(key, label, shown_unit, series))
    marks = tuple(
        (t, f"{what} ({run_label})" if len(runs) > 1 else what) for run_label, report in runs for t, what in trajectory_of(report).marks
    )
    title = f"{first.scene}: the motion in time" + (", one curve per value" if len(runs) > 1 else "")
    notes = tuple(dict.fromkeys(trajectory_of(report).note for _, report in runs if trajectory_of(report).note))
    return Chart(title, "t", "time", "s", tuple(panels), marks, notes)


def axis_title(label: str, unit: str) -> str:
    shown = pretty_unit(unit)
    return f"{label} ({shown})" if shown else label


def _limits(values: Sequence[float], *, with_zero: bool, cells: int | None) -> tuple[float, float]:
    """A range holding the values, half of one of ``cells`` wider each side so points on an edge
    are drawn; with ``with_zero``, zero is included when the values already come near it."""
    low, high = min(values), max(values)
    if with_zero and 0 < low < high / 3:
        low = 0.0
    elif with_zero and low / 3 < high < 0:
        high = 0.0
    if low == high:
        pad = abs(low) / 10 or 1.0
        return low - pad, high + pad
    margin = 0.0 if cells is None else (high - low) / (2 * cells)
    return low - (margin if low != 0 else 0.0), high + margin


def _tick(value: float, chars: int, delta: float, left: bool = False) -> str:
    text = fmt(value, 3)
    return text.ljust(chars) if left else text.rjust(chars)


def _plotted(series: Series) -> tuple[list[float], list[float]]:
    pairs = [(x, y) for x, y in zip(series.xs, series.ys) if y is not None and math.isfinite(y)]
    return [x for x, _ in pairs], [y for _, y in pairs]


def _spread(series: Series) -> list[tuple[float, float, float]]:
    """(x, y, σ) of each point that has a finite value and σ."""
    return [(x, y, s) for x, y, s in zip(series.xs, series.ys, series.spread)
            if y is not None and s is not None and math.isfinite(y) and math.isfinite(s)]


BAND = "·"  # the marker of a band's edges in the terminal


def _cell(x: float, y: float, limits: tuple[float, float, float, float], width: int, height: int) -> tuple[int, int]:
    """The character cell (row from the bottom, column) plotille draws (x, y) in: each cell is 2 × 4
    braille dots, a value's dot the nearest (plotille.Canvas, rounding half to even as it does)."""
    x_low, x_high, y_low, y_high = limits
    return round((y - y_low) / ((y_high - y_low) / (4 * height))) // 4, round((x - x_low) / ((x_high - x_low) / (2 * width))) // 2


def _line_cells(lines: Sequence[tuple[list[float], list[float]]], limits, width: int, height: int) -> set[tuple[int, int]]:
    """The cells the lines pass through, as plotille draws them (on a canvas of the figure's size)."""
    import plotille  # deferred: as in terminal

    x_low, x_high, y_low, y_high = limits
    canvas = plotille.Canvas(width, height, x_low, y_low, x_high, y_high)
    for xs, ys in lines:
        canvas.point(xs[0], ys[0])
        for x0, y0, x1, y1 in zip(xs, ys, xs[1:], ys[1:]):
            canvas.line(x0, y0, x1, y1)
    rows = canvas.plot(linesep="\n").split("\n")
    return {(height - 1 - r, c) for r, row in enumerate(rows) for c, char in enumerate(row) if char != "\u2800"}


def terminal(chart: Chart, columns: int, *, colour: bool, height: int = 12) -> str:
    """The chart as text for a terminal ``columns`` wide: panels one above the other.

    In a chart of samples (a fit's), each panel is drawn in layers, lowest first: a line's ±σ band
    (its edges dotted, ·), the samples' error bars, the samples (markers), and the lines last, over
    them all: a marker in a cell a line passes through is left out, so the line is seen whole."""
    import plotille  # deferred: plotille (about 25 ms), only when a chart is drawn

    width = max(columns - Y_AXIS_WIDTH, 10)
    out = textwrap.wrap(chart.title, columns)
    for panel in chart.panels:
        drawn = [(n, _plotted(series)) for n, series in enumerate(panel.series)]
        drawn = [(n, xy) for n, xy in drawn if xy[0]]
        if not drawn:
            out += ["", f"{axis_title(panel.label, panel.unit)}: no values to draw"]
            continue
        spreads = {n: _spread(panel.series[n]) for n, _ in drawn}
        figure = plotille.Figure()
        figure.width, figure.height = width, height
        figure.with_colors, figure.origin = colour, False
        figure.register_label_formatter(float, _tick)
        figure.register_label_formatter(int, _tick)
        figure.x_label, figure.y_label = "", axis_title(panel.key, panel.unit)
        x_low, x_high = _limits([x for _, (xs, _) in drawn for x in xs], with_zero=False, cells=None)
        figure.set_x_limits(min_=x_low, max_=x_high)
        edges = [y + sign * s for triples in spreads.values() for _, y, s in triples for sign in (-1, 1)]
        y_low, y_high = _limits([y for _, (_, ys) in drawn for y in ys] + edges, with_zero=True, cells=height)
        figure.set_y_limits(min_=y_low, max_=y_high)
        limits = (x_low, x_high, y_low, y_high)
        for x, _ in chart.marks:
            if x_low <= x <= x_high:
                figure.axvline((x - x_low) / (x_high - x_low), lc="white" if colour else None)
        lines = [(n, xy) for n, xy in drawn if not panel.series[n].points]
        samples = len(lines) < len(drawn)
        covered = _line_cells([xy for _, xy in lines], limits, width, height) if samples and lines else set()

        def uncovered(xs, ys):
            kept = [(x, y) for x, y in zip(xs, ys) if _cell(x, y, limits, width, height) not in covered]
            return [x for x, _ in kept], [y for _, y in kept]

        def tint(n):
            return COLOURS[n % len(COLOURS)] if colour else None

        for n, _ in lines:  # the bands, lowest
            edge_xs, edge_ys = uncovered([x for x, _, _ in spreads[n] for _ in (0, 1)], [y + sign * s for _, y, s in spreads[n] for sign in (-1, 1)])
            if edge_xs:
                figure.scatter(edge_xs, edge_ys, lc=tint(n), marker=BAND)
        for n, _ in drawn:  # the samples' error bars
            if panel.series[n].points:
                for x, y, s in spreads[n]:
                    figure.plot([x, x], [y - s, y + s], lc=tint(n))
        under = []  # (n, samples under a line, samples)
        for n, (xs, ys) in drawn:  # the samples
            if panel.series[n].points:
                kept_xs, kept_ys = uncovered(xs, ys)
                if kept_xs:
                    figure.scatter(kept_xs, kept_ys, lc=tint(n), marker=MARKERS[n % len(MARKERS)])
                if len(kept_xs) < len(xs):
                    under.append((n, len(xs) - len(kept_xs), len(xs)))
        for n, (xs, ys) in lines:  # the lines, last: over the samples
            figure.plot(xs, ys, lc=tint(n))
        for n, (xs, ys) in drawn if len(panel.series) > 1 and not samples else ():  # markers tell series apart without colour,
            every = max(1, 3 * len(xs) // width)  # drawn after every line, one in three columns at most
            figure.scatter(xs[::every], ys[::every], lc=tint(n), marker=MARKERS[n % len(MARKERS)])
        axis = "\n".join(line.rstrip() for line in figure.show(legend=False).replace("> ()", ">").replace("| ()", "|").splitlines())
        out += ["", *textwrap.wrap(f"{panel.key}: {panel.label}", columns), axis, f"{' ' * 12}{axis_title(chart.x_key, chart.x_unit)}"]
        for n, hidden, total in under:  # said, so that a sample on the line is not taken for a missing one
            said = f"{MARKERS[n % len(MARKERS)]} {hidden} of {total} {panel.series[n].label} lie under the {' and '.join(panel.series[m].label for m, _ in lines)} line, drawn over them"
            out += textwrap.wrap(said, columns)
    if len(chart.panels[0].series) > 1:
        out += textwrap.wrap(_legend(chart.panels[0].series), columns)
    for x, what in chart.marks:
        out += textwrap.wrap(f"│ at {chart.x_key} = {fmt(x, 4)} {pretty_unit(chart.x_unit)}".rstrip() + f": {what}", columns, subsequent_indent="  ")
    for note in chart.notes:
        out += textwrap.wrap(f"note: {note}", columns, subsequent_indent="  ")
    return "\n".join(out) + "\n"


def _legend(series: Sequence[Series]) -> str:
    """What each series' marker is: samples by their marker (± their error bars), a line as ⠤ beside
    samples (and its band as ·), else by the markers drawn along it."""
    marked = any(one.points for one in series)  # samples as markers beside lines: a line is a line
    items = []
    for n, one in enumerate(series):
        items.append(f"{MARKERS[n % len(MARKERS)] if one.points or not marked else '⠤'} {one.label}" + (" ± σ" if one.points and _spread(one) else ""))
        if not one.points and _spread(one):
            items.append(f"{BAND} {one.label} ± 1σ (band)")
    return "  ".join(items)


def check_file(path: str) -> None:
    """--out names an .svg or .png file with a name before its suffix, not a link or a folder, in
    a folder that can be written (taucli.writing.files); and matplotlib is there to draw it."""
    files.check(path, "--out", (".svg", ".png"), "--out chart.svg")
    if importlib.util.find_spec("matplotlib") is None:
        raise InputError("--out", "needs matplotlib to draw files", hint="pip install 'taucli[plot]' (from a checkout: pip install '.[plot]')")


def _matplotlib_folder() -> None:
    """matplotlib keeps its settings and font list in ~/.config/matplotlib and ~/.cache/matplotlib
    (or $XDG_CONFIG_HOME, $XDG_CACHE_HOME) and warns over several lines on stderr where it cannot
    make them (a read-only or missing home), or makes a missing home's whole tree. They are made
    here as the cache folder is (at most two levels, never a home); where they cannot be, unless
    MPLCONFIGDIR says otherwise, it is given a temporary folder, removed at exit."""
    if os.environ.get("MPLCONFIGDIR"):
        return
    home = os.path.expanduser("~")
    bases = (os.environ.get("XDG_CONFIG_HOME") or os.path.join(home, ".config"), os.environ.get("XDG_CACHE_HOME") or os.path.join(home, ".cache"))
    if all(made(os.path.join(base, "matplotlib")) and os.access(os.path.join(base, "matplotlib"), os.W_OK) for base in bases):
        return
    import atexit  # deferred: only where matplotlib has no folder of its own
    import shutil  # deferred: as above
    import tempfile  # deferred: as above

    folder = tempfile.mkdtemp(prefix="taucli-matplotlib-")
    atexit.register(shutil.rmtree, folder, ignore_errors=True)
    os.environ["MPLCONFIGDIR"] = folder


def figure(chart: Chart):
    """The chart as a matplotlib Figure (not one of pyplot's: nothing is shown or kept open, and
    no backend is chosen), a panel per quantity over the chart's x; matplotlib is imported here."""
    _matplotlib_folder()
    try:
        from matplotlib.figure import Figure  # deferred: matplotlib (hundreds of ms), only for a figure
    except ImportError:
        raise ImportError("plot() needs matplotlib: pip install 'taucli[plot]' (from a checkout: pip install '.[plot]')") from None

    drawn = Figure(figsize=(7, 2.6 * len(chart.panels) + 0.6))
    axes = drawn.subplots(len(chart.panels), 1, sharex=True, squeeze=False)
    for row, panel in zip(axes, chart.panels):
        ax = row[0]
        for n, series in enumerate(panel.series):
            xs, ys = _plotted(series)
            spread = _spread(series)
            if series.points and spread:  # each sample's error bar ±σ
                ax.errorbar([x for x, _, _ in spread], [y for _, y, _ in spread], yerr=[s for _, _, s in spread], label=series.label or None,
                            linestyle="none", marker="o" if len(xs) < 200 else ".", markersize=4, elinewidth=0.8, capsize=0, zorder=2)
            elif series.points:
                ax.plot(xs, ys, label=series.label or None, linestyle="none", marker="o" if len(xs) < 200 else ".", markersize=4, zorder=2)
            else:  # a line over the samples, and its band ±1σ under them
                line, = ax.plot(xs, ys, label=series.label or None, marker="o" if len(xs) < 12 else None, zorder=3)
                if spread:
                    ax.fill_between([x for x, _, _ in spread], [y - s for _, y, s in spread], [y + s for _, y, s in spread], color=line.get_color(),
                                    alpha=0.25, linewidth=0, label=f"{series.label} ± 1σ" if series.label else None, zorder=1)
        for x, what in chart.marks:
            ax.axvline(x, linestyle="--", linewidth=0.8, color="grey")
        ax.set_ylabel(axis_title(panel.label, panel.unit))
        ax.grid(True, linewidth=0.3)
        if len(panel.series) > 1:
            ax.legend(fontsize="small")
    for x, what in chart.marks:
        axes[0][0].annotate(what, (x, 1.0), xycoords=("data", "axes fraction"), fontsize="small", rotation=90, va="top", ha="right")
    axes[-1][0].set_xlabel(axis_title(chart.x_label, chart.x_unit))
    drawn.suptitle(chart.title, fontsize="medium")
    drawn.tight_layout()
    return drawn


def motion_figure(runs: Sequence[tuple[str, Report]]):
    """report.plot() and Sweep.plot() (#46 item 10): the motion in time of each run, one series
    per run, as a matplotlib Figure; each curve in SI, as the trajectory gives it."""
    for _, report in runs:
        if report.trajectory is None:
            raise ValueError(f"plot() draws a motion in time, and this {report.scene} report has none "
                             "(its results are its answer; a sweep's results against its keyword: Sweep.to_pandas())")
    return figure(motion_chart(runs))


def write_file(chart: Chart, path: str, said_to=None) -> None:
    """The chart as an SVG or PNG file (matplotlib's Agg renderer, or its SVG one); where it went
    is said on ``said_to`` (stderr: stdout holds the answer alone)."""
    drawn = figure(chart)
    files.replace_atomically(path, lambda temporary: drawn.savefig(temporary, format=os.path.splitext(path)[1][1:].lower()), "--out", "--out chart.svg")
    if said_to is not None:
        said_to.write(f"taucli: wrote the chart to {printable(path)}\n")  # a path's control characters escaped (#43 item 14)
