"""#34 items 5 and 6, the pendulum: how far the swing reaches (amplitude, rise, KE_bottom, from
--omega0 or --omega-bottom), angles from the upward vertical (--from-top), and the pivot's force
as components (--components). References are written from the physics in mpmath
(tests/references/pendulum.py: Pendulum from the bottom, Toppling from the top), and published
problems with the book's printed answers."""

from __future__ import annotations

import math
import random

import mpmath as mp
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taucli
from conftest import assert_usage_error, run_taucli
from references import DPS
from references.compare import rad, rad_s
from references.pendulum import Pendulum, Toppling

G0 = 9.80665


def _between(lo, hi):
    """Floats in [lo, hi], 0 or of a size a quantity may have (not subnormal)."""
    return st.floats(lo, hi).filter(lambda x: x == 0 or abs(x) > 1e-30)


def values(report) -> dict:
    return {key: value.value for key, value in report.results.items()}


def _rod(length=1.0, mass=2.0, **given) -> dict:
    return values(taucli.pendulum(shape="rod", length=length, mass=mass, axis="end", **given))


# -- published problems ---------------------------------------------------------------------------

def test_serway_rod_nudged_from_the_vertical_at_the_horizontal():
    """Serway & Jewett, Physics for Scientists and Engineers, ch. 10: a uniform rod (L, M) pivoted
    at one end is nudged from rest in the vertical position; at the horizontal the book prints
    ω = √(3g/L), α = 3g/2L, and the pivot's force R_x = −3Mg/2 (towards the pivot), R_y = Mg/4."""
    length, mass, g = 1.2, 3.0, 9.8
    r = _rod(length, mass, g=g, from_top=True, angle="90deg", components=True)
    assert abs(r["omega"]) == pytest.approx(math.sqrt(3 * g / length), rel=1e-14)
    assert r["pivot_radial"] == pytest.approx(3 * mass * g / 2, rel=1e-14)
    assert r["pivot_horizontal"] == pytest.approx(-3 * mass * g / 2, rel=1e-14)  # the centre of mass is on the side of +90°
    assert r["pivot_vertical"] == pytest.approx(mass * g / 4, rel=1e-14)
    assert r["pivot_tangential"] == pytest.approx(-mass * g / 4, rel=1e-14)  # up: against larger angles, which go down
    assert r["pivot_force"] == pytest.approx(mass * g * math.hypot(1.5, 0.25), rel=1e-14)


def test_hrw_falling_chimney_at_35_degrees():
    """Halliday, Resnick & Walker, Fundamentals of Physics, ch. 10: a chimney (a thin rod 55.0 m
    tall) falls over; at 35.0° from the vertical the book prints the top's radial acceleration
    5.32 m/s² and tangential acceleration 8.43 m/s² (g = 9.8 m/s²)."""
    r = _rod(55.0, 1.0, g=9.8, from_top=True, angle="35deg", at=55.0)
    assert round(r["a_c"], 2) == 5.32
    assert round(r["a_t"], 2) == 8.43
    assert r["a_c"] == pytest.approx(3 * 9.8 * (1 - math.cos(math.radians(35))), rel=1e-13)
    assert r["a_t"] == pytest.approx(1.5 * 9.8 * math.sin(math.radians(35)), rel=1e-13)


def test_serway_meter_stick_falling_from_upright():
    """Serway & Jewett, ch. 10: a meter stick held vertically with one end on the floor falls,
    the end on the floor not slipping; the book prints the other end's speed 5.42 m/s."""
    done = run_taucli("pendulum", "--shape", "rod", "--length", "1m", "--mass", "0.1kg", "--axis", "end", "--from-top",
                      "--angle", "90deg", "--at", "1m", "--get", "v_t")
    assert done.code == 0, done.err
    assert round(float(done.out), 2) == 5.42
    assert float(done.out) == pytest.approx(math.sqrt(3 * G0), rel=1e-14)


def test_rod_released_from_the_horizontal_pivot_components():
    """A uniform rod released from the horizontal (Serway's 'Rotating Rod', ch. 10): the pivot
    carries mg/4 at the release, straight up, and 5mg/2 at the bottom, straight up."""
    m = 2.0
    r = _rod(1.0, m, angle0="90deg", components=True)
    assert r["pivot_vertical0"] == pytest.approx(m * G0 / 4, rel=1e-14)
    assert r["pivot_tangential0"] == pytest.approx(m * G0 / 4, rel=1e-14)  # up, which is towards larger angles at +90°
    assert r["pivot_radial0"] == 0 and r["pivot_horizontal0"] == 0
    assert r["pivot_vertical_bottom"] == pytest.approx(2.5 * m * G0, rel=1e-14)
    assert r["pivot_radial_bottom"] == pytest.approx(2.5 * m * G0, rel=1e-14)
    assert r["pivot_horizontal_bottom"] == 0 and r["pivot_tangential_bottom"] == 0
    assert r["pivot_force_bottom"] == pytest.approx(2.5 * m * G0, rel=1e-14)


def test_the_rod_given_serways_speed_at_the_bottom_swings_to_the_horizontal():
    """Serway's rotating rod backwards: at the bottom ω = √(3g/L), so it rises to 90°, its centre
    of mass L/2 higher, with KE at the bottom mgL/2."""
    length, m = 1.0, 2.0
    r = _rod(length, m, omega_bottom=rad_s(math.sqrt(3 * G0 / length)))
    assert r["amplitude"] == pytest.approx(math.pi / 2, rel=1e-14)
    assert r["rise"] == pytest.approx(length / 2, rel=1e-14)
    assert r["KE_bottom"] == pytest.approx(m * G0 * length / 2, rel=1e-14)
    assert r["omega_bottom"] == pytest.approx(math.sqrt(3 * G0 / length), rel=1e-15)
    backwards = _rod(length, m, omega_bottom=rad_s(-math.sqrt(3 * G0 / length)))
    assert backwards["amplitude"] == pytest.approx(-math.pi / 2, rel=1e-14)


def test_a_bob_from_the_bottom():
    """A simple pendulum (L = 2 m) passing the bottom at 3 m/s: cos θₐ = 1 − v²/(2gL), h = v²/2g."""
    with mp.workdps(30):
        v, length = mp.mpf(3), mp.mpf(2)
        turn = mp.acos(1 - v**2 / (2 * G0 * length))
    r = values(taucli.pendulum(shape="point", radius="2m", mass="1kg", omega_bottom="1.5rad/s"))
    assert r["amplitude"] == pytest.approx(float(turn), rel=1e-14)
    assert r["rise"] == pytest.approx(9 / (2 * G0), rel=1e-14)
    assert r["KE_bottom"] == pytest.approx(4.5, rel=1e-15)


# -- the swing's reach: references from the physics ------------------------------------------------

def test_reach_against_the_reference_with_a_spring():
    """Gravity and a spring: the turning angle ahead solves U(θₐ) = E (mpmath's bisection)."""
    for theta0, omega0 in ((0.3, 2.0), (-1.0, 0.0), (2.5, -4.0), (0.0, 6.0)):
        r = values(taucli.pendulum(inertia=2.0, mass=1.0, cm_distance=1.0, torsion=3.0, angle0=rad(theta0), omega0=rad_s(omega0)))
        ref = Pendulum(2.0, 1.0, 1.0, G0, 3.0, theta0, omega0)
        with mp.workdps(DPS):
            assert r["amplitude"] == pytest.approx(float(ref.amplitude()), rel=1e-13)
            assert r["rise"] == pytest.approx(float(ref.rise()), rel=1e-12, abs=1e-15)
            assert r["KE_bottom"] == pytest.approx(float(ref.I * ref.w2(0) / 2), rel=1e-14)


def test_over_the_top_there_is_no_turning_angle():
    done = run_taucli("pendulum", "--shape", "rod", "--length", "1m", "--mass", "2kg", "--axis", "end", "--omega-bottom", "8rad/s", "--json")
    assert done.code == 0, done.err
    doc = done.json()
    assert doc["results"]["amplitude"]["value"] is None and doc["results"]["rise"]["value"] is None
    assert any("goes over the top" in note for note in doc["notes"])


def test_a_torsion_pendulum_reaches_its_harmonic_amplitude():
    r = values(taucli.pendulum(inertia=0.02, torsion=0.5, omega_bottom="3rad/s"))
    assert r["amplitude"] == pytest.approx(3 / math.sqrt(0.5 / 0.02), rel=1e-15)
    assert "rise" not in r  # no gravity: nothing rises


def test_omega_bottom_in_other_units_gives_the_same_reach():
    a = _rod(omega_bottom="30rpm")
    b = _rod(omega_bottom=rad_s(math.pi))
    assert a["amplitude"] == pytest.approx(b["amplitude"], rel=1e-15)
    assert a["rise"] == pytest.approx(b["rise"], rel=1e-15)


def test_omega_bottom_refusals():
    rod = ["pendulum", "--shape", "rod", "--length", "1m", "--mass", "2kg", "--axis", "end"]
    assert_usage_error(run_taucli(*rod, "--omega-bottom", "3rad/s", "--omega0", "1rad/s"), "--omega-bottom", "--omega0")
    assert_usage_error(run_taucli(*rod, "--omega-bottom", "3rad/s", "--angle0", "30deg"), "--omega-bottom", "--angle0")
    ok = run_taucli(*rod, "--omega-bottom", "3rad/s", "--from-top", "--angle0", "180deg", "--get", "KE_bottom")
    assert ok.code == 0 and float(ok.out) == pytest.approx(3.0, rel=1e-15)


@settings(max_examples=60, deadline=None)
@given(theta0=_between(-3.1, 3.1), omega0=_between(-8, 8), length=st.floats(0.1, 5))
def test_energy_balances_of_the_reach(theta0, omega0, length):
    """mg·rise = ½Iω₀² (gravity alone), KE_bottom = ½Iω₀² + mgd(1 − cos θ₀), and the turning angle
    has ω = 0: mgd(cos θ₀ − cos θₐ) = ½Iω₀²."""
    m = 1.5
    r = _rod(length, m, angle0=rad(theta0), omega0=rad_s(omega0))
    inertia, d = m * length**2 / 3, length / 2
    ke0 = inertia * omega0**2 / 2
    assert r["KE_bottom"] == pytest.approx(ke0 + m * G0 * d * (1 - math.cos(theta0)), rel=1e-12, abs=1e-12)
    if r["goes_over"]:
        assert r["amplitude"] is None
        return
    assert m * G0 * r["rise"] == pytest.approx(ke0, rel=1e-12, abs=1e-14)
    assert m * G0 * d * (math.cos(theta0) - math.cos(r["amplitude"])) == pytest.approx(ke0, rel=1e-6, abs=1e-9 * m * G0 * d)


# -- angles from the top ---------------------------------------------------------------------------

def test_from_top_against_the_toppling_reference():
    """Random bodies under gravity alone, angles from the upward vertical: |ω| at --angle, the
    turning angle, and the pivot's force at the start and at --angle, against Toppling (written in φ)."""
    rng = random.Random(34_005)
    for _ in range(40):
        length, m, g = 10 ** rng.uniform(-1, 1.5), 10 ** rng.uniform(-1, 2), rng.choice((G0, 9.8, 1.62))
        phi0 = rng.uniform(-math.pi, math.pi) if rng.random() < 0.8 else 0.0
        omega0 = 0.0 if rng.random() < 0.4 else rng.uniform(-2, 2) * math.sqrt(g / length)
        target = rng.uniform(-math.pi, math.pi)
        r = _rod(length, m, g=g, from_top=True, angle0=rad(phi0), omega0=rad_s(omega0), angle=rad(target), components=True)
        ref = Toppling(m * length**2 / 3, m, length / 2, g, phi0, omega0)
        with mp.workdps(DPS):
            scale = m * g * (1 + length * omega0**2 / g)
            radial, tangential, horizontal, vertical = ref.pivot(phi0, mp.mpf(omega0) ** 2)
            for key, exact in (("radial0", radial), ("tangential0", tangential), ("horizontal0", horizontal), ("vertical0", vertical)):
                assert r["pivot_" + key] == pytest.approx(float(exact), rel=1e-12, abs=1e-13 * scale), key
            w2 = ref.omega2(target)
            if w2 < 0:
                assert r["omega"] is None
            elif r["omega"] is not None and w2 > 1e-6 * scale / (m * length):
                assert abs(r["omega"]) == pytest.approx(float(mp.sqrt(w2)), rel=1e-10)
                for key, exact in zip(("radial", "tangential", "horizontal", "vertical"), ref.pivot(target, w2)):
                    assert r["pivot_" + key] == pytest.approx(float(exact), rel=1e-10, abs=1e-12 * scale), key
            turn = ref.turning()
            c = mp.cos(phi0) + ref.I * mp.mpf(omega0) ** 2 / (2 * ref.G)
            if abs(c - 1) > 1e-9 and not (omega0 == 0 and phi0 == 0):
                if turn is None:
                    assert r["amplitude"] is None
                else:
                    assert r["amplitude"] == pytest.approx(float(turn), rel=1e-9, abs=1e-12)


def test_from_top_the_theta_at_a_time_is_from_the_top():
    """φ(t) from the top keeps ½Iω² + mgd cos φ; at the top φ = 0 the body is balanced."""
    r = _rod(2.0, 1.0, from_top=True, angle0="10deg", time="1s")
    inertia, big_g = 4 / 3, G0 * 1.0
    energy = lambda phi, w: inertia * w * w / 2 + big_g * math.cos(phi)  # noqa: E731
    assert energy(r["theta"], r["omega"]) == pytest.approx(energy(math.radians(10), 0.0), rel=1e-12)
    balanced = _rod(2.0, 1.0, from_top=True)
    assert balanced["alpha0"] == 0 and balanced["amplitude"] == 0


def test_from_top_angles_in_other_units_give_the_same_answers():
    a = _rod(from_top=True, angle0="10deg", angle="1.5rad", components=True)
    b = _rod(from_top=True, angle0=rad(math.radians(10)), angle="85.94366926962348deg", components=True)
    for key in ("omega", "amplitude", "pivot_horizontal", "pivot_vertical"):
        assert a[key] == pytest.approx(b[key], rel=1e-13), key


def test_from_top_refusals():
    rod = ["pendulum", "--shape", "rod", "--length", "1m", "--mass", "2kg", "--axis", "end", "--from-top"]
    assert_usage_error(run_taucli(*rod, "--torsion", "1N*m/rad"), "--from-top", "gravity alone")
    assert_usage_error(run_taucli(*rod, "--angle0", "200deg"), "--angle0", "from the top")
    assert_usage_error(run_taucli(*rod, "--angle", "-181deg"), "--angle", "from the top")


# -- the pivot's components ------------------------------------------------------------------------

@settings(max_examples=60, deadline=None)
@given(theta0=_between(-3.14, 3.14), omega0=_between(-8, 8), target=_between(-3.14, 3.14), top=st.booleans())
def test_components_make_up_the_size(theta0, omega0, target, top):
    """√(F_r² + F_t²) = √(F_h² + F_v²) = the size, wherever they are given."""
    r = _rod(1.0, 2.0, angle0=rad(theta0), omega0=rad_s(omega0), angle=rad(target), components=True, from_top=top)
    for suffix in ("0", "_bottom", ""):
        size = r["pivot_force" + suffix]
        if size is None:
            assert r["pivot_radial" + suffix] is None
            continue
        assert math.hypot(r["pivot_radial" + suffix], r["pivot_tangential" + suffix]) == pytest.approx(size, rel=1e-14)
        assert math.hypot(r["pivot_horizontal" + suffix], r["pivot_vertical" + suffix]) == pytest.approx(size, rel=1e-12)


def test_components_only_when_asked():
    r = _rod(angle0="90deg")
    assert "pivot_radial0" not in r and "pivot_force0" in r
    done = run_taucli("pendulum", "--shape", "rod", "--length", "1m", "--mass", "2kg", "--axis", "end", "--angle0", "90deg", "--get", "pivot_vertical_bottom")
    assert done.code == 0 and float(done.out) == pytest.approx(2.5 * 2 * G0, rel=1e-14)
