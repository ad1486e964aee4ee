"""--help fits the terminal, and every example in help and in the docs can be typed as shown (#36 item 4).

Help is wrapped at the terminal's width, at spaces only: no line is longer than the width, and no
value (``'0.1kg*m^2'``) is cut. A long ``Example:`` goes on over lines ending in a backslash,
which bash, zsh and fish all read as one command. Every example quotes a value holding a
character a shell would glob or choke on (``* ? [ ^ (``): zsh says "no matches found" for an
unquoted ``0.3N*m`` before taucli runs, fish "No matches for wildcard".
"""

from __future__ import annotations

import re

import pytest

from conftest import documents_text
from taucli.front import help
from taucli.options import COMMANDS
from taucli.options.tools import ROOT
from terminal import SHELLS, WIDTHS, Terminal

ALL = (ROOT, *COMMANDS.values())
SCENE_EXAMPLES = [command for command in COMMANDS.values() if command.library is not None]
GLOB = set("*?[^(")


def _help(command, columns: int, monkeypatch) -> str:
    monkeypatch.setenv("COLUMNS", str(columns))
    return help.text(command)


def unquoted_glob(command_line: str) -> list[str]:
    """The characters of ``command_line`` outside quotes that a shell would glob or choke on
    (``$(…)`` and ``$?`` are the shell's own)."""
    bad, quote, i = [], None, 0
    while i < len(command_line):
        c = command_line[i]
        if quote:
            quote = None if c == quote else quote
        elif c in "'\"":
            quote = c
        elif c == "\\" or (c == "$" and command_line[i + 1 : i + 2] in ("(", "?")):
            i += 1
        elif c in GLOB:
            bad.append(c)
        i += 1
    return bad


def test_unquoted_glob_finds_what_a_shell_globs():
    assert unquoted_glob("taucli spin-down --friction 0.3N*m") == ["*"]
    assert unquoted_glob("taucli spin-down --friction '0.3N*m' --to \"I=g*cm^2\"") == []
    assert unquoted_glob("--want a=4.0m/s^2") == ["^"]
    assert unquoted_glob("XDG_CACHE_HOME=$(mktemp -d) taucli --help; echo $?") == []


@pytest.mark.parametrize("columns", [30, 40, 60, 80])
def test_no_help_line_is_wider_than_the_terminal(columns, monkeypatch):
    for command in ALL:
        for line in _help(command, columns, monkeypatch).splitlines():
            assert len(line) <= columns, f"{command.name} at {columns}: {line!r}"


@pytest.mark.parametrize("columns", [30, 40, 80])
def test_a_value_is_never_cut(columns, monkeypatch):
    """Each word holding a unit or an example (``'0.1kg*m^2'``, ``9.80665``) is whole on one line."""
    for command in ALL:
        shown = _help(command, columns, monkeypatch)
        words = set(shown.split())
        for option in (*command.options, *command.output):
            for word in option.help_text().split():
                if re.search(r"\d", word) and "|" not in word:
                    assert word in words, f"{command.name} {option.flag} at {columns}: {word!r} was cut"


@pytest.mark.parametrize("columns", [40, 80])
def test_a_long_example_goes_on_with_backslashes(columns, monkeypatch):
    text = _help(COMMANDS["drive"], columns, monkeypatch)
    block = text.split("Example:", 1)[1].split("\n\n", 1)[0]
    lines = [line.strip() for line in block.strip("\n").splitlines()]
    assert all(line.endswith(" \\") for line in lines[:-1]) and not lines[-1].endswith("\\")
    assert " ".join(line.removesuffix(" \\") for line in lines) == COMMANDS["drive"].example


def _help_examples() -> list[tuple[str, str]]:
    """(where, text) for every example taucli's help gives: each command's Example and every
    ``e.g. …`` or ``--option VALUE`` in its summary, description and options' help."""
    found = []
    for command in ALL:
        found.append((f"{command.name} Example", command.example))
        texts = [command.summary, command.description, *(o.help_text() for o in (*command.options, *command.output))]
        for text in texts:
            for match in re.finditer(r"e\.g\.\s+((?:--[a-z0-9-]+\s+)?(?:'[^']*'|\"[^\"]*\"|[^\s,;)])+)", text):
                found.append((command.name, match[1]))
            for match in re.finditer(r"--[a-z0-9-]+ ((?:'[^']*'|\"[^\"]*\"|[^\s,;)(])+)", text):
                if not match[1].isupper():
                    found.append((command.name, match[0]))
        for value in re.findall(r"units: (.*?)\. ", command.description):
            found.extend((command.name, part) for part in re.findall(r"'[^']*'|[^,\s]+(?: [^,\s]+)?", value))
    return found


def _document_examples() -> list[tuple[str, str]]:
    """(where, command line) for every command in README and docs/: ``$ `` lines of console
    blocks, every line of sh blocks, and inline code that starts with ``taucli `` or ``--``."""
    found = []
    for name, text in documents_text():
        block = None
        for number, line in enumerate(text.splitlines(), 1):
            if line.startswith("```"):
                block = line[3:].strip() if block is None else None
                continue
            where = f"{name}:{number}"
            if block == "console" and line.startswith("$ "):
                found.append((where, line[2:]))
            elif block in ("sh", "bash", "zsh", "fish") and not line.lstrip().startswith("#"):
                found.append((where, line))
            elif block is None:
                found.extend((where, code) for code in re.findall(r"`([^`]+)`", line)
                             if code.startswith(("taucli ", "--")) and not re.search(r"[A-Z]{2,}\[", code))  # not a syntax: --x COLUMN[=OPTION]
    return found


def test_every_example_in_help_is_quoted_for_every_shell():
    examples = _help_examples()
    assert len(examples) > 50
    bad = [(where, text) for where, text in examples if unquoted_glob(text)]
    assert not bad, f"quote these for zsh and fish: {bad}"


def test_every_example_in_the_docs_is_quoted_for_every_shell():
    examples = _document_examples()
    assert len(examples) > 300
    bad = [(where, text) for where, text in examples if unquoted_glob(text)]
    assert not bad, f"quote these for zsh and fish: {bad}"


@pytest.mark.parametrize("shell", SHELLS)
@pytest.mark.parametrize("columns", WIDTHS)
def test_help_fits_a_real_terminal(shell, columns):
    """In a terminal of that width (no COLUMNS set), as a person sees it."""
    terminal = Terminal(shell, columns)
    try:
        for name in ("atwood", "drive"):
            shown, status = terminal.run(f"taucli {name} --help")
            assert status == 0
            lines = shown.splitlines()
            assert len(lines) > 40
            assert max(len(line) for line in lines) <= columns
    finally:
        terminal.close()


@pytest.mark.parametrize("shell", SHELLS)
def test_each_example_as_shown_at_40_columns_runs(shell):
    """Each scene's Example, copied from its help at 40 columns (lines ending in a backslash),
    runs in the shell as it is."""
    terminal = Terminal(shell, 40)
    try:
        for command in SCENE_EXAMPLES:
            shown, status = terminal.run(f"taucli {command.name} --help")
            block = shown.split("Example:", 1)[1].split("\n\n", 1)[0].strip("\n")
            typed = "\n".join(line.strip() for line in block.splitlines())
            assert "\\\n" in typed or len(command.example) <= 38
            printed, status = terminal.run(typed + " --no-steps")
            assert status == 0, f"{shell}: {typed}\n{printed}"
    finally:
        terminal.close()


def test_every_kinds_example_is_typed_for_every_shell():
    """The example an error message gives for a kind ("(e.g. '0.3 N*m')") works as typed."""
    from taucli.quantities.kinds import KINDS

    assert not [kind.example for kind in KINDS.values() if unquoted_glob(kind.example)]
