"""The Python API: one function per scene, made from the scene's table.

``taucli.spin_down(omega0="30 rad/s", inertia=0.1, friction="0.3 N*m")`` reads its keywords as
the command line reads its options (texts with units; a number is SI), solves, and returns the
Report. A scene's positional argument (inertia's and rolling's SHAPE) may be given first. A list
for one keyword that takes one quantity is a sweep: a Sweep of the reports, one per value.
"""

from __future__ import annotations

import inspect
import textwrap
from collections.abc import Callable

from taucli.answering import answer
from taucli.answering.python import plain
from taucli.options import SCENES
from taucli.core.errors import InputError
from taucli.writing.report import Report
from taucli.writing.swept import Sweep
from taucli.quantities.kinds import KINDS
from taucli.options.table import CHOICE, COUNT, CURVE, FILE, FLAG, TEXT, VECTOR, Command, Option


def function(name: str) -> Callable[..., Report] | None:
    """The API function of the scene called ``name`` (spin_down), or None."""
    command = SCENES.get(name.replace("_", "-"))
    if command is None or command.function_name != name:
        return None
    return _made(command)


def _made(command: Command) -> Callable[..., Report | Sweep]:
    positional = [option.name for option in command.options if option.positional]

    def scene(*args, **given) -> Report | Sweep:
        if len(args) > len(positional):
            raise TypeError(f"{command.function_name}() takes {len(positional)} positional argument(s) but {len(args)} were given")
        for name, value in zip(positional, args):
            if name in given:
                raise TypeError(f"{command.function_name}() got multiple values for argument {name!r}")
            given[name] = value
        given = {name.replace("-", "_"): plain(value, name) for name, value in given.items()}
        _no_sweeps(command, given)
        finding = {name: given.pop(name, None) for name in ("find", "want", "minimize", "maximize")}
        swept = _swept(command, given)
        if swept is None:
            return answer.solve(command, given, **finding)
        return Sweep(command.name, swept, given[swept], [answer.solve(command, {**given, swept: value}, **finding) for value in given[swept]])

    parameters = [
        inspect.Parameter(
            option.name,
            inspect.Parameter.POSITIONAL_OR_KEYWORD if option.positional else inspect.Parameter.KEYWORD_ONLY,
            default=None,
        )
        for option in command.options
    ]  # and find=, want= (#22), read by taucli.answering.answer.solve
    scene.__signature__ = inspect.Signature(parameters, return_annotation=Report)
    scene.__name__ = scene.__qualname__ = command.function_name
    scene.__module__ = "taucli"
    scene.__doc__ = docstring(command)
    return scene


def convert(quantity: str, unit: str | None = None):
    """``quantity`` ("3000 rpm", "2 lb*ft^2", "4.0+/-0.1 kg") written in ``unit`` (else SI), read as
    every option reads a text: a Conversion with .value, .unit, .kind, .si_value, .si_unit,
    .uncertainty and .notes. A text taucli cannot read raises InputError, as on the command line
    (``taucli convert QUANTITY [UNIT]``)."""
    from taucli.quantities.conversion import convert_quantity  # deferred: pint

    for name, text in (("quantity", quantity), ("unit", unit)):
        if not (isinstance(text, str) or (name == "unit" and text is None)):
            raise InputError(name, "expected a text: a number and its unit" if name == "quantity" else "expected a unit's text, or None for SI",
                             example='"3000 rpm"' if name == "quantity" else '"rad/s"', got=f"{text!r} ({type(text).__name__})")
    return convert_quantity(quantity, unit)


def _no_sweeps(command: Command, given: dict) -> None:
    """A range "1..3 kg" is the command line's sweep; in Python a sweep is a list (#42, #46)."""
    for name, value in given.items():
        option = command.option(name)
        if isinstance(value, str) and ".." in value and option is not None and option.sweepable:
            raise InputError(name, "takes one value, or a list of values for a sweep (FROM..TO is the command line's range); "
                             f"give the values, as in taucli.{command.function_name}(..., {name}=[1.0, 2.0, 3.0]) (a number is SI)",
                             got=repr(value))


def _swept(command: Command, given: dict) -> str | None:
    """The keyword given a list of values (a sweep: one report per value), or None. A keyword that
    takes one quantity may be swept (a repeatable one takes its list as its values); one per call."""
    swept = [name for name, value in given.items() if isinstance(value, (list, tuple)) and (option := command.option(name)) is not None and option.sweepable]
    if not swept:
        return None
    if len(swept) > 1:
        first, second = swept[:2]
        raise InputError(second, f"is a list, and so is {{{first}}}: a call sweeps one keyword; for a grid, sweep one in a loop over the other, "
                         f"as in [taucli.{command.function_name}(..., {first}=x, {second}=[...]) for x in (...)]", got=repr(given[second])[:80])
    if not given[swept[0]]:
        raise InputError(swept[0], "is an empty list: a sweep takes one value or more", example=f"{swept[0]}=[1.0, 2.0, 3.0]")
    return swept[0]


def _kind(option: Option) -> str:
    """What a keyword takes, as help() lists it: "mass, kg", "one of disc, ring", "True or False"."""
    if option.kind == FLAG:
        what = "True or False"
    elif option.kind == CHOICE:
        what = "one of " + ", ".join(option.choices)
    elif option.kind == COUNT:
        what = "a whole number"
    elif option.kind == FILE:
        what = "a file's path"
    elif option.kind == CURVE:
        what = "a CSV file's path (angle, torque), a formula of theta, or (θ rad, T N·m) pairs"
    elif option.kind == TEXT:
        what = "text"
    elif option.kind == VECTOR:
        what = f'a vector of {option.of}s, "x,y,z UNIT" (SI: {KINDS[option.of].si_unit})' if option.of in KINDS else "a vector"
    elif option.kind in KINDS:
        unit = KINDS[option.kind].si_unit
        what = f"{option.kind}, a number in {unit}" if unit else "a number"
        if option.also in KINDS:
            what += f", or {option.also}"
        if option.words:
            what += " or " + " or ".join(repr(word) for word in option.words)
    else:
        what = f"a {option.kind} spec, {option.shown_metavar}"
    if option.repeatable:
        what += "; repeatable: a list"
    if option.default:
        what += f"; default {option.default}"
    if option.makes:
        what += "; makes " + ", ".join(option.makes)
    return what


def docstring(command: Command) -> str:
    """help(taucli.spin_down): the summary, then each keyword with its kind, unit, default and
    help, from the scene's table (#36), its results and an example."""
    keywords = []
    for option in command.options:
        keywords.append(f"    {option.name} ({_kind(option)})")
        keywords += textwrap.wrap(option.help, 88, initial_indent=" " * 8, subsequent_indent=" " * 8)
    return "\n".join([
        command.summary,
        "",
        "Each keyword takes a text with its unit (\"30 rad/s\", \"300 rpm\") or a number in the SI unit",
        "listed; None (the default) leaves it out, as a missing option does. find=NAME with",
        "want=\"RESULT=VALUE\" solves for an input; a text such as \"4.0+/-0.1 kg\" carries an uncertainty.",
        "A list of values for one keyword gives a taucli.Sweep of reports, one per value (.to_pandas()).",
        "",
        "Keywords:",
        *keywords,
        "",
        *textwrap.wrap(f"Results (report.results[NAME].value, SI): {command.results_line()}.", 96),
        "",
        f"As on the command line: {command.example}",
    ])  # fmt: skip
