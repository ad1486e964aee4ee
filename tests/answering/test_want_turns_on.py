"""--want RESULT=VALUE turns on what makes RESULT (#48 item 3), as --get, --y and --to do: a
result a flag makes (--energy: KE0) is never blamed on the range of the input solved for."""

from __future__ import annotations

import pytest

import taucli
from conftest import example_keys
from taucli.options import SCENES
from taucli.quantities.kinds import KINDS

MADE = [(command, option, result) for command in SCENES.values() for option in command.options for result in option.makes]


def test_the_issue_s_flywheel():
    """A 1500 rpm rotor braked by 40 MW: the inertia that stores 1200 MJ is 2E/ω² = 97,268 kg·m²."""
    report = taucli.spin_down(omega0="1500rpm", torque="-40MW/(1500rpm)", time="0.1s", find="inertia", want="KE0=1200MJ")
    omega = 1500 * 2 * 3.141592653589793 / 60
    assert report.results["inertia"].value == pytest.approx(2 * 1200e6 / omega**2, rel=1e-9)


@pytest.mark.parametrize("command, option, result", MADE, ids=[f"{c.name}-{o.name}-{r}" for c, o, r in MADE])
def test_a_result_a_flag_makes_can_be_wanted(command, option, result):
    """Every result a flag makes, wanted at its own value with each input of the example solved
    for: answered, or refused for a reason other than "gives no RESULT" (the flag left off)."""
    given = example_keys(command)
    function = getattr(taucli, command.function_name)
    made = function(**given, **{option.name: True}).results
    if result not in made or not isinstance(made[result].value, float):
        pytest.skip(f"the example makes no number {result} with {option.flag}")
    wanted = f"{result}={made[result].value!r} {made[result].unit or ''}".strip()
    tried = 0
    for name, text in given.items():
        option_given = command.option(name)
        if option_given is None or option_given.kind not in KINDS or option_given.positional:
            continue
        tried += 1
        try:
            function(**given, find=name, want=wanted)
        except taucli.InputError as err:
            assert f"gives no {result}" not in str(err), (name, str(err))
    assert tried
