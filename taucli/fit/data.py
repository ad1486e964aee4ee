"""Reading a table of measured samples: CSV as phone sensor apps, data loggers and spreadsheets
write it.

- The first line that is neither blank nor a comment (``#``) names the columns; a header may carry
  its unit in parentheses or brackets, ``Time (s)`` or ``t [ms]``.
- Columns are separated by tabs, else semicolons, else commas (the header says which): the
  rules of taucli.answering.csv_text, which a torque profile is read by too.
- A decimal comma is read where the file shows that it is one (docs/units.md: a comma that could
  be a thousands separator is refused, never guessed): the columns are separated by semicolons or
  tabs, no number has a decimal point, and some number has other than three digits after its
  comma. A file whose every comma is followed by three digits (``1,500``) is refused.
- Every cell of a row is a finite number or empty: a blank or NaN cell (phyphox pads with NaN,
  Vernier and PASCO pad shorter runs with blanks) is read as NaN, no measurement, and the fit
  leaves out the rows where a column it uses has one (samples.py, with a note); infinity or
  text is refused with its line.
- A binary file, a file that is not UTF-8 or Windows-1252 text, ragged rows, an empty table and
  a line longer than csv's limit are refused, one line each.

Plain Python (csv): no numpy, no pint.
"""

from __future__ import annotations

import csv
import io
import math
import os
import re
from dataclasses import dataclass

from taucli.answering.csv_text import delimiter as _delimiter, split_header
from taucli.core.errors import InputError
from taucli.core.written import printable

OPTION = "data"  # the argument the messages name (DATA)
MAX_BYTES = 200 * 1024 * 1024
MAX_ROWS = 2_000_000

_NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")
_COMMA_NUMBER = re.compile(r"[+-]?\d*,(\d+)(?:[eE][+-]?\d+)?")
_NOT_FINITE = {"nan", "inf", "-inf", "+inf", "infinity", "-infinity", "+infinity"}


@dataclass(frozen=True)
class Column:
    """One column of a table: its header as written, the name and unit the header gives, and its
    numbers as the file writes them (in the header's unit)."""

    header: str
    name: str
    unit: str  # "" where the header names none
    values: tuple[float, ...]


@dataclass(frozen=True)
class DataTable:
    source: str  # the file's name, or "stdin"
    columns: tuple[Column, ...]
    lines: tuple[int, ...]  # the line of the file each row is on
    delimiter: str
    decimal_comma: bool

    def column(self, header: str) -> Column:
        return next(column for column in self.columns if column.header == header)


def read(source, stdin=None) -> DataTable:
    """The table in the file ``source`` (``-``: stdin; an open file object, from Python), or a
    usage error naming what is wrong."""
    name = _name(source)
    text = _text(source, stdin)
    lines = text.splitlines()
    start = next((i for i, line in enumerate(lines) if line.strip() and not line.lstrip().startswith("#")), None)
    if start is None:
        raise InputError(OPTION, f"{name} holds no table: expected a header line naming the columns, then a row of numbers per sample",
                         example="t (s),omega (rad/s)")
    delimiter = _delimiter(lines[start])  # the rules a torque profile is read by too
    rows = _rows(lines, start, delimiter, name)
    if not rows:
        raise InputError(OPTION, f"{name} holds no table: expected a header line naming the columns, then a row of numbers per sample",
                         example="t (s),omega (rad/s)")
    headers = [cell.strip() for cell in rows[0][1]]
    if any(not header for header in headers):
        raise InputError(OPTION, f"{name} line {rows[0][0]}: expected a name for every column", got=repr(lines[start][:80]))
    if len(set(headers)) != len(headers):
        twice = sorted({header for header in headers if headers.count(header) > 1})
        raise InputError(OPTION, f"{name} line {rows[0][0]}: names a column twice: {', '.join(twice)}")
    if all(_NUMBER.fullmatch(header) for header in headers):
        raise InputError(OPTION, f"{name} line {rows[0][0]}: expected a header naming the columns before the numbers", example="t (s),omega (rad/s)")
    body = rows[1:]
    if not body:
        raise InputError(OPTION, f"{name} has a header and no rows of numbers")
    for line, cells in body:
        if len(cells) != len(headers):
            raise InputError(OPTION, f"{name} line {line}: expected {len(headers)} cells, as the header names, got {len(cells)}")
    decimal_comma = _decimal_comma(body, delimiter, name)
    numbers = [[_number(cell, line, header, name, decimal_comma) for cell, header in zip(cells, headers)] for line, cells in body]
    columns = tuple(Column(header, *split_header(header), tuple(row[i] for row in numbers)) for i, header in enumerate(headers))
    return DataTable(name, columns, tuple(line for line, _ in body), delimiter, decimal_comma)


def _name(source) -> str:
    """The file's name as messages and steps show it: its control characters escaped (#43)."""
    return printable("stdin" if source == "-" else source if isinstance(source, str) else str(getattr(source, "name", None) or "the file object"))


def _text(source, stdin) -> str:
    name = _name(source)
    if not isinstance(source, str):  # an open file object (the Python API)
        try:
            raw = source.read(MAX_BYTES + 1)
        except (OSError, ValueError, TypeError) as err:
            raise InputError(OPTION, "expected an open file to read a table from", got=f"{name}: {err}") from None
        if not isinstance(raw, (str, bytes)):
            raise InputError(OPTION, "expected a file object whose read() gives text or bytes", got=f"{name}: {type(raw).__name__}")
        if len(raw) > MAX_BYTES:
            raise InputError(OPTION, f"{name} is larger than {MAX_BYTES // 1024 // 1024} MB: give a part of it (fit takes at most 5000 samples)")
    elif source == "-":
        if stdin is None:
            raise InputError(OPTION, "cannot be - here: no stdin to read it from")
        raw = stdin.buffer.read() if hasattr(stdin, "buffer") else stdin.read()
    else:
        try:
            if os.path.getsize(source) > MAX_BYTES:
                raise InputError(OPTION, f"{name} is larger than {MAX_BYTES // 1024 // 1024} MB: give a part of it (fit takes at most 5000 samples)")
            with open(source, "rb") as handle:
                raw = handle.read()
        except OSError as err:
            raise InputError(OPTION, "expected a readable data file (or - for stdin)", got=f"{source!r}: {err.strerror or err}") from None
    if isinstance(raw, str):
        return raw
    if b"\x00" in raw[:65536]:
        raise InputError(OPTION, f"{name} is not a text table (it holds NUL bytes: a binary file?)", hint="export the data as CSV")
    for encoding in ("utf-8-sig", "cp1252"):
        try:
            return raw.decode(encoding)
        except UnicodeDecodeError:
            continue
    raise InputError(OPTION, f"{name} is not text in UTF-8 or Windows-1252", hint="export the data as CSV in UTF-8")


def _rows(lines: list[str], start: int, delimiter: str, name: str) -> list[tuple[int, list[str]]]:
    """(line number, cells) of the header and each row after it, blank lines and comments left out."""
    rows = []
    reader = csv.reader(io.StringIO("\n".join(lines[start:])), delimiter=delimiter)
    try:
        for cells in reader:
            line = start + reader.line_num
            if not cells or all(not cell.strip() for cell in cells) or cells[0].lstrip().startswith("#"):
                continue
            rows.append((line, cells))
            if len(rows) > MAX_ROWS:
                raise InputError(OPTION, f"{name} has more than {MAX_ROWS:,} rows: give a part of it (fit takes at most 5000 samples)")
    except csv.Error as err:
        raise InputError(OPTION, f"{name} line {start + reader.line_num}: cannot be read as a table ({err})") from None
    return rows


def _decimal_comma(body: list[tuple[int, list[str]]], delimiter: str, name: str) -> bool:
    """Whether the numbers use a decimal comma (see the module's rule), or a usage error where a
    comma could be a thousands separator."""
    with_comma = with_point = None
    decimal = False
    for line, cells in body:
        for cell in cells:
            cell = cell.strip()
            if "," in cell:
                with_comma = with_comma or (line, cell)
                found = _COMMA_NUMBER.fullmatch(cell)
                if found is not None and len(found[1]) != 3:
                    decimal = True
            if "." in cell and _NUMBER.fullmatch(cell):
                with_point = with_point or (line, cell)
    if with_comma is None:
        return False
    line, cell = with_comma
    if delimiter == ",":
        raise InputError(OPTION, f"{name} line {line}: a comma inside a cell of a comma-separated table could be a decimal comma or a thousands separator",
                         got=repr(cell), hint="write 4.5, or separate the columns with ; for a decimal comma")
    if with_point is not None:
        raise InputError(OPTION, f"{name} line {line}: numbers with a comma beside numbers with a point ({with_point[1]!r} on line {with_point[0]}): "
                         "the comma could be a thousands separator", got=repr(cell), hint="write every number with a point")
    if not decimal:
        raise InputError(OPTION, f"{name} line {line}: every comma is followed by three digits, so it could be a thousands separator "
                         "or a decimal comma", got=repr(cell), hint="write 1.5 or 1500")
    return True


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
