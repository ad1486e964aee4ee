"""The CSV rules every table taucli reads shares: a torque profile (``--torque-profile``) and
``taucli fit``'s data (#42: one reader of headers and separators).

- Columns are separated by tabs, else semicolons, else commas: the header line says which.
- Cells may be quoted as spreadsheets write them (``"time (s)","torque (N*m)"``).
- A header carries its unit in parentheses or brackets, ``Time (s)`` or ``t [ms]``, wherever it
  stands (PASCO writes ``Time (ms) Run #1``): the last bracketed group is the unit, the words
  either side of it the name; a header with none names no unit (the reader says what it takes
  it as).

Plain Python (csv, re): no pint.
"""

from __future__ import annotations

import csv
import re

_UNIT = re.compile(r"\(\s*([^()\[\]]*?)\s*\)|\[\s*([^()\[\]]*?)\s*\]")  # (unit) or [unit], nothing bracketed inside


def delimiter(header: str) -> str:
    """The separator of the table whose header line is ``header``: tab, else semicolon, else comma."""
    return "\t" if "\t" in header else ";" if ";" in header else ","


def cells(line: str, separator: str) -> list[str]:
    """The cells of one line, quotes as csv reads them, each stripped."""
    return [cell.strip() for cell in next(csv.reader([line], delimiter=separator), [])]


def split_header(header: str) -> tuple[str, str]:
    """("Time", "s") from "Time (s)" or "Time [s]"; ("Time Run #1", "ms") from "Time (ms) Run #1"
    (the last bracketed group is the unit wherever it stands, the words either side the name);
    (header, "") where it names none."""
    found = None
    for found in _UNIT.finditer(header):
        pass
    if found is None:
        return header.strip(), ""
    unit = (found[1] if found[1] is not None else found[2]).strip()
    name = " ".join(part for part in (header[:found.start()].strip(), header[found.end():].strip()) if part)
    return (name, unit) if name else (header.strip(), "")
