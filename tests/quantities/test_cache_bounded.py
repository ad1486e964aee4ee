"""A cache file costs time at most (docs/running.md), whatever stands in its place (#43 item 13):
a link to /dev/zero, a file of gigabytes (sparse: no disk), or a FIFO that no one writes, as the
unit cache (units-*.json), pint's checksums (pint.sums) or one of pint's pickles. The run gives the
same answer, in a child held to 1 GB of memory and 60 s, and the file is built again."""

from __future__ import annotations

import os
import resource
import stat
import subprocess
import sys

import pytest

from taucli.quantities import cache

# "kilogram", not "kg": a unit outside the table shipped in the package, so pint is asked and the cache written
ARGS = ("atwood", "--m1", "4kilogram", "--m2", "1kilogram", "--get", "a")
A = "5.88399"  # g(m1 - m2)/(m1 + m2), 4 kg and 1 kg
LIMIT = 1 << 30


def _run(folder) -> tuple[int, str, str]:
    env = {key: value for key, value in os.environ.items() if key not in ("XDG_CACHE_HOME",)}
    env.update(TAUCLI_CACHE_DIR=str(folder), PYTHONIOENCODING="utf-8")

    def held():
        resource.setrlimit(resource.RLIMIT_AS, (LIMIT, LIMIT))

    done = subprocess.run([sys.executable, "-m", "taucli", *ARGS], capture_output=True, text=True, env=env, timeout=60, preexec_fn=held)
    return done.returncode, done.stdout.strip(), done.stderr


def _replace(path, what: str) -> None:
    if path.exists() or path.is_symlink():
        path.unlink()
    if what == "a link to /dev/zero":
        path.symlink_to("/dev/zero")
    elif what == "a file of 4 GB":
        with open(path, "wb") as handle:
            handle.truncate(4 << 30)  # sparse: no disk is used
    else:
        os.mkfifo(path)


@pytest.mark.parametrize("what", ["a link to /dev/zero", "a file of 4 GB", "a FIFO no one writes"])
@pytest.mark.parametrize("which", ["units-*.json", "pint.sums", "pint/*.pickle"])
def test_a_cache_file_that_is_not_one_costs_time_only(tmp_path, which, what):
    folder = tmp_path / "cache"
    assert _run(folder) == (0, A, "")
    (path,) = sorted(folder.glob(which))[:1]
    _replace(path, what)
    if which != "units-*.json":
        for stored in folder.glob("units-*.json"):
            stored.unlink()  # so that pint is asked, and reads its folder
    assert _run(folder) == (0, A, "")
    assert _run(folder) == (0, A, "")
    if which != "pint/*.pickle" or path.exists():  # (pint may name its pickles anew)
        assert stat.S_ISREG(os.lstat(path).st_mode) and path.stat().st_size < cache.MAX_FILE * 16  # built again


def test_a_unit_cache_larger_than_the_cap_is_not_read(tmp_path):
    folder = tmp_path / "cache"
    assert _run(folder) == (0, A, "")
    (path,) = folder.glob("units-*.json")
    path.write_text(path.read_text() + " " * cache.MAX_FILE)  # a valid file, only too large
    assert _run(folder) == (0, A, "")
    assert path.stat().st_size < cache.MAX_FILE  # written again from what this run asked of pint


def test_checksums_are_taken_a_chunk_at_a_time_and_only_of_regular_files(tmp_path):
    small = tmp_path / "small"
    small.write_bytes(b"abc" * 1000)
    import zlib
    assert cache.file_checksum(str(small)) == f"{zlib.crc32(b'abc' * 1000):08x}"
    big = tmp_path / "big"
    with open(big, "wb") as handle:
        handle.truncate(cache.MAX_CHECKED + 1)
    zero = tmp_path / "zero"
    zero.symlink_to("/dev/zero")
    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    assert [cache.file_checksum(str(p)) for p in (big, zero, fifo, tmp_path, tmp_path / "missing")] == ["?"] * 5
