"""Startup of whole runs against a naive typer + rich + pint script, medians and ratios (issue #7).

    python tests/benchmarks/startup.py [--runs 30]

Times whole processes with hyperfine when it is installed (else a subprocess loop), in one
run, so that the ratios compare like with like. The naive script is what one writes first: import
typer, rich and pint at the top, build a UnitRegistry (with pint's definition cache, so the
baseline is not a straw man), let typer parse the options. taucli runs
from the environment this script runs in (its console script beside sys.executable). Warm-up
runs fill taucli's unit cache first, as a user's second run would find it.

Targets: a computation at most 0.5x the naive script, --help at most 0.3x.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

NAIVE_SCRIPT = '''
import typer
import pint
from rich.console import Console

app = typer.Typer()
ureg = pint.UnitRegistry(cache_folder=":auto:")  # pint's own definition cache, as its docs advise


@app.command()
def atwood(m1: str = typer.Option(...), m2: str = typer.Option(...), pulley_mass: str = typer.Option("0 kg")):
    """Acceleration of an Atwood machine with a solid-disc pulley."""
    heavy = ureg.Quantity(m1).to("kg").magnitude
    light = ureg.Quantity(m2).to("kg").magnitude
    pulley = ureg.Quantity(pulley_mass).to("kg").magnitude
    a = (heavy - light) * 9.80665 / (heavy + light + pulley / 2)
    Console().print(f"a = {a:.6g} m/s^2")


if __name__ == "__main__":
    app()
'''

ATWOOD = ["atwood", "--m1", "4kg", "--m2", "1kg", "--pulley-mass", "2kg"]
TARGETS = {"computation": 0.5, "help": 0.3}


def cases(taucli: str, naive: str) -> list[tuple[str, list[str], str | None]]:
    """(name, command, target group) for each whole run timed."""
    python = sys.executable
    return [
        ("python -c pass", [python, "-c", "pass"], None),
        ("naive typer+rich+pint script", [python, naive, *ATWOOD[1:]], None),
        ("taucli atwood ... --get a", [taucli, *ATWOOD, "--get", "a"], "computation"),
        ("taucli atwood ... (table and steps)", [taucli, *ATWOOD], None),
        ("taucli atwood ... --json", [taucli, *ATWOOD, "--json"], None),
        # Help is written from the tables and keeps nothing: timed with caching off (issue #17).
        ("TAUCLI_CACHE_DIR= taucli --help", ["env", "TAUCLI_CACHE_DIR=", taucli, "--help"], "help"),
        ("TAUCLI_CACHE_DIR= taucli atwood --help", ["env", "TAUCLI_CACHE_DIR=", taucli, "atwood", "--help"], "help"),
    ]


def with_hyperfine(commands: list[list[str]], runs: int) -> list[float]:
    """Median wall time in seconds of each command, from hyperfine's JSON export."""
    with tempfile.TemporaryDirectory() as scratch:
        export = Path(scratch) / "times.json"
        subprocess.run(
            ["hyperfine", "-N", "--style", "none", "--warmup", "3", "--runs", str(runs), "--export-json", str(export)]
            + [" ".join(_quote(word) for word in command) for command in commands],
            check=True,
            stdout=subprocess.DEVNULL,
        )
        return [result["median"] for result in json.loads(export.read_text())["results"]]


def with_subprocess(commands: list[list[str]], runs: int) -> list[float]:
    """Median wall time of each command, runs interleaved so drift hits all alike."""
    times: list[list[float]] = [[] for _ in commands]
    for round_number in range(runs + 3):
        for index, command in enumerate(commands):
            start = time.perf_counter()
            subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
            if round_number >= 3:
                times[index].append(time.perf_counter() - start)
    return [statistics.median(spread) for spread in times]


def _quote(word: str) -> str:
    return word if all(ch.isalnum() or ch in "-_./=" for ch in word) else "'" + word.replace("'", "'\\''") + "'"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=30)
    args = parser.parse_args()
    taucli = str(Path(sys.executable).with_name("taucli"))
    if not os.path.exists(taucli):
        print(f"no taucli beside {sys.executable}: install taucli in this environment", file=sys.stderr)
        return 2
    with tempfile.TemporaryDirectory() as scratch:
        naive = str(Path(scratch) / "naive_atwood.py")
        Path(naive).write_text(NAIVE_SCRIPT)
        table = cases(taucli, naive)
        commands = [command for _, command, _ in table]
        for command in commands:  # each must work before it is timed
            subprocess.run(command, stdout=subprocess.DEVNULL, check=True)
        tool = "hyperfine" if shutil.which("hyperfine") else "subprocess loop"
        medians = with_hyperfine(commands, args.runs) if tool == "hyperfine" else with_subprocess(commands, args.runs)
    naive_median = medians[1]
    print(f"whole runs, median of {args.runs} ({tool}); ratio = median / naive script's median")
    missed = 0
    for (name, _, target), median in zip(table, medians):
        ratio = median / naive_median
        verdict = ""
        if target is not None:
            limit = TARGETS[target]
            verdict = f"target <= {limit}x: " + ("met" if ratio <= limit else "MISSED")
            missed += ratio > limit
        print(f"  {name:<38} {median * 1000:7.1f} ms  {ratio:5.2f}x  {verdict}")
    return 1 if missed else 0


if __name__ == "__main__":
    sys.exit(main())
