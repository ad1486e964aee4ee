"""#31 item 10: a --g that any input uses is accepted, in every scene; one that nothing uses is
refused. A weight given for a mass is read with the scene's --g (docs/units.md), so
`spin-down --shape disc --mass 490N --radius 1m --g 9.80m/s^2` is a 50 kg disc; today's code
refused it ("--g is used only for the weight on a --face"), and inertia and torque took no --g."""

from __future__ import annotations

import pytest

import taucli
from conftest import assert_usage_error, run_taucli

DISC = 0.5 * (490 / 9.80) * 1.0**2  # ½MR², M = W/g


@pytest.mark.parametrize("scene,args", [
    ("spin-down", ("--shape", "disc", "--mass", "490N", "--radius", "1m", "--omega0", "1rad/s", "--friction", "1N*m")),
    ("impulse", ("--shape", "disc", "--mass", "490N", "--radius", "1m", "--torque", "1N*m", "--duration", "1s")),
    ("inertia", ("disc", "--mass", "490N", "--radius", "1m")),
])  # fmt: skip
def test_a_weight_for_a_mass_is_read_with_the_scenes_g(scene, args):
    key = "I" if scene != "impulse" else "inertia"
    done = run_taucli(scene, *args, "--g", "9.80m/s^2", "--get", key)
    assert done.code == 0, done.err
    assert float(done.out) == pytest.approx(DISC, rel=1e-14)


def test_the_python_api_and_a_batch_line_read_it_the_same_way():
    assert taucli.inertia("disc", mass="490 N", radius=1, g="9.80 m/s^2").results["I"].value == pytest.approx(DISC, rel=1e-14)
    line = '{"r": "1,0,0 m", "mass": "19.6N", "velocity": "0,1,0 m/s", "g": "9.8 m/s^2"}'
    done = run_taucli("torque", "--batch", stdin=line)
    assert done.code == 0, done.out
    assert done.json()["results"]["L"]["value"] == pytest.approx(2.0, rel=1e-15)  # 19.6 N / 9.8 m/s² = 2 kg at 1 m, 1 m/s
    assert run_taucli("torque", "--r", "1,0,0 m", "--mass", "19.6N", "--velocity", "0,1,0 m/s", "--g", "9.8", "--get", "L").out.strip() == "2"


@pytest.mark.parametrize("scene,args", [
    ("spin-down", ("--inertia", "1", "--omega0", "1rad/s", "--friction", "1")),
    ("impulse", ("--inertia", "1", "--torque", "1", "--duration", "1s")),
    ("inertia", ("disc", "--mass", "50kg", "--radius", "1m")),
    ("torque", ("--r", "1,0,0 m", "--force", "0,1,0 N")),
])  # fmt: skip
def test_a_g_that_nothing_uses_is_refused(scene, args):
    assert_usage_error(run_taucli(scene, *args, "--g", "9.8"), "--g is used only")
