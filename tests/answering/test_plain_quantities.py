"""The batch's shortcut (answering.inputs._plain_quantities: options read as one quantity at once)
takes exactly the options ``_repeated`` itself reads as one quantity: one that reads words, another
kind, a repeat or a formula of t goes the long way. A merge once let formulas of t take the short
way, and `--torque '10 N*m/s * t'` was refused as not a torque."""

from __future__ import annotations

import pytest

from taucli.answering import inputs
from taucli.options import COMMANDS
from taucli.quantities import units


@pytest.mark.parametrize("name", sorted(COMMANDS))
def test_the_shortcut_takes_only_plain_quantities(name):
    command = COMMANDS[name]
    plain = inputs._plain_quantities(command)
    for option in command.options:
        special = option.words or option.also is not None or option.repeatable or getattr(option, "of_time", False)
        if option.kind in units.KINDS and not special:
            assert plain.get(option.name) == (option.kind, option.sign), option.name
        else:
            assert option.name not in plain, option.name


def test_a_formula_of_time_is_read_from_the_command_line_batch_and_python():
    import taucli
    from conftest import run_taucli
    ran = run_taucli("spin-down", "--inertia", "2kg*m^2", "--torque", "10 N*m/s * t", "--time", "2s", "--get", "omega")
    assert ran.code == 0 and float(ran.out) == pytest.approx(10.0, rel=1e-12), ran.err  # ω = ∫10t dt / I = 5t²/2 at 2 s
    assert taucli.spin_down(inertia="2 kg*m^2", torque="10 N*m/s * t", time="2 s").results["omega"].value == pytest.approx(10.0, rel=1e-12)
