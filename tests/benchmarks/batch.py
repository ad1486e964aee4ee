"""Batch mode throughput and memory: Atwood scenes per second, and peak memory (issue #7).

    python tests/benchmarks/batch.py [--lines 100000] [--repeats 3]

Writes LINES random Atwood scenes (seeded; unit strings such as "3.217kg" and "1.5 kg", as a
script would send) to a file, and runs `taucli atwood --batch` on it in a subprocess, with and
without --no-steps. Each run reports its own peak memory (VmHWM). Prints the median rate over
the repeats, and, to place the machine, how long pint takes to parse one quantity here (the
issue quotes about 100 us on its machine).
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


def run(scenes: Path, extra: list[str]) -> tuple[float, int, int]:
    """(seconds, peak KiB, output lines) of one batch run."""
    with scenes.open() as source, tempfile.TemporaryFile("w+") as sink:
        start = time.perf_counter()
        done = subprocess.run(
            [sys.executable, "-c", MEASURED, "atwood", "--batch", *extra], stdin=source, stdout=sink, stderr=subprocess.PIPE, text=True
        )
        elapsed = time.perf_counter() - start
        if done.returncode != 0:
            raise SystemExit(f"batch run failed: {done.stderr}")
        sink.seek(0)
        count = sum(1 for _ in sink)
    return elapsed, int(done.stderr.split("peak_kib")[-1]), count


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
    print(f"pint parses '4 kg' in {pint_parse_us():.0f} us on this machine (the issue: about 100 us)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
