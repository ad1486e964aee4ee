"""#46 item 1: a yo-yo pulled or held by a second force besides the string it unwinds from, and
--time for a yo-yo (AP Physics C 2013, Mech. 3: a disc, M = 2.0 kg, R = 0.10 m, hung in a rope
fixed to the ceiling that runs under it and up to a hand; F = 9.8 N holds it, F = 12 N lifts it at
1.47 m/s², and after 3 s it turns at 44 rad/s).

The reference is written from energy, not from the solver's forces: with the drop x as the one
coordinate, KE = ½ (m + I/r²) ẋ² and the forces' work per metre of drop is m g − F (1 + d/r) (the
pulled point rises 1 + d/r times as far as the centre drops: the body turns about the point where
the fixed string leaves it), so (m + I/r²) a = m g − F (1 + d/r); the string's tension follows from
the centre's motion, T = m (g − a) − F.
"""

from __future__ import annotations

import random

import mpmath
import pytest

import taucli
from conftest import assert_usage_error, run_taucli

MP_DPS = 40


def reference(m, I, r, F, d, g, v0=0.0, t=None):
    """a (down), T, a_hand (up), and after t: v, ω, x, the pull's work, from the energy method in mpmath."""
    m, I, r, F, d, g, v0 = (mpmath.mpf(x) for x in (m, I, r, F, d, g, v0))
    force = m * g - F * (r + d) / r  # the generalised force along the drop
    a = force / (m + I / r**2)
    out = {"a": a, "T": m * (g - a) - F, "a_hand": -a * (r + d) / r, "alpha": a / r}
    if t is not None:
        t = mpmath.mpf(t)
        x = v0 * t + a * t * t / 2
        out.update(v=v0 + a * t, omega=(v0 + a * t) / r, drop=x, work_pull=-F * x * (r + d) / r)
    return out


def close(got, want, rel=1e-13, scale=0.0):
    return abs(got - float(want)) <= rel * max(abs(got), abs(float(want)), scale)


def test_ap_physics_c_2013_mech_3_by_command_line():
    """F = 9.8 N holds the disc (a = 0); F = 12 N: a = 1.47 m/s² up and ω = 44 rad/s after 3 s. Before
    #46 the yo-yo refused --pull (and had no --time, --pull-at)."""
    held = run_taucli("rolling", "disc", "--yoyo", "--mass", "2.0kg", "--radius", "0.10m", "--pull-at", "0.10m", "--g", "9.8",
                      "--find", "pull", "--want", "a=0", "--get", "pull")
    assert held.code == 0, held.err
    assert float(held.out) == pytest.approx(9.8, rel=1e-9)
    done = run_taucli("rolling", "disc", "--yoyo", "--mass", "2.0kg", "--radius", "0.10m", "--pull", "12N", "--pull-at", "0.10m",
                      "--time", "3s", "--g", "9.8", "--json")
    assert done.code == 0, done.err
    res = done.json()["results"]
    want = reference(2.0, 0.5 * 2.0 * 0.01, 0.1, 12.0, 0.1, 9.8, t=3.0)
    for key in ("a", "T", "a_hand", "alpha", "v", "omega", "drop", "work_pull"):
        assert close(res[key]["value"], want[key], 1e-12), (key, res[key], want[key])
    assert round(-res["a"]["value"], 2) == 1.47 and round(-res["omega"]["value"]) == 44


def test_batch_and_python_are_the_command_line():
    keys = {"shape": "disc", "yoyo": True, "mass": "2kg", "radius": "10cm", "pull": "12N", "pull_at": "10cm", "time": "3s", "g": "9.8 m/s^2"}
    line = run_taucli("rolling", "--batch", stdin=__import__("json").dumps(keys) + "\n")
    assert line.code == 0, line.err
    batch = __import__("json").loads(line.out)["results"]
    api = taucli.rolling(**keys).results
    for key in ("a", "omega", "drop", "work_pull", "T"):
        assert batch[key]["value"] == pytest.approx(api[key].value, rel=1e-15)


@pytest.mark.parametrize("seed", range(40))
def test_against_the_energy_reference(seed):
    """Random bodies, axles, pulls on either side of the centre, thrown up or down, after a time."""
    rng = random.Random(seed)
    m, R = 10 ** rng.uniform(-1, 1), 10 ** rng.uniform(-2, 0)
    k2 = rng.uniform(0.1, 1.0)
    r = R * rng.uniform(0.1, 1.0)
    d = R * rng.uniform(-1.0, 1.0)
    F = m * 9.8 * rng.uniform(0.01, 0.9)
    v0, t = rng.uniform(-2, 2), 10 ** rng.uniform(-1, 1)
    want = reference(m, k2 * m * R * R, r, F, d, 9.8, v0, t)
    if want["T"] < 0:  # a slack string: refused (test_refusals)
        return
    report = taucli.rolling(k2=k2, yoyo=True, mass=m, radius=R, axle_radius=r, pull=F, pull_at=d, time=t, v0=v0, g=9.8)
    res = {key: value.value for key, value in report.results.items()}
    scale = {"T": m * 9.8 + abs(F), "a": 9.8 + abs(F) / m, "a_hand": 9.8 + abs(F) / m, "alpha": (9.8 + abs(F) / m) / r}
    for key in ("a", "T", "a_hand", "alpha"):
        assert close(res[key], want[key], 1e-13, scale[key]), (key, res[key], want[key])
    for key, size in (("v", abs(v0) + abs(float(want["a"])) * t), ("omega", (abs(v0) + abs(float(want["a"])) * t) / r)):
        assert close(res[key], want[key], 1e-13, size), (key, res[key], want[key])


def test_the_same_in_other_units():
    """Unit invariance: the AP disc in grams, centimetres, kilonewtons and milliseconds."""
    si = taucli.rolling("disc", yoyo=True, mass=2.0, radius=0.1, pull=12.0, pull_at=0.1, time=3.0, g=9.8).results
    other = taucli.rolling("disc", yoyo=True, mass="2000 g", radius="10 cm", pull="0.012 kN", pull_at="100 mm", time="3000 ms", g="980 cm/s^2").results
    for key in si:
        if si[key].value is not None:
            assert other[key].value == pytest.approx(si[key].value, rel=1e-13), key


def test_a_pull_through_the_centre_and_one_on_the_strings_side():
    """d = 0: a = (g − F/m)/(1 + q); d = −r (a second string wound beside the first): the pull only
    relieves the fixed string, and a is the free yo-yo's."""
    free = taucli.rolling("disc", yoyo=True, mass=1.0, radius=0.1, g=9.8).results["a"].value
    beside = taucli.rolling("disc", yoyo=True, mass=1.0, radius=0.1, pull=2.0, pull_at=-0.1, g=9.8).results
    assert beside["a"].value == pytest.approx(free, rel=1e-15) and beside["T"].value == pytest.approx(1.0 * 9.8 / 3 - 2.0)
    centre = taucli.rolling("disc", yoyo=True, mass=1.0, radius=0.1, pull=2.0, g=9.8)
    assert centre.results["a"].value == pytest.approx((9.8 - 2.0) / 1.5) and any("no pull_at" in note for note in centre.notes)


@pytest.mark.parametrize("args, fragments", [
    (("--pull", "30N", "--pull-at", "-0.1m"), ("--pull", "slack")),
    (("--pull-at", "0.1m"), ("--pull-at", "needs --pull")),
    (("--pull", "5N", "--pull-height", "0.1m"), ("--pull-height", "does not apply with --yoyo")),
    (("--pull", "5N", "--time", "1s", "--height", "1m"), ("--time", "conflicts with --height")),
    (("--pull", "12N", "--pull-at", "0.1m", "--height", "1m", "--g", "9.8"), ("--height", "never reached")),
    (("--pull", "30N"), ("--pull", "slack")),
    (("--time", "-1s"), ("--time",)),
    (("--time", "nan s"), ("--time",)),
])
def test_refusals(args, fragments):
    assert_usage_error(run_taucli("rolling", "disc", "--yoyo", "--mass", "2kg", "--radius", "0.1m", *args), *fragments)


def test_refusals_outside_a_yoyo():
    assert_usage_error(run_taucli("rolling", "disc", "--angle", "10deg", "--length", "1m", "--time", "1s"), "--time", "applies with --yoyo")
    assert_usage_error(run_taucli("rolling", "disc", "--pull", "5N", "--pull-at", "1cm"), "--pull-at", "applies with --yoyo")
    assert_usage_error(run_taucli("rolling", "disc", "--yoyo", "--pull", "5N", "--radius", "0.1m"), "--mass", "required with --pull")
