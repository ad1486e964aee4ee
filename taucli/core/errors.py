"""Exit statuses and the errors a user can cause.

Every error carries structured fields and builds its one-line message in ``__str__``;
``cli.main`` is the one funnel that turns them into a line on stderr and an exit status.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Mapping
from enum import IntEnum

from taucli.core.written import printable

_NAMED = re.compile(r"\{([a-z][a-z0-9_]*)\}")


def spelled(text: str, spell: Callable[[str], str], known: Mapping[str, object] | Callable[[str], object]) -> str:
    """``text`` with each {name} of a known option written as ``spell`` writes it (--name, name)."""
    found = known if callable(known) else known.get
    return _NAMED.sub(lambda m: spell(m[1]) if found(m[1]) is not None else m[0], text)


_FLAG = re.compile(r"(?<![\w-])--([a-z][a-z0-9]*(?:-[a-z0-9]+)*)")


def as_named(text: str, known: Callable[[str], bool]) -> str:
    """``text`` with each --flag of a ``known`` parameter written {name}, as ``spelled`` takes it: a
    note or a message a solver wrote with the command line's flag is then spelled per surface
    (--pulley-radius on the command line, pulley_radius in Python and batch, #42)."""
    return _FLAG.sub(lambda m: f"{{{m[1].replace('-', '_')}}}" if known(m[1].replace("-", "_")) else m[0], text)


class ExitStatus(IntEnum):
    """The exit statuses taucli uses, and only these."""

    OK = 0
    INTERNAL = 1  # a bug in taucli: the message asks for a report
    USAGE = 2  # bad input: wrong unit, bad number, missing or conflicting option
    OUTPUT = 74  # the answer could not be written: stdout closed, a full disk, an I/O error (sysexits' EX_IOERR)
    INTERRUPTED = 130  # Ctrl-C


_VERBS = {"is", "does", "needs", "conflicts", "knows", "must", "applies", "goes", "or", "and", "cannot", "are"}


class TaucliError(Exception):
    """Base of taucli's own errors."""

    exit_status = ExitStatus.INTERNAL


class InputError(TaucliError, ValueError):
    """A value or a combination of options the user gave cannot be used."""

    exit_status = ExitStatus.USAGE

    def __init__(
        self,
        option: str,
        expected: str,
        *,
        got: str | None = None,
        example: str | None = None,
        hint: str | None = None,
    ) -> None:
        super().__init__(option, expected, got, example, hint)
        if option.startswith("{") and option.endswith("}") and _PARAMETER.fullmatch(option[1:-1]):
            option = option[1:-1]  # "{m1}": a parameter's name written as the texts write one
        self.option = option
        self.expected = expected
        self.got = got
        self.example = example
        self.hint = hint

    def __str__(self) -> str:
        return self.spelled(lambda name: name)

    def named(self, known: Callable[[str], bool]) -> InputError:
        """Itself, each --flag of a ``known`` parameter in its texts written {name} (see as_named)."""
        if self.option.startswith("--") and known(self.option[2:].replace("-", "_")):
            self.option = self.option[2:].replace("-", "_")
        for field in ("expected", "example", "hint"):
            text = getattr(self, field)
            if text and "--" in text:
                setattr(self, field, as_named(text, known))
        return self

    def spelled(self, spell: Callable[[str], str]) -> str:
        """The one-line message, each parameter named as ``spell`` names it.

        The option, and each {name} in the texts, is a parameter's name (``pulley_mass``); the
        command line spells it as its flag (--pulley-mass), the Python API and batch as it is.
        """
        def name(text: str) -> str:
            return spelled(text, spell, lambda word: word)

        option = spell(self.option) if _PARAMETER.fullmatch(self.option) else name(self.option)
        # "--mass is required ..." reads as a sentence; "--mass: expected a mass" as a label.
        joiner = " " if self.expected.split(" ", 1)[0] in _VERBS else ": "
        option = clipped(option)
        message = f"{option}{joiner}{name(self.expected)}" if option else name(self.expected)
        if self.example:
            message += f" (e.g. {name(self.example)})"
        if self.got is not None:
            message += f", got {clipped(self.got, GOT)}"
        if self.hint:
            message += f"; {name(self.hint)}"
        return bounded(message)


_PARAMETER = re.compile(r"[a-z][a-z0-9_]*")

# A message quotes at most QUOTED characters of one word of what was typed (a 100 KB value, a
# 10 MB batch key), and its "got" part at most GOT: the start and the end, either side of "…".
QUOTED = 80
GOT = 2 * QUOTED
_LONG_WORD = re.compile(r"\S{%d,}" % (QUOTED + 1))


def clipped(text: str, limit: int = QUOTED) -> str:
    """``text`` as it is, or its start and end (``limit`` characters in all) either side of "…"."""
    if len(text) <= limit:
        return text
    tail = limit // 4
    return f"{text[: limit - tail - 1]}…{text[-tail:]}"


def bounded(message: str) -> str:
    """A message that can be written anywhere as UTF-8, on one line, and shown safely on a
    terminal: each control character of it (an ESC, a newline in a file's name) and each byte
    that was not UTF-8 (read as a lone surrogate) written as its escape, \\x1b, \\n, \\xff
    (taucli.core.written.printable); each word at most QUOTED characters."""
    return _LONG_WORD.sub(lambda word: clipped(word.group()), printable(message))


class Unused(InputError):
    """An option the scene has no use for with these inputs (--g with no weight to hold up). The
    pipeline passes it over instead where the reading of another input used it (a weight given
    for a mass, read with --g)."""


def out_of_range() -> InputError:
    """What an OverflowError from a solver means: inputs so large (or small) that a result passes
    the largest double. Float ``**`` and math functions raise where ``*`` would give inf."""
    return InputError(
        "", "the inputs are out of range: a result would pass the largest number a double holds (about 1.8e308)",
        hint="give magnitudes nearer everyday sizes",
    )


def did_you_mean(name: str, choices, cutoff: float = 0.6) -> str | None:
    """'did you mean ...?' for the closest of ``choices`` to a mistyped ``name``, or None."""
    import difflib  # deferred: only a mistyped name asks for a did-you-mean

    choices = list(choices)
    if len(name) > 2 * max((len(str(choice)) for choice in choices), default=0) + 8:
        return None  # far longer than any choice (a list of 2,000 values given for a shape): no near match, and difflib's time grows with its length
    close = difflib.get_close_matches(name, choices, n=1, cutoff=cutoff)
    return f"did you mean {close[0]!r}?" if close else None
