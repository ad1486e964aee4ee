"""The contacts pressed on a turning body, given as "key=value" specs (#24, #35, #47, #48): --brake (a
shoe, on a lever or not, or internal expanding shoes), --face (a flat face or a cone clutch's), --band (a band brake, or a
band-and-block one), --caliper (a caliper disc brake), --centrifugal (a centrifugal clutch). Read as taucli.answering.specs reads every spec, into the records of
taucli.scenes.given.
"""

from __future__ import annotations

import math

from taucli.core.errors import InputError
from taucli.answering.reading import Inputs
from taucli.answering.specs import _MU_FIELDS, _read_fields, _spec_fields, _specs, coefficients
from taucli.writing.report import fmt
from taucli.scenes.given import PADS, PRESSURES, SHOES, Band, Brake, Caliper, Centrifugal, Face
from taucli.options.table import Option


# --brake, --face and --band of spin-down and impulse (#24, #35): "key=value ..." specs like --particle's.
BRAKE_FIELDS = {**_MU_FIELDS, "force": ("force", "nonnegative"), "radius": ("length", "positive"),
                "lever": ("length", "positive"), "pivot": ("length", "positive"), "offset": ("length", "any"),
                "shoe_angle": ("angle", "positive"), "heel_angle": ("angle", "nonnegative"), "width": ("length", "positive"),
                "hinge": ("length", "positive"), "pmax": ("pressure", "positive")}
EXPANDING_KEYS = ("heel_angle", "width", "hinge", "pmax", "shoes")  # only with expanding=yes (taucli.scenes.expanding)
FACE_FIELDS = {**_MU_FIELDS, "force": ("force", "nonnegative"), "inner_radius": ("length", "nonnegative"), "outer_radius": ("length", "positive"),
               "surfaces": ("dimensionless", "positive"), "pmax": ("pressure", "positive"), "cone": ("angle", "positive")}
BAND_FIELDS = {**_MU_FIELDS, "wrap": ("angle", "positive"), "radius": ("length", "positive"), "width": ("length", "positive"),
               "tension": ("force", "nonnegative"), "force": ("force", "nonnegative"), "lever": ("length", "positive"),
               "slack_arm": ("length", "positive"), "tight_arm": ("length", "positive"),
               "blocks": ("dimensionless", "positive"), "block_angle": ("angle", "positive"), "thickness": ("length", "nonnegative")}

CALIPER_FIELDS = {**_MU_FIELDS, "force": ("force", "nonnegative"), "inner_radius": ("length", "nonnegative"), "outer_radius": ("length", "positive"),
                  "angle": ("angle", "positive"), "pad_radius": ("length", "positive"), "centre_distance": ("length", "positive"),
                  "surfaces": ("dimensionless", "positive")}
CALIPER_EXAMPLE = '{caliper} "mu=0.37 force=3748lbf inner-radius=3.875in outer-radius=5.5in angle=108deg model=wear"'
BUTTON_EXAMPLE = '{caliper} "mu=0.31 force=500N pad=circular pad-radius=12mm centre-distance=50mm model=wear"'
CENTRIFUGAL_FIELDS = {"shoes": ("dimensionless", "positive"), "mass": ("mass", "positive"), "radius": ("length", "positive"),
                      "spring_force": ("force", "nonnegative"), "mu": ("dimensionless", "nonnegative"), "drum_radius": ("length", "positive")}
CENTRIFUGAL_EXAMPLE = '{centrifugal} "shoes=4 mass=6kg radius=160mm spring-force=1450N mu=0.35 drum-radius=250mm"'


def brakes(option: Option, given, inputs: Inputs, stdin) -> tuple:
    """Each "force=… mu=… [radius=…]" (force= the normal force N), or "force=… lever=… pivot=…
    [offset=…] mu=…" (force= the force F on a lever; see taucli.scenes.contact)."""
    example = '{brake} "force=100N mu=0.4 radius=0.5m"'
    lever_example = '{brake} "force=200N lever=1m pivot=0.4m offset=0.05m mu=0.3 radius=0.2m"'
    brakes = []
    for number, source, spec in _specs(option, given):
        _, fields = _spec_fields(spec, source, {*BRAKE_FIELDS, "expanding", "shoes"}, example, shape_word=False)
        if fields.get("expanding", "no") not in ("yes", "no"):
            raise InputError(source, "expanding= is yes (internal expanding shoes) or no", example=EXPANDING_EXAMPLE, got=repr("expanding=" + fields["expanding"]))
        if fields.get("expanding") == "yes":
            brakes.append(_expanding(option, number, source, spec, fields, inputs))
            continue
        if any(key in fields for key in EXPANDING_KEYS):
            key = next(key for key in EXPANDING_KEYS if key in fields)
            raise InputError(source, f"takes {key.replace('_', '-')}= only with expanding=yes (internal expanding shoes)", example=EXPANDING_EXAMPLE, got=repr(spec))
        if "force" not in fields:
            raise InputError(source, "needs force=", example=example, got=repr(spec))
        if ("lever" in fields) != ("pivot" in fields):
            raise InputError(source, "takes lever= (where the force acts) with pivot= (where the shoe is), both from the lever's pivot",
                             example=lever_example, got=repr(spec))
        if "offset" in fields and "lever" not in fields:
            raise InputError(source, "takes offset= (the friction's arm about the lever's pivot) only with lever= and pivot=", example=lever_example, got=repr(spec))
        values = _read_fields(fields, BRAKE_FIELDS, source, f"brake{number}", inputs, option.name, number - 1)
        mu_k, mu_s = coefficients(source, values)
        shoe_angle = values.get("shoe_angle")
        if shoe_angle is not None and shoe_angle > math.pi * (1 + 1e-12):
            raise InputError(source, "shoe-angle= is the arc 2θ the shoe covers, at most 180deg (the pressure p_max·cos φ is 0 at ±90°)",
                             example='{brake} "force=800N mu=0.35 radius=160mm shoe-angle=90deg"', got=repr("shoe-angle=" + fields["shoe_angle"]))
        brakes.append(Brake(source, values["force"], mu_k, mu_s, values.get("radius"), values.get("lever"), values.get("pivot"), values.get("offset", 0.0),
                            shoe_angle))
    return tuple(brakes)


EXPANDING_EXAMPLE = '{brake} "expanding=yes force=2.3kN mu=0.32 width=32mm radius=150mm hinge=123mm lever=212mm heel-angle=0deg shoe-angle=126deg"'


def _expanding(option: Option, number: int, source: str, spec: str, fields: dict, inputs: Inputs) -> Brake:
    """Internal expanding shoes: "expanding=yes force=…|pmax=… mu=… width=… [radius=…] hinge=…
    lever=… heel-angle=… shoe-angle=… [shoes=both|leading|trailing]" (taucli.scenes.expanding)."""
    missing = [key for key in ("mu", "width", "hinge", "lever", "heel_angle", "shoe_angle") if key not in fields and not (key == "mu" and "mu_k" in fields)]
    if missing:
        raise InputError(source, f"with expanding=yes needs {missing[0].replace('_', '-')}= (the shoes' width=, hinge= the pin's distance from the drum's centre, "
                         "lever= the actuating force's arm about the pin, heel-angle= and shoe-angle= the lining's arc from the pin's line)",
                         example=EXPANDING_EXAMPLE, got=repr(spec))
    if ("force" in fields) == ("pmax" in fields):
        raise InputError(source, "with expanding=yes takes force= (the actuating force on each shoe) or pmax= (the largest lining pressure), one of them",
                         example=EXPANDING_EXAMPLE, got=repr(spec))
    for key in ("pivot", "offset"):
        if key in fields:
            raise InputError(source, f"with expanding=yes takes no {key}= (the shoe's own hinge pin is its lever's pivot: hinge= and lever=)",
                             example=EXPANDING_EXAMPLE, got=repr(spec))
    shoes = fields.get("shoes", "both")
    if shoes not in SHOES:
        raise InputError(source, f"shoes= is one of {', '.join(SHOES)} (leading: the self-energizing one, the drum's rim running past it from its toe towards its hinge pin)",
                         example=EXPANDING_EXAMPLE, got=repr("shoes=" + shoes))
    values = _read_fields(fields, BRAKE_FIELDS, source, f"brake{number}", inputs, option.name, number - 1)
    mu_k, mu_s = coefficients(source, values)
    if values["heel_angle"] + values["shoe_angle"] > math.pi * (1 + 1e-12):
        raise InputError(source, "has heel-angle= + shoe-angle= beyond 180deg: the pressure p_a·sin θ falls to 0 at 180° from the pin's line",
                         example=EXPANDING_EXAMPLE, got=f"{fmt(math.degrees(values['heel_angle'] + values['shoe_angle']))}°")
    return Brake(source, values.get("force"), mu_k, mu_s, values.get("radius"), values["lever"], None, 0.0, values["shoe_angle"], True,
                 values["heel_angle"], values["width"], values["hinge"], values.get("pmax"), shoes)


def faces(option: Option, given, inputs: Inputs, stdin) -> tuple:
    """Each "mu=… [force=… | pmax=…] [inner-radius=… outer-radius=…] [model=uniform|wear] [surfaces=N]".
    pressure=uniform|wear, the model's old key, is read as model= with a note."""
    example = '{face} "mu=0.2", or {face} "mu=0.3 force=2kN inner-radius=5cm outer-radius=12cm model=wear surfaces=2"'
    faces = []
    for number, source, spec in _specs(option, given):
        _, fields = _spec_fields(spec, source, {*FACE_FIELDS, "model", "pressure"}, example, shape_word=False)
        if "pressure" in fields:
            if fields["pressure"] not in PRESSURES:
                raise InputError(source, "pressure= was the model's old key (uniform|wear): the largest lining pressure is pmax=, the model model=",
                                 example='{face} "mu=0.3 pmax=1MPa inner-radius=5cm outer-radius=12cm model=wear"', got=repr("pressure=" + fields["pressure"]))
            if "model" in fields:
                raise InputError(source, "has model= and pressure=: pressure= is the old spelling of model=, give it once", example=example, got=repr(spec))
            fields["model"] = fields.pop("pressure")
            inputs.notes.append(f"{source}: pressure={fields['model']} read as model={fields['model']} (the pressure model; pmax= gives the largest pressure)")
        if "force" in fields and "pmax" in fields:
            raise InputError(source, "takes force= (the clamp force) or pmax= (the largest pressure, giving the force), not both",
                             example='{face} "mu=0.3 pmax=1MPa inner-radius=5cm outer-radius=12cm"', got=repr(spec))
        values = _read_fields(fields, FACE_FIELDS, source, f"face{number}", inputs, option.name, number - 1)
        mu_k, mu_s = coefficients(source, values)
        model = fields.get("model", "uniform")
        if model not in PRESSURES:
            raise InputError(source, f"model= is one of {', '.join(PRESSURES)}", example=example, got=repr(model))
        surfaces = values.get("surfaces", 1.0)
        if surfaces != int(surfaces):
            raise InputError(source, "surfaces= is a whole number", example=example, got=repr(fields["surfaces"]))
        cone = values.get("cone")
        if cone is not None and cone > math.pi / 2 * (1 + 1e-12):
            raise InputError(source, "cone= is the semi-cone angle, above 0 and at most 90deg (90deg: a flat face)",
                             example='{face} "mu=0.2 force=5kN inner-radius=170mm outer-radius=205mm cone=20deg"', got=repr("cone=" + fields["cone"]))
        faces.append(Face(source, mu_k, mu_s, values.get("force"), values.get("inner_radius"), values.get("outer_radius"), model, int(surfaces),
                          values.get("pmax"), cone))
    return tuple(faces)


def bands(option: Option, given, inputs: Inputs, stdin) -> tuple:
    """Each "mu=… wrap=… [radius=…] [width=…]" with "tension=…" (the pull on the slack end) or
    "force=… lever=… slack-arm=…|tight-arm=…" (a lever; both arms: a differential band brake)."""
    example = '{band} "mu=0.25 wrap=270deg radius=0.3m force=400N lever=750mm slack-arm=125mm"'
    bands = []
    for number, source, spec in _specs(option, given):
        _, fields = _spec_fields(spec, source, BAND_FIELDS, example, shape_word=False)
        blocked = "blocks" in fields or "block_angle" in fields
        block_example = '{band} "mu=0.3 blocks=12 block-angle=15deg radius=300mm thickness=75mm tension=1kN"'
        if blocked and ("blocks" not in fields or "block_angle" not in fields or "wrap" in fields or "width" in fields):
            raise InputError(source, "a band-and-block brake takes blocks= (how many) with block-angle= (the angle 2θ each covers), "
                             "and no wrap= (it is blocks × block-angle) nor width= (the blocks, not the band, press the drum)",
                             example=block_example, got=repr(spec))
        if "thickness" in fields and not blocked:
            raise InputError(source, "takes thickness= (the blocks') only with blocks= and block-angle=", example=block_example, got=repr(spec))
        if "wrap" not in fields and not blocked:
            raise InputError(source, "needs wrap= (the angle of drum the band covers)", example=example, got=repr(spec))
        levered = [key for key in ("force", "lever", "slack_arm", "tight_arm") if key in fields]
        if ("tension" in fields) == bool(levered):
            raise InputError(source, "needs tension= (the pull on the band's slack end) or a lever: force= lever= and slack-arm= or tight-arm=, not both",
                             example=example, got=repr(spec))
        if levered and ("force" not in fields or "lever" not in fields or not {"slack_arm", "tight_arm"} & set(fields)):
            raise InputError(source, "a lever needs force= at lever= from its pivot, and slack-arm= or tight-arm= (or both) where the band's ends are",
                             example=example, got=repr(spec))
        values = _read_fields(fields, BAND_FIELDS, source, f"band{number}", inputs, option.name, number - 1)
        mu_k, mu_s = coefficients(source, values)
        blocks, wrap = None, values.get("wrap")
        if blocked:
            blocks = values["blocks"]
            if blocks != int(blocks):
                raise InputError(source, "blocks= is a whole number", example=block_example, got=repr(fields["blocks"]))
            blocks = int(blocks)
            wrap = blocks * values["block_angle"]
            if wrap > 2 * math.pi * (1 + 1e-12):
                raise InputError(source, "has blocks= × block-angle= above a full turn (360deg)", example=block_example,
                                 got=f"{blocks} × {fmt(math.degrees(values['block_angle']))}° = {fmt(math.degrees(wrap))}°")
        bands.append(Band(source, mu_k, wrap, mu_s, values.get("radius"), values.get("width"), values.get("tension"), values.get("force"),
                          values.get("lever"), values.get("slack_arm"), values.get("tight_arm"), blocks, values.get("block_angle"),
                          values.get("thickness", 0.0)))
    return tuple(bands)


def centrifugals(option: Option, given, inputs: Inputs, stdin) -> tuple:
    """"shoes=… mass=… radius=… spring-force=… mu=… drum-radius=…" (taucli.scenes.centrifugal):
    every key is needed; radius= is the shoes' centre of mass when they touch the drum, at most drum-radius=."""
    clutches = []
    for number, source, spec in _specs(option, given):
        _, fields = _spec_fields(spec, source, CENTRIFUGAL_FIELDS, CENTRIFUGAL_EXAMPLE, shape_word=False)
        missing = [key.replace("_", "-") + "=" for key in CENTRIFUGAL_FIELDS if key not in fields]
        if missing:
            raise InputError(source, f"needs {' '.join(missing)}", example=CENTRIFUGAL_EXAMPLE, got=repr(spec))
        values = _read_fields(fields, CENTRIFUGAL_FIELDS, source, f"centrifugal{number}", inputs, option.name, number - 1)
        shoes = values["shoes"]
        if shoes != int(shoes):
            raise InputError(source, "shoes= is a whole number", example=CENTRIFUGAL_EXAMPLE, got=repr("shoes=" + fields["shoes"]))
        if values["radius"] > values["drum_radius"] * (1 + 1e-12):
            raise InputError(source, "has radius= (the shoes' centre of mass when they touch the drum) beyond drum-radius= (the drum's inner radius)",
                             example=CENTRIFUGAL_EXAMPLE, got=f"{fmt(values['radius'])} m > {fmt(values['drum_radius'])} m")
        clutches.append(Centrifugal(source, int(shoes), values["mass"], values["radius"], values["spring_force"], values["mu"], values["drum_radius"]))
    return tuple(clutches)


def calipers(option: Option, given, inputs: Inputs, stdin) -> tuple:
    """Each "mu=… force=… [pad=annular] [inner-radius=…] outer-radius=… [angle=…] [model=uniform|wear] [surfaces=N]" or
    "mu=… force=… pad=circular pad-radius=… centre-distance=… [model=…] [surfaces=N]" (taucli.scenes.caliper);
    pad= follows from the keys where it is not given; surfaces= 2 unless given (a pad each side of the disc)."""
    annular_keys, circular_keys = ("inner_radius", "outer_radius", "angle"), ("pad_radius", "centre_distance")
    calipers = []
    for number, source, spec in _specs(option, given):
        _, fields = _spec_fields(spec, source, {*CALIPER_FIELDS, "model", "pad"}, CALIPER_EXAMPLE, shape_word=False)
        given_annular, given_circular = [key for key in annular_keys if key in fields], [key for key in circular_keys if key in fields]
        if "pad" not in fields and given_annular and given_circular:
            raise InputError(source, "mixes an annular pad's keys (" + " ".join(key.replace("_", "-") + "=" for key in given_annular) + ") with a circular pad's ("
                             + " ".join(key.replace("_", "-") + "=" for key in given_circular) + "): give one pad", example=CALIPER_EXAMPLE, got=repr(spec))
        pad = fields.get("pad", "circular" if given_circular else "annular")
        if pad not in PADS:
            raise InputError(source, f"pad= is one of {', '.join(PADS)}", example=BUTTON_EXAMPLE, got=repr("pad=" + pad))
        example = BUTTON_EXAMPLE if pad == "circular" else CALIPER_EXAMPLE
        foreign = [key for key in (annular_keys if pad == "circular" else circular_keys) if key in fields]
        if foreign:
            raise InputError(source, f"a{'' if pad == 'circular' else 'n'} {pad} pad takes " + (
                "pad-radius= and centre-distance= (the distance of its centre from the axis), not " if pad == "circular" else
                "inner-radius=, outer-radius= and angle=, not ") + " nor ".join(key.replace("_", "-") + "=" for key in foreign),
                example=example, got=repr(spec))
        needed = ("force", *(circular_keys if pad == "circular" else ("outer_radius",)))
        missing = [key.replace("_", "-") + "=" for key in needed if key not in fields]
        if missing:
            raise InputError(source, f"needs {' '.join(missing)}", example=example, got=repr(spec))
        model = fields.get("model", "uniform")
        if model not in PRESSURES:
            raise InputError(source, f"model= is one of {', '.join(PRESSURES)}", example=example, got=repr("model=" + model))
        values = _read_fields(fields, CALIPER_FIELDS, source, f"caliper{number}", inputs, option.name, number - 1)
        mu_k, mu_s = coefficients(source, values)
        surfaces = values.get("surfaces", 2.0)
        if surfaces != int(surfaces):
            raise InputError(source, "surfaces= is a whole number (the pads pressed on the disc, 2 for one caliper)", example=example,
                             got=repr("surfaces=" + fields["surfaces"]))
        if pad == "circular" and values["pad_radius"] >= values["centre_distance"]:
            raise InputError(source, "has pad-radius= not below centre-distance= (the pad would reach the axis)", example=example,
                             got=f"{fmt(values['pad_radius'])} m ≥ {fmt(values['centre_distance'])} m")
        inner = values.get("inner_radius", 0.0)
        if pad == "annular" and inner > values["outer_radius"]:
            raise InputError(source, "has inner-radius= above outer-radius=", example=example, got=f"{fmt(inner)} m > {fmt(values['outer_radius'])} m")
        if values.get("angle") is not None and values["angle"] > 2 * math.pi * (1 + 1e-12):
            raise InputError(source, "angle= is the pad's sector angle, at most 360deg", example=example, got=repr("angle=" + fields["angle"]))
        calipers.append(Caliper(source, mu_k, values["force"], pad, mu_s, inner, values.get("outer_radius"), values.get("angle"),
                                values.get("pad_radius"), values.get("centre_distance"), model, int(surfaces)))
    return tuple(calipers)
