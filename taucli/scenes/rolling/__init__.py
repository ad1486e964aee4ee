"""A round body on an incline: rolling or slipping; a skidding ball on the flat until it rolls;
a body pulled on the flat or a slope, a spool pulled by its string, a yo-yo (solve_pull,
solve_yoyo, and solve_rolling_flat for a body rolling at v0).

One module per model; rolling() here picks one from what is given, solves it, and adds what it
assumed:

    body            the body and its k² = I/(mR²) (K2); the checks every model makes
    incline         rolling or slipping on a slope: to the bottom, or up to where it stops
    flat            a ball skidding on the flat until it rolls; a body rolling along at v0
    pull            a body pulled at a height above its centre; a spool pulled by its string
    yoyo            a yo-yo falling as its string unwinds
    point_on_body   a point of the body (--at), turning with it about its centre
"""

from __future__ import annotations

from taucli.errors import InputError
from taucli.report import Report
from taucli.scenes.assumed import Assumed
from taucli.scenes.rolling.body import K2, Roller, roller
from taucli.scenes.rolling.flat import solve_flat, solve_rolling_flat
from taucli.scenes.rolling.incline import solve_incline
from taucli.scenes.rolling.point_on_body import point_on_body
from taucli.scenes.rolling.pull import Pull, given_pull, solve_pull
from taucli.scenes.rolling.yoyo import solve_yoyo

__all__ = ["K2", "Pull", "Roller", "roller", "rolling", "solve_flat", "solve_incline", "solve_pull", "solve_rolling_flat", "solve_yoyo"]

NOT_WITH_YOYO = "does not apply with {yoyo} (a yo-yo falls on its string: {height} for the drop, {v0} to throw it down)"
NOT_WITH_PULL = "does not apply with {pull}: the pulled body starts from rest ({length} for the distance it moves)"


def rolling(
    *,
    shape: str | None = None,
    k2: float | None = None,
    inertia: float | None = None,
    mass: float | None = None,
    radius: float | None = None,
    angle: float | None = None,
    mu_s: float | None = None,
    mu_k: float | None = None,
    length: float | None = None,
    height: float | None = None,
    v0: float | None = None,
    omega0: float | None = None,
    pull: float | None = None,
    pull_height: float | None = None,
    pull_angle: float | None = None,
    axle_radius: float | None = None,
    yoyo: bool | None = None,
    g: float | None = None,
    at: float | str | None = None,
) -> Report:
    """``taucli rolling``: down (or up) an incline, or a ball skidding on the flat (--v0 or
    --omega0 with no slope, length or height) until it rolls; a body pulled (--pull), a spool
    (--axle-radius), a yo-yo (--yoyo); --at r, a point of the body at r from its centre."""
    if at is not None:
        report = rolling(shape=shape, k2=k2, inertia=inertia, mass=mass, radius=radius, angle=angle, mu_s=mu_s, mu_k=mu_k, length=length,
                         height=height, v0=v0, omega0=omega0, pull=pull, pull_height=pull_height, pull_angle=pull_angle,
                         axle_radius=axle_radius, yoyo=yoyo, g=g)
        return point_on_body(report, at, radius, v0 or 0.0, omega0, axle_radius if yoyo else radius)
    assumed = Assumed()
    if yoyo:
        body, about_axle = _yoyo_body(shape, k2, inertia, mass, radius, axle_radius)
        _refuse(NOT_WITH_YOYO, angle=angle, pull=pull, pull_height=pull_height, pull_angle=pull_angle, mu_s=mu_s, mu_k=mu_k, length=length,
                omega0=omega0)
        return assumed.applied(solve_yoyo(body, assumed.gravity(g), axle=axle_radius, height=height, v0=v0 or 0.0, about_axle=about_axle))
    body = roller(shape, k2, inertia, mass, radius)
    if pull is None and angle in (None, 0.0) and v0 is not None and omega0 is None and mu_k is None and length is None and height is None:
        return solve_rolling_flat(body, v0)  # rolling on the flat: gravity plays no part
    gravity = assumed.gravity(g)
    if pull is not None:
        _refuse(NOT_WITH_PULL, v0=v0, omega0=omega0, height=height)
        pulled = given_pull(pull, pull_angle, pull_height, axle_radius, assumed.notes)
        return assumed.applied(solve_pull(body, angle or 0.0, gravity, pulled, mu_s=mu_s, mu_k=mu_k, length=length))
    _needs_pull(pull_height=pull_height, pull_angle=pull_angle, axle_radius=axle_radius)
    if _set_moving_on_the_flat(angle, v0, omega0, length, height):
        return assumed.applied(solve_flat(body, gravity, mu_k=mu_k, v0=v0 or 0.0, omega0=omega0 or 0.0, mu_s=mu_s))
    slope = _slope(angle, omega0)
    return assumed.applied(solve_incline(body, slope, gravity, mu_s=mu_s, mu_k=mu_k, length=length, height=height, v0=v0 or 0.0))


def _yoyo_body(
    shape: str | None, k2: float | None, inertia: float | None, mass: float | None, radius: float | None, axle_radius: float | None
) -> tuple[Roller, float | None]:
    """The yo-yo's body, and the axle radius its k2 is already I/(m r²) about, if it is: a yo-yo
    needs only I/(m r²), so given I, m and r its outer radius plays no part (Halliday's
    950 g·cm², 120 g, r = 3.2 mm)."""
    if inertia is not None and radius is None and axle_radius is not None and mass is not None and shape is None and k2 is None:
        return Roller(inertia / (mass * axle_radius**2), "body", mass, None), axle_radius
    return roller(shape, k2, inertia, mass, radius), None


def _refuse(message: str, **options: float | None) -> None:
    """The first of ``options`` given (not None), refused with ``message``: the model has no use for it."""
    for name, value in options.items():
        if value is not None:
            raise InputError(name, message)


def _needs_pull(**options: float | None) -> None:
    """The pull's options, refused without --pull (--axle-radius is a yo-yo's too)."""
    for name, value in options.items():
        if value is not None:
            raise InputError(name, "needs {pull} (the force on the body" + (", or {yoyo}" if name == "axle_radius" else "") + ")", example="{pull} 10N")


def _set_moving_on_the_flat(angle: float | None, v0: float | None, omega0: float | None, length: float | None, height: float | None) -> bool:
    """A ball set moving on the flat (no slope; --v0 or --omega0): it skids, or rolls along. A
    distance down a slope has no place there."""
    flat = angle is None or angle == 0
    if flat and (v0 is not None or omega0 is not None) and (length is not None or height is not None):
        # #16 item 12: this once became a 0° incline from rest, silently setting --v0 aside
        raise InputError(
            "length" if length is not None else "height",
            "applies down a slope; on the flat a ball given {v0} or {omega0} skids (with {mu_k}) or rolls along, and no distance ends it",
            example="{angle} 10deg {length} 1m, or leave it out",
        )
    return flat and (v0 is not None or omega0 is not None)


def _slope(angle: float | None, omega0: float | None) -> float:
    """The incline's angle, which it needs; --omega0 belongs to a ball on the flat."""
    if angle is None:
        raise InputError("angle", "is required on an incline", example="{angle} 30deg")
    if omega0 is not None:
        raise InputError("omega0", "applies on the flat ({angle} 0 with {v0}): a skidding ball")
    return angle
