"""An answer that cannot be written (#43 item 8): stdout closed (`>&-`) or full (`> /dev/full`)
was "internal error ... this is a bug in taucli" (exit 1), or a traceback for --help. Now one line
on stderr naming standard output, and exit 74 (docs/running.md), for every way of answering:
each scene's example plainly, --json, --get, --format, a sweep, help, --version, completions,
fit, and a batch."""

from __future__ import annotations

import os
import shlex
import subprocess
import sys
from pathlib import Path

import pytest

from taucli.options import SCENES

ROOT = Path(__file__).resolve().parents[2]
FULL = Path("/dev/full")


def _scene_lines() -> list[list[str]]:
    lines = []
    for command in SCENES.values():
        example = shlex.split(command.example)[1:]
        lines += [example, [*example, "--json"], [*example, "--get", command.headline], [*example, "--format", "md"]]
    return lines


LINES = [*_scene_lines(), ["atwood", "--m1", "4kg,5kg", "--m2", "1kg"], ["--help"], ["atwood", "--help"], ["--version"],
         ["completions", "bash"], ["fit", "spin-down", "-", "--inertia", "0.1kg*m^2", "--fit", "friction,omega0"]]
FRICTION = b"t (s),omega (rad/s)\n0,29.928\n1,27.012\n2,23.986\n3,20.976\n4,18.048\n5,15.003\n6,11.986\n7,9.090\n8,5.975\n9,2.937\n"  # docs/fit.md


def _run(args: list[str], stdout, stdin: bytes = b"") -> subprocess.CompletedProcess:
    env = {**os.environ, "PYTHONIOENCODING": "utf-8"}
    env.pop("TAUCLI_DEBUG", None)
    return subprocess.run([sys.executable, "-m", "taucli", *args], input=stdin, stdout=stdout, stderr=subprocess.PIPE, cwd=ROOT, env=env, timeout=120)


def _assert_one_line(done: subprocess.CompletedProcess, args) -> None:
    err = done.stderr.decode("utf-8")
    assert done.returncode == 74, (args, done.returncode, err)
    assert err.count("\n") == 1 and err.startswith("taucli: error: cannot write the answer to standard output: "), (args, err)


@pytest.mark.skipif(not FULL.exists(), reason="no /dev/full here")
@pytest.mark.parametrize("args", LINES, ids=[" ".join(args)[:60] for args in LINES])
def test_a_full_stdout_is_one_line_and_exit_74(args):
    with FULL.open("wb") as full:
        _assert_one_line(_run(args, full, FRICTION if args[0] == "fit" else b""), args)


@pytest.mark.parametrize("args", [LINES[0], LINES[1], ["--help"], ["--version"], ["completions", "fish"]])
def test_a_closed_stdout_is_one_line_and_exit_74(args):
    done = subprocess.run([sys.executable, "-c", "import os, runpy, sys; os.close(1); sys.argv = ['taucli', *sys.argv[1:]]; "
                           "runpy.run_module('taucli', run_name='__main__')", *args], capture_output=False, stderr=subprocess.PIPE,
                          stdin=subprocess.DEVNULL, cwd=ROOT, timeout=120)
    _assert_one_line(done, args)


@pytest.mark.skipif(not FULL.exists(), reason="no /dev/full here")
def test_a_batch_to_a_full_stdout():
    lines = b'{"m1": "4kg", "m2": "1kg"}\n' * 3
    with FULL.open("wb") as full:
        _assert_one_line(_run(["atwood", "--batch"], full, lines), "batch")


def test_a_reader_that_leaves_early_is_still_quiet():
    child = subprocess.Popen([sys.executable, "-m", "taucli", "atwood", "--m1", "4kg", "--m2", "1kg"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, cwd=ROOT)
    child.stdout.read(1)
    child.stdout.close()
    assert child.wait(timeout=60) == 0 and child.stderr.read() == b""
