"""drive's --load: "inertia=… ratio=… efficiency=… torque=…" (or a mass, "mass=… radius=…|speed=…
force=…"), one of several loads a motor drives, each through its own train; read as every spec is
(taucli.answering.specs) into a taucli.scenes.drive.loads.Load.
"""

from __future__ import annotations

from taucli.answering.reading import Inputs
from taucli.answering.specs import _read_fields, _spec_fields, _specs
from taucli.core.errors import InputError
from taucli.options.table import Option
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
