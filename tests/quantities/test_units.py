"""The units layer: text to SI floats, dimension and range checks, safe evaluation."""

from __future__ import annotations

import math
import time

import pytest

from taucli.quantities import units
from taucli.core.errors import InputError

# (text, kind, SI value): the SI values are worked out by hand from the unit definitions.
READINGS = [
    ("4kg", "mass", 4.0),
    ("4 kg", "mass", 4.0),
    ("250 g", "mass", 0.25),
    ("10 lb", "mass", 4.5359237),
    ("4", "mass", 4.0),
    ("0.3 N*m", "torque", 0.3),
    ("0.3 N·m", "torque", 0.3),
    ("0.3 N⋅m", "torque", 0.3),
    ("1 lbf*ft", "torque", 4.4482216152605 * 0.3048),
    ("30deg", "angle", math.pi / 6),
    ("30°", "angle", math.pi / 6),
    ("0.5 rad", "angle", 0.5),
    ("0", "angle", 0.0),  # a bare 0 is the one angle that needs no unit
    ("300 rpm", "angular velocity", 10 * math.pi),
    ("2 rev/s", "angular velocity", 4 * math.pi),
    ("90 deg/s", "angular velocity", math.pi / 2),
    ("0.1 kg*m^2", "moment of inertia", 0.1),
    ("0.1 kg*m**2", "moment of inertia", 0.1),
    ("0.1 kg·m²", "moment of inertia", 0.1),
    ("1000 g*cm^2", "moment of inertia", 1e-4),
    ("20 cm", "length", 0.2),
    ("2 ft", "length", 0.6096),
    ("250 ms", "time", 0.25),
    ("6 rad/s^2", "angular acceleration", 6.0),
    ("0.01 N*m*s", "viscous coefficient", 0.01),
    ("0.001 N*m*s^2", "drag coefficient", 0.001),
    ("9.81 m/s^2", "acceleration", 9.81),
    ("36 km/h", "velocity", 10.0),
    ("6 N", "force", 6.0),
    ("1 kN", "force", 1000.0),
    ("(2)kg", "mass", 2.0),
    ("−3 N*m", "torque", -3.0),
]


@pytest.mark.parametrize("text,kind,expected", READINGS)
def test_reads_quantities_in_si(text, kind, expected):
    parsed = units.parse(text, "--x", kind, sign="any")
    assert parsed.value == pytest.approx(expected, rel=1e-12)
    assert parsed.note is None


def test_hz_for_an_angular_velocity_means_revolutions_per_second_with_a_note():
    parsed = units.parse("5 Hz", "--omega0", "angular velocity")
    assert parsed.value == pytest.approx(10 * math.pi, rel=1e-15)
    assert "Hz" in parsed.note and "rev" in parsed.note


REJECTED = [
    ("5 m", "mass", "which is a length"),
    ("0.3 N", "torque", "which is a force"),
    ("3 kg", "angle", "which is a mass"),
    ("5 kgg", "mass", "unknown unit 'kgg'; did you mean 'kg'?"),
    ("abc", "mass", "unknown unit"),
    ("", "mass", "empty"),
    ("   ", "mass", "empty"),
    ("nan", "mass", "finite"),
    ("nan kg", "mass", "finite"),
    ("inf", "mass", "finite"),
    ("-inf kg", "mass", "finite"),
    ("1e400 kg", "mass", "finite"),
    ("-4 kg", "mass", "positive"),
    ("0 kg", "mass", "positive"),
    ("4,5 kg", "mass", "comma"),
    ("9**9**9 kg", "mass", "power of a power"),
    ("9^9^9 kg", "mass", "power of a power"),
    ("10**99999 kg", "mass", "power larger"),
    ("2**(3**2) kg", "mass", "power"),
    ("kg**", "mass", "plain number"),
    ("1" * 40 + " kg", "mass", "digits"),
    ("((((((1))))))", "mass", "nested"),
    ("kg*" * 40 + "kg", "mass", "longer than"),
    ("4 kg; import os", "mass", "character ';'"),
    ("__import__('os')", "mass", "character"),
    ("4 kg)", "mass", "not a quantity"),
    ("1e-41 kg", "mass", "between 1e-40 and 1e40 kg"),
    ("1e-38 g", "mass", "= 1e-41 kg"),
    ("2e40", "length", "between 1e-40 and 1e40 m"),
    ("-1e41 N*m", "torque", "between"),
]


@pytest.mark.parametrize("text,kind,fragment", REJECTED)
def test_refuses_with_a_message_naming_option_and_kind(text, kind, fragment):
    with pytest.raises(InputError) as caught:
        units.parse(text, "--opt", kind)
    message = str(caught.value)
    assert message.startswith("--opt: expected")
    assert kind.split()[0] in message
    assert fragment in message
    assert "(e.g. " in message


def test_the_bounds_of_size_are_inclusive_and_zero_is_allowed():
    assert units.parse("1e-40", "--m", "mass").value == 1e-40
    assert units.parse("1e40 kg", "--m", "mass").value == 1e40
    assert units.parse("0 kg", "--m", "mass", sign="nonnegative").value == 0.0
    assert units.parse("-1e40 N*m", "--t", "torque", sign="any").value == -1e40


HOSTILE = [
    "9**9**9 kg", "2^2^2^2^2 kg", "10**400 kg", "(" * 500 + "4" + ")" * 500 + " kg", "9" * 100_000 + " kg",
    "*".join(["kg"] * 5000), "*".join(["kg/kg"] * 3000), "4 kg" + " + 1 kg" * 2000, "1e999999999 kg",
    "__import__('os').system('true')", "exp(1000) kg", "kg" * 50_000,
    "k" * 40 + "+", "k " * 39 + "+",  # 2^n ways to cut the letters into unit names, once tried one by one
]


@pytest.mark.parametrize("text", HOSTILE, ids=lambda text: text[:24])
def test_hostile_expressions_are_refused_at_once_by_the_cli(text):
    """Through the console script's entry point (tests/fuzzing.py): exit 2, one line, under a second."""
    from fuzzing import Vector, run

    outcome = run(Vector("inertia", ["disc", "--mass", text, "--radius", "1m"]), ".")
    assert outcome.status == 2 and not outcome.problems, outcome.problems
    assert outcome.err.startswith("taucli: error: --mass: expected a ") and "mass" in outcome.err


def test_exponent_tower_is_refused_at_once():
    start = time.perf_counter()
    with pytest.raises(InputError):
        units.parse("9**9**9 kg", "--mass", "mass")
    assert time.perf_counter() - start < 1.0  # a hang check, not a benchmark: pint would run for hours


def test_sign_policies():
    assert units.parse("0 kg", "--m2", "mass", sign="nonnegative").value == 0.0
    with pytest.raises(InputError, match="zero or more"):
        units.parse("-1 kg", "--m2", "mass", sign="nonnegative")
    assert units.parse("-2 N*m", "--torque", "torque", sign="any").value == -2.0


def test_convert_to_other_units():
    assert units.convert(1.0, "N*m", "lbf*ft", "--to") == pytest.approx(1 / (4.4482216152605 * 0.3048), rel=1e-12)
    assert units.convert(10 * math.pi, "rad/s", "rpm", "--to") == pytest.approx(300.0, rel=1e-14)
    assert units.convert(2 * math.pi, "rad/s", "Hz", "--to") == pytest.approx(1.0, rel=1e-14)
    with pytest.raises(InputError, match="moment of inertia"):
        units.convert(0.1, "kg*m**2", "s", "--to")
    with pytest.raises(InputError):
        units.convert(0.1, "kg*m**2", "9**9**9", "--to")


_UNIT_WORDS = ["kg", "g", "lb", "lbf", "N", "cm", "m", "ft", "s", "ms", "rpm", "Hz", "rad/s", "deg", "rev", "N*m", "kg*m^2", "J", "mph", "oz", "1/s", "km", "degC"]


@pytest.mark.parametrize("kind", sorted(units.KINDS))
def test_a_unit_read_before_reads_again_as_parse_reads_it(kind):
    """units.known (a batch's shortcut for "number unit" seen before) gives parse's value, or
    steps aside (None) wherever parse would note, refuse or read otherwise."""
    from hypothesis import given, settings
    from hypothesis import strategies as st

    @settings(max_examples=150, deadline=None)
    @given(number=st.one_of(st.floats(-1e6, 1e6), st.sampled_from([0.0, -0.0, 1e-30, 1e30, 1e300])), unit=st.sampled_from(_UNIT_WORDS),
           space=st.sampled_from(["", " "]), sign=st.sampled_from(["positive", "nonnegative", "any"]))
    def check(number, unit, space, sign):
        text = f"{number!r}{space}{unit}"
        try:
            expected = units.parse(text, "--x", kind, sign=sign)
        except InputError:
            expected = None
        units.parse(f"1{space}{unit}", "--x", kind, sign="any") if expected is not None else None  # the unit is now read before
        found = units.known(text, kind, sign)
        if found is not None:
            assert expected is not None and expected.note is None and found == expected.value

    check()


@pytest.mark.parametrize("kind", sorted(units.KINDS))
@pytest.mark.parametrize("text", ["1degC", "2 degF", "1 degC*m", "nan", "NaN", "nan/s", "__dict__", "__class__", "2 __init__"])
def test_texts_pint_stumbles_on_are_refused_for_every_kind_not_a_crash(kind, text):
    """pint will not multiply an offset unit (it raised OffsetUnitCalculusError: exit 1), and
    `name in registry` raised for "nan" (a number) and "__dict__" (an attribute) for angular kinds."""
    with pytest.raises(InputError):
        units.parse(text, "--x", kind, sign="any")
