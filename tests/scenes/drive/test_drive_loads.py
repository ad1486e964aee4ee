"""drive --load: several loads, each through its own train and efficiency (#47 item 3).

Reference written from the power that flows to each load, in mpmath: the motor turning at ω and
accelerating at α gives J_m α ω to its rotor, τ_mf ω to the friction at its shaft, and to load i
the power at its shaft Pᵢ = (Jᵢα/Nᵢ + Tᵢ)(ω/Nᵢ), of which its own train takes a share: Pᵢ/ηᵢ where
the motor drives it (Pᵢ ≥ 0), η′ᵢPᵢ where the load drives back (Pᵢ < 0). The motor's torque is the
sum over ω. The kinetic energy ½Jᵢ(ω/Nᵢ)² of each load is that of Jᵢ/Nᵢ² at the motor; a mass m
moved at v while the motor turns at ω_m stores ½mv², so it is m(v/ω_m)² there.

Published instance: Dubey, Fundamentals of Electrical Drives, Example 2.1: a motor (0.2 kg·m²,
1420 rpm) drives a load of 10 kg·m² and 10 N·m through a gear a = 0.1 (N = 10) of efficiency 0.9,
and lifts 1000 kg at 1.5 m/s through a coupling of efficiency 0.85 (g = 9.81): the book gives
J = 0.4 kg·m² and T_l = 117.53 N·m.
"""

from __future__ import annotations

import random

import mpmath
import pytest

import taucli
from conftest import assert_usage_error

mpmath.mp.dps = 30


def _motor_torque(rotor, friction, loads, alpha, omega=mpmath.mpf(1)):
    """Σ of the powers each part takes, over ω (loads: (J, N, η, η′, T))."""
    power = rotor * alpha * omega + friction * omega
    for inertia, ratio, eta, back, torque in loads:
        shaft = (inertia * alpha / ratio + torque) * omega / ratio
        power += shaft / eta if shaft >= 0 else back * shaft
    return power / omega


def test_dubey_example_2_1_two_loads():
    report = taucli.drive(motor_inertia="0.2 kg*m^2", load=["inertia=10kg*m^2 ratio=10 efficiency=0.9 torque=10N*m",
                                                             "mass=1000kg speed=1.5m/s force=9810N efficiency=0.85"], motor_speed="1420 rpm")
    results = report.results
    omega = mpmath.mpf(1420) * 2 * mpmath.pi / 60
    inertia = mpmath.mpf("0.2") + mpmath.mpf(10) / 100 + 1000 * (mpmath.mpf("1.5") / omega) ** 2
    torque = mpmath.mpf(10) / (10 * mpmath.mpf("0.9")) + 9810 * mpmath.mpf("1.5") / omega / mpmath.mpf("0.85")
    assert results["total_inertia"].value == pytest.approx(float(inertia), rel=1e-14)
    assert results["load_torque_motor"].value == pytest.approx(float(torque), rel=1e-14)
    assert results["power_run"].value == pytest.approx(float(torque * omega), rel=1e-14)
    assert round(results["total_inertia"].value, 1) == 0.4  # the book's 0.4 kg·m²
    assert round(results["load_torque_motor"].value, 2) == 117.53  # the book's 117.53 N·m
    rows = report.tables["loads"].rows
    assert [row[4] for row in rows] == [pytest.approx(0.1, rel=1e-15), pytest.approx(float(1000 * (mpmath.mpf("1.5") / omega) ** 2), rel=1e-14)]


@pytest.mark.parametrize("seed", range(3))
def test_random_loads_against_the_power_flow(seed):
    """Runs-up at a constant α and moves (the load driving back while the motor brakes) of 1 to 4 loads."""
    rng = random.Random(4731 + seed)
    for _ in range(8):
        rotor, friction = rng.uniform(1e-4, 1e-2), rng.choice([0.0, rng.uniform(0, 0.5)])
        loads, specs = [], []
        for _ in range(rng.randint(1, 4)):
            inertia, ratio, eta, back = rng.uniform(1e-3, 2), rng.uniform(1, 40), rng.uniform(0.5, 1), rng.uniform(0.2, 1)
            torque = rng.choice([0.0, rng.uniform(-20, 20)])
            loads.append((inertia, ratio, eta, back, torque))
            specs.append(f"inertia={inertia!r}kg*m^2 ratio={ratio!r} efficiency={eta!r} efficiency-back={back!r} torque={torque!r}N*m")
        q = [tuple(mpmath.mpf(x) for x in load) for load in loads]
        top, accel, decel = rng.uniform(50, 300), rng.uniform(0.05, 1), rng.uniform(0.05, 1)
        values = {k: v.value for k, v in taucli.drive(motor_inertia=rotor, motor_friction=friction, load=specs, until_omega=f"{top} rad/s",
                                                      accel_time=f"{accel} s", decel_time=f"{decel} s", run_time="1 s").results.items()}
        case = (rotor, friction, loads, top, accel, decel)
        r, f = mpmath.mpf(rotor), mpmath.mpf(friction)
        assert values["torque_accel"] == pytest.approx(float(_motor_torque(r, f, q, mpmath.mpf(top) / accel)), rel=1e-12, abs=1e-12), case
        assert values["torque_decel"] == pytest.approx(float(_motor_torque(r, f, q, -mpmath.mpf(top) / decel)), rel=1e-12, abs=1e-12), case
        assert values["load_torque_motor"] == pytest.approx(float(_motor_torque(r, f, q, 0)), rel=1e-12, abs=1e-12), case
        assert values["reflected_inertia"] == pytest.approx(float(sum(j / n**2 for j, n, *_ in q)), rel=1e-13), case


def test_the_run_up_energy_balances_load_by_load():
    """At a constant α to a speed: the motor's work is the kinetic energy, the loads' work and what each train takes."""
    results = taucli.drive(motor_inertia="0.2 kg*m^2", load=["inertia=10kg*m^2 ratio=10 efficiency=0.9 torque=10N*m",
                                                              "mass=1000kg radius=0.2m ratio=20 force=-500N efficiency=0.85 efficiency-back=0.5"],
                           until_omega="1420 rpm", in_time="2 s", energy=True).results
    omega, t = mpmath.mpf(1420) * 2 * mpmath.pi / 60, mpmath.mpf(2)
    alpha, theta = omega / t, omega * t / 2
    loads = [(mpmath.mpf(10), mpmath.mpf(10), mpmath.mpf("0.9"), mpmath.mpf("0.9"), mpmath.mpf(10)),
             (1000 * mpmath.mpf("0.2") ** 2, mpmath.mpf(20), mpmath.mpf("0.85"), mpmath.mpf("0.5"), -500 * mpmath.mpf("0.2"))]
    torque = _motor_torque(mpmath.mpf("0.2"), 0, loads, alpha)
    assert results["torque_accel"].value == pytest.approx(float(torque), rel=1e-13)
    assert results["work_motor"].value == pytest.approx(float(torque * theta), rel=1e-13)
    assert results["work_motor"].value == pytest.approx(results["KE"].value + results["work_load"].value + results["work_loss"].value, rel=1e-12)


def test_one_load_given_either_way_is_the_same_drive():
    """A single --load is the scene's single load (--ratio, --efficiency, --efficiency-back, --load-inertia, --load-torque):
    the inertia, the load torque, a run-up's and a move's torques alike."""
    rng = random.Random(4732)
    for _ in range(10):
        inertia, ratio, eta, back, torque = rng.uniform(0.01, 2), rng.uniform(1, 30), rng.uniform(0.5, 1), rng.uniform(0.2, 1), rng.uniform(-5, 5)
        motion = rng.choice([dict(until_omega="2000 rpm", in_time="0.5 s"), dict(until_omega="1500 rpm", accel_time="0.2 s", run_time="1 s", dwell_time="0.5 s")])
        one = taucli.drive(motor_inertia="1e-3 kg*m^2", load=[f"inertia={inertia!r} ratio={ratio!r} efficiency={eta!r} efficiency-back={back!r} torque={torque!r}"],
                           **motion).results
        single = taucli.drive(motor_inertia="1e-3 kg*m^2", load_inertia=inertia, ratio=[ratio], efficiency=eta, efficiency_back=back, load_torque=torque,
                              **motion).results
        for key in ("reflected_inertia", "total_inertia", "load_torque_motor", "torque_accel", "torque_decel", "torque_rms", "energy_regen"):
            if key in single:
                assert one[key].value == pytest.approx(single[key].value, rel=1e-13, abs=1e-13), (key, inertia, ratio, eta, back, torque, motion)


def test_a_mass_on_a_drum_is_the_single_loads_mass():
    one = taucli.drive(motor_inertia="1e-3 kg*m^2", load=["mass=50kg radius=5cm ratio=10 force=100N efficiency=0.8"], until_omega="1500 rpm", in_time="1 s").results
    single = taucli.drive(motor_inertia="1e-3 kg*m^2", load_mass="50 kg", drum_radius="5 cm", ratio=[10], load_force="100 N", efficiency=0.8,
                          until_omega="1500 rpm", in_time="1 s").results
    for key in ("reflected_inertia", "load_torque_motor", "torque_accel"):
        assert one[key].value == pytest.approx(single[key].value, rel=1e-14), key


@pytest.mark.parametrize("args", [
    ("--ratio", "3"), ("--efficiency", "0.9"), ("--efficiency-back", "0.5"), ("--load-inertia", "1kg*m^2"), ("--load-mass", "3kg"),
    ("--drum-radius", "0.1m"), ("--lead", "5mm"), ("--load-torque", "2N*m"), ("--load-force", "20N"), ("--shape", "disc"),
    ("--speed", "1m/s"), ("--accel", "1m/s^2"), ("--distance", "1m"),
])
def test_the_single_loads_options_are_refused_beside_load(taucli, args):
    assert_usage_error(taucli("drive", "--load", "inertia=1kg*m^2 ratio=5", *args, "--until-omega", "100rpm", "--in-time", "1s"),
                       args[0], "--load", "e.g. --load")


@pytest.mark.parametrize(("spec", "fragments"), [
    ("inertia=1kg*m^2 efficiency=1.5", ("efficiency=1.5",)),
    ("inertia=1kg*m^2 efficiency-back=1.5", ("efficiency-back=1.5",)),
    ("ratio=5", ("needs inertia=",)),
    ("mass=10kg", ("radius=",)),
    ("force=10N", ("radius=",)),
    ("inertia=1kg*m^2 radius=0.1m", ("without a mass=",)),
    ("mass=10kg radius=0.1m speed=1m/s", ("radius= and speed=",)),
    ("mass=10kg speed=1m/s ratio=3", ("speed= and ratio=",)),
    ("inertia=1m", ("inertia=",)),
    ("inertia=1kg*m^2 ratio=-2", ("ratio=",)),
    ("inertia=1kg*m^2 ratio=0", ("ratio=",)),
    ("inertia=1kg*m^2 efficiency=0", ("efficiency=",)),
    ("mass=-3kg radius=1m", ("mass=",)),
    ("mass=3kg radius=0m", ("radius=",)),
    ("mass=3kg speed=2rad/s", ("speed=",)),
    ("torque=3N", ("torque=",)),
    ("force=3N*m radius=1m", ("force=",)),
    ("inertia=1kg*m^2 wheel=3", ("knows",)),
])
def test_a_bad_load_is_refused_in_one_line_with_an_example(taucli, spec, fragments):
    assert_usage_error(taucli("drive", "--load", spec, "--motor-speed", "1000rpm"), "--load", "(e.g. ", *fragments)


def test_speed_needs_the_motor_speed_and_the_line_law_waits(taucli):
    assert_usage_error(taucli("drive", "--load", "mass=3kg speed=1m/s"), "--motor-speed", "speed=")
    assert_usage_error(taucli("drive", "--load", "inertia=1kg*m^2", "--motor-speed", "1000rpm", "--accel-time", "1s", "--until-omega", "100rpm"),
                       "--motor-speed", "move")
    assert_usage_error(taucli("drive", "--load", "inertia=1kg*m^2", "--stall-torque", "2N*m", "--no-load-speed", "100rpm", "--until-omega", "50rpm"),
                       "--load", "not built", "--motor-curve", "(e.g. ")


def test_find_a_ratio_inside_a_load():
    report = taucli.drive(motor_inertia="0.2 kg*m^2", load=["inertia=10kg*m^2 efficiency=0.9 torque=10N*m",
                                                             "mass=1000kg speed=1.5m/s force=9810N efficiency=0.85"], motor_speed="1420 rpm",
                          find="load1.ratio", want="load_torque_motor=118 N*m")
    omega = mpmath.mpf(1420) * 2 * mpmath.pi / 60
    rest = 9810 * mpmath.mpf("1.5") / omega / mpmath.mpf("0.85")
    assert report.results["load1.ratio"].value == pytest.approx(float(10 / (mpmath.mpf("0.9") * (118 - rest))), rel=1e-10)


def test_the_power_at_the_motor_speed_for_one_load_too():
    """--motor-speed gives power_run, the load's torque at the motor (losses included) times the speed, with one load as with several."""
    results = taucli.drive(load_torque="50 N*m", ratio=[10], efficiency=0.9, motor_speed="1400 rpm").results
    omega = mpmath.mpf(1400) * 2 * mpmath.pi / 60
    assert results["power_run"].value == pytest.approx(float(50 / (10 * mpmath.mpf("0.9")) * omega), rel=1e-14)
