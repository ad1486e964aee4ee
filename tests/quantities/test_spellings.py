"""Every way a person types a quantity is read as meant, or refused with one line that names the fix
(issue #15): the same value spelled a dozen ways per kind, through units.parse, the command line,
--batch and a sweep; the issue's table as the person meant it; weights, mixed numbers, angles; the
bounds of each kind, typed or computed; and a property: re-expressing every input of a scene in
another unit of its kind leaves its SI results unchanged.

Expected values come from the unit definitions (1 lb = 0.45359237 kg, 1 ft = 0.3048 m,
g0 = 9.80665 m/s^2, 1 rev = 2π rad) and the physics, written out here.
"""

from __future__ import annotations

import json
import math

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from conftest import assert_usage_error, run_taucli
from taucli.front import cli
from taucli.quantities import spellings
from taucli.quantities import units
from taucli.core.errors import InputError

PI = math.pi
LB = 0.45359237  # kg
OZ = LB / 16
G0 = 9.80665  # m/s^2
LBF = LB * G0  # N
FT = 0.3048  # m
IN = 0.0254  # m
RPM = 2 * PI / 60  # rad/s
LBF_FT = LBF * FT  # N*m


# kind -> (SI value, spellings, where the command line takes it: scene arguments, option, input key).
# A spelling is its text, or (text, a fragment of the note its reading must carry).
SPELLINGS = {
    "mass": (4.5, [
        "4.5kg", "4.5 kg", "4500 g", f"{4.5 / LB!r} lbm", "4.5e3 g", "4500000 mg", "0.0045 tonne", f"{4.5 / LB!r} lb", f"{4.5 / OZ!r}oz", "4.5",
        ("4 1/2 kg", "4 1/2 read as the mixed number 4 + 1/2"), ("4½ kg", "mixed number"), "9/2 kg", "4 kg + 500 g", "(4.5) kg",
        ("4.5 kgf", "a weight, read as the mass W/g = 4.5 kg (standard gravity g = 9.80665 m/s²)"), (f"{4.5 * G0!r} N", "W/g"),
    ], ("atwood", "--m2", "1kg"), "--m1"),
    "length": (0.25, [
        "0.25m", "0.25 m", "25 cm", "25cm", "250 mm", "2.5e-4 km", "250000 µm", f"{0.25 / FT!r} ft", f"{0.25 / IN!r} in", "1/4 m",
        "0.25", "20 cm + 50 mm",
    ], ("atwood", "--m1", "4kg", "--m2", "1kg"), "--distance"),
    "angle": (PI / 6, [
        "30deg", "30 deg", "30°", "30 °", "30 degrees", f"{PI / 6!r} rad", f"{PI / 6!r}rad", "1/12 rev", "1/12 turn", "1800 arcmin",
        "0.5 rad + 0.0235987755982988 rad",
    ], ("spin-down", "--inertia", "1", "--force", "1N", "--lever", "1m"), "--push-angle"),
    "time": (90.0, [
        "90s", "90 s", "90 sec", "90 seconds", "1.5 min", "1.5min", ("1 1/2 min", "mixed number"), "90000 ms", "0.025 h", "90",
        "1 min + 30 s", "9e1 s",
    ], ("spin-down", "--inertia", "1", "--omega0", "1rad/s", "--friction", "0.1"), "--time"),
    "angular velocity": (100 * PI, [
        "3000rpm", "3000 rpm", "3000 RPM", "3000 Rpm", "3000 rev/min", "3000 r/min", "50 rps", "50 rev/s", "18000 deg/s", "18000°/s",
        f"{100 * PI!r} rad/s", (f"({100 * PI!r} m/s)/(1 m)", "ω = v/R = 314.159 rad/s"), (f"({100 * PI!r} m/s)/(100 cm)", "ω = v/R"),
        ("3000 min^-1", "min^-1 read as revolutions per minute (ω = 2πn)"), ("3000 min-1", "revolutions per minute"),
        ("3000 1/min", "1/min read as revolutions per minute"), ("50 Hz", "Hz read as revolutions per second"),
        ("50 HZ", "Hz read as revolutions per second"),
    ], ("spin-down", "--inertia", "1", "--friction", "0.1"), "--omega0"),
    "angular acceleration": (2 * PI, [
        "60 rpm/s", "60 RPM/s", "1 rev/s^2", "1 rev/s2", "360 deg/s^2", "3600 rev/min^2", f"{2 * PI!r} rad/s^2",
        ("1 Hz/s", "Hz/s read as revolutions per second squared"), ("60 1/(min*s)", "revolutions per unit time"),
        (f"({2 * PI!r} m/s^2)/(1 m)", "α = a_t/R = 6.28319 rad/s²"),
    ], None, None),
    "torque": (LBF_FT, [
        "1 lbf*ft", "1 lbf·ft", "1 lbf-ft", "1 ft-lbf", "1 ft*lbf", "12 lbf*in", "12 in-lbf", f"{LBF_FT!r} N*m", f"{LBF_FT!r} Nm",
        f"{LBF_FT!r}Nm", f"{LBF_FT!r} N-m", f"{LBF_FT!r} N.m", f"{LBF_FT!r} N·m", f"{LBF_FT * 1000!r} mN*m", f"{LBF_FT / 1000!r} kNm",
        f"{LBF_FT!r}", (f"{LBF_FT!r} J", "a joule is an energy; a torque is N·m"),
        ("1 lb*ft", "lb read as pound-force, lbf*ft"), ("1 lb-ft", "pound-force"), ("1 ft*lb", "ft*lbf"), ("1 ft-lb", "pound-force"),
        ("1 lbft", "pound-force"), ("1 ftlb", "pound-force"), ("12 in-lb", "in*lbf"), ("192 oz-in", "oz read as ounce-force, ozf*in"),
    ], ("spin-down", "--inertia", "1"), "--torque"),
    "moment of inertia": (0.5, [
        "0.5 kg*m^2", "0.5kg*m^2", "0.5 kg*m**2", "0.5 kgm^2", "0.5 kgm2", "0.5 kg m2", "0.5 kg m^2", "0.5 kg·m²", "0.5 kgm²", "0.5 kg.m^2",
        "0.5 kg-m^2", "5000 kg*cm^2", "5000000 g*cm^2", "5e6 gcm^2", "5e6 gcm2", (f"{0.5 / (LB * FT**2)!r} lb*ft^2", "WR²"), "0.5", "1/2 kg*m^2",
        (f"{0.5 / (LB * IN**2)!r} lb*in^2", "a pound or ounce of mass"), f"{0.5 / (LBF * IN)!r} lbf*in*s^2", (f"{0.5 / (LBF * IN)!r} lb*in*s^2", "lb read as pound-force, lbf*in*s^2"),
        (f"{0.5 / (LBF / 16 * IN)!r} oz-in-s^2", "oz read as ounce-force"),
    ], ("spin-down", "--friction", "0.1", "--omega0", "1rad/s"), "--inertia"),
    "force": (10 * LBF, [
        "10 lbf", "10lbf", "160 ozf", f"{10 * LBF!r} N", f"{10 * LBF!r}N", f"{10 * LBF / 1000!r} kN", f"{10 * LBF * 1000!r} mN",
        f"{10 * LB!r} kgf", f"{10 * LBF!r}", ("10 lb", "lb read as pound-force, lbf"), (f"{10 * LB!r} kg", "kg read as kilogram-force"),
    ], ("spin-down", "--inertia", "1", "--lever", "1m"), "--force"),
    "acceleration": (G0, [
        "9.80665 m/s^2", "9.80665 m/s2", "9.80665 m/s²", "9.80665 m/s/s", "9.80665 m*s^-2", "1 g0", "980.665 cm/s^2", f"{G0 / FT!r} ft/s^2",
        f"{G0 / FT!r} ft/s2", "9.80665",
    ], ("atwood", "--m1", "4kg", "--m2", "1kg"), "--g"),
    "velocity": (10.0, [
        "10 m/s", "10m/s", "36 km/h", "600 m/min", "1000 cm/s", f"{10 / FT!r} ft/s", f"{10 / 0.44704!r} mph", "10", "10 m*s^-1", "10 m s-1",
        "10 m/sec",
    ], ("atwood", "--m1", "4kg", "--m2", "1kg"), "--v0"),
    "viscous coefficient": (0.02, [
        "0.02 N*m*s", "0.02 Nms", "0.02 N-m-s", "0.02 N.m.s", "0.02 N m s", "0.02 N*m/(rad/s)", "20 mN*m*s", "0.02 kg*m^2/s",
        f"{0.02 * RPM!r} N*m/rpm", f"{0.02 / LBF_FT!r} lbf*ft*s", "0.02",
    ], ("spin-down", "--inertia", "1", "--omega0", "1rad/s"), "--viscous"),
    "drag coefficient": (0.003, [
        "0.003 N*m*s^2", "0.003 N*m*s2", "0.003 Nms^2", "0.003 Nms2", "0.003 N-m-s^2", "0.003 N m s2", "0.003 N*m/(rad/s)^2", "3 mN*m*s^2",
        "0.003 kg*m^2", f"{0.003 / LBF_FT!r} lbf*ft*s^2", "0.003",
    ], ("spin-down", "--inertia", "1", "--omega0", "1rad/s"), "--drag"),
    # angular momentum (#46 item 2): L = Iω, kg·m²/s = N·m·s = J·s, the radian left out as SI does; an angle named in it is a rate's
    "angular momentum": (2.4, [
        "2.4 kg*m^2/s", "2.4 kg*m2/s", "2.4 kg·m²/s", "2.4 N*m*s", "2.4 Nms", "24000 kg*cm^2/s", "2.4 J*s", "2.4 kg*m^2*rad/s",
        f"{2.4 / (2 * PI)!r} kg*m^2*rev/s", f"{2.4 / RPM!r} kg*m^2*rpm", f"{2.4 / 60!r} N*m*min", "2.4",
        (f"{2.4 / (2 * PI)!r} kg*m^2*Hz", "Hz as revolutions per second"),
    ], ("impulse", "--momentum1", "3.6", "--duration", "4s"), "--momentum0"),
    "dimensionless": (0.25, ["0.25", ".25", "0.250", "2.5e-1", "1/4", "25/100", "0.25 dimensionless", "0.5 * 0.5"],
                      ("atwood", "--m1", "4kg", "--m2", "1kg", "--incline", "30deg"), "--mu-k"),
    # power (#18): 1 hp (mechanical) = 550 ft·lbf/s = 745.69987158227 W
    "power": (1500.0, ["1500 W", "1500W", "1.5 kW", "1.5kW", "0.0015 MW", "1500 J/s", "1500 N*m/s", (f"{1500 / 745.69987158227022!r} hp", "hp read as the mechanical horsepower"), (f"{1500 / 735.49875!r} PS", "PS read as the metric horsepower"), "1500"],
              ("spin-down", "--inertia", "2", "--until-omega", "100rpm"), "--power"),
    "energy": (2.5e6, ["2.5e6 J", "2.5 MJ", "2500 kJ", "2500kJ", f"{2.5e6 / 3.6e6!r} kW*h", f"{2.5e6 / 3600!r} Wh", f"{2.5e6 / 3.6e6!r} kWh",
                       ("2.5e6 N*m", "N·m is a torque; an energy is J"), "2.5e6"], ("spin-down", "--inertia", "2", "--friction", "1"), "--ke0"),
    # torsion constant (#19): 1 N·m/deg = 180/π N·m/rad
    "torsion constant": (0.5, ["0.5 N*m/rad", "0.5 Nm/rad", "0.5 N.m/rad", "500 mN*m/rad", f"{0.5 * math.pi / 180!r} N*m/deg", "0.5 J/rad",
                               "0.5 N*m", "0.5"], ("pendulum", "--inertia", "0.02", "--cm-distance", "0", "--mass", "1kg", "--angle0", "30deg"), "--torsion"),
    # lead (a screw's advance per turn): a length alone is per revolution, a length per angle is turned into that
    "lead": (0.2 * IN, [
        "0.2 in/rev", "0.2in/rev", "0.2 in", "0.2in", "5.08 mm", "5.08mm/rev", "5.08 mm/turn", f"{5.08 / 360!r} mm/deg",
        f"{0.2 * IN / (2 * PI)!r} m/rad", f"{0.2 * IN!r}", f"{0.2 * IN!r} m/rev", "1/5 in",
    ], ("drive", "--load-mass", "10kg"), "--lead"),
    # density (a part's density=): 1 lb/ft³ = 0.45359237 kg / 0.3048³ m³
    "density": (7800.0, ["7800 kg/m^3", "7800 kg/m3", "7.8 g/cm^3", "7.8 g/cm3", "7.8 g/mL", "7800 kg*m^-3",
                         f"{7800 / (0.45359237 / 0.3048**3)!r} lb/ft^3", "7.8 tonne/m^3", "7800"], None, None),
    # pressure (a face's pmax=, a spec key): 1 bar = 1e5 Pa, 1 psi = 6894.757293168361 Pa
    "pressure": (1.5e6, ["1.5 MPa", "1.5MPa", "1.5e6 Pa", "1500 kPa", "15 bar", "15bar", f"{1.5e6 / 6894.757293168361!r} psi", "1.5e6"],
                 None, None),
    # stress (flywheel --allowable-stress): 1 psi = 1 lbf/in² = 6894.757293168361 Pa
    "stress": (6e6, ["6 MPa", "6MPa", "6e6 Pa", "6000 kPa", "0.006 GPa", "6 N/mm^2", "6 N/mm2", f"{6e6 / 6894.757293168361!r} psi", "6e6"],
               ("flywheel", "--omega-mean", "300rpm", "--fluctuation", "0.02", "--energy-swing", "5kJ", "--rim-radius", "0.6m", "--density", "7200kg/m^3"),
               "--allowable-stress"),
    # momentum (torque --momentum, a vector read a component at a time): 1 N·s = 1 kg·m/s
    "momentum": (2.0, ["2 kg*m/s", "2kg*m/s", "2 kg m/s", "2 N*s", "2000 g*m/s", "200000 g*cm/s", f"{2 / (0.45359237 * 0.3048)!r} lb*ft/s", "2"],
                 None, None),
    # areal and linear density (#34: --density of a plate or disc, of a rod or ring, read by its unit)
    "areal density": (20.0, ["20 kg/m^2", "20 kg/m2", "2 g/cm^2", "2 g/cm2", "20 kg*m^-2", "20000 g/m^2",
                             f"{20 / (0.45359237 / 0.3048**2)!r} lb/ft^2", "20"], None, None),
    "linear density": (0.5, ["0.5 kg/m", "500 g/m", "5 g/cm", "0.5 kg*m^-1", "0.005 kg/cm", f"{0.5 / (0.45359237 / 0.3048)!r} lb/ft",
                             "50 g/dm", "0.5"], None, None),
    # specific heat (spin-down --specific-heat, #47): per kelvin, a kelvin of rise being a degree Celsius of it
    "specific heat": (460.0, ["460 J/(kg*K)", "460J/(kg*K)", "0.46 kJ/(kg*K)", "0.46 J/(g*K)", "460 J/kg/K", "460 J*kg^-1*K^-1",
                              "460 m^2/(s^2*K)", "460 W*s/(kg*K)", "460 J/(kg*delta_degC)", "460"],
                      ("spin-down", "--inertia", "1kg*m^2", "--omega0", "10rad/s", "--brake", "force=10N mu=0.4 radius=0.2m", "--heat-mass", "2kg"),
                      "--specific-heat"),
}  # fmt: skip


def spellings_of(kind: str) -> list[tuple[str, str | None]]:
    return [item if isinstance(item, tuple) else (item, None) for item in SPELLINGS[kind][1]]


def test_every_kind_has_a_table_of_spellings():
    assert set(SPELLINGS) == set(units.KINDS)
    assert all(len(SPELLINGS[kind][1]) >= 8 for kind in SPELLINGS)


@pytest.mark.parametrize(
    "kind,text,note", [(kind, text, note) for kind in SPELLINGS for text, note in spellings_of(kind)], ids=lambda x: x if isinstance(x, str) else ""
)
def test_each_spelling_reads_as_the_same_si_value(kind, text, note):
    parsed = units.parse(text, "--x", kind, sign="any")
    assert parsed.value == pytest.approx(SPELLINGS[kind][0], rel=1e-12)
    if note is None:
        assert parsed.note is None, parsed.note
    else:
        assert parsed.note is not None and note in parsed.note and parsed.note.startswith(f"--x {text}: "), parsed.note


def _in_process(argv: list[str], capsys) -> dict:
    status = cli.main([*argv, "--json", "--no-steps"])
    captured = capsys.readouterr()
    assert status == 0, (argv, captured.err)
    return json.loads(captured.out)


COMMAND_KINDS = [kind for kind in SPELLINGS if SPELLINGS[kind][2] is not None]


@pytest.mark.parametrize("kind", COMMAND_KINDS)
def test_each_spelling_reads_the_same_on_the_command_line(kind, capsys):
    """Every spelling as an option's value (in this process), and the first unit spelling in a shell."""
    value, _, base, option = SPELLINGS[kind]
    key = option.lstrip("-").replace("-", "_")
    for text, note in spellings_of(kind):
        document = _in_process([*base, option, text], capsys)
        assert document["inputs"][key]["value"] == pytest.approx(value, rel=1e-12), text
        if note:
            assert any(note in said for said in document["notes"]), (text, document["notes"])
    text = next(text for text, _ in spellings_of(kind) if not units._is_number(text))
    shell = run_taucli(*base, option, text, "--json", "--no-steps")
    assert shell.code == 0, shell.err
    assert shell.json()["inputs"][key]["value"] == pytest.approx(value, rel=1e-12)


@pytest.mark.parametrize("kind", COMMAND_KINDS)
def test_each_spelling_reads_the_same_in_a_batch(kind):
    value, _, base, option = SPELLINGS[kind]
    key = option.lstrip("-").replace("-", "_")
    texts = [text for text, _ in spellings_of(kind)]
    result = run_taucli(*base, "--batch", "--no-steps", stdin="".join(json.dumps({key: text}) + "\n" for text in texts))
    assert result.code == 0, result.err + result.out
    documents = [json.loads(line) for line in result.out.splitlines()]
    assert len(documents) == len(texts)
    for text, document in zip(texts, documents):
        assert document["inputs"][key]["value"] == pytest.approx(value, rel=1e-12), text


@pytest.mark.parametrize("kind", COMMAND_KINDS)
def test_each_spelling_reads_the_same_as_a_sweep_point(kind):
    """A list A,B,C...: a bare number in a list takes the last item's unit, so bare spellings are left out."""
    value, _, base, option = SPELLINGS[kind]
    key = option.lstrip("-").replace("-", "_")
    texts = [text for text, _ in spellings_of(kind) if not units._is_number(text)]
    result = run_taucli(*base, option, ",".join(texts), "--json", "--no-steps")
    assert result.code == 0, result.err
    documents = result.json()
    assert len(documents) == len(texts)
    for text, document in zip(texts, documents):
        assert document["inputs"][key]["value"] == pytest.approx(value, rel=1e-12), text


def test_angular_acceleration_units_read_the_same_in_to(capsys):
    """No option takes an angular acceleration yet; --to reads its units: α = τ/I = 2π rad/s² = 1 rev/s²."""
    for unit, in_unit in [("rpm/s", 60.0), ("RPM/s", 60.0), ("rev/s^2", 1.0), ("deg/s^2", 360.0), ("Hz/s", 1.0), ("rad/s^2", 2 * PI)]:
        document = _in_process(["spin-down", "--inertia", "1", "--torque", f"{2 * PI!r}", "--to", f"alpha0={unit}"], capsys)
        assert document["results"]["alpha0"]["value"] == pytest.approx(in_unit, rel=1e-12), unit
    for unit in ("1/s^2", "s^-2"):  # radians or revolutions per second squared: --to reads a unit as an option does (#31)
        assert cli.main(["spin-down", "--inertia", "1", "--torque", "1", "--to", f"alpha0={unit}"]) == 2
        assert f"--to: expected a unit of an angular acceleration that names its angle (e.g. 'rad/s^2' or 'rev/s^2'), got '{unit}'" in capsys.readouterr().err


REFUSED = [
    (("spin-down", "--inertia", "1", "--force", "6N", "--lever", "0.25m", "--push-angle", "60"), ("--push-angle: expected an angle with its unit", "60deg or 1.05rad", "'60'")),
    (("rolling", "sphere", "--angle", "30", "--length", "2m"), ("--angle: expected an angle with its unit",)),
    (("atwood", "--m1", "4kg", "--m2", "1kg", "--incline", "30"), ("--incline: expected an angle with its unit",)),
    (("rolling", "sphere", "--angle", "2*15", "--length", "2m"), ("--angle: expected an angle with its unit",)),
    (("atwood", "--m1", "3 4 kg"), ("--m1", "two numbers side by side", "'3*4 kg'")),
    (("atwood", "--m1", "2 3/4/5"), ("--m1", "two numbers side by side")),
    (("atwood", "--m1", "(2)(3) kg"), ("--m1", "two numbers side by side", "'(2)*(3) kg'")),
    (("atwood", "--m1", "1 3/2 kg"), ("--m1", "two numbers side by side", "a fraction below 1")),
    (("atwood", "--m1", "4kg", "--m2", "1kg", "--distance", "5 ft 3 in"), ("--distance", "a number after a unit", "'5 ft + 3 in'")),
    (("atwood", "--m1", "4 kg 3"), ("--m1", "a number after its unit", "before its unit")),
    (("spin-down", "--inertia", "1", "--torque", "2 N.5"), ("--torque", "a number right after the unit 'N'")),
    (("spin-down", "--inertia", "1", "--torque", "2 nm"), ("--torque", "which is a length", "did you mean 'N*m'?")),
    (("spin-down", "--inertia", "1", "--torque", "2 NM"), ("--torque", "unknown unit 'NM'", "did you mean 'N*m'?")),
    (("atwood", "--m1", "5 KG"), ("--m1", "unknown unit 'KG'", "did you mean 'kg'?")),
    (("atwood", "--m1", "5 MG"), ("--m1", "did you mean 'mg' or 'Mg'?")),
    (("atwood", "--m1", "4kg", "--m2", "1kg", "--incline", "30deg", "--mu-k", "20deg"), ("--mu-k: expected a plain number", "which is an angle")),
    (("spin-down", "--inertia", "1e61 kg*m^2", "--friction", "1"), ("--inertia", "between 1e-60 and 1e60 kg*m**2", "'0.1 kg*m^2'")),
    (("inertia", "sphere", "--mass", "1e40kg", "--radius", "1e40m"), ("--mass and --radius: expected a moment of inertia", "between 1e-60 and 1e60", "I = 4e+119 kg*m**2")),
    (("inertia", "disc", "--mass", "1kg", "--radius", "1m", "--part", "point mass=1e40kg offset=1e12m"), ("--mass, --radius and --part 2", "I = 1e+64")),
    (("spin-down", "--shape", "point", "--mass", "1e-40kg", "--radius", "1e-40m", "--friction", "1"), ("--mass and --radius", "I = 1e-120")),
]


@pytest.mark.parametrize("args,fragments", REFUSED, ids=lambda x: " ".join(x)[:60])
def test_a_refused_spelling_gets_one_line_that_names_the_fix(args, fragments):
    assert_usage_error(run_taucli(*args), *fragments)


# The table, as the person meant it.


def test_min_to_the_minus_one_is_revolutions_per_minute():
    """t_stop = I ω0 / τ_f, ω0 = 3000 rev/min = 3000 × 2π/60 rad/s."""
    result = run_taucli("spin-down", "--inertia", "0.1", "--omega0", "3000 min^-1", "--friction", "0.2", "--json", "--no-steps")
    assert result.code == 0, result.err
    document = result.json()
    assert document["results"]["t_stop"]["value"] == pytest.approx(0.1 * (3000 * 2 * PI / 60) / 0.2, rel=1e-12)
    assert "--omega0 3000 min^-1: min^-1 read as revolutions per minute (ω = 2πn)" in document["notes"]


def test_a_push_angle_needs_its_unit_and_then_gives_f_r_sin_phi():
    assert_usage_error(run_taucli("spin-down", "--inertia", "1", "--force", "6N", "--lever", "0.25m", "--push-angle", "60"), "--push-angle", "60deg")
    result = run_taucli("spin-down", "--inertia", "1", "--force", "6N", "--lever", "0.25m", "--push-angle", "60deg", "--get", "alpha0")
    assert result.code == 0, result.err
    assert float(result.out) == pytest.approx(6 * 0.25 * math.sin(PI / 3) / 1, rel=1e-12)  # α = τ/I = F r sin φ / I


def test_a_record_turntable_is_33_and_a_third_rpm():
    result = run_taucli("spin-down", "--inertia", "1", "--omega0", "33 1/3 rpm", "--friction", "1", "--json", "--no-steps")
    assert result.code == 0, result.err
    document = result.json()
    assert document["inputs"]["omega0"]["value"] == pytest.approx((33 + 1 / 3) * 2 * PI / 60, rel=1e-12)
    assert document["inputs"]["omega0"]["value"] == pytest.approx(3.4907, abs=5e-5)
    assert "--omega0 33 1/3 rpm: 33 1/3 read as the mixed number 33 + 1/3" in document["notes"]


def test_fifty_per_second_is_refused_naming_both_readings():
    """ω in s⁻¹ is rad/s in a physics book and rev/s by ISO 80000-3: no reading is safe (#31)."""
    result = run_taucli("spin-down", "--inertia", "1", "--omega0", "50 1/s", "--friction", "1", "--json", "--no-steps")
    assert_usage_error(result, "--omega0: expected an angular velocity with its angle unit (e.g. 50rad/s or 50rev/s), got '50 1/s': "
                               "1/s could be radians or revolutions per second")


@pytest.mark.parametrize("text", ["2Nm", "2 N-m", "2 N.m", "2 kNm"])
def test_newton_metres_as_engineers_write_them(text):
    scale = 1000 if "k" in text else 1
    assert units.parse(text, "--torque", "torque") == units.Parsed(2.0 * scale, None)


@pytest.mark.parametrize("text,pounds", [("2 ft-lb", 2), ("15 lb*ft", 15), ("15 ft*lb", 15), ("24 in-lb", 2)])
def test_a_pound_in_a_torque_is_a_pound_force_with_a_note(text, pounds):
    parsed = units.parse(text, "--torque", "torque")
    assert parsed.value == pytest.approx(pounds * LBF_FT, rel=1e-12)
    assert "lb read as pound-force" in parsed.note


def test_a_weight_for_a_mass_is_w_over_g():
    default = units.parse("40N", "--mass", "mass")
    assert default.value == pytest.approx(40 / G0, rel=1e-14)
    assert default.note == "--mass 40N: a weight, read as the mass W/g = 4.07886 kg (standard gravity g = 9.80665 m/s²)"
    given_g = units.parse("40N", "--mass", "mass", gravity=9.8)
    assert given_g.value == pytest.approx(40 / 9.8, rel=1e-14)
    assert "g = 9.8 m/s²" in given_g.note and "standard" not in given_g.note
    assert units.parse("10 lbf", "--mass", "mass").value == pytest.approx(10 * LB, rel=1e-14)
    assert units.parse("10 lbf", "--mass", "mass", gravity=G0 / 6).value == pytest.approx(60 * LB, rel=1e-14)  # on the Moon, roughly
    with pytest.raises(InputError, match="needs a positive gravity"):
        units.parse("10 lbf", "--mass", "mass", gravity=0.0)


def test_a_weight_for_a_mass_on_the_command_line(taucli):
    result = taucli("atwood", "--m1", "40N", "--m2", "10 lbf", "--json", "--no-steps")
    assert result.code == 0, result.err
    document = result.json()
    assert document["inputs"]["m1"]["value"] == pytest.approx(40 / G0, rel=1e-12)
    assert document["inputs"]["m2"]["value"] == pytest.approx(10 * LB, rel=1e-12)
    assert sum("a weight, read as the mass W/g" in note for note in document["notes"]) == 2


# Mixed numbers, numbers side by side, and what respelling must leave alone.

SIDE_BY_SIDE = ["3 4 kg", "2 3/4/5", "3 4", "2(3) kg", "(2)(3) kg", "(2) 3 kg", "5 ft 3 in", "4 kg 3", "1 3/2 kg", "1 2/2 kg", "2 1/0 kg",
                "33 1/3 1/3 rpm", "1 1/2.5 kg", "1 1/2e3 kg", "2 3e2 kg", "2 .5 kg", "2 N.5", "2 1/(3) kg", "2 1/2/3 kg", "kg 3"]  # fmt: skip


@pytest.mark.parametrize("text", SIDE_BY_SIDE)
def test_numbers_side_by_side_never_reach_an_answer(text):
    with pytest.raises(InputError) as caught:
        units.parse(text, "--m", "mass", sign="any")
    assert caught.value.hint or "side by side" in str(caught.value), str(caught.value)


@pytest.mark.parametrize(
    "text,kind,expected",
    [
        ("33 1/3 rpm", "angular velocity", (100 / 3) * RPM), ("1 1/2 kg", "mass", 1.5), ("-1 1/2 N*m", "torque", -1.5), ("2 3/4", "length", 2.75),
        ("1 1/2kg", "mass", 1.5), ("0 1/2 kg", "mass", 0.5), ("33⅓ rpm", "angular velocity", (100 / 3) * RPM), ("2½ in", "length", 2.5 * IN),
        ("50 1/min", "angular velocity", 50 * RPM), ("1 1/min", "angular velocity", RPM), ("2 * 3 kg", "mass", 6.0), ("3/4 kg", "mass", 0.75),
    ],
)  # fmt: skip
def test_a_mixed_number_and_a_unit_1_over_a_time_are_not_numbers_side_by_side(text, kind, expected):
    assert units.parse(text, "--x", kind, sign="any").value == pytest.approx(expected, rel=1e-14)


@pytest.mark.parametrize(
    "text,kind,expected",
    [
        ("-2 N*m", "torque", -2.0), ("1e-3 kg", "mass", 1e-3), ("1e-3kg", "mass", 1e-3), ("1.5e-3 N.m", "torque", 1.5e-3), ("2.5N.m", "torque", 2.5),
        ("4kg-200g", "mass", 3.8), ("4 kg - 200 g", "mass", 3.8), ("4s-1s", "time", 3.0), ("3 min^-1", "angular velocity", 3 * RPM),
        ("3 min**-1", "angular velocity", 3 * RPM), ("2 m^-1*m^2", "length", 2.0), ("-0.5 rad", "angle", -0.5), ("1e-2 m", "length", 0.01),
        ("2 m/s2", "acceleration", 2.0), ("1 g0", "acceleration", G0), (".5 N.m", "torque", 0.5),
    ],
)  # fmt: skip
def test_respelling_leaves_minus_signs_exponents_and_decimals_alone(text, kind, expected):
    assert units.parse(text, "--x", kind, sign="any").value == pytest.approx(expected, rel=1e-14)


@pytest.mark.parametrize(
    "text,kind", [("1 rpm + 1 s^-1", "angular velocity"), ("1 rev/min + 1 1/min", "angular velocity"), ("30 deg + 1", "angle"), ("0.5 + 30 deg", "dimensionless")]
)
def test_a_sum_of_a_unit_with_an_angle_and_one_without_is_refused(text, kind):
    """pint would add them reading the radian as 1: 1 rpm + 1 s^-1 as 1 rpm + 1 rad/s."""
    with pytest.raises(InputError, match="adds a unit with an angle to one without"):
        units.parse(text, "--x", kind)


def test_a_sum_of_units_of_one_sort_is_read():
    assert units.parse("1 Hz + 1 Hz", "--x", "angular velocity").value == pytest.approx(4 * PI, rel=1e-15)
    assert units.parse("1 rpm + 60 rpm", "--x", "angular velocity").value == pytest.approx(61 * RPM, rel=1e-15)
    assert units.parse("1 rpm + 1 Hz", "--x", "angular velocity").value == pytest.approx(61 * RPM, rel=1e-15)  # Hz is rev/s here too (#42)
    assert units.parse("30 deg + 0.5 rad", "--x", "angle").value == pytest.approx(PI / 6 + 0.5, rel=1e-15)


@pytest.mark.parametrize(
    "text,respelled",
    [
        ("N-m", "N*m"), ("N.m", "N*m"), ("2Nm", "2N*m"), ("ft-lbf", "ft*lbf"), ("kgm^2", "kg*m**2"), ("kg m2", "kg*m**2"), ("RPM", "rpm"),
        ("3000 min-1", "3000 min**-1"), ("r/min", "rev/min"), ("s^-1", "s**-1"), ("1e-3 kg", "1e-3 kg"), ("-2 N*m", "-2 N*m"),
        ("4kg-200g", "4kg-200g"), ("4 kg - 200 g", "4 kg - 200 g"), ("2.5 N", "2.5 N"), ("g0", "g0"), ("4s-1s", "4s-1s"), ("m-2 s", "m-2 s"),
    ],
)  # fmt: skip
def test_respell_rewrites_units_only(text, respelled):
    assert spellings.respell(text) == respelled


def test_a_respelled_unit_shares_the_cache_entry_of_its_pint_spelling(tmp_path, monkeypatch):
    from taucli.quantities import cache

    store = cache.Store(str(tmp_path), "units", lambda: "this test")
    monkeypatch.setattr(cache, "unit_factors", lambda: store)
    monkeypatch.setattr(cache, "shipped_unit_factors", dict)  # pint asked, as for a unit not shipped (#36)
    monkeypatch.setattr(units, "_FACTORS", {})
    for text in ("2 Nm", "2 N*m", "2 N-m", "2 N.m", "2 N m", "2 N * m"):
        assert units.parse(text, "--torque", "torque").value == 2.0
    for text in ("1 kgm^2", "1 kg m2", "1 kg*m**2", "1 kg m^2", "1 kg·m²"):
        assert units.parse(text, "--inertia", "moment of inertia").value == 1.0
    assert sorted(store.entries) == ["N*m|torque|N*m", "kg*m**2|moment of inertia|kg*m**2"]


def test_a_repeat_run_with_engineering_spellings_imports_no_pint(tmp_path):
    from conftest import modules_after_run

    env = {"TAUCLI_CACHE_DIR": str(tmp_path)}
    argv = ["spin-down", "--inertia", "2 kgm^2", "--omega0", "3000 RPM", "--torque", "2Nm", "--get", "alpha0"]
    assert "pint" not in {name.split(".")[0] for name in modules_after_run(argv, env)}  # respelled, then shipped (#36)
    rare = ["spin-down", "--inertia", "2 kgm^2", "--omega0", "180000 rev/h", "--torque", "2 N-m", "--get", "alpha0"]
    assert "pint" in {name.split(".")[0] for name in modules_after_run(rare, env)}  # rev/h is not shipped
    assert "pint" not in {name.split(".")[0] for name in modules_after_run(rare, env)}


# Bounds: textbook astronomy fits, typed or computed, and no product a solver forms overflows.

SUN_I = 0.4 * 1.989e30 * 6.96e8**2  # a uniform sphere: 3.85e47 kg*m^2
EARTH_ORBIT_I = 5.972e24 * 1.496e11**2  # a point at 1 au: 1.34e47 kg*m^2
EARTH_ORBIT_OMEGA = 2 * PI / (365.25 * 86400)  # rad/s
NEUTRON_STAR_I = 0.4 * 2.8e30 * 1.0e4**2  # 1.4 solar masses, 10 km: 1.1e38 kg*m^2


def test_the_suns_moment_of_inertia_is_the_same_typed_or_computed(taucli):
    computed = taucli("inertia", "sphere", "--mass", "1.989e30kg", "--radius", "6.96e8m", "--get", "I")
    assert computed.code == 0, computed.err
    assert float(computed.out) == pytest.approx(SUN_I, rel=1e-12)
    typed = taucli("impulse", "--inertia", f"{SUN_I!r} kg*m^2", "--inertia-final", f"{NEUTRON_STAR_I!r}kg*m^2", "--omega0", "2.9e-6rad/s", "--get", "omega1")
    assert typed.code == 0, typed.err
    assert float(typed.out) == pytest.approx(SUN_I * 2.9e-6 / NEUTRON_STAR_I, rel=1e-12)  # L conserved: I0 ω0 = I1 ω1
    shaped = taucli("spin-down", "--shape", "sphere", "--mass", "1.989e30kg", "--radius", "6.96e8m", "--omega0", "2.9e-6rad/s", "--friction", "1e20N*m", "--get", "t_stop")
    assert shaped.code == 0, shaped.err
    assert float(shaped.out) == pytest.approx(SUN_I * 2.9e-6 / 1e20, rel=1e-12)


def test_the_earths_orbital_angular_momentum(taucli):
    result = taucli("impulse", "--inertia", f"{EARTH_ORBIT_I!r}kg*m^2", "--omega0", f"{EARTH_ORBIT_OMEGA!r}rad/s", "--torque", "0", "--duration", "1s", "--get", "L0")
    assert result.code == 0, result.err
    assert float(result.out) == pytest.approx(EARTH_ORBIT_I * EARTH_ORBIT_OMEGA, rel=1e-12)  # 2.66e40 kg*m^2/s
    assert 2.6e40 < float(result.out) < 2.7e40


def test_a_molecule_fits_too():
    assert units.parse("1.94e-46 kg*m^2", "--inertia", "moment of inertia").value == 1.94e-46  # O2, an open-textbook problem


@pytest.mark.parametrize("kind", sorted(units.KINDS))
def test_the_bounds_of_each_kind_are_inclusive_and_the_same_for_check_bounds(kind):
    low, high = units.KINDS[kind].bounds
    unit = units.KINDS[kind].si_unit
    for value in (low, high, -high, 0.0):
        assert units.parse(f"{value!r} {unit}".strip() if kind != "angle" or value == 0 else f"{value!r} rad", "--x", kind, sign="any").value == value
        units.check_bounds(value, kind, "--x")
    for value in (low / 2, high * 2, math.inf):
        with pytest.raises(InputError, match="between"):
            units.check_bounds(value, kind, "--x")


CORNERS = [(i, w, tau, t) for i in units.KINDS["moment of inertia"].bounds for w in (1e-40, 1e40) for tau in (1e-40, 1e40) for t in (1e-40, 1e40)]


@pytest.mark.parametrize("inertia,omega0,torque,time", CORNERS)
def test_at_the_corners_of_the_bounds_every_result_is_a_finite_number(inertia, omega0, torque, time, capsys):
    """I ω², ω² I t², τ t²/I at the bounds stay inside a double: no result turns null for overflow."""
    for drive in ("--friction", "--torque"):
        document = _in_process(["spin-down", "--inertia", repr(inertia), "--omega0", f"{omega0!r}rad/s", drive, repr(torque), "--time", repr(time)], capsys)
        assert not [note for note in document["notes"] if "no finite value" in note], document["notes"]
        for name in ("I", "alpha0", "omega", "theta", "revs"):
            assert math.isfinite(document["results"][name]["value"]), (drive, name)


# The property: re-expressing each input in another unit of its kind changes no SI result.

UNITS = {  # kind -> (unit, its SI value from the definitions)
    "mass": [("kg", 1.0), ("g", 1e-3), ("lb", LB), ("oz", OZ), ("tonne", 1e3), ("mg", 1e-6), ("kgf", 1.0), ("lbf", LB)],
    "length": [("m", 1.0), ("cm", 0.01), ("mm", 1e-3), ("ft", FT), ("in", IN), ("km", 1e3)],
    "angle": [("rad", 1.0), ("deg", PI / 180), ("°", PI / 180), ("rev", 2 * PI), ("arcmin", PI / 10800)],
    "time": [("s", 1.0), ("ms", 1e-3), ("min", 60.0), ("h", 3600.0), ("sec", 1.0)],
    "angular velocity": [("rad/s", 1.0), ("rpm", RPM), ("RPM", RPM), ("min^-1", RPM), ("1/min", RPM), ("Hz", 2 * PI), ("rps", 2 * PI), ("m/s/m", 1.0),
                         ("rev/s", 2 * PI), ("deg/s", PI / 180)],
    "torque": [("N*m", 1.0), ("Nm", 1.0), ("N-m", 1.0), ("lbf*ft", LBF_FT), ("lb*ft", LBF_FT), ("ft-lb", LBF_FT), ("kN*m", 1e3), ("N*cm", 0.01),
               ("oz-in", OZ * G0 * IN)],
    "moment of inertia": [("kg*m^2", 1.0), ("kgm^2", 1.0), ("kg m2", 1.0), ("g*cm^2", 1e-7), ("lb*ft^2", LB * FT**2), ("kg*cm^2", 1e-4)],
    "force": [("N", 1.0), ("kN", 1e3), ("lbf", LBF), ("kgf", G0), ("lb", LBF)],
    "acceleration": [("m/s^2", 1.0), ("m/s2", 1.0), ("ft/s^2", FT), ("cm/s^2", 0.01), ("g0", G0)],
    "viscous coefficient": [("N*m*s", 1.0), ("Nms", 1.0), ("N*m/(rad/s)", 1.0), ("N*m/rpm", 1 / RPM), ("mN*m*s", 1e-3)],
}  # fmt: skip
SI_UNITS = {"mass": "kg", "length": "m", "angle": "rad", "time": "s", "angular velocity": "rad/s", "torque": "N*m", "moment of inertia": "kg*m^2",
            "force": "N", "acceleration": "m/s^2", "viscous coefficient": "N*m*s"}  # fmt: skip
DEG = PI / 180

# scene -> (its arguments, {option: (kind, smallest, largest SI value)}), ranges kept clear of
# near-cancellations (m1 - m2, a push near 180°) that would turn an ulp in an input into 1e-12.
PROPERTY_SCENES = {
    "inertia": (["inertia", "disc"], {"--mass": ("mass", 0.5, 20.0), "--radius": ("length", 0.05, 2.0)}),
    "spin-down": (["spin-down"], {"--inertia": ("moment of inertia", 0.01, 10.0), "--omega0": ("angular velocity", 1.0, 300.0),
                                  "--friction": ("torque", 0.05, 5.0), "--viscous": ("viscous coefficient", 0.001, 0.1)}),
    "spin-down push": (["spin-down"], {"--inertia": ("moment of inertia", 0.01, 10.0), "--omega0": ("angular velocity", 1.0, 300.0),
                                       "--force": ("force", 1.0, 50.0), "--lever": ("length", 0.05, 1.0), "--push-angle": ("angle", 20 * DEG, 160 * DEG),
                                       "--viscous": ("viscous coefficient", 0.001, 0.1), "--time": ("time", 0.1, 100.0)}),
    "atwood": (["atwood"], {"--m1": ("mass", 2.0, 10.0), "--m2": ("mass", 0.1, 1.0), "--pulley-mass": ("mass", 0.1, 5.0),
                            "--pulley-radius": ("length", 0.02, 0.5), "--distance": ("length", 0.1, 5.0), "--g": ("acceleration", 9.0, 10.0)}),
    "rolling": (["rolling", "sphere"], {"--angle": ("angle", 5 * DEG, 60 * DEG), "--length": ("length", 0.5, 10.0), "--mass": ("mass", 0.1, 10.0),
                                        "--radius": ("length", 0.01, 0.5)}),
    "impulse": (["impulse"], {"--inertia": ("moment of inertia", 0.01, 10.0), "--omega0": ("angular velocity", 0.5, 100.0),
                              "--torque": ("torque", 0.1, 10.0), "--duration": ("time", 0.01, 5.0)}),
}  # fmt: skip


def _same(a, b) -> bool:
    if isinstance(a, float) and isinstance(b, float):
        return math.isclose(a, b, rel_tol=1e-12, abs_tol=0.0)
    return a == b


@pytest.mark.parametrize("scene", PROPERTY_SCENES)
def test_re_expressing_every_input_in_another_unit_leaves_the_si_results_unchanged(scene, capsys):
    base, options = PROPERTY_SCENES[scene]

    @settings(max_examples=40, deadline=None, database=None, suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
    @given(st.data())
    def check(data):
        si_args, other_args = list(base), list(base)
        drawn = []
        for option, (kind, low, high) in options.items():
            value = data.draw(st.floats(low, high), label=option)
            unit, factor = data.draw(st.sampled_from(UNITS[kind]), label=f"{option} unit")
            drawn.append((option, kind, value, unit, factor))
        # a weight given for a mass is W/g with the scene's own g (--g), not standard gravity
        g = next((value for option, _, value, _, _ in drawn if option == "--g"), G0)  # drawn in SI
        for option, kind, value, unit, factor in drawn:
            if kind == "mass" and unit in ("kgf", "lbf"):
                factor *= G0 / g
            si_args += [option, f"{value!r} {SI_UNITS[kind]}"]
            other_args += [option, f"{value / factor!r} {unit}"]
        si, other = _in_process(si_args, capsys), _in_process(other_args, capsys)
        for name, result in si["results"].items():
            assert _same(result["value"], other["results"][name]["value"]), (name, result["value"], other["results"][name]["value"], other_args)
        for name, given_value in si["inputs"].items():
            assert _same(given_value["value"], other["inputs"][name]["value"]), (name, other_args)

    check()


# #42 item 2: one rule for every kind with an angle in its unit, wherever the unit stands. A rate's
# spelling and its value in rad/s (Hz and min^-1: a rotational frequency, ω = 2πn): the same in an
# angular velocity, per second in an angular acceleration, and divided into a viscous (τ = bω) or drag
# (τ = kω²) coefficient. A 1/s alone is refused for a rate (rad/s or rev/s?); in a coefficient, N·m·s
# is SI's own unit, the radian left out.
RATES = {
    "rad/s": 1.0, "deg/s": PI / 180, "rpm": RPM, "RPM": RPM, "rev/min": RPM, "r/min": RPM, "rps": 2 * PI, "rev/s": 2 * PI,
    "Hz": 2 * PI, "HZ": 2 * PI, "kHz": 2000 * PI, "min^-1": RPM, "1/min": RPM, "turn/s": 2 * PI,
}  # fmt: skip
# kind -> (the unit with the rate in it, how a value of 1 rate unit becomes the kind's SI value)
COMPOUNDS = {
    "angular velocity": ("({})", lambda w: w),
    "angular acceleration": ("({})/s", lambda w: w),
    "viscous coefficient": ("N*m/({})", lambda w: 1 / w),
    "drag coefficient": ("N*m/({})^2", lambda w: 1 / w**2),
    "angular momentum": ("kg*m^2*({})", lambda w: w),
}
# Where the unit stands: a number and its unit, grouped, in a product, a quotient, a sum.
PLACES = ["3 {}", "(3 {})", "2*(1.5 {})", "(6 {})/2", "3*(1 {})", "1 {} + 2 {}"]


def test_every_kind_with_an_angle_in_its_unit_has_its_compound_spellings():
    from taucli.quantities.kinds import ANGLE_POWERS

    timed = {kind for kind in ANGLE_POWERS if "s" in units.KINDS[kind].si_unit}  # those a rate goes into
    assert timed == set(COMPOUNDS)


@pytest.mark.parametrize("kind", sorted(COMPOUNDS))
@pytest.mark.parametrize("rate", sorted(RATES))
@pytest.mark.parametrize("place", PLACES)
def test_a_rate_reads_the_same_inside_every_compound_unit_and_place(kind, rate, place):
    unit, si = COMPOUNDS[kind]
    text = place.format(*[unit.format(rate)] * place.count("{}"))
    parsed = units.parse(text, "--x", kind, sign="any")
    assert parsed.value == pytest.approx(3 * si(RATES[rate]), rel=1e-13), text
    if rate in ("Hz", "HZ", "kHz", "min^-1", "1/min"):  # a rotational frequency read as revolutions: said
        assert parsed.note is not None and "revolutions per" in parsed.note, (text, parsed.note)


@pytest.mark.parametrize("kind", ["angular velocity", "angular acceleration"])
@pytest.mark.parametrize("per_second", ["1/s", "s^-1", "s**-1"])
@pytest.mark.parametrize("place", PLACES)
def test_a_bare_per_second_is_refused_for_a_rate_wherever_it_stands(kind, per_second, place):
    unit, _ = COMPOUNDS[kind]
    text = place.format(*[unit.format(per_second)] * place.count("{}"))
    with pytest.raises(InputError, match="could be radians or revolutions|adds a unit with an angle"):
        units.parse(text, "--x", kind, sign="any")


@pytest.mark.parametrize(
    "text,kind,si",
    [("0.01 N*m*s", "viscous coefficient", 0.01), ("0.01 N*m/(1/s)", "viscous coefficient", 0.01), ("0.001 N*m*s^2", "drag coefficient", 0.001),
     ("0.5 N*m", "torsion constant", 0.5), ("0.5 N*m/rev", "torsion constant", 0.5 / (2 * PI)), ("0.5 N*m/grad", "torsion constant", 0.5 * 200 / PI)],
)
def test_si_leaves_the_radian_out_of_a_coefficient(text, kind, si):
    assert units.parse(text, "--x", kind).value == pytest.approx(si, rel=1e-14)


@pytest.mark.parametrize(
    "text,kind,words",
    [("2 rad*Hz", "angular velocity", "the angle squared"), ("0.01 N*m*s*rev", "viscous coefficient", "has per angle once"),
     ("0.01 N*m*h", "viscous coefficient", "an hour with no angle"), ("0.001 N*m/Hz", "drag coefficient", "which is"),
     ("2 rev*rad", "angle", "the angle squared")],
)
def test_a_unit_with_the_wrong_power_of_the_angle_is_refused(text, kind, words):
    with pytest.raises(InputError, match=words):
        units.parse(text, "--x", kind)


def test_hz_in_a_coefficient_on_the_command_line_is_revolutions_per_second(taucli):
    """The issue's run: b = 0.01 N·m/(rev/s) = 0.01/(2π) N·m·s, so ω(1 s) = 10·exp(−b) rad/s with I = 1."""
    for viscous in ("0.01 N*m/Hz", "0.01 N*m/(rev/s)"):
        done = taucli("spin-down", "--inertia", "1", "--omega0", "10rad/s", "--viscous", viscous, "--time", "1s", "--get", "omega")
        assert float(done.out) == pytest.approx(10 * math.exp(-0.01 / (2 * PI)), rel=1e-12)
    drag = taucli("spin-down", "--inertia", "1", "--omega0", "10rad/s", "--drag", "0.001 N*m/Hz^2", "--time", "1s", "--get", "omega")
    k = 0.001 / (2 * PI) ** 2  # ω' = −kω²: ω = ω0/(1 + kω0 t)
    assert float(drag.out) == pytest.approx(10 / (1 + k * 10), rel=1e-12)
