"""#42 item 3: a dimension left out is never assumed silently.

Class check: for every scene that takes a body by its shape, every shape, every axis and every
optional dimension, a run that leaves the dimension out is refused, or gives the same results as
one that gives it (the dimension cancels: a disc about its symmetry axis), or has a note naming
the option. The numbers themselves are checked against the closed forms written here in mpmath
(a cylinder about a diameter: M(R²/4 + L²/12); a tube: M((R₁² + R₂²)/4 + L²/12)).
"""

from __future__ import annotations

import json

import mpmath
import pytest

import taucli
from conftest import run_taucli
from taucli.core.errors import InputError
from taucli.scenes.shapes import SHAPES

DIMS = {"radius": "0.2 m", "inner_radius": "0.1 m", "outer_radius": "0.3 m", "length": "0.7 m", "width": "0.4 m", "height": "0.5 m", "depth": "0.6 m"}


def _through_centre(shape: str, axis: str) -> bool:
    return SHAPES[shape].axis(axis).through_centre


RUNS = {
    "inertia": lambda body: taucli.inertia(**body),
    "spin-down": lambda body: taucli.spin_down(**body, omega0="10 rad/s", friction="1 N*m"),
    "impulse": lambda body: taucli.impulse(**body, omega0="0 rad/s", torque="1 N*m", duration="1 s"),
    "pendulum": lambda body: taucli.pendulum(**body, **({"offset": "0.5 m"} if _through_centre(body["shape"], body["axis"]) else {})),
    "gyro (a rotor turned)": lambda body: taucli.gyro(**body, spin="100 rad/s", precession="1 rad/s"),
    "gyro (a top)": lambda body: taucli.gyro(**body, spin="100 rad/s", cm_distance="0.1 m"),
    "flywheel": lambda body: taucli.flywheel(**body, omega_mean="300 rpm", fluctuation=0.02),
    "drive": lambda body: taucli.drive(**body, motor_inertia="1e-4 kg*m^2", ratio=10, until_omega="3000 rpm", in_time="0.2 s"),
}
CASES = [(scene, shape, axis.name, dim) for scene in RUNS for shape, found in SHAPES.items() for axis in found.axes for dim in found.optional]


def _values(report) -> dict:
    return {name: value.value for name, value in report.results.items()}


@pytest.mark.parametrize("scene, shape, axis, dim", CASES)
def test_a_dimension_left_out_is_refused_cancels_or_is_named_in_a_note(scene, shape, axis, dim):
    body = {"shape": shape, "axis": axis, "mass": "2 kg", **{d: DIMS[d] for d in SHAPES[shape].dims}}
    try:
        given = RUNS[scene]({**body, dim: DIMS[dim]})
    except InputError:
        pytest.skip(f"{scene} refuses a {shape} about {axis} with its {dim} given (not this check's)")
    try:
        left_out = RUNS[scene](body)
    except InputError:
        return  # refused: no number assumed
    if _values(left_out) == _values(given):
        return  # the dimension cancels about this axis
    assert any(dim in note for note in left_out.notes), (scene, shape, axis, dim, left_out.notes)  # the option, as Python spells it


def test_the_issues_tube_about_a_diameter_says_it_is_taken_as_flat():
    mpmath.mp.dps = 30
    m, r1, r2, length = (mpmath.mpf(x) for x in ("2", "0.2", "0.3", "1"))
    tube = ("inertia", "tube", "--mass", "2kg", "--inner-radius", "0.2m", "--outer-radius", "0.3m", "--axis", "diameter", "--json")
    left_out, given = json.loads(run_taucli(*tube).out), json.loads(run_taucli(*tube, "--length", "1m").out)
    assert left_out["results"]["I"]["value"] == pytest.approx(float(m * (r1**2 + r2**2) / 4), rel=1e-14)
    assert given["results"]["I"]["value"] == pytest.approx(float(m * ((r1**2 + r2**2) / 4 + length**2 / 12)), rel=1e-14)
    assert any("no --length" in note for note in left_out["notes"]) and not any("--length" in note for note in given["notes"])


@pytest.mark.parametrize("scene, args", [
    ("inertia", ["disc", "--mass", "2kg", "--radius", "0.2m", "--axis", "diameter"]),
    ("pendulum", ["--shape", "disc", "--mass", "2kg", "--radius", "0.2m", "--axis", "diameter", "--offset", "0.5m"]),
    ("spin-down", ["--shape", "disc", "--mass", "2kg", "--radius", "0.2m", "--axis", "diameter", "--omega0", "10rad/s", "--friction", "1N*m"]),
])
def test_a_disc_about_a_diameter_names_length_on_the_command_line(scene, args):
    run = run_taucli(scene, *args, "--no-steps")
    assert run.code == 0, run.err
    assert "no --length" in " ".join(run.out.split()), run.out


@pytest.mark.parametrize("run", [
    lambda: taucli.inertia(shape="ring", mass="1 kg", radius="0.1 m", part=["disc mass=1kg radius=0.1m axis=diameter"]),
    lambda: taucli.atwood(m1="1 kg", m2="2 kg", pulley_radius="0.1 m", part=["disc mass=1kg radius=0.1m axis=diameter"]),
    lambda: taucli.impulse(inertia=1, omega0="1 rad/s", couple=["disc mass=1kg radius=0.1m axis=diameter omega0=0"]),
    lambda: taucli.impulse(inertia=1, omega0="1 rad/s", part_after=["disc mass=1kg radius=0.1m axis=diameter"]),
    lambda: taucli.pendulum(shape="rod", mass="1 kg", length="1 m", axis="end", part=["disc mass=1kg radius=0.1m axis=diameter offset=1m"]),
], ids=["inertia part", "atwood pulley part", "impulse couple", "impulse part after", "pendulum part"])
def test_a_part_about_a_diameter_without_length_is_named_in_a_note(run):
    assert any("no length= in" in note for note in run().notes)


@pytest.mark.parametrize("shape", sorted(SHAPES))
def test_a_dimension_of_another_shape_is_refused_naming_it_not_a_crash(shape):
    """Found by the fuzz test after #42 item 14: `inertia tube --radius=1m` (a disc's dimension on a
    tube, no mass) crashed (exit 1, TypeError) where the check of an unused dimension probed I with
    every dimension given. Each shape, with each dimension no shape of its own takes, and no mass."""
    own = {*SHAPES[shape].dims, *SHAPES[shape].optional}
    for other in sorted({d for s in SHAPES.values() for d in (*s.dims, *s.optional)} - own):
        done = run_taucli("inertia", shape, f"--{other.replace('_', '-')}=1m")
        assert done.code == 2 and "internal error" not in done.err and len(done.err.strip().splitlines()) == 1, (shape, other, done.err)
