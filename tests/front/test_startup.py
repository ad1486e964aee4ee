"""Startup: what a run imports, and the unit cache that keeps pint off repeat runs.

Timing is in tests/benchmarks/startup.py; these tests pin the causes: help and completion import
no solver, no pint, no rich and no pydantic; a computation whose units were seen before imports
no pint; and no state of the cache folder can change an answer.
"""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys

import pytest

from conftest import modules_after_run, run_taucli

ATWOOD = ("atwood", "--m1", "4kg", "--m2", "1kg", "--pulley-mass", "2kg")


def _top(modules: set[str]) -> set[str]:
    return {name.split(".")[0] for name in modules}


@pytest.mark.parametrize("argv", [["--help"], ["atwood", "--help"], ["inertia", "-h"], ["spin-down", "--omega0", "3rad/s", "--help"]])
def test_help_is_written_from_the_tables_without_typer(argv, tmp_path):
    """No typer, click, pint, rich or pydantic, no solver, and nothing kept in a cache."""
    loaded = modules_after_run(argv, {"TAUCLI_CACHE_DIR": str(tmp_path)})
    assert not _top(loaded) & {"typer", "click", "pint", "rich", "pydantic"}
    assert not {name for name in loaded if name.startswith(("taucli.scenes", "taucli.numerics.steppers", "taucli.front.cli"))}
    assert not list(tmp_path.iterdir())


def test_version_imports_no_solver_no_units_no_rich_no_pydantic(tmp_path):
    loaded = modules_after_run(["--version"], {"TAUCLI_CACHE_DIR": str(tmp_path)})
    assert not _top(loaded) & {"pint", "rich", "pydantic"}
    assert not {name for name in loaded if name.startswith(("taucli.scenes", "taucli.numerics.steppers"))}


def test_a_repeat_computation_imports_neither_pint_nor_pydantic(tmp_path):
    env = {"TAUCLI_CACHE_DIR": str(tmp_path)}
    first = modules_after_run([*ATWOOD, "--get", "a"], env)
    assert not _top(first) & {"pint", "rich", "pydantic"}  # common units: shipped with taucli (#36 item 8)
    rare = ["atwood", "--m1", "4kg", "--m2", "14000 grain", "--get", "a"]
    assert "pint" in _top(modules_after_run(rare, env))  # a unit not shipped: pint is asked, and remembered
    again = modules_after_run(rare, env)
    assert not _top(again) & {"pint", "rich", "pydantic"}


def _answer(env: dict[str, str]) -> float:
    # 14000 grain = 2 lb: a unit not in the shipped table, so that pint is asked and its answer kept
    done = run_taucli("atwood", "--m1", "4kg", "--m2", "14000 grain", "--pulley-mass", "300 g", "--g", "32.174 ft/s^2", "--get", "a", env=env)
    assert done.code == 0 and done.err == "", done.err
    return float(done.out)


# (m1 - m2) g / (m1 + m2 + M/2) with m2 = 2 lb = 0.90718474 kg, g = 32.174 ft/s^2 = 9.8066352 m/s^2
EXPECTED_A = (4 - 0.90718474) * 9.8066352 / (4 + 0.90718474 + 0.15)


def test_every_state_of_the_cache_folder_gives_the_same_answer(tmp_path):
    folder = tmp_path / "cache"
    fresh = _answer({"TAUCLI_CACHE_DIR": str(folder)})  # missing: created
    assert fresh == pytest.approx(EXPECTED_A, rel=1e-12)
    (units_file,) = folder.glob("units-*.json")
    assert (folder / "pint").is_dir()
    assert _answer({"TAUCLI_CACHE_DIR": str(folder)}) == fresh  # warm: no pint at all

    units_file.write_text('{"stamp": 3, "units": [')  # corrupt
    for pickle in (folder / "pint").iterdir():
        pickle.write_bytes(b"\x80\x04garbage")
    assert _answer({"TAUCLI_CACHE_DIR": str(folder)}) == fresh
    assert json.loads(units_file.read_text())["entries"]  # rewritten

    stored = json.loads(units_file.read_text())
    stored["entries"] = {key: [value[0] * 2, value[1]] for key, value in stored["entries"].items()}
    stored["stamp"] = "an older taucli or pint"  # stale: its factors must not be used
    units_file.write_text(json.dumps(stored))
    assert _answer({"TAUCLI_CACHE_DIR": str(folder)}) == fresh

    a_file = tmp_path / "a-file"
    a_file.write_text("")
    for unwritable in (str(a_file / "cache"), "/proc/taucli-cache", ""):  # under a file, read-only, off
        assert _answer({"TAUCLI_CACHE_DIR": unwritable}) == fresh


def test_a_missing_home_still_answers(tmp_path):
    env = {"HOME": str(tmp_path / "nowhere"), "XDG_CACHE_HOME": ""}
    done = subprocess.run(
        [sys.executable, "-m", "taucli", *ATWOOD, "--get", "a"],
        capture_output=True,
        text=True,
        env={k: v for k, v in {**os.environ, **env}.items() if k != "TAUCLI_CACHE_DIR"},
    )
    assert done.returncode == 0 and done.stderr == ""
    assert float(done.stdout) == pytest.approx(3 * 9.80665 / 6, rel=1e-15)


@pytest.mark.parametrize(
    "text,kind",
    [
        ("4kg", "mass"), ("2 lb", "mass"), ("250 g", "mass"), ("300 rpm", "angular velocity"), ("-2.5 rev/s", "angular velocity"),
        ("5 Hz", "angular velocity"), ("0.3 N*m", "torque"), ("12 lbf*ft", "torque"), ("30deg", "angle"), ("1e-3 kg*m^2", "moment of inertia"),
        ("7 g*cm**2", "moment of inertia"), ("0.01 N*m*s", "viscous coefficient"), ("3 N*m/(rad/s)", "viscous coefficient"),
        ("9.81 m/s^2", "acceleration"), ("60 km/h", "velocity"), ("kg", "mass"), ("4", "mass"), (".5", "length"), ("1.5e2 mm", "length"),
    ],
)  # fmt: skip
def test_a_cached_unit_reads_as_pint_reads_the_whole_text(text, kind, tmp_path, monkeypatch):
    """Number times pint's factor for the unit is what pint makes of the whole text, to 1 ulp."""
    from taucli.quantities import cache
    from taucli.quantities import registry
    from taucli.quantities import screen
    from taucli.quantities import units

    store = cache.Store(str(tmp_path), "units", lambda: "this test")
    monkeypatch.setattr(cache, "unit_factors", lambda: store)
    first = units.parse(text, "--x", kind, sign="any")
    again = units.parse(text, "--x", kind, sign="any")  # now from the cache
    cleaned = screen.screen(text, "--x", units.KINDS[kind])
    whole, _ = registry.from_pint(cleaned, text, "--x", units.KINDS[kind])
    assert again == first
    assert abs(first.value - whole) <= math.ulp(whole)


def test_text_that_is_not_number_times_unit_goes_to_pint_whole():
    from taucli.quantities import units

    assert units.parse("4 kg + 200 g", "--m1", "mass").value == pytest.approx(4.2, rel=1e-15)
    assert units.parse("(4 + 1) kg", "--m1", "mass").value == 5.0
    assert units.parse("2 * 3 kg", "--m1", "mass").value == 6.0


def test_help_groups_options_under_their_panels():
    done = run_taucli("atwood", "--help", env={"COLUMNS": "100"})
    assert done.code == 0
    lines = done.out.splitlines()
    for title in ("Options:", "Pulley:", "Motion and method:", "Output:"):
        assert title in lines
    pulley = lines.index("Pulley:")
    assert lines[pulley + 1].split()[0] == "--pulley-mass"
    assert "\x1b[" not in done.out and "╭" not in done.out


def test_two_environments_sharing_a_cache_folder_keep_their_own_entries(tmp_path):
    """Another pint (another venv) has its own file, so neither evicts the other's answers."""
    from taucli.quantities import cache

    one = cache.Store(str(tmp_path), "units", lambda: "pint 0.24 in venv one")
    one.put("kg|mass|lb", [0.45359237, 0])
    other = cache.Store(str(tmp_path), "units", lambda: "pint 0.25 in venv two")
    assert other.get("kg|mass|lb") is None
    other.put("kg|mass|lb", [0.4535923700000001, 0])
    assert cache.Store(str(tmp_path), "units", lambda: "pint 0.24 in venv one").get("kg|mass|lb") == [0.45359237, 0]
    assert len(list(tmp_path.glob("units-*.json"))) == 2
