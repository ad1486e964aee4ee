"""One pipeline for every way in: text -> read (the command's table) -> library -> Report.

A single run, a sweep's point, a batch line and a Python call all come through ``solve``; none
of them calls back into a command of the command line.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable, Mapping
from functools import lru_cache
from typing import TextIO

from taucli.core.errors import InputError, Unused, as_named, spelled
from taucli.answering import cancels
from taucli.answering.inputs import read
from taucli.writing.report import Report
from taucli.options.table import Command


@lru_cache(maxsize=None)
def library(target: str) -> Callable[..., Report]:
    """The function named by a table's "module:function"."""
    module, _, name = target.partition(":")
    return getattr(importlib.import_module(module), name)


def _as_named(name: str) -> str:
    return name


def solve(
    command: Command, given: Mapping[str, object], *, stdin: TextIO | None = None, spell: Callable[[str], str] = _as_named
) -> Report:
    """The scene's report for the options ``given`` (names -> text, SI numbers, flags or lists).

    Notes name options as {name}; ``spell`` writes each as the caller's surface does (the
    command line: its flag; Python and batch: the name).
    """
    known = command.input_names.__contains__
    try:
        arguments, inputs = read(command, given, stdin=stdin)
        solver = library(command.library)
        try:
            report = solver(**arguments)
        except Unused as unused:
            if unused.option != "g" or not inputs.gravity_used:
                raise
            report = solver(**{name: value for name, value in arguments.items() if name != "g"})  # --g read a weight as a mass: it is used
        except InputError as error:
            found = cancels.stand_ins(arguments, error)  # a shape with no --mass: what the mass cancels from (#42 item 14)
            if found is None:
                raise
            report = cancels.without(solver, *found, error)
    except InputError as err:  # a solver's "--pulley-radius" is spelled as the caller's surface spells it (#42)
        raise err.named(known)
    # the library's report is made for this call alone: completed in place (a batch line makes one per line)
    report.notes = [_spoken(note, command, known, spell) for note in (*inputs.notes, *report.notes)]
    report.inputs = {**inputs.values, **report.inputs}
    return report


_SPOKEN: dict[tuple, str] = {}  # (command, surface, note) -> the note as that surface says it: most notes repeat line after line


def _spoken(note: str, command: Command, known: Callable[[str], bool], spell: Callable[[str], str]) -> str:
    """A note with each option named as the caller's surface names it (its flag, or its name)."""
    key = (command.name, spell, note)
    found = _SPOKEN.get(key)
    if found is None:
        found = as_named(note, known) if "--" in note else note
        found = spelled(found, spell, command.option) if "{" in found else found
        if len(_SPOKEN) < 4096:  # notes with numbers in them are new each time: bounded
            _SPOKEN[key] = found
    return found
