"""Shared helpers: run taucli through its real entry point, as a user's shell does."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import pytest
from hypothesis import settings

# A green run means the same on every machine: under CI each property test draws the examples its
# own name fixes (derandomize) and no database of earlier failures is read or written. Elsewhere
# the draws are random (`--hypothesis-seed N` repeats one run); what a random run finds is kept in
# its test as an @example.
settings.register_profile("ci", derandomize=True, database=None, print_blob=True)
if os.environ.get("CI"):
    settings.load_profile("ci")

# One cache folder for the whole run, shared by the subprocesses: the user's own stays untouched.
if "TAUCLI_CACHE_DIR" not in os.environ:
    import tempfile

    os.environ["TAUCLI_CACHE_DIR"] = tempfile.mkdtemp(prefix="taucli-test-cache-")


@dataclass
class Run:
    code: int
    out: str
    err: str

    def json(self) -> dict:
        return strict_json(self.out)


ROOT = Path(__file__).resolve().parent.parent
DOCUMENTS = (ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md")))  # README and each page of docs/: their commands are tested


def documents_text() -> list[tuple[str, str]]:
    """(name, text) of README and each page in docs/, e.g. ("docs/atwood.md", "...")."""
    return [(str(path.relative_to(ROOT)), path.read_text(encoding="utf-8")) for path in DOCUMENTS]


def strict_json(text: str):
    """json.loads that refuses NaN, Infinity and -Infinity, as strict JSON does."""
    return json.loads(text, parse_constant=_reject_constant)


def _reject_constant(name: str):
    raise ValueError(f"non-strict JSON constant {name}")


def run_taucli(*args: str, env: dict[str, str] | None = None, stdin: str | None = None, timeout: float = 30) -> Run:
    """Run `python -m taucli ARGS` in a subprocess with no terminal, and capture what it prints."""
    full_env = {**os.environ, "PYTHONIOENCODING": "utf-8", **(env or {})}
    full_env.pop("TAUCLI_DEBUG", None)
    done = subprocess.run(
        [sys.executable, "-m", "taucli", *args],
        input=stdin,
        capture_output=True,
        text=True,
        encoding="utf-8",
        env=full_env,
        timeout=timeout,
    )
    return Run(done.returncode, done.stdout, done.stderr)


@pytest.fixture(autouse=True)
def _mpmath_precision(request):
    """Each test's mpmath references at its module's MP_DPS digits (30 where it names none), and
    the precision restored afterwards: mpmath.mp is one global, so a module's `mpmath.mp.dps = 40`
    held only until the next module was imported, and a test that set it changed the next ones."""
    import mpmath

    with mpmath.workdps(getattr(request.module, "MP_DPS", 30)):
        yield


@pytest.fixture
def taucli():
    return run_taucli


def assert_usage_error(result: Run, *fragments: str) -> None:
    """Exit 2, nothing on stdout, one line on stderr naming what is wrong, no traceback."""
    assert result.code == 2, (result.code, result.out, result.err)
    assert result.out == ""
    lines = result.err.strip().splitlines()
    assert len(lines) == 1, result.err
    assert lines[0].startswith("taucli: error: "), lines[0]
    assert "Traceback" not in result.err
    for fragment in fragments:
        assert fragment in lines[0], (fragment, lines[0])


def modules_after_run(argv: list[str], env: dict[str, str]) -> set[str]:
    """The modules loaded by a whole run of ``taucli ARGV``, through its console entry point."""
    code = (
        "import io, contextlib, runpy, sys\n"
        f"sys.argv = ['taucli', *{argv!r}]\n"
        "with contextlib.redirect_stdout(io.StringIO()):\n"
        "    try:\n        runpy.run_module('taucli', run_name='__main__')\n"
        "    except SystemExit as done:\n        assert not done.code, done.code\n"
        "print(' '.join(sys.modules))"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env={**os.environ, **env})
    assert done.returncode == 0, done.stderr
    return set(done.stdout.split())


def with_notes_as_keys(doc: dict) -> dict:
    """A command line's --json document with its notes naming options as batch and Python do: a
    key, not a flag (--pulley-radius -> pulley_radius; #42 item 19), to compare with a batch line."""
    import re

    return {**doc, "notes": [re.sub(r"--([a-z][a-z0-9-]*)", lambda m: m[1].replace("-", "_"), note) for note in doc["notes"]]}


def example_keys(command) -> dict:
    """A command's example in its table as a batch line's keys (``taucli atwood --m1 4kg …`` ->
    {"m1": "4kg", …}; a flag True, the positional SHAPE by its name)."""
    import shlex

    from taucli.options.table import FLAG

    words, given = shlex.split(command.example)[2:], {}
    positional = [option.name for option in command.options if option.positional]
    while words:
        word = words.pop(0)
        if word.startswith("--"):
            option = command.option(word[2:].replace("-", "_"))
            given[option.name] = True if option.kind == FLAG else words.pop(0)
        else:
            given[positional.pop(0)] = word
    return given
