"""gyro --vehicle: a vehicle on a turn (#47 item 5). The reference is written here with vectors in
mpmath, not the books' scalar couples: in the vehicle's frame (x forward, y left, z up) turning
left at Ω = v/R, each rotor's angular momentum L = I ω (ŷ for a wheel rolling forward, ω × (−r ẑ)
= −v x̂) is turned, dL/dt = Ω ẑ × L; the road's forces supply it and the centrifugal force's
moment, taken about the centre of gravity (four wheels) or the contact point (two)."""

from __future__ import annotations

import math
import random

import mpmath
import pytest

import taucli
from conftest import assert_usage_error

G = mpmath.mpf("9.80665")


def _cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def _rotors_rate(wheels, wheel_inertia, engine_inertia, ratio, v, r, turn):
    """dL/dt of every rotor, as a vector: the road wheels roll (ω_w ŷ, ω_w = v/r), the engine turns ratio times as fast."""
    spin = v / r
    total = [0, wheels * wheel_inertia * spin + engine_inertia * ratio * spin, 0]
    return _cross([0, 0, v / turn], total)


def _four_wheeler(m, h, x, I_w, I_e, ratio, r, v, turn):
    """Loads per wheel: N_in + N_out = mg (each side), and about the x axis through the centre of
    gravity the normal forces (±x/2 ŷ) and the road's grip m v²/R ŷ at −h ẑ give dL/dt."""
    rate = _rotors_rate(4, I_w, I_e, ratio, v, r, turn)[0]
    grip = _cross([0, 0, -h], [0, m * v * v / turn, 0])[0]
    # (x/2)(N_in − N_out) + grip = rate
    difference = (rate - grip) * 2 / x
    inner_side, outer_side = (m * G + difference) / 2, (m * G - difference) / 2
    return inner_side / 2, outer_side / 2


def _lean(m, h, I_w, I_e, ratio, r, v, turn):
    """About the contact point, in the turning frame: the weight at the leaning centre of gravity, the
    centrifugal force there, and dL/dt of the leaning rotors (spin axis ŷ cos θ − ẑ sin θ): find θ."""
    def residual(theta):
        cg = [0, h * mpmath.sin(theta), h * mpmath.cos(theta)]
        weight = _cross(cg, [0, 0, -m * G])[0]
        centrifugal = _cross(cg, [0, -m * v * v / turn, 0])[0]
        spin = v / r
        momentum = (2 * I_w + ratio * I_e) * spin
        rate = _cross([0, 0, v / turn], [0, momentum * mpmath.cos(theta), -momentum * mpmath.sin(theta)])[0]
        return weight + centrifugal - rate
    return mpmath.findroot(residual, (mpmath.mpf("1e-6"), mpmath.pi / 2 - mpmath.mpf("1e-6")), solver="bisect")


def test_khurmi_trolley_car():
    """Khurmi & Gupta, Theory of Machines, ex. 14.10: a trolley car of 2500 kg on rails 1.5 m apart,
    a curve of 30 m at 24 km/h; wheels 0.75 m across; each axle with its wheels 18 kg·m², driven by
    a motor (12 kg·m² each) turning against the wheels at five times their speed; the centre of
    gravity 0.9 m up; g = 9.81. The book: 7132 N on each outer wheel, 5131 N on each inner one."""
    results = taucli.gyro(vehicle="four-wheeler", mass="2500 kg", track="1.5 m", turn_radius="30 m", speed="24 km/h", wheel_radius="0.375 m",
                          wheel_inertia="9 kg*m^2", engine_inertia="24 kg*m^2", gear_ratio=-5, cg_height="0.9 m", g="9.81 m/s^2").results
    assert round(results["reaction_outer"].value) == 7132 and round(results["reaction_inner"].value) == 5131


@pytest.mark.parametrize("seed", range(3))
def test_random_four_wheelers_against_the_vectors(seed):
    rng = random.Random(4750 + seed)
    for _ in range(20):
        m, h, x = rng.uniform(500, 5000), rng.uniform(0.3, 1.5), rng.uniform(1.0, 2.5)
        I_w, I_e, ratio, r = rng.uniform(0, 20), rng.uniform(0, 30), rng.uniform(-8, 8), rng.uniform(0.2, 0.6)
        v, turn = rng.uniform(1, 20), rng.uniform(20, 200)
        values = {k: val.value for k, val in taucli.gyro(vehicle="four-wheeler", mass=m, cg_height=h, track=x, wheel_inertia=I_w, engine_inertia=I_e,
                                                         gear_ratio=ratio, wheel_radius=r, speed=v, turn_radius=turn).results.items()}
        inner, outer = _four_wheeler(*(mpmath.mpf(q) for q in (m, h, x, I_w, I_e, ratio, r, v, turn)))
        if inner < 0 or outer < 0:  # a wheel lifts: it carries no load, and neither side's is the balance's
            assert values["reaction_inner"] is None and values["reaction_outer"] is None
        else:
            assert values["reaction_outer"] == pytest.approx(float(outer), rel=1e-12)
            assert values["reaction_inner"] == pytest.approx(float(inner), rel=1e-10, abs=1e-9 * m)
        overturn = values["speed_overturn"]
        if overturn is not None:  # at that speed the vector balance leaves the inner (or, tipping inward, the outer) wheels unloaded
            at_overturn = _four_wheeler(*(mpmath.mpf(q) for q in (m, h, x, I_w, I_e, ratio, r, overturn, turn)))
            assert min(abs(side) for side in at_overturn) <= 1e-9 * m * 9.8


@pytest.mark.parametrize("seed", range(2))
def test_random_two_wheelers_lean_against_the_vectors(seed):
    rng = random.Random(4760 + seed)
    for _ in range(10):
        m, h, I_w, I_e, ratio, r = rng.uniform(150, 400), rng.uniform(0.4, 0.9), rng.uniform(0.5, 2), rng.uniform(0, 0.5), rng.uniform(2, 10), rng.uniform(0.25, 0.4)
        v, turn = rng.uniform(5, 30), rng.uniform(30, 200)
        lean = taucli.gyro(vehicle="two-wheeler", mass=m, cg_height=h, wheel_inertia=I_w, engine_inertia=I_e, gear_ratio=ratio, wheel_radius=r,
                           speed=v, turn_radius=turn).results["lean_balance"].value
        exact = _lean(*(mpmath.mpf(q) for q in (m, h, I_w, I_e, ratio, r, v, turn)))
        assert lean == pytest.approx(float(exact), rel=1e-12)


def test_no_spinning_parts_leaves_the_centrifugal_couple_alone():
    """Without wheels' or engine's inertia the inner wheels unload at v² = gxR/(2h), the rigid-body result."""
    values = taucli.gyro(vehicle="four-wheeler", mass="1500 kg", cg_height="0.55 m", track="1.5 m", speed="60 km/h", turn_radius="40 m").results
    assert values["couple_gyro"].value == 0
    assert values["speed_overturn"].value == pytest.approx(math.sqrt(9.80665 * 1.5 * 40 / (2 * 0.55)), rel=1e-14)


def test_units_do_not_change_the_turn():
    si = taucli.gyro(vehicle="two-wheeler", mass="250 kg", cg_height="0.6 m", speed="25 m/s", turn_radius="50 m", wheel_inertia="1 kg*m^2",
                     wheel_radius="0.3 m", engine_inertia="0.2 kg*m^2", gear_ratio=5).results
    other = taucli.gyro(vehicle="two-wheeler", mass=f"{250 / 0.45359237} lb", cg_height="60 cm", speed="90 km/h", turn_radius="0.05 km",
                        wheel_inertia="10000 kg*cm^2", wheel_radius="300 mm", engine_inertia="0.2 kg*m^2", gear_ratio=5).results
    for key in ("lean_balance", "couple_gyro", "couple_centrifugal"):
        assert other[key].value == pytest.approx(si[key].value, rel=1e-12), key


def test_refusals(taucli):
    base = ("gyro", "--vehicle", "four-wheeler", "--mass", "2000kg", "--cg-height", "0.6m", "--speed", "90km/h", "--turn-radius", "100m")
    assert_usage_error(taucli(*base), "--track")
    assert_usage_error(taucli(*base, "--track", "1.5m", "--wheel-inertia", "1kg*m^2"), "--wheel-radius")
    assert_usage_error(taucli(*base, "--track", "1.5m", "--spin", "100rpm"), "--spin")
    assert_usage_error(taucli("gyro", "--cg-height", "0.6m", "--spin", "100rpm", "--inertia", "1kg*m^2"), "--cg-height", "--vehicle")
    assert_usage_error(taucli(*base[:3], "--vehicle", "tricycle"), "--vehicle")


def test_no_load_is_printed_on_a_wheel_that_lifts():
    """Past the overturning speed, or with an engine turning hard against the wheels (the couple
    then tips the vehicle inward), a wheel's load would be negative: both loads are null, and
    speed_overturn is where the wheels that lift are unloaded, by the vector balance."""
    kw = dict(vehicle="four-wheeler", mass="2500 kg", track="1.5 m", turn_radius="30 m", wheel_radius="0.375 m", wheel_inertia="9 kg*m^2",
              cg_height="0.9 m")
    past = taucli.gyro(**kw, speed="100 km/h").results
    assert past["reaction_inner"].value is None and past["reaction_outer"].value is None
    inward = taucli.gyro(**kw, speed="100 km/h", engine_inertia="240 kg*m^2", gear_ratio=-5).results
    assert inward["reaction_inner"].value is None and inward["reaction_outer"].value is None
    speed = inward["speed_overturn"].value
    _, outer = _four_wheeler(*(mpmath.mpf(q) for q in (2500, 0.9, 1.5, 9, 240, -5, 0.375, speed, 30)))
    assert abs(outer) <= 1e-9 * 2500 * 9.8  # the outer wheels unloaded at that speed
    slower = taucli.gyro(**kw, speed=f"{speed * 0.99} m/s", engine_inertia="240 kg*m^2", gear_ratio=-5).results
    assert slower["reaction_outer"].value > 0 and slower["reaction_inner"].value > 0
