"""Rows of plain numbers read a batch at a time (#45 item 3: a million rows in about a second).

taucli.fit.data reads a table row by row through csv and checks each cell (a number, a blank, a
decimal comma, a number past a double). Most tables are rows of plain numbers and nothing else:
for those the rows are taken BATCH at a time, the whole batch checked by two regular expressions
(no character but those of numbers, NaN, spaces and the delimiter; every row the header's count
of cells) and its numbers converted at once by numpy (float: a number as data._NUMBER reads it). The first batch that holds
anything else (a blank cell, a comma in a cell, a comment, a quote, a number past a double, a
blank line) and every row after it are read row by row as before, with their lines, so that each
refusal and note is the one it was.
"""

from __future__ import annotations

import itertools
import re

import numpy as np

BATCH = 8192


def _patterns(delimiter: str, count: int) -> tuple[re.Pattern, re.Pattern]:
    """(any character no cell of plain numbers holds; rows of ``count`` cells each)."""
    d = re.escape(delimiter)
    cell = f"[^{d}\n]*"
    row = cell + f"(?:{d}{cell}){{{count - 1}}}"
    return re.compile(f"[^0-9eE+\\-.nNaA \t\n{d}]"), re.compile(f"(?:{row}\n)*{row}")


def _batch(pairs, delimiter: str, count: int, patterns: tuple[re.Pattern, re.Pattern]):
    """The batch's numbers, rows × cells (None: not rows of plain numbers alone). float reads what
    data._NUMBER reads among these characters, and a NaN with a sign besides (refused row by row)."""
    text = "\n".join(line for _, line in pairs)
    other, rows = patterns
    if other.search(text) or not rows.fullmatch(text):
        return None, None
    cells = text.replace("\n", delimiter).split(delimiter)
    try:
        numbers = np.array(cells, dtype=float).reshape(len(pairs), count)
    except ValueError:  # a blank cell, "1e", "+-1": refused, or read as no measurement, row by row
        return None, None
    if not np.all(np.isfinite(numbers) | np.isnan(numbers)):
        return None, None  # past a double (1e400): refused row by row
    for i in np.flatnonzero(np.isnan(numbers.ravel())):
        if cells[i].strip().lower() != "nan":
            return None, None
    for i in np.flatnonzero(numbers.ravel() == 0):  # 1e-400: not 0, whatever a double rounds it to (refused row by row)
        if any(digit in "123456789" for digit in cells[i].lower().partition("e")[0]):
            return None, None
    return numbers, cells


def taken(numbered, delimiter: str, values: list, lines, commas, rest_rows, most: int):
    """Appends the leading batches of plain numbers to ``values`` (a Numbers per column) and
    ``lines``, telling ``commas`` of the first number with a point, and yields (line, cells) of
    every row after them from ``rest_rows(pairs, start, count)`` (data._rows), as before."""
    count = len(values)
    patterns = _patterns(delimiter, count)
    rows = 0
    while True:
        pairs = list(itertools.islice(numbered, BATCH))
        if not pairs:
            return
        numbers, cells = _batch(pairs, delimiter, count, patterns) if rows + len(pairs) <= most else (None, None)
        if numbers is None:
            yield from rest_rows(itertools.chain(pairs, numbered), pairs[0][0] - 1, rows)
            return
        if commas.with_point is None:
            point = next((i for i, cell in enumerate(cells) if "." in cell), None)
            if point is not None:
                commas.with_point = (pairs[point // count][0], cells[point].strip())
        for column, found in zip(values, numbers.T):
            column.frombytes(np.ascontiguousarray(found).tobytes())
        lines.frombytes(np.array([number for number, _ in pairs], dtype=np.int64).tobytes())
        rows += len(pairs)
