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
