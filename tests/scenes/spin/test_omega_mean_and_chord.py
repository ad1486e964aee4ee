"""#46 item 5: a point's straight-line displacement (chord) beside its arc, and a run's mean
angular velocity θ/t, against references written from the physics (tests/references/point.py
chord: Pythagoras on the two positions; tests/references/spin_mean.py: t and θ as quadratures of
I dω/dt = −L(ω)). The chord in every scene with --at is also in test_references_point.py.
"""

from __future__ import annotations

import json
import math

import mpmath
import pytest
from hypothesis import given, settings, strategies as st

import taucli
from conftest import run_taucli
from references import relative_error
from references.point import chord
from references.spin_mean import at_time, constant_alpha, stop

INCH = 0.0254
SAW = ("--omega0", "4250rpm", "--until-omega", "0", "--in-time", "4s", "--at", "5in")


def _saw_angle():
    """The saw's blade from 4250 rpm to rest in 4.00 s at constant α: θ = ½ω₀t."""
    with mpmath.workdps(60):
        return mpmath.mpf(4250) * 2 * mpmath.pi / 60 * 4 / 2


def test_the_saw_blade_tooth_command_line_batch_and_python():
    """Knight (and Cutnell & Johnson), a 10.0-inch saw blade slows from 4250 rpm to rest in
    4.00 s: a tooth on its rim travels 4450.6 in along its arc (141.67 turns) and ends 8.66 in
    from where it started in a straight line (the last 2/3 turn: 2 × 5 in × sin 120°)."""
    exact_chord, exact_arc = chord(5 * INCH, _saw_angle()), 5 * INCH * _saw_angle()
    line = run_taucli("spin-down", *SAW, "--get", "chord", "--get", "s", "--to", "chord=in", "--to", "s=in")
    assert line.code == 0, line.err
    got_chord, got_arc = (float(x) for x in line.out.split())
    assert round(got_chord, 2) == 8.66 and round(got_arc, 1) == 4450.6  # the book's
    assert relative_error(got_chord * INCH, exact_chord) < 1e-12 and relative_error(got_arc * INCH, exact_arc) < 1e-14
    batch = run_taucli("spin-down", "--batch", stdin=json.dumps({"omega0": "4250 rpm", "until_omega": 0, "in_time": "4 s", "at": "5 in"}) + "\n")
    assert batch.code == 0, batch.err
    results = json.loads(batch.out)["results"]
    assert relative_error(results["chord"]["value"], exact_chord) < 1e-12
    assert "net angle" in results["chord"]["label"]
    report = taucli.spin_down(omega0="4250 rpm", until_omega=0, in_time="4 s", at="5 in")
    assert relative_error(report.results["chord"].value, exact_chord) < 1e-12
    assert relative_error(report.results["omega_mean"].value, mpmath.mpf(4250) * 2 * mpmath.pi / 60 / 2) < 1e-14  # ω₀/2 at constant α


def test_the_chord_is_of_the_net_angle_when_the_wheel_turns_back():
    """--alpha carries the wheel through ω = 0 and back: 10 rad/s at −2 rad/s² is back where it
    started at t = 10 s (θ = 0): no chord and no mean speed, though it has gone 50 rad out and back."""
    report = taucli.spin_down(alpha="-2 rad/s^2", omega0="10 rad/s", time="10 s", at="0.5 m")
    assert report.results["chord"].value == pytest.approx(0, abs=1e-15)
    assert report.results["omega_mean"].value == pytest.approx(0, abs=1e-15)


def test_a_rolling_body_and_an_impulse_give_the_chord_beside_the_arc():
    rolled = taucli.rolling("disc", angle="30deg", length="2m", radius="0.1m", at="0.05m").results  # θ = L/R = 20 rad
    assert relative_error(rolled["chord"].value, chord(0.05, 20)) < 1e-14
    struck = taucli.impulse(inertia=2, torque=3, duration=1.5, omega0="1 rad/s", at=0.5).results  # θ = ω₀t + ½(τ/I)t²
    assert relative_error(struck["chord"].value, chord(0.5, 1.5 + 0.75 * 2.25)) < 1e-14


def test_irodov_1_247_the_mean_speed_is_a_third_of_the_first():
    """Irodov 1.247: a flywheel slowed by a torque proportional to √ω: ⟨ω⟩ = ω₀/3 over the whole
    deceleration. --drag k with --drag-exponent 0.5 (k in N·m·s² as every drag is read)."""
    line = run_taucli("spin-down", "--inertia", "1kg*m^2", "--omega0", "9rad/s", "--drag", "1N*m*s^2", "--drag-exponent", "0.5", "--get", "omega_mean")
    assert line.code == 0, line.err
    assert float(line.out) == pytest.approx(3.0, rel=1e-8)
    assert relative_error(stop(1, 9, drag=1, exponent=0.5)[2], 3) < 1e-30  # the reference gives the book's answer


@settings(max_examples=8, deadline=None)
@given(inertia=st.floats(0.01, 100), omega0=st.floats(0.1, 1000), drag=st.floats(0.001, 10), exponent=st.floats(0.1, 0.9),
       friction=st.sampled_from([0.0, 0.0, 1.0]))
def test_mean_speed_to_the_stop_under_drag_below_one(inertia, omega0, drag, exponent, friction):
    """Drag kωⁿ with n < 1 (and friction, or not) stops the wheel: θ_stop/t_stop against the
    quadratures. rk45 at rtol 1e-10 and its located stop: budget 1e-7."""
    friction *= drag * omega0**exponent  # of the drag's size at the start
    report = taucli.spin_down(inertia=inertia, omega0=f"{omega0!r} rad/s", drag=drag, drag_exponent=exponent, friction=friction or None)
    t, theta, mean = stop(inertia, omega0, friction=friction, drag=drag, exponent=exponent)
    assert relative_error(report.results["omega_mean"].value, mean) < 1e-7
    if not friction:  # drag alone: ω₀(1 − n)/(2 − n), as Irodov's ω₀/3 at n = ½
        assert relative_error(mean, mpmath.mpf(omega0) * (1 - mpmath.mpf(exponent)) / (2 - mpmath.mpf(exponent))) < 1e-30


@settings(max_examples=8, deadline=None)
@given(inertia=st.floats(0.01, 100), omega0=st.floats(0.1, 1000), friction=st.floats(0.01, 10), viscous=st.floats(0.001, 10),
       share=st.floats(0.01, 0.99))
def test_mean_speed_by_a_time_under_friction_and_viscous_drag(inertia, omega0, friction, viscous, share):
    """A closed form (τ_f + bω): θ(t)/t at a time before the stop, held to 1e-12."""
    t_stop = stop(inertia, omega0, friction=friction, viscous=viscous)[0]
    time = float(t_stop) * share
    report = taucli.spin_down(inertia=inertia, omega0=f"{omega0!r} rad/s", friction=friction, viscous=viscous, time=time)
    _, theta, mean = at_time(inertia, omega0, time, friction=friction, viscous=viscous)
    assert relative_error(report.results["omega_mean"].value, mean) < 1e-12


@settings(max_examples=40, deadline=None)
@given(omega0=st.just(0.0) | st.floats(1e-3, 1000) | st.floats(-1000, -1e-3), alpha=st.floats(0.001, 100) | st.floats(-100, -0.001), time=st.floats(0.001, 100))
def test_mean_speed_at_constant_alpha_is_the_net_angle_over_the_time(omega0, alpha, time):
    """θ/t = ω₀ + ½αt, through ω = 0 and back (the net angle): budget 1e-13 times the
    cancellation of that sum."""
    report = taucli.spin_down(alpha=f"{alpha!r} rad/s^2", omega0=f"{omega0!r} rad/s", time=time)
    theta, mean = constant_alpha(omega0, alpha, time)
    size = abs(omega0) + abs(alpha) * time / 2
    got = report.results["omega_mean"].value
    assert abs(got - float(mean)) <= 1e-13 * size * 4, (got, mean)


def test_the_mean_speed_of_a_run_without_an_end_is_null_and_says_why():
    report = taucli.spin_down(inertia=1, omega0="10 rad/s", viscous=0.5)
    assert report.results["omega_mean"].value is None
    assert any(note.startswith("omega_mean:") and "time gives one" in note for note in report.notes)  # as Python spells it
    assert math.isclose(taucli.spin_down(inertia=1, omega0="10 rad/s", viscous=0.5, time=0).results["omega_mean"].value, 10)


def test_at_constant_alpha_the_mean_is_half_the_first_and_last_speeds_and_keeps_no_rounding():
    """A wheel slowing at constant α to its stop turns at ω₀/2 on average, whatever the friction:
    an uncertain friction leaves omega_mean exact (θ_stop/t_stop's rounding, moved by the
    propagation's differences, had read as a dependence: 15.000000000000 ± 0.000000000005).
    Held at rest by static friction after its stop, it is θ_stop/t instead."""
    line = run_taucli("spin-down", "--shape", "disc", "--mass", "5kg", "--radius", "0.2m", "--omega0", "30rad/s", "--friction", "0.3+/-0.006 N*m", "--json")
    assert line.code == 0, line.err
    mean = line.json()["results"]["omega_mean"]
    assert mean["value"] == 15.0 and mean["uncertainty"] == 0
    held = taucli.spin_down(shape="disc", mass="5 kg", radius="0.2 m", omega0="30 rad/s", friction="0.3 N*m", time="20 s").results
    assert relative_error(held["omega_mean"].value, mpmath.mpf(150) / 20) < 1e-15  # θ_stop = 150 rad, then at rest
