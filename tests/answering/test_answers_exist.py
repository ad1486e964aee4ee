"""#31 items 11-14: answers that exist, given rather than refused, null or mislabelled.

Each reference here is worked from the physics, not read off taucli."""

from __future__ import annotations

import math

import mpmath
import pytest

from conftest import run_taucli

MP_DPS = 30


def _results(*args: str) -> dict:
    done = run_taucli(*args, "--json")
    assert done.code == 0, done.err
    return {key: value["value"] for key, value in done.json()["results"].items()}


def test_energy_and_work_are_at_the_target_speed_for_a_torque_law():
    """Item 11: I = 1, ω₀ = 100 rad/s, friction 1 N·m and viscous 0.1 N·m·s, to ω = 50 rad/s.
    I dω/dt = −τ_f − bω: t = (I/b) ln((τ_f + bω₀)/(τ_f + bω₁)), θ = ∫ω dt, W_f = τ_f θ,
    W_b = KE0 − KE − W_f. Today KE and the works were at the stop."""
    r = _results("spin-down", "--inertia", "1", "--omega0", "100rad/s", "--friction", "1", "--viscous", "0.1", "--until-omega", "50rad/s", "--energy")
    i, tf, b, w0, w1 = map(mpmath.mpf, (1, 1, "0.1", 100, 50))
    t = i / b * mpmath.log((tf + b * w0) / (tf + b * w1))
    omega = lambda s: (w0 + tf / b) * mpmath.exp(-b * s / i) - tf / b  # noqa: E731
    theta = mpmath.quad(omega, [0, t])
    assert r["KE"] == pytest.approx(float(i * w1**2 / 2), rel=1e-14)
    assert r["work_friction"] == pytest.approx(float(tf * theta), rel=1e-12)
    assert r["work_viscous"] == pytest.approx(float(i * (w0**2 - w1**2) / 2 - tf * theta), rel=1e-12)
    assert r["power_viscous"] == pytest.approx(float(b * w1**2), rel=1e-14)


def test_energy_is_at_the_target_speed_at_a_constant_alpha():
    """Item 11 with --alpha: α = −2 rad/s², ω from 100 to 50 rad/s in t = 25 s; τ = Iα + τ_f."""
    r = _results("spin-down", "--inertia", "1", "--omega0", "100rad/s", "--alpha", "-2rad/s^2", "--friction", "1", "--until-omega", "50rad/s")
    assert r["KE"] == pytest.approx(0.5 * 50**2, rel=1e-15)
    theta = (100 + 50) / 2 * 25
    assert r["work_friction"] == pytest.approx(1 * theta, rel=1e-15)
    assert r["work_drive"] == pytest.approx((1 * -2 + 1) * theta, rel=1e-15)


def test_energy_is_at_the_target_angle():
    r = _results("spin-down", "--inertia", "1", "--omega0", "100rad/s", "--friction", "1", "--until-angle", "10rev", "--energy")
    theta = 20 * math.pi
    assert r["work_friction"] == pytest.approx(theta, rel=1e-14)
    assert r["KE"] == pytest.approx(5000 - theta, rel=1e-14)  # KE0 − τ_f θ


def test_a_body_rolling_steadily_has_no_tangential_acceleration():
    """Item 12: rolling at v₀ on the flat, α = 0: a_t = 0, a_total = a_c = v²/R... at r = R."""
    r = _results("rolling", "sphere", "--v0", "20m/s", "--radius", "0.3m", "--at", "rim")
    assert r["a_t"] == 0 and r["alpha"] == 0
    assert r["a_total"] == pytest.approx(20**2 / 0.3, rel=1e-15)


def test_naming_a_result_turns_on_what_makes_it():
    """Item 13: --get KE0 without --energy was refused as "not a result"."""
    done = run_taucli("spin-down", "--inertia", "2", "--omega0", "10rad/s", "--friction", "1", "--get", "KE0", "--get", "work_friction")
    assert done.code == 0, done.err
    assert [float(x) for x in done.out.split()] == [pytest.approx(100.0, rel=1e-15), pytest.approx(100.0, rel=1e-15)]


def test_a_null_from_get_says_why_on_stderr():
    """Item 13: `--get t_stop` under viscous drag alone printed null and nothing else."""
    done = run_taucli("spin-down", "--inertia", "1", "--viscous", "1", "--omega0", "1rad/s", "--get", "t_stop")
    assert done.code == 0 and done.out == "null\n"
    assert done.err.startswith("taucli: note: t_stop: drag alone") and len(done.err.splitlines()) == 1


def test_a_load_of_constant_power_is_said_to_drain_the_wheel():
    """Item 14: a negative --power was "½Iω² grows linearly in time", and its power read 0 at the stop."""
    done = run_taucli("spin-down", "--inertia", "1", "--omega0", "10rad/s", "--power", "-10W", "--until-omega", "0", "--json")
    doc = done.json()
    assert "falls" in doc["model"] and "grows" not in doc["model"]
    assert doc["results"]["power"]["value"] == -10.0  # it drains P right up to the stop
    assert float(run_taucli("spin-down", "--inertia", "1", "--omega0", "10rad/s", "--power", "-10W", "--time", "6s", "--get", "power").out) == 0.0


def test_a_wheel_with_no_torque_is_not_said_to_have_friction():
    doc = run_taucli("spin-down", "--inertia", "1", "--omega0", "10rad/s", "--json").json()
    assert "friction" not in doc["model"] and "no torque" in doc["model"]
