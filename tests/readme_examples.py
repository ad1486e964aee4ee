"""Rewrite the console examples of README and docs/ with what taucli prints now (at 80 columns).

    python tests/readme_examples.py README.md docs/*.md

The same commands tests/front/test_readme.py checks (no pipes, redirects or `taucli bench`); files a
block shows with `$ cat FILE` are written to a scratch folder first. Run it after a change that
alters what a scene prints, then read the diff: a changed number is a changed answer.
"""

from __future__ import annotations

import os
import re
import shlex
import subprocess
import sys
import tempfile
from pathlib import Path


def rewrite(text: str) -> str:
    def block(match: re.Match) -> str:
        body = match.group(1)
        entries = re.split(r"^\$ ", body, flags=re.M)
        out = [entries[0]]
        with tempfile.TemporaryDirectory() as scratch:
            Path(scratch, "docs").symlink_to(Path(__file__).resolve().parent.parent / "docs", target_is_directory=True)  # docs/data/... by path
            for entry in entries[1:]:
                command, _, printed = entry.partition("\n")
                if command.startswith("cat ") and " " not in command[4:]:
                    Path(scratch, command[4:]).write_text(printed, encoding="utf-8")
                elif command.startswith("taucli ") and not re.search(r"[|<>]", command) and not command.startswith("taucli bench"):
                    done = subprocess.run(
                        [sys.executable, "-m", "taucli", *shlex.split(command)[1:]], capture_output=True, text=True,
                        cwd=scratch, env={**os.environ, "COLUMNS": "80"},
                    )  # fmt: skip
                    printed = done.stdout + done.stderr
                out.append(f"{command}\n{printed}")
        return "```console\n" + "$ ".join(out) + "```"

    return re.sub(r"```console\n(.*?)```", block, text, flags=re.S)


if __name__ == "__main__":
    for name in sys.argv[1:]:
        path = Path(name)
        path.write_text(rewrite(path.read_text(encoding="utf-8")), encoding="utf-8")
