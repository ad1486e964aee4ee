"""The command line: typer commands made from the commands' tables, and the one error funnel.

No physics here, and no option written out: each command's options, help and results come from
its table (taucli.options). A scene's command reads how to answer (--json, --get, a sweep, a
batch) and hands the rest to the pipeline; ``--help`` is written from the tables by taucli.front.help
without typer at all.
"""

from __future__ import annotations

import difflib
import inspect
import os
import sys
import traceback
from dataclasses import dataclass, field
from typing import Annotated, Optional, TextIO

import typer

from taucli.answering import answer
from taucli.front import help
from taucli.answering import pipeline
from taucli.writing import render
from taucli.front import streams, usage
from taucli.core.errors import ExitStatus, InputError, TaucliError, bounded, out_of_range
from taucli.options import COMMANDS
from taucli.options.common import POINT_RESULTS
from taucli.options.tools import ROOT
from taucli.options.table import FLAG, TEXT, Command, Option


@dataclass
class Environment:
    """Where a run reads and writes: passed in, so that tests and batch can give their own."""

    stdin: TextIO | None = field(default_factory=lambda: sys.stdin)
    stdout: TextIO = field(default_factory=lambda: sys.stdout)
    stderr: TextIO = field(default_factory=lambda: sys.stderr)


class _AsTyped:
    """Coercion that leaves a value as click parsed it: strings as typed, flags as booleans.

    typer 0.29 validates every given value through a pydantic TypeAdapter; importing pydantic
    costs about 100 ms, a third of a run, to turn a str into the same str. taucli reads every
    value itself (taucli.answering.inputs). Where typer has no ``_runtime_param`` (before 0.29, or after a
    change), its own coercion stays: slower, never wrong; tests/front/test_startup.py notices.
    """

    TYPES = (str, list[str], bool)

    @classmethod
    def install(cls, param) -> None:
        descriptor = getattr(param, "type_descriptor", None)
        if hasattr(param, "_runtime_param") and descriptor is not None and descriptor.annotation in cls.TYPES:
            param._runtime_param = cls

    @staticmethod
    def coerce(value, param, ctx):
        if value is None:
            return () if param.multiple or param.nargs == -1 else None
        return value


class _ReadAsTyped:
    def parse_args(self, ctx, args):
        for param in self.get_params(ctx):
            _AsTyped.install(param)
        return super().parse_args(ctx, args)


class TaucliGroup(_ReadAsTyped, typer.core.TyperGroup):
    pass


class TaucliCommand(_ReadAsTyped, typer.core.TyperCommand):
    pass


def _parameter(option: Option):
    """The typer parameter of one option of a table."""
    if option.positional:
        marker = typer.Argument(metavar=option.shown_metavar, help=option.help_text(), show_default=False)
        annotation, default = (Optional[list[str]] if option.repeatable else Optional[str]), None
    elif option.kind == FLAG:
        marker = typer.Option(option.flag, help=option.help_text())
        annotation, default = bool, False
    else:
        marker = typer.Option(option.flag, metavar=option.shown_metavar, help=option.help_text())
        annotation, default = (Optional[list[str]] if option.repeatable else Optional[str]), None
    return inspect.Parameter(option.name, inspect.Parameter.KEYWORD_ONLY, default=default, annotation=Annotated[annotation, marker])


def _typed(function, options):
    """``function`` with the typer parameters of ``options`` as its signature."""
    parameters = [_parameter(option) for option in options]
    function.__signature__ = inspect.Signature(parameters)
    function.__annotations__ = {parameter.name: parameter.annotation for parameter in parameters}
    return function


def _callback(command: Command, env: Environment):
    """The function typer calls for ``command``: its parameters are the table's options."""
    def run(**given) -> int:
        if command.library is not None:
            return run_scene(command, given, env)
        return pipeline.library(command.handler)(env=env, **given)

    _typed(run, (*command.options, *command.output))
    run.__name__ = command.function_name
    run.__doc__ = command.summary
    return run


def build_app(env: Environment, only: str | None = None) -> typer.Typer:
    """The typer app of every command, or of the one named ``only`` (typer builds the options of
    each command it has, 2-4 ms each, before it parses any)."""
    app = typer.Typer(
        name="taucli",
        cls=TaucliGroup,
        no_args_is_help=True,
        add_completion=False,
        pretty_exceptions_enable=False,
        rich_markup_mode=None,
        context_settings={"help_option_names": ["-h", "--help"]},
    )

    def own(version: bool = False, debug: bool = False) -> None:
        """taucli's own options: --version is answered before typer is reached (taucli.front.help)."""

    app.callback()(_typed(own, ROOT.options))
    for command in COMMANDS.values():
        if only is None or command.name == only:
            # a repeated argument takes the rest of the line, options it reads itself included (fit: the scene's options)
            rest = {"ignore_unknown_options": True} if any(option.positional and option.repeatable for option in command.options) else {}
            app.command(command.name, cls=TaucliCommand, context_settings=rest)(_callback(command, env))
    return app


def _present(value) -> bool:
    return value is not None and value is not False and value != () and value != []


def run_scene(command: Command, given: dict, env: Environment) -> int:
    """One scene's run: a single answer, a sweep, or a batch, as the answer options say."""
    asked = {option.name: given.pop(option.name, None) for option in command.output}
    scene_given = {name: value for name, value in given.items() if _present(value)}
    points = _whole_number(command, asked["points"])
    swept_range = swept_list = None
    if points is not None or any(isinstance(value, str) and (".." in value or "," in value) for value in scene_given.values()):
        from taucli.answering import sweep  # deferred: sweeps and the charts they draw (3 ms), only for a range or a list

        swept_range, swept_list = sweep.find(command, scene_given, points)
    if asked["batch"]:
        for name in ("plot", "out", "points", "y", "jsonl", "get", "format"):
            if _present(asked[name]):
                why = "writes whole JSON documents" if name == "get" else "writes one --json document per line"
                raise InputError(name, f"does not combine with {{batch}}, which {why}", example="{batch} {no_steps}" if name == "get" else None)
        if swept_range or swept_list:
            raise InputError((swept_range or swept_list).name, "cannot be a range or a list with {batch}: give one scene per line")
        from taucli.front import batch  # deferred: only --batch
        return batch.run(command, {**scene_given, **_finding(asked, batch=True)}, render.Output(to=tuple(asked["to"] or ()), steps=not asked["no_steps"]), env,
                         limit=None if asked["no_limit"] else answer.LIMIT_SECONDS)
    output = render.Output(
        json=bool(asked["json"] or asked["jsonl"]),
        get=tuple(asked["get"] or ()),
        to=tuple(asked["to"] or ()),
        steps=not asked["no_steps"],
        plot=bool(asked["plot"]),
        out=asked["out"],
        json_lines=bool(asked["jsonl"]),
        uncertainty=bool(asked["uncertainty"]),
        format=_format(asked),
    )
    named = {*output.get, *(asked["y"] or ()), *(to.partition("=")[0].strip() for to in output.to)}
    _point_at_the_rim(command, scene_given, named)
    answer.turn_on_what_makes(command, scene_given, named)
    if output.plot and output.get:
        raise InputError("plot", "draws a chart, and {get} prints numbers only", hint="{out} FILE.svg writes the chart to a file")
    if asked["y"] and swept_range is None:
        raise InputError("y", "names what a range's chart shows; give a range FROM..TO", example="{inertia} '0.5..4kg*m^2' {y} alpha0")
    if output.out is not None:
        from taucli.writing import plot  # deferred: charts (2 ms), only for --out

        plot.check_file(output.out)
    finding = {**_finding(asked), "mc": _whole_number(command, asked["mc"], "mc")}
    limit = None if asked["no_limit"] else answer.LIMIT_SECONDS

    with render.progress_bar(env.stderr, bool(finding.get("find") or finding["mc"])) as progress:
        def solve(options: dict):
            report = answer.solve(command, options, stdin=env.stdin, spell=command.flag, limit=limit, progress=progress, **finding)
            _made_what_is_named(command, report, output, asked["y"] or (), options)
            return report

        if swept_range is None and swept_list is None:
            report = solve(scene_given)
        else:
            from taucli.answering import sweep  # deferred: as above

            solved = sweep.solve_all(command, swept_range, swept_list, scene_given, solve)
    if swept_range is None and swept_list is None:
        render.render(report, output, env.stdout, env.stderr)
        return int(ExitStatus.OK)
    sweep.render(solved, swept_range, swept_list, output, list(asked["y"] or ()), env.stdout, env.stderr)
    return int(ExitStatus.OK)


def _point_at_the_rim(command: Command, given: dict, asked: set) -> None:
    """A point's result asked for (--get v_t) with no --at: the point on the rim (#24), which
    the scene finds, or refuses where the body has no one radius."""
    if command.option("at") is not None and given.get("at") is None and asked & {result.key for result in POINT_RESULTS}:
        given["at"] = "rim"


def _made_what_is_named(command: Command, report, output: render.Output, y, given: dict) -> None:
    """A result named in --get, --y or --to that this run did not make because an option it
    needs was not given: name that option (#42: "v needs --distance or --time")."""
    for option, names in (("get", output.get), ("y", y), ("to", [to.partition("=")[0].strip() for to in output.to])):
        for name in names:
            result = command.result(name)
            if name not in report.results and result is not None and result.needs and not result.made_by(given.get):
                raise InputError(option, f"{name} needs {result.needed()}", example=command.needs_example(result, given.get))


def _format(asked: dict) -> Optional[str]:
    """--format (#36): one of md, latex, html, csv, alone among the ways to answer."""
    return render.chosen_format(asked["format"], {name: _present(asked[name]) for name in ("json", "jsonl", "get", "plot")})


def _whole_number(command: Command, text: Optional[str], name: str = "points") -> Optional[int]:
    if text is None:
        return None
    try:
        if not text.strip().isascii() or "_" in text:  # one rule with quantities: no 1_000, no fullwidth ５
            raise ValueError(text)
        return int(text)
    except ValueError:
        raise InputError(name, "expected a whole number", example=f"{{{name}}} 50", got=repr(text)) from None


def _finding(asked: dict, *, batch: bool = False) -> dict:
    """--find and --want (#22), where given: a batch's lines take them as keys too."""
    if batch and (asked["mc"] is not None or asked["uncertainty"]):
        name = "mc" if asked["mc"] is not None else "uncertainty"
        raise InputError(name, "does not combine with {batch}, which writes whole JSON documents (each with its \"uncertainty\")")
    return {name: asked[name] for name in ("find", "want", "minimize", "maximize") if asked.get(name) is not None}


def _no_such_option(command: Command, unknown: str) -> str:
    """'--slip is not an option of atwood', and the closest of the command's own options where one
    is close (names compared without their dashes, which every flag shares)."""
    message = f"{unknown} is not an option of {command.name}"
    names = {option.flag[2:]: option.flag for option in (*command.options, *command.output) if not option.positional}
    names["help"] = "--help"  # --hlep (#42)
    if (unknown[1:2].isdigit() or unknown[1:2] == ".") and any(option.positional and option.kind == TEXT for option in command.options):
        return f"{message}: an argument that starts with a minus goes after -- (e.g. taucli {command.name} -- '-40 N*m' 'lbf*ft')"
    close = difflib.get_close_matches(unknown.lstrip("-").lower(), list(names), n=1, cutoff=0.6)  # --M1: flags are lower case
    return f"{message}; did you mean {names[close[0]]!r}?" if close else message


def _is_usage_error(err: Exception) -> bool:
    """Typer's (vendored or plain click) usage errors: they carry an exit code and a message."""
    return isinstance(getattr(err, "exit_code", None), int) and hasattr(err, "format_message")


def _fail(env: Environment, status: ExitStatus, message: str) -> int:
    print(f"taucli: error: {bounded(' '.join(message.split()))}", file=env.stderr)
    return int(status)


def _reader_gone() -> int:
    """The reader went away (`| head -c1`): say nothing more, and do not fail again on exit."""
    os.dup2(os.open(os.devnull, os.O_WRONLY), sys.__stdout__.fileno())
    return int(ExitStatus.OK)


def command_at(args: list[str]) -> int:
    """Where the command's name is in ``args``: the first word that is not an option (taucli's
    own options take no value), or len(args) when there is none."""
    return next((i for i, word in enumerate(args) if not word.startswith("-")), len(args))


def _debugging(args: list[str]) -> bool:
    """--debug before the command's name (taucli's own option), or TAUCLI_DEBUG in the environment."""
    return "--debug" in args[: command_at(args)] or bool(os.environ.get("TAUCLI_DEBUG"))


def main(argv: list[str] | None = None, env: Environment | None = None) -> int:
    """Run taucli; every exception becomes one line on stderr and an exit status."""
    args = sys.argv[1:] if argv is None else list(argv)
    env = env or Environment()
    env.stdout = streams.guarded(env.stdout)  # closed or full: one line and exit 74 (taucli.front.streams)
    try:
        answered = help.answer(args, env.stdout, env.stderr)
    except streams.OutputFailed as err:
        return streams.failed(err, env.stderr)
    if answered is not None:
        return answered
    at = command_at(args)
    command = COMMANDS.get(args[at]) if at < len(args) else None
    misread = usage.explain(command, args, at) or usage.given_twice(command, args, at)  # --m1 --m2 1kg, --torque 2 N m, -help, --m1 twice: the fix
    if misread is not None:
        where = f" (see 'taucli {command.name} --help')" if command is not None else " (see 'taucli --help')"
        return _fail(env, ExitStatus.USAGE, misread + where)
    try:
        result = build_app(env, command.name if command else None)(args=args, prog_name="taucli", standalone_mode=False)
        env.stdout.flush()  # what is still buffered is written now, where a failure is answered, not at exit
    except streams.OutputFailed as err:
        return streams.failed(err, env.stderr)
    except TaucliError as err:
        spell = command.flag if command is not None else (lambda name: name)
        return _fail(env, err.exit_status, err.spelled(spell) if isinstance(err, InputError) else str(err))
    except OverflowError:
        return _fail(env, ExitStatus.USAGE, str(out_of_range()))
    except KeyboardInterrupt:
        print(file=env.stderr)
        return int(ExitStatus.INTERRUPTED)
    except BrokenPipeError:
        return _reader_gone()
    except SystemExit as err:
        # With standalone_mode off, click's only sys.exit is its answer to a broken pipe (EPIPE:
        # exit 1), and rich's Console answers one with SystemExit(1) too.
        if err.code == 1:
            return _reader_gone()
        raise
    except Exception as err:
        if _is_usage_error(err):
            ctx = getattr(err, "ctx", None)
            where = f" (see '{ctx.command_path} --help')" if ctx is not None else " (see 'taucli --help')"
            unknown = getattr(err, "option_name", None)
            if unknown is not None and command is not None and type(err).__name__ == "NoSuchOption":
                return _fail(env, ExitStatus.USAGE, _no_such_option(command, unknown) + where)
            return _fail(env, ExitStatus.USAGE, err.format_message() + where)
        if _debugging(args):
            traceback.print_exc()
        return _fail(
            env,
            ExitStatus.INTERNAL,
            f"internal error ({type(err).__name__}: {err}); this is a bug in taucli, please report it "
            "with the command line (taucli --debug ... shows the traceback)",
        )
    return result if isinstance(result, int) else int(ExitStatus.OK)
