"""inertia: the draws (each shape about each axis, shifted, or of parts) and the definitions."""

from __future__ import annotations

import math
import random

from definitions.check import Checker, inputs, mag, spec, values

SHAPE_FORMULAS = {  # (shape, axis): I of mass M with the dimensions d
    ("point", None): lambda M, d: M * d["radius"] ** 2,
    ("ring", "central"): lambda M, d: M * d["radius"] ** 2,
    ("ring", "diameter"): lambda M, d: M * d["radius"] ** 2 / 2,
    ("disc", "central"): lambda M, d: M * d["radius"] ** 2 / 2,
    ("disc", "diameter"): lambda M, d: M * (d["radius"] ** 2 / 4 + d.get("length", 0.0) ** 2 / 12),
    ("tube", "central"): lambda M, d: M * (d["inner_radius"] ** 2 + d["outer_radius"] ** 2) / 2,
    ("tube", "diameter"): lambda M, d: M * ((d["inner_radius"] ** 2 + d["outer_radius"] ** 2) / 4 + d.get("length", 0.0) ** 2 / 12),
    ("sphere", None): lambda M, d: 2 * M * d["radius"] ** 2 / 5,
    ("shell", None): lambda M, d: 2 * M * d["radius"] ** 2 / 3,
    ("thick-shell", None): lambda M, d: 2 * M * (d["outer_radius"] ** 5 - d["inner_radius"] ** 5) / (5 * (d["outer_radius"] ** 3 - d["inner_radius"] ** 3)),
    ("rod", "center"): lambda M, d: M * d["length"] ** 2 / 12,
    ("rod", "end"): lambda M, d: M * d["length"] ** 2 / 3,
    ("plate", "normal"): lambda M, d: M * (d["width"] ** 2 + d["height"] ** 2) / 12,
    ("plate", "center-width"): lambda M, d: M * d["height"] ** 2 / 12,
    ("plate", "center-height"): lambda M, d: M * d["width"] ** 2 / 12,
    ("plate", "edge-width"): lambda M, d: M * d["height"] ** 2 / 3,
    ("plate", "edge-height"): lambda M, d: M * d["width"] ** 2 / 3,
    ("box", "height"): lambda M, d: M * (d["width"] ** 2 + d["depth"] ** 2) / 12,
    ("box", "width"): lambda M, d: M * (d["height"] ** 2 + d["depth"] ** 2) / 12,
    ("box", "depth"): lambda M, d: M * (d["width"] ** 2 + d["height"] ** 2) / 12,
    ("cone", None): lambda M, d: 3 * M * d["radius"] ** 2 / 10,
}

SHAPE_DIMENSIONS = {"point": ("radius",), "ring": ("radius",), "disc": ("radius", "length"), "tube": ("inner_radius", "outer_radius", "length"),
                    "sphere": ("radius",), "shell": ("radius",), "thick-shell": ("inner_radius", "outer_radius"), "rod": ("length",),
                    "plate": ("width", "height"), "box": ("width", "height", "depth"), "cone": ("radius", "height")}

CENTRAL_AXES = {"central", "center", "normal", "center-width", "center-height", "diameter", "height", "width", "depth", None}

def draw_inertia(rng: random.Random) -> tuple[dict, list[str]]:
    """A standard shape about each of its axes, shifted by --offset, or a body of parts (shapes, a
    given I moved by the parallel axes, a radius of gyration, a density)."""
    shape, axis = rng.choice(tuple(SHAPE_FORMULAS))
    kw: dict = {"shape": shape, "mass": mag(rng, -2, 2)}
    size = mag(rng, -2, 1)
    for name in SHAPE_DIMENSIONS[shape]:
        if name == "length" and shape in ("disc", "tube") and (axis != "diameter" or rng.random() < 0.3):
            continue
        kw[name] = size * mag(rng, -0.5, 0.5)
    if "inner_radius" in kw:
        kw["inner_radius"] = kw["outer_radius"] * rng.uniform(0, 0.95)
    if axis is not None and rng.random() < 0.8:
        kw["axis"] = axis
    tags = [shape]
    if axis in CENTRAL_AXES and rng.random() < 0.3 and shape != "point":
        kw["offset"] = size * mag(rng, -1, 0.5)
        tags.append("offset")
    if rng.random() < 0.3:
        kw["part"] = []
        for _ in range(rng.choice((1, 2, 3))):
            m = kw["mass"] * mag(rng, -1, 0.5)
            kind = rng.choice(("point", "disc", "inertia", "gyration", "density"))
            if kind == "point":
                kw["part"].append("point " + spec(mass=(m, "kg"), offset=(size * rng.random(), "m")))
            elif kind == "disc":
                kw["part"].append("disc " + spec(mass=(m, "kg"), radius=(size * rng.random(), "m"), offset=(size * rng.random(), "m")))
            elif kind == "inertia":
                kw["part"].append(spec(inertia=(m * size * size * rng.random(), "kg*m^2"), mass=(m, "kg"), offset=(size * rng.random(), "m")))
            elif kind == "gyration":
                kw["part"].append(spec(gyration=(size * rng.random(), "m"), mass=(m, "kg")))
            else:
                kw["part"].append("sphere " + spec(density=(mag(rng, 2, 4), "kg/m^3"), radius=(size * rng.random(), "m")))
            tags.append("part " + kind)
    if kw["mass"] and rng.random() < 0.05:
        kw["mass"] = 0.0
    return kw, tags

def check_inertia(kw: dict, report, c: Checker) -> None:
    res, inp = values(report), inputs(report)
    I = res["I"]
    if "part" in kw:
        rows = report.tables["parts"].rows
        c.eq("a body's I = Σ its parts' I", I, math.fsum(row[4] for row in rows))
        c.eq("a body's mass = Σ its parts' masses", res.get("mass"), math.fsum(row[1] for row in rows))
        for shape, mass, i_cm, offset, i, share in rows:
            c.eq("a part's I = I_cm + m d²", i, i_cm + mass * offset * offset)
            c.eq("a part's share = 100 I_part/I", share, 100 * i / I)
        for n, text in enumerate(kw["part"], start=2):
            key = f"part{n}_"
            row = rows[n - 1]
            if key + "gyration" in inp:
                c.eq("a part's I = m k² (gyration=)", row[2], inp[key + "mass"] * inp[key + "gyration"] ** 2)
            elif key + "density" in inp:
                c.eq("a part's mass = ρ V (density=, a sphere)", row[1], inp[key + "density"] * 4 * math.pi * inp[key + "radius"] ** 3 / 3)
            elif key + "inertia" in inp:
                c.eq("a part's I_cm = inertia=", row[2], inp[key + "inertia"])
        mass = res.get("mass")
    else:
        mass = inp["mass"]
        axis = kw.get("axis", next(a for (s, a) in SHAPE_FORMULAS if s == kw["shape"]))
        dims = {name: inp[name] for name in SHAPE_DIMENSIONS[kw["shape"]] if name in inp}
        own = SHAPE_FORMULAS[(kw["shape"], axis)](mass, dims)
        if "offset" in inp:
            c.eq("I_cm = the shape's closed form", res.get("I_cm"), own)
            c.eq("I = I_cm + M d² (parallel axes)", I, own + mass * inp["offset"] ** 2)
        else:
            c.eq("I = the shape's closed form", I, own)
    if mass:
        c.eq("k = √(I/M)", res.get("k"), math.sqrt(I / mass))


# #34: a body by its density, read by its unit: its measure (volume, area, length) from each shape's geometry.
MEASURES = {
    ("disc", "kg/m^3"): lambda d: math.pi * d["radius"] ** 2 * d["length"],
    ("sphere", "kg/m^3"): lambda d: 4 * math.pi * d["radius"] ** 3 / 3,
    ("box", "kg/m^3"): lambda d: d["width"] * d["height"] * d["depth"],
    ("disc", "kg/m^2"): lambda d: math.pi * d["radius"] ** 2,
    ("plate", "kg/m^2"): lambda d: d["width"] * d["height"],
    ("shell", "kg/m^2"): lambda d: 4 * math.pi * d["radius"] ** 2,
    ("tube", "kg/m^2"): lambda d: math.pi * (d["outer_radius"] ** 2 - d["inner_radius"] ** 2),
    ("rod", "kg/m"): lambda d: d["length"],
    ("ring", "kg/m"): lambda d: 2 * math.pi * d["radius"],
}


def draw_by_density(rng: random.Random) -> tuple[dict, list[str]]:
    """A shape by its density (kg/m³, kg/m², kg/m as its unit says), or a body by --gyration and --mass."""
    if rng.random() < 0.2:
        return {"gyration": mag(rng, -2, 1), "mass": mag(rng, -2, 3)}, ["gyration"]
    shape, unit = rng.choice(sorted(MEASURES))
    kw: dict = {"shape": shape}
    needs = {"disc": ("radius",) if unit == "kg/m^2" else ("radius", "length"), "tube": ("inner_radius", "outer_radius")}.get(shape, SHAPE_DIMENSIONS[shape])
    for name in needs:
        kw[name] = mag(rng, -2, 1)
    if "inner_radius" in kw:
        kw["inner_radius"] = kw["outer_radius"] * rng.uniform(0, 0.95)
    kw["density"] = f"{mag(rng, -1, 4)!r} {unit}"
    return kw, ["density " + unit]


def check_by_density(kw: dict, report, c: Checker) -> None:
    res, inp = values(report), inputs(report)
    if "gyration" in kw:
        c.eq("I = M k² (--gyration)", res["I"], inp["mass"] * inp["gyration"] ** 2)
        return
    unit = kw["density"].split()[1]
    dims = {name: inp[name] for name in ("radius", "inner_radius", "outer_radius", "length", "width", "height", "depth") if name in inp}
    mass = inp["density"] * MEASURES[(kw["shape"], unit)](dims)
    c.eq("mass = density × (volume | area | length)", res["mass"], mass)
    axis = next((axis for (shape, axis) in SHAPE_FORMULAS if shape == kw["shape"]), None)
    c.eq("I of the shape with the mass its density gives", res["I"], SHAPE_FORMULAS[(kw["shape"], axis)](mass, dims))
