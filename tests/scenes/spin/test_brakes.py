"""spin-down with brakes and pressed faces (#24): each a constant Coulomb torque, checked against
references written from the physics (the face torques as integrals over the contact at 50
digits with mpmath.quad), the property that a brake is the same --friction, and the textbook
problems."""

from __future__ import annotations

import math

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taucli
from conftest import assert_usage_error, run_taucli

MP_DPS = 50  # the references' precision, set for each test by conftest
with mpmath.workdps(MP_DPS):
    G = mpmath.mpf("9.80665")  # standard gravity, exact to MP_DPS digits


def values(report):
    return {name: value.value for name, value in report.results.items()}


def face_reference(mu, force, inner, outer, pressure):
    """τ = ∫ μ·p(r)·(2πr dr)·r over the contact; p uniform (F over the area) or p = C/r (uniform
    wear: p·r the same everywhere) with C fixed by ∫ p·2πr dr = F."""
    mu, force, inner, outer = (mpmath.mpf(x) for x in (mu, force, inner, outer))
    if pressure == "uniform":
        p = lambda r: force / (mpmath.pi * (outer**2 - inner**2))  # noqa: E731
    else:
        c = force / (2 * mpmath.pi * (outer - inner))
        p = lambda r: c / r  # noqa: E731
    return mpmath.quad(lambda r: mu * p(r) * 2 * mpmath.pi * r * r, [inner, outer])


def test_brake_shoe_stops_a_flywheel():
    """A 100 N shoe with μ = 0.4 on the rim (0.5 m) of a 50 kg disc flywheel at 300 rpm:
    τ = μNr = 20 N·m, I = ½MR² = 6.25 kg·m², t = Iω₀/τ, θ = Iω₀²/(2τ); all the energy to the brake."""
    result = values(taucli.spin_down(shape="disc", mass="50kg", radius="0.5m", omega0="300rpm", brake="force=100N mu=0.4", energy=True))
    inertia = mpmath.mpf(50) * mpmath.mpf("0.5") ** 2 / 2
    torque = mpmath.mpf("0.4") * 100 * mpmath.mpf("0.5")
    omega0 = 300 * 2 * mpmath.pi / 60
    assert result["torque_brake"] == pytest.approx(float(torque), rel=1e-15)
    assert result["t_stop"] == pytest.approx(float(inertia * omega0 / torque), rel=1e-14)
    assert result["revs_stop"] == pytest.approx(float(inertia * omega0**2 / (2 * torque) / (2 * mpmath.pi)), rel=1e-14)
    assert result["work_brake"] == pytest.approx(float(inertia * omega0**2 / 2), rel=1e-14)
    assert result["power_brake"] == pytest.approx(float(torque * omega0), rel=1e-14)
    assert "work_friction" not in result and "power_friction" not in result


@settings(max_examples=40, deadline=None)
@given(
    inertia=st.floats(0.01, 100), omega0=st.floats(-500, 500).filter(lambda x: x == 0 or abs(x) > 1e-6), force=st.floats(0.1, 1e4), mu=st.floats(0.01, 1.5),
    radius=st.floats(0.01, 3), drive=st.floats(-50, 50).filter(lambda x: x == 0 or abs(x) > 1e-6), viscous=st.sampled_from([None, 0.02]), time=st.sampled_from([None, 0.7]),
)
def test_a_brake_is_the_same_friction(inertia, omega0, force, mu, radius, drive, viscous, time):
    """Property: --brake "force=N mu=μ radius=r" gives exactly what --friction μNr gives, with a
    drive, a viscous loss and --time or not; its work and power are what friction's were."""
    common = dict(inertia=inertia, omega0=omega0, torque=drive, viscous=viscous, time=time, energy=True)
    braked = values(taucli.spin_down(brake=f"force={force!r}N mu={mu!r} radius={radius!r}m", **common))
    plain = values(taucli.spin_down(friction=f"{mu * force * radius!r} N*m", **common))
    for key, value in plain.items():
        mine = braked.get(key.replace("friction", "brake"), braked.get(key))
        if value is None:
            assert mine is None, key
        else:
            assert mine == pytest.approx(value, rel=1e-12, abs=1e-12), key


def test_brake_with_friction_shares_the_loss_by_torque():
    """An axle friction of 1 N·m and a 3 N·m brake: the friction takes a quarter of the energy."""
    result = values(taucli.spin_down(inertia=2, omega0=10, friction=1, brake="force=30N mu=0.5 radius=0.2m", energy=True))
    assert result["t_stop"] == pytest.approx(2 * 10 / 4, rel=1e-15)
    assert result["work_friction"] == pytest.approx(0.25 * 100, rel=1e-14)
    assert result["work_brake"] == pytest.approx(0.75 * 100, rel=1e-14)
    assert result["power_brake"] == pytest.approx(3 * 10, rel=1e-14)


def test_two_shoes_add():
    result = values(taucli.spin_down(inertia=1, omega0=10, brake=["force=100N mu=0.4 radius=0.5m", "force=50N mu=0.2 radius=0.5m"]))
    assert result["torque_brake"] == pytest.approx(20 + 5, rel=1e-15)
    assert result["t_stop"] == pytest.approx(10 / 25, rel=1e-15)


def test_static_mu_holds_the_wheel():
    """A drive of 1.5 N·m against a shoe of μk·N·r = 1 N·m and μs·N·r = 2 N·m: at rest it holds."""
    held = values(taucli.spin_down(inertia=1, torque=1.5, brake="force=10N mu-k=0.1 mu-s=0.2 radius=1m", time=2))
    assert held["omega"] == 0 and held["theta"] == 0
    turning = values(taucli.spin_down(inertia=1, torque=2.5, brake="force=10N mu-k=0.1 mu-s=0.2 radius=1m", time=2))
    assert turning["alpha0"] == pytest.approx(2.5 - 1, rel=1e-15)  # once it turns, kinetic μ


def test_units_do_not_matter():
    a = values(taucli.spin_down(inertia=3, omega0=20, brake="force=0.1kN mu=0.3 radius=25cm", face="mu=0.2 force=2lbf outer-radius=4in"))
    b = values(taucli.spin_down(inertia=3, omega0=20, brake="force=100N mu=0.3 radius=0.25m", face=f"mu=0.2 force={2 * 4.4482216152605!r}N outer-radius=0.1016m"))
    for key in a:
        assert a[key] == pytest.approx(b[key], rel=1e-13), key


@pytest.mark.parametrize("pressure", ["uniform", "wear"])
@pytest.mark.parametrize(("inner", "outer"), [(0.05, 0.12), (0.0, 0.2), (0.3, 0.30001)])
def test_face_torque_against_the_integral(pressure, inner, outer):
    result = values(taucli.spin_down(inertia=1, omega0=5, face=f"mu=0.3 force=2kN inner-radius={inner}m outer-radius={outer}m pressure={pressure} surfaces=2"))
    assert result["torque_face"] == pytest.approx(float(2 * face_reference("0.3", 2000, inner, outer, pressure)), rel=1e-14)


def test_clutch_plate_in_both_pressure_models():
    """A clutch plate, μ = 0.3, 2 kN, Ri = 5 cm, Ro = 12 cm, two surfaces: uniform pressure
    (2/3)μF(Ro³ − Ri³)/(Ro² − Ri²) × 2 = 107.76 N·m, uniform wear μF(Ro + Ri)/2 × 2 = 102 N·m."""
    spec = "mu=0.3 force=2kN inner-radius=5cm outer-radius=12cm surfaces=2"
    uniform = taucli.spin_down(omega0="3000rpm", alpha=0, face=spec)
    wear = taucli.spin_down(omega0="3000rpm", alpha=0, face=spec + " pressure=wear")
    assert uniform.results["torque_face"].value == pytest.approx(107.7647058823529, rel=1e-14)
    assert wear.results["torque_face"].value == pytest.approx(102, rel=1e-15)
    assert "uniform pressure" in uniform.model and "uniform wear" in wear.model
    assert uniform.results["torque"].value == pytest.approx(uniform.results["torque_face"].value, rel=1e-15)


def test_uniform_pressure_keeps_its_digits_as_the_annulus_thins():
    """As Ri → Ro both models tend to μ·F·R; the difference form would lose every digit."""
    outer = 0.25
    inner = outer * (1 - 1e-12)
    result = values(taucli.spin_down(inertia=1, omega0=5, face=f"mu=0.5 force=10N inner-radius={inner!r}m outer-radius={outer!r}m"))
    assert result["torque_face"] == pytest.approx(float(face_reference("0.5", 10, inner, outer, "uniform")), rel=1e-15)


def test_disc_spinning_flat_on_a_table():
    """A 2 kg disc of radius 10 cm spinning at 10 rad/s flat on a table with μ = 0.2: τ = (2/3)μmgR,
    α = τ/(½mR²) = 4μg/(3R), t = ω₀/α."""
    result = values(taucli.spin_down(shape="disc", mass="2kg", radius="10cm", omega0="10rad/s", face="mu=0.2"))
    torque = 2 * mpmath.mpf("0.2") * 2 * G * mpmath.mpf("0.1") / 3
    assert result["torque_face"] == pytest.approx(float(torque), rel=1e-15)
    assert result["t_stop"] == pytest.approx(float(10 / (4 * mpmath.mpf("0.2") * G / (3 * mpmath.mpf("0.1")))), rel=1e-14)


def test_ring_lying_flat_is_mu_f_r():
    result = values(taucli.spin_down(shape="ring", mass="1kg", radius="0.3m", omega0=4, face="mu=0.25"))
    assert result["torque_face"] == pytest.approx(float(mpmath.mpf("0.25") * G * mpmath.mpf("0.3")), rel=1e-15)


def test_a_tool_held_at_constant_speed_needs_no_body():
    result = values(taucli.spin_down(omega0="10rev/s", brake="force=10N mu=0.1 radius=20cm"))
    assert result["torque"] == pytest.approx(0.2, rel=1e-15)
    assert result["power"] == pytest.approx(0.2 * 20 * math.pi, rel=1e-15)
    assert result["power_brake"] == pytest.approx(0.2 * 20 * math.pi, rel=1e-15)


def test_face_and_brake_results_are_in_the_table():
    document = run_taucli("spin-down", "--shape", "disc", "--mass", "2kg", "--radius", "0.1m", "--omega0", "10rad/s", "--face", "mu=0.2",
                          "--brake", "force=1N mu=0.1", "--energy", "--json").json()
    assert {"torque_brake", "work_brake", "power_brake", "torque_face", "work_face", "power_face"} <= set(document["results"])


@pytest.mark.parametrize(
    ("argv", "fragment"),
    [
        (["--brake", "mu=0.4 radius=1m"], "needs force="),
        (["--brake", "force=1N radius=1m"], "needs mu="),
        (["--brake", "force=1N mu-k=0.4 mu-s=0.2 radius=1m"], "mu-s= below"),
        (["--brake", "force=1N mu=0.4 mu-k=0.3 radius=1m"], "mu= and mu-k="),
        (["--brake", "force=1N mu=0.4"], "needs radius="),
        (["--brake", "force=1N mu=0.4 colour=red radius=1m"], "knows"),
        (["--face", "mu=0.2 force=1N outer-radius=1m pressure=soft"], "pressure="),
        (["--face", "mu=0.2 force=1N outer-radius=1m surfaces=1.5"], "whole number"),
        (["--face", "mu=0.2 force=1N inner-radius=2m outer-radius=1m"], "above"),
        (["--face", "mu=0.2"], "needs outer-radius="),
        (["--face", "mu=0.2 outer-radius=1m"], "needs force="),
    ],
)
def test_refusals(argv, fragment):
    assert_usage_error(run_taucli("spin-down", "--inertia", "1", "--omega0", "3rad/s", *argv), fragment)


def test_face_weight_under_another_gravity():
    """On the Moon (g = 1.62 m/s²) the disc on its face takes t = 3Rω₀/(4μg)."""
    result = values(taucli.spin_down(shape="disc", mass="2kg", radius="10cm", omega0="10rad/s", face="mu=0.2", g="1.62m/s^2"))
    assert result["t_stop"] == pytest.approx(float(3 * mpmath.mpf("0.1") * 10 / (4 * mpmath.mpf("0.2") * mpmath.mpf("1.62"))), rel=1e-14)
    assert_usage_error(run_taucli("spin-down", "--inertia", "1", "--omega0", "1rad/s", "--g", "1.62m/s^2"), "--face")
