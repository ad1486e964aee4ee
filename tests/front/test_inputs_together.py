"""What inputs make together is bounded as each one is (#43 item 6): nine stages of `--ratio 1e-40`
multiply to below a double (ZeroDivisionError, exit 1). Every repeatable quantity option of every
scene, given many times at the smallest and the largest value its kind takes, in a run that is
otherwise the scene's example: an answer or one line of usage error, never exit 1."""

from __future__ import annotations

import io
import shlex

import pytest

from taucli.front.cli import Environment, main
from taucli.options import SCENES
from taucli.quantities.kinds import KINDS

REPEATED = [(scene, option) for scene, command in sorted(SCENES.items()) for option in command.options
            if option.repeatable and (option.kind in KINDS or option.of in KINDS)]


def _run(args):
    out, err = io.StringIO(), io.StringIO()
    code = main(args, Environment(stdin=io.StringIO(), stdout=out, stderr=err))
    return code, out.getvalue(), err.getvalue()


@pytest.mark.parametrize(("scene", "option"), REPEATED, ids=[f"{scene}{option.flag}" for scene, option in REPEATED])
@pytest.mark.parametrize("size", [1e-40, 1e40])
@pytest.mark.parametrize("copies", [2, 9])
def test_many_values_at_a_bound_are_answered_or_refused_in_one_line(scene, option, size, copies):
    kind = KINDS[option.kind if option.kind in KINDS else option.of]
    value = f"{size:g} {kind.si_unit}".strip()
    example = [word for word in shlex.split(SCENES[scene].example)[2:]]
    code, out, err = _run([scene, *example, *[word for _ in range(copies) for word in (option.flag, value)], "--get", SCENES[scene].headline])
    assert code in (0, 2), (code, err)
    if code == 2:
        assert out == "" and len(err.splitlines()) == 1 and err.startswith("taucli: error: "), err


def test_the_issues_example():
    code, out, err = _run(["drive", "--motor-inertia", "1.2 kg*cm^2", *["--ratio", "1e-40"] * 9, "--load-inertia", "0.05 kg*m^2",
                           "--until-omega", "3000rpm", "--in-time", "0.2s"])
    assert code == 2 and out == "" and "--ratio: expected a dimensionless between 1e-40 and 1e40" in err and "N below 1e-308 from the stages" in err, err
