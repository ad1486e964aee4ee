"""The layering rules: solvers are pure, --help builds no unit registry."""

from __future__ import annotations

import subprocess
import sys

import pytest

from taucli.writing.report import Report, Value, fmt, pretty_unit
from taucli.writing.document import document
from taucli.writing.render import finite_only

HEAVY = ("typer", "rich", "pint")


def _modules_after(code: str) -> set[str]:
    done = subprocess.run(
        [sys.executable, "-c", code + "\nimport sys\nprint(' '.join(sys.modules))"], capture_output=True, text=True, check=True
    )
    return set(done.stdout.split()[-1:] and done.stdout.splitlines()[-1].split())


def test_solvers_import_no_typer_rich_or_pint():
    loaded = _modules_after("import taucli.scenes.inertia")
    assert not {name for name in loaded if name.split(".")[0] in HEAVY}


@pytest.mark.parametrize(
    "x,text",
    [(0.1, "0.1"), (7.639437268, "7.63944"), (24.0, "24"), (19.6, "19.6"), (10000.0, "10000"), (1.5e-5, "1.5e-5"), (-3.0, "-3"), (0.0, "0"), (2.5e9, "2.5e9"), (9.9999996, "10")],
)
def test_numbers_read_as_in_a_worked_solution(x, text):
    assert fmt(x) == text


def test_units_read_as_a_person_writes_them():
    assert pretty_unit("kg*m**2") == "kg·m²"
    assert pretty_unit("rad/s**2") == "rad/s²"
    assert pretty_unit("N*m*s") == "N·m·s"
    assert pretty_unit(None) == ""


def test_a_result_that_does_not_exist_is_null_with_a_note():
    report = Report("spin-down", "m", "closed form", {"t_stop": Value(float("inf"), "s", "time to stop")})
    cleaned = finite_only(report)
    assert cleaned.results["t_stop"].value is None
    assert any("t_stop" in note for note in cleaned.notes)
    assert document(cleaned)["results"]["t_stop"]["value"] is None


def test_the_names_offered_match_the_tables_they_stand_for():
    from taucli.front import bench
    from taucli.core import names
    from taucli.numerics import steppers as numerics
    from taucli.numerics import quadrature
    from taucli.scenes.atwood import Pulley
    from taucli.scenes.inertia import SHAPES
    from taucli.scenes.rolling import K2

    assert names.SHAPE_AXES == {name: tuple(axis.name for axis in shape.axes) for name, shape in SHAPES.items()}
    assert names.ROLLING_BODIES == tuple(K2)
    assert names.METHOD_NAMES == ("auto", "exact", *numerics.METHODS)
    assert names.QUADRATURE_NAMES == ("auto", *quadrature.StreamingQuadrature.RULES)
    assert names.PULLEY_SHAPES == tuple(Pulley.SHAPE_FACTORS)
    assert names.BENCH_SCENES == tuple(bench.SCENES)
