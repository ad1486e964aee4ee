"""The JSON document of a run (DESIGN.md's): taucli, scene, model, method, inputs, results,
steps, notes, and "uncertainty" beside "value" where a result has one; as a dict (``document``)
and as the strict, compact text a batch writes line after line (``document_text``).
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping

from taucli.core.version import __version__
from taucli.writing.report import Report, Table, Value

# Compact, and strict: NaN or Infinity raise rather than print (finite_only keeps them out).
STRICT_JSON = json.JSONEncoder(ensure_ascii=False, allow_nan=False, separators=(",", ":"))


def _json_value(value: Value) -> dict:
    entry = {"value": value.value, "unit": value.unit}
    if value.label:
        entry["label"] = value.label
    return entry


def _json_table(table: Table) -> list[dict]:
    return [{key: cell for (key, _, _), cell in zip(table.columns, row)} for row in table.rows]


def document(report: Report, *, steps: bool = True) -> dict:
    """The JSON document of DESIGN.md: taucli, scene, model, method, inputs, results, steps, notes.

    Without ``steps`` (--no-steps) the key stays, an empty list, so the shape does not change.
    """
    doc = {
        "taucli": __version__,
        "scene": report.scene,
        "model": report.model,
        "method": report.method,
        "inputs": {name: {"value": v.value, "unit": v.unit} for name, v in report.inputs.items()},
        "results": {name: _json_value(v) for name, v in report.results.items()},
        "steps": document_steps(report.steps) if steps else [],
        "notes": list(report.notes),
    }
    for name, table in report.tables.items():
        if name not in report.results:  # a result that is also a table (fit's correlation): its value in JSON, the table to a person
            doc[name] = _json_table(table)
    if getattr(report, "uncertainties", None) is not None:
        _json_uncertain(doc, report)
    return doc


_ENCODED: dict[object, str] = {}  # a text, or a result's (name, unit, label), -> its JSON, as written before
_ENCODE_TEXT = json.encoder.encode_basestring  # a str's JSON as STRICT_JSON writes it (not ASCII-only)


def _text(text: str | None) -> str:
    found = _ENCODED.get(text)
    if found is None:
        found = "null" if text is None else _ENCODE_TEXT(text)
        if len(_ENCODED) < 4096:  # texts repeat (units, labels, notes); numbers in notes make some new each time
            _ENCODED[text] = found
    return found


def _number(value) -> str:
    """A value's JSON as STRICT_JSON writes it: float repr, null, true/false; NaN and ±inf refused."""
    kind = value.__class__
    if kind is float:
        if value != value or value in (math.inf, -math.inf):
            raise ValueError(f"{value!r} is not a number strict JSON allows")
        return float.__repr__(value)
    if value is None:
        return "null"
    if kind is bool:
        return "true" if value else "false"
    return STRICT_JSON.encode(value)


def _entry(key: tuple[str, str | None, str]) -> tuple[str, str]:
    """The JSON around a value: '"name":{"value":' and ',"unit":…,"label":…}' (after the uncertainty)."""
    name, unit, label = key
    found = (_text(name) + ':{"value":', ',"unit":' + _text(unit) + (',"label":' + _text(label) if label else "") + "}")
    if len(_ENCODED) < 4096:
        _ENCODED[key] = found
    return found


def _values(values: Mapping[str, Value], labelled: bool, spreads: Mapping[str, float]) -> str:
    parts = []
    for name, v in values.items():
        value = v.value
        # a finite float (x − x is 0 only then) written at once: most values of most documents
        number = float.__repr__(value) if value.__class__ is float and value - value == 0.0 else _number(value)
        if spreads and name in spreads:
            number += ',"uncertainty":' + _number(spreads[name])
        key = (name, v.unit, v.label if labelled else "")
        ends = _ENCODED.get(key) or _entry(key)
        parts.append(ends[0] + number + ends[1])
    return "{" + ",".join(parts) + "}"


def document_text(report: Report, *, steps: bool = True, plot: dict | None = None) -> str:
    """``document(report)`` as strict, compact JSON: the text STRICT_JSON.encode gives for it,
    written from the JSON of each unit, label and note as first written (a batch writes the
    same texts on every line; only the numbers change). ``plot`` is added under "plot"."""
    uncertain = getattr(report, "uncertainties", None) is not None
    parts = [
        '{"taucli":', _text(__version__), ',"scene":', _text(report.scene), ',"model":', _text(report.model),
        ',"method":', _text(report.method),
        ',"inputs":', _values(report.inputs, False, report.input_uncertainties if uncertain else {}),
        ',"results":', _values(report.results, True, report.uncertainties if uncertain else {}),
        ',"steps":', STRICT_JSON.encode(document_steps(report.steps)) if steps and report.steps else "[]",
        ',"notes":[', ",".join(map(_text, report.notes)), "]",
    ]  # fmt: skip
    for name, table in report.tables.items():
        if name not in report.results:  # (as in document)
            parts += [",", _text(name), ":", STRICT_JSON.encode(_json_table(table))]
    if uncertain and report.draws:
        parts += [',"monte_carlo":', STRICT_JSON.encode(_monte_carlo(report))]
    if plot is not None:
        parts += [',"plot":', STRICT_JSON.encode(plot)]
    parts.append("}")
    return "".join(parts)


def _json_uncertain(doc: dict, report) -> None:
    """#22: "uncertainty" beside "value" in each result (and input) that has one; --mc's check."""
    for part, spreads in (("results", report.uncertainties), ("inputs", report.input_uncertainties)):
        for name, entry in doc[part].items():
            if name in spreads:
                doc[part][name] = {"value": entry["value"], "uncertainty": spreads[name], **entry}
    if report.draws:
        doc["monte_carlo"] = _monte_carlo(report)


def _monte_carlo(report) -> dict:
    return {"draws": report.draws, "results": {name: {"mean": mean, "uncertainty": spread} for name, (mean, spread) in report.monte_carlo.items()}}


def document_steps(steps) -> list[dict]:
    return [{"title": s.title, "equation": s.equation, "numbers": s.numbers, "result": s.result, "why": s.why} for s in steps]
