"""pendulum: the draws (a body of given I or a shape, gravity and a spring, each method) and the definitions."""

from __future__ import annotations

import math
import random

from definitions.check import (
    G0,
    TWO_PI,
    Checker,
    inputs,
    mag,
    signed,
    spec,
    total_mass,
    values,
)


def draw_pendulum(rng: random.Random) -> tuple[dict, list[str]]:
    """A body on a pivot: given I, m and d, or a shape about an axis off its centre (with parts);
    gravity, a torsion spring or both; a start anywhere (over the top too); --angle, --time,
    --at; each method."""
    kw: dict = {}
    tags = []
    mass, size = mag(rng, -1, 1.5), mag(rng, -1.5, 0.5)
    x = rng.random()
    if x < 0.35:
        d = size * rng.uniform(0, 1) if rng.random() < 0.9 else 0.0
        kw.update(inertia=mass * (d * d + size * size * rng.uniform(0.01, 1)), mass=mass, cm_distance=d)
        tags.append("inertia")
    elif x < 0.55:
        kw.update(shape="rod", mass=mass, length=size, axis="end")
        tags.append("rod")
    elif x < 0.7:
        kw.update(shape="disc", mass=mass, radius=size, offset=size * rng.uniform(0, 1.5))
        tags.append("disc")
    elif x < 0.85:
        kw.update(shape="point", mass=mass, radius=size)
        if rng.random() < 0.5:
            kw["part"] = ["point " + spec(mass=(mass * mag(rng, -1, 0.5), "kg"), offset=(size * rng.uniform(0.1, 2), "m"))]
        tags.append("point")
    else:
        kw.update(shape="plate", mass=mass, width=size, height=size * mag(rng, -0.5, 0.5), axis="edge-height")
        tags.append("plate")
    gravity_torque = mass * G0 * size
    if rng.random() < 0.3 or kw.get("cm_distance") == 0:
        kw["torsion"] = gravity_torque * mag(rng, -1.5, 1)
        tags.append("torsion")
    if rng.random() < 0.15:
        kw["g"] = rng.uniform(1, 25)
    y = rng.random()
    if y < 0.15:
        kw["angle0"] = math.pi * rng.choice((1, -1))
        tags.append("at the top")
    elif y < 0.9:
        kw["angle0"] = rng.uniform(-math.pi, math.pi)
    if rng.random() < 0.5:
        kw["omega0"] = signed(rng, math.sqrt(G0 / size) * mag(rng, -1, 0.5), 0.5)
    if rng.random() < 0.15:  # #34: from the bottom at a given speed
        kw.pop("angle0", None)
        kw["omega_bottom"] = kw.pop("omega0", None) or signed(rng, math.sqrt(G0 / size) * mag(rng, -1, 0.5), 0.5)
        tags.append("omega_bottom")
    elif "torsion" not in kw and rng.random() < 0.2:  # #34: angles from the top
        kw["from_top"] = True
        tags.append("from the top")
    if rng.random() < 0.5:
        kw["components"] = True
        tags.append("components")
    if rng.random() < 0.4:
        kw["angle"] = rng.uniform(-math.pi, math.pi)
        tags.append("angle")
    if rng.random() < 0.4:
        kw["time"] = math.sqrt(size / G0) * mag(rng, -1, 1)
        tags.append("time")
    if rng.random() < 0.3:
        kw["at"] = size * rng.uniform(0, 2)
        tags.append("at")
    if rng.random() < 0.2:
        kw["method"] = rng.choice(("exact", "small-angle", "euler", "rk4", "rk45", "verlet"))
        tags.append("method " + kw["method"])
    return kw, tags

def check_pendulum(kw: dict, report, c: Checker) -> None:
    res, inp = values(report), inputs(report)
    g = inp.get("g", G0)
    inertia = res["I"]
    m = total_mass(inp)
    d = res.get("cm_distance", inp.get("cm_distance", 0.0))
    kappa = inp.get("torsion", 0.0)
    G = (m or 0.0) * g * d  # gravity's torque at 90°
    theta0, omega0 = inp.get("angle0", 0.0), inp.get("omega0", 0.0)
    top = bool(kw.get("from_top"))  # a flag: not echoed among the inputs
    # angles from the top (gravity alone): φ is the same place as θ = φ ± 180° from the bottom
    # (the one in [−180°, 180°], so that φ = ±180° is the bottom exactly), which every formula below
    # takes; the horizontal's sense turns with the zero
    def bottom_angle(phi):
        return phi if not top else phi - math.pi if phi > 0 else phi + math.pi

    theta0 = bottom_angle(theta0)
    if "omega_bottom" in inp:
        theta0, omega0 = 0.0, inp["omega_bottom"]

    def potential(theta):  # U(θ) = mgd(1 − cos θ) + ½κθ²
        return 2 * G * math.sin(theta / 2) ** 2 + kappa * theta * theta / 2

    def accel(theta):  # α(θ) = −(mgd sin θ + κθ)/I
        return -(G * (0.0 if abs(theta) == math.pi else math.sin(theta)) + kappa * theta) / inertia

    energy = inertia * omega0 * omega0 / 2 + potential(theta0)
    c.eq("period_small = 2π√(I/(mgd + κ))", res.get("period_small"), TWO_PI * math.sqrt(inertia / (G + kappa)))
    if m and d:
        c.eq("equivalent_length = I/(md)", res.get("equivalent_length"), inertia / (m * d))
        c.eq("centre_of_percussion = I/(md)", res.get("centre_of_percussion"), inertia / (m * d))
    c.eq("alpha0 = |mgd sin θ₀ + κθ₀|/I", res.get("alpha0"), abs(accel(theta0)))
    if res.get("omega_bottom") is not None:
        c.eq("½Iω_bottom² = ½Iω₀² + U(θ₀)", inertia * res["omega_bottom"] ** 2 / 2, energy)
    if inp.get("angle") is not None and res.get("omega") is not None:
        c.eq("½Iω² + U(θ) = ½Iω₀² + U(θ₀) at --angle", inertia * res["omega"] ** 2 / 2 + potential(bottom_angle(inp["angle"])), energy, potential(bottom_angle(inp["angle"])))
    if G:
        rise = potential(math.pi) - potential(theta0)
        c.eq("½Iω_over² = U(180°) − U(θ₀)", inertia * res["omega0_over"] ** 2 / 2, max(rise, 0.0), potential(math.pi), potential(theta0))
        if not kappa:
            c.true("goes_over ⇔ |ω₀| > omega0_over (gravity alone)", res["goes_over"] == (abs(omega0) > res["omega0_over"]),
                   f"goes_over {res['goes_over']}, ω₀ {omega0}, ω_over {res['omega0_over']}")
    if m is not None and res.get("pivot_force0") is not None:
        def pivot(theta, speed):
            return m * math.hypot(d * speed * speed + g * math.cos(theta), d * accel(theta) + g * (0.0 if abs(theta) == math.pi else math.sin(theta)))
        scale = m * (g + d * abs(accel(theta0)) + d * omega0 * omega0)
        c.eq("pivot force at the start = m|a_cm − g|", res["pivot_force0"], pivot(theta0, abs(omega0)), scale)
        if res.get("omega_bottom") is not None:
            c.eq("pivot force at the bottom = m|a_cm − g|", res.get("pivot_force_bottom"), pivot(0.0, res["omega_bottom"]), m * g)
    # #34 item 5: the swing's reach
    if res.get("KE_bottom") is not None and res.get("omega_bottom") is not None:
        c.eq("KE_bottom = ½Iω_b²", res["KE_bottom"], inertia * res["omega_bottom"] ** 2 / 2)
    if res.get("amplitude") is not None and (omega0 or accel(theta0)):
        amp = bottom_angle(res["amplitude"])
        c.eq("U(θₐ) = ½Iω₀² + U(θ₀): it turns where its kinetic energy is spent", potential(amp), energy, energy, G * abs(math.sin(amp)))
        if G and res.get("rise") is not None:
            c.eq("rise = d(cos θ₀ − cos θₐ)", res["rise"], d * (math.cos(theta0) - math.cos(amp)), d)
            if not kappa:
                c.eq("m g rise = ½Iω₀² (gravity alone)", (m or 0.0) * g * res["rise"], inertia * omega0 * omega0 / 2)
    # #34 item 6: the pivot's force as components, from the centre of mass's x'' and y''
    if m is not None and d and res.get("pivot_radial0") is not None:
        def components(theta, w):
            a = accel(theta)
            fx = m * d * (a * math.cos(theta) - w * w * math.sin(theta))
            fy = m * d * (a * math.sin(theta) + w * w * math.cos(theta)) + m * g
            return (-fx * math.sin(theta) + fy * math.cos(theta), fx * math.cos(theta) + fy * math.sin(theta), -fx if top else fx, fy)
        places = [("0", theta0, omega0), ("_bottom", 0.0, res.get("omega_bottom"))]
        if inp.get("angle") is not None:
            places.append(("", bottom_angle(inp["angle"]), res.get("omega")))
        for suffix, theta, w in places:
            if w is None or res.get("pivot_radial" + suffix) is None:
                continue
            scale = m * (g + d * abs(accel(theta)) + d * w * w)
            for name, want in zip(("radial", "tangential", "horizontal", "vertical"), components(theta, w)):
                c.eq(f"pivot_{name}{suffix} = m a_cm − m g, resolved", res["pivot_" + name + suffix], want, scale)
    exact = report.method.startswith("closed form")
    small = kw.get("method") == "small-angle"
    if inp.get("time") is not None and res.get("theta") is not None and res.get("omega") is not None and inp.get("angle") is None:
        theta, omega = res["theta"], res["omega"]
        if small:
            harmonic = lambda th, w: inertia * w * w / 2 + (G + kappa) * th * th / 2
            c.eq("small-angle: ½Iω² + ½(mgd + κ)θ² kept at --time", harmonic(theta, omega), harmonic(theta0, omega0))
        elif exact:
            c.eq("½Iω² + U(θ) kept at --time (exact)", inertia * omega * omega / 2 + potential(bottom_angle(theta)), energy, potential(bottom_angle(theta)), G)
    if exact and not G and kappa and res.get("period") is not None:
        c.eq("a torsion pendulum's period 2π√(I/κ)", res["period"], TWO_PI * math.sqrt(inertia / kappa))
    if small and res.get("period") is not None:
        c.eq("small-angle period = period_small", res["period"], res["period_small"])
    if inp.get("at") is not None:
        r = inp["at"]
        c.eq("a_t0 = r α₀ along the motion", res.get("a_t0"), r * _along(accel(theta0), omega0))
        if inp.get("angle") is not None and res.get("omega") is not None:  # ω at --angle signed, as the body first gets there
            c.eq("v_t = r |ω| at --angle", res.get("v_t"), r * abs(res["omega"]))
            c.eq("a_t = r α along the motion at --angle", res.get("a_t"), r * _along(accel(bottom_angle(inp["angle"])), res["omega"]))
            c.eq("a_c = r ω² at --angle", res.get("a_c"), r * res["omega"] ** 2)


def _along(alpha: float, omega: float) -> float:
    """α along the motion (taucli.scenes.point): negative while the body slows; from rest, |α|."""
    return alpha if omega > 0 else -alpha if omega < 0 else abs(alpha)
