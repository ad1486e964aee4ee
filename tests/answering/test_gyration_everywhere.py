"""#42 item 15: a body by its radius of gyration (I = Mk²) wherever a body is given: flywheel,
gyro with --precession, rolling (k² = I/(mR²) = (k/R)²), atwood's pulley (--pulley-gyration).

References from the physics, written here by hand:
- the gyroscopic couple on a rotor whose axis turns at Ω: C = IωΩ, I = Mk²;
- a flywheel's energy swing ΔE = Iω²Cs;
- a body rolling down a slope: a = g sin θ/(1 + k²/R²);
- an Atwood machine: a = (m1 − m2)g/(m1 + m2 + I/R²)."""

from __future__ import annotations

import mpmath
import pytest
from conftest import assert_usage_error, run_taucli

mpmath.mp.dps = 40
G = mpmath.mpf("9.80665")


def got(*args: str) -> float:
    run = run_taucli(*args)
    assert run.code == 0, run.err
    return float(run.out)


def test_gyro_precession_takes_a_rotor_by_its_radius_of_gyration():
    # 400 kg at k = 0.3 m spinning at 2400 rpm, turned at 0.5 rad/s: C = Mk²ωΩ
    want = 400 * mpmath.mpf("0.3") ** 2 * (2400 * 2 * mpmath.pi / 60) * mpmath.mpf("0.5")
    assert got("gyro", "--mass", "400kg", "--gyration", "0.3m", "--spin", "2400rpm", "--precession", "0.5rad/s", "--get", "couple") == pytest.approx(float(want), rel=1e-12)


def test_flywheel_takes_its_radius_of_gyration():
    # ΔE = Mk²ω²Cs, ω = 300 rpm
    want = 500 * mpmath.mpf("0.6") ** 2 * (300 * 2 * mpmath.pi / 60) ** 2 * mpmath.mpf("0.02")
    assert got("flywheel", "--mass", "500kg", "--gyration", "0.6m", "--omega-mean", "300rpm", "--fluctuation", "0.02", "--get", "energy_swing") == pytest.approx(
        float(want), rel=1e-12)


def test_rolling_takes_its_radius_of_gyration_with_its_radius():
    want = G * mpmath.sin(mpmath.pi / 6) / (1 + (mpmath.mpf("0.07") / mpmath.mpf("0.1")) ** 2)
    assert got("rolling", "--gyration", "0.07m", "--radius", "0.1m", "--angle", "30deg", "--get", "a") == pytest.approx(float(want), rel=1e-12)
    assert_usage_error(run_taucli("rolling", "--gyration", "0.07m", "--angle", "30deg"), "--radius")


def test_atwoods_pulley_takes_its_radius_of_gyration():
    inertia = 2 * mpmath.mpf("0.08") ** 2
    want = (4 - 1) * G / (4 + 1 + inertia / mpmath.mpf("0.1") ** 2)
    args = ("atwood", "--m1", "4kg", "--m2", "1kg", "--pulley-radius", "0.1m", "--pulley-gyration", "0.08m")
    assert got(*args, "--pulley-mass", "2kg", "--get", "a") == pytest.approx(float(want), rel=1e-12)
    assert_usage_error(run_taucli(*args), "--pulley-mass")
    assert_usage_error(run_taucli(*args, "--pulley-mass", "2kg", "--pulley-inertia", "0.1kg*m^2"), "--pulley-inertia")
