"""drive --segment: a motor's duty cycle (#47 item 3). Reference from the heating it stands for,
in mpmath: the motor's loss goes as the square of its load, so the steady load that heats it as
much over the cycle is the root of the time-weighted mean square, a standstill's time counted
1/k of itself (--rest-factor k); integrated here as a piecewise-constant load by mpmath.quad."""

from __future__ import annotations

import random

import mpmath
import pytest

import taucli
from conftest import assert_usage_error


def _rms(loads, times, rests, k):
    edges = [mpmath.mpf(0)]
    for t in times:
        edges.append(edges[-1] + t)
    heat = sum(mpmath.quad(lambda _: mpmath.mpf(load) ** 2, [a, b]) for load, a, b in zip(loads, edges, edges[1:]))
    weighted = sum(mpmath.mpf(t) / (k if rest else 1) for t, rest in zip(times, rests))
    return mpmath.sqrt(heat / weighted)


@pytest.mark.parametrize("seed", range(3))
def test_random_duty_cycles(seed):
    rng = random.Random(4790 + seed)
    for _ in range(10):
        count = rng.randint(2, 6)
        by = rng.choice(["torque", "power"])
        loads = [rng.choice([0.0, rng.uniform(-50, 200)]) for _ in range(count)]
        times = [rng.uniform(1, 600) for _ in range(count)]
        rests = [load == 0 and rng.random() < 0.5 for load in loads]
        k = rng.choice([1, 3, 4])
        unit = "N*m" if by == "torque" else "kW"
        segments = [f"time={t}s {by}={load}{unit}" + (" rest=yes" if rest else "") for load, t, rest in zip(loads, times, rests)]
        results = taucli.drive(segment=segments, rest_factor=k).results
        factor = 1 if by == "torque" else 1000
        exact = _rms([load * factor for load in loads], times, rests, k)
        assert results[f"{by}_rms"].value == pytest.approx(float(exact), rel=1e-12, abs=1e-300)
        assert results["t_cycle"].value == pytest.approx(sum(times), rel=1e-14)


def test_a_motor_rated_against_its_duty():
    results = taucli.drive(segment=["time=10min power=100kW", "time=5min power=0 rest=yes", "time=8min power=50kW"], rest_factor=3,
                           rated_power="60 kW").results
    exact = _rms([100e3, 0, 50e3], [600, 300, 480], [False, True, False], 3)
    assert results["power_rms"].value == pytest.approx(float(exact), rel=1e-13)
    assert results["rms_to_rated"].value == pytest.approx(float(exact) / 60e3, rel=1e-13)


def test_units_do_not_change_the_rms():
    si = taucli.drive(segment=["time=600s power=74569.987158227022W", "time=300s power=0"]).results["power_rms"].value  # 100 hp = 550 ft·lbf/s
    other = taucli.drive(segment=["time=10min power=100hp", "time=5min power=0hp"]).results["power_rms"].value
    assert other == pytest.approx(si, rel=1e-12)


def test_refusals(taucli):
    assert_usage_error(taucli("drive", "--segment", "time=10min"), "--segment", "torque=")
    assert_usage_error(taucli("drive", "--segment", "time=10min torque=2N*m", "--segment", "time=1min power=1kW"), "--segment")
    assert_usage_error(taucli("drive", "--segment", "time=10min torque=2N*m", "--ratio", "3"), "--ratio", "--segment")
    assert_usage_error(taucli("drive", "--segment", "time=10min torque=2N*m", "--rest-factor", "0.5"), "--rest-factor")
    assert_usage_error(taucli("drive", "--segment", "time=10min torque=2N*m rest=maybe"), "--segment")
    assert_usage_error(taucli("drive", "--rest-factor", "3", "--load-inertia", "1kg*m^2"), "--rest-factor", "--segment")
