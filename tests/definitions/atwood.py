"""atwood: the draws (hanging, a slope, a stepped pulley, a string that may slide; #34: each block
on a table or its own incline, pulls on them, a drive on the pulley, both strings on one side,
the stop) and the definitions."""

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


def _side(rng: random.Random, tags: list[str], number: str) -> str:
    """A --side1/--side2 spec: hang, a table or an incline, with or without friction."""
    surface = rng.choice(("hang", "table", "incline", "incline"))
    if surface == "hang":
        return "hang"
    fields: dict = {}
    if surface == "incline":
        fields["angle"] = (rng.uniform(0, math.pi / 2), "rad")
    x = rng.random()
    if x < 0.5:
        mu_k = rng.uniform(0, 0.8)
        fields["mu_k"] = (mu_k, "")
        if rng.random() < 0.5:
            fields["mu_s"] = (mu_k + rng.uniform(0, 0.4), "")
        tags.append("side friction")
    elif x < 0.6:
        fields["mu_s"] = (rng.uniform(0, 1), "")
    tags.append(f"side{number} {surface}")
    return (surface + " " + spec(**fields)).strip()


def draw_atwood(rng: random.Random) -> tuple[dict, list[str]]:
    """An Atwood machine: hanging, m2 on a table or a slope, a stepped pulley, a string that may
    slide over the rim, or (#34) each block where --side1/--side2 put it with pulls on them, a
    drive on the pulley and both strings on one side; a pulley massless, of a shape, of a given I
    or with parts; axle friction; the motion after a distance or at a time; a point on the pulley."""
    mode = rng.choice(("hanging", "hanging", "incline", "stepped", "rim", "general", "general", "general"))
    tags = [mode]
    m1 = mag(rng, -1, 1.5)
    kw: dict = {"m1": m1}
    if rng.random() < 0.9 or mode == "general":
        kw["m2"] = 0.0 if rng.random() < 0.08 else m1 * mag(rng, -1, 1)
    radius = mag(rng, -1.5, 0)
    if rng.random() < 0.65 or (mode == "general" and rng.random() < 0.5):
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
    elif mode == "stepped" or (mode == "general" and rng.random() < 0.35):
        kw["radius1"] = radius * mag(rng, -0.5, 0.3)
        if rng.random() < 0.8 or "pulley_radius" not in kw:
            kw["radius2"] = radius * mag(rng, -0.5, 0.3)
        tags.append("steps")
    elif mode == "rim":
        kw["rim_mu"] = rng.uniform(0, 0.3) if rng.random() < 0.6 else mag(rng, -3, 0)
        if rng.random() < 0.4:
            kw["wrap"] = rng.uniform(0.2, 2 * math.pi)
    if mode == "general":
        if rng.random() < 0.6:
            kw["side1"] = _side(rng, tags, "1")
        if rng.random() < 0.6 and "m2" in kw:
            kw["side2"] = _side(rng, tags, "2")
        if rng.random() < 0.5:
            pulls = []
            for _ in range(rng.choice((1, 1, 2))):
                on = rng.choice(("1", "2"))
                fields = {"force": (signed(rng, m1 * G0 * mag(rng, -1.5, 0.5), 0.25), "N"), "on": on}
                if not (kw.get(f"side{on}", "hang")).startswith("hang") and rng.random() < 0.6:
                    fields["angle"] = (rng.uniform(-1.2, 1.2), "rad")
                pulls.append(spec(**fields))
            kw["pull"] = pulls
            tags.append("pull")
            if rng.random() < 0.2 and not any("on=1" not in p for p in pulls):
                del kw["m1"]  # the string's end pulled by hand
                tags.append("pull in place of m1")
        if rng.random() < 0.35:
            kw["torque"] = signed(rng, m1 * G0 * radius * mag(rng, -1, 0.5), 0.5)
            tags.append("drive")
        if rng.random() < 0.3:
            kw["same_side"] = True
            tags.append("same side")
    if rng.random() < 0.2:
        kw["g"] = rng.uniform(1, 25)
    speed = math.sqrt(G0 * radius) * mag(rng, -1, 1)
    if rng.random() < (0.3 if mode != "general" else 0.5):
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
    side = random.Random(str(rng.getstate()))  # #35's draws, leaving the stream the older draws see as it was
    if side.random() < 0.08:
        return _fixed_drum(side)
    return kw, tags


def _fixed_drum(rng: random.Random) -> tuple[dict, list[str]]:
    """A rope over a drum that cannot turn (--fixed-drum): two hanging masses, μ, the wrap, a start and a target."""
    kw: dict = {"m1": mag(rng, -1, 2), "m2": mag(rng, -1, 2), "fixed_drum": True, "wrap": (rng.uniform(0.2, 4) * math.pi, "rad")}
    kw["wrap"] = f"{kw['wrap'][0]!r}rad"
    tags = ["fixed drum"]
    if rng.random() < 0.5:
        kw["rim_mu"] = rng.uniform(0, 0.6)
    else:
        kw["mu_k"] = rng.uniform(0, 0.5)
        kw["mu_s"] = kw["mu_k"] * rng.uniform(1, 1.5)
    if rng.random() < 0.3:
        kw["v0"] = rng.uniform(-3, 3)
    if rng.random() < 0.5:
        kw["distance"] = mag(rng, -1, 1)
    return kw, tags


def check_fixed_drum(res: dict, inp: dict, c: Checker) -> None:
    """The rope's capstan limit and the masses' Newton's laws: held within e^{±μs β} (T = weights),
    sliding with T_tight = e^{μk β} T_slack towards the side it moves to."""
    g, m1, m2, wrap = inp.get("g", G0), inp["m1"], inp["m2"], inp["wrap"]
    mu_k = inp.get("rim_mu", inp.get("mu_k"))
    mu_s = inp.get("rim_mu", inp.get("mu_s", mu_k))
    c.eq("rim_mu_min = |ln(m₁/m₂)|/β", res.get("rim_mu_min"), abs(math.log(m1 / m2)) / wrap)
    c.true("holds ⇔ |ln(m₁/m₂)| ≤ μs β (from rest)", inp.get("v0", 0.0) != 0 or res["holds"] == (abs(math.log(m1 / m2)) <= mu_s * wrap), str(res["holds"]))
    a, t1, t2 = res.get("a"), res.get("T1"), res.get("T2")
    if a is None:
        return
    c.eq("m₁g − T₁ = m₁a", m1 * g - t1, m1 * a, m1 * g, t1)
    c.eq("T₂ − m₂g = m₂a", t2 - m2 * g, m2 * a, m2 * g, t2)
    if not res["holds"] or inp.get("v0", 0.0):
        tight, slack = (t1, t2) if (inp.get("v0", 0.0) or a) > 0 else (t2, t1)
        c.eq("T_tight = e^{μk β} T_slack", tight, slack * math.exp(mu_k * wrap))


def _place(kw: dict, inp: dict, number: str) -> tuple[float, float | None, float | None]:
    """(θ, μk, μs) under block ``number``: hanging θ = 90°, no friction; μk None where only μs is given."""
    text = kw.get(f"side{number}")
    if text is None and number == "2" and "incline" in inp:
        mu_k = inp.get("mu_k", 0.0 if "mu_s" not in inp else None)
        return inp["incline"], mu_k, inp.get("mu_s", mu_k)
    if text is None or text.startswith("hang"):
        return math.pi / 2, 0.0, 0.0
    key = f"side{number}_"
    angle = inp.get(key + "angle", 0.0)
    mu_k = inp.get(key + "mu_k", inp.get(key + "mu", 0.0 if key + "mu_s" not in inp else None))
    return angle, mu_k, inp.get(key + "mu_s", mu_k)


def _pulls(kw: dict, inp: dict) -> dict[str, list[float]]:
    """Each block's pulls summed: [along its path away from the pulley, lifting it off its surface]."""
    out = {"1": [0.0, 0.0], "2": [0.0, 0.0]}
    pulls = kw.get("pull") or ()
    for n, text in enumerate(pulls, start=1):
        key = f"pull{n}_"
        force, angle = inp[key + "force"], inp.get(key + "angle", 0.0)
        on = "2" if "on=2" in text else "1"
        out[on][0] += force * math.cos(angle)
        out[on][1] += force * math.sin(angle)
    return out


def check_atwood(kw: dict, report, c: Checker) -> None:
    res, inp = values(report), inputs(report)
    if kw.get("fixed_drum"):
        check_fixed_drum(res, inp, c)
        return
    a = res.get("a")
    if a is None:
        return  # μk not given where it slides: nothing is known but that it moves
    g = inp.get("g", G0)
    m1, m2 = inp.get("m1", 0.0), inp.get("m2", 0.0)
    v0 = inp.get("v0", 0.0)
    stepped = "radius1" in inp or "radius2" in inp
    same = bool(kw.get("same_side"))
    sliding_rim = res.get("grips") is False
    R = inp.get("pulley_radius")
    r1 = inp.get("radius1", R)
    r2 = inp.get("radius2", R)
    axle = inp.get("axle_friction", 0.0)
    drive = inp.get("torque", 0.0)
    direction = (v0 > 0) - (v0 < 0) or (a > 0) - (a < 0)  # the way m1 moves at the start (down positive)
    moving = direction != 0
    sgn = lambda x: (x > 0) - (x < 0)
    sigma = -1 if same else 1
    rho = sigma * (r2 / r1 if stepped else 1.0)  # m2's speed towards the pulley over m1's away from it
    a2 = res.get("a2", rho * a)

    # the pulley's inertia: a given I, or k·M·R² (k = ½ a disc, 1 a ring) at its radius (a stepped one's: its larger step), and ring parts m r²
    rim = R if R is not None else (max(r1, r2) if stepped else None)
    parts = math.fsum(inp.get(f"part{n}_mass", 0.0) * inp.get(f"part{n}_radius", 0.0) ** 2 for n in range(1, 4))
    if "pulley_inertia" in inp:
        moment = inp["pulley_inertia"] + parts
    elif rim is not None:
        moment = {"disc": 0.5, "ring": 1.0}[kw.get("pulley_shape", "disc")] * inp.get("pulley_mass", 0.0) * rim * rim + parts
    else:
        moment = None

    # each block along its path: G the pull of gravity and of the pulls away from the pulley, N the surface's push
    (theta1, mu_k1, mu_s1), (theta2, mu_k2, mu_s2) = _place(kw, inp, "1"), _place(kw, inp, "2")
    pulls = _pulls(kw, inp)
    hang1, hang2 = theta1 == math.pi / 2, theta2 == math.pi / 2
    sin1, cos1 = (1.0, 0.0) if hang1 else (math.sin(theta1), math.cos(theta1))
    sin2, cos2 = (1.0, 0.0) if hang2 else (math.sin(theta2), math.cos(theta2))
    along1, along2 = m1 * g * sin1 + pulls["1"][0], m2 * g * sin2 + pulls["2"][0]
    normal1, normal2 = m1 * g * cos1 - pulls["1"][1], m2 * g * cos2 - pulls["2"][1]
    c.true("N ≥ 0 on each surface (a block lifted off is refused)", normal1 >= -1e-12 * m1 * g and normal2 >= -1e-12 * m2 * g, f"N1 {normal1}, N2 {normal2}")
    for n, tension in (("1", res.get("T1")), ("2", res.get("T2"))):
        if tension is not None:  # a string only pulls (#34: a slack string is refused)
            c.true(f"T{n} ≥ 0", tension >= -1e-12 * (abs(along1) + abs(along2) + abs(m1 * a) + abs(m2 * a2) + 1e-300), f"T{n} = {tension}")

    # Newton for each block, moving: m1 away from the pulley in sense s, m2 towards it at ρ times m1's speed
    if moving and mu_k1 is not None and mu_k2 is not None and not sliding_rim:
        f1, f2 = mu_k1 * normal1, mu_k2 * normal2
        c.eq("T1 = G1 − s μk1 N1 − m1 a", res.get("T1"), along1 - direction * f1 - m1 * a, along1, f1, m1 * a)
        c.eq("T2 = G2 + s sgn(ρ) μk2 N2 + m2 a2", res.get("T2"), along2 + direction * sgn(rho) * f2 + m2 * a2, along2, f2, m2 * a2)
    elif moving and not sliding_rim and hang1 and hang2:
        c.eq("T1 = m1(g − a)", res.get("T1"), m1 * (g - a), m1 * g, m1 * a)
    if stepped or same:
        c.eq("a2 = ρ a (the strings' constraint)", res.get("a2"), rho * a)
    # the pulley: the tensions' torque less the drive's and the axle's turns it
    if not sliding_rim and r1 is not None:
        c.eq("alpha = a/r1", res.get("alpha"), a / r1)
    if moving and moment is not None and res.get("T1") is not None and res.get("T2") is not None and not sliding_rim and r1 is not None:
        torque = res["T1"] * r1 - sigma * res["T2"] * r2 - drive - direction * axle
        c.eq("T1 r1 − σ T2 r2 − τd − τa sgn ω = I α", torque, moment * a / r1, res["T1"] * r1, res["T2"] * r2, drive, axle)
    # at rest: each block and the pulley balance with frictions within their static limits
    if not moving and res.get("T1") is not None and res.get("T2") is not None and mu_s1 is not None and mu_s2 is not None:
        scale = abs(along1) + abs(along2) + mu_s1 * normal1 + mu_s2 * normal2 + (axle + abs(drive)) / (r1 or 1.0)
        c.true("at rest |T1 − G1| ≤ μs1 N1", abs(res["T1"] - along1) <= mu_s1 * normal1 + 1e-12 * scale, f"{res['T1']} vs {along1} ± {mu_s1 * normal1}")
        c.true("at rest |T2 − G2| ≤ μs2 N2", abs(res["T2"] - along2) <= mu_s2 * normal2 + 1e-12 * scale * max(1.0, 1 / abs(rho)),
               f"{res['T2']} vs {along2} ± {mu_s2 * normal2}")
        if r1 is not None:
            c.true("at rest |T1 − ρT2 − τd/r1| ≤ τa/r1", abs(res["T1"] - rho * res["T2"] - drive / r1) <= axle / r1 + 1e-12 * scale,
                   f"{res['T1']} − {rho}·{res['T2']}")
    classic = hang1 and not kw.get("pull") and not drive and not stepped and not same
    if classic and hang2 and not axle and m1 + m2 > 0 and not sliding_rim and res.get("a_massless") is not None:
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
    if "t_stop" in res:  # with --v0: when it first stops (0: held, null: never)
        if stop is not None:
            c.eq("t_stop = −v₀/a", res["t_stop"], stop)
            c.eq("distance_stop = v₀ t_stop/2 = −v₀²/2a", res.get("distance_stop"), v0 * stop / 2)
        elif v0 == 0 and a == 0:
            c.true("held from rest: t_stop = distance_stop = 0", res["t_stop"] == 0 and res.get("distance_stop") == 0)
        else:
            c.true("never stops: t_stop null", res["t_stop"] is None and res.get("distance_stop") is None, f"t_stop {res['t_stop']}")
    time, distance = inp.get("time"), inp.get("distance")
    if time is not None and res.get("distance") is not None and (stop is None or time <= stop):
        c.eq("distance = v₀t + ½at²", res["distance"], v0 * time + a * time * time / 2, v0 * time, a * time * time / 2)
        if distance is None:
            c.eq("v = v₀ + at", res.get("v"), v0 + a * time, v0, a * time)
        # the energy balance before the stop: the forces' work is the kinetic energy gained, body by body
        if moment is not None and r1 is not None and mu_k1 is not None and mu_k2 is not None and not sliding_rim and res.get("v") is not None and distance is None:
            x, v = res["distance"], res["v"]
            friction = mu_k1 * normal1 + abs(rho) * mu_k2 * normal2 + axle / r1
            work = along1 * x - along2 * rho * x - drive * x / r1 - friction * abs(x)
            kinetic = lambda u: (m1 * u * u + m2 * (rho * u) ** 2 + moment * (u / r1) ** 2) / 2  # noqa: E731
            c.eq("W_gravity + W_pulls + W_drive − W_friction = ΔKE", work, kinetic(v) - kinetic(v0), along1 * x, along2 * rho * x, drive * x / r1,
                 friction * x, kinetic(v), kinetic(v0), rel=1e-9)
    if distance is not None and res.get("t") is not None and (stop is None or res["t"] <= stop):
        t = res["t"]
        c.eq("v = v₀ + at after the distance", res.get("v"), v0 + a * t, v0, a * t)
        c.eq("|v₀t + ½at²| = the distance", abs(v0 * t + a * t * t / 2), distance, v0 * t, a * t * t / 2)
        if res.get("v") is not None:
            c.eq("v² = v₀² + 2a·x", res["v"] ** 2, v0 * v0 + 2 * a * distance * (sgn(res["v"]) or direction), v0 * v0, 2 * a * distance)
    # a point on the pulley, which turns with m1's string: ω = v/R, α = a/R, θ = x/R
    if kw.get("at") is not None and res.get("alpha") is not None:
        r = inp["at"] if kw["at"] != "rim" else R
        string = r1
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
