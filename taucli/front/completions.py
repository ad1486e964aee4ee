"""Shell completion scripts for bash, zsh and fish, generated from the commands' tables.

The scripts are static: pressing TAB runs the shell's own code and never starts Python. What
each option takes comes from its table entry: a quantity's kind (after a number, TAB offers
that number with each of the kind's common units, units.KINDS: ``--m1 4`` TAB gives 4kg 4g 4lb
4oz 4tonne), a choice's words, a file, the command's result names (after --get and --y), or
what --find may solve for (its inputs, and the keys of its specs: particle.speed, brake.mu).
completions/ holds the output, and tests/front/test_completions.py fails when it differs from a fresh
generation.
"""

from __future__ import annotations

from dataclasses import dataclass

from taucli.options import table
from taucli.answering import unknowns
from taucli.core.names import SHAPE_AXES, SHELLS  # noqa: F401 (completions.SHELLS: the shells it writes for)
from taucli.options import COMMANDS, SCENES
from taucli.options.tools import ROOT
from taucli.quantities.units import KINDS

FILE_NAMES = {"bash": "taucli.bash", "zsh": "_taucli", "fish": "taucli.fish"}
RESULT_NAMES = ("get", "y")  # options whose value is one of the command's results
RESULT_IS = ("to", "want")  # options whose value is RESULT=...: completed to "RESULT=" (#42)
FIT = "fit"  # fit's --fit: NAME,NAME of the scene typed, as --find takes them
FIND = "find"  # its value is an input of the command, or a key of a spec (taucli.answering.unknowns: particle.speed)


@dataclass(frozen=True)
class Option:
    flag: str
    help: str
    takes_value: bool = False
    repeatable: bool = False
    label: str = ""  # what the value is, for zsh's and fish's descriptions
    choices: tuple[str, ...] = ()
    units: tuple[str, ...] = ()
    files: bool = False
    described: tuple[tuple[str, str], ...] = ()  # (choice, what it is): --get's results, each with its own label
    axes: bool = False  # --axis: the axes of the shape typed so far (names.SHAPE_AXES)
    fit_names: bool = False  # fit's --fit: the inputs of the scene typed, after any NAME, typed (#42 item 23)


@dataclass(frozen=True)
class Command:
    name: str
    help: str
    options: tuple[Option, ...]
    positional: tuple[str, ...] = ()  # words the first argument takes
    files: bool = False  # the words after the first argument are files (fit's data)
    argument: str = "shape"  # what the first argument is, for zsh's description


def spec() -> tuple[tuple[Option, ...], tuple[Command, ...]]:
    """taucli's own options, and each command with its options, read off the commands' tables."""

    return _options(ROOT, ROOT.options), tuple(
        Command(
            command.name,
            _sentence(command.summary),
            _options(command, (*command.options, *command.output)),
            next((option.choices for option in command.options if option.positional), ()),
            any(option.positional and option.kind == table.FILE for option in command.options),
            next((option.shown_metavar.lower() for option in command.options if option.positional), "shape"),
        )
        for command in COMMANDS.values()
    )


def _options(command: table.Command, options) -> tuple[Option, ...]:
    found = [Option("--help", "Show this message and exit.")]
    for option in options:
        if option.positional:
            continue
        if not option.takes_value:
            found.append(Option(option.flag, _sentence(option.help_text())))
            continue
        choices = option.choices
        described: tuple[tuple[str, str], ...] = ()
        if option.name in RESULT_NAMES and command.results and (option.name == "get" or command.library is not None):  # fit's --y is a column
            choices = tuple(result.key for result in command.results)
            described = tuple((result.key, _sentence(result.label.replace(table.FILLED, ""))) for result in command.results)
        if option.name in RESULT_IS and command.results and command.library is not None:
            choices = tuple(result.key + "=" for result in command.results)
        if option.name == FIND and command.results:
            choices = unknowns.names(command)
        found.append(
            Option(
                option.flag,
                _sentence(option.help_text()),
                takes_value=True,
                repeatable=option.repeatable,
                label=(option.kind if option.is_quantity and not option.metavar else option.shown_metavar.split()[0].strip('"')).lower(),
                choices=choices,
                units=KINDS[option.kind].common_units if option.is_quantity else (),
                files=option.kind in (table.FILE, table.CURVE),
                described=described,
                axes=option.name == "axis" and option.kind == table.CHOICE,
                fit_names=command.name == FIT and option.name == FIT,
            )
        )
    return tuple(sorted(found, key=lambda option: option.flag == "--help"))


def _fit_names() -> dict[str, tuple[str, ...]]:
    """What fit's --fit offers after each scene: its inputs and the keys of its specs (as --find)."""
    return {name: unknowns.names(command) for name, command in SCENES.items()}


def _sentence(text: str | None) -> str:
    return " ".join((text or "").split())


def script(shell: str) -> str:
    """The completion script for ``shell``."""
    own, commands = spec()
    return {"bash": _bash, "zsh": _zsh, "fish": _fish}[shell](own, commands)


HEADER = "# taucli completion for {shell}: generated by `taucli completions {shell}`; do not edit.\n"


def _bash(own: tuple[Option, ...], commands: tuple[Command, ...]) -> str:
    lines = [
        HEADER.format(shell="bash").rstrip("\n"),
        "# Install: copy to ~/.local/share/bash-completion/completions/taucli (with the bash-completion",
        "# package), or without it save it anywhere and source it from ~/.bashrc:",
        "#   taucli completions bash > ~/.taucli.bash && echo 'source ~/.taucli.bash' >> ~/.bashrc",
        "# It needs nothing but bash's own complete and compgen.",
        "",
        "_taucli_units() {",
        "    # A number typed so far, with each unit after it: 4 -> 4kg 4g ...",
        '    local number="${cur%%[!0-9.eE+-]*}" unit',
        '    [[ -n "$number" && "$number" == [0-9.+-]* ]] || return 0',
        "    for unit in \"$@\"; do",
        '        [[ "$number$unit" == "$cur"* ]] && COMPREPLY+=("$number${unit//\\*/\\\\*}")',
        "    done",
        "}",
        "",
        "_taucli_axes() {",
        "    # The axes of the shape typed so far (after --shape, or as the command's SHAPE); all when none is",
        '    local i shape="" axes',
        "    for ((i = 2; i < COMP_CWORD; i++)); do",
        '        if [[ "${COMP_WORDS[i-1]}" == --shape || "${COMP_WORDS[i-1]}" != -* ]]; then',
        '            case "${COMP_WORDS[i]}" in ' + "|".join(SHAPE_AXES) + ') shape="${COMP_WORDS[i]}" ;; esac',
        "        fi",
        "    done",
        '    case "$shape" in',
        *(f'        {shape}) axes="{" ".join(axes)}" ;;' for shape, axes in SHAPE_AXES.items()),
        f'        *) axes="{" ".join(dict.fromkeys(a for axes in SHAPE_AXES.values() for a in axes))}" ;;',
        "    esac",
        '    COMPREPLY=($(compgen -W "$axes" -- "$cur"))',
        "}",
        "",
        "_taucli_fit_names() {",
        "    # fit's --fit: the inputs of the scene typed, after the NAME, typed so far",
        '    local i scene="" names prefix=""',
        "    for ((i = 2; i < COMP_CWORD; i++)); do",
        '        case "${COMP_WORDS[i]}" in ' + "|".join(_fit_names()) + ') scene="${COMP_WORDS[i]}"; break ;; esac',
        "    done",
        '    case "$scene" in',
        *(f'        {scene}) names="{" ".join(names)}" ;;' for scene, names in _fit_names().items()),
        "    esac",
        '    [[ "$cur" == *,* ]] && prefix="${cur%,*},"',
        '    COMPREPLY=($(compgen -P "$prefix" -W "$names" -- "${cur##*,}"))',
        "}",
        "",
        "_taucli() {",
        '    local cur="${COMP_WORDS[COMP_CWORD]}" prev="${COMP_WORDS[COMP_CWORD-1]}" command="" i',
        "    COMPREPLY=()",
        "    for ((i = 1; i < COMP_CWORD; i++)); do",
        '        case "${COMP_WORDS[i]}" in -*) ;; *) command="${COMP_WORDS[i]}"; break ;; esac',
        "    done",
        '    if [[ -z "$command" ]]; then',
        f'        COMPREPLY=($(compgen -W "{" ".join(c.name for c in commands)} {" ".join(o.flag for o in own)}" -- "$cur"))',
        "        return 0",
        "    fi",
        '    case "$command" in',
    ]
    for command in commands:
        lines.append(f"    {command.name})")
        lines.append('        case "$prev" in')
        for option in command.options:
            if not option.takes_value:
                continue
            if option.units:
                action = f"_taucli_units {' '.join(_bash_word(u) for u in option.units)}"
            elif option.axes:
                action = "_taucli_axes"
            elif option.fit_names:
                action = "_taucli_fit_names"
            elif option.choices:
                action = f'COMPREPLY=($(compgen -W "{" ".join(option.choices)}" -- "$cur"))'
                if all(choice.endswith("=") for choice in option.choices):  # RESULT= : the value goes on after it
                    action += "; compopt -o nospace"
            elif option.files:
                action = 'COMPREPLY=($(compgen -f -- "$cur"))'
            else:
                action = ":"
            lines.append(f"            {option.flag}) {action}; return 0 ;;")
        lines.append("        esac")
        flags = " ".join(option.flag for option in command.options)
        if command.positional:
            lines.append('        if [[ "$cur" != -* ]]; then')
            if command.files:  # the word after the command is the first argument; later ones are files
                lines.append(f'            (( COMP_CWORD == i + 1 )) && COMPREPLY=($(compgen -W "{" ".join(command.positional)}" -- "$cur")) || COMPREPLY=($(compgen -f -- "$cur"))')
            else:
                lines.append(f'            COMPREPLY=($(compgen -W "{" ".join(command.positional)}" -- "$cur"))')
            lines.append("            return 0")
            lines.append("        fi")
        lines.append(f'        COMPREPLY=($(compgen -W "{flags}" -- "$cur"))')
        lines.append("        ;;")
    lines += ["    esac", "    return 0", "}", "", "complete -F _taucli taucli", ""]
    return "\n".join(lines)


def _bash_word(unit: str) -> str:
    return f"'{unit}'" if any(ch in unit for ch in "*()/^") else unit


def _zsh_text(text: str) -> str:
    """Text inside a single-quoted _arguments spec: brackets and colons escaped."""
    return text.replace("\\", "\\\\").replace("[", "\\[").replace("]", "\\]").replace(":", "\\:").replace("'", "'\\''")


def _zsh_option(option: Option) -> str:
    spec = ("*" if option.repeatable else "") + option.flag
    spec += f"[{_zsh_text(option.help)}]"
    if option.takes_value:
        if option.units:  # braces: run as code, with no compadd options appended to the units
            action = "{_taucli_units " + " ".join(f'"{unit}"' for unit in option.units) + "}"
        elif option.axes:
            action = "{_taucli_axes}"
        elif option.fit_names:
            action = "{_taucli_fit_names}"
        elif option.described:
            action = "((" + " ".join(f"{choice}\\:{_zsh_described(label)}" for choice, label in option.described) + "))"
        elif option.choices:
            action = "(" + " ".join(option.choices) + ")"
        elif option.files:
            action = "_files"
        else:
            action = " "
        spec += f":{_zsh_text(option.label)}:{action}"
    return f"'{spec}'"


def _zsh_described(label: str) -> str:
    """A choice's description in a ((choice\\:description ...)) action, inside a single-quoted spec."""
    return '"' + label.replace("\\", "").replace('"', "").replace(":", "").replace("'", "'\\''").replace("[", "(").replace("]", ")") + '"'


def _zsh(own: tuple[Option, ...], commands: tuple[Command, ...]) -> str:
    lines = [
        "#compdef taucli",
        HEADER.format(shell="zsh").rstrip("\n"),
        "# Install: copy to a folder on $fpath as _taucli (e.g. ~/.zfunc, with fpath=(~/.zfunc $fpath)",
        "# before compinit in ~/.zshrc).",
        "",
        "_taucli_units() {",
        "    # A number typed so far, with each unit after it: 4 -> 4kg 4g ...",
        "    local number=${PREFIX%%[^0-9.eE+-]*} unit",
        "    local -a candidates",
        "    if [[ -z $number || $number != [0-9.+-]* ]]; then",
        "        _message 'a number and a unit, e.g. 4'$1",
        "        return 1",
        "    fi",
        '    for unit in "$@"; do candidates+=("$number$unit"); done',
        "    compadd -a candidates",
        "}",
        "",
        "_taucli_axes() {",
        "    # The axes of the shape typed so far (after --shape, or as the command's SHAPE); all when none is",
        "    local i shape axes",
        "    for ((i = 2; i < CURRENT; i++)); do",
        "        if [[ $words[i-1] == --shape || $words[i-1] != -* ]]; then",
        "            case $words[i] in " + "|".join(SHAPE_AXES) + ") shape=$words[i] ;; esac",
        "        fi",
        "    done",
        "    case $shape in",
        *(f"        {shape}) axes=({' '.join(axes)}) ;;" for shape, axes in SHAPE_AXES.items()),
        f"        *) axes=({' '.join(dict.fromkeys(a for axes in SHAPE_AXES.values() for a in axes))}) ;;",
        "    esac",
        "    compadd -a axes",
        "}",
        "",
        "_taucli_fit_names() {",
        "    # fit's --fit: the inputs of the scene typed, NAME,NAME",
        "    local word scene",
        "    local -a names",
        "    for word in $words; do",
        "        case $word in " + "|".join(_fit_names()) + ") scene=$word; break ;; esac",
        "    done",
        "    case $scene in",
        *(f"        {scene}) names=({' '.join(names)}) ;;" for scene, names in _fit_names().items()),
        "    esac",
        "    (( $#names )) && _values -s , input $names",
        "}",
        "",
        "_taucli() {",
        "    local curcontext=$curcontext state line",
        "    typeset -A opt_args",
        "    _arguments -C \\",
    ]
    for option in own:
        lines.append(f"        '(- *)'{_zsh_option(option)} \\")
    lines += [
        "        '1:command:->command' \\",
        "        '*::argument:->argument'",
        "    case $state in",
        "    command)",
        "        local -a commands",
        "        commands=(",
    ]
    for command in commands:
        lines.append(f"            '{command.name}:{_zsh_text(command.help)}'")
    lines += [
        "        )",
        "        _describe -t commands 'taucli command' commands",
        "        ;;",
        "    argument)",
        "        curcontext=${curcontext%:*:*}:taucli-$line[1]:",
        "        case $line[1] in",
    ]
    for command in commands:
        lines.append(f"        {command.name})")
        lines.append("            _arguments \\")
        specs = [_zsh_option(option) for option in command.options]
        if command.positional:
            specs.append(f"'1:{command.argument}:({' '.join(command.positional)})'")
        if command.files:
            specs.append("'*:file:_files'")
        lines += [f"                {spec} \\" for spec in specs[:-1]] + [f"                {specs[-1]}", "            ;;"]
    lines += ["        esac", "        ;;", "    esac", "}", "", '_taucli "$@"', ""]
    return "\n".join(lines)


def _fish_text(text: str) -> str:
    return "'" + text.replace("\\", "\\\\").replace("'", "\\'") + "'"


def _fish(own: tuple[Option, ...], commands: tuple[Command, ...]) -> str:
    lines = [
        HEADER.format(shell="fish").rstrip("\n"),
        "# Install: copy to ~/.config/fish/completions/taucli.fish",
        "",
        "function __taucli_units --description 'a number typed so far, with each unit after it'",
        "    set -l number (string match -r -- '^[-+]?[0-9.]+(?:[eE][-+]?[0-9]+)?' (commandline -ct))",
        "    test -n \"$number\"; or return",
        "    for unit in $argv",
        "        echo $number$unit",
        "    end",
        "end",
        "",
        "function __taucli_axes --description 'the axes of the shape typed so far (all when none is)'",
        "    set -l words (commandline -opc)",
        "    set -l shape",
        "    for i in (seq 3 (count $words))",
        "        set -l previous $words[(math $i - 1)]",
        "        if test \"$previous\" = --shape; or not string match -q -- '-*' $previous",
        f"            contains -- $words[$i] {' '.join(SHAPE_AXES)}; and set shape $words[$i]",
        "        end",
        "    end",
        "    switch \"$shape\"",
        *(f"        case {shape}\n            printf '%s\\t{shape}\\n' {' '.join(axes)}" for shape, axes in SHAPE_AXES.items()),
        f"        case '*'\n            printf '%s\\n' {' '.join(dict.fromkeys(a for axes in SHAPE_AXES.values() for a in axes))}",
        "    end",
        "end",
        "",
        "function __taucli_fit_names --description 'the inputs of the scene typed, after the NAME, typed so far'",
        "    set -l scene",
        "    for word in (commandline -opc)",
        f"        contains -- $word {' '.join(_fit_names())}; and set scene $word; and break",
        "    end",
        "    set -l prefix (string replace -r -- '[^,]*$' '' (commandline -ct))",
        "    switch \"$scene\"",
        *(f"        case {scene}\n            printf \"$prefix%s\\n\" {' '.join(names)}" for scene, names in _fit_names().items()),
        "    end",
        "end",
        "",
        "complete -c taucli -f",
    ]
    for option in own:
        lines.append(f"complete -c taucli -n __fish_use_subcommand -l {option.flag[2:]} -d {_fish_text(option.help)}")
    for command in commands:
        lines.append(f"complete -c taucli -n __fish_use_subcommand -a {command.name} -d {_fish_text(command.help)}")
    for command in commands:
        condition = f"-n '__fish_seen_subcommand_from {command.name}'"
        if command.positional:
            lines.append(f"complete -c taucli {condition} -a {_fish_text(' '.join(command.positional))}")
        if command.files:
            lines.append(f"complete -c taucli {condition} -F")
        for option in command.options:
            line = f"complete -c taucli {condition} -l {option.flag[2:]}"
            if option.units:
                line += f" -x -a {_fish_text('(__taucli_units ' + ' '.join(_fish_word(u) for u in option.units) + ')')}"
            elif option.axes:
                line += " -x -a '(__taucli_axes)'"
            elif option.fit_names:
                line += " -x -a '(__taucli_fit_names)'"
            elif option.described:  # one line a result, each with its own label
                lines += [f"{line} -x -a {_fish_text(choice)} -d {_fish_text(label)}" for choice, label in option.described]
                continue
            elif option.choices:
                line += f" -x -a {_fish_text(' '.join(option.choices))}"
            elif option.files:
                line += " -r -F"
            elif option.takes_value:
                line += " -x"
            lines.append(f"{line} -d {_fish_text(option.help)}")
    return "\n".join(lines) + "\n"


def _fish_word(unit: str) -> str:
    return '"' + unit + '"' if any(ch in unit for ch in "*()") else unit
