"""taucli flywheel: the fluctuation of speed and energy (Khurmi & Gupta, Theory of Machines, ch. 16).

References from the physics, not the solver's formula ΔE = Iω²Cs: the kinetic energy ½Iω² at the
two ends of the band (mpmath at 40 digits), the energy a punch takes against what a steady motor
gives over the time it works (integrated), the hoop stress from the tension that turns each
element of the rim round its circle.
"""

from __future__ import annotations

import math

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taucli
from conftest import assert_usage_error, run_taucli
from taucli.core.errors import InputError

RPM = 2 * math.pi / 60


def results(report):
    return {name: value.value for name, value in report.results.items()}


def test_khurmi_engine_flywheel_speeds():
    """Khurmi & Gupta, Theory of Machines, ch. 16: a flywheel of 6.5 tonnes, radius of gyration
    1.8 m; the fluctuation of energy is 56 kN·m at a mean speed of 120 rpm. The book: the greatest
    and least speeds are 121 and 119 rpm."""
    found = results(taucli.flywheel(shape="ring", mass="6.5 t", radius="1.8 m", energy_swing="56 kJ", omega_mean="120 rpm"))
    assert round(found["omega_max"] / RPM) == 121 and round(found["omega_min"] / RPM) == 119
    with mpmath.workdps(40):
        inertia, mean = mpmath.mpf(6500) * mpmath.mpf("1.8") ** 2, 120 * 2 * mpmath.pi / 60
        # the band about the mean whose kinetic energies differ by ΔE: ½I((ω + δ)² − (ω − δ)²) = 2Iωδ = ΔE
        half = mpmath.findroot(lambda d: inertia / 2 * ((mean + d) ** 2 - (mean - d) ** 2) - 56000, 1)
    assert found["omega_max"] == pytest.approx(float(mean + half), rel=1e-14)
    assert found["omega_min"] == pytest.approx(float(mean - half), rel=1e-14)


def test_khurmi_punching_press_rim_mass():
    """Khurmi & Gupta, Theory of Machines, ch. 16: 38 mm holes punched in 32 mm plate, 7 N·m of
    energy per mm² sheared, one hole every 10 s, a stroke of 100 mm; the rim's mean speed 25 m/s and
    the total fluctuation of speed at most 3%. The book: the punch works 1.6 s of the 10 (a share
    32/(2 × 100)), ΔE = 22.46 kN·m and the flywheel's mass 1198 kg."""
    energy = 7 * math.pi * 38 * 32  # N·m: 7 N·m/mm² over π d t
    found = results(taucli.flywheel(energy_per_cycle=energy, punch_fraction=32 / 200, rim_speed="25 m/s", fluctuation=0.03))
    assert round(found["mass"]) == 1198
    assert round(found["energy_swing"] / 1000, 2) == 22.46
    # from the physics: over the 1.6 s of punching the punch takes E, the motor gives P·t (P = E/10 s)
    with mpmath.workdps(30):
        given_by_motor = mpmath.quad(lambda t: mpmath.mpf(energy) / 10, [0, mpmath.mpf("1.6")])
        swing = energy - given_by_motor
    assert found["energy_swing"] == pytest.approx(float(swing), rel=1e-14)


def test_the_band_gives_the_mean_and_cs():
    found = results(taucli.flywheel(inertia=250, omega_max="303 rpm", omega_min="297 rpm"))
    assert found["cs"] == pytest.approx(0.02, rel=1e-13)
    with mpmath.workdps(40):
        top, bottom = mpmath.mpf(303) * 2 * mpmath.pi / 60, mpmath.mpf(297) * 2 * mpmath.pi / 60
        swing = 250 * (top**2 - bottom**2) / 2
    assert found["energy_swing"] == pytest.approx(float(swing), rel=1e-14)


@settings(max_examples=60, deadline=None)
@given(st.floats(0.1, 1e4), st.floats(1, 1e4), st.floats(1e-4, 0.5))
def test_any_two_give_the_third_and_back(inertia, omega, cs):
    """I and Cs give ΔE; that ΔE with Cs gives I back, with I gives Cs back; and ΔE is the kinetic
    energy between ω_max and ω_min."""
    swing = taucli.flywheel(inertia=inertia, omega_mean=omega, fluctuation=cs).results["energy_swing"].value
    assert taucli.flywheel(energy_swing=swing, omega_mean=omega, fluctuation=cs).results["I"].value == pytest.approx(inertia, rel=1e-14)
    assert taucli.flywheel(inertia=inertia, energy_swing=swing, omega_mean=omega).results["cs"].value == pytest.approx(cs, rel=1e-14)
    with mpmath.workdps(40):  # the kinetic energy between the ends, where the difference of squares would cancel in doubles
        top, bottom = mpmath.mpf(omega) * (1 + mpmath.mpf(cs) / 2), mpmath.mpf(omega) * (1 - mpmath.mpf(cs) / 2)
        want = mpmath.mpf(inertia) * (top**2 - bottom**2) / 2
    assert swing == pytest.approx(float(want), rel=1e-14)


def test_speed_variation_is_half_of_cs_and_units_do_not_matter():
    a = results(taucli.flywheel(inertia=100, omega_mean="300 rpm", speed_variation=0.01))
    b = results(taucli.flywheel(inertia="2373.036 lb*ft^2", omega_mean="5 rev/s", fluctuation=0.02))
    assert a["cs"] == pytest.approx(0.02, rel=1e-15)
    assert b["energy_swing"] == pytest.approx(a["energy_swing"] * 2373.036 * 0.45359237 * 0.3048**2 / 100, rel=1e-12)


def test_the_rims_hoop_stress_from_the_tension_that_turns_it():
    """A thin rim of section A: the element R dφ needs a centripetal force ρA R dφ v²/R, which the
    two tensions σA at its ends give (2σA sin(dφ/2) ≈ σA dφ): σ = ρv², at the mean and the top speed."""
    found = results(taucli.flywheel(omega_mean="300 rpm", fluctuation=0.02, energy_swing="5 kJ", rim_radius="0.6 m", density="7200 kg/m^3",
                                    allowable_stress="6 MPa"))
    v = 300 * RPM * 0.6
    with mpmath.workdps(30):
        d_phi = mpmath.mpf("1e-10")
        sigma = 7200 * (v * v / 0.6) * 0.6 * d_phi / (2 * mpmath.sin(d_phi / 2))
    assert found["hoop_stress"] == pytest.approx(float(sigma), rel=1e-12)
    assert found["hoop_stress_max"] == pytest.approx(7200 * (v * 1.01) ** 2, rel=1e-14)
    assert found["rim_area"] * 2 * math.pi * 0.6 * 7200 == pytest.approx(found["mass"], rel=1e-14)
    assert found["stress_margin"] == pytest.approx(6e6 / found["hoop_stress_max"], rel=1e-15)


def test_a_rim_past_its_allowable_stress_is_noted():
    report = taucli.flywheel(omega_mean="3000 rpm", fluctuation=0.02, energy_swing="5 kJ", rim_radius="1 m", density="7200 kg/m^3", allowable_stress="6 MPa")
    assert report.results["stress_margin"].value < 1
    assert any("burst" in note for note in report.notes)


@pytest.mark.parametrize(
    "argv, fragments",
    [
        (("--omega-mean", "300rpm", "--fluctuation", "0.02"), ("and", "are not given")),
        (("--inertia", "1", "--omega-mean", "300rpm", "--fluctuation", "0.02", "--energy-swing", "1kJ"), ("one too many",)),
        (("--inertia", "1", "--fluctuation", "0.02"), ("--omega-mean", "is required")),
        (("--inertia", "1", "--omega-mean", "300rpm", "--omega-max", "303rpm", "--omega-min", "297rpm"), ("conflicts",)),
        (("--inertia", "1", "--omega-max", "303rpm", "--omega-min", "297rpm", "--fluctuation", "0.02"), ("conflicts with the band",)),
        (("--inertia", "1", "--omega-max", "297rpm", "--omega-min", "303rpm"), ("--omega-max", "above")),
        (("--inertia", "1", "--omega-mean", "300rpm", "--fluctuation", "2.5"), ("--fluctuation", "between 0 and 2")),
        (("--inertia", "1", "--omega-mean", "300rpm", "--fluctuation", "0.02", "--density", "7200kg/m^3"), ("--density", "rim")),
        (("--inertia", "1", "--omega-mean", "300rpm", "--fluctuation", "0.02", "--punch-fraction", "0.2"), ("--punch-fraction", "--energy-per-cycle")),
        (("--inertia", "1", "--rim-speed", "25m/s", "--fluctuation", "0.02"), ("--rim-speed", "--rim-radius")),
        (("--inertia", "1", "--omega-mean", "300rpm", "--energy-swing", "1MJ"), ("--energy-swing", "more than the flywheel holds")),
    ],
)
def test_refusals_are_one_line(argv, fragments):
    assert_usage_error(run_taucli("flywheel", *argv), *fragments)


def test_batch_and_python_agree():
    line = '{"inertia": 100, "omega_mean": "300 rpm", "fluctuation": 0.02}\n'
    done = run_taucli("flywheel", "--batch", stdin=line)
    import json

    assert json.loads(done.out)["results"]["energy_swing"]["value"] == taucli.flywheel(inertia=100, omega_mean="300 rpm", fluctuation=0.02).results["energy_swing"].value
    with pytest.raises(InputError):
        taucli.flywheel(inertia=100)
