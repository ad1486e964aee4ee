"""flywheel from a turning-moment diagram (#47 item 4): --loops with the diagram's scales, a
press's motor power, the speed band as rim speeds.

The reference builds a real diagram from the loops: each loop a half-sine hump of the torque
about the mean line, T(θ) − T_mean = ±A sin(π(θ − θ₀)/w) over its width w, with A = area·π/(2w)
so that its area is the loop's; the flywheel's energy E(θ) = ∫(T − T_mean)dθ is integrated by
mpmath.quad at the loops' ends and inside them, and ΔE = max E − min E."""

from __future__ import annotations

import random

import mpmath
import pytest

import taucli
from conftest import assert_usage_error


def _swing_of_the_diagram(areas, torque_scale, angle_scale):
    per_mm2 = mpmath.mpf(torque_scale) * mpmath.mpf(angle_scale)
    widths = [mpmath.mpf(1) + abs(mpmath.mpf(a)) ** 0.5 for a in areas]  # any widths: the energy depends on the areas alone
    humps = []
    start = mpmath.mpf(0)
    for area, width in zip(areas, widths):
        humps.append((start, width, mpmath.mpf(area) * mpmath.pi / (2 * width)))
        start += width

    def torque(theta):
        for begin, width, height in humps:
            if begin <= theta <= begin + width:
                return height * mpmath.sin(mpmath.pi * (theta - begin) / width)
        return mpmath.mpf(0)

    points = [mpmath.mpf(0)]
    for begin, width, _ in humps:
        points += [begin + width * k / 8 for k in range(1, 9)]
    energy, values, last = mpmath.mpf(0), [mpmath.mpf(0)], mpmath.mpf(0)
    for point in points[1:]:
        energy += mpmath.quad(torque, [last, point])
        values.append(energy)
        last = point
    return (max(values) - min(values)) * per_mm2


def test_khurmi_petrol_engine():
    """Khurmi & Gupta, Theory of Machines, ex. 16.x: scales 1 mm = 5 N·m and 1 mm = 1°; loops 295, 685,
    40, 340, 960, 270 mm² above and below the mean line in turn; 36 kg at a radius of gyration of
    150 mm, 1800 rpm. The book: ΔE ≈ 86 N·m, Cs ≈ 0.003."""
    results = taucli.flywheel(loops="295,-685,40,-340,960,-270", scale_torque="5 N*m", scale_angle="1 deg", mass="36 kg", gyration="150 mm",
                              omega_mean="1800 rpm").results
    exact = 985 * 5 * mpmath.pi / 180
    assert results["energy_swing"].value == pytest.approx(float(exact), rel=1e-14)
    assert round(results["cs"].value, 3) == 0.003


@pytest.mark.parametrize("seed", range(3))
def test_random_diagrams_against_the_integrated_curve(seed):
    rng = random.Random(4740 + seed)
    for _ in range(8):
        areas = [round(rng.uniform(5, 900), 1) * (1 if k % 2 == 0 else -1) for k in range(rng.randint(2, 7))]
        areas.append(round(-sum(areas), 6))  # the cycle closes
        torque_scale, angle_scale_deg = rng.uniform(0.5, 50), rng.uniform(0.5, 4)
        swing = taucli.flywheel(loops=",".join(repr(a) for a in areas), scale_torque=f"{torque_scale} N*m", scale_angle=f"{angle_scale_deg} deg",
                                inertia="2 kg*m^2", omega_mean="600 rpm").results["energy_swing"].value
        exact = _swing_of_the_diagram(areas, torque_scale, mpmath.radians(angle_scale_deg))
        assert swing == pytest.approx(float(exact), rel=1e-10), areas


def test_loops_that_do_not_close_are_noted():
    report = taucli.flywheel(loops="100,-50", scale_torque="1 N*m", scale_angle="1 rad", inertia="1 kg*m^2", omega_mean="100 rad/s")
    assert any("not 0" in note for note in report.notes)
    assert report.results["energy_swing"].value == pytest.approx(100.0)


def test_press_motor_power_and_the_rim_band():
    """A press takes 26.7 kJ per cycle of 3 s: the motor supplies 8.9 kW; a rim band 30 and 29 m/s has
    Cs = 1/29.5 and the mean 29.5 m/s: a rim that swings 5 kJ has m = ΔE/(v²Cs)."""
    press = taucli.flywheel(energy_per_cycle="26.7 kJ", punch_fraction=0.16, cycle_time="3 s", omega_mean="300 rpm", fluctuation=0.1).results
    assert press["power_motor"].value == pytest.approx(8900.0, rel=1e-14)
    rim = taucli.flywheel(rim_speed_max="30 m/s", rim_speed_min="29 m/s", energy_swing="5 kJ").results
    assert rim["cs"].value == pytest.approx(1 / 29.5, rel=1e-14)
    assert rim["mass"].value == pytest.approx(5000 / (29.5**2 * (1 / 29.5)), rel=1e-12)  # ΔE = mv²Cs
    banded = taucli.flywheel(rim_speed_max="30 m/s", rim_speed_min="29 m/s", inertia="50 kg*m^2", rim_radius="0.5 m").results
    assert banded["omega_mean"].value == pytest.approx(59.0, rel=1e-14)
    assert banded["energy_swing"].value == pytest.approx(0.5 * 50 * ((30 / 0.5) ** 2 - (29 / 0.5) ** 2), rel=1e-12)


def test_units_do_not_change_the_diagram():
    si = taucli.flywheel(loops="295,-685,40,-340,960,-270", scale_torque="5 N*m", scale_angle="1 deg", inertia="0.81 kg*m^2", omega_mean="1800 rpm")
    other = taucli.flywheel(loops="295,-685,40,-340,960,-270", scale_torque=f"{5 / 1.3558179483314004} lbf*ft", scale_angle="0.0174532925199432957 rad",
                            inertia="0.81 kg*m^2", omega_mean="30 Hz")
    assert other.results["energy_swing"].value == pytest.approx(si.results["energy_swing"].value, rel=1e-12)


def test_refusals(taucli):
    assert_usage_error(taucli("flywheel", "--loops", "295,-685", "--scale-torque", "5N*m", "--inertia", "1kg*m^2", "--omega-mean", "300rpm"), "--scale-angle")
    assert_usage_error(taucli("flywheel", "--loops", "295,abc", "--scale-torque", "5N*m", "--scale-angle", "1deg", "--inertia", "1kg*m^2",
                              "--omega-mean", "300rpm"), "--loops")
    assert_usage_error(taucli("flywheel", "--scale-torque", "5N*m", "--inertia", "1kg*m^2", "--omega-mean", "300rpm", "--fluctuation", "0.02"), "--scale-torque")
    assert_usage_error(taucli("flywheel", "--cycle-time", "3s", "--inertia", "1kg*m^2", "--omega-mean", "300rpm", "--fluctuation", "0.02"), "--cycle-time")
    assert_usage_error(taucli("flywheel", "--rim-speed-max", "30m/s", "--inertia", "1kg*m^2", "--fluctuation", "0.02"), "--rim-speed")
