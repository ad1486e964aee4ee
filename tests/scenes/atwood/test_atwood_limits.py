"""#42 items 5 and 13: atwood's --distance past the point where the masses turn back, and m2's
surface given with no m2.

References are written from the physics: under a constant acceleration a (m1 downward positive)
from a velocity v0, m1's displacement is s(t) = v0 t + a t²/2; where v0 and a have opposite signs
the masses stop at s* = −v0²/(2a), and a displacement beyond s* on that side is never reached.
"""

from __future__ import annotations

import json

import mpmath
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import taucli
from conftest import assert_usage_error, run_taucli
from taucli.core.errors import InputError


# Item 13: a surface for m2 with no m2 ------------------------------------------------------------

@pytest.mark.parametrize("surface", [{"incline": "30deg"}, {"incline": "30deg", "mu_k": 0.2}, {"mu_k": 0.2}, {"mu_s": 0.3}])
def test_a_surface_for_m2_without_m2_is_refused_in_python(surface):
    with pytest.raises(InputError):
        taucli.atwood(m1="2 kg", **surface)


@pytest.mark.parametrize("args, option", [(["--incline", "30deg", "--mu-k", "0.2"], "--incline"), (["--mu-k", "0.2"], "--mu-k"),
                                          (["--mu-s", "0.3"], "--mu-s")])
def test_a_surface_for_m2_without_m2_is_refused_naming_the_fix(args, option):
    assert_usage_error(run_taucli("atwood", "--m1", "2kg", *args), option, "--m2")


# Item 5: --distance past where the masses turn back ---------------------------------------------

G = 9.80665


def hanging_reference(m1, m2, v0, distance, r1=None, r2=None):
    """(t, v) after m1 has moved ``distance`` along the way it first moves, or None where the masses
    stop short of it; with steps r1, r2 (m1 on r1): a1 = g (m1 r1 − m2 r2) r1 / (m1 r1² + m2 r2²)."""
    mpmath.mp.dps = 40
    m1, m2, v0, d = (mpmath.mpf(x) for x in (m1, m2, v0, distance))
    if r1 is None:
        a = G * (m1 - m2) / (m1 + m2)
    else:
        r1, r2 = mpmath.mpf(r1), mpmath.mpf(r2)
        a = G * (m1 * r1 - m2 * r2) * r1 / (m1 * r1**2 + m2 * r2**2)
    sense = mpmath.sign(v0) if v0 else mpmath.sign(a)
    u, acc = abs(v0), sense * a  # along the way it first moves
    if acc < 0 and d > u * u / (-2 * acc):
        return None
    t = (-u + mpmath.sqrt(u * u + 2 * acc * d)) / acc if acc else d / u
    return float(t), float(sense * (u + acc * t))


def test_the_issues_machine_never_travels_2_m_and_says_it_turns_back():
    report = taucli.atwood(m1="1 kg", m2="2 kg", v0="3 m/s", distance="2 m")
    assert report.results["t"].value is None and report.results["v"].value is None
    note = next(note for note in report.notes if "never travel 2 m" in note)
    assert "turn back" in note and "1.37662 m" in note  # v0²/2|a| = 9/(2·9.80665/3) = 1.37662 m


@settings(max_examples=60, deadline=None)
@given(m1=st.floats(0.1, 20), m2=st.floats(0.1, 20), v0=st.floats(-10, 10).filter(lambda v: v == 0 or abs(v) > 1e-6), distance=st.floats(0.01, 20), stepped=st.booleans(),
       r1=st.floats(0.05, 0.5), r2=st.floats(0.05, 0.5))
def test_after_distance_is_along_the_first_way_or_null_where_they_turn_back(m1, m2, v0, distance, stepped, r1, r2):
    kwargs = dict(m1=m1, m2=m2, v0=v0, distance=distance)
    if stepped:
        kwargs.update(radius1=r1, radius2=r2)
    balance = (m1 * r1 - m2 * r2) if stepped else (m1 - m2)
    assume(abs(balance) > 1e-6 * (m1 + m2))  # a machine in balance from rest never moves (another test's)
    expected = hanging_reference(m1, m2, v0, distance, *((r1, r2) if stepped else ()))
    report = taucli.atwood(**kwargs)
    t, v = report.results["t"].value, report.results["v"].value
    if expected is None:
        assert t is None and v is None
        assert any("never travel" in note for note in report.notes)
    else:
        assert t == pytest.approx(expected[0], rel=1e-9, abs=1e-12)
        assert v == pytest.approx(expected[1], rel=1e-9, abs=1e-9)


@pytest.mark.parametrize("layout", [dict(rim_mu=0.3), dict(fixed_drum=True, rim_mu=0.01), dict(radius1="0.1 m", radius2="0.2 m"),
                                    dict(side1="table mu-k=0.3"), dict(pulley_mass="1 kg"), dict(axle_friction="0.05 N*m", pulley_radius="0.1 m"),
                                    dict(pulley_radius="0.1 m", at="0.1 m")])
def test_every_layout_gives_null_past_the_stop(layout):
    """In every model and layout with --distance: a distance beyond the stop (which each reports
    with --v0) is never reached: t and v are null, with the note."""
    report = taucli.atwood(m1="1 kg", m2="2 kg", v0="3 m/s", distance="50 m", **layout)
    assert report.results["distance_stop"].value is not None and 0 < abs(report.results["distance_stop"].value) < 50
    assert report.results["t"].value is None and report.results["v"].value is None
    assert any("never travel 50 m" in note and ("turn back" in note or "stay there" in note) for note in report.notes), report.notes


def test_past_the_stop_the_cli_prints_nulls_and_exits_0():
    run = run_taucli("atwood", "--m1", "1kg", "--m2", "2kg", "--v0", "3m/s", "--distance", "2m", "--json")
    assert run.code == 0, run.err
    results = json.loads(run.out)["results"]
    assert results["t"]["value"] is None and results["v"]["value"] is None
