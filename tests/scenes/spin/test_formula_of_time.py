"""#46 item 4: a torque or an angular acceleration as a formula of time (α = 2.0 − 3.0t, τ = 10t),
in spin-down (ω(t), θ(t)) and impulse (J = ∫τ dt). Before, '(2 - 3*t/s) rad/s^2' was refused as
a quantity (a tonne over a second...).

The references are the physics written out in mpmath: ω = ω₀ + ∫α dt and θ = ∫ω dt by mpmath's own
quadrature of the formula written as an mpmath function (nested: θ integrates ω, not the solver's
one integral of (t − s)α), J = ∫τ dt, and the work ∫τω dt.
"""

from __future__ import annotations

import random

import mpmath
import pytest

import taucli
from conftest import assert_usage_error, run_taucli

MP_DPS = 30


def kinematics(alpha, omega0, T):
    """ω(T) and θ(T) from α(t) by mpmath's quadrature: ω = ω₀ + ∫₀ᵀ α, θ = ∫₀ᵀ ω(s) ds (nested)."""
    def omega(s):
        return omega0 + mpmath.quad(alpha, [0, s])
    return omega(T), mpmath.quad(omega, [0, T])


def close(got, want, rel=1e-12, scale=0.0):
    return abs(got - float(want)) <= rel * max(abs(got), abs(float(want)), scale)


def test_the_issues_alpha_and_giancolis_wheel():
    """α = 2.0 − 3.0t from rest: ω(2 s) = 2·2 − 1.5·4 = −2 rad/s, θ = 4 − 8/2 = 0; it is back at rest at
    t = 4/3 s. Giancoli (Physics for Scientists and Engineers, ch. 10): α = 5.0t² − 8.5t from rest,
    at t = 2.0 s ω = −3.7 rad/s and θ = −4.7 rad."""
    done = run_taucli("spin-down", "--alpha", "(2.0 - 3.0*t/s) rad/s^2", "--time", "2s", "--json")
    assert done.code == 0, done.err
    res = done.json()["results"]
    assert close(res["omega"]["value"], -2.0, scale=2.0) and abs(res["theta"]["value"]) < 1e-14 and res["alpha_end"]["value"] == -4.0
    back = run_taucli("spin-down", "--alpha", "(2.0 - 3.0*t/s) rad/s^2", "--until-omega", "0", "--get", "t_until")
    assert float(back.out) == pytest.approx(4 / 3, rel=1e-13)
    wheel = taucli.spin_down(alpha="(5.0*(t/s)^2 - 8.5*t/s) rad/s^2", time="2.0 s").results
    assert round(wheel["omega"].value, 1) == -3.7 and round(wheel["theta"].value, 1) == -4.7


def test_the_issues_torque_in_impulse():
    """τ = 10t N·m for 2 s: J = ∫τ dt = 5t² = 20 N·m·s; on 2 kg·m² from rest ω₁ = 10 rad/s."""
    done = run_taucli("impulse", "--torque", "10 N*m/s * t", "--duration", "2s", "--inertia", "2kg*m^2", "--json")
    assert done.code == 0, done.err
    res = done.json()["results"]
    assert res["J"]["value"] == 20.0 and res["omega1"]["value"] == pytest.approx(10.0, rel=1e-15)
    assert res["L1"]["value"] - res["L0"]["value"] == pytest.approx(res["J"]["value"], rel=1e-15)  # J = ΔL
    assert float(run_taucli("impulse", "--torque", "(10 N*m/s)*t", "--duration", "2s", "--get", "J").out) == 20.0


FORMULAS = [  # (text, mpmath α(t)), each with its angle unit
    ("(2.0 - 3.0*t/s) rad/s^2", lambda t: 2 - 3 * t),
    ("2 rad/s^2 - 3 rad/s^3 * t + 0.5 rad/s^5 * t^3", lambda t: 2 - 3 * t + t**3 / 2),
    ("5 rad/s^2 * exp(-t/(2 s))", lambda t: 5 * mpmath.exp(-t / 2)),
    ("3 rad/s^2 * sin(2 rad/s * t)", lambda t: 3 * mpmath.sin(2 * t)),
    ("sqrt(t/s) rev/s^2", lambda t: 2 * mpmath.pi * mpmath.sqrt(t)),
    ("(1 rad/s^2)/(1 + t/s)^2", lambda t: 1 / (1 + t) ** 2),
]


@pytest.mark.parametrize("text, alpha", FORMULAS, ids=[text for text, _ in FORMULAS])
def test_alpha_against_the_quadrature_of_mpmath(text, alpha):
    omega0, T = 1.5, 2.5
    want_omega, want_theta = kinematics(alpha, omega0, T)
    res = taucli.spin_down(alpha=text, omega0=f"{omega0} rad/s", time=f"{T} s").results
    assert close(res["omega"].value, want_omega, 1e-12, 10) and close(res["theta"].value, want_theta, 1e-12, 10), (res["omega"], res["theta"])
    assert close(res["alpha_end"].value, alpha(mpmath.mpf(T)), 1e-13, 1)


@pytest.mark.parametrize("seed", range(12))
def test_torque_polynomials_energy_and_momentum(seed):
    """A random cubic torque on a random body: ω and θ against mpmath; the balances the class
    holds: L = Iω, KE = ½Iω², work_drive = ∫τω dt (mpmath) = ΔKE, and impulse's J = ∫τ dt = ΔL."""
    rng = random.Random(seed)
    c = [rng.uniform(-5, 5) for _ in range(4)]
    inertia, omega0, T = 10 ** rng.uniform(-1, 1), rng.uniform(-3, 3), 10 ** rng.uniform(-1, 0.5)
    text = f"({c[0]!r} + {c[1]!r}*t/s + {c[2]!r}*(t/s)^2 + {c[3]!r}*(t/s)^3) N*m"

    def tau(t):
        return c[0] + c[1] * t + c[2] * t**2 + c[3] * t**3

    want_omega, want_theta = kinematics(lambda t: tau(t) / inertia, omega0, T)
    res = taucli.spin_down(torque=text, inertia=inertia, omega0=omega0, time=T).results
    size = abs(omega0) + sum(abs(x) for x in c) * max(T, 1) ** 3 / inertia
    assert close(res["omega"].value, want_omega, 1e-13, size) and close(res["theta"].value, want_theta, 1e-13, size * max(T, 1))
    assert res["L"].value == pytest.approx(inertia * res["omega"].value, rel=1e-15)
    work = mpmath.quad(lambda t: tau(t) * (omega0 + mpmath.quad(lambda s: tau(s) / inertia, [0, t])), [0, T])
    assert close(res["work_drive"].value, work, 1e-11, inertia * size * size)
    assert close(res["KE"].value - res["KE0"].value, work, 1e-11, inertia * size * size)
    J = mpmath.quad(tau, [0, T])
    imp = taucli.impulse(torque=text, duration=T, inertia=inertia, omega0=omega0).results
    assert close(imp["J"].value, J, 1e-13, size * inertia) and close(imp["L1"].value - imp["L0"].value, J, 1e-12, size * inertia)


def test_the_same_formula_in_other_units():
    """Unit invariance: N·m and s against N·cm, ms and rpm/s."""
    si = taucli.spin_down(torque="(2 N*m/s)*t + 1 N*m", inertia=2.0, omega0="3 rad/s", time=2.0).results
    other = taucli.spin_down(torque="(200 N*cm)*(t/(1000 ms)) + 100 N*cm", inertia="20000 kg*cm^2", omega0="3 rad/s", time="2000 ms").results
    for key in ("omega", "theta", "KE", "work_drive", "torque"):
        assert other[key].value == pytest.approx(si[key].value, rel=1e-13), key
    alpha_si = taucli.spin_down(alpha="(2 - 3*t/s) rad/s^2", time=2.0).results["omega"].value
    alpha_rpm = taucli.spin_down(alpha=f"({2 * 30 / 3.141592653589793!r} - {3 * 30 / 3.141592653589793!r}*t/s) rpm/s", time=2.0).results["omega"].value
    assert alpha_rpm == pytest.approx(alpha_si, rel=1e-13)


def test_batch_is_the_command_line():
    single = run_taucli("spin-down", "--alpha", "(2 - 3*t/s) rad/s^2", "--time", "2s", "--json").json()
    batch = __import__("json").loads(run_taucli("spin-down", "--batch", stdin='{"alpha": "(2 - 3*t/s) rad/s^2", "time": "2s"}\n').out)
    assert batch["results"] == single["results"]


@pytest.mark.parametrize("args, fragments", [
    (("--alpha", "(2 - 3*t) rad/s^2", "--time", "1s"), ("--alpha", "different kinds")),
    (("--alpha", "(2 - 3*t/s)/s^2", "--time", "1s"), ("--alpha", "angle unit")),
    (("--alpha", "sin(t) rad/s^2", "--time", "1s"), ("--alpha", "sin(")),
    (("--alpha", "(t/s)^20 rad/s^2", "--time", "1s"), ("--alpha", "power")),
    (("--alpha", "1/(t/s - 1) rad/s^2", "--time", "2s"), ("--alpha", "no finite value")),
    (("--alpha", "1/t rad/s", "--time", "1s"), ("--alpha", "division by zero")),
    (("--alpha", "exp(1000*t/s) rad/s^2", "--time", "2s"), ("--alpha", "no finite value")),
    (("--alpha", "abc*t rad/s^2", "--time", "1s"), ("--alpha", "not a unit")),
    (("--alpha", "__import__('os') * t", "--time", "1s"), ("--alpha",)),
    (("--alpha", "(t/s rad/s^2", "--time", "1s"), ("--alpha", "without its )")),
    (("--alpha", "t/s rad/s^2", "--time", "1s", "--friction", "1N*m", "--inertia", "1kg*m^2"), ("--friction", "formula of t")),
    (("--torque", "t/s N*m", "--time", "1s"), ("--torque", "needs the body")),
    (("--alpha", "-t/s rad/s^2", "--until-omega", "100rad/s"), ("--until-omega", "not reached")),
])
def test_refusals(args, fragments):
    assert_usage_error(run_taucli("spin-down", *args), *fragments)


def test_impulse_refusals():
    assert_usage_error(run_taucli("impulse", "--torque", "t/s N*m", "--inertia", "1kg*m^2"), "--duration", "required")
    assert_usage_error(run_taucli("impulse", "--torque", "t/s N*m", "--duration", "1s", "--inertia-final", "1kg*m^2", "--inertia", "2kg*m^2"),
                       "--inertia-final", "formula of t")
