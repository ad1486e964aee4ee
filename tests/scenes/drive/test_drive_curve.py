"""drive --motor-curve: an induction motor's run-up on Kloss's curve (#47 item 3).

Reference written from the physics in mpmath: the motor's torque T(s) = 2T_max/(s/s_m + s_m/s),
s = 1 − ω/ω_s, goes to the rotor (J_m α), the friction at its shaft and each load through its
train (the power at the load's shaft over η while the motor drives it, times η′ where it drives
back); α(ω) is the root of that balance (mpmath.findroot), and

    t = ∫ dω/α,   θ = ∫ ω dω/α,   E_r = ∫ s·T·ω_s dt = ∫ T (ω_s − ω) dω/α

by mpmath.quad. Unloaded, the textbook closed forms for a start (the drives books derive both
from J dω/dt = T(s)): t = (Jω_s/2T_max)[(1 − s²)/(2s_m) + s_m ln(1/s)] and the energy dissipated
in the rotor E_r = ½Jω_s²(1 − s²), from rest to the slip s. No published run-up problem was found
in the sources searched; the cases here are checked against these and against the integrals.
"""

from __future__ import annotations

import json
import random

import mpmath
import pytest

import taucli
from conftest import assert_usage_error, run_taucli

mpmath.mp.dps = 30
RPM = 2 * mpmath.pi / 60


def _kloss(tmax, sm, ws):
    def torque(w):
        s = 1 - w / ws
        return 2 * tmax / (s / sm + sm / s)
    return torque


def _alpha(rotor, friction, loads, torque):
    """α where the power balance gives the motor's torque (loads: (J, N, η, η′, T))."""
    def asked(a):
        total = rotor * a + friction
        for inertia, ratio, eta, back, t in loads:
            shaft = inertia * a / ratio + t
            total += shaft / (ratio * eta) if shaft >= 0 else back * shaft / ratio
        return total - torque
    return mpmath.findroot(asked, (mpmath.mpf(-1e6), mpmath.mpf(1e6)), solver="anderson")


def _integrals(motor, alpha, w0, w1, ws, splits=()):
    points = [w0, *sorted(splits), w1]
    t = mpmath.quad(lambda w: 1 / alpha(w), points)
    theta = mpmath.quad(lambda w: w / alpha(w), points)
    loss = mpmath.quad(lambda w: motor(w) * (ws - w) / alpha(w), points)
    return t, theta, loss


@pytest.mark.parametrize("start", [0, 300])
def test_unloaded_run_up_is_the_books_closed_form(start):
    inertia, tmax, sm, sync, target = mpmath.mpf("2.5"), mpmath.mpf(400), mpmath.mpf("0.18"), 1500 * RPM, 1450 * RPM
    results = taucli.drive(motor_curve="tmax=400N*m slip-max=0.18 sync=1500rpm", motor_inertia="2.5 kg*m^2", until_omega="1450 rpm",
                           omega0=f"{start} rpm").results
    s0, s1 = 1 - start * RPM / sync, 1 - target / sync
    t = inertia * sync / (2 * tmax) * ((s0**2 - s1**2) / (2 * sm) + sm * mpmath.log(s0 / s1))
    assert results["t_accel"].value == pytest.approx(float(t), rel=1e-13)
    assert results["energy_accel"].value == pytest.approx(float(inertia * sync**2 * (s0**2 - s1**2) / 2), rel=1e-13)
    motor = _kloss(tmax, sm, sync)
    _, theta, loss = _integrals(motor, lambda w: motor(w) / inertia, start * RPM, target, sync)
    assert results["theta_accel"].value == pytest.approx(float(theta), rel=1e-12)
    assert results["energy_accel"].value == pytest.approx(float(loss), rel=1e-12)


@pytest.mark.parametrize("seed", range(3))
def test_random_run_ups_through_a_train_against_the_power_balance(seed):
    rng = random.Random(4733 + seed)
    for _ in range(4):
        rotor, load, ratio, eta = rng.uniform(0.01, 1), rng.uniform(0, 50), rng.uniform(1, 20), rng.uniform(0.6, 1)
        tmax, sm, sync = rng.uniform(50, 500), rng.uniform(0.05, 0.6), rng.choice([750, 1000, 1500, 3000])
        start_torque = 2 * tmax / (1 / sm + sm)
        torque = rng.uniform(0, 0.6) * min(start_torque, tmax) * ratio * eta
        friction = rng.choice([0.0, 0.01 * tmax])
        q = [mpmath.mpf(x) for x in (rotor, load, ratio, eta, torque, friction, tmax, sm)]
        ws = sync * RPM
        motor = _kloss(q[6], q[7], ws)
        running = q[4] / (q[2] * q[3]) + q[5]
        k = q[6] / running
        steady = ws * (1 - q[7] / (k + mpmath.sqrt(k * k - 1)))
        target = float(steady) * rng.uniform(0.5, 0.99)
        results = taucli.drive(motor_curve=f"tmax={tmax!r}N*m slip-max={sm!r} sync={sync}rpm", motor_inertia=rotor, load_inertia=load, ratio=[ratio],
                               efficiency=eta, load_torque=torque, motor_friction=friction or None, until_omega=f"{target!r} rad/s").results
        loads = [(q[1], q[2], q[3], q[3], q[4])]
        t, theta, loss = _integrals(motor, lambda w: _alpha(q[0], q[5], loads, motor(w)), 0, mpmath.mpf(target), ws)
        case = (rotor, load, ratio, eta, torque, friction, tmax, sm, sync, target)
        assert results["t_accel"].value == pytest.approx(float(t), rel=1e-10), case
        assert results["theta_accel"].value == pytest.approx(float(theta), rel=1e-10), case
        assert results["energy_accel"].value == pytest.approx(float(loss), rel=1e-10), case


def test_several_loads_one_driving_back_on_the_way():
    """A load that pulls (T < 0) drives the motor once the acceleration no longer needs all of its pull:
    its train turns round on the way, and the integral is split there."""
    spec = ["inertia=10kg*m^2 ratio=5 efficiency=0.9 torque=100N*m", "inertia=5kg*m^2 ratio=3 efficiency=0.8 efficiency-back=0.6 torque=-60N*m"]
    results = taucli.drive(motor_curve="tmax=400N*m slip-max=0.2 sync=1500rpm", motor_inertia="2 kg*m^2", load=spec, until_omega="1490 rpm").results
    loads = [(mpmath.mpf(10), mpmath.mpf(5), mpmath.mpf("0.9"), mpmath.mpf("0.9"), mpmath.mpf(100)),
             (mpmath.mpf(5), mpmath.mpf(3), mpmath.mpf("0.8"), mpmath.mpf("0.6"), mpmath.mpf(-60))]
    ws = 1500 * RPM
    motor = _kloss(mpmath.mpf(400), mpmath.mpf("0.2"), ws)
    alpha = lambda w: _alpha(mpmath.mpf(2), 0, loads, motor(w))  # noqa: E731
    corner = mpmath.mpf(60) * 3 / 5  # load 2 turns round at α = −TN/J = 36 rad/s²
    turn = mpmath.findroot(lambda w: alpha(w) - corner, 1460 * RPM)
    assert 0 < turn < 1490 * RPM, "the case does not cross the corner: it tests nothing"
    t, theta, loss = _integrals(motor, alpha, 0, 1490 * RPM, ws, [turn])
    assert results["t_accel"].value == pytest.approx(float(t), rel=1e-10)
    assert results["theta_accel"].value == pytest.approx(float(theta), rel=1e-10)
    assert results["energy_accel"].value == pytest.approx(float(loss), rel=1e-10)


def test_the_command_line_batch_and_python_agree():
    args = ["--motor-curve", "tmax=400N*m slip-max=0.2 sync=1500rpm", "--motor-inertia", "2kg*m^2", "--load-torque", "100N*m", "--until-omega", "1400rpm"]
    cli = run_taucli("drive", *args, "--json").json()["results"]
    line = json.dumps({"motor_curve": "tmax=400N*m slip-max=0.2 sync=1500rpm", "motor_inertia": "2kg*m^2", "load_torque": "100N*m", "until_omega": "1400rpm"})
    batch = json.loads(run_taucli("drive", "--batch", stdin=line + "\n").out)["results"]
    python = taucli.drive(motor_curve="tmax=400N*m slip-max=0.2 sync=1500rpm", motor_inertia="2kg*m^2", load_torque="100N*m", until_omega="1400rpm").results
    for key in ("t_accel", "energy_accel", "theta_accel", "alpha0"):
        assert cli[key]["value"] == batch[key]["value"] == python[key].value, key


def test_where_the_motor_stalls_it_is_refused_naming_the_speed(taucli):
    base = ["drive", "--motor-curve", "tmax=400N*m slip-max=0.2 sync=1500rpm", "--motor-inertia", "2kg*m^2"]
    # T(s = 1) = 800/(5 + 0.2) = 153.8 N·m: a load of 200 N·m never starts
    assert_usage_error(taucli(*base, "--load-torque", "200N*m", "--until-omega", "1000rpm"), "--motor-curve", "cannot start", "stalls")
    # 100 N·m: k = 4, s = 0.2/(k + √(k² − 1)) = 0.0254: it settles at 1461.9 rpm
    k = mpmath.mpf(4)
    steady = 1500 * (1 - mpmath.mpf("0.2") / (k + mpmath.sqrt(k * k - 1)))
    ran = taucli(*base, "--load-torque", "100N*m", "--until-omega", "1470rpm")
    assert_usage_error(ran, "--until-omega", "never reached", f"{float(steady):.6g} rpm")
    assert run_taucli(*base, "--load-torque", "100N*m", "--until-omega", "1460rpm").code == 0
    assert_usage_error(taucli(*base, "--until-omega", "1500rpm"), "--until-omega", "synchronous")
    assert_usage_error(taucli(*base), "--until-omega", "required")
    assert_usage_error(taucli(*base, "--until-omega", "1000rpm", "--omega0", "1600rpm"), "--omega0", "synchronous")
    assert_usage_error(taucli(*base, "--until-omega", "1000rpm", "--omega0", "1200rpm"), "--until-omega", "above")


@pytest.mark.parametrize("args", [
    ("--stall-torque", "2N*m", "--no-load-speed", "1000rpm"), ("--motor-torque", "2N*m"), ("--in-time", "1s"), ("--alpha", "10rad/s^2"),
    ("--accel-time", "1s"), ("--energy",),
])
def test_the_curve_conflicts_with_other_ways_to_the_speed(taucli, args):
    assert_usage_error(taucli("drive", "--motor-curve", "tmax=400N*m slip-max=0.2 sync=1500rpm", "--motor-inertia", "2kg*m^2",
                              "--until-omega", "1000rpm", *args), args[0], "--motor-curve")


def test_omega0_goes_with_the_curve(taucli):
    assert_usage_error(taucli("drive", "--load-inertia", "1kg*m^2", "--omega0", "100rpm", "--until-omega", "1000rpm", "--in-time", "1s"),
                       "--omega0", "--motor-curve", "(e.g. ")


@pytest.mark.parametrize(("spec", "fragment"), [
    ("tmax=400N*m slip-max=0.2", "sync="), ("slip-max=0.2 sync=1500rpm", "tmax="), ("tmax=400N*m sync=1500rpm", "slip-max="),
    ("tmax=400N slip-max=0.2 sync=1500rpm", "tmax="), ("tmax=-400N*m slip-max=0.2 sync=1500rpm", "tmax="),
    ("tmax=400N*m slip-max=0 sync=1500rpm", "slip-max="), ("tmax=400N*m slip-max=2m sync=1500rpm", "slip-max="),
    ("tmax=400N*m slip-max=0.2 sync=1500", "sync="), ("tmax=400N*m slip-max=0.2 sync=15m/s", "sync="),
    ("tmax=400N*m slip-max=0.2 sync=1500rpm poles=4", "knows"), ("tmax=400N*m tmax=300N*m slip-max=0.2 sync=1500rpm", "twice"),
])
def test_a_bad_curve_is_refused_in_one_line_with_an_example(taucli, spec, fragment):
    assert_usage_error(taucli("drive", "--motor-curve", spec, "--motor-inertia", "2kg*m^2", "--until-omega", "1000rpm"),
                       "--motor-curve", fragment, "(e.g. ")


def test_find_the_breakdown_torque_for_a_run_up_time():
    report = taucli.drive(motor_curve="slip-max=0.2 sync=1500rpm", motor_inertia="2 kg*m^2", load_torque="100 N*m", until_omega="1400 rpm",
                          find="motor_curve.tmax", want="t_accel=1 s")
    tmax = report.results["motor_curve.tmax"].value
    ws = 1500 * RPM
    motor = _kloss(mpmath.mpf(tmax), mpmath.mpf("0.2"), ws)
    t = mpmath.quad(lambda w: 2 / (motor(w) - 100), [0, 1400 * RPM])
    assert float(t) == pytest.approx(1.0, rel=1e-9)
