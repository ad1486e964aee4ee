"""Rolling and slipping: each case against the article's three equations solved with mpmath,
energy conservation, and continuity at the roll/slip boundary."""

from __future__ import annotations

import math

import mpmath
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from taucli.core.errors import InputError
from taucli.scenes.rolling import K2, Roller, roller, solve_flat, solve_incline


def values(report):
    return {name: value.value for name, value in report.results.items()}


def rolling_reference(k2, mass, radius, angle, g):
    """Unknowns a, α, f:  m a + f = m g sin θ;  I α − f R = 0;  a − R α = 0."""
    with mpmath.workdps(40):
        k2, m, r, angle, g = (mpmath.mpf(x) for x in (k2, mass, radius, angle, g))
        matrix = mpmath.matrix([[m, 0, 1], [0, k2 * m * r**2, -r], [1, -r, 0]])
        return mpmath.lu_solve(matrix, mpmath.matrix([m * g * mpmath.sin(angle), 0, 0]))


def slipping_reference(k2, mass, radius, angle, g, mu_k):
    """f = μk N is known; m a = m g sin θ − f and I α = f R give a and α."""
    with mpmath.workdps(40):
        k2, m, r, angle, g, mu_k = (mpmath.mpf(x) for x in (k2, mass, radius, angle, g, mu_k))
        friction = mu_k * m * g * mpmath.cos(angle)
        return (m * g * mpmath.sin(angle) - friction) / m, friction * r / (k2 * m * r**2), friction


angles = st.floats(0, math.radians(89.9))


@settings(max_examples=200, deadline=None)
@given(shape=st.sampled_from(sorted(K2)), mass=st.floats(0.01, 100), radius=st.floats(0.001, 10), angle=angles, g=st.floats(1, 30))
def test_rolling_solves_the_three_equations(shape, mass, radius, angle, g):
    result = values(solve_incline(Roller(K2[shape], shape, mass, radius), angle, g))
    a, alpha, friction = rolling_reference(K2[shape], mass, radius, angle, g)
    assert result["a"] == pytest.approx(float(a), rel=1e-14, abs=1e-300)
    assert result["alpha"] == pytest.approx(float(alpha), rel=1e-14, abs=1e-300)
    assert result["friction"] == pytest.approx(float(friction), rel=1e-14, abs=1e-300)
    assert result["rolls"] is True


@settings(max_examples=200, deadline=None)
@given(k2=st.floats(0.05, 1.5), mass=st.floats(0.01, 100), radius=st.floats(0.001, 10), angle=st.floats(0.2, 1.5), mu=st.floats(0, 1))
def test_slipping_solves_translation_and_rotation_with_kinetic_friction(k2, mass, radius, angle, mu):
    mu_min = math.tan(angle) * k2 / (1 + k2)
    mu_s = mu_min * 0.5
    mu_k = min(mu, mu_s)
    result = values(solve_incline(Roller(k2, "body", mass, radius), angle, 9.80665, mu_s=mu_s, mu_k=mu_k))
    assert result["rolls"] is False
    a, alpha, friction = slipping_reference(k2, mass, radius, angle, 9.80665, mu_k)
    assert result["a"] == pytest.approx(float(a), rel=1e-13)
    assert result["alpha"] == pytest.approx(float(alpha), rel=1e-13, abs=1e-300)
    assert result["friction"] == pytest.approx(float(friction), rel=1e-13, abs=1e-300)


@settings(max_examples=200, deadline=None)
@given(shape=st.sampled_from(sorted(K2)), mass=st.floats(0.01, 100), radius=st.floats(0.001, 10), angle=st.floats(0.01, 1.5), height=st.floats(0.01, 100))
def test_pure_rolling_conserves_energy(shape, mass, radius, angle, height):
    g = 9.80665
    result = values(solve_incline(Roller(K2[shape], shape, mass, radius), angle, g, height=height))
    v = result["v"]
    omega = v / radius
    kinetic = 0.5 * mass * v * v + 0.5 * K2[shape] * mass * radius**2 * omega**2
    assert kinetic == pytest.approx(mass * g * height, rel=1e-13)
    assert result["KE_trans"] + result["KE_rot"] == pytest.approx(mass * g * height, rel=1e-13)


@pytest.mark.parametrize("shape", sorted(K2))
def test_roll_slip_boundary_is_continuous(shape):
    k2, angle = K2[shape], math.radians(35)
    mu_min = math.tan(angle) * k2 / (1 + k2)
    roller = Roller(k2, shape, 2.0, 0.1)
    at = values(solve_incline(roller, angle, 9.8, mu_s=mu_min, mu_k=mu_min))
    below_mu = mu_min * (1 - 1e-12)
    below = values(solve_incline(roller, angle, 9.8, mu_s=below_mu, mu_k=below_mu))
    above = values(solve_incline(roller, angle, 9.8, mu_s=mu_min * (1 + 1e-12), mu_k=mu_min))
    assert at["rolls"] is True and above["rolls"] is True and below["rolls"] is False
    for name in ("a", "friction", "alpha"):
        assert below[name] == pytest.approx(at[name], rel=1e-10)
        assert above[name] == pytest.approx(at[name], rel=1e-10)


def test_skidding_ball_reaches_five_sevenths_of_its_speed():
    """A bowled ball with no spin rolls at 5/7 v0; the time from the equations of motion."""
    mu_k, g, v0, radius = 0.2, 9.81, 5.0, 0.11
    result = values(solve_flat(Roller(0.4, "sphere", 0.16, radius), g, mu_k=mu_k, v0=v0))
    assert result["v_roll"] == pytest.approx(5 * v0 / 7, rel=1e-15)
    with mpmath.workdps(30):
        # v(t) = v0 − μk g t and R ω(t) = (μk g / k2) t; the slip vanishes at the root:
        t_ref = mpmath.findroot(lambda t: (v0 - mu_k * g * t) - (mu_k * g / mpmath.mpf(0.4)) * t, 0.5)
    assert result["t_roll"] == pytest.approx(float(t_ref), rel=1e-14)
    assert result["d_roll"] == pytest.approx(float(v0 * t_ref - mu_k * g * t_ref**2 / 2), rel=1e-14)
    lost = 0.5 * 0.16 * v0**2 - 0.5 * 0.16 * (5 * v0 / 7) ** 2 * 1.4
    assert result["energy_lost"] == pytest.approx(lost, rel=1e-13)


def test_a_body_given_by_its_inertia_has_k2_from_it():
    assert roller(None, None, 0.004, 1.0, 0.1).k2 == pytest.approx(0.4, rel=1e-15)


def test_backspin_slows_the_ball_more():
    result = values(solve_flat(Roller(0.4, "sphere", None, 0.1), 9.8, mu_k=0.2, v0=5.0, omega0=-20.0))
    assert result["v_roll"] == pytest.approx((5.0 - 0.4 * 2.0) / 1.4)


def test_without_friction_a_skidding_ball_never_rolls():
    """Found by the fuzz suite (#9): μk = 0 divided by zero (exit 1). With no force at the contact
    v and ω stay as they are (m dv/dt = 0, I dω/dt = 0): it never rolls, and loses no energy."""
    report = solve_flat(Roller(0.4, "sphere", 2.0, 0.1), 9.8, mu_k=0.0, v0=3.0, omega0=5.0)
    result = values(report)
    assert result["t_roll"] is None and result["v_roll"] is None and result["d_roll"] is None
    assert result["energy_lost"] == 0.0
    assert any("never rolls" in note for note in report.notes)
    trajectory = report.trajectory()
    assert [trajectory.state(t) for t in (0.0, 0.5, 1.0)] == [(0.0, 3.0), (1.5, 3.0), (3.0, 3.0)]


@given(shape=st.sampled_from(sorted(K2)), v0=st.floats(0.1, 50), angle=st.floats(0.05, 1.5))
def test_climbing_turns_all_kinetic_energy_into_height(shape, v0, angle):
    k2 = K2[shape]
    result = values(solve_incline(Roller(k2, shape), angle, 9.80665, v0=v0))
    assert 9.80665 * result["h_climb"] == pytest.approx(0.5 * v0 * v0 * (1 + k2), rel=1e-13)


@pytest.mark.parametrize(
    "call,fragment",
    [
        (lambda: solve_incline(Roller(0.4, "sphere"), math.radians(90.5), 9.8), "angle"),
        (lambda: solve_incline(Roller(0.4, "sphere"), -0.1, 9.8), "angle"),
        (lambda: solve_incline(Roller(0.4, "sphere"), 0.5, 9.8, mu_s=0.1, mu_k=0.2), "mu_k must not exceed"),
        (lambda: solve_incline(Roller(0.4, "sphere"), 0.5, 9.8, length=1, height=1), "length conflicts"),
        (lambda: solve_flat(Roller(0.4, "sphere"), 9.8, mu_k=None, v0=3.0), "mu_k is required"),
        (lambda: solve_flat(Roller(0.4, "sphere"), 9.8, mu_k=0.3, mu_s=0.2, v0=3.0), "mu_k must not exceed"),
        (lambda: roller("sphear", None, None, None, None), "did you mean 'sphere'?"),
        (lambda: roller("sphere", 0.4, None, None, None), "k2 conflicts with shape"),
        (lambda: roller(None, None, 0.01, 1.0, None), "radius is required with inertia"),
        (lambda: solve_flat(Roller(0.4, "sphere"), 9.8, mu_k=0.2, v0=3.0, omega0=5.0), "radius is required"),
    ],
)
def test_impossible_scenes_are_input_errors(call, fragment):
    with pytest.raises(InputError) as caught:
        call()
    assert fragment in str(caught.value)


# Roll or slip with what is given (#16, items 9-11) -------------------------------------------

G = 9.80665


def test_a_ring_that_slips_without_mu_k_reports_what_it_knows():
    """#16: `rolling ring --angle 60deg --mu-s 0.6` refused ('--mu-k is required') though it
    knows the ring slips: μ_min = tan 60° · 1/2 = 0.866 > 0.6. It reports rolls = false and
    μ_min; a, alpha, friction (and v, t at the bottom) need μk: null, with a note."""
    report = solve_incline(Roller(1.0, "ring", 2.0, 0.1), math.radians(60), G, mu_s=0.6, length=2.0)
    result = values(report)
    with mpmath.workdps(30):
        mu_min = mpmath.tan(mpmath.radians(60)) / 2
    assert result["rolls"] is False
    assert result["mu_min"] == pytest.approx(float(mu_min), rel=1e-15)
    for name in ("a", "alpha", "friction", "v", "t"):
        assert result[name] is None, name
    assert any("--mu-k" in note and "slips" in note for note in report.notes)
    report.steps[:]  # the steps are written without the missing numbers


def test_with_only_mu_k_static_friction_is_taken_equal_to_it_in_both_scenes():
    """#16: with only μk, rolling assumed it rolls while atwood took μs = μk. One rule now, and
    one note: μs = μk, the least static friction can be. A sphere on 60° with μk = 0.1 (μ_min
    = 0.495) slips: a = g(sin θ − μk cos θ); with μk = 0.6 it rolls, as any μs ≥ μk would."""
    angle = math.radians(60)
    slipping = solve_incline(Roller(0.4, "sphere", 1.0, 0.1), angle, G, mu_k=0.1)
    with mpmath.workdps(30):
        theta = mpmath.radians(60)
        exact = G * (mpmath.sin(theta) - mpmath.mpf(0.1) * mpmath.cos(theta))
    assert slipping.results["rolls"].value is False
    assert slipping.results["a"].value == pytest.approx(float(exact), rel=1e-14)
    assert values(solve_incline(Roller(0.4, "sphere"), angle, G, mu_k=0.6))["rolls"] is True

    from taucli.scenes.atwood import Pulley, Slope
    from taucli.scenes.atwood import solve as atwood

    machine = atwood(1.0, 1.0, Pulley(), G, slope=Slope(angle, 0.1))
    (rolling_note,) = [n for n in slipping.notes if "--mu-s" in n]
    (atwood_note,) = [n for n in machine.notes if "--mu-s" in n]
    assert rolling_note.split(":")[0] == atwood_note.split(":")[0] == "no --mu-s"
    assert "μs = μk" in rolling_note and "μs = μk" in atwood_note


@pytest.mark.parametrize("shape", sorted(K2))
def test_with_only_mu_k_the_roll_slip_boundary_is_continuous(shape):
    k2, angle = K2[shape], math.radians(40)
    mu_min = math.tan(angle) * k2 / (1 + k2)
    body = Roller(k2, shape, 2.0, 0.1)
    above = values(solve_incline(body, angle, G, mu_k=mu_min * (1 + 1e-12)))
    below = values(solve_incline(body, angle, G, mu_k=mu_min * (1 - 1e-12)))
    assert above["rolls"] is True and below["rolls"] is False
    for name in ("a", "alpha", "friction"):
        assert below[name] == pytest.approx(above[name], rel=1e-10)


@pytest.mark.parametrize("shape", sorted(K2))
def test_a_vertical_face_gives_free_fall_and_no_friction(shape):
    """#16: `rolling disc --angle 90deg` was refused. On a vertical face N = 0: no friction, so
    a = g, α = 0 whatever μ, and no μs makes it roll (μ_min = tan θ · k²/(1 + k²) -> ∞: null)."""
    body = Roller(K2[shape], shape, 2.0, 0.1)
    for friction in ({}, {"mu_s": 0.5}, {"mu_s": 0.5, "mu_k": 0.3}, {"mu_k": 0.3}):
        report = solve_incline(body, math.pi / 2, G, height=1.0, **friction)
        result = values(report)
        assert result["a"] == G and result["friction"] == 0.0 and result["alpha"] == 0.0
        assert result["rolls"] is False and result["mu_min"] is None
        assert result["v"] == pytest.approx(math.sqrt(2 * G), rel=1e-15)
        assert any("mu_min" in note and "no normal force" in note for note in report.notes)
    near = values(solve_incline(body, math.pi / 2 - 1e-9, G, mu_s=0.5, mu_k=0.3))
    assert near["a"] == pytest.approx(G, rel=1e-9) and near["rolls"] is False


def test_a_body_with_no_rotational_inertia_needs_no_friction_to_roll():
    """k² = 0 (the limit of a wheel whose mass is all at its axle): rolling needs f = 0, so it
    rolls on any surface with a = g sin θ, μ_min = 0, and on the flat its spin matches its speed
    at once with nothing lost. The limit k² -> 0 of each result."""
    angle = math.radians(30)
    zero = values(solve_incline(Roller(0.0, "body", 1.0, 0.1), angle, G, mu_s=0.1, mu_k=0.05, length=1.0))
    tiny = values(solve_incline(Roller(1e-12, "body", 1.0, 0.1), angle, G, mu_s=0.1, mu_k=0.05, length=1.0))
    assert zero["rolls"] is True and zero["mu_min"] == 0.0 and zero["friction"] == 0.0
    assert zero["a"] == pytest.approx(G * 0.5, rel=1e-15)
    for name in ("a", "alpha", "v", "t", "KE_trans"):
        assert zero[name] == pytest.approx(tiny[name], rel=1e-11)
    flat = values(solve_flat(Roller(0.0, "body", 1.0, 0.1), G, mu_k=0.2, v0=3.0, omega0=5.0))
    assert flat["t_roll"] == 0.0 and flat["v_roll"] == 3.0 and flat["energy_lost"] == 0.0
    vertical = values(solve_incline(Roller(0.0, "body", 1.0, 0.1), math.pi / 2, G))
    assert vertical["a"] == G and vertical["alpha"] is None  # no torque on no inertia: α is not fixed


def friction_work_reference(k2, mass, radius, mu_k, g, v0, omega0):
    """The heat made while the ball skids, from the equations of motion alone (40 digits):
    m dv/dt = −μk m g sgn s, k² m R² dω/dt = μk m g R sgn s, s = v − Rω; friction does work
    μk m g |s| per unit time on the sliding contact until s = 0 (found by findroot)."""
    with mpmath.workdps(40):
        k2, m, r, mu, g, v0, w0 = (mpmath.mpf(x) for x in (k2, mass, radius, mu_k, g, v0, omega0))
        sign = mpmath.sign(v0 - r * w0)
        slip = lambda t: (v0 - sign * mu * g * t) - r * (w0 + sign * mu * g * t / (k2 * r))  # noqa: E731
        if sign == 0:
            return mpmath.mpf(0)
        t_roll = mpmath.findroot(slip, abs(v0 - r * w0) / (mu * g))
        return mpmath.quad(lambda t: mu * m * g * abs(slip(t)), [0, t_roll])


@settings(max_examples=300, deadline=None)
@given(
    k2=st.one_of(st.sampled_from(sorted(K2.values())), st.floats(1e-3, 2)),
    v0=st.floats(-50, 50),
    spin=st.one_of(st.floats(-50, 50), st.just(None)),
    closeness=st.one_of(st.just(0.0), st.integers(1, 50).map(lambda e: 2.0**-e)),
)
@example(k2=0.4, v0=81.33599174441359, spin=None, closeness=2.0**-30)
def test_skidding_energy_lost_is_never_negative_and_matches_the_work_of_friction(k2, v0, spin, closeness):
    """#16: energy_lost was KE before − KE after, which cancels when the ball nearly rolls
    already and came out negative (−9e-13 J for v0 = 81.3 m/s, Rω0 = v0(1 − 1e-9)). It is
    ½ m k²/(1 + k²) (v0 − Rω0)²: ≥ 0, and within 1e-13 of the friction's work where the slip
    is well conditioned; where v0 and Rω0 nearly cancel, within the rounding of Rω0 itself,
    amplified by κ = (|v0| + |Rω0|)/|v0 − Rω0| (twice: the energy goes as the slip squared)."""
    mass, radius, mu_k, g = 0.16, 0.11, 0.2, 9.81
    spin_speed = v0 * (1 - closeness) if spin is None else spin  # R ω0; near v0 the two cancel
    omega0 = spin_speed / radius
    lost = solve_flat(Roller(k2, "body", mass, radius), g, mu_k=mu_k, v0=v0, omega0=omega0).results["energy_lost"].value
    assert lost >= 0
    exact = friction_work_reference(k2, mass, radius, mu_k, g, v0, omega0)
    with mpmath.workdps(40):
        slip = abs(v0 - mpmath.mpf(radius) * omega0)
        conditioning = float((abs(v0) + abs(spin_speed)) / slip) if slip else 1.0
    assert abs(mpmath.mpf(lost) - exact) <= max(1e-13, 8 * 2.0**-53 * conditioning) * exact + 1e-300
