"""The batches of plain numbers (taucli.fit.fast_rows) read a table exactly as the row-by-row
reader does (#45 item 3): the same numbers, the same lines, the same refusal naming the same line,
on random tables with a defect somewhere in them (rows with a cell too many and one too few whose
delimiters add up, a blank line, \\r\\n and \\r line ends, a blank cell, NaN, text, a number past a
double or too small for one, a line longer than a table's). Held against the row-by-row reader,
which is the reader the refusals were written for, with the batches switched off."""

from __future__ import annotations

import io
import random

import pytest

from taucli.core.errors import InputError
from taucli.fit import data, fast_rows


def _read(text: str, monkeypatch=None, batches: bool = True):
    if not batches:
        monkeypatch.setattr(fast_rows, "_batch", lambda *args: (None, None))
    try:
        table = data.read(io.BytesIO(text.encode()))
    except InputError as err:
        return ("refused", str(err))
    finally:
        if not batches:
            monkeypatch.undo()
    return ([[repr(value) for value in column.values] for column in table.columns], list(table.lines), table.decimal_comma)  # repr: NaN equals NaN


DEFECTS = (
    None,
    "cells add up",  # a row with a cell too many, another with one too few: the delimiters' count is right
    "blank line", "crlf", "cr", "blank cell", "nan", "text", "past a double", "too small", "comment", "long line", "decimal comma",
)


def _table(rng: random.Random, defect: str | None) -> str:
    rows = rng.randint(1, 3 * fast_rows.BATCH)
    delimiter = rng.choice([",", ";", "\t"]) if defect != "decimal comma" else ";"
    lines = ["t (s)" + delimiter + "omega (rad/s)" + delimiter + "x"]
    for i in range(rows):
        lines.append(delimiter.join(repr(round(rng.uniform(-100, 100), rng.randint(0, 9))) for _ in range(3)))
    at = rng.randint(1, rows)
    if defect == "cells add up" and rows >= 2:
        other = rng.randint(1, rows)
        if other != at:
            lines[at] += delimiter + "1.5"
            lines[other] = delimiter.join(lines[other].split(delimiter)[:2])
    elif defect == "blank line":
        lines.insert(at, "")
    elif defect == "blank cell":
        lines[at] = delimiter + lines[at].split(delimiter, 1)[1]
    elif defect == "nan":
        lines[at] = "NaN" + delimiter + lines[at].split(delimiter, 1)[1]
    elif defect == "text":
        lines[at] = "abc" + delimiter + lines[at].split(delimiter, 1)[1]
    elif defect == "past a double":
        lines[at] = "1e400" + delimiter + lines[at].split(delimiter, 1)[1]
    elif defect == "too small":
        lines[at] = "1e-400" + delimiter + lines[at].split(delimiter, 1)[1]
    elif defect == "comment":
        lines.insert(at, "# a note")
    elif defect == "long line":
        lines.insert(at, "1" * (1024 * 1024 + 1))
    elif defect == "decimal comma":
        lines[at] = lines[at].replace(".", ",")
    ending = {"crlf": "\r\n", "cr": "\r"}.get(defect, "\n")
    return ending.join(lines) + (ending if rng.random() < 0.5 else "")


@pytest.mark.parametrize("defect", DEFECTS)
def test_batches_read_as_rows_do(defect, monkeypatch):
    rng = random.Random(f"batch reader {defect}")
    for _ in range(3 if defect != "long line" else 1):
        text = _table(rng, defect)
        batched = _read(text)
        assert batched == _read(text, monkeypatch, batches=False)
        if defect is None:
            assert batched[0] != "refused" and len(batched[1]) == len(text.splitlines()) - 1  # every row read


def test_a_refusal_in_a_later_batch_names_its_line():
    rows = ["t (s),omega (rad/s)"] + [f"{i},{i / 2}" for i in range(3 * fast_rows.BATCH)]
    rows[2 * fast_rows.BATCH + 7] = "1,2,3"
    with pytest.raises(InputError, match=f"line {2 * fast_rows.BATCH + 8}: expected 2 cells"):
        data.read(io.BytesIO("\n".join(rows).encode()))
