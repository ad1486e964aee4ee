"""Time per solve and error of each spin-down method on two scenes (run by hand).

    python tests/benchmarks/methods_spin.py

Scenes: the article's potter's wheel (I = 0.1 kg·m², τ_f = 0.3 N·m, ω₀ = 30 rad/s), and a coast
under friction, viscous and quadratic drag (τ_f = 0.3 N·m, b = 0.01 N·m·s, k = 0.001 N·m·s²).
Error: the larger relative error of t_stop and θ_stop against 50-digit quadrature. Time: median of
repeated in-process solves (timeit), per solve.
"""

from __future__ import annotations

import statistics
import timeit

import mpmath

from taucli.scenes.spin import Torques, solve

mpmath.mp.dps = 50
SCENES = {
    "potter's wheel": (0.1, Torques(friction=0.3), 30.0),
    "friction + viscous + drag": (0.1, Torques(friction=0.3, viscous=0.01, drag=0.001), 30.0),
}
METHODS = [("exact", None), ("euler", 1e-2), ("euler", 1e-3), ("euler", 1e-4), ("rk4", 1e-1), ("rk4", 1e-2), ("rk4", 1e-3), ("rk45", None)]


def reference(inertia, torques, omega0):
    c, b, k = (mpmath.mpf(x) for x in (torques.friction, torques.viscous, torques.drag))
    resisting = lambda w: c + b * w + k * w**2  # noqa: E731
    return mpmath.quad(lambda w: inertia / resisting(w), [0, omega0]), mpmath.quad(lambda w: inertia * w / resisting(w), [0, omega0])


def main() -> None:
    print(f"{'scene':28} {'method':16} {'time/solve':>12} {'rel. error':>11}")
    for scene, (inertia, torques, omega0) in SCENES.items():
        t_ref, theta_ref = reference(inertia, torques, omega0)
        for method, dt in METHODS:
            # estimate_error=False: the method alone (with it, a fixed step also runs the closed
            # form for its error estimate, and withholds answers more than 1e-3 off)
            run = lambda: solve(inertia, torques, omega0, method=method, dt=dt, estimate_error=False)  # noqa: E731
            report = run()
            error = max(
                float(abs(mpmath.mpf(report.results["t_stop"].value) - t_ref) / t_ref),
                float(abs(mpmath.mpf(report.results["theta_stop"].value) - theta_ref) / theta_ref),
            )
            number = max(1, int(0.2 / max(timeit.timeit(run, number=1), 1e-7)))
            per_solve = statistics.median(timeit.repeat(run, number=number, repeat=5)) / number
            label = method if dt is None else f"{method} dt={dt:g}"
            print(f"{scene:28} {label:16} {per_solve * 1e6:10.1f} µs {error:11.1e}")


if __name__ == "__main__":
    main()
