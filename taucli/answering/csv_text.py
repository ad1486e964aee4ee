"""The CSV rules every table taucli reads shares: a torque profile (``--torque-profile``) and
``taucli fit``'s data (#42: one reader of headers and separators), and how its text is read.

- Columns are separated by tabs, else semicolons, else commas: the header line says which,
  outside its quotes (``"a;b",c`` is comma-separated).
- Cells may be quoted as spreadsheets write them (``"time (s)","torque (N*m)"``).
- A header carries its unit in parentheses or brackets, ``Time (s)`` or ``t [ms]``, wherever it
  stands (PASCO writes ``Time (ms) Run #1``): the last bracketed group is the unit, the words
  either side of it the name; a header with none names no unit (the reader says what it takes
  it as).
- A table is at most MAX_BYTES long, whatever it comes from (a file, a device such as
  /dev/zero, a FIFO, stdin): it is read a chunk at a time and refused as soon as it passes that,
  so no more than the cap is ever read (#43).
- Text is UTF-8 (a BOM is skipped), else Windows-1252 where the file is not UTF-8; UTF-16 and
  UTF-32 with a byte-order mark, and UTF-16 without one where the first 256 characters of it
  (every other byte NUL) decode to text with no control character but tab and line ends (a
  spreadsheet's "Unicode text": ``Winkel (°)`` too), are read too. Any other NUL byte is a
  binary file, and its refusal says what it is where its first bytes tell (a zip archive such
  as an .xlsx workbook, an old .xls, a PDF, an image) and what to do.
- Lines end at ``\\n``, ``\\r\\n`` or ``\\r`` and nowhere else: a form feed, U+0085 or U+2028 inside
  a cell is a character of the cell (str.splitlines() would split there and number every later
  line wrong).

Plain Python (codecs, csv, re): no pint.
"""

from __future__ import annotations

import codecs
import csv
import re
from collections.abc import Callable, Iterator

from taucli.core.errors import InputError

MAX_BYTES = 200 * 1024 * 1024  # a table taucli reads; fit takes 5000 samples, a profile is integrated as it streams
MAX_LINE = 1024 * 1024  # characters in one line of a table (csv's own limit for a cell is 131,072)
CHUNK = 1 << 16

_UNIT = re.compile(r"\(\s*([^()\[\]]*?)\s*\)|\[\s*([^()\[\]]*?)\s*\]")  # (unit) or [unit], nothing bracketed inside
_QUOTED = re.compile(r'"[^"]*(?:"|$)')
_LINE_END = re.compile(r"\r\n|\r|\n")
_BOMS = ((codecs.BOM_UTF32_LE, "utf-32"), (codecs.BOM_UTF32_BE, "utf-32"), (codecs.BOM_UTF16_LE, "utf-16"), (codecs.BOM_UTF16_BE, "utf-16"))


def delimiter(header: str) -> str:
    """The separator of the table whose header line is ``header``: tab, else semicolon, else comma,
    whichever is outside the header's quotes."""
    bare = _QUOTED.sub("", header)
    return "\t" if "\t" in bare else ";" if ";" in bare else ","


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


def too_large(option: str, name: str, what: str = "") -> InputError:
    """The refusal of a table past MAX_BYTES (``what``: why that is enough, said in parentheses)."""
    return InputError(option, f"{name} is larger than {MAX_BYTES / 1024 / 1024:g} MB, the most taucli reads of a table" + (f" ({what})" if what else ""),
                      hint="give a part of it: keep every 10th row with awk 'NR % 10 == 1' data.csv > part.csv, or split it into files of fewer rows")


def lines(read: Callable[[int], object], name: str, option: str, what: str = "") -> Iterator[str]:
    """The lines of the table ``read(n)`` gives (bytes or text, a chunk at a time), without their
    ends, decoded as the module says; an InputError naming ``name`` as soon as the table passes
    MAX_BYTES, a line passes MAX_LINE, or the text is binary or in no encoding taucli reads."""
    for block in blocks(read, name, option, what):
        yield from block


def blocks(read: Callable[[int], object], name: str, option: str, what: str = "") -> Iterator[list[str]]:
    """``lines``' lines, a list of them per chunk read: a reader of a million rows takes them
    without a step per line (#45 item 3). A line past MAX_LINE is refused after the lines before it."""
    rest = ""
    number = 0
    for text in _decoded(read, name, option, what):
        rest += text
        hold = rest.endswith("\r")  # its \n may come in the next chunk: "\r\n" is one line end
        whole = rest[:-1] if hold else rest
        *done, rest = _LINE_END.split(whole) if "\r" in whole else whole.split("\n")  # str.split: a tenth of the time
        rest += "\r" if hold else ""
        if done and max(map(len, done)) > MAX_LINE:
            long = next(i for i, line in enumerate(done) if len(line) > MAX_LINE)
            if long:
                yield done[:long]
            raise _too_long(option, name, number + long + 1)
        if done:
            number += len(done)
            yield done
        if len(rest) > MAX_LINE:
            raise _too_long(option, name, number + 1)
    if rest:
        if rest.endswith("\r"):
            rest = rest[:-1]
        yield [rest]


def _too_long(option: str, name: str, number: int) -> InputError:
    return InputError(option, f"{name} line {number}: longer than {MAX_LINE:,} characters, so not a table of numbers", hint="export the data as CSV")


# What a binary file is, by its first bytes: (magic, what it is, what to do).
_MAGIC = (
    (b"PK\x03\x04", "a zip archive (an .xlsx workbook, phyphox's export, an .ods)", "taucli fit reads an .xlsx or a zip of CSVs given by its file name; else export the data as CSV"),
    (b"\xd0\xcf\x11\xe0", "an old Excel workbook (.xls)", "save it as .xlsx or CSV in Excel"),
    (b"%PDF", "a PDF document", "export the data as CSV from the program that made it"),
    (b"\x89PNG", "a PNG image", "export the data as CSV, not the graph"),
    (b"\xff\xd8\xff", "a JPEG image", "export the data as CSV, not the graph"),
    (b"SQLite format 3", "an SQLite database", "export the table as CSV"),
)


def _binary(option: str, name: str, head: bytes = b"") -> InputError:
    for magic, what, hint in _MAGIC:
        if head.startswith(magic):
            return InputError(option, f"{name} is {what}, not a text table", hint=hint)
    return InputError(option, f"{name} is not a text table: it holds NUL bytes in no text encoding taucli reads (UTF-8, Windows-1252, UTF-16, UTF-32)",
                      hint="export the data as CSV in UTF-8")


def _not_text(option: str, name: str, why: str = "") -> InputError:
    return InputError(option, f"{name} is not text in UTF-8 or Windows-1252{why}", hint="export the data as CSV in UTF-8")


def _decoded(read: Callable[[int], object], name: str, option: str, what: str) -> Iterator[str]:
    """The text of the source a chunk at a time, at most MAX_BYTES of it read (see ``lines``)."""
    total = 0

    def chunk():
        nonlocal total
        got = read(CHUNK)
        if got is None:
            got = b""
        if not isinstance(got, (str, bytes)):
            raise InputError(option, "expected a file object whose read() gives text or bytes", got=f"{name}: {type(got).__name__}")
        total += len(got)
        if total > MAX_BYTES:
            raise too_large(option, name, what)
        return got

    head = chunk()
    if isinstance(head, str):  # a text stream: decoded already
        while head:
            if "\x00" in head:
                raise _binary(option, name)
            yield head
            head = chunk()
        return
    while 0 < len(head) < 4 and (more := chunk()):  # enough to see a byte-order mark
        head += more
    encoding = next((encoding for bom, encoding in _BOMS if head.startswith(bom)), None)
    if encoding is None and b"\x00" in head:
        encoding = _utf16_without_bom(head)
        if encoding is None:
            raise _binary(option, name, head)
    if encoding is not None:
        decoder = codecs.getincrementaldecoder(encoding)()
        try:
            while head:
                text = decoder.decode(head)
                if "\x00" in text:
                    raise _binary(option, name)
                yield text
                head = chunk()
            yield decoder.decode(b"", final=True)
        except UnicodeDecodeError:
            raise InputError(option, f"{name} is not text in {encoding.upper()}: it starts as such and then holds a byte that is not",
                             hint="export the data as CSV in UTF-8") from None
        return
    yield from _utf8_else_cp1252(head, chunk, name, option)


def _utf16_without_bom(head: bytes) -> str | None:
    """UTF-16 without a byte-order mark (text a spreadsheet saved as "Unicode text"): every other
    byte NUL in most characters, and the first 256 characters decode to text with no control
    character but tab and line ends (``°`` and ``ω`` too); None for anything else with a NUL."""
    whole = head[:min(len(head) - len(head) % 2, 512)]  # a chunk may end inside a character
    even, odd = whole[0::2], whole[1::2]
    if not even:
        return None
    for encoding, high, low in (("utf-16-le", odd, even), ("utf-16-be", even, odd)):
        if high.count(0) * 4 < len(high) * 3 or 0 in low:  # (a character whose low byte is NUL: Ā, Ȁ… are no table's)
            continue
        try:
            text = whole.decode(encoding)
        except UnicodeDecodeError:
            continue
        if not any(ord(c) < 32 and c not in "\t\r\n" or 0x7F <= ord(c) < 0xA0 for c in text):
            return encoding
    return None


def _utf8_else_cp1252(head: bytes, chunk: Callable[[], bytes], name: str, option: str) -> Iterator[str]:
    """UTF-8 (a BOM skipped); where a byte is not UTF-8 and every character before it was ASCII,
    Windows-1252 from there on (the same text as reading the whole file so); a file that is UTF-8
    with non-ASCII characters and then not is refused (it is in no one encoding)."""
    decoder = codecs.getincrementaldecoder("utf-8-sig")()
    ascii_so_far = True
    raw = head
    while raw:
        pending = decoder.getstate()[0]
        try:
            text = decoder.decode(raw)
        except UnicodeDecodeError:
            if not ascii_so_far:
                raise _not_text(option, name, ": it is UTF-8 up to a point and then holds a byte that is not") from None
            yield from _cp1252(pending + raw, chunk, name, option)
            return
        if "\x00" in text:
            raise _binary(option, name)
        ascii_so_far = ascii_so_far and text.isascii()  # (bytes the decoder holds are not text yet)
        yield text
        raw = chunk()
    pending = decoder.getstate()[0]
    if pending:  # the file ends inside a UTF-8 character
        if not ascii_so_far:
            raise _not_text(option, name, ": it ends inside a UTF-8 character") from None
        yield from _cp1252(pending, chunk, name, option)


def _cp1252(raw: bytes, chunk: Callable[[], bytes], name: str, option: str) -> Iterator[str]:
    while raw:
        try:
            text = raw.decode("cp1252")
        except UnicodeDecodeError:
            raise _not_text(option, name) from None
        if "\x00" in text:
            raise _binary(option, name)
        yield text
        raw = chunk()
