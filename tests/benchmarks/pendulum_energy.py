"""Energy drift against periods simulated, per stepper, on θ'' = −sin θ from rest at 60° (#19).

Run by hand: python tests/benchmarks/pendulum_energy.py [periods]. Prints, for each method at a
step of T/40 (T the exact period), the relative energy error after 1, 10, 100, ... periods and
the time per step. Explicit Euler's energy grows, RK4's decays in proportion to the time, and
velocity Verlet's stays within its (hω)² oscillation however long the run.
"""

from __future__ import annotations

import math
import sys
import time

from taucli.numerics.steppers.elliptic import complete_k
from taucli.numerics.steppers import integrate_angle

THETA0 = math.radians(60)


def energy(theta: float, omega: float) -> float:
    return omega * omega / 2 + 2 * math.sin(theta / 2) ** 2


def main(periods: int = 10_000) -> None:
    period = 4 * complete_k(math.cos(THETA0 / 2))
    dt = period / 40
    start = energy(THETA0, 0.0)
    marks = [10**k for k in range(int(math.log10(periods)) + 1)]
    print(f"θ₀ = 60°, T = {period:.15g} s, dt = T/40; relative energy error after N periods")
    print(f"{'method':8}" + "".join(f"{n:>12}" for n in marks) + f"{'µs/step':>10}")
    for method in ("euler", "rk4", "verlet"):
        theta, omega, done, row, steps = THETA0, 0.0, 0, [], 0
        began = time.perf_counter()
        for mark in marks:
            solution = integrate_angle(lambda th: -math.sin(th), theta, omega, (mark - done) * period, method, dt=dt, max_steps=10**9)
            theta, omega, done, steps = solution.theta, solution.omega, mark, steps + solution.steps
            row.append(energy(theta, omega) / start - 1 if math.isfinite(theta) else math.nan)
        per_step = (time.perf_counter() - began) / steps * 1e6
        print(f"{method:8}" + "".join(f"{e:>12.3g}" for e in row) + f"{per_step:>10.2f}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 10_000)
