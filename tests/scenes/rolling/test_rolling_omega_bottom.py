"""ω at the bottom of a slope (#48 item 1): `rolling --help` lists omega and says --radius is
"needed only for α and ω"; ω = v/R rolling, and R·ω from the friction's spin-up while it slides.
References from the physics in mpmath: energy for the rolling body, Newton's laws for the sliding one."""

from __future__ import annotations

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taucli

G = mpmath.mpf("9.80665")
K2 = {"sphere": mpmath.mpf(2) / 5, "disc": mpmath.mpf(1) / 2, "ring": mpmath.mpf(1), "shell": mpmath.mpf(2) / 3}


def rolling_omega(k2, angle_deg, length, radius):
    """mgL sin θ = ½mv²(1 + k²), v = ωR."""
    theta = mpmath.radians(angle_deg)
    v = mpmath.sqrt(2 * G * length * mpmath.sin(theta) / (1 + k2))
    return v / radius, v


def sliding_omega(k2, angle_deg, length, radius, mu_k):
    """a = g(sin θ − μk cos θ) down the slope; the friction μk·mg cos θ spins it up: α = μk g cos θ/(k²R)."""
    theta = mpmath.radians(angle_deg)
    a = G * (mpmath.sin(theta) - mu_k * mpmath.cos(theta))
    t = mpmath.sqrt(2 * length / a)
    return mu_k * G * mpmath.cos(theta) / (k2 * radius) * t


def test_the_issue_s_sphere():
    omega, v = rolling_omega(K2["sphere"], 30, 2, mpmath.mpf("0.1"))
    report = taucli.rolling("sphere", angle="30deg", length="2m", radius="0.1m", mass="1kg")
    assert report.results["omega"].value == pytest.approx(float(omega), rel=1e-13)
    assert report.results["KE_rot"].value == pytest.approx(float(K2["sphere"] * v**2 / 2), rel=1e-13)


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(sorted(K2)), st.floats(5, 80), st.floats(0.1, 50), st.floats(0.01, 2), st.booleans())
def test_omega_at_the_bottom_rolling_or_sliding(shape, angle, length, radius, by_height):
    """Rolling (μs large) and sliding (μs = μk small), by the slope's length or its height."""
    rolling, _ = rolling_omega(K2[shape], angle, length, radius)
    where = {"height": f"{length * float(mpmath.sin(mpmath.radians(angle)))!r} m"} if by_height else {"length": f"{length!r} m"}
    report = taucli.rolling(shape, angle=f"{angle!r} deg", radius=f"{radius!r} m", mu_s=5, **where)
    assert report.results["omega"].value == pytest.approx(float(rolling), rel=1e-10)
    mu_k = 0.3 * float(mpmath.tan(mpmath.radians(angle))) * float(K2[shape] / (1 + K2[shape]))  # below μ_min: it slides
    sliding = taucli.rolling(shape, angle=f"{angle!r} deg", radius=f"{radius!r} m", mu_s=mu_k, mu_k=mu_k, length=f"{length!r} m")
    assert sliding.results["rolls"].value is False
    assert sliding.results["omega"].value == pytest.approx(float(sliding_omega(K2[shape], angle, length, radius, mu_k)), rel=1e-10)
