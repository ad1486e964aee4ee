"""drive's --segment: "time=… torque=…|power=… [rest=yes]", a segment of a motor's duty cycle,
read as every spec is (taucli.answering.specs) into a taucli.scenes.drive.duty.Segment.
"""

from __future__ import annotations

from taucli.answering.reading import Inputs
from taucli.answering.specs import _read_fields, _spec_fields, _specs
from taucli.core.errors import InputError
from taucli.options.table import Option
from taucli.scenes.drive.duty import Segment

SEGMENT_FIELDS = {"time": ("time", "positive"), "torque": ("torque", "any"), "power": ("power", "any")}  # key: (kind, sign)
EXAMPLE = '{segment} "time=10min power=100kW"'


def segments(option: Option, given, inputs: Inputs, stdin) -> tuple:
    """Each segment: time= with torque= or power= (either may be 0: idle), rest=yes for the motor at a standstill."""
    found = []
    for number, source, spec in _specs(option, given):
        _, fields = _spec_fields(spec, source, {*SEGMENT_FIELDS, "rest"}, EXAMPLE, shape_word=False)
        if "time" not in fields:
            raise InputError(source, "needs time=", example=EXAMPLE, got=repr(spec))
        if ("torque" in fields) == ("power" in fields):
            raise InputError(source, "needs torque= or power= (one of them)", example=EXAMPLE, got=repr(spec))
        rest = fields.get("rest", "no")
        if rest not in ("yes", "no"):
            raise InputError(source, "expected rest=yes or rest=no", example='{segment} "time=5min torque=0 rest=yes"', got=repr(spec))
        values = _read_fields(fields, SEGMENT_FIELDS, source, f"segment{number}", inputs, option.name, number - 1)
        found.append(Segment(source, values["time"], values.get("torque"), values.get("power"), rest == "yes"))
    return tuple(found)
