"""#34 item 2: energy added to a wheel or taken from it (--work), and its stored energy put to a
load (--lift-mass: the height; --vehicle-mass: the speed) at an --efficiency.

The physics: a wheel on a fixed axle holds all its energy as rotation, KE = ½Iω²; work W done on
it changes KE by W (the work-energy theorem); the energy it gives up slowing from ω₀ to ω₁,
½I(ω₀² − ω₁²), reaches a load at the efficiency η: mgh for a mass lifted, ½mv² for a vehicle
set moving from rest. References in mpmath from those balances."""

from __future__ import annotations

import math

import mpmath
import pytest
from conftest import assert_usage_error, run_taucli
from hypothesis import given, settings
from hypothesis import strategies as st

import taucli

mpmath.mp.dps = 40


def values(report):
    return {key: value.value for key, value in report.results.items()}


def test_openstax_college_physics_chapter_10_problem_27a_the_flywheel_bus():
    """OpenStax College Physics, ch. 10, Problem 27(a): a bus of 10,000 kg holds a 1500 kg flywheel
    (a disc, 0.600 m); 90.0% of its rotational energy takes the bus from rest to 20.0 m/s. The
    book's answer: 128 rad/s. taucli solves for ω₀ with --find."""
    r = values(taucli.spin_down(shape="disc", mass="1500 kg", radius="0.600 m", vehicle_mass="10000 kg", efficiency=0.9,
                                find="omega0", want="vehicle_speed=20 m/s"))
    assert abs(r["omega0"]) == pytest.approx(128, abs=0.5)  # the book's 128 rad/s
    ke_bus = mpmath.mpf(10000) * 20**2 / 2
    inertia = mpmath.mpf(1500) * mpmath.mpf("0.6") ** 2 / 2
    assert abs(r["omega0"]) == pytest.approx(float(mpmath.sqrt(2 * ke_bus / mpmath.mpf("0.9") / inertia)), rel=1e-12)


def test_a_pull_on_a_cord_wound_on_a_ring_jee_main():
    """JEE Main (Physics), a published exam question: a cord wound on a 10 kg, 10 cm wheel whose mass
    is at its rim, at rest, pulled with 20 N through 1 m: W = Fd = 20 J. The printed answer:
    20 rad/s."""
    r = values(taucli.spin_down(shape="ring", mass="10 kg", radius="10 cm", work="20 J"))
    assert r["omega_after"] == pytest.approx(20, rel=1e-14)
    assert r["KE_after"] == pytest.approx(20, rel=1e-14)


def test_work_taken_by_water_from_a_propeller():
    """I = 3 kg·m², 600 rpm; the water takes 50 kJ: ω₁ = √(ω₀² − 2·50000/I) (a reference in mpmath)."""
    r = values(taucli.spin_down(inertia="3 kg*m^2", omega0="-600 rpm", work="-5 kJ"))
    w0 = 600 * 2 * mpmath.pi / 60
    want = mpmath.sqrt(w0**2 - 2 * 5000 / mpmath.mpf(3))
    assert r["omega_after"] == pytest.approx(-float(want), rel=1e-14)  # it keeps turning the way it turned
    assert r["KE0"] - r["KE_after"] == pytest.approx(5000, rel=1e-12)


def test_lift_and_vehicle_to_a_lower_speed_at_an_efficiency():
    """A 2 kg·m² wheel from 300 rpm to 100 rpm, η = 0.5, lifts 10 kg (g = 9.8): h = η½I(ω₀² − ω₁²)/(mg);
    or sets 10 kg moving: v = √(2η½I(ω₀² − ω₁²)/m)."""
    r = values(taucli.spin_down(inertia=2, omega0="300 rpm", until_omega="100 rpm", lift_mass="10 kg", vehicle_mass="10 kg",
                                efficiency=0.5, g="9.8 m/s^2"))
    w0, w1 = 10 * mpmath.pi, 10 * mpmath.pi / 3
    given_up = mpmath.mpf(2) * (w0**2 - w1**2) / 2
    assert r["energy_delivered"] == pytest.approx(float(given_up / 2), rel=1e-14)
    assert r["lift_height"] == pytest.approx(float(given_up / 2 / (10 * mpmath.mpf("9.8"))), rel=1e-14)
    assert r["vehicle_speed"] == pytest.approx(float(mpmath.sqrt(given_up / 10)), rel=1e-14)
    assert r["omega_after"] == pytest.approx(float(w1), rel=1e-14)


def test_lift_uses_standard_gravity_with_a_note():
    report = taucli.spin_down(inertia=1, omega0="10 rad/s", lift_mass="1 kg")
    assert values(report)["lift_height"] == pytest.approx(50 / 9.80665, rel=1e-14)
    assert any("standard gravity" in note for note in report.notes)


def test_results_do_not_change_with_the_units_of_the_inputs():
    si = values(taucli.spin_down(inertia=2, omega0="300 rpm", work=-50.0))
    other = values(taucli.spin_down(inertia="20000000 g*cm^2", omega0="5 rev/s", work="-0.05 kJ"))
    assert other["omega_after"] == pytest.approx(si["omega_after"], rel=1e-14)
    lift = values(taucli.spin_down(inertia=2, omega0="300 rpm", lift_mass=10.0))
    lift_g = values(taucli.spin_down(inertia=2, omega0="300 rpm", lift_mass="10000 g"))
    assert lift_g["lift_height"] == pytest.approx(lift["lift_height"], rel=1e-14)


@settings(max_examples=200, deadline=None)
@given(inertia=st.floats(1e-3, 1e3), omega0=st.one_of(st.just(0.0), st.floats(1e-3, 1e3), st.floats(-1e3, -1e-3)),
       share=st.one_of(st.just(-1.0), st.just(0.0), st.floats(1e-6, 3), st.floats(-1, -1e-6)))
def test_work_energy_balance(inertia, omega0, share):
    """½Iω₁² − ½Iω₀² = W, ω₁ of the sign of ω₀; W down to −KE₀."""
    ke0 = inertia * omega0 * omega0 / 2
    work = share * ke0 if ke0 else abs(share)
    r = values(taucli.spin_down(inertia=inertia, omega0=omega0, work=work))
    assert r["KE_after"] - r["KE0"] == pytest.approx(work, rel=1e-12, abs=1e-12 * ke0)
    assert inertia * r["omega_after"] ** 2 / 2 == pytest.approx(r["KE_after"], rel=1e-12, abs=1e-300)
    assert r["omega_after"] * omega0 >= 0


@settings(max_examples=200, deadline=None)
@given(inertia=st.floats(1e-3, 1e3), omega0=st.floats(0.1, 1e3), fraction=st.one_of(st.just(0.0), st.floats(1e-6, 1)), eta=st.floats(0.01, 1),
       mass=st.floats(1e-2, 1e4))
def test_energy_balance_of_a_load(inertia, omega0, fraction, eta, mass):
    """η·½I(ω₀² − ω₁²) = mgh = ½mv²."""
    r = values(taucli.spin_down(inertia=inertia, omega0=omega0, until_omega=fraction * omega0, efficiency=eta, lift_mass=mass, vehicle_mass=mass))
    given_up = inertia * omega0**2 * (1 - fraction**2) / 2
    assert r["energy_delivered"] == pytest.approx(eta * given_up, rel=1e-12, abs=1e-12 * inertia * omega0**2)
    assert mass * 9.80665 * r["lift_height"] == pytest.approx(r["energy_delivered"], rel=1e-12, abs=1e-300)
    assert mass * r["vehicle_speed"] ** 2 / 2 == pytest.approx(r["energy_delivered"], rel=1e-12, abs=1e-300)


def test_cli_prints_the_speed_after_and_refuses_what_does_not_fit():
    result = run_taucli("spin-down", "--inertia", "2kg*m^2", "--omega0", "300rpm", "--work", "-50J", "--get", "omega_after")
    assert result.code == 0 and float(result.out) == pytest.approx(math.sqrt(math.pi**2 * 100 - 50), rel=1e-5)
    assert_usage_error(run_taucli("spin-down", "--inertia", "2kg*m^2", "--omega0", "300rpm", "--work", "-1kJ"), "--work: takes more energy than the wheel stores")
    assert_usage_error(run_taucli("spin-down", "--inertia", "2kg*m^2", "--omega0", "300rpm", "--efficiency", "0.5"), "--efficiency goes with --lift-mass")
    assert_usage_error(run_taucli("spin-down", "--inertia", "2kg*m^2", "--omega0", "300rpm", "--lift-mass", "5kg", "--efficiency", "1.5"), "--efficiency")
    assert_usage_error(run_taucli("spin-down", "--omega0", "300rpm", "--work", "5J"), "--work needs a body")
    assert_usage_error(run_taucli("spin-down", "--inertia", "2kg*m^2", "--omega0", "300rpm", "--work", "5J", "--friction", "1N*m"), "--friction conflicts with --work")
    assert_usage_error(run_taucli("spin-down", "--inertia", "2kg*m^2", "--omega0", "300rpm", "--lift-mass", "5kg", "--until-omega", "400rpm"), "--until-omega")


def test_a_brake_under_a_withheld_euler_step_gives_null_shares_not_a_traceback():
    """Found by new random draws: a brake with --energy under an unstable euler step crashed
    sharing out a withheld work_friction (None / float)."""
    report = taucli.spin_down(shape="ring", mass=2.09, radius=2.51, omega0=1.318, drag=6.609, force=-115.67, lever=0.7613, push_angle=2.795,
                              brake=["force=190.87N mu=0.4993 radius=0.6015m"], time=0.127, energy=True, method="euler", dt=0.00102)
    assert report.results["work_brake"].value is None
