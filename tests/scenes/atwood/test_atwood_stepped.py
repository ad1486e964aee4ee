"""The stepped pulley and the string that slides over the rim (#21): each against the bodies'
equations solved as a linear system with mpmath, energy balances, and continuity at the capstan
limit."""

from __future__ import annotations

import math

import mpmath
import pytest
from hypothesis import assume, example, given, settings
from hypothesis import strategies as st

import taucli
from taucli.core.errors import InputError
from taucli.scenes.atwood import Pulley, atwood, solve_rim, solve_stepped

G = 9.80665
masses = st.floats(0.01, 100)


def values(report):
    return {name: value.value for name, value in report.results.items()}


def stepped_reference(m1, m2, inertia, r1, r2, axle, g, direction):
    """Unknowns α, T1, T2:  m1 r1 α + T1 = m1 g;  m2 r2 α − T2 = −m2 g;  I α − r1 T1 + r2 T2 = −s τ."""
    with mpmath.workdps(40):
        m1, m2, inertia, r1, r2, axle, g = (mpmath.mpf(x) for x in (m1, m2, inertia, r1, r2, axle, g))
        matrix = mpmath.matrix([[m1 * r1, 1, 0], [m2 * r2, 0, -1], [inertia, -r1, r2]])
        return mpmath.lu_solve(matrix, mpmath.matrix([m1 * g, -m2 * g, -direction * axle]))


@settings(max_examples=300, deadline=None)
@given(m1=masses, m2=st.one_of(st.just(0.0), masses), inertia=st.one_of(st.just(0.0), st.floats(1e-4, 10)), r1=st.floats(0.01, 1),
       r2=st.floats(0.01, 1), axle=st.one_of(st.just(0.0), st.floats(0, 5)), g=st.floats(1, 30))
def test_the_stepped_pulley_solves_the_three_body_equations(m1, m2, inertia, r1, r2, axle, g):
    result = values(solve_stepped(m1, m2, Pulley(0.0, None, None, inertia, axle), g, r1, r2))
    assume(result["a"] != 0)
    alpha, tension1, tension2 = stepped_reference(m1, m2, inertia, r1, r2, axle, g, 1 if result["a"] > 0 else -1)
    assert result["alpha"] == pytest.approx(float(alpha), rel=1e-11, abs=1e-12 * g / r1)
    assert result["a"] == pytest.approx(float(alpha * r1), rel=1e-11, abs=1e-12 * g)
    assert result["a2"] == pytest.approx(float(alpha * r2), rel=1e-11, abs=1e-12 * g * r2 / r1)
    assert result["T1"] == pytest.approx(float(tension1), rel=1e-11, abs=1e-12 * m1 * g)
    assert result["T2"] == pytest.approx(float(tension2), rel=1e-11, abs=1e-12 * (m1 + m2) * g)


def test_a_stepped_pulley_with_equal_steps_is_the_articles_machine():
    result = values(solve_stepped(4.0, 1.0, Pulley(2.0, 0.1), 9.8, 0.1, 0.1))
    assert result["a"] == pytest.approx(4.9, rel=1e-15) and result["T1"] == pytest.approx(19.6, rel=1e-15)
    assert result["T2"] == pytest.approx(14.7, rel=1e-15) and result["a2"] == pytest.approx(4.9, rel=1e-15)


def test_a_textbook_stepped_pulley():
    """m1 = 0.5 kg on r1 = 0.2 m against m2 = 1 kg on r2 = 0.05 m, I = 0.04 kg·m², g = 9.8:
    α = (0.98 − 0.49)/(0.04 + 0.02 + 0.0025) = 7.84 rad/s²; the lighter mass wins on the larger step."""
    result = values(solve_stepped(0.5, 1.0, Pulley(0.0, None, None, 0.04), 9.8, 0.2, 0.05))
    assert result["alpha"] == pytest.approx(7.84, rel=1e-14)
    assert result["T1"] == pytest.approx(0.5 * (9.8 - 1.568), rel=1e-14)
    assert result["T2"] == pytest.approx(1.0 * (9.8 + 0.392), rel=1e-14)


def test_balanced_torques_hold_the_stepped_pulley():
    report = solve_stepped(1.0, 2.0, Pulley(1.0, 0.2), G, 0.2, 0.1)
    result = values(report)
    assert result["a"] == 0 and result["T1"] == pytest.approx(G) and result["T2"] == pytest.approx(2 * G)
    assert any("nothing moves" in note for note in report.notes)


@settings(max_examples=150, deadline=None)
@given(m1=masses, m2=masses, inertia=st.floats(1e-4, 1), r1=st.floats(0.01, 1), r2=st.floats(0.01, 1), axle=st.floats(0, 2), d=st.floats(0.01, 10))
def test_stepped_work_of_gravity_is_kinetic_energy_plus_axle_losses(m1, m2, inertia, r1, r2, axle, d):
    result = values(solve_stepped(m1, m2, Pulley(0.0, None, None, inertia, axle), G, r1, r2, distance=d))
    assume(result["a"] > 0)
    v1 = result["v"]
    with mpmath.workdps(40):
        turned = mpmath.mpf(d) / r1
        omega = mpmath.mpf(v1) / r1
        work = m1 * G * mpmath.mpf(d) - m2 * G * r2 * turned
        kinetic = mpmath.mpf(m1) * v1**2 / 2 + mpmath.mpf(m2) * (omega * r2) ** 2 / 2 + inertia * omega**2 / 2
        assert float(kinetic + axle * turned) == pytest.approx(float(work), rel=1e-10)


# A string that may slide over the rim ----------------------------------------------------------


def rim_reference(m1, m2, inertia_over_r2, g, mu, wrap):
    """Grip: unknowns a, T1, T2 with (T1 − T2) = (I/R²) a. If T_high/T_low > e^{μβ}, slide:
    unknowns a, a_rim, T1, T2 with T_high = e^{μβ} T_low and (T1 − T2) = (I/R²) a_rim."""
    with mpmath.workdps(40):
        m1, m2, M, g, mu, wrap = (mpmath.mpf(x) for x in (m1, m2, inertia_over_r2, g, mu, wrap))
        a, t1, t2 = mpmath.lu_solve(mpmath.matrix([[m1, 1, 0], [m2, 0, -1], [M, -1, 1]]), mpmath.matrix([m1 * g, -m2 * g, 0]))
        E = mpmath.exp(mu * wrap)
        if max(t1, t2) <= E * min(t1, t2) * (1 + mpmath.mpf(10) ** -35):  # equal masses: equal to the solver's rounding
            return dict(a=a, a_rim=a, T1=t1, T2=t2, grips=True)
        capstan = [1, -E] if t1 > t2 else [-E, 1]  # T_high − E T_low = 0
        matrix = mpmath.matrix([[m1, 0, 1, 0], [m2, 0, 0, -1], [0, M, -1, 1], [0, 0, *capstan]])
        a, a_rim, t1, t2 = mpmath.lu_solve(matrix, mpmath.matrix([m1 * g, -m2 * g, 0, 0]))
        return dict(a=a, a_rim=a_rim, T1=t1, T2=t2, grips=False)


@settings(max_examples=300, deadline=None)
@given(m1=masses, m2=masses, pulley_mass=masses, shape=st.sampled_from(["disc", "ring"]), mu=st.floats(0, 1), wrap=st.floats(0.1, 10))
@example(m1=0.010000000000000002, m2=0.01, pulley_mass=0.25, shape="disc", mu=0.0, wrap=1.0)  # T1 − T2 ~ 1e-16 T1: from (I/R²)a, not T1 − T2
def test_the_string_grips_or_slides_as_the_capstan_limit_says(m1, m2, pulley_mass, shape, mu, wrap):
    radius = 0.1
    pulley = Pulley(pulley_mass, radius, shape)
    result = values(solve_rim(m1, m2, pulley, G, mu, wrap))
    ref = rim_reference(m1, m2, pulley.effective_mass(), G, mu, wrap)
    assert result["grips"] is ref["grips"]
    for name in ("a", "a_rim", "T1", "T2"):
        assert result[name] == pytest.approx(float(ref[name]), rel=1e-11, abs=1e-12 * G * (1 if name.startswith("a") else m1 + m2)), name
    assert result["alpha"] == pytest.approx(result["a_rim"] / radius, rel=1e-14)
    if not ref["grips"]:  # the string runs ahead of the rim, the way the masses go
        assert (result["a"] - result["a_rim"]) * math.copysign(1, result["a"]) > 0


@pytest.mark.parametrize("m1,m2", [(4.0, 1.0), (1.0, 4.0), (1.2, 1.0), (10.0, 0.1)])
@pytest.mark.parametrize("wrap", [math.pi, math.pi / 2, 4 * math.pi])
def test_the_capstan_limit_is_continuous(m1, m2, wrap):
    pulley = Pulley(2.0, 0.1)
    need = values(solve_rim(m1, m2, pulley, G, 1.0, wrap))["rim_mu_min"]
    a = rim_reference(m1, m2, 1.0, G, 100, wrap)["a"]  # μ large: it grips
    gripping = values(solve_rim(m1, m2, pulley, G, need * (1 + 1e-12), wrap))
    sliding = values(solve_rim(m1, m2, pulley, G, need * (1 - 1e-12), wrap))
    assert gripping["grips"] is True and sliding["grips"] is False
    for name in ("a", "a_rim", "T1", "T2", "alpha"):
        assert sliding[name] == pytest.approx(gripping[name], rel=1e-9), name
    assert gripping["a"] == pytest.approx(float(a), rel=1e-13)


@settings(max_examples=150, deadline=None)
@given(m1=masses, m2=masses, pulley_mass=masses, mu=st.floats(0, 0.3), d=st.floats(0.01, 10))
def test_sliding_string_work_of_gravity_is_kinetic_energy_plus_heat_at_the_rim(m1, m2, pulley_mass, mu, d):
    """m1 g x − m2 g x = ½(m1 + m2)v² + ½ I ω² + |T1 − T2| |x − Rθ| (friction works on the slide)."""
    radius = 0.2
    result = values(solve_rim(m1, m2, Pulley(pulley_mass, radius), G, mu, math.pi, distance=d))
    assume(result["a"] != 0)
    with mpmath.workdps(40):
        t = mpmath.mpf(result["t"])
        x = mpmath.sign(result["a"]) * d
        turned = mpmath.mpf(result["alpha"]) * t * t / 2
        omega = mpmath.mpf(result["alpha"]) * t
        inertia = mpmath.mpf(pulley_mass) * radius**2 / 2
        work = (m1 - mpmath.mpf(m2)) * G * x
        kinetic = (m1 + mpmath.mpf(m2)) * mpmath.mpf(result["v"]) ** 2 / 2 + inertia * omega**2 / 2
        heat = abs(mpmath.mpf(result["T1"]) - result["T2"]) * abs(x - radius * turned)
        assert float(kinetic + heat) == pytest.approx(float(work), rel=1e-9)


def test_a_string_over_a_heavy_pulley_slides():
    """4 kg and 1 kg over a 2 kg disc, g = 9.8: gripping needs T1/T2 = 19.6/14.7 = 4/3, so
    μ ≥ ln(4/3)/π = 0.0916. With μ = 0.05 it slides: E = e^{0.05π}, a = g(4 − E)/(4 + E)."""
    result = values(solve_rim(4.0, 1.0, Pulley(2.0, 0.1), 9.8, 0.05, math.pi))
    with mpmath.workdps(30):
        E = mpmath.exp(mpmath.mpf(0.05) * mpmath.pi)
        assert result["rim_mu_min"] == pytest.approx(float(mpmath.log(mpmath.mpf(4) / 3) / mpmath.pi), rel=1e-14)
        assert result["a"] == pytest.approx(float(9.8 * (4 - E) / (4 + E)), rel=1e-14)
        assert result["T2"] == pytest.approx(float(2 * 4 * 9.8 / (4 + E)), rel=1e-14)
    assert result["grips"] is False and result["a_rim"] < result["a"]


def test_units_do_not_change_the_answer():
    si = taucli.atwood(m1=4.0, m2=1.0, pulley_mass=2.0, pulley_radius=0.1, rim_mu=0.05, wrap=math.pi, distance=1.0)
    other = taucli.atwood(m1="4000 g", m2="1 kg", pulley_mass="2 kg", pulley_radius="10 cm", rim_mu=0.05, wrap="180 deg", distance="100 cm")
    for name in ("a", "T1", "T2", "alpha", "a_rim", "v", "t"):
        assert other.results[name].value == pytest.approx(si.results[name].value, rel=1e-12)
    stepped = taucli.atwood(m1="500 g", m2="1 kg", pulley_inertia="0.04 kg*m^2", radius1="20 cm", radius2="5 cm")
    assert stepped.results["alpha"].value == pytest.approx(7.84 * G / 9.8, rel=1e-13)


@pytest.mark.parametrize(
    "arguments,fragment",
    [
        (dict(m1=1.0, m2=1.0, radius1=0.1), "radius2 is required"),
        (dict(m1=1.0, m2=1.0, radius1=0.1, radius2=0.2, rim_mu=0.3), "radius1 does not apply with rim_mu"),
        (dict(m1=1.0, m2=1.0, wrap=3.0), "wrap needs rim_mu"),
        (dict(m1=1.0, rim_mu=0.3, pulley_mass=1.0), "m2 must be more than 0"),
        (dict(m1=1.0, m2=1.0, rim_mu=0.3, incline=0.2), "incline does not apply with rim_mu"),
        (dict(m1=1.0, m2=1.0, rim_mu=0.3, axle_friction=0.1, pulley_radius=0.1), "axle_friction does not apply"),
    ],
)
def test_impossible_machines_are_input_errors(arguments, fragment):
    with pytest.raises(InputError) as caught:
        atwood(**arguments)
    assert fragment in str(caught.value)


def test_found_by_fuzzing_a_rough_rim_and_an_inertia_without_a_radius():
    """A scratch fuzz run (#21): μβ = 1000π overflowed e^(μβ) in the note (exit 1); a pulley
    inertia with no radius reached an assert before the usual 'pulley_radius is required'."""
    report = atwood(m1=1e-9, m2=1e-9, rim_mu=1000.0)
    assert values(report)["grips"] is True and any("e^3141.59" in note for note in report.notes)
    with pytest.raises(InputError) as caught:
        atwood(m1=1e-9, m2=1e-9, pulley_inertia=0.0, rim_mu=0.0)
    assert "pulley_radius is required" in str(caught.value)


@settings(max_examples=300, deadline=None)
@given(m2=masses, r2=st.floats(0.01, 1), r1=st.floats(0.01, 1), gap=st.integers(1, 60), inertia=st.one_of(st.just(0.0), st.floats(1e-4, 1)))
def test_a_stepped_pulley_near_balance_keeps_full_precision(m2, r2, r1, gap, inertia):
    """m1 r1 = m2 r2 (1 + 2^-gap): α within 4 ulp of the 50-digit (m1 g r1 − m2 g r2)/(I + m1 r1² + m2 r2²).
    Written as m1·r1 − m2·r2 in floats the two rounded products lose up to `gap` bits."""
    m1 = m2 * r2 * (1 + 2.0**-gap) / r1
    alpha = values(solve_stepped(m1, m2, Pulley(0.0, None, None, inertia), G, r1, r2))["alpha"]
    with mpmath.workdps(50):
        m1_, m2_, r1_, r2_ = (mpmath.mpf(x) for x in (m1, m2, r1, r2))
        exact = G * (m1_ * r1_ - m2_ * r2_) / (inertia + m1_ * r1_**2 + m2_ * r2_**2)
    assert abs(mpmath.mpf(alpha) - exact) <= 4 * abs(exact) * mpmath.mpf(2) ** -52
