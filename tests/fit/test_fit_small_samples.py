"""Small samples (#44 item 13): a 95 % interval from Student's t where σ comes from the scatter,
and --scale-covariance (the covariance scaled by χ²/ν with σ given, lmfit's default).

References from the physics and the textbook straight line, not from taucli: a coast under a
constant friction torque is ω(t) = ω₀ − (τ/I)t, a straight line whose weighted least squares and
standard errors are written out in mpmath (Taylor, An Introduction to Error Analysis, §8.3).
"""

from __future__ import annotations

import io
import random

import mpmath
import pytest

from taucli.fit import command
from tests.conftest import assert_usage_error, run_taucli

INERTIA = 0.1


def _fit(rows, sigma=None, *, scale_covariance=False, column_sigma=False):
    header = "t (s),omega (rad/s)" + (",u (rad/s)" if column_sigma else "")
    text = header + "\n" + "".join(",".join(repr(float(v)) for v in row) + "\n" for row in rows)
    more = {"scale_covariance": True} if scale_covariance else {}
    return command.fitted("spin-down", ["-"], {"inertia": f"{INERTIA} kg*m^2"}, fit="friction,omega0", sigma=sigma, stdin=io.StringIO(text), **more)


def test_student_t_95_intervals_cover_95_percent_of_small_samples():
    """Five samples (ν = 3): ±1.96σ would cover about 86 %; t·σ (t = 3.182) covers 95 %."""
    rng = random.Random(44)
    tau, omega0, noise, trials = 0.06, 30.0, 0.05, 300
    covered = {"friction": 0, "omega0": 0}
    normal = 0
    for _ in range(trials):
        rows = [(t, omega0 - tau / INERTIA * t + rng.gauss(0, noise)) for t in range(5)]
        report = _fit(rows)
        for name, truth in (("friction", tau), ("omega0", omega0)):
            value, half = report.results[name].value, report.results[f"{name}_ci95"].value
            covered[name] += abs(value - truth) <= half
        normal += abs(report.results["friction"].value - tau) <= 1.96 * report.uncertainties["friction"]
    for name, count in covered.items():
        assert 0.92 * trials <= count <= 0.98 * trials, (name, count / trials)
    assert normal < 0.91 * trials, normal / trials  # the normal's interval is too short with ν = 3: the t's is what covers
    assert "ν = 3" in report.results["friction_ci95"].label


def _line(rows, sigmas):
    """The weighted straight line y = a + bt (mpmath): (a, b), their covariance (JᵀWJ)⁻¹, and χ²."""
    w = [1 / mpmath.mpf(s) ** 2 for s in sigmas]
    S = mpmath.fsum(w)
    Sx = mpmath.fsum(wi * t for wi, (t, _) in zip(w, rows))
    Sy = mpmath.fsum(wi * y for wi, (_, y) in zip(w, rows))
    Sxx = mpmath.fsum(wi * t * t for wi, (t, _) in zip(w, rows))
    Sxy = mpmath.fsum(wi * t * y for wi, (t, y) in zip(w, rows))
    delta = S * Sxx - Sx**2
    a, b = (Sxx * Sy - Sx * Sxy) / delta, (S * Sxy - Sx * Sy) / delta
    chi2 = mpmath.fsum(wi * (y - a - b * t) ** 2 for wi, (t, y) in zip(w, rows))
    return a, b, Sxx / delta, S / delta, chi2


def test_scale_covariance_gives_the_weighted_line_scaled_by_chi2():
    """σᵢ given per sample: without --scale-covariance, σ(ω₀) = √(Σwt²/Δ); with it, × √(χ²/ν); ω₀ and τ = −Ib unchanged."""
    mpmath.mp.dps = 30
    rng = random.Random(7)
    sigmas = [0.02, 0.05, 0.03, 0.08, 0.04, 0.06]
    rows = [(t, 30.0 - 0.6 * t + rng.gauss(0, 3 * s)) for t, s in enumerate(sigmas)]  # scatter 3× the σ given: χ²/ν near 9
    a, b, var_a, var_b, chi2 = _line(rows, sigmas)
    dof = len(rows) - 2
    plain = _fit([(*row, s) for row, s in zip(rows, sigmas)], "u", column_sigma=True)
    scaled = _fit([(*row, s) for row, s in zip(rows, sigmas)], "u", column_sigma=True, scale_covariance=True)
    for report, factor in ((plain, 1), (scaled, chi2 / dof)):
        assert report.results["omega0"].value == pytest.approx(float(a), rel=1e-9)
        assert report.results["friction"].value == pytest.approx(float(-INERTIA * b), rel=1e-9)
        assert report.uncertainties["omega0"] == pytest.approx(float(mpmath.sqrt(var_a * factor)), rel=1e-6)
        assert report.uncertainties["friction"] == pytest.approx(float(INERTIA * mpmath.sqrt(var_b * factor)), rel=1e-6)
    assert "friction_ci95" not in plain.results  # σ given, not scaled: the normal's 1.96σ, no t
    assert scaled.results["friction_ci95"].value == pytest.approx(float(mpmath.sqrt(var_b * chi2 / dof)) * INERTIA * 2.7764451051977987, rel=1e-6)
    assert "scaled by χ²/ν" in scaled.method


def test_scale_covariance_is_in_the_options_table_and_refused_without_sigma(tmp_path):
    path = tmp_path / "coast.csv"
    path.write_text("t (s),omega (rad/s)\n0,30\n1,29.4\n2,28.8\n3,28.2\n", encoding="utf-8")
    assert "--scale-covariance" in run_taucli("fit", "--help").out
    assert_usage_error(run_taucli("fit", "spin-down", str(path), "--inertia", "0.1kg*m^2", "--fit", "friction,omega0", "--scale-covariance"),
                       "--scale-covariance: scales the covariance by χ²/ν where --sigma gives")
