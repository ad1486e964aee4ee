"""taucli convert on the command line: a line for a person, --json, --get, and one-line refusals."""

from __future__ import annotations

import json
import math

from conftest import assert_usage_error, run_taucli


def test_a_person_reads_the_value_its_unit_and_its_kind():
    run = run_taucli("convert", "3000 rpm", "rad/s")
    assert run.code == 0 and run.out == "3000 rpm = 314.159 rad/s  (angular velocity)\n", run


def test_notes_come_with_the_line():
    run = run_taucli("convert", "2 lb*ft^2")
    assert run.code == 0 and run.out.startswith("2 lb*ft^2 = 0.0842802 kg·m²  (moment of inertia)\nnote: "), run


def test_json_is_strict_and_carries_si_and_notes():
    run = run_taucli("convert", "4.0+/-0.1 kg", "lb", "--json")
    doc = json.loads(run.out)
    assert run.code == 0 and doc["kind"] == "mass" and doc["si"] == {"value": 4.0, "unit": "kg", "uncertainty": 0.1}
    assert math.isclose(doc["value"], 4 / 0.45359237, rel_tol=1e-14) and doc["unit"] == "lb" and doc["notes"] == []


def test_get_prints_bare_numbers_and_notes_go_to_stderr():
    run = run_taucli("convert", "1 hp", "W", "--get", "value", "--get", "si_unit")
    assert run.code == 0 and run.out == "745.69987158227 W\n" and "mechanical horsepower" in run.err, run


def test_a_negative_quantity_goes_after_double_dash():
    assert run_taucli("convert", "--get", "value", "--", "-40 N*m", "lbf*ft").out.startswith("-29.50")
    assert_usage_error(run_taucli("convert", "-40 N*m", "lbf*ft"), "goes after --", "taucli convert -- '-40 N*m' 'lbf*ft'")


def test_refusals_are_one_line_naming_the_argument():
    assert_usage_error(run_taucli("convert"), "QUANTITY is required")
    assert_usage_error(run_taucli("convert", "5"), "QUANTITY: ", "no unit")
    assert_usage_error(run_taucli("convert", "3000 rpm", "kg"), "UNIT: expected a unit of an angular velocity")
    assert_usage_error(run_taucli("convert", "3 kg", "--get", "valu"), "--get: expected one of value")
    assert_usage_error(run_taucli("convert", "3 kg", "--get", "value", "--json"), "--get does not combine with --json")
