"""taucli convert (#46 item 9): a quantity read as every option reads it, written in another unit.

The factors below are written from the units' definitions (the international pound and foot of
1959, standard gravity, the horsepowers' definitions, ω = 2πn), in mpmath, not from pint."""

from __future__ import annotations

import math

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taucli
from taucli.quantities.conversion import convert_quantity
from taucli.quantities.kinds import KINDS
from taucli.quantities.units import parse

LB, FT, INCH, G0 = mpmath.mpf("0.45359237"), mpmath.mpf("0.3048"), mpmath.mpf("0.0254"), mpmath.mpf("9.80665")
LBF = LB * G0
TURN = 2 * mpmath.pi

# (text, unit, the value in that unit, from the definitions)
DEFINED = [
    ("3000 rpm", "rad/s", 3000 * TURN / 60),
    ("1 rad/s", "rpm", 60 / TURN),
    ("50 Hz", "rad/s", 50 * TURN),  # a rotational frequency: ω = 2πn
    ("1 rev/s^2", "rad/s^2", TURN),
    ("90 deg", "rad", mpmath.pi / 2),
    ("30 grad", "deg", mpmath.mpf(27)),
    ("2 lb*ft^2", "kg*m^2", 2 * LB * FT**2),
    ("1 slug*ft^2", "kg*m^2", LBF / FT * FT**2),
    ("0.002 lb*in*s^2", "kg*m^2", mpmath.mpf("0.002") * LBF * INCH),
    ("1 lbf*ft", "N*m", LBF * FT),
    ("10 kg-cm", "N*m", 10 * G0 / 100),  # a servo's kgf·cm
    ("1 hp", "W", 550 * LBF * FT),
    ("1 PS", "W", 75 * G0),
    ("1 PS", "hp", 75 * G0 / (550 * LBF * FT)),
    ("60 mph", "m/s", 60 * mpmath.mpf("1609.344") / 3600),
    ("1 psi", "Pa", LBF / INCH**2),
    ("0.01 N*m/Hz", "N*m*s", mpmath.mpf("0.01") / TURN),
    ("1 kW*h", "MJ", mpmath.mpf("3.6")),
    ("7.85 g/cm^3", "kg/m^3", mpmath.mpf(7850)),
    ("2 t", "kg", mpmath.mpf(2000)),
    ("2 long_ton", "lb", mpmath.mpf(4480)),
    ("5 mm", "in", mpmath.mpf("0.005") / INCH),
    ("-40 N*m", "lbf*ft", -40 / (LBF * FT)),
    ("85%", None, mpmath.mpf("0.85")),
]


@pytest.mark.parametrize("text, unit, expected", DEFINED, ids=[f"{t}->{u}" for t, u, _ in DEFINED])
def test_a_quantity_in_another_unit_is_its_definition(text, unit, expected):
    assert convert_quantity(text, unit).value == pytest.approx(float(expected), rel=1e-13)


def test_without_a_unit_it_is_si_of_its_kind():
    done = convert_quantity("3000 rpm")
    assert (done.kind, done.unit) == ("angular velocity", "rad/s") and done.value == pytest.approx(100 * math.pi, rel=1e-15)
    assert convert_quantity("2 lbf").unit == "N"  # a force, not the mass it weighs
    assert convert_quantity("1 N*m").kind == "torque" and convert_quantity("1 J").kind == "energy"
    assert convert_quantity("5 mm").kind == "length" and convert_quantity("2 lb*ft^2").kind == "moment of inertia"
    assert convert_quantity("2 kg*m^2/s").kind == "angular momentum"  # a new user's trial: it was called a viscous coefficient
    assert convert_quantity("0.01 N*m/Hz").kind == "viscous coefficient"


# The unit pairs of each kind a property draws from: every common unit of every kind.
PAIRS = [(kind.name, unit) for kind in KINDS.values() for unit in kind.common_units]


@settings(max_examples=300, deadline=None)
@given(st.sampled_from(PAIRS), st.data(), st.floats(min_value=1e-6, max_value=1e6))
def test_any_unit_of_a_kind_gives_the_si_value_every_option_reads(pair, data, number):
    """A value written in one unit, converted to another of its kind and back, and to SI: the SI
    value is what an option of that kind reads from the first text (the meaning does not change
    with the unit it is written in); or, where another kind reads the same text as another number
    (1 mm/rev: a lead, or a length of (1/2π) mm), a refusal naming both."""
    kind, unit = pair
    other = data.draw(st.sampled_from(KINDS[kind].common_units))
    text = f"{number!r} {unit}"
    option = parse(text, "x", kind, sign="any").value
    try:
        there = convert_quantity(text, other)
    except taucli.InputError as err:
        assert "could be" in str(err) and kind in str(err), str(err)
        return
    back = convert_quantity(f"{there.value!r} {other}", unit)
    assert there.si_value == pytest.approx(option, rel=1e-14)
    assert back.value == pytest.approx(number, rel=1e-12)
    assert convert_quantity(text).value == pytest.approx(option, rel=1e-14)


def test_an_uncertainty_is_converted_with_its_value():
    done = convert_quantity("4.0+/-0.1 kg", "lb")
    assert done.value == pytest.approx(4 / float(LB), rel=1e-14) and done.uncertainty == pytest.approx(0.1 / float(LB), rel=1e-14)
    assert done.si_uncertainty == pytest.approx(0.1)
    assert convert_quantity("4.0(1) kg", "g").uncertainty == pytest.approx(100)


@pytest.mark.parametrize("text, unit, says", [
    ("5", None, "a number alone has no unit to convert from"),
    ("3 kgg", None, "did you mean 'kg'"),
    ("3 m^5", None, "of a kind taucli takes"),
    ("1 Hz", "1/s", "names its angle"),  # 1/s: radians or revolutions per second
    ("3000 rpm", "kg", "a unit of an angular velocity"),
    ("2 ton", "kg", "short ton"),
    ("1e50 kg", None, "between 1e-40 and 1e40"),
    ("1e-400 kg", None, "below what a double holds"),
    ("4+/--1 kg", None, "uncertainty"),
    ("0.001 N*m/Hz^2", None, "a moment of inertia or a drag coefficient"),  # Hz as 1/s for an inertia, rev/s for a coefficient
])
def test_what_cannot_be_read_is_refused_naming_why(text, unit, says):
    with pytest.raises(taucli.InputError, match=None) as raised:
        convert_quantity(text, unit)
    assert says in str(raised.value), str(raised.value)


def test_notes_say_how_a_text_was_read():
    assert "revolutions per second" in " ".join(convert_quantity("50 Hz", "rad/s").notes)
    assert "metric horsepower" in convert_quantity("1 PS", "W").notes[0]
    assert convert_quantity("3000 rpm", "rad/s").notes == ()


def test_the_python_api():
    assert taucli.convert("3000 rpm", "rad/s").value == pytest.approx(100 * math.pi, rel=1e-15)
    with pytest.raises(taucli.InputError, match=r"^quantity: expected a text"):
        taucli.convert(3000, "rad/s")
    with pytest.raises(taucli.InputError, match=r"^unit: "):
        taucli.convert("3 kg", 5)
