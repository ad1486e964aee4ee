"""--to NAME=UNIT on every result of every scene that has a unit (#16 item 1): each converts by
the factor between the units, written here from their definitions, and none fails."""

from __future__ import annotations

import math

import pytest

from conftest import run_taucli
from taucli.options import SCENES
from test_table import WORKING

# An SI unit (as results give it) -> another unit of its kind and how many of it make one SI unit.
OTHER = {
    "kg*m**2": ("g*cm^2", 1e7),
    "m": ("cm", 100.0),
    "kg": ("g", 1e3),
    "s": ("ms", 1e3),
    "rad": ("deg", 180 / math.pi),
    "rev": ("rad", 2 * math.pi),
    "rad/s": ("rpm", 60 / (2 * math.pi)),
    "rad/s**2": ("deg/s^2", 180 / math.pi),
    "m/s": ("km/h", 3.6),
    "m/s**2": ("cm/s^2", 100.0),
    "N": ("kN", 1e-3),
    "N*m": ("mN*m", 1e3),
    "N*m*s": ("mN*m*s", 1e3),
    "J": ("kJ", 1e-3),
    "kg*m**2/s": ("g*cm^2/s", 1e7),
    "W": ("kW", 1e-3),
    "Pa": ("kPa", 1e-3),
    "m**2": ("cm^2", 1e4),
    "kg*m/s": ("g*cm/s", 1e5),  # #34: an impulse's linear momentum
    "N*s": ("mN*s", 1e3),  # #34: the pivot's impulse
    "kg*m": ("g*cm", 1e5),  # #47: an unbalance m·r
    "K": ("mK", 1e3),  # #47: a brake's temperature rise (a difference of temperatures)
}


@pytest.mark.parametrize("name", list(WORKING))
def test_every_result_with_a_unit_converts(name):
    document = run_taucli(name, *WORKING[name], "--json").json()
    for key, result in document["results"].items():
        if not result["unit"] or not isinstance(result["value"], float):
            continue
        unit, factor = OTHER[result["unit"]]
        done = run_taucli(name, *WORKING[name], "--to", f"{key}={unit}", "--get", key)
        assert done.code == 0, (key, done.err)
        assert float(done.out) == pytest.approx(result["value"] * factor, rel=1e-12), key
        same = run_taucli(name, *WORKING[name], "--to", f"{key}={result['unit']}", "--get", key)
        assert float(same.out) == pytest.approx(result["value"], rel=1e-14), key  # --get prints 15 significant digits (#36)


def test_every_result_unit_is_one_this_test_knows():
    units = {result.unit for command in SCENES.values() for result in command.results if result.unit}
    assert units <= set(OTHER), units - set(OTHER)
