"""taucli torque: τ = r × F and L = r × mv against references written from the geometry at 40
digits (determinants, distances to a line), in any units, and the errors a user can cause."""

from __future__ import annotations

import math

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taucli
from conftest import assert_usage_error, run_taucli
from taucli.core.errors import InputError
from taucli.scenes.torque import cross, difference_of_products, sin_exact

MP_DPS = 40  # the references' precision, set for each test by conftest


def values(report):
    return {name: value.value for name, value in report.results.items()}


def leibniz(m):
    """A 3×3 determinant by its definition: Σ over permutations σ of sign(σ) Π m[i][σ(i)]."""
    from itertools import permutations

    total = mpmath.mpf(0)
    for p in permutations(range(3)):
        inversions = sum(1 for i in range(3) for j in range(i + 1, 3) if p[i] > p[j])
        total += (-1) ** inversions * m[0][p[0]] * m[1][p[1]] * m[2][p[2]]
    return total


def det_cross(r, f):
    """r × F as the determinant |x̂ ŷ ẑ; r; F|, each component the determinant with that unit
    vector in the first row (mpmath at 40 digits: exact for products of doubles)."""
    rows = [[mpmath.mpf(c) for c in r], [mpmath.mpf(c) for c in f]]
    return [leibniz([unit, *rows]) for unit in ([1, 0, 0], [0, 1, 0], [0, 0, 1])]


def line_distance(r, f):
    """The distance from the origin to the line through r along F: |r − (r·F/F·F) F| (40 digits)."""
    r = [mpmath.mpf(c) for c in r]
    f = [mpmath.mpf(c) for c in f]
    t = sum(a * b for a, b in zip(r, f)) / sum(b * b for b in f)
    return mpmath.sqrt(sum((a - t * b) ** 2 for a, b in zip(r, f)))


def test_the_issue_example():
    result = values(taucli.torque(r="0.3,0.4,0 m", force="0,0,10 N"))
    assert (result["tau_x"], result["tau_y"], result["tau_z"]) == (4.0, -3.0, 0.0)
    assert result["tau"] == 5.0
    assert result["lever_arm"] == 0.5
    assert result["sense"] == "counter-clockwise about (0.8, -0.6, 0)"


def test_a_wrench():
    """A 0.25 m wrench along +x, 80 N pushed along +y at its end: 20 N·m counter-clockwise from +z."""
    result = values(taucli.torque(r="25,0,0 cm", force="0,80,0 N"))
    assert result["tau_z"] == pytest.approx(20.0, rel=1e-15)
    assert result["sense"] == "counter-clockwise seen from +z"
    assert values(taucli.torque(r="25,0,0 cm", force="0,-80,0 N"))["sense"] == "clockwise seen from +z"


components = st.one_of(st.just(0.0), st.floats(1e-6, 1e6), st.floats(-1e6, -1e-6))  # as an input may be
vectors = st.tuples(components, components, components)


@settings(max_examples=300, deadline=None)
@given(r=vectors, f=vectors)
def test_cross_product_against_the_determinant(r, f):
    exact = det_cross(r, f)
    got = cross(r, f)
    for g, e in zip(got, exact):
        assert abs(g - e) <= 4 * math.ulp(float(abs(e))) if e else g == 0


@settings(max_examples=300, deadline=None)
@given(f=st.tuples(*[st.floats(0.1, 10)] * 3), k=st.floats(0.1, 10), tilt=st.floats(-1e-9, 1e-9))
def test_nearly_parallel_r_and_f_keep_their_digits(f, k, tilt):
    """r almost along F: each component a difference of near-equal products, kept to a few ulp."""
    r = (k * f[0] + tilt, k * f[1], k * f[2] - tilt)
    for g, e in zip(cross(r, f), det_cross(r, f)):
        assert abs(g - e) <= 4 * math.ulp(float(abs(e))) + 1e-300


def test_difference_of_products_where_the_naive_form_loses_everything():
    a, b = 1 + 2**-30, 1 - 2**-30  # a·b = 1 − 2⁻⁶⁰, which rounds to 1
    assert a * b - 1.0 == 0.0
    assert difference_of_products(a, b, 1.0, 1.0) == -(2.0**-60)


@settings(max_examples=200, deadline=None)
@given(r=vectors, f=vectors.filter(lambda v: math.hypot(*v) > 1e-3))
def test_lever_arm_is_the_distance_to_the_line_of_action(r, f):
    result = values(taucli.torque(r=r, force=f))
    assert result["lever_arm"] == pytest.approx(float(line_distance(r, f)), rel=1e-12, abs=1e-9 * math.hypot(*r))


@settings(max_examples=200, deadline=None)
@given(lever=st.floats(1e-3, 1e3), force=st.one_of(st.just(0.0), st.floats(1e-3, 1e3), st.floats(-1e3, -1e-3)), degrees=st.one_of(st.just(0.0), st.floats(1e-6, 720), st.floats(-720, -1e-6)))
def test_the_planar_form_is_the_vector_form_in_the_plane(lever, force, degrees):
    """--force F --lever r --angle θ is r = (r, 0, 0), F = F(cos θ, sin θ, 0)."""
    theta = mpmath.radians(degrees)
    planar = values(taucli.torque(force=f"{force!r} N", lever=f"{lever!r} m", angle=f"{degrees!r} deg"))
    reference = det_cross((lever, 0, 0), (force * mpmath.cos(theta), force * mpmath.sin(theta), 0))[2]
    assert planar["tau_z"] == pytest.approx(float(reference), rel=1e-12, abs=1e-12 * lever * abs(force))
    assert planar["tau_x"] == planar["tau_y"] == 0
    if force:
        assert planar["lever_arm"] == pytest.approx(float(lever * abs(mpmath.sin(theta))), rel=1e-12, abs=1e-12 * lever)


def test_the_planar_book_problem():
    """20 N at 0.5 m, 60° from the lever: τ = 0.5 × 20 × sin 60° = 8.66 N·m, counter-clockwise."""
    result = values(taucli.torque(force="20N", lever="0.5m", angle="60deg"))
    assert result["tau_z"] == pytest.approx(5 * math.sqrt(3), rel=1e-15)
    assert result["lever_arm"] == pytest.approx(0.25 * math.sqrt(3), rel=1e-15)


def test_sin_is_exact_at_whole_quarter_turns():
    assert sin_exact(math.pi) == 0.0
    assert sin_exact(-math.pi / 2) == -1.0
    assert sin_exact(math.radians(450)) == 1.0
    assert sin_exact(0.5) == math.sin(0.5)
    report = taucli.torque(force="10N", lever="1m", angle="180deg")
    assert report.results["tau_z"].value == 0.0
    assert any("along its lever" in note for note in report.notes)


def test_the_same_in_any_units():
    si = values(taucli.torque(r="0.3,0.4,0 m", force="0,0,10 N", mass="2kg", velocity="1,2,3 m/s"))
    other = values(taucli.torque(r="30cm,400mm,0m", force="(0, 0, 0.01 kN)", mass="2000 g", velocity="[3.6, 7.2, 10.8 km/h]"))
    for key, value in si.items():
        assert other[key] == pytest.approx(value, rel=1e-14, abs=1e-15) if isinstance(value, float) else other[key] == value


def test_net_torque_of_several_forces_and_the_resultants_line():
    """Two parallel forces on a beam along x: 10 N up at x = 1 m, 30 N up at x = 3 m. The
    resultant, 40 N, acts at x = (10·1 + 30·3)/40 = 2.5 m, so its lever arm is 2.5 m."""
    report = taucli.torque(r=["1,0,0 m", "3,0,0 m"], force=["0,10,0 N", "0,30,0 N"])
    result = values(report)
    assert result["tau_z"] == 100.0
    assert result["lever_arm"] == pytest.approx(2.5, rel=1e-15)
    assert [row[-1] for row in report.tables["forces"].rows] == [1.0, 3.0]


def test_a_couple_has_no_resultant_line():
    report = taucli.torque(r=["1,0,0 m", "-1,0,0 m"], force=["0,5,0 N", "0,-5,0 N"])
    assert report.results["tau_z"].value == 10.0
    assert report.results["lever_arm"].value is None
    assert any("couple" in note for note in report.notes)


def test_angular_momentum_of_a_particle():
    """3 kg at (2, 0, 0) m moving at (0, 4, 0) m/s: L = 2 × 3 × 4 = 24 kg·m²/s along +z."""
    result = values(taucli.torque(r="2,0,0 m", mass="3kg", velocity="0,4,0 m/s"))
    assert (result["L_x"], result["L_y"], result["L_z"], result["L"]) == (0.0, 0.0, 24.0, 24.0)
    assert result["L_sense"] == "counter-clockwise seen from +z"
    assert "tau" not in result


@settings(max_examples=200, deadline=None)
@given(r0=vectors, v=vectors, m=st.floats(1e-3, 1e3), t=st.floats(-10, 10))
def test_a_free_particle_keeps_its_angular_momentum(r0, v, m, t):
    """No force, no torque: along the straight line r0 + v t, L = r × mv does not change, and it
    equals m|v| times the line's distance from the point."""
    r1 = tuple(a + b * t for a, b in zip(r0, v))
    r1 = tuple(c if abs(c) > 1e-30 else 0.0 for c in r1)  # an input is 0 or at least 1e-40 in size
    before = values(taucli.torque(r=r0, mass=m, velocity=v))
    after = values(taucli.torque(r=r1, mass=m, velocity=v))
    scale = m * math.hypot(*v) * (math.hypot(*r0) + math.hypot(*r1)) + 1e-300
    for key in ("L_x", "L_y", "L_z"):
        assert after[key] == pytest.approx(before[key], abs=1e-13 * scale)
    if any(v):
        assert before["L"] == pytest.approx(float(m * mpmath.sqrt(sum(mpmath.mpf(c) ** 2 for c in v)) * line_distance(r0, v)), abs=1e-12 * scale)


def test_several_particles_add():
    result = values(taucli.torque(r=["1,0,0 m", "0,1,0 m"], mass=["1kg", "2kg"], velocity=["0,1,0 m/s", "1,0,0 m/s"]))
    assert result["L_z"] == 1.0 - 2.0


def test_forces_and_particles_share_their_positions_one_each():
    result = values(taucli.torque(r="2,0,0 m", force="0,5,0 N", mass="1kg", velocity="0,3,0 m/s"))
    assert result["tau_z"] == 10.0 and result["L_z"] == 6.0


@pytest.mark.parametrize(
    "given, name, fragment",
    [
        ({}, "force", "is required"),
        ({"r": "1,0,0 m", "force": ["0,1,0 N", "0,2,0 N"]}, "r", "is given 1 times"),
        ({"r": "1 m", "force": "0,1,0 N"}, "r", "expected a vector"),
        ({"force": "20N"}, "lever", "is given 0 times"),
        ({"r": "1,0,0 m", "force": "0,1,0 N", "lever": "1m"}, "lever", "goes with a force given as a size"),
        ({"r": "1,0,0 m", "mass": ["1kg", "2kg"], "velocity": "0,1,0 m/s"}, "mass", "each particle"),
        ({"r": "1,0 m", "force": "0,1,0 N"}, "{r}", "three components"),
        ({"r": "1, 2m, 0 m", "force": "0,1,0 N"}, "{r}", "one unit after the last"),
        ({"r": "1,0,0 kg", "force": "0,1,0 N"}, "{r} (x)", "length"),
    ],
)
def test_errors_name_the_option(given, name, fragment):
    with pytest.raises(InputError) as caught:
        taucli.torque(**given)
    assert fragment in str(caught.value)
    assert caught.value.args[0] == name or name in str(caught.value)


def test_command_line_and_json():
    run = run_taucli("torque", "--r", "1,0,0 m", "--force", "0,2,0 N", "--r", "0,1,0 m", "--force", "3,0,0 N", "--json")
    assert run.code == 0, run.err
    document = run.json()
    assert document["results"]["tau_z"]["value"] == -1.0
    assert [row["lever_arm"] for row in document["forces"]] == [1.0, 1.0]
    assert document["inputs"]["r1"] == {"value": [1.0, 0.0, 0.0], "unit": "m"}
    assert_usage_error(run_taucli("torque", "--r", "1,0,0 m", "--force", "0,1 N"), "--force", "three components")


def test_forces_not_in_one_plane_reduce_to_a_wrench():
    """F₁ = (0,0,5) N at (0,1,0) m and F₂ = (0,3,0) N at (2,0,0) m: τ = (5, 0, 6) N·m, F = (0, 3, 5) N,
    τ·F ≠ 0. The central axis is where the torque is least (its part along F alone): the distance
    to it is the least |p| over the points p about which τ − p × F is parallel to F."""
    report = taucli.torque(r=["0,1,0 m", "2,0,0 m"], force=["0,0,5 N", "0,3,0 N"])
    f = [mp(0), mp(3), mp(5)]
    tau = [mp(5), mp(0), mp(6)]
    # p ⟂ F on the central axis solves F × p = τ_⊥ with τ_⊥ = τ − (τ·F/F·F)F: p = (τ_⊥ × F)/|F|² rotated, |p| = |τ_⊥|/|F|.
    tf = sum(a * b for a, b in zip(tau, f)) / sum(b * b for b in f)
    perp = [a - tf * b for a, b in zip(tau, f)]
    distance = mpmath.sqrt(sum(c * c for c in perp)) / mpmath.sqrt(sum(b * b for b in f))
    assert report.results["lever_arm"].value == pytest.approx(float(distance), rel=1e-15)
    assert any("wrench" in note for note in report.notes)


def mp(x):
    return mpmath.mpf(x)


# --- about a point, and a particle by its momentum (#34 item 11) -----------------------------


def test_hrw_pebble_about_the_origin_and_about_a_point():
    """Halliday, Resnick & Walker, Fundamentals of Physics, ch. 11 (torque as a vector): F = (2.0 N)î
    − (3.0 N)k̂ acts on a pebble at r = (0.50 m)ĵ − (2.0 m)k̂. The torque about the origin, and
    about the point (2.0 m, 0, −3.0 m): the book prints (−1.5 N·m)î − (4.0 N·m)ĵ − (1.0 N·m)k̂ for both."""
    origin = values(taucli.torque(r="0,0.5,-2 m", force="2,0,-3 N"))
    about = values(taucli.torque(r="0,0.5,-2 m", force="2,0,-3 N", about="2,0,-3 m"))
    for result in (origin, about):
        assert (result["tau_x"], result["tau_y"], result["tau_z"]) == (-1.5, -4.0, -1.0)
    # the reference: the determinant with r − a in the second row, at 40 digits
    want = det_cross([0 - 2, 0.5 - 0, -2 + 3], [2, 0, -3])
    assert [about["tau_x"], about["tau_y"], about["tau_z"]] == [float(w) for w in want]


@settings(max_examples=60, deadline=None)
@given(st.lists(st.one_of(st.just(0.0), st.floats(1e-6, 10), st.floats(-10, -1e-6)), min_size=9, max_size=9))
def test_about_a_point_is_the_torque_of_r_minus_a(c):
    """τ about a = (r − a) × F (the determinant at 40 digits), and = τ about the origin − a × F."""
    r, f, a = c[0:3], c[3:6], c[6:9]
    result = values(taucli.torque(r=[r], force=[f], about=a))
    want = det_cross([mpmath.mpf(x) - mpmath.mpf(y) for x, y in zip(r, a)], f)
    scale = sum(abs(x) for x in r + a) * sum(abs(x) for x in f) + 1e-300
    for key, w in zip(("tau_x", "tau_y", "tau_z"), want):
        assert abs(result[key] - float(w)) <= 4e-16 * scale


def test_hrw_object_angular_momentum_from_its_momentum():
    """Halliday, Resnick & Walker, Fundamentals of Physics, ch. 11: a 2.00 kg object at d = (2.00 m)î
    + (4.00 m)ĵ − (3.00 m)k̂ with v = −(6.00 m/s)î + (3.00 m/s)ĵ + (3.00 m/s)k̂: L about the origin
    is (42.0 î + 24.0 ĵ + 60.0 k̂) kg·m²/s. Given by its momentum p = mv = (−12, 6, 6) kg·m/s, the same."""
    by_momentum = values(taucli.torque(r="2,4,-3 m", momentum="-12,6,6 kg*m/s"))
    by_velocity = values(taucli.torque(r="2,4,-3 m", mass="2 kg", velocity="-6,3,3 m/s"))
    for result in (by_momentum, by_velocity):
        assert (result["L_x"], result["L_y"], result["L_z"]) == (42.0, 24.0, 60.0)
    assert by_momentum["L"] == pytest.approx(math.sqrt(42**2 + 24**2 + 60**2), rel=1e-15)


def test_momentum_in_other_units_and_about_a_point():
    """p in N·s or g·cm/s is the same momentum; about a, L = (r − a) × p (a particle moving straight
    through the point has none about it)."""
    si = values(taucli.torque(r="1,2,0 m", momentum="3,0,0 kg*m/s", about="0,1,0 m"))
    other = values(taucli.torque(r="100,200,0 cm", momentum="3e5,0,0 g*cm/s", about="0,1,0 m"))
    assert si["L_z"] == pytest.approx(-3.0, rel=1e-15) and other["L_z"] == pytest.approx(-3.0, rel=1e-12)
    through = values(taucli.torque(r="1,2,0 m", momentum="3,0,0 N*s", about="0,2,0 m"))
    assert through["L"] == 0.0


@pytest.mark.parametrize(
    "argv, fragments",
    [
        (("--r", "1,0,0 m", "--momentum", "0,1,0 kg*m/s", "--mass", "1kg"), ("--momentum", "conflicts with --velocity and --mass")),
        (("--r", "1,0,0 m", "--momentum", "0,1,0 m/s"), ("--momentum", "momentum")),
        (("--force", "10N", "--lever", "1m", "--about", "1,0,0 m"), ("--about", "goes with forces given as vectors")),
        (("--r", "1,0,0 m", "--force", "0,1,0 N", "--about", "1 m"), ("--about", "expected one point")),
    ],
)
def test_about_and_momentum_refusals_are_one_line(argv, fragments):
    assert_usage_error(run_taucli("torque", *argv), *fragments)
