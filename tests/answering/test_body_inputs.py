"""#34 item 3: a body by its density (--density, read by its unit: kg/m³ with a solid's dimensions,
kg/m² for a disc, plate, washer or thin shell, kg/m for a rod or ring) and by its radius of
gyration (--gyration with --mass, I = Mk²), in every scene with a body.

References from the physics: the mass is the density times the volume, the area or the length
(written here from each shape's measure, not from taucli's tables), and I = ∫r²dm of each shape."""

from __future__ import annotations

import mpmath
import pytest
from conftest import assert_usage_error, run_taucli

import taucli

mpmath.mp.dps = 40
pi = mpmath.pi


def values(report):
    return {key: value.value for key, value in report.results.items()}


def inertia_of(**kw) -> float:
    return values(taucli.inertia(**kw))["I"]


@pytest.mark.parametrize(
    "kw, want",
    [
        # a disc of steel by volume: M = ρπR²L, I = ½MR²
        (dict(shape="disc", radius="0.3 m", length="2 cm", density="7800 kg/m^3"), 7800 * pi * mpmath.mpf("0.09") * mpmath.mpf("0.02") * mpmath.mpf("0.09") / 2),
        # a disc by area: M = σπR²
        (dict(shape="disc", radius="0.3 m", density="20 kg/m^2"), 20 * pi * mpmath.mpf("0.09") * mpmath.mpf("0.09") / 2),
        # a plate about its centre, perpendicular: M = σWH, I = M(W² + H²)/12
        (dict(shape="plate", width="1 m", height="0.5 m", density="8 kg/m^2"), 8 * mpmath.mpf("0.5") * (1 + mpmath.mpf("0.25")) / 12),
        # a washer (a tube by its mass per area): M = σπ(R₂² − R₁²), I = ½M(R₁² + R₂²)
        (dict(shape="tube", inner_radius="0.1 m", outer_radius="0.2 m", density="10 kg/m^2"), 10 * pi * mpmath.mpf("0.03") * mpmath.mpf("0.05") / 2),
        # a thin spherical shell: M = σ4πR², I = (2/3)MR²
        (dict(shape="shell", radius="0.5 m", density="2 kg/m^2"), 2 * 4 * pi * mpmath.mpf("0.25") * 2 * mpmath.mpf("0.25") / 3),
        # a rod about its centre: M = λL, I = ML²/12
        (dict(shape="rod", length="2 m", density="0.5 kg/m"), mpmath.mpf("0.5") * 2 * 4 / 12),
        # a ring: M = λ2πR, I = MR²
        (dict(shape="ring", radius="1.5 m", density="0.2 kg/m"), mpmath.mpf("0.2") * 2 * pi * mpmath.mpf("1.5") ** 3),
    ],
)
def test_a_body_by_its_density_per_volume_area_or_length(kw, want):
    assert inertia_of(**kw) == pytest.approx(float(want), rel=1e-14)
    r = values(taucli.spin_down(**kw, omega0="10 rad/s", friction="1 N*m"))  # the same body in a scene
    assert r["I"] == pytest.approx(float(want), rel=1e-14)


def test_a_density_means_the_same_in_any_unit():
    si = inertia_of(shape="disc", radius="0.3 m", density="20 kg/m^2")
    assert inertia_of(shape="disc", radius="30 cm", density="2 g/cm^2") == pytest.approx(si, rel=1e-14)
    assert inertia_of(shape="rod", length="2 m", density="5 g/cm") == pytest.approx(inertia_of(shape="rod", length="2 m", density="0.5 kg/m"), rel=1e-14)
    # a number alone is kg/m³
    assert inertia_of(shape="sphere", radius="0.1 m", density=7800) == pytest.approx(inertia_of(shape="sphere", radius="0.1 m", density="7.8 g/cm^3"), rel=1e-14)


def test_the_inertia_scene_reports_the_mass_a_density_gives():
    r = values(taucli.inertia(shape="disc", radius="0.2 m", density="20 kg/m^2"))
    assert r["mass"] == pytest.approx(float(20 * pi * mpmath.mpf("0.04")), rel=1e-14)


def test_parts_by_areal_and_linear_density():
    """A sign: a 1 m × 0.5 m plate at 20 kg/m² on a 1 m rod at 2 kg/m, both about their centres."""
    r = values(taucli.spin_down(part=["plate density=20kg/m^2 width=1m height=0.5m", "rod density=2kg/m length=1m"], omega0="1 rad/s", friction="1 N*m"))
    assert r["I"] == pytest.approx(10 * 1.25 / 12 + 2 / 12, rel=1e-14)


def test_gyration_a_20_kg_flywheel_of_k_95_mm_to_800_rpm_in_40_s():
    """I = Mk² = 20 × 0.095² kg·m²; α = ω/t; τ = Iα; revolutions ½ω t /2π."""
    r = values(taucli.spin_down(gyration="95 mm", mass="20 kg", until_omega="800 rpm", in_time="40 s"))
    inertia = 20 * mpmath.mpf("0.095") ** 2
    omega = 800 * 2 * pi / 60
    assert r["I"] == pytest.approx(float(inertia), rel=1e-14)
    assert r["torque"] == pytest.approx(float(inertia * omega / 40), rel=1e-14)
    assert r["revs"] == pytest.approx(float(omega * 40 / 2 / (2 * pi)), rel=1e-14)


def test_gyration_in_every_scene_with_a_body():
    k, m = "0.2 m", "3 kg"
    inertia = 3 * 0.04
    assert values(taucli.inertia(gyration=k, mass=m))["I"] == pytest.approx(inertia, rel=1e-15)
    assert values(taucli.impulse(gyration=k, mass=m, omega0=0, torque="2 N*m", duration="1 s"))["omega1"] == pytest.approx(2 / inertia, rel=1e-14)
    L = values(taucli.gyro(gyration=k, mass=m, spin="100 rad/s", cm_distance="5 cm"))["L"]
    assert L == pytest.approx(100 * inertia, rel=1e-14)
    reflected = values(taucli.drive(gyration=k, mass=m, ratio=5, motor_inertia=0, until_omega="3000 rpm", in_time="1 s"))["reflected_inertia"]
    assert reflected == pytest.approx(inertia / 25, rel=1e-14)


def test_a_pendulum_by_its_radius_of_gyration():
    """k about the centre of mass with --offset d: I = m(k² + d²) about the pivot, T = 2π√(I/(mgd));
    k about the pivot with --cm-distance: I = mk²."""
    r = values(taucli.pendulum(gyration="0.2 m", mass="2 kg", offset="0.5 m", angle0="5 deg"))
    k, d, g = mpmath.mpf("0.2"), mpmath.mpf("0.5"), mpmath.mpf("9.80665")
    assert r["I"] == pytest.approx(float(2 * (k * k + d * d)), rel=1e-14)
    assert r["period_small"] == pytest.approx(float(2 * pi * mpmath.sqrt((k * k + d * d) / (g * d))), rel=1e-14)
    about_pivot = values(taucli.pendulum(gyration="0.5385164807134504 m", mass="2 kg", cm_distance="0.5 m", angle0="5 deg"))
    assert about_pivot["period_small"] == pytest.approx(r["period_small"], rel=1e-13)


def test_density_in_gyro_gives_the_weight_too():
    """A steel disc top by its density: its mass ρπR²L both in I and in the weight mgr."""
    by_density = values(taucli.gyro(shape="disc", radius="4 cm", length="1 cm", density="7800 kg/m^3", spin="3000 rpm", cm_distance="4 cm"))
    mass = float(7800 * pi * mpmath.mpf("0.04") ** 2 * mpmath.mpf("0.01"))
    by_mass = values(taucli.gyro(shape="disc", radius="4 cm", length="1 cm", mass=mass, spin="3000 rpm", cm_distance="4 cm"))
    assert by_density["omega_p"] == pytest.approx(by_mass["omega_p"], rel=1e-14)


def test_what_does_not_fit_is_refused():
    assert_usage_error(run_taucli("inertia", "rod", "--length", "1m", "--density", "2kg/m^2"), "--density needs a flat body")
    assert_usage_error(run_taucli("inertia", "disc", "--radius", "1m", "--density", "2kg"), "--density: expected a density, an areal density or a linear density")
    assert_usage_error(run_taucli("inertia", "disc", "--radius", "1m", "--mass", "2kg", "--density", "2kg/m^2"), "--density conflicts with --mass")
    assert_usage_error(run_taucli("spin-down", "--shape", "disc", "--radius", "1m", "--gyration", "0.3m", "--mass", "1kg", "--omega0", "1rad/s"),
                       "--gyration conflicts with --shape")
    assert_usage_error(run_taucli("spin-down", "--gyration", "0.3m", "--omega0", "1rad/s", "--friction", "1N*m"), "--mass is required with --gyration")
    assert_usage_error(run_taucli("spin-down", "--inertia", "1kg*m^2", "--gyration", "0.3m", "--mass", "1kg", "--omega0", "1rad/s"), "--gyration conflicts with --inertia")
    assert_usage_error(run_taucli("pendulum", "--gyration", "0.3m", "--mass", "1kg", "--angle0", "10deg"), "--gyration needs --cm-distance when k is about the pivot")
    assert_usage_error(run_taucli("inertia", "disc", "--radius", "1m", "--density", "2kg/m^3"), "--length is needed for the volume")
    assert_usage_error(run_taucli("inertia", "--part", "plate density=20kg width=1m height=0.5m", "--gyration", "1m", "--mass", "1kg"), "density=: expected a density")
