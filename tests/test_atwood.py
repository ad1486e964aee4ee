"""The Atwood machine: the article's numbers, and each case against the three equations per body
solved as a linear system with mpmath (not the closed form retyped)."""

from __future__ import annotations

import math

import mpmath
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from taucli.errors import InputError
from taucli.scenes.atwood import HANGING, Pulley, Slope, solve


def values(report):
    return {name: value.value for name, value in report.results.items()}


def test_article_example_2():
    """m1 = 4 kg, m2 = 1 kg, solid disc pulley 2 kg, g = 9.8: a = 4.9, T1 = 19.6 N, T2 = 14.7 N."""
    result = values(solve(4.0, 1.0, Pulley(2.0, 0.1, "disc"), 9.8))
    assert result["a"] == pytest.approx(4.9, rel=1e-15)
    assert result["T1"] == pytest.approx(19.6, rel=1e-15)
    assert result["T2"] == pytest.approx(14.7, rel=1e-15)
    assert result["a_massless"] == pytest.approx(29.4 / 5, rel=1e-15)
    assert result["alpha"] == pytest.approx(49.0, rel=1e-15)


def test_article_mass_on_a_string_wound_on_a_disc_falls_at_half_g():
    """m = 1 kg hanging from a 2 kg disc: a = g/(1 + M/2m) = g/2, beside free fall at g."""
    result = values(solve(1.0, 0.0, Pulley(2.0), 9.8))
    assert result["a"] == pytest.approx(4.9, rel=1e-15)
    assert result["a_massless"] == pytest.approx(9.8, rel=1e-15)
    assert result["T2"] == 0.0


def reference(m1, m2, pulley_mass, shape, radius, angle, mu_k, axle, g, direction):
    """Solve m1 a + T1 = m1 g;  m2 a − T2 = −m2 g sin θ − s μk N;  (I/R²) a − T1 + T2 = −s τ/R."""
    with mpmath.workdps(40):
        m1, m2, pulley_mass, radius, angle, mu_k, axle, g = (mpmath.mpf(x) for x in (m1, m2, pulley_mass, radius, angle, mu_k, axle, g))
        inertia = (mpmath.mpf(1) / 2 if shape == "disc" else 1) * pulley_mass * radius**2
        hanging = angle == mpmath.mpf(HANGING)
        sin_a = 1 if hanging else mpmath.sin(angle)
        normal = 0 if hanging else m2 * g * mpmath.cos(angle)
        matrix = mpmath.matrix([[m1, 1, 0], [m2, 0, -1], [inertia / radius**2, -1, 1]])
        rhs = mpmath.matrix([m1 * g, -m2 * g * sin_a - direction * mu_k * normal, -direction * axle / radius])
        return mpmath.lu_solve(matrix, rhs)


masses = st.floats(0.01, 100)


@settings(max_examples=200, deadline=None)
@given(
    m1=masses,
    m2=st.one_of(st.just(0.0), masses),
    pulley_mass=st.one_of(st.just(0.0), masses),
    shape=st.sampled_from(["disc", "ring"]),
    radius=st.floats(0.01, 2),
    angle=st.one_of(st.just(HANGING), st.floats(0, HANGING)),
    mu_k=st.floats(0, 1),
    axle=st.one_of(st.just(0.0), st.floats(0, 5)),
    g=st.floats(1, 30),
)
def test_acceleration_and_tensions_solve_the_three_body_equations(m1, m2, pulley_mass, shape, radius, angle, mu_k, axle, g):
    if angle == HANGING:
        mu_k = 0.0
    report = solve(m1, m2, Pulley(pulley_mass, radius, shape, None, axle), g, slope=Slope(angle, mu_k, mu_k))
    result = values(report)
    assume(result["a"] != 0)  # moving: the kinetic equations hold
    direction = 1 if result["a"] > 0 else -1
    a, tension_high, tension_low = reference(m1, m2, pulley_mass, shape, radius, angle, mu_k, axle, g, direction)
    scale = max(abs(float(a)), 1e-300)
    assert result["a"] == pytest.approx(float(a), rel=1e-12, abs=1e-12 * g)
    assert result["T1"] == pytest.approx(float(tension_high), rel=1e-12, abs=1e-12 * m1 * g)
    assert result["T2"] == pytest.approx(float(tension_low), rel=1e-12, abs=1e-12 * (m1 + m2) * g)
    assert scale > 0


@settings(max_examples=150, deadline=None)
@given(m1=masses, m2=masses, pulley_mass=masses, mu_k=st.floats(0, 0.5), axle=st.floats(0, 2), angle=st.floats(0.1, 1.5), d=st.floats(0.01, 10))
def test_work_of_gravity_equals_kinetic_energy_plus_friction_losses(m1, m2, pulley_mass, mu_k, axle, angle, d):
    g, radius = 9.80665, 0.2
    report = solve(m1, m2, Pulley(pulley_mass, radius, "disc", None, axle), g, slope=Slope(angle, mu_k, mu_k), distance=d)
    result = values(report)
    assume(result["a"] > 0)
    v = result["v"]
    inertia = 0.5 * pulley_mass * radius**2
    gravity_work = m1 * g * d - m2 * g * math.sin(angle) * d
    kinetic = 0.5 * (m1 + m2) * v * v + 0.5 * inertia * (v / radius) ** 2
    losses = mu_k * m2 * g * math.cos(angle) * d + axle / radius * d
    assert gravity_work == pytest.approx(kinetic + losses, rel=1e-11)


def test_massless_limit_is_continuous():
    light = values(solve(4.0, 1.0, Pulley(1e-12, 0.1), 9.8))
    massless = values(solve(4.0, 1.0, Pulley(0.0, 0.1), 9.8))
    for name in ("a", "T1", "T2"):
        assert light[name] == pytest.approx(massless[name], rel=1e-11)
    assert massless["T1"] == massless["T2"]  # the article: a massless pulley keeps the tension equal


def test_equal_masses_stay_at_rest_with_tensions_from_statics():
    report = solve(2.0, 2.0, Pulley(1.0), 9.8)
    result = values(report)
    assert result["a"] == 0 and result["T1"] == result["T2"] == pytest.approx(19.6)
    assert any("nothing moves" in note for note in report.notes)


def test_axle_friction_holds_and_then_is_overcome():
    held = values(solve(1.1, 1.0, Pulley(1.0, 0.1, None, None, 0.1), 9.8))
    assert held["a"] == 0 and held["T1"] == pytest.approx(1.1 * 9.8) and held["T2"] == pytest.approx(9.8)
    moving = values(solve(1.2, 1.0, Pulley(1.0, 0.1, None, None, 0.1), 9.8))
    assert moving["a"] == pytest.approx((0.2 * 9.8 - 1.0) / 2.7)


def test_table_with_static_friction_at_the_threshold():
    """m2 = 2 kg on a table, μs = 0.5: m1 = 1 kg is just held; a hair more starts it at μk."""
    at_threshold = values(solve(1.0, 2.0, Pulley(), 9.8, slope=Slope(0.0, 0.3, 0.5)))
    assert at_threshold["a"] == 0
    above = values(solve(1.0 + 1e-9, 2.0, Pulley(), 9.8, slope=Slope(0.0, 0.3, 0.5)))
    assert above["a"] == pytest.approx((1.0 * 9.8 - 0.3 * 2 * 9.8) / 3.0, rel=1e-6)


def test_heavier_m2_moves_the_other_way():
    result = values(solve(1.0, 3.0, Pulley(2.0), 9.8))
    assert result["a"] == pytest.approx(-2 * 9.8 / 5)
    assert result["T1"] == pytest.approx(1.0 * (9.8 + 2 * 9.8 / 5))


def test_distance_and_time_from_rest():
    result = values(solve(4.0, 1.0, Pulley(2.0), 9.8, distance=1.0, time=2.0))
    assert result["t"] == pytest.approx(math.sqrt(2 / 4.9))
    assert result["distance"] == pytest.approx(0.5 * 4.9 * 4)


def test_thrown_upward_it_stops_and_comes_back():
    """v0 = −4.9 m/s (m1 going up) with a = +4.9: stops after 1 s, back through the start at 2 s."""
    result = values(solve(4.0, 1.0, Pulley(2.0), 9.8, v0=-4.9, time=2.0))
    assert result["distance"] == pytest.approx(0.0, abs=1e-12)
    assert result["v"] == pytest.approx(4.9)


@pytest.mark.parametrize(
    "args,fragment",
    [
        (dict(m1=0.0, m2=0.0, pulley=Pulley()), "cannot both be zero"),
        (dict(m1=1.0, m2=1.0, pulley=Pulley(1.0, 0.1, None, 0.01)), "--pulley-inertia"),
        (dict(m1=1.0, m2=1.0, pulley=Pulley(0.0, None, None, 0.01)), "--pulley-radius is required"),
        (dict(m1=1.0, m2=1.0, pulley=Pulley(0.0, None, None, None, 0.1)), "--pulley-radius is required"),
        (dict(m1=1.0, m2=1.0, pulley=Pulley(1.0, 0.1, "cone")), "--pulley-shape"),
        (dict(m1=1.0, m2=1.0, pulley=Pulley(), slope=Slope(math.radians(95))), "--incline"),
        (dict(m1=1.0, m2=1.0, pulley=Pulley(), slope=Slope(HANGING, 0.2)), "--mu-k applies"),
        (dict(m1=1.0, m2=1.0, pulley=Pulley(), slope=Slope(0.3, 0.5, 0.2)), "--mu-k must not exceed"),
    ],
)
def test_impossible_machines_are_input_errors(args, fragment):
    with pytest.raises(InputError) as caught:
        solve(g=9.8, **args)
    assert fragment in str(caught.value)


@settings(max_examples=200, deadline=None)
@given(m2=st.floats(0.01, 100), gap=st.integers(1, 50), pulley_mass=st.one_of(st.just(0.0), masses))
def test_near_equal_masses_keep_full_precision(m2, gap, pulley_mass):
    """m1 = m2(1 + 2^-gap): a within 4 ulp of the 50-digit value of (m1 − m2)g/(m1 + m2 + M/2).

    Measured over 5,000 cases: at most 1.5 ulp. Writing the drive as m1 g − m2 g instead loses up
    to gap bits (it failed this test from gap = 4).
    """
    m1 = m2 * (1 + 2.0**-gap)
    a = values(solve(m1, m2, Pulley(pulley_mass), 9.80665))["a"]
    with mpmath.workdps(50):
        exact = (mpmath.mpf(m1) - m2) * mpmath.mpf(9.80665) / (mpmath.mpf(m1) + m2 + mpmath.mpf(pulley_mass) / 2)
    assert abs(mpmath.mpf(a) - exact) <= 4 * abs(exact) * mpmath.mpf(2) ** -52
