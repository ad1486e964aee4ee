"""#34 item 1: reach a speed within an angle, `--until-omega` with `--in-angle`: the constant α
(ω₁² = ω₀² + 2αθ) and with a body the drive torque against the stated losses, and the time.
References from the physics, by hand and in mpmath."""

from __future__ import annotations

import math

import mpmath
import pytest

import taucli
from conftest import assert_usage_error, run_taucli

MP_DPS = 40


def values(report):
    return {key: value.value for key, value in report.results.items()}


def test_bring_a_disc_to_120_rpm_in_20_turns():
    """A 10 kg, 0.3 m disc from rest to 120 rpm within 20 revolutions: α = ω₁²/(2θ) = π/5 rad/s²,
    τ = ½MR²α, t = 2θ/ω₁ = 20 s."""
    r = values(taucli.spin_down(shape="disc", mass="10 kg", radius="0.3 m", until_omega="120 rpm", in_angle="20 rev"))
    omega1, theta = 4 * math.pi, 40 * math.pi
    alpha = omega1**2 / (2 * theta)
    assert r["alpha"] == pytest.approx(alpha, rel=1e-14)
    assert r["torque"] == pytest.approx(0.5 * 10 * 0.09 * alpha, rel=1e-14)
    assert r["t_until"] == pytest.approx(2 * theta / omega1, rel=1e-14)


def test_stop_a_wheel_in_ten_revolutions_against_friction_and_a_viscous_torque():
    """I = 2, ω₀ = 300 rpm, τ_f = 1 N·m, b = 0.05 N·m·s, to rest within 10 rev: with c = τ_f − τ,
    θ(c) = (I/b)[ω₀ − (c/b) ln(1 + bω₀/c)] = 20π, solved for c; t = (I/b) ln(1 + bω₀/c)."""
    i, w0, f, b, theta = map(mpmath.mpf, (2, 10 * mpmath.pi, 1, "0.05", 20 * mpmath.pi))
    turned = lambda c: i / b * (w0 - c / b * mpmath.log(1 + b * w0 / c))  # noqa: E731
    c = mpmath.findroot(lambda c: turned(c) - theta, 14)
    r = values(taucli.spin_down(inertia=2, omega0="300 rpm", friction="1 N*m", viscous="0.05 N*m*s", until_omega=0, in_angle="10 rev"))
    assert r["torque"] == pytest.approx(float(f - c), rel=1e-12)
    assert r["t_until"] == pytest.approx(float(i / b * mpmath.log(1 + b * w0 / c)), rel=1e-10)


def test_without_a_body_it_is_kinematics():
    r = values(taucli.spin_down(omega0="100 rpm", until_omega="500 rpm", in_angle="50 rev"))
    w0, w1, theta = 100 * math.pi / 30, 500 * math.pi / 30, 100 * math.pi
    assert r["alpha"] == pytest.approx((w1**2 - w0**2) / (2 * theta), rel=1e-14)


def test_in_angle_needs_its_target_and_no_drive():
    assert_usage_error(run_taucli("spin-down", "--inertia", "1", "--in-angle", "10rev"), "--in-angle needs --until-omega")
    assert_usage_error(run_taucli("spin-down", "--inertia", "1", "--until-omega", "0", "--in-angle", "10rev", "--torque", "1"), "--in-angle")
    assert_usage_error(run_taucli("spin-down", "--inertia", "1", "--until-omega", "0", "--in-angle", "10rev", "--time", "1s"), "--time conflicts with --in-angle")
