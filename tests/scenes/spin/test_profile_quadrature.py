"""#32 item 1: a torque profile sampled unevenly. Simpson's rule takes samples in pairs of
intervals and fits a parabola through three; over t = 0, 0.002, 0.5, 0.502, 1.0 s the parabolas
overshoot, and auto (Simpson) gave J = 43.2 N·m·s where |τ| ≤ 2 N·m makes |J| ≤ 2 N·m·s.
Every J printed must lie between the least and the largest torque times Δt."""

from __future__ import annotations

import math
import random

import pytest

import taucli

TIMES = (0.0, 0.002, 0.5, 0.502, 1.0)


def _csv(tmp_path, times, torques) -> str:
    path = tmp_path / "profile.csv"
    path.write_text("t [s], torque [N*m]\n" + "".join(f"{t!r}, {f!r}\n" for t, f in zip(times, torques)))
    return str(path)


def _trapezoid(times, torques) -> float:
    return math.fsum((b - a) * (fa + fb) / 2 for a, b, fa, fb in zip(times, times[1:], torques, torques[1:]))


def test_auto_takes_the_trapezoid_rule_on_uneven_samples_and_says_why(tmp_path):
    torques = (2.0, -2.0, 2.0, -2.0, 2.0)
    report = taucli.impulse(inertia=1, torque_profile=_csv(tmp_path, TIMES, torques))
    assert report.results["J"].value == pytest.approx(_trapezoid(TIMES, torques), abs=1e-15)
    assert any("unevenly spaced" in note for note in report.notes)


def test_simpson_asked_for_is_withheld_where_it_leaves_what_the_samples_allow(tmp_path):
    report = taucli.impulse(inertia=1, torque_profile=_csv(tmp_path, TIMES, (2.0, -2.0, 2.0, -2.0, -2.0)), method="simpson")
    assert report.results["J"].value is None and report.results["omega1"].value is None
    assert any("J withheld" in note for note in report.notes)


def test_every_j_lies_within_the_least_and_largest_torque_times_the_duration(tmp_path):
    rng = random.Random(32)
    for _ in range(200):
        count = rng.randint(3, 9)
        times = sorted({0.0, *(rng.random() ** rng.choice((1, 4)) for _ in range(count - 1))})
        torques = [rng.uniform(-2, 2) for _ in times]
        if len(times) < 3:
            continue
        value = taucli.impulse(inertia=1, torque_profile=_csv(tmp_path, times, torques)).results["J"].value
        span = times[-1] - times[0]
        assert min(torques) * span - 1e-12 <= value <= max(torques) * span + 1e-12


def test_evenly_spaced_smooth_samples_still_take_simpson(tmp_path):
    times = [k / 10 for k in range(11)]
    torques = [math.sin(t) for t in times]
    report = taucli.impulse(inertia=1, torque_profile=_csv(tmp_path, times, torques))
    assert report.method == "simpson"
    assert report.results["J"].value == pytest.approx(1 - math.cos(1.0), rel=1e-5)  # Simpson's h⁴ error at h = 0.1
