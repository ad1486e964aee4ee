"""Angular momentum at the target (#48 item 6): L = Iω where ω is reported, at a time, an angle or
a speed. Reference: a constant friction torque τ_f on I from ω₀: ω(θ) = √(ω₀² − 2τ_fθ/I)."""

from __future__ import annotations

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taucli


@settings(max_examples=40, deadline=None)
@given(st.floats(0.1, 100), st.floats(10, 1000), st.floats(0.01, 10), st.floats(0.05, 0.9))
def test_l_at_an_angle_is_i_omega_there(inertia, omega0, friction, share):
    stop = mpmath.mpf(inertia) * omega0**2 / (2 * mpmath.mpf(friction))  # θ at the stop: ½Iω₀² = τθ
    angle = share * stop
    omega = mpmath.sqrt(mpmath.mpf(omega0) ** 2 - 2 * mpmath.mpf(friction) * angle / inertia)
    report = taucli.spin_down(inertia=inertia, omega0=f"{omega0!r} rad/s", friction=friction, until_angle=f"{float(angle)!r} rad")
    assert report.results["L"].value == pytest.approx(float(inertia * omega), rel=1e-9)


def test_l_at_a_time_and_none_without_a_body():
    report = taucli.spin_down(inertia="2 kg*m^2", omega0="300rpm", friction="1 N*m", time="5s")
    assert report.results["L"].value == pytest.approx(2 * (10 * float(mpmath.pi) - 0.5 * 5), rel=1e-14)
    assert "L" not in taucli.spin_down(omega0="300rpm", alpha="-1 rad/s^2", time="2s").results  # kinematics alone: no I
