"""--mc on arrays against the draw-by-draw path (issue #45 item 4): medians, in one run.

    python tests/benchmarks/mc_speed.py [--draws 100000] [--runs 5]

For each case, a closed-form scene the docs use with uncertain inputs:
- the Monte Carlo alone (propagate.monte_carlo in this process: the draws, the solves, the
  summaries), on arrays (taucli.answering.mc_arrays) and draw by draw (each draw through
  pipeline.solve, as where numpy is not installed or the scene has no array form);
- the whole run (``python -m taucli ... --mc N --no-limit`` in a subprocess: start-up, the
  nominal answer, its Jacobian, the Monte Carlo, the table), with numpy and with it hidden
  (sys.modules["numpy"] = None: the scalar path).

Times are CPU seconds (time.process_time, and the children's user + system time), not wall
time: on a machine shared with other work they are what the run itself costs. The Monte Carlo draw by draw runs fewer draws (--scalar-draws, 10,000 by default), scaled to N:
it is linear in the draws; its whole run is one run of all N. Target: 10⁵ draws of a closed-form scene in under a second of solver
time.
"""

from __future__ import annotations

import argparse
import resource
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from taucli.answering import answer, propagate  # noqa: E402
from taucli.options import SCENES  # noqa: E402

CASES = {
    "spin-down coast (I, ω₀ ±; friction, viscous, --time)": ("spin-down", {
        "inertia": "2+/-0.1 kg*m^2", "omega0": "100+/-2 rad/s", "friction": "0.5 N*m", "viscous": "0.01", "time": "10s"}),
    "spin-down, quadratic drag and friction (D < 0)": ("spin-down", {
        "inertia": "2+/-0.1 kg*m^2", "omega0": "100rad/s", "friction": "0.5+/-0.05 N*m", "drag": "0.001", "time": "10s"}),
    "atwood, axle friction (held in a third of the draws)": ("atwood", {
        "m1": "1.1+/-0.1kg", "m2": "1kg", "pulley_radius": "0.1m", "axle_friction": "0.05 N*m"}),
    "rolling down an incline, rolling or slipping": ("rolling", {
        "shape": "sphere", "angle": "30+/-1deg", "length": "2+/-0.01m", "mass": "1kg", "radius": "0.1m", "mu_s": "0.17+/-0.01", "mu_k": "0.1"}),
    "pendulum from rest, exact period (L, θ₀ ±)": ("pendulum", {
        "shape": "point", "mass": "1kg", "radius": "1+/-0.01m", "angle0": "30+/-2deg"}),
}

HIDDEN = "import runpy, sys; sys.modules['numpy'] = None; sys.argv = ['taucli', *sys.argv[1:]]; runpy.run_module('taucli', run_name='__main__')"


def _monte_carlo(scene: str, given: dict, draws: int, arrays: bool) -> float:
    """CPU seconds of propagate.monte_carlo alone."""
    command = SCENES[scene]
    central, spreads, _ = answer._read(command, given, propagate.readable(command, given))
    solved = propagate.Scene(command, central, None, answer._as_named)
    report = propagate.measured(solved.report({}), {}, spreads, [])
    started = time.process_time()
    propagate.monte_carlo(solved, report, spreads, draws, lambda draw: solved.report(draw), arrays=arrays)
    return time.process_time() - started


def _argv(scene: str, given: dict, draws: int) -> list[str]:
    argv = [scene]
    for name, value in given.items():
        argv += [value] if (scene, name) == ("rolling", "shape") else [f"--{name.replace('_', '-')}", value]  # (rolling's shape is positional)
    return [*argv, "--mc", str(draws), "--no-limit", "--no-steps"]


def _whole(argv: list[str], hidden: bool) -> float:
    """CPU seconds (user + system) of the whole run in a subprocess."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    command = [sys.executable, "-c", HIDDEN, *argv] if hidden else [sys.executable, "-m", "taucli", *argv]
    subprocess.run(command, cwd=ROOT, capture_output=True, check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--draws", type=int, default=100_000)
    parser.add_argument("--scalar-draws", type=int, default=10_000)
    parser.add_argument("--runs", type=int, default=5)
    args = parser.parse_args()
    n, m = args.draws, args.scalar_draws
    print(f"{n:,} draws; CPU seconds, medians of {args.runs} runs; draw by draw timed at {m:,} draws and scaled")
    print(f"{'case':<55} {'MC arrays':>10} {'MC scalar':>10} {'ratio':>7} {'run arrays':>11} {'run scalar':>11}")
    for label, (scene, given) in CASES.items():
        fast = statistics.median(_monte_carlo(scene, given, n, True) for _ in range(args.runs))
        slow = statistics.median(_monte_carlo(scene, given, m, False) for _ in range(max(1, args.runs // 2))) * n / m
        argv = _argv(scene, given, n)
        run_fast = statistics.median(_whole(argv, False) for _ in range(args.runs))
        run_slow = _whole(argv, True)  # (one run: it takes seconds)
        print(f"{label:<55} {fast:>9.3f}s {slow:>9.2f}s {slow / fast:>6.0f}x {run_fast:>10.2f}s {run_slow:>10.1f}s")


if __name__ == "__main__":
    main()
