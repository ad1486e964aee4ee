"""A rope over a drum that cannot turn (atwood --fixed-drum, #35): held within e^{±μs β}, sliding
with the capstan ratio e^{μk β} beyond. References from the physics at 50 digits (the rope's
tension grown element by element with mpmath.odefun, the masses' equations solved with
mpmath.findroot); the energy balance and the boundary's continuity as properties; a published
problem with its printed answers."""

from __future__ import annotations

import math

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taucli
from conftest import assert_usage_error, run_taucli

G = 9.80665


def values(report):
    return {name: value.value for name, value in report.results.items()}


def sliding_reference(m1, m2, mu, wrap, sense, g=G):
    """(a, T₁, T₂) sliding: the slack side's tension grown along the wrap by dT = μ T dφ
    (mpmath.odefun), and each mass's Newton's law, m₁g − T₁ = m₁a and T₂ − m₂g = m₂a, solved for
    (a, T_slack) with mpmath.findroot."""
    m1, m2, mu, wrap, g = (mpmath.mpf(x) for x in (m1, m2, mu, wrap, g))
    grow = mpmath.odefun(lambda phi, t: mu * t, 0, 1)(wrap)  # T_tight/T_slack
    if sense > 0:  # m₁ down: side 1 tight
        a, slack = mpmath.findroot(lambda a, t: [m1 * g - grow * t - m1 * a, t - m2 * g - m2 * a], (0, m2 * g))
        return a, grow * slack, slack
    a, slack = mpmath.findroot(lambda a, t: [m1 * g - t - m1 * a, grow * t - m2 * g - m2 * a], (0, m1 * g))
    return a, slack, grow * slack


@pytest.mark.parametrize(("wrap", "printed"), [("180deg", 1.31e3), ("540deg", 372)])
def test_cylinder_held_by_a_cord_over_a_pipe_hibbeler(wrap, printed):
    """Hibbeler, Engineering Mechanics: Statics (ch. 8, frictional forces on flat belts): a 250 kg
    cylinder held by a cord over a fixed pipe, μs = 0.2; the smallest force that supports it with
    the cord once over the pipe (β = 180°) and twice (β = 540°). Printed: 1.31 kN and 372 N. Here
    the force is the weight of the least m₂ that holds, found from rim_mu_min = 0.2."""
    report = taucli.atwood(m1="250kg", fixed_drum=True, rim_mu=0.2, wrap=wrap, find="m2", want="rim_mu_min=0.2")
    force = report.results["m2"].value * G
    assert force == pytest.approx(printed, rel=5e-3)
    assert force == pytest.approx(250 * G * math.exp(-0.2 * math.radians(float(wrap[:-3]))), rel=1e-12)


@pytest.mark.parametrize(("m1", "m2"), [(250, 100), (40, 90), (3, 2.8)])
def test_sliding_against_the_rope_elements(m1, m2):
    result = values(taucli.atwood(m1=f"{m1}kg", m2=f"{m2}kg", fixed_drum=True, mu_s=0.01, mu_k=0.01, wrap="200deg"))
    a, tension1, tension2 = sliding_reference(m1, m2, 0.01, math.radians(200), 1 if m1 > m2 else -1)
    assert result["holds"] is False
    assert result["a"] == pytest.approx(float(a), rel=1e-13)
    assert result["T1"] == pytest.approx(float(tension1), rel=1e-13)
    assert result["T2"] == pytest.approx(float(tension2), rel=1e-13)


def test_held_tensions_are_the_weights():
    report = taucli.atwood(m1="120kg", m2="100kg", fixed_drum=True, mu_s=0.3, mu_k=0.2)
    result = values(report)
    assert result["holds"] is True and result["a"] == 0
    assert (result["T1"], result["T2"]) == (pytest.approx(120 * G, rel=1e-15), pytest.approx(100 * G, rel=1e-15))
    assert result["rim_mu_min"] == pytest.approx(math.log(1.2) / math.pi, rel=1e-15)


def test_static_holds_where_kinetic_would_not_and_only_mu_s_leaves_sliding_null():
    """μs = 0.3 holds 120/100 (ln 1.2/π = 0.058); μk alone is taken as μs (noted); a sliding rope
    with only μs given has no a (null, noted)."""
    held = values(taucli.atwood(m1="120kg", m2="100kg", fixed_drum=True, mu_s=0.3, mu_k=0.01))
    assert held["holds"] is True
    only_kinetic = taucli.atwood(m1="120kg", m2="100kg", fixed_drum=True, mu_k=0.01)
    assert only_kinetic.results["holds"].value is False and any("static friction taken as equal" in n for n in only_kinetic.notes)
    only_static = taucli.atwood(m1="300kg", m2="100kg", fixed_drum=True, mu_s=0.1)
    assert only_static.results["a"].value is None and any("needs mu_k" in n for n in only_static.notes)


@settings(max_examples=50, deadline=None)
@given(m1=st.floats(0.1, 1000), m2=st.floats(0.1, 1000), mu=st.sampled_from([0.0]) | st.floats(1e-6, 1.0), wrap=st.floats(0.1, 20), distance=st.floats(0.01, 10))
def test_energy_balance_while_sliding(m1, m2, mu, wrap, distance):
    """Property: over a distance d slid from rest, ½(m₁ + m₂)v² = |m₁ − m₂|·g·d − (T_tight − T_slack)·d
    (the friction's work is the tension it takes off times the rope slid over the drum); held: nothing moves."""
    result = values(taucli.atwood(m1=m1, m2=m2, fixed_drum=True, rim_mu=mu, wrap=f"{wrap!r}rad", distance=distance))
    if result["holds"]:
        assert result["a"] == 0 and abs(math.log(m1 / m2)) <= mu * wrap * (1 + 1e-12)
        return
    v = result["v"]
    friction = abs(result["T1"] - result["T2"]) * distance
    kinetic = 0.5 * (m1 + m2) * v * v
    assert kinetic == pytest.approx(abs(m1 - m2) * G * distance - friction, rel=1e-9, abs=1e-9 * (m1 + m2) * G * distance)


@settings(max_examples=40, deadline=None)
@given(m2=st.floats(1, 100), wrap=st.floats(0.5, 10), excess=st.floats(1e-9, 1e-3))
def test_boundary_is_continuous(m2, wrap, excess):
    """Just past the capstan limit (μk = μs), a slides from 0: a → 0 and the tensions → the weights."""
    mu = 0.2
    m1 = m2 * math.exp(mu * wrap) * (1 + excess)
    result = values(taucli.atwood(m1=m1, m2=m2, fixed_drum=True, rim_mu=mu, wrap=f"{wrap!r}rad"))
    assert result["holds"] is False
    assert 0 < result["a"] <= G * 2 * excess
    assert result["T2"] == pytest.approx(m2 * G, rel=4 * excess)


def test_set_moving_against_the_heavier_side_stops_then_slides_back():
    """--v0 upward for the heavy m₁: it slides with the up-sense acceleration, stops, and (not held) slides back."""
    result = values(taucli.atwood(m1="300kg", m2="100kg", fixed_drum=True, rim_mu=0.1, v0="-2m/s"))
    a_up = float(sliding_reference(300, 100, 0.1, math.pi, -1)[0])
    assert result["a"] == pytest.approx(a_up, rel=1e-13)
    assert result["t_stop"] == pytest.approx(2 / a_up, rel=1e-13)


@pytest.mark.parametrize(
    ("args", "fragments"),
    [
        (["--m1", "2kg", "--m2", "1kg", "--fixed-drum"], ["--fixed-drum", "--rim-mu"]),
        (["--m1", "2kg", "--m2", "1kg", "--fixed-drum", "--rim-mu", "0.2", "--mu-k", "0.1"], ["--mu-k", "--rim-mu"]),
        (["--m1", "2kg", "--m2", "1kg", "--fixed-drum", "--rim-mu", "0.2", "--pulley-mass", "1kg"], ["--pulley-mass", "--fixed-drum"]),
        (["--m1", "2kg", "--m2", "0kg", "--fixed-drum", "--rim-mu", "0.2"], ["--m2"]),
        (["--m1", "2kg", "--fixed-drum", "--rim-mu", "0.2"], ["--m2"]),
        (["--m1", "2kg", "--m2", "1kg", "--fixed-drum", "--rim-mu", "0.2", "--pulley-radius", "5cm"], ["--pulley-radius", "--fixed-drum"]),
        (["--m1", "2kg", "--m2", "1kg", "--fixed-drum", "--rim-mu", "0.2", "--at", "rim"], ["--at", "--fixed-drum"]),
    ],
)
def test_refusals(args, fragments):
    assert_usage_error(run_taucli("atwood", *args), *fragments)
