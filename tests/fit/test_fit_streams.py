"""A table is read as it streams (#43 items 11 and 18): at most the byte cap of any source, a
file, a device, a FIFO, stdin or a Python file object, refused as soon as it passes the cap or
the row cap; its text decoded as what it is (UTF-16 and UTF-32 with a BOM too); its lines split
at \\n, \\r\\n and \\r only, so an error names the line a person sees in an editor; its separator
read outside the header's quotes. A torque profile is held to the same cap.

The caps are made small here (monkeypatch) so that an endless source is refused in a moment; each
source below raises if it is read much past the cap, so a reader that reads it whole fails fast.
"""

from __future__ import annotations

import codecs
import os
import re
import resource
import subprocess
import sys
import threading

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from taucli.answering import csv_text, profile
from taucli.core.errors import InputError
from taucli.fit import data

CAP = 256 * 1024
CHUNK = getattr(csv_text, "CHUNK", 1 << 16)  # what the reader reads at a time
ROW = b"0.001000,99.999900\n"


@pytest.fixture
def small_cap(monkeypatch):
    monkeypatch.setattr(csv_text, "MAX_BYTES", CAP, raising=False)
    monkeypatch.setattr(data, "MAX_BYTES", CAP, raising=False)
    monkeypatch.setattr(profile, "MAX_BYTES", CAP, raising=False)
    return CAP


class Endless:
    """A source that never ends (a device, a generator on a pipe): a header, then ``fill`` over and
    over. It counts what it gave and raises once it has given ``stop`` bytes, far past the cap."""

    def __init__(self, fill: bytes = ROW, header: bytes = b"t (s),omega (rad/s)\n", stop: int = 40 * CAP, text: bool = False):
        self.header, self.fill, self.stop, self.text = header, fill, stop, text
        self.given = 0

    def read(self, size: int = -1):
        if size is None or size < 0:
            raise AssertionError("read to the end of an endless source")
        if self.given >= self.stop:
            raise AssertionError(f"read {self.given} bytes of an endless source, past a cap of {CAP}")
        stream = self.header if not self.given else b""
        phase = max(0, self.given - len(self.header)) % len(self.fill)
        out = (stream + (self.fill * ((size + phase) // len(self.fill) + 2))[phase:])[:size]
        self.given += len(out)
        return out.decode() if self.text else out


class Rows:
    """An endless torque profile read a line at a time (a text stream): its header, then rows whose
    time increases without end; counts the characters it gave, raises far past the cap."""

    def __init__(self):
        self.given = self.row = 0

    def readline(self, size: int = -1) -> str:
        if self.given >= 40 * CAP:
            raise AssertionError(f"read {self.given} characters of an endless profile, past a cap of {CAP}")
        line = "t [s], torque [N*m]\n" if not self.given else f"{self.row},1\n"
        self.row += 1
        self.given += len(line)
        return line


class Stdin:
    def __init__(self, buffer):
        self.buffer = buffer


@pytest.mark.parametrize("fill,said", [(ROW, "is larger than 0.25 MB"), (b"# a comment, not a row, over and over\n", "is larger than 0.25 MB"),
                                       (b"\n", "is larger than 0.25 MB")])
@pytest.mark.parametrize("how", ["stdin", "file object", "text file object"])
def test_an_endless_source_is_refused_at_the_byte_cap(small_cap, fill, said, how):
    source = Endless(fill, text=how == "text file object")
    with pytest.raises(InputError) as caught:
        data.read("-", Stdin(source)) if how == "stdin" else data.read(source)
    assert said in str(caught.value) and "awk 'NR % 10 == 1' data.csv > part.csv" in str(caught.value)
    assert CAP < source.given <= CAP + CHUNK


def test_rows_are_counted_as_they_stream(monkeypatch):
    monkeypatch.setattr(data, "MAX_ROWS", 1000)
    source = Endless(stop=1000 * len(ROW) + 2 * CHUNK)
    with pytest.raises(InputError, match="more than 1,000 rows"):
        data.read("-", Stdin(source))


def test_a_fifo_fed_without_end_is_read_only_to_the_cap(small_cap, tmp_path):
    fifo = tmp_path / "endless.csv"
    os.mkfifo(fifo)
    written = [0]

    def writer():
        try:
            with open(fifo, "wb") as out:
                out.write(b"t (s),omega (rad/s)\n")
                while written[0] < 40 * CAP:
                    out.write(ROW * 100)
                    written[0] += len(ROW) * 100
        except BrokenPipeError:
            pass

    thread = threading.Thread(target=writer, daemon=True)
    thread.start()
    with pytest.raises(InputError, match="endless.csv is larger than"):
        data.read(str(fifo))
    thread.join(10)
    assert not thread.is_alive() and written[0] < CAP + 2 * CHUNK + 1024 * 1024  # (the pipe's own buffer besides)


def test_a_regular_file_past_the_cap_is_refused_before_it_is_read(small_cap, tmp_path):
    path = tmp_path / "big.csv"
    path.write_bytes(b"t (s),omega (rad/s)\n" + ROW * (CAP // len(ROW) + 1))
    with pytest.raises(InputError, match=r"big.csv is larger than 0.25 MB, the most taucli reads of a table"):
        data.read(str(path))


def _fit_in_a_child(data_file: str, stdin=None, limit=1 << 30):
    """`taucli fit` in a child held to ``limit`` bytes of memory and 60 s: a reader that reads
    /dev/zero whole dies of MemoryError (exit 1) or is stopped, one that does not refuses it."""
    def held():
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    return subprocess.run([sys.executable, "-m", "taucli", "fit", "spin-down", data_file, "--inertia", "0.1kg*m^2", "--fit", "friction"],
                          stdin=stdin, capture_output=True, text=True, timeout=60, preexec_fn=held)


@pytest.mark.parametrize("device", ["/dev/zero", "/dev/urandom"])
def test_a_device_as_the_data_file_is_refused_at_once(device):
    if not os.path.exists(device):
        pytest.skip(f"no {device} here")
    done = _fit_in_a_child(device)
    assert done.returncode == 2 and done.stderr.count("\n") == 1, done.stderr
    assert f"{device} is not a text table" in done.stderr


def test_dev_zero_on_stdin_is_refused_at_once():
    with open("/dev/zero", "rb") as zero:
        done = _fit_in_a_child("-", stdin=zero)
    assert done.returncode == 2 and "stdin is not a text table" in done.stderr, done.stderr


def test_a_torque_profile_is_held_to_the_same_cap(small_cap):
    source = Rows()
    read = profile.read_profile(source)
    with pytest.raises(InputError, match="the profile is larger than 0.25 MB"):
        for _ in read.samples:
            pass
    assert CAP < source.given <= CAP + 20


# --- what the text is (item 18) ---

ROWS = "t (s),omega (rad/s)\n0,1\n1,2\nx,3\n"  # line 4 is the bad one


@pytest.mark.parametrize("encoding", ["utf-16", "utf-16-le-bom", "utf-16-be-bom", "utf-16-le", "utf-16-be", "utf-32", "utf-8-sig", "cp1252"])
def test_a_table_in_utf16_or_utf32_is_read_as_text(tmp_path, encoding):
    path = tmp_path / "t.csv"
    boms = {"utf-16-le-bom": (codecs.BOM_UTF16_LE, "utf-16-le"), "utf-16-be-bom": (codecs.BOM_UTF16_BE, "utf-16-be")}
    bom, codec = boms.get(encoding, (b"", encoding))
    path.write_bytes(bom + ("t (s),omega (rad/s)\n0,1.5\n1,2.5\n").encode(codec))
    found = data.read(str(path))
    assert found.column("omega (rad/s)").values == (1.5, 2.5) and found.lines == (2, 3)
    path.write_bytes(bom + ROWS.encode(codec))
    with pytest.raises(InputError, match=r"t.csv line 4: expected a number in column 't \(s\)'"):
        data.read(str(path))


def test_nul_bytes_that_are_not_utf16_are_a_binary_file(tmp_path):
    path = tmp_path / "b.csv"
    path.write_bytes(b"t,omega\n\x00\x01\x02")
    with pytest.raises(InputError, match="is not a text table"):
        data.read(str(path))


def test_a_separator_inside_the_headers_quotes_is_part_of_a_name():
    for separator in (",", ";"):
        other = ";" if separator == "," else "\t"
        text = f'"t{other} (s)"{separator}omega (rad/s)\n0{separator}1\n1{separator}2\n'
        found = data.read("-", _text_stdin(text))
        assert [c.header for c in found.columns] == [f"t{other} (s)", "omega (rad/s)"] and found.delimiter == separator
    assert csv_text.delimiter('"time; s","torque"') == "," and csv_text.delimiter('"a,b";c') == ";" and csv_text.delimiter('a\t"b;c"') == "\t"


def _text_stdin(text: str, encoding: str = "utf-8"):
    import io
    return Stdin(io.BytesIO(text.encode(encoding)))


SEPARATORS_NOT_LINE_ENDS = ["\f", "\v", "\x1c", "\x1d", "\x1e", "\x85", "\u2028", "\u2029"]


@pytest.mark.parametrize("char", SEPARATORS_NOT_LINE_ENDS)
def test_a_character_str_splitlines_splits_at_is_not_a_line_end(char):
    text = f'"t{char} (s)",omega (rad/s)\n0,1{char}\n1,"2 {char}"\nx,3\n'
    with pytest.raises(InputError) as caught:
        data.read("-", _text_stdin(text))
    assert "stdin line 4:" in str(caught.value)
    text = f"t (s),omega (rad/s)\n0,1\n1,2{char}5\n"
    with pytest.raises(InputError, match="stdin line 3: expected a number"):
        data.read("-", _text_stdin(text))


def test_line_ends_are_lf_crlf_and_cr_and_nothing_else():
    for end in ("\n", "\r\n", "\r"):
        text = end.join(["# comment", "t (s),omega (rad/s)", "", "0,1", "1,2", "x,3", ""])
        with pytest.raises(InputError, match="stdin line 6: expected a number"):
            data.read("-", _text_stdin(text))


def read_lines(raw: bytes, chunk: int) -> list[str]:
    stream = iter(raw[i:i + chunk] for i in range(0, len(raw), chunk))
    return list(csv_text.lines(lambda size: next(stream, b""), "t.csv", "data"))


@settings(max_examples=300, deadline=None)
@given(st.lists(st.tuples(st.text(st.characters(blacklist_characters="\r\n\x00\ufeff", blacklist_categories=("Cs",)), max_size=12),
                          st.sampled_from(["\n", "\r\n", "\r"])), max_size=12),
       st.sampled_from(["", "\n", "\r"]), st.integers(1, 9), st.sampled_from(["utf-8", "utf-8-sig", "utf-16", "utf-32"]))
def test_lines_are_the_text_split_at_its_line_ends_whatever_the_chunks(parts, tail, chunk, encoding):
    """The streamed lines of any text, cut into chunks anywhere (inside a character, between \\r
    and \\n), are the text split at \\n, \\r\\n and \\r: no more, no fewer."""
    text = "".join(line + end for line, end in parts) + ("last" + tail if tail else "")
    expected = re.split(r"\r\n|\r|\n", text)
    if expected and expected[-1] == "":
        expected.pop()
    assert read_lines(text.encode(encoding), chunk) == expected


@pytest.mark.parametrize("chunk", [1, 2, 3, 7, 64])
def test_windows_1252_is_read_wherever_a_chunk_ends(chunk):
    """A file that is not UTF-8 is Windows-1252 from its first byte, as if read whole: a byte that
    starts a UTF-8 character at the end of a chunk and is not followed by one included."""
    text = "t (°C),omega (rad/s) é\n0,1 \u00c3\n"
    assert read_lines(text.encode("cp1252"), chunk) == text.encode("cp1252").decode("cp1252").split("\n")[:-1]
    assert read_lines(b"t,w\n0,1\xc3", chunk) == ["t,w", "0,1\u00c3"]


def test_utf8_then_a_byte_that_is_not_is_refused_not_misread():
    with pytest.raises(InputError, match="UTF-8 up to a point"):
        read_lines("t (°C),w\n0,1\n".encode() + b"\xe9\n", 4)
