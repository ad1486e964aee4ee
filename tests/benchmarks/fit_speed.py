"""taucli fit against scipy's curve_fit and lmfit on the same data and model (issue #45).

    python tests/benchmarks/fit_speed.py [--repeats 3] [--sizes 100,1000,10000,1000000]

Each case writes a coast-down (seeded normal noise, σ = 0.05 rad/s) to a CSV file, then times:
taucli's whole ``taucli fit`` in a subprocess (reading, the fit, the report), curve_fit on the
same arrays with the same closed form written in numpy, and lmfit (when installed) likewise.
Medians over the repeats. The start-up is ``taucli`` importing its fit (numpy, scipy.optimize)
and exiting, timed the same way; the ratio is taucli's time less its start-up over curve_fit's.

The target (#45): closed forms at 10⁴ and 10⁶ samples within 3× curve_fit's fit time, plus the
start-up. Prints a Markdown table (docs/fit.md shows one).
"""

from __future__ import annotations

import argparse
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


CASES = {  # name: (model, truth, taucli's --fit, the time sampled)
    "coast, friction + viscous": (viscous_model, (FRICTION, VISCOUS, OMEGA0), "friction,viscous,omega0", 18.0),
    "coast, friction + quadratic drag": (drag_model, (FRICTION, DRAG, OMEGA0), "friction,drag,omega0", 12.0),
}


def _timed(run) -> float:
    started = time.perf_counter()
    run()
    return time.perf_counter() - started


def _taucli(path: Path, fit: str) -> float:
    command = [sys.executable, "-m", "taucli", "fit", "spin-down", str(path), "--inertia", f"{INERTIA} kg*m^2", "--fit", fit,
               "--sigma", f"{SIGMA} rad/s", "--get", fit.split(",")[0], "--no-limit"]
    return _timed(lambda: subprocess.run(command, check=True, capture_output=True))


def _startup() -> float:
    code = "import taucli.fit.command, scipy.optimize"
    return _timed(lambda: subprocess.run([sys.executable, "-c", code], check=True))


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
    startup = statistics.median(_startup() for _ in range(args.repeats))
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        for name, (model, truth, fit, span) in CASES.items():
            for n in sizes:
                t = np.linspace(0, span, n)
                y = model(t, *truth) + np.random.default_rng(n).normal(0, SIGMA, n)
                path = Path(folder) / f"{n}.csv"
                path.write_text("t (s),omega (rad/s)\n" + "".join(f"{a!r},{b!r}\n" for a, b in zip(t.tolist(), y.tolist())))
                start = [value * 1.2 for value in truth]
                ours = statistics.median(_taucli(path, fit) for _ in range(args.repeats))
                theirs = statistics.median(_curve_fit(model, t, y, start) for _ in range(args.repeats))
                other = [_lmfit(model, t, y, start) for _ in range(args.repeats)]
                other = None if other[0] is None else statistics.median(other)
                rows.append((name, n, ours, theirs, other, (ours - startup) / theirs))
                print(f"{name}, {n:,}: taucli {ours:.2f} s, curve_fit {theirs * 1e3:.1f} ms", file=sys.stderr)
    print(f"start-up (taucli importing its fit, numpy and scipy.optimize): {startup:.2f} s\n")
    print("| case | samples | taucli fit (whole run) | curve_fit | lmfit | (taucli − start-up) / curve_fit |")
    print("|---|---|---|---|---|---|")
    for name, n, ours, theirs, other, ratio in rows:
        print(f"| {name} | {n:,} | {ours:.2f} s | {theirs * 1e3:.1f} ms | {'—' if other is None else f'{other * 1e3:.1f} ms'} | {ratio:,.0f}× |")


if __name__ == "__main__":
    main()
