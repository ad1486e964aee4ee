"""Clutches and brakes of the machinery chapters (#47 item 2, #48 item 5): cone clutches
(--face cone=), band-and-block brakes (--band blocks=), and the rest as they come. References are
written from the physics at 50 digits: the pressure integrated over the contact itself (a cone's
slant face ring by ring, each block's arc element by element), never the closed form the solver
uses; the limits (a cone of 90° is a flat face, many short blocks are a band); the same answers in
other units; and the refusals.
"""

from __future__ import annotations

import math

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taucli
from conftest import assert_usage_error, run_taucli


def values(report):
    return {name: value.value for name, value in report.results.items()}


# --- cone clutches -------------------------------------------------------------------------------


def cone_reference(mu, force, inner, outer, angle, model):
    """A conical face of semi-angle α between the radii Ri and Ro, walked along its slant s from
    the inner edge: r(s) = Ri + s·sin α, the ring's area 2πr·ds. The normal pressure p is uniform
    (new) or C/r (worn in: p·r, the wear rate, the same everywhere), its level fixed by the axial
    force, F = ∫ p·sin α dA (each ring's normal force tilted α off the radius); the torque is
    ∫ μ·p·r dA. Returns (τ, p_max)."""
    mu, force, inner, outer, angle = (mpmath.mpf(x) for x in (mu, force, inner, outer, angle))
    sine = mpmath.sin(angle)
    slant = (outer - inner) / sine
    radius = lambda s: inner + s * sine  # noqa: E731
    shape = (lambda r: 1) if model == "uniform" else (lambda r: 1 / r)  # noqa: E731
    axial = mpmath.quad(lambda s: shape(radius(s)) * sine * 2 * mpmath.pi * radius(s), [0, slant])
    level = force / axial
    torque = mpmath.quad(lambda s: mu * level * shape(radius(s)) * radius(s) * 2 * mpmath.pi * radius(s), [0, slant])
    return torque, level * shape(inner)


@pytest.mark.parametrize("model", ["uniform", "wear"])
@pytest.mark.parametrize("degrees", [10, 12.5, 20, 45, 75])
def test_cone_clutch_against_its_face_integrated(model, degrees):
    """τ and the largest pressure of a cone clutch from the pressure integrated over its slant face."""
    spec = f"mu=0.25 force=3kN inner-radius=150mm outer-radius=190mm cone={degrees}deg model={model}"
    result = values(taucli.spin_down(inertia="1kg*m^2", omega0="100rpm", face=spec))
    torque, pmax = cone_reference(0.25, 3000, 0.15, 0.19, mpmath.radians(degrees), model)
    assert result["torque_face"] == pytest.approx(float(torque), rel=1e-13)
    assert result["pressure_face"] == pytest.approx(float(pmax), rel=1e-13)
    assert result["force_face"] == 3000


def test_cone_clutch_khurmi_axial_load():
    """Khurmi and Gupta, Theory of Machines, Example 10.31: a conical friction clutch carries 90 kW
    at 1500 rpm, semi-cone angle 20°, μ = 0.2, mean diameter 375 mm. Worn in, τ = μ·W·R/sin α at
    the mean radius R, so the axial load is W = τ·sin α/(μ·R) (worked here from the statement)."""
    report = taucli.spin_down(omega0="1500rpm", face="mu=0.2 inner-radius=187.5mm outer-radius=187.5mm cone=20deg model=wear",
                              find="face.force", want="torque_face=90kW/(1500rpm)")
    torque = mpmath.mpf(90000) / (1500 * 2 * mpmath.pi / 60)
    load = torque * mpmath.sin(mpmath.radians(20)) / (mpmath.mpf("0.2") * mpmath.mpf("0.1875"))
    assert report.results["face.force"].value == pytest.approx(float(load), rel=1e-9)
    assert float(load) == pytest.approx(5226, abs=1)


@pytest.mark.parametrize("model", ["uniform", "wear"])
def test_cone_of_ninety_degrees_is_the_flat_face(model):
    """Limit: α → 90° gives the flat plate (exactly at 90°, and by 1 − cos of the gap just below)."""
    flat = values(taucli.spin_down(inertia="1kg*m^2", omega0="100rpm", face=f"mu=0.3 force=4kN inner-radius=87.5mm outer-radius=125mm model={model}"))
    right = values(taucli.spin_down(inertia="1kg*m^2", omega0="100rpm", face=f"mu=0.3 force=4kN inner-radius=87.5mm outer-radius=125mm model={model} cone=90deg"))
    near = values(taucli.spin_down(inertia="1kg*m^2", omega0="100rpm", face=f"mu=0.3 force=4kN inner-radius=87.5mm outer-radius=125mm model={model} cone=89.99deg"))
    assert right["torque_face"] == flat["torque_face"]
    assert near["torque_face"] == pytest.approx(flat["torque_face"] / math.cos(math.radians(0.01)), rel=1e-14)
    assert near["torque_face"] > flat["torque_face"]


@settings(max_examples=25, deadline=None)
@given(mu=st.floats(0.05, 0.8), force=st.floats(1, 1e5), inner=st.sampled_from([0.0]) | st.floats(1e-3, 0.3), width=st.floats(1e-3, 0.3), degrees=st.floats(5, 90),
       model=st.sampled_from(["uniform", "wear"]))
def test_cone_clutch_same_in_other_units(mu, force, inner, width, degrees, model):
    """Property: the same cone in inches, pounds-force and radians gives the same SI torque."""
    if model == "wear" and inner == 0:
        inner = 0.01
    outer = inner + width
    si = values(taucli.spin_down(inertia="1kg*m^2", omega0="10rad/s",
                                 face=f"mu={mu!r} force={force!r}N inner-radius={inner!r}m outer-radius={outer!r}m cone={degrees!r}deg model={model}"))
    us = values(taucli.spin_down(inertia="1kg*m^2", omega0="10rad/s",
                                 face=f"mu={mu!r} force={force / 4.4482216152605!r}lbf inner-radius={inner / 0.0254!r}in "
                                      f"outer-radius={outer / 0.0254!r}in cone={math.radians(degrees)!r}rad model={model}"))
    assert us["torque_face"] == pytest.approx(si["torque_face"], rel=1e-12)
    torque, _ = cone_reference(mu, force, inner, outer, math.radians(degrees), model)
    assert si["torque_face"] == pytest.approx(float(torque), rel=1e-11)


@pytest.mark.parametrize(
    ("spec", "fragments"),
    [
        ("mu=0.2 force=5kN inner-radius=170mm outer-radius=205mm cone=100deg", ["--face", "cone=", "90deg"]),
        ("mu=0.2 force=5kN inner-radius=170mm outer-radius=205mm cone=0deg", ["--face", "cone="]),
        ("mu=0.2 force=5kN inner-radius=170mm outer-radius=205mm cone=20", ["--face", "cone="]),
        ("mu=0.2 force=5kN inner-radius=170mm outer-radius=205mm cone=2m", ["--face", "cone="]),
    ],
)
def test_cone_refusals(spec, fragments):
    assert_usage_error(run_taucli("spin-down", "--inertia", "1kg*m^2", "--omega0", "10rad/s", "--face", spec), *fragments)


def test_cone_clutch_in_batch_and_cli_as_in_python():
    """The same cone from a batch line, the command line and the Python API."""
    spec = "mu=0.2 force=5kN inner-radius=170mm outer-radius=205mm cone=20deg model=wear"
    python = taucli.spin_down(omega0="1500rpm", face=spec).results["torque_face"].value
    line = run_taucli("spin-down", "--batch", stdin='{"omega0": "1500rpm", "face": "%s"}\n' % spec)
    assert line.code == 0 and line.json()["results"]["torque_face"]["value"] == python
    cli = run_taucli("spin-down", "--omega0", "1500rpm", "--face", spec, "--get", "torque_face")
    assert float(cli.out) == pytest.approx(python, rel=1e-14)
    torque, _ = cone_reference(0.2, 5000, 0.17, 0.205, mpmath.radians(20), "wear")
    assert python == pytest.approx(float(torque), rel=1e-13)


# --- band-and-block brakes -----------------------------------------------------------------------


def blocks_reference(mu, blocks, block_angle, slack):
    """The band's tensions block by block: each block of angle 2θ, between T₀ on its slack side and
    T on its tight side, is held by the drum's push N and its friction μN at its middle; resolving
    across and along that middle radius, (T + T₀) sin θ − N = 0 and (T − T₀) cos θ − μN = 0, solved
    for (T, N) as a linear system, block after block from T₂. Returns (T₁, ΣμN)."""
    mu, half = mpmath.mpf(mu), mpmath.mpf(block_angle) / 2
    tension, rubbing = mpmath.mpf(slack), mpmath.mpf(0)
    for _ in range(blocks):
        matrix = mpmath.matrix([[mpmath.sin(half), -1], [mpmath.cos(half), -mu]])
        tension, normal = mpmath.lu_solve(matrix, mpmath.matrix([-tension * mpmath.sin(half), tension * mpmath.cos(half)]))
        rubbing += mu * normal
    return tension, rubbing


def test_band_and_block_khurmi():
    """Khurmi and Gupta, Theory of Machines, the band-and-block brake of 12 blocks of 15° on a drum
    600 mm across, the blocks 75 mm thick, μ = 0.3, its ends on pins 40 mm and 150 mm either side of
    the fulcrum, 250 N at 900 mm; drum and flywheel 1800 kg with k = 600 mm, from 300 rpm. The band's
    line is 75 mm out from the drum, so τ = (T₁ − T₂)(0.3 + 0.075) m (worked from the statement)."""
    report = taucli.spin_down(mass="1800kg", gyration="600mm", omega0="300rpm",
                              band="mu=0.3 blocks=12 block-angle=15deg radius=300mm thickness=75mm force=250N lever=900mm slack-arm=150mm tight-arm=40mm")
    result = values(report)
    ratio, _ = blocks_reference(0.3, 12, mpmath.radians(15), 1)
    slack = 250 * mpmath.mpf("0.9") / (mpmath.mpf("0.15") - mpmath.mpf("0.04") * ratio)
    torque = (ratio - 1) * slack * mpmath.mpf("0.375")
    inertia = 1800 * mpmath.mpf("0.6") ** 2
    assert result["tension_slack"] == pytest.approx(float(slack), rel=1e-13)
    assert result["tension_tight"] == pytest.approx(float(ratio * slack), rel=1e-13)
    assert result["torque_band"] == pytest.approx(float(torque), rel=1e-13)
    assert result["alpha0"] == pytest.approx(float(-torque / inertia), rel=1e-13)
    assert result["t_stop"] == pytest.approx(float(10 * mpmath.pi / (torque / inertia)), rel=1e-13)
    assert result["pressure_band"] is None


@pytest.mark.parametrize(("mu", "blocks", "degrees"), [(0.3, 12, 15), (0.25, 14, 15), (0.4, 1, 60), (1e-4, 8, 20), (0.5, 20, 18)])
def test_band_and_block_against_the_blocks_solved_one_by_one(mu, blocks, degrees):
    """T₁ from T₂ = 100 N grown block by block; the torque (T₁ − T₂)·r from the band's ends
    (without thickness, the friction's ΣμN·r summed over the blocks, which ties the two)."""
    result = values(taucli.spin_down(inertia="1kg*m^2", omega0="100rpm", band=f"mu={mu} blocks={blocks} block-angle={degrees}deg radius=0.2m tension=100N"))
    tight, rubbing = blocks_reference(mu, blocks, mpmath.radians(degrees), 100)
    assert result["tension_tight"] == pytest.approx(float(tight), rel=1e-13)
    assert result["torque_band"] == pytest.approx(float((tight - 100) * mpmath.mpf("0.2")), rel=1e-13)
    # the friction at the blocks' middles, resolved along the band, is T₁ − T₂ with each block's cos θ
    assert float(rubbing / mpmath.cos(mpmath.radians(degrees) / 2)) == pytest.approx(float(tight - 100), rel=1e-13)


@pytest.mark.parametrize("blocks", [1000, 100000])
def test_many_short_blocks_are_the_band(blocks):
    """Limit: n blocks of 2θ covering the same wrap W = 240° tend to the band's e^{μW} as n → ∞: with
    tan θ = θ + θ³/3 + … and artanh x = x + x³/3 + …, 2n·artanh(μ tan θ) = μW + μ(1 + μ²)W³/(12n²) + O(1/n⁴)."""
    band = values(taucli.spin_down(inertia="1kg*m^2", omega0="100rpm", band="mu=0.35 wrap=240deg radius=0.2m tension=100N"))
    lined = values(taucli.spin_down(inertia="1kg*m^2", omega0="100rpm",
                                    band=f"mu=0.35 blocks={blocks} block-angle={240 / blocks!r}deg radius=0.2m tension=100N"))
    mu, wrap = 0.35, math.radians(240)
    assert lined["tension_tight"] == pytest.approx(band["tension_tight"] * math.exp(mu * (1 + mu * mu) * wrap**3 / (12 * blocks**2)), rel=1e-11)
    assert lined["tension_tight"] > band["tension_tight"]


def test_band_and_block_same_in_other_units():
    si = values(taucli.spin_down(inertia="1kg*m^2", omega0="10rad/s", band="mu=0.3 blocks=10 block-angle=20deg radius=0.25m thickness=3cm tension=200N"))
    us = values(taucli.spin_down(inertia="1kg*m^2", omega0="10rad/s",
                                 band=f"mu=0.3 blocks=10 block-angle={math.radians(20)!r}rad radius={0.25 / 0.0254!r}in thickness={3 / 2.54!r}in "
                                      f"tension={200 / 4.4482216152605!r}lbf"))
    for key in ("torque_band", "tension_tight", "tension_slack", "t_stop"):
        assert us[key] == pytest.approx(si[key], rel=1e-12), key


@pytest.mark.parametrize(
    ("spec", "fragments"),
    [
        ("mu=0.3 blocks=12 radius=0.3m tension=1kN", ["--band", "block-angle="]),
        ("mu=0.3 block-angle=15deg radius=0.3m tension=1kN", ["--band", "blocks="]),
        ("mu=0.3 blocks=12 block-angle=15deg wrap=180deg radius=0.3m tension=1kN", ["--band", "wrap="]),
        ("mu=0.3 blocks=12 block-angle=15deg width=5cm radius=0.3m tension=1kN", ["--band", "width="]),
        ("mu=0.3 wrap=180deg thickness=5cm radius=0.3m tension=1kN", ["--band", "thickness="]),
        ("mu=0.3 blocks=2.5 block-angle=15deg radius=0.3m tension=1kN", ["--band", "whole number"]),
        ("mu=0.3 blocks=30 block-angle=15deg radius=0.3m tension=1kN", ["--band", "full turn"]),
        ("mu=1.2 blocks=3 block-angle=100deg radius=0.3m tension=1kN", ["--band", "locks itself", "tan θ"]),
    ],
)
def test_band_and_block_refusals(spec, fragments):
    assert_usage_error(run_taucli("spin-down", "--inertia", "1kg*m^2", "--omega0", "10rad/s", "--band", spec), *fragments)


# --- the temperature rise of a brake -------------------------------------------------------------


def heat_reference(inertia, omega0, torque):
    """The heat of a constant friction torque τ stopping a wheel: ∫ τ·|ω(t)| dt over the stop, with
    ω(t) = ω₀ − (τ/I)·t integrated by mpmath.quad from 0 to Iω₀/τ."""
    inertia, omega0, torque = (mpmath.mpf(x) for x in (inertia, omega0, torque))
    return mpmath.quad(lambda t: torque * abs(omega0 - torque / inertia * t), [0, inertia * omega0 / torque])


def test_temperature_rise_serway_brake_drums():
    """Serway and Vuille, College Physics (11th ed.), ch. 11 problem 24: a 1500 kg car at 30 m/s
    halts; its four 8.0 kg iron brake drums (c = 448 J/(kg·°C)) take its kinetic energy: ΔT =
    ½mv²/(4·8·448) = 47 °C (worked from the statement). Here a wheel holding that energy is stopped by a brake."""
    report = taucli.spin_down(inertia="10kg*m^2", ke0="675kJ", brake="force=2kN mu=0.4 radius=0.3m", heat_mass="32kg", specific_heat="448 J/(kg*K)")
    result = values(report)
    omega0 = mpmath.sqrt(2 * mpmath.mpf(675000) / 10)
    heat = heat_reference(10, omega0, mpmath.mpf("0.4") * 2000 * mpmath.mpf("0.3"))
    assert result["temperature_rise"] == pytest.approx(float(heat / (32 * 448)), rel=1e-13)
    assert result["temperature_rise"] == pytest.approx(47.08, abs=0.01)
    assert any("Temperature rise" in step.title for step in report.steps)


def test_temperature_rise_shares_the_heat_with_the_axle():
    """The brakes', faces' and bands' heat (not the axle's) warms the mass: a 1 N·m axle and a 3 N·m
    brake stopping 2 kg·m² from 10 rad/s give the brake three quarters of ½Iω₀²."""
    result = values(taucli.spin_down(inertia=2, omega0=10, friction=1, brake="force=30N mu=0.5 radius=0.2m", heat_mass="2kg", specific_heat="500 J/(kg*K)"))
    heat = heat_reference(2, 10, 4) * 3 / 4
    assert result["temperature_rise"] == pytest.approx(float(heat / 1000), rel=1e-13)
    alone = values(taucli.spin_down(inertia=2, omega0=10, friction=1, heat_mass="2kg", specific_heat="500 J/(kg*K)"))
    assert alone["temperature_rise"] == pytest.approx(float(heat_reference(2, 10, 1) / 1000), rel=1e-13)


def test_temperature_rise_same_in_other_units():
    si = values(taucli.spin_down(inertia="3kg*m^2", omega0="500rpm", face="mu=0.3 force=1kN inner-radius=5cm outer-radius=10cm", heat_mass="4kg",
                                 specific_heat="460 J/(kg*K)"))
    other = values(taucli.spin_down(inertia="3kg*m^2", omega0="500rpm", face="mu=0.3 force=1kN inner-radius=5cm outer-radius=10cm", heat_mass="4000g",
                                    specific_heat="0.46 kJ/(kg*K)"))
    assert other["temperature_rise"] == pytest.approx(si["temperature_rise"], rel=1e-14)
    assert si["temperature_rise"] == pytest.approx(si["work_face"] / (4 * 460), rel=1e-15)
    shown = run_taucli("spin-down", "--inertia", "3kg*m^2", "--omega0", "500rpm", "--face", "mu=0.3 force=1kN inner-radius=5cm outer-radius=10cm",
                       "--heat-mass", "4kg", "--specific-heat", "460 J/(kg*K)", "--get", "temperature_rise")
    assert shown.code == 0 and float(shown.out) == pytest.approx(si["temperature_rise"], rel=1e-12)


@pytest.mark.parametrize(
    ("args", "fragments"),
    [
        (["--brake", "force=10N mu=0.4 radius=0.2m", "--heat-mass", "2kg"], ["--specific-heat"]),
        (["--brake", "force=10N mu=0.4 radius=0.2m", "--specific-heat", "460 J/(kg*K)"], ["--heat-mass"]),
        (["--heat-mass", "2kg", "--specific-heat", "460 J/(kg*K)"], ["--heat-mass", "--brake"]),
        (["--brake", "force=10N mu=0.4 radius=0.2m", "--heat-mass", "2kg", "--specific-heat", "460 J/kg"], ["--specific-heat"]),
        (["--brake", "force=10N mu=0.4 radius=0.2m", "--heat-mass", "-2kg", "--specific-heat", "460 J/(kg*K)"], ["--heat-mass"]),
    ],
)
def test_temperature_rise_refusals(args, fragments):
    assert_usage_error(run_taucli("spin-down", "--inertia", "1kg*m^2", "--omega0", "10rad/s", *args), *fragments)


# --- long-shoe drum brakes -----------------------------------------------------------------------


def long_shoe_reference(mu, normal, radius, shoe_angle):
    """A long shoe of arc 2θ, its pressure p_max·cos φ (φ from its middle), per unit width: its
    resultant normal force along the middle N = ∫ p·cos φ·r dφ fixes p_max; its friction moment
    about the axle is τ = ∫ μ·p·r·r dφ, both over −θ..θ by mpmath.quad. Returns τ."""
    mu, normal, radius, half = mpmath.mpf(mu), mpmath.mpf(normal), mpmath.mpf(radius), mpmath.mpf(shoe_angle) / 2
    per_pmax = mpmath.quad(lambda phi: mpmath.cos(phi) * mpmath.cos(phi) * radius, [-half, half])
    pmax = normal / per_pmax
    return mpmath.quad(lambda phi: mu * pmax * mpmath.cos(phi) * radius * radius, [-half, half])


@pytest.mark.parametrize("degrees", [10, 60, 90, 120, 180])
def test_long_shoe_against_its_pressure_integrated(degrees):
    result = values(taucli.spin_down(inertia="1kg*m^2", omega0="100rpm", brake=f"force=500N mu=0.3 radius=0.2m shoe-angle={degrees}deg"))
    assert result["torque_brake"] == pytest.approx(float(long_shoe_reference(0.3, 500, 0.2, mpmath.radians(degrees))), rel=1e-13)


def test_long_shoe_on_a_lever_brakes_and_dynamometers_illustration():
    """A textbook's chapter "Brakes and Dynamometers", Illustration 1 (as a Python textbook
    companion transcribes it): a drum 0.32 m across, the shoe's contact 90°, μ = 0.35, 820 N at
    0.66 m on the lever, the shoe at 0.3 m and the friction's line 0.06 m from the fulcrum:
    printed 120.4553 N·m (with π taken as 3.14). N and the friction from the lever's moments,
    F ℓ = N x − f c, with f = τ/r from the pressure integrated round the arc."""
    result = values(taucli.spin_down(inertia="1kg*m^2", omega0="100rpm",
                                     brake="force=820N lever=0.66m pivot=0.3m offset=0.06m mu=0.35 radius=160mm shoe-angle=90deg"))
    assert result["torque_brake"] == pytest.approx(120.4553, abs=0.05)
    ratio = long_shoe_reference(1, 1, 1, mpmath.pi / 2)  # f/N for μ = 1, r = 1
    mu_equivalent = mpmath.mpf("0.35") * ratio
    normal = 820 * mpmath.mpf("0.66") / (mpmath.mpf("0.3") - mu_equivalent * mpmath.mpf("0.06"))
    assert result["force_brake"] == pytest.approx(float(normal), rel=1e-13)
    assert result["torque_brake"] == pytest.approx(float(mu_equivalent * normal * mpmath.mpf("0.16")), rel=1e-13)


def test_a_short_arc_is_the_short_shoe():
    """Limit: μ′ = 4μ sin θ/(2θ + sin 2θ) → μ as θ → 0 (μ′/μ = 1 + θ²/6 + …)."""
    short = values(taucli.spin_down(inertia="1kg*m^2", omega0="100rpm", brake="force=500N mu=0.3 radius=0.2m"))
    arc = values(taucli.spin_down(inertia="1kg*m^2", omega0="100rpm", brake="force=500N mu=0.3 radius=0.2m shoe-angle=0.01deg"))
    half = math.radians(0.005)
    assert arc["torque_brake"] == pytest.approx(short["torque_brake"] * (1 + half * half / 6), rel=1e-12)


def test_long_shoe_same_in_other_units():
    si = values(taucli.spin_down(inertia="1kg*m^2", omega0="100rpm", brake="force=500N mu=0.3 radius=0.2m shoe-angle=100deg"))
    us = values(taucli.spin_down(inertia="1kg*m^2", omega0="100rpm",
                                 brake=f"force={500 / 4.4482216152605!r}lbf mu=0.3 radius={0.2 / 0.0254!r}in shoe-angle={math.radians(100)!r}rad"))
    assert us["torque_brake"] == pytest.approx(si["torque_brake"], rel=1e-12)


@pytest.mark.parametrize("spec", ["force=5N mu=0.3 radius=0.2m shoe-angle=200deg", "force=5N mu=0.3 radius=0.2m shoe-angle=2",
                                  "force=5N mu=0.3 radius=0.2m shoe-angle=3m"])
def test_long_shoe_refusals(spec):
    assert_usage_error(run_taucli("spin-down", "--inertia", "1kg*m^2", "--omega0", "10rad/s", "--brake", spec), "--brake", "shoe-angle=")
