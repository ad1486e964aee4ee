"""The README's console examples print what the README shows (at 80 columns).

Each ```console block is a short session: `$ cat FILE` shows a file the next commands read (the
test writes it), and `$ taucli ...` shows a command and all it printed, stdout then stderr.
Commands with a pipe or a redirect, and `taucli bench` (its timings differ from run to run),
are left out; a test below counts what is checked, so that the README cannot drift out of it.
"""

from __future__ import annotations

import re
import shlex
from pathlib import Path

import pytest

from conftest import run_taucli

README = Path(__file__).parent.parent / "README.md"


def sessions() -> list[tuple[str, str, dict[str, str]]]:
    """(command, what it printed, files shown before it in its block) for each checkable command."""
    found = []
    for block in re.findall(r"```console\n(.*?)```", README.read_text(encoding="utf-8"), re.S):
        files: dict[str, str] = {}
        for entry in re.split(r"^\$ ", block, flags=re.M)[1:]:
            command, _, printed = entry.partition("\n")
            if command.startswith("cat ") and " " not in command[4:]:
                files[command[4:]] = printed
            elif command.startswith("taucli ") and not re.search(r"[|<>]", command) and not command.startswith("taucli bench"):
                found.append((command, printed, dict(files)))
    return found


def _lines(text: str) -> list[str]:
    return [line.rstrip() for line in text.strip("\n").splitlines()]


def test_the_readme_has_examples_to_check():
    assert len(sessions()) >= 15


@pytest.mark.parametrize("command,printed,files", sessions(), ids=[command[:70] for command, _, _ in sessions()])
def test_a_readme_example_prints_what_the_readme_shows(command, printed, files, tmp_path, monkeypatch):
    for name, text in files.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    result = run_taucli(*shlex.split(command)[1:], env={"COLUMNS": "80"})
    assert _lines(result.out + result.err) == _lines(printed)


@pytest.mark.parametrize("shell", ["zsh", "fish"])
def test_every_readme_command_works_as_typed_in_zsh_and_fish(shell, tmp_path):
    """#16 item 17: `--friction 0.3N*m` unquoted is a glob, and zsh stops at 'no matches found'.
    Each README command, run by the shell itself, exits as it does when bash runs it."""
    import os
    import shutil
    import subprocess
    import sys

    found = shutil.which(shell)
    if found is None:
        if os.environ.get("CI"):
            pytest.fail(f"{shell} is not installed: .ci/run installs it")
        pytest.skip(f"{shell} is not installed (apt-get install {shell})")
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir()
    (bin_dir / "taucli").write_text(f"#!/bin/sh\nexec {sys.executable} -m taucli \"$@\"\n")
    (bin_dir / "taucli").chmod(0o755)
    env = {**os.environ, "PATH": f"{bin_dir}:{os.environ['PATH']}", "COLUMNS": "80"}
    commands = [command for command, _, files in sessions() if not files]
    assert len(commands) > 30
    for command in commands:
        in_bash = subprocess.run(["bash", "-c", command], capture_output=True, text=True, env=env, cwd=tmp_path, timeout=60)
        in_shell = subprocess.run([found, "-c", command], capture_output=True, text=True, env=env, cwd=tmp_path, timeout=60)
        assert "no matches found" not in in_shell.stderr and "No matches for wildcard" not in in_shell.stderr, (command, in_shell.stderr)
        assert in_shell.returncode == in_bash.returncode, (command, in_shell.stderr)
        assert in_shell.stdout == in_bash.stdout, command
