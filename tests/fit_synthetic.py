"""Synthetic measurements from the scenes' own forward models, with stated parameters and Gaussian
noise: the data of docs/fit.md where no published set was found, and of the coverage tests.

    python tests/fit_synthetic.py docs/data      # rewrites docs/data/phyphox-gyroscope.csv

Every table is made by ``taucli`` itself (``pipeline.solve``) at the parameters named here, then
rounded as an instrument would print it, with noise from ``random.Random(seed)``.
"""

from __future__ import annotations

import math
import random
import sys
from pathlib import Path

from taucli import pipeline
from taucli.options import SCENES


def solve(scene: str, **options) -> dict:
    report = pipeline.solve(SCENES[scene], options)
    return {key: value.value for key, value in report.results.items()}


# A turntable coasting down: I = 0.1 kg·m², ω₀ = 30 rad/s, friction 0.06 N·m, viscous 0.01 N·m·s.
COAST = {"inertia": 0.1, "omega0": 30.0, "friction": 0.06, "viscous": 0.01}


def coast_down(times, noise: float, seed: int, **options) -> list[tuple[float, float]]:
    rng = random.Random(seed)
    given = {**COAST, **options}
    return [(t, solve("spin-down", **given, time=t)["omega"] + rng.gauss(0.0, noise)) for t in times]


def csv(header: str, rows, formats) -> str:
    return header + "\n" + "".join(",".join(format(value, spec) for value, spec in zip(row, formats)) + "\n" for row in rows)


def java_float(x: float) -> str:
    """A number as phyphox writes it (Java's %E style: 1.234567890E-2)."""
    mantissa, exponent = f"{x:.9E}".split("E")
    return f"{mantissa}E{int(exponent)}"


def phyphox_gyroscope(seed: int = 7) -> str:
    """A phone lying on a turntable (I = 0.05 kg·m² with the phone), spun by hand for 1.5 s, then
    coasting under friction 0.02 N·m and viscous 0.004 N·m·s: phyphox's "Gyroscope" export at
    50 Hz for 20 s, noise 0.01 rad/s on each axis, a small wobble on x and y."""
    rng = random.Random(seed)
    push, omega_top = 1.5, 12.0
    rows = ['"Time (s)","Gyroscope x (rad/s)","Gyroscope y (rad/s)","Gyroscope z (rad/s)","Absolute (rad/s)"']
    for k in range(0, 1000):
        t = k / 50 + 0.0043
        if t < push:
            z = omega_top * (t / push) ** 2 * (1.2 - 0.2 * t / push)  # the hand's push: not the scene's model
        else:
            z = solve("spin-down", inertia=0.05, omega0=omega_top, friction=0.02, viscous=0.004, time=t - push)["omega"]
        x = 0.03 * math.sin(z * t) + rng.gauss(0, 0.01)
        y = 0.03 * math.cos(z * t) + rng.gauss(0, 0.01)
        z += rng.gauss(0, 0.01)
        rows.append(",".join(java_float(v) for v in (t, x, y, z, math.sqrt(x * x + y * y + z * z))))
    return "\n".join(rows) + "\n"


if __name__ == "__main__":
    folder = Path(sys.argv[1] if len(sys.argv) > 1 else "docs/data")
    (folder / "phyphox-gyroscope.csv").write_text(phyphox_gyroscope(), encoding="utf-8")
