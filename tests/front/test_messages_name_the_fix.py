"""Messages that name the fix (#42 items 18-20): a result that needs another option says which,
each surface spells names as it takes them, and every example in a message works as typed."""

from __future__ import annotations

import shlex

import pytest

import taucli
from conftest import assert_usage_error, run_taucli
from taucli.options import SCENES
from taucli.quantities.kinds import KINDS

NEEDING = [(command, result) for command in SCENES.values() for result in command.results if getattr(result, "needs", ())]


def test_results_that_need_an_option_say_so_in_the_table():
    keys = {(command.name, result.key) for command, result in NEEDING}
    assert {("atwood", "v"), ("atwood", "t"), ("spin-down", "omega")} <= keys
    for command, result in NEEDING:
        assert all(command.option(name) is not None for name in result.needs), (command.name, result.key)


@pytest.mark.parametrize("command, result", NEEDING, ids=[f"{c.name}-{r.key}" for c, r in NEEDING])
def test_a_result_that_needs_an_option_names_it(command, result):
    """--get RESULT where no option that makes it was given: "RESULT needs --a or --b", and the
    first of them, given as the example says, makes it."""
    args = shlex.split(command.example)[1:]
    assert not set(result.needs) & {arg[2:].replace("-", "_") for arg in args}
    refused = run_taucli(*args, "--get", result.key)
    flags = [command.option(name).flag for name in result.needs]
    assert_usage_error(refused, f"--get: {result.key} needs ", *flags)
    first = command.option(result.needs[0])
    made = run_taucli(*args, first.flag, KINDS[first.kind].example.strip("'"), "--get", result.key)
    assert made.code == 0 and made.out.strip(), (made, first.flag)


def test_the_two_messages_of_the_issue():
    assert_usage_error(run_taucli("atwood", "--m1", "4kg", "--m2", "1kg", "--get", "v"),
                       "--get: v needs --distance or --time (e.g. --distance '0.2 m')")
    assert_usage_error(run_taucli("spin-down", "--inertia", "2", "--omega0", "30rad/s", "--friction", "1", "--get", "omega"),
                       "--get: omega needs --time, --until-omega or --until-angle")
    assert_usage_error(run_taucli("spin-down", "--inertia", "2", "--omega0", "30rad/s", "--friction", "1", "--to", "omega=rpm"),
                       "--to: omega needs --time")


def test_python_names_the_keyword_that_makes_a_result():
    report = taucli.atwood(m1="4kg", m2="1kg")
    with pytest.raises(taucli.MissingResult) as raised:
        report.results["v"]
    assert "distance= or time=" in str(raised.value)


# item 19: each surface spells names as it takes them


def _keywords(command) -> tuple[list[str], dict[str, str]]:
    """A scene's example as the Python API takes it: positional words, and keywords."""
    words, given = [], {}
    args = iter(shlex.split(command.example)[2:])
    for arg in args:
        if arg.startswith("--"):
            given[arg[2:].replace("-", "_")] = next(args)
        else:
            words.append(arg)
    return words, given


def _variants(command):
    """The example, and the example with each keyword left out in turn (a note or an error each)."""
    words, given = _keywords(command)
    yield words, given
    for name in given:
        yield words, {key: value for key, value in given.items() if key != name}


def _flags_in(text: str, command) -> list[str]:
    return [option.flag for option in command.options if option.flag in text.replace("—", " ")]


@pytest.mark.parametrize("command", list(SCENES.values()), ids=list(SCENES))
def test_python_notes_and_errors_name_keywords_not_flags(command):
    function = getattr(taucli, command.function_name)
    said = []
    for words, given in _variants(command):
        try:
            said += function(*words, **given).notes
        except taucli.InputError as err:
            said.append(str(err))
    for text in said:
        assert not _flags_in(text, command), (text, command.name)


def test_python_and_batch_spell_the_pulley_as_keywords():
    notes = taucli.atwood(m1="4kg", m2="1kg", pulley_mass="2kg").notes
    assert any("give pulley_radius for" in note for note in notes) and any("pulley_shape ring" in note for note in notes), notes
    with pytest.raises(taucli.InputError, match=r"radius2 is required with radius1 \(or pulley_radius for it\)"):
        taucli.atwood(m1="4kg", m2="1kg", radius1="0.1m")
    lines = '{"m1": "4kg", "m2": "1kg", "pulley_mass": "2kg"}\n{"m1": "4kg", "m2": "1kg", "radius1": "0.1m"}\n'
    run = run_taucli("atwood", "--batch", stdin=lines)
    assert "give pulley_radius for" in run.out and "--pulley" not in run.out, run.out
    cli = run_taucli("atwood", "--m1", "4kg", "--m2", "1kg", "--radius1", "0.1m")
    assert_usage_error(cli, "--radius2 is required with --radius1 (or --pulley-radius for it)")
