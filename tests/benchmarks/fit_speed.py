"""taucli fit against scipy's curve_fit and lmfit on the same data and model (issue #45).

    python tests/benchmarks/fit_speed.py [--repeats 3] [--sizes 100,1000,10000,1000000]

Each case (a coast-down at each of --sizes, and the issue's other cases at their own sizes)
writes its samples (seeded normal noise, σ = 0.05 rad/s or rad) to a CSV file, then times:
taucli's whole ``taucli fit`` in a subprocess (reading, the fit, the report), curve_fit on the
same arrays with the same closed form written in numpy, and lmfit (when installed) likewise.
Medians over the repeats. taucli runs by its Python API in a fresh interpreter, which times
itself after importing taucli's fit, numpy and scipy.optimize: that is the fit's own time (the
file read, the fit, the report), and the rest of the run is its start-up. The ratio is the fit's
own time over curve_fit's.

The target (#45): closed forms at 10⁴ and 10⁶ samples within 3× curve_fit's fit time, plus the
start-up. Prints a Markdown table (docs/fit.md shows one).
"""

from __future__ import annotations

import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

INERTIA, FRICTION, VISCOUS, DRAG, OMEGA0, SIGMA = 0.1, 0.05, 0.01, 2e-4, 30.0, 0.05


def viscous_model(t, friction, viscous, omega0):
    """ω(t) under friction and viscous torque, held at 0 from the stop on."""
    steady = friction / viscous
    return np.maximum((omega0 + steady) * np.exp(-viscous * t / INERTIA) - steady, 0.0)


def drag_model(t, friction, drag, omega0):
    """ω(t) under friction and quadratic drag: the tangent solution, held at 0 from the stop on."""
    scale = np.sqrt(friction / drag)
    phase = np.arctan(omega0 / scale) - np.sqrt(friction * drag) * t / INERTIA
    return np.where(phase > 0, scale * np.tan(np.maximum(phase, 0.0)), 0.0)


def swing_model(t, g):
    """θ(t) of a point pendulum (1 m) let go at 60° from rest: sin(θ/2) = k sn(K − ω₀t, k)."""
    from scipy.special import ellipj, ellipk

    k = math.sin(math.radians(60) / 2)
    sn = ellipj(ellipk(k * k) - np.sqrt(g / 1.0) * t, k * k)[0]
    return 2 * np.arcsin(k * sn)


def exponent_model(t, drag, exponent, omega0):
    """ω(t) under friction (held) and drag kωⁿ: solve_ivp (rtol 1e-10) once, its dense output read at every t."""
    from scipy.integrate import solve_ivp

    rate = lambda _, w: [(-0.02 - drag * max(w[0], 0.0) ** exponent) / INERTIA]  # noqa: E731
    stop = lambda _, w: w[0]  # noqa: E731
    stop.terminal = True
    found = solve_ivp(rate, (0, float(np.max(t))), [omega0], rtol=1e-10, atol=1e-12, dense_output=True, events=stop)
    return np.where(t <= found.t[-1], found.sol(np.minimum(t, found.t[-1]))[0], 0.0)


# name: (model, truth, the scene and its options held, --fit, the time sampled, the sizes (None: --sizes), the column measured)
COAST = ("spin-down", {"inertia": f"{INERTIA} kg*m^2"})
CASES = {
    "coast, friction + viscous": (viscous_model, (FRICTION, VISCOUS, OMEGA0), COAST, "friction,viscous,omega0", 18.0, None, "omega (rad/s)"),
    "coast, friction + quadratic drag": (drag_model, (FRICTION, DRAG, OMEGA0), COAST, "friction,drag,omega0", 12.0, (5000,), "omega (rad/s)"),
    "pendulum swing θ(t), 60°": (swing_model, (9.80665,), ("pendulum", {"shape": "point", "mass": "1kg", "radius": "1m", "angle0": "60deg"}), "g",
                                 6.0, (1000,), "theta (rad)"),
    "coast, drag kωⁿ with n fitted": (exponent_model, (0.003, 1.5, OMEGA0), ("spin-down", {**COAST[1], "friction": "0.02 N*m"}),
                                      "drag,drag_exponent,omega0", 10.0, (50,), "omega (rad/s)"),
}

# taucli's fit by its Python API in a fresh interpreter: the time after its imports is the fit's own
# (reading the file, the fit, the report), the rest of the run's is its start-up
RUN = """
import sys, time, json
started = time.perf_counter()
import taucli.fit, taucli.fit.command, scipy.optimize
imported = time.perf_counter()
scene, path, fit, sigma, options = json.loads(sys.argv[1])
taucli.fit.fit(scene, path, fit=fit, sigma=sigma, **options)
print(time.perf_counter() - imported)
"""


def _timed(run) -> float:
    started = time.perf_counter()
    run()
    return time.perf_counter() - started


def _taucli(path: Path, scene: tuple[str, dict], fit: str, sigma: str) -> tuple[float, float]:
    """(the whole run, the fit's own time after the imports)."""
    started = time.perf_counter()
    environment = {name: value for name, value in os.environ.items() if name != "PYTHONDONTWRITEBYTECODE"}  # (as installed: compiled once)
    done = subprocess.run([sys.executable, "-c", RUN, json.dumps([scene[0], str(path), fit, sigma, scene[1]])], check=True, capture_output=True, text=True,
                          env=environment)
    return time.perf_counter() - started, float(done.stdout.split()[-1])


def _curve_fit(model, t, y, start) -> float:
    from scipy.optimize import curve_fit

    return _timed(lambda: curve_fit(model, t, y, p0=start, sigma=np.full(len(t), SIGMA), absolute_sigma=True))


def _lmfit(model, t, y, start) -> float | None:
    try:
        import lmfit
    except ImportError:
        return None
    fitted = lmfit.Model(model)
    params = fitted.make_params(**dict(zip(fitted.param_names, start)))
    return _timed(lambda: fitted.fit(y, params, t=t, weights=np.full(len(t), 1 / SIGMA)))


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--sizes", default="100,1000,10000,1000000")
    args = parser.parse_args()
    sizes = [int(size) for size in args.sizes.split(",")]
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        for name, (model, truth, scene, fit, span, own, measured) in CASES.items():
            for n in own or sizes:
                t = np.linspace(0, span, n)
                y = model(t, *truth) + np.random.default_rng(n).normal(0, SIGMA, n)
                path = Path(folder) / f"{n}.csv"
                path.write_text(f"t (s),{measured}\n" + "".join(f"{a!r},{b!r}\n" for a, b in zip(t.tolist(), y.tolist())))
                start = [value * 1.1 for value in truth]
                runs = [_taucli(path, scene, fit, f"{SIGMA} {measured.split('(')[1].rstrip(')')}") for _ in range(args.repeats)]
                whole, ours = statistics.median(run[0] for run in runs), statistics.median(run[1] for run in runs)
                theirs = statistics.median(_curve_fit(model, t, y, start) for _ in range(args.repeats))
                other = [_lmfit(model, t, y, start) for _ in range(args.repeats)]
                other = None if other[0] is None else statistics.median(other)
                rows.append((name, n, whole, ours, theirs, other))
                print(f"{name}, {n:,}: taucli {whole:.2f} s ({ours:.2f} s after start-up), curve_fit {theirs * 1e3:.1f} ms", file=sys.stderr)
    print("| case | samples | taucli fit, whole run | taucli, after start-up | curve_fit | lmfit | ratio (after start-up / curve_fit) |")
    print("|---|---|---|---|---|---|---|")
    for name, n, whole, ours, theirs, other in rows:
        print(f"| {name} | {n:,} | {whole:.2f} s | {ours:.3f} s | {theirs * 1e3:.1f} ms | {'—' if other is None else f'{other * 1e3:.1f} ms'} "
              f"| {ours / theirs:,.0f}× |")


if __name__ == "__main__":
    main()
