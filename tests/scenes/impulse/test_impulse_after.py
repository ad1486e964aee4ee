"""#34 items 3 and 4 in impulse: the body after a change by parts (--part-after), the period of a turn
after (2π/|ω₁|), and with a particle the system's linear momentum before and after and the pivot's
impulse.

The physics: with no external torque about the axis L = Iω is conserved as I changes; a turn at
ω takes 2π/|ω|; over a blow the pivot's force is the only impulsive external force on the body and
the particle, so it alone changes their linear momentum, J_pivot = p₁ − p₀ (Newton's second law
for the system), with p = M v_cm + m v, v_cm = ωd. The angular impulse J the particle gives the
body at r gives the body Δω = Jr/I, so J_pivot = −J + MdΔω = J(Mdr/I − 1): nothing at the centre of
percussion r = I/(Md) (2L/3 for a rod about its end; Kleppner and Kolenkow, An Introduction to
Mechanics, the centre of percussion)."""

from __future__ import annotations

import math

import mpmath
import pytest
from conftest import assert_usage_error, run_taucli
from hypothesis import given, settings
from hypothesis import strategies as st

import taucli

mpmath.mp.dps = 40


def values(report):
    return {key: value.value for key, value in report.results.items()}


def test_serway_the_merry_go_round_a_student_walks_in():
    """Serway and Jewett, Physics for Scientists and Engineers, ch. 11, example "The Merry-Go-Round":
    a 100 kg disc of radius 2.0 m turns at 2.0 rad/s with a 60 kg student at its rim; she walks to
    0.50 m from the centre. The book's answer: 4.1 rad/s."""
    r = values(taucli.impulse(shape="disc", mass="100 kg", radius="2.0 m", part="point mass=60kg offset=2m",
                              part_after="point mass=60kg offset=0.5m", omega0="2.0 rad/s"))
    assert r["omega1"] == pytest.approx(4.1, abs=0.05)  # the book's 4.1 rad/s
    i0, i1 = mpmath.mpf(100) * 4 / 2 + 60 * 4, mpmath.mpf(100) * 4 / 2 + 60 * mpmath.mpf("0.25")
    assert r["omega1"] == pytest.approx(float(i0 * 2 / i1), rel=1e-15)
    assert r["L1"] == pytest.approx(r["L0"], rel=1e-15)
    assert r["period"] == pytest.approx(float(2 * mpmath.pi * i1 / (i0 * 2)), rel=1e-15)


def test_part_after_is_the_same_as_inertia_final_and_conflicts_with_it():
    by_parts = values(taucli.impulse(inertia=3, part_after="point mass=5kg offset=0.2m", omega0="10 rad/s"))
    by_value = values(taucli.impulse(inertia=3, inertia_final=3.2, omega0="10 rad/s"))
    assert by_parts["omega1"] == pytest.approx(by_value["omega1"], rel=1e-15)
    assert_usage_error(run_taucli("impulse", "--inertia", "3", "--inertia-final", "4", "--part-after", "point mass=5kg offset=0.2m", "--omega0", "1rad/s"),
                       "--part-after conflicts with --inertia-final")


def test_the_period_after_an_impulse_and_none_at_rest():
    r = values(taucli.impulse(inertia="0.1 kg*m^2", omega0=0, torque="2 N*m", duration="0.5 s"))
    assert r["period"] == pytest.approx(2 * math.pi / 10, rel=1e-15)
    report = taucli.impulse(inertia="0.1 kg*m^2", omega0="10 rad/s", torque="-2 N*m", duration="0.5 s")
    assert report.results["period"].value is None
    assert any("period" in note for note in report.notes)


def test_a_rod_on_a_pivot_struck_and_rebounding():
    """A 1 kg, 1 m rod about its end at rest; 0.1 kg at 10 m/s strikes its tip, e = 0.5:
    ω₁ = m r v (1 + e)/(I + m r²), v′ = ω₁r − ev; p₀ = mv, p₁ = M(L/2)ω₁ + mv′."""
    r = values(taucli.impulse(shape="rod", mass="1 kg", length="1 m", axis="end", omega0=0, particle="mass=0.1kg speed=10m/s radius=1m e=0.5"))
    I, M, m, v, e, L = mpmath.mpf(1) / 3, 1, mpmath.mpf("0.1"), 10, mpmath.mpf("0.5"), 1
    w1 = m * L * v * (1 + e) / (I + m * L * L)
    v1 = w1 * L - e * v
    assert r["p0"] == pytest.approx(1.0, rel=1e-15)
    assert r["p1"] == pytest.approx(float(M * L / 2 * w1 + m * v1), rel=1e-14)
    assert r["pivot_impulse"] == pytest.approx(float(M * L / 2 * w1 + m * v1 - m * v), rel=1e-14)


@pytest.mark.parametrize("particle", ["mass=0.1kg speed=10m/s e=0.5", "mass=0.3kg speed=-4m/s", "mass=2kg speed=1m/s speed-after=-0.5m/s"])
def test_no_blow_at_the_centre_of_percussion(particle):
    """Struck at r = I/(Md) = 2L/3 the pivot's impulse is nothing, whatever strikes there."""
    r = values(taucli.impulse(shape="rod", mass="1.5 kg", length="0.9 m", axis="end", omega0="1 rad/s", particle=f"{particle} radius=0.6m"))
    assert r["pivot_impulse"] == pytest.approx(0, abs=1e-14 * abs(r["p0"]) + 1e-15)


@settings(max_examples=150, deadline=None)
@given(M=st.floats(0.1, 100), L=st.floats(0.1, 10), m=st.floats(0.01, 10), v=st.floats(-50, 50).filter(lambda x: abs(x) > 1e-3),
       where=st.floats(0.05, 1), e=st.one_of(st.just(0.0), st.floats(1e-6, 1)), w0=st.one_of(st.just(0.0), st.floats(-10, -1e-3), st.floats(1e-3, 10)))
def test_the_pivot_impulse_balances_the_momentum(M, L, m, v, where, e, w0):
    """J_pivot = p₁ − p₀ = J(Mdr/I − 1), J = m(v − v′) the particle's loss of momentum, d = L/2, I = ML²/3."""
    r = values(taucli.impulse(shape="rod", mass=M, length=L, axis="end", omega0=f"{w0!r} rad/s", particle=f"mass={m!r}kg speed={v!r}m/s radius={where * L!r}m e={e!r}"))
    I, d, radius = M * L * L / 3, L / 2, where * L
    parts = {row[0]: row for row in taucli.impulse(shape="rod", mass=M, length=L, axis="end", omega0=f"{w0!r} rad/s",
                                                  particle=f"mass={m!r}kg speed={v!r}m/s radius={radius!r}m e={e!r}").tables["parts"].rows}
    v1 = parts["particle"][4]
    blow = m * (v - v1)
    assert r["pivot_impulse"] == pytest.approx(blow * (M * d * radius / I - 1), rel=1e-9, abs=1e-9 * (abs(blow) + abs(r["p0"])))
    assert r["p1"] - r["p0"] == pytest.approx(r["pivot_impulse"], rel=1e-9, abs=1e-12 * (abs(r["p0"]) + abs(r["p1"])))


def test_momentum_is_null_with_a_note_where_the_centre_is_not_known():
    report = taucli.impulse(inertia=2, omega0=0, particle="mass=0.1kg speed=10m/s radius=1m")
    assert "pivot_impulse" not in report.results  # a body of given I alone has no mass to give a momentum
    report = taucli.impulse(shape="disc", mass="2 kg", radius="1 m", part="point mass=1kg offset=0.5m", omega0=0, particle="mass=0.1kg speed=10m/s radius=1m")
    assert report.results["pivot_impulse"].value is None
    assert any("pivot_impulse" in note for note in report.notes)
    report = taucli.impulse(shape="disc", mass="2 kg", radius="1 m", omega0=0, particle="mass=0.1kg speed=10m/s radius=1m angle=60deg")
    assert report.results["p0"].value is None


def test_openstax_the_catcher_stops_his_arm_after_the_catch():
    """OpenStax University Physics vol. 1, ch. 11 (angular momentum), problem: a catcher's arm (a
    4.0 kg, 0.5 m rod about the shoulder) catches a 0.145 kg ball at 40 m/s at its end, then stops
    in 0.3 s. Answers as printed: (a) 7.85 rad/s, (b) 9.67 N·m. Physics: mvL = (ML²/3 + mL²)ω_c;
    τ = I₁(0 − ω_c)/Δt."""
    r = values(taucli.impulse(shape="rod", mass="4.0 kg", length="0.5 m", axis="end", particle="mass=0.145kg speed=40m/s radius=0.5m",
                              omega1=0, duration="0.3 s"))
    assert r["omega_impact"] == pytest.approx(7.85, abs=0.005)
    assert abs(r["torque"]) == pytest.approx(9.67, abs=0.005)
    m, v, M, L = mpmath.mpf("0.145"), 40, 4, mpmath.mpf("0.5")
    i1 = M * L * L / 3 + m * L * L
    w_c = m * v * L / i1
    assert r["omega_impact"] == pytest.approx(float(w_c), rel=1e-15)
    assert r["torque"] == pytest.approx(float(-i1 * w_c / mpmath.mpf("0.3")), rel=1e-14)
    assert r["J"] == pytest.approx(r["L1"] - r["L0"], rel=1e-14)  # L just after the blow is L₀
    assert r["KE_lost"] == pytest.approx(float(m * v * v / 2 - i1 * w_c**2 / 2), rel=1e-13)


@settings(max_examples=100, deadline=None)
@given(m=st.floats(0.01, 10), v=st.floats(1, 100), M=st.floats(0.1, 10), tau=st.floats(-50, 50).filter(lambda x: abs(x) > 1e-3), dt=st.floats(0.01, 5))
def test_after_the_catch_the_torque_changes_the_momentum_the_catch_kept(m, v, M, tau, dt):
    """L₀ = I₁ω_c (the blow conserves L), then τΔt = I₁ω₁ − I₁ω_c = L₁ − L₀."""
    r = values(taucli.impulse(shape="rod", mass=M, length=1.0, axis="end", particle=f"mass={m!r}kg speed={v!r}m/s radius=1m", torque=tau, duration=dt))
    i1 = M / 3 + m
    assert i1 * r["omega_impact"] == pytest.approx(r["L0"], rel=1e-13)
    assert r["J"] == pytest.approx(tau * dt, rel=1e-14)
    assert r["L1"] - r["L0"] == pytest.approx(r["J"], rel=1e-9, abs=1e-12 * abs(r["L0"]))


def test_after_the_catch_two_of_torque_duration_omega1():
    base = ("impulse", "--shape", "rod", "--mass", "4kg", "--length", "0.5m", "--axis", "end", "--particle", "mass=0.145kg speed=40m/s radius=0.5m")
    assert_usage_error(run_taucli(*base, "--duration", "0.3s"), "--duration needs --torque or --omega1 after the collision")
    assert_usage_error(run_taucli(*base, "--duration", "0.3s", "--torque", "1N*m", "--omega1", "0"), "--omega1 conflicts with --torque and --duration")


def test_a_particle_that_rebounds_keeps_its_speed_after_when_a_torque_follows():
    """A particle that leaves the body (e=, speed-after=) is no part of what the torque after turns:
    speed_after is the collision's (#42 item 18: the run with a torque after had none). Physics:
    Iω₀ + mvr = Iω_c + mv′r and v′ − ω_c r = −e(v − ω₀r)."""
    inertia, m, v, r, e = mpmath.mpf("0.1"), mpmath.mpf("0.4"), 20, mpmath.mpf("0.6"), mpmath.mpf("0.5")
    w_c = (m * v * r + m * r * e * v) / (inertia + m * r * r)  # ω₀ = 0: v′ = ω_c r − ev
    v_after = w_c * r - e * v
    particle = "mass=0.4kg speed=20m/s radius=0.6m e=0.5"
    alone = taucli.impulse(inertia="0.1 kg*m^2", omega0=0, particle=particle)
    then = taucli.impulse(inertia="0.1 kg*m^2", omega0=0, particle=particle, torque="2 N*m", duration="0.5 s")
    assert alone.results["speed_after"].value == pytest.approx(float(v_after), rel=1e-15)
    assert then.results["speed_after"].value == alone.results["speed_after"].value
    assert then.results["omega_impact"].value == pytest.approx(float(w_c), rel=1e-15)
    sticks = taucli.impulse(inertia="0.1 kg*m^2", omega0=0, particle="mass=0.4kg speed=20m/s radius=0.6m", torque="2 N*m", duration="0.5 s")
    assert "speed_after" not in sticks.results  # it rides on: its speed after the torque is the body's at r, not the collision's
