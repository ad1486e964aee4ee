"""The Typer app: one thin command per scene: parse options -> call the solver -> render.

No physics here. Solvers, units and renderers are imported inside the commands, so that
``--help`` builds no unit registry and imports no solver it does not show.
"""

import os
import sys
from typing import TYPE_CHECKING, Annotated, Optional

import typer

from taucli.errors import ExitStatus, InputError, TaucliError, out_of_range
from taucli.names import BENCH_SCENES, METHOD_NAMES, PULLEY_SHAPES, QUADRATURE_NAMES, ROLLING_BODIES, SHAPE_AXES, SHAPE_NAMES

if TYPE_CHECKING:
    from taucli.inputs import Inputs


class _AsTyped:
    """Coercion that leaves a value as click parsed it: strings as typed, flags as booleans.

    typer 0.29 validates every given value through a pydantic TypeAdapter; importing pydantic
    costs about 100 ms, a third of a run, to turn a str into the same str. taucli reads every
    value itself (units.parse). Where typer has no ``_runtime_param`` (before 0.29, or after a
    change), its own coercion stays: slower, never wrong; tests/test_startup.py notices.
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


class _Lean:
    """What taucli's commands change in typer's: options read as typed, and plain-text help with
    options grouped under their panel titles.

    Typer's rich help imports rich's markdown support (~130 ms, more than the rest of a run);
    click's formatter is already loaded, reads the same without colour, and wraps to the terminal.
    """

    def parse_args(self, ctx, args):
        for param in self.get_params(ctx):
            _AsTyped.install(param)
        return super().parse_args(ctx, args)

    def format_options(self, ctx, formatter) -> None:
        sections: dict[str, list[tuple[str, str]]] = {}
        for param in self.get_params(ctx):
            record = param.get_help_record(ctx)
            if record is not None:
                title = "Arguments" if param.param_type_name == "argument" else getattr(param, "rich_help_panel", None) or "Options"
                sections.setdefault(title, []).append(record)
        for title, records in sections.items():
            with formatter.section(title):
                formatter.write_dl(records)
        if hasattr(self, "format_commands"):
            self.format_commands(ctx, formatter)


class TaucliGroup(_Lean, typer.core.TyperGroup):
    pass


class TaucliCommand(_Lean, typer.core.TyperCommand):
    pass


EXIT_STATUSES = (
    "Exit status: 0 success; 1 internal error (a bug in taucli: please report it, and --debug shows "
    "the traceback); 2 bad input (one line on stderr names the option); 130 interrupted (Ctrl-C)."
)

app = typer.Typer(
    name="taucli",
    cls=TaucliGroup,
    help="Rigid-body rotation about a fixed axis: τ_net = Iα and what follows from it.\n\n"
    "Quantities take units: 4kg, 300 rpm, 0.3 N*m, 30deg. A bare number is SI.\n\n"
    + EXIT_STATUSES,
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
    rich_markup_mode=None,
)


def _show_version(value: bool) -> None:
    if value:
        from taucli import __version__

        print(f"taucli {__version__}")
        raise typer.Exit()


@app.callback()
def taucli(
    version: Annotated[
        bool, typer.Option("--version", callback=_show_version, is_eager=True, help="Print the version and exit.")
    ] = False,
    debug: Annotated[
        bool, typer.Option("--debug", help="On an internal error (exit 1), print the traceback (or set TAUCLI_DEBUG=1).")
    ] = False,
) -> None:
    """Rigid-body rotation about a fixed axis: τ_net = Iα and what follows from it."""


_OUTPUT = "Output"
_BODY = "Body (shape and dimensions)"

JsonFlag = Annotated[bool, typer.Option("--json", help="Print one strict JSON document on stdout.", rich_help_panel=_OUTPUT)]
GetOption = Annotated[
    Optional[list[str]],
    typer.Option("--get", metavar="NAME", help="Print only this result's number (repeatable, one per line).", rich_help_panel=_OUTPUT),
]
ToOption = Annotated[
    Optional[list[str]],
    typer.Option("--to", metavar="NAME=UNIT", help="Show a result in this unit, e.g. --to I=g*cm^2 (repeatable).", rich_help_panel=_OUTPUT),
]
NoStepsFlag = Annotated[bool, typer.Option("--no-steps", help="Leave out the worked steps (the human view, and --json's steps list).", rich_help_panel=_OUTPUT)]
BatchFlag = Annotated[
    bool,
    typer.Option(
        "--batch",
        help="Many scenes: read JSON lines on stdin, keys the option names (m1, pulley_mass), and write one --json document per line.",
        rich_help_panel=_OUTPUT,
    ),
]


JsonLinesFlag = Annotated[bool, typer.Option("--jsonl", help="Like --json, but a sweep's documents one per line rather than one array.", rich_help_panel=_OUTPUT)]
_SWEEP = "Sweep and plot (any quantity option takes a range FROM..TO or a list A,B)"
PlotFlag = Annotated[
    bool,
    typer.Option(
        "--plot",
        help="Draw the motion against time (a list: one curve per value; a range: its chart), leaving out a sweep's table. With --json: the samples.",
        rich_help_panel=_SWEEP,
    ),
]
OutOption = Annotated[
    Optional[str],
    typer.Option("--out", metavar="FILE", help="Also draw the chart to FILE.svg or FILE.png (needs matplotlib: pip install 'taucli[plot]').", rich_help_panel=_SWEEP),
]
PointsOption = Annotated[Optional[str], typer.Option("--points", metavar="N", help="Values in a range FROM..TO, ends included (default 50).", rich_help_panel=_SWEEP)]
YOption = Annotated[
    Optional[list[str]],
    typer.Option("--y", metavar="NAME", help="A result to chart against a range (repeatable; default the scene's main result).", rich_help_panel=_SWEEP),
]

_collected: list | None = None  # while a sweep solves its points, emit hands reports here


def dispatch(command, given: dict) -> Optional[int]:
    """Run a batch or a sweep in place of the single run of ``command``; None for a single run."""
    swept_range = swept_list = None
    if given["points"] is not None or any(isinstance(value, str) and (".." in value or "," in value) for value in given.values()):
        from taucli import sweep

        swept_range, swept_list = sweep.find(given, _whole_number("--points", given["points"]))
    if given["batch"]:
        for name in ("plot", "out", "points", "y", "jsonl"):
            if given[name]:
                raise InputError("--" + name, "does not combine with --batch, which writes one --json document per line")
        if swept_range or swept_list:
            raise InputError((swept_range or swept_list).option, "cannot be a range or a list with --batch: give one scene per line")
        from taucli import batch

        return batch.run(command, given, sys.stdin, sys.stdout)
    output = _output(given)
    if output.plot and output.get:
        raise InputError("--plot", "draws a chart, and --get prints numbers only", hint="--out FILE.svg writes the chart to a file")
    if given["y"] and swept_range is None:
        raise InputError("--y", "names what a range's chart shows; give a range FROM..TO", example="--inertia 0.5..4kg*m^2 --y alpha0")
    if output.out is not None:
        from taucli import plot

        plot.check_file(output.out)
    if swept_range is None and swept_list is None:
        return None
    from taucli import sweep

    def solve(options: dict):
        global _collected
        _collected = []
        try:
            command(**{**options, "batch": False, "plot": False, "out": None, "points": None, "y": None, "get": None})
            return _collected[0]
        finally:
            _collected = None

    points = sweep.solve_all(swept_range, swept_list, given, solve)
    sweep.render(points, swept_range, swept_list, output, list(given["y"] or ()), sys.stdout)
    return int(ExitStatus.OK)


def _whole_number(option: str, text: Optional[str]) -> Optional[int]:
    if text is None:
        return None
    try:
        return int(text)
    except ValueError:
        raise InputError(option, "expected a whole number", example=f"{option} 50", got=repr(text)) from None


def _output(given: dict):
    from taucli.render import Output

    return Output(
        json=given["json_"] or given["jsonl"],
        get=tuple(given["get"] or ()),
        to=tuple(given["to"] or ()),
        steps=not given["no_steps"],
        plot=given["plot"],
        out=given["out"],
        json_lines=given["jsonl"],
    )


def _length_option(flag: str, help_text: str):
    return Annotated[Optional[str], typer.Option(flag, metavar="LENGTH", help=help_text, rich_help_panel=_BODY)]


MassOption = Annotated[Optional[str], typer.Option("--mass", metavar="MASS", help="Mass of the body, e.g. 5kg.", rich_help_panel=_BODY)]
RadiusOption = _length_option("--radius", "Radius (a point's distance from the axis), e.g. 0.2m.")
InnerRadiusOption = _length_option("--inner-radius", "Inner radius (tube, thick-shell).")
OuterRadiusOption = _length_option("--outer-radius", "Outer radius (tube, thick-shell).")
LengthOption = _length_option("--length", "Length (rod; cylinder along its axis).")
WidthOption = _length_option("--width", "Width (plate, box).")
HeightOption = _length_option("--height", "Height (plate, box, cone).")
DepthOption = _length_option("--depth", "Depth (box).")
AxisOption = Annotated[
    Optional[str],
    typer.Option(
        "--axis",
        metavar="AXIS",
        help="Axis, where the shape has several: "
        + "; ".join(f"{'|'.join(axes)} ({name})" for name, axes in SHAPE_AXES.items() if len(axes) > 1)
        + " (default: the first).",
        rich_help_panel=_BODY,
    ),
]
OffsetOption = _length_option("--offset", "Distance of the rotation axis from the parallel axis through the centre of mass.")


def read_shape(inputs: "Inputs", shape: str | None, mass: str | None, axis: str | None, offset: str | None, **dims: str | None):
    """The body part named by SHAPE and the shape options, as an inertia Part in SI."""
    from taucli.scenes.inertia import Part, lookup_shape

    if shape is None:
        raise InputError("SHAPE", f"is required, one of {', '.join(SHAPE_NAMES)}", example="taucli inertia disc --mass 5kg --radius 0.2m")
    found = lookup_shape(shape)
    mass_si = inputs.required("--mass", mass, "mass", why=f" for a {found.title}")
    lengths = {
        name: inputs.quantity("--" + name.replace("_", "-"), text, "length", sign="nonnegative" if name == "inner_radius" else "positive")
        for name, text in dims.items()
        if text is not None
    }
    offset_si = inputs.quantity("--offset", offset, "length", sign="nonnegative")
    return Part(found.name, mass_si, lengths, axis, offset_si)


def emit(report, inputs: "Inputs", given: dict) -> None:
    """Render a solver's report with the inputs as read, in the format asked for (or hand it to a sweep)."""
    from taucli import render

    report = render.attach_inputs(report, inputs.values, inputs.notes)
    if _collected is not None:
        _collected.append(report)
        return
    render.render(report, _output(given), sys.stdout)


@app.command(cls=TaucliCommand, epilog=EXIT_STATUSES)
def inertia(
    shape: Annotated[
        Optional[str], typer.Argument(metavar="SHAPE", help=f"One of: {', '.join(SHAPE_NAMES)}.", show_default=False)
    ] = None,
    mass: MassOption = None,
    radius: RadiusOption = None,
    inner_radius: InnerRadiusOption = None,
    outer_radius: OuterRadiusOption = None,
    length: LengthOption = None,
    width: WidthOption = None,
    height: HeightOption = None,
    depth: DepthOption = None,
    axis: AxisOption = None,
    offset: OffsetOption = None,
    part: Annotated[
        Optional[list[str]],
        typer.Option(
            "--part",
            metavar='"SHAPE key=value ..."',
            help='Another part of the same body about the same axis, e.g. --part "point mass=100g offset=0.2m" (repeatable).',
            rich_help_panel=_BODY,
        ),
    ] = None,
    json_: JsonFlag = False,
    get: GetOption = None,
    to: ToOption = None,
    no_steps: NoStepsFlag = False,
    batch: BatchFlag = False,
    jsonl: JsonLinesFlag = False,
    plot: PlotFlag = False,
    out: OutOption = None,
    points: PointsOption = None,
    y: YOption = None,
) -> Optional[int]:
    """Moment of inertia of a standard shape: shifted (--offset), or a body of several parts.

    Results: I, k (radius of gyration), I_cm (with --offset), mass (several parts).

    \b
    Example: taucli inertia disc --mass 5kg --radius 0.2m
    """
    given = dict(locals())
    if (status := dispatch(inertia, given)) is not None:
        return status
    from taucli.inputs import SHAPE_DIMENSIONS, Inputs, parse_part_spec
    from taucli.scenes import inertia as scene

    inputs = Inputs()
    dims = dict(radius=radius, inner_radius=inner_radius, outer_radius=outer_radius, length=length, width=width, height=height, depth=depth)
    assert set(dims) == set(SHAPE_DIMENSIONS)
    parts = [read_shape(inputs, shape, mass, axis, offset, **dims)]
    parts += [parse_part_spec(spec, number, inputs) for number, spec in enumerate(part or [], start=2)]
    emit(scene.solve(parts), inputs, given)


InertiaOption = Annotated[
    Optional[str],
    typer.Option("--inertia", metavar="I", help="Moment of inertia about the axle, e.g. 0.1kg*m^2 (or give --shape).", rich_help_panel=_BODY),
]
ShapeOption = Annotated[
    Optional[str],
    typer.Option("--shape", metavar="SHAPE", help=f"The body's shape, with --mass and its dimensions: {', '.join(SHAPE_NAMES)}.", rich_help_panel=_BODY),
]
_MOTION = "Motion and method"
MethodOption = Annotated[
    str, typer.Option("--method", metavar="METHOD", help=" | ".join(METHOD_NAMES) + ".", rich_help_panel=_MOTION)
]
DtOption = Annotated[Optional[str], typer.Option("--dt", metavar="TIME", help="Fixed step for euler and rk4 (default 1 ms).", rich_help_panel=_MOTION)]
RtolOption = Annotated[Optional[str], typer.Option("--rtol", metavar="NUMBER", help="Relative tolerance for rk45 (default 1e-10).", rich_help_panel=_MOTION)]


def read_body(inputs: "Inputs", inertia: str | None, shape: str | None, mass: str | None, axis: str | None, offset: str | None, **dims: str | None):
    """The moment of inertia from --inertia or from --shape and its options: (I, steps)."""
    from taucli.scenes.inertia import body_inertia

    given = [name for name, text in (("--mass", mass), ("--axis", axis), ("--offset", offset), *((f"--{k.replace('_', '-')}", v) for k, v in dims.items())) if text is not None]
    if inertia is not None:
        if shape is not None:
            raise InputError("--inertia", "conflicts with --shape: give one of them")
        if given:
            raise InputError(given[0], "goes with --shape; with --inertia it is not used")
        return inputs.required("--inertia", inertia, "moment of inertia"), ()
    if shape is None:
        raise InputError("--inertia", "or --shape is required", example="--inertia 0.1kg*m^2, or --shape disc --mass 5kg --radius 0.2m")
    body = body_inertia([read_shape(inputs, shape, mass, axis, offset, **dims)])
    return body.inertia, body.steps


@app.command("spin-down", cls=TaucliCommand)
def spin_down(
    inertia: InertiaOption = None,
    shape: ShapeOption = None,
    mass: MassOption = None,
    radius: RadiusOption = None,
    inner_radius: InnerRadiusOption = None,
    outer_radius: OuterRadiusOption = None,
    length: LengthOption = None,
    width: WidthOption = None,
    height: HeightOption = None,
    depth: DepthOption = None,
    axis: AxisOption = None,
    offset: OffsetOption = None,
    omega0: Annotated[Optional[str], typer.Option("--omega0", metavar="OMEGA", help="Initial angular velocity (default 0), e.g. 300rpm.", rich_help_panel=_MOTION)] = None,
    torque: Annotated[Optional[str], typer.Option("--torque", metavar="TORQUE", help="Driving torque along +ω (negative: against it), e.g. 1.5N*m.")] = None,
    force: Annotated[Optional[str], typer.Option("--force", metavar="FORCE", help="A push at --lever that makes the driving torque, e.g. 6N.")] = None,
    lever: Annotated[Optional[str], typer.Option("--lever", metavar="LENGTH", help="Distance of the push from the axle, e.g. 0.25m.")] = None,
    push_angle: Annotated[Optional[str], typer.Option("--push-angle", metavar="ANGLE", help="Angle between lever arm and force (default 90deg).")] = None,
    friction: Annotated[Optional[str], typer.Option("--friction", metavar="TORQUE", help="Constant friction torque at the axle (also holds it at rest), e.g. 0.3N*m.")] = None,
    viscous: Annotated[Optional[str], typer.Option("--viscous", metavar="B", help="Viscous coefficient b (torque bω), e.g. 0.01N*m*s.")] = None,
    drag: Annotated[Optional[str], typer.Option("--drag", metavar="K", help="Drag coefficient k (torque kωⁿ), e.g. 0.001N*m*s^2.")] = None,
    drag_exponent: Annotated[Optional[str], typer.Option("--drag-exponent", metavar="N", help="Exponent n of the drag torque kωⁿ, 1 to 10 (default 2).")] = None,
    time: Annotated[Optional[str], typer.Option("--time", metavar="TIME", help="Report ω, θ and revolutions at this time, e.g. 4s.", rich_help_panel=_MOTION)] = None,
    until_omega: Annotated[Optional[str], typer.Option("--until-omega", metavar="OMEGA", help="Report the time and angle to reach this speed.", rich_help_panel=_MOTION)] = None,
    method: MethodOption = "auto",
    dt: DtOption = None,
    rtol: RtolOption = None,
    json_: JsonFlag = False,
    get: GetOption = None,
    to: ToOption = None,
    no_steps: NoStepsFlag = False,
    batch: BatchFlag = False,
    jsonl: JsonLinesFlag = False,
    plot: PlotFlag = False,
    out: OutOption = None,
    points: PointsOption = None,
    y: YOption = None,
) -> Optional[int]:
    """A wheel on a fixed axle, slowing or spun up: I dω/dt = τ_drive − τ_f − bω − kω².

    Results: I, alpha0, t_stop, theta_stop, revs_stop, omega_inf; with --time: omega, theta, revs;
    with --until-omega: t_until, theta_until.

    \b
    Example: taucli spin-down --shape disc --mass 5kg --radius 0.2m --omega0 30rad/s --friction 0.3N*m
    """
    given = dict(locals())
    if (status := dispatch(spin_down, given)) is not None:
        return status
    from taucli.inputs import Inputs
    from taucli.scenes import spin

    inputs = Inputs()
    dims = dict(radius=radius, inner_radius=inner_radius, outer_radius=outer_radius, length=length, width=width, height=height, depth=depth)
    moment, body_steps = read_body(inputs, inertia, shape, mass, axis, offset, **dims)
    push = None
    if force is not None or lever is not None or push_angle is not None:
        if torque is not None:
            raise InputError("--torque", "conflicts with --force and --lever: give the torque, or the push that makes it")
        push_force = inputs.required("--force", force, "force", sign="any", why=" with --lever")
        push_lever = inputs.required("--lever", lever, "length", why=" with --force")
        angle = inputs.quantity("--push-angle", push_angle, "angle", sign="any")
        push = spin.Push(push_force, push_lever) if angle is None else spin.Push(push_force, push_lever, angle)
        drive = push.torque
    else:
        drive = inputs.quantity("--torque", torque, "torque", sign="any") or 0.0
    exponent = inputs.quantity("--drag-exponent", drag_exponent, "dimensionless", sign="positive")
    torques = spin.Torques(
        drive,
        inputs.quantity("--friction", friction, "torque", sign="nonnegative") or 0.0,
        inputs.quantity("--viscous", viscous, "viscous coefficient", sign="nonnegative") or 0.0,
        inputs.quantity("--drag", drag, "drag coefficient", sign="nonnegative") or 0.0,
        2.0 if exponent is None else exponent,
    )
    report = spin.solve(
        moment,
        torques,
        inputs.quantity("--omega0", omega0, "angular velocity", sign="any") or 0.0,
        time=inputs.quantity("--time", time, "time", sign="nonnegative"),
        until_omega=inputs.quantity("--until-omega", until_omega, "angular velocity", sign="any"),
        method=method,
        dt=inputs.quantity("--dt", dt, "time"),
        rtol=inputs.quantity("--rtol", rtol, "dimensionless"),
        push=push,
        inertia_steps=body_steps,
    )
    emit(report, inputs, given)


STANDARD_GRAVITY = 9.80665
GOption = Annotated[Optional[str], typer.Option("--g", metavar="ACCEL", help="Gravity (default 9.80665 m/s^2).")]


def read_gravity(inputs: "Inputs", g: str | None) -> float:
    """--g, or standard gravity with a note that says so."""
    if g is None:
        return inputs.assume("g", STANDARD_GRAVITY, "acceleration", f"g = {STANDARD_GRAVITY} m/s² (standard gravity); --g to change it")
    return inputs.required("--g", g, "acceleration")


_PULLEY = "Pulley"


@app.command(cls=TaucliCommand, epilog=EXIT_STATUSES)
def atwood(
    m1: Annotated[Optional[str], typer.Option("--m1", metavar="MASS", help="The hanging mass; its downward motion is positive.")] = None,
    m2: Annotated[Optional[str], typer.Option("--m2", metavar="MASS", help="The other mass (0: one mass on a string wound on the pulley).")] = None,
    pulley_mass: Annotated[Optional[str], typer.Option("--pulley-mass", metavar="MASS", help="Pulley mass (default 0: massless).", rich_help_panel=_PULLEY)] = None,
    pulley_radius: Annotated[Optional[str], typer.Option("--pulley-radius", metavar="LENGTH", help="Pulley radius (needed only for alpha, axle friction or --pulley-inertia).", rich_help_panel=_PULLEY)] = None,
    pulley_shape: Annotated[Optional[str], typer.Option("--pulley-shape", metavar="|".join(PULLEY_SHAPES), help="Pulley shape (default disc).", rich_help_panel=_PULLEY)] = None,
    pulley_inertia: Annotated[Optional[str], typer.Option("--pulley-inertia", metavar="I", help="Pulley moment of inertia, instead of mass and shape.", rich_help_panel=_PULLEY)] = None,
    axle_friction: Annotated[Optional[str], typer.Option("--axle-friction", metavar="TORQUE", help="Constant friction torque at the axle (holds at rest too).", rich_help_panel=_PULLEY)] = None,
    incline: Annotated[Optional[str], typer.Option("--incline", metavar="ANGLE", help="m2 on a slope at this angle (0deg: a table) instead of hanging.")] = None,
    mu_k: Annotated[Optional[str], typer.Option("--mu-k", metavar="NUMBER", help="Kinetic friction coefficient under m2.")] = None,
    mu_s: Annotated[Optional[str], typer.Option("--mu-s", metavar="NUMBER", help="Static friction coefficient under m2.")] = None,
    g: GOption = None,
    v0: Annotated[Optional[str], typer.Option("--v0", metavar="SPEED", help="Initial speed of m1 (down positive; default 0).", rich_help_panel=_MOTION)] = None,
    distance: Annotated[Optional[str], typer.Option("--distance", metavar="LENGTH", help="Report the time and speed after this distance.", rich_help_panel=_MOTION)] = None,
    time: Annotated[Optional[str], typer.Option("--time", metavar="TIME", help="Report the speed and displacement at this time.", rich_help_panel=_MOTION)] = None,
    json_: JsonFlag = False,
    get: GetOption = None,
    to: ToOption = None,
    no_steps: NoStepsFlag = False,
    batch: BatchFlag = False,
    jsonl: JsonLinesFlag = False,
    plot: PlotFlag = False,
    out: OutOption = None,
    points: PointsOption = None,
    y: YOption = None,
) -> Optional[int]:
    """Two masses on a string over a pulley with mass: acceleration and tensions.

    Results: a (m1 downward positive), T1, T2, alpha, a_massless; v, t with --distance; v, distance with --time.

    \b
    Example: taucli atwood --m1 4kg --m2 1kg --pulley-mass 2kg --pulley-radius 0.1m
    """
    given = dict(locals())
    if (status := dispatch(atwood, given)) is not None:
        return status
    from taucli.inputs import Inputs
    from taucli.scenes import atwood as scene

    inputs = Inputs()
    mass1 = inputs.required("--m1", m1, "mass", sign="nonnegative")
    if m2 is None:
        inputs.notes.append("no --m2: a single mass on a string wound on the pulley")
    mass2 = inputs.quantity("--m2", m2, "mass", sign="nonnegative") or 0.0
    pulley = scene.Pulley(
        inputs.quantity("--pulley-mass", pulley_mass, "mass", sign="nonnegative") or 0.0,
        inputs.quantity("--pulley-radius", pulley_radius, "length"),
        pulley_shape,
        inputs.quantity("--pulley-inertia", pulley_inertia, "moment of inertia", sign="nonnegative"),
        inputs.quantity("--axle-friction", axle_friction, "torque", sign="nonnegative") or 0.0,
    )
    angle = inputs.quantity("--incline", incline, "angle", sign="any")
    slope = scene.Slope(
        scene.HANGING if angle is None else angle,
        inputs.quantity("--mu-k", mu_k, "dimensionless", sign="nonnegative") or 0.0,
        inputs.quantity("--mu-s", mu_s, "dimensionless", sign="nonnegative"),
    )
    report = scene.solve(
        mass1,
        mass2,
        pulley,
        read_gravity(inputs, g),
        slope=slope,
        v0=inputs.quantity("--v0", v0, "velocity", sign="any") or 0.0,
        distance=inputs.quantity("--distance", distance, "length", sign="nonnegative"),
        time=inputs.quantity("--time", time, "time", sign="nonnegative"),
    )
    emit(report, inputs, given)


@app.command(cls=TaucliCommand, epilog=EXIT_STATUSES)
def rolling(
    shape: Annotated[Optional[str], typer.Argument(metavar="SHAPE", help=f"{', '.join(ROLLING_BODIES)} (or give --k2 or --inertia).", show_default=False)] = None,
    k2: Annotated[Optional[str], typer.Option("--k2", metavar="NUMBER", help="I/(mR²) of the body, instead of SHAPE.", rich_help_panel=_BODY)] = None,
    inertia: Annotated[Optional[str], typer.Option("--inertia", metavar="I", help="Moment of inertia about the centre (with --mass and --radius).", rich_help_panel=_BODY)] = None,
    mass: Annotated[Optional[str], typer.Option("--mass", metavar="MASS", help="Mass (needed only for forces and energies).", rich_help_panel=_BODY)] = None,
    radius: Annotated[Optional[str], typer.Option("--radius", metavar="LENGTH", help="Radius (needed only for α and ω).", rich_help_panel=_BODY)] = None,
    angle: Annotated[Optional[str], typer.Option("--angle", metavar="ANGLE", help="Slope of the incline, 0 to 90deg.")] = None,
    mu_s: Annotated[Optional[str], typer.Option("--mu-s", metavar="NUMBER", help="Static friction coefficient (decides roll or slip).")] = None,
    mu_k: Annotated[Optional[str], typer.Option("--mu-k", metavar="NUMBER", help="Kinetic friction coefficient (when it slips or skids).")] = None,
    length: Annotated[Optional[str], typer.Option("--length", metavar="LENGTH", help="Distance down the slope to the bottom.", rich_help_panel=_MOTION)] = None,
    height: Annotated[Optional[str], typer.Option("--height", metavar="LENGTH", help="Height of the slope, instead of --length.", rich_help_panel=_MOTION)] = None,
    v0: Annotated[Optional[str], typer.Option("--v0", metavar="SPEED", help="Speed up the slope (how far it climbs), or on the flat (skid).", rich_help_panel=_MOTION)] = None,
    omega0: Annotated[Optional[str], typer.Option("--omega0", metavar="OMEGA", help="Spin on the flat, in the rolling sense (skid to roll).", rich_help_panel=_MOTION)] = None,
    g: GOption = None,
    json_: JsonFlag = False,
    get: GetOption = None,
    to: ToOption = None,
    no_steps: NoStepsFlag = False,
    batch: BatchFlag = False,
    jsonl: JsonLinesFlag = False,
    plot: PlotFlag = False,
    out: OutOption = None,
    points: PointsOption = None,
    y: YOption = None,
) -> Optional[int]:
    """A round body on an incline: does it roll or slip, and how fast; or a skidding ball on the flat.

    Results: a, alpha, friction, mu_min, rolls; v, t at the bottom (--length or --height);
    d_climb, h_climb, t_climb (--v0 up the slope); t_roll, d_roll, v_roll on the flat.

    \b
    Example: taucli rolling sphere --angle 30deg --length 2m
    """
    given = dict(locals())
    if (status := dispatch(rolling, given)) is not None:
        return status
    from taucli.inputs import Inputs
    from taucli.scenes import rolling as scene

    inputs = Inputs()
    mass_si = inputs.quantity("--mass", mass, "mass")
    radius_si = inputs.quantity("--radius", radius, "length")
    body = scene.roller(
        shape,
        inputs.quantity("--k2", k2, "dimensionless"),
        inputs.quantity("--inertia", inertia, "moment of inertia"),
        mass_si,
        radius_si,
    )
    slope = inputs.quantity("--angle", angle, "angle", sign="any")
    speed = inputs.quantity("--v0", v0, "velocity", sign="any")
    spin = inputs.quantity("--omega0", omega0, "angular velocity", sign="any")
    gravity = read_gravity(inputs, g)
    friction_s = inputs.quantity("--mu-s", mu_s, "dimensionless", sign="nonnegative")
    friction_k = inputs.quantity("--mu-k", mu_k, "dimensionless", sign="nonnegative")
    on_the_flat = (slope is None or slope == 0) and (speed is not None or spin is not None) and length is None and height is None
    if on_the_flat:
        report = scene.solve_flat(body, gravity, mu_k=friction_k, v0=speed or 0.0, omega0=spin or 0.0, mu_s=friction_s)
    else:
        if slope is None:
            raise InputError("--angle", "is required on an incline", example="--angle 30deg")
        if spin is not None:
            raise InputError("--omega0", "applies on the flat (--angle 0 with --v0): a skidding ball")
        report = scene.solve_incline(
            body,
            slope,
            gravity,
            mu_s=friction_s,
            mu_k=friction_k,
            length=inputs.quantity("--length", length, "length"),
            height=inputs.quantity("--height", height, "length"),
            v0=speed or 0.0,
        )
    emit(report, inputs, given)


@app.command(cls=TaucliCommand, epilog=EXIT_STATUSES)
def impulse(
    inertia: InertiaOption = None,
    shape: ShapeOption = None,
    mass: MassOption = None,
    radius: RadiusOption = None,
    inner_radius: InnerRadiusOption = None,
    outer_radius: OuterRadiusOption = None,
    length: LengthOption = None,
    width: WidthOption = None,
    height: HeightOption = None,
    depth: DepthOption = None,
    axis: AxisOption = None,
    offset: OffsetOption = None,
    omega0: Annotated[Optional[str], typer.Option("--omega0", metavar="OMEGA", help="Angular velocity before.")] = None,
    omega1: Annotated[Optional[str], typer.Option("--omega1", metavar="OMEGA", help="Angular velocity after.")] = None,
    torque: Annotated[Optional[str], typer.Option("--torque", metavar="TORQUE", help="Constant torque while it acts.")] = None,
    duration: Annotated[Optional[str], typer.Option("--duration", metavar="TIME", help="How long the torque acts.")] = None,
    inertia_final: Annotated[Optional[str], typer.Option("--inertia-final", metavar="I", help="Inertia after a change with no torque (the skater).")] = None,
    torque_profile: Annotated[Optional[str], typer.Option("--torque-profile", metavar="FILE", help="CSV 't [ms], torque [N*m]' then rows; - for stdin.")] = None,
    method: Annotated[str, typer.Option("--method", metavar="METHOD", help="Quadrature for a profile: " + " | ".join(QUADRATURE_NAMES) + ".")] = "auto",
    json_: JsonFlag = False,
    get: GetOption = None,
    to: ToOption = None,
    no_steps: NoStepsFlag = False,
    batch: BatchFlag = False,
    jsonl: JsonLinesFlag = False,
    plot: PlotFlag = False,
    out: OutOption = None,
    points: PointsOption = None,
    y: YOption = None,
) -> Optional[int]:
    """Angular impulse: τΔt = IΔω, any four of I, ω₀, ω₁, τ, Δt giving the fifth; or I that changes.

    Results: J, delta_omega, inertia, omega0, omega1, torque, duration, L0, L1, KE0, KE1;
    with --inertia-final: work; with --torque-profile: peak_torque and ω at the samples.

    \b
    Example: taucli impulse --inertia 0.1kg*m^2 --omega0 0 --torque 2N*m --duration 0.5s
    """
    given = dict(locals())
    if (status := dispatch(impulse, given)) is not None:
        return status
    from taucli.inputs import Inputs
    from taucli.scenes import impulse as scene

    inputs = Inputs()
    dims = dict(radius=radius, inner_radius=inner_radius, outer_radius=outer_radius, length=length, width=width, height=height, depth=depth)
    body_given = inertia is not None or shape is not None
    moment, body_steps = read_body(inputs, inertia, shape, mass, axis, offset, **dims) if body_given else (None, ())
    start = inputs.quantity("--omega0", omega0, "angular velocity", sign="any")
    if inertia_final is not None or torque_profile is not None:
        mode = "--inertia-final" if inertia_final is not None else "--torque-profile"
        for option, text in (("--omega1", omega1), ("--torque", torque), ("--duration", duration), ("--inertia-final", inertia_final if mode != "--inertia-final" else None)):
            if text is not None:
                raise InputError(option, f"conflicts with {mode}")
        if moment is None:
            raise InputError("--inertia", f"or --shape is required with {mode}", example="--inertia 2kg*m^2")
        if mode == "--inertia-final":
            final = inputs.required("--inertia-final", inertia_final, "moment of inertia")
            report = scene.solve_changing_inertia(moment, final, start or 0.0, inertia_steps=body_steps)
        else:
            from taucli.profile import read_profile

            report = _impulse_from_profile(scene, read_profile, torque_profile, moment, start, method, inputs, body_steps)
    else:
        if method != "auto":
            raise InputError("--method", "applies to --torque-profile (trapezoid or simpson); constant torque has a closed form")
        report = scene.solve_balance(
            moment,
            start,
            inputs.quantity("--omega1", omega1, "angular velocity", sign="any"),
            inputs.quantity("--torque", torque, "torque", sign="any"),
            inputs.quantity("--duration", duration, "time"),
            inertia_steps=body_steps,
        )
    emit(report, inputs, given)


def _impulse_from_profile(scene, read_profile, source: str, moment: float, start: float | None, method: str, inputs: "Inputs", body_steps):
    """Stream the profile from a file (or stdin for -) into the quadrature."""
    if start is None:
        start = inputs.assume("omega0", 0.0, "angular velocity", "no --omega0: the body starts at rest")
    if source == "-":
        profile = read_profile(sys.stdin)
        inputs.notes.extend(profile.notes)
        return scene.solve_profile(moment, start, profile.samples, rule=method, inertia_steps=body_steps)
    try:
        with open(source, encoding="utf-8") as handle:
            profile = read_profile(handle)
            inputs.notes.extend(profile.notes)
            return scene.solve_profile(moment, start, profile.samples, rule=method, inertia_steps=body_steps)
    except OSError as err:
        raise InputError("--torque-profile", "expected a readable CSV file (or - for stdin)", got=f"{source!r}: {err.strerror}") from None
    except UnicodeDecodeError:
        raise InputError("--torque-profile", "expected a UTF-8 text file", got=repr(source)) from None


@app.command(cls=TaucliCommand, epilog=EXIT_STATUSES)
def bench(
    scene: Annotated[Optional[list[str]], typer.Option("--scene", metavar="SCENE", help=" or ".join(BENCH_SCENES) + " (repeatable; default both).")] = None,
    quick: Annotated[bool, typer.Option("--quick", help="Fewer settings and repeats: a few seconds.")] = False,
    out: Annotated[Optional[str], typer.Option("--out", metavar="FILE", help="Also draw the charts to FILE.svg or FILE.png (needs matplotlib).")] = None,
    json_: JsonFlag = False,
) -> None:
    """Speed against accuracy: time per solve and error of every method, charted (log-log).

    Each point is one method at one step, tolerance or sample count on a fixed problem (the
    article's potter's wheel, a friction + viscous + drag coast, a power-law drag, a stiff brake,
    a half-sine torque pulse), its error against a 50-digit reference. '!' marks a run that
    diverged. scipy's solve_ivp is charted too when scipy is installed.

    \b
    Example: taucli bench --quick
    """
    import json

    from taucli import bench as workbench

    chosen = tuple(scene or workbench.SCENES)
    for name in chosen:
        if name not in workbench.SCENES:
            raise InputError("--scene", f"expected one of {', '.join(workbench.SCENES)}", got=repr(name))
    if out is not None and not out.lower().endswith((".svg", ".png")):
        raise InputError("--out", "expected a file name ending in .svg or .png", example="--out chart.svg", got=repr(out))
    if out is not None:
        try:
            import matplotlib  # noqa: F401
        except ImportError:
            raise InputError("--out", "needs matplotlib", hint="pip install 'taucli[plot]'") from None
    points = workbench.run(chosen, quick=quick)
    if out is not None:
        workbench.write_image(points, out)
    if json_:
        print(json.dumps(workbench.document(points), allow_nan=False))
        return
    import shutil

    width = max(60, min(shutil.get_terminal_size((100, 24)).columns, 110))
    for problem in dict.fromkeys(p.problem for p in points):
        print("\n".join(workbench.chart(points, problem, width=width)))
        print()
    if out is not None:
        print(f"charts written to {out}")


@app.command(cls=TaucliCommand, epilog=EXIT_STATUSES)
def completions(
    shell: Annotated[Optional[str], typer.Argument(metavar="SHELL", help="bash, zsh or fish.", show_default=False)] = None,
) -> None:
    """Print the completion script for SHELL: commands, options, shapes, methods, and units after a number.

    The scripts are static: pressing TAB never starts Python. The README says where each goes.

    \b
    Example: taucli completions bash > ~/.local/share/bash-completion/completions/taucli
    """
    from taucli import completions as scripts

    if shell not in scripts.SHELLS:
        raise InputError("SHELL", f"expected one of {', '.join(scripts.SHELLS)}", example="taucli completions bash", got=None if shell is None else repr(shell))
    sys.stdout.write(scripts.script(shell))


def _is_usage_error(err: Exception) -> bool:
    """Typer's (vendored or plain click) usage errors: they carry an exit code and a message."""
    return isinstance(getattr(err, "exit_code", None), int) and hasattr(err, "format_message")


def _fail(status: ExitStatus, message: str) -> int:
    print(f"taucli: error: {' '.join(message.split())}", file=sys.stderr)
    return int(status)


def app_for(args: list[str]):
    """``app`` with only the command being run registered, when one is named.

    Typer builds the options of every registered command (2-4 ms each) before it parses any;
    the first word that is not an option names the command (taucli's own options take no value).
    """
    import copy

    at = _command_at(args)
    name = args[at] if at < len(args) else None
    chosen = [info for info in app.registered_commands if (info.name or info.callback.__name__.replace("_", "-")) == name]
    if not chosen:
        return app
    lean = copy.copy(app)
    lean.registered_commands = chosen
    return lean


def _reader_gone() -> int:
    """The reader went away (`| head -c1`): say nothing more, and do not fail again on exit."""
    os.dup2(os.open(os.devnull, os.O_WRONLY), sys.__stdout__.fileno())
    return int(ExitStatus.OK)


def _command_at(args: list[str]) -> int:
    """Where the command's name is in ``args``: the first word that is not an option (taucli's
    own options take no value), or len(args) when there is none."""
    return next((i for i, word in enumerate(args) if not word.startswith("-")), len(args))


def _debugging(args: list[str]) -> bool:
    """--debug before the command's name (taucli's own option), or TAUCLI_DEBUG in the environment."""
    return "--debug" in args[: _command_at(args)] or bool(os.environ.get("TAUCLI_DEBUG"))


def main(argv: list[str] | None = None) -> int:
    """Run taucli; every exception becomes one line on stderr and an exit status."""
    args = sys.argv[1:] if argv is None else list(argv)
    try:
        result = app_for(args)(args=args, prog_name="taucli", standalone_mode=False)
    except TaucliError as err:
        return _fail(err.exit_status, str(err))
    except OverflowError:
        return _fail(ExitStatus.USAGE, str(out_of_range()))
    except KeyboardInterrupt:
        print(file=sys.stderr)
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
            if type(err).__name__ == "NoArgsIsHelpError":  # `taucli` alone: the help, on stderr
                print(err.format_message(), file=sys.stderr)
                return int(ExitStatus.USAGE)
            ctx = getattr(err, "ctx", None)
            where = f" (see '{ctx.command_path} --help')" if ctx is not None else " (see 'taucli --help')"
            return _fail(ExitStatus.USAGE, err.format_message() + where)
        if _debugging(args):
            import traceback

            traceback.print_exc()
        return _fail(
            ExitStatus.INTERNAL,
            f"internal error ({type(err).__name__}: {err}); this is a bug in taucli, please report it "
            "with the command line (taucli --debug ... shows the traceback)",
        )
    return result if isinstance(result, int) else int(ExitStatus.OK)
