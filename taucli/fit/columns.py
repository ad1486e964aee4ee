"""How a table's columns map to the scene: what a header tells beyond its unit
(csv_text.split_header reads the unit), and the rules that follow from it:

- A run mark: PASCO writes ``Time (ms) Run #1``, Vernier ``Run 1: Time (s)`` (Logger Pro's
  current run ``Latest: Time (s)``). Where every marked
  column of a table is of one run, the mark is left out of the names (``Time``), so the columns
  match the scene by name as an unmarked export does; the header is kept as written. A table of
  several runs side by side is several tables, one a run (split_runs): each run's columns with
  the mark left out, so they match by name too, and a fit takes them together as it takes
  several files (each file, and each run in one, a run of its own: --per-run fits an input for
  each). ``--x`` or ``--y`` naming a marked header as written (``"Run 2: Time (s)"``) fits that
  run alone.
- A column with no unit (none in its header, none in the mapping that names it) is read in SI
  only where its name is the input's or the result's own (``t`` or ``time`` for --time, ``m1``,
  ``omega``), with a note; any other name is refused, naming the mapping that gives it a unit:
  a bare ``millis`` column read as seconds is a wrong number where a refusal is possible. An
  angle or an angular speed with no unit is refused whatever its name (radians or degrees?), as a
  bare number for ``--angle`` is. A pure number (k², μ) has no unit to read.
- A column is matched to the scene by --x and --y, else by its name (match_by_name: an option's
  name, ``t`` or ``time`` for --time, a result's name). Two columns that would give one input
  (``length (m)`` and ``length (cm)``; ``t (s)`` and ``time (s)``) are refused, naming both and
  the --x that picks one (each sample has one value of each input: taking both would
  interleave them); a column named like an input that --x gives from another is left out, with
  a note.

Plain Python: no numpy, no pint (the units are read by taucli.quantities.units).
"""

from __future__ import annotations

import math
import re
from dataclasses import replace

from taucli.core.errors import InputError, did_you_mean
from taucli.fit.data import Column, DataTable, Numbers, split_header
from taucli.options.table import Command
from taucli.quantities import units
from taucli.writing.report import pretty_unit

TIME_NAMES = ("t", "time")
AMBIGUOUS = frozenset({"angle", "angular velocity", "angular acceleration"})  # a bare number is refused (docs/units.md)

_RUN_AFTER = re.compile(r"\s*\bRun\s*#?\s*(\d+)\s*$", re.IGNORECASE)  # PASCO: "Time Run #1"
_RUN_BEFORE = re.compile(r"^\s*(?:Run\s*#?\s*(\d+)|(Latest))\s*:\s*", re.IGNORECASE)  # Vernier: "Run 1: Time", Logger Pro's "Latest: Time"


def key(name: str) -> str:
    """A name as options and results are looked up by: "Pulley-Mass" -> "pulley_mass"."""
    return name.strip().lower().replace("-", "_").replace(" ", "_")


def quoted(text: str) -> str:
    """``text`` as typed in bash, zsh and fish: in single quotes where it holds a space or ( ) [ ] * ^ ?
    (in double quotes, \\ " $ escaped, where it holds a single quote: a header "Newton's t (s)")."""
    if not re.search(r"[\s()\[\]*^?'\"$#&;|<>~!{}\\]", text):
        return text
    return f"'{text}'" if "'" not in text else '"' + re.sub(r'([\\"$])', r"\\\1", text) + '"'


def run_of(name: str) -> tuple[str, str | None]:
    """(the name without its run mark, the run's number) from "Time Run #1" or "Run 1: Time";
    (name, None) where it has none."""
    for mark in (_RUN_AFTER, _RUN_BEFORE):
        found = mark.search(name)
        if found is not None and (rest := (name[:found.start()] + name[found.end():]).strip()):
            return rest, found[1] or found[found.lastindex]
    return name, None


def split_runs(table: DataTable, picked: set[str] = frozenset()) -> list[DataTable]:
    """The runs of a table, one table each (the module's rule): where its columns carry several
    runs' marks, each run's columns with their marks left out of headers and names, the unmarked
    columns (a time shared by the runs) in each, and the rows where every one of the run's own
    cells is blank left out (a shorter run's padding). ``picked``: headers --x and --y name as
    written; where one has a mark, that run alone is fitted, its headers as written."""
    marks = list(dict.fromkeys(run for run in (run_of(column.name)[1] for column in table.columns) if run is not None))
    if len(marks) < 2:
        return [one_run_named(table)]
    chosen = {run_of(split_name(header))[1] for header in picked} - {None}
    if chosen:
        kept = [column for column in table.columns if run_of(column.name)[1] in ({None} | chosen)]
        return [replace(table, columns=tuple(kept))]
    shared = [column for column in table.columns if run_of(column.name)[1] is None]
    runs = []
    first_names = None
    for mark in marks:
        own = [column for column in table.columns if run_of(column.name)[1] == mark]
        names = sorted(run_of(column.name)[0] for column in own)
        if first_names is None:
            first_names = names
        elif names != first_names:
            raise InputError("data", f"{table.source}: run {mark} has the columns {', '.join(names)}, and run {marks[0]} has {', '.join(first_names)}: "
                             "every run of one fit has the same columns", hint=f"fit one run: {{x}} {quoted(own[0].header)}")
        keep = [i for i in range(len(table.lines)) if any(not math.isnan(column.values[i]) for column in own)]
        columns = [replace(column, header=run_of(column.header)[0], name=run_of(column.name)[0], values=Numbers("d", (column.values[i] for i in keep)))
                   for column in (*shared, *own)]
        runs.append(replace(table, source=f"{table.source} (run {mark})", columns=tuple(columns), lines=Numbers("q", (table.lines[i] for i in keep))))
    return runs


def split_name(header: str) -> str:
    return split_header(header)[0]


def one_run_named(table: DataTable) -> DataTable:
    """``table`` with its columns named without their run mark, where every marked column is of one run."""
    runs = {run_of(column.name)[1] for column in table.columns} - {None}
    if len(runs) != 1:
        return table
    return replace(table, columns=tuple(replace(column, name=run_of(column.name)[0]) for column in table.columns))


def own_name(name: str, target: str, is_result: bool) -> bool:
    """Whether a column called ``name`` is named as the input or result ``target`` itself is."""
    return key(name) == key(target) or (not is_result and target == "time" and key(name) in TIME_NAMES)


def bare_factor(column: Column, target: str, is_result: bool, kind: str | None, si_unit: str, label: str, notes: list[str]) -> float:
    """SI per unit of a used column that names no unit (see the module's rule): 1, with a note,
    or a usage error naming the mapping that gives it a unit."""
    if kind in AMBIGUOUS:
        example = {"angle": "theta (rad)", "angular velocity": "omega (rad/s)"}.get(kind, "alpha (rad/s^2)")
        raise InputError("data", f"column {column.header!r} ({label}) has no unit, and a bare number is ambiguous for {units.article(kind)} "
                         "(radians or degrees, rad/s or rpm)", hint=f"write its unit in the header, e.g. {example}")
    if not si_unit:
        return 1.0  # a pure number: nothing to read
    shown = pretty_unit(si_unit)
    if not own_name(column.name, target, is_result):
        common = units.KINDS[kind].common_units if kind in units.KINDS else ()
        example = (common[1] if len(common) > 1 else si_unit).replace("**", "^")
        option = "y" if is_result else "x"
        own = " or ".join(TIME_NAMES) if target == "time" and not is_result else target
        raise InputError("data", f"column {column.header!r} ({label}) has no unit, and only a column named {own} is read in SI ({shown}) without one",
                         hint=f"give the unit its numbers are in: {{{option}}} {quoted(column.header + '=' + target + ' (' + example + ')')}")
    notes.append(f"column {column.header!r} has no unit: read in {shown}, the SI unit of {label}")
    return 1.0


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


def spec(text: str, option: str) -> tuple[str, str | None, str]:
    """(COLUMN, TARGET or None, the unit TARGET carries) from "COLUMN[=TARGET [(UNIT)]]"."""
    column, sep, target = str(text).rpartition("=") if "=" in str(text) else (str(text), "", "")
    column, target = column.strip(), target.strip()
    if not column or (sep and not target):
        raise InputError(option, "expected COLUMN or COLUMN=NAME", example=f'{{{option}}} "Time (s)"' if option == "x" else '{y} "w (rad/s)=omega"', got=repr(text))
    if not sep:
        return column, None, ""
    name, unit = split_header(target)
    return column, name, unit


def find(tables: list[DataTable], wanted: str, option: str) -> str:
    """The header of the column ``wanted`` names: its header, or its name without the unit (a
    single run's header without its mark too: "Angular Velocity (rad/s)" for "Run 1: Angular Velocity (rad/s)")."""
    headers = list(dict.fromkeys(column.header for column in tables[0].columns))
    for match in (lambda c: c.header == wanted, lambda c: c.name == wanted, lambda c: c.header.lower() == wanted.lower() or c.name.lower() == wanted.lower(),
                  lambda c: run_of(c.header)[0].lower() == wanted.lower()):
        found = [column.header for column in tables[0].columns if match(column)]
        if len(found) == 1:
            return found[0]
    raise InputError(option, f"expected a column of {tables[0].source}: {', '.join(repr(h) for h in headers)}", got=repr(wanted),
                     hint=did_you_mean(wanted, headers))
