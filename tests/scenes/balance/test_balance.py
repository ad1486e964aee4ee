"""taucli balance: balancing of rotating masses (Khurmi & Gupta, Theory of Machines, ch. 21; Irodov 1.281).

References from the physics, not the solver's complex sums: each mass's centrifugal force
m r ω² along its radius and its weight, as 3-vectors at their points along the shaft (mpmath at
40 digits); a balanced rotor is one whose forces and moments about any point add to zero, and the
bearings' loads are the forces that hold the rest in equilibrium (Newton's laws in the frame that
turns with the shaft, solved as a linear system).
"""

from __future__ import annotations

import json
import math

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taucli
from conftest import assert_usage_error, run_taucli

DEG = math.pi / 180


def results(report):
    return {name: value.value for name, value in report.results.items()}


def _spec(m, r, angle_deg, plane=None):
    return f"mass={m!r}kg radius={r!r}m angle={angle_deg!r}deg" + ("" if plane is None else f" plane={plane!r}m")


def _vector(m, r, angle_deg, plane, omega2=1, g=0):
    """A mass's centrifugal force (per ω², or at ω² = omega2) and weight, and where they act: 3-vectors in mpmath."""
    theta = mpmath.mpf(angle_deg) * mpmath.pi / 180
    radial = mpmath.matrix([mpmath.cos(theta), mpmath.sin(theta), 0])
    point = mpmath.mpf(r) * radial + mpmath.matrix([0, 0, mpmath.mpf(plane or 0)])
    force = mpmath.mpf(m) * mpmath.mpf(r) * omega2 * radial + mpmath.matrix([0, 0, -mpmath.mpf(m) * g])
    return point, force


def _cross(a, b):
    return mpmath.matrix([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]])


def _resultants(masses):
    """Σ F and Σ r × F about the origin of centrifugal forces per ω² (masses: (m, r, θ in deg, plane))."""
    force, moment = mpmath.matrix(3, 1), mpmath.matrix(3, 1)
    for m, r, angle, plane in masses:
        point, f = _vector(m, r, angle, plane)
        force += f
        moment += _cross(point, f)
    return force, moment


def test_khurmi_four_masses_in_one_plane():
    """Khurmi & Gupta, Theory of Machines, Example 21.1: 200, 300, 240 and 260 kg at 0.2, 0.15, 0.25
    and 0.3 m, successive angles 45°, 75°, 135°; the balancing mass at 0.2 m. The book: 116 kg at
    201.48° (its graphical and rounded sums; the exact polygon closes at 201.31°)."""
    masses = [(200, 0.2, 0), (300, 0.15, 45), (240, 0.25, 120), (260, 0.3, 255)]
    found = results(taucli.balance(mass=[_spec(*m) for m in masses], balance_radius="0.2 m"))
    assert round(found["balance_mass"]) == 116
    assert abs(found["balance_angle"] / DEG - 201.48) < 0.2
    with mpmath.workdps(40):
        force, _ = _resultants([(*m, 0) for m in masses])
        size = mpmath.sqrt(force[0] ** 2 + force[1] ** 2)
        angle = mpmath.atan2(-force[1], -force[0]) % (2 * mpmath.pi)
    assert found["balance_mr"] == pytest.approx(float(size), rel=1e-14)
    assert found["balance_mass"] == pytest.approx(float(size / mpmath.mpf("0.2")), rel=1e-14)
    assert found["balance_angle"] == pytest.approx(float(angle), rel=1e-14)


def test_irodov_1_281_the_speed_at_which_the_lower_bearing_is_free():
    """Irodov 1.281: a horizontal uniform rod, 1.40 kg and 100 cm, turns about a vertical axis
    through its end A, at the middle of the 55 cm axis. The book: the lower end's horizontal force
    vanishes at ω = √(2g/l) = 6.0 rad/s, and the upper end's is then F = mgl₀/l = 25 N."""
    done = run_taucli("balance", "--mass", "mass=1.4kg length=100cm", "--bearing", "-27.5cm", "--bearing", "27.5cm", "--vertical", "--g", "9.8",
                      "--find", "speed", "--want", "bearing_force_A=0", "--json")
    assert done.code == 0, done.err
    found = {key: value["value"] for key, value in done.json()["results"].items()}
    assert round(found["speed"], 1) == 6.0 and round(found["bearing_force_B"]) == 25
    # from the physics: the rod's weight at its centre (0.5 m out) and its centrifugal pull there,
    # held by horizontal forces at z = ±0.275 m: forces add to zero, moments about A add to zero
    with mpmath.workdps(40):
        g, l, m, half = mpmath.mpf("9.8"), mpmath.mpf("0.55"), mpmath.mpf("1.4"), mpmath.mpf("0.5")
        omega = mpmath.sqrt(2 * g / l)  # lower force zero: m g half = (l/2) m ω² half
        upper = m * omega**2 * half
    assert found["speed"] == pytest.approx(float(omega), rel=1e-9)
    assert found["bearing_force_B"] == pytest.approx(float(upper), rel=1e-9)
    assert found["bearing_force_A"] == pytest.approx(0, abs=1e-9)


@st.composite
def scenes(draw):
    count = draw(st.integers(1, 5))

    def number(low, high):
        return draw(st.floats(low, high).map(lambda x: round(x, 6)))

    masses = [(number(0.01, 500), number(0.001, 2), number(0, 360), number(-2, 2)) for _ in range(count)]
    a = number(-3, 3)
    b = a + draw(st.sampled_from([-1, 1])) * number(0.05, 3)
    return masses, a, b


@settings(max_examples=60, deadline=None)
@given(scenes(), st.floats(0.5, 400), st.booleans())
def test_random_scenes_balance_and_their_bearings_hold_the_rotor(scene, omega, vertical):
    """Any masses along a shaft: the two balancing masses the scene reports, put at their angles in
    their planes, leave no force and no moment (3-vectors, mpmath); and the bearings' loads, with
    the masses' centrifugal forces (and weights, on a vertical shaft), hold the rotor in equilibrium."""
    masses, a, b = scene
    g = 9.80665
    found = results(taucli.balance(mass=[_spec(*m) for m in masses], plane=[f"{a!r} m", f"{b!r} m"], speed=omega,
                                   bearing=[f"{a!r} m", f"{b!r} m"], vertical=vertical))
    with mpmath.workdps(40):
        balancers = [(found[f"balance_mr_{p}"], 1, (found[f"balance_angle_{p}"] or 0) / DEG, plane) for p, plane in (("A", a), ("B", b))]
        force, moment = _resultants([*masses, *balancers])
        scale = sum(m * r for m, r, *_ in masses) * (1 + max(abs(p) for *_, p in masses) + abs(a) + abs(b))
        assert float(mpmath.norm(force)) <= 1e-12 * scale
        assert float(mpmath.norm(moment)) <= 1e-12 * scale
        # the bearings: F_on_shaft at A and B (minus what the shaft puts on them) plus every mass's force = 0, moments too
        total_f, total_m = mpmath.matrix(3, 1), mpmath.matrix(3, 1)
        for m, r, angle, plane in masses:
            point, f = _vector(m, r, angle, plane, omega2=mpmath.mpf(omega) ** 2, g=g if vertical else 0)
            total_f += f
            total_m += _cross(point, f)
        for name, z in (("A", a), ("B", b)):
            size, angle = found[f"bearing_force_{name}"], found[f"bearing_angle_{name}"] or 0
            on_shaft = -size * mpmath.matrix([mpmath.cos(angle), mpmath.sin(angle), 0])
            total_f += on_shaft
            total_m += _cross(mpmath.matrix([0, 0, z]), on_shaft)
        load = (omega**2 + (g if vertical else 0)) * scale
        assert abs(float(total_f[0])) <= 1e-11 * load and abs(float(total_f[1])) <= 1e-11 * load
        assert abs(float(total_m[0])) <= 1e-11 * load and abs(float(total_m[1])) <= 1e-11 * load
    assert found["force_unbalanced"] == pytest.approx(omega**2 * found["unbalance"], rel=1e-14)


def test_one_mass_per_unit_is_the_same_scene():
    """Unit invariance: the same masses in kg, m, deg and in g, mm, rad give the same SI results."""
    si = results(taucli.balance(mass=["mass=2kg radius=0.3m angle=30deg plane=0.1m", "mass=3kg radius=0.2m angle=150deg plane=0.4m"],
                                plane=["0 m", "0.5 m"], balance_radius="0.25 m", speed="300 rpm", bearing=["-0.1 m", "0.6 m"]))
    other = results(taucli.balance(mass=[f"mass=2000g radius=300mm angle={math.radians(30)!r}rad plane=10cm",
                                         f"mass=3000g radius=200mm angle={math.radians(150)!r}rad plane=400mm"],
                                   plane=["0 mm", "50 cm"], balance_radius="250 mm", speed="5 rev/s", bearing=["-100 mm", "600 mm"]))
    assert set(si) == set(other)
    for key, value in si.items():
        assert other[key] == pytest.approx(value, rel=1e-12, abs=1e-12), key


def test_command_line_batch_and_python_agree():
    masses = ["mass=200kg radius=0.2m angle=0deg", "mass=300kg radius=0.15m angle=45deg"]
    done = run_taucli("balance", "--mass", masses[0], "--mass", masses[1], "--balance-radius", "0.2m", "--json")
    line = json.dumps({"mass": masses, "balance_radius": "0.2m"})
    batch = run_taucli("balance", "--batch", stdin=line + "\n")
    python = results(taucli.balance(mass=masses, balance_radius="0.2m"))
    cli = {key: value["value"] for key, value in done.json()["results"].items()}
    batched = {key: value["value"] for key, value in json.loads(batch.out)["results"].items()}
    assert cli == batched == python
    assert python["balance_mass"] == pytest.approx(math.hypot(40 + 45 / math.sqrt(2), 45 / math.sqrt(2)) / 0.2, rel=1e-14)


def test_find_a_balancing_radius_and_a_mass_in_a_spec():
    """--find over the inputs: the radius that makes the balancing mass 100 kg, and the third
    mass's mass= that leaves an unbalance of 40 kg·m (two roots)."""
    masses = ["--mass", "mass=200kg radius=0.2m angle=0deg", "--mass", "mass=300kg radius=0.15m angle=45deg"]
    done = run_taucli("balance", *masses, "--find", "balance_radius", "--want", "balance_mass=100kg", "--get", "balance_radius")
    assert done.code == 0, done.err
    assert float(done.out) == pytest.approx(math.hypot(40 + 45 / math.sqrt(2), 45 / math.sqrt(2)) / 100, rel=1e-9)
    done = run_taucli("balance", *masses, "--mass", "radius=1m angle=180deg", "--find", "mass3.mass", "--want", "unbalance=40kg*m", "--json")
    assert done.code == 0, done.err
    found = done.json()["results"]
    x, y = 40 + 45 / math.sqrt(2), 45 / math.sqrt(2)  # (x − m₃, y) of size 40: m₃ = x ∓ √(40² − y²), the smaller reported
    assert found["mass3.mass"]["value"] == pytest.approx(x - math.sqrt(40**2 - y**2), rel=1e-9)
    assert sorted(found["roots"]["value"]) == pytest.approx(sorted([x - math.sqrt(1600 - y * y), x + math.sqrt(1600 - y * y)]), rel=1e-9)


@pytest.mark.parametrize(("args", "fragments"), [
    ([], ("--mass",)),
    (["--mass", "radius=0.2m"], ("--mass", "mass=")),
    (["--mass", "mass=2kg"], ("--mass", "radius=")),
    (["--mass", "mass=2kg radius=0.2m colour=red"], ("--mass",)),
    (["--mass", "mass=-2kg radius=0.2m"], ("--mass",)),
    (["--mass", "mass=2kg radius=-0.2m"], ("--mass",)),
    (["--mass", "mass=2kg radius=0.2m angle=3"], ("--mass",)),
    (["--mass", "mass=2kg radius=0.2m plane=1m", "--mass", "mass=2kg radius=0.2m"], ("--mass", "plane=")),
    (["--mass", "mass=2kg radius=0.2m", "--plane", "0m", "--plane", "0m"], ("--plane",)),
    (["--mass", "mass=2kg radius=0.2m", "--plane", "0m", "--plane", "1m", "--plane", "2m"], ("--plane",)),
    (["--mass", "mass=2kg radius=0.2m", "--balance-radius", "0.1m", "--balance-radius", "0.2m"], ("--balance-radius",)),
    (["--mass", "mass=2kg radius=0.2m", "--bearing", "0m"], ("--bearing",)),
    (["--mass", "mass=2kg radius=0.2m", "--bearing", "0m", "--bearing", "1m"], ("--speed",)),
    (["--mass", "mass=2kg radius=0.2m", "--vertical"], ("--vertical",)),
    (["--mass", "mass=2kg radius=0.2m", "--speed", "-3rad/s"], ("--speed",)),
    (["--mass", "mass=2kg radius=0.2m", "--speed", "300"], ("--speed",)),
])
def test_bad_inputs_exit_2_with_one_line(args, fragments):
    assert_usage_error(run_taucli("balance", *args), *fragments)


def test_masses_that_balance_already_need_no_balancing_mass_and_have_no_angle():
    found = taucli.balance(mass=["mass=2kg radius=0.3m angle=10deg", "mass=3kg radius=0.2m angle=190deg"])
    assert found.results["balance_mr"].value == 0 and found.results["balance_angle"].value is None
    assert any("balance already" in note for note in found.notes)
