"""Batch mode: many scenes in one process, JSON lines in, JSON lines out.

Each input line is a JSON object whose keys are the scene's option names (``m1``,
``pulley_mass``; ``pulley-mass`` reads too) and whose values are unit strings or numbers (a
number is SI); ``null`` leaves an option out. Options given on the command line with ``--batch``
apply to every line that does not give its own. Each output line is the document ``--json``
prints for that scene. A line that fails gives an error object in its place, and the run goes on:

    {"taucli": "0.1.0", "line": 3, "error": {"option": "--m1", "message": "--m1: expected a mass ..."}}

Lines are read, solved and written one at a time, each flushed, so memory stays flat however
long the input, and a run that is killed leaves only whole lines. The exit status is 0 when
every line gave a document, 2 when some line was bad input, 1 when some line met a bug.
"""

from __future__ import annotations

import inspect
import json
import math
import sys
from collections.abc import Callable, Iterable
from typing import TextIO, get_args, get_origin

from taucli import __version__
from taucli.errors import ExitStatus, InputError, TaucliError, did_you_mean, out_of_range
from taucli.sweep import marked

NOT_PER_LINE = ("batch", "json_", "get", "jsonl", "plot", "out", "points", "y")  # output: fixed for the whole run


def run(command: Callable, given: dict, lines: Iterable[str] | None, out: TextIO) -> int:
    """Run ``command`` once per line of ``lines``; ``given`` holds the command line's options."""
    if given.get("get"):
        raise InputError("--get", "does not combine with --batch, which writes whole JSON documents", example="--batch --no-steps")
    if lines is None:
        raise InputError("--batch", "reads JSON lines on stdin, but stdin is closed", example="taucli atwood --batch < scenes.jsonl")
    if getattr(lines, "isatty", lambda: False)():
        print("taucli: reading scenes as JSON lines from the terminal, one per line; Ctrl-D ends", file=sys.stderr)
    parameters = inspect.signature(command).parameters
    options = {name: _shape(parameter) for name, parameter in parameters.items() if name not in NOT_PER_LINE}
    fixed = {name: value for name, value in given.items() if name in options and value != parameters[name].default}
    failures = {ExitStatus.USAGE: 0, ExitStatus.INTERNAL: 0}
    first_failure = None
    total = 0
    for number, line in enumerate(lines, start=1):
        total = number
        try:
            command(**{**fixed, **_options(line, options, command.__name__)}, json_=True, get=None, batch=False)
            continue
        except TaucliError as err:
            status, option, message = err.exit_status, getattr(err, "option", None), str(err)
        except OverflowError:
            status, option, message = ExitStatus.USAGE, None, str(out_of_range())
        except (KeyboardInterrupt, BrokenPipeError):
            raise
        except Exception as err:  # a bug: reported on its line, and the run goes on
            status, option, message = ExitStatus.INTERNAL, None, f"internal error ({type(err).__name__}: {err}); this is a bug in taucli, please report it"
        failures[status] = failures.get(status, 0) + 1
        first_failure = first_failure or number
        error = {"option": option or None, "message": " ".join(message.split())}
        out.write(json.dumps({"taucli": __version__, "line": number, "error": error}, ensure_ascii=False, separators=(",", ":")) + "\n")
        out.flush()
    failed = sum(failures.values())
    if not failed:
        return int(ExitStatus.OK)
    print(f"taucli: error: {failed} of {total} lines failed (the first: line {first_failure})", file=sys.stderr)
    return int(ExitStatus.INTERNAL if failures[ExitStatus.INTERNAL] else ExitStatus.USAGE)


def _reject_constant(name: str):
    raise ValueError(f"{name} is not a number JSON allows")


_STRICT = json.JSONDecoder(parse_constant=_reject_constant)


_EXAMPLE_LINE = '{"m1": "4kg", "m2": "1kg"}'


def _shape(parameter: inspect.Parameter) -> str:
    """What a parameter takes: "flag", "list" (of texts) or "text"."""
    if isinstance(parameter.default, bool):
        return "flag"
    return "list" if _takes_list(parameter.annotation) else "text"


def _options(line: str, options: dict[str, str], scene: str) -> dict:
    """The keyword arguments of the command for one line of JSON."""
    text = line.strip()
    if not text:
        raise InputError("", "expected a JSON object of options", example=_EXAMPLE_LINE, got="an empty line")
    try:
        given = _STRICT.decode(text)
    except ValueError as err:
        raise InputError("", "expected a JSON object of options", example=_EXAMPLE_LINE, got=f"{text[:60]!r} ({err})") from None
    if not isinstance(given, dict):
        raise InputError("", "expected a JSON object of options", example=_EXAMPLE_LINE, got=repr(text[:60]))
    arguments = {}
    for key, value in given.items():
        name = key.replace("-", "_").removeprefix("__")
        if name == "json":
            name = "json_"
        if name not in options:
            known = [option for option in options if option != "json_"]
            raise InputError(key, f"is not an option of {scene.replace('_', '-')} in a batch", hint=did_you_mean(name, known))
        if value is not None:
            arguments[name] = _argument(value, options[name], name)
    ranges, lists = marked(arguments)
    if ranges or lists:
        name = (ranges + lists)[0]
        raise InputError("--" + name.replace("_", "-"), "cannot be a range or a list in a batch: give one scene per line", got=repr(arguments[name]))
    if arguments.get("torque_profile") == "-":
        raise InputError("--torque-profile", "cannot be - in a batch: stdin holds the scenes", example='"torque_profile": "pulse.csv"')
    return arguments


def _argument(value, shape: str, name: str):
    """A JSON value as the command's parameter takes it: text, a flag, or a list of texts."""
    if isinstance(value, str) and shape == "text":
        return value
    option = "--" + name.replace("_", "-")
    if shape == "flag":
        if not isinstance(value, bool):
            raise InputError(option, "expected true or false", got=json.dumps(value))
        return value
    if isinstance(value, bool):
        raise InputError(option, "expected a number or a text with a unit, not true or false", example='"4kg"')
    if shape == "list":
        return [_text(item, option) for item in (value if isinstance(value, list) else [value])]
    return _text(value, option)


def _takes_list(annotation) -> bool:
    """Whether a parameter's annotation (Annotated[Optional[list[str]], ...]) holds a list."""
    if get_origin(annotation) is list:
        return True
    return any(_takes_list(inner) for inner in get_args(annotation))


def _text(value, option: str) -> str:
    if isinstance(value, str):
        return value
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        if isinstance(value, float) and not math.isfinite(value):
            raise InputError(option, "expected a finite number", got=json.dumps(value, allow_nan=True))
        return repr(float(value)) if isinstance(value, float) else str(value)
    raise InputError(option, "expected a number or a text with a unit", example='"4kg"', got=json.dumps(value))
