"""Reading a table of measured samples: CSV as phone sensor apps, data loggers and spreadsheets
write it.

- The first line that is neither blank nor a comment (``#``) names the columns; a header may carry
  its unit in parentheses or brackets, ``Time (s)`` or ``t [ms]``.
- Columns are separated by tabs, else semicolons, else commas (the header says which): the
  rules of taucli.answering.csv_text, which a torque profile is read by too.
- A decimal comma is read where the whole file shows that it is one (docs/units.md: a comma that
  could be a thousands separator is refused, never guessed): the columns are separated by
  semicolons or tabs, no number has a decimal point, and some number is no thousands-grouped
  one: other than three digits after its comma, an exponent, or before it 0, nothing, a leading
  0 or more than three digits (``0,000``, ``1234,500``). A file whose every comma could group
  thousands (``1,500`` and ``12,250`` alone) is refused.
- Excel's trailing empty columns (a header ending ``,,`` and cells empty under them) are left
  out; a cell under them that is not empty is refused.
- A row of units under the header (``t;omega`` then ``s;rad/s``, as loggers write them): every
  cell of it that is not empty a unit, none a number; each is the unit of its column, as
  ``t (s)`` would be (a column whose header has a unit of its own and another below is refused).
- An .xlsx workbook and a zip of CSV files (phyphox's export) are read directly
  (taucli.fit.sources): the sheet, or the CSV inside, is the table.
- Every cell of a row is a finite number or empty: a blank or NaN cell (phyphox pads with NaN,
  Vernier and PASCO pad shorter runs with blanks) is read as NaN, no measurement, and the fit
  leaves out the rows where a column it uses has one (samples.py, with a note); infinity or
  text is refused with its line.
- The text is read as csv_text says (UTF-8, Windows-1252, UTF-16 or -32 with a BOM; lines end at
  \\n, \\r\\n or \\r only), streamed: at most MAX_BYTES of any source (a file, a device, a FIFO,
  stdin) and MAX_ROWS rows are read, the rest refused as soon as it passes them.
- A binary file, a file that is not UTF-8 or Windows-1252 text, ragged rows, an empty table and
  a line longer than csv's limit are refused, one line each.

csv, and numpy for the batches of plain numbers (taucli.fit.fast_rows); no pint.
"""

from __future__ import annotations

import csv
import itertools
import math
import os
import re
from array import array
from collections.abc import Sequence
from dataclasses import dataclass

from taucli.answering.csv_text import MAX_BYTES, blocks as text_blocks, delimiter as _delimiter, split_header, too_large
from taucli.core.errors import InputError
from taucli.core.written import printable
from taucli.fit import fast_rows, sources

OPTION = "data"  # the argument the messages name (DATA)
MAX_ROWS = 2_000_000

_NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")
_COMMA_NUMBER = re.compile(r"[+-]?(\d*),(\d+)([eE][+-]?\d+)?")
_UNIT_CELL = re.compile(r"[(\[]?\s*(?:[^\W\d_]|[°%])[^,;\t]{0,23}?\s*[)\]]?")  # a unit under a header: s, rad/s, m/s^2, (°), [ms]
_NOT_FINITE = {"nan", "inf", "-inf", "+inf", "infinity", "-infinity", "+infinity"}


class Numbers(array):
    """A column's numbers (or the rows' lines) as a compact array, 8 bytes each, equal to any
    tuple or list of the same numbers as the tuple it replaces was (``column.values == (1.5, 2.5)``)."""

    def __eq__(self, other):
        if isinstance(other, (tuple, list, array)):
            return len(self) == len(other) and all(a == b for a, b in zip(self, other))
        return NotImplemented

    def __ne__(self, other):
        equal = self.__eq__(other)
        return equal if equal is NotImplemented else not equal

    __hash__ = None


@dataclass(frozen=True)
class Column:
    """One column of a table: its header as written, the name and unit the header gives, and its
    numbers as the file writes them (in the header's unit)."""

    header: str
    name: str
    unit: str  # "" where the header names none
    values: Sequence[float]  # Numbers: 8 bytes a number, not a tuple's 32


@dataclass(frozen=True)
class DataTable:
    source: str  # the file's name, or "stdin"
    columns: tuple[Column, ...]
    lines: Sequence[int]  # the line of the file each row is on (Numbers)
    delimiter: str
    decimal_comma: bool

    def column(self, header: str) -> Column:
        return next(column for column in self.columns if column.header == header)


def read(source, stdin=None) -> DataTable:
    """The table in the file ``source`` (``-``: stdin; an open file object, from Python), or a
    usage error naming what is wrong. The source is read as it streams (csv_text.lines: at most
    MAX_BYTES of it, whatever it is), each row turned into numbers as it comes: what is kept is the
    numbers, 8 bytes each, and the line each row is on."""
    name = _name(source)
    numbered = _Numbered(_lines(source, stdin, name))
    found = next(((number, line) for number, line in numbered if line.strip() and not line.lstrip().startswith("#")), None)
    if found is None:
        raise InputError(OPTION, f"{name} holds no table: expected a header line naming the columns, then a row of numbers per sample",
                         example="t (s),omega (rad/s)")
    start, header_line = found[0] - 1, found[1]
    if header_line.lstrip().startswith("<"):
        raise InputError(OPTION, f"{name} is XML or HTML (a phyphox experiment or state file, a web page), not a table",
                         hint="export the data as CSV (phyphox: the menu's Export Data, then give the zip it writes or the CSV in it)")
    delimiter = _delimiter(header_line)  # the rules a torque profile is read by too
    rows = _rows(itertools.chain([(found[0], header_line)], numbered), start, delimiter, name)
    first = next(rows, None)
    if first is None:
        raise InputError(OPTION, f"{name} holds no table: expected a header line naming the columns, then a row of numbers per sample",
                         example="t (s),omega (rad/s)")
    headers = [cell.strip() for cell in first[1]]
    while len(headers) > 1 and not headers[-1]:  # Excel's trailing empty columns
        headers.pop()
    if any(not header for header in headers):
        raise InputError(OPTION, f"{name} line {first[0]}: expected a name for every column", got=repr(header_line[:80]))
    if len(set(headers)) != len(headers):
        twice = sorted({header for header in headers if headers.count(header) > 1})
        raise InputError(OPTION, f"{name} line {first[0]}: names a column twice: {', '.join(twice)}")
    if all(_NUMBER.fullmatch(header) for header in headers):
        raise InputError(OPTION, f"{name} line {first[0]}: expected a header naming the columns before the numbers", example="t (s),omega (rad/s)")
    headers, rows, pending = _units_row(headers, rows, name)
    values = [Numbers("d") for _ in headers]
    lines = Numbers("q")
    commas = _Commas()

    def add(line: int, cells: list[str]) -> None:
        if len(cells) > len(headers) and not any(cell.strip() for cell in cells[len(headers):]):
            cells = cells[:len(headers)]  # cells under Excel's trailing empty columns
        if len(cells) != len(headers):
            past = len(cells) > len(headers) and len(first[1]) > len(headers)
            raise InputError(OPTION, f"{name} line {line}: expected {len(headers)} cells, as the header names, got {len(cells)}"
                             + (f" (a cell under no column's name: {next(cell for cell in cells[len(headers):] if cell.strip()).strip()[:20]!r})" if past else ""),
                             hint="name every column in the header" if past else None)
        for cell, header, column in zip(cells, headers, values):
            # A comma is read as a decimal comma here; the file's commas, all seen, then say whether it is one or the table is refused.
            column.append(_number(cell, line, header, name, commas.seen(line, cell)))
        lines.append(line)

    before = 1 + (pending is not None) + (pending is None and rows is None)  # the header, and the row under it where it was read
    if pending is not None:
        add(*pending)
    # the rest: plain numbers a batch at a time (fast_rows), anything else row by row as the rows above
    rest = rows if rows is not None else fast_rows.taken(numbered, delimiter, values, lines, commas,
                                                          lambda pairs, at, count: _rows(pairs, at, delimiter, name, count + before), MAX_ROWS)
    for line, cells in rest:
        add(line, cells)
    if not lines:
        raise InputError(OPTION, f"{name} has a header and no rows of numbers")
    decimal_comma = commas.decided(delimiter, name)
    columns = tuple(Column(header, *split_header(header), column) for header, column in zip(headers, values))
    return DataTable(name, columns, lines, delimiter, decimal_comma)


def _units_row(headers: list[str], rows, name: str):
    """(the headers, the rows still to read, the row under the header if it is a row of numbers)
    with a row of units under the header (the module's rule) read into the headers: ``t`` over
    ``s`` is ``t (s)``. The rows still to read are None where they are the source's own lines,
    not yet read (the batches of plain numbers may take them: fast_rows)."""
    second = next(rows, None)
    if second is None:
        return headers, iter(()), None
    line, cells = second
    units = [cell.strip() for cell in cells[:len(headers)]]
    if (len(cells) < len(headers) or any(cell.strip() for cell in cells[len(headers):]) or not any(units)
            or any(unit and (_NUMBER.fullmatch(unit) or unit.lower() in _NOT_FINITE or not _UNIT_CELL.fullmatch(unit)) for unit in units)):
        return headers, None, second
    named = []
    for header, unit in zip(headers, units):
        unit = unit.strip("()[] ")
        own = split_header(header)[1]
        if unit and own and own != unit:
            raise InputError(OPTION, f"{name} line {line}: column {header!r} has the unit {own} in its header and {unit} in the row of units under it",
                             hint="keep one of them")
        named.append(f"{header} ({unit})" if unit and not own else header)
    return named, None, None


def _name(source) -> str:
    """The file's name as messages and steps show it: its control characters escaped (#43)."""
    return printable("stdin" if source == "-" else source if isinstance(source, str) else str(getattr(source, "name", None) or "the file object"))


class _Numbered:
    """(line number, line) of the source, one at a time, from its lines a block at a time; what is
    left of them is also taken a block at a time (``blocks``: the batches of plain numbers)."""

    def __init__(self, blocks) -> None:
        self._blocks = blocks
        self._block: list[str] = []
        self._at = 0  # the next line's index in _block
        self._number = 0  # lines handed out

    def __iter__(self):
        return self

    def __next__(self) -> tuple[int, str]:
        while self._at >= len(self._block):
            self._block, self._at = next(self._blocks), 0
        line = self._block[self._at]
        self._at += 1
        self._number += 1
        return self._number, line

    def blocks(self):
        """(the number of its first line, the lines) of what is left, a block at a time."""
        while True:
            if self._at >= len(self._block):
                block = next(self._blocks, None)
                if block is None:
                    return
                self._block, self._at = block, 0
            taken, first = self._block[self._at:] if self._at else self._block, self._number + 1
            self._at = len(self._block)
            self._number += len(taken)
            yield first, taken


def _in_blocks(lines, size: int = fast_rows.BATCH):
    while block := list(itertools.islice(lines, size)):
        yield block


def _lines(source, stdin, name: str):
    """The lines of the source a block at a time, streamed (csv_text.blocks), a file larger than the cap refused before it is read."""
    if not isinstance(source, str):  # an open file object (the Python API)
        return _guarded(source.read, name, "expected an open file to read a table from")
    if source == "-":
        if stdin is None:
            raise InputError(OPTION, "cannot be - here: no stdin to read it from")
        return _guarded((stdin.buffer if hasattr(stdin, "buffer") else stdin).read, name, "expected a readable stdin")
    if sources.is_zip(source):  # an .xlsx workbook, or phyphox's zip of CSVs
        return _in_blocks(sources.lines(source, name, OPTION, _WHAT))
    try:
        if os.path.getsize(source) > MAX_BYTES:  # a regular file says its size (a device or a FIFO says 0: the stream's cap holds there)
            raise too_large(OPTION, name, _WHAT)
        handle = open(source, "rb")  # noqa: SIM115 (closed when its lines are read: _closing)
    except OSError as err:
        raise InputError(OPTION, "expected a readable data file (or - for stdin)", got=f"{source!r}: {err.strerror or err}") from None
    return _closing(handle, _guarded(handle.read, name, "expected a readable data file (or - for stdin)"))


_WHAT = f"fit reads at most {MAX_ROWS:,} rows"


def _guarded(read, name: str, expected: str):
    """csv_text.blocks over ``read``, an error of the read itself (an I/O error, a closed file) one line."""
    try:
        yield from text_blocks(read, name, OPTION, _WHAT)
    except (OSError, ValueError, TypeError) as err:
        if isinstance(err, InputError):
            raise
        raise InputError(OPTION, expected, got=f"{name}: {err}") from None


def _closing(handle, lines):
    with handle:
        yield from lines


def _rows(numbered, start: int, delimiter: str, name: str, count: int = 0):
    """(line number, cells) of the header and each row after it, blank lines and comments left
    out, streamed; a table past MAX_ROWS refused as soon as it passes (``count``: the rows before)."""
    reader = csv.reader((line + "\n" for _, line in numbered), delimiter=delimiter)
    try:
        for cells in reader:
            line = start + reader.line_num
            if not cells or all(not cell.strip() for cell in cells) or cells[0].lstrip().startswith("#"):
                continue
            count += 1
            if count > MAX_ROWS + 1:  # (the header besides)
                raise InputError(OPTION, f"{name} has more than {MAX_ROWS:,} rows, the most fit reads of a table",
                                 hint=too_large(OPTION, name).hint)
            yield line, cells
    except csv.Error as err:
        raise InputError(OPTION, f"{name} line {start + reader.line_num}: cannot be read as a table ({err})") from None


class _Commas:
    """Whether the numbers use a decimal comma (see the module's rule), learnt from each cell as
    the rows stream (``seen``), decided when all are seen (``decided``): True, False, or a usage
    error where a comma could be a thousands separator."""

    def __init__(self) -> None:
        self.with_comma: tuple[int, str] | None = None
        self.with_point: tuple[int, str] | None = None
        self.decimal = False

    def seen(self, line: int, cell: str) -> bool:
        """Takes in one cell; whether it holds a comma (read as a decimal one until decided)."""
        if "," in cell:
            cell = cell.strip()
            self.with_comma = self.with_comma or (line, cell)
            found = _COMMA_NUMBER.fullmatch(cell)
            if found is not None and _not_grouped(found):
                self.decimal = True
            return True
        if self.with_point is None and "." in cell and _NUMBER.fullmatch(cell.strip()):
            self.with_point = (line, cell.strip())
        return False

    def decided(self, delimiter: str, name: str) -> bool:
        if self.with_comma is None:
            return False
        line, cell = self.with_comma
        if delimiter == ",":
            raise InputError(OPTION, f"{name} line {line}: a comma inside a cell of a comma-separated table could be a decimal comma or a thousands separator",
                             got=repr(cell), hint="write 4.5, or separate the columns with ; for a decimal comma")
        if self.with_point is not None:
            raise InputError(OPTION, f"{name} line {line}: numbers with a comma beside numbers with a point ({self.with_point[1]!r} on line {self.with_point[0]}): "
                             "the comma could be a thousands separator", got=repr(cell), hint="write every number with a point")
        if not self.decimal:
            raise InputError(OPTION, f"{name} line {line}: every comma could group thousands (three digits after it, one to three before), "
                             "so it could be a thousands separator or a decimal comma", got=repr(cell), hint="write 1.5 or 1500")
        return True


def _not_grouped(found: re.Match) -> bool:
    """Whether a number with one comma is no thousands-grouped one, so the comma is a decimal one:
    other than three digits after it, an exponent, or before it 0, nothing, a leading 0 or more
    than three digits (0,500; ,5; 1234,500)."""
    whole, decimals, exponent = found[1], found[2], found[3]
    return len(decimals) != 3 or exponent is not None or not whole or whole.startswith("0") or len(whole) > 3


def _number(cell: str, line: int, header: str, name: str, decimal_comma: bool) -> float:
    text = cell.strip()
    if decimal_comma:
        text = text.replace(",", ".", 1) if text.count(",") == 1 else text
    if not text or text.lower() == "nan":
        return math.nan  # no measurement here (see the module's rule)
    if text.lower() in _NOT_FINITE:
        raise InputError(OPTION, f"{name} line {line}: column {header!r} is {text}, not a finite number; a row is refused, not skipped",
                         hint="remove the row, or fill the cell")
    if not _NUMBER.fullmatch(text):
        raise InputError(OPTION, f"{name} line {line}: expected a number in column {header!r}", got=repr(cell.strip()[:40]))
    value = float(text)
    if value in (float("inf"), float("-inf")):
        raise InputError(OPTION, f"{name} line {line}: column {header!r} holds a number too large for a double", got=repr(cell.strip()[:40]))
    if value == 0 and any(digit in "123456789" for digit in text.lower().partition("e")[0]):  # 1e-400: not 0, whatever a double rounds it to
        raise InputError(OPTION, f"{name} line {line}: column {header!r} holds a nonzero number too small for a double (it would be read as 0)",
                         got=repr(cell.strip()[:40]))
    return value
