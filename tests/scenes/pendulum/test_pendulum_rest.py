"""#42 item 12: a pendulum at rest at the bottom, under gravity, a torsion spring or both.

It stays at the bottom: ω_bottom = 0, KE_bottom = 0, t_bottom = 0, and its period is the limit of
a swing's as the amplitude goes to 0, that of small swings, T₀ = 2π√(I/(mgd + κ)) (the linearised
equation I θ'' = −(mgd + κ)θ), the same for every method. The reference is that formula in
mpmath, written here from the equation of motion, not read from taucli.
"""

from __future__ import annotations

import json

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taucli
from conftest import run_taucli

METHODS = ("auto", "exact", "euler", "rk4", "rk45", "verlet", "small-angle")
G = 9.80665


def small_period(inertia, mass, d, kappa, g=G) -> float:
    mpmath.mp.dps = 40
    return float(2 * mpmath.pi * mpmath.sqrt(mpmath.mpf(inertia) / (mpmath.mpf(mass) * g * mpmath.mpf(d) + mpmath.mpf(kappa))))


def values(report) -> dict:
    return {name: value.value for name, value in report.results.items()}


@pytest.mark.parametrize("method", METHODS)
def test_the_issues_pendulum_at_rest_with_a_spring_has_its_small_swing_period_in_every_method(method):
    got = values(taucli.pendulum(inertia=1, mass="1 kg", cm_distance="0.5 m", torsion="1 N*m/rad", method=method, angle="0 deg"))
    assert got["omega_bottom"] == 0 and got["KE_bottom"] == 0 and got["t_bottom"] == 0
    assert got["omega"] == 0 and got["t_angle"] == 0
    assert got["period"] == pytest.approx(small_period(1, 1, 0.5, 1), rel=1e-12)
    assert got["period"] == pytest.approx(2.586, abs=5e-4)  # the issue's hand value


@settings(max_examples=30, deadline=None)
@given(extra=st.floats(0.01, 100), mass=st.floats(0.1, 50), d=st.floats(0.01, 2), kappa=st.floats(0.01, 100),
       gravity=st.booleans(), spring=st.booleans())
def test_at_rest_at_the_bottom_every_body_stays_with_its_small_swing_period(extra, mass, d, kappa, gravity, spring):
    inertia = extra + mass * d * d  # I about the pivot = I_cm + Md²
    if not gravity and not spring:
        spring = True
    kwargs = dict(inertia=inertia)
    if gravity:
        kwargs.update(mass=mass, cm_distance=d)
    if spring:
        kwargs.update(torsion=kappa)
    got = values(taucli.pendulum(**kwargs))
    expected = small_period(inertia, mass if gravity else 0, d if gravity else 0, kappa if spring else 0)
    assert got["omega_bottom"] == 0 and got["KE_bottom"] == 0
    assert got["period"] == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("method", METHODS)
def test_at_rest_with_a_spring_the_json_is_written_and_its_notes_say_nothing_of_a_top(method):
    run = run_taucli("pendulum", "--inertia", "1", "--mass", "1kg", "--cm-distance", "0.5m", "--torsion", "1N*m/rad", "--method", method, "--json")
    assert run.code == 0, run.err
    document = json.loads(run.out)
    assert document["results"]["omega_bottom"]["value"] == 0
    assert document["results"]["KE_bottom"]["value"] == 0
    assert document["results"]["period"]["value"] == pytest.approx(small_period(1, 1, 0.5, 1), rel=1e-12)
    assert not any("top" in note for note in document["notes"]), document["notes"]
