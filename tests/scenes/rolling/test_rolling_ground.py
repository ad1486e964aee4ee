"""A rolling body's points seen from the ground (#34 item 9: --at top, bottom, front, back or an
angle from the top), and what --at at a radius gives where the body was set moving (#34's
defects: an incline with --v0, a yo-yo thrown down with only --radius).

The reference is the rigid body's velocity field worked by hand as vectors, v_P = v_cm + ω × r
and a_P = a_cm + α × r + ω × (ω × r), with ω and α along −z (the rolling sense of +x, y up) and
the cross products written out component by component (not the solver's cos/sin forms). The
textbook problem: Halliday, Resnick & Walker, *Fundamentals of Physics*, chapter 11, the car at
80 km/h on tires 66 cm across; printed for the hitchhiker: the top (44 m/s)î, the bottom 0, the
acceleration at the top and the bottom 1.5 × 10³ m/s².
"""

from __future__ import annotations

import math

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taucli
from taucli.core.errors import InputError
from taucli.scenes.rolling import K2

G = 9.80665
MP_DPS = 40


def values(report):
    return {name: value.value for name, value in report.results.items()}


def cross(u, w):
    return (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])


def ground_reference(v, omega, a, alpha, R, phi):
    """Speed and direction of v_P, size and direction of a_P, for the rim point φ from the top
    (forward positive): r = R (sin φ, cos φ, 0); ω = −ω ẑ, α = −α ẑ."""
    r = (R * mpmath.sin(phi), R * mpmath.cos(phi), mpmath.mpf(0))
    spin, spin_up = (0, 0, -mpmath.mpf(omega)), (0, 0, -mpmath.mpf(alpha))
    turning = cross(spin, r)
    velocity = (v + turning[0], turning[1])
    inward = cross(spin, turning)
    tangential = cross(spin_up, r)
    accel = (a + tangential[0] + inward[0], tangential[1] + inward[1])
    return mpmath.hypot(*velocity), mpmath.atan2(velocity[1], velocity[0]), mpmath.hypot(*accel), mpmath.atan2(accel[1], accel[0])


def test_the_hitchhikers_tire():
    """Halliday: 80 km/h, tires 66 cm across. Printed: top (44 m/s)î, bottom 0; |a| = 1.5e3 m/s² at both."""
    tire = dict(v0="80 km/h", radius="33cm")
    top = values(taucli.rolling("ring", at="top", **tire))
    bottom = values(taucli.rolling("ring", at="bottom", **tire))
    front = values(taucli.rolling("ring", at="front", **tire))
    v = 80 / 3.6
    assert top["v_ground"] == pytest.approx(2 * v, rel=1e-15) and round(top["v_ground"]) == 44
    assert top["v_ground_angle"] == 0
    assert bottom["v_ground"] == 0 and bottom["v_ground_angle"] is None
    for point, direction in ((top, -math.pi / 2), (bottom, math.pi / 2)):
        assert point["a_ground"] == pytest.approx(v * v / 0.33, rel=1e-14)
        assert f"{point['a_ground']:.1e}" == "1.5e+03"
        assert point["a_ground_angle"] == pytest.approx(direction, rel=1e-15)
    assert front["v_ground"] == pytest.approx(math.sqrt(2) * v, rel=1e-15)
    assert front["v_ground_angle"] == pytest.approx(-math.pi / 4, rel=1e-15)
    assert front["a_ground_angle"] == pytest.approx(math.pi, rel=1e-15)  # towards the centre: backward


@settings(max_examples=200, deadline=None)
@given(shape=st.sampled_from(sorted(K2)), angle=st.floats(0.05, 1.5), length=st.floats(0.01, 10), radius=st.floats(0.01, 1),
       phi=st.floats(-math.pi, math.pi).filter(lambda x: x == 0 or abs(x) > 1e-9), mu=st.one_of(st.none(), st.floats(0.001, 0.3)))
def test_a_rim_point_at_the_bottom_of_a_slope(shape, angle, length, radius, phi, mu):
    """Down a slope from rest, rolling or slipping: the state at the bottom (a, α from Newton's
    laws; v = at, ω = αt), then the rim point by the vector sum."""
    k2 = mpmath.mpf(K2[shape])
    with mpmath.workdps(40):
        sin_a, cos_a = mpmath.sin(angle), mpmath.cos(angle)
        rolls = mu is None or mu >= mpmath.tan(angle) * k2 / (1 + k2)
        a = G * sin_a / (1 + k2) if rolls else G * (sin_a - mu * cos_a)
        alpha = a / radius if rolls else mu * G * cos_a / (k2 * radius)
        t = mpmath.sqrt(2 * length / a)
        want = ground_reference(a * t, alpha * t, a, alpha, mpmath.mpf(radius), mpmath.mpf(phi))
    found = values(taucli.rolling(shape, angle=angle, length=length, radius=radius, mu_s=mu, mu_k=mu, at=f"{phi!r} rad"))
    scale = float(a * t)
    assert found["v_ground"] == pytest.approx(float(want[0]), rel=1e-11, abs=1e-13 * scale)
    if found["v_ground"] > 1e-9 * scale:
        assert math.remainder(found["v_ground_angle"] - float(want[1]), 2 * math.pi) == pytest.approx(0, abs=1e-9)
    assert found["a_ground"] == pytest.approx(float(want[2]), rel=1e-10)
    assert math.remainder(found["a_ground_angle"] - float(want[3]), 2 * math.pi) == pytest.approx(0, abs=1e-9)


@settings(max_examples=100, deadline=None)
@given(shape=st.sampled_from(sorted(K2)), scene=st.sampled_from(["incline", "pull", "hanging", "flat"]), size=st.floats(0.1, 10))
def test_the_bottom_point_of_a_rolling_body_is_at_rest(shape, scene, size):
    options = {
        "incline": dict(angle="25deg", length=size),
        "pull": dict(pull=size, mass="2kg", length="1m", pull_height="3cm"),
        "hanging": dict(hanging_mass=size, mass="2kg", string="top", length="1m"),
        "flat": dict(v0=size),
    }[scene]
    found = values(taucli.rolling(shape, radius="5cm", at="bottom", **options))
    assert found.get("rolls") is not False
    assert found["v_ground"] == 0
    top = values(taucli.rolling(shape, radius="5cm", at="top", **options))
    assert top["v_ground"] == pytest.approx(2 * abs(found.get("v", found.get("omega", 0) * 0.05)), rel=1e-14)


def test_a_skidding_ball_slides_at_its_contact():
    """Thrown at 7 m/s with no spin: at the start the bottom moves at v − Rω = 7 m/s; once it
    rolls (v = 5 m/s for a sphere), the bottom is at rest and the top moves at 10 m/s."""
    start = values(taucli.rolling("sphere", v0="7m/s", mu_k=0.2, radius="10cm", at="bottom"))
    assert start["v_ground"] == 0  # the end: rolling at last
    top = values(taucli.rolling("sphere", v0="7m/s", mu_k=0.2, radius="10cm", at="top"))
    assert top["v_ground"] == pytest.approx(10.0, rel=1e-14)
    forever = values(taucli.rolling("sphere", v0="7m/s", mu_k=0, radius="10cm", at="bottom"))  # never rolls: the start
    assert forever["v_ground"] == pytest.approx(7.0, rel=1e-15)


@pytest.mark.parametrize("word,angle", [("top", "0deg"), ("front", "90deg"), ("bottom", "180deg"), ("back", "-90deg"), ("back", "0.75 rev")])
def test_the_named_points_are_their_angles(word, angle):
    scene = dict(angle="30deg", length="2m", radius="10cm", mass="1kg")
    named, measured = values(taucli.rolling("disc", at=word, **scene)), values(taucli.rolling("disc", at=angle, **scene))
    for key in ("v_ground", "a_ground"):
        assert measured[key] == pytest.approx(named[key], rel=1e-14, abs=1e-14), key


def test_a_radius_still_gives_the_motion_about_the_centre():
    found = values(taucli.rolling("disc", angle="30deg", length="2m", radius="10cm", at="5cm"))
    assert "v_ground" not in found and found["v_t"] == pytest.approx(found["v"] / 2, rel=1e-14)


@pytest.mark.parametrize(
    "options,fragment",
    [
        (dict(angle="30deg", length="1m", at="top"), "radius"),  # no radius: the rim is not placed
        (dict(yoyo=True, radius="3cm", at="top"), "yo-yo"),  # no ground under a yo-yo
        (dict(angle="30deg", radius="3cm", at="45+/-1deg"), "no uncertainty"),
        (dict(angle="30deg", radius="3cm", at="topp"), "top, bottom, front, back or an angle"),
        (dict(angle="30deg", radius="3cm", at="2 kg"), "length"),
    ],
)
def test_what_a_rim_point_cannot_take_is_refused(options, fragment):
    with pytest.raises(InputError) as caught:
        taucli.rolling("disc", **options)
    assert caught.value.option == "at" and fragment in str(caught.value)


def test_the_rim_swept_from_the_command_line(taucli):
    """Once round the rim: 2v at the top, √2 v at the front and the back, 0 at the bottom."""
    out = taucli("rolling", "ring", "--v0", "80km/h", "--radius", "33cm", "--at", "0deg..360deg", "--points", "5", "--get", "v_ground")
    assert out.code == 0, out.err
    speeds = [float(line.split("\t")[1]) for line in out.out.splitlines()]
    v = 80 / 3.6
    assert speeds == pytest.approx([2 * v, math.sqrt(2) * v, 0, math.sqrt(2) * v, 2 * v], rel=1e-14, abs=1e-12)


# --- --at at a radius where the body was set moving (#34's defects) ---------------------------


@settings(max_examples=100, deadline=None)
@given(shape=st.sampled_from(sorted(K2)), angle=st.floats(0.05, 1.5), length=st.floats(0.01, 10), radius=st.floats(0.01, 1),
       v0=st.one_of(st.floats(0.01, 10), st.floats(-10, -0.01)))
def test_set_rolling_up_a_slope_it_reaches_the_bottom_with_its_start_speed_taken_in(shape, angle, length, radius, v0):
    """Set rolling at v₀ up the slope (v₀ < 0: down it) L from the bottom: energy, ½ m (1 + k²)
    (v² − v₀²) = m g L sin θ; the time from x(t) = −v₀t + ½at² = L; and the rim about the centre
    moves at ωR = v (rolling), where it gave 4.65 m/s for v = 2.65 m/s."""
    k2 = mpmath.mpf(K2[shape])
    with mpmath.workdps(40):
        v = mpmath.sqrt(v0**2 + 2 * G * mpmath.sin(angle) * length / (1 + k2))
        a = G * mpmath.sin(angle) / (1 + k2)
        t = mpmath.findroot(lambda t: -v0 * t + a * t * t / 2 - length, (v + abs(v0)) / a)
    found = values(taucli.rolling(shape, angle=angle, length=length, radius=radius, v0=v0, at="rim"))
    assert found["v"] == pytest.approx(float(v), rel=1e-13)
    assert found["t"] == pytest.approx(float(t), rel=1e-11)
    assert found["v_t"] == pytest.approx(found["v"], rel=1e-12)
    assert found["v_t0"] == pytest.approx(abs(v0), rel=1e-14)
    assert found["s"] == pytest.approx(length, rel=1e-9)  # the net arc: the distance down from the start


def test_the_issues_sphere_set_rolling_up_the_slope():
    """#34: sphere, 30°, 1 m, v₀ = 2 m/s up, R = 0.1 m, --at rim: v_t was 4.65 m/s at the bottom
    beside v = 2.65 m/s from rest. Now v = √(2² + 2 × 3.50237 × 1) = 3.3173 m/s, and v_t with it."""
    report = taucli.rolling("sphere", angle="30deg", length="1m", v0="2m/s", radius="0.1m", at="rim")
    found = values(report)
    assert found["v"] == pytest.approx(math.sqrt(4 + 2 * G * 0.5 / 1.4), rel=1e-14)
    assert found["v_t"] == pytest.approx(found["v"], rel=1e-14)
    assert "from rest" not in report.results["v"].label
    assert any("climbs" in note for note in report.notes)


def test_a_yo_yo_thrown_down_with_only_its_radius_has_a_point():
    """#34: --yoyo --radius 3cm --v0 1m/s --at rim was refused ("--at needs --radius"): with no
    axle the string is wound at R, so ω₀ = v₀/R and the rim moves at v₀ about the centre."""
    found = values(taucli.rolling("disc", yoyo=True, radius="3cm", v0="1m/s", at="rim", height="1m"))
    assert found["v_t0"] == pytest.approx(1.0, rel=1e-15)
    assert found["v_t"] == pytest.approx(found["v"], rel=1e-14)
