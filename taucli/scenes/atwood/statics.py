"""The tensions of a machine at rest: what statics fixes, and the bounds of what it does not.

Held, each block and the pulley balance with their static frictions within their limits,
and each string pulls (T ≥ 0):

    m1:      T1 = G1 + f1,            |f1| ≤ μs1 N1,   T1 ≥ 0
    m2:      T2 = G2 − f2,            |f2| ≤ μs2 N2,   T2 ≥ 0
    pulley:  T1 − ρ T2 = τd/r1 + u,   |u| ≤ τa/r1

(G each block's pull away from the pulley, ρ = a2/a). Each tension lies in the projection of
that polygon on its own axis: T1 ∈ I1 ∩ (Ia + ρ I2), T2 ∈ I2 ∩ (I1 − Ia)/ρ. Statics fixes a
tension where its interval is one point (one friction alone, or the frictions at their limits:
on the point of slipping); otherwise any value in it balances, and it is null with the bounds in
a note. An empty polygon is a machine that only a pushing string could hold: refused.
"""

from __future__ import annotations

from taucli.core.errors import InputError
from taucli.writing.report import fmt

EPSILON = 2.0**-52


def held_tensions(f, grips: tuple[float, float], notes: list[str]) -> tuple[float | None, float | None]:
    """T1 and T2 at rest for the machine's forces ``f`` (machine.Forces) and each block's
    static limit μs N (``grips``)."""
    rho, drive, axle = f.rho, f.drive_force, f.axle_force
    block1 = _clip(f.along1 - grips[0], f.along1 + grips[0])
    block2 = _clip(f.along2 - grips[1], f.along2 + grips[1])
    scale = abs(f.along1) + grips[0] + abs(rho) * (abs(f.along2) + grips[1]) + abs(drive) + axle
    # T1 − ρT2 within [drive − axle, drive + axle]
    across = _scaled(block2, rho)
    tension1 = _meet(block1, (drive - axle + across[0], drive + axle + across[1]), scale)
    tension2 = _meet(block2, _scaled((block1[0] - drive - axle, block1[1] - drive + axle), 1 / rho), scale / abs(rho))
    if tension1 is None or tension2 is None:
        raise InputError("the string", "goes slack at rest: only a string that pushes could hold the blocks where they are (a slack string is not modelled)")
    found = []
    for number, (low, high) in (("1", tension1), ("2", tension2)):
        if high - low <= 16 * EPSILON * (scale if number == "1" else scale / abs(rho)):
            found.append((low + high) / 2)
            continue
        found.append(None)
        shares = [what for what, there in (("at the axle", axle), ("under m1", grips[0]), ("under m2", grips[1])) if there]
        notes.append(
            f"T{number}: statically indeterminate: friction {' and '.join(shares)} share the load in a way statics cannot fix; "
            f"it lies between {fmt(low, 6)} and {fmt(high, 6)} N"
        )
    return found[0], found[1]


def _clip(low: float, high: float) -> tuple[float, float]:
    """A tension's interval, where a string can only pull."""
    return max(low, 0.0), high


def _scaled(interval: tuple[float, float], factor: float) -> tuple[float, float]:
    low, high = interval[0] * factor, interval[1] * factor
    return (low, high) if factor >= 0 else (high, low)


def _meet(first: tuple[float, float], second: tuple[float, float], scale: float) -> tuple[float, float] | None:
    """The two intervals' overlap; ends crossed by rounding alone meet in their middle; None where they do not meet."""
    low, high = max(first[0], second[0]), min(first[1], second[1])
    if low <= high:
        return low, high
    if low - high <= 16 * EPSILON * scale:
        middle = (low + high) / 2
        return middle, middle
    return None
