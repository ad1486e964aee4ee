"""A real shell in a terminal of a given width, for the tests of what a person sees and types.

``Terminal("zsh", 40)`` starts zsh (bash, fish) with no start-up files in a pseudo-terminal 40
columns wide, with this checkout's ``taucli`` first on PATH and no COLUMNS in the environment,
so taucli finds the width as it does for a person: from the terminal. ``run(line)`` types a
command line and returns what it printed (raw, as taucli wrote it: the terminal's own wrapping
is not applied) and its exit status. Skips where pexpect or the shell is not installed.
"""

from __future__ import annotations

import os
import re
import shutil
import sys
import tempfile

import pytest

SHELLS = ("bash", "zsh", "fish")
WIDTHS = (40, 80)

_STATUS = {"bash": "$?", "zsh": "$?", "fish": "$status"}
_START = {
    "bash": ["--norc", "--noprofile"],
    "zsh": ["-f"],
    "fish": ["--no-config"],
}


def shell_bin_dir() -> str:
    """A folder holding a ``taucli`` that runs this checkout with this Python."""
    folder = tempfile.mkdtemp(prefix="taucli-term-bin-")
    path = os.path.join(folder, "taucli")
    with open(path, "w", encoding="utf-8") as handle:
        handle.write(f"#!/bin/sh\nexec {sys.executable} -m taucli \"$@\"\n")
    os.chmod(path, 0o755)
    return folder


class Terminal:
    def __init__(self, shell: str, columns: int, rows: int = 50, env: dict | None = None):
        pexpect = pytest.importorskip("pexpect")
        if shutil.which(shell) is None:
            pytest.skip(f"{shell} is not installed")
        self.shell = shell
        environment = {k: v for k, v in os.environ.items() if k not in ("COLUMNS", "LINES", "TAUCLI_DEBUG")}
        environment.update(PATH=f"{shell_bin_dir()}:{os.environ['PATH']}", TERM="xterm-256color", PYTHONIOENCODING="utf-8",
                           LANG="C.UTF-8", LC_ALL="C.UTF-8", **(env or {}))
        self.child = pexpect.spawn(shell, _START[shell], env=environment, dimensions=(rows, columns), encoding="utf-8", timeout=60)
        self._settle()

    def _settle(self) -> None:
        self.child.sendline("echo __RE''ADY__")
        self.child.expect("__READY__")

    def run(self, line: str) -> tuple[str, int]:
        """Type ``line`` (it may hold backslash-newline continuations) and return (output, status)."""
        self.child.sendline(f"echo __BE''GIN__; {line}; echo __E''ND__{_STATUS[self.shell]}")
        self.child.expect(r"__BEGIN__\r?\n")
        self.child.expect(r"__END__(\d+)")
        output = self.child.before
        return plain(output).replace("\r\n", "\n").replace("\r", ""), int(self.child.match.group(1))

    def close(self) -> None:
        self.child.sendline("exit")
        self.child.close(force=True)


def plain(text: str) -> str:
    """``text`` without terminal escape sequences a line editor may have written."""
    return re.sub(r"\x1b\[[0-9;?]*[A-Za-z]|\x1b\][^\x07]*\x07|\x1b[=>]", "", text)
