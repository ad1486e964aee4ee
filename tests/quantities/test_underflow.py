"""A value written nonzero that a double rounds to 0 is bounded as written (#43 item 4):
`--friction '1e-400 N*m'` was read as 0 and passed the bounds ("never stops") while `1e-41` was
refused. Every kind, and every place a number is read: an option's text, a spec's key, a
vector's component, a batch line's JSON number, a torque profile's cell."""

from __future__ import annotations

import io
import json

import pytest

from taucli.core.errors import InputError
from taucli.front.cli import Environment, main
from taucli.quantities import units
from taucli.quantities.kinds import KINDS

BELOW = "nonzero but below what a double holds"


@pytest.mark.parametrize("kind", sorted(KINDS))
def test_every_kind_refuses_a_value_below_a_double(kind):
    unit = KINDS[kind].si_unit
    for text in (f"1e-400 {unit}", f"-3.5e-330 {unit}", f"1e-200*1e-200 {unit}", f"1e-323 m{unit}" if unit == "m" else f"1e-400 {unit}"):
        with pytest.raises(InputError, match=BELOW):
            units.parse(text.strip(), "{x}", kind, sign="any")
    for zero in (f"0 {unit}", f"0.0e-400 {unit}", f"(2-2) {unit}"):
        assert units.parse(zero.strip(), "{x}", kind, sign="any").value == 0


def _run(args, stdin=""):
    out, err = io.StringIO(), io.StringIO()
    code = main(args, Environment(stdin=io.StringIO(stdin), stdout=out, stderr=err))
    return code, out.getvalue(), err.getvalue()


@pytest.mark.parametrize("args", [
    ["spin-down", "--inertia", "1", "--omega0", "30rad/s", "--friction", "1e-400 N*m"],
    ["spin-down", "--inertia", "1", "--omega0", "30rad/s", "--brake", "force=1e-400N mu=0.4 radius=0.5m"],
    ["inertia", "disc", "--mass", "1kg", "--radius", "0.1m", "--part", "point mass=1e-400kg offset=1m"],
    ["torque", "--r", "1e-400,0.4,0 m", "--force", "0,0,10 N"],
])
def test_the_command_line_refuses_it_wherever_it_is_typed(args):
    code, out, err = _run(args)
    assert code == 2 and out == "" and BELOW in err and len(err.splitlines()) == 1, err


def test_a_batch_lines_json_number_and_a_profiles_cell(tmp_path):
    lines = '{"inertia": 1, "omega0": "30rad/s", "friction": 1e-400}\n{"inertia": 1, "omega0": "30rad/s", "friction": 0.0}\n'
    code, out, _ = _run(["spin-down", "--batch", "--no-steps"], lines)
    refused, answered = (json.loads(line) for line in out.splitlines())
    assert code == 2 and BELOW in refused["error"]["message"] and answered["inputs"]["friction"]["value"] == 0.0
    profile = tmp_path / "pulse.csv"
    profile.write_text("t [s], torque [N*m]\n0,1\n1,1e-400\n2,1\n")
    code, out, err = _run(["impulse", "--inertia", "1", "--omega0", "0", "--torque-profile", str(profile)])
    assert code == 2 and BELOW in err and "line 3" in err, err
