"""#32 item 2, the pendulum: the sign of ω where it first reaches --angle, ω₀,over near the top, a
swing that turns near the top with a weak spring, an angle never reached, long periods, a body
below M d², parts on both sides of the pivot, a_t along the motion. References are mpmath's, from
the energy: ½Iω² + mgd(1 − cos θ) + ½κθ² = E, t = ∫dθ/ω."""

from __future__ import annotations

import math

import mpmath as mp
import pytest

import taucli
from conftest import assert_usage_error, run_taucli
from taucli.core.errors import InputError

MP_DPS = 40
G0 = 9.80665


def values(report):
    return {key: value.value for key, value in report.results.items()}


def _point(**given):
    return values(taucli.pendulum(shape="point", radius=1, mass=1, **given))


def test_omega_at_an_angle_has_the_sign_it_has_when_the_body_first_gets_there():
    """From rest at 60° the bob reaches 10° on the way down, ω < 0 (README's convention: positive
    toward larger angles): −√(2g(cos 10° − cos 60°)). Today +3.0836."""
    omega = _point(angle0="60 deg", angle="10 deg")["omega"]
    exact = -mp.sqrt(2 * G0 * (mp.cos(mp.radians(10)) - mp.cos(mp.radians(60))))
    assert omega == pytest.approx(float(exact), rel=1e-14)
    assert _point(angle0="60 deg", omega0="1 rad/s", angle="62 deg")["omega"] > 0  # on its way out
    assert _point(angle0="-60 deg", angle="-10 deg")["omega"] > 0


def test_the_tangential_acceleration_at_an_angle_is_along_the_motion():
    """Speeding up toward the bottom, a_t > 0; past it, slowing, a_t < 0 (a size before)."""
    down = _point(angle0="60 deg", angle="10 deg", at="1 m")
    past = _point(angle0="60 deg", angle="-10 deg", at="1 m")
    assert down["a_t"] == pytest.approx(G0 * math.sin(math.radians(10)), rel=1e-14)
    assert past["a_t"] == pytest.approx(-G0 * math.sin(math.radians(10)), rel=1e-14)


def test_the_speed_that_just_reaches_the_top_keeps_its_digits_near_the_top():
    """ω₀,over² = (4mgd/I) cos²(θ₀/2): at 179.9999999° it is 5.4656e-9 rad/s; it was 0."""
    theta0 = math.radians(179.9999999)
    exact = 2 * mp.sqrt(G0) * mp.cos(mp.mpf(theta0) / 2)
    got = taucli.pendulum(shape="point", radius=1, mass=1, angle0=theta0).results["omega0_over"].value
    assert got == pytest.approx(float(exact), rel=1e-13, abs=0)


def test_a_swing_that_turns_at_the_top_with_a_weak_spring_has_the_period_of_its_energy():
    """--torsion 1e-5 --angle0 180deg: the period is 4∫₀^π dθ/ω (it was 16.43 s against 18.816)."""
    r = values(taucli.pendulum(shape="point", radius=1, mass=1, torsion="1e-5 N*m/rad", angle0="180 deg"))
    g, k = mp.mpf(G0), mp.mpf("1e-5")
    top = mp.mpf(math.pi)  # the double 180° is read as
    # in x = π − θ, U(π) − U(π − x) as a product, with no difference of near-equal energies near the top
    drop = lambda x: 2 * g * mp.sin((2 * top - x) / 2) * mp.sin(x / 2) + k * x * (2 * top - x) / 2  # noqa: E731
    quarter = mp.quad(lambda x: 1 / mp.sqrt(2 * drop(x)), [0, top])
    assert r["period"] == pytest.approx(float(4 * quarter), rel=1e-12)
    assert r["t_bottom"] == pytest.approx(float(quarter), rel=1e-12)


def test_an_angle_beyond_a_top_it_cannot_pass_is_never_reached():
    """--torsion 0.001 --angle0 170deg --angle -200deg gave ω = 0.939 with t_angle null: U(−200°)
    is below E, but the top at −180° is above it."""
    report = taucli.pendulum(shape="point", radius=1, mass=1, torsion="0.001 N*m/rad", angle0="170 deg", angle="-200 deg")
    assert report.results["omega"].value is None and report.results["t_angle"].value is None
    assert any("never reaches" in note for note in report.notes)


def test_a_long_period_is_found():
    """--inertia 2 --mass 1 --cm-distance 1 --angle0 1rad --omega0 10rad/s --torsion 0.001: the
    period (≈ 239.8 s) and t_bottom (≈ 119.81 s) were null: the search stopped short."""
    r = values(taucli.pendulum(inertia=2, mass=1, cm_distance=1, angle0="1 rad", omega0="10 rad/s", torsion="0.001 N*m/rad"))
    i, g, k, th0, w0 = mp.mpf(2), mp.mpf(G0), mp.mpf("0.001"), mp.mpf(1), mp.mpf(10)
    u = lambda th: g * (1 - mp.cos(th)) + k * th**2 / 2  # noqa: E731
    energy = i * w0**2 / 2 + u(th0)
    turn = th0  # the first angle past θ₀ where U = E (U's tops rise with the spring's ½κθ²: the first it cannot pass)
    while u(turn + mp.mpf("0.01")) < energy:
        turn += mp.mpf("0.01")
    turn = mp.findroot(lambda th: u(th) - energy, (turn, turn + mp.mpf("0.01")), solver="bisect")
    speed = lambda th: mp.sqrt(2 * (energy - u(th)) / i)  # noqa: E731
    cuts = [mp.pi * n for n in range(1, int(turn / mp.pi) + 1)]  # one piece per half-turn of sin θ
    quarter = mp.quad(lambda th: 1 / speed(th), [0, *cuts, turn])
    out = mp.quad(lambda th: 1 / speed(th), [th0, *cuts, turn])
    assert r["period"] == pytest.approx(float(4 * quarter), rel=1e-11)
    assert r["t_bottom"] == pytest.approx(float(out + quarter), rel=1e-11)


def test_a_body_below_m_d_squared_is_refused():
    with pytest.raises(InputError, match="at least M d²"):
        taucli.pendulum(inertia=0.5, mass=1, cm_distance=1, angle0="30 deg")
    assert_usage_error(run_taucli("pendulum", "--inertia", "0.5", "--mass", "1kg", "--cm-distance", "1m", "--angle0", "30deg"), "--inertia", "M d²")


def test_parts_on_both_sides_of_the_pivot_take_signed_offsets():
    """d = |Σmᵢdᵢ|/M: 1 kg at +0.5 m and 2 kg at −0.5 m give d = 0.5/3 on the heavier side, with a note."""
    report = taucli.pendulum(shape="point", radius=0.5, mass=1, part=("point mass=2kg offset=-0.5m",), angle0="10 deg")
    assert report.results["cm_distance"].value == pytest.approx(0.5 / 3, rel=1e-15)
    assert report.results["I"].value == pytest.approx(0.75, rel=1e-15)
    assert any("negative offset" in note for note in report.notes)
