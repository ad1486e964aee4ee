"""How a table's columns map to the scene:

- A column is matched to the scene by --x and --y, else by its name (match_by_name: an option's
  name, ``t`` or ``time`` for --time, a result's name). Two columns that would give one input
  (``length (m)`` and ``length (cm)``; ``t (s)`` and ``time (s)``) are refused, naming both and
  the --x that picks one (each sample has one value of each input: taking both would
  interleave them); a column named like an input that --x gives from another is left out, with
  a note.

Plain Python: no numpy, no pint.
"""

from __future__ import annotations

import re

from taucli.core.errors import InputError
from taucli.fit.data import Column, DataTable
from taucli.options.table import Command

TIME_NAMES = ("t", "time")



def key(name: str) -> str:
    """A name as options and results are looked up by: "Pulley-Mass" -> "pulley_mass"."""
    return name.strip().lower().replace("-", "_").replace(" ", "_")


def quoted(text: str) -> str:
    """``text`` as typed in bash, zsh and fish: in single quotes where it holds a space or ( ) [ ] * ^ ?."""
    return f"'{text}'" if re.search(r"[\s()\[\]*^?'\"]", text) else text


def refuse_two_for_one(first: str, second: str, target: str, explicit: bool) -> None:
    """Two columns giving the input ``target`` of each sample: by --x (``explicit``) or by their names."""
    if explicit:
        raise InputError("x", f"gives {{{target}}} from two columns, {first!r} and {second!r}: each sample has one {target}",
                         hint=f"map one of them: {{x}} {quoted(first + '=' + target)}")
    raise InputError("data", f"columns {first!r} and {second!r} would both give {{{target}}} for each sample (their names say so), "
                     "and each sample has one", hint=f"pick one: {{x}} {quoted(first + '=' + target)} (the other is then left out)")


def refuse_a_column_mapped_twice(chosen: dict, header: str, target: str | None, option: str) -> None:
    """--x or --y naming a column that --x named already, or two columns for one input."""
    if header in chosen:
        raise InputError(option, f"names column {header!r} again (it gives {chosen[header][0]} already): one column, one meaning", got=repr(header))
    if option == "x":
        given = next((other for other, (was, is_result, _) in chosen.items() if was == target and not is_result), None)
        if given is not None:
            refuse_two_for_one(given, header, target, explicit=True)


def match_by_name(command: Command, table: DataTable, chosen: dict, sigma_header: str | None, y_given: bool, notes: list[str]) -> list[str]:
    """Match the columns --x and --y leave by their names; the headers of those left unused. A
    column named like an input --x gives from another column is left out; two named like one
    input are refused (the module's rule)."""
    unused, superseded = [], []
    given = {target: header for header, (target, is_result, _) in chosen.items() if not is_result}  # by --x
    by_name: dict[str, str] = {}  # input -> the column whose name gives it
    for column in table.columns:
        if column.header in chosen or column.header == sigma_header:
            continue
        target, is_result = _named_target(command, column, y_given)
        if target is None:
            unused.append(column.header)
        elif is_result:
            chosen[column.header] = (target, True, "")
        elif target in given:
            superseded.append(column.header)
            notes.append(f"column {column.header!r} not used: --x gives {target} from column {given[target]!r}")
        else:
            if target in by_name:
                refuse_two_for_one(by_name[target], column.header, target, explicit=False)
            by_name[target] = column.header
            chosen[column.header] = (target, False, "")
    if unused:
        notes.append(f"columns not used: {', '.join(repr(header) for header in unused)} (neither an input of {command.name} nor the result measured)")
    return unused + superseded


def _named_target(command: Command, column: Column, y_given: bool) -> tuple[str | None, bool]:
    """(the input or result a column's name gives, whether it is a result), or (None, False)."""
    name = key(column.name)
    option = command.option(name)
    result = command.result(column.name) or command.result(name)
    if option is not None and option.name in command.input_names and option.is_quantity and not option.repeatable:
        return option.name, False
    if name in TIME_NAMES and result is None and command.option("time") is not None:
        return "time", False
    if result is not None and not y_given:
        return result.key, True
    return None, False
