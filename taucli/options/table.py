"""The vocabulary of the one table each command is described by: its options and its results.

A command's table is the single description that the command line (typer), ``--help``, the
batch keys, sweeps, completions, the fuzz grammar, the option tables of docs/ and the Python
API all read. Plain data: importing a table imports no solver, no typer, no rich and no pint.

An option's ``name`` is the solver's keyword and the batch key; the flag is derived from it
(``pulley_mass`` -> ``--pulley-mass``). Its ``kind`` is a quantity kind of taucli.quantities.units
("mass", "angular velocity", ...) or one of the other kinds below.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from taucli.quantities.kinds import KINDS
from taucli.writing.report import NotApplicable, made_value

# Kinds that are not quantities.
CHOICE = "choice"  # a word from ``choices``
FLAG = "flag"  # on or off
FILE = "file"  # a path (- for stdin where the option says so)
PART = "part"  # "SHAPE key=value ...", repeatable
TEXT = "text"  # free text, read by the command itself (--to NAME=UNIT, --get NAME)
COUNT = "count"  # a whole number
VECTOR = "vector"  # "x,y,z UNIT": three components of the quantity kind in ``of`` (or one size, where a scene takes that)
NOT_QUANTITIES = frozenset({CHOICE, FLAG, FILE, PART, TEXT, COUNT})
NOT_QUANTITIES = NOT_QUANTITIES | {VECTOR}  # read a component at a time by its own reader, never swept
PARTICLE = "particle"  # "mass=… speed=… radius=… [angle=…] [speed-after=… | e=… | radius-after=…] [speed-relative=…]", repeatable
COUPLE = "couple"  # "[SHAPE] inertia=… | mass=… dims…, omega0=…": another body on the axis, repeatable
NOT_QUANTITIES = NOT_QUANTITIES | {PARTICLE, COUPLE}
BRAKE = "brake"  # "force=… mu=… [mu-s=…] [radius=…] [lever=… pivot=… offset=…] [shoe-angle=…]" or "expanding=yes …": a brake shoe on a turning body, repeatable
FACE = "face"  # "mu=… [force=…|pmax=…] [inner-radius=…] [outer-radius=…] [model=uniform|wear] [surfaces=…] [cone=…]": a pressed flat face (or a cone clutch's conical one), repeatable
BAND = "band"  # "mu=… wrap=… [radius=…] [width=…] tension=…|force=… lever=… slack-arm=…|tight-arm=…" (blocks=… block-angle=… [thickness=…] in place of wrap=: band-and-block): a band brake, repeatable
CENTRIFUGAL = "centrifugal"  # "shoes=… mass=… radius=… spring-force=… mu=… drum-radius=…": a centrifugal clutch read at ω₀
CALIPER = "caliper"  # "mu=… force=… [pad=annular] inner-radius=… outer-radius=… [angle=…] | pad=circular pad-radius=… centre-distance=…, [model=uniform|wear] [surfaces=N]": a caliper disc brake, repeatable
NOT_QUANTITIES = NOT_QUANTITIES | {BRAKE, FACE, BAND, CENTRIFUGAL, CALIPER}
SIDE = "side"  # "hang" | "table [mu-s=… mu-k=…]" | "incline angle=… [mu-s=… mu-k=…]": where a block of atwood is
PULL = "pull"  # "force=… [angle=…] [on=1|2]": a pull on a block of atwood, repeatable
NOT_QUANTITIES = NOT_QUANTITIES | {SIDE, PULL}
ROTOR = "rotor"  # "inertia=… spin=… sense=cw-from-rear": another rotor whose axis a vehicle turns (gyro), repeatable
NOT_QUANTITIES = NOT_QUANTITIES | {ROTOR}
REVOLVING = "revolving"  # "mass=… radius=… angle=… [plane=…] [length=…]": a mass turning with a shaft (balance), repeatable
NOT_QUANTITIES = NOT_QUANTITIES | {REVOLVING}
SEGMENT = "segment"  # "time=… torque=…|power=… [rest=yes]": a segment of a motor's duty cycle (drive), repeatable
NOT_QUANTITIES = NOT_QUANTITIES | {SEGMENT}
PHASE = "phase"  # "[coast] alpha=…|torque=… time=…|angle=…|until-omega=…": one phase of a spin-down run, repeatable, in order
NOT_QUANTITIES = NOT_QUANTITIES | {PHASE}
CURVE = "curve"  # a turning-moment diagram T(θ): a CSV file of crank angle and torque, or a formula of theta (flywheel)
NOT_QUANTITIES = NOT_QUANTITIES | {CURVE}
LOAD = "load"  # "inertia=… | mass=… radius=…|speed=…, ratio=… efficiency=… [efficiency-back=…] torque=… force=…": one of several loads a motor drives (drive), repeatable
NOT_QUANTITIES = NOT_QUANTITIES | {LOAD}
MOTOR_CURVE = "motor_curve"  # "tmax=… slip-max=… sync=…": an induction motor's torque–slip curve by Kloss's formula (drive)
NOT_QUANTITIES = NOT_QUANTITIES | {MOTOR_CURVE}

# The metavar of each quantity kind, shown in help and read by the completion scripts.
METAVARS = {
    "mass": "MASS",
    "length": "LENGTH",
    "angle": "ANGLE",
    "time": "TIME",
    "angular velocity": "OMEGA",
    "angular acceleration": "ALPHA",
    "torque": "TORQUE",
    "moment of inertia": "I",
    "force": "FORCE",
    "acceleration": "ACCEL",
    "velocity": "SPEED",
    "viscous coefficient": "B",
    "angular momentum": "L",
    "drag coefficient": "K",
    "dimensionless": "NUMBER",
    "power": "POWER",
    "energy": "ENERGY",
    "density": "DENSITY",
    "stress": "STRESS",
    "torsion constant": "KAPPA",
    "lead": "LEAD",
    "pressure": "PRESSURE",
}


@dataclass(frozen=True)
class Option:
    """One input of a command: what it takes, its help, and where it shows."""

    name: str
    kind: str
    help: str
    sign: str = "positive"  # for quantities: "positive" (> 0), "nonnegative" (>= 0) or "any"
    default: str | None = None  # as help shows it; the library applies it
    panel: str | None = None  # the heading it is listed under in --help
    choices: tuple[str, ...] = ()
    repeatable: bool = False
    positional: bool = False  # the command's argument (SHAPE) rather than an option
    metavar: str | None = None  # else the kind's
    of: str | None = None  # VECTOR: the quantity kind of its components ("force")
    words: tuple[str, ...] = ()  # words a quantity option takes as well ("rim" for --at)
    also: str | tuple[str, ...] | None = None  # other quantity kinds it takes, passed on as a Value (rolling's --at 30deg: an angle on the rim)
    of_time: bool = False  # takes a formula of t as well (quantities.formula), passed on as an OfTime

    @property
    def also_kinds(self) -> tuple[str, ...]:
        """The other quantity kinds it takes, in the order they are tried."""
        return () if self.also is None else (self.also,) if isinstance(self.also, str) else self.also
    first_reached: tuple[str, str] | None = None  # --find: of several roots, the first the motion reaches: least (this result, a time; then the angle from this option, the start)
    makes: tuple[str, ...] = ()  # FLAG: the results it turns on; naming one in --get, --y or --to turns it on
    example: str | None = None  # a value a message may suggest, where its kind has none (a spec: "force=100N mu=0.4 radius=0.5m")

    @property
    def flag(self) -> str:
        """How the command line spells it: --pulley-mass, or SHAPE for the argument."""
        return self.name.upper() if self.positional else "--" + self.name.replace("_", "-")

    @property
    def is_quantity(self) -> bool:
        return self.kind not in NOT_QUANTITIES

    @property
    def takes_value(self) -> bool:
        return self.kind != FLAG

    @property
    def shown_metavar(self) -> str:
        if self.metavar:
            return self.metavar
        if self.kind == CHOICE:
            return "|".join(self.choices) if len(self.choices) <= 3 else self.name.upper()
        return METAVARS.get(self.kind) or self.kind.upper()

    @property
    def sweepable(self) -> bool:
        """A range FROM..TO or a list A,B may stand for its value (quantities only)."""
        return self.is_quantity and not self.repeatable

    def help_text(self) -> str:
        """The help, with the default (as shown) before its closing full stop."""
        if not self.default:
            return self.help
        return f"{self.help.removesuffix('.')} (default {self.default})."


@dataclass(frozen=True)
class Result:
    """One result of a scene: its JSON key, SI unit, and what it is.

    A label with "…" has a part the solver fills in: "velocity …" is "velocity after 2 m" in
    one run and "velocity at t = 3 s" in another (the part brings its own leading space).
    """

    key: str
    unit: str | None
    label: str
    # What makes it where the docs example does not: alternatives, any one of which a run needs, each
    # one option or several given together ("time+alpha"): v needs ("distance", "time").
    needs: tuple[str, ...] = ()
    example: str | None = None  # the first alternative as typed, where its options' own example values do not make it

    @property
    def alternatives(self) -> tuple[tuple[str, ...], ...]:
        """The ways to make it, each the options given together: (("time", "alpha"), ("time", "torque"))."""
        return tuple(tuple(alternative.split("+")) for alternative in self.needs)

    def needed(self, spell=lambda name: f"{{{name}}}") -> str:
        """What makes it, as a message says it: "{distance} or {time}"; "{time} with {alpha}, or
        {in_time} with {until_omega}"; "{v0} with {mass}, {length} and {radius}"; "{ratio} twice"
        (each name as ``spell`` writes it: a placeholder, spelled per surface, by default)."""
        ways = []
        for alternative in self.alternatives:
            counted = [spell(name) + ("" if n == 1 else " twice" if n == 2 else f" {n} times") for name, n in _counted(alternative)]
            first, rest = counted[0], counted[1:]
            together = ", ".join(rest[:-1]) + " and " + rest[-1] if len(rest) > 1 else "".join(rest)
            ways.append(f"{first} with {together}" if rest else first)
        if any(len(alternative) > 1 for alternative in self.alternatives):
            return ", or ".join(ways)  # "or" between the ways, where a way may hold a comma
        return ", ".join(ways[:-1]) + " or " + ways[-1] if len(ways) > 1 else "".join(ways)

    def made_by(self, given) -> bool:
        """Whether ``given`` (a name -> value lookup) holds every option of one of its alternatives
        (a repeatable option named n times in one, n values of it)."""
        return any(all(holds(given, name, n) for name, n in _counted(alternative)) for alternative in self.alternatives)


def _counted(alternative: tuple[str, ...]) -> list[tuple[str, int]]:
    """Each option of a way to make a result once, with the times it is named ("ratio+ratio": two stages)."""
    return [(name, alternative.count(name)) for name in dict.fromkeys(alternative)]


def holds(given, name: str, times: int = 1) -> bool:
    """Whether ``given`` (a name -> value lookup) holds the option ``name`` (``times`` values of it):
    a text, a list, True for a flag, a number at a sweep's point (0.0 is given: no ==, as 0.0 == False)."""
    value = given(name)
    if value is None or value is False or isinstance(value, (list, tuple)) and len(value) < times:
        return False
    return times == 1 or isinstance(value, (list, tuple))


@dataclass(frozen=True)
class Command:
    """A command of the command line, described once."""

    name: str  # as typed: "spin-down"
    summary: str  # one line: the first of --help and the command list
    example: str
    options: tuple[Option, ...]
    description: str = ""  # more of --help, after the summary
    results: tuple[Result, ...] = ()
    headline: str | None = None  # the result a range's chart shows by default
    library: str | None = None  # "module:function" that takes the options' values in SI
    handler: str | None = None  # for commands that are not scenes: "module:function"
    output: tuple[Option, ...] = ()  # how to answer (--json, --get, ...), not read as inputs
    _index: dict = field(default_factory=dict, compare=False, repr=False)

    def __post_init__(self) -> None:
        names = [option.name for option in (*self.options, *self.output)]
        if len(set(names)) != len(names):  # an option listed twice (a shared group and its own line)
            raise ValueError(f"{self.name}: options named twice in its table: {sorted({n for n in names if names.count(n) > 1})}")
        self._index.update({option.name: option for option in (*self.options, *self.output)})
        self._index["inputs:"] = frozenset(option.name for option in self.options)
        self._index["position:"] = {option.name: number for number, option in enumerate(self.options)}
        self._index.update({"result:" + result.key: result for result in self.results})
        # what Results.put needs of each result, looked up once: (unit, label, whether it has a "…")
        self._index["results:"] = {result.key: (result.unit, result.label, FILLED in result.label) for result in self.results}

    @property
    def function_name(self) -> str:
        """The Python API's name for it: taucli.spin_down."""
        return self.name.replace("-", "_")

    def option(self, name: str) -> Option | None:
        return self._index.get(name)

    def result(self, key: str) -> Result | None:
        return self._index.get("result:" + key)

    def flag(self, name: str) -> str:
        """The flag of an option (or the name unchanged when it is none of this command's)."""
        found = self.option(name)
        return found.flag if found is not None else name

    def in_order(self, names) -> list[str]:
        """The input ``names`` in the table's order (the order the inputs are echoed in)."""
        return sorted(names, key=self._index["position:"].__getitem__)

    @property
    def input_names(self) -> frozenset[str]:
        """The names of its inputs (the options a scene reads), not of how to answer."""
        return self._index["inputs:"]

    def results_line(self) -> str:
        return ", ".join(result.key for result in self.results)

    def needs_example(self, result: Result, given=lambda name: None) -> str | None:
        """The first way to make ``result`` as typed, each option a {name} placeholder with a value:
        the result's own example, else each option's (or its kind's) example value, quoted for the
        shell, leaving out the options ``given`` holds already; None where an option of it has no
        example value."""
        if result.example is not None:  # the way's options already given left out ("--length 2m --radius 0.1m" beside --length: "--radius 0.1m"); a setting it makes kept
            way = set(result.alternatives[0]) if result.needs else set()
            kept = [m[0] for m in _PLACED.finditer(result.example) if not (m[1] in way and holds(given, m[1]))]
            return " ".join(kept) if kept else result.example
        if not result.needs:
            return None
        typed = []
        for name in result.alternatives[0]:
            option = self.option(name)
            if option is None:
                return None
            value = option.example or (KINDS[option.kind].example if option.kind in KINDS else None)
            if holds(given, name):
                continue
            if option.kind == FLAG:
                typed.append(f"{{{name}}}")
            elif value is None:
                return None
            else:
                typed.append(f"{{{name}}} {shell_word(value)}")
        return " ".join(typed)


class Results(dict):
    """The results a solver fills in (a dict of key -> Value), each from its scene's table: the
    unit and the label come from there.

    ``put("t", 1.2, " 2 m")`` checks that ``t`` is one of the scene's results, so a name that
    is not in the table fails at once rather than reaching a user, and fills the label's "…".
    """

    __slots__ = ("command", "_known")

    def __init__(self, command: Command):
        super().__init__()
        self.command = command
        self._known = command._index["results:"]

    def __missing__(self, key: str):
        """``results["KE0"]`` where this run has no KE0: say what makes it (#36)."""
        raise MissingResult(key, self.command, tuple(self))

    def put(self, key: str, value, part: str = "") -> None:
        found = self._known.get(key)
        if found is None:
            raise KeyError(f"{key!r} is not a result of {self.command.name} in its table")
        unit, label, open_part = found
        self[key] = made_value((value, unit, label.replace(FILLED, part) if open_part else label))

    def not_applicable(self, *keys: str) -> None:
        """Each of ``keys`` null because the scene cannot have it (NotApplicable: a note says why;
        the human views leave its row out)."""
        for key in keys:
            self.put(key, None)
            self[key] = NotApplicable(*self[key])


_PLACED = re.compile(r"""\{([a-z][a-z0-9_]*)\}(?: (?!\{)(?:'[^']*'|"[^"]*"|\S+))?""")  # "{name} value" (a flag: "{name}") in an example

FILLED = "…"  # where a result's label takes the part its solver fills in
_PLAIN = re.compile(r"[A-Za-z0-9_.,:/+@%-][A-Za-z0-9_.,:/+=@%-]*")  # a word every shell (bash, zsh, fish) takes as it is (zsh expands a leading =)


def shell_word(value: str) -> str:
    """``value`` as one word of a command line in bash, zsh and fish: as it is, else in single
    quotes (a kind's example may come quoted already: "'6 rad/s^2'")."""
    if value[:1] in "'\"" and value[-1:] == value[:1] or _PLAIN.fullmatch(value):
        return value
    return "'" + value.replace("'", "'\\''") + "'"


class MissingResult(KeyError):
    """A result this run has not made: which keyword makes it, or which results the run has.

    A KeyError, so that ``"KE0" in results`` and ``results.get("KE0")`` work as on any dict.
    """

    def __init__(self, key: str, command: Command, present: tuple[str, ...]):
        super().__init__(key)
        self.key, self.scene, self.present = key, command.name, present
        self.makers = tuple(option.name for option in command.options if key in option.makes)
        result = command.result(key)
        self.in_table = result is not None
        self.needs = result.needs if result is not None else ()
        self._result = result

    def __str__(self) -> str:
        if self.needs:
            keywords = self._result.needed(lambda name: f"{name}=")
            flags = self._result.needed(lambda name: "--" + name.replace("_", "-"))
            return f"{self.key} is not among this run's results: it needs {keywords} ({flags} on the command line)"
        if self.makers:
            turn_on = " or ".join(f"{name}=True" for name in self.makers)
            flags = " or ".join("--" + name.replace("_", "-") for name in self.makers)
            return f"{self.key} is not among this run's results: {turn_on} turns it on ({flags} on the command line)"
        if self.in_table:
            return (f"{self.key} is a result of {self.scene} that these inputs do not make (its page in docs/ says which do); "
                    f"this run's results: {', '.join(self.present)}")
        return f"{self.key} is not a result of {self.scene}; this run's results: {', '.join(self.present)}"
