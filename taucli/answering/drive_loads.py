"""drive's --load: "inertia=… ratio=… efficiency=… torque=…" (or a mass, "mass=… radius=…|speed=…
force=…"), one of several loads a motor drives, each through its own train; and --motor-curve,
"tmax=… slip-max=… sync=…", an induction motor's curve. Read as every spec is
(taucli.answering.specs) into a taucli.scenes.drive.loads.Load and a taucli.scenes.drive.curve.Kloss.
"""

from __future__ import annotations

from taucli.answering.reading import Inputs, word
from taucli.answering.specs import _read_fields, _spec_fields, _specs
from taucli.core.errors import InputError
from taucli.options.table import Option
from taucli.scenes.drive.curve import Kloss
from taucli.scenes.drive.loads import Load

LOAD_FIELDS = {  # key: (kind, sign)
    "inertia": ("moment of inertia", "nonnegative"),
    "mass": ("mass", "positive"),
    "radius": ("length", "positive"),
    "speed": ("velocity", "positive"),
    "ratio": ("dimensionless", "positive"),
    "efficiency": ("dimensionless", "positive"),
    "efficiency_back": ("dimensionless", "positive"),
    "torque": ("torque", "any"),
    "force": ("force", "any"),
}
EXAMPLE = '{load} "inertia=10kg*m^2 ratio=10 efficiency=0.9 torque=10N*m"'
MASS_EXAMPLE = '{load} "mass=1000kg speed=1.5m/s force=9810N efficiency=0.85" {motor_speed} 1420rpm'


def loads(option: Option, given, inputs: Inputs, stdin) -> tuple:
    """Each load: what it is (inertia=, a mass=, or only a torque= or force=), how it is driven
    (ratio=, or a mass's radius= at its shaft or speed= at the motor's --motor-speed) and through
    what (efficiency=, efficiency-back=)."""
    found = []
    for number, source, spec in _specs(option, given):
        _, fields = _spec_fields(spec, source, LOAD_FIELDS, EXAMPLE, shape_word=False)
        if not {"inertia", "mass", "torque", "force"} & fields.keys():
            raise InputError(source, "needs inertia=, mass=, torque= or force=: what the load is or what it resists with", example=EXAMPLE, got=repr(spec))
        if "radius" in fields and "speed" in fields:
            raise InputError(source, "has radius= and speed=: give the drum's radius at the load's shaft or the mass's speed at the motor's speed, not both",
                             example=MASS_EXAMPLE, got=repr(spec))
        moved = "radius" in fields or "speed" in fields
        for key in ("mass", "force"):
            if key in fields and not moved:
                raise InputError(source, f"has {key}= but nothing that moves it: radius= (a drum at the load's shaft) or speed= (its speed at {{motor_speed}})",
                                 example=MASS_EXAMPLE, got=repr(spec))
        if moved and not {"mass", "force"} & fields.keys():
            key = "radius" if "radius" in fields else "speed"
            raise InputError(source, f"has {key}= without a mass= or force= that it moves", example=MASS_EXAMPLE, got=repr(spec))
        if "speed" in fields and "ratio" in fields:
            raise InputError(source, "has speed= and ratio=: the mass's speed at the motor's speed holds the whole train's ratio; leave out ratio=",
                             example=MASS_EXAMPLE, got=repr(spec))
        values = _read_fields(fields, LOAD_FIELDS, source, f"load{number}", inputs, option.name, number - 1)
        found.append(Load(source, **values))
    return tuple(found)


CURVE_FIELDS = {"tmax": ("torque", "positive"), "slip_max": ("dimensionless", "positive"), "sync": ("angular velocity", "positive")}
CURVE_EXAMPLE = "{motor_curve} 'tmax=400N*m slip-max=0.2 sync=1500rpm'"


def motor_curve(option: Option, given, inputs: Inputs, stdin) -> Kloss:
    """tmax= (the breakdown torque), slip-max= (the slip where it falls), sync= (the synchronous speed): all three."""
    source = "{" + option.name + "}"
    if isinstance(given, (list, tuple)) and len(given) == 1:  # --find puts its trial key into the one spec as into a repeated one's
        given = given[0]
    spec = word(option, given)
    _, fields = _spec_fields(spec, source, CURVE_FIELDS, CURVE_EXAMPLE, shape_word=False)
    missing = [key.replace("_", "-") + "=" for key in CURVE_FIELDS if key not in fields]
    if missing:
        raise InputError(source, f"needs {', '.join(missing)}: Kloss's curve is the breakdown torque, the slip where it falls and the synchronous speed",
                         example=CURVE_EXAMPLE, got=repr(spec))
    values = _read_fields(fields, CURVE_FIELDS, source, option.name, inputs, option.name, 0)
    return Kloss(source, values["tmax"], values["slip_max"], values["sync"])
