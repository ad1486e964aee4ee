"""Assumptions never silent (issue #9): every result that rests on something the user did not say
(g's value, no slip, the pulley's shape, Hz read as rev/s) says so in its notes; once the user
says it, the note goes.
"""

from __future__ import annotations

import json

import pytest

from conftest import run_taucli


def notes(*args: str) -> list[str]:
    result = run_taucli(*args, "--json", "--no-steps")
    assert result.code == 0, result.err
    return result.json()["notes"]


def mentions(found: list[str], fragment: str) -> bool:
    return any(fragment in note for note in found)


@pytest.mark.parametrize(
    "args",
    [
        ("atwood", "--m1", "4kg", "--m2", "1kg"),
        ("rolling", "sphere", "--angle", "30deg", "--length", "2m"),
        ("rolling", "sphere", "--v0", "7m/s", "--mu-k", "0.2"),
    ],
    ids=["atwood", "rolling incline", "rolling skid"],
)
def test_standard_gravity_is_stated_unless_g_is_given(args):
    assert mentions(notes(*args), "g = 9.80665 m/s² (standard gravity)")
    assert not mentions(notes(*args, "--g", "9.8"), "standard gravity")


def test_the_pulley_shape_default_is_stated_unless_given():
    given = ("atwood", "--m1", "4kg", "--m2", "1kg", "--pulley-mass", "2kg", "--g", "9.8")
    assert mentions(notes(*given), "pulley taken as a uniform solid disc")
    assert not mentions(notes(*given, "--pulley-shape", "disc"), "taken as a uniform")
    assert not mentions(notes("atwood", "--m1", "4kg", "--m2", "1kg", "--g", "9.8"), "pulley taken")  # no pulley mass, no shape


def test_no_slip_is_stated_wherever_an_answer_rests_on_it():
    # The string on a pulley that has inertia: a = αR.
    assert mentions(notes("atwood", "--m1", "4kg", "--m2", "1kg", "--pulley-mass", "2kg", "--pulley-shape", "ring"), "not to slip on the pulley")
    # A body on a slope with no μs given is assumed to roll, with the μs that needs.
    assert mentions(notes("rolling", "sphere", "--angle", "30deg"), "assumed to roll without slipping, which needs μs ≥ μ_min = 0.164957")
    given = notes("rolling", "sphere", "--angle", "30deg", "--mu-s", "0.5")
    assert not mentions(given, "assumed to roll")


@pytest.mark.parametrize(
    "args,option",
    [
        (("spin-down", "--inertia", "1", "--omega0", "10Hz", "--friction", "1"), "--omega0 10Hz"),
        (("impulse", "--inertia", "1", "--omega0", "1Hz", "--omega1", "2Hz", "--duration", "1s"), "--omega1 2Hz"),
        (("impulse", "--inertia", "1", "--omega0", "1rad/s", "--torque", "1", "--duration", "1", "--to", "omega1=Hz"), "--to Hz"),
        (("spin-down", "--inertia", "1", "--omega0", "2Hz,2Hz", "--friction", "1"), "--omega0 2Hz"),
    ],
    ids=["an input", "another input", "--to", "a sweep"],
)
def test_hz_read_as_revolutions_per_second_is_stated(args, option):
    result = run_taucli(*args, "--json", "--no-steps")
    assert result.code == 0, result.err
    documents = result.json() if isinstance(result.json(), list) else [result.json()]
    for document in documents:
        assert mentions(document["notes"], f"{option}: Hz read as revolutions per second")


def test_hz_is_stated_in_a_batch_line_too():
    result = run_taucli("spin-down", "--batch", "--no-steps", stdin=json.dumps({"inertia": "1", "omega0": "5Hz", "friction": "1"}) + "\n")
    assert mentions(json.loads(result.out)["notes"], "omega0 5Hz: Hz read as revolutions per second")  # batch names keys (#42 item 19)


def test_rpm_and_rad_per_s_need_no_note():
    assert not mentions(notes("spin-down", "--inertia", "1", "--omega0", "300rpm", "--friction", "1"), "Hz")
