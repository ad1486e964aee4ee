"""Values from Python as the readers take them (the Python API's scenes and taucli.fit.fit): a
numpy scalar or 0-d array as its number, an array as a list, a number wider than a double as a
float where one holds it. numpy is never imported here: its values are known by their module.
"""

from __future__ import annotations

import math
import numbers

from taucli.core.errors import InputError


def plain(value, name: str):
    """A value as Python's own types hold it: a numpy scalar or 0-d array as its number
    (np.int64(4) -> 4), an array as a list (np.array([1., 2., 3.]) -> a 3-vector), inside lists
    and tuples too. numpy is not imported: its values are known by their module. A whole number
    past a double's range (10**400) is refused here, before any message would write its digits."""
    if type(value).__module__.partition(".")[0] == "numpy" and callable(getattr(value, "tolist", None)):
        value = value.tolist()
    if type(value).__module__.partition(".")[0] == "numpy":  # a longdouble or clongdouble, which tolist() leaves as it is
        value = _wider(value, name)
    if isinstance(value, int) and value.bit_length() > 1024:
        digits = int(value.bit_length() * math.log10(2)) + 1
        raise InputError(name, "expected a number a double holds (at most about 1.8e308 in size)", got=f"a whole number of about {digits} digits")
    if type(value) in (list, tuple):
        return type(value)(plain(item, name) for item in value)
    if isinstance(value, (dict, set, frozenset)):  # refused by the readers, whose messages quote them: no 10**5000 inside
        for item in (*value, *(value.values() if isinstance(value, dict) else ())):
            plain(item, name)
    return value


def _wider(value, name: str):
    """A numpy number wider than a double (longdouble, clongdouble) as Python's own: a float where
    a double holds it, a complex (refused by the readers as any complex is); one past a double's
    range, or nonzero and below it, refused here rather than read as inf or 0."""
    if isinstance(value, numbers.Complex) and not isinstance(value, numbers.Real):
        return complex(value)
    if not isinstance(value, numbers.Real):
        return value
    number = float(value)
    if value == value and (math.isinf(number) != (abs(value) == math.inf) or (number == 0 and value != 0)):
        raise InputError(name, "expected a number a double holds (about 1e-308 to 1.8e308 in size, or 0)", got=f"{value!r} ({type(value).__name__})")
    return number
