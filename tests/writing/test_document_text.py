"""The JSON writer (document.document_text) writes exactly what the encoder makes of document.document.

The writer builds each document from the JSON of its units, labels and notes as first written
(a batch writes the same texts on every line); the dict form is the reference it must match,
byte for byte, in every scene, with steps, tables, uncertainties, a plot, and odd values.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

import taucli
from taucli.options import COMMANDS
from taucli.answering.pipeline import solve
from taucli.writing.report import Report, Table, Value
from taucli.writing.document import STRICT_JSON, document, document_text

from test_table import WORKING


def _reference(report, steps=True):
    return STRICT_JSON.encode(document(report, steps=steps))


@pytest.mark.parametrize("name", list(WORKING))
@pytest.mark.parametrize("steps", [True, False])
def test_every_scene_writes_the_documents_text(name, steps):
    command = COMMANDS[name]
    argv, given, positional = list(WORKING[name]), {}, [o for o in command.options if o.positional]
    if positional and not argv[0].startswith("--"):
        given[positional[0].name] = argv.pop(0)
    while argv:
        flag, value = argv.pop(0), argv.pop(0)
        option = next(o for o in command.options if o.flag == flag)
        given[option.name] = [*given.get(option.name, []), value] if option.repeatable else value
    report = solve(command, given)
    assert document_text(report, steps=steps) == _reference(report, steps)


def test_uncertainties_and_the_monte_carlo_check_are_written_as_the_dict_says():
    from taucli.answering.answer import solve as solve_uncertain

    given = {"m1": "4.0+/-0.1 kg", "m2": "1 kg", "pulley_mass": "2kg", "pulley_radius": "0.1m"}
    report = solve_uncertain(COMMANDS["atwood"], given, mc=2000)
    assert report.uncertainties and report.draws
    assert document_text(report) == _reference(report)


def test_a_plot_is_written_under_plot():
    from taucli.writing.plot import plot_document

    report = taucli.spin_down(inertia=0.1, omega0=30, friction=0.3)
    text = document_text(report, plot=plot_document(report))
    doc = document(report)
    doc["plot"] = plot_document(report)
    assert text == STRICT_JSON.encode(doc)


_TEXTS = st.text(st.characters(codec="utf-8"), max_size=12)
_VALUES = st.one_of(st.none(), st.booleans(), st.integers(), st.floats(allow_nan=False, allow_infinity=False), _TEXTS,
                    st.lists(st.floats(allow_nan=False, allow_infinity=False), max_size=3))


@given(
    results=st.dictionaries(_TEXTS, st.tuples(_VALUES, st.one_of(st.none(), _TEXTS), _TEXTS), max_size=4),
    notes=st.lists(_TEXTS, max_size=3),
    model=_TEXTS,
    rows=st.lists(st.tuples(_VALUES, _VALUES), max_size=2),
)
def test_any_report_is_written_as_the_encoder_writes_it(results, notes, model, rows):
    report = Report(
        "atwood", model, "closed form", {key: Value(*value) for key, value in results.items()}, [], notes,
        {key: Value(value[0], value[1], "") for key, value in results.items()},
        {"parts": Table((("a", None, "A"), ("b", "kg", "B")), tuple(rows))},
    )  # fmt: skip
    assert document_text(report) == _reference(report)


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf])
def test_a_number_json_does_not_allow_is_refused_as_the_encoder_refuses_it(bad):
    report = Report("atwood", "m", "closed form", {"a": Value(bad, "m/s**2", "x")})
    with pytest.raises(ValueError):
        document_text(report)
    with pytest.raises(ValueError):
        _reference(report)
