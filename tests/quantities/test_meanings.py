"""Units that read as meant, or are refused, by what they mean (#42 items 1, 4 and 17): an ambiguous
ton, the metric and the mechanical horsepower, gradians; a unit of another kind with the same
dimension (a joule for a torque); numbers as books print them (85%, 10:1, 2π rad/s, m·s⁻²,
0.135*20*pi/15 N*m) and a power over a speed in a sum of speeds (an induction motor's slip line).

Expected values from the definitions: 1 lb = 0.45359237 kg, g0 = 9.80665 m/s², a short ton 2000 lb,
a long ton 2240 lb, a tonne 1000 kg; PS = 75 kgf·m/s = 735.49875 W, hp = 550 ft·lbf/s; a gradian
is 1/400 of a turn.
"""

from __future__ import annotations

import json
import math

import pytest

from conftest import assert_usage_error
from taucli.core.errors import InputError
from taucli.quantities import units

PI = math.pi
LB = 0.45359237  # kg
G0 = 9.80665  # m/s²
FT = 0.3048  # m
RPM = 2 * PI / 60  # rad/s
PS = 75 * G0  # W: 75 kgf·m/s
HP = 550 * LB * G0 * FT  # W: 550 ft·lbf/s


def _json(taucli, *args: str) -> dict:
    done = taucli(*args, "--json", "--no-steps")
    assert done.code == 0, done.err
    return json.loads(done.out)


# Item 1: ton, PS, hp, grad.


@pytest.mark.parametrize("text", ["2 ton", "2ton", "2 tons", "1 ton + 1 kg"])
def test_a_ton_is_refused_naming_the_tonne_the_short_ton_and_the_long_ton(taucli, text):
    done = taucli("inertia", "disc", "--mass", text, "--radius", "1m", "--get", "I")
    assert_usage_error(done, "--mass", "tonne (1000 kg)", "short ton (2000 lb)", "long ton (2240 lb)", "short_ton", "long_ton")


@pytest.mark.parametrize("text", ["16 tonf", "16 ton_force", "16ton"])
def test_a_ton_force_is_refused_naming_each_force_form(taucli, text):
    done = taucli("spin-down", "--inertia", "1", "--omega0", "10rad/s", "--face", f"mu=0.04 force={text} inner-radius=6in outer-radius=8in")
    assert_usage_error(done, "force=", "tonne-force (9806.65 N)", "short_ton_force", "long_ton_force")


@pytest.mark.parametrize("text,kg", [("2 t", 2000.0), ("2 tonne", 2000.0), ("2 short_ton", 4000 * LB), ("2 long_ton", 4480 * LB)])
def test_each_named_ton_is_read(taucli, text, kg):
    done = taucli("inertia", "disc", "--mass", text, "--radius", "1m", "--get", "I")
    assert done.code == 0, done.err
    assert float(done.out) == pytest.approx(kg / 2, rel=1e-12)  # I = MR²/2 with R = 1 m


def test_a_long_ton_for_a_force_is_its_weight():
    assert units.parse("16 long_ton_force", "--force", "force").value == pytest.approx(16 * 2240 * LB * G0, rel=1e-14)
    parsed = units.parse("16 long_ton", "--force", "force")
    assert parsed.value == pytest.approx(16 * 2240 * LB * G0, rel=1e-14) and "standard gravity" in parsed.note


def test_ps_is_the_metric_horsepower_with_a_note(taucli):
    """A constant power P into a free wheel: ½Iω² grows by Pt, ω = √(ω0² + 2Pt/I)."""
    document = _json(taucli, "spin-down", "--inertia", "1", "--omega0", "100rad/s", "--power", "1PS", "--time", "1s")
    assert document["results"]["omega"]["value"] == pytest.approx(math.sqrt(100**2 + 2 * PS), rel=1e-12)
    assert any(note.startswith("--power 1PS: PS read as the metric horsepower, 735.49875 W") for note in document["notes"]), document["notes"]


def test_hp_is_the_mechanical_horsepower_with_a_note_naming_ps(taucli):
    document = _json(taucli, "spin-down", "--inertia", "1", "--omega0", "100rad/s", "--power", "1hp", "--time", "1s")
    assert document["results"]["omega"]["value"] == pytest.approx(math.sqrt(100**2 + 2 * HP), rel=1e-12)
    assert any("hp read as the mechanical horsepower, 745.7 W" in note and "PS" in note for note in document["notes"]), document["notes"]
    assert units.converted(HP, "W", "hp", "--to").note is not None  # --to power=hp says which too


@pytest.mark.parametrize("text", ["30grad", "30 gon", "30 gradian"])
def test_grad_is_gradians_with_a_note(text):
    parsed = units.parse(text, "--angle0", "angle")
    assert parsed.value == pytest.approx(30 * 2 * PI / 400, rel=1e-15)  # 27°
    assert parsed.note == f"--angle0 {text}: grad: gradians, 400 per turn; degrees are deg"


# Item 4: a unit of another kind with the same dimension.


def test_a_joule_for_a_torque_is_read_with_a_note(taucli):
    document = _json(taucli, "spin-down", "--inertia", "1", "--omega0", "10rad/s", "--friction", "0.3J", "--time", "1s")
    assert document["results"]["omega"]["value"] == pytest.approx(10 - 0.3, rel=1e-14)  # α = −τ/I
    assert "--friction 0.3J: a joule is an energy; a torque is N·m (read as 1 J = 1 N·m)" in document["notes"]


@pytest.mark.parametrize("text", ["0.3 kJ/1000", "0.3 J", "300 mJ"])
def test_any_unit_of_energy_for_a_torque_is_noted(text):
    parsed = units.parse(text, "--torque", "torque")
    assert parsed.value == pytest.approx(0.3, rel=1e-14) and "a torque is N·m" in parsed.note


def test_newton_metres_for_an_energy_are_read_with_a_note(taucli):
    document = _json(taucli, "spin-down", "--inertia", "2", "--friction", "1", "--ke0", "100 N*m")
    assert document["inputs"]["ke0"]["value"] == 100.0
    assert "--ke0 100 N*m: N·m is a torque; an energy is J (read as 1 N·m = 1 J)" in document["notes"]
    assert units.parse("100 J", "--ke0", "energy").note is None and units.parse("2 N*m", "--torque", "torque").note is None


# Item 17: numbers as people write them.


@pytest.mark.parametrize(
    "text,kind,si",
    [
        ("85%", "dimensionless", 0.85), ("2 %", "dimensionless", 0.02), ("10:1", "dimensionless", 10.0), ("3 : 2", "dimensionless", 1.5),
        ("2π rad/s", "angular velocity", 2 * PI), ("100π rad/s", "angular velocity", 100 * PI), ("π/6 rad", "angle", PI / 6),
        ("2*pi*50 rad/s", "angular velocity", 100 * PI), ("(2π) rad/s", "angular velocity", 2 * PI),
        ("9.81 m·s⁻²", "acceleration", 9.81), ("9.81 m s⁻²", "acceleration", 9.81), ("2 m·s⁻¹", "velocity", 2.0), ("7800 kg·m⁻³", "density", 7800.0),
        ("0.135*20*pi/15 N*m", "torque", 0.135 * 20 * PI / 15), ("0.135*20*π/15 N·m", "torque", 0.135 * 20 * PI / 15),
        ("(0.135*20*pi/15) N*m", "torque", 0.135 * 20 * PI / 15), ("2/3 N*m", "torque", 2 / 3), ("3×10⁻³ kg·m²", "moment of inertia", 3e-3),
        ("1.2 × 10^4 N", "force", 1.2e4), ("1/2 rpm", "angular velocity", RPM / 2), ("4π²/9 kg*m^2", "moment of inertia", 4 * PI**2 / 9),
    ],
)  # fmt: skip
def test_a_number_expression_with_its_constants_then_its_unit(text, kind, si):
    parsed = units.parse(text, "--x", kind)
    assert parsed.value == pytest.approx(si, rel=1e-14)
    assert parsed.note is None


def test_percent_and_ratio_on_the_command_line(taucli):
    document = _json(taucli, "drive", "--motor-inertia", "1.2 kg*cm^2", "--ratio", "10:1", "--load-inertia", "0.05 kg*m^2", "--efficiency", "85%")
    assert document["inputs"]["ratio"]["value"] == 10.0 and document["inputs"]["efficiency"]["value"] == pytest.approx(0.85, rel=1e-15)
    assert document["results"]["reflected_inertia"]["value"] == pytest.approx(0.05 / 10**2, rel=1e-12)  # J/N²
    flywheel = _json(taucli, "flywheel", "--omega-mean", "300rpm", "--fluctuation", "2%", "--energy-swing", "5kJ")
    assert flywheel["results"]["I"]["value"] == pytest.approx(5000 / ((300 * RPM) ** 2 * 0.02), rel=1e-12)  # ΔE = Iω²Cs


@pytest.mark.parametrize(
    "text,kind,words",
    [("1:10", "dimensionless", "either way round"), ("2π", "angular velocity", "a number alone could be rpm or rad/s"),
     ("5%", "mass", "which is a plain number"), ("1:2 kg", "mass", "':'")],
)
def test_what_cannot_be_read_as_meant_is_refused(text, kind, words):
    with pytest.raises(InputError, match=words):
        units.parse(text, "--x", kind)


SLIP_LINE = "1000rpm − 300N*m/(50kW/(960rpm))*40rpm"


def test_an_induction_motors_slip_line_reads_a_power_over_a_speed_as_a_torque(taucli):
    """The torque–speed line through synchronous speed (1000 rpm) and the rated point (50 kW at
    960 rpm, 40 rpm of slip): at 300 N·m the slip is 300 N·m / T_rated × 40 rpm, T_rated = P/ω."""
    rated = 50e3 / (960 * RPM)  # N·m
    expected = (1000 - 300 / rated * 40) * RPM
    document = _json(taucli, "spin-down", "--inertia", "1", "--omega0", SLIP_LINE, "--friction", "1")
    assert document["inputs"]["omega0"]["value"] == pytest.approx(expected, rel=1e-14)
    assert any(note.startswith(f"--omega0 {SLIP_LINE}: a power is a torque times an angular velocity in rad/s (P = τω)") for note in document["notes"])
    assert units.parse("300N*m/(50kW/(960rpm))", "--x", "dimensionless").value == pytest.approx(300 / rated, rel=1e-14)
    assert units.parse("1kW/(10 N*m)", "--x", "angular velocity").value == pytest.approx(100.0, rel=1e-15)  # ω = P/τ in rad/s
