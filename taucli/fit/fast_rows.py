"""Rows of plain numbers read a batch at a time (#45 item 3: a million rows in about a second).

taucli.fit.data reads a table row by row through csv and checks each cell (a number, a blank, a
decimal comma, a number past a double). Most tables are rows of plain numbers and nothing else:
for those the rows are taken BATCH at a time, the whole batch checked at once on its bytes
(no character but those of numbers, NaN, spaces and the delimiter; every row the header's count
of cells) and its numbers converted at once by numpy (float: a number as data._NUMBER reads it). The first batch that holds
anything else (a blank cell, a comma in a cell, a comment, a quote, a number past a double, a
blank line) and every row after it are read row by row as before, with their lines, so that each
refusal and note is the one it was.
"""

from __future__ import annotations

import functools
import itertools

import numpy as np

BATCH = 8192


@functools.lru_cache(maxsize=4)
def _allowed(delimiter: str) -> np.ndarray:
    """Which bytes a batch of plain numbers may hold: digits, e E + - . n N a A (NaN), spaces, tabs,
    line ends and the delimiter."""
    allowed = np.zeros(256, dtype=bool)
    allowed[list(b"0123456789eE+-.nNaA \t\n")] = True
    allowed[ord(delimiter)] = True
    return allowed


def _plain(text: str, delimiter: str, rows: int, count: int) -> bool:
    """Whether ``text`` (``rows`` lines joined by \\n) holds only the characters of plain numbers and
    ``count`` cells on every line: the delimiters before the k-th line end are k·(count − 1)."""
    if not text.isascii():
        return False
    raw = np.frombuffer(text.encode("ascii"), dtype=np.uint8)
    if not _allowed(delimiter)[raw].all():
        return False
    separators = np.flatnonzero(raw == ord(delimiter))
    if len(separators) != rows * (count - 1):
        return False
    ends = np.flatnonzero(raw == 10)
    return bool(np.array_equal(np.searchsorted(separators, ends), (count - 1) * np.arange(1, rows)))


def _batch(block: list[str], delimiter: str, count: int):
    """The batch's numbers, rows × cells (None: not rows of plain numbers alone). float reads what
    data._NUMBER reads among these characters, and a NaN with a sign besides (refused row by row)."""
    text = "\n".join(block)
    if not _plain(text, delimiter, len(block), count):
        return None, None
    cells = text.replace("\n", delimiter).split(delimiter)
    try:
        numbers = np.array(cells, dtype=float).reshape(len(block), count)
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


def _batches(numbered):
    """(the number of the first line, at least BATCH lines) of what is left of ``numbered``
    (data._Numbered), its blocks joined; the last batch may be shorter."""
    first, held = None, []
    for number, block in numbered.blocks():
        first = number if first is None else first
        held.extend(block)  # a copy: the block is the source's own list
        if len(held) >= BATCH:
            yield first, held
            first, held = None, []
    if held:
        yield first, held


def taken(numbered, delimiter: str, values: list, lines, commas, rest_rows, most: int):
    """Appends the leading batches of plain numbers to ``values`` (a Numbers per column) and
    ``lines``, telling ``commas`` of the first number with a point, and yields (line, cells) of
    every row after them from ``rest_rows(pairs, start, count)`` (data._rows), as before."""
    count = len(values)
    rows = 0
    for first, block in _batches(numbered):
        numbers, cells = _batch(block, delimiter, count) if rows + len(block) <= most else (None, None)
        if numbers is None:
            pairs = [(first + i, line) for i, line in enumerate(block)]
            yield from rest_rows(itertools.chain(pairs, numbered), first - 1, rows)
            return
        if commas.with_point is None:
            point = next((i for i, cell in enumerate(cells) if "." in cell), None)
            if point is not None:
                commas.with_point = (first + point // count, cells[point].strip())
        for column, found in zip(values, numbers.T):
            column.frombytes(np.ascontiguousarray(found).tobytes())
        lines.frombytes(np.arange(first, first + len(block), dtype=np.int64).tobytes())
        rows += len(block)
