"""The console examples of README and of every page in docs/ print what the page shows (at 80 columns).

Each ```console block is a short session: `$ cat FILE` shows a file the next commands read (the
test writes it), and `$ taucli ...` shows a command and all it printed, stdout then stderr.
Commands with a pipe or a redirect run in bash, in a folder holding the block's files (jq, which
some pipe into, is installed by .ci/run); `taucli bench` is left out (its timings differ from run
to run). A test below counts what is checked, so that no page can drift out of it.
"""

from __future__ import annotations

import shlex
import shutil
import subprocess

import pytest

from conftest import run_taucli
from pages import fit_output_agrees, lines_of, needs, piped, sessions, shell_env, with_docs


def test_the_pages_have_examples_to_check():
    assert len(sessions()) >= 80
    assert sum(piped(command) for command, _, _ in sessions()) >= 2


@pytest.mark.parametrize("command,printed,files", sessions(), ids=[command[:70] for command, _, _ in sessions()])
def test_an_example_prints_what_its_page_shows(command, printed, files, tmp_path, monkeypatch):
    for name, text in files.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    with_docs(tmp_path)
    monkeypatch.chdir(tmp_path)
    if piped(command):
        if "jq" in command:
            needs("jq")
        done = subprocess.run(["bash", "-c", command], capture_output=True, text=True, env=shell_env(tmp_path), cwd=tmp_path, timeout=60)
        out, err = done.stdout, done.stderr
    else:
        result = run_taucli(*shlex.split(command)[1:], env={"COLUMNS": "80"})
        out, err = result.out, result.err
    assert fit_output_agrees(command, out, err, printed), (lines_of(out + err), lines_of(printed))


@pytest.mark.parametrize("shell", ["zsh", "fish"])
def test_every_readme_and_docs_command_works_as_typed_in_zsh_and_fish(shell, tmp_path):
    """#16 item 17: `--friction 0.3N*m` unquoted is a glob, and zsh stops at 'no matches found'.
    Each command of README and docs/, run by the shell itself (in a folder with its block's files),
    exits and prints as it does when bash runs it."""
    needs(shell)
    found = shutil.which(shell)
    env = shell_env(tmp_path)
    commands = sessions()
    assert len(commands) >= 80
    for number, (command, _, files) in enumerate(commands):
        if "jq" in command and shutil.which("jq") is None:
            continue  # (the test above says so)
        folder = tmp_path / str(number)
        folder.mkdir()
        with_docs(folder)
        for name, text in files.items():
            (folder / name).write_text(text, encoding="utf-8")
        in_bash = subprocess.run(["bash", "-c", command], capture_output=True, text=True, env=env, cwd=folder, timeout=60)
        in_shell = subprocess.run([found, "-c", command], capture_output=True, text=True, env=env, cwd=folder, timeout=60)
        assert "no matches found" not in in_shell.stderr and "No matches for wildcard" not in in_shell.stderr, (command, in_shell.stderr)
        assert in_shell.returncode == in_bash.returncode, (command, in_shell.stderr)
        assert in_shell.stdout == in_bash.stdout, command
