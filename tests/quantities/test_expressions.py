"""#34 item 12: what a student types. sqrt(…), sin(…), cos(…), tan(…) read within the screen's
bounds; a power of a group of powers; a number and its unit after a slash grouped as one divisor,
with a note. Values from the definitions (√13, sin 30° = ½, v/R), not from taucli."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from conftest import assert_usage_error, run_taucli
from taucli.quantities import units
from taucli.core.errors import InputError


def _read(text: str, kind: str = "length", option: str = "radius"):
    return units.parse(text, option, kind, sign="any")


@pytest.mark.parametrize("text, kind, value", [
    ("sqrt(13) m", "length", math.sqrt(13)),
    ("((3m)^2 + (2m)^2)^0.5", "length", math.sqrt(13)),
    ("sin(30deg)*5N", "force", 2.5),
    ("sqrt(13 m^2)", "length", math.sqrt(13)),
    ("(13 m^2)^0.5", "length", math.sqrt(13)),
    ("2sqrt(3) m", "length", 2 * math.sqrt(3)),
    ("SQRT(16) cm", "length", 0.04),
    ("cos(60 deg)*10 N*m", "torque", 5.0),
    ("tan(45deg)*3 N", "force", 3.0),
    ("sin(0.5 rad)*1 N", "force", math.sin(0.5)),
    ("cos(1 rev) m", "length", 1.0),
    ("sqrt(2*9.81 m/s^2*0.5 m)/(0.25 m)", "angular velocity", math.sqrt(2 * 9.81 * 0.5) / 0.25),  # ω = v/R, v from energy
])
def test_a_students_expression_is_read(text, kind, value):
    """Each was refused before: 'a power of a power', or 'a number after a unit' with the fix 'sqrt + (13) m'."""
    assert _read(text, kind).value == pytest.approx(value, rel=1e-15)


def test_the_book_values_are_exact():
    assert _read("sin(30deg)*5N", "force").value == 2.5  # not 2.4999999999999996
    assert _read("cos(60deg)*5N", "force").value == 2.5
    assert _read("tan(45deg)*5N", "force").value == 5.0
    assert _read("sin(90deg)*5N", "force").value == 5.0
    assert _read("cos(90deg)*5N + 1N", "force").value == 1.0


def test_each_function_says_what_it_was_read_as():
    assert _read("sqrt(13) m").note == "radius sqrt(13) m: sqrt(13) = 3.60555"
    assert _read("sin(30deg)*5N", "force").note == "radius sin(30deg)*5N: sin(30deg) = 0.5"
    assert _read("((3m)^2 + (2m)^2)^0.5").note is None  # plain arithmetic: nothing to say


@pytest.mark.parametrize("text, kind, value, grouped", [
    ("36km/h/200m", "angular velocity", 0.05, "36km/h/(200m)"),
    ("36 km/h / 200 m", "angular velocity", 0.05, "36 km/h / (200 m)"),
    ("10 m/s/2 s", "acceleration", 5.0, "10 m/s/(2 s)"),
    ("6 m/s^2/2 s^-1", "velocity", 3.0, "6 m/s**2/(2 s**-1)"),
])
def test_a_number_and_its_unit_after_a_slash_divide_together(text, kind, value, grouped):
    """pint reads 36km/h/200m as 36 km/h / 200 × m (a length²/time, refused); a student means
    (36 km/h)/(200 m) = 10 m/s / 200 m = 0.05 rad/s."""
    read = _read(text, kind)
    assert read.value == pytest.approx(value, rel=1e-15)
    assert f"read as {grouped}" in read.note


@pytest.mark.parametrize("text, kind, value", [("1/2 rpm", "angular velocity", math.pi / 60), ("(90 km/h)/(60 m)", "angular velocity", 25 / 60),
                                               ("5 m/s/2", "velocity", 2.5), ("33 1/3 rpm", "angular velocity", 2 * math.pi * 100 / 3 / 60)])
def test_what_is_not_a_number_and_unit_after_a_slash_stays_as_it_was(text, kind, value):
    read = _read(text, kind)
    assert read.value == pytest.approx(value, rel=1e-15)
    assert read.note is None or "read as" not in read.note or "mixed" in read.note


@pytest.mark.parametrize("text, kind, fragment", [
    ("sin(30)*5N", "force", "needs an angle with its unit"),
    ("sqrt(-4) m", "length", "of a negative number"),
    ("tan(90deg)*1N", "force", "is infinite"),
    ("sqrt() m", "length", "of nothing"),
    ("sqrt(4 m", "length", "without its )"),
    ("(9^9)^9 kg", "mass", "powers of powers"),
    ("sqrt(10^12)^12 m", "length", "powers of powers"),
    ("9^9^9 kg", "mass", "a power of a power"),
    ("sqrt(sqrt(sqrt(sqrt(sqrt(2))))) m", "length", "nested too deeply"),
    ("sqrt(13).real m", "length", "unknown unit 'real'"),
    ("sqrt(1e300 m^2)*1e300", "length", "finite"),
    ("sqrt(2)*sqrt(2)*sqrt(2)*sqrt(2)*sqrt(2)*sqrt(2)*sqrt(2) m", "length", "more than 6 functions"),
])
def test_the_screen_still_bounds_what_is_read(text, kind, fragment):
    with pytest.raises(InputError) as refused:
        _read(text, kind)
    assert fragment in str(refused.value)


def test_on_the_command_line():
    done = run_taucli("inertia", "disc", "--mass", "1kg", "--radius", "sqrt(13) m", "--get", "I")
    assert done.code == 0 and float(done.out) == pytest.approx(13 / 2, rel=1e-15)
    done = run_taucli("spin-down", "--inertia", "1", "--omega0", "36km/h/200m", "--json")
    assert done.code == 0 and done.json()["inputs"]["omega0"]["value"] == pytest.approx(0.05, rel=1e-15)
    assert any("read as 36km/h/(200m)" in note for note in done.json()["notes"])
    assert_usage_error(run_taucli("spin-down", "--inertia", "1", "--lever", "1m", "--force", "sin(30)*5N"), "--force", "sin(30deg)")


@settings(max_examples=80, deadline=None)
@given(x=st.floats(1e-6, 1e6), degrees=st.floats(-720, 720).filter(lambda d: d == 0 or abs(d) > 1e-20))
def test_a_function_reads_the_same_in_other_units(x, degrees):
    """sqrt(x m²) = sqrt(10⁴x cm²) in metres; sin(θ deg) = sin(θπ/180 rad)."""
    a = _read(f"sqrt({x!r} m^2)").value
    b = _read(f"sqrt({x * 1e4!r} cm^2)").value
    assert a == pytest.approx(math.sqrt(x), rel=1e-14) and b == pytest.approx(a, rel=1e-14)
    in_degrees = _read(f"sin({degrees!r} deg)*2 N", "force").value
    in_radians = _read(f"sin({math.radians(degrees)!r} rad)*2 N", "force").value
    assert in_degrees == pytest.approx(in_radians, rel=1e-9, abs=1e-12)
    assert in_degrees == pytest.approx(2 * math.sin(math.radians(degrees)), rel=1e-9, abs=1e-12)


@pytest.mark.parametrize("variable", ["t", "theta"])
@pytest.mark.parametrize("text, why", [
    ("(2 - 3*{v}/s N*m", "a ( without its )"),
    ("(2 - 3*sin({v}) N*m", "a ( without its )"),
    ("(2 - 3*{v}/s)) N*m", "a ) without its ("),
    (")2 - 3*{v}/s( N*m", "a ) without its ("),
])
def test_a_formula_with_a_parenthesis_unclosed_says_so(variable, text, why):
    """A formula of t or θ with a parenthesis left open was read as if closed at the end, then
    refused as adding parts of different kinds (and a θ formula offered t/s): the cause is named."""
    from taucli.core.errors import InputError
    from taucli.quantities.formula import ANGLE, TIME, read_formula
    from taucli.quantities.units import KINDS
    typed = text.format(v=variable).replace("/s", "" if variable == "theta" else "/s")
    with pytest.raises(InputError) as refused:
        read_formula(typed, "torque", KINDS["torque"], TIME if variable == "t" else ANGLE)
    assert why in str(refused.value) and "different kinds" not in str(refused.value)
