"""A first run (an empty cache folder, made fresh before each run) against a warm one, for a
calculation and for --help; this checkout against another (main, say), interleaved round by
round so that a loaded machine's load falls on all alike. Medians of wall and CPU time.

    python tests/benchmarks/first_run.py [ROUNDS] [OTHER_CHECKOUT]

The figures in docs/running.md ("The first run") come from it.
"""

from __future__ import annotations

import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CALC = "atwood --m1 4kg --m2 1kg --pulley-mass 2kg --pulley-radius 0.1m".split()
HELP = "atwood --help".split()


def run(tree: str, args: list[str], folder: str, first: bool) -> tuple[float, float]:
    if first:
        shutil.rmtree(folder, ignore_errors=True)
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONDONTWRITEBYTECODE", "TAUCLI_CACHE_DIR")}
    env.update(XDG_CACHE_HOME=folder, PYTHONPATH=tree)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    # cwd: not a checkout (python -m puts the working folder first on sys.path)
    subprocess.run([sys.executable, "-m", "taucli", *args], env=env, cwd=tempfile.gettempdir(), stdout=subprocess.DEVNULL, check=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime


def main() -> None:
    rounds = int(sys.argv[1]) if len(sys.argv) > 1 else 15
    trees = [("this checkout", HERE)] + ([("other", os.path.abspath(sys.argv[2]))] if len(sys.argv) > 2 else [])
    scratch = tempfile.mkdtemp(prefix="taucli-first-run-")
    configs = [
        (f"{label}: {what}, {'first run' if first else 'warm'}", tree, args, os.path.join(scratch, f"{n}-{first}"), first)
        for n, (label, tree) in enumerate(trees) for what, args in (("calculation", CALC), ("--help", HELP)) for first in (True, False)
    ]
    for _, tree, args, folder, first in configs:  # the warm folders filled, the bytecode written
        if not first:
            run(tree, args, folder, first)
    times: dict[str, list[tuple[float, float]]] = {name: [] for name, *_ in configs}
    for _ in range(rounds):
        for name, tree, args, folder, first in configs:
            times[name].append(run(tree, args, folder, first))
    for name, *_ in configs:
        walls, cpus = zip(*times[name])
        print(f"{name:36s} wall median {statistics.median(walls) * 1000:6.0f} ms   CPU median {statistics.median(cpus) * 1000:5.0f} ms")
    shutil.rmtree(scratch, ignore_errors=True)


if __name__ == "__main__":
    main()
