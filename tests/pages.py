"""The console examples of README and of every page in docs/, as tests read them, and how a fit's
numbers for a machine are compared with a page (tests/front/test_readme.py, tests/fit/test_fit_digits.py)."""

from __future__ import annotations

import io
import os
import re
import shlex
import shutil
import sys

import pytest

from conftest import ROOT, documents_text


def sessions() -> list[tuple[str, str, dict[str, str]]]:
    """(command, what it printed, files shown before it in its block) for each checkable command
    of README and of every page in docs/."""
    found = []
    blocks = [block for _, text in documents_text() for block in re.findall(r"```console\n(.*?)```", text, re.S)]
    for block in blocks:
        files: dict[str, str] = {}
        for entry in re.split(r"^\$ ", block, flags=re.M)[1:]:
            command, _, printed = entry.partition("\n")
            if command.startswith("cat ") and " " not in command[4:]:
                files[command[4:]] = printed
            elif command.startswith("taucli ") and not command.startswith("taucli bench"):
                found.append((command, printed, dict(files)))
    return found


def lines_of(text: str) -> list[str]:
    return [line.rstrip() for line in text.strip("\n").splitlines()]


# What a fit prints for a machine (--get, --json) keeps every digit of the double it found, and the
# digits past a small fraction of each value's uncertainty are the least-squares search's rounding:
# they change with numpy's and scipy's versions (and the search's path), not with the samples. The
# page's examples of them are compared within these; what a person reads is compared as text.
FIT_OF_UNCERTAINTY = 1e-6  # a fitted value, within this fraction of the uncertainty printed beside it
FIT_RELATIVE = 1e-9  # any other number of a fit's machine output (χ²/ν, R², a value without its ±), relative
FIT_UNCERTAINTY_RELATIVE = 1e-6  # an uncertainty: from a Jacobian by differences at the solution


def fit_machine_output(command: str) -> bool:
    """A fit's example that prints numbers for a machine (--get, --json), not a page for a person."""
    return command.startswith("taucli fit ") and bool(re.search(r"--(get|json)\b", command))


def _number(text: str) -> float | None:
    try:
        return float(text)
    except ValueError:
        return None


def _numbers_agree(got: str, page: str, relative: float, absolute: float = 0.0) -> bool:
    a, b = _number(got), _number(page)
    if a is None or b is None:
        return got == page
    return abs(a - b) <= absolute + relative * abs(b)


def fit_numbers_agree(got_lines: list[str], page_lines: list[str]) -> bool:
    """--get's lines of a fit ("value" or "value uncertainty") within the fit's tolerances above;
    any word that is not a number (null, an error) as text."""
    if len(got_lines) != len(page_lines):
        return False
    for got, page in zip(got_lines, page_lines):
        got_words, page_words = got.split(), page.split()
        if len(got_words) != len(page_words):
            return False
        spread = _number(page_words[1]) if len(page_words) == 2 else None
        if spread is not None:
            agree = (_numbers_agree(got_words[0], page_words[0], FIT_RELATIVE, FIT_OF_UNCERTAINTY * abs(spread))
                     and _numbers_agree(got_words[1], page_words[1], FIT_UNCERTAINTY_RELATIVE))
        else:
            agree = all(_numbers_agree(g, p, FIT_RELATIVE) for g, p in zip(got_words, page_words))
        if not agree:
            return False
    return True


def fit_output_agrees(command: str, out: str, err: str, printed: str) -> bool:
    """What an example printed (stdout, then stderr) against its page: a fit's numbers for a
    machine within the tolerances above, the lines on stderr beside them (its warnings) as text;
    anything else as text."""
    if not fit_machine_output(command):
        return lines_of(out + err) == lines_of(printed)
    page, numbers = lines_of(printed), lines_of(out) if out.strip() else []
    return fit_numbers_agree(numbers, page[:len(numbers)]) and lines_of(err) == page[len(numbers):] if err.strip() else fit_numbers_agree(numbers, page)


def piped(command: str) -> bool:
    return bool(re.search(r"[|<>]", command))


def shell_env(tmp_path) -> dict[str, str]:
    """The environment of a shell whose `taucli` is this checkout's, at 80 columns."""
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir(exist_ok=True)
    (bin_dir / "taucli").write_text(f"#!/bin/sh\nexec {sys.executable} -m taucli \"$@\"\n")
    (bin_dir / "taucli").chmod(0o755)
    return {**os.environ, "PATH": f"{bin_dir}:{os.environ['PATH']}", "COLUMNS": "80"}


def with_docs(folder) -> None:
    """docs/ beside the block's files: a page reads a longer data file by its path (docs/data/...)."""
    (folder / "docs").symlink_to(ROOT / "docs", target_is_directory=True)


def needs(program: str) -> None:
    if shutil.which(program) is None:
        if os.environ.get("CI"):
            pytest.fail(f"{program} is not installed: .ci/run installs it")
        pytest.skip(f"{program} is not installed (apt-get install {program})")


# What an example prints for a machine, or to a file, left off when it is asked for as a document.
MACHINE_FLAGS = {"--json", "--jsonl", "--plot", "--uncertainty"}
MACHINE_OPTIONS = {"--get", "--format", "--out", "--y", "--residuals"}


def as_format(command: str, fmt: str) -> list[str]:
    """An example's words with what it prints for a machine left off and --format FMT added."""
    words, kept, skip = shlex.split(command)[1:], [], False
    machine = MACHINE_OPTIONS - ({"--y"} if words[0] == "fit" else set())  # (fit's --y names the column measured, not a chart's result)
    for word in words:
        if skip:
            skip = False
        elif word in machine:
            skip = True
        elif word not in MACHINE_FLAGS:
            kept.append(word)
    return [*kept, "--format", fmt]


def examples_as(fmt: str, folder) -> list[tuple[str, str, int, str, str]]:
    """(command, what its page printed, exit status, stdout, stderr) of each scene's and fit's
    example of README and docs/ (no pipe; help, completions and bench aside), run in this process in
    ``folder`` (which it changes to: the block's files written there, docs/ beside them) as
    --format FMT."""
    from taucli.front.cli import Environment, main
    from taucli.options import SCENES

    with_docs(folder)
    os.chdir(folder)
    found = []
    for command, printed, files in sessions():
        if command.split()[1] not in (*SCENES, "fit") or piped(command):
            continue
        for name, text in files.items():
            (folder / name).write_text(text, encoding="utf-8")
        env = Environment(stdin=io.StringIO(""), stdout=io.StringIO(), stderr=io.StringIO())
        code = main(as_format(command, fmt), env)
        found.append((command, printed, code, env.stdout.getvalue(), env.stderr.getvalue()))
    return found
