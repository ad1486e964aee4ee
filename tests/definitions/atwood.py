"""atwood: the draws (hanging, a slope, a stepped pulley, a string that may slide) and the definitions."""

from __future__ import annotations

import math
import random

import taucli
from definitions.check import (
    G0,
    Checker,
    inputs,
    mag,
    point_checks,
    signed,
    spec,
    values,
)


def draw_atwood(rng: random.Random) -> tuple[dict, list[str]]:
    """An Atwood machine: hanging, m2 on a table or a slope, a stepped pulley, a string that may
    slide over the rim; a pulley massless, of a shape, of a given I or with parts; axle friction;
    the motion after a distance or at a time; a point on the pulley."""
    mode = rng.choice(("hanging", "hanging", "incline", "stepped", "rim"))
    tags = [mode]
    m1 = mag(rng, -1, 1.5)
    kw: dict = {"m1": m1}
    if rng.random() < 0.9:
        kw["m2"] = 0.0 if rng.random() < 0.08 else m1 * mag(rng, -1, 1)
    radius = mag(rng, -1.5, 0)
    if rng.random() < 0.65:
        kw["pulley_radius"] = radius
    x = rng.random()
    if x < 0.45:
        kw["pulley_mass"] = m1 * mag(rng, -1.5, 0.5)
        if rng.random() < 0.4:
            kw["pulley_shape"] = rng.choice(("disc", "ring"))
        tags.append("pulley mass")
    elif x < 0.7:
        kw["pulley_inertia"] = m1 * radius * radius * mag(rng, -1.5, 0.5)
        tags.append("pulley inertia")
    if rng.random() < 0.1:
        kw["part"] = ["ring " + spec(mass=(m1 * mag(rng, -2, 0), "kg"), radius=(radius * rng.uniform(0.2, 1), "m"))]
        tags.append("part")
    if mode != "rim" and rng.random() < 0.25:
        kw["axle_friction"] = m1 * G0 * radius * mag(rng, -2, -0.2)
        tags.append("axle friction")
    if mode == "incline":
        kw["incline"] = 0.0 if rng.random() < 0.2 else rng.uniform(0, math.pi / 2)
        if rng.random() < 0.7:
            kw["mu_k"] = rng.uniform(0, 0.8)
            tags.append("mu_k")
        if rng.random() < 0.5:
            kw["mu_s"] = kw.get("mu_k", 0.0) + rng.uniform(0, 0.4)
            tags.append("mu_s")
    elif mode == "stepped":
        kw["radius1"] = radius * mag(rng, -0.5, 0.3)
        if rng.random() < 0.8 or "pulley_radius" not in kw:
            kw["radius2"] = radius * mag(rng, -0.5, 0.3)
    elif mode == "rim":
        kw["rim_mu"] = rng.uniform(0, 0.3) if rng.random() < 0.6 else mag(rng, -3, 0)
        if rng.random() < 0.4:
            kw["wrap"] = rng.uniform(0.2, 2 * math.pi)
    if rng.random() < 0.2:
        kw["g"] = rng.uniform(1, 25)
    speed = math.sqrt(G0 * radius) * mag(rng, -1, 1)
    if rng.random() < 0.3:
        kw["v0"] = signed(rng, speed, 0.5)
        tags.append("v0")
    if rng.random() < 0.35:
        kw["distance"] = radius * mag(rng, -1, 1.5)
        tags.append("distance")
    if rng.random() < 0.35:
        kw["time"] = math.sqrt(radius / G0) * mag(rng, -1, 1)
        tags.append("time")
    if rng.random() < 0.3:
        kw["at"] = "rim" if rng.random() < 0.3 else radius * rng.uniform(0, 1.5)
        tags.append("at")
    return kw, tags

def check_atwood(kw: dict, report, c: Checker) -> None:
    res, inp = values(report), inputs(report)
    a = res.get("a")
    if a is None:
        return  # μk not given where it slides: nothing is known but that it moves
    g = inp.get("g", G0)
    m1, m2 = inp["m1"], inp.get("m2", 0.0)
    v0 = inp.get("v0", 0.0)
    stepped = "radius1" in inp or "radius2" in inp
    sliding_rim = res.get("grips") is False
    hanging = "incline" not in inp
    R = inp.get("pulley_radius")
    r1 = inp.get("radius1", R)
    r2 = inp.get("radius2", R)
    axle = inp.get("axle_friction", 0.0)
    a2 = res.get("a2", a)
    direction = (v0 > 0) - (v0 < 0) or (a > 0) - (a < 0)  # the way m1 moves at the start (down positive)
    moving = direction != 0
    sgn = lambda x: (x > 0) - (x < 0)

    # the pulley's inertia: a given I, or k·M·R² (k = ½ a disc, 1 a ring) at its radius (a stepped one's: its larger step), and ring parts m r²
    rim = R if R is not None else (max(r1, r2) if stepped else None)
    parts = math.fsum(inp.get(f"part{n}_mass", 0.0) * inp.get(f"part{n}_radius", 0.0) ** 2 for n in range(1, 4))
    if "pulley_inertia" in inp:
        moment = inp["pulley_inertia"] + parts
    elif rim is not None:
        moment = {"disc": 0.5, "ring": 1.0}[kw.get("pulley_shape", "disc")] * inp.get("pulley_mass", 0.0) * rim * rim + parts
    else:
        moment = None

    # Newton for each mass
    c.eq("T1 = m1(g − a)", res.get("T1"), m1 * (g - a), m1 * g, m1 * a)
    if hanging:
        if moving or not axle:
            c.eq("T2 = m2(g + a2), m2 hanging", res.get("T2"), m2 * (g + a2), m2 * g, m2 * a2)
    elif moving and inp.get("mu_k", 0.0 if "mu_s" not in inp else None) is not None:
        theta, mu_k = inp["incline"], inp.get("mu_k", 0.0)
        along, normal = m2 * g * math.sin(theta), m2 * g * math.cos(theta)
        c.eq("T2 = m2(a + g sin θ) + μk N sgn v", res.get("T2"), m2 * a + along + direction * mu_k * normal, m2 * a, along, mu_k * normal)
    # the pulley: the tensions' torque less the axle's turns it
    if not stepped and R is not None and not sliding_rim:
        c.eq("alpha = a/R", res.get("alpha"), a / R)
    if stepped:
        c.eq("a2 = a r2/r1", res.get("a2"), a * r2 / r1)
        c.eq("alpha = a/r1", res.get("alpha"), a / r1)
    if moving and moment is not None and res.get("T1") is not None and res.get("T2") is not None:
        if stepped:
            torque, scale = res["T1"] * r1 - res["T2"] * r2 - direction * axle, (res["T1"] * r1, res["T2"] * r2, axle)
            c.eq("T1 r1 − T2 r2 − τ_a sgn ω = I α", torque, moment * res["alpha"], *scale)
        elif not sliding_rim and R is not None:
            torque = (res["T1"] - res["T2"]) * R - direction * axle
            c.eq("(T1 − T2)R − τ_a sgn ω = I a/R", torque, moment * a / R, res["T1"] * R, res["T2"] * R, axle)
    if hanging and not stepped and not axle and m1 + m2 > 0 and not sliding_rim:
        c.eq("a_massless = (m1 − m2)g/(m1 + m2)", res.get("a_massless"), (m1 - m2) * g / (m1 + m2))
    # a string that may slide: the capstan limit
    if "rim_mu" in inp:
        mu, wrap = inp["rim_mu"], inp.get("wrap", math.pi)
        high, low = max(res["T1"], res["T2"]), min(res["T1"], res["T2"])
        c.true("grips ⇔ rim_mu ≥ rim_mu_min", res["grips"] == (mu >= res["rim_mu_min"]), f"grips {res['grips']}, μ {mu}, μ_min {res['rim_mu_min']}")
        if res["grips"]:
            c.eq("T_high = T_low e^(rim_mu_min β) (gripping)", high, low * math.exp(res["rim_mu_min"] * wrap))
            c.eq("a_rim = a (gripping)", res.get("a_rim"), a)
        else:
            c.eq("T_high = T_low e^(μβ) (sliding)", high, low * math.exp(mu * wrap))
            if R is not None:
                c.eq("a_rim = α R", res.get("a_rim"), res.get("alpha") * R if res.get("alpha") is not None else None)
            if moment:
                c.eq("(T1 − T2)R = I a_rim/R", (res["T1"] - res["T2"]) * R if R else None, moment * res["a_rim"] / R if R else None, res["T1"] * (R or 0), res["T2"] * (R or 0))
    # the motion: uniform before any stop
    stop = -v0 / a if v0 * a < 0 else None
    time, distance = inp.get("time"), inp.get("distance")
    if time is not None and res.get("distance") is not None and (stop is None or time <= stop):
        c.eq("distance = v₀t + ½at²", res["distance"], v0 * time + a * time * time / 2, v0 * time, a * time * time / 2)
        if distance is None:
            c.eq("v = v₀ + at", res.get("v"), v0 + a * time, v0, a * time)
    if distance is not None and res.get("t") is not None and (stop is None or res["t"] <= stop):
        t = res["t"]
        c.eq("v = v₀ + at after the distance", res.get("v"), v0 + a * t, v0, a * t)
        c.eq("|v₀t + ½at²| = the distance", abs(v0 * t + a * t * t / 2), distance, v0 * t, a * t * t / 2)
        if res.get("v") is not None:
            c.eq("v² = v₀² + 2a·x", res["v"] ** 2, v0 * v0 + 2 * a * distance * (sgn(res["v"]) or direction), v0 * v0, 2 * a * distance)
    # a point on the pulley, which turns with m1's string: ω = v/R, α = a/R, θ = x/R
    if kw.get("at") is not None and res.get("alpha") is not None:
        r = inp["at"] if kw["at"] != "rim" else R
        string = r1 if stepped else R
        if distance is not None:
            speed, path, t_at = res.get("v"), distance, res.get("t")
        elif time is not None:
            speed, path, t_at = res.get("v"), res.get("distance"), time
        else:
            speed, path, t_at = v0, 0.0, 0.0
        if speed is not None and t_at is not None:
            alpha_at = res["alpha"]
            if stop is not None and t_at > stop:  # stopped, then held or turned back: the machine's α from rest
                rest = {key: value for key, value in kw.items() if key not in ("v0", "distance", "time", "at")}
                alpha_at = taucli.atwood(**rest).results["alpha"].value
            point_checks(c, res, r, speed / string, alpha_at, None if path is None else path / string,
                         start=(v0 / string, res["alpha"]) if t_at else None)
