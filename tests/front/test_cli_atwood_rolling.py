"""`taucli atwood` and `taucli rolling` through the real entry point."""

from __future__ import annotations

import math

import pytest

from conftest import assert_usage_error

G = 9.80665


def test_atwood_article_example_with_steps(taucli):
    out = taucli("atwood", "--m1", "4kg", "--m2", "1kg", "--pulley-mass", "2kg", "--pulley-radius", "0.1m", "--g", "9.8").out
    for text in ("m₁g − T₁ = m₁a", "T₂ − m₂g = m₂a", "T₁ − T₂ = (M/2)a", "= 4.9 m/s²", "= 19.6 N", "= 14.7 N", "5.88 m/s²", "0.98 m/s²"):
        assert text in out, text


def test_atwood_json_get_and_notes(taucli):
    doc = taucli("atwood", "--m1", "4kg", "--m2", "1kg", "--pulley-mass", "2kg", "--json").json()
    assert doc["results"]["a"]["value"] == pytest.approx(3 * G / 6)
    assert doc["results"]["alpha"]["value"] is None
    assert any("standard gravity" in note for note in doc["notes"])
    assert any("solid disc" in note for note in doc["notes"])
    assert any("pulley-radius" in note for note in doc["notes"])
    a, t1 = taucli("atwood", "--m1", "4kg", "--m2", "1kg", "--get", "a", "--get", "T1").out.split()
    assert float(a) == pytest.approx(3 * G / 5) and float(t1) == pytest.approx(4 * (G - 3 * G / 5))


def test_atwood_in_pounds_and_feet(taucli):
    """8 lb and 2 lb over a 4 lb disc, 3 ft of travel: a = 6g/12 regardless of units."""
    doc = taucli("atwood", "--m1", "8lb", "--m2", "2lb", "--pulley-mass", "4lb", "--distance", "3ft", "--to", "a=ft/s^2", "--to", "T1=lbf", "--json").json()
    a_si = 6 * G / 12
    assert doc["results"]["a"]["value"] == pytest.approx(a_si / 0.3048)
    assert doc["results"]["T1"]["value"] == pytest.approx(8 * (G - a_si) * 0.45359237 / (0.45359237 * G))
    assert doc["results"]["t"]["value"] == pytest.approx(math.sqrt(2 * 3 * 0.3048 / a_si))


@pytest.mark.parametrize(
    "args,fragments",
    [
        (("--m1", "-4kg", "--m2", "1kg"), ("--m1", "zero or more")),
        (("--m2", "1kg"), ("--m1 is required",)),
        (("--m1", "0kg", "--m2", "0kg"), ("cannot both be zero",)),
        (("--m1", "1kg", "--m2", "1kg", "--incline", "100deg"), ("--incline", "0 to 90")),
        (("--m1", "1kg", "--m2", "1kg", "--incline", "0deg", "--mu-k", "0.5", "--mu-s", "0.2"), ("--mu-k must not exceed",)),
        (("--m1", "1kg", "--m2", "1kg", "--pulley-inertia", "0.01"), ("--pulley-radius is required",)),
        (("--m1", "1kg", "--m2", "1kg", "--axle-friction", "0.1 N"), ("--axle-friction", "torque", "force")),
        (("--m1", "1kg", "--m2", "1kg", "--pulley-shape", "cone", "--pulley-mass", "1kg"), ("--pulley-shape",)),
        (("--m1", "1kg", "--g", "-9.8"), ("--g", "positive")),
    ],
)
def test_atwood_bad_input(taucli, args, fragments):
    assert_usage_error(taucli("atwood", *args), *fragments)


def test_rolling_sphere_with_steps(taucli):
    out = taucli("rolling", "sphere", "--angle", "30deg", "--length", "2m").out
    for text in ("m a = m g sin θ − f", "I α = f R", "a = R α", "a = g sin θ / (1 + k²)", "3.50237 m/s²", "μ_min"):
        assert text in out, text


def test_rolling_slips_when_static_friction_is_short(taucli):
    doc = taucli("rolling", "disc", "--angle", "40deg", "--mu-s", "0.2", "--mu-k", "0.15", "--mass", "2kg", "--radius", "0.1m", "--json").json()
    assert doc["results"]["rolls"] == {"value": False, "unit": None, "label": doc["results"]["rolls"]["label"]}
    angle = math.radians(40)
    assert doc["results"]["a"]["value"] == pytest.approx(G * (math.sin(angle) - 0.15 * math.cos(angle)))
    assert "slipping" in doc["model"]
    assert taucli("rolling", "disc", "--angle", "40deg", "--mu-s", "0.2", "--mu-k", "0.15", "--get", "rolls").out == "false\n"


def test_rolling_in_feet(taucli):
    v = float(taucli("rolling", "cylinder", "--angle", "15deg", "--height", "4ft", "--to", "v=ft/s", "--get", "v").out)
    assert v == pytest.approx(math.sqrt(2 * G * 4 * 0.3048 / 1.5) / 0.3048)


def test_skidding_ball_on_the_flat(taucli):
    doc = taucli("rolling", "sphere", "--v0", "7m/s", "--mu-k", "0.2", "--json").json()
    assert doc["results"]["v_roll"]["value"] == pytest.approx(5.0)
    assert "skidding" in doc["model"]


@pytest.mark.parametrize(
    "args,fragments",
    [
        (("sphere", "--angle", "95deg"), ("--angle", "90")),
        (("sphere", "--angle", "-5deg"), ("--angle",)),
        (("sphere", "--angle", "30"), ("--angle",)),  # a bare number is radians: 30 rad is no slope
        (("sphere", "--angle", "30deg", "--mu-s", "0.1", "--mu-k", "0.3"), ("--mu-k must not exceed",)),
        (("sphere", "--angle", "30deg", "--mass", "-1kg"), ("--mass", "positive")),
        (("sphear", "--angle", "30deg"), ("SHAPE", "did you mean 'sphere'")),
        (("--angle", "30deg"), ("SHAPE", "--k2")),
        (("--inertia", "0.01", "--angle", "30deg"), ("--mass is required",)),
        (("sphere", "--k2", "0.4", "--angle", "30deg"), ("--k2", "conflicts")),
    ],
)
def test_rolling_bad_input(taucli, args, fragments):
    assert_usage_error(taucli("rolling", *args), *fragments)


def test_rolling_at_v0_alone_needs_no_mass(taucli):
    """#21: --v0 alone rolls along; since 246630e its energies alone need the mass (null, with a note)."""
    doc = taucli("rolling", "sphere", "--v0", "3m/s", "--json").json()
    assert doc["results"]["a"]["value"] == 0 and doc["results"]["KE"]["value"] is None
    assert any("KE_trans, KE_rot, KE: give --mass" in note for note in doc["notes"])


def test_an_incline_with_no_coefficient_given_is_smooth(taucli):
    """friction.py's rule through the command line: neither μ given, m2 slides without friction;
    only μs given and it slides, what needs μk is null with a note."""
    import math

    smooth = taucli("atwood", "--m1", "4kg", "--m2", "1kg", "--incline", "30deg", "--json").json()
    expected = (4 - 1 * math.sin(math.radians(30))) * 9.80665 / 5
    assert smooth["results"]["a"]["value"] == pytest.approx(expected, rel=1e-14)
    rough = taucli("atwood", "--m1", "4kg", "--m2", "1kg", "--incline", "30deg", "--mu-s", "0.3", "--json").json()
    assert rough["results"]["a"]["value"] is None
    assert any("--mu-k" in note for note in rough["notes"])


def test_an_unknown_option_is_answered_from_the_commands_own_options(taucli):
    """#16 item 18: --slip was answered 'Possible options: --help, --jsonl'."""
    slip = taucli("atwood", "--m1", "4kg", "--m2", "1kg", "--slip", "1")
    assert_usage_error(slip, "--slip is not an option of atwood")
    assert "--jsonl" not in slip.err
    assert_usage_error(taucli("atwood", "--m1", "4kg", "--pulley-mas", "1kg"), "did you mean '--pulley-mass'?")
    assert_usage_error(taucli("rolling", "sphere", "--angel", "30deg"), "did you mean '--angle'?")


def test_a_speed_on_the_flat_with_a_length_is_refused_not_read_as_a_slope_from_rest(taucli):
    """#16 item 12: --angle 0deg --v0 1 --mu-k 0.3 --length 1 became a 0° incline from rest (v0 set
    aside: 'from rest it stays where it is'), with exit 0."""
    assert_usage_error(taucli("rolling", "sphere", "--angle", "0deg", "--v0", "1", "--mu-k", "0.3", "--length", "1"), "--length applies down a slope")
    assert_usage_error(taucli("rolling", "sphere", "--v0", "1m/s", "--height", "1m"), "--height applies down a slope")


@pytest.mark.parametrize(
    "given,inertia",
    [
        (["--part", "ring mass=2kg radius=0.1m"], 2 * 0.1**2),  # a thin ring: MR²
        (["--pulley-mass", "2kg", "--part", "point mass=1kg radius=0.1m"], 0.5 * 2 * 0.1**2 + 1 * 0.1**2),  # a disc and a point on its rim
        (["--pulley-inertia", "0.01kg*m^2", "--part", "rod mass=0.6kg length=0.2m", "--part", "rod mass=0.6kg length=0.2m"], 0.01 + 2 * 0.6 * 0.2**2 / 12),
    ],
    ids=["ring part", "disc and a point", "inertia and two spokes"],
)
def test_a_pulley_of_parts(taucli, given, inertia):
    """#18: --part for the pulley in atwood: a = (m1 − m2)g/(m1 + m2 + I/R²), I the sum of the parts'."""
    done = taucli("atwood", "--m1", "4kg", "--m2", "1kg", "--pulley-radius", "0.1m", "--g", "9.8", *given, "--json")
    assert done.code == 0, done.err
    expected = (4 - 1) * 9.8 / (4 + 1 + inertia / 0.1**2)
    assert done.json()["results"]["a"]["value"] == pytest.approx(expected, rel=1e-14)
    assert_usage_error(taucli("atwood", "--m1", "4kg", "--m2", "1kg", *given), "--pulley-radius is required with --part")
