"""Batch mode: many scenes in one process, JSON lines in, JSON lines out.

Each input line is a JSON object whose keys are the scene's option names (``m1``,
``pulley_mass``; ``pulley-mass`` reads too) and whose values are unit strings or numbers (a
number is SI); ``null`` leaves an option out. A line may also say ``to`` and ``no_steps``.
Options given on the command line with ``--batch`` apply to every line that does not give its
own. Each output line is the document ``--json`` prints for that scene. A line that fails gives
an error object in its place, naming the key, and the run goes on:

    {"taucli": "0.1.0", "line": 3, "error": {"option": "m1", "message": "m1: expected a mass ..."}}

Blank lines are skipped (every other line gives one line out). Lines are read, solved and
written one at a time; memory stays flat however long the input (a line is at most MAX_LINE
characters), and only whole lines reach the reader: each write holds whole lines, and on SIGTERM
or SIGINT the line in hand is finished and written before the run ends. SIGKILL cannot be
caught: a line longer than a pipe takes at once (PIPE_BUF, 4,096 bytes: a document with its
steps) may then be left part written. Output is flushed whenever no further input is waiting, so a person
typing lines sees each answer at once, and a file or pipe of many lines is written in blocks. The exit status is 0 when every line gave a
document, 2 when some line was bad input, 1 when some line met a bug.
"""

from __future__ import annotations

import gc
import json
from collections import Counter
import os
import select
import signal
import stat
from collections.abc import Iterator

from taucli.core.version import __version__
from taucli.answering.answer import solve
from taucli.core.errors import ExitStatus, InputError, TaucliError, bounded, clipped, did_you_mean, out_of_range
from taucli.writing.document import document_text
from taucli.writing.render import Output, prepared
from taucli.options.table import FLAG, Command

PER_LINE_OUTPUT = ("to", "no_steps")  # how to answer, which a line may say for itself
FINDING = ("find", "want", "minimize", "maximize")  # --find NAME --want RESULT=VALUE (#22), which a line may say for itself
_EXAMPLE_LINE = '{"m1": "4kg", "m2": "1kg"}'
# A write of at most PIPE_BUF bytes reaches a pipe whole (POSIX): lines are written in blocks
# of no more than this, each block ending a line, so a run that is killed leaves whole lines.
BLOCK_BYTES = 4096
# The longest line read (1 MiB of characters: a scene's line is under a kilobyte): a longer one, or
# input with no line end at all (/dev/zero), gives an error object and the rest of it is passed
# over a block at a time, so memory stays flat whatever comes in.
MAX_LINE = 1 << 20


def run(command: Command, fixed: dict, output: Output, env, *, limit: float | None = None) -> int:
    """Solve one scene per line of ``env.stdin``; ``fixed`` holds the command line's options;
    ``limit`` bounds each line's --find (seconds, estimated)."""
    lines = env.stdin
    if lines is None:
        raise InputError("batch", "reads JSON lines on stdin, but stdin is closed", example="taucli atwood --batch < scenes.jsonl")
    interactive = getattr(lines, "isatty", lambda: False)()
    whole = _a_file(lines)  # all of it there already: no one to wait for, so write in blocks without asking
    if interactive:
        print("taucli: reading scenes as JSON lines from the terminal, one per line; Ctrl-D ends", file=env.stderr)
    if fixed.get("torque_profile") == "-":
        raise InputError("torque_profile", "cannot be - with {batch}: stdin holds the scenes", example='"torque_profile": "pulse.csv"')
    keys = _keys(command)
    texts = frozenset(option.name for option in command.options if option.sweepable)  # one quantity's text each
    out, encoding = _sink(env.stdout)
    failures = {ExitStatus.USAGE: 0, ExitStatus.INTERNAL: 0}
    first_failure = None
    number = solved = 0
    pending: list = []  # texts, or their bytes where the stream has a byte buffer
    size = 0
    signals = _Signals()
    gc.freeze()  # what start-up made (modules, tables, the unit cache) lives on: the collector need not walk it after every few lines
    try:
        for number, line in enumerate(_lines(lines), start=1):
            signals.busy = True  # from here until the line's answer is out, a signal waits for it
            if line.__class__ is str and not line.strip():  # a blank line (a file's last newline, a spacer a person typed): nothing to solve
                signals.idle()
                continue
            solved += 1
            try:
                if line.__class__ is not str:
                    raise line
                given, answer = _line(line, keys, command, texts)
                if fixed:  # (a line's own dict, made for it: no copy needed where the command line gave nothing)
                    given = {**fixed, **given}
                report = solve(command, given, find=given.pop("find", None), want=given.pop("want", None), limit=limit,
                               minimize=given.pop("minimize", None), maximize=given.pop("maximize", None))  # notes name keys as a line gives them (#42)
                shown = output._replace(**answer) if answer else output
                text = document_text(prepared(report, shown), steps=shown.steps) + "\n"
            except TaucliError as err:
                text = _error(number, err.exit_status, err, failures)
                first_failure = first_failure or number
            except OverflowError:
                text = _error(number, ExitStatus.USAGE, out_of_range(), failures)
                first_failure = first_failure or number
            except (KeyboardInterrupt, BrokenPipeError):
                raise
            except Exception as err:  # a bug: reported on its line, and the run goes on
                text = _error(number, ExitStatus.INTERNAL, err, failures)
                first_failure = first_failure or number
            if encoding is not None:  # encoded once: to count its bytes, and to write them
                text = text.encode(*encoding)
                length = len(text)
            else:
                length = len(text) if text.isascii() else len(text.encode())
            if pending and size + length > BLOCK_BYTES:
                _write(out, pending)
                pending, size = [], 0
            pending.append(text)
            size += length
            if interactive or line.__class__ is not str or not (whole or _waiting(lines)):  # a line too long: its error now, before the rest is passed over
                _write(out, pending)
                pending, size = [], 0
            signals.idle()
    except _Stopped:
        pass
    finally:
        signals.restore()
        gc.unfreeze()
    _write(out, pending)
    if signals.caught is not None:
        return _stopped(signals.caught, env)
    failed = sum(failures.values())
    if not failed:
        return int(ExitStatus.OK)
    print(f"taucli: error: {failed} of {solved} lines failed (the first: line {first_failure})", file=env.stderr)
    return int(ExitStatus.INTERNAL if failures[ExitStatus.INTERNAL] else ExitStatus.USAGE)


class _Stopped(BaseException):
    """SIGTERM or SIGINT came while no line was in hand: the run ends now."""


class _Signals:
    """SIGTERM and SIGINT during a batch. A line being solved or written is finished first (the
    signal is noted, and a write it interrupts goes on: Python retries it), then the run ends;
    while taucli waits for input, the run ends at once. Either way only whole lines are written.
    Outside the main thread Python's own handling stays."""

    def __init__(self) -> None:
        self.busy = False
        self.caught: int | None = None
        self.saved: dict = {}
        try:
            for number in (signal.SIGINT, signal.SIGTERM):
                self.saved[number] = signal.signal(number, self._caught)
        except (ValueError, OSError, AttributeError):
            self.restore()

    def _caught(self, number: int, frame) -> None:
        self.caught = number
        if not self.busy:
            raise _Stopped

    def idle(self) -> None:
        """The line in hand is answered: end here if a signal came meanwhile."""
        self.busy = False
        if self.caught is not None:
            raise _Stopped

    def restore(self) -> None:
        for number, handler in self.saved.items():
            signal.signal(number, handler if handler is not None else signal.SIG_DFL)
        self.saved = {}


def _stopped(number: int, env) -> int:
    """The end of a run that a signal stopped, once every whole line is out: Ctrl-C's status, or
    the process ends by SIGTERM, as it would have without taucli's handler."""
    if number == signal.SIGINT:
        print(file=env.stderr)
        return int(ExitStatus.INTERRUPTED)
    signal.signal(number, signal.SIG_DFL)
    os.kill(os.getpid(), number)
    return 128 + number


def _too_long(start: str) -> InputError:
    return InputError("", f"a line is at most {MAX_LINE:,} characters (1 MiB); expected a JSON object of options", example=_EXAMPLE_LINE,
                      got=f"a longer line starting {start[:40]!r}")


def _lines(stream) -> Iterator:
    """The lines of ``stream``, each read at most MAX_LINE characters (bytes, from a byte stream)
    at a time: a line, or the InputError of a line that is longer (the rest of it is then read and
    passed over). Where the stream has a byte buffer (stdin), lines are read as bytes and each is
    decoded as UTF-8, whatever the locale says (JSON is UTF-8, RFC 8259): a byte that is not
    UTF-8 stays in its line as an escape (surrogateescape), so that line is answered or refused
    on its own, and the others are read as written."""
    buffer = getattr(stream, "buffer", None)
    readline = getattr(buffer if buffer is not None else stream, "readline", None)
    if readline is None:  # a list of lines
        yield from (line if len(line) <= MAX_LINE else _too_long(line) for line in stream)
        return
    end = "\n" if buffer is None else b"\n"
    while line := readline(MAX_LINE + 1):
        if len(line) <= MAX_LINE or line.endswith(end):
            yield line if buffer is None else line.decode("utf-8", "surrogateescape")
            continue
        yield _too_long(line if buffer is None else line[:80].decode("utf-8", "surrogateescape"))
        while (rest := readline(MAX_LINE)) and not rest.endswith(end):
            pass


def _a_file(lines) -> bool:
    """Whether ``lines`` reads a regular file (not a terminal, pipe or socket)."""
    try:
        return stat.S_ISREG(os.fstat(lines.fileno()).st_mode)
    except (OSError, ValueError, AttributeError, TypeError):
        return False


def _waiting(lines) -> bool:
    """Whether more input is ready now, so that writing can wait for it; a file or pipe that
    cannot be asked (a list of lines) counts as ready."""
    try:
        ready, _, _ = select.select([lines], [], [], 0)
    except (OSError, ValueError, TypeError, AttributeError):
        return True
    return bool(ready)


def _sink(stream) -> tuple:
    """Where the blocks go: the stream's byte buffer and (encoding, errors) where it has one, else
    the stream itself and None."""
    buffer, encoding = getattr(stream, "buffer", None), getattr(stream, "encoding", None)
    if buffer is None or not isinstance(encoding, str):
        return stream, None
    stream.flush()  # anything written to it as text goes first
    return buffer, (encoding, getattr(stream, "errors", None) or "strict")


def _write(out, pending: list) -> None:
    """The pending lines, in one write where the stream takes them at once; the rest of them, when a
    raw stream (PYTHONUNBUFFERED=1) takes only part (a signal, a full pipe), until all is out."""
    if not pending:
        return
    block = pending[0][:0].join(pending)  # "" or b"", as the pending lines are
    if isinstance(block, str):
        out.write(block)
    else:
        view = memoryview(block)
        while view:
            written = out.write(view)
            if written is None:  # a non-blocking stream that is full: wait until it takes more
                select.select([], [out], [])
                continue
            view = view[written:]
    out.flush()


def _error(number: int, status: ExitStatus, err: Exception, failures: dict) -> str:
    if isinstance(err, InputError):
        option, message = err.option or None, str(err)
    elif isinstance(err, TaucliError):
        option, message = None, str(err)
    else:
        option, message = None, f"internal error ({type(err).__name__}: {err}); this is a bug in taucli, please report it"
    failures[status] = failures.get(status, 0) + 1
    error = {"option": option and bounded(clipped(option)), "message": bounded(" ".join(message.split()))}
    return json.dumps({"taucli": __version__, "line": number, "error": error}, ensure_ascii=False, separators=(",", ":")) + "\n"


def _reject_constant(name: str):
    raise ValueError(f"{name} is not a number JSON allows")


class _Pairs(dict):
    """A JSON object that gave a key more than once (json.loads keeps the last unsaid), with those keys."""

    def __init__(self, pairs: list) -> None:
        super().__init__(pairs)
        self.twice = {key for key, count in Counter(key for key, _ in pairs).items() if count > 1}


def _object(pairs: list) -> dict:
    """A JSON object: a plain dict (made in C: every line has one), or _Pairs where a key comes twice."""
    found = dict(pairs)
    return found if len(found) == len(pairs) else _Pairs(pairs)


def _number(text: str):
    """A JSON number as a float; one written nonzero that a double rounds to 0 (1e-400) as its
    text, which is then read, and bounded, as what was written (not as 0)."""
    value = float(text)
    if value == 0 and any(digit in "123456789" for digit in text.lower().partition("e")[0]):
        return text
    return value


_STRICT = json.JSONDecoder(parse_constant=_reject_constant, parse_float=_number, object_pairs_hook=_object)


def _keys(command: Command) -> dict[str, str]:
    """Every key a line may use (``pulley_mass``, ``pulley-mass``, ``--pulley-mass``) -> the option's name."""
    names = [option.name for option in command.options] + list(PER_LINE_OUTPUT) + list(FINDING)
    keys = {}
    for name in names:
        for key in (name, name.replace("_", "-"), "--" + name.replace("_", "-")):
            keys[key] = name
    return keys


def _line(line: str, keys: dict[str, str], command: Command, texts: frozenset[str] = frozenset()) -> tuple[dict, dict]:
    """The options of one line, and what it says of how to answer (to, no_steps). ``texts``: the
    options whose value is one quantity's text, passed on as it is unless it is a range or list."""
    text = line.strip()
    try:
        given = _STRICT.decode(text)
    except ValueError as err:
        raise InputError("", "expected a JSON object of options", example=_EXAMPLE_LINE, got=f"{text[:60]!r} ({err})") from None
    except RecursionError:  # arrays or objects nested some thousand deep
        raise InputError("", "expected a JSON object of options, not values nested this deep", example=_EXAMPLE_LINE, got=repr(text[:60])) from None
    if not isinstance(given, dict):
        raise InputError("", "expected a JSON object of options", example=_EXAMPLE_LINE, got=repr(text[:60]))
    options: dict = {}
    answer: dict = {}
    spelled: dict[str, str] = {}  # option name -> the key that gave it (pulley_mass and pulley-mass are one option)
    twice = given.twice if given.__class__ is _Pairs else ()
    for key in given:  # every key first: a key given twice is refused before any value is read
        name = keys.get(key)
        if name is None:
            known = [option.name for option in command.options]
            raise InputError(key, f"is not an option of {command.name} in a batch", hint=did_you_mean(key.replace("-", "_"), known))
        if key in twice:
            raise InputError(name, "is given twice in one line; an option takes one value (a list where it is repeatable): give it once",
                             example=_EXAMPLE_LINE, got=repr(text[:60]))
        if name in spelled:
            raise InputError(name, f"is given twice in one line (as {spelled[name]!r} and {key!r}): give it once", example=_EXAMPLE_LINE, got=repr(text[:60]))
        spelled[name] = key
    for key, value in given.items():
        name = keys[key]
        if value is None:
            continue
        if name == "to":
            answer["to"] = tuple(value if isinstance(value, list) else [value])
            if not all(isinstance(to, str) for to in answer["to"]):
                raise InputError("to", "expected a text NAME=UNIT or a list of them", example='"to": ["a=ft/s^2", "T1=lbf"]', got=json.dumps(value)[:80])
        elif name == "no_steps":
            answer["steps"] = not _flag(value, name)
        elif name in FINDING:
            options[name] = value
        elif value.__class__ is str and name in texts and ".." not in value and "," not in value:
            options[name] = value  # the usual value: one quantity's text
        else:
            option = command.option(name)
            if option.kind == FLAG:
                value = _flag(value, name)
            elif isinstance(value, bool):
                raise InputError(name, "expected a number or a text with a unit, not true or false", example='"4kg"')
            elif isinstance(value, str) and (".." in value or "," in value) and option.sweepable:
                raise InputError(name, "cannot be a range or a list in a batch: give one scene per line", got=repr(value))
            options[name] = value
    return options, answer


def _flag(value, name: str) -> bool:
    if not isinstance(value, bool):
        raise InputError(name, "expected true or false", got=json.dumps(value))
    return value
