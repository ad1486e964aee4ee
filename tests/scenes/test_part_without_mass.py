"""A part given by its inertia alone has no mass (#48 item 2): a body's total mass and k are then
unknown (null, with a note), never the other parts' mass; a scene that needs every mass (a
pendulum's gravity) refuses, naming mass=; no scene crashes. Over every scene that takes --part."""

from __future__ import annotations

import math

import pytest

import taucli
from conftest import example_keys
from taucli.options import SCENES

WITH_PARTS = [command for command in SCENES.values() if command.option("part") is not None]


def test_the_issue_s_wheel():
    """A 0.200 kg bead 0.60 m out and a part of I = 0.180 kg·m²: I = 0.252; M and k unknown."""
    report = taucli.inertia("point", mass="0.200kg", radius="0.60m", part=["inertia=0.180kg*m^2"])
    assert report.results["I"].value == pytest.approx(0.2 * 0.36 + 0.18, rel=1e-15)
    assert report.results["mass"].value is None and report.results["k"].value is None
    assert any("mass=" in note for note in report.notes), report.notes
    known = taucli.inertia("point", mass="0.200kg", radius="0.60m", part=["inertia=0.180kg*m^2 mass=1kg"])
    assert known.results["k"].value == pytest.approx(math.sqrt(0.252 / 1.2), rel=1e-15)


@pytest.mark.parametrize("command", WITH_PARTS, ids=[c.name for c in WITH_PARTS])
def test_a_part_of_inertia_alone_in_every_scene(command):
    """The scene's example with such a part: an answer whose mass and k (where it has them) are
    null, or a refusal (InputError: a pendulum's "mass= is needed"), never a crash."""
    given = example_keys(command)
    function = getattr(taucli, command.function_name)
    try:
        without = function(**given, part=["inertia=0.1kg*m^2"])
    except taucli.InputError:
        return
    for name in ("mass", "k"):
        if name in without.results:
            assert without.results[name].value is None, (name, without.results[name])
