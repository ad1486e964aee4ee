"""Fuzzing every scene's entry point with hostile command lines (issue #9); see tests/fuzzing.py.

The default run tries 60 vectors a scene (300 in all). The opt-in run tries many more:

    TAUCLI_FUZZ_EXAMPLES=10000 python -m pytest -s tests/front/test_fuzz.py

and prints how many vectors each scene ran (with -s: pytest drops a passing run's output). A vector that once broke the contract is kept in
FOUND below, with the seed that found it, and runs in every test run.
"""

from __future__ import annotations

import os
from collections import Counter

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from fuzzing import SCENES, Vector, profile_files, run, scratch_folder, vectors
from fuzzing_commands import BENCH_SECONDS, COMMANDS, FIT_LIMIT, FIT_SECONDS, vectors_of, write_docs_tables

EXAMPLES = int(os.environ.get("TAUCLI_FUZZ_EXAMPLES", "60"))
_scratch = scratch_folder()
FILES = profile_files(__import__("pathlib").Path(_scratch.name))
FIT_RUNS = write_docs_tables(__import__("pathlib").Path(_scratch.name))
SECONDS_OF = {"fit": FIT_SECONDS, "bench": BENCH_SECONDS}
TRIED: Counter[str] = Counter()

# Each was found by the fuzz suite, and is fixed; the seed is hypothesis's, printed with the failure.
FOUND = [
    # exit 1: rk45 settling on a stiff steady speed was called unstable (seed found by hand first)
    Vector("spin-down", ["--inertia", "1", "--torque", "1", "--viscous", "0.1", "--drag", "0.01", "--drag-exponent", "3.3", "--method", "rk45", "--time", "1999s", "--json"]),
    # exit 1: --out in a folder that does not exist reached matplotlib's savefig
    Vector("atwood", ["--m2=0.817oz,0.01kg", "--m1=1.5mg", "--out=/nonexistent/dir/c.svg", "--pulley-radius=0.01m", "--no-steps"]),
    # exit 2 after the answer was printed: /proc/c.svg passes os.access for root, then cannot be created
    Vector("atwood", ["--m1", "0.01kg", "--out", "/proc/c.svg", "--no-steps"]),
    # exit 1: an inertia of 5e-324 gives infinite speeds in the profile's table, which strict JSON refused
    Vector("impulse", ["--inertia", "5e-324kg*m^2", "--torque-profile", "{good}", "--method", "simpson", "--jsonl"]),
    # exit 1: float ** raised OverflowError for lengths and masses of 1e185
    Vector("inertia", ["rod", "--mass", "1.5187990587061118e+185kg", "--length", "1.5187990587061118e+185m", "--axis", "end", "--json", "--no-steps"]),
    # exit 1: a skidding ball with μk = 0 divided by zero for the time it takes to roll
    Vector("rolling", ["sphere", "--v0", "1m/s", "--mu-k", "0"]),
    # exit 1: rk45 overflowed (ω not finite) and the advice to lower --dt multiplied rk45's dt of None
    Vector("spin-down", ["--shape", "disc", "--mass", "8kg", "--radius", "1e-08m", "--force", "1.7e308N", "--lever", "1e-08m", "--push-angle", "60deg", "--time", "4s", "--method", "rk45", "--json"]),
    # exit 1: a radius of 1e-320 m made I = ½MR² underflow to 0, a divisor
    Vector("spin-down", ["--shape", "disc", "--mass", "8kg", "--radius", "1e-320m", "--force", "6N", "--lever", "0.25m", "--time", "4s", "--method", "rk45"]),
    # 1.1-1.2 s: the plot's 201 samples each integrated from 0 (rk45, power-law drag)
    Vector("spin-down", ["--inertia", "1kg*m^2", "--omega0", "1e+07rad/s", "--drag", "0.01N*m*s^2", "--drag-exponent", "2.5", "--until-omega", "10rad/s", "--json", "--plot"]),
    # 9.5-13.5 s: a million rk4 steps were allowed (2 million per integration)
    Vector("spin-down", ["--inertia", "1kg*m^2", "--omega0", "10rad/s", "--friction", "1N*m", "--viscous", "0.01N*m*s", "--method", "rk4", "--dt", "0.01ms", "--jsonl"]),
    # exit 1: float ** overflowed in rk4 for I and ω₀ of 1e300 (now refused as out of range when read)
    Vector("spin-down", ["--inertia", "1e300kg*m^2", "--omega0", "1e300rad/s", "--friction", "6.5699540919324514e-80N*m", "--viscous", "0.5N*m*s", "--method", "rk4", "--dt", "10ms", "--json"]),
    # exit 1: rk4 far past its stability limit reached inf − inf inside fsum (10,000-vector run)
    Vector("spin-down", ["--inertia", "0.9999999999999999kg*m^2", "--omega0", "10rad/s", "--friction", "1N*m", "--viscous", "1e9N*m*s", "--method", "rk4", "--dt", "10ms"]),
    # hang (20 s, memory growing): a torque profile from a file with no line end was read as one endless line
    Vector("impulse", ["--duration", "15.6µs", "--torque=23.7kN*m", "--inertia", "4.76g*cm^2", "--torque-profile", "/dev/zero", "--method=auto"]),
    # hours and memory without bound: a range of 10,000 points times a list of 10,000 values (found in review; the grammar
    # then gained long lists, and a 5,000-value list took 18 s: a sweep now has at most 200 points)
    Vector("atwood", ["--m1", "1..2kg", "--points", "10000", "--m2", ",".join(["1kg"] * 10000), "--get", "a"]),
    # exit 1 (#34, found while the grammar learned --pull): pulls on string ends with no mass and a pulley of I = 0 divided by zero
    Vector("atwood", ["--pull", "force=15N", "--pull", "force=5N on=2", "--pulley-radius", "33cm", "--pulley-inertia", "0kg*m^2", "--v0", "-2m/s"]),
    # exit 1 (#33): time steps of 1e-200 s divided by zero, with either rule
    Vector("impulse", ["--inertia", "1kg*m^2", "--omega0", "0", "--torque-profile", "{tiny_steps}", "--method", "trapezoid"]),
    # exit 1 (#33): a batch line nested 1,000 deep (RecursionError), and "to" that is not a text (AttributeError)
    Vector("atwood", ["--batch"], "[" * 1000 + "]" * 1000 + "\n" + '{"m1": "4kg", "to": true}\n{"m1": "4kg", "to": [1]}'),
]


@pytest.fixture(scope="module", autouse=True)
def tally(pytestconfig):
    """How many vectors each scene ran, on the terminal whatever pytest captures."""
    yield
    reporter = pytestconfig.pluginmanager.get_plugin("terminalreporter")
    if TRIED and reporter is not None:
        reporter.write_line(f"fuzz: {dict(TRIED)} vectors per scene, {EXAMPLES} asked for each")


def _check(vector: Vector) -> None:
    outcome = run(vector, _scratch.name, **({"seconds": SECONDS_OF[vector.scene]} if vector.scene in SECONDS_OF else {}))
    assert not outcome.problems, f"{vector!r}\n  -> {outcome.problems}\n  stderr: {outcome.err[-800:]}"


@pytest.fixture(scope="module", autouse=True)
def warm():
    """Build the unit registry and import matplotlib once, so the first vector's time is its own."""
    run(Vector("atwood", ["--m1", "4 furlong*kg/furlong", "--out", "warm.svg"]), _scratch.name)


@pytest.mark.parametrize("scene", SCENES)
def test_hostile_command_lines_keep_the_contract(scene):
    @settings(max_examples=EXAMPLES, deadline=None, database=None, suppress_health_check=list(HealthCheck))
    @given(st.data())
    def fuzz(data):
        TRIED[scene] += 1
        _check(data.draw(vectors(scene, FILES), label="vector"))

    fuzz()


@pytest.fixture
def fit_limit(monkeypatch):
    """fit's time budget lowered to FIT_LIMIT: a vector that would fit for long is refused by it."""
    from taucli.fit import command

    monkeypatch.setattr(command, "LIMIT_SECONDS", FIT_LIMIT)


@pytest.mark.parametrize("name", COMMANDS)
def test_hostile_command_lines_of_the_other_commands_keep_the_contract(name, fit_limit):
    from pathlib import Path

    @settings(max_examples=EXAMPLES, deadline=None, database=None, suppress_health_check=list(HealthCheck))
    @given(st.data())
    def fuzz(data):
        TRIED[name or "(no command)"] += 1
        _check(data.draw(vectors_of(name, Path(_scratch.name), FIT_RUNS, FILES), label="vector"))

    fuzz()


@pytest.mark.parametrize("vector", FOUND, ids=lambda vector: repr(vector)[:100])
def test_vectors_that_once_failed(vector):
    _check(Vector(vector.scene, [arg.format(**FILES) for arg in vector.args], vector.stdin))


def test_every_scene_and_command_is_fuzzed():
    from taucli.options import COMMANDS as ALL
    from taucli.options import SCENES as TABLES

    assert set(SCENES) == set(TABLES)
    assert set(SCENES) | set(COMMANDS) == set(ALL) | {""}
    assert len(FIT_RUNS) >= 10  # docs/fit.md's runs, with their tables
