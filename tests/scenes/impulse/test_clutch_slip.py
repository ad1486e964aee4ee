"""A clutch that slips (impulse --couple "… torque=…", #35): two bodies on one axis brought to a
common speed through a finite clutch torque. References from the physics at 50 digits: each body's
speed under the clutch's torque, the instant they meet found with mpmath.findroot and the heat as
the clutch's torque integrated over the speed difference (mpmath.quad); the balances (heat = KE
lost, each body's angular impulse T·t_slip = its ΔL, L conserved) as properties; a published
problem with its printed answers."""

from __future__ import annotations

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taucli
from conftest import assert_usage_error, run_taucli


def values(report):
    return {name: value.value for name, value in report.results.items()}


def clutch_reference(i1, w1, i2, w2, torque):
    """(ω_f, t_slip, heat): each body's speed changes at T/I against the other's while they differ
    (the clutch's torque is equal and opposite on the two); t_slip where the speeds meet, the heat
    ∫ T |ω₁ − ω₂| dt over the slip."""
    i1, w1, i2, w2, torque = (mpmath.mpf(x) for x in (i1, w1, i2, w2, torque))
    sense = mpmath.sign(w1 - w2)
    speed1 = lambda t: w1 - sense * torque / i1 * t  # noqa: E731
    speed2 = lambda t: w2 + sense * torque / i2 * t  # noqa: E731
    slip = mpmath.findroot(lambda t: speed1(t) - speed2(t), 0)
    heat = mpmath.quad(lambda t: torque * abs(speed1(t) - speed2(t)), [0, slip])
    return speed1(slip), slip, heat


def test_motor_and_rotor_khurmi():
    """Khurmi & Gupta, Theory of Machines (friction clutches): a motor armature and shaft of 800 kg,
    k = 200 mm, at 1250 rpm, switched off and clutched suddenly to a rotor of 1300 kg, k = 180 mm,
    at rest, through a single plate clutch, both sides effective, 220 mm and 160 mm across, 570 N
    of spring load, μ = 0.35 (uniform wear: T = 37.905 N·m). Printed: 539.7 rpm, 62.8 s, 155.8 kJ."""
    torque = taucli.spin_down(omega0="1250rpm", face="mu=0.35 force=570N inner-radius=80mm outer-radius=110mm model=wear surfaces=2")
    assert torque.results["torque_face"].value == pytest.approx(37.905, rel=1e-14)
    result = values(taucli.impulse(inertia="32kg*m^2", omega0="1250rpm", couple="inertia=42.12kg*m^2 omega0=0 torque=37.905N*m"))
    assert result["omega1"] * 60 / (2 * mpmath.pi) == pytest.approx(539.7, abs=0.05)
    assert result["t_slip"] == pytest.approx(62.8, abs=0.05)
    assert result["heat"] == pytest.approx(155.8e3, abs=50)
    common, slip, heat = clutch_reference(32, 1250 * 2 * mpmath.pi / 60, 42.12, 0, 37.905)
    assert result["omega1"] == pytest.approx(float(common), rel=1e-14)
    assert result["t_slip"] == pytest.approx(float(slip), rel=1e-14)
    assert result["heat"] == pytest.approx(float(heat), rel=1e-13)


SPEEDS = st.sampled_from([0.0]) | st.floats(-500, 500).filter(lambda x: abs(x) > 1e-6)


@settings(max_examples=60, deadline=None)
@given(i1=st.floats(1e-3, 1e3), i2=st.floats(1e-3, 1e3), w1=SPEEDS, w2=SPEEDS, torque=st.floats(1e-2, 1e4))
def test_clutch_balances(i1, i2, w1, w2, torque):
    """Properties: L conserved; heat = KE0 − KE1 ≥ 0; each body's angular impulse is T·t_slip;
    the couple faster than the body (either sense) works the same way."""
    report = taucli.impulse(inertia=i1, omega0=f"{w1!r} rad/s", couple=f"inertia={i2!r}kg*m^2 omega0={w2!r}rad/s torque={torque!r}N*m")
    result = values(report)
    scale = i1 * abs(w1) + i2 * abs(w2)
    assert result["L1"] == pytest.approx(result["L0"], rel=1e-12, abs=1e-12 * scale)
    energy = 0.5 * (i1 * w1 * w1 + i2 * w2 * w2)
    assert result["heat"] >= 0
    assert result["heat"] == pytest.approx(result["KE0"] - result["KE1"], rel=1e-9, abs=1e-12 * energy)
    common = result["omega1"]
    assert torque * result["t_slip"] == pytest.approx(i1 * abs(w1 - common), rel=1e-9, abs=1e-12 * scale)
    assert torque * result["t_slip"] == pytest.approx(i2 * abs(common - w2), rel=1e-9, abs=1e-12 * scale)
    parts = report.tables["parts"].rows
    assert parts[0][3] + parts[1][3] == pytest.approx(0, abs=1e-12 * scale)


def test_speeds_over_time_in_the_chart():
    """--plot: each body's ω falls or rises linearly at T/I to the common speed at t_slip, then stays."""
    report = taucli.impulse(inertia="2kg*m^2", omega0="100rad/s", couple="inertia=3kg*m^2 omega0=0 torque=50N*m")
    trajectory = report.trajectory()
    slip = report.results["t_slip"].value
    assert trajectory.state(slip / 2) == pytest.approx((100 - 25 * slip / 2, 50 / 3 * slip / 2), rel=1e-14)
    assert trajectory.state(1.5 * slip) == pytest.approx((40.0, 40.0), rel=1e-14)
    assert (slip, "the clutch stops slipping") in trajectory.marks


def test_units_do_not_change_the_answer():
    si = values(taucli.impulse(inertia="2kg*m^2", omega0="100rad/s", couple="inertia=3kg*m^2 omega0=0 torque=50N*m"))
    us = values(taucli.impulse(inertia="47.4608lb*ft^2", omega0=f"{100 * 60 / (2 * 3.141592653589793)!r}rpm",
                               couple=f"inertia={3 / 0.0421401100938048!r}lb*ft^2 omega0=0 torque={50 / 1.3558179483314004!r}lbf*ft"))
    for key in ("omega1", "t_slip", "heat"):
        assert us[key] == pytest.approx(si[key], rel=1e-5), key


@pytest.mark.parametrize(
    ("args", "fragments"),
    [
        (["--couple", "inertia=3kg*m^2 torque=50N*m", "--couple", "inertia=1kg*m^2"], ["--couple", "one"]),
        (["--couple", "inertia=3kg*m^2 torque=0N*m"], ["--couple", "torque="]),
        (["--couple", "inertia=0kg*m^2 torque=5N*m"], ["--couple", "inertia="]),
        (["--couple", "inertia=3kg*m^2 torque=5N*m", "--particle", "mass=1kg speed=1m/s radius=1m"], ["--couple"]),
    ],
)
def test_refusals(args, fragments):
    assert_usage_error(run_taucli("impulse", "--inertia", "1kg*m^2", "--omega0", "10rad/s", *args), *fragments)
