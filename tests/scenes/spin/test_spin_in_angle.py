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


@pytest.mark.parametrize("losses", [("--friction", "1", "--viscous", "0.001"), ("--drag", "0.001"), ("--viscous", "0.01")])
def test_an_angle_against_the_motion_is_refused_with_losses(losses):
    """#42 item 9: from −300 rpm to −100 rpm the speed stays negative under any constant drive (ω(t) is
    monotonic), so the wheel cannot have turned +10 rev: refused as the lossless path refuses, not
    answered with the search's bound (1 N·m) or a drive of 1e-59 N·m."""
    result = run_taucli("spin-down", "--inertia", "2", "--omega0", "-300rpm", "--until-omega", "-100rpm", "--in-angle", "10rev", *losses)
    assert_usage_error(result, "--in-angle", "the mean speed must turn the wheel that way")


def test_an_angle_with_the_motion_backwards_with_losses_is_the_physics():
    """The same turned the way it goes, −10 rev: with ω < 0, I ω dω/dθ = τ + f − bω, so
    θ(τ) = ∫ I ω / (τ + f − bω) dω from ω₀ to ω₁; the drive is the τ at which θ = −20π rad."""
    inertia, friction, viscous = mpmath.mpf(2), mpmath.mpf(1), mpmath.mpf("0.001")
    w0, w1 = -10 * mpmath.pi, -10 * mpmath.pi / 3

    def angle(tau):
        return mpmath.quad(lambda w: inertia * w / (tau + friction - viscous * w), [w0, w1]) + 20 * mpmath.pi

    tau = mpmath.findroot(angle, 10)
    r = values(taucli.spin_down(inertia=2, omega0="-300 rpm", until_omega="-100 rpm", in_angle="-10 rev", friction=1, viscous=0.001))
    assert r["torque"] == pytest.approx(float(tau), rel=1e-9)
