"""#42 item 14: a body given by its shape needs no --mass for a result the mass cancels from (a
pendulum's period, a disc's precession rate); the results that depend on it are null with the
reason, and refused naming --mass when asked for with --get. And a dimension I about the axis
does not use is not required (a plate's width for the axis along its width).

References from the physics, written here: a rod about its end, I = ML²/3 and d = L/2, swings
with T = 2π√(I/(Mgd)) = 2π√(2L/(3g)); a disc's precession Ω = Mgr/(Iω), I = ½MR²."""

from __future__ import annotations

import math
import random

import mpmath
import pytest
from conftest import assert_usage_error, run_taucli

import taucli

mpmath.mp.dps = 40


def values(report):
    return {key: value.value for key, value in report.results.items()}


def test_the_period_of_a_rod_solves_for_its_length_without_its_mass():
    # T = 2π√(2L/(3g))  =>  L = 3gT²/(8π²)
    run = run_taucli("pendulum", "--shape", "rod", "--axis", "end", "--g", "9.80", "--find", "length", "--want", "period_small=1.2s", "--get", "length")
    assert run.code == 0, run.err
    want = 3 * mpmath.mpf("9.80") * mpmath.mpf("1.2") ** 2 / (8 * mpmath.pi**2)
    assert float(run.out.split()[0]) == pytest.approx(float(want), rel=1e-9)


def test_a_discs_precession_rate_needs_no_mass():
    # Ω = Mgr/(Iω) with I = ½MR²: Ω = 2gr/(R²ω)
    run = run_taucli("gyro", "--shape", "disc", "--radius", "0.1m", "--spin", "100rad/s", "--cm-distance", "0.05m", "--get", "omega_p")
    assert run.code == 0, run.err
    want = 2 * mpmath.mpf("9.80665") * mpmath.mpf("0.05") / (mpmath.mpf("0.1") ** 2 * 100)
    assert float(run.out) == pytest.approx(float(want), rel=1e-12)


def test_a_result_that_needs_the_mass_is_refused_when_asked_for_naming_mass():
    run = run_taucli("pendulum", "--shape", "rod", "--axis", "end", "--length", "1m", "--get", "I")
    assert_usage_error(run, "--mass")
    shown = run_taucli("pendulum", "--shape", "rod", "--axis", "end", "--length", "1m", "--json").json()
    assert shown["results"]["I"]["value"] is None
    assert any("--mass" in note and "I" in note for note in shown["notes"])


def test_the_mass_is_still_required_where_every_result_depends_on_it():
    # a torque on a disc of unknown mass: no α, no ω or θ at a time (#46: to the stop its mean
    # speed ω₀/2 does not depend on the mass, so without --time that one result is answered)
    run = run_taucli("spin-down", "--shape", "disc", "--radius", "0.2m", "--omega0", "30rad/s", "--torque", "-2N*m", "--time", "2s")
    assert_usage_error(run, "--mass")
    stop = run_taucli("spin-down", "--shape", "disc", "--radius", "0.2m", "--omega0", "30rad/s", "--torque", "-2N*m", "--json").json()
    assert stop["results"]["omega_mean"]["value"] == 15 and stop["results"]["t_stop"]["value"] is None


def test_a_plates_width_is_not_needed_about_the_axis_along_its_width():
    # I = MH²/12 about the in-plane axis through the centre parallel to the width
    report = taucli.inertia(shape="plate", mass="3kg", height="0.4m", axis="center-width")
    assert values(report)["I"] == pytest.approx(float(3 * mpmath.mpf("0.4") ** 2 / 12), rel=1e-14)
    # about the normal axis both are needed: still refused
    assert_usage_error(run_taucli("inertia", "plate", "--mass", "3kg", "--height", "0.4m", "--axis", "normal"), "--width")


# The class check: every scene with a body, random shapes, with and without --mass.
SHAPES = [
    ("disc", {"radius": (0.05, 0.5)}, None), ("ring", {"radius": (0.05, 0.5)}, None), ("sphere", {"radius": (0.05, 0.5)}, None),
    ("shell", {"radius": (0.05, 0.5)}, None), ("rod", {"length": (0.2, 2.0)}, "end"), ("rod", {"length": (0.2, 2.0)}, "center"),
    ("tube", {"inner_radius": (0.02, 0.05), "outer_radius": (0.06, 0.3)}, None), ("cone", {"radius": (0.05, 0.3)}, None),
    ("plate", {"width": (0.1, 1.0), "height": (0.1, 1.0)}, "edge-width"), ("plate", {"height": (0.1, 1.0)}, "center-width"),
    ("box", {"width": (0.1, 1.0), "height": (0.1, 1.0), "depth": (0.1, 1.0)}, "depth"),
]
SCENES = {
    "inertia": {},
    "pendulum": {"angle0": "30deg", "angle": "10deg"},
    "gyro": {"spin": "300rad/s", "cm_distance": "0.05m"},
    "spin_down": {"omega0": "30rad/s", "alpha": "-2rad/s^2", "time": "3s"},
    "impulse": {"omega0": "3rad/s", "omega1": "5rad/s", "duration": "2s"},
    "flywheel": {"omega_min": "90rad/s", "omega_max": "100rad/s"},
}


def _body(rng: random.Random):
    shape, dims, axis = rng.choice(SHAPES)
    given = {name: f"{rng.uniform(*bounds):.6g} m" for name, bounds in dims.items()}
    if axis is not None:
        given["axis"] = axis
    return shape, given


def _solve(scene: str, shape: str, body: dict, mass: str | None):
    kw = dict(SCENES[scene], **body, **({"mass": mass} if mass else {}))
    if scene == "gyro" and shape not in ("disc", "ring", "sphere", "shell", "tube"):
        return None
    kw["shape"] = shape
    if scene == "pendulum" and body.get("axis") not in ("end", "edge-width"):
        kw["offset"] = "0.3 m"  # the pivot off the centre of mass
    try:
        return getattr(taucli, scene)(**kw)
    except taucli.InputError:
        return None


@pytest.mark.parametrize("seed", range(24))
@pytest.mark.parametrize("scene", list(SCENES))
def test_every_result_free_of_the_mass_is_given_without_it(scene, seed):
    rng = random.Random(f"{scene}{seed}")
    shape, body = _body(rng)
    light, heavy = (f"{rng.uniform(0.5, 50):.6g} kg" for _ in range(2))
    with_light, with_heavy = _solve(scene, shape, body, light), _solve(scene, shape, body, heavy)
    if with_light is None or with_heavy is None:
        pytest.skip("this body does not fit this scene")
    without = _solve(scene, shape, body, None)
    a, b = values(with_light), values(with_heavy)
    free = [key for key in a if a[key] is not None and isinstance(a[key], (float, int, bool)) and b.get(key) is not None
            and (a[key] == b[key] or (not isinstance(a[key], bool) and math.isclose(a[key], b[key], rel_tol=1e-9, abs_tol=1e-300)))]
    if not free:
        assert without is None
        return
    assert without is not None, f"{scene} {shape} {body}: refused though {free} do not depend on the mass"
    got = values(without)
    for key in a:
        if key in free:
            assert got[key] == pytest.approx(a[key], rel=1e-9, abs=1e-300), key
        else:  # depends on the mass (or none either way): null, and the note names --mass where it had a value
            assert got[key] is None, key
            if a[key] is not None:
                assert any("mass" in note and key in note for note in without.notes), key
                assert without.needs[key][0] == "mass"
