"""Moment of inertia of a body: a shape (taucli.scenes.shapes) about one of its axes, shifted by
the parallel-axis theorem, given by its own I, its radius of gyration or its density, and bodies
of several parts.

I = Σ m r² over the body's mass about the rotation axis; I = I_cm + M d² for an axis at d from
the parallel one through the centre of mass; a body's I is the sum of its parts' about one axis.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace

from taucli.quantities.kinds import check_bounds
from taucli.core.errors import InputError, Unused
from taucli.options.inertia import COMMAND as TABLE
from taucli.writing.report import Report, Step, Table, fmt, quantity_text
from taucli.scenes.given import Part
from taucli.scenes.moved import moved
from taucli.scenes.shapes import AREAS, LENGTHS, SHAPES, VOLUMES, Axis, Shape, fill, lookup_shape, thin_notes, unused
from taucli.options.table import Results


@dataclass(frozen=True)
class PartInertia:
    """A part's moment of inertia about its own centre and about the rotation axis.

    ``inertia_centre`` is about the axis through the part's centre of mass parallel to the
    rotation axis, and ``offset`` the distance between the two, so that always
    inertia = inertia_centre + mass·offset² (a point: 0 and its distance; a rod about its end:
    ML²/12 and L/2).
    """

    part: Part
    shape: Shape
    axis: Axis
    inertia_centre: float
    inertia: float
    steps: tuple[Step, ...]
    offset: float = 0.0
    notes: tuple[str, ...] = ()  # what was assumed for a dimension left out (#42 item 3)


@dataclass(frozen=True)
class BodyInertia:
    """The moment of inertia of a whole body about the rotation axis, with its worked steps."""

    inertia: float
    mass: float | None  # None where a part's mass is not known (a part of given inertia alone)
    parts: tuple[PartInertia, ...]
    steps: tuple[Step, ...]
    description: str
    notes: tuple[str, ...] = ()


def _given_inertia(part: Part) -> PartInertia:
    """A part given by its own I (inertia=) or radius of gyration (gyration= with mass=), moved by
    offset= with the parallel-axis theorem (which needs its mass)."""
    if part.inertia is not None and part.gyration is not None:
        raise InputError(part.option("gyration"), "conflicts with inertia=: give the part's I one way")
    if part.dims or part.density is not None:
        raise InputError(part.option("inertia" if part.inertia is not None else "gyration"), "needs no shape or dimensions: they are in its I")
    steps: list[Step] = []
    if part.gyration is not None:
        if part.mass is None:
            raise InputError(part.option("mass"), "is needed with gyration= (I = Mk²)", example=part.example("gyration", "0.3m"))
        own = part.mass * part.gyration**2
        steps.append(Step("Moment of inertia from the radius of gyration", "I = Mk²",
                          f"{quantity_text(part.mass, 'kg')} × ({quantity_text(part.gyration, 'm')})²", quantity_text(own, "kg*m**2"),
                          "k is the distance at which the whole mass, gathered in a ring, would have the same I"))
    else:
        own = part.inertia
        steps.append(Step("Moment of inertia given", "I = I_given", "", quantity_text(own, "kg*m**2"), "the part's own moment of inertia, as given"))
    shape = Shape("given", "part of given inertia", (), (Axis("given", "its own axis", "I", "", lambda mass: own, "as given"),))
    if part.offset is None:
        return PartInertia(part, shape, shape.axes[0], own, own, tuple(steps))
    if part.mass is None:
        raise InputError(part.option("mass"), "is needed with offset= (the parallel-axis theorem: I = I_cm + Md²)", example=part.example("offset", "0.2m"))
    moved = own + part.mass * part.offset**2
    steps.append(Step("Shift to the rotation axis (parallel-axis theorem)", "I = I_cm + Md²",
                      f"{quantity_text(own, 'kg*m**2')} + {quantity_text(part.mass, 'kg')} × ({quantity_text(part.offset, 'm')})²",
                      quantity_text(moved, "kg*m**2"), "the given I is about the part's centre of mass, at distance d from the rotation axis"))
    return PartInertia(part, shape, shape.axes[0], own, moved, tuple(steps), part.offset)


# What a density is per, by its unit: the measures of the shapes it applies to, the symbols, the words.
_PER = {
    "kg/m**3": (VOLUMES, "M = ρV", "V", "m**3", "volume", "a solid of known volume", "a uniform body's mass is its density times its volume"),
    "kg/m**2": (AREAS, "M = σA", "A", "m**2", "area", "a flat body (a disc, a plate, a washer: a tube; a thin shell)",
                "a uniform sheet's mass is its mass per area times its area"),
    "kg/m": (LENGTHS, "M = λℓ", "ℓ", "m", "length", "a thin body along a line (a rod, a ring)", "a uniform wire's mass is its mass per length times its length"),
}


def _mass_from_density(part: Part, shape: Shape) -> tuple[Part, Step]:
    """The part with its mass from its density: ρ × volume, σ × area (a plate's or disc's mass per
    area) or λ × length (a rod's or ring's per length), as the density's unit says."""
    if part.mass is not None:
        raise InputError(part.option("density"), "conflicts with mass=: give the part's mass or its density")
    measures, law, symbol, unit, measure, needs, why = _PER[part.density_unit]
    if shape.name not in measures:
        raise InputError(part.option("density"), f"needs {needs} when it is per {measure} ({part.density_unit.replace('**', '^')}): {', '.join(measures)}, not a {shape.title}")
    equation, measure_of = measures[shape.name]
    needed = measure_of.__code__.co_varnames[: measure_of.__code__.co_argcount]  # its parameters' names
    for dim in needed:
        if dim not in part.dims:
            raise InputError(part.option(dim), f"is needed for the {measure} of a {shape.title} ({equation})", example=part.example(dim, "0.05m"))
    size = measure_of(**{dim: part.dims[dim] for dim in needed})
    mass = part.density * size
    step = Step(f"Mass of the {shape.title} from its density", f"{law},  {equation}",
                f"{quantity_text(part.density, part.density_unit)} × {quantity_text(size, unit)}", quantity_text(mass, "kg"), why)
    return replace(part, mass=mass, density=None), step


def part_inertia(part: Part, placed: bool = False) -> PartInertia:
    """I of one part about the rotation axis: its shape's closed form, then any parallel shift.
    ``placed``: the scene places parts round the axis (angle=: inertia's --body-offset)."""
    if part.angle is not None and not placed:
        raise InputError(part.option("angle"), "places a part round the axis for taucli inertia --body-offset (it finds the body's centre of mass); "
                         "about the axis only a part's distance counts: leave it out", example=part.example("offset", "0.2m"))
    if part.inertia is not None or part.gyration is not None:
        return _given_inertia(part)
    density_step = None
    if part.density is not None:
        part, density_step = _mass_from_density(part, lookup_shape(part.shape, f"{part.source} shape".strip() if part.source else "SHAPE"))
        found = part_inertia(part, placed)
        return PartInertia(found.part, found.shape, found.axis, found.inertia_centre, found.inertia, (density_step, *found.steps), found.offset)
    if part.mass is None:
        raise InputError(part.option("mass"), "is needed (or density=, inertia=, gyration=)", example=part.example("mass", "1kg"))
    shape = lookup_shape(part.shape, f"{part.source} shape".strip() if part.source else "SHAPE")
    axis = shape.axis(part.axis)
    dims = dict(part.dims)
    for dim in shape.dims:
        if dim not in dims and not unused(shape, axis, dim, dims):
            needs = ", ".join(part.mention(d) for d in ("mass", *shape.dims))
            raise InputError(part.option(dim), f"is needed for a {shape.title} (it takes {needs})", example=part.example(dim, "0.2m"))
    for dim in dims:
        if dim not in shape.dims and dim not in shape.optional:
            takes = ", ".join(part.mention(d) for d in (*shape.dims, *shape.optional))
            raise InputError(part.option(dim), f"does not apply to a {shape.title} (it takes {takes or 'only the mass'})")
    if "inner_radius" in dims and dims["inner_radius"] > dims["outer_radius"]:
        raise InputError(
            part.option("inner_radius"),
            "expected at most the outer radius",
            got=f"{fmt(dims['inner_radius'])} m > {fmt(dims['outer_radius'])} m",
        )
    if shape.name == "point":
        return _point_inertia(part, shape, axis, dims)

    mass = part.mass
    notes = thin_notes(part.source, shape, axis, dims)
    dims.update({dim: 1.0 for dim in shape.dims if dim not in dims})  # one I about this axis does not use (#42 item 14)
    inertia_centre = axis.moment(mass, **dims)  # about the axis named, before any shift
    shifted = part.offset is not None
    if shifted and not axis.through_centre:
        raise InputError(
            part.option("offset"),
            f"needs an axis through the centre of mass, and {axis.description} is not one",
            hint=f"use {{axis}} {shape.axes[0].name} with the offset",
        )
    symbol = "I_cm" if shifted else "I"
    steps = [
        Step(
            f"Moment of inertia of a {shape.title} about {axis.description}",
            axis.equation.replace("I =", f"{symbol} =", 1),
            fill(axis.numbers, mass, dims),
            quantity_text(inertia_centre, "kg*m**2"),
            axis.why,
        )
    ]
    inertia = inertia_centre
    if shifted:
        offset = part.offset
        inertia = inertia_centre + mass * offset**2
        steps.append(
            Step(
                "Shift to the rotation axis (parallel-axis theorem)",
                "I = I_cm + Md²",
                f"{quantity_text(inertia_centre, 'kg*m**2')} + {quantity_text(mass, 'kg')} × ({quantity_text(offset, 'm')})²",
                quantity_text(inertia, "kg*m**2"),
                "the rotation axis is parallel to one through the centre of mass at distance d; "
                "the cross term ∫2x·d dm vanishes because the centre of mass is on the first axis",
            )
        )
        return PartInertia(part, shape, axis, inertia_centre, inertia, tuple(steps), offset, notes)
    if axis.centre is not None:  # about an end or an edge: the same I seen from the centre of mass
        central, distance = axis.centre
        return PartInertia(part, shape, axis, shape.axis(central).moment(mass, **dims), inertia, tuple(steps), distance(**dims), notes)
    return PartInertia(part, shape, axis, inertia_centre, inertia, tuple(steps), 0.0, notes)


def _point_inertia(part: Part, shape: Shape, axis: Axis, dims: Mapping[str, float]) -> PartInertia:
    if "radius" in dims and part.offset is not None:
        raise InputError(part.option("offset"), "conflicts with the radius: a point's distance from the axis is one of them, not both")
    distance = dims.get("radius", part.offset)
    if distance is None:
        raise InputError(part.option("radius"), "is needed for a point mass: its distance from the axis", example=part.example("radius", "0.2m"))
    inertia = axis.moment(part.mass, radius=distance)
    step = Step(
        "Moment of inertia of a point mass",
        axis.equation,
        fill(axis.numbers, part.mass, {"radius": distance}),
        quantity_text(inertia, "kg*m**2"),
        axis.why,
    )
    return PartInertia(part, shape, axis, 0.0, inertia, (step,), distance)


def describe_part(result: PartInertia) -> str:
    if result.shape.name == "given":
        text = "a part of given inertia" if result.part.gyration is None else f"a part of radius of gyration {fmt(result.part.gyration)} m"
        return text + (f", shifted {fmt(result.part.offset)} m (parallel-axis theorem)" if result.part.offset is not None else "")
    if result.shape.name == "point":
        distance = result.part.dims.get("radius", result.part.offset)
        return f"point mass {fmt(distance)} m from the axis"
    text = f"{result.shape.title} about {result.axis.description}"
    if result.shape.name != "point" and result.part.offset is not None:
        text += f", shifted {fmt(result.part.offset)} m (parallel-axis theorem)"
    return text


def body_inertia(parts: Sequence[Part], placed: bool = False) -> BodyInertia:
    """I of a body of one or more parts about one axis: I = Σ I_i (moments about one axis add).
    ``placed``: its parts may say where they lie round the axis (angle=)."""
    results = tuple(part_inertia(part, placed) for part in parts)
    mass = None if any(r.part.mass is None for r in results) else math.fsum(r.part.mass for r in results)
    inertia = math.fsum(r.inertia for r in results)
    # The bounds of a typed --inertia hold for one computed from a shape too.
    check_bounds(inertia, "moment of inertia", _given(parts), got=f"I = {inertia:g} kg*m**2")
    notes = tuple(note for r in results for note in r.notes)
    if len(results) == 1:
        return BodyInertia(inertia, mass, results, results[0].steps, describe_part(results[0]), notes)
    steps: list[Step] = []
    for number, result in enumerate(results, start=1):
        steps.extend(Step(f"Part {number}: {s.title[0].lower()}{s.title[1:]}", s.equation, s.numbers, s.result, s.why) for s in result.steps)
    terms = " + ".join(f"I{_subscript(n)}" for n in range(1, len(results) + 1))
    steps.append(
        Step(
            "Add the parts",
            f"I = {terms}",
            " + ".join(quantity_text(r.inertia, "kg*m**2") for r in results),
            quantity_text(inertia, "kg*m**2"),
            "each part's Σmr² is taken about the same axis, so the sums add",
        )
    )
    description = f"body of {len(results)} parts: " + "; ".join(describe_part(r) for r in results)
    return BodyInertia(inertia, mass, results, tuple(steps), description, notes)


def _given(parts: Sequence[Part]) -> str:
    """The options that gave the parts, as a message names them: "{mass} and {radius}",
    "{mass}, {radius} and {part} 2"."""
    named = []
    for part in parts:
        if part.source:
            named.append(part.source)
        else:
            named += ["{mass}", *("{" + dim + "}" for dim in part.dims), *(["{offset}"] if part.offset is not None else [])]
    return named[0] if len(named) == 1 else f"{', '.join(named[:-1])} and {named[-1]}"


def _subscript(n: int) -> str:
    return str(n).translate(str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉"))


def solve(parts: Sequence[Part], body_offset: float | None = None, show_mass: bool = False) -> Report:
    """The inertia scene: I about the axis, the radius of gyration k = √(I/M), I_cm when shifted;
    with ``body_offset`` d the whole body moved to a parallel axis d from its centre of mass:
    I = I_cm + Md², I_cm about the body's centre of mass (taucli.scenes.moved)."""
    body = built = body_inertia(parts, placed=True)
    if body_offset is not None:
        body, about_cm = moved(built, body_offset)
    gyration = math.sqrt(body.inertia / body.mass) if body.mass else None
    notes = list(body.notes)
    if body.mass is None:  # (#48 item 2: a part of I alone was counted as massless)
        unknown = ", ".join(r.part.source or "the shape" for r in body.parts if r.part.mass is None)
        notes.append(f"mass, k: the mass of {unknown} is not known (given by its inertia alone): give mass= for the total mass and k = √(I/M)")
    results = Results(TABLE)
    results.put("I", body.inertia)
    results.put("k", gyration)
    single = body.parts[0] if len(body.parts) == 1 else None
    if body_offset is not None:
        results.put("I_cm", about_cm)
    elif single is not None and single.shape.name != "point" and single.part.offset is not None:
        results.put("I_cm", single.inertia_centre)
    if single is None or show_mass:
        results.put("mass", body.mass)
    steps = list(body.steps)
    if gyration is not None:
        steps.append(Step("Radius of gyration", "k = √(I/M)", f"√({quantity_text(body.inertia, 'kg*m**2')} / {quantity_text(body.mass, 'kg')})",
                          quantity_text(gyration, "m"), "the distance from the axis at which the whole mass, gathered in a ring, would have the same I"))
    tables = {} if single is not None else {"parts": parts_table(built)}  # each part's share of I about the axis it was built on
    return Report("inertia", body.description, "closed form", results, steps, notes, {}, tables)


def parts_table(body: BodyInertia) -> Table:
    """The parts of a body: each one's mass, I_cm, offset, I about the axis and share of the whole."""
    rows = tuple(
        (r.shape.name, r.part.mass, r.inertia_centre, r.offset, r.inertia, 100 * r.inertia / body.inertia if body.inertia else None)
        for r in body.parts
    )
    columns = (
        ("shape", None, "part"),
        ("mass", "kg", "mass"),
        ("I_cm", "kg*m**2", "I_cm"),
        ("offset", "m", "offset"),
        ("I", "kg*m**2", "I"),
        ("share", "%", "share of I"),
    )
    return Table(columns, rows)


def main_part(shape: str | None, mass: float | None, axis: str | None, offset: float | None, dims: Mapping[str, float | None],
              gyration: float | None = None, density=None) -> Part:
    """The part the main options describe: SHAPE (or --shape) with --mass (or --density) and its
    dimensions; or, with no shape, --gyration with --mass (I = Mk²)."""
    if gyration is not None:
        if shape is not None:
            raise InputError("gyration", "conflicts with {shape}: a shape's I comes from its dimensions; give one of them")
        if density is not None:
            raise InputError("density", "conflicts with {gyration}: with a radius of gyration give {mass}")
        given = [name for name, value in dims.items() if value is not None]
        if given:
            raise InputError(given[0], "goes with {shape}; with {gyration} the body needs only {mass}")
        if mass is None:
            raise InputError("mass", "is required with {gyration} (I = Mk²)", example="{mass} 5kg {gyration} 0.3m")
        return Part("", mass, {}, None, offset, gyration=gyration)
    if shape is None:
        raise InputError("shape", f"is required, one of {', '.join(SHAPES)}", example="taucli inertia disc {mass} 5kg {radius} 0.2m")
    found = lookup_shape(shape, "shape")
    present = {name: value for name, value in dims.items() if value is not None}
    if density is not None:
        if mass is not None:
            raise InputError("density", "conflicts with {mass}: give the body's mass or its density")
        value, unit = (density.value, density.unit) if hasattr(density, "unit") else (density, "kg/m**3")
        return Part(found.name, None, present, axis, offset, density=value, density_unit=unit)
    if mass is None:
        raise InputError("mass", f"is required for a {found.title} (or {{density}})", example="{mass} 5kg")
    return Part(found.name, mass, present, axis, offset)


def inertia(*, shape: str | None = None, mass: float | None = None, axis: str | None = None, offset: float | None = None, part: Sequence[Part] = (),
            body_offset: float | None = None, g: float | None = None, gyration: float | None = None, density=None, **dims: float | None) -> Report:
    """``taucli inertia``: a shape's moment of inertia (shifted by --offset), or a body of parts
    (the whole moved by --body-offset: I = I_cm + Md² on the total mass). --g serves only to read
    a weight given for a mass (--mass 490N). A shape by its --density (the mass is then a result), or a body by its
    --gyration and --mass."""
    if g is not None:
        raise Unused("g", "is used only to read a weight given for a mass", example="{mass} 490N {g} 9.8m/s^2")
    report = solve([main_part(shape, mass, axis, offset, dims, gyration, density), *part], body_offset, show_mass=density is not None)
    if offset is not None and part:
        report.notes.append(f"--offset moves the {shape} alone (the first part); each --part keeps its own offset=; "
                            "--body-offset moves the whole body (the parallel-axis theorem on its total mass)")
    return report


def body_table(
    *, inertia: float | None = None, shape: str | None = None, mass: float | None = None, axis: str | None = None,
    offset: float | None = None, part: Sequence[Part] = (), gyration: float | None = None, density=None, **dims: float | None,
) -> Table | None:
    """The parts table of a scene's body made of parts (None for a body of one piece)."""
    if not part:
        return None
    if inertia is not None:
        pieces = [Part("", None, inertia=inertia), *part]
    elif shape is not None or gyration is not None:
        pieces = [main_part(shape, mass, axis, offset, dims, gyration, density), *part]
    else:
        pieces = list(part)
    return parts_table(body_inertia(pieces)) if len(pieces) > 1 else None


def body_mass(
    *, inertia: float | None = None, shape: str | None = None, mass: float | None = None, axis: str | None = None,
    offset: float | None = None, part: Sequence[Part] = (), gyration: float | None = None, density=None, **dims: float | None,
) -> float | None:
    """The whole body's mass where its pieces give it (the shape's with every part's, a part of
    density= by its volume); None where a piece has none (--inertia, a part of inertia= alone)."""
    pieces = ([main_part(shape, mass, axis, offset, dims, gyration, density)] if shape is not None or gyration is not None else []) + list(part)
    if inertia is not None or not pieces:
        return mass
    found = body_inertia(pieces)
    return found.mass if all(p.part.mass is not None for p in found.parts) else None


def body(
    *, inertia: float | None = None, shape: str | None = None, mass: float | None = None, axis: str | None = None,
    offset: float | None = None, part: Sequence[Part] = (), gyration: float | None = None, density=None, notes: list[str] | None = None,
    **dims: float | None,
) -> tuple[float, Sequence[Step]]:
    """The moment of inertia of a scene's body and its steps: --inertia, or --shape with its options
    (--mass or --density), or --gyration with --mass. What was assumed for a dimension left out (a
    thin disc about a diameter) is added to ``notes``."""
    found = _body(inertia, shape, mass, axis, offset, part, gyration, density, dims)
    if found is None:
        return inertia, ()
    if notes is not None:
        notes.extend(note for note in found.notes if note not in notes)
    return found.inertia, found.steps


def body_notes(body_options: Mapping) -> list[str]:
    """What body() assumes for the body these options give (none where they give none)."""
    if not any(body_options.get(name) is not None for name in ("inertia", "shape", "gyration")) and not body_options.get("part"):
        return []
    notes: list[str] = []
    body(**body_options, notes=notes)
    return notes


def _body(inertia, shape, mass, axis, offset, part, gyration, density, dims) -> BodyInertia | None:
    """body()'s BodyInertia (None for an --inertia alone)."""
    shape_options = [name for name, value in (("mass", mass), ("axis", axis), ("offset", offset), ("density", density), *dims.items()) if value is not None]
    if inertia is not None and gyration is not None:
        raise InputError("gyration", "conflicts with {inertia}: give the body's I one way")
    if gyration is not None or (density is not None and shape is not None):
        return body_inertia([main_part(shape, mass, axis, offset, dims, gyration, density), *part])
    if inertia is not None:
        if shape is not None:
            raise InputError("inertia", "conflicts with {shape}: give one of them")
        if shape_options:
            raise InputError(shape_options[0], "goes with {shape}; with {inertia} it is not used")
        if not part:
            return None
        return body_inertia([Part("", None, inertia=inertia), *part])
    if shape is None:
        if part and not shape_options:  # the parts make up the whole body
            return body_inertia(part)
        raise InputError("inertia", "or {shape} is required", example="{inertia} '0.1kg*m^2', or {shape} disc {mass} 5kg {radius} 0.2m")
    return body_inertia([main_part(shape, mass, axis, offset, dims), *part])
