"""Every answer right or refused (#31): readings that gave a wrong number, each now read as meant
or refused with the fix. The table of docs/units.md (tests/quantities/test_units_table.py) reads them through
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
from taucli.answering import answer
from taucli.quantities import measurement
from taucli.quantities import units
from taucli.core.errors import InputError

PI = math.pi


# 2. 1/time for a rotation


@pytest.mark.parametrize(
    "text,kind,reading",
    [
        ("80 1/s", "angular velocity", "(e.g. 80rad/s or 80rev/s), got '80 1/s': 1/s could be radians or revolutions per second"),
        ("80 s^-1", "angular velocity", "(e.g. 80rad/s or 80rev/s), got '80 s^-1': s^-1 could be radians or revolutions per second"),
        ("80/s", "angular velocity", "(e.g. 80rad/s or 80rev/s)"),
        ("80 s⁻¹", "angular velocity", "(e.g. 80rad/s or 80rev/s)"),
        ("2 1/h", "angular velocity", "(e.g. 2rad/h or 2rev/h), got '2 1/h': 1/h could be radians or revolutions per hour"),
        ("3 ms^-1", "angular velocity", "(e.g. 3rad/ms or 3rev/ms)"),
        ("2*40/s", "angular velocity", "(e.g. 80rad/s or 80rev/s)"),
        ("6 1/s^2", "angular acceleration", "(e.g. '6 rad/s^2' or '6 rev/s^2'), got '6 1/s^2': 1/s^2 could be radians or revolutions per second squared"),
        ("6 s^-2", "angular acceleration", "(e.g. '6 rad/s^2' or '6 rev/s^2')"),
    ],
)
def test_a_bare_reciprocal_time_is_refused_naming_both_readings(text, kind, reading):
    with pytest.raises(InputError) as refused:
        units.parse(text, "--omega0", kind, sign="any")
    assert str(refused.value).startswith(f"--omega0: expected {'an angular velocity' if kind == 'angular velocity' else 'an angular acceleration'} with its angle unit")
    assert reading in str(refused.value)


def test_the_refusal_names_examples_that_read_as_typed():
    """Each example the refusal gives is read back: 80rad/s as 80 rad/s, 80rev/s as 160π rad/s."""
    assert units.parse("80rad/s", "--x", "angular velocity").value == 80.0
    assert units.parse("80rev/s", "--x", "angular velocity").value == pytest.approx(160 * PI, rel=1e-15)
    assert units.parse("6 rad/s^2", "--x", "angular acceleration").value == 6.0
    assert units.parse("6 rev/s^2", "--x", "angular acceleration").value == pytest.approx(12 * PI, rel=1e-15)
    assert units.parse("300rpm", "--x", "angular velocity").value == pytest.approx(10 * PI, rel=1e-15)
    assert units.parse("6rpm/s", "--x", "angular acceleration").value == pytest.approx(PI / 5, rel=1e-15)


@pytest.mark.parametrize(
    "text,kind,si,note",
    [
        ("(90 km/h)/(60 m)", "angular velocity", 25 / 60, "--x (90 km/h)/(60 m): ω = v/R = 0.416667 rad/s"),
        ("25 m/s/m", "angular velocity", 25.0, "--x 25 m/s/m: ω = v/R = 25 rad/s"),
        ("(6 m/min)/(30 cm)", "angular velocity", 1 / 3, "ω = v/R = 0.333333 rad/s"),
        ("2*(10 m/s)/(0.5 m)", "angular velocity", 40.0, "ω = v/R = 40 rad/s"),
        ("(6 m/s^2)/(0.3 m)", "angular acceleration", 20.0, "--x (6 m/s^2)/(0.3 m): α = a_t/R = 20 rad/s²"),
        ("3000 min^-1", "angular velocity", 100 * PI, "min^-1 read as revolutions per minute"),
        ("50 Hz", "angular velocity", 100 * PI, "Hz read as revolutions per second"),
        ("1 Hz/s", "angular acceleration", 2 * PI, "Hz/s read as revolutions per second squared"),
        ("5 kHz", "angular velocity", 10000 * PI, "kHz read as 1000 revolutions per second"),  # not "per unit time"
        ("2 mHz", "angular velocity", 0.004 * PI, "mHz read as 1/1000 revolutions per second"),
        ("60 1/(min*s)", "angular acceleration", 2 * PI, "revolutions per unit time"),
        ("(50 Hz)*(0.1 m)/(0.2 m)", "angular velocity", 50 * PI, "with Hz as revolutions per second"),  # a gear's ratio of a frequency
    ],
)
def test_a_reciprocal_time_that_says_which_it_is_is_read_with_its_note(text, kind, si, note):
    parsed = units.parse(text, "--x", kind, sign="any")
    assert parsed.value == pytest.approx(si, rel=1e-14)
    assert parsed.note is not None and note in parsed.note, parsed.note


@pytest.mark.parametrize("text", ["(1 m)/(2 m)/s", "(10 m/s)/(0.5 s)", "(2 m/s)*(1/s)/(1 m/s)", "(1 m/m)*80/s"])
def test_a_length_in_a_reciprocal_time_is_no_speed_over_a_length_unless_it_is_one(text):
    """Only a speed divided by a length is v/R: a length ratio times 1/s is still a bare 1/s."""
    with pytest.raises(InputError):
        units.parse(text, "--x", "angular velocity", sign="any")


def test_a_speed_over_a_length_is_radians_on_the_command_line_with_its_note():
    """A wheel of radius 60 m rolling at 90 km/h: ω = v/R = 25/60 rad/s; t_stop = Iω/τ."""
    done = run_taucli("spin-down", "--inertia", "2", "--omega0", "(90 km/h)/(60 m)", "--friction", "0.5", "--json", "--no-steps")
    assert done.code == 0, done.err
    document = done.json()
    assert document["results"]["t_stop"]["value"] == pytest.approx(2 * (25 / 60) / 0.5, rel=1e-14)
    assert document["notes"] == ["--omega0 (90 km/h)/(60 m): ω = v/R = 0.416667 rad/s"]


def test_a_disc_spun_at_80_per_second_is_refused_not_read_as_revolutions():
    assert_usage_error(
        run_taucli("spin-down", "--inertia", "1", "--omega0", "80 s^-1", "--friction", "1"),
        "--omega0: expected an angular velocity with its angle unit (e.g. 80rad/s or 80rev/s), got '80 s^-1': s^-1 could be radians or revolutions per second",
    )


@pytest.mark.parametrize(
    "target,fragments",
    [
        ("omega=1/s", ("--to: expected a unit of an angular velocity that names its angle (e.g. rad/s or rev/s), got '1/s'", "radians or revolutions per second")),
        ("omega=s^-1", ("(e.g. rad/s or rev/s)", "got 's^-1'")),
        ("alpha0=1/s^2", ("(e.g. 'rad/s^2' or 'rev/s^2')", "got '1/s^2'")),
    ],
)
def test_to_reads_the_unit_asked_for_by_the_same_rule(target, fragments):
    assert_usage_error(run_taucli("spin-down", "--inertia", "1", "--omega0", "30rad/s", "--friction", "1", "--time", "1s", "--to", target), *fragments)


def test_to_hz_is_still_revolutions_per_second_with_a_note():
    done = run_taucli("spin-down", "--inertia", "1", "--omega0", "30rad/s", "--friction", "1", "--time", "1s", "--to", "omega=Hz", "--json")
    assert done.code == 0, done.err
    assert done.json()["results"]["omega"]["value"] == pytest.approx(29 / (2 * PI), rel=1e-14)
    assert "--to Hz: Hz read as revolutions per second (n = ω/2π)" in done.json()["notes"]


def test_want_reads_its_value_as_an_option_does_and_says_so():
    """--want omega=3000 min^-1 is 100π rad/s, with the note the option would have had."""
    done = run_taucli("spin-down", "--inertia", "1", "--torque", "1", "--time", "1s", "--find", "omega0", "--want", "omega=3000 min^-1", "--json")
    assert done.code == 0, done.err
    document = done.json()
    assert document["results"]["omega0"]["value"] == pytest.approx(100 * PI - 1, rel=1e-12)
    assert "--want omega 3000 min^-1: min^-1 read as revolutions per minute (ω = 2πn)" in document["notes"]


# 3. a bare number for a rotation rate


@pytest.mark.parametrize(
    "args,fragments",
    [
        (("spin-down", "--inertia", "1", "--omega0", "300", "--friction", "1"),
         ("--omega0: expected an angular velocity with its unit (e.g. 300rpm or 300rad/s), got '300': a number alone could be rpm or rad/s",)),
        (("spin-down", "--time", "1s", "--alpha", "6"), ("--alpha: expected an angular acceleration with its unit (e.g. 6rpm/s or '6 rad/s^2'), got '6'",)),
        (("impulse", "--inertia", "1", "--omega0", "0", "--omega1", "-2.5", "--torque", "1"), ("--omega1", "(e.g. -2.5rpm or -2.5rad/s)")),
        (("gyro", "--inertia", "1", "--spin", "2*50", "--torque", "1"), ("--spin", "(e.g. 100rpm or 100rad/s), got '2*50'")),
        (("impulse", "--inertia", "1", "--omega0", "0", "--couple", "inertia=1 omega0=30"), ("couple omega0=", "(e.g. 30rpm or 30rad/s)")),
    ],
)
def test_a_bare_number_for_a_rotation_rate_is_refused_naming_rpm_and_rad_per_s(args, fragments):
    assert_usage_error(run_taucli(*args), *fragments)


def test_zero_needs_no_unit_and_numbers_from_json_and_python_are_si():
    assert units.parse("0", "--x", "angular velocity", sign="any").value == 0.0
    assert units.parse("-0", "--x", "angular acceleration", sign="any").value == 0.0
    done = run_taucli("spin-down", "--inertia", "1", "--friction", "1", "--batch", "--no-steps", stdin='{"omega0": 300}\n{"omega0": "300"}\n')
    first, second = (json.loads(line) for line in done.out.splitlines())
    assert first["inputs"]["omega0"]["value"] == 300.0
    assert "300rpm or 300rad/s" in second["error"]["message"]
    assert taucli.spin_down(inertia=1, friction=1, omega0=300).inputs["omega0"].value == 300.0
    assert taucli.spin_down(alpha=6, time=1).results["omega"].value == 6.0
    with pytest.raises(InputError, match="300rpm or 300rad/s"):
        taucli.spin_down(inertia=1, friction=1, omega0="300")


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
    assert [line.split("\t") for line in done.out.splitlines()] == [["1", "0.5"], ["3", "1.5"], ["5", "2.5"]]  # --get: at most 15 digits, no trailing .0 (#36)


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
