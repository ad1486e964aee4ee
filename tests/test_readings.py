"""Every answer right or refused (#31): readings that gave a wrong number, each now read as meant
or refused with the fix. The table of docs/units.md (tests/test_units_table.py) reads them through
every way in; here each item of the issue is pinned down on its own.

  2. a 1/time for an angular velocity or acceleration: revolutions where it says so (Hz, min^-1),
     radians for a speed over a length (ω = v/R), refused where it could be either (1/s, s^-1);
  3. a bare number for an angular velocity or acceleration: refused as a bare angle is, 0 aside,
     while a JSON number and a Python number stay SI;
  4. a range is A..B, a list A,B: "1...5kg" and "1-5kg" are refused, not read as 1 → 0.5 kg;
  9. a parenthesis in an expression is no uncertainty: only the grammar of "4.0(1)" makes one;
 14. a prefix's name glued to a unit's symbol ("kilos": pint's kilosecond) is an unknown unit.
"""

from __future__ import annotations

import json
import math

import pytest

import taucli
from conftest import assert_usage_error, run_taucli
from taucli import answer, measurement, units
from taucli.errors import InputError

PI = math.pi


# 9. a parenthesis is not an uncertainty


@pytest.mark.parametrize("text", ["250kg*(0.6m)^2", "(0.5) kg*m^2", "2*(3 kg)", "(2)(3) kg", "1/(2 s)"])
def test_a_parenthesis_in_an_expression_marks_no_uncertainty(text):
    assert not measurement.marked(text)
    assert answer.plain({"inertia": text})


@pytest.mark.parametrize("text", ["4.0(1) kg", "4.0(1)", "1.234(56)e3 m", "4.0+/-0.1 kg", "4.0 ± 0.1 kg", "(4.0 ± 0.1) kg"])
def test_an_uncertainty_is_marked_by_its_grammar(text):
    assert measurement.marked(text)
    assert not answer.plain({"inertia": text})


def test_a_torque_profile_takes_an_inertia_with_parentheses(tmp_path):
    """I = 250 kg × (0.6 m)² = 90 kg·m²; a 1 s pulse of 9 N·m: Δω = 9/90 = 0.1 rad/s."""
    (tmp_path / "pulse.csv").write_text("t,torque\n0,9\n1,9\n", encoding="utf-8")
    done = run_taucli("impulse", "--inertia", "250kg*(0.6m)^2", "--torque-profile", str(tmp_path / "pulse.csv"), "--omega0", "0", "--get", "omega1")
    assert done.code == 0, done.err
    assert float(done.out) == pytest.approx(0.1, rel=1e-12)
    refused = run_taucli("impulse", "--inertia", "90(1) kg*m^2", "--torque-profile", str(tmp_path / "pulse.csv"), "--omega0", "0")
    assert_usage_error(refused, "does not combine with an uncertainty")
