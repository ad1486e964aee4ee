"""--brake and --face in impulse (#24): a constant torque over Δt against Coulomb friction.

The reference is the motion worked here in mpmath: I dω/dt = τ − τ_f sgn ω while it turns; at
ω = 0 static friction (τ_s ≥ τ_f) holds it unless |τ| > τ_s, and then it turns back with the
friction reversed. Checked: ω₁, the net angular impulse I(ω₁ − ω₀) = τΔt − ∫τ_f sgn ω dt, the
energy balance ΔKE = τθ − τ_f·(angle swept), and the same answer in other units.
"""

from __future__ import annotations

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taucli
from taucli.core.errors import InputError

MP_DPS = 40  # the references' precision, set for each test by conftest


def _reference(inertia, omega0, torque, duration, kinetic, static):
    """(ω₁, net angle θ, angle swept both ways, the friction's angular impulse against +ω) from
    the piecewise motion (held at rest, static friction's is what balances τ)."""
    inertia, omega0, torque, duration, kinetic, static = map(mpmath.mpf, (inertia, omega0, torque, duration, kinetic, static))
    t, omega, theta, swept, friction_impulse = mpmath.mpf(0), omega0, mpmath.mpf(0), mpmath.mpf(0), mpmath.mpf(0)
    while t < duration:
        if omega == 0:
            if abs(torque) <= static:
                friction_impulse += torque * (duration - t)  # static friction balances τ for the rest of the time
                break
            sense = mpmath.sign(torque)
        else:
            sense = mpmath.sign(omega)
        alpha = (torque - sense * kinetic) / inertia
        left = duration - t
        to_stop = -omega / alpha if alpha * sense < 0 else mpmath.inf
        span = min(left, to_stop)
        angle = omega * span + alpha * span**2 / 2
        theta, swept = theta + angle, swept + abs(angle)
        friction_impulse += sense * kinetic * span
        omega = mpmath.mpf(0) if span == to_stop else omega + alpha * span
        t += span
    return omega, theta, swept, friction_impulse


@settings(max_examples=120, deadline=None)
@given(inertia=st.floats(0.1, 10), omega0=st.one_of(st.just(0.0), st.floats(0.5, 30), st.floats(-30, -0.5)),
       torque=st.one_of(st.floats(0.5, 50), st.floats(-50, -0.5)), duration=st.floats(0.1, 5), force=st.floats(1, 200),
       mu=st.floats(0.05, 0.8), extra=st.floats(0, 0.3), radius=st.floats(0.05, 1))
def test_a_braked_impulse_against_the_piecewise_motion(inertia, omega0, torque, duration, force, mu, extra, radius):
    spec = f"force={force!r}N mu-k={mu!r} mu-s={mu + extra!r} radius={radius!r}m"
    found = {key: value.value for key, value in
             taucli.impulse(inertia=inertia, omega0=omega0, torque=torque, duration=duration, brake=[spec]).results.items()}
    kinetic, static = mu * force * radius, (mu + extra) * force * radius
    omega1, theta, swept, friction_impulse = _reference(inertia, omega0, torque, duration, kinetic, static)
    scale = abs(omega0) + abs(torque) * duration / inertia + kinetic * duration / inertia
    assert found["omega1"] == pytest.approx(float(omega1), rel=1e-9, abs=1e-12 * scale)
    assert found["J"] == pytest.approx(torque * duration, rel=1e-14)
    # momentum: I Δω = τΔt − ∫τ_f sgn ω dt
    assert found["J_net"] == pytest.approx(float(torque * mpmath.mpf(duration) - friction_impulse), rel=1e-9, abs=1e-12 * inertia * scale)
    # energy: ΔKE = τθ − τ_f × swept, with work_brake = τ_f × swept
    assert found["work_brake"] == pytest.approx(float(kinetic * swept), rel=1e-9, abs=1e-12 * kinetic * scale * duration)
    gained = found["KE1"] - found["KE0"]
    assert gained == pytest.approx(float(torque * theta - kinetic * swept), rel=1e-8, abs=1e-9 * float(found["KE0"] + abs(torque * theta) + 1e-300))
    assert found["power_brake"] == pytest.approx(kinetic * abs(omega0), rel=1e-14)


def test_held_at_rest_when_the_torque_is_within_static_friction():
    found = taucli.impulse(inertia=1, omega0=0, torque="5N*m", duration="2s", brake=["force=100N mu-k=0.1 mu-s=0.2 radius=0.5m"])
    values = {key: value.value for key, value in found.results.items()}
    assert values["omega1"] == 0 and values["J_net"] == 0 and values["work_brake"] == 0
    assert any("holds" in note for note in found.notes)


def test_a_reversal_and_other_units():
    """ω₀ = 10 rad/s, τ = −30 N·m, τ_f = 20 N·m, I = 2.5: stops at 0.5 s, back at −4 rad/s² for 2.5 s."""
    metres = taucli.impulse(inertia="2.5kg*m^2", omega0="10rad/s", torque="-30N*m", duration="3s", brake=["force=100N mu=0.4 radius=0.5m"])
    other = taucli.impulse(inertia="25000kg*cm^2", omega0=f"{10 * 60 / (2 * 3.141592653589793)!r}rpm", torque="-30000N*mm", duration="3000ms",
                           brake=["force=0.1kN mu=0.4 radius=50cm"])
    assert metres.results["omega1"].value == pytest.approx(-10.0, rel=1e-14)
    for key in ("omega1", "J", "J_net", "work_brake", "KE1"):
        assert other.results[key].value == pytest.approx(metres.results[key].value, rel=1e-12), key


def test_a_face_on_a_table_takes_its_weight():
    """A 2 kg disc of radius 0.1 m lying flat, μ = 0.2, uniform pressure: τ = (2/3)μ m g R."""
    found = taucli.impulse(shape="disc", mass="2kg", radius="0.1m", omega0="20rad/s", torque="0.1N*m", duration="1s", face=["mu=0.2"])
    expected = mpmath.mpf(2) / 3 * mpmath.mpf("0.2") * 2 * mpmath.mpf("9.80665") * mpmath.mpf("0.1")
    assert found.results["torque_face"].value == pytest.approx(float(expected), rel=1e-14)


@pytest.mark.parametrize("given,name", [
    ({"omega1": "5rad/s", "torque": "1N*m"}, "omega1"),
    ({"torque": "1N*m"}, "duration"),
    ({"duration": "1s"}, "torque"),
    ({"torque": "1N*m", "duration": "1s", "particle": ["mass=1kg speed=1m/s radius=1m"]}, "particle"),
    ({"torque": "1N*m", "duration": "1s", "method": "simpson"}, "method"),
    ({"torque": "1N*m", "duration": "1s", "g": "9.8m/s^2"}, "g"),
])
def test_what_a_braked_impulse_refuses(given, name):
    with pytest.raises(InputError) as caught:
        taucli.impulse(inertia=1, omega0=1, brake=["force=10N mu=0.1 radius=0.1m"], **given)
    assert caught.value.option == name
