"""The kinds of quantity an option takes, and their bounds: each kind's SI unit, an example to
show, the units offered for "did you mean" and completion, and the sizes a value may have.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from taucli.core.errors import InputError


# Every quantity is 0 or within its kind's bounds in SI: wider than physics asks of a turning body
# (an electron's mass is 9e-31 kg, the observable universe 9e26 m across; an O2 molecule's moment of
# inertia is 2e-46 kg*m^2, the Sun's 4e47), and narrow enough that the products a solver forms stay
# inside a double's range, 1e-308..1.8e308: with I within 1e-60..1e60 and the rest within
# 1e-40..1e40, m*r^2, I*omega^2 and omega^2*I*t^2 (at most 1e60 * 1e80 * 1e80 = 1e220) neither
# overflow nor underflow to a zero divisor. A moment of inertia computed from a shape is held to
# the same bounds (check_bounds, called by scenes.inertia).
BOUNDS = (1e-40, 1e40)


INERTIA_BOUNDS = (1e-60, 1e60)


_PLAIN = re.compile(r"[-\d.e]+ [A-Za-z]+(?:/[A-Za-z]+)?")  # "4 kg", "2 m/s": no character a shell reads


@dataclass(frozen=True)
class Kind:
    """A physical kind of quantity an option takes."""

    name: str  # "moment of inertia"
    si_unit: str  # the unit a bare number means; pint reads it back
    example: str  # shown in messages, as typed in bash, zsh and fish (quoted where it holds * or ^)
    common_units: tuple[str, ...] = ()  # offered for "did you mean" and completion
    bounds: tuple[float, float] = BOUNDS  # the smallest and largest size in SI (0 aside)

    @property
    def typed(self) -> str:
        """The example as one word of a command line: 4kg, 2m/s (a number and a plain unit run
        together, which a shell passes whole), else as written (quoted)."""
        return self.example.replace(" ", "") if _PLAIN.fullmatch(self.example) else self.example


KINDS: dict[str, Kind] = {
    kind.name: kind
    for kind in (
        Kind("mass", "kg", "4 kg", ("kg", "g", "lb", "oz", "tonne")),
        Kind("length", "m", "0.2 m", ("m", "cm", "mm", "km", "in", "ft")),
        Kind("angle", "rad", "30 deg", ("deg", "rad", "rev")),
        Kind("time", "s", "4 s", ("s", "ms", "min", "h")),
        Kind("angular velocity", "rad/s", "300 rpm", ("rad/s", "rpm", "rev/s", "deg/s", "Hz")),
        Kind("angular acceleration", "rad/s**2", "'6 rad/s^2'", ("rad/s^2", "rpm/s", "rev/s^2")),
        Kind("torque", "N*m", "'0.3 N*m'", ("N*m", "mN*m", "kN*m", "lbf*ft", "lbf*in")),
        Kind("moment of inertia", "kg*m**2", "'0.1 kg*m^2'", ("kg*m^2", "g*cm^2", "lb*ft^2"), INERTIA_BOUNDS),
        Kind("force", "N", "6 N", ("N", "kN", "lbf")),
        Kind("acceleration", "m/s**2", "'9.81 m/s^2'", ("m/s^2", "ft/s^2", "g0")),
        Kind("velocity", "m/s", "2 m/s", ("m/s", "km/h", "ft/s", "mph")),
        Kind("momentum", "kg*m/s", "'2 kg*m/s'", ("kg*m/s", "N*s", "g*cm/s")),
        Kind("viscous coefficient", "N*m*s", "'0.01 N*m*s'", ("N*m*s", "N*m/(rad/s)")),
        Kind("angular momentum", "kg*m**2/s", "'2.4 kg*m^2/s'", ("kg*m^2/s", "N*m*s", "g*cm^2/s")),  # L = Iω, and an angular impulse J = ΔL
        Kind("drag coefficient", "N*m*s**2", "'0.001 N*m*s^2'", ("N*m*s^2",)),
        Kind("dimensionless", "", "0.5", ()),
        Kind("power", "W", "1 kW", ("W", "kW", "MW", "hp")),
        Kind("energy", "J", "1 MJ", ("J", "kJ", "MJ", "kW*h", "Wh")),
        Kind("density", "kg/m**3", "'7800 kg/m^3'", ("kg/m^3", "g/cm^3", "lb/ft^3")),
        Kind("areal density", "kg/m**2", "'20 kg/m^2'", ("kg/m^2", "g/cm^2")),  # a plate's or disc's mass per area
        Kind("linear density", "kg/m", "0.5 kg/m", ("kg/m", "g/cm", "g/m")),  # a rod's or ring's mass per length
        Kind("pressure", "Pa", "1 MPa", ("Pa", "kPa", "MPa", "bar", "psi")),
        Kind("stress", "Pa", "200 MPa", ("Pa", "kPa", "MPa", "GPa", "psi", "N/mm^2")),
        Kind("torsion constant", "N*m/rad", "'0.5 N*m/rad'", ("N*m/rad", "N*m/deg", "mN*m/rad")),
        Kind("lead", "m/rev", "5 mm", ("mm", "in", "mm/rev", "in/rev")),  # a screw's advance per turn: a length alone is per revolution
        Kind("specific heat", "J/kg/K", "'460 J/(kg*K)'", ("J/(kg*K)", "kJ/(kg*K)", "J/(g*K)")),  # the heat that warms a kilogram by a kelvin
    )
}


STANDARD_GRAVITY = 9.80665  # m/s^2: what lbf and kgf are defined with


ANGULAR = frozenset({"angular velocity", "angular acceleration"})


# The power of the radian in each kind's unit where it has one (rad/s: 1, N*m/(rad/s): -1): the angle
# a unit of that kind must name, or leave out as SI does (N*m*s for a viscous coefficient).
ANGLE_POWERS = {"angle": 1, "angular velocity": 1, "angular acceleration": 1, "viscous coefficient": -1, "drag coefficient": -2,
                "torsion constant": -1, "lead": -1, "angular momentum": 1}


FORCES = frozenset({"force", "torque", "viscous coefficient", "drag coefficient", "moment of inertia"})  # a mass here is its weight (lb*in*s^2: lbf)


def article(name: str) -> str:
    return ("an " if name[0] in "aeiou" else "a ") + name


def check_bounds(value: float, kind_name: str, option: str, *, sign: str = "nonnegative", got: str | None = None, text: str | None = None) -> None:
    """Refuse a nonzero ``value`` (SI) outside its kind's bounds, typed or computed, as parse does.

    ``got`` says what was given ("I = 4e+119 kg*m**2"); by default the text and its SI value.
    """
    kind = KINDS[kind_name]
    low, high = kind.bounds
    if math.isfinite(value) and (not value or low <= abs(value) <= high):
        return
    raise out_of_bounds(kind_name, option, sign=sign, got=got or f"{text!r} = {value:g} {kind.si_unit}".rstrip())


def out_of_bounds(kind_name: str, option: str, *, sign: str, got: str) -> InputError:
    """The refusal of a value outside its kind's bounds (or too small for a double to hold)."""
    kind = KINDS[kind_name]
    low, high = kind.bounds
    zero = "" if sign == "positive" else "of 0 or "
    return InputError(option, f"expected {article(kind.name)} {zero}between {_power_of_ten(low)} and {_power_of_ten(high)} {kind.si_unit} in size", example=kind.typed, got=got)


def _power_of_ten(x: float) -> str:
    return f"{x:.0e}".replace("e+", "e").replace("e0", "e").replace("e-0", "e-")


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


# Kinds whose bare number is refused, 0 aside: it could be degrees or radians, rpm or rad/s.
NEEDS_ITS_UNIT = frozenset({"angle", *ANGULAR})


def bare_number(option: str, text: str, kind: Kind, value: float) -> InputError:
    """The refusal of a bare number for an angle, an angular velocity or an angular acceleration
    (one that is not finite, nan or 1e999, is refused as such: no unit would make it one)."""
    if not math.isfinite(value):
        return not_finite(option, text, kind)
    if kind.name == "angle":
        return bare_angle(option, text)
    number = text.strip() if _is_number(text.strip()) else f"{value:.6g}"
    if kind.name == "angular acceleration":
        return InputError(option, "expected an angular acceleration with its unit", example=f"{number}rpm/s or '{number} rad/s^2'",
                          got=f"{text!r}: a number alone could be rpm/s or rad/s²")
    return InputError(option, "expected an angular velocity with its unit", example=f"{number}rpm or {number}rad/s", got=f"{text!r}: a number alone could be rpm or rad/s")


def not_finite(option: str, text: str, kind: Kind) -> InputError:
    return InputError(option, f"expected a finite {kind.name}", example=kind.typed, got=f"{text!r}, which is not a finite number")


def bare_angle(option: str, text: str, value: float = 0.0) -> InputError:
    if not math.isfinite(value):
        return not_finite(option, text, KINDS["angle"])
    return InputError(option, "expected an angle with its unit", example="60deg or 1.05rad", got=f"{text!r}: a number alone could be degrees or radians")
