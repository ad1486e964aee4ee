"""The standard shapes: each one's moment of inertia about each of its axes, in closed form, and
its volume (for a part given by its density).

Each closed form is written so that it keeps full double precision up to its limits (a thick shell
whose inner radius approaches the outer one, a tube whose inner radius approaches zero or the
outer one).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass

from taucli.core.errors import InputError, did_you_mean
from taucli.writing.report import quantity_text


# Dimension name -> (symbol in equations, placeholder in number templates).
DIMENSIONS: dict[str, str] = {
    "radius": "R",
    "inner_radius": "R1",
    "outer_radius": "R2",
    "length": "L",
    "width": "W",
    "height": "H",
    "depth": "D",
}


@dataclass(frozen=True)
class Axis:
    """An axis a shape can turn about, with the closed form for I about it."""

    name: str
    description: str
    equation: str  # symbolic, as in the article: "I = ½MR²"
    numbers: str  # the same with placeholders {M}, {R}, ... for the values
    moment: Callable[..., float]  # moment(mass, **dims) -> I about this axis
    why: str
    through_centre: bool = True  # the parallel-axis theorem needs an axis through the centre of mass
    # For an axis not through the centre: the name of the parallel axis through it, and the
    # distance between the two from the dimensions (so a parts table can show I_cm and offset).
    centre: tuple[str, Callable[..., float]] | None = None
    # #42 item 3: an optional dimension I depends on about this axis, and the body it stands for
    # when left out (taken as 0): said in a note, never assumed silently.
    thin: Mapping[str, str] | None = None


@dataclass(frozen=True)
class Shape:
    """A standard uniform body."""

    name: str
    title: str
    dims: tuple[str, ...]  # required
    axes: tuple[Axis, ...]
    optional: tuple[str, ...] = ()

    def axis(self, name: str | None) -> Axis:
        if name is None:
            return self.axes[0]
        for axis in self.axes:
            if axis.name == name:
                return axis
        choices = ", ".join(a.name for a in self.axes)
        raise InputError("axis", f"expected one of {choices} for a {self.title}", example=f"{{axis}} {self.axes[0].name}", got=repr(name))


def _thick_shell(mass: float, inner_radius: float, outer_radius: float) -> float:
    """I = (2/5) M (R2^5 - R1^5) / (R2^3 - R1^3), in the form free of cancellation.

    With x = R1/R2, (1 - x^5)/(1 - x^3) = (1 + x + x^2 + x^3 + x^4)/(1 + x + x^2): both sums are
    of positive terms, so the ratio keeps full precision as x -> 1 (the thin shell, 2/3 M R^2)
    and as x -> 0 (the solid sphere, 2/5 M R^2).
    """
    x = inner_radius / outer_radius
    return 0.4 * mass * outer_radius**2 * (1 + x * (1 + x * (1 + x * (1 + x)))) / (1 + x * (1 + x))


_CENTRAL = "its symmetry axis"


SHAPES: dict[str, Shape] = {
    shape.name: shape
    for shape in (
        Shape("point", "point mass", (), (
            Axis("distance", "an axis at distance R", "I = MR²", "{M} × {R}²",
                 lambda mass, radius=0.0: mass * radius * radius,
                 "all of its mass is at one distance R from the axis, so Σmr² has one term"),
        ), optional=("radius",)),
        Shape("ring", "thin ring", ("radius",), (
            Axis("central", _CENTRAL, "I = MR²", "{M} × {R}²", lambda mass, radius: mass * radius * radius,
                 "every bit of the ring is at the same distance R from the axis"),
            Axis("diameter", "a diameter", "I = ½MR²", "½ × {M} × {R}²", lambda mass, radius: mass * radius * radius / 2,
                 "perpendicular axes: I_z = I_x + I_y = MR² and I_x = I_y by symmetry"),
        )),
        Shape("disc", "solid disc (cylinder)", ("radius",), (
            Axis("central", _CENTRAL, "I = ½MR²", "½ × {M} × {R}²", lambda mass, radius, length=0.0: mass * radius * radius / 2,
                 "a uniform disc: rings of radius r hold mass in proportion to r, ∫r²dm = ½MR²"),
            Axis("diameter", "a diameter through its centre", "I = M(R²/4 + L²/12)", "{M} × ({R}²/4 + {L}²/12)",
                 lambda mass, radius, length=0.0: mass * (radius**2 / 4 + length**2 / 12),
                 "a stack of thin discs (¼MR² each about a diameter) along the length L, shifted by the parallel-axis theorem",
                 thin={"length": "a thin disc (L = 0): I = ¼MR² about a diameter"}),
        ), optional=("length",)),
        Shape("tube", "hollow cylinder (tube)", ("inner_radius", "outer_radius"), (
            Axis("central", _CENTRAL, "I = ½M(R₁² + R₂²)", "½ × {M} × ({R1}² + {R2}²)",
                 lambda mass, inner_radius, outer_radius, length=0.0: mass * (inner_radius**2 + outer_radius**2) / 2,
                 "a disc of radius R₂ less a disc of radius R₁ of the same density"),
            Axis("diameter", "a diameter through its centre", "I = M((R₁² + R₂²)/4 + L²/12)", "{M} × (({R1}² + {R2}²)/4 + {L}²/12)",
                 lambda mass, inner_radius, outer_radius, length=0.0: mass * ((inner_radius**2 + outer_radius**2) / 4 + length**2 / 12),
                 "thin annuli (¼M(R₁² + R₂²) each about a diameter) stacked along the length L",
                 thin={"length": "a flat annulus of no length (L = 0): I = ¼M(R₁² + R₂²) about a diameter"}),
        ), optional=("length",)),
        Shape("sphere", "solid sphere", ("radius",), (
            Axis("central", "a diameter", "I = ⅖MR²", "⅖ × {M} × {R}²", lambda mass, radius: 0.4 * mass * radius * radius,
                 "a uniform ball: thin discs stacked along the axis, each ½r²dm"),
        )),
        Shape("shell", "thin spherical shell", ("radius",), (
            Axis("central", "a diameter", "I = ⅔MR²", "⅔ × {M} × {R}²", lambda mass, radius: 2 * mass * radius * radius / 3,
                 "all the mass at radius R; averaged over the sphere, the squared distance from an axis is ⅔R²"),
        )),
        Shape("thick-shell", "thick spherical shell", ("inner_radius", "outer_radius"), (
            Axis("central", "a diameter", "I = ⅖M(R₂⁵ − R₁⁵)/(R₂³ − R₁³)", "⅖ × {M} × ({R2}⁵ − {R1}⁵)/({R2}³ − {R1}³)", _thick_shell,
                 "a ball of radius R₂ less a ball of radius R₁; computed as ⅖MR₂²(1+x+x²+x³+x⁴)/(1+x+x²), x = R₁/R₂, "
                 "which keeps full precision as the shell gets thin"),
        )),
        Shape("rod", "thin rod", ("length",), (
            Axis("center", "a perpendicular axis through its centre", "I = ML²/12", "{M} × {L}²/12", lambda mass, length: mass * length**2 / 12,
                 "∫x² (M/L) dx from −L/2 to L/2"),
            Axis("end", "a perpendicular axis through one end", "I = ML²/3", "{M} × {L}²/3", lambda mass, length: mass * length**2 / 3,
                 "∫x² (M/L) dx from 0 to L", through_centre=False, centre=("center", lambda length: length / 2)),
        )),
        Shape("plate", "rectangular plate", ("width", "height"), (
            Axis("normal", "the axis normal to it through its centre", "I = M(W² + H²)/12", "{M} × ({W}² + {H}²)/12",
                 lambda mass, width, height: mass * (width**2 + height**2) / 12,
                 "perpendicular axes: the two in-plane central moments, MW²/12 and MH²/12, add"),
            Axis("center-width", "the in-plane axis through its centre parallel to the width", "I = MH²/12", "{M} × {H}²/12",
                 lambda mass, width, height: mass * height**2 / 12, "strips along the width, each at its distance across the height"),
            Axis("center-height", "the in-plane axis through its centre parallel to the height", "I = MW²/12", "{M} × {W}²/12",
                 lambda mass, width, height: mass * width**2 / 12, "strips along the height, each at its distance across the width"),
            Axis("edge-width", "an edge of length W", "I = MH²/3", "{M} × {H}²/3",
                 lambda mass, width, height: mass * height**2 / 3, "strips parallel to the edge, at distances 0 to H", through_centre=False,
                 centre=("center-width", lambda width, height: height / 2)),
            Axis("edge-height", "an edge of length H", "I = MW²/3", "{M} × {W}²/3",
                 lambda mass, width, height: mass * width**2 / 3, "strips parallel to the edge, at distances 0 to W", through_centre=False,
                 centre=("center-height", lambda width, height: width / 2)),
        )),
        Shape("box", "rectangular box", ("width", "height", "depth"), (
            Axis("height", "the axis through its centre parallel to the height", "I = M(W² + D²)/12", "{M} × ({W}² + {D}²)/12",
                 lambda mass, width, height, depth: mass * (width**2 + depth**2) / 12, "plates stacked along the axis, each M(W² + D²)/12"),
            Axis("width", "the axis through its centre parallel to the width", "I = M(H² + D²)/12", "{M} × ({H}² + {D}²)/12",
                 lambda mass, width, height, depth: mass * (height**2 + depth**2) / 12, "plates stacked along the axis, each M(H² + D²)/12"),
            Axis("depth", "the axis through its centre parallel to the depth", "I = M(W² + H²)/12", "{M} × ({W}² + {H}²)/12",
                 lambda mass, width, height, depth: mass * (width**2 + height**2) / 12, "plates stacked along the axis, each M(W² + H²)/12"),
        )),
        Shape("cone", "solid cone", ("radius",), (
            Axis("central", _CENTRAL, "I = (3/10)MR²", "0.3 × {M} × {R}²", lambda mass, radius, height=0.0: 0.3 * mass * radius * radius,
                 "discs of radius r = Rz/H stacked along the height, each ½r²dm; the height cancels"),
        ), optional=("height",)),
    )
}  # fmt: skip


def unused(shape: Shape, axis: Axis, dim: str, dims: Mapping[str, float]) -> bool:
    """Whether I about ``axis`` (and its distance from the centre of mass) is the same whatever
    ``dim`` is: a plate's width for the axis along its width (#42 item 14). Probed at 1 m and 2 m,
    the other dimensions 1 m where not given."""
    probes = []
    for value in (1.0, 2.0):
        own = {name: length for name, length in dims.items() if name in shape.dims or name in shape.optional}  # another shape's dimension is refused after
        lengths = {**{name: 1.0 for name in shape.dims}, **own, dim: value}
        probes.append((axis.moment(1.0, **lengths), axis.centre[1](**lengths) if axis.centre is not None else 0.0))
    return probes[0] == probes[1]


def thin_notes(source: str, shape: Shape, axis: Axis, dims: Mapping[str, float]) -> tuple[str, ...]:
    """A note for each dimension I depends on about this axis that was left out (taken as 0): a
    disc or a tube about a diameter with no length is a thin one (#42 item 3)."""
    if not axis.thin:
        return ()
    notes = []
    for dim, body in axis.thin.items():
        if dim not in dims:  # the option as each surface spells it: {length} (--length, length=), {part} 2
            named = f"{dim.replace('_', '-')}= in {source}" if source else f"{{{dim}}}"
            notes.append(f"no {named}: the {shape.title} taken as {body}; give {named} for a body of some {dim.replace('_', ' ')}")
    return tuple(notes)


# Other words for a shape, answered with "did you mean" and never taken in its place: a word a
# reader may mean otherwise ("cylinder": solid, or a thin-walled can?) is refused, not guessed.
OTHER_NAMES = {
    "cylinder": "disc", "solid-cylinder": "disc", "disk": "disc", "wheel": "disc",
    "hollow-cylinder": "tube", "pipe": "tube", "cylindrical-shell": "tube",
    "hoop": "ring", "ball": "sphere", "solid-sphere": "sphere", "hollow-sphere": "shell", "spherical-shell": "shell",
    "bar": "rod", "stick": "rod", "particle": "point", "mass": "point", "cube": "box", "cuboid": "box", "block": "box",
    "sheet": "plate", "rectangle": "plate", "slab": "plate",
}
_WHY = {"disc": " (a solid cylinder; a hollow one is tube)", "tube": " (a hollow cylinder)", "shell": " (a thin spherical shell)"}


def lookup_shape(name: str, option: str = "SHAPE") -> Shape:
    """The shape of that name, or a usage error listing the shapes, with "did you mean" for a
    near miss or another word for one of them (``cylinder``: disc)."""
    try:
        return SHAPES[name]
    except KeyError:
        hint = did_you_mean(name, SHAPES)
        if hint is None:
            import difflib  # deferred: only a mistyped shape asks for it

            close = difflib.get_close_matches(name.lower().replace("_", "-").replace(" ", "-"), list(OTHER_NAMES), n=1, cutoff=0.75)
            if close:
                meant = OTHER_NAMES[close[0]]
                hint = f"did you mean {meant!r}?{_WHY.get(meant, '')}"
        raise InputError(option, f"expected a shape: {', '.join(SHAPES)}", example="disc", got=repr(name), hint=hint) from None


def fill(template: str, mass: float, dims: Mapping[str, float]) -> str:
    values = {"M": quantity_text(mass, "kg")}
    for dim, symbol in DIMENSIONS.items():
        values[symbol] = f"({quantity_text(dims.get(dim, 0.0), 'm')})"  # an optional dimension left out is 0
    return template.format(**values)


# The volume of each solid shape, from its dimensions: for a part given by its density.
# A flat body's area (its mass from an areal density, kg/m²) and a thin one's length (from a linear
# density, kg/m): a tube given by its mass per area is a flat annulus (a washer), of the same I.
AREAS: dict[str, tuple[str, Callable[..., float]]] = {
    "disc": ("A = πR²", lambda radius: math.pi * radius * radius),
    "tube": ("A = π(R₂² − R₁²)", lambda inner_radius, outer_radius: math.pi * (outer_radius - inner_radius) * (outer_radius + inner_radius)),
    "plate": ("A = WH", lambda width, height: width * height),
    "shell": ("A = 4πR²", lambda radius: 4 * math.pi * radius * radius),
}
LENGTHS: dict[str, tuple[str, Callable[..., float]]] = {
    "rod": ("ℓ = L", lambda length: length),
    "ring": ("ℓ = 2πR", lambda radius: 2 * math.pi * radius),
}
VOLUMES: dict[str, tuple[str, Callable[..., float]]] = {
    "disc": ("V = πR²L", lambda radius, length: math.pi * radius * radius * length),
    "tube": ("V = π(R₂² − R₁²)L", lambda inner_radius, outer_radius, length: math.pi * (outer_radius - inner_radius) * (outer_radius + inner_radius) * length),
    "sphere": ("V = (4/3)πR³", lambda radius: 4 / 3 * math.pi * radius**3),
    "thick-shell": ("V = (4/3)π(R₂³ − R₁³)", lambda inner_radius, outer_radius: 4 / 3 * math.pi * (outer_radius - inner_radius)
                    * (outer_radius * outer_radius + outer_radius * inner_radius + inner_radius * inner_radius)),
    "box": ("V = WHD", lambda width, height, depth: width * height * depth),
    "cone": ("V = πR²H/3", lambda radius, height: math.pi * radius * radius * height / 3),
}
