"""Messages that name the fix for a command line the shell split otherwise than meant (#36 item 5).

Each is one line on stderr, exit 2, naming the option and an example that works as typed.
"""

from __future__ import annotations

import pytest

from conftest import run_taucli
from taucli.scenes.shapes import OTHER_NAMES, SHAPES
from terminal import SHELLS, Terminal


def _refused(*args: str) -> str:
    run = run_taucli(*args)
    assert run.code == 2 and run.out == "", run
    assert run.err.count("\n") == 1 and run.err.startswith("taucli: error: ")
    return run.err


@pytest.mark.parametrize("args", [
    ("atwood", "--m1", "--m2", "1kg"),
    ("atwood", "--m1", "--m2"),
    ("atwood", "--m2", "1kg", "--m1"),
    ("atwood", "--m1", "--help"),
])
def test_an_option_left_without_its_value(args):
    assert "--m1 needs a value (e.g. --m1 4kg)" in _refused(*args)


def test_the_example_of_a_missing_value_is_typed_for_every_shell():
    assert "--inertia needs a value (e.g. --inertia '0.1 kg*m^2')" in _refused("spin-down", "--inertia", "--omega0", "1rad/s")
    assert "--pulley-shape needs a value (e.g. --pulley-shape disc)" in _refused("atwood", "--m1", "1kg", "--pulley-shape")


def test_a_value_with_spaces_left_unquoted():
    err = _refused("spin-down", "--inertia", "0.1", "--omega0", "30rad/s", "--torque", "2", "N", "m")
    assert "--torque '2 N m'" in err and "--torque 2Nm" in err
    err = _refused("spin-down", "--inertia", "0.1", "--omega0", "30rad/s", "--torque", "2", "N*m")
    assert "--torque '2 N*m'" in err and "--torque '2N*m'" in err  # the joined form quoted too: it holds a *
    assert "--m1 4kg" in _refused("atwood", "--m1", "4", "kg", "--m2", "1kg")


def test_the_suggested_spellings_give_the_answer():
    quoted = run_taucli("spin-down", "--inertia", "0.1", "--omega0", "30rad/s", "--torque", "2 N m", "--get", "alpha0")
    joined = run_taucli("spin-down", "--inertia", "0.1", "--omega0", "30rad/s", "--torque", "2Nm", "--get", "alpha0")
    assert quoted.code == joined.code == 0 and float(quoted.out) == float(joined.out) == pytest.approx(20.0)


@pytest.mark.parametrize("args,meant", [(("-help",), "--help"), (("atwood", "-help"), "--help"), (("atwood", "-m1", "4kg"), "--m1")])
def test_a_long_option_with_one_dash(args, meant):
    assert f"did you mean {meant}?" in _refused(*args)


@pytest.mark.parametrize("args,command", [(("help",), None), (("help", "atwood"), "atwood"), (("help", "pendulum"), "pendulum"), (("atwood", "help"), "atwood")])
def test_help_as_a_command(args, command):
    run = run_taucli(*args)
    assert run.code == 0 and run.err == ""
    assert run.out == run_taucli(*((command,) if command else ()), "--help").out
    if command is None:
        assert "Commands:" in run.out and "atwood" in run.out


def test_help_for_a_command_that_does_not_exist_is_refused():
    """taucli help atwod printed taucli's own help with exit 0, as if asked for it."""
    err = _refused("help", "atwod")
    assert "help: expected a command" in err and "did you mean 'atwood'?" in err


@pytest.mark.parametrize("word,meant", [("cylinder", "disc"), ("Cylinder", "disc"), ("cilinder", "disc"), ("hoop", "ring"), ("hollow-cylinder", "tube"), ("ball", "sphere")])
def test_another_word_for_a_shape_is_refused_with_the_name_to_use(word, meant):
    """Refused, never taken: docs/inertia.md says why."""
    err = _refused("inertia", word, "--mass", "5kg", "--radius", "0.2m")
    assert f"did you mean {meant!r}?" in err
    assert f"did you mean {meant!r}?" in _refused("spin-down", "--shape", word, "--mass", "5kg", "--radius", "0.2m", "--omega0", "1rad/s")


def test_the_other_names_point_at_shapes():
    assert set(OTHER_NAMES.values()) <= set(SHAPES) and not set(OTHER_NAMES) & set(SHAPES)


@pytest.mark.parametrize("shell", SHELLS)
def test_the_fixes_as_a_shell_splits_the_words(shell):
    """Typed in a real shell: the shell's own splitting is what the message explains."""
    terminal = Terminal(shell, 80)
    try:
        said, status = terminal.run("taucli atwood --m1 --m2 1kg")
        assert status == 2 and "--m1 needs a value (e.g. --m1 4kg)" in said
        said, status = terminal.run("taucli spin-down --inertia 0.1 --omega0 30rad/s --torque 2 N m")
        assert status == 2 and "--torque '2 N m'" in said and "--torque 2Nm" in said
        said, status = terminal.run("taucli spin-down --inertia 0.1 --omega0 30rad/s --torque '2 N m' --get alpha0")
        assert status == 0 and said.strip() == "20"
        said, status = terminal.run("taucli -help")
        assert status == 2 and "did you mean --help?" in said
        said, status = terminal.run("taucli help")
        assert status == 0 and "Commands:" in said
        said, status = terminal.run("taucli inertia cylinder --mass 5kg --radius 0.2m")
        assert status == 2 and "did you mean 'disc'?" in said
    finally:
        terminal.close()
