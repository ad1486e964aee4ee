"""Batch mode throughput and memory: Atwood scenes per second, and peak memory (issue #7).

    python tests/benchmarks/batch.py [--lines 100000] [--repeats 3]

Writes LINES random Atwood scenes (seeded; unit strings such as "3.217kg" and "1.5 kg", as a
script would send) to a file, and runs `taucli atwood --batch` on it in a subprocess, with and
without --no-steps. Each run reports its own peak memory (VmHWM). Prints the median rate over
the repeats, and, to place the machine, how long pint takes to parse one quantity here (the
issue quotes about 100 us on its machine).

It also runs FLOOR, the least a Python program can do under the same contract: read each JSON
line, look its four units up in a dict, work the massive-pulley formulas inline, and write the
same document (checked against taucli's, key for key), flushed per line. No validation, no
notes logic, no other scene. Its rate is the ceiling for any pure-Python taucli on this machine.
"""

from __future__ import annotations

import argparse
import json
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
        "notes": ["g = 9.80665 m/s\u00b2 (standard gravity); --g to change it",
                  "pulley taken as a uniform solid disc (I = \u00bdMR\u00b2); --pulley-shape ring for a thin ring",
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


def run(scenes: Path, extra: list[str], program: str = MEASURED) -> tuple[float, int, int, str]:
    """(seconds, peak KiB, output lines, first output line) of one batch run."""
    with scenes.open() as source, tempfile.TemporaryFile("w+") as sink:
        start = time.perf_counter()
        done = subprocess.run(
            [sys.executable, "-c", program, "atwood", "--batch", *extra], stdin=source, stdout=sink, stderr=subprocess.PIPE, text=True
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
        scenes = Path(scratch) / "scenes.jsonl"
        write_scenes(scenes, args.lines)
        print(f"{args.lines} Atwood scenes, median of {args.repeats} runs (one process each, one core)")
        for extra in (["--no-steps"], []):
            runs = [run(scenes, extra) for _ in range(args.repeats)]
            seconds = statistics.median(r[0] for r in runs)
            peak = max(r[1] for r in runs)
            assert all(r[2] == args.lines for r in runs), "one output line per input line"
            label = "taucli atwood --batch " + " ".join(extra)
            print(f"  {label:<34} {args.lines / seconds:8.0f} scenes/s  ({seconds:.2f} s)  peak {peak / 1024:.1f} MiB")
            if extra:
                ours, ours_seconds = runs[0][3], seconds
        floors = [run(scenes, [], FLOOR) for _ in range(args.repeats)]
        assert same_documents(ours, floors[0][3]), "the floor program writes taucli's document"
        floor_seconds = statistics.median(r[0] for r in floors)
        print(f"  {'floor: minimal Python, same I/O':<34} {args.lines / floor_seconds:8.0f} scenes/s  ({floor_seconds:.2f} s)")
        print(f"  taucli --no-steps runs at {floor_seconds / ours_seconds:.2f}x the floor's rate")
    print(f"pint parses '4 kg' in {pint_parse_us():.0f} us on this machine (the issue: about 100 us)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
