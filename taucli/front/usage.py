"""What a command line the parser could not take was most likely meant to say, as the fix.

Asked only after typer (click) has refused the words, so a good run pays nothing. Each message
names the option and an example that works as typed in bash, zsh and fish:

    taucli atwood --m1 --m2 1kg          --m1 needs a value (e.g. --m1 4kg)
    taucli spin-down --torque 2 N m      --torque: a value with spaces is one word only in quotes
    taucli -help                         -help is not an option; did you mean --help?
"""

from __future__ import annotations

import re

from taucli.quantities.kinds import KINDS
from taucli.options.table import CHOICE, Command, Option

HELP_WORDS = ("-h", "--help")
_GLOB = re.compile(r"[*?\[\]^()\s'\"]")


def typed(value: str) -> str:
    """``value`` as typed in bash, zsh and fish: in single quotes where it holds a character a
    shell would glob, split or read as a quote."""
    return f"'{value}'" if _GLOB.search(value) and "'" not in value else value


def example_value(option: Option) -> str | None:
    """A value ``option`` takes, as typed: ``4kg``, ``'0.1kg*m^2'``, ``disc``."""
    if option.kind == CHOICE and option.choices:
        return option.choices[0]
    kind = KINDS.get(option.kind)
    if kind is None:
        return None
    shown = kind.example.strip("'")
    return typed(shown.replace(" ", "") if re.fullmatch(r"[-\d.e]+ [A-Za-z]+", shown) else shown)


def _needs_value(option: Option) -> str:
    value = example_value(option)
    return f"{option.flag} needs a value" + (f" (e.g. {option.flag} {value})" if value else "")


def _single_dash(word: str, flags: set[str]) -> str | None:
    """``-help`` for ``--help``, ``-m1`` for ``--m1``: a long option typed with one dash."""
    if re.fullmatch(r"-[A-Za-z][A-Za-z0-9-]+", word) and f"-{word}" in flags:
        return f"{word} is not an option; did you mean {'-' + word}?"
    return None


def explain(command: Command | None, args: list[str], at: int) -> str | None:
    """The fix for a command line the parser refused, or None where there is nothing to add to
    the parser's own message. ``command`` is the command named at ``args[at]`` (None: none)."""
    if command is None:
        for word in args[:at]:
            found = _single_dash(word, {"--help", "--version", "--debug"})
            if found:
                return found
        return None
    options = {option.flag: option for option in (*command.options, *command.output) if not option.positional}
    flags = {*options, *HELP_WORDS}
    positional = [option for option in command.options if option.positional]
    words = args[at + 1 :]
    i = 0
    last: tuple[Option, str] | None = None  # the last option given a value, and the value
    while i < len(words):
        word = words[i]
        if word == "--":
            return None
        option = options.get(word.split("=", 1)[0]) if word.startswith("--") else None
        if option is not None and option.takes_value and "=" not in word:
            if i + 1 == len(words) or words[i + 1] in flags:
                return _needs_value(option)
            last = (option, words[i + 1])
            i += 2
            continue
        if option is not None:
            last = None
            i += 1
            continue
        if word.startswith("-") and not re.match(r"-[\d.]", word):
            found = _single_dash(word, flags)
            if found:
                return found
            last = None
            i += 1
            continue
        if positional:
            positional.pop(0)
            last = None
            i += 1
            continue
        if last is not None:  # words left over after an option's value: a value with spaces, unquoted
            extra = []
            while i < len(words) and not words[i].startswith("-"):
                extra.append(words[i])
                i += 1
            option, value = last
            whole = " ".join((value, *extra))
            quoted = f"{option.flag}: got {value!r}, then {' '.join(extra)!r} as words of their own; a value with spaces is one word only in quotes: {option.flag} '{whole}'"
            if any("=" in word for word in (value, *extra)):  # key=value ... of a spec: its spaces part the keys, so only the quotes will do
                return quoted
            return quoted + f", or write it without spaces: {option.flag} {typed(''.join((value, *extra)))}"
        return None
    return None


def given_twice(command: Command | None, args: list[str], at: int) -> str | None:
    """'--inertia is given twice' where an option that takes one value is given more than once
    (typer would keep the last and drop the first unsaid); repeatable options aside (--part,
    --get), and words after ``--``. Flags given twice mean what once does."""
    if command is None:
        return None
    options = {option.flag: option for option in (*command.options, *command.output) if not option.positional}
    words = args[at + 1 :]
    seen: dict[str, str] = {}
    i = 0
    while i < len(words):
        word = words[i]
        if word == "--":
            return None
        flag, equals, value = word.partition("=") if word.startswith("--") else ("", "", "")
        option = options.get(flag)
        if option is None or not option.takes_value:
            i += 1
            continue
        if not equals:
            value = words[i + 1] if i + 1 < len(words) else ""
            i += 1
        i += 1
        if option.repeatable:
            continue
        if flag in seen:
            return (f"{flag} is given twice ({typed(seen[flag])} and {typed(value)}); it takes one value: give it once, "
                    f"e.g. {flag} {typed(value)}")
        seen[flag] = value
    return None
