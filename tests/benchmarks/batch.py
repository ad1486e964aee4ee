"""Batch mode throughput and memory: Atwood scenes per second, and peak memory (issue #7).

    python tests/benchmarks/batch.py [--lines 100000] [--repeats 3]

Writes LINES random Atwood scenes (seeded; unit strings such as "3.217kg" and "1.5 kg", as a
script would send) to a file, and runs `taucli atwood --batch` on it in a subprocess, with and
without --no-steps, and a spin-down batch beside it. Each run reports its own peak memory
(VmHWM). The cases are run in turn, REPEATS rounds (interleaved: a busy spell of the machine
falls on every case alike); prints each case's median rate, the ratio of taucli's --no-steps
rate to the floor's (#45 item 6: the target is 0.6x or more), and, to place the machine, how
long pint takes to parse one quantity here (the issue quotes about 100 us on its machine).

It also runs FLOOR, the least a Python program can do under the same contract: read each JSON
line, look its four units up in a dict, work the massive-pulley formulas inline, and write the
same document (checked against taucli's, key for key), flushed per line. No validation, no
notes logic, no other scene. Its rate is the ceiling for any pure-Python taucli on this machine.
"""

from __future__ import annotations

import argparse
import json
import os
import random
import statistics
import subprocess
import sys
import tempfile
import time
import timeit
from pathlib import Path

MEASURED = (
    "import runpy, sys\n"
    "sys.argv = ['taucli', *sys.argv[1:]]\n"
    "try:\n    runpy.run_module('taucli', run_name='__main__')\n"
    "finally:\n"
    "    peak = open('/proc/self/status').read().split('VmHWM:')[1].split()[0]\n"
    "    print('peak_kib', peak, file=sys.stderr)\n"
)


FLOOR = r"""
import json, re, sys
NUMBER_UNIT = re.compile(r"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*")
FACTOR = {"kg": 1.0, "cm": 0.01}
encoder = json.JSONEncoder(ensure_ascii=False, allow_nan=False, separators=(",", ":"))
decoder = json.JSONDecoder()
def si(text):
    number, unit = NUMBER_UNIT.fullmatch(text).groups()
    return float(number) * FACTOR[unit]
for line in sys.stdin:
    scene = decoder.decode(line)
    m1, m2, pulley_mass, radius = (si(scene[key]) for key in ("m1", "m2", "pulley_mass", "pulley_radius"))
    g = 9.80665
    moving_mass = m1 + m2 + pulley_mass / 2
    a = (m1 - m2) * g / moving_mass
    document = {
        "taucli": "0.1.0", "scene": "atwood", "model": "massive pulley (solid disc), string does not slip", "method": "closed form",
        "inputs": {"m1": {"value": m1, "unit": "kg"}, "m2": {"value": m2, "unit": "kg"}, "pulley_mass": {"value": pulley_mass, "unit": "kg"},
                   "pulley_radius": {"value": radius, "unit": "m"}, "g": {"value": g, "unit": "m/s**2"}},
        "results": {
            "a": {"value": a, "unit": "m/s**2", "label": "acceleration of the masses (m1 downward positive)"},
            "T1": {"value": m1 * (g - a), "unit": "N", "label": "tension on m1's side"},
            "T2": {"value": m2 * (g + a), "unit": "N", "label": "tension on m2's side"},
            "alpha": {"value": a / radius, "unit": "rad/s**2", "label": "angular acceleration of the pulley"},
            "a_massless": {"value": (m1 - m2) * g / (m1 + m2), "unit": "m/s**2", "label": "acceleration with a massless pulley, for comparison"},
        },
        "steps": [],
        "notes": ["g = 9.80665 m/s\u00b2 (standard gravity); g to change it",
                  "pulley taken as a uniform solid disc (I = \u00bdMR\u00b2); pulley_shape ring for a thin ring",
                  "the string taken not to slip on the pulley (a = \u03b1R): friction at the rim turns it"],
    }
    sys.stdout.write(encoder.encode(document) + "\n")
    sys.stdout.flush()
"""


def same_documents(ours: str, floor: str) -> bool:
    """The same keys, texts and numbers (to 1e-12 relative: the formulas are arranged differently)."""

    def same(x, y) -> bool:
        if isinstance(x, dict):
            return isinstance(y, dict) and x.keys() == y.keys() and all(same(x[k], y[k]) for k in x)
        if isinstance(x, list):
            return isinstance(y, list) and len(x) == len(y) and all(map(same, x, y))
        if isinstance(x, float) and isinstance(y, float):
            return abs(x - y) <= 1e-12 * max(abs(x), abs(y))
        return x == y

    return same(json.loads(ours), json.loads(floor))


def write_scenes(path: Path, lines: int) -> None:
    rng = random.Random(7)
    with path.open("w") as handle:
        for _ in range(lines):
            scene = {
                "m1": f"{rng.uniform(1, 10):.3f}kg",
                "m2": f"{rng.uniform(0, 5):.3f} kg",
                "pulley_mass": f"{rng.uniform(0, 3):.2f}kg",
                "pulley_radius": "10cm",
            }
            handle.write(json.dumps(scene) + "\n")


def write_spins(path: Path, lines: int) -> None:
    """Spin-down scenes beside the Atwood ones: a disc coasting against friction (closed form)."""
    rng = random.Random(11)
    with path.open("w") as handle:
        for _ in range(lines):
            scene = {"shape": "disc", "mass": f"{rng.uniform(1, 10):.3f} kg", "radius": f"{rng.uniform(5, 50):.1f} cm",
                     "omega0": f"{rng.uniform(100, 3000):.0f} rpm", "friction": f"{rng.uniform(0.05, 1):.3f} N*m"}
            handle.write(json.dumps(scene) + "\n")


def run(scenes: Path, extra: list[str], program: str = MEASURED, scene: str = "atwood", env: dict | None = None) -> tuple[float, int, int, str]:
    """(seconds, peak KiB, output lines, first output line) of one batch run."""
    with scenes.open() as source, tempfile.TemporaryFile("w+") as sink:
        start = time.perf_counter()
        done = subprocess.run(
            [sys.executable, "-c", program, scene, "--batch", *extra], stdin=source, stdout=sink, stderr=subprocess.PIPE, text=True, env=env
        )
        elapsed = time.perf_counter() - start
        if done.returncode != 0:
            raise SystemExit(f"batch run failed: {done.stderr}")
        sink.seek(0)
        first = sink.readline()
        count = 1 + sum(1 for _ in sink) if first else 0
    peak = done.stderr.split("peak_kib")[-1] if "peak_kib" in done.stderr else "0"
    return elapsed, int(peak), count, first


def pint_parse_us() -> float:
    import pint

    ureg = pint.UnitRegistry(cache_folder=":auto:")
    ureg.Quantity("4 kg")
    return min(timeit.repeat(lambda: ureg.Quantity("4 kg"), number=500, repeat=5)) / 500 * 1e6


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--lines", type=int, default=100_000)
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as scratch:
        scenes, spins = Path(scratch) / "scenes.jsonl", Path(scratch) / "spins.jsonl"
        write_scenes(scenes, args.lines)
        write_spins(spins, args.lines)
        print(f"{args.lines} scenes a run, median of {args.repeats} interleaved runs (one process each, one core)")
        cases = {  # label -> (program, scene, input, options)
            "taucli atwood --batch --no-steps": (MEASURED, "atwood", scenes, ["--no-steps"]),
            "floor: minimal Python, same I/O": (FLOOR, "atwood", scenes, []),
            "taucli atwood --batch": (MEASURED, "atwood", scenes, []),
            "taucli spin-down --batch --no-steps": (MEASURED, "spin-down", spins, ["--no-steps"]),
        }
        # taucli's modules compiled once, as an installed taucli has them (PYTHONDONTWRITEBYTECODE
        # would have every run compile them again: start-up that no user pays)
        env = {name: value for name, value in os.environ.items() if name != "PYTHONDONTWRITEBYTECODE"}
        env["PYTHONPYCACHEPREFIX"] = str(Path(scratch) / "bytecode")
        run(scenes, ["--no-steps"], env=env)
        runs: dict[str, list] = {label: [] for label in cases}
        for _ in range(args.repeats):  # interleaved: a slow spell of the machine falls on every case alike
            for label, (program, scene, source, extra) in cases.items():
                runs[label].append(run(source, extra, program, scene, env))
        seconds = {}
        for label, done in runs.items():
            assert all(r[2] == args.lines for r in done), "one output line per input line"
            seconds[label] = statistics.median(r[0] for r in done)
            peak = max(r[1] for r in done)
            memory = f"  peak {peak / 1024:.1f} MiB" if peak else ""
            print(f"  {label:<36} {args.lines / seconds[label]:8.0f} scenes/s  ({seconds[label]:.2f} s){memory}")
        ours = runs["taucli atwood --batch --no-steps"][0][3]
        assert same_documents(ours, runs["floor: minimal Python, same I/O"][0][3]), "the floor program writes taucli's document"
        ratio = seconds["floor: minimal Python, same I/O"] / seconds["taucli atwood --batch --no-steps"]
        print(f"  taucli atwood --batch --no-steps runs at {ratio:.2f}x the floor's rate (target: 0.6x or more)")
    print(f"pint parses '4 kg' in {pint_parse_us():.0f} us on this machine (the issue: about 100 us)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
