"""The CSV rules every table taucli reads shares: a torque profile (``--torque-profile``) and
``taucli fit``'s data (#42: one reader of headers and separators).

- Columns are separated by tabs, else semicolons, else commas: the header line says which.
- Cells may be quoted as spreadsheets write them (``"time (s)","torque (N*m)"``).
- A header carries its unit in parentheses or brackets, ``Time (s)`` or ``t [ms]``; a header
  with none names no unit (the reader says what it takes it as).

Plain Python (csv, re): no pint.
"""

from __future__ import annotations

import csv
import re

_WITH_UNIT = re.compile(r"^(.*?)\s*[(\[]\s*([^()\[\]]*?)\s*[)\]]\s*$")


def delimiter(header: str) -> str:
    """The separator of the table whose header line is ``header``: tab, else semicolon, else comma."""
    return "\t" if "\t" in header else ";" if ";" in header else ","


def cells(line: str, separator: str) -> list[str]:
    """The cells of one line, quotes as csv reads them, each stripped."""
    return [cell.strip() for cell in next(csv.reader([line], delimiter=separator), [])]


def split_header(header: str) -> tuple[str, str]:
    """("Time", "s") from "Time (s)" or "Time [s]"; (header, "") where it names no unit."""
    found = _WITH_UNIT.match(header)
    if found is None or not found[1].strip():
        return header.strip(), ""
    return found[1].strip(), found[2].strip()
