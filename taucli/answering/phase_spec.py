"""spin-down's --phase: "[coast] alpha=…|torque=… time=…|angle=…|until-omega=…", one phase of a run
each, read as specs are (taucli.answering.specs) into taucli.scenes.given.Phase."""

from __future__ import annotations

from taucli.answering.reading import Inputs
from taucli.answering.specs import _read_fields, _spec_fields, _specs
from taucli.core.errors import InputError
from taucli.options.table import Option
from taucli.scenes.given import Phase

PHASE_FIELDS = {"alpha": ("angular acceleration", "any"), "torque": ("torque", "any"), "time": ("time", "nonnegative"), "angle": ("angle", "any"),
                "until_omega": ("angular velocity", "any")}


def phases(option: Option, given, inputs: Inputs, stdin) -> tuple:
    """spin-down's --phase, each "[coast] alpha=…|torque=… time=…|angle=…|until-omega=…": a rate
    and one end, or (no rate) two ends, from which α follows."""
    example = '{phase} "alpha=2.9e-3rad/s^2 time=2100s" {phase} "coast time=1400s" {phase} "alpha=-2.3e-3rad/s^2 until-omega=4rad/s"'
    found = []
    for number, source, spec in _specs(option, given):
        word_, fields = _spec_fields(spec, source, PHASE_FIELDS, example, shape_word=True)
        if word_ is not None and word_.lower() != "coast":
            raise InputError(source, "expected key=value pairs, or the word coast (α = 0) before them", example=example, got=repr(word_))
        rates = [key for key in ("alpha", "torque") if key in fields] + (["coast"] if word_ else [])
        ends = [key for key in ("time", "angle", "until_omega") if key in fields]
        if len(rates) > 1:
            raise InputError(source, f"has {' and '.join(r.replace('_', '-') + ('' if r == 'coast' else '=') for r in rates)}: give one rate (alpha=, torque= or coast)",
                             example=example, got=repr(spec))
        if (rates and len(ends) != 1) or (not rates and len(ends) != 2):
            raise InputError(source, "needs a rate (alpha=, torque= or coast) and one end (time=, angle= or until-omega=), or two ends and no rate "
                             "(α follows from them)", example=example, got=repr(spec))
        values = _read_fields(fields, PHASE_FIELDS, source, f"phase{number}", inputs, option.name, number - 1)
        found.append(Phase(source, 0.0 if word_ else values.get("alpha"), values.get("torque"), values.get("time"), values.get("angle"), values.get("until_omega")))
    return tuple(found)
