"""How a run is answered: plainly, with uncertainties, solving for an input, or by Monte Carlo.

The one layer above the pipeline. Every surface (the command line, a sweep's point, a batch line,
the Python API) calls ``solve``: with no uncertainty, no ``--find`` and no ``--mc`` it is
``pipeline.solve`` and nothing else; otherwise taucli.answering.propagate (uncertainties through the
scene) or taucli.answering.find (an input solved for) works around the pipeline. Neither imports this.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping

from taucli.answering import pipeline
from taucli.core.errors import InputError
from taucli.answering.inputs import read
from taucli.quantities.measurement import CONCISE, split
from taucli.writing.report import Report
from taucli.options.table import FILE, Command


LIMIT_SECONDS = 60.0  # the longest --find or --mc may be estimated to take on the command line before it is refused (--no-limit lifts it)


def _as_named(name: str) -> str:
    return name


def plain(given: Mapping[str, object], find=None, want=None, mc=None) -> bool:
    """Whether ``pipeline.solve`` alone answers: no input carries an uncertainty, nothing is
    solved for and no Monte Carlo is asked."""
    if find is not None or want is not None or mc:
        return False
    for value in given.values():  # inline, not a helper per value: this runs on every batch line (measurement.marked)
        if value.__class__ is str and ("±" in value or "+/-" in value or (")" in value and CONCISE.fullmatch(value) is not None)):
            return False
        if value.__class__ in (list, tuple) and any(item.__class__ is str and ("±" in item or "+/-" in item) for item in value):
            return False  # a repeated option's value with an uncertainty: read by _read, which says it is not carried through
    return True


def turn_on_what_makes(command: Command, given: dict, asked: set) -> None:
    """A result named in --get, --y, --to or --want is made: the flag that makes it (--energy for
    KE0) is turned on, as if given."""
    for option in command.options:
        if option.makes and not given.get(option.name) and asked & set(option.makes):
            given[option.name] = True


def solve(
    command: Command,
    given: Mapping[str, object],
    *,
    find: str | None = None,
    want: str | None = None,
    mc: int | None = None,
    stdin=None,
    spell: Callable[[str], str] = _as_named,
    limit: float | None = None,
    progress=None,
    minimize: str | None = None,
    maximize: str | None = None,
) -> Report:
    """The scene's report, as ``pipeline.solve`` gives it, with uncertainties where any input
    carries one, solved for the input ``find`` where ``want`` (RESULT=VALUE) says. ``limit``
    (seconds) refuses --find and --mc work estimated to take longer; ``progress`` is told how many
    of its planned solves are done."""
    if isinstance(want, str) and find is not None:  # --want KE0=…: what makes KE0 (--energy) is on, as for --get (#48 item 3)
        given = dict(given)
        turn_on_what_makes(command, given, {want.partition("=")[0].strip()})
    optimum = _optimum(find, want, minimize, maximize)
    if optimum is not None:  # what makes the result is on, as for --want
        given = dict(given)
        turn_on_what_makes(command, given, {optimum[0]})
    if plain(given, find, want, mc) and optimum is None:
        return pipeline.solve(command, given, stdin=stdin, spell=spell)
    from taucli.answering import find as finding  # deferred: find and propagate, with what they import, only for these runs
    from taucli.answering import propagate
    if optimum is None and (find is None) != (want is None):
        raise InputError("find" if find is None else "want", "goes with {" + ("want" if find is None else "find") + "}",
                         example="{find} pulley_inertia {want} a=4.0m/s^2")
    if mc is not None and not 2 <= mc <= propagate.MC_MAX:
        raise InputError("mc", f"expected a number of draws from 2 to {propagate.MC_MAX}", example="{mc} 2000", got=repr(mc))
    for name, value in given.items():
        option = command.option(name)
        if option is not None and option.kind == FILE and value is not None:
            raise InputError(name, "does not combine with an uncertainty, {find} or {mc}: the scene is solved many times, and a file is read once")
    unknown = finding.unknown(command, find, given) if find is not None else None
    central, spreads, placed = _read(command, given, propagate.readable(command, given, unknown))
    notes: list[str] = []
    scene = propagate.Scene(command, central, stdin, spell, unknown, limit=limit)
    for name, (input_, centre) in placed.items():  # a spec's key, a repeated option's value: moved in its place
        scene.unknowns[name] = input_
        scene.si[name] = centre
    scene.progress = progress
    if optimum is not None:
        from taucli.answering.optimum import optimize  # deferred: only for --minimize and --maximize

        if spreads or mc:
            raise InputError(optimum[2], "takes inputs without uncertainties (and no {mc}): the optimum is found at the values given")
        return optimize(scene, unknown, optimum[0], optimum[1], notes)
    if unknown is not None:
        return finding.solve_for(scene, unknown, want, spreads, notes, mc)
    nominal = scene.report({})
    if not spreads and not mc:
        nominal.notes = [*notes, *nominal.notes]
        return nominal
    slopes = propagate.jacobian(scene, {name: scene.si[name] for name in spreads}, spreads)
    sigma = propagate.combine(slopes, spreads, propagate.numeric(nominal))
    notes = [*notes, *propagate.linearity(scene, nominal, spreads, slopes)]
    report = propagate.measured(nominal, sigma, spreads, notes)
    if mc:
        scene.plan(mc, "mc")
        propagate.monte_carlo(scene, report, spreads, mc, lambda draw: scene.report(draw), arrays=True)
    return report


OPTIMUM_EXAMPLE = "{find} ratio {minimize} torque_rms"  # (drive: the gear ratio with the least RMS motor torque)


def _optimum(find, want, minimize, maximize) -> tuple[str, float, str] | None:
    """(the result, +1 for the least or −1 for the most, the option) where --minimize or --maximize asks; None else."""
    asked = [(name, value) for name, value in (("minimize", minimize), ("maximize", maximize)) if value is not None]
    if not asked:
        return None
    name, value = asked[0]
    if len(asked) > 1:
        raise InputError("maximize", "conflicts with {minimize}: ask for the least or the most of one result", example=OPTIMUM_EXAMPLE)
    if want is not None:
        raise InputError(name, "conflicts with {want}: --find solves for a target or for the least or most of a result, one of them", example=OPTIMUM_EXAMPLE)
    if find is None:
        raise InputError(name, "goes with {find}: the input whose value gives the " + ("least" if name == "minimize" else "most") + " of the result",
                         example=OPTIMUM_EXAMPLE)
    return str(value).strip(), 1.0 if name == "minimize" else -1.0, name


def _read(command: Command, given: Mapping[str, object], readable: Mapping[str, object]) -> tuple[dict, dict[str, float], dict]:
    """The options with each value's text in place of "value ± σ", each σ in SI (read from
    ``readable``: the options with a stand-in where --find solves for a key of a spec), and the
    inputs with a σ that are not options of their own (a spec's key, one value of a repeated
    option): name -> (how it is moved in its place, its value in SI)."""
    _, inputs = read(command, readable)
    spreads: dict[str, float] = {}
    placed: dict = {}
    central = dict(given)
    for key, sigma in (inputs.uncertainties or {}).items():
        origin = inputs.origins.get(key)
        option = command.option(key)
        if origin is not None:
            from taucli.answering.unknowns import Placed  # deferred: only for an uncertainty inside a spec or a repeated option

            input_ = Placed(key, origin)
            central = input_.changed(central, lambda text: split(text)[0] if split(text) is not None else text)
            placed[key] = (input_, inputs.values[key].value)
        elif option is not None and option.is_quantity and not option.repeatable:
            central[key] = split(given[key])[0]
        else:  # never shown with an uncertainty of 0: refused where it cannot be carried through
            raise InputError(key, "takes no uncertainty here: give its value alone", got=repr(sigma))
        if sigma > 0:
            spreads[key] = sigma
    return central, spreads, placed
