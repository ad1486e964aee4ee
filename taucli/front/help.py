"""``--help``, written from the commands' tables: no typer, no rich, no cache.

    taucli --help          the commands, taucli's own options, the exit statuses
    taucli atwood --help   the command's summary, results, example and options by panel
    taucli help [COMMAND]  the same as --help

``requested`` finds a help request in the arguments as click would: -h or --help where it is not
the value of an option that takes one, before any ``--``.
"""

from __future__ import annotations

import os
import re
import shutil
import sys

from taucli.core.errors import bounded, did_you_mean
from taucli.core.version import __version__
from taucli.options import COMMANDS, SCENES
from taucli.options.tools import EXIT_STATUSES, ROOT
from taucli.writing.report import pretty_unit
from taucli.options.table import Command, Option

HELP_WORDS = ("-h", "--help")
UNKNOWN = object()  # taucli help WORD where WORD names no command
HELP_LINE = ("-h, --help", "Show this message and exit.")


def requested(args: list[str]) -> Command | None:
    """The command whose help ``args`` ask for (ROOT for taucli's own), or None."""
    if not args:
        return ROOT
    at = next((i for i, word in enumerate(args) if not word.startswith("-")), len(args))
    if any(word in HELP_WORDS for word in args[:at]):
        return ROOT
    if at == len(args):
        return None
    if args[at] == "help":  # taucli help, taucli help atwood: as --help; taucli help nonsense: no help to give
        return COMMANDS.get(args[at + 1], UNKNOWN) if at + 1 < len(args) else ROOT
    command = COMMANDS.get(args[at])
    if command is None:
        return None
    takes_value = {option.flag for option in (*command.options, *command.output) if option.takes_value and not option.positional}
    words = iter(args[at + 1 :])
    for word in words:
        if word == "--":
            return None
        if word in HELP_WORDS or (word == "help" and not any("help" in option.choices for option in command.options if option.positional)):
            return command  # (taucli atwood help, taucli inertia help: as --help, where "help" is no argument's value)
        if word in takes_value:
            next(words, None)
    return None


NARROW = 60  # below this many columns an option's help goes under its name, not beside it


def width() -> int:
    """The columns help may fill: the terminal's width less 2 (at most 78), at least 20.

    Every line fits: help breaks only at spaces, so a value (``'0.1kg*m^2'``) is never split.
    """
    return max(min(shutil.get_terminal_size((80, 24)).columns, 80) - 2, 20)


def _wrap(text: str, columns: int, indent: str, later: str | None = None) -> list[str]:
    """``text`` in lines of at most ``columns``, broken at spaces, never inside a word: a value
    (``'0.1kg*m^2'``) stays whole. A list of choices too long for a line (``a|b|c``) may break
    after a ``|``; any other word longer than a line stands alone on its line."""
    later = indent if later is None else later
    pieces: list[tuple[str, bool]] = []  # (piece, whether a space goes before it)
    for word in text.split():
        if len(word) + len(later) > columns and "|" in word:
            parts = word.split("|")
            pieces += [(part + "|", i == 0) for i, part in enumerate(parts[:-1])] + [(parts[-1], False)]
        else:
            pieces.append((word, True))
    lines: list[str] = []
    line = ""
    for piece, spaced in pieces:
        lead = indent if not lines else later
        joined = f"{line} {piece}" if line and spaced else line + piece
        if line and len(lead) + len(joined) > columns:
            lines.append(lead + line)
            line = piece
        else:
            line = joined
    if line:
        lines.append((indent if not lines else later) + line)
    return lines


def _paragraph(text: str, columns: int) -> list[str]:
    return _wrap(text, columns, "  ") + [""]


def _definitions(rows: list[tuple[str, str]], columns: int) -> list[str]:
    """Two columns, the second wrapped beside the first (or below it when the first is long, or
    the terminal narrow)."""
    first = min(max(len(term) for term, _ in rows), 30) + 2
    if columns < NARROW:
        first = 0
    lines = []
    for term, text in rows:
        if not first or len(term) + 2 > first:
            lines.extend(_wrap(term, columns, "  ", "      "))
            lines.extend(_wrap(text, columns, " " * (first + 2 if first else 6)))
        else:
            wrapped = _wrap(text, columns - first - 2, "") or [""]
            lines.append(f"  {term.ljust(first)}{wrapped[0]}".rstrip())
            lines.extend(" " * (first + 2) + part for part in wrapped[1:])
    return lines


def example_lines(example: str, columns: int) -> list[str]:
    """``Example:`` and a command line that fits: broken before an option with a backslash, which
    bash, zsh and fish all read as the line going on, so it can be copied as shown."""
    one = f"  Example: {example}"
    if len(one) <= columns:
        return [one]
    words = []
    for word in _shell_words(example):  # an option and its value part only where the pair is too long for a line
        words += word.split(" ", 1) if len(word) + 8 > columns and not word.startswith(("'", '"')) else [word]
    lines, line = [], "    " + words[0]
    for word in words[1:]:
        joined = f"{line} {word}"
        # keep an option with its value: break before a word that starts an option
        if len(joined) + 2 > columns and line.strip():
            lines.append(line + " \\")
            line = "      " + word
        else:
            line = joined
    return ["  Example:", *lines, line]


def _shell_words(command: str) -> list[str]:
    """The words of a command line as typed, quotes kept, an option joined to its value where the
    pair fits (``--m1 4kg``), and a redirection to its target (``> FILE``)."""
    words = re.findall(r"""(?:'[^']*'|"[^"]*"|[^\s'"])+""", command)
    joined: list[str] = []
    for word in words:
        if joined and (not word.startswith("-") and (joined[-1].startswith("-") and " " not in joined[-1] or joined[-1] in ("|",))):
            joined[-1] += " " + word
        else:
            joined.append(word)
    return joined


def _term(option: Option) -> str:
    return option.flag if option.positional or not option.takes_value else f"{option.flag} {option.shown_metavar}"


def text(command: Command) -> str:
    """The help of ``command`` (ROOT: taucli's own), as lines ending in a newline."""
    columns = width()
    if command is ROOT:
        lines = [*_wrap("Usage: taucli [OPTIONS] COMMAND [ARGS]...", columns, "", "  "), ""]
        for paragraph in (command.summary, command.description, EXIT_STATUSES):
            lines += _paragraph(paragraph, columns)
        lines.append("Options:")
        lines += _definitions([*((_term(o), o.help_text()) for o in command.options), HELP_LINE], columns)
        lines += ["", "Commands:"]
        lines += _definitions([(c.name, c.summary) for c in COMMANDS.values()], columns)
        return "\n".join(lines) + "\n"
    arguments = " ".join(f"[{option.flag}]" if option.default else option.flag for option in command.options if option.positional)
    lines = [*_wrap(f"Usage: taucli {command.name} [OPTIONS]{' ' + arguments if arguments else ''}", columns, "", "  "), ""]
    lines += _paragraph(command.summary, columns)
    if command.description:
        lines += _paragraph(command.description, columns)
    if command.results:
        lines += _paragraph(f"Results: {command.results_line()}.", columns)
    lines += [*example_lines(command.example, columns), ""]
    sections: dict[str, list[tuple[str, str]]] = {}
    for option in (*command.options, *command.output):
        title = "Arguments" if option.positional else option.panel or "Options"
        sections.setdefault(title, []).append((_term(option), option.help_text()))
    sections.setdefault("Options", []).append(HELP_LINE)
    for title, rows in sections.items():
        lines += _wrap(f"{title}:", columns, "", "  ")
        lines += _definitions(rows, columns)
        lines.append("")
    lines += _paragraph(EXIT_STATUSES, columns)
    if command.name in SCENES:
        lines += _paragraph(f"More, with worked examples: {page(command)} in taucli's source (its README lists every page).", columns)
    return "\n".join(lines).rstrip("\n") + "\n"


def page(command: Command) -> str:
    """The path of a scene's reference page in taucli's source."""
    return f"docs/{command.name}.md"


def answer(args: list[str], stdout, stderr) -> int | None:
    """Answer a help or version request in ``args`` (the exit status), or None for anything else.

    ``taucli`` alone prints taucli's help on stderr and is a usage error (exit 2).
    """
    at = next((i for i, word in enumerate(args) if not word.startswith("-")), len(args))
    command = requested(args)
    if command is None and "--version" not in args[:at]:
        return None
    if command is UNKNOWN:
        word = args[at + 1]
        guess = did_you_mean(word, list(COMMANDS))
        stderr.write(f"taucli: error: help: expected a command ({', '.join(COMMANDS)}), got {bounded(repr(word))}"
                     f"{'; ' + guess if guess else ''} (e.g. taucli help atwood)\n")
        return 2
    stream = stderr if not args else stdout
    try:
        if command is None:
            stream.write(f"taucli {__version__}\n")
        else:
            stream.write(text(command))
        stream.flush()
    except BrokenPipeError:
        os.dup2(os.open(os.devnull, os.O_WRONLY), stream.fileno())
    return 2 if not args else 0


# Each scene's page in docs/ holds its options and results as generated here, between these
# markers; tests/test_table.py checks them, and ``python -m taucli.front.help docs`` rewrites them.
TABLE_START = "<!-- options of {name}: generated from its table by `python -m taucli.front.help docs` -->"
TABLE_END = "<!-- end of the options of {name} -->"


def markdown(command: Command) -> str:
    """The options and results of a scene as Markdown tables, for its page in docs/."""
    lines = ["| option | takes | what it is |", "|---|---|---|"]
    for option in command.options:
        takes = option.kind + ("".join(f" or {kind}" for kind in option.also_kinds)) if option.is_quantity else option.shown_metavar.replace("|", " or ")
        lines.append(f"| `{option.flag}` | {takes} | {option.help_text().replace('|', '/')} |")
    lines += ["", "| result | unit | what it is |", "|---|---|---|"]
    for result in command.results:
        needs = f" — needs {result.needed(lambda name: f'`{command.flag(name)}`')}" if result.needs else ""
        lines.append(f"| `{result.key}` | {pretty_unit(result.unit) or '–'} | {result.label}{needs} |")
    return "\n".join(lines)


def update_pages(folder: str) -> bool:
    """Rewrite the generated tables of each scene's page in ``folder`` (docs/); whether any changed."""
    changed = False
    for command in (*SCENES.values(), COMMANDS["fit"]):  # fit: not a scene, and its page holds its table too
        path = os.path.join(folder, f"{command.name}.md")
        with open(path, encoding="utf-8") as handle:
            old = handle.read()
        start, end = TABLE_START.format(name=command.name), TABLE_END.format(name=command.name)
        if start not in old:
            raise SystemExit(f"{path} has no generated table (the line {start!r})")
        before, _, rest = old.partition(start)
        _, _, after = rest.partition(end)
        new = f"{before}{start}\n{markdown(command)}\n{end}{after}"
        if new != old:
            with open(path, "w", encoding="utf-8") as handle:
                handle.write(new)
            changed = True
    return changed


if __name__ == "__main__":
    sys.exit(1 if update_pages(sys.argv[1]) else 0)
