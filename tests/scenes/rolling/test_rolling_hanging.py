"""A rolling body joined to a hanging mass by a string over a pulley (#34 item 8), and a yo-yo
spun in place (#34 item 9).

Each case against Newton's laws for the body, the hanging mass and the pulley written as one
linear system and solved with mpmath (40 digits), not the solver's closed forms; energy balances
(the work of gravity is the kinetic energy of the three bodies plus the heat of a sliding
contact); the string's constraint; continuity at the roll/slip boundary; units; refusals; the
command line, a batch and Python. Textbook problems: D. C. Pandey, *Understanding Physics:
Mechanics*, vol. 2, "Rotational Mechanics", subjective questions (a 10 kg cylinder with a tape
wound round it, a 100 N pulley of radius 5 cm, a 5 kg hanging mass: printed a₂ = 4g/11 = 3.6
m/s², v = 4gt/11); Tipler & Mosca, *Physics for Scientists and Engineers*, chapter 9 (the hand
that holds a cylinder's centre still as it spins up: printed T = Mg, α = 2g/R, a = 2g).
"""

from __future__ import annotations

import json
import math

import mpmath
import pytest
from conftest import assert_usage_error, run_taucli
from hypothesis import given, settings
from hypothesis import strategies as st

import taucli
from taucli.core.errors import InputError
from taucli.scenes.rolling import K2

G = 9.80665
MP_DPS = 40


def values(report):
    return {name: value.value for name, value in report.results.items()}


def hanging_reference(k2, M, R, m, m_p, r_p, theta, g, lever, mu_s=None, mu_k=None):
    """Newton's laws, 40 digits. Unknowns a, α, f, T, T₂, a_h, α_p (x towards the pulley, α in
    the rolling sense of x, f at the contact against x, a_h of the hanging mass downward):

        M a − T + f = −M g sin θ            the body along the surface
        I α − f R − c T R = 0               the body about its centre, I = k² M R²
        m a_h + T₂ = m g                    the hanging mass
        I_p α_p − (T₂ − T) r_p = 0          the pulley, I_p = ½ m_p r_p²
        a_h − r_p α_p = 0                   the string on the pulley
        a_h − a − c R α = 0                 the string leaves the body's centre (c = 0) or top (c = 1)
        a − R α = 0                         rolling; when it slips, f = ±μk N instead
    """
    k2, M, R, m, m_p, r_p, theta, g = (mpmath.mpf(x) for x in (k2, M, R, m, m_p, r_p, theta, g))
    c = lever
    inertia, pulley = k2 * M * R**2, m_p * r_p**2 / 2
    rows = [
        [M, 0, 1, -1, 0, 0, 0],
        [0, inertia, -R, -c * R, 0, 0, 0],
        [0, 0, 0, 0, 1, m, 0],
        [0, 0, 0, r_p, -r_p, 0, pulley],
        [0, 0, 0, 0, 0, 1, -r_p],
        [-1, -c * R, 0, 0, 0, 1, 0],
    ]
    right = [-M * g * mpmath.sin(theta), 0, m * g, 0, 0, 0]
    solved = mpmath.lu_solve(mpmath.matrix(rows + [[1, -R, 0, 0, 0, 0, 0]]), mpmath.matrix(right + [0]))
    normal = M * g * mpmath.cos(theta)
    f_roll = solved[2]
    static = mu_s if mu_s is not None else mu_k
    rolls = static is None or abs(f_roll) <= static * normal
    if not rolls:
        solved = mpmath.lu_solve(mpmath.matrix(rows + [[0, 0, 1, 0, 0, 0, 0]]), mpmath.matrix(right + [mpmath.sign(f_roll) * mu_k * normal]))
    a, alpha, f, T, T2, a_h, alpha_p = solved
    return dict(a=a, alpha=alpha, friction=f, T=T, T2=T2, a_hanging=a_h, alpha_pulley=alpha_p, rolls=rolls, mu_min=abs(f_roll) / normal)


scenes = dict(
    shape=st.sampled_from(sorted(K2)),
    M=st.floats(0.1, 50),
    R=st.floats(0.01, 1),
    m=st.floats(0.01, 50),
    m_p=st.one_of(st.just(0.0), st.floats(0.01, 20)),
    r_p=st.floats(0.01, 1),
    theta=st.one_of(st.just(0.0), st.floats(0.01, 1.5)),
    lever=st.sampled_from([0, 1]),
    mu=st.one_of(st.none(), st.tuples(st.floats(1e-6, 1.5), st.one_of(st.just(0.0), st.floats(1e-6, 1)))),
)


def _solve(shape, M, R, m, m_p, r_p, theta, lever, mu, **more):
    mu_s, mu_k = (None, None) if mu is None else (mu[0], min(mu))
    return taucli.rolling(shape, mass=M, radius=R, hanging_mass=m, pulley_mass=m_p, pulley_radius=r_p, angle=theta, string=("centre", "top")[lever],
                          mu_s=mu_s, mu_k=mu_k, **more)


@settings(max_examples=300, deadline=None)
@given(**scenes)
def test_the_body_the_hanging_mass_and_the_pulley_solve_newtons_laws(shape, M, R, m, m_p, r_p, theta, lever, mu):
    mu_s, mu_k = (None, None) if mu is None else (mu[0], min(mu))
    want = hanging_reference(K2[shape], M, R, m, m_p, r_p, theta, G, lever, mu_s, mu_k)
    if min(want["T"], want["T2"]) < 0:  # the string would go slack: refused, never a wrong number
        with pytest.raises(InputError, match="slack"):
            _solve(shape, M, R, m, m_p, r_p, theta, lever, mu)
        return
    found = values(_solve(shape, M, R, m, m_p, r_p, theta, lever, mu))
    assert found["rolls"] is bool(want["rolls"])
    scale = float(M * G + m * G)  # forces that nearly cancel are good to ulps of the weights
    for key in ("T", "T2", "friction"):
        assert found[key] == pytest.approx(float(want[key]), rel=1e-11, abs=1e-12 * scale), key
    for key in ("a", "a_hanging"):
        assert found[key] == pytest.approx(float(want[key]), rel=1e-11, abs=1e-12 * G * (1 + M / m)), key
    assert found["alpha"] * R == pytest.approx(float(want["alpha"] * R), rel=1e-11, abs=1e-12 * G * (1 + M / m))
    assert found["alpha_pulley"] * r_p == pytest.approx(found["a_hanging"], rel=1e-14, abs=0)
    if theta:
        assert found["mu_min"] == pytest.approx(float(want["mu_min"]), rel=1e-10, abs=1e-12 * (1 + M / m))


@settings(max_examples=200, deadline=None)
@given(**scenes, distance=st.floats(0.01, 10))
def test_gravitys_work_is_the_kinetic_energy_of_the_three_bodies_plus_the_heat_of_sliding(shape, M, R, m, m_p, r_p, theta, lever, mu, distance):
    """From rest: m g x_h − M g sin θ x = ½Mv² + ½Iω² + ½mv_h² + ½I_p(v_h/r_p)² + |f| |x − Rθ|."""
    try:
        report = _solve(shape, M, R, m, m_p, r_p, theta, lever, mu, length=distance)
    except InputError:
        return  # a slack string (checked above)
    found = values(report)
    if not found["a"]:
        return
    t, v, v_h, omega = found["t"], found["v"], found["v_hanging"], found["omega"]
    x, x_h, turned = found["a"] * t * t / 2, found["a_hanging"] * t * t / 2, found["alpha"] * t * t / 2
    assert abs(x) == pytest.approx(distance, rel=1e-13)
    work = m * G * x_h - M * G * math.sin(theta) * x
    kinetic = M * v * v / 2 + K2[shape] * M * R * R * omega * omega / 2 + m * v_h * v_h / 2 + (m_p * r_p * r_p / 2) * (v_h / r_p) ** 2 / 2
    heat = abs(found["friction"]) * abs(x - R * turned)
    assert kinetic + heat == pytest.approx(work, rel=1e-9, abs=1e-12 * (m * G * abs(x_h) + M * G * abs(x)))
    assert found["KE"] == pytest.approx(M * v * v / 2 + K2[shape] * M * (R * omega) ** 2 / 2, rel=1e-12)


@settings(max_examples=100, deadline=None)
@given(**scenes)
def test_the_string_moves_with_the_point_it_leaves(shape, M, R, m, m_p, r_p, theta, lever, mu):
    """While it rolls the top moves at 2v, the centre at v: a_h = (1 + c) a; the bottom is at rest."""
    try:
        found = values(_solve(shape, M, R, m, m_p, r_p, theta, lever, mu, length=1.0, at="bottom"))
    except InputError:
        return
    if found["rolls"]:
        assert found["a_hanging"] == pytest.approx((1 + lever) * found["a"], rel=1e-14, abs=0)
        assert found["v_ground"] == 0
    else:
        assert found["a_hanging"] == pytest.approx(found["a"] + lever * found["alpha"] * R, rel=1e-12, abs=1e-12 * G)


@pytest.mark.parametrize("lever", [0, 1])
@pytest.mark.parametrize("theta", [0.0, 0.5])
def test_the_roll_slip_boundary_is_continuous(lever, theta):
    shape, M, R, m, m_p, r_p = "disc", 3.0, 0.2, 1.2, 0.8, 0.1
    mu_min = values(_solve(shape, M, R, m, m_p, r_p, theta, lever, None))["mu_min"]
    at = values(_solve(shape, M, R, m, m_p, r_p, theta, lever, (mu_min, mu_min)))
    below = values(_solve(shape, M, R, m, m_p, r_p, theta, lever, (mu_min * (1 - 1e-12),) * 2))
    assert at["rolls"] is True and below["rolls"] is False
    for key in ("a", "alpha", "T", "T2", "a_hanging", "friction"):
        assert below[key] == pytest.approx(at[key], rel=1e-10), key


def test_a_textbook_cylinder_with_a_tape_over_a_heavy_pulley():
    """D. C. Pandey: a 10 kg cylinder of radius 10 cm, a tape wound round it and over a pulley
    weighing 100 N, radius 5 cm, to a 5 kg mass; it rolls without slipping. Printed: a₂ = 4g/11
    = 3.6 m/s², v = 4gt/11 (the pulley's weight read with g = 10 m/s², as the book does)."""
    found = values(taucli.rolling("disc", mass="10kg", radius="10cm", hanging_mass="5kg", string="top", pulley_mass="100N",
                                  pulley_radius="5cm", g="10 m/s^2", length="1m"))
    assert found["a_hanging"] == pytest.approx(4 * 10 / 11, rel=1e-14)
    assert round(found["a_hanging"], 1) == 3.6
    assert found["v_hanging"] == pytest.approx(4 * 10 / 11 * found["t"], rel=1e-14)
    assert found["a"] == pytest.approx(2 * 10 / 11, rel=1e-14)  # the cylinder's centre, half the tape's
    # the book's seven equations: 5g − T₂ = 5a₂;  T₁ + f = 10 a₁ (friction forward);  (T₁ − f)R₁ = ½ 10 R₁² α₁
    assert 5 * 10 - found["T2"] == pytest.approx(5 * found["a_hanging"], rel=1e-14)
    assert found["T"] - found["friction"] == pytest.approx(10 * found["a"], rel=1e-14)
    assert found["T"] + found["friction"] == pytest.approx(0.5 * 10 * found["a"], rel=1e-14)


def test_units_do_not_change_the_answer():
    si = values(taucli.rolling("sphere", mass=2.0, radius=0.1, hanging_mass=0.5, pulley_mass=0.3, pulley_radius=0.05, angle=math.radians(20),
                               string="top", mu_s=0.3, length=1.5))
    other = values(taucli.rolling("sphere", mass="2000 g", radius="10 cm", hanging_mass="500 g", pulley_mass="0.3 kg", pulley_radius="50 mm",
                                  angle="20 deg", string="top", mu_s=0.3, length="150 cm"))
    for key, value in si.items():
        assert other[key] == pytest.approx(value, rel=1e-13), key


def test_a_massless_pulley_has_one_tension_and_the_article_limit():
    """The axle in a frame, a massless pulley, on the flat: a = m g/(m + M(1 + k²)), T = T₂."""
    found = values(taucli.rolling("disc", mass="3kg", hanging_mass="1kg", g=10))
    assert found["a"] == pytest.approx(10 / (1 + 3 * 1.5), rel=1e-14)
    assert found["T"] == found["T2"]
    assert "alpha_pulley" not in found


@pytest.mark.parametrize(
    "options,name",
    [
        (dict(string="top"), "string"),
        (dict(pulley_mass="1kg"), "pulley_mass"),
        (dict(hanging_mass="1kg", pull="5N"), "pull"),
        (dict(hanging_mass="1kg", v0="1m/s"), "v0"),
        (dict(hanging_mass="1kg", axle_radius="1cm"), "axle_radius"),
        (dict(hanging_mass="1kg", height="1m"), "height"),
        (dict(hanging_mass="1kg", yoyo=True), "hanging_mass"),
        (dict(hanging_mass="1kg", string="side"), "string"),
        (dict(hanging_mass="1kg", angle="95deg"), "angle"),
    ],
)
def test_what_the_hanging_mass_cannot_take_is_refused(options, name):
    with pytest.raises(InputError) as caught:
        taucli.rolling("disc", mass="2kg", radius="5cm", **options)
    assert caught.value.option == name


def test_the_body_needs_its_mass():
    # #42 item 14: what depends on the body's mass is null with the reason, and refused naming --mass when asked for
    report = taucli.rolling("disc", hanging_mass="1kg")
    assert report.results["a"].value is None and report.needs["a"][0] == "mass"
    assert_usage_error(run_taucli("rolling", "disc", "--hanging-mass", "1kg", "--get", "a"), "--mass")


def test_from_the_command_line_and_a_batch(taucli):
    args = ("rolling", "disc", "--mass", "10kg", "--radius", "10cm", "--hanging-mass", "5kg", "--string", "top", "--pulley-mass", "100N",
            "--pulley-radius", "5cm", "--g", "10")
    assert float(taucli(*args, "--get", "a_hanging").out) == pytest.approx(40 / 11, rel=1e-14)
    line = {"shape": "disc", "mass": "10kg", "radius": "10cm", "hanging_mass": "5kg", "string": "top", "pulley_mass": "100N",
            "pulley_radius": "5cm", "g": "10 m/s^2"}
    done = taucli("rolling", "--batch", stdin=json.dumps(line) + "\n")
    assert done.code == 0, done.err
    assert json.loads(done.out)["results"]["a_hanging"]["value"] == pytest.approx(40 / 11, rel=1e-14)


def test_the_largest_hanging_mass_a_disc_rolls_with(taucli):
    """--find: the axle of a 7.1 kg disc on a string over a massless pulley, μs = 0.202: it rolls
    while a = m g/(m + 1.5 M) ≤ 2 μs g (f = ½ M a ≤ μs M g), so m ≤ 1.5 M (2μs)/(1 − 2μs)."""
    found = taucli("rolling", "disc", "--mass", "7.1kg", "--find", "hanging_mass", "--want", "mu_min=0.202", "--get", "hanging_mass")
    assert float(found.out) == pytest.approx(1.5 * 7.1 * 0.404 / (1 - 0.404), rel=1e-9)


# --- a yo-yo spun in place -----------------------------------------------------------------


def test_the_hand_that_holds_a_cylinders_centre_still():
    """Tipler & Mosca, chapter 9: a uniform cylinder on a string wound round it, the string's upper
    end held by a hand accelerated upward so that the centre does not move. Printed: T = Mg,
    α = 2g/R, a = 2g."""
    M, R = 0.5, 0.04
    found = values(taucli.rolling("disc", yoyo=True, in_place=True, mass=M, radius=R))
    assert found["T"] == pytest.approx(M * G, rel=1e-15)
    assert found["alpha"] == pytest.approx(2 * G / R, rel=1e-15)
    assert found["a_hand"] == pytest.approx(2 * G, rel=1e-15)
    assert found["a"] == 0


@settings(max_examples=200, deadline=None)
@given(inertia=st.floats(1e-4, 1), mass=st.floats(0.01, 10), axle=st.floats(0.001, 0.1), omega0=st.one_of(st.just(0.0), st.floats(1e-3, 100)), length=st.floats(0.001, 5))
def test_the_hands_work_goes_into_spin(inertia, mass, axle, omega0, length):
    """Newton for the centre (T = m g) and the rotation (I α = T r); the string pulled is r θ with
    θ = ω₀t + ½αt²; the hand's work T L is ½ I (ω² − ω₀²)."""
    found = values(taucli.rolling(yoyo=True, in_place=True, inertia=inertia, mass=mass, axle_radius=axle, omega0=omega0, length=length))
    with mpmath.workdps(40):
        alpha = mpmath.mpf(mass) * G * axle / inertia
        t = mpmath.findroot(lambda t: axle * (omega0 * t + alpha * t * t / 2) - length, float(length / axle / max(omega0, 1)))
        omega = omega0 + alpha * t
    assert found["alpha"] == pytest.approx(float(alpha), rel=1e-14)
    assert found["t"] == pytest.approx(float(t), rel=1e-12)
    assert found["omega"] == pytest.approx(float(omega), rel=1e-12)
    assert inertia * (found["omega"] ** 2 - omega0**2) / 2 == pytest.approx(mass * G * length, rel=1e-9)
    assert found["KE_rot"] == pytest.approx(inertia * found["omega"] ** 2 / 2, rel=1e-12)


def test_a_yo_yo_given_by_its_inertia_spins_up_without_a_radius():
    """Chabay & Sherwood's yo-yo (I = 0.01 kg·m², M = 0.3 kg) at 14 rad/s as the hand rises from
    0.26 m to 0.66 m: ω² = ω₀² + 2MgL/I, 20.8 rad/s; α and the hand's acceleration need r."""
    found = values(taucli.rolling(yoyo=True, in_place=True, inertia="0.01 kg*m^2", mass="0.3kg", omega0="14 rad/s", length="40cm", g=9.8))
    assert found["omega"] == pytest.approx(math.sqrt(14**2 + 2 * 0.3 * 9.8 * 0.4 / 0.01), rel=1e-14)
    assert found["alpha"] is None and found["a_hand"] is None and found["t"] is None


@pytest.mark.parametrize("options,name", [(dict(height="1m"), "height"), (dict(v0="1m/s"), "v0"), (dict(angle="10deg"), "angle"),
                                          (dict(omega0="-3rad/s"), "omega0"), (dict(hanging_mass="1kg"), "hanging_mass")])
def test_what_a_yo_yo_spun_in_place_cannot_take_is_refused(options, name):
    with pytest.raises(InputError) as caught:
        taucli.rolling("disc", in_place=True, mass="0.2kg", radius="3cm", **options)
    assert caught.value.option == name


@pytest.mark.parametrize("body,name", [(dict(k2=0, radius="3cm"), "k2"), (dict(inertia=0, mass="1kg", axle_radius="1cm"), "inertia")])
def test_no_rotational_inertia_cannot_be_spun_in_place(body, name):
    with pytest.raises(InputError) as caught:
        taucli.rolling(in_place=True, **body)
    assert caught.value.option == name


def test_spun_in_place_from_the_command_line(taucli):
    out = taucli("rolling", "disc", "--in-place", "--mass", "0.5kg", "--radius", "4cm", "--get", "a_hand", "--get", "T")
    assert [float(line) for line in out.out.split()] == pytest.approx([2 * G, 0.5 * G], rel=1e-15)
