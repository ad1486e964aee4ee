"""#21 through the real entry point: the pull, the spool, the yo-yo, the stepped pulley and the
string that slides; their usage errors are one line naming the flag."""

from __future__ import annotations

import json

import pytest

from conftest import assert_usage_error, run_taucli, with_notes_as_keys

G = 9.80665


def test_a_spool_in_json_and_in_other_units(taucli):
    doc = taucli("rolling", "disc", "--pull", "5N", "--axle-radius", "3cm", "--radius", "6cm", "--mass", "1kg", "--mu-s", "2",
                 "--to", "critical_angle=deg", "--json").json()
    assert doc["results"]["critical_angle"] == {"value": pytest.approx(60.0), "unit": "deg", "label": "pull angle at which the spool stays put"}
    assert doc["results"]["a"]["value"] == pytest.approx(5.0 * 0.5 / 1.5)
    inches = float(taucli("rolling", "disc", "--pull", "5N", "--axle-radius", "3cm", "--radius", "6cm", "--mass", "1kg",
                          "--to", "a=in/s^2", "--get", "a").out)
    assert inches * 0.0254 == pytest.approx(5.0 * 0.5 / 1.5)


def test_a_yoyo_by_batch_is_the_single_run():
    single = run_taucli("rolling", "disc", "--yoyo", "--mass", "0.1kg", "--radius", "3cm", "--axle-radius", "5mm", "--height", "1m", "--json").json()
    line = json.dumps({"shape": "disc", "yoyo": True, "mass": "0.1kg", "radius": "3cm", "axle_radius": "5mm", "height": "1m"})
    batch = json.loads(run_taucli("rolling", "--batch", stdin=line + "\n").out)
    assert batch == with_notes_as_keys(single)  # a key in batch, a flag on the command line (#42 item 19)
    assert single["results"]["a"]["value"] == pytest.approx(G / (1 + 0.5 * 36))


def test_a_stepped_pulley_and_a_sliding_string_with_steps(taucli):
    out = taucli("atwood", "--m1", "0.5kg", "--m2", "1kg", "--pulley-inertia", "0.04kg*m^2", "--radius1", "0.2m", "--radius2", "0.05m", "--g", "9.8").out
    assert "α = (m₁g r₁ − m₂g r₂) / (I + m₁r₁² + m₂r₂²)" in out and "= 7.84 rad/s²" in out
    out = taucli("atwood", "--m1", "4kg", "--m2", "1kg", "--pulley-mass", "2kg", "--rim-mu", "0.05", "--g", "9.8").out
    assert "T₁ = e^(μβ) T₂" in out and "slides" in out and "--rim-mu" in out


@pytest.mark.parametrize(
    "scene,args,fragments",
    [
        ("rolling", ("disc", "--pull", "100N", "--pull-angle", "70deg", "--mass", "1kg"), ("--pull", "lifts the body off")),
        ("rolling", ("disc", "--pull-height", "1cm"), ("--pull-height", "needs --pull")),
        ("rolling", ("disc", "--pull", "1N", "--mass", "1kg", "--axle-radius", "7cm", "--radius", "5cm"), ("--axle-radius", "within")),
        ("rolling", ("disc", "--yoyo", "--angle", "30deg"), ("--angle", "--yoyo")),
        ("rolling", ("disc", "--pull", "1N", "--pull-angle", "120deg", "--mass", "1kg"), ("--pull-angle", "−90 to 90")),
        ("atwood", ("--m1", "1kg", "--m2", "1kg", "--radius1", "5cm"), ("--radius2 is required",)),
        ("atwood", ("--m1", "1kg", "--m2", "1kg", "--wrap", "90deg"), ("--wrap needs --rim-mu",)),
        ("atwood", ("--m1", "1kg", "--rim-mu", "0.2"), ("--m2", "more than 0")),
    ],
)
def test_usage_errors(taucli, scene, args, fragments):
    assert_usage_error(taucli(scene, *args), *fragments)
