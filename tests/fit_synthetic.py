"""Synthetic measurements from the scenes' own forward models, with stated parameters and Gaussian
noise: the data of docs/fit.md where no published set was found, and of the coverage tests.

    python tests/fit_synthetic.py docs/data      # rewrites docs/data/phyphox-gyroscope.csv and damped-swing.csv

and ``docs_tables()`` gives the short tables docs/fit.md shows.

Every table is made by ``taucli`` itself (``pipeline.solve``) at the parameters named here, then
rounded as an instrument would print it, with noise from ``random.Random(seed)``.
"""

from __future__ import annotations

import math
import random
import sys
from pathlib import Path

from taucli.answering import pipeline
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


def decimal_comma(text: str, header: str) -> str:
    """A comma-separated table as a spreadsheet in a decimal-comma locale saves it: semicolons
    between the cells, a comma in each number."""
    rows = text.splitlines()[1:]
    return header + "\n" + "".join(row.replace(",", ";").replace(".", ",") + "\n" for row in rows)


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


def damped_swing(seed: int = 8) -> str:
    """A 200 g bob on 0.8 m swinging in air (b = 0.004 N·m·s, g = 9.81 m/s²), released from rest at
    20° 0.35 s before the recording starts: θ(t) at 20 Hz for 15 s, noise 0.004 rad (a rotary
    sensor's export)."""
    rng = random.Random(seed)
    swing = dict(shape="point", mass=0.2, radius=0.8, g=9.81, angle0=math.radians(20), viscous=0.004, start_time=-0.35)
    rows = [(k / 20, solve("pendulum", **swing, time=k / 20)["theta"] + rng.gauss(0, 0.004)) for k in range(300)]
    return csv("t (s),theta (rad)", rows, ("g", ".4f"))


def docs_tables() -> dict[str, str]:
    """The short tables docs/fit.md shows (``cat``), each from its scene at the parameters named."""
    rng = random.Random(12)
    friction = [(t, solve("spin-down", inertia=0.1, omega0=30, friction=0.3, time=t)["omega"] + rng.gauss(0, 0.05)) for t in range(10)]
    rng = random.Random(13)
    spin_up = [(t, 0.05, 0, solve("spin-down", inertia=0.02, omega0=0, torque=0.05, friction=0.004, time=t)["omega"] + rng.gauss(0, 0.02)) for t in range(1, 7)]
    spin_up += [(t, 0, 12, solve("spin-down", inertia=0.02, omega0=12, friction=0.004, time=t)["omega"] + rng.gauss(0, 0.02)) for t in range(1, 7)]
    rng = random.Random(14)
    periods = [(a, solve("pendulum", shape="point", mass=0.05, radius=1.0, angle0=math.radians(a), g=9.81)["period"] + rng.gauss(0, 0.002))
               for a in (10, 20, 30, 40, 50, 60, 70, 80)]
    rng = random.Random(15)
    ramp = [(a, length, solve("rolling", shape="shell", angle=math.radians(a), length=length)["t"] + rng.gauss(0, 0.005)) for a in (4, 8, 12) for length in (0.5, 1.0)]
    rng = random.Random(16)
    torsion = [(m, solve("pendulum", shape="point", mass=m / 1000, radius=0.1, part=["inertia=0.001"], cm_distance=0, torsion=0.01)["period"]
                + rng.gauss(0, 0.002)) for m in (50, 100, 150, 200, 250)]
    coast = csv("t (s),omega (rad/s)", coast_down([1.5 * i for i in range(12)], 0.05, 11), ("g", ".3f"))
    rng = random.Random(17)  # lengths to the top of a bob of radius 1.9 cm, periods at 10°
    lengths = [(length, solve("pendulum", shape="point", mass=0.05, radius=length + 0.019, angle0=math.radians(10), g=9.81)["period"]
                + rng.gauss(0, 0.002)) for length in (0.3, 0.5, 0.7, 0.9, 1.1)]
    rng = random.Random(18)  # a coast under drag kω^1.5 alone: k = 0.002 N·m·s^1.5, I = 0.1 kg·m², ω₀ = 30 rad/s
    drag = [(t, solve("spin-down", inertia=0.1, omega0=30, drag=0.002, drag_exponent=1.5, time=t)["omega"] + rng.gauss(0, 0.05)) for t in range(0, 24, 2)]
    return {
        "coast.csv": coast,
        "coast-de.csv": decimal_comma(coast, "t [s];omega [rad/s]"),
        "torsion.csv": csv("mass (g),period (s)", torsion, ("g", ".3f")),
        "friction.csv": csv("t (s),omega (rad/s)", friction, ("g", ".3f")),
        "pasco.csv": csv("Time (ms) Run #1,Angular Velocity (rad/s) Run #1", [(1000 * t, w) for t, w in friction], ("g", ".3f")),
        "millis.csv": csv("millis,omega (rad/s)", [(1000 * t, w) for t, w in friction[:4]], ("g", ".3f")),
        "spin-up.csv": csv("t (s),torque (N*m),omega0 (rad/s),omega (rad/s)", spin_up, ("g", "g", "g", ".3f")),
        "periods.csv": csv("amplitude (deg),period (s)", periods, ("g", ".4f")),
        "ramp.csv": csv("angle (deg),length (m),t (s)", ramp, ("g", "g", ".3f")),
        "lengths.csv": csv("L (m),period (s)", lengths, ("g", ".4f")),
        "drag.csv": csv("t (s),omega (rad/s)", drag, ("g", ".3f")),
    }


if __name__ == "__main__":
    folder = Path(sys.argv[1] if len(sys.argv) > 1 else "docs/data")
    (folder / "phyphox-gyroscope.csv").write_text(phyphox_gyroscope(), encoding="utf-8")
    (folder / "damped-swing.csv").write_text(damped_swing(), encoding="utf-8")
