"""#46 item 8: a whole body of parts, some off the axis they were placed about, moved to a
parallel axis: the parallel-axis theorem on the body's centre of mass, I = I_cm + M d², with I_cm
about that centre (not about the axis the parts were built on). References written from the
physics (tests/references/placed_body.py): I about any point as Σ (I_c + m|p − A|²) part by part,
and Hibbeler's wheel by ∫ r² dm over its ring and spokes.
"""

from __future__ import annotations

import json

import mpmath
import pytest
from hypothesis import given, settings, strategies as st

import taucli
from conftest import assert_usage_error, run_taucli
from references import relative_error
from references.placed_body import body, own_inertia, placed, wheel_about_rim
from taucli.core.errors import InputError

SPOKES = [f"rod mass=2kg length=0.5m axis=end angle={a}deg" for a in (0, 90, 180, 270)]


def test_hibbeler_17_14_a_wheel_with_spokes_about_a_point_on_its_rim():
    """Hibbeler, Engineering Mechanics: Dynamics, 17-14: a thin ring of 10 kg and four slender
    spokes of 2 kg, radius 500 mm, about A on the rim: I_A = 7.67 kg·m² (I_O = 3.17 kg·m²)."""
    exact = wheel_about_rim()
    args = ["inertia", "ring", "--mass", "10kg", "--radius", "500mm", *(a for spoke in SPOKES for a in ("--part", spoke)), "--body-offset", "500mm"]
    line = run_taucli(*args, "--get", "I", "--get", "I_cm")
    assert line.code == 0, line.err
    got, about_cm = (float(x) for x in line.out.split())
    assert round(got, 2) == 7.67 and round(about_cm, 2) == 3.17  # the book's
    assert relative_error(got, exact) < 1e-14
    batch = run_taucli("inertia", "--batch", stdin=json.dumps({"shape": "ring", "mass": "10 kg", "radius": "0.5 m", "part": SPOKES, "body_offset": "0.5 m"}) + "\n")
    assert batch.code == 0, batch.err
    assert relative_error(json.loads(batch.out)["results"]["I"]["value"], exact) < 1e-14
    report = taucli.inertia("ring", mass="10 kg", radius="0.5 m", part=SPOKES, body_offset="0.5 m")
    assert relative_error(report.results["I"].value, exact) < 1e-14


def test_a_body_whose_centre_of_mass_is_off_the_axis_it_was_built_on():
    """A 2 kg disc (r 0.1 m) with a 1 kg point on its rim: built about the disc's centre, I_O =
    0.02 kg·m², but its centre of mass is 1/30 m off it, and I_cm = I_O − M c² = 0.01667 kg·m².
    Moved 1 m from that centre: 3.01667 kg·m² (the old tree refused the point off the axis)."""
    parts = [(2, own_inertia("disc", 2, 0.1), (0, 0)), (1, 0, placed(0.1, 0))]
    exact = body(parts, 1)
    report = taucli.inertia("disc", mass="2 kg", radius="0.1 m", part=["point mass=1kg offset=0.1m"], body_offset="1 m").results
    assert relative_error(report["I_cm"].value, exact["I_cm"]) < 1e-14
    assert relative_error(report["I"].value, exact["I"]) < 1e-14
    assert report["I_cm"].value < 0.02  # not I about the axis it was built on


SHAPES = st.sampled_from(["point", "disc", "rod", "given"])


@st.composite
def placed_parts(draw):
    """A disc or ring centred on the axis (or the shape moved by --offset), and one to four
    parts: points, discs moved by offset=, rods about an end, a given I moved by offset=, each
    at its angle= round the axis."""
    shape = draw(st.sampled_from(["disc", "ring"]))
    mass, radius = draw(st.floats(0.01, 100)), draw(st.floats(0.01, 10))
    kw = {"shape": shape, "mass": mass, "radius": radius}
    where = (0.0, 0.0)
    if draw(st.booleans()):
        kw["offset"] = draw(st.floats(0.001, 10))
        where = (kw["offset"], 0.0)
    pieces = [(mass, own_inertia(shape, mass, radius), where)]
    specs = []
    for _ in range(draw(st.integers(1, 4))):
        kind, m = draw(SHAPES), draw(st.floats(0.01, 100))
        d, degrees = draw(st.floats(0.001, 10)), draw(st.sampled_from([0.0, 90.0, 180.0, -90.0, 45.0]) | st.floats(0.01, 360) | st.floats(-360, -0.01))
        angle = f"angle={degrees!r}deg"
        a = mpmath.radians(degrees)
        if kind == "point":
            specs.append(f"point mass={m!r}kg offset={d!r}m {angle}")
            pieces.append((m, 0, placed(d, a)))
        elif kind == "disc":
            r = draw(st.floats(0.01, 10))
            specs.append(f"disc mass={m!r}kg radius={r!r}m offset={d!r}m {angle}")
            pieces.append((m, own_inertia("disc", m, r), placed(d, a)))
        elif kind == "rod":
            specs.append(f"rod mass={m!r}kg length={2 * d!r}m axis=end {angle}")
            pieces.append((m, own_inertia("rod", m, 2 * d), placed(d, a)))
        else:
            own = draw(st.floats(0.001, 100))
            specs.append(f"inertia={own!r}kg*m^2 mass={m!r}kg offset={d!r}m {angle}")
            pieces.append((m, own, placed(d, a)))
    return {**kw, "part": specs}, pieces


@settings(max_examples=60, deadline=None)
@given(drawn=placed_parts(), distance=st.just(0.0) | st.floats(1e-6, 20), direction=st.floats(0, 6.3))
def test_random_bodies_moved_off_their_centre_of_mass(drawn, distance, direction):
    """I_cm and I about an axis d from the centre of mass, against Σ (I_c + m|p − A|²) over the
    parts at A = c + d(cos u, sin u) for a random u (the result must not depend on it). Budget:
    1e-12 times the cancellation in I_O − M|c|² that the reference's route does not have."""
    kw, pieces = drawn
    report = taucli.inertia(**kw, body_offset=f"{distance!r} m").results
    exact = body(pieces, distance, direction)
    loss = float(max(1, exact["I_O"] / exact["I_cm"]))
    assert relative_error(report["I_cm"].value, exact["I_cm"]) < 1e-12 * loss
    assert relative_error(report["I"].value, exact["I"]) < 1e-12 * loss
    assert relative_error(report["mass"].value, exact["M"]) < 1e-14


def test_two_parts_off_the_axis_need_their_angles():
    refused = run_taucli("inertia", "disc", "--mass", "2kg", "--radius", "0.1m", "--part", "point mass=1kg offset=0.1m",
                         "--part", "point mass=1kg offset=0.1m", "--body-offset", "1m")
    assert_usage_error(refused, "--part 2 angle=", "--body-offset", "two or more parts are off the axis")
    with pytest.raises(InputError, match="needs the mass of every part"):
        taucli.inertia("disc", mass="2 kg", radius="0.1 m", part=["inertia=0.2kg*m^2"], body_offset="1 m")


@pytest.mark.parametrize("scene, kw", [
    ("spin_down", dict(shape="disc", mass="2 kg", radius="0.1 m", omega0="1 rad/s", friction="1 N*m")),
    ("pendulum", dict(shape="rod", mass="2 kg", length="1 m", axis="end", angle0="10 deg")),
])
def test_angle_is_refused_where_only_a_parts_distance_counts(scene, kw):
    """Elsewhere a part's direction round the axis is not used (a pendulum's parts are on one line
    through the pivot): angle= is refused, not silently dropped."""
    with pytest.raises(InputError) as refused:
        getattr(taucli, scene)(**kw, part=["point mass=1kg offset=0.2m angle=90deg"])
    assert "angle=" in str(refused.value) and "body_offset" in str(refused.value).replace("--body-offset", "body_offset")
