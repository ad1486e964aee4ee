"""Reading one quantity: text with a unit (or an SI number) to an SI float, with its notes.

``Inputs`` is what a scene's reading gathers as it goes: each value in SI (echoed in the report),
the notes a reading raised (a weight read as a mass, a mixed number), the scene's gravity for a
weight given as a mass, and the uncertainty of a measured value ("4.0+/-0.1 kg").
"""

from __future__ import annotations

from dataclasses import dataclass, field

from taucli.quantities import units
from taucli.core.errors import InputError
from taucli.quantities.measurement import marked, split
from taucli.writing.report import Value, made_value
from taucli.options.table import Option


@dataclass(frozen=True)
class Origin:
    """Where a value was among an option's values: the ``index``-th value given (0: the first) of
    ``option``, and in it the spec's ``key`` (None: the value itself); ``spelled`` names it in
    messages ("{part} 2 mass="); ``unit`` is the SI unit a moved value is written in, ``sign`` the
    sign it may take."""

    option: str
    index: int
    key: str | None
    spelled: str
    unit: str
    sign: str


@dataclass
class Inputs:
    """What was read: each value as given, in SI, and any notes on reading it."""

    values: dict[str, Value] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)
    gravity: float | None = None  # the scene's --g, for a weight given as a mass
    gravity_used: bool = False  # a weight was read as a mass with the scene's --g
    uncertainties: dict[str, float] | None = None  # "4.0+/-0.1 kg": each σ in SI (taucli.quantities.measurement)
    # Where a value read under a key other than its option's name came from, so that an uncertainty
    # given there is carried through as an option's is (taucli.answering.answer): key -> Origin.
    origins: dict[str, Origin] = field(default_factory=dict)

    def quantity(self, name: str, given, kind: str, *, sign: str = "positive", key: str | None = None, origin: Origin | None = None) -> float | None:
        """The SI value of ``given``: text with a unit, or a number, which is SI. ``origin``: where
        in an option's values it was (a spec's key, the nth value of a repeated option)."""
        if given is None:
            return None
        if origin is not None:
            self.origins[key or name] = origin
        if given.__class__ is str and (value := units.known(given, kind, sign)) is not None:  # most texts of a batch
            self.values[key or name] = made_value((value, units.KINDS[kind].si_unit, ""))
            return value
        option = name if name.startswith("{") else "{" + name + "}"
        if isinstance(given, str):
            if marked(given):
                given = self._uncertain(given, option, kind, key or name)
            parsed = units.parse(given, option, kind, sign=sign, gravity=self.gravity)
            value, note = parsed.value, parsed.note
            self.gravity_used = self.gravity_used or (parsed.weight and self.gravity is not None)
        elif isinstance(given, (int, float)) and not isinstance(given, bool):
            value, note = units.si_number(given, option, kind, sign=sign), None
        else:
            raise InputError(name, "expected a number or a text with a unit", example='"4kg"', got=repr(given))
        self.values[key or name] = Value(value, units.KINDS[kind].si_unit, "")
        if note:
            self.notes.append(note)
        return value

    def _uncertain(self, given: str, option: str, kind: str, key: str) -> str:
        """The value's text of "4.0+/-0.1 kg", its uncertainty kept (SI) under ``key``."""
        parts = split(given)
        if parts is None:
            return given
        spread = units.parse(parts[1], option + " (its uncertainty)", kind, sign="nonnegative", gravity=self.gravity).value
        self.uncertainties = {**(self.uncertainties or {}), key: spread}
        return parts[0]


def word(option: Option, given) -> str:
    if not isinstance(given, str):
        expected = f"one of {', '.join(option.choices)}" if option.choices else "a text"
        raise InputError(option.name, f"expected {expected}", got=f"{given!r} ({type(given).__name__})")
    return given.strip()
