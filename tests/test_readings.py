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


# 4. ranges


@pytest.mark.parametrize("text", ["1...5kg", "1....5kg", "1..5..9kg", "1..5...9kg"])
def test_a_range_is_two_dots_exactly(text):
    assert_usage_error(
        run_taucli("inertia", "disc", "--mass", text, "--radius", "0.2m", "--get", "I"),
        "--mass: expected a range FROM..TO (two dots) or a list A,B (e.g. --mass 1..5kg or --mass 1,5kg)", f"got '{text}'",
    )


def test_a_range_example_is_quoted_where_a_shell_needs_it():
    assert_usage_error(run_taucli("spin-down", "--inertia", "1", "--torque", "1...2N*m"), "(e.g. --torque '1..5N*m' or --torque '1,5N*m')")


@pytest.mark.parametrize("text,fix", [("1-5kg", "1..5kg"), ("1 - 5 kg", "1..5kg"), ("1–5kg", "1..5kg"), ("0.5-4 kg m^2", "'0.5..4kg*m^2'")])
def test_a_dash_between_two_numbers_is_refused_naming_the_range(text, fix):
    kind = "moment of inertia" if "m^2" in text else "mass"
    with pytest.raises(InputError) as refused:
        units.parse(text, "--x", kind)
    assert f"got {text!r}: a dash between two numbers; a range is written {fix}" in str(refused.value)


def test_a_subtraction_and_an_exponent_are_no_dash_between_numbers():
    assert units.parse("4kg-200g", "--x", "mass").value == pytest.approx(3.8, rel=1e-15)
    assert units.parse("1e-5kg", "--x", "mass").value == 1e-5
    assert units.parse("-5 N*m", "--x", "torque", sign="any").value == -5.0


def test_two_dots_still_sweep_from_one_end_to_the_other():
    done = run_taucli("inertia", "disc", "--mass", "1..5kg", "--radius", "1m", "--points", "3", "--get", "I")
    assert done.code == 0, done.err
    assert [line.split("\t") for line in done.out.splitlines()] == [["1.0", "0.5"], ["3.0", "1.5"], ["5.0", "2.5"]]


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


# 14. a prefix's name glued to a unit's symbol


@pytest.mark.parametrize(
    "text,kind,suggestion",
    [
        ("5kilos", "mass", "unknown unit 'kilos'; did you mean 'kg'?"),
        ("5 Kilos", "mass", "unknown unit 'Kilos'; did you mean 'kg'?"),
        ("5 kilos", "time", "unknown unit 'kilos'; did you mean 'ks'?"),
        ("5 megas", "mass", "unknown unit 'megas'; did you mean 'Mg'?"),
        ("5 millim", "length", "unknown unit 'millim'; did you mean 'mm'?"),
        ("5 kiloN", "force", "unknown unit 'kiloN'; did you mean 'kN'?"),
        ("5 micros", "time", "unknown unit 'micros'"),
        ("5 kilos + 2 kg", "mass", "unknown unit 'kilos'; did you mean 'kg'?"),
    ],
)
def test_a_prefix_name_glued_to_a_unit_symbol_is_an_unknown_unit(text, kind, suggestion):
    with pytest.raises(InputError) as refused:
        units.parse(text, "--x", kind)
    assert suggestion in str(refused.value)


@pytest.mark.parametrize(
    "text,kind,si",
    [("5 kilograms", "mass", 5.0), ("5 kg", "mass", 5.0), ("5 kilometres", "length", 5000.0), ("5 kmeter", "length", 5000.0),
     ("5 mins", "time", 300.0), ("5 hrs", "time", 18000.0), ("5 microns", "length", 5e-6), ("5 Ms", "time", 5e6), ("1 kWh", "energy", 3.6e6)],
)  # fmt: skip
def test_names_with_names_and_symbols_with_symbols_still_read(text, kind, si):
    assert units.parse(text, "--x", kind).value == pytest.approx(si, rel=1e-14)
