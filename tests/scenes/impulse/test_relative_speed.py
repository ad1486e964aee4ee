"""#46 item 6: a particle given by its speed relative to the turning body (--particle "… speed-relative=…").

A toy train on a track on a wheel free to turn, a person walking on a turntable: after, the
particle moves along the rim at v_rel relative to the body, whose point there moves at ω₁ρ, so its
speed over the ground is v′ = ω₁ρ + v_rel; with no torque about the axis L is conserved:

    I ω₀ + Σ m v₀ r = I ω₁ + Σ m ρ (ω₁ρ + v_rel).

The references (tests/references/impulse.py, speed_relative) are written from this alone.
"""

from __future__ import annotations

import json
import math

import pytest

import taucli as api
from conftest import assert_usage_error
from references.impulse import Particle, meet


def test_halliday_toy_train_on_a_free_wheel(taucli):
    """Halliday, Fundamentals of Physics, ch. 11 (a track mounted on a large wheel, a hoop): the train
    of mass m starts from rest to 0.176 m/s relative to the track; the wheel's mass 1.97 m, radius
    0.584 m. Book: 0.101 rad/s (the wheel turns the other way). The train's mass cancels: m = 1 kg."""
    run = taucli("impulse", "--shape", "ring", "--mass", "1.97kg", "--radius", "0.584m",
                 "--particle", "mass=1kg radius=0.584m speed-relative=0.176m/s", "--json")
    assert run.code == 0, run.err
    results = run.json()["results"]
    assert results["omega1"]["value"] == pytest.approx(-0.176 / (2.97 * 0.584), rel=1e-12)  # −v/((1 + M/m) R)
    assert round(abs(results["omega1"]["value"]), 3) == 0.101
    assert results["L0"]["value"] == 0 and results["L1"]["value"] == 0
    # the train over the ground: v_rel + ω₁R = v_rel · M/(M + m)
    assert results["speed_after"]["value"] == pytest.approx(0.176 * 1.97 / 2.97, rel=1e-12)
    # energy: nothing moved before; the motor gave the wheel ½Iω₁² and the train ½mv′²
    ke1 = 0.5 * 1.97 * 0.584**2 * results["omega1"]["value"] ** 2 + 0.5 * (0.176 * 1.97 / 2.97) ** 2
    assert results["KE1"]["value"] == pytest.approx(ke1, rel=1e-12)
    assert results["KE_lost"]["value"] == pytest.approx(-ke1, rel=1e-12)


def test_a_person_running_on_a_turntable_at_rest():
    """Giancoli's merry-go-round (55 kg at the edge of a 6.5 m turntable of 1700 kg·m², running at
    3.8 m/s with respect to it): ω = −m v R / (I + m R²) = −0.298 rad/s."""
    report = api.impulse(inertia="1700 kg*m^2", particle="mass=55kg radius=3.25m speed-relative=3.8m/s")
    assert report.results["omega1"].value == pytest.approx(-55 * 3.8 * 3.25 / (1700 + 55 * 3.25**2), rel=1e-13)
    assert report.results["omega1"].value == pytest.approx(-0.298, abs=5e-4)


def test_a_walker_on_a_turning_table_who_then_walks():
    """The table and the walker turn together at ω₀; the walker then walks at v_rel: L₀ = (I + mR²)ω₀."""
    exact = meet(400.0, 0.5, [Particle(60.0, 2.0, speed_relative=-1.5)])
    w1 = (400 * 0.5 + 60 * 4 * 0.5 + 60 * 2 * 1.5) / (400 + 60 * 4)
    assert float(exact["omega1"]) == pytest.approx(w1, rel=1e-15)  # the reference against the balance by hand
    report = api.impulse(inertia=400.0, omega0="0.5 rad/s", particle="mass=60kg radius=2m speed-relative=-1.5m/s")
    for name in ("omega1", "L0", "L1", "KE0", "KE1", "KE_lost"):
        assert report.results[name].value == pytest.approx(float(exact[name]), rel=1e-13), name


def test_command_line_batch_and_python_agree(taucli):
    spec = "mass=2kg radius=0.5m speed=1m/s speed-relative=0.3m/s"
    single = taucli("impulse", "--inertia", "0.8kg*m^2", "--omega0", "2rad/s", "--particle", spec, "--json").json()
    batch = taucli("impulse", "--batch", stdin=json.dumps({"inertia": "0.8kg*m^2", "omega0": "2rad/s", "particle": spec}) + "\n")
    assert batch.code == 0, batch.err
    document = json.loads(batch.out.splitlines()[0])
    report = api.impulse(inertia="0.8kg*m^2", omega0="2rad/s", particle=spec)
    # L: 0.8·2 + 2·1·0.5 = 2.6 = (0.8 + 2·0.25) ω₁ + 2·0.5·0.3
    w1 = (0.8 * 2 + 2 * 1 * 0.5 - 2 * 0.5 * 0.3) / (0.8 + 2 * 0.25)
    for results in (single["results"], document["results"]):
        assert results["omega1"]["value"] == pytest.approx(w1, rel=1e-14)
    assert report.results["omega1"].value == pytest.approx(w1, rel=1e-14)
    assert single["inputs"]["particle1_speed_relative"]["value"] == 0.3


def test_several_walkers_keep_the_energy_balance():
    """Two walkers in opposite senses on a light table: KE₁ = ½ I ω₁² + Σ ½ m v′², KE_lost = KE₀ − KE₁ < 0 (legs do work)."""
    parts = [Particle(50.0, 2.0, speed_relative=1.0), Particle(70.0, 1.5, speed_relative=-2.0, radius_after=1.0)]
    exact = meet(300.0, 0.2, parts)
    report = api.impulse(inertia=300.0, omega0="0.2 rad/s",
                            particle=["mass=50kg radius=2m speed-relative=1m/s", "mass=70kg radius=1.5m radius-after=1m speed-relative=-2m/s"])
    for name in ("omega1", "L1", "KE0", "KE1", "KE_lost"):
        assert report.results[name].value == pytest.approx(float(exact[name]), rel=1e-13), name
    assert report.results["KE_lost"].value < 0
    rows = report.tables["parts"].rows
    assert math.fsum(row[3] for row in rows) == pytest.approx(0.0, abs=1e-12)  # the parts' angular impulses cancel
    w1 = report.results["omega1"].value
    assert rows[1][4] == pytest.approx(w1 * 2 + 1.0, rel=1e-13) and rows[2][4] == pytest.approx(w1 * 1 - 2.0, rel=1e-13)


@pytest.mark.parametrize("spec, fragment", [
    ("mass=1kg radius=1m speed=2m/s speed-relative=1m/s e=0.5", "speed-relative="),
    ("mass=1kg radius=1m speed=2m/s speed-relative=1m/s speed-after=1m/s", "speed-relative="),
    ("mass=1kg radius=1m speed-relative=1rad/s", "speed-relative="),
])
def test_a_relative_speed_with_what_leaves_or_of_another_kind_is_refused(taucli, spec, fragment):
    assert_usage_error(taucli("impulse", "--inertia", "2kg*m^2", "--particle", spec), fragment)


def test_a_walker_beside_a_particle_that_leaves_is_refused(taucli):
    run = taucli("impulse", "--inertia", "2kg*m^2", "--particle", "mass=1kg radius=1m speed-relative=1m/s",
                 "--particle", "mass=1kg radius=1m speed=2m/s speed-after=1m/s")
    assert_usage_error(run, "speed-relative=", "run of its own")
