"""Uncertainty through a whole scene (#22): reading "4.0+/-0.1 kg", first-order propagation with
the full Jacobian, against mpmath's differentiation of an independent reference of the scene."""

from __future__ import annotations

import io
import json
import math

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taucli
from taucli.front import cli
from taucli.answering import pipeline
from taucli.options import SCENES
from taucli.writing.document import STRICT_JSON, document
from taucli.quantities.measurement import split, with_uncertainty

MP_DPS = 40  # the references' precision, set for each test by conftest
with mpmath.workdps(MP_DPS):
    G = mpmath.mpf("9.80665")  # standard gravity, exact to MP_DPS digits


def run(*args: str, stdin: str = "") -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    code = cli.main(list(args), cli.Environment(stdin=io.StringIO(stdin), stdout=out, stderr=err))
    return code, out.getvalue(), err.getvalue()


# An independent Atwood machine, from the physics: m1 g − T1 = m1 a, T2 − m2 g = m2 a,
# (T1 − T2) R = (½ M R²)(a/R); so a = (m1 − m2) g / (m1 + m2 + M/2).
def atwood_reference(m1, m2, M, g=G):
    a = (m1 - m2) * g / (m1 + m2 + M / 2)
    return {"a": a, "T1": m1 * (g - a), "T2": m2 * (g + a), "a_massless": (m1 - m2) * g / (m1 + m2)}


def reference_sigma(f, point: dict, spreads: dict, key: str) -> float:
    """√Σ (∂f/∂x σx)², each derivative by mpmath.diff at 40 digits."""
    total = mpmath.mpf(0)
    for name, sigma in spreads.items():
        def along(x, name=name):
            return f(**{**{k: mpmath.mpf(v) for k, v in point.items()}, name: x})[key]
        total += (mpmath.diff(along, mpmath.mpf(point[name])) * mpmath.mpf(sigma)) ** 2
    return float(mpmath.sqrt(total))


@pytest.mark.parametrize(
    "text, value, spread",
    [
        ("4.0+/-0.1 kg", "4.0 kg", "0.1 kg"),
        ("4.0 ± 0.1 kg", "4.0 kg", "0.1 kg"),
        ("4.0±0.1kg", "4.0 kg", "0.1 kg"),
        ("(4.0 ± 0.1) kg", "4.0 kg", "0.1 kg"),
        ("4.0 kg ± 100 g", "4.0 kg", "100 g"),
        ("4.0 kg +/- 0.1", "4.0 kg", "0.1 kg"),
        ("4.0(1) kg", "4.0 kg", "1e-1 kg"),
        ("4.00(12) kg", "4.00 kg", "12e-2 kg"),
        ("1234(5) g", "1234 g", "5e0 g"),
        ("6.674(3)e-11", "6.674e-11", "3e-14"),
        ("4 ± 0.1", "4", "0.1"),
    ],
)
def test_every_spelling_of_an_uncertainty_splits_into_the_value_and_its_spread(text, value, spread):
    assert split(text) == (value, spread)


@pytest.mark.parametrize("text", ["4 kg", "0.3 N*m/(rad/s)", "300 rpm", "(4 kg"])
def test_a_text_with_no_uncertainty_is_not_split(text):
    assert split(text) is None


def test_the_articles_atwood_with_m1_uncertain_matches_mpmath_for_every_result():
    report = taucli.atwood(m1="4.0+/-0.1 kg", m2="1kg", pulley_mass="2kg", pulley_radius="0.1m")
    point = {"m1": 4, "m2": 1, "M": 2}
    for key in ("a", "T1", "T2", "a_massless"):
        expected = reference_sigma(atwood_reference, point, {"m1": 0.1}, key)
        assert report.uncertainties[key] == pytest.approx(expected, rel=1e-8), key
    # alpha = a/R
    assert report.uncertainties["alpha"] == pytest.approx(report.uncertainties["a"] / 0.1, rel=1e-8)
    assert report.results["a"].value == pytest.approx(4.903325, rel=1e-12)  # the value is the article's


def test_several_uncertain_inputs_add_in_quadrature_through_the_full_jacobian():
    report = taucli.atwood(m1="4.0 ± 0.1 kg", m2="1.0(2) kg", pulley_mass="(2.0 ± 0.3) kg", pulley_radius="0.1m", g="9.81+/-0.02")
    point = {"m1": 4, "m2": 1, "M": 2, "g": mpmath.mpf("9.81")}
    spreads = {"m1": 0.1, "m2": 0.2, "M": 0.3, "g": 0.02}
    for key in ("a", "T1", "T2", "a_massless"):
        assert report.uncertainties[key] == pytest.approx(reference_sigma(atwood_reference, point, spreads, key), rel=1e-7), key


def test_the_uncertainty_does_not_depend_on_the_unit_it_is_written_in():
    kg = taucli.atwood(m1="4.0+/-0.1 kg", m2="1kg", pulley_mass="2kg")
    grams = taucli.atwood(m1="4000 ± 100 g", m2="1kg", pulley_mass="2kg")
    mixed = taucli.atwood(m1="4 kg ± 100 g", m2="1kg", pulley_mass="2kg")
    for key in kg.uncertainties:
        assert grams.uncertainties[key] == pytest.approx(kg.uncertainties[key], rel=1e-9)
        assert mixed.uncertainties[key] == pytest.approx(kg.uncertainties[key], rel=1e-9)


def test_spin_down_uncertainties_match_the_independent_formulas():
    # t = I ω0 / τ, θ = I ω0² / (2τ): relative uncertainties add in quadrature.
    report = taucli.spin_down(inertia="0.1+/-0.002 kg*m^2", omega0="30+/-0.5 rad/s", friction="0.3+/-0.01 N*m")
    rel_t = math.sqrt(0.02**2 + (0.5 / 30) ** 2 + (0.01 / 0.3) ** 2)
    rel_theta = math.sqrt(0.02**2 + (2 * 0.5 / 30) ** 2 + (0.01 / 0.3) ** 2)
    assert report.uncertainties["t_stop"] == pytest.approx(10 * rel_t, rel=1e-7)
    assert report.uncertainties["theta_stop"] == pytest.approx(150 * rel_theta, rel=1e-7)


def test_monte_carlo_agrees_with_first_order_within_its_standard_error_on_a_near_linear_scene():
    code, out, _ = run("atwood", "--m1", "4.0+/-0.02kg", "--m2", "1kg", "--pulley-mass", "2kg", "--mc", "4000", "--json")
    assert code == 0
    doc = json.loads(out)
    draws = doc["monte_carlo"]["draws"]
    for key in ("a", "T1", "T2"):
        linear = doc["results"][key]["uncertainty"]
        mean, spread = doc["monte_carlo"]["results"][key]["mean"], doc["monte_carlo"]["results"][key]["uncertainty"]
        assert abs(spread - linear) < 3 * linear / math.sqrt(2 * (draws - 1)), key
        assert abs(mean - doc["results"][key]["value"]) < 3 * linear / math.sqrt(draws), key


def test_a_stop_within_one_sigma_is_said_to_be_far_from_linear():
    report = taucli.atwood(m1="1.1+/-0.1 kg", m2="1kg", pulley_radius="0.1m", axle_friction="0.05 N*m")
    assert any("far from linear" in note and "friction holds" in note for note in report.notes)
    quiet = taucli.atwood(m1="4.0+/-0.01 kg", m2="1kg", pulley_mass="2kg")
    assert not any("linear" in note for note in quiet.notes)


def test_json_puts_the_uncertainty_beside_the_value_and_stays_strict():
    code, out, _ = run("atwood", "--m1", "4.0+/-0.1kg", "--m2", "1kg", "--pulley-mass", "2kg", "--json", "--to", "a=cm/s^2")
    doc = json.loads(out, parse_constant=lambda name: pytest.fail(name))
    assert list(doc["results"]["T1"])[:2] == ["value", "uncertainty"]
    assert doc["inputs"]["m1"]["uncertainty"] == 0.1
    plain = taucli.atwood(m1="4.0+/-0.1 kg", m2="1kg", pulley_mass="2kg").uncertainties["a"]
    assert doc["results"]["a"]["unit"] == "cm/s^2"
    assert doc["results"]["a"]["uncertainty"] == pytest.approx(100 * plain, rel=1e-12)  # --to converts it too


def test_get_prints_a_second_column_only_when_asked():
    args = ("atwood", "--m1", "4.0+/-0.1kg", "--m2", "1kg", "--pulley-mass", "2kg", "--get", "a")
    assert run(*args)[1] == "4.903325\n"
    value, spread = run(*args, "--uncertainty")[1].split()
    assert float(value) == 4.903325 and float(spread) == pytest.approx(0.0817220833, rel=1e-6)
    assert run("atwood", "--m1", "4kg", "--m2", "1kg", "--get", "a", "--uncertainty")[1].split()[1] == "0"


def test_the_human_view_matches_digits_to_the_uncertainty():
    code, out, _ = run("atwood", "--m1", "4.0+/-0.1kg", "--m2", "1kg", "--pulley-mass", "2kg", "--pulley-radius", "0.1m")
    assert "4.90 ± 0.08" in out and "19.61 ± 0.16" in out and "49.0 ± 0.8" in out


@pytest.mark.parametrize(
    "value, sigma, shown",
    [(4.903325, 0.0817, "4.90 ± 0.08"), (19.6133, 0.163, "19.61 ± 0.16"), (150.0, 15.0, "150 ± 15"),
     (0.0235, 0.00184, "0.0235 ± 0.0018"), (1.234e9, 5.6e7, "(1.23 ± 0.06)e9"), (2.0, 0.0, "2 ± 0")],
)
def test_with_uncertainty(value, sigma, shown):
    assert with_uncertainty(value, sigma) == shown


@pytest.mark.parametrize("scene", ["atwood", "spin-down"])
def test_without_an_uncertainty_the_plain_path_is_untouched(scene):
    command = SCENES[scene]
    options = {"m1": "4kg", "m2": "1kg", "pulley_mass": "2kg"} if scene == "atwood" else {"inertia": "0.1 kg*m^2", "omega0": "30 rad/s", "friction": "0.3 N*m"}
    from taucli.answering import answer

    through = answer.solve(command, options)
    direct = pipeline.solve(command, options)
    assert type(through) is type(direct)
    assert STRICT_JSON.encode(document(through)) == STRICT_JSON.encode(document(direct))


def test_a_batch_line_may_carry_an_uncertainty():
    code, out, _ = run("atwood", "--batch", stdin='{"m1": "4.0+/-0.1kg", "m2": "1kg", "pulley_mass": "2kg"}\n{"m1": "4kg", "m2": "1kg"}\n')
    first, second = (json.loads(line) for line in out.splitlines())
    assert code == 0 and "uncertainty" in first["results"]["a"] and "uncertainty" not in second["results"]["a"]


@pytest.mark.parametrize("bad", ["4.0+/--0.1kg", "4.0+/-0.1s", "4.0+/-abc"])
def test_a_bad_uncertainty_is_a_usage_error_naming_the_option(bad):
    code, _, err = run("atwood", "--m1", bad, "--m2", "1kg")
    assert code == 2 and "--m1" in err and "Traceback" not in err


@settings(max_examples=25, deadline=None)
@given(
    m1=st.floats(0.5, 50), m2=st.floats(0.1, 50), M=st.one_of(st.just(0.0), st.floats(0.01, 20)), relative=st.floats(1e-4, 0.05),
)
def test_property_the_uncertainty_of_a_is_its_slope_times_sigma(m1, m2, M, relative):
    sigma = m1 * relative
    report = taucli.atwood(m1=f"{m1!r} ± {sigma!r} kg", m2=m2, pulley_mass=M)
    if report.results["a"].value is None or "a" not in report.uncertainties:
        return
    expected = reference_sigma(atwood_reference, {"m1": m1, "m2": m2, "M": M}, {"m1": sigma}, "a")
    assert report.uncertainties["a"] == pytest.approx(expected, rel=1e-6, abs=1e-12)


@settings(max_examples=25, deadline=None)
@given(value=st.floats(1e-3, 1e3), relative=st.floats(1e-4, 0.5), scale=st.floats(0.5, 4))
def test_property_sigma_scales_with_the_inputs_sigma_to_first_order(value, relative, scale):
    one = taucli.spin_down(inertia=f"{value!r} ± {value * relative * 1e-3!r}", omega0="30 rad/s", friction="0.3 N*m")
    many = taucli.spin_down(inertia=f"{value!r} ± {value * relative * 1e-3 * scale!r}", omega0="30 rad/s", friction="0.3 N*m")
    assert many.uncertainties["t_stop"] == pytest.approx(scale * one.uncertainties["t_stop"], rel=1e-6)


@pytest.mark.parametrize("flag", [("--mc", "100"), ("--uncertainty",)])
def test_batch_refuses_mc_and_the_get_column(flag):
    code, _, err = run("atwood", "--batch", *flag, stdin='{"m1": "4kg"}\n')
    assert code == 2 and flag[0] in err and "--batch" in err


@pytest.mark.parametrize("call", [
    lambda: taucli.pendulum(shape="point", mass="1kg", radius="1+/-0.01 m", angle0="10deg"),
    lambda: taucli.rolling(shape="sphere", angle="30+/-1 deg", length="2m"),
    lambda: taucli.drive(load_mass="250 kg", lead="10mm", ratio=[2], efficiency="0.9+/-0.03", mu=0.2, motor_inertia="0.3e-4 kg*m^2",
                         distance="0.275m", speed="15m/min", accel="2.5 m/s^2", dwell_time="0.3s"),
])
def test_a_model_that_names_an_input_does_not_change_as_the_input_moves(call):
    """The model's text names the value of an input ("point mass 1 m from the axis", "30° slope",
    "η = 0.9"): at ±1σ that number moves, and the model is the same one. Only a change of its
    words (a stop, slipping, a stage held) is far from linear."""
    report = call()
    assert not any("far from linear" in note for note in report.notes), report.notes
