"""Rolling with a pull, the spool, the yo-yo, and a body rolling on the flat (#21).

Each case against the body's equations solved with mpmath from the geometry: the pull as a
vector applied at a point (or along a string tangent to the axle), its torque as the cross
product r × F, the three equations (translation, rotation about the centre, no slip) as a linear
system; energy balances; continuity at the roll/slip boundary and through the spool's critical
angle.
"""

from __future__ import annotations

import math

import mpmath
import pytest
from hypothesis import assume, example, given, settings
from hypothesis import strategies as st

import taucli
from taucli.core.errors import InputError
from taucli.scenes.rolling import K2, Pull, Roller, rolling, solve_pull, solve_yoyo

G = 9.80665


def values(report):
    return {name: value.value for name, value in report.results.items()}


def pull_reference(k2, m, R, slope, g, F, phi, *, height=0.0, axle=None, side=-1, mu_s=None, mu_k=None):
    """a (along +x), α (clockwise, the rolling sense of +x), f (against +x), N, rolls; 40 digits.

    x runs along the surface: along the pull on the flat, down the slope on a slope (the pull
    then points up it); y away from the surface. The pull is the vector F u, u = (±cos φ, sin φ),
    applied at P = (0, h), or for a string wound at r at the tangent point P = r n, n ⊥ u, on the
    side of the surface (n_y < 0, "from below") or away from it.
    """
    with mpmath.workdps(40):
        k2, m, R, slope, g, F, phi = (mpmath.mpf(x) for x in (k2, m, R, slope, g, F, phi))
        sigma = 1 if slope == 0 else -1
        u = (sigma * mpmath.cos(phi), mpmath.sin(phi))
        if axle is None:
            P = (mpmath.mpf(0), mpmath.mpf(height))
        else:
            n = (u[1], -u[0])
            if n[1] > 0:
                n = (-n[0], -n[1])
            if side > 0:
                n = (-n[0], -n[1])
            P = (mpmath.mpf(axle) * n[0], mpmath.mpf(axle) * n[1])
        force = (F * u[0], F * u[1])
        torque_cw = -(P[0] * force[1] - P[1] * force[0])  # −(P × F)_z: clockwise rolls towards +x
        inertia = k2 * m * R**2
        along = force[0] + m * g * mpmath.sin(slope)
        normal = m * g * mpmath.cos(slope) - force[1]
        # unknowns a, α, f:  m a + f = along;  I α − R f = τ;  a − R α = 0
        a, alpha, f = mpmath.lu_solve(mpmath.matrix([[m, 0, 1], [0, inertia, -R], [1, -R, 0]]), mpmath.matrix([along, torque_cw, 0]))
        static = mu_s if mu_s is not None else mu_k
        # a friction that is 0 in exact arithmetic (a cylinder pulled at R/2) is ~1e-40 here: a tie rolls
        rolls = static is None or abs(f) <= static * normal + mpmath.mpf(10) ** -30 * (abs(along) + m * g)
        if not rolls:
            f = mpmath.sign(f) * mu_k * normal
            a = (along - f) / m
            alpha = (f * R + torque_cw) / inertia
        return dict(a=a, alpha=alpha, friction=f, normal=normal, rolls=rolls, torque=torque_cw, along=force[0])


bodies = st.sampled_from(sorted(K2))


@settings(max_examples=300, deadline=None)
@given(
    shape=bodies,
    mass=st.floats(0.1, 50),
    radius=st.floats(0.01, 2),
    slope=st.one_of(st.just(0.0), st.floats(0.01, 1.5)),
    force=st.floats(0.1, 200),
    phi=st.floats(-1.5, 1.5),
    where=st.one_of(st.floats(-1, 1).map(lambda s: ("point", s)), st.tuples(st.just("string"), st.floats(0.01, 1), st.sampled_from([-1, 1]))),
    mu=st.one_of(st.none(), st.tuples(st.floats(0, 1.5), st.floats(0, 1))),
)
@example(shape="cylinder", mass=2.0, radius=0.2, slope=0.0, force=10.0, phi=0.0, where=("point", 0.5), mu=(0.0, 0.0))  # friction 0 exactly: μ = 0 rolls
def test_a_pulled_body_solves_its_three_equations(shape, mass, radius, slope, force, phi, where, mu):
    k2 = K2[shape]
    if where[0] == "point":
        pull = Pull(force, phi, where[1] * radius)
        geometry = dict(height=where[1] * radius)
    else:
        pull = Pull(force, phi, 0.0, where[1] * radius, where[2])
        geometry = dict(axle=where[1] * radius, side=where[2])
    mu_s, mu_k = (None, None) if mu is None else (mu[0], mu[0] * mu[1])
    ref = pull_reference(k2, mass, radius, slope, G, force, phi, mu_s=mu_s, mu_k=mu_k, **geometry)
    assume(ref["normal"] > 1e-9 * mass * G)
    result = values(solve_pull(Roller(k2, shape, mass, radius), slope, G, pull, mu_s=mu_s, mu_k=mu_k))
    assert result["rolls"] is ref["rolls"]
    scale = (force + mass * G) / mass
    assert result["a"] == pytest.approx(float(ref["a"]), rel=1e-12, abs=1e-13 * scale)
    assert result["alpha"] == pytest.approx(float(ref["alpha"]), rel=1e-12, abs=1e-13 * scale / radius)
    assert result["friction"] == pytest.approx(float(ref["friction"]), rel=1e-12, abs=1e-13 * mass * scale)


def test_textbook_pulls():
    """A disc pulled by a string over its top: a = 4F/3m, friction F/3 forward (it helps). A
    sphere pulled at its centre: a = 5F/7m, friction 2F/7 backward. A ring pulled at the top
    needs no friction at all: a = F/m."""
    disc = values(solve_pull(Roller(0.5, "disc", 3.0, 0.2), 0.0, G, Pull(6.0, 0.0, 0.2), mu_s=0.5))
    assert disc["a"] == pytest.approx(4 * 6.0 / 9.0, rel=1e-15) and disc["friction"] == pytest.approx(-2.0, rel=1e-15)
    assert disc["alpha"] == pytest.approx(disc["a"] / 0.2, rel=1e-15)
    sphere = values(solve_pull(Roller(0.4, "sphere", 7.0, 0.1), 0.0, G, Pull(14.0), mu_s=0.5))
    assert sphere["a"] == pytest.approx(10 / 7, rel=1e-15) and sphere["friction"] == pytest.approx(4.0, rel=1e-15)
    ring = values(solve_pull(Roller(1.0, "ring", 2.0, 0.5), 0.0, G, Pull(3.0, 0.0, 0.5), mu_s=0.0))
    assert ring["rolls"] is True and ring["friction"] == 0.0 and ring["a"] == pytest.approx(1.5, rel=1e-15)


def test_pulled_up_a_slope():
    """A cylinder (m = 2 kg, R = 0.1 m) pulled up a 30° slope at its centre by 20 N (g = 10):
    down the slope positive, a = (10 − 20)/(2 × 1.5) = −10/3 m/s² (it rolls up), f = k² m a − 0
    = −10/3 N (against a: down the slope)."""
    result = values(solve_pull(Roller(0.5, "cylinder", 2.0, 0.1), math.radians(30), 10.0, Pull(20.0), mu_s=1.0))
    assert result["a"] == pytest.approx(-10 / 3, rel=1e-14)
    assert result["friction"] == pytest.approx(-10 / 3, rel=1e-14)


@settings(max_examples=200, deadline=None)
@given(
    shape=bodies,
    mass=st.floats(0.1, 50),
    radius=st.floats(0.01, 2),
    slope=st.one_of(st.just(0.0), st.floats(0.01, 1.5)),
    force=st.floats(0.1, 200),
    phi=st.floats(-1.4, 1.4),
    where=st.one_of(st.floats(-1, 1).map(lambda s: ("point", s)), st.tuples(st.just("string"), st.floats(0.01, 1), st.sampled_from([-1, 1]))),
    mu=st.one_of(st.none(), st.tuples(st.floats(0, 1.5), st.floats(0.01, 1))),
    distance=st.floats(0.01, 10),
)
def test_work_of_gravity_and_the_pull_is_kinetic_energy_plus_friction_heat(shape, mass, radius, slope, force, phi, where, mu, distance):
    """Over the distance the centre moves from rest: m g sin θ x + F_x x + τ θ = ½ m v² + ½ I ω²
    + |f| |x − R θ| (the pull's work is that of its force and of its torque; friction works only
    on the slip x − Rθ)."""
    k2 = K2[shape]
    if where[0] == "point":
        pull, geometry = Pull(force, phi, where[1] * radius), dict(height=where[1] * radius)
    else:
        pull, geometry = Pull(force, phi, 0.0, where[1] * radius, where[2]), dict(axle=where[1] * radius, side=where[2])
    mu_s, mu_k = (None, None) if mu is None else (mu[0], mu[0] * mu[1])
    ref = pull_reference(k2, mass, radius, slope, G, force, phi, mu_s=mu_s, mu_k=mu_k, **geometry)
    assume(ref["normal"] > 1e-9 * mass * G and abs(ref["a"]) > 1e-6)
    result = values(solve_pull(Roller(k2, shape, mass, radius), slope, G, pull, mu_s=mu_s, mu_k=mu_k, length=distance))
    with mpmath.workdps(40):
        t = mpmath.mpf(result["t"])
        x = mpmath.sign(ref["a"]) * distance
        turned = mpmath.mpf(result["alpha"]) * t * t / 2
        work = (mass * G * mpmath.sin(slope) + ref["along"]) * x + ref["torque"] * turned
        heat = abs(ref["friction"]) * abs(x - radius * turned)
        kinetic = mpmath.mpf(result["KE_trans"]) + mpmath.mpf(result["KE_rot"])
        assert float(kinetic + heat) == pytest.approx(float(work), rel=1e-9, abs=1e-12 * (force + mass * G) * distance)
    assert result["KE"] == pytest.approx(result["KE_trans"] + result["KE_rot"], rel=1e-15)
    assert result["v"] == pytest.approx(result["a"] * result["t"], rel=1e-14)


@pytest.mark.parametrize("shape", sorted(K2))
@pytest.mark.parametrize("where", [dict(height=0.08), dict(height=-0.05), dict(axle=0.04)])
def test_the_roll_slip_boundary_is_continuous(shape, where):
    k2, mass, radius, force, phi = K2[shape], 2.0, 0.1, 30.0, math.radians(20)
    pull = Pull(force, phi, where.get("height", 0.0), where.get("axle"))
    body = Roller(k2, shape, mass, radius)
    mu_min = values(solve_pull(body, 0.0, G, pull))["mu_min"]
    assert mu_min > 0
    above = values(solve_pull(body, 0.0, G, pull, mu_s=mu_min * (1 + 1e-12), mu_k=mu_min))
    below = values(solve_pull(body, 0.0, G, pull, mu_s=mu_min * (1 - 1e-12), mu_k=mu_min * (1 - 1e-12)))
    assert above["rolls"] is True and below["rolls"] is False
    for name in ("a", "alpha", "friction"):
        assert below[name] == pytest.approx(above[name], rel=1e-9, abs=1e-12)


# The spool ------------------------------------------------------------------------------------


@pytest.mark.parametrize("ratio", [0.2, 0.5, 0.8])
def test_the_spool_rolls_towards_the_pull_below_the_critical_angle_and_away_above_it(ratio):
    """A spool (R = 0.1 m, axle r) pulled by its string from below: cos θc = r/R. Below θc it rolls
    the way it is pulled, above it back (the spool paradox); a passes through zero continuously."""
    mass, radius = 1.5, 0.1
    body = Roller(0.5, "disc", mass, radius)
    report = solve_pull(body, 0.0, G, Pull(5.0, 0.0, 0.0, ratio * radius), mu_s=2.0)
    critical = values(report)["critical_angle"]
    with mpmath.workdps(30):
        assert critical == pytest.approx(float(mpmath.acos(ratio)), rel=1e-14)
    accelerations = []
    for offset in (-1e-3, -1e-7, 0.0, 1e-7, 1e-3):
        phi = critical + offset
        result = values(solve_pull(body, 0.0, G, Pull(5.0, phi, 0.0, ratio * radius), mu_s=2.0))
        ref = pull_reference(0.5, mass, radius, 0.0, G, 5.0, phi, axle=ratio * radius, mu_s=2.0)
        assert result["a"] == pytest.approx(float(ref["a"]), abs=1e-14)
        accelerations.append(result["a"])
    assert accelerations[0] > accelerations[1] > 0 > accelerations[3] > accelerations[4]
    assert abs(accelerations[2]) < 1e-14
    # a near θc is (F/m(1+k²))(cos θ − r/R): linear in the offset, so it passes through zero
    slope = -5.0 * math.sin(critical) / (mass * 1.5)
    assert accelerations[1] == pytest.approx(slope * -1e-7, rel=1e-6)


def test_the_spool_pulled_from_the_top_always_rolls_forward():
    report = solve_pull(Roller(0.5, "disc", 1.0, 0.1), 0.0, G, Pull(5.0, math.radians(80), 0.0, 0.05, +1), mu_s=2.0)
    assert values(report)["critical_angle"] is None and values(report)["a"] > 0
    assert any("critical_angle: none" in note for note in report.notes)


def test_the_spool_on_a_slope_stays_put_where_the_pull_balances_gravity_about_the_contact():
    """On a slope the pull (up it) holds the spool where F(cos φ − r/R) = m g sin θ."""
    mass, radius, axle, slope, force = 5.0, 0.1, 0.03, math.radians(10), 40.0
    body = Roller(0.5, "disc", mass, radius)
    critical = values(solve_pull(body, slope, G, Pull(force, 0.0, 0.0, axle), mu_s=2.0))["critical_angle"]
    with mpmath.workdps(30):
        exact = mpmath.acos(mpmath.mpf(axle) / radius + mass * G * mpmath.sin(slope) / force)
    assert critical == pytest.approx(float(exact), rel=1e-13)
    held = values(solve_pull(body, slope, G, Pull(force, critical, 0.0, axle), mu_s=2.0))
    assert abs(held["a"]) < 1e-13


# The yo-yo ------------------------------------------------------------------------------------


def yoyo_reference(k2, m, R, r, g):
    """Unknowns a, α, T:  m a + T = m g;  I α − r T = 0;  a − r α = 0."""
    with mpmath.workdps(40):
        k2, m, R, r, g = (mpmath.mpf(x) for x in (k2, m, R, r, g))
        return mpmath.lu_solve(mpmath.matrix([[m, 0, 1], [0, k2 * m * R**2, -r], [1, -r, 0]]), mpmath.matrix([m * g, 0, 0]))


@settings(max_examples=200, deadline=None)
@given(shape=bodies, mass=st.floats(0.01, 10), radius=st.floats(0.005, 1), share=st.floats(0.01, 1), height=st.floats(0.01, 10), v0=st.floats(-5, 5))
def test_the_yoyo_solves_its_equations_and_keeps_its_energy(shape, mass, radius, share, height, v0):
    k2, axle = K2[shape], share * radius
    result = values(solve_yoyo(Roller(k2, shape, mass, radius), G, axle=axle, height=height, v0=v0))
    a, alpha, tension = yoyo_reference(k2, mass, radius, axle, G)
    assert result["a"] == pytest.approx(float(a), rel=1e-13)
    assert result["alpha"] == pytest.approx(float(alpha), rel=1e-13)
    assert result["T"] == pytest.approx(float(tension), rel=1e-13)
    with mpmath.workdps(40):
        inertia = k2 * mpmath.mpf(mass) * mpmath.mpf(radius) ** 2
        start = mpmath.mpf(mass) * v0 * v0 / 2 + inertia * (mpmath.mpf(v0) / axle) ** 2 / 2
        end = mpmath.mpf(result["KE_trans"]) + mpmath.mpf(result["KE_rot"])
        assert float(end) == pytest.approx(float(start + mass * G * height), rel=1e-12)
        assert result["KE_rot"] == pytest.approx(float(inertia * mpmath.mpf(result["omega"]) ** 2 / 2), rel=1e-12)
        t = mpmath.mpf(result["t"])
        scale = abs(v0) * t + a * t * t / 2  # thrown up, it climbs and falls back: the two terms cancel to h
        assert float(v0 * t + a * t * t / 2) == pytest.approx(height, abs=float(1e-12 * scale))


def test_the_yoyo_wound_at_its_rim_is_the_articles_disc():
    """A disc on a string wound at its own rim falls at 2g/3 with T = mg/3 (no radius needed)."""
    result = values(solve_yoyo(Roller(0.5, "disc", 0.3, None), 9.8))
    assert result["a"] == pytest.approx(9.8 * 2 / 3, rel=1e-15) and result["T"] == pytest.approx(0.98, rel=1e-15)
    assert result["alpha"] is None


def test_rolling_on_the_flat_has_its_kinetic_energy_in_two_parts():
    """A solid sphere rolling at v: KE = 7/10 m v², of which 2/7 is rotation."""
    result = values(rolling(shape="sphere", mass=2.0, radius=0.1, v0=3.0))
    assert result["KE"] == pytest.approx(0.7 * 2.0 * 9.0, rel=1e-15)
    assert result["KE_rot"] == pytest.approx(2 / 7 * result["KE"], rel=1e-15)
    assert result["omega"] == pytest.approx(30.0, rel=1e-15)
    skid = values(rolling(shape="sphere", v0=7.0, mu_k=0.2))  # --v0 with --mu-k still skids
    assert skid["v_roll"] == pytest.approx(5.0, rel=1e-15)


def test_units_do_not_change_the_answer():
    si = taucli.rolling(shape="disc", mass=2.0, radius=0.1, pull=10.0, pull_angle=0.3, axle_radius=0.04, mu_s=0.8, length=1.0)
    other = taucli.rolling(shape="disc", mass="2000 g", radius="10 cm", pull="1 kN / 100", pull_angle=f"{math.degrees(0.3)} deg",
                           axle_radius="40 mm", mu_s=0.8, length="100 cm")
    for name in ("a", "alpha", "friction", "critical_angle", "v", "KE"):
        assert other.results[name].value == pytest.approx(si.results[name].value, rel=1e-12)


@pytest.mark.parametrize(
    "arguments,fragment",
    [
        (dict(shape="disc", pull=100.0, pull_angle=1.2, mass=1.0), "pull: lifts the body off"),
        (dict(shape="disc", pull=10.0, pull_angle=2.0, mass=1.0), "pull_angle: expected an angle from −90 to 90"),
        (dict(shape="disc", pull=10.0, axle_radius=0.2, radius=0.1, mass=1.0), "axle_radius must lie within"),
        (dict(shape="disc", pull=10.0, pull_height=0.05, mass=1.0), "radius is required"),
        (dict(shape="disc", pull=10.0), "mass is required"),
        (dict(shape="disc", pull_height=0.05), "pull_height needs pull"),
        (dict(shape="disc", axle_radius=0.05), "axle_radius needs pull"),
        (dict(shape="disc", pull=10.0, mass=1.0, v0=1.0), "v0 does not apply with pull"),
        (dict(shape="disc", yoyo=True, angle=0.3), "angle does not apply with yoyo"),
        (dict(shape="disc", yoyo=True, axle_radius=0.01), "radius is required with axle_radius"),
    ],
)
def test_impossible_pulls_are_input_errors(arguments, fragment):
    with pytest.raises(InputError) as caught:
        rolling(**arguments)
    assert fragment in str(caught.value)


@pytest.mark.parametrize("angle", [math.pi / 2, -math.pi / 2])
def test_a_pull_straight_up_or_down_moves_nothing_along(angle):
    """φ = ±90°: no component along the surface and (at the centre) no torque: a = 0 exactly,
    not the 6e-17 of math.cos(π/2)."""
    result = values(solve_pull(Roller(0.5, "disc", 2.0, 0.1), 0.0, G, Pull(10.0, angle), mu_s=0.1))
    assert result["a"] == 0.0 and result["friction"] == 0.0 and result["alpha"] == 0.0


@pytest.mark.parametrize("slope", [math.radians(10), math.radians(35)])
@pytest.mark.parametrize("where", [dict(height=0.08), dict(height=-0.05), dict(axle=0.04), dict(axle=0.04, side=1)])
@pytest.mark.parametrize("force", [5.0, 40.0])
def test_the_roll_slip_boundary_is_continuous_on_a_slope(slope, where, force):
    """Pulled up a slope (a pull that wins, and one that loses to gravity): just above μ_min it
    rolls, just below it slips, and a, α, friction agree to the size of the step in μ."""
    pull = Pull(force, math.radians(15), where.get("height", 0.0), where.get("axle"), where.get("side", -1))
    body = Roller(0.5, "disc", 2.0, 0.1)
    mu_min = values(solve_pull(body, slope, G, pull))["mu_min"]
    above = values(solve_pull(body, slope, G, pull, mu_s=mu_min * (1 + 1e-12), mu_k=mu_min))
    below = values(solve_pull(body, slope, G, pull, mu_s=mu_min * (1 - 1e-12), mu_k=mu_min * (1 - 1e-12)))
    assert above["rolls"] is True and below["rolls"] is False
    for name in ("a", "alpha", "friction"):
        assert below[name] == pytest.approx(above[name], rel=1e-9, abs=1e-12)
    ref = pull_reference(0.5, 2.0, 0.1, slope, G, force, math.radians(15), mu_s=mu_min * (1 + 1e-12), mu_k=mu_min,
                         **{k: v for k, v in where.items()})
    assert above["a"] == pytest.approx(float(ref["a"]), rel=1e-12, abs=1e-14)


def test_halliday_yoyo_needs_no_outer_radius():
    """A yo-yo of I = 950 g·cm², m = 120 g, axle r = 3.2 mm, string 120 cm (g = 9.8): the book's
    a = 12.5 cm/s², T = 1.16 N, and at the end of the string v = 55 cm/s, ω ≈ 1.7e2 rad/s,
    KE_trans ≈ 1.8e-2 J, KE_rot ≈ 1.4 J. Only I/(m r²) enters, so --radius is not asked for."""
    report = rolling(yoyo=True, inertia=950e-7, mass=0.12, axle_radius=3.2e-3, height=1.2, g=9.8)
    result = values(report)
    with mpmath.workdps(40):
        I, m, r, h, g = (mpmath.mpf(x) for x in ("950e-7", "0.12", "3.2e-3", "1.2", "9.8"))
        a, alpha, tension = mpmath.lu_solve(mpmath.matrix([[m, 0, 1], [0, I, -r], [1, -r, 0]]), mpmath.matrix([m * g, 0, 0]))
        v = mpmath.sqrt(2 * a * h)
    assert result["a"] == pytest.approx(float(a), rel=1e-14) and round(result["a"] * 100, 1) == 12.5
    assert result["T"] == pytest.approx(float(tension), rel=1e-14) and round(result["T"], 2) == 1.16
    assert result["v"] == pytest.approx(float(v), rel=1e-14) and round(result["v"], 2) == 0.55
    assert result["omega"] == pytest.approx(float(v / r), rel=1e-14)
    assert result["KE_rot"] == pytest.approx(float(I * (v / r) ** 2 / 2), rel=1e-13)
    assert result["KE"] == pytest.approx(float(m * g * h), rel=1e-13)
