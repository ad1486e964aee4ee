"""A centrifugal clutch (#48 item 5): --centrifugal "shoes= mass= radius= spring-force= mu=
drum-radius=" in spin-down and impulse, read at ω₀. References from the physics at 50 digits:
the engagement speed is the root of the shoe's radial balance m·ω²·r − S = 0 (found by
mpmath.findroot, not the square root the solver takes), the torque the friction of n shoes at the
drum. Published problems, the same answers from the command line, batch and
Python, and every key's refusals.
"""

from __future__ import annotations

import json
import math

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taucli
from conftest import assert_usage_error, run_taucli
from taucli.answering.contact_specs import CENTRIFUGAL_FIELDS

# A textbook problem of the kind Khurmi and Gupta's Theory of Machines sets (ch. 10, centrifugal
# clutches), as worked at bissoy.com/mcq/380116: four shoes, each pulled against its stop by a
# spring of 700 N with a radial clearance of 10 mm, spring stiffness 75 N/mm, the shoe's mass centre 150 mm from the axis at rest, the rim 500 mm
# across, 6 kg shoes, μ = 0.35; "find the power transmitted by the clutch at 400 r.p.m.". At
# contact the shoe's centre is at r₁ = 150 + 10 = 160 mm and the spring pulls 700 + 10 × 75 =
# 1450 N. The worked answer: Pc = 1684.58 N, F = μ(Pc − Ps) = 82.1 N, T = 82.1 N·m,
# P = 3.439 kW (with ω rounded to 41.89 rad/s).
KHURMI = "shoes=4 mass=6kg radius=160mm spring-force=1450N mu=0.35 drum-radius=250mm"


def values(report):
    return {name: value.value for name, value in report.results.items()}


def reference(shoes, mass, radius, spring, mu, drum, omega):
    """(ω_e, τ) from the shoe's radial balance: the drum pushes back with N = m·ω²·r − S once
    positive; ω_e is where that balance first holds with N = 0 (a root, found numerically)."""
    with mpmath.workdps(50):
        return _reference(shoes, mass, radius, spring, mu, drum, omega)


def _reference(shoes, mass, radius, spring, mu, drum, omega):
    shoes, mass, radius, spring, mu, drum, omega = (mpmath.mpf(x) for x in (shoes, mass, radius, spring, mu, drum, omega))
    balance = lambda w: mass * w**2 * radius - spring  # noqa: E731  (centrifugal force less the spring's pull)
    engage = mpmath.findroot(balance, mpmath.sqrt(spring / (mass * radius)) * mpmath.mpf("1.1")) if spring else mpmath.mpf(0)
    normal = max(balance(abs(omega)), 0)
    return engage, shoes * mu * normal * drum


def test_khurmi_power_transmitted_at_400_rpm():
    result = values(taucli.spin_down(omega0="400rpm", centrifugal=KHURMI))
    omega = 400 * 2 * mpmath.pi / 60
    engage, torque = reference(4, 6, "0.16", 1450, "0.35", "0.25", omega)
    assert result["omega_engage"] == pytest.approx(float(engage), rel=1e-14)
    assert result["torque_centrifugal"] == pytest.approx(float(torque), rel=1e-14)
    assert result["power_centrifugal"] == pytest.approx(float(torque * omega), rel=1e-14)
    assert result["torque_centrifugal"] == pytest.approx(82.1, abs=0.1)  # the book's 82.1 N·m
    assert result["power_centrifugal"] == pytest.approx(3439, abs=5)  # the book's 3.439 kW, its ω rounded to 41.89 rad/s


def test_three_shoes_start_to_move():
    """Three shoes of 5 kg, each held by a residual spring tension of 200 N, their centres 0.2 m
    out: they begin to move out at m·ω²·R = 200 N, ω = √200 = 14.14 rad/s, 135 rev/min (a
    textbook problem, worked at brainmass.com/physics/rotation/centrifugal-clutch-223190)."""
    run = run_taucli("spin-down", "--centrifugal", "shoes=3 mass=5kg radius=0.2m spring-force=200N mu=0.3 drum-radius=0.2m",
                     "--get", "omega_engage", "--to", "omega_engage=rpm")
    assert run.code == 0, run.err
    assert float(run.out) == pytest.approx(float(mpmath.sqrt(200) * 60 / (2 * mpmath.pi)), rel=1e-14)
    assert round(float(run.out)) == 135


def test_the_clutch_is_reported_beside_the_motion_not_applied_to_it():
    """With a body and its own torques, the motion is the same as without the clutch; the clutch's
    results come first, with a note saying it is not applied."""
    plain = taucli.spin_down(inertia="2kg*m^2", omega0="400rpm", friction="10N*m", time="2s")
    both = taucli.spin_down(inertia="2kg*m^2", omega0="400rpm", friction="10N*m", time="2s", centrifugal=KHURMI)
    for key, value in plain.results.items():
        assert both.results[key].value == value.value, key
    assert list(both.results)[:3] == ["omega_engage", "torque_centrifugal", "power_centrifugal"]
    assert any("not applied" in note for note in both.notes)
    struck = taucli.impulse(inertia="2kg*m^2", omega0="400rpm", torque="10N*m", duration="2s", centrifugal=KHURMI)
    assert values(struck)["torque_centrifugal"] == values(both)["torque_centrifugal"]
    assert values(struck)["omega1"] == pytest.approx(400 * math.pi / 30 + 10, rel=1e-14)


def test_below_engagement_no_torque_and_no_speed_no_torque():
    slow = taucli.spin_down(omega0="300rpm", centrifugal=KHURMI)
    assert values(slow)["torque_centrifugal"] == 0.0 and values(slow)["power_centrifugal"] == 0.0
    assert any("not above the engagement speed" in note for note in slow.notes)
    unknown = run_taucli("spin-down", "--centrifugal", KHURMI, "--json")
    assert unknown.code == 0, unknown.err
    document = unknown.json()
    assert document["results"]["torque_centrifugal"]["value"] is None
    assert document["results"]["omega_engage"]["value"] == pytest.approx(math.sqrt(1450 / (6 * 0.16)), rel=1e-15)
    assert any("--omega0" in note for note in document["notes"])


@settings(max_examples=40, deadline=None)
@given(shoes=st.integers(1, 8), mass=st.floats(0.05, 20), radius=st.floats(0.01, 0.5), gap=st.sampled_from([0.0]) | st.floats(1e-4, 0.1), spring=st.sampled_from([0.0]) | st.floats(1e-3, 5e3),
       mu=st.sampled_from([0.0]) | st.floats(1e-3, 0.8), ratio=st.sampled_from([0.0, 1.0]) | st.floats(1e-3, 3))
def test_against_the_shoe_balance(shoes, mass, radius, gap, spring, mu, ratio):
    """Property: at any speed (below, near and above engagement) the torque is the reference's."""
    drum = radius + gap
    engage = math.sqrt(spring / (mass * radius))
    omega = engage * ratio if spring else ratio * 50
    spec = f"shoes={shoes} mass={mass!r}kg radius={radius!r}m spring-force={spring!r}N mu={mu!r} drum-radius={drum!r}m"
    result = values(taucli.spin_down(omega0=f"{omega!r} rad/s", centrifugal=spec))
    ref_engage, ref_torque = reference(shoes, mass, radius, spring, mu, drum, omega)
    assert result["omega_engage"] == pytest.approx(float(ref_engage), rel=1e-13, abs=1e-300)
    assert result["torque_centrifugal"] == pytest.approx(float(ref_torque), rel=1e-9, abs=1e-12 * spring * mu * drum * shoes)


def test_just_above_engagement_keeps_its_digits():
    """N = m·r·(ω − ω_e)(ω + ω_e): 1e-9 above engagement, the torque is still right to 1e-6 (m·ω²·r − S
    formed as a difference would lose 9 of its 16 digits)."""
    engage = math.sqrt(1450 / (6 * 0.16))
    omega = engage * (1 + 1e-9)
    result = values(taucli.spin_down(omega0=f"{omega!r} rad/s", centrifugal=KHURMI))
    _, torque = reference(4, 6, "0.16", 1450, "0.35", "0.25", mpmath.mpf(omega))
    assert result["torque_centrifugal"] == pytest.approx(float(torque), rel=1e-6)


def test_command_line_batch_and_python_agree():
    python = values(taucli.impulse(omega0="400rpm", centrifugal=KHURMI))
    line = run_taucli("impulse", "--batch", stdin=json.dumps({"omega0": "400rpm", "centrifugal": KHURMI}) + "\n")
    assert line.code == 0 and line.json()["results"]["torque_centrifugal"]["value"] == python["torque_centrifugal"]
    cli = run_taucli("impulse", "--omega0", "400rpm", "--centrifugal", KHURMI, "--get", "power_centrifugal")
    assert cli.code == 0 and float(cli.out) == pytest.approx(python["power_centrifugal"], rel=1e-14)


def test_a_shoe_mass_is_solved_for():
    """--find centrifugal.mass: the shoe mass that passes 100 N·m at 400 rpm, N = τ/(nμR), m = (N + S)/(ω²r)."""
    report = taucli.spin_down(omega0="400rpm", centrifugal="shoes=4 radius=160mm spring-force=1450N mu=0.35 drum-radius=250mm",
                              find="centrifugal.mass", want="torque_centrifugal=100N*m")
    omega = 400 * 2 * mpmath.pi / 60
    mass = (100 / (4 * mpmath.mpf("0.35") * mpmath.mpf("0.25")) + 1450) / (omega**2 * mpmath.mpf("0.16"))
    assert report.results["centrifugal.mass"].value == pytest.approx(float(mass), rel=1e-10)


# Each key: left out, of the wrong kind, and out of its range, refused with exit 2, one line naming the key.
WRONG_KIND = {"shoes": "4kg", "mass": "6m", "radius": "160N", "spring_force": "1450m", "mu": "0.35m", "drum_radius": "250N"}
OUT_OF_RANGE = {"shoes": "0", "mass": "-6kg", "radius": "0m", "spring_force": "-1N", "mu": "-0.35", "drum_radius": "-250mm"}


def _spec(**changes):
    fields = dict(pair.split("=") for pair in KHURMI.split())
    for key, text in changes.items():
        flag = key.replace("_", "-")
        if text is None:
            fields.pop(flag)
        else:
            fields[flag] = text
    return " ".join(f"{key}={text}" for key, text in fields.items())


def test_every_key_is_covered():
    assert set(WRONG_KIND) == set(OUT_OF_RANGE) == set(CENTRIFUGAL_FIELDS)


@pytest.mark.parametrize("scene", ["spin-down", "impulse"])
@pytest.mark.parametrize("key", sorted(CENTRIFUGAL_FIELDS))
def test_each_key_refused_left_out_wrong_or_out_of_range(scene, key):
    flag = key.replace("_", "-")
    for spec, fragments in ((_spec(**{key: None}), ["--centrifugal", f"needs {flag}="]),
                            (_spec(**{key: WRONG_KIND[key]}), ["--centrifugal", f"{flag}="]),
                            (_spec(**{key: OUT_OF_RANGE[key]}), ["--centrifugal", f"{flag}="])):
        assert_usage_error(run_taucli(scene, "--omega0", "400rpm", "--centrifugal", spec), *fragments)


@pytest.mark.parametrize(
    ("spec", "fragments"),
    [
        (_spec(shoes="4.5"), ["--centrifugal", "shoes=", "whole number"]),
        (_spec(radius="300mm"), ["--centrifugal", "radius=", "drum-radius="]),
        (KHURMI + " colour=red", ["--centrifugal", "knows", "drum-radius"]),
        ("4 6kg", ["--centrifugal", "key=value"]),
    ],
)
def test_refusals(spec, fragments):
    assert_usage_error(run_taucli("spin-down", "--omega0", "400rpm", "--centrifugal", spec), *fragments)
