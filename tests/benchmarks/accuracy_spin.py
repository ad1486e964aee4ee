"""Measure the spin-down closed forms' error against 50-digit quadrature (run by hand).

    python tests/benchmarks/accuracy_spin.py [cases]

Draws friction + viscous + quadratic scenes over the whole valid space, a third of them at a
limit (b -> 0, k -> 0, D -> 0, tiny ω₀), and prints the largest error of t_stop and θ_stop in
ulp, with the scene that gave it.
"""

from __future__ import annotations

import random
import sys

import mpmath

from taucli.scenes.closed_forms import ClosedFormPhase

mpmath.mp.dps = 50
ULP = mpmath.mpf(2) ** -52


def reference(inertia, friction, viscous, drag, omega0):
    i, c, b, k, w0 = (mpmath.mpf(x) for x in (inertia, friction, viscous, drag, omega0))
    resisting = lambda u: c + b * w0 * u + k * (w0 * u) ** 2  # noqa: E731
    return i * w0 * mpmath.quad(lambda u: 1 / resisting(u), [0, 1]), i * w0**2 * mpmath.quad(lambda u: u / resisting(u), [0, 1])


def draw(rng: random.Random):
    inertia = 10 ** rng.uniform(-3, 3)
    friction = 10 ** rng.uniform(-3, 2)
    omega0 = 10 ** rng.uniform(-6, 4)
    viscous = 10 ** rng.uniform(-6, 2)
    drag = 10 ** rng.uniform(-8, 0)
    limit = rng.randrange(6)
    if limit == 0:
        viscous = 10 ** rng.uniform(-40, -9)
    elif limit == 1:
        drag = 10 ** rng.uniform(-40, -9)
    elif limit == 2:  # D = b² − 4kτ_f -> 0 from either side
        drag = viscous**2 / (4 * friction) * (1 + rng.choice((-1, 1)) * 10 ** rng.uniform(-15, -3))
    elif limit == 3:
        omega0 = 10 ** rng.uniform(-150, -6)
    return inertia, friction, viscous, drag, omega0


def main(cases: int) -> None:
    rng = random.Random(20261122)
    worst = {"t_stop": (0.0, None), "theta_stop": (0.0, None)}
    for _ in range(cases):
        scene = draw(rng)
        phase = ClosedFormPhase(scene[0], -scene[1], scene[2], scene[3], scene[4])
        t_stop = phase.stop_time()
        got = {"t_stop": t_stop, "theta_stop": phase.theta(t_stop)}
        exact = dict(zip(("t_stop", "theta_stop"), reference(*scene)))
        for name in got:
            ulps = float(abs(mpmath.mpf(got[name]) - exact[name]) / (abs(exact[name]) * ULP))
            if ulps > worst[name][0]:
                worst[name] = (ulps, scene)
    for name, (ulps, scene) in worst.items():
        print(f"{name}: at most {ulps:.1f} ulp over {cases} scenes (worst: I, τ_f, b, k, ω₀ = {scene})")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 5000)
