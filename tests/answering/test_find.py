"""--find NAME --want RESULT=VALUE (#22): the inverse against the forward solve and against
independent inverses written from the physics; every root; the refusals."""

from __future__ import annotations

import io
import json
import math

import mpmath
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import taucli
from taucli.front import cli
from taucli.core.errors import InputError
from taucli.answering.find import brent

MP_DPS = 40  # the references' precision, set for each test by conftest
with mpmath.workdps(MP_DPS):
    G = mpmath.mpf("9.80665")  # standard gravity, exact to MP_DPS digits


def run(*args: str, stdin: str = "") -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    code = cli.main(list(args), cli.Environment(stdin=io.StringIO(stdin), stdout=out, stderr=err))
    return code, out.getvalue(), err.getvalue()


# Atwood from the physics: (m1 − m2) g = (m1 + m2 + I/R²) a, so I = R² ((m1 − m2) g / a − m1 − m2).
def pulley_inertia(m1, m2, R, a, g=G):
    return R**2 * ((m1 - m2) * g / a - m1 - m2)


def test_the_lab_pulley_inertia_from_a_measured_acceleration():
    report = taucli.atwood(m1="4kg", m2="1kg", pulley_radius="0.1m", find="pulley_inertia", want="a=4.0+/-0.1m/s^2")
    expected = pulley_inertia(4, 1, mpmath.mpf("0.1"), 4)
    assert report.results["pulley_inertia"].value == pytest.approx(float(expected), rel=1e-13)
    assert report.results["a"].value == pytest.approx(4.0, rel=1e-13)
    # δI = |∂I/∂a| δa, the derivative by mpmath of the independent inverse
    slope = mpmath.diff(lambda a: pulley_inertia(4, 1, mpmath.mpf("0.1"), a), 4)
    assert report.uncertainties["pulley_inertia"] == pytest.approx(float(abs(slope) * mpmath.mpf("0.1")), rel=1e-7)
    assert "closed-form inverse" in report.method
    assert report.steps[0].equation.startswith("a(pulley_inertia)")


@pytest.mark.parametrize("name, options, want", [
    ("pulley_inertia", {"m1": "4kg", "m2": "1kg", "pulley_radius": "0.1m"}, "a=4m/s^2"),
    ("pulley_mass", {"m1": "4kg", "m2": "1kg"}, "a=4.9m/s^2"),
    ("friction", {"shape": "disc", "mass": "5kg", "radius": "0.2m", "omega0": "30rad/s"}, "t_stop=10s"),
])
def test_a_closed_form_inverse_agrees_with_the_root_finder(name, options, want):
    scene = taucli.atwood if "m1" in options else taucli.spin_down
    closed = scene(**options, find=name, want=want)
    # a zero friction (or a zero viscous loss) given is the same scene, outside the closed form's model
    found = scene(**options, **({"axle_friction": 0} if "m1" in options else {"viscous": 0}), find=name, want=want)
    assert "closed-form inverse" in closed.method and "Brent" in found.method
    assert closed.results[name].value == pytest.approx(found.results[name].value, rel=1e-13)


def test_the_solved_inputs_uncertainty_includes_every_inputs():
    report = taucli.atwood(m1="4.0+/-0.05kg", m2="1kg", pulley_radius="0.1m+/-0.001m", find="pulley_inertia", want="a=4.0+/-0.1m/s^2")
    point = {"m1": mpmath.mpf(4), "R": mpmath.mpf("0.1"), "a": mpmath.mpf(4)}
    spreads = {"m1": 0.05, "R": 0.001, "a": 0.1}
    total = 0
    for name, sigma in spreads.items():
        def along(x, name=name):
            p = {**point, name: x}
            return pulley_inertia(p["m1"], 1, p["R"], p["a"])
        total += (mpmath.diff(along, point[name]) * sigma) ** 2
    assert report.uncertainties["pulley_inertia"] == pytest.approx(float(mpmath.sqrt(total)), rel=1e-6)
    # T1 = m1 (g − a): with a held by the target, its uncertainty comes from m1 and a
    expected_t1 = math.hypot(0.05 * (9.80665 - 4), 4 * 0.1)
    assert report.uncertainties["T1"] == pytest.approx(expected_t1, rel=1e-6)


def test_friction_torque_from_a_measured_stop_time():
    # τ = I ω0 / t: the potter's wheel (I = 0.1 kg·m², ω0 = 30 rad/s) that stops in 10 ± 0.2 s
    report = taucli.spin_down(shape="disc", mass="5kg", radius="0.2m", omega0="30rad/s", find="friction", want="t_stop=10+/-0.2s")
    assert report.results["friction"].value == pytest.approx(0.3, rel=1e-13)
    assert report.uncertainties["friction"] == pytest.approx(0.3 * 0.2 / 10, rel=1e-7)
    assert report.results["t_stop"].value == pytest.approx(10, rel=1e-13)


@settings(max_examples=20, deadline=None)
@given(m1=st.floats(1, 20), m2=st.floats(0.1, 20), fraction=st.floats(0.05, 0.95))
def test_property_the_inverse_solved_forward_gives_the_target(m1, m2, fraction):
    assume(m1 > m2 * 1.01)
    a0 = (m1 - m2) * 9.80665 / (m1 + m2)  # the massless pulley's: a with I = 0, the most a can be
    target = fraction * a0
    report = taucli.atwood(m1=m1, m2=m2, pulley_radius=0.1, find="pulley_inertia", want=f"a={target!r}")
    inertia = report.results["pulley_inertia"].value
    forward = taucli.atwood(m1=m1, m2=m2, pulley_radius=0.1, pulley_inertia=inertia)
    assert forward.results["a"].value == pytest.approx(target, rel=1e-12)
    assert inertia == pytest.approx(float(pulley_inertia(mpmath.mpf(m1), mpmath.mpf(m2), mpmath.mpf("0.1"), mpmath.mpf(target))), rel=1e-10)


def test_every_root_is_listed_and_the_smallest_in_size_is_the_result():
    # KE1 = ½ I ω1² = 4 J with I = 2 kg·m²: ω1 = ±2 rad/s
    report = taucli.impulse(inertia="2 kg*m^2", omega0=0, duration="1s", find="omega1", want="KE1=4J")
    assert sorted(report.results["roots"].value) == pytest.approx([-2, 2], rel=1e-13)
    assert abs(report.results["omega1"].value) == pytest.approx(2, rel=1e-13)
    assert any("2 values" in note for note in report.notes)


def test_a_target_no_value_reaches_is_refused_with_the_reachable_range():
    with pytest.raises(InputError) as caught:
        taucli.atwood(m1="2kg", m2="1kg", pulley_radius="0.1m", find="pulley_mass", want="a=9m/s^2")
    message = str(caught.value)
    assert "cannot be met" in message and "3.26888" in message  # a at a massless pulley: g/3


def test_a_target_that_holds_over_an_interval_is_refused_naming_it():
    # friction that holds: a = 0 for every axle friction from (m1 − m2) g R upward
    code, _, err = run("atwood", "--m1", "2kg", "--m2", "1kg", "--pulley-radius", "0.1m", "--find", "axle_friction", "--want", "a=0")
    assert code == 2 and "0.980665 N·m upward" in err and "--axle-friction" in err


@pytest.mark.parametrize(
    "args, fragment",
    [
        (("--find", "pulley_inertia"), "--want"),
        (("--want", "a=4"), "--find"),
        (("--find", "colour", "--want", "a=4"), "expected a quantity option"),
        (("--find", "m2", "--want", "a=4"), "leave it out"),
        (("--find", "pulley_inertia", "--want", "speed=4"), "expected a result"),
        (("--find", "pulley_inertia", "--want", "a=4kg"), "--want"),
        (("--find", "pulley_inertia", "--want", "grips=1"), "yes or no"),
    ],
)
def test_bad_find_and_want_are_usage_errors(args, fragment):
    code, _, err = run("atwood", "--m1", "4kg", "--m2", "1kg", "--pulley-radius", "0.1m", *args)
    assert code == 2 and fragment in err and "Traceback" not in err


def test_batch_lines_take_find_and_want():
    lines = '{"m1": "4kg", "m2": "1kg", "pulley_radius": "0.1m", "find": "pulley_inertia", "want": "a=4m/s^2"}\n{"m1": "4kg", "m2": "1kg"}\n'
    code, out, _ = run("atwood", "--batch", "--no-steps", stdin=lines)
    first, second = (json.loads(line) for line in out.splitlines())
    assert code == 0
    assert first["results"]["pulley_inertia"]["value"] == pytest.approx(float(pulley_inertia(4, 1, mpmath.mpf("0.1"), 4)), rel=1e-13)
    assert "pulley_inertia" not in second["results"]


def test_a_sweep_solves_for_the_input_at_each_point():
    code, out, _ = run("atwood", "--m1", "4kg", "--m2", "1kg", "--pulley-radius", "0.1m", "--find", "pulley_inertia", "--want", "a=4m/s^2", "--distance", "1m,2m", "--json")
    assert code == 0
    docs = json.loads(out)
    assert [doc["results"]["pulley_inertia"]["value"] for doc in docs] == pytest.approx([float(pulley_inertia(4, 1, mpmath.mpf("0.1"), 4))] * 2, rel=1e-13)


def test_brent_finds_a_root_to_a_few_ulp():
    root, steps = brent(lambda x: x**3 - 2, 0.0, 2.0, -2.0, 6.0)
    assert root == pytest.approx(2 ** (1 / 3), rel=4e-16) and steps < 60


def test_monte_carlo_with_find_agrees_with_the_implicit_function_theorem():
    code, out, _ = run("atwood", "--m1", "4kg+/-0.02kg", "--m2", "1kg", "--pulley-radius", "0.1m", "--find", "pulley_inertia",
                       "--want", "a=4.0+/-0.02m/s^2", "--mc", "3000", "--json")
    doc = json.loads(out)
    draws = doc["monte_carlo"]["draws"]
    for key in ("pulley_inertia", "T1"):
        linear = doc["results"][key]["uncertainty"]
        drawn = doc["monte_carlo"]["results"][key]["uncertainty"]
        assert code == 0 and abs(drawn - linear) < 3 * linear / math.sqrt(2 * (draws - 1)), key
