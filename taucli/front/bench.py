"""The work-precision chart: time per solve against error, for every method of every scene that
has more than one (spin-down: the closed form and the steppers; impulse: the quadrature rules).

Each point is one method at one setting (a step, a tolerance, a sample count) on one fixed
reference problem: the median time of repeated in-process solves, less the timer's own
overhead, and the relative error against a 50-digit reference computed once with mpmath (the
values below; tests/front/test_bench.py recomputes them). A run that went unstable is kept as a
diverged point, never dropped.
"""

from __future__ import annotations

import math
import statistics
import textwrap
import timeit
from collections.abc import Callable
from dataclasses import asdict, dataclass
from decimal import Decimal, localcontext

from taucli.core.version import __version__
from taucli.numerics.steppers import TooManySteps
from taucli.scenes.impulse import solve_profile
from taucli.scenes.pendulum import BlewUp, Harmonic, Stepped, Swing, exact_model
from taucli.scenes.spin import Torques, solve

# name -> (inertia, torques, ω₀, (t_stop, θ_stop) to 50 digits for these double inputs)
SPIN_PROBLEMS: dict[str, tuple[float, Torques, float, tuple[str, str]]] = {
    "potter's wheel": (0.1, Torques(friction=0.3), 30.0, (
        "10.000000000000000925185853854297151258447623626544",
        "150.00000000000001387778780781445726887671435439817")),
    "friction + viscous + drag": (0.1, Torques(friction=0.3, viscous=0.01, drag=0.001), 30.0, (
        "5.0381452638705053114161196498586372595344007193292",
        "55.281169302352497277851732874297723662419480272026")),
    "power-law drag n=1.5": (0.1, Torques(friction=0.3, drag=0.001, drag_exponent=1.5), 30.0, (
        "8.3492536439584948998689574196791838429746444953536",
        "115.78450574568049671525555821563861040677676681217")),
    "stiff viscous brake": (0.01, Torques(friction=0.05, viscous=0.5), 100.0, (
        "0.13817509558630441347164874985184924352030283891658",
        "1.9861824904413695995191726857097003233417627791599")),
}  # fmt: skip
# name -> (peak torque, length, J = 2 τ_peak T / π to 50 digits)
PULSE_PROBLEMS: dict[str, tuple[float, float, str]] = {
    "half-sine pulse": (50.0, 0.01, "0.31830988618379067816392311312735509344922283101589"),
}

FULL = {
    "euler": [1e-1, 3e-2, 1e-2, 3e-3, 1e-3],
    "rk4": [0.3, 0.1, 3e-2, 1e-2, 3e-3],
    "rk45": [1e-4, 1e-6, 1e-8, 1e-10, 1e-12],
    "scipy": [1e-4, 1e-7, 1e-10, 1e-13],
    "samples": [5, 11, 31, 101, 301, 1001, 3001],
}
# --quick (#42 item 23: it took 9 s to 30 s): two settings a method, each timed for 4 ms, not 20
QUICK = {"euler": [1e-1, 1e-2], "rk4": [0.3, 3e-2], "rk45": [1e-5, 1e-12], "scipy": [1e-9], "samples": [5, 31, 301]}
SECONDS_TIMED = {False: 0.02, True: 0.004}  # the least time of each repeat of a timing, by quick
SCENES = ("spin-down", "impulse")
SCENES += ("pendulum",)  # (#19)
MARKERS = {"exact": "X", "euler": "e", "rk4": "4", "rk45": "d", "scipy RK45": "R", "scipy DOP853": "8", "scipy LSODA": "L", "trapezoid": "t", "simpson": "s"}
MARKERS.update({"verlet": "v", "small-angle": "h"})  # (#19)
# name -> (amplitude θ₀ in degrees, period 4K(sin(θ₀/2)) of θ'' = −sin θ from rest at θ₀, to 50
# digits for the double math.radians(θ₀))
PENDULUM_PROBLEMS: dict[str, tuple[float, str]] = {
    "pendulum at 60°": (60.0, "6.7430014192503840637329802594068084835009956534441"),
    "pendulum at 179°": (179.0, "24.511115298106897760983209285784891344579310211168"),
}
FULL.update({"pendulum euler": [1e-2, 3e-3, 1e-3, 3e-4], "pendulum rk4": [0.3, 0.1, 3e-2, 1e-2, 3e-3], "verlet": [0.1, 3e-2, 1e-2, 3e-3, 1e-3]})
QUICK.update({"pendulum euler": [1e-2], "pendulum rk4": [0.3, 3e-2], "verlet": [0.1, 1e-2]})
_least = SECONDS_TIMED[False]  # this run's, set by run()
ERROR_FLOOR = 1e-17  # an error of 0 is drawn here


@dataclass(frozen=True)
class Point:
    """One method at one setting on one problem: seconds per solve and relative error."""

    scene: str
    problem: str
    method: str
    setting: str
    seconds: float
    error: float | None  # None when the run diverged
    status: str  # "ok" or "diverged"


def time_per_call(function: Callable[[], object], repeats: int, least: float | None = None) -> float:
    """Median seconds per call over ``repeats`` timings of at least ``least`` seconds each (else
    the run's), less the cost of timing an empty call."""
    once = timeit.timeit(function, number=1)
    number = max(1, int((least or _least) / max(once, 1e-7)))
    timings = timeit.repeat(function, number=number, repeat=repeats)
    overhead = min(timeit.repeat(lambda: None, number=number, repeat=3))
    return max(statistics.median(timings) - overhead, 0.0) / number


def _relative(got: float, reference: str) -> float:
    """|got − reference| / |reference| in 60-digit decimal: the double and the 50-digit
    reference are both taken exactly, so even errors of an ulp are measured, not rounded."""
    with localcontext() as context:
        context.prec = 60
        exact = Decimal(reference)
        return float(abs(Decimal(got) - exact) / abs(exact))


def _spin_points(name: str, ladder: dict, repeats: int) -> list[Point]:
    inertia, torques, omega0, (t_ref, theta_ref) = SPIN_PROBLEMS[name]
    closed_form = torques.drag == 0 or torques.drag_exponent == 2
    runs: list[tuple[str, str, Callable]] = []
    if closed_form:
        runs.append(("exact", "closed form", lambda: solve(inertia, torques, omega0, method="exact")))
    # The fixed steps without the error estimate spin-down gives them (a reference run, and
    # answers off by more than 1e-3 withheld): the chart times each method alone, and plots
    # its error however large.
    for dt in ladder["euler"]:
        runs.append(("euler", f"dt={dt:g}", lambda dt=dt: solve(inertia, torques, omega0, method="euler", dt=dt, estimate_error=False)))
    for dt in ladder["rk4"]:
        runs.append(("rk4", f"dt={dt:g}", lambda dt=dt: solve(inertia, torques, omega0, method="rk4", dt=dt, estimate_error=False)))
    for rtol in ladder["rk45"]:
        runs.append(("rk45", f"rtol={rtol:g}", lambda rtol=rtol: solve(inertia, torques, omega0, method="rk45", rtol=rtol)))
    points = []
    for method, setting, run in runs:
        report = run()
        t_stop, theta_stop = report.results["t_stop"].value, report.results["theta_stop"].value
        if t_stop is None or theta_stop is None:
            points.append(Point("spin-down", name, method, setting, time_per_call(run, repeats), None, "diverged"))
            continue
        error = max(_relative(t_stop, t_ref), _relative(theta_stop, theta_ref))
        points.append(Point("spin-down", name, method, setting, time_per_call(run, repeats), error, "ok"))
    points.extend(_scipy_points(name, ladder, repeats))
    return points


def _scipy_points(name: str, ladder: dict, repeats: int) -> list[Point]:
    """scipy's solve_ivp, where installed: what a user would reach for instead."""
    try:
        from scipy.integrate import solve_ivp  # deferred: scipy, the optional bench extra
    except ImportError:
        return []
    inertia, torques, omega0, (t_ref, theta_ref) = SPIN_PROBLEMS[name]

    def rate(_, y):
        omega = max(y[0], 0.0)
        return [(-torques.friction - torques.viscous * omega - torques.drag * omega**torques.drag_exponent) / inertia, y[0]]

    def stopped(_, y):
        return y[0]

    stopped.terminal, stopped.direction = True, -1

    def error(solution) -> float:
        t_stop, theta_stop = float(solution.t_events[0][0]), float(solution.y_events[0][0][1])
        return max(_relative(t_stop, t_ref), _relative(theta_stop, theta_ref))

    return _scipy_runs("spin-down", name, solve_ivp, rate, [omega0, 0.0], 1.01 * inertia * omega0 / torques.friction, stopped, error, ladder, repeats)


def _scipy_runs(scene: str, name: str, solve_ivp, rate, start: list[float], bound: float, event, error, ladder: dict, repeats: int) -> list[Point]:
    """Each of scipy's RK45, DOP853 and LSODA at each rtol of the ladder, run to ``event``:
    the time per solve and ``error(solution)``, or diverged where the event never came."""
    points = []
    for method in ("RK45", "DOP853", "LSODA"):
        for rtol in ladder["scipy"]:
            def run(method=method, rtol=rtol):
                return solve_ivp(rate, (0.0, bound), start, method=method, rtol=rtol, atol=rtol * 1e-3, events=event)

            solution = run()
            reached = bool(solution.t_events[0].size)
            points.append(Point(scene, name, f"scipy {method}", f"rtol={rtol:g}", time_per_call(run, repeats),
                                error(solution) if reached else None, "ok" if reached else "diverged"))
    return points


def _pulse_points(name: str, ladder: dict, repeats: int) -> list[Point]:
    peak, length, reference = PULSE_PROBLEMS[name]
    points = []
    for samples in ladder["samples"]:
        data = [(length * k / (samples - 1), peak * math.sin(math.pi * k / (samples - 1))) for k in range(samples)]
        for rule in ("trapezoid", "simpson"):
            def run(rule=rule, data=data):
                return solve_profile(1.0, 0.0, data, rule=rule)

            error = _relative(run().results["J"].value, reference)
            points.append(Point("impulse", name, rule, f"n={samples}", time_per_call(run, repeats), error, "ok"))
    return points


def _pendulum_points(name: str, ladder: dict, repeats: int) -> list[Point]:
    """The period of θ'' = −sin θ from rest (I = mgd = 1): the time each method takes to find it,
    and its error. The steppers locate the turning points (ω = 0) as events, as the scene does."""
    degrees, reference = PENDULUM_PROBLEMS[name]
    swing = Swing(1.0, 1.0, 0.0, math.radians(degrees), 0.0)
    horizon = 3 * float(reference)
    runs: list[tuple[str, str, Callable]] = [
        ("exact", "elliptic K", lambda: exact_model(swing).period),
        ("small-angle", "2π√(I/mgd)", lambda: Harmonic(1.0, swing.theta0, 0.0).period),
    ]
    for method, key in (("euler", "pendulum euler"), ("rk4", "pendulum rk4"), ("verlet", "verlet")):
        for dt in ladder[key]:
            runs.append((method, f"dt={dt:g}", lambda method=method, dt=dt: Stepped(swing, method, dt, 1e-10, horizon).period(False)))
    for rtol in ladder["rk45"]:
        runs.append(("rk45", f"rtol={rtol:g}", lambda rtol=rtol: Stepped(swing, "rk45", 1e-2, rtol, horizon).period(False)))
    points = []
    for method, setting, find_period in runs:
        def run_once(find_period=find_period):
            try:
                return find_period()
            except (TooManySteps, BlewUp):  # a diverged point, timed as far as it went
                return None

        period = run_once()
        status = "ok" if period is not None else "diverged"
        error = _relative(period, reference) if period is not None else None
        points.append(Point("pendulum", name, method, setting, time_per_call(run_once, repeats), error, status))
    points.extend(_scipy_pendulum_points(name, swing.theta0, reference, ladder, repeats))
    return points


def _scipy_pendulum_points(name: str, theta0: float, reference: str, ladder: dict, repeats: int) -> list[Point]:
    """scipy's solve_ivp on the same pendulum, where installed: the period as twice the time to
    the first turning point (its event ω = 0, falling through zero from rest at θ₀ > 0)."""
    try:
        from scipy.integrate import solve_ivp  # deferred: scipy, the optional bench extra
    except ImportError:
        return []

    def rate(_, y):
        return [y[1], -math.sin(y[0])]

    def turned(_, y):
        return y[1]

    turned.terminal, turned.direction = True, 1  # ω < 0 on the way down, back up to 0 at the far side

    def error(solution) -> float:
        return _relative(2 * float(solution.t_events[0][0]), reference)

    return _scipy_runs("pendulum", name, solve_ivp, rate, [theta0, 0.0], 3 * float(reference), turned, error, ladder, repeats)


def run(scenes: tuple[str, ...] = SCENES, quick: bool = False) -> list[Point]:
    """Measure every point of the chosen scenes."""
    global _least
    ladder, repeats = (QUICK, 3) if quick else (FULL, 5)
    _least = SECONDS_TIMED[quick]
    points: list[Point] = []
    if "spin-down" in scenes:
        for name in SPIN_PROBLEMS:
            points.extend(_spin_points(name, ladder, repeats))
    if "impulse" in scenes:
        for name in PULSE_PROBLEMS:
            points.extend(_pulse_points(name, ladder, repeats))
    if "pendulum" in scenes:
        for name in PENDULUM_PROBLEMS:
            points.extend(_pendulum_points(name, ladder, repeats))
    return points


def chart(points: list[Point], problem: str, width: int = 72, height: int = 18) -> list[str]:
    """A log-log text chart of one problem: error (up) against time per solve (right).

    Each method has a letter (legend below); diverged runs are '!' on the top line, at their time.
    """
    mine = [p for p in points if p.problem == problem]
    times = [math.log10(max(p.seconds, 1e-9)) for p in mine]
    errors = [math.log10(max(p.error, ERROR_FLOOR)) for p in mine if p.error is not None]
    x_low, x_high = math.floor(min(times)), math.ceil(max(times))
    y_low, y_high = math.floor(min(errors, default=-16)), max(math.ceil(max(errors, default=0)), 0)
    x_high += x_high == x_low
    y_high += y_high == y_low
    plot_width = width - 8
    grid = [[" "] * plot_width for _ in range(height)]
    for point, x in zip(mine, times):
        column = min(plot_width - 1, int((x - x_low) / (x_high - x_low) * (plot_width - 1) + 0.5))
        if point.error is None:
            grid[0][column] = "!"
            continue
        y = math.log10(max(point.error, ERROR_FLOOR))
        row = min(height - 1, int((y_high - y) / (y_high - y_low) * (height - 1) + 0.5))
        grid[row][column] = MARKERS.get(point.method, "?")
    lines = textwrap.wrap(f"{problem} ({mine[0].scene}): relative error against time per solve", width)
    step = (y_high - y_low) / (height - 1)
    for index, row in enumerate(grid):
        exponent = y_high - index * step
        decade = round(exponent)
        label = f"1e{decade}" if abs(exponent - decade) <= step / 2 and decade % 2 == 0 else ""
        lines.append(f"{label:>7}|" + "".join(row).rstrip())
    lines.append(" " * 7 + "+" + "-" * plot_width)
    ticks = [" "] * plot_width
    free_from = 0  # labels keep a space between them; one that would not is left out
    for decade in range(x_low, x_high + 1):
        label = _seconds_label(decade)
        column = min(int((decade - x_low) / (x_high - x_low) * (plot_width - 1) + 0.5), plot_width - len(label))  # kept inside the width
        if column < free_from:
            continue
        for offset, char in enumerate(label):
            ticks[column + offset] = char
        free_from = column + len(label) + 1
    lines.append(" " * 8 + "".join(ticks).rstrip())
    used = sorted({p.method for p in mine}, key=list(MARKERS).index)
    legend = [f"{MARKERS[m]} {m}" for m in used] + (["! diverged"] if any(p.error is None for p in mine) else [])
    kept_whole = "   ".join(entry.replace(" ", "\u00a0") for entry in legend)  # an entry is not split between lines
    wrapped = textwrap.wrap(kept_whole, width, initial_indent=" " * 8, subsequent_indent=" " * 8, break_on_hyphens=False)
    lines.extend(line.replace("\u00a0", " ") for line in wrapped)
    return lines


def _seconds_label(decade: int) -> str:
    return {-9: "1ns", -8: "10ns", -7: "100ns", -6: "1µs", -5: "10µs", -4: "100µs", -3: "1ms", -2: "10ms", -1: "100ms", 0: "1s", 1: "10s"}.get(decade, f"1e{decade}s")


def document(points: list[Point]) -> dict:
    return {"taucli": __version__, "bench": [asdict(p) for p in points]}


def write_image(points: list[Point], path: str) -> None:
    """The same charts as an SVG or PNG file (matplotlib, the optional 'plot' extra)."""
    import matplotlib  # deferred: matplotlib (hundreds of ms), the optional plot extra

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt  # deferred: matplotlib, as above

    problems = list(dict.fromkeys(p.problem for p in points))
    columns = min(len(problems), 3)
    rows = math.ceil(len(problems) / columns)
    figure, axes = plt.subplots(rows, columns, figsize=(5 * columns, 4 * rows), squeeze=False)
    for axis, problem in zip(axes.flat, problems):
        mine = [p for p in points if p.problem == problem]
        for method in dict.fromkeys(p.method for p in mine):
            ok = [p for p in mine if p.method == method and p.error is not None]
            axis.loglog([p.seconds for p in ok], [max(p.error, ERROR_FLOOR) for p in ok], marker="o", label=method)
            diverged = [p for p in mine if p.method == method and p.error is None]
            if diverged:
                axis.scatter([p.seconds for p in diverged], [1.0] * len(diverged), marker="x", color="red")
        axis.set_title(problem)
        axis.set_xlabel("time per solve (s)")
        axis.set_ylabel("relative error")
        axis.grid(True, which="major", alpha=0.3)
        axis.legend(fontsize="small")
    for axis in list(axes.flat)[len(problems):]:
        axis.set_visible(False)
    figure.tight_layout()
    figure.savefig(path)
    plt.close(figure)
