"""#34 items 7 and 10: each block hanging, on a table or on its own incline; pulls on the blocks; a
drive and a brake on the pulley; the stop and what follows it; both strings on one side of a
stepped pulley; a pulley of parts on steps without --pulley-radius; a string that would go slack.

The references are written from the physics, not from the solver: Newton's law for each block
along its path and for the pulley about its axle, with the string's constraints, solved as one
linear system in mpmath (40 digits); whether the machine moves from rest from the power of its
forces at unit speed against the most static friction can give; the energy balance (the work of
gravity, of the pulls, of the drive and of friction against the kinetic energies of the blocks
and the pulley). The textbook problems carry the book's printed answers.
"""

from __future__ import annotations

import json
import math

import mpmath
import pytest
from hypothesis import assume, event, example, given, settings
from hypothesis import strategies as st

import taucli
from conftest import assert_usage_error, run_taucli, with_notes_as_keys
from taucli.core.errors import InputError
from taucli.scenes.atwood import HANGING, Machine, Pulley, Slope, solve, solve_machine, solve_stepped

MP_DPS = 40
G = 9.80665


def values(report) -> dict:
    return {name: value.value for name, value in report.results.items()}


# The reference: Newton for each body ------------------------------------------------------------


def newton(m1, m2, side1, side2, pull1, pull2, torque, axle, inertia, r1, r2, same, g, s, mu1, mu2):
    """Unknowns a1 (m1's acceleration away from the pulley), a2 (m2's towards it), α (the pulley's,
    positive as m1 goes away), T1, T2; moving in sense s (m1 away from the pulley: s = +1):

        m1:      m1 a1 = m1 g sin θ1 + P1 cos φ1 − T1 − s μ1 N1
        m2:      m2 a2 = T2 − m2 g sin θ2 − P2 cos φ2 − s σ μ2 N2     (m2's velocity is σ r2/r1 times m1's)
        pulley:  I α = T1 r1 − σ T2 r2 − τd − s τa
        strings: a1 = α r1,  a2 = σ α r2

    each side (θ, μ) with θ = 90° hanging, N = m g cos θ − P sin φ; σ = −1 where both strings are on one side."""
    mp = mpmath.mpf
    sigma = -1 if same else 1
    m1, m2, g, inertia, r1, r2, torque, axle = map(mp, (m1, m2, g, inertia, r1, r2, torque, axle))
    (t1, p1, phi1), (t2, p2, phi2) = ((side1, *pull1), (side2, *pull2))
    sin1, cos1 = (mp(1), mp(0)) if t1 == HANGING else (mpmath.sin(t1), mpmath.cos(t1))
    sin2, cos2 = (mp(1), mp(0)) if t2 == HANGING else (mpmath.sin(t2), mpmath.cos(t2))
    n1 = m1 * g * cos1 - mp(p1) * mpmath.sin(phi1)
    n2 = m2 * g * cos2 - mp(p2) * mpmath.sin(phi2)
    # rows: the five equations in (a1, a2, alpha, T1, T2)
    matrix = mpmath.matrix([
        [m1, 0, 0, 1, 0],
        [0, m2, 0, 0, -1],
        [0, 0, inertia, -r1, sigma * r2],
        [1, 0, -r1, 0, 0],
        [0, 1, -sigma * r2, 0, 0],
    ])
    rhs = mpmath.matrix([
        m1 * g * sin1 + mp(p1) * mpmath.cos(phi1) - s * mp(mu1) * n1,
        -m2 * g * sin2 - mp(p2) * mpmath.cos(phi2) - s * sigma * mp(mu2) * n2,
        -torque - s * axle,
        0,
        0,
    ])
    a1, a2, alpha, tension1, tension2 = mpmath.lu_solve(matrix, rhs)
    return dict(a=a1, a2=a2, alpha=alpha, T1=tension1, T2=tension2, N1=n1, N2=n2)


def sets_off(m1, m2, side1, side2, pull1, pull2, torque, axle, r1, r2, same, g, mus1, mus2) -> int:
    """From rest: +1 or −1 where the forces' power at unit speed (m1 away from the pulley at 1 m/s)
    beats the most static friction can take, 0 where it cannot."""
    mp = mpmath.mpf
    m1, m2, g = mp(m1), mp(m2), mp(g)
    sigma = -1 if same else 1
    speed2 = sigma * mp(r2) / r1  # m2's speed towards the pulley
    sin1 = mp(1) if side1 == HANGING else mpmath.sin(side1)
    sin2 = mp(1) if side2 == HANGING else mpmath.sin(side2)
    cos1 = mp(0) if side1 == HANGING else mpmath.cos(side1)
    cos2 = mp(0) if side2 == HANGING else mpmath.cos(side2)
    power = ((m1 * g * sin1 + mp(pull1[0]) * mpmath.cos(pull1[1])) * 1
             - (m2 * g * sin2 + mp(pull2[0]) * mpmath.cos(pull2[1])) * speed2 - mp(torque) / r1)
    grip = (mp(mus1) * (m1 * g * cos1 - mp(pull1[0]) * mpmath.sin(pull1[1])) + mp(mus2) * (m2 * g * cos2 - mp(pull2[0]) * mpmath.sin(pull2[1])) * abs(speed2)
            + mp(axle) / r1)
    return 0 if abs(power) <= grip else (1 if power > 0 else -1)


def readable(low: float, high: float):
    """Floats in [low, high], 0 or at least 1e-40 in size, as the units read a quantity (no subnormal inputs)."""
    return st.floats(low, high).filter(lambda x: x == 0 or abs(x) >= 1e-40)


angles = st.one_of(st.just(HANGING), st.just(0.0), st.floats(0.05, 1.5))
pull = st.one_of(st.just((0.0, 0.0)), st.tuples(readable(-30, 60), readable(-1.2, 1.2)))


@st.composite
def machines(draw):
    m1 = draw(st.floats(0.05, 20))
    m2 = draw(st.one_of(st.just(0.0), st.floats(0.05, 20)))
    side1, side2 = draw(angles), draw(angles)
    pull1, pull2 = draw(pull), draw(pull)
    if side1 == HANGING:
        pull1 = (pull1[0], 0.0)
    if side2 == HANGING:
        pull2 = (pull2[0], 0.0)
    mu1 = 0.0 if side1 == HANGING else draw(readable(0, 0.8))
    mu2 = 0.0 if side2 == HANGING else draw(readable(0, 0.8))
    stepped = draw(st.booleans())
    r1 = draw(st.floats(0.02, 0.5))
    r2 = draw(st.floats(0.02, 0.5)) if stepped else r1
    same = draw(st.booleans()) if draw(st.booleans()) else False
    inertia = draw(st.one_of(st.just(0.0), st.floats(1e-4, 2)))
    torque = draw(st.one_of(st.just(0.0), readable(-40, 40)))
    axle = draw(st.one_of(st.just(0.0), readable(0, 3)))
    v0 = draw(st.sampled_from([0.0, 0.0, 1.5, -2.0]))
    return dict(m1=m1, m2=m2, side1=side1, side2=side2, pull1=pull1, pull2=pull2, mu1=mu1, mu2=mu2, stepped=stepped, r1=r1, r2=r2,
                same=same, inertia=inertia, torque=torque, axle=axle, v0=v0)


def build(c, *, time=None, distance=None, stop=False):
    pulls = tuple((p[0] * math.cos(p[1]), p[0] * math.sin(p[1])) for p in (c["pull1"], c["pull2"]))
    machine = Machine(
        c["m1"], c["m2"], Pulley(0.0, c["r1"], None, c["inertia"], c["axle"]), G,
        Slope(c["side1"], c["mu1"], c["mu1"]), Slope(c["side2"], c["mu2"], c["mu2"]), pulls[0], pulls[1], c["torque"],
        (c["r1"], c["r2"]) if c["stepped"] else None, c["same"],
    )
    return solve_machine(machine, v0=c["v0"], time=time, distance=distance, stop=stop)


def _lifted(c) -> bool:
    return any(side != HANGING and (m * G * math.cos(side) - p[0] * math.sin(p[1])) < 0
               for side, m, p in ((c["side1"], c["m1"], c["pull1"]), (c["side2"], c["m2"], c["pull2"])))


@settings(max_examples=400, deadline=None)
@given(c=machines())
@example(c=dict(m1=1.0, m2=1.0, side1=HANGING, side2=HANGING, pull1=(0.0, 0.0), pull2=(0.0, 0.0), mu1=0.0, mu2=0.0, stepped=False, r1=0.1, r2=0.1,
                same=False, inertia=0.0, torque=0.0, axle=2.5, v0=-3.0))  # the issue's string that pushes: T1 = −2.69 N, refused
def test_each_body_obeys_newton_and_a_string_only_pulls(c):
    """a, a2, α, T1, T2 against the five equations solved in mpmath; refused exactly where the
    reference needs a tension below zero (a slack string), or a pull lifts a block off its surface."""
    assume(c["m1"] + c["m2"] * (c["r2"] / c["r1"]) ** 2 + c["inertia"] / c["r1"] ** 2 > 0)
    if _lifted(c):
        with pytest.raises(InputError, match="lifts it off its surface"):
            build(c)
        return
    with mpmath.workdps(40):
        sense = int(mpmath.sign(c["v0"])) if c["v0"] else sets_off(c["m1"], c["m2"], c["side1"], c["side2"], c["pull1"], c["pull2"], c["torque"],
                                                                   c["axle"], c["r1"], c["r2"], c["same"], G, c["mu1"], c["mu2"])
        assume(sense != 0)  # held: statics, below
        ref = newton(c["m1"], c["m2"], c["side1"], c["side2"], c["pull1"], c["pull2"], c["torque"], c["axle"], c["inertia"], c["r1"], c["r2"],
                     c["same"], G, sense, c["mu1"], c["mu2"])
        scale = G * (c["m1"] + c["m2"]) + sum(abs(p[0]) for p in (c["pull1"], c["pull2"])) + (abs(c["torque"]) + c["axle"]) / c["r1"]
        slack = min(ref["T1"], ref["T2"]) < -1e-9 * scale
        near = abs(min(ref["T1"], ref["T2"])) <= 1e-9 * scale
    assume(not near)  # a string on the point of going slack: either answer is the rounding's
    if slack:
        event("slack: refused")
        with pytest.raises(InputError, match="goes slack"):
            build(c)
        return
    event("moving: compared" + (" (stepped)" if c["stepped"] else "") + (" (one side)" if c["same"] else ""))
    result = values(build(c))
    accel = float(abs(ref["a"])) + scale / (c["m1"] + c["m2"] + c["inertia"] / c["r1"] ** 2 + 1e-300)
    assert result["a"] == pytest.approx(float(ref["a"]), rel=1e-11, abs=1e-12 * accel)
    assert result["alpha"] == pytest.approx(float(ref["alpha"]), rel=1e-11, abs=1e-12 * accel / c["r1"])
    assert result["T1"] == pytest.approx(float(ref["T1"]), rel=1e-11, abs=1e-11 * scale)
    assert result["T2"] == pytest.approx(float(ref["T2"]), rel=1e-11, abs=1e-11 * scale * max(1, c["r1"] / c["r2"]))
    if c["stepped"] or c["same"]:  # the string's constraint: m2 moves σ r2/r1 as fast as m1
        assert result["a2"] == pytest.approx(float(ref["a2"]), rel=1e-11, abs=1e-12 * accel * c["r2"] / c["r1"])


@settings(max_examples=300, deadline=None)
@given(c=machines(), fraction=st.floats(0.05, 3))
@example(c=dict(m1=0.05, m2=0.05000000000000001, side1=HANGING, side2=HANGING, pull1=(0.0, 0.0), pull2=(0.0, 0.0), mu1=0.0, mu2=0.0, stepped=False,
                r1=0.5, r2=0.5, same=False, inertia=0.0, torque=0.0, axle=0.0, v0=0.0), fraction=1.0)  # m1 g − m2 g in floats lost the balance
def test_the_work_of_the_forces_is_the_kinetic_energy_gained(c, fraction):
    """At --time t, across a stop too: W_gravity + W_pulls + W_drive − W_friction = ΔKE, with
    KE = ½m1v1² + ½m2v2² + ½Iω² body by body (v2 = σ(r2/r1)v1, ω = v1/r1). The conservative and
    driving forces' work is their force times each block's displacement (the drive's, −τd θ);
    friction's is its size times the path, out and back."""
    assume(not _lifted(c))
    assume(c["m1"] + c["m2"] + c["inertia"] > 0)
    try:
        first = values(build(c, stop=True))
    except InputError:
        assume(False)
    stop = first.get("t_stop")
    scale_t = abs(stop) if stop else math.sqrt(c["r1"] / G) + abs(c["v0"]) / G
    t = fraction * scale_t
    try:
        report = build(c, time=t, stop=True)
    except InputError:
        assume(False)
    r = values(report)
    assume(r["a"] is not None)
    rho = (-1 if c["same"] else 1) * c["r2"] / c["r1"]
    x, v, v0 = r["distance"], r["v"], c["v0"]
    with mpmath.workdps(40):
        mp = mpmath.mpf
        sin1 = mp(1) if c["side1"] == HANGING else mpmath.sin(c["side1"])
        sin2 = mp(1) if c["side2"] == HANGING else mpmath.sin(c["side2"])
        cos1 = mp(0) if c["side1"] == HANGING else mpmath.cos(c["side1"])
        cos2 = mp(0) if c["side2"] == HANGING else mpmath.cos(c["side2"])
        p1, p2 = c["pull1"], c["pull2"]
        away1, away2 = mp(x), -rho * mp(x)  # each block's displacement away from the pulley
        work = ((mp(c["m1"]) * G * sin1 + p1[0] * mpmath.cos(p1[1])) * away1 + (mp(c["m2"]) * G * sin2 + p2[0] * mpmath.cos(p2[1])) * away2
                - c["torque"] * mp(x) / c["r1"])  # (in mpmath from the start: m1 g − m2 g may nearly cancel)
        if stop is not None and stop > 0 and t > stop:
            path = abs(mp(r["distance_stop"])) + abs(mp(x) - mp(r["distance_stop"]))
        else:
            path = abs(mp(x))
        friction = (c["mu1"] * (mp(c["m1"]) * G * cos1 - p1[0] * mpmath.sin(p1[1])) + abs(rho) * c["mu2"] * (mp(c["m2"]) * G * cos2 - p2[0] * mpmath.sin(p2[1]))
                    + c["axle"] / mp(c["r1"])) * path
        kinetic = lambda u: (c["m1"] * u**2 + c["m2"] * (rho * u) ** 2 + c["inertia"] * (u / c["r1"]) ** 2) / 2  # noqa: E731
        gained = kinetic(mp(v)) - kinetic(mp(v0))
        size = abs(work) + abs(friction) + kinetic(mp(v)) + kinetic(mp(v0)) + 1e-300
        assert abs(work - friction - gained) <= 1e-9 * size, (float(work), float(friction), float(gained))


# Static friction holds where it can, and the tensions at rest --------------------------------------


@settings(max_examples=300, deadline=None)
@given(c=machines(), extra=readable(0, 0.5))
def test_held_machines_balance_within_their_static_limits(c, extra):
    """At rest (from rest, where the forces cannot beat static friction, μs = μk + extra): each
    tension statics fixes balances its block and the pulley with frictions within their limits,
    and is ≥ 0; where it is null, the note's bounds are where such balances exist."""
    assume(not _lifted(c))
    c = {**c, "v0": 0.0}
    mus1 = 0.0 if c["side1"] == HANGING else c["mu1"] + extra
    mus2 = 0.0 if c["side2"] == HANGING else c["mu2"] + extra
    with mpmath.workdps(40):
        sense = sets_off(c["m1"], c["m2"], c["side1"], c["side2"], c["pull1"], c["pull2"], c["torque"], c["axle"], c["r1"], c["r2"], c["same"], G, mus1, mus2)
    assume(sense == 0)
    pulls = tuple((p[0] * math.cos(p[1]), p[0] * math.sin(p[1])) for p in (c["pull1"], c["pull2"]))
    machine = Machine(c["m1"], c["m2"], Pulley(0.0, c["r1"], None, c["inertia"], c["axle"]), G, Slope(c["side1"], c["mu1"], mus1),
                      Slope(c["side2"], c["mu2"], mus2), pulls[0], pulls[1], c["torque"], (c["r1"], c["r2"]) if c["stepped"] else None, c["same"])
    try:
        report = solve_machine(machine)
    except InputError as refused:
        assert "slack at rest" in str(refused)
        event("held: only a pushing string holds it")
        return
    r = values(report)
    if r["a"] != 0:
        event("on the edge: the solver sets it going")  # |F| equal to the grip to rounding
        return
    rho = (-1 if c["same"] else 1) * c["r2"] / c["r1"]
    sin = lambda t: 1.0 if t == HANGING else math.sin(t)  # noqa: E731
    cos = lambda t: 0.0 if t == HANGING else math.cos(t)  # noqa: E731
    along1 = c["m1"] * G * sin(c["side1"]) + pulls[0][0]
    along2 = c["m2"] * G * sin(c["side2"]) + pulls[1][0]
    limit1 = mus1 * (c["m1"] * G * cos(c["side1"]) - pulls[0][1])
    limit2 = mus2 * (c["m2"] * G * cos(c["side2"]) - pulls[1][1])
    axle, drive = c["axle"] / c["r1"], c["torque"] / c["r1"]
    scale = abs(along1) + abs(along2) * abs(rho) + limit1 + limit2 * abs(rho) + axle + abs(drive) + 1e-300
    if r["T1"] is not None and r["T2"] is not None:
        event("held: both tensions fixed")
        tolerance = 1e-12 * scale
        assert r["T1"] >= -tolerance and r["T2"] >= -tolerance
        assert abs(r["T1"] - along1) <= limit1 + tolerance
        assert abs(r["T2"] - along2) <= limit2 + tolerance * (1 + 1 / abs(rho))
        assert abs(r["T1"] - rho * r["T2"] - drive) <= axle + tolerance
    else:
        event("held: a tension bounded")
        assert any("statically indeterminate" in note for note in report.notes)


def test_held_on_two_rough_surfaces_the_tensions_are_bounded_not_guessed():
    """A 30° slope (m1 = 2 kg, μs = 0.5) against a table (m2 = 3 kg, μs = 0.4): the pull along
    the string, m1 g sin 30° = 9.8 N, is less than the 8.49 + 11.77 N static friction can give,
    so it holds; with friction under both blocks statics cannot share the load: T1 and T2 are
    null with their bounds, T1 in [m1 g sin θ − μs1 N1, m1 g sin θ + μs1 N1] ∩ (T2's ≥ 0)."""
    report = taucli.atwood(m1=2.0, m2=3.0, side1="incline angle=30deg mu-s=0.5 mu-k=0.3", side2="table mu-s=0.4 mu-k=0.3", g=9.8)
    r = values(report)
    assert r["a"] == 0 and r["T1"] is None and r["T2"] is None
    (note1,) = [n for n in report.notes if n.startswith("T1")]
    low, high = (float(x) for x in note1.split("between ")[1].split(" N")[0].split(" and "))
    along, grip1, grip2 = 2 * 9.8 * 0.5, 0.5 * 2 * 9.8 * math.cos(math.radians(30)), 0.4 * 3 * 9.8
    assert low == pytest.approx(max(along - grip1, 0), rel=1e-5) and high == pytest.approx(min(along + grip1, grip2), rel=1e-5)


def test_held_with_one_friction_statics_fixes_both_tensions():
    """m1 = 2 kg hanging, m2 = 5 kg on a table with μs = 0.5 (μk 0.4): held; T1 = T2 = m1 g (a
    massless pulley, no axle friction), static friction m1 g on m2."""
    r = values(taucli.atwood(m1=2.0, m2=5.0, side2="table mu-s=0.5 mu-k=0.4", g=9.8))
    assert r["a"] == 0 and r["T1"] == r["T2"] == pytest.approx(2 * 9.8, rel=1e-15)


def test_a_block_pushed_into_the_pulley_harder_than_anything_holds_it_is_refused():
    """A negative pull on a hanging m1 larger than its weight would need the string to push."""
    with pytest.raises(InputError, match="goes slack"):
        taucli.atwood(m1=1.0, m2=1.0, pull=["force=-30N on=1"], pulley_mass=1.0)


# The stop, and what follows ----------------------------------------------------------------------


def test_a_load_thrown_up_coasts_to_rest_and_comes_back():
    """m1 = 3 kg against m2 = 1 kg over a 2 kg disc, thrown up at 4 m/s: a = 2g/5 throughout
    (no friction), t_stop = 4/a, distance_stop = −16/(2a); at 2 t_stop it is back where it began."""
    a = 2 * G / 5
    r = values(taucli.atwood(m1=3.0, m2=1.0, pulley_mass=2.0, v0=-4.0, time=2 * 4 / a))
    assert r["t_stop"] == pytest.approx(4 / a, rel=1e-15)
    assert r["distance_stop"] == pytest.approx(-16 / (2 * a), rel=1e-15)
    assert r["distance"] == pytest.approx(0.0, abs=1e-14) and r["v"] == pytest.approx(4.0, rel=1e-14)


def test_a_descending_load_braked_stops_and_is_held():
    """100 kg lowered at 3 m/s from a 50 kg disc drum of radius 0.2 m, a 300 N·m brake: a =
    (m g − τ/R)/(m + M/2), negative; it stops at v0/|a| and the brake (more than m g R) holds it."""
    g = 9.8
    a = (100 * g - 300 / 0.2) / (100 + 25)
    r = values(taucli.atwood(m1=100.0, pulley_mass=50.0, pulley_radius=0.2, axle_friction=300.0, v0=3.0, time=2.0, g=g))
    assert r["a"] == pytest.approx(a, rel=1e-14)
    assert r["t_stop"] == pytest.approx(3 / -a, rel=1e-14) and r["distance_stop"] == pytest.approx(9 / (2 * -a), rel=1e-14)
    assert r["distance"] == r["distance_stop"] and r["v"] == 0


def test_no_stop_is_null_with_a_note_and_a_held_machine_stops_at_once():
    report = taucli.atwood(m1=3.0, m2=1.0, v0=1.0)
    assert report.results["t_stop"].value is None and report.results["distance_stop"].value is None
    assert any(note.startswith("t_stop, distance_stop: null") for note in report.notes)
    held = values(taucli.atwood(m1=1.0, m2=1.0, v0=0.0))
    assert held["t_stop"] == 0 and held["distance_stop"] == 0
    assert "t_stop" not in taucli.atwood(m1=3.0, m2=1.0).results  # without --v0 no stop is asked about


def test_after_a_stop_a_string_that_would_go_slack_is_refused_where_reached_and_noted_before():
    """m1 = 1 kg on a table (μ = 0.5) on a drum (I/R² = 2 kg) whose motor pays the string out
    (τ = −0.5 N·m at R = 0.1 m, 5 N along the string), m1 thrown towards the drum at 2 m/s: the
    drum's inertia and the table's friction slow it together, T1 = (f J − D)/(m1 + J) > 0; once
    stopped, the motor's 5 N beats the 4.9 N of static friction, but only a string that pushes
    could move m1 away from the drum: T1 = −f − m1 a < 0 there."""
    machine = dict(m1=1.0, side1="table mu-k=0.5", pulley_inertia=0.02, pulley_radius=0.1, torque=-0.5, v0=-2.0, g=9.8)
    first = values(taucli.atwood(**machine))
    assert first["a"] == pytest.approx((5 + 4.9) / 3, rel=1e-14) and first["T1"] == pytest.approx((4.9 * 2 - 5) / 3, rel=1e-13)
    stop = 2 / first["a"]
    before = taucli.atwood(**machine, time=0.5 * stop)
    assert any("after the stop the string would go slack" in note for note in before.notes)
    with pytest.raises(InputError, match="slack on m1's side after the stop"):
        taucli.atwood(**machine, time=2 * stop)


# The book's problems, with the book's answers ------------------------------------------------------


def test_verma_two_inclines_smooth_then_rough():
    """H. C. Verma, Concepts of Physics 1, ch. 10, ex. 27 and 28: 4 kg and 2 kg on 45° inclines,
    pulley I = 0.5 kg·m², r = 10 cm; answers 0.25 m/s², and 0.125 m/s² with μ = 0.5 under the 2 kg."""
    common = dict(m1=4.0, m2=2.0, side1="incline angle=45deg", pulley_inertia=0.5, pulley_radius=0.1, g=9.8)
    smooth = values(taucli.atwood(**common, side2="incline angle=45deg"))["a"]
    rough = values(taucli.atwood(**common, side2="incline angle=45deg mu-k=0.5"))["a"]
    assert round(smooth, 2) == 0.25 and round(rough, 2) == pytest.approx(0.12) and rough == pytest.approx(0.125, abs=0.0015)
    assert smooth == pytest.approx(2 * 9.8 / math.sqrt(2) / 56, rel=1e-14) and rough == pytest.approx(smooth / 2, rel=1e-14)


def test_serway_ramp_and_table_with_friction_under_both():
    """Serway and Jewett, PSE 9th ed., problem 10.32: 6.00 kg on a 30° ramp, 2.00 kg on the top, μk =
    0.360 under both, a 10.0 kg disc of 0.250 m; answers a = 0.309 m/s², T = 7.67 N and 9.22 N."""
    r = values(taucli.atwood(m1="6.00kg", side1="incline angle=30deg mu-k=0.360", m2="2.00kg", side2="table mu-k=0.360", pulley_mass="10.0kg",
                             pulley_radius="0.250m", g=9.8))
    assert f"{r['a']:.3f}" == "0.309" and f"{r['T2']:.2f}" == "7.67" and f"{r['T1']:.2f}" == "9.22"


def test_hrw_block_pulled_away_from_a_wheel():
    """Halliday, Resnick and Walker, Fundamentals of Physics, ch. 10, problem 87: P = 3.0 N on a
    2.0 kg block on a frictionless table, its cord on a wheel of I = 0.050 kg·m², R = 0.20 m;
    answer α = 4.6 rad/s² (= P R/(I + m R²))."""
    alpha = values(taucli.atwood(m1=2.0, side1="table", pull="force=3.0N", pulley_inertia=0.050, pulley_radius=0.20))["alpha"]
    assert f"{alpha:.1f}" == "4.6" and alpha == pytest.approx(3.0 * 0.2 / (0.05 + 2 * 0.04), rel=1e-14)


def test_giancoli_heavy_pulley_and_bucket():
    """Giancoli, Physics: Principles with Applications, ch. 8, "A heavy pulley": 15.0 N on a cord
    at 33.0 cm against 1.10 N·m takes it from rest to 30.0 rad/s in 3.00 s: I = 0.385 kg·m²;
    "Pulley and bucket": a 15.0 N bucket (1.53 kg) instead: α = 6.98 rad/s², a = 2.30 m/s²."""
    found = taucli.atwood(pull="force=15.0N", pulley_radius="33.0cm", axle_friction=1.10, find="pulley_inertia", want="alpha=10rad/s^2")
    assert f"{found.results['pulley_inertia'].value:.3f}" == "0.385"
    r = values(taucli.atwood(m1=1.53, pulley_inertia=0.385, pulley_radius=0.33, axle_friction=1.10, g=9.8))
    assert f"{r['alpha']:.2f}" == "6.98" and f"{r['a']:.2f}" == "2.30"


def test_mine_cage_drive_and_coast_to_rest():
    """The mine cage (4 t, a drum of 1.5 m, 750 kg, k = 600 mm, 3 kN·m of bearing friction; g = 9.8):
    the drive for 1.5 m/s² up, 37.44 kN·m; the drive ceasing at 6 m/s up: 9.64 m/s², and it rises
    v²/2a = 1.87 m (physicsforums.com thread 680184 gives the first two)."""
    cage = dict(m1="4t", part=["gyration=0.6m mass=750kg"], pulley_radius=0.75, axle_friction="3kN*m", g=9.8)
    torque = taucli.atwood(**cage, find="torque", want="a=-1.5m/s^2").results["torque"].value
    assert torque == pytest.approx(0.75 * 4000 * (9.8 + 1.5) + 270 * 1.5 / 0.75 + 3000, rel=1e-12) and round(torque / 1000, 2) == 37.44
    r = values(taucli.atwood(**cage, v0=-6.0))
    assert f"{r['a']:.2f}" == "9.64" and f"{-r['distance_stop']:.2f}" == "1.87"
    assert r["t_stop"] == pytest.approx(6 / r["a"], rel=1e-15)


def test_serway_vuille_two_cords_on_one_cylinder():
    """Serway and Vuille, College Physics 11th ed., problem 8.87: two equal masses m on cords
    wrapped around a solid cylinder M (both on one side): T = Mmg/(M + 4m), a = 4mg/(M + 4m)."""
    for big, small in ((3.0, 1.0), (2.6, 0.7), (10.0, 0.2)):
        r = values(taucli.atwood(m1=small, m2=small, pulley_mass=big, same_side=True, g=9.8))
        assert r["T1"] == pytest.approx(big * small * 9.8 / (big + 4 * small), rel=1e-14) == r["T2"]
        assert r["a"] == pytest.approx(4 * small * 9.8 / (big + 4 * small), rel=1e-14) and r["a2"] == -r["a"]


def test_serway_block_pulled_at_an_angle_beside_a_hanging_ball():
    """Serway and Jewett, PSE, Example 5.12 (symbolically): a block m1 on a rough table pulled
    away from the pulley with F at θ above the table, a ball m2 hanging: a = [F(cos θ + μk sin θ)
    − (m2 + μk m1) g]/(m1 + m2) (a massless pulley)."""
    m1, m2, force, theta, mu = 3.0, 1.0, 25.0, math.radians(30), 0.25
    r = values(taucli.atwood(m1=m1, side1=f"table mu-k={mu}", m2=m2, pull=f"force={force}N angle=30deg"))
    want = (force * (math.cos(theta) + mu * math.sin(theta)) - (m2 + mu * m1) * G) / (m1 + m2)
    assert r["a"] == pytest.approx(want, rel=1e-14)


def test_a_stepped_pulley_of_parts_needs_no_pulley_radius():
    """College of Marin, PHYS worksheet "Pulley": two welded discs of radii R and 2R of one length
    (masses m and 4m), I = (17/2)mR²; blocks on the steps, on opposite sides and on one."""
    parts = ["disc mass=1kg radius=0.1m", "disc mass=4kg radius=0.2m"]
    inertia = 8.5 * 1 * 0.1**2
    for same in (False, True):
        r = values(taucli.atwood(m1=2.0, m2=3.0, radius1=0.1, radius2=0.2, part=parts, same_side=same))
        sigma = -1 if same else 1
        alpha = G * (2 * 0.1 - sigma * 3 * 0.2) / (inertia + 2 * 0.01 + 3 * 0.04)
        assert r["alpha"] == pytest.approx(alpha, rel=1e-14) and r["a2"] == pytest.approx(sigma * alpha * 0.2, rel=1e-14)
    with_mass = taucli.atwood(m1=2.0, m2=3.0, radius1=0.1, radius2=0.2, pulley_mass=1.0, part=parts)
    assert any("taken out to the larger step, R = 0.2 m" in note for note in with_mass.notes)
    r = values(with_mass)
    assert r["alpha"] == pytest.approx(G * (0.2 - 0.6) / (inertia + 0.5 * 0.04 + 0.02 + 0.12), rel=1e-14)


def test_a_stepped_pulley_may_carry_a_block_on_a_slope_now():
    """#21 refused --incline with --radius1; the one coordinate takes it: m2 on a 30° slope on r2."""
    r = values(taucli.atwood(m1=1.0, m2=4.0, radius1=0.2, radius2=0.05, incline=math.radians(30), pulley_inertia=0.01))
    with mpmath.workdps(40):
        ref = newton(1.0, 4.0, HANGING, math.radians(30), (0, 0), (0, 0), 0, 0, 0.01, 0.2, 0.05, False, G, 1, 0, 0)
    assert r["alpha"] == pytest.approx(float(ref["alpha"]), rel=1e-13) and r["T2"] == pytest.approx(float(ref["T2"]), rel=1e-13)


def test_the_classic_solvers_are_the_general_machine():
    """solve and solve_stepped are solve_machine of the article's machine and of a stepped pulley."""
    assert values(solve(4.0, 1.0, Pulley(2.0, 0.1), 9.8)) == values(solve_machine(Machine(4.0, 1.0, Pulley(2.0, 0.1), 9.8)))
    stepped = values(solve_stepped(0.5, 1.0, Pulley(0.0, None, None, 0.04), 9.8, 0.2, 0.05))
    assert stepped == values(solve_machine(Machine(0.5, 1.0, Pulley(0.0, None, None, 0.04), 9.8, radii=(0.2, 0.05))))


# From the command line, batch and Python ---------------------------------------------------------


def test_the_command_line_batch_and_python_agree():
    args = ["--m1", "6kg", "--side1", "incline angle=30deg mu-k=0.36", "--m2", "2kg", "--side2", "table mu-k=0.36", "--pull", "force=5N angle=10deg on=2",
            "--torque", "1N*m", "--pulley-mass", "10kg", "--pulley-radius", "0.25m", "--v0", "-1m/s", "--time", "0.5s"]
    single = run_taucli("atwood", *args, "--json").json()
    line = json.dumps({"m1": "6kg", "side1": "incline angle=30deg mu-k=0.36", "m2": "2kg", "side2": "table mu-k=0.36", "pull": ["force=5N angle=10deg on=2"],
                       "torque": "1N*m", "pulley_mass": "10kg", "pulley_radius": "0.25m", "v0": "-1m/s", "time": "0.5s"})
    batch = json.loads(run_taucli("atwood", "--batch", stdin=line + "\n").out)
    assert batch == with_notes_as_keys(single)  # a key in batch, a flag on the command line (#42 item 19)
    python = taucli.atwood(m1="6kg", side1="incline angle=30deg mu-k=0.36", m2="2kg", side2="table mu-k=0.36", pull="force=5N angle=10deg on=2",
                           torque="1N*m", pulley_mass="10kg", pulley_radius="0.25m", v0="-1m/s", time="0.5s")
    assert {k: v["value"] for k, v in single["results"].items()} == values(python)
    assert "t_stop" in single["results"] and single["inputs"]["pull1_force"] == {"value": 5.0, "unit": "N"}


def test_the_wrap_needs_rim_mu_with_at_too():
    """#34: `--wrap 90deg --at 5cm` exited 0: atwood() called itself for --at without the wrap."""
    assert_usage_error(run_taucli("atwood", "--m1", "4kg", "--m2", "1kg", "--pulley-radius", "0.1m", "--wrap", "90deg", "--at", "5cm"), "--wrap needs --rim-mu")


def test_the_issue_string_that_pushes_is_refused():
    """#34: m1 thrown up against axle friction gave T1 = −2.67 N; a slack string is not modelled."""
    done = run_taucli("atwood", "--m1", "1kg", "--m2", "1kg", "--pulley-radius", "0.1m", "--axle-friction", "2.5N*m", "--v0", "-3m/s")
    assert_usage_error(done, "the string goes slack on m1's side", "T1 = -2.693 N", "not modelled")


@pytest.mark.parametrize(
    "args,fragments",
    [
        (("--m1", "1kg", "--side1", "incline"), ("--side1", "incline needs angle=")),
        (("--m1", "1kg", "--side1", "table angle=3deg"), ("--side1", "takes no angle=")),
        (("--m1", "1kg", "--side1", "hang mu-k=0.2"), ("--side1", "hang: takes no keys")),
        (("--m1", "1kg", "--side1", "shelf"), ("--side1", "expected hang, table, incline")),
        (("--m1", "1kg", "--side1", "table mu-k=0.5 mu-s=0.2"), ("--side1", "mu-s= below mu-k=")),
        (("--m1", "1kg", "--side1", "incline angle=100deg"), ("--side1 angle=", "0 to 90 deg")),
        (("--m1", "1kg", "--m2", "1kg", "--side2", "table", "--incline", "30deg"), ("--incline conflicts with --side2",)),
        (("--m1", "1kg", "--side2", "table"), ("--side2 needs --m2",)),
        (("--m2", "1kg",), ("--m1 is required", "--pull")),
        (("--m1", "1kg", "--pull", "force=2N on=3"), ("--pull", "on= is 1 or 2")),
        (("--m1", "1kg", "--pull", "force=2N angle=120deg"), ("--pull", "−90 to 90")),
        (("--m1", "1kg", "--pull", "angle=20deg"), ("--pull", "needs force=")),
        (("--m1", "1kg", "--pull", "force=2N angle=20deg"), ("--pull", "a hanging block is pulled along its string")),
        (("--m1", "1kg", "--side1", "table", "--pull", "force=100N angle=60deg"), ("--pull", "lifts it off its surface")),
        (("--m1", "1kg", "--m2", "1kg", "--torque", "1N*m"), ("--pulley-radius is required with --torque",)),
        (("--m1", "1kg", "--m2", "1kg", "--rim-mu", "0.2", "--side1", "table"), ("--side1 does not apply with --rim-mu",)),
        (("--m1", "1kg", "--m2", "1kg", "--rim-mu", "0.2", "--same-side"), ("--same-side does not apply with --rim-mu",)),
        (("--m1", "1kg", "--m2", "1kg", "--radius1", "0.1m", "--radius2", "0.2m", "--same-side"), ("the string goes slack on m2's side",)),
    ],
)
def test_usage_errors_name_the_option(args, fragments):
    assert_usage_error(run_taucli("atwood", *args), *fragments)
