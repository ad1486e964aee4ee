"""#42 item 6: a pendulum balanced exactly on the top falls one way, said in a note: toward
--angle (θ decreasing to a positive angle, increasing to a negative one), else the way θ
decreases; ω at --angle is signed so, and a_t (along the motion) is positive: it speeds up all
the way to the bottom, as from a start a hair off the top.

The reference is energy and the torque, written here in mpmath for a rod of length L about its
end: I = mL²/3, d = L/2, ½Iω² = mgd(1 + cos θ) (from the top), α = −mgd sin θ / I, a_t = r|α|
while it speeds up.
"""

from __future__ import annotations

import json
import math

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taucli
from conftest import run_taucli

G = 9.80665


def reference(length, theta, r, g=G):
    """(|ω|, a_t along the fall) at θ of a rod of length L falling from rest on the top."""
    mpmath.mp.dps = 40
    length, theta, r = mpmath.mpf(length), mpmath.mpf(theta), mpmath.mpf(r)
    inertia, d = length**2 / 3, length / 2  # per unit mass
    speed = mpmath.sqrt(2 * g * d * (1 + mpmath.cos(theta)) / inertia)
    return float(speed), float(r * g * d * abs(mpmath.sin(theta)) / inertia)


def values(report) -> dict:
    return {name: value.value for name, value in report.results.items()}


def test_the_issues_rod_from_the_top_speeds_up_at_145_degrees():
    run = run_taucli("pendulum", "--shape", "rod", "--axis", "end", "--length", "55m", "--mass", "1kg", "--angle0", "180deg", "--angle", "145deg",
                     "--at", "55m", "--json")
    assert run.code == 0, run.err
    document = json.loads(run.out)
    speed, a_t = reference(55, math.radians(145), 55)
    assert document["results"]["omega"]["value"] == pytest.approx(-speed, rel=1e-12)  # falling toward 145°: θ decreases
    assert document["results"]["a_t"]["value"] == pytest.approx(a_t, rel=1e-12)  # +8.4373 m/s²: it speeds up
    assert any("taken to fall toward θ = 145°" in note for note in document["notes"]), document["notes"]


@settings(max_examples=40, deadline=None)
@given(length=st.floats(0.1, 100), degrees=st.floats(-179, 179).filter(lambda x: abs(x) > 1e-3), fraction=st.floats(0.05, 1),
       start=st.sampled_from([180.0, -180.0]))
def test_from_the_top_the_signs_are_those_of_a_start_a_hair_off_it_on_the_side_of_angle(length, degrees, fraction, start):
    body = dict(shape="rod", axis="end", length=length, mass=1, at=fraction * length, angle=f"{degrees!r} deg")
    top = values(taucli.pendulum(**body, angle0=f"{start} deg"))
    speed, a_t = reference(length, math.radians(degrees), fraction * length)
    sense = -1 if degrees > 0 else 1  # toward --angle
    assert top["omega"] == pytest.approx(sense * speed, rel=1e-9)
    assert top["a_t"] == pytest.approx(a_t, rel=1e-9, abs=1e-12)
    hair = values(taucli.pendulum(**body, angle0=f"{math.copysign(180 - 1e-7, degrees)!r} deg"))  # just off the top, on --angle's side
    assert math.copysign(1, hair["omega"]) == math.copysign(1, top["omega"])
    assert hair["a_t"] == pytest.approx(top["a_t"], rel=1e-5, abs=1e-9)


def test_with_no_angle_the_note_says_it_falls_the_way_theta_decreases():
    report = taucli.pendulum(shape="rod", axis="end", length="1 m", mass="1 kg", angle0="180 deg")
    assert any("the way θ decreases" in note for note in report.notes), report.notes


def test_find_angle_from_the_top_gives_roots_where_the_fall_speeds_up_at_that_rate():
    report = taucli.pendulum(shape="rod", axis="end", length="55 m", mass="1 kg", angle0="180 deg", at="55 m", find="angle", want="a_t=9.80m/s^2")
    mpmath.mp.dps = 40
    inertia, d = mpmath.mpf(55) ** 2 / 3, mpmath.mpf(55) / 2
    first = mpmath.asin(mpmath.mpf("9.80") * inertia / (55 * G * d))  # r g d sin θ / I = a_t
    expected = sorted(float(x) for x in (first, mpmath.pi - first, -first, first - mpmath.pi))
    assert sorted(report.results["roots"].value) == pytest.approx(expected, rel=1e-10)
    assert report.results["a_t"].value == pytest.approx(9.80, rel=1e-10)
    angle = report.results["angle"].value
    assert any(abs(angle - x) < 1e-9 for x in expected)
    assert math.copysign(1, report.results["omega"].value) == (-1 if angle > 0 else 1)  # toward the angle found


@pytest.mark.parametrize("method", ["exact", "euler", "rk4", "rk45", "verlet", "small-angle"])
def test_every_method_gives_the_same_signs_from_the_top(method):
    got = values(taucli.pendulum(shape="rod", axis="end", length="55 m", mass="1 kg", angle0="180 deg", angle="145 deg", at="55 m", method=method))
    speed, a_t = reference(55, math.radians(145), 55)
    assert got["omega"] == pytest.approx(-speed, rel=1e-12)
    assert got["a_t"] == pytest.approx(a_t, rel=1e-12)


def test_find_angle_from_the_top_gives_the_first_angle_of_the_fall():
    """#42 item 6: a rod on its end falling from the top, a_t = (3g/2) sin θ at its tip: a_t = 9.80
    at sin θ = 9.80/(1.5 g), four angles in a turn (±41.8°, ±138.2°). The fall from 180° meets
    138.2° first (41.8° from the top); --find gave 41.8°, a point it reaches later (−41.8° before
    the fall had a direction)."""
    g = mpmath.mpf("9.80665")
    first = float(mpmath.pi - mpmath.asin(mpmath.mpf("9.80") / (mpmath.mpf("1.5") * g)))
    report = taucli.pendulum(shape="rod", axis="end", length="55m", mass="1kg", angle0="180deg", find="angle", want="a_t=9.80m/s^2", at="55m")
    assert report.results["angle"].value == pytest.approx(first, rel=1e-12)
    assert sorted(abs(r) for r in report.results["roots"].value) == pytest.approx(sorted([first, first, math.pi - first, math.pi - first]), rel=1e-12)
    assert any("the first the motion reaches is the result" in note for note in report.notes)
