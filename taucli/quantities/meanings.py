"""What a unit means beyond pint's reading of it: the radian's bookkeeping, a unit of another kind
with the same dimension, and the names that read with a note or not at all.

pint reads the radian as 1, so it never says when a unit leaves its angle out or names one too
many: ``N*m/Hz`` is N·m·s to it (Hz = 1/s), ``rad*Hz`` an angular velocity. One rule here, for
every kind with an angle in its unit (``kinds.ANGLE_POWERS``: angular velocity and acceleration,
viscous and drag coefficients, torsion constant, angle, lead), wherever the unit stands in the
text:

- ``Hz`` (any prefix) is revolutions per second, a rotational frequency (ISO 80000-3: ω = 2πn),
  inside a coefficient as alone: ``N*m/Hz`` is N·m/(rev/s), ``N*m/Hz^2`` N·m/(rev/s)²;
  ``rpm``, ``rps`` and ``rev`` are revolutions by their names;
- a power is a torque times an angular velocity in rad/s (P = τω): P/ω is a torque with no
  angle (a slip line's ``300N*m/(50kW/(960rpm))*40rpm`` is an angular velocity), P/τ an
  angular velocity in radians;
- the unit then holds the kind's power of the angle (rad/s, N·m/(rev/s)), or none where SI leaves
  it out (``N*m*s`` for a viscous coefficient, ``N*m`` for a torsion constant: radians; a
  time in it other than the second, ``N*m*min``, could be per radian or per revolution and is
  refused); a 1/time alone for an angular velocity is decided by registry._per_time. Any other
  power of the angle (``rad*Hz``, ``N*m*s*rev``) is refused.

A torque typed in joules (or an energy in newton-metres) is read, with a note: the same dimension,
another kind. ``ton`` (short, long or metric?) is refused; ``PS`` is the metric horsepower
(pint's picosiemens otherwise), ``hp`` the mechanical one, ``grad`` gradians: each with a note.
"""

from __future__ import annotations

from functools import lru_cache

from taucli.quantities import spellings
from taucli.core.errors import InputError
from taucli.quantities.kinds import Kind, article

# How a unit is read (registry.HOWS holds these beside its own): a power used as τω, a unit of
# energy for a torque and of torque for an energy, and names that read with a note.
POWER_AS_TORQUE_SPEED, ENERGY_FOR_TORQUE, TORQUE_FOR_ENERGY, MECHANICAL_HP, METRIC_HP, GRADIANS = 6, 7, 8, 9, 10, 11
HOWS = (POWER_AS_TORQUE_SPEED, ENERGY_FOR_TORQUE, TORQUE_FOR_ENERGY, MECHANICAL_HP, METRIC_HP, GRADIANS)

NOTES = {
    POWER_AS_TORQUE_SPEED: "a power is a torque times an angular velocity in rad/s (P = τω): P/ω is a torque, P/τ an angular velocity",
    ENERGY_FOR_TORQUE: "a joule is an energy; a torque is N·m (read as 1 J = 1 N·m)",
    TORQUE_FOR_ENERGY: "N·m is a torque; an energy is J (read as 1 N·m = 1 J)",
    MECHANICAL_HP: "hp read as the mechanical horsepower, 745.7 W (550 ft·lbf/s); the metric one is PS, 735.49875 W",
    METRIC_HP: "PS read as the metric horsepower, 735.49875 W (75 kgf·m/s); hp is the mechanical one, 745.7 W",
    GRADIANS: "grad: gradians, 400 per turn; degrees are deg",
}

# pint's name of a unit -> how a unit holding it is read (the first found, in this order).
_NAMED = (("metric_horsepower", METRIC_HP), ("horsepower", MECHANICAL_HP), ("grade", GRADIANS))

CONSTANTS = frozenset({"pi"})  # numbers by name (the screen writes π as pi): 0.135*20*pi/15 N*m is (0.135·20π/15) N·m


# "ton": a short ton (2000 lb) to pint, a metric tonne to most of the world, a long ton (2240 lb) to
# a British book. Refused, naming each.
AMBIGUOUS_TONS = {"ton": "mass", "tons": "mass", "tonf": "force", "ton_force": "force", "tons_force": "force", "force_ton": "force"}


def ton_refusal(name: str, number: str, force: bool) -> tuple[str, str]:
    """Why ``name`` is refused, and the fix with ``number`` ("16") in each reading."""
    if force or AMBIGUOUS_TONS[name] == "force":
        return (f"{name} could be a tonne-force (9806.65 N), a short ton-force (2000 lbf) or a long ton-force (2240 lbf)",
                f"write {number}tf, {number}short_ton_force or {number}long_ton_force")
    return ("ton could be a tonne (1000 kg), a short ton (2000 lb) or a long ton (2240 lb)",
            f"write {number}t (or {number}tonne), {number}short_ton or {number}long_ton")


@lru_cache(maxsize=256)
def _is_hertz(ureg, name: str) -> bool:
    try:
        return any(unit == "hertz" for _, unit, _ in ureg.parse_unit_name(name))
    except Exception:  # noqa: BLE001 - a name pint cannot split is no hertz
        return False


def with_revolutions(ureg, cleaned: str) -> tuple[str, bool]:
    """``cleaned`` with each Hz (any prefix) written as revolutions per second ("N*m/Hz" ->
    "N*m/(Hz*rev)"), and whether there was one."""
    out, found = [], False
    for token in spellings.tokens(cleaned):
        if token.kind == "name" and _is_hertz(ureg, token.text):
            out.append(f"({token.text}*rev)")
            found = True
        else:
            out.append(token.text)
    return "".join(out), found


@lru_cache(maxsize=256)
def _a_power(ureg, name: str) -> bool:
    return ureg.Quantity(1, name).dimensionality == ureg.Quantity(1, "W").dimensionality


def power_units(ureg, q) -> int:
    """The power of the units of power in ``q`` (kW/(960 rpm): -1... of kW: 1): each holds one
    radian when a power is a torque times an angular velocity in rad/s."""
    return sum(power for name, power in q.unit_items() if _a_power(ureg, name))


def names_a_power(ureg, cleaned: str) -> bool:
    """Whether ``cleaned`` names a unit of power anywhere ("1000rpm - 300N*m/(50kW/(960rpm))*40rpm")."""
    return any(token.kind == "name" and _known(ureg, token.text) and _a_power(ureg, token.text) for token in spellings.tokens(cleaned))


def _known(ureg, name: str) -> bool:
    try:
        return name in ureg
    except Exception:  # noqa: BLE001 - a name pint cannot look up is no unit of power
        return False


def other_times(q) -> list[str]:
    """The units of time in ``q`` other than the second (``N*m*min``: minute)."""
    times = {"minute", "hour", "day", "week", "year", "millisecond", "microsecond", "nanosecond", "kilosecond"}
    return [name for name, power in q.unit_items() if power and name in times]


def named(ureg, q, kind_name: str) -> int | None:
    """How a unit of ``q`` read as given for ``kind_name`` is read where a note is due: a unit of
    energy for a torque, of torque for an energy, a horsepower or gradians; else None."""
    names = [name for name, power in q.unit_items() if power]
    energy = ureg.Quantity(1, "J").dimensionality
    if kind_name == "torque" and any(ureg.Quantity(1, name).dimensionality == energy for name in names):
        return ENERGY_FOR_TORQUE
    if kind_name == "energy" and any(name.endswith("newton") for name in names) and not any(
        ureg.Quantity(1, name).dimensionality == energy for name in names
    ):
        return TORQUE_FOR_ENERGY
    return next((how for name, how in _NAMED if name in names), None)


def revolutions_note(unit: str | None) -> str:
    """How Hz or min^-1 inside a coefficient's unit was read: "N*m/Hz read with Hz as rev/s"."""
    per = "min^-1 as revolutions per minute" if unit and "min" in unit and "Hz" not in unit else "Hz as revolutions per second"
    return f"{unit.replace('**', '^') + ' ' if unit else ''}read with {per} (ω = 2πn)"


def ambiguous_time(symbol: str, time: str, count: str, text: str, option: str, kind: Kind) -> InputError:
    """The refusal of ``N*m*min`` for a viscous coefficient: per radian or per revolution per minute?"""
    square = "^2" if kind.name == "drag coefficient" else ""
    example = f"'{count} N*m/(rad/{symbol}){square}' or '{count} N*m/(rev/{symbol}){square}'"
    if kind.name == "angular momentum":  # L = Iω: the angle in the numerator, as in ω
        example = f"'{count} kg*m^2*rad/{symbol}' or '{count} kg*m^2*rev/{symbol}'"
    return InputError(option, f"expected {article(kind.name)} that names its angle", example=example,
                      got=f"{text!r}: {'an' if time == 'hour' else 'a'} {time} with no angle could be per radian or per revolution")


def angle_power_words(power: int) -> str:
    return {0: "no angle", 1: "the angle once", -1: "per angle once", 2: "the angle squared", -2: "per angle squared"}.get(
        power, f"the angle to the power {power}")

