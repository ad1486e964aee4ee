"""The cache is a trust boundary, and the home directory is the user's (#33 items 11, 12)."""

from __future__ import annotations

import json
import os
import stat
from pathlib import Path

import pytest

from conftest import run_taucli

# "kilogram", not "kg": a unit outside the table shipped in the package (#36), so pint is asked and the cache written
ARGS = ("atwood", "--m1", "4kilogram", "--m2", "1kilogram", "--get", "a")
A = "5.88399"  # g(m1 - m2)/(m1 + m2), 4 kg and 1 kg


def _run(env: dict, cwd: str | None = None):
    env = {"TAUCLI_CACHE_DIR": None, "XDG_CACHE_HOME": None, **env}  # conftest's shared folder aside
    full = {key: value for key, value in {**os.environ, **env}.items() if value is not None}
    for key, value in env.items():
        if value is None:
            full.pop(key, None)
    import subprocess
    import sys

    done = subprocess.run([sys.executable, "-m", "taucli", *ARGS], capture_output=True, text=True, env={**full, "PYTHONIOENCODING": "utf-8"}, timeout=60, cwd=cwd)
    return done.returncode, done.stdout.strip(), done.stderr


def test_an_edited_unit_cache_is_not_read_and_is_rebuilt(tmp_path):
    folder = tmp_path / "cache"
    assert _run({"TAUCLI_CACHE_DIR": str(folder)}) == (0, A, "")
    (stored,) = folder.glob("units-*.json")
    document = json.loads(stored.read_text())
    assert document["entries"]["kg|mass|kilogram"] == [1.0, 0] and document["checksum"]
    document["entries"]["kg|mass|kilogram"] = [2.0, 0]  # "4kilogram" would read as 8 kg, "1kilogram" as 2 kg: a = g(8 - 2)/10
    stored.write_text(json.dumps(document))
    assert _run({"TAUCLI_CACHE_DIR": str(folder)}) == (0, A, "")
    assert json.loads(stored.read_text())["entries"]["kg|mass|kilogram"] == [1.0, 0]  # rebuilt from pint
    document["checksum"] = "00000000"
    stored.write_text(json.dumps(document))
    assert _run({"TAUCLI_CACHE_DIR": str(folder)}) == (0, A, "")


def test_an_edited_pint_cache_file_is_removed_and_built_again(tmp_path):
    folder = tmp_path / "cache"
    assert _run({"TAUCLI_CACHE_DIR": str(folder)})[:2] == (0, A)
    pickles = sorted((folder / "pint").glob("*.pickle"))
    assert pickles and (folder / "pint.sums").exists()
    before = pickles[0].read_bytes()
    pickles[0].write_bytes(before[:-8] + b"\0" * 8)
    for stored in folder.glob("units-*.json"):
        stored.unlink()  # so that pint is asked
    assert _run({"TAUCLI_CACHE_DIR": str(folder)}) == (0, A, "")
    assert pickles[0].read_bytes() == before  # written again by pint, not read as it was


def test_xdg_cache_home_is_followed(tmp_path):
    assert _run({"XDG_CACHE_HOME": str(tmp_path / "xdg"), "HOME": str(tmp_path)}) == (0, A, "")
    assert list((tmp_path / "xdg" / "taucli").glob("units-*.json"))
    assert not (tmp_path / ".cache").exists()


def _listing(path: str) -> set | None:
    return set(os.listdir(path)) if os.path.isdir(path) else None


@pytest.mark.parametrize("home", ["", "/nonexistent-taucli-home/home", "relative/home"])
def test_no_home_directory_is_ever_made(tmp_path, home):
    """HOME= put the cache in /.cache/taucli, HOME=/nonexistent/home made that whole tree."""
    before = _listing("/.cache/taucli")
    assert _run({"HOME": home}, cwd=str(tmp_path)) == (0, A, "")
    assert not Path("/nonexistent-taucli-home").exists() and not (tmp_path / "relative").exists()
    assert _listing("/.cache/taucli") == before


def test_a_home_without_a_cache_folder_gets_one(tmp_path):
    assert _run({"HOME": str(tmp_path)}) == (0, A, "")
    assert list((tmp_path / ".cache" / "taucli").glob("units-*.json"))


@pytest.mark.skipif(os.geteuid() == 0, reason="root writes through a read-only mode")
def test_nothing_writable_means_no_cache_and_the_same_answer(tmp_path):
    tmp_path.chmod(stat.S_IRUSR | stat.S_IXUSR)
    try:
        assert _run({"HOME": str(tmp_path)}) == (0, A, "")
    finally:
        tmp_path.chmod(stat.S_IRWXU)


def test_a_chart_file_from_a_read_only_home_says_nothing_on_stderr(tmp_path):
    """matplotlib warned over several lines that its config folder could not be made; stderr now
    holds only where the chart went (#36)."""
    home = tmp_path / "home"
    home.mkdir()
    out = tmp_path / "chart.svg"
    done = run_taucli("atwood", "--m1", "4kg", "--m2", "1kg", "--distance", "1m", "--no-steps", "--out", str(out),
                      env={"HOME": str(home / "missing"), "XDG_CONFIG_HOME": "/proc/taucli-config", "XDG_CACHE_HOME": "/proc/taucli-cache", "MPLCONFIGDIR": ""})
    assert done.code == 0 and done.err == f"taucli: wrote the chart to {out}\n" and out.stat().st_size > 1000
