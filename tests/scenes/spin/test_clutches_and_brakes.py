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

