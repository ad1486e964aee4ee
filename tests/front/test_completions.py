"""Shell completion: the committed scripts are what the app generates, and they work in real
bash, zsh and fish, installed as docs/shell.md says, with TAB pressed in a terminal (a pty).

The `taucli` on PATH in these shells is a stub that records being run: TAB must never start it.
The shells come from Debian's packages (bash-completion, zsh, fish); .ci/run installs them.
Without them the shell tests skip, except in CI, where they fail.
"""

from __future__ import annotations

import fcntl
import os
import pty
import re
import select
import shutil
import signal
import struct
import termios
import time
from pathlib import Path


import pytest

from conftest import run_taucli
from taucli.front import completions
from taucli.core import names

COMPLETIONS = Path(__file__).resolve().parents[2] / "completions"


@pytest.mark.parametrize("shell", completions.SHELLS)
def test_the_committed_script_is_a_fresh_generation(shell):
    committed = (COMPLETIONS / completions.FILE_NAMES[shell]).read_text()
    assert committed == completions.script(shell), f"completions/ is stale: run taucli completions {shell} > completions/{completions.FILE_NAMES[shell]}"


@pytest.mark.parametrize("shell", completions.SHELLS)
def test_taucli_completions_prints_the_script(shell):
    done = run_taucli("completions", shell)
    assert done.code == 0 and done.out == (COMPLETIONS / completions.FILE_NAMES[shell]).read_text()


def test_an_unknown_shell_is_a_usage_error():
    done = run_taucli("completions", "tcsh")
    assert done.code == 2 and "expected one of bash, zsh, fish" in done.err


def test_every_option_of_every_command_is_offered():
    import typer.main

    from taucli.front.cli import Environment, build_app
    from taucli.options import COMMANDS

    _, commands = completions.spec()
    offered = {command.name: {option.flag for option in command.options} for command in commands}
    for name, command in typer.main.get_command(build_app(Environment())).commands.items():
        flags = {opt for param in command.params if param.param_type_name == "option" for opt in param.opts}
        assert flags | {"--help"} == offered[name]
    assert tuple(offered) == tuple(COMMANDS)


# --- in the real shells -------------------------------------------------------------------




def _shell_or_skip(name: str) -> str:
    """The shell, or a skip saying what to install (under CI a failure: .ci/run installs them).
    The tests install nothing themselves (#16 item 19)."""
    found = shutil.which(name)
    if found is None:
        if os.environ.get("CI"):
            pytest.fail(f"{name} is not installed: .ci/run installs bash-completion, zsh and fish")
        pytest.skip(f"{name} is not installed (apt-get install bash-completion zsh fish)")
    return found


def _strip_terminal(raw: bytes) -> str:
    text = raw.decode("utf-8", "replace")
    text = re.sub(r"\x1b\][^\x07]*\x07|\x1b\[[0-9;?]*[ -/]*[@-~]|\x1b[()][A-Z0-9]|\x1b[=>78]|[\r\x07\x08]", "", text)
    return text.replace("\\", "")


def _press_tab(argv: list[str], env: dict[str, str], setup: list[str], ready: str, typed: str) -> str:
    """Start an interactive shell on a pty, run ``setup``, type ``typed`` (TABs included), and
    return what the terminal shows after it, escape sequences removed."""
    pid, fd = pty.fork()
    if pid == 0:  # the child: the shell
        os.execvpe(argv[0], argv, env)
    fcntl.ioctl(fd, termios.TIOCSWINSZ, struct.pack("HHHH", 50, 200, 0, 0))
    shown = b""

    def read(seconds: float, until: bytes | None = None, quiet: float = 0.4) -> None:
        """Read what the shell shows until ``until`` appears, or it is quiet for ``quiet`` s."""
        nonlocal shown
        end = time.monotonic() + seconds
        last = time.monotonic()
        while time.monotonic() < end:
            ready_now, _, _ = select.select([fd], [], [], 0.05)
            if ready_now:
                try:
                    shown += os.read(fd, 65536)
                except OSError:
                    return
                last = time.monotonic()
                if until is not None and until in shown:
                    return
            elif until is None and time.monotonic() - last > quiet:
                return

    try:
        for line in [*setup, ready]:
            os.write(fd, line.encode() + b"\n")
        read(20, b"READY42")
        start = len(shown)
        for chunk in typed.split("\t")[:-1]:
            os.write(fd, chunk.encode() + b"\t")
            read(5)
        os.write(fd, typed.split("\t")[-1].encode())
        read(5)
        return _strip_terminal(shown[start:])
    finally:
        os.kill(pid, signal.SIGKILL)
        os.waitpid(pid, 0)
        os.close(fd)


def _stub_taucli(home: Path) -> Path:
    """A `taucli` that only records that it ran: fish completes only commands on PATH."""
    bin_dir = home / "bin"
    bin_dir.mkdir()
    stub = bin_dir / "taucli"
    stub.write_text(f"#!/bin/sh\necho ran >> {home / 'taucli-ran'}\n")
    stub.chmod(0o755)
    return bin_dir


def _install(shell: str, home: Path) -> tuple[list[str], dict[str, str], list[str], str]:
    """The shell installed as docs/shell.md says; its argv, environment, setup lines and ready line."""
    bin_dir = _stub_taucli(home)
    env = {"HOME": str(home), "PATH": f"{bin_dir}:/usr/bin:/bin", "TERM": "xterm", "LANG": "C.UTF-8"}
    script = COMPLETIONS / completions.FILE_NAMES[shell]
    if shell == "bash":
        target = home / ".local/share/bash-completion/completions/taucli"
        target.parent.mkdir(parents=True)
        shutil.copy(script, target)
        loader = "/usr/share/bash-completion/bash_completion"
        if not os.path.exists(loader):
            _shell_or_skip("bash-completion's loader")
        return [_shell_or_skip("bash"), "--norc", "--noprofile", "-i"], {**env, "PS1": "$ "}, [f"source {loader}"], "echo READY$((40+2))"
    if shell == "zsh":
        target = home / ".zfunc/_taucli"
        target.parent.mkdir(parents=True)
        shutil.copy(script, target)
        setup = ["fpath=(~/.zfunc $fpath)", "autoload -U compinit && compinit -u", "PS1='$ '"]
        return [_shell_or_skip("zsh"), "-f", "-i"], env, setup, "echo READY$((40+2))"
    target = home / ".config/fish/completions/taucli.fish"
    target.parent.mkdir(parents=True)
    shutil.copy(script, target)
    return [_shell_or_skip("fish"), "-i", "-C", "set -g fish_greeting ''"], env, [], "echo READY(math 40 + 2)"


CASES = {
    # what is typed (TABs included) -> what the terminal must then show
    "a command": ("taucli at\t", ["taucli atwood"]),
    "the shapes": ("taucli inertia \t\t", list(names.SHAPE_NAMES)),
    "the pulley options": ("taucli atwood --pu\t\t\t", ["--pulley-mass", "--pulley-radius", "--pulley-shape", "--pulley-inertia"]),
    "units after a number": ("taucli atwood --m1 4\t\t", ["4kg", "4lb", "4tonne"]),
    "methods": ("taucli spin-down --method r\t\t\t", ["rk4", "rk45"]),
}


@pytest.mark.parametrize("shell", completions.SHELLS)
@pytest.mark.parametrize("case", list(CASES))
def test_tab_in_the_real_shell(shell, case, tmp_path):
    typed, expected = CASES[case]
    argv, env, setup, ready = _install(shell, tmp_path)
    shown = _press_tab(argv, env, setup, ready, typed)
    for word in expected:
        assert word in shown, (shell, typed, shown)
    assert not (tmp_path / "taucli-ran").exists(), "pressing TAB ran taucli"


# --- #36 item 6 -------------------------------------------------------------------------------


def _bash_without_the_package(home: Path) -> tuple[list[str], dict[str, str], list[str], str]:
    """bash with no bash-completion package: the script saved where README says and sourced, as
    the line README adds to ~/.bashrc does (bash --norc: nothing else is loaded)."""
    bin_dir = _stub_taucli(home)
    shutil.copy(COMPLETIONS / completions.FILE_NAMES["bash"], home / ".taucli.bash")
    env = {"HOME": str(home), "PATH": f"{bin_dir}:/usr/bin:/bin", "TERM": "xterm", "LANG": "C.UTF-8", "PS1": "$ "}
    return [_shell_or_skip("bash"), "--norc", "--noprofile", "-i"], env, ["source ~/.taucli.bash"], "echo READY$((40+2))"


def test_bash_without_the_bash_completion_package(tmp_path):
    argv, env, setup, ready = _bash_without_the_package(tmp_path)
    shown = _press_tab(argv, env, setup, ready, "type _init_completion >/dev/null 2>&1 || echo NO-PACKAGE; complete -p taucli\n")
    assert "NO-PACKAGE" in shown and "complete -F _taucli taucli" in shown
    for typed, expected in (CASES["a command"], CASES["units after a number"], CASES["the shapes"], ("taucli inertia rod --axis \t\t", ["center", "end"])):
        shown = _press_tab(argv, env, setup, ready, typed)
        assert all(word in shown for word in expected), (typed, shown)
    assert not (tmp_path / "taucli-ran").exists()


def test_readme_says_how_to_source_the_bash_script():
    readme = (COMPLETIONS.parent / "README.md").read_text(encoding="utf-8")
    shell_page = (COMPLETIONS.parent / "docs/shell.md").read_text(encoding="utf-8")
    for text in (readme, shell_page):
        assert "taucli completions bash > ~/.taucli.bash" in text and "source ~/.taucli.bash" in text and "~/.bashrc" in text


AXES = {
    # typed -> (axes offered, axes not offered)
    "taucli inertia rod --axis \t\t": (["center", "end"], ["diameter", "edge-width", "central"]),
    "taucli inertia plate --mass 1kg --axis \t\t": (["center-width", "edge-height", "normal"], ["diameter", "central "]),
    "taucli spin-down --shape box --axis \t\t": (["height", "width", "depth"], ["diameter", "center-width"]),
    "taucli pendulum --shape disc --axis \t\t": (["central", "diameter"], ["edge-width", "depth"]),
}


@pytest.mark.parametrize("shell", completions.SHELLS)
@pytest.mark.parametrize("typed", list(AXES))
def test_axis_offers_the_axes_of_the_shape_typed(shell, typed, tmp_path):
    argv, env, setup, ready = _install(shell, tmp_path) if shell != "bash" else _bash_without_the_package(tmp_path)
    shown = _press_tab(argv, env, setup, ready, typed)
    offered, not_offered = AXES[typed]
    tail = shown.split("--axis", 1)[-1]
    assert all(axis in tail for axis in offered), (shell, typed, shown)
    assert not any(axis in tail for axis in not_offered), (shell, typed, shown)


def test_axis_with_no_shape_typed_offers_every_axis():
    _, commands = completions.spec()
    axis = next(option for command in commands if command.name == "inertia" for option in command.options if option.flag == "--axis")
    assert axis.axes
    bash = completions.script("bash")
    assert '*) axes="distance central diameter center end' in bash


@pytest.mark.parametrize("shell", ["fish", "zsh"])
def test_each_result_of_get_has_its_own_label(shell, tmp_path):
    argv, env, setup, ready = _install(shell, tmp_path)
    shown = _press_tab(argv, env, setup, ready, "taucli atwood --get T\t")
    assert "tension on m1's side" in shown and "tension on m2's side" in shown, shown
    script = completions.script("fish")
    gets = [line for line in script.splitlines() if "from atwood'" in line and " -l get " in line]
    labels = [line.rsplit(" -d ", 1)[1] for line in gets]
    assert len(gets) == len(completions.COMMANDS["atwood"].results) and len(set(labels)) == len(labels)


FIT = {
    # typed -> (offered, not offered): fit's --fit offers the inputs of the scene typed (#42 item 23)
    "taucli fit atwood a.csv --fit m\t\t": (["m1", "m2", "mu_k"], ["motor_inertia", "mass "]),
    "taucli fit spin-down coast.csv --fit friction,visc\t": (["friction,viscous"], ["m1"]),
}


@pytest.mark.parametrize("shell", completions.SHELLS)
@pytest.mark.parametrize("typed", list(FIT))
def test_fit_offers_the_inputs_of_the_scene_typed(shell, typed, tmp_path):
    argv, env, setup, ready = _install(shell, tmp_path) if shell != "bash" else _bash_without_the_package(tmp_path)
    shown = _press_tab(argv, env, setup, ready, typed)
    offered, not_offered = FIT[typed]
    tail = shown.split("--fit", 1)[-1]
    assert all(name in tail for name in offered), (shell, typed, shown)
    assert not any(name in tail for name in not_offered), (shell, typed, shown)
    assert not (tmp_path / "taucli-ran").exists()
