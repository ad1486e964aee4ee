"""Band brakes (--band), block brakes on a lever (--brake lever= pivot= offset=) and a face's
pressure model and largest pressure (--face model= pmax=) (#35): published problems with their
printed answers, references written from the physics at 50 digits (the band's tension grown
element by element with mpmath.odefun and its friction integrated along the wrap; a face's clamp
force and torque integrated over the annulus; a lever's two equilibrium equations solved as a
linear system), energy balances as properties, and the refusals."""

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


def band_reference(mu, wrap, radius, slack):
    """The band from its elements: an element dφ under tension T presses the drum with T dφ and
    slides, so friction adds dT = μ T dφ (tension grown with mpmath.odefun from T₂ at the slack
    end); the torque is the friction summed along the wrap, ∫ μ T(φ) r dφ. Returns (T₁, τ)."""
    mu, wrap, radius, slack = (mpmath.mpf(x) for x in (mu, wrap, radius, slack))
    tension = mpmath.odefun(lambda phi, t: mu * t, 0, slack)
    torque = mpmath.quad(lambda phi: mu * tension(phi) * radius, [0, wrap])
    return tension(wrap), torque


def lever_reference(force, lever, pivot, offset, mu):
    """N and the friction force f on a block brake's shoe from the lever's two equations, solved as
    a linear system: moments about the pivot F ℓ − N x + f c = 0, and sliding f = μ N."""
    matrix = mpmath.matrix([[mpmath.mpf(pivot), -mpmath.mpf(offset)], [mpmath.mpf(mu), -1]])
    normal, friction = mpmath.lu_solve(matrix, mpmath.matrix([mpmath.mpf(force) * mpmath.mpf(lever), 0]))
    return normal, friction


def test_simple_band_brake_mechdiploma():
    """mechdiploma.com, "simple band brake" (a lever 40 cm long, drum 40 cm across, the band over
    5/8 of it, one end at the fulcrum, the other on a pin 8 cm from it, μ = 0.25, 500 N at the
    lever's end, the drum turning so that the pin's end is the tight one): printed T₁ = 2500 N,
    T₂ = 936.3 N, braking torque 312.74 N·m (with e^{μθ} rounded to 2.67)."""
    result = values(taucli.spin_down(inertia="1kg*m^2", omega0="100rpm", band="mu=0.25 wrap=225deg radius=20cm force=500N lever=40cm tight-arm=8cm"))
    assert result["tension_tight"] == pytest.approx(2500, rel=1e-14)
    assert result["tension_slack"] == pytest.approx(936.3, rel=2e-3)
    assert result["torque_band"] == pytest.approx(312.74, rel=5e-4)
    tight, torque = band_reference(0.25, math.radians(225), 0.2, result["tension_slack"])
    assert result["torque_band"] == pytest.approx(float(torque), rel=1e-13)
    assert result["tension_tight"] == pytest.approx(float(tight), rel=1e-13)


def test_band_brake_khurmi_operating_force():
    """Khurmi & Gupta, Theory of Machines, the band brake over 3/4 of a 450 mm drum giving 225 N·m,
    μ = 0.25, one end at the fulcrum and the other on a pin 100 mm from it, the force at 500 mm:
    printed P = 289 N with the tight end on the pin and P = 89 N with the slack end there."""
    common = dict(inertia="1kg*m^2", omega0="100rpm", find="band.force", want="torque_band=225N*m")
    tight = taucli.spin_down(band="mu=0.25 wrap=270deg radius=225mm lever=500mm tight-arm=100mm", **common)
    slack = taucli.spin_down(band="mu=0.25 wrap=270deg radius=225mm lever=500mm slack-arm=100mm", **common)
    assert tight.results["band.force"].value == pytest.approx(289, abs=0.5)
    assert slack.results["band.force"].value == pytest.approx(89, abs=0.5)


def test_differential_band_brake_from_the_lever_moments():
    """A differential band brake: F ℓ = T₂ b − T₁ a, the tight end on the far side of the pivot
    helping the force; against the element-by-element reference."""
    spec = "mu=0.3 wrap=250deg radius=0.25m force=100N lever=0.6m slack-arm=0.2m tight-arm=0.03m"
    result = values(taucli.impulse(inertia="2kg*m^2", omega0="300rpm", torque="0N*m", duration="0.5s", band=spec))
    ratio = mpmath.e ** (mpmath.mpf("0.3") * mpmath.radians(250))
    slack = 100 * mpmath.mpf("0.6") / (mpmath.mpf("0.2") - ratio * mpmath.mpf("0.03"))
    tight, torque = band_reference(0.3, math.radians(250), 0.25, slack)
    assert result["tension_slack"] == pytest.approx(float(slack), rel=1e-13)
    assert result["torque_band"] == pytest.approx(float(torque), rel=1e-13)
    assert result["tension_tight"] == pytest.approx(float(tight), rel=1e-13)


def test_band_lining_pressure_and_units():
    """p_max = T₁/(r w); the same band in inches and pounds-force gives the same SI answers."""
    si = values(taucli.spin_down(inertia="1kg*m^2", omega0="10rad/s", band="mu=0.3 wrap=180deg radius=0.2m tension=100N width=5cm"))
    us = values(taucli.spin_down(inertia="1kg*m^2", omega0="10rad/s",
                                 band=f"mu=0.3 wrap=3.14159265358979rad radius={0.2 / 0.0254!r}in tension={100 / 4.4482216152605!r}lbf width={5 / 2.54!r}in"))
    assert si["pressure_band"] == pytest.approx(si["tension_tight"] / (0.2 * 0.05), rel=1e-15)
    for key in ("torque_band", "tension_tight", "tension_slack", "pressure_band", "t_stop"):
        assert us[key] == pytest.approx(si[key], rel=1e-12), key
    shown = run_taucli("spin-down", "--inertia", "1kg*m^2", "--omega0", "10rad/s", "--band", "mu=0.3 wrap=180deg radius=0.2m tension=100N width=5cm",
                       "--to", "pressure_band=psi", "--get", "pressure_band")
    assert float(shown.out) == pytest.approx(si["pressure_band"] / 6894.757293168361, rel=1e-12)


@settings(max_examples=30, deadline=None)
@given(inertia=st.floats(0.01, 100), omega0=st.floats(1, 500), mu=st.floats(0.02, 1.0), wrap=st.floats(0.2, 12), radius=st.floats(0.02, 2),
       tension=st.floats(1, 1e4), axle=st.sampled_from([None, 0.5]))
def test_band_takes_the_energy_it_stops(inertia, omega0, mu, wrap, radius, tension, axle):
    """Property: a wheel stopped by a band (and an axle's friction) has given all its energy to
    them, each its torque's share: KE0 = work_band + work_friction, work_band = τ_band θ_stop."""
    result = values(taucli.spin_down(inertia=inertia, omega0=f"{omega0!r} rad/s", friction=axle,
                                     band=f"mu={mu!r} wrap={wrap!r}rad radius={radius!r}m tension={tension!r}N", energy=True))
    assert result["work_band"] + (result.get("work_friction") or 0.0) == pytest.approx(result["KE0"], rel=1e-12)
    assert result["work_band"] == pytest.approx(result["torque_band"] * result["theta_stop"], rel=1e-12)
    assert result["tension_tight"] == pytest.approx(tension * math.exp(mu * wrap), rel=1e-12)


@settings(max_examples=30, deadline=None)
@given(omega0=st.floats(1, 300), torque=st.sampled_from([0.0]) | st.floats(1e-3, 50), duration=st.floats(0.01, 5), mu=st.floats(0.02, 1.0), tension=st.floats(1, 500))
def test_band_in_impulse_balances_energy(omega0, torque, duration, mu, tension):
    """Property: a torque along ω₀ against a band over Δt: KE1 − KE0 = τθ − work_band, and the
    net angular impulse J − τ_band Δt while it turns (I Δω)."""
    report = taucli.impulse(inertia="0.5kg*m^2", omega0=f"{omega0!r} rad/s", torque=f"{torque!r} N*m", duration=f"{duration!r} s",
                            band=f"mu={mu!r} wrap=200deg radius=0.1m tension={tension!r}N")
    result = values(report)
    assert result["work_band"] >= 0
    if result["omega1"] > 0:  # it turned all along Δt
        theta = (omega0 + result["omega1"]) / 2 * duration
        assert result["KE1"] - result["KE0"] == pytest.approx(torque * theta - result["work_band"], rel=1e-9, abs=1e-9 * result["KE0"])
        assert result["J_net"] == pytest.approx(torque * duration - result["torque_band"] * duration, rel=1e-9, abs=1e-9 * result["J"] + 1e-12)


def test_block_brake_gate_short_shoe():
    """GATE (Mechanical Engineering), a short-shoe external drum brake as posted with its solution
    at gkseries.com: drum 500 mm across, a = 1000 mm (the force's arm), b = 500 mm (the shoe's),
    c = 200 mm (the friction's line), μ = 0.35, F = 100 N, turning so that F·a = N·b − μN·c:
    printed N = 232.558 N, braking torque 20.35 N·m."""
    result = values(taucli.spin_down(inertia="1kg*m^2", omega0="100rpm",
                                     brake="force=100N lever=1000mm pivot=500mm offset=200mm mu=0.35 radius=250mm"))
    assert result["force_brake"] == pytest.approx(232.558, abs=5e-4)
    assert result["torque_brake"] == pytest.approx(20.35, abs=5e-3)
    normal, friction = lever_reference(100, 1.0, 0.5, 0.2, 0.35)
    assert result["force_brake"] == pytest.approx(float(normal), rel=1e-14)
    assert result["torque_brake"] == pytest.approx(float(friction * mpmath.mpf("0.25")), rel=1e-14)


@pytest.mark.parametrize("offset", [-0.1, 0.0, 0.1])
def test_block_brake_normal_force_against_the_lever_equations(offset):
    """Self-energizing (c > 0), neutral (c = 0) and de-energizing (c < 0): N from the lever's
    equations; static μ gives the holding torque through its own N."""
    report = taucli.impulse(inertia="1kg*m^2", omega0="0rad/s", torque="1N*m", duration="1s",
                            brake=f"force=50N lever=0.8m pivot=0.3m offset={offset}m mu-k=0.3 mu-s=0.4 radius=0.15m")
    result = values(report)
    normal, _ = lever_reference(50, 0.8, 0.3, offset, 0.3)
    assert result["force_brake"] == pytest.approx(float(normal), rel=1e-14)
    assert result["omega1"] == 0  # held: 1 N·m is far below μs N_s r
    assert any("static friction holds" in note for note in report.notes)


def shigley_clutch(model):
    return values(taucli.spin_down(inertia="1kg*m^2", omega0="100rpm", face=f"mu=0.3 force=4kN inner-radius=87.5mm outer-radius=125mm model={model}"))


def test_plate_clutch_shigley():
    """Shigley's Mechanical Engineering Design (9th ed.), ch. 16, the plate clutch of one pair of
    surfaces 250 mm OD by 175 mm ID, f = 0.30, F = 4 kN: torque capacity 127.5 N·m under uniform
    wear and 128.8 N·m under uniform pressure; p_a = F/(2π r_i (r_o − r_i)) and F/(π(r_o² − r_i²))."""
    wear, uniform = shigley_clutch("wear"), shigley_clutch("uniform")
    assert wear["torque_face"] == pytest.approx(127.5, abs=0.05)
    assert uniform["torque_face"] == pytest.approx(128.8, abs=0.05)
    assert wear["pressure_face"] == pytest.approx(194.0e3, rel=1e-3)
    assert uniform["pressure_face"] == pytest.approx(159.8e3, rel=1e-3)


@pytest.mark.parametrize("model", ["uniform", "wear"])
def test_face_pmax_gives_the_clamp_force_and_torque(model):
    """pmax= with the radii: F = ∫ p 2πr dr and τ = ∫ μ p 2πr² dr with p = p_max (uniform) or
    p_max Ri/r (worn in), at 50 digits; and force= of that F gives back p_max."""
    spec = f"mu=0.25 pmax=0.8MPa inner-radius=60mm outer-radius=110mm model={model} surfaces=2"
    result = values(taucli.spin_down(inertia="1kg*m^2", omega0="100rpm", face=spec))
    p, inner, outer, mu = mpmath.mpf(8e5), mpmath.mpf("0.06"), mpmath.mpf("0.11"), mpmath.mpf("0.25")
    pressure = (lambda r: p) if model == "uniform" else (lambda r: p * inner / r)
    force = mpmath.quad(lambda r: pressure(r) * 2 * mpmath.pi * r, [inner, outer])
    torque = 2 * mpmath.quad(lambda r: mu * pressure(r) * 2 * mpmath.pi * r * r, [inner, outer])
    assert result["force_face"] == pytest.approx(float(force), rel=1e-14)
    assert result["torque_face"] == pytest.approx(float(torque), rel=1e-14)
    back = values(taucli.spin_down(inertia="1kg*m^2", omega0="100rpm",
                                   face=f"mu=0.25 force={result['force_face']!r}N inner-radius=60mm outer-radius=110mm model={model} surfaces=2"))
    assert back["pressure_face"] == pytest.approx(8e5, rel=1e-14)


def test_old_pressure_key_is_read_as_the_model_with_a_note():
    report = taucli.spin_down(inertia="1kg*m^2", omega0="100rpm", face="mu=0.3 force=4kN inner-radius=87.5mm outer-radius=125mm pressure=wear")
    assert report.results["torque_face"].value == pytest.approx(shigley_clutch("wear")["torque_face"], rel=1e-15)
    assert any("pressure=wear read as model=wear" in note for note in report.notes)


@pytest.mark.parametrize(
    ("args", "fragments"),
    [
        (["--face", "mu=0.3 pressure=1MPa inner-radius=5cm outer-radius=12cm"], ["--face", "pmax="]),
        (["--face", "mu=0.3 force=1kN pmax=1MPa outer-radius=12cm"], ["--face", "not both"]),
        (["--face", "mu=0.3 pmax=1MPa outer-radius=12cm model=wear"], ["--face", "inner-radius="]),
        (["--face", "mu=0.3 force=1kN model=worn"], ["--face", "model="]),
        (["--band", "mu=0.3 radius=0.2m tension=10N"], ["--band", "wrap="]),
        (["--band", "mu=0.3 wrap=180deg radius=0.2m tension=10N force=5N"], ["--band", "tension="]),
        (["--band", "mu=0.3 wrap=180deg radius=0.2m force=5N slack-arm=1cm"], ["--band", "lever="]),
        (["--band", "mu=0.3 wrap=300deg radius=0.2m force=5N lever=1m slack-arm=5cm tight-arm=3cm"], ["--band", "locks itself"]),
        (["--brake", "force=5N mu=0.5 lever=1m pivot=0.1m offset=0.3m radius=0.2m"], ["--brake", "locks itself"]),
        (["--brake", "force=5N mu=0.5 lever=1m radius=0.2m"], ["--brake", "pivot="]),
        (["--brake", "force=5N mu=0.5 offset=1m radius=0.2m"], ["--brake", "offset="]),
        (["--band", "mu=0.3 wrap=180deg radius=0.2m tension=10N", "--torque", "-5N*m"], ["--band", "turn it back"]),
        (["--brake", "force=5N mu=0.5 lever=1m pivot=0.5m offset=0.1m radius=0.2m", "--torque", "-5N*m"], ["--brake", "turn it back"]),
    ],
)
def test_refusals(args, fragments):
    assert_usage_error(run_taucli("spin-down", "--inertia", "1kg*m^2", "--omega0", "10rad/s", *args), *fragments)


def test_impulse_refuses_a_band_against_the_torque():
    assert_usage_error(run_taucli("impulse", "--inertia", "1kg*m^2", "--omega0", "10rad/s", "--torque", "-5N*m", "--duration", "1s",
                                  "--band", "mu=0.3 wrap=180deg radius=0.2m tension=10N"), "--band", "turn it back")


def test_a_brake_without_a_lever_is_unchanged():
    """force= without lever= is still the normal force N (no force_brake result)."""
    result = values(taucli.spin_down(inertia="1kg*m^2", omega0="10rad/s", brake="force=100N mu=0.4 radius=0.5m"))
    assert result["torque_brake"] == pytest.approx(20.0, rel=1e-15)
    assert "force_brake" not in result


def test_a_face_given_pmax_needs_no_gravity():
    """pmax= sets the clamp force: no weight, so no standard gravity assumed, and --g is unused."""
    report = taucli.spin_down(inertia="1kg*m^2", omega0="100rpm", face="mu=0.3 pmax=1MPa inner-radius=5cm outer-radius=12cm")
    assert not any("standard gravity" in note for note in report.notes)
    assert_usage_error(run_taucli("spin-down", "--inertia", "1kg*m^2", "--omega0", "10rad/s", "--g", "9.8",
                                  "--face", "mu=0.3 pmax=1MPa inner-radius=5cm outer-radius=12cm"), "--g")


def test_band_static_and_kinetic_coefficients():
    """At rest the band holds up to (T₁ − T₂)r with μs; past it the drum turns against μk's torque."""
    spec = "mu-s=0.4 mu-k=0.3 wrap=180deg radius=0.1m tension=100N"
    kinetic = 100 * math.expm1(0.3 * math.pi) * 0.1
    holding = 100 * math.expm1(0.4 * math.pi) * 0.1
    held = values(taucli.impulse(inertia="1kg*m^2", omega0="0rad/s", torque=f"{(kinetic + holding) / 2!r}N*m", duration="1s", band=spec))
    assert held["omega1"] == 0 and held["torque_band"] == pytest.approx(kinetic, rel=1e-14)
    turns = values(taucli.impulse(inertia="1kg*m^2", omega0="0rad/s", torque=f"{holding * 1.01!r}N*m", duration="1s", band=spec))
    assert turns["omega1"] == pytest.approx(holding * 1.01 - kinetic, rel=1e-12)
