"""drive --efficiency-back and --motor-friction (#47 item 3).

Reference written from a power balance at the motor shaft, in mpmath: the motor turning at ω
gives J_m α ω to its rotor, τ_mf ω to the friction at its shaft (no teeth between), and to the
train the output's power P = (Jα/N + T)(ω/N), of which the teeth take their share: P/η where
the motor drives (P ≥ 0), η′P where the output drives back (P < 0). Dividing by ω gives the
torque in each phase of a move; the run-up's energy must balance: W = KE + W_load + W_loss."""

from __future__ import annotations

import random

import mpmath
import pytest

import taucli
from conftest import assert_usage_error


def _torque(rotor, load, ratio, eta, eta_back, friction, torque, alpha, omega=mpmath.mpf(1)):
    power_out = (load * alpha / ratio + torque) * omega / ratio
    through = power_out / eta if power_out >= 0 else eta_back * power_out
    return (rotor * alpha * omega + friction * omega + through) / omega


@pytest.mark.parametrize("seed", range(3))
def test_random_moves_against_the_power_balance(seed):
    rng = random.Random(4730 + seed)
    for _ in range(10):
        rotor, load, ratio = rng.uniform(1e-5, 1e-3), rng.uniform(1e-3, 1), rng.uniform(1, 30)
        eta, eta_back, friction, torque = rng.uniform(0.5, 1), rng.uniform(0.2, 1), rng.uniform(0, 0.5), rng.uniform(0, 5)
        accel, decel, top = rng.uniform(0.05, 0.5), rng.uniform(0.05, 0.5), rng.uniform(100, 400)
        values = {k: v.value for k, v in taucli.drive(motor_inertia=rotor, load_inertia=load, ratio=[ratio], efficiency=eta, efficiency_back=eta_back,
                                                      motor_friction=friction, load_torque=torque, accel_time=f"{accel} s", decel_time=f"{decel} s",
                                                      run_time="1 s", until_omega=f"{top} rad/s").results.items()}
        q = [mpmath.mpf(x) for x in (rotor, load, ratio, eta, eta_back, friction, torque)]
        case = (rotor, load, ratio, eta, eta_back, friction, torque, accel, decel, top)
        assert values["torque_accel"] == pytest.approx(float(_torque(*q, mpmath.mpf(top) / accel)), rel=1e-12), case
        assert values["torque_decel"] == pytest.approx(float(_torque(*q, -mpmath.mpf(top) / decel)), rel=1e-12, abs=1e-12), case
        assert values["load_torque_motor"] == pytest.approx(float(_torque(*q, 0)), rel=1e-12), case


def test_no_efficiency_back_is_the_efficiency_both_ways():
    kw = dict(motor_inertia="1e-4 kg*m^2", load_inertia="0.05 kg*m^2", ratio=[10], efficiency=0.8, load_torque="1 N*m", accel_time="0.1 s",
              run_time="1 s", until_omega="3000 rpm")
    same = taucli.drive(**kw).results
    given = taucli.drive(**kw, efficiency_back=0.8).results
    for key in ("torque_accel", "torque_decel", "torque_rms", "power_regen"):
        assert given[key].value == pytest.approx(same[key].value, rel=1e-15), key


def test_the_run_up_energy_balances_with_the_motor_friction():
    """Under a constant motor torque to a speed: the motor's work is the kinetic energy, the load's
    work, and what the teeth and the shaft's friction take (work_loss), τ_mf θ among it."""
    kw = dict(motor_inertia="2e-4 kg*m^2", load_inertia="0.05 kg*m^2", ratio=[10], efficiency=0.8, load_torque="1 N*m", motor_torque="1.5 N*m",
              until_omega="2000 rpm", energy=True)
    plain = taucli.drive(**kw).results
    rough = taucli.drive(**kw, motor_friction="0.1 N*m").results
    assert rough["work_motor"].value == pytest.approx(rough["KE"].value + rough["work_load"].value + rough["work_loss"].value, rel=1e-12)
    assert rough["t_accel"].value > plain["t_accel"].value  # the friction takes some of the drive
    theta, omega = rough["theta_accel"].value, 2000 * 2 * mpmath.pi / 60
    output = 0.05 * (omega / 10) ** 2 / 2 + 1 * theta / 10  # the output's kinetic energy and the load's work, at the output shaft
    assert rough["work_loss"].value == pytest.approx(float((1 / mpmath.mpf("0.8") - 1) * output + mpmath.mpf("0.1") * theta), rel=1e-12)


def test_units_do_not_change_the_friction():
    kw = dict(motor_inertia="1e-4 kg*m^2", load_inertia="0.05 kg*m^2", ratio=[10], efficiency=0.8, load_torque="1 N*m", accel_time="0.1 s",
              run_time="1 s", until_omega="3000 rpm", efficiency_back=0.5)
    si = taucli.drive(**kw, motor_friction="0.05 N*m").results
    other = taucli.drive(**kw, motor_friction=f"{0.05 / 0.112984829027617} lbf*in").results
    for key in ("torque_accel", "torque_decel", "torque_rms", "load_torque_motor"):
        assert other[key].value == pytest.approx(si[key].value, rel=1e-12), key


def test_refusals(taucli):
    base = ("drive", "--motor-inertia", "1e-4kg*m^2", "--load-inertia", "0.05kg*m^2", "--ratio", "10", "--accel-time", "0.1s", "--until-omega", "3000rpm")
    assert_usage_error(taucli(*base, "--efficiency-back", "1.5"), "--efficiency-back")
    assert_usage_error(taucli(*base, "--efficiency-back", "0"), "--efficiency-back")
    assert_usage_error(taucli(*base, "--motor-friction", "-0.1N*m"), "--motor-friction")


@pytest.mark.parametrize("seed", range(2))
def test_energy_given_back_per_cycle(seed):
    """While braking (τ_d < 0) the load drives the motor: ∫(−τω)dt over the ramp down, ω falling
    linearly from the top speed, is −τ_d ω t_d/2 (mpmath.quad of the ramp); a braking resistor takes
    it over the cycle. A load torque that brakes it harder than the ramp asks gives nothing back."""
    rng = random.Random(4770 + seed)
    for _ in range(8):
        rotor, load, ratio, eta, torque = rng.uniform(1e-5, 1e-3), rng.uniform(1e-3, 1), rng.uniform(1, 30), rng.uniform(0.5, 1), rng.uniform(0, 5)
        accel, decel, run, dwell, top = rng.uniform(0.05, 0.5), rng.uniform(0.05, 0.5), rng.uniform(0, 2), rng.uniform(0, 1), rng.uniform(100, 400)
        values = {k: v.value for k, v in taucli.drive(motor_inertia=rotor, load_inertia=load, ratio=[ratio], efficiency=eta, load_torque=torque,
                                                      accel_time=f"{accel} s", decel_time=f"{decel} s", run_time=f"{run} s", dwell_time=f"{dwell} s",
                                                      until_omega=f"{top} rad/s").results.items()}
        q = [mpmath.mpf(x) for x in (rotor, load, ratio, eta, eta, 0, torque)]
        braking = _torque(*q, -mpmath.mpf(top) / decel)
        given_back = mpmath.quad(lambda t: max(-braking * top * (1 - t / decel), 0), [0, decel])
        assert values["energy_regen"] == pytest.approx(float(given_back), rel=1e-12, abs=1e-12)
        assert values["power_resistor"] == pytest.approx(float(given_back / (accel + run + decel + dwell)), rel=1e-12, abs=1e-12)
        if run:
            assert values["power_run"] == pytest.approx(float(_torque(*q, 0) * top), rel=1e-12)
