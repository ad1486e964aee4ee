"""The stream an answer is written to, and what a run says when it cannot be written.

``Guarded`` wraps standard output: a write or flush that fails (stdout closed with ``>&-``, a
full disk or ``> /dev/full``, an I/O error) raises ``OutputFailed``, which the front ends turn
into one line on stderr naming the output and exit status 74 (docs/running.md), where it was an
internal error. A reader that leaves early (BrokenPipeError) is not a failure: it passes through,
as before, to be answered quietly.
"""

from __future__ import annotations

import os
import sys

from taucli.core.errors import ExitStatus, TaucliError


class OutputFailed(TaucliError):
    """The answer could not be written to where it was going."""

    exit_status = ExitStatus.OUTPUT


def _failed(name: str, err: BaseException | None) -> OutputFailed:
    if err is None:
        return OutputFailed(f"cannot write the answer to {name}: it is closed (a command line with >&-?); give the answer somewhere to go")
    reason = getattr(err, "strerror", None) or str(err) or type(err).__name__
    return OutputFailed(f"cannot write the answer to {name}: {reason} (a full disk or device?)")


class Guarded:
    """``stream`` (None: closed) whose writes and flushes raise OutputFailed where they fail;
    everything else is the stream's own (encoding, isatty, fileno, its byte buffer guarded too)."""

    def __init__(self, stream, name: str = "standard output") -> None:
        self._stream = stream
        self._name = name

    def write(self, text):
        if self._stream is None:
            raise _failed(self._name, None)
        try:
            return self._stream.write(text)
        except BrokenPipeError:
            raise
        except (OSError, ValueError) as err:  # ValueError: "I/O operation on closed file"
            raise _failed(self._name, err) from None

    def flush(self) -> None:
        if self._stream is None:
            return
        try:
            self._stream.flush()
        except BrokenPipeError:
            raise
        except (OSError, ValueError) as err:
            raise _failed(self._name, err) from None

    @property
    def buffer(self):
        buffer = getattr(self._stream, "buffer", None)
        return None if buffer is None else Guarded(buffer, self._name)

    def isatty(self) -> bool:
        return self._stream is not None and self._stream.isatty()

    def __getattr__(self, name: str):
        if self._stream is None:
            raise AttributeError(name)
        return getattr(self._stream, name)


def guarded(stream, name: str = "standard output") -> Guarded:
    return stream if isinstance(stream, Guarded) else Guarded(stream, name)


def failed(err: OutputFailed, stderr) -> int:
    """Say why the answer could not be written, and make sure nothing fails again on exit (Python
    flushes stdout once more as it ends: what is left in its buffer goes to /dev/null)."""
    try:
        stdout = sys.__stdout__
        if stdout is not None:
            os.dup2(os.open(os.devnull, os.O_WRONLY), stdout.fileno())
    except (OSError, ValueError):
        pass
    if stderr is not None:
        try:
            print(f"taucli: error: {err}", file=stderr)
        except (OSError, ValueError):
            pass
    return int(ExitStatus.OUTPUT)
