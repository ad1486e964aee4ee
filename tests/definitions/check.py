"""The checker of tests/scenes/test_definitions.py: draw, solve, count what is refused, check what is accepted.

A definition holds where |got − want| ≤ REL · max(|got|, |want|, scale): scale 0 for a product or a
quotient, the largest term for a sum or a difference, 1 rad for an angle (test_definitions explains why).
And what several scenes share: a point at r on a turning body, a body, its brakes and faces.
"""

from __future__ import annotations

import math
import random
from collections import Counter

import taucli
from taucli.options import SCENES

REL = 1e-12

TWO_PI = 2 * math.pi

G0 = 9.80665

class Checker:
    """Holds one scene's checks: how often each definition was checked, and what disagreed."""

    def __init__(self, scene: str):
        self.scene = scene
        self.checked: Counter[str] = Counter()
        self.failures: list[str] = []
        self.call = ""

    def eq(self, name: str, got, want, *scale: float, rel: float = REL) -> None:
        """got agrees with want to ``rel`` of the largest of |got|, |want| and the scales; skipped where either is null."""
        if got is None or want is None:
            return
        self.checked[name] += 1
        bound = rel * max(abs(got), abs(want), *(abs(s) for s in scale if s is not None and math.isfinite(s)))
        if not abs(got - want) <= bound:
            self.failures.append(f"{name}: got {got!r}, definition gives {want!r} (|diff| {abs(got - want):.3g} > {bound:.3g})\n    {self.call}")

    def true(self, name: str, condition: bool, detail: str = "") -> None:
        self.checked[name] += 1
        if not condition:
            self.failures.append(f"{name}: does not hold {detail}\n    {self.call}")

def values(report) -> dict:
    return {key: value.value for key, value in report.results.items()}

def inputs(report) -> dict:
    return {key: value.value for key, value in report.inputs.items()}

def call_text(function: str, kw: dict) -> str:
    args = [repr(kw["shape"])] if function in ("inertia", "rolling") and "shape" in kw else []
    args += [f"{key}={value!r}" for key, value in kw.items() if not (key == "shape" and args)]
    return f"taucli.{function}({', '.join(args)})"

def run_scene(function: str, draw, check, draws: int, seed: int, least_share: float, branches: dict[str, int], known=()) -> tuple[int, Checker]:
    """Draw ``draws`` keyword sets, solve each, check each accepted report; every branch named in
    ``branches`` must be reached that many times among the accepted; a share ``least_share`` of
    the draws must be accepted. Returns (accepted, checker)."""
    rng = random.Random(seed)
    scene = getattr(taucli, function)
    checker = Checker(function)
    accepted = refused = skipped = 0
    reached: Counter[str] = Counter()
    for _ in range(draws):
        kw, tags = draw(rng)
        if rng.random() < 0.2 and as_text(function, kw, rng):
            tags = [*tags, "units"]
        if any(predicate(kw) for predicate in known):
            skipped += 1
            continue
        checker.call = call_text(function, kw)
        try:
            report = scene(**kw)
        except taucli.InputError:
            refused += 1
            continue
        accepted += 1
        reached.update(tags)
        check(kw, report, checker)
    if checker.failures:
        shown, per_name = [], Counter()
        for failure in checker.failures:  # two of each definition, at most 30 in all
            name = failure.partition(":")[0]
            per_name[name] += 1
            if per_name[name] <= 2 and len(shown) < 30:
                shown.append(failure)
        raise AssertionError(f"{len(checker.failures)} disagreements in {function} ({dict(per_name)}):\n" + "\n".join(shown))
    assert accepted >= least_share * (draws - skipped), f"{function}: only {accepted} of {draws - skipped} draws accepted ({refused} refused)"
    short = {tag: (reached[tag], least) for tag, least in branches.items() if reached[tag] < least}
    assert not short, f"{function}: branches reached too seldom (reached, wanted): {short}"
    return accepted, checker

UNITS = {  # a kind of quantity: a unit other than its SI one, and how many of it make the SI unit
    "mass": ("g", 1e3), "length": ("cm", 1e2), "time": ("ms", 1e3), "angle": ("deg", 180 / math.pi), "angular velocity": ("rpm", 30 / math.pi),
    "angular acceleration": ("rev/s^2", 0.5 / math.pi), "torque": ("N*cm", 1e2), "force": ("kN", 1e-3), "moment of inertia": ("g*cm^2", 1e7),
    "energy": ("kJ", 1e-3), "power": ("kW", 1e-3), "velocity": ("km/h", 3.6), "acceleration": ("cm/s^2", 1e2),
}

def as_text(function: str, kw: dict, rng: random.Random) -> bool:
    """One of the draw's numbers written as a text in another unit, as a user types it (the checks
    read the values back from the report's echo of its inputs, in SI)."""
    table = SCENES[function.replace("_", "-")]
    names = [name for name, value in kw.items() if isinstance(value, float) and table.option(name) is not None and table.option(name).kind in UNITS]
    if not names:
        return False
    name = rng.choice(names)
    unit, factor = UNITS[table.option(name).kind]
    kw[name] = f"{kw[name] * factor!r} {unit}"
    return True

def mag(rng: random.Random, low: float, high: float) -> float:
    """A size 10^u, u uniform in [low, high]."""
    return 10 ** rng.uniform(low, high)

def signed(rng: random.Random, size: float, negative: float = 0.3) -> float:
    return -size if rng.random() < negative else size

def spec(**fields) -> str:
    """A spec text, "force=12.5N mu=0.4", from (value, unit) pairs or words."""
    out = []
    for key, value in fields.items():
        key = key.replace("_", "-")
        if isinstance(value, tuple):
            number, unit = value
            out.append(f"{key}={number!r}{unit}")
        else:
            out.append(f"{key}={value}")
    return " ".join(out)

def _along(alpha: float, omega: float) -> float:
    """α along the motion: as is while ω > 0, reversed while ω < 0; from rest the body sets off
    along α, so it speeds up: |α| (#32: a_t was −1, a_angle −π/2, under a negative torque from rest)."""
    return alpha if omega > 0 else -alpha if omega < 0 else abs(alpha)


def point_checks(c: Checker, res: dict, r: float, omega, alpha, theta, *, start=None, prefix: str = "") -> None:
    """v_t = |ω|r, a_c = ω²r, a_t = ±αr along the motion, a_total, a_angle, s = rθ; and at the start
    (``start`` = (ω₀, α₀)) v_t0, a_c0, a_total0, a_angle0."""
    if omega is not None:
        c.eq(prefix + "v_t = |ω| r", res.get("v_t"), abs(omega) * r)
        c.eq(prefix + "a_c = ω² r", res.get("a_c"), omega * omega * r)
        if alpha is not None:
            a_t = _along(alpha, omega) * r
            c.eq(prefix + "a_t = ±α r along the motion", res.get("a_t"), a_t)
    if res.get("a_t") is not None and res.get("a_c") is not None:
        c.eq(prefix + "a_total = √(a_t² + a_c²)", res.get("a_total"), math.hypot(res["a_t"], res["a_c"]))
        if res.get("a_angle") is not None:
            c.eq(prefix + "a_angle = atan2(a_t, a_c)", res["a_angle"], math.atan2(res["a_t"], res["a_c"]), 1.0)
    if theta is not None:
        c.eq(prefix + "s = r θ", res.get("s"), r * theta)
    if start is not None:
        omega0, alpha0 = start
        c.eq(prefix + "v_t0 = |ω₀| r", res.get("v_t0"), abs(omega0) * r)
        c.eq(prefix + "a_c0 = ω₀² r", res.get("a_c0"), omega0 * omega0 * r)
        if alpha0 is not None:
            a_t0 = _along(alpha0, omega0) * r
            c.eq(prefix + "a_total0 = √(a_t0² + a_c0²)", res.get("a_total0"), math.hypot(a_t0, omega0 * omega0 * r))
            if res.get("a_angle0") is not None:
                c.eq(prefix + "a_angle0 = atan2(a_t0, a_c0)", res["a_angle0"], math.atan2(a_t0, omega0 * omega0 * r), 1.0)

def draw_body(rng: random.Random, kw: dict, *, shapes=("disc", "ring", "tube", "parts")) -> tuple[float, float | None]:
    """A body for spin-down, impulse, pendulum or gyro: --inertia, or a shape (with a part); its
    rough I (for the scale of the torques) and its rim's radius where it has one."""
    if rng.random() < 0.4:
        inertia = mag(rng, -2, 2)
        kw["inertia"] = inertia
        return inertia, None
    mass, radius = mag(rng, -1, 2), mag(rng, -1.5, 0.5)
    shape = rng.choice(shapes)
    if shape == "ring":
        kw.update(shape="ring", mass=mass, radius=radius)
        return mass * radius * radius, radius
    if shape == "tube":
        inner = radius * rng.uniform(0.1, 0.9)
        kw.update(shape="tube", mass=mass, inner_radius=inner, outer_radius=radius)
        return mass * (inner * inner + radius * radius) / 2, radius
    kw.update(shape="disc", mass=mass, radius=radius)
    inertia = mass * radius * radius / 2
    if shape == "parts":
        small, offset = mass * mag(rng, -1.5, 0), radius * rng.uniform(0.2, 1.0)
        kw["part"] = ["point " + spec(mass=(small, "kg"), offset=(offset, "m"))]
        inertia += small * offset * offset
    return inertia, radius

def total_mass(inp: dict) -> float | None:
    """The body's mass with its parts' (from the inputs' echo), None where no mass is given."""
    if inp.get("mass") is None:
        return None
    return math.fsum([inp["mass"], *(value for key, value in inp.items() if key.startswith("part") and key.endswith("_mass"))])

def rim_of(inp: dict) -> float | None:
    return inp.get("radius", inp.get("outer_radius"))

def contact_torques(inp: dict, kw: dict, rim: float | None, weight_mass: float | None, g: float) -> tuple[float, float]:
    """The brakes' μ·N·r and the faces' (2/3)μF(Ro³ − Ri³)/(Ro² − Ri²) or μF(Ro + Ri)/2 per surface, from the inputs' echo."""
    brake = face = 0.0
    for n in range(1, len(kw.get("brake") or ()) + 1):
        key = f"brake{n}_"
        mu = inp.get(key + "mu", inp.get(key + "mu_k"))
        normal = inp[key + "force"]
        if key + "lever" in inp:  # a block brake: moments about the lever's pivot, F ℓ + μN c = N x
            normal = inp[key + "force"] * inp[key + "lever"] / (inp[key + "pivot"] - mu * inp.get(key + "offset", 0.0))
        brake += mu * normal * inp.get(key + "radius", rim)
    for n, text in enumerate(kw.get("face") or (), start=1):
        key = f"face{n}_"
        mu = inp.get(key + "mu", inp.get(key + "mu_k"))
        force = inp.get(key + "force", None if weight_mass is None else weight_mass * g)
        if key + "outer_radius" in inp:
            inner, outer = inp.get(key + "inner_radius", 0.0), inp[key + "outer_radius"]
        elif kw.get("shape") == "ring":
            inner = outer = rim
        else:
            inner, outer = inp.get("inner_radius", 0.0), rim
        wear = "pressure=wear" in text or "model=wear" in text
        if key + "pmax" in inp:  # the clamp force: ∫p dA, p = p_max (uniform) or p_max Ri/r (worn in)
            p = inp[key + "pmax"]
            force = 2 * math.pi * p * inner * (outer - inner) if wear else math.pi * p * (outer * outer - inner * inner)
        if wear:
            lever = (outer + inner) / 2
        else:
            lever = 2 * (outer ** 3 - inner ** 3) / (3 * (outer * outer - inner * inner)) if outer != inner else outer
        face += mu * force * lever * inp.get(key + "surfaces", 1)
    return brake, face

def band_torque(inp: dict, kw: dict, rim: float | None) -> float:
    """A band brake's (T₁ − T₂) r with T₁ = T₂ e^{μθ}, its tensions from the lever's moments about
    its pivot (F ℓ = T₂ b − T₁ a; an end not on the lever is at the pivot), from the inputs' echo."""
    total = 0.0
    for n in range(1, len(kw.get("band") or ()) + 1):
        key = f"band{n}_"
        mu, wrap = inp.get(key + "mu", inp.get(key + "mu_k")), inp[key + "wrap"]
        ratio = math.exp(mu * wrap)
        moment = inp.get(key + "force", 0.0) * inp.get(key + "lever", 0.0)
        if key + "tension" in inp:
            slack = inp[key + "tension"]
        elif key + "slack_arm" not in inp:  # the tight end alone on the lever, the slack end at the pivot: F ℓ = T₁ a
            slack = moment / inp[key + "tight_arm"] / ratio
        else:  # the slack end on F's side, the tight end (if on the lever) on the other: F ℓ = T₂ b − T₁ a
            slack = moment / (inp[key + "slack_arm"] - ratio * inp.get(key + "tight_arm", 0.0))
        total += (ratio * slack - slack) * inp.get(key + "radius", rim)
    return total

BODY_KEYS = ("inertia", "shape", "mass", "radius", "inner_radius", "outer_radius", "length", "width", "height", "depth", "axis", "offset", "part")

def body_moment(kw: dict, inp: dict | None = None) -> float:
    """The body's moment of inertia as taucli inertia gives it (its definition is tested there);
    a given one from the report's echo ``inp`` where there is one."""
    body = {key: kw[key] for key in BODY_KEYS if key in kw}
    if "shape" not in body:
        return body["inertia"] if inp is None else inp["inertia"]
    return taucli.inertia(body.pop("shape"), **body).results["I"].value
