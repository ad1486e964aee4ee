"""Exit statuses and the errors a user can cause.

Every error carries structured fields and builds its one-line message in ``__str__``;
``cli.main`` is the one funnel that turns them into a line on stderr and an exit status.
"""

from __future__ import annotations

from enum import IntEnum


class ExitStatus(IntEnum):
    """The exit statuses taucli uses, and only these."""

    OK = 0
    INTERNAL = 1  # a bug in taucli: the message asks for a report
    USAGE = 2  # bad input: wrong unit, bad number, missing or conflicting option
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
        self.option = option
        self.expected = expected
        self.got = got
        self.example = example
        self.hint = hint

    def __str__(self) -> str:
        # "--mass is required ..." reads as a sentence; "--mass: expected a mass" as a label.
        joiner = " " if self.expected.split(" ", 1)[0] in _VERBS else ": "
        message = f"{self.option}{joiner}{self.expected}" if self.option else self.expected
        if self.example:
            message += f" (e.g. {self.example})"
        if self.got is not None:
            message += f", got {self.got}"
        if self.hint:
            message += f"; {self.hint}"
        return message


def out_of_range() -> InputError:
    """What an OverflowError from a solver means: inputs so large (or small) that a result passes
    the largest double. Float ``**`` and math functions raise where ``*`` would give inf."""
    return InputError(
        "", "the inputs are out of range: a result would pass the largest number a double holds (about 1.8e308)",
        hint="give magnitudes nearer everyday sizes",
    )


def did_you_mean(name: str, choices, cutoff: float = 0.6) -> str | None:
    """'did you mean ...?' for the closest of ``choices`` to a mistyped ``name``, or None."""
    import difflib

    close = difflib.get_close_matches(name, list(choices), n=1, cutoff=cutoff)
    return f"did you mean {close[0]!r}?" if close else None
