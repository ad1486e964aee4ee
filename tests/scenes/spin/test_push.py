"""#31 item 8: a given torque and a push at a lever act on one axle and add (a drive and a push,
or a load torque and a push: a judo throw), in spin-down and in impulse, both shown in the steps.
Today's code refused --torque beside --force and --lever."""

from __future__ import annotations

import math

import pytest

from conftest import run_taucli


def test_spin_down_adds_a_load_torque_and_a_push():
    done = run_taucli("spin-down", "--inertia", "0.1kg*m^2", "--torque", "-1N*m", "--force", "6N", "--lever", "0.25m", "--time", "2s", "--json")
    assert done.code == 0, done.err
    doc = done.json()
    drive = -1 + 6 * 0.25  # N·m, the two torques about one axle
    assert doc["results"]["alpha0"]["value"] == pytest.approx(drive / 0.1, rel=1e-15)
    assert doc["results"]["omega"]["value"] == pytest.approx(drive / 0.1 * 2, rel=1e-15)
    equations = [step["equation"] for step in doc["steps"]]
    assert "τ = F r" in equations and "τ_drive = τ + F r sin φ" in equations


def test_a_push_at_an_angle_adds_its_share_only():
    done = run_taucli("spin-down", "--inertia", "2", "--torque", "3N*m", "--force", "10N", "--lever", "0.5m", "--push-angle", "30deg", "--get", "alpha0")
    assert done.code == 0, done.err
    assert float(done.out) == pytest.approx((3 + 10 * 0.5 * math.sin(math.radians(30))) / 2, rel=1e-14)


def test_impulse_adds_a_torque_and_a_push():
    done = run_taucli("impulse", "--inertia", "0.1kg*m^2", "--torque", "2N*m", "--force", "4N", "--lever", "0.5m", "--duration", "0.5s", "--json")
    assert done.code == 0, done.err
    results = done.json()["results"]
    assert results["torque"]["value"] == pytest.approx(4.0, rel=1e-15)
    assert results["omega1"]["value"] == pytest.approx((2 + 4 * 0.5) * 0.5 / 0.1, rel=1e-15)
    assert results["J"]["value"] == pytest.approx(2.0, rel=1e-15)


def test_a_push_alone_is_still_the_drive():
    done = run_taucli("impulse", "--inertia", "0.1", "--force", "4N", "--lever", "0.5m", "--duration", "0.5s", "--get", "omega1")
    assert done.code == 0, done.err
    assert float(done.out) == pytest.approx(4 * 0.5 * 0.5 / 0.1, rel=1e-15)
