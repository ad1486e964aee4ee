"""The files fit reads that are not text tables, each turned into the lines of a CSV table for
taucli.fit.data to read as it reads any other:

- an .xlsx workbook (a zip archive holding ``xl/workbook.xml``, whatever the file's name): the
  one sheet with cells in it (phyphox's ``Metadata …`` sheets aside), a row a line, each number
  as Python writes a float (so never a decimal comma), an empty cell empty; a workbook with
  data on several sheets is refused, naming them. Read by openpyxl (the fit extra), imported
  here only when a workbook is given;
- any other zip archive (phyphox's export: a CSV per set of data, and a ``meta/`` folder): the
  one CSV (or .tsv, .txt) inside, outside ``meta/``, read as a text file is; several are refused,
  naming them and the ``unzip -p`` that gives one.

A member of an archive is read as it streams, at most its declared size (zipfile stops there),
and the table's caps (MAX_BYTES, MAX_ROWS) hold as for a text file.

Plain Python (zipfile, csv, io): no numpy, no pint.
"""

from __future__ import annotations

import csv
import io
import os
import stat
import zipfile
from collections.abc import Iterator

from taucli.answering.csv_text import MAX_BYTES, lines as text_lines, too_large
from taucli.core.errors import InputError

ZIP = b"PK\x03\x04"
_TABLES = (".csv", ".tsv", ".txt")
_META = ("meta/", "__macosx/")  # phyphox's metadata; macOS's resource forks


def is_zip(path: str) -> bool:
    """Whether the file at ``path`` is a regular file that starts as a zip archive does (an .xlsx
    is one); a FIFO or a device is never read ahead here (its bytes would be lost to the table)."""
    try:
        if not stat.S_ISREG(os.stat(path).st_mode):
            return False
        with open(path, "rb") as handle:
            return handle.read(4) == ZIP
    except OSError:
        return False


def lines(path: str, name: str, option: str, what: str) -> Iterator[str]:
    """The lines of the table in the zip archive at ``path`` (a workbook's sheet, or the CSV inside)."""
    try:
        archive = zipfile.ZipFile(path)
    except (zipfile.BadZipFile, OSError, ValueError) as err:
        raise InputError(option, f"{name} starts as a zip archive and cannot be read as one ({err})", hint="export the data as CSV") from None
    with archive:
        members = [info for info in archive.infolist() if not info.is_dir()]
        if any(info.filename == "xl/workbook.xml" for info in members):
            archive.close()
            yield from _sheet(path, name, option, members)
            return
        if any(info.filename == "content.xml" for info in members):
            raise InputError(option, f"{name} is an OpenDocument file (.ods, a LibreOffice spreadsheet), not a table fit reads",
                             hint="save the sheet as .xlsx or CSV (File, Save As)")
        tables = [info for info in members if info.filename.lower().endswith(_TABLES) and not info.filename.lower().startswith(_META)]
        if not tables:
            held = ", ".join(info.filename for info in members[:6]) + (", …" if len(members) > 6 else "")
            raise InputError(option, f"{name} is a zip archive with no CSV file in it (it holds {held or 'nothing'})",
                             hint="export the data from phyphox as CSV, or give the CSV file itself")
        if len(tables) > 1:
            listed = ", ".join(repr(info.filename) for info in tables[:6]) + (", …" if len(tables) > 6 else "")
            raise InputError(option, f"{name} is a zip archive of {len(tables)} tables ({listed}): fit reads one",
                             hint=f"give the one you mean: unzip -p {_quoted(name)} {_quoted(tables[0].filename)} | taucli fit SCENE - …")
        member = tables[0]
        if member.file_size > MAX_BYTES:
            raise too_large(option, f"{name} ({member.filename})", what)
        with archive.open(member) as handle:
            yield from text_lines(handle.read, f"{name} ({member.filename})", option, what)


def _quoted(text: str) -> str:
    return text if text.replace("-", "").replace("_", "").replace(".", "").replace("/", "").isalnum() else "'" + text.replace("'", "'\\''") + "'"


def _sheet(path: str, name: str, option: str, members) -> Iterator[str]:
    """The rows of the workbook's one sheet with data, as CSV lines."""
    if any(info.file_size > MAX_BYTES for info in members):
        raise too_large(option, name)
    try:
        import openpyxl  # deferred: only for a workbook
    except ImportError:
        raise InputError(option, f"{name} is an Excel workbook (.xlsx), and reading one needs openpyxl", hint="pip install 'taucli[fit]', or save the sheet as CSV") from None
    try:
        book = openpyxl.load_workbook(path, read_only=True, data_only=True)
    except Exception as err:  # noqa: BLE001 (openpyxl raises many kinds on a broken workbook; each is one line here)
        raise InputError(option, f"{name} is a zip archive that openpyxl cannot read as a workbook ({type(err).__name__}: {err})",
                         hint="open it in a spreadsheet and save it as .xlsx or CSV") from None
    try:
        sheets = [sheet for sheet in book.worksheets if not sheet.title.lower().startswith("metadata") and _has_cells(sheet)]
        if not sheets:
            raise InputError(option, f"{name} is a workbook with no cells in any sheet", hint="save the sheet that holds the data as .xlsx or CSV")
        if len(sheets) > 1:
            listed = ", ".join(repr(sheet.title) for sheet in sheets[:6])
            raise InputError(option, f"{name} is a workbook with data on {len(sheets)} sheets ({listed}): fit reads one",
                             hint="save the sheet you mean as CSV (File, Save a copy), or delete the others")
        width = 0  # the header's: a row may end early where its last cells are empty
        for row in sheets[0].iter_rows(values_only=True):
            cells = _cells(row)
            width = width or len(cells)
            yield _line(cells + [""] * (width - len(cells)))
    finally:
        book.close()


def _has_cells(sheet) -> bool:
    return any(any(cell is not None for cell in row) for row in sheet.iter_rows(max_row=50, values_only=True))


def _cells(row) -> list[str]:
    """One row of a sheet as texts: a float as Python writes it, empty for none, the empty cells at its end left out."""
    cells = ["" if cell is None else repr(float(cell)) if isinstance(cell, float) else str(cell).replace("\r", " ").replace("\n", " ") for cell in row]
    while cells and not cells[-1]:
        cells.pop()
    return cells


def _line(cells: list[str]) -> str:
    out = io.StringIO()
    csv.writer(out, lineterminator="").writerow(cells)
    return out.getvalue()
