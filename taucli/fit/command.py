"""The command line of ``taucli fit SCENE FILE… [SCENE OPTIONS]``: no physics here.

The words after SCENE are data files and the scene's own options (``--inertia 0.1kg*m^2``), read
with the scene's table as ``taucli SCENE`` reads them; fit's own options (``--fit``, ``--x``,
``--json``) typer has read already. Then: the tables -> the samples -> the fit -> the report ->
the writer, and the chart where asked for.
"""

from __future__ import annotations

import numpy as np

from taucli.writing import render
from taucli.writing.document import document_text
from taucli.core.errors import InputError, did_you_mean
from taucli.fit import budget, chart, data, residuals, results, runs, samples, solve
from taucli.fit.model import Model
from taucli.answering.answer import LIMIT_SECONDS
from taucli.answering.inputs import read
from taucli.options import COMMANDS, SCENES
from taucli.options.fit import COMMAND as FIT
from taucli.writing.report import Report
from taucli.options.table import FLAG, Command


def _scene(name: str | None) -> Command:
    if name is None or name.replace("_", "-") not in SCENES:
        raise InputError("scene", f"expected a scene: {', '.join(SCENES)}", example="taucli fit spin-down coast.csv --inertia '0.1 kg*m^2' --fit friction",
                         got=None if name is None else repr(name), hint=did_you_mean(str(name), list(SCENES)) if name else None)
    return SCENES[name.replace("_", "-")]


def split_words(command: Command, words: list[str]) -> tuple[list[str], dict[str, object]]:
    """(the data files, the scene's options) from the words after SCENE."""
    files: list[str] = []
    given: dict[str, object] = {}
    flags = {option.flag: option for option in command.options if not option.positional}
    position = [option for option in command.options if option.positional]
    items = iter(words)
    for word in items:
        if word.startswith("--") and len(word) > 2:
            flag, equals, value = word.partition("=")
            option = flags.get(flag)
            if option is None:
                raise _not_taken(command, flag, sorted(flags) + sorted({o.flag for o in (*FIT.options, *FIT.output)}))
            if option.kind == FLAG:
                given[option.name] = True
                continue
            if not equals:
                value = next(items, None)
                if value is None:
                    raise InputError("", f"{flag} expects a value", example=f"taucli fit {command.name} FILE {flag} {option.shown_metavar}")
            if option.repeatable:
                given.setdefault(option.name, []).append(value)
            elif option.name in given:
                raise InputError("", f"{flag} is given twice")
            else:
                given[option.name] = value
        elif position and word in position[0].choices and position[0].name not in given:
            given[position[0].name] = word  # a scene's SHAPE (rolling sphere), where it takes one
        else:
            files.append(word)
    if not files:
        raise InputError("data", "expected a data file (CSV) after the scene", example=f"taucli fit {command.name} runs.csv --fit NAME")
    return files, given


def _not_taken(command: Command, flag: str, known: list[str]) -> InputError:
    """A flag that is neither fit's nor an input of the scene: where another command takes it, say
    so (fit … --format suggested --force), else the nearest name."""
    if any(option.flag == flag for option in command.output):
        writes = flag in ("--jsonl", "--batch", "--points", "--y")
        return InputError("", f"{flag} is an option of taucli {command.name}'s own runs, not of fit",
                          hint="fit answers as text, as one JSON document (--json), as numbers (--get NAME, with --uncertainty), "
                          "or as a document (--format md|latex|html|csv)" if writes else None)
    takers = [other.name for other in COMMANDS.values() if other.name not in ("fit", command.name)
              and any(option.flag == flag for option in (*other.options, *other.output))]
    if takers:
        return InputError("", f"{flag} is not an input of {command.name} nor an option of fit ({', '.join(takers)} take{'s' if len(takers) == 1 else ''} it)")
    return InputError("", f"{flag} is not an option of fit, nor an input of {command.name}", hint=did_you_mean(flag, known))


def fitted(scene: str, files: list[str], given: dict, *, fit, x=(), y=None, sigma=None, ranges=(), every=None, per_run=(), counts_per_rev=None, counts=None,
           stdin=None, spell=None, scale_covariance: bool = False, bounds=()) -> Report:
    """The fit's report (what the Python API returns: no time limit, as --find's has none there)."""
    return fit_of(scene, files, given, fit=fit, x=x, y=y, sigma=sigma, ranges=ranges, every=every, per_run=per_run, counts_per_rev=counts_per_rev,
                  counts=counts, stdin=stdin, spell=spell, scale_covariance=scale_covariance, bounds=bounds)[0]


def fit_of(scene: str, files: list[str], given: dict, *, fit, x=(), y=None, sigma=None, ranges=(), every=None, per_run=(), counts_per_rev=None, counts=None,
           stdin=None, spell=None, limit: float | None = None, progress=None, scale_covariance: bool = False, bounds=()) -> tuple[Report, solve.Fit]:
    """The fit's report, and the fit itself (for the chart). ``limit`` (seconds) refuses a fit
    estimated to take longer (taucli.fit.budget); ``progress`` is told the solves done and planned;
    ``scale_covariance``: with ``sigma``, the covariance scaled by χ²/ν."""
    command = _scene(scene)
    spell = spell or command.flag
    if scale_covariance and sigma is None:
        raise InputError("scale_covariance", "scales the covariance by χ²/ν where {sigma} gives the samples' uncertainties; without them "
                         "it is scaled by the residual variance already", example="{sigma} 0.05rad/s {scale_covariance}")
    tables = [data.read(source, stdin) for source in files]
    names = solve.names_of(fit)
    gravity = read(command, {"g": given["g"]})[0].get("g") if given.get("g") is not None else None
    found_samples = samples.build(command, tables, x=x, y=y, sigma=sigma, ranges=ranges, every=every, fitted=names, given=set(given), gravity=gravity,
                                  counts_per_rev=counts_per_rev, counts=counts)
    model, starts, notes = solve.model_of(command, given, names, found_samples, stdin=stdin, spell=spell)
    if per_run and not runs.names(per_run):
        raise InputError("per_run", "expected the inputs of {fit} to fit for each run, by name", example="{fit} friction,omega0 {per_run} omega0",
                         got=repr(",".join(str(part) for part in per_run)))
    bound = None
    if limit is not None or progress is not None:
        faster = [name for name in ("dt", "method") if command.option(name) is not None]
        bound = budget.Budget(limit, progress, every=int(str(every).strip()) if every is not None else 1, faster=faster)
    if runs.names(per_run):
        try:
            model, starts = _per_run(model, starts, runs.names(per_run), notes, bound)
        except budget.Spent as spent:  # (one budget for the runs' own fits and the joint one)
            raise spent.refusal from None
    solve.bounds_of(model, bounds, gravity)  # (after the runs' model: a bound holds for every run's own value too)
    model.budget = bound
    try:
        with np.errstate(all="ignore"):  # numbers past a double's range are looked for where they matter (NaN, inf: refused or said)
            found = solve.fit(model, starts, rescale=scale_covariance)
            if runs.names(per_run):  # the starts are the runs' own fits, not values the user gave
                found.method = found.method.replace("from the starts given", "from each run fitted alone")
            report = results.written(found)
    except budget.Spent as spent:
        raise spent.refusal from None
    except np.linalg.LinAlgError as err:  # a least squares on numbers that leave it without a solution
        raise InputError("fit", f"the least squares has no solution with these samples and inputs ({err})",
                         hint="give magnitudes nearer everyday sizes, or fit fewer inputs") from None
    report.notes[:0] = notes
    return report, found


BAR_AFTER = 1.0  # seconds a fit runs before its progress bar shows (on a terminal): a quick fit shows none


def _per_run(model: Model, starts: dict[str, float], per_run: list[str], notes: list[str], bound) -> tuple[Model, dict[str, float]]:
    """The model with the inputs --per-run names fitted for each run, and its start (taucli.fit.runs);
    the runs' own fits spend of the fit's time budget ``bound`` (a budget.Budget, or None) too."""
    samples = model.samples
    unknowns = runs.expand(model.unknowns, per_run, samples)

    def fit_run(run_samples) -> dict[str, float]:
        alone = Model(model.command, model.held, model.unknowns, run_samples, si=model.si, stdin=model.stdin, spell=model.spell)
        alone.budget = bound
        with np.errstate(all="ignore"):
            return dict(zip(alone.names, (float(x) for x in solve.fit(alone, starts).p)))

    joint = runs.starts(samples, unknowns, starts, fit_run)
    first = samples.run_names[0]
    notes.append(f"{len(samples.run_names)} runs fitted together ({', '.join(samples.run_names)}): {', '.join(per_run)} fitted for each, "
                 f"the other inputs shared; the scene's results below are run 1's ({first})")
    return Model(model.command, model.held, unknowns, samples, si=model.si, spreads=model.spreads, stdin=model.stdin, spell=model.spell), joint


def run(env, given: dict) -> int:
    """taucli fit: read, fit, write."""
    command = _scene(given.get("scene"))
    files, scene_given = split_words(command, list(given.get("data") or []))
    output = render.Output(
        json=bool(given.get("json")), get=tuple(given.get("get") or ()), to=tuple(given.get("to") or ()), steps=not given.get("no_steps"),
        uncertainty=bool(given.get("uncertainty")),
        format=render.chosen_format(given.get("format"), {name: bool(given.get(name)) for name in ("json", "get", "plot")}),
    )
    if given.get("plot") and output.get:
        raise InputError("plot", "draws a chart, and {get} prints numbers only", hint="{out} FILE.svg writes the chart to a file")
    if given.get("out") is not None:
        from taucli.writing import plot  # deferred: charts, only for --out

        plot.check_file(given["out"])
    if given.get("residuals") is not None:
        residuals.check(given["residuals"], files)
    try:
        with render.progress_bar(env.stderr, True, after=BAR_AFTER) as progress:
            report, found = fit_of(command.name, files, scene_given, fit=given.get("fit"), x=tuple(given.get("x") or ()), y=given.get("y"),
                                   sigma=given.get("sigma"), ranges=tuple(given.get("range") or ()), every=given.get("every"),
                                   per_run=tuple(given.get("per_run") or ()), counts_per_rev=given.get("counts_per_rev"), counts=given.get("counts"), stdin=env.stdin,
                                   limit=None if given.get("no_limit") else LIMIT_SECONDS, progress=progress,
                                   scale_covariance=bool(given.get("scale_covariance")), bounds=tuple(given.get("bound") or ()))
    except InputError as err:  # each name by its flag: fit's own (--fit, DATA), else the scene's (--inertia)
        raise InputError("", err.spelled(lambda name: FIT.flag(name) if FIT.option(name) is not None else command.flag(name))) from None
    found.model.budget = None  # the fit is done: the chart's curve and band, and the residuals, are not its time
    if given.get("residuals") is not None:  # the files first, as the scenes write --out's: one that cannot be written is refused before any answer
        residuals.write(found, given["residuals"], said_to=env.stderr)
    drawn = chart.chart(found) if given.get("out") is not None or (given.get("plot") and not output.json) else None
    if given.get("out") is not None:  # the file first, as the scenes do: one that cannot be written (a full disk) is refused before any answer
        from taucli.writing import plot  # deferred: matplotlib, only for --out

        plot.write_file(drawn, given["out"], said_to=env.stderr)
    if output.json:
        shown = render.prepared(report, output)
        document = chart.document(found) if given.get("plot") else None
        env.stdout.write(document_text(shown, steps=output.steps, plot=document) + "\n")
    else:
        render.render(report, output, env.stdout, env.stderr)
        if given.get("plot"):
            from taucli.writing import plot  # deferred: charts, only for --plot

            columns, colour = render.terminal_style(env.stdout)
            env.stdout.write("\n" + plot.terminal(drawn, columns, colour=colour))
    env.stdout.flush()
    if output.json or output.get:  # a script reads the numbers alone: the fit's warnings beside them, one line each
        env.stderr.write("".join(f"taucli: warning: {text}\n" for text in warnings(report)))
    return 0


WARNING = "warning: "  # a note that says the numbers may be wrong (taucli.fit.results)


def warnings(report: Report) -> list[str]:
    """The fit's warnings, each on one line without its prefix: what --get and --json also say on
    stderr, as the human view says them among the notes (a result is never hidden behind a flag)."""
    return [" ".join(note[len(WARNING):].split()) for note in report.notes if note.startswith(WARNING)]
