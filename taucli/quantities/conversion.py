"""A quantity written in another unit (``taucli convert``), read by the rules every option reads by.

The text says its kind only through its unit, and a unit may fit several kinds (N·m: a torque, a
torsion constant; mm: a length, a screw's lead). Each kind reads it as an option of that kind
would, notes included; the kind kept is the first (in ``KINDS``' order) whose reading, and whose
reading of the unit asked for, is of its own kind: ``1 N*m`` is a torque, not an energy typed in
N·m, and ``2 lbf`` a force, not the mass it weighs. Where the kinds left give different numbers
the text is refused as ambiguous rather than one of them printed.
"""

from __future__ import annotations

import math
import re
from typing import NamedTuple

from taucli.core.errors import InputError
from taucli.quantities import meanings, measurement
from taucli.quantities.kinds import ANGLE_POWERS, KINDS, Kind, article
from taucli.quantities.registry import MASS_AS_WEIGHT, WEIGHT, quantity
from taucli.quantities.units import converted, parse, read

# How a text is read when it is a quantity of another kind than the one read (a weight for a mass,
# a joule for a torque): another kind's reading of it comes first when there is one.
_ANOTHER_KIND = frozenset({WEIGHT, MASS_AS_WEIGHT, meanings.ENERGY_FOR_TORQUE, meanings.TORQUE_FOR_ENERGY})

# Kinds that share a dimension with a kind before them and are read as such only when nothing
# else reads the text: N·m is a torque before a torsion constant (N·m/rad), kg·m² an inertia
# before a drag coefficient (N·m·s²), mm a length before a screw's lead, Pa a pressure, kg·m²/s
# and N·m·s an angular momentum before a viscous coefficient (N·m per rad/s; the one number either
# way, but a viscous coefficient names its angle: N*m/rpm, N*m/Hz are read only as one).
_SECOND_READINGS = frozenset({"torsion constant", "lead", "drag coefficient", "stress", "viscous coefficient"})

EXAMPLE = "'3000 rpm' rad/s"


class Conversion(NamedTuple):
    """A quantity in the unit asked for (or SI), the kind it was read as, and how it was read."""

    given: str
    kind: str
    value: float  # in ``unit``
    unit: str  # as asked (or the kind's SI unit), with ^ for powers
    si_value: float
    si_unit: str
    notes: tuple[str, ...]
    uncertainty: float | None = None  # the standard uncertainty given with it ("3+/-0.1 kg"), in ``unit``
    si_uncertainty: float | None = None


def convert_quantity(text: str, unit: str | None = None) -> Conversion:
    """``text`` (a number and its unit, perhaps with its uncertainty: "4.0+/-0.1 kg") in ``unit``,
    or in SI when ``unit`` is None. The uncertainty is the value's kind, read the same way."""
    parts = measurement.split(text) if measurement.marked(text) else None
    if parts is None:
        return _converted(text, unit)
    done = _converted(parts[0], unit)
    try:
        si_spread = parse(parts[1], "quantity", done.kind, sign="nonnegative").value
    except InputError as err:
        raise InputError("quantity", f"expected an uncertainty of {article(done.kind)} after ± (zero or more)", example="'4.0+/-0.1 kg'", got=err.got or repr(text)) from None
    spread = si_spread if unit is None or not unit.strip() else converted(si_spread, KINDS[done.kind].si_unit, unit, "unit").value
    return done._replace(given=text, uncertainty=abs(spread), si_uncertainty=si_spread)


class _Reading(NamedTuple):
    """One kind's reading of the text, and of the unit asked for (the value in it)."""

    kind: Kind
    si_value: float
    value: float
    note: str | None
    another_kind: bool  # read as a quantity of another kind: a weight for a mass, a joule for a torque
    angle_left_over: bool  # the text or the unit has an angle the kind has not (1 mm/rev for a length)


def _converted(text: str, unit: str | None) -> Conversion:
    """``text`` (a number and its unit) in ``unit``, or in SI when ``unit`` is None."""
    readings = _readings(text)
    if unit is None or not unit.strip():
        chosen = _chosen(readings, text, None)
        si_unit = chosen.kind.si_unit.replace("**", "^")
        return Conversion(text, chosen.kind.name, chosen.value, si_unit, chosen.si_value, si_unit, _notes(chosen.note))
    candidates, refusals = [], []
    for reading in readings:
        try:
            target = converted(reading.si_value, reading.kind.si_unit, unit, "unit")
        except InputError as err:
            refusals.append(err)
            continue
        other = target.note is not None and (any(meanings.NOTES.get(how, "\0") in target.note for how in _ANOTHER_KIND) or _as_weight(target.note))
        candidates.append(reading._replace(value=target.value, note=_joined(reading.note, target.note), another_kind=reading.another_kind or other,
                                           angle_left_over=reading.angle_left_over or _angle_left_over("1 " + unit, reading.kind)))
    if not candidates:
        raise refusals[0]  # "unit: expected a unit of an angular velocity (e.g. rad/s), got 'kg'"
    chosen = _chosen(candidates, text, unit)
    return Conversion(text, chosen.kind.name, chosen.value, unit.strip(), chosen.si_value, chosen.kind.si_unit.replace("**", "^"), _notes(chosen.note))


def _readings(text: str) -> list[_Reading]:
    """Every kind's reading of ``text``, or the refusal that says best why none reads it."""
    readings, refusals = [], []
    for kind in KINDS.values():
        try:
            parsed = parse(text, "quantity", kind.name, sign="any")
        except InputError as err:
            refusals.append(err)
            continue
        how = read(text, "quantity", kind).how
        readings.append(_Reading(kind, parsed.value, parsed.value, parsed.note, how in _ANOTHER_KIND, _angle_left_over(text, kind)))
    if readings and read(text, "quantity", readings[0].kind).unit == "":
        raise InputError("quantity", "expected a number with its unit: a number alone has no unit to convert from", example=EXAMPLE, got=repr(text))
    if not readings:
        raise _best_refusal(refusals, text)
    return readings


def _angle_left_over(text: str, kind: Kind) -> bool:
    """Whether ``text`` has an angle in its unit that ``kind`` has not (1 mm/rev: a lead, which a
    length reads as (1/2π) mm, the radian being 1 to pint; v = ωR is still a velocity when nothing
    else reads it)."""
    if kind.name in ANGLE_POWERS or kind.name == "dimensionless":
        return False
    q, _ = quantity(text, "quantity", kind.name)
    return dict(q.to_root_units().unit_items()).get("radian", 0) != 0


def _best_refusal(refusals: list[InputError], text: str) -> InputError:
    """Why no kind reads ``text``: the reason its own kind gave (a bound, an unknown unit and the
    unit it is close to), else that its dimension is none of taucli's kinds."""
    own = [err for err in refusals if "which is" not in (err.got or "")]
    suggested = [err for err in own if "did you mean" in (err.got or "") + (err.hint or "")]
    if suggested or (own and len({err.got for err in own}) == 1):
        err = (suggested or own)[0]
        return InputError("quantity", "expected a number and a unit taucli reads", example=EXAMPLE, got=err.got, hint=err.hint)
    if own:
        return own[0]  # out of its kind's bounds: "expected a mass of 0 or between 1e-40 and 1e40 kg in size"
    return InputError("quantity", "expected a quantity of a kind taucli takes (a mass, a length, an angle, a torque, …: docs/units.md lists them)",
                      example=EXAMPLE, got=refusals[0].got or repr(text))


def _chosen(candidates: list[_Reading], text: str, unit: str | None) -> _Reading:
    """The first reading (in KINDS' order) with no angle left over, not of _SECOND_READINGS, of
    its own kind, as far as there is one; refused when the readings as good as it disagree about
    the number (N*m/Hz^2: an inertia with Hz as 1/s, or a drag coefficient with Hz as rev/s)."""
    first = min(candidates, key=lambda c: (c.angle_left_over, c.kind.name in _SECOND_READINGS, c.another_kind))
    alike = [c for c in candidates if not c.another_kind and c.angle_left_over == first.angle_left_over]
    disagree = [c.kind.name for c in alike
                if not (math.isclose(c.value, first.value, rel_tol=1e-12, abs_tol=0.0) and math.isclose(c.si_value, first.si_value, rel_tol=1e-12, abs_tol=0.0))]
    if disagree:
        kinds = " or ".join(article(name) for name in [first.kind.name, *dict.fromkeys(disagree)])
        raise InputError("unit" if unit else "quantity", f"could be {kinds}, which differ here: give a unit that names one", example=EXAMPLE,
                         got=repr(text) + (f" in {unit!r}" if unit else ""))
    return first


def _as_weight(note: str | None) -> bool:
    return note is not None and bool(re.search(r"\bweight\b", note))


def _joined(*notes: str | None) -> str | None:
    said = [note for note in notes if note]
    return "\n".join(said) if said else None


def _notes(note: str | None) -> tuple[str, ...]:
    """Each note, without the option's name the reader put before it (convert has no options)."""
    return tuple(re.sub(r"^(quantity|unit) ", "", line) for line in note.split("\n")) if note else ()
