"""A round body on an incline: rolling or slipping; a skidding ball on the flat until it rolls;
a body pulled on the flat or a slope, a spool pulled by its string, a yo-yo, a yo-yo spun in
place, a body joined to a hanging mass over a pulley (solve_pull, solve_yoyo, solve_in_place,
solve_hanging, and solve_rolling_flat for a body rolling at v0).

One module per model; rolling() here picks one from what is given, solves it, and adds what it
assumed:

    body            the body and its k² = I/(mR²) (K2); the checks every model makes
    incline         rolling or slipping on a slope: to the bottom, or up to where it stops
    flat            a ball skidding on the flat until it rolls; a body rolling along at v0
    pull            a body pulled at a height above its centre; a spool pulled by its string
    hanging         a body joined by a string over a pulley to a hanging mass
    yoyo            a yo-yo falling as its string unwinds
    drum            a yo-yo whose string is wound at its top on a drum that turns
    in_place        a yo-yo whose string is pulled so that it spins in place
    point_on_body   a point of the body (--at): about its centre, or on its rim seen from the ground (ground_point)
"""

from __future__ import annotations

from taucli.core.errors import InputError
from taucli.writing.report import Report
from taucli.scenes.assumed import Assumed
from taucli.scenes.rolling.body import K2, Roller, roller
from taucli.scenes.rolling.drum import Drum, given_drum, solve_yoyo_on_drum
from taucli.scenes.rolling.flat import solve_flat, solve_rolling_flat
from taucli.scenes.rolling.hanging import Hanging, given_hanging, solve_hanging
from taucli.scenes.rolling.in_place import solve_in_place
from taucli.scenes.rolling.incline import solve_incline
from taucli.scenes.rolling.point_on_body import motion, point_on_body
from taucli.scenes.rolling.pull import Pull, given_pull, solve_pull
from taucli.scenes.rolling.yoyo import YoyoPull, solve_yoyo

__all__ = ["K2", "Drum", "Hanging", "Pull", "Roller", "roller", "rolling", "solve_flat", "solve_hanging", "solve_in_place", "solve_incline", "solve_pull",
           "solve_rolling_flat", "solve_yoyo", "solve_yoyo_on_drum"]

NOT_WITH_YOYO = ("does not apply with {yoyo} (a yo-yo falls on its string: {height} or {time} for the run, {v0} to throw it down, "
                 "{pull} with {pull_at} for a vertical pull on it besides its string)")
ONLY_YOYO = "applies with {yoyo} (a yo-yo on its string; a pulled body on the flat or a slope moves {length})"
NOT_IN_PLACE = "does not apply with {in_place} (its centre stays put: {length} for the string the hand pulls, {omega0} for the spin at the start)"
NOT_WITH_PULL = "does not apply with {pull}: the pulled body starts from rest ({length} for the distance it moves)"
NOT_WITH_HANGING = "does not apply with {hanging_mass}: the body starts from rest, on the flat or a slope ({length} for the distance it moves)"


def rolling(
    *,
    shape: str | None = None,
    k2: float | None = None,
    inertia: float | None = None,
    gyration: float | None = None,
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
    pull_at: float | None = None,
    yoyo: bool | None = None,
    in_place: bool | None = None,
    hanging_mass: float | None = None,
    string: str | None = None,
    pulley_mass: float | None = None,
    pulley_radius: float | None = None,
    g: float | None = None,
    time: float | None = None,
    at: object = None,
    drum_mass: float | None = None,
    drum_inertia: float | None = None,
    drum_radius: float | None = None,
    drum_friction: float | None = None,
) -> Report:
    """``taucli rolling``: down (or up) an incline, or a ball skidding on the flat (--v0 or
    --omega0 with no slope, length or height) until it rolls; a body pulled (--pull), a spool
    (--axle-radius), a yo-yo (--yoyo), one spun in place (--in-place), a body joined to a hanging
    mass (--hanging-mass); --at r, a point of the body at r from its centre, or --at top, bottom,
    front, back or an angle (a Value in radians), a point on its rim seen from the ground.
    --gyration k with --radius R is the body's k² = I/(mR²) = (k/R)². A yo-yo's string may be wound
    at its top on a drum that turns (--drum-mass or --drum-inertia, --drum-radius, --drum-friction)."""
    if gyration is not None:  # #42 item 15: the body by its radius of gyration
        k2 = _by_gyration(gyration, radius, shape, k2, inertia)
    drum = {"drum_mass": drum_mass, "drum_inertia": drum_inertia, "drum_radius": drum_radius, "drum_friction": drum_friction}
    if not yoyo:
        _refuse(ONLY_YOYO, pull_at=pull_at, time=time, **drum)
    if in_place:
        _refuse(NOT_IN_PLACE, **drum)
    model, report = _solve(shape, k2, inertia, mass, radius, angle, mu_s, mu_k, length, height, v0, omega0, pull, pull_height, pull_angle,
                           axle_radius, yoyo, in_place, hanging_mass, string, pulley_mass, pulley_radius, g, pull_at, time, given_drum(**drum))
    if at is None:
        return report
    body = motion(model, report, v0=v0, omega0=omega0, radius=radius, axle=axle_radius, slope=angle)
    return point_on_body(report, at, radius, body)


def _solve(shape, k2, inertia, mass, radius, angle, mu_s, mu_k, length, height, v0, omega0, pull, pull_height, pull_angle, axle_radius, yoyo,
           in_place, hanging_mass, string, pulley_mass, pulley_radius, g, pull_at=None, time=None, drum=None) -> tuple[str, Report]:
    """The model the options ask for, by name (as point_on_body.motion reads it), and its report."""
    assumed = Assumed()
    hanging = {"hanging_mass": hanging_mass, "string": string, "pulley_mass": pulley_mass, "pulley_radius": pulley_radius}
    if in_place:
        _refuse(NOT_IN_PLACE, angle=angle, pull=pull, pull_height=pull_height, pull_angle=pull_angle, mu_s=mu_s, mu_k=mu_k, height=height, v0=v0,
                **hanging)
        description, gyration2, axle = _spun_body(shape, k2, inertia, mass, radius, axle_radius)
        return "in place", assumed.applied(solve_in_place(description, gyration2, mass, axle, assumed.gravity(g), omega0=omega0 or 0.0, length=length))
    if yoyo:
        body, about_axle = _yoyo_body(shape, k2, inertia, mass, radius, axle_radius)
        _refuse(NOT_WITH_YOYO, angle=angle, pull_height=pull_height, pull_angle=pull_angle, mu_s=mu_s, mu_k=mu_k, length=length,
                omega0=omega0, **hanging)
        if pull is None:
            _needs({"pull_at": pull_at}, "needs {pull} (the force whose line it places)", "{pull} 12N {pull_at} 0.1m")
        second = None if pull is None else YoyoPull(pull, pull_at or 0.0)
        if pull is not None and pull_at is None:
            assumed.notes.append("no --pull-at: the pull's line passes through the centre (a second string tied at the axle)")
        return "yoyo", assumed.applied(solve_yoyo(body, assumed.gravity(g), axle=axle_radius, height=height, v0=v0 or 0.0, about_axle=about_axle,
                                                  pull=second, time=time, drum=drum))
    body = roller(shape, k2, inertia, mass, radius)
    if hanging_mass is not None:
        _refuse(NOT_WITH_HANGING, pull=pull, pull_height=pull_height, pull_angle=pull_angle, axle_radius=axle_radius, v0=v0, omega0=omega0, height=height)
        joined = given_hanging(hanging_mass, string, pulley_mass, pulley_radius)
        return "hanging", assumed.applied(solve_hanging(body, angle or 0.0, assumed.gravity(g), joined, mu_s=mu_s, mu_k=mu_k, length=length))
    _needs(hanging, "needs {hanging_mass} (the mass the string holds)", "{hanging_mass} 1kg")
    if pull is None and angle in (None, 0.0) and v0 is not None and omega0 is None and mu_k is None and length is None and height is None:
        return "flat", solve_rolling_flat(body, v0)  # rolling on the flat: gravity plays no part
    gravity = assumed.gravity(g)
    if pull is not None:
        _refuse(NOT_WITH_PULL, v0=v0, omega0=omega0, height=height)
        pulled = given_pull(pull, pull_angle, pull_height, axle_radius, assumed.notes)
        return "pull", assumed.applied(solve_pull(body, angle or 0.0, gravity, pulled, mu_s=mu_s, mu_k=mu_k, length=length))
    _needs({"pull_height": pull_height, "pull_angle": pull_angle}, "needs {pull} (the force on the body)", "{pull} 10N")
    _needs({"axle_radius": axle_radius}, "needs {pull} (the force on the body, or {yoyo})", "{pull} 10N")
    if _set_moving_on_the_flat(angle, v0, omega0, length, height):
        return "skid", assumed.applied(solve_flat(body, gravity, mu_k=mu_k, v0=v0 or 0.0, omega0=omega0 or 0.0, mu_s=mu_s))
    slope = _slope(angle, omega0)
    return "incline", assumed.applied(solve_incline(body, slope, gravity, mu_s=mu_s, mu_k=mu_k, length=length, height=height, v0=v0 or 0.0))


def _spun_body(
    shape: str | None, k2: float | None, inertia: float | None, mass: float | None, radius: float | None, axle_radius: float | None
) -> tuple[str, float, float | None]:
    """A yo-yo spun in place: its description, I/m (all its spin needs), and the radius its string
    leaves from (the axle's, else the body's own; None where neither is given). Given I and m it
    needs no radius at all for ω, only for α and the hand's acceleration."""
    if radius is not None and axle_radius is not None and axle_radius > radius:
        raise InputError("axle_radius", "must lie within the body's radius", example="{axle_radius} 0.005m", got=f"{axle_radius:g} m > R = {radius:g} m")
    if inertia is not None and mass is not None and radius is None and shape is None and k2 is None:
        body, per_mass, axle = "body", inertia / mass, axle_radius
    else:
        found = roller(shape, k2, inertia, mass, radius)
        if found.radius is None:
            raise InputError("radius", "is required with {in_place} and a shape or {k2} (I/m = k² R²)", example="{radius} 0.03m")
        body, per_mass, axle = found.description, found.k2 * found.radius**2, axle_radius if axle_radius is not None else radius
    if per_mass == 0:
        raise InputError("k2" if k2 is not None else "inertia", "must be positive with {in_place}: with no rotational inertia the string "
                         "would spin the body up without limit (α = m g r/I)", example="{k2} 0.5")
    return body, per_mass, axle


def _yoyo_body(
    shape: str | None, k2: float | None, inertia: float | None, mass: float | None, radius: float | None, axle_radius: float | None
) -> tuple[Roller, float | None]:
    """The yo-yo's body, and the axle radius its k2 is already I/(m r²) about, if it is: a yo-yo
    needs only I/(m r²), so given I, m and r its outer radius plays no part (Halliday's
    950 g·cm², 120 g, r = 3.2 mm)."""
    if inertia is not None and radius is None and axle_radius is not None and mass is not None and shape is None and k2 is None:
        return Roller(inertia / (mass * axle_radius**2), "body", mass, None), axle_radius
    return roller(shape, k2, inertia, mass, radius), None


def _by_gyration(gyration: float, radius: float | None, shape: str | None, k2: float | None, inertia: float | None) -> float:
    """k² = I/(mR²) = (k/R)² of a body of radius of gyration k rolling on radius R."""
    for name, value in (("shape", shape), ("k2", k2), ("inertia", inertia)):
        if value is not None:
            raise InputError("gyration", f"conflicts with {{{name}}}: describe the body once")
    if radius is None:
        raise InputError("radius", "is required with {gyration} (the body's I/(mR²) is (k/R)²)", example="{gyration} 0.07m {radius} 0.1m")
    return (gyration / radius) ** 2


def _refuse(message: str, **options: float | None) -> None:
    """The first of ``options`` given (not None), refused with ``message``: the model has no use for it."""
    for name, value in options.items():
        if value is not None:
            raise InputError(name, message)


def _needs(options: dict, message: str, example: str) -> None:
    """The first of ``options`` given, refused with ``message``: it belongs to a model not asked for."""
    for name, value in options.items():
        if value is not None:
            raise InputError(name, message, example=example)


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
