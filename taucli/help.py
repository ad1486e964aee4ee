"""``--help``, written from the commands' tables: no typer, no rich, no cache.

    taucli --help          the commands, taucli's own options, the exit statuses
    taucli atwood --help   the command's summary, results, example and options by panel

``requested`` finds a help request in the arguments as click would: -h or --help where it is not
the value of an option that takes one, before any ``--``.
"""

from __future__ import annotations

import os
import shutil
import sys
import textwrap

from taucli.version import __version__
from taucli.options import COMMANDS, SCENES
from taucli.options.tools import EXIT_STATUSES, ROOT
from taucli.report import pretty_unit
from taucli.table import Command, Option

HELP_WORDS = ("-h", "--help")
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
    command = COMMANDS.get(args[at])
    if command is None:
        return None
    takes_value = {option.flag for option in (*command.options, *command.output) if option.takes_value and not option.positional}
    words = iter(args[at + 1 :])
    for word in words:
        if word == "--":
            return None
        if word in HELP_WORDS:
            return command
        if word in takes_value:
            next(words, None)
    return None


def width() -> int:
    """As click's formatter: the terminal's width less 2, at most 78, at least 50."""
    return max(min(shutil.get_terminal_size((80, 24)).columns, 80) - 2, 50)


def _paragraph(text: str, columns: int) -> list[str]:
    return textwrap.wrap(text, columns, initial_indent="  ", subsequent_indent="  ", break_on_hyphens=False) + [""]


def _definitions(rows: list[tuple[str, str]], columns: int) -> list[str]:
    """Two columns, the second wrapped beside the first (or below it when the first is long)."""
    first = min(max(len(term) for term, _ in rows), 30) + 2
    lines = []
    for term, text in rows:
        wrapped = textwrap.wrap(text, max(columns - first - 2, 20), break_on_hyphens=False) or [""]
        if len(term) + 2 > first:
            lines.append(f"  {term}")
            lines.extend(" " * (first + 2) + part for part in wrapped)
        else:
            lines.append(f"  {term.ljust(first)}{wrapped[0]}".rstrip())
            lines.extend(" " * (first + 2) + part for part in wrapped[1:])
    return lines


def _term(option: Option) -> str:
    return option.flag if not option.takes_value else f"{option.flag} {option.shown_metavar}"


def text(command: Command) -> str:
    """The help of ``command`` (ROOT: taucli's own), as lines ending in a newline."""
    columns = width()
    if command is ROOT:
        lines = ["Usage: taucli [OPTIONS] COMMAND [ARGS]...", ""]
        for paragraph in (command.summary, command.description, EXIT_STATUSES):
            lines += _paragraph(paragraph, columns)
        lines.append("Options:")
        lines += _definitions([*((_term(o), o.help_text()) for o in command.options), HELP_LINE], columns)
        lines += ["", "Commands:"]
        lines += _definitions([(c.name, c.summary) for c in COMMANDS.values()], columns)
        return "\n".join(lines) + "\n"
    arguments = " ".join(option.flag for option in command.options if option.positional)
    lines = [f"Usage: taucli {command.name} [OPTIONS]{' ' + arguments if arguments else ''}", ""]
    lines += _paragraph(command.summary, columns)
    if command.description:
        lines += _paragraph(command.description, columns)
    if command.results:
        lines += _paragraph(f"Results: {command.results_line()}.", columns)
    lines += [f"  Example: {command.example}", ""]
    sections: dict[str, list[tuple[str, str]]] = {}
    for option in (*command.options, *command.output):
        title = "Arguments" if option.positional else option.panel or "Options"
        sections.setdefault(title, []).append((_term(option), option.help_text()))
    sections.setdefault("Options", []).append(HELP_LINE)
    for title, rows in sections.items():
        lines.append(f"{title}:")
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
# markers; tests/test_table.py checks them, and ``python -m taucli.help docs`` rewrites them.
TABLE_START = "<!-- options of {name}: generated from its table by `python -m taucli.help docs` -->"
TABLE_END = "<!-- end of the options of {name} -->"


def markdown(command: Command) -> str:
    """The options and results of a scene as Markdown tables, for its page in docs/."""
    lines = ["| option | takes | what it is |", "|---|---|---|"]
    for option in command.options:
        takes = option.kind + (f" or {option.also}" if option.also else "") if option.is_quantity else option.shown_metavar.replace("|", " or ")
        lines.append(f"| `{option.flag}` | {takes} | {option.help_text().replace('|', '/')} |")
    lines += ["", "| result | unit | what it is |", "|---|---|---|"]
    for result in command.results:
        lines.append(f"| `{result.key}` | {pretty_unit(result.unit) or '–'} | {result.label} |")
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
