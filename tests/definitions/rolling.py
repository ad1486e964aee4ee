"""rolling: the draws (an incline, the flat, a pull, a spool, a yo-yo) and the definitions."""

from __future__ import annotations

import math
import random

from definitions.check import G0, Checker, inputs, mag, point_checks, signed, values

ROLLING_K2 = {"sphere": 0.4, "shell": 2 / 3, "disc": 0.5, "cylinder": 0.5, "ring": 1.0, "hoop": 1.0}

def draw_rolling(rng: random.Random) -> tuple[dict, list[str]]:
    """A rolling body: down an incline (rolling or slipping, to the bottom, or climbing), skidding
    or rolling on the flat, pulled (through the centre, above or below it, a spool), a yo-yo."""
    mode = rng.choice(("incline", "incline", "flat", "pull", "pull", "yoyo"))
    tags = [mode]
    kw: dict = {}
    mass, radius = mag(rng, -1.5, 1.5), mag(rng, -2, 0)
    x = rng.random()
    if x < 0.6:
        kw["shape"] = rng.choice(tuple(ROLLING_K2))
    elif x < 0.8:
        kw["k2"] = rng.uniform(0, 1.2)
        tags.append("k2")
    else:
        kw.update(inertia=mass * radius * radius * rng.uniform(0.05, 1.2), mass=mass, radius=radius)
        tags.append("inertia")
    if rng.random() < 0.6:
        kw.setdefault("mass", mass)
    if rng.random() < 0.6:
        kw.setdefault("radius", radius)
    speed = math.sqrt(G0 * radius) * mag(rng, -1, 1)
    if rng.random() < 0.2:
        kw["g"] = rng.uniform(1, 25)
    if mode == "incline":
        kw["angle"] = rng.uniform(0, math.pi / 2) if rng.random() < 0.95 else math.pi / 2
        if rng.random() < 0.5:
            kw["mu_s"] = rng.uniform(0, 1)
            tags.append("mu_s")
        if rng.random() < 0.5:
            kw["mu_k"] = rng.uniform(0, kw.get("mu_s", 1))
            tags.append("mu_k")
        y = rng.random()
        if y < 0.4:
            kw["length"] = radius * mag(rng, 0, 2)
            tags.append("length")
        elif y < 0.6:
            kw["height"] = radius * mag(rng, 0, 2)
            tags.append("height")
        elif y < 0.85:
            kw["v0"] = speed
            tags.append("climb")
    elif mode == "flat":
        kw["v0"] = signed(rng, speed, 0.2)
        if rng.random() < 0.6:
            kw["mu_k"] = rng.uniform(0.01, 1)
            tags.append("skid")
            if rng.random() < 0.5:
                kw["omega0"] = signed(rng, speed / radius * mag(rng, -1, 0.5), 0.4)
                kw.setdefault("radius", radius)
        else:
            tags.append("rolls along")
    elif mode == "pull":
        kw.setdefault("mass", mass)
        if rng.random() < 0.35:
            kw["angle"] = rng.uniform(0, 1.2)
            tags.append("pull up a slope")
        kw["pull"] = mass * G0 * mag(rng, -1.5, 0.3)
        if rng.random() < 0.5:
            kw["pull_angle"] = rng.uniform(-math.pi / 2, math.pi / 2)
        if rng.random() < 0.35:
            kw.setdefault("radius", radius)
            kw["axle_radius"] = kw["radius"] * rng.uniform(0.05, 1)
            if rng.random() < 0.3:
                kw["pull_height"] = kw["axle_radius"] * rng.choice((1, -1))
            tags.append("spool")
        elif rng.random() < 0.6:
            kw.setdefault("radius", radius)
            kw["pull_height"] = kw["radius"] * rng.uniform(-1, 1)
            tags.append("pull height")
        if rng.random() < 0.6:
            kw["mu_s"] = rng.uniform(0, 1)
        if rng.random() < 0.5:
            kw["mu_k"] = rng.uniform(0, kw.get("mu_s", 1))
        if rng.random() < 0.5:
            kw["length"] = radius * mag(rng, 0, 2)
            tags.append("length")
    else:  # a yo-yo
        kw["yoyo"] = True
        if "inertia" in kw and rng.random() < 0.5:
            kw.pop("radius", None)
            kw["axle_radius"] = radius * rng.uniform(0.05, 1)
            tags.append("yoyo by I")
        elif rng.random() < 0.6:
            kw.setdefault("radius", radius)
            kw["axle_radius"] = kw["radius"] * rng.uniform(0.05, 1)
            tags.append("axle")
        if rng.random() < 0.6:
            kw["height"] = radius * mag(rng, 0, 2)
            tags.append("drop")
            if rng.random() < 0.4:
                kw["v0"] = signed(rng, speed, 0.3)
    if rng.random() < 0.3:
        kw["at"] = "rim" if rng.random() < 0.3 else radius * rng.uniform(0, 1.2)
        tags.append("at")
    if rng.random() < 0.05:
        name = rng.choice(("pull", "v0", "omega0", "length", "height", "angle", "axle_radius"))
        kw.setdefault(name, mag(rng, -1, 0))
        tags.append("stray")
    return kw, tags

def check_rolling(kw: dict, report, c: Checker) -> None:
    res, inp = values(report), inputs(report)
    model = report.model
    g = inp.get("g", G0)
    m, R = inp.get("mass"), inp.get("radius")
    if "k2" in inp:
        k2 = inp["k2"]
    elif "shape" in kw:
        k2 = ROLLING_K2[kw["shape"]]
    else:
        k2 = inp["inertia"] / (m * R * R) if R is not None else None
    moment = None if m is None or R is None or k2 is None else k2 * m * R * R
    a, alpha, friction = res.get("a"), res.get("alpha"), res.get("friction")
    v, omega, t = res.get("v"), res.get("omega"), res.get("t")

    def energies(speed, rim_speed=None, spin=None, rotational=moment):
        if m is not None and speed is not None:
            c.eq("KE_trans = ½ m v²", res.get("KE_trans"), m * speed * speed / 2)
        if rotational is not None and spin is not None:
            c.eq("KE_rot = ½ I ω²", res.get("KE_rot"), rotational * spin * spin / 2)
        elif m is not None and rim_speed is not None:
            c.eq("KE_rot = ½ k² m (Rω)²", res.get("KE_rot"), k2 * m * rim_speed * rim_speed / 2)
        if res.get("KE_trans") is not None and res.get("KE_rot") is not None:
            c.eq("KE = KE_trans + KE_rot", res.get("KE"), res["KE_trans"] + res["KE_rot"])

    if model.startswith("yo-yo"):
        r = inp.get("axle_radius", R)
        if "radius" not in inp and "inertia" in inp:
            q = inp["inertia"] / (m * r * r)  # I/(m r²) about the axle: no outer radius needed
        else:
            q = k2 if "axle_radius" not in inp else k2 * (R / r) ** 2
        body_moment_ = q * m * r * r if m is not None and r is not None else None
        if m is not None:
            c.eq("T = m(g − a)", res.get("T"), m * (g - a), m * g, m * a)
            if body_moment_ is not None:
                c.eq("I α = T r", body_moment_ * res["alpha"] if res.get("alpha") is not None else None, res["T"] * r)
        c.eq("alpha = a/r", alpha, a / r if r is not None else None)
        h, v0 = inp.get("height"), inp.get("v0", 0.0)
        if h is not None:
            c.eq("v² = v₀² + 2ah", v * v, v0 * v0 + 2 * a * h, v0 * v0, 2 * a * h)
            c.eq("h = v₀t + ½at²", v0 * t + a * t * t / 2, h, v0 * t, a * t * t / 2)
            c.eq("omega = v/r", omega, v / r if r is not None else None)  # (r the axle's; R when none is given)
            energies(v, spin=omega, rotational=body_moment_)
            if m is not None:
                c.eq("KE − KE₀ = m g h", res["KE"] - (1 + q) * m * v0 * v0 / 2, m * g * h, res["KE"])
    elif "skidding" in model:
        v0, w0 = inp["v0"], inp.get("omega0", 0.0)
        if res.get("v_roll") is not None:
            slip = v0 - (R * w0 if w0 else 0.0)
            sgn = (slip > 0) - (slip < 0)
            c.eq("v_roll = v₀ − sgn(slip) μk g t_roll (the centre skids at μk g)", res["v_roll"], v0 - sgn * inp["mu_k"] * g * res["t_roll"], v0)
            c.eq("v_roll = (v₀ + k²Rω₀)/(1 + k²) (L about the contact)", res["v_roll"], (v0 + k2 * (R * w0 if w0 else 0.0)) / (1 + k2), v0, k2 * R * w0 if w0 else 0)
            c.eq("d_roll = ½(v₀ + v_roll) t_roll", res.get("d_roll"), (v0 + res["v_roll"]) * res["t_roll"] / 2, v0 * res["t_roll"])
            if R is not None:
                c.eq("omega_roll = v_roll/R", res.get("omega_roll"), res["v_roll"] / R)
            if m is not None:
                before = m * v0 * v0 / 2 + k2 * m * (R * w0 if w0 else 0.0) ** 2 / 2
                c.eq("energy_lost = KE before − KE after", res.get("energy_lost"), before - (1 + k2) * m * res["v_roll"] ** 2 / 2, before)
    elif "on the flat" in model and "rolling without slipping" in model and "pull" not in kw:
        v0 = inp["v0"]
        c.eq("omega = v/R (rolling)", omega, v0 / R if R is not None else None)
        energies(v0, rim_speed=v0)
    elif "pull" in kw:
        theta = inp.get("angle", 0.0)
        phi = inp.get("pull_angle", 0.0)
        F = inp["pull"]
        sigma = 1.0 if theta == 0 else -1.0
        cos_p, sin_p = (0.0, math.copysign(1.0, phi)) if abs(phi) == math.pi / 2 else (math.cos(phi), math.sin(phi))
        if "axle_radius" in inp:
            lever = (1 if inp.get("pull_height", -1) > 0 else -1) * inp["axle_radius"]
        else:
            lever = inp.get("pull_height", 0.0) * cos_p
        sin_t, cos_t = (1.0, 0.0) if theta == math.pi / 2 else (math.sin(theta), math.cos(theta))  # a vertical face: no normal force
        normal = max(m * g * cos_t - F * sin_p, 0.0)
        along = sigma * F * cos_p + m * g * sin_t
        if a is not None and friction is not None:
            c.eq("m a = σF cos φ + m g sin θ − f", m * a, along - friction, sigma * F * cos_p, m * g * sin_t, friction)
        if alpha is not None and friction is not None and moment is not None:
            c.eq("I α = f R + σ F ℓ", moment * alpha, friction * R + sigma * F * lever, friction * R, F * lever)
        if res.get("rolls") and a is not None:
            if R is not None:
                c.eq("alpha = a/R (rolling)", alpha, a / R)
            if normal > 0:
                c.eq("mu_min = |f|/N", res.get("mu_min"), abs(friction) / normal)
        elif a is not None and friction is not None:
            c.eq("|f| = μk N (slipping)", abs(friction), inp.get("mu_k", 0.0) * normal)
        if res.get("critical_angle") is not None:
            phi_c = res["critical_angle"]
            c.eq("a = 0 at the critical angle: σF cos φc + m g sin θ + σFℓ/R = 0", sigma * F * math.cos(phi_c) + m * g * sin_t + sigma * F * lever / R, 0.0,
                 F, m * g * sin_t)
        L = inp.get("length")
        if L is not None and t is not None:
            c.eq("|a| t²/2 = L", abs(a) * t * t / 2, L)
            c.eq("v = a t", v, a * t)
            c.eq("omega = α t", omega, alpha * t if alpha is not None else None)
            energies(v, spin=omega)
    else:  # an incline
        theta = inp["angle"]
        vertical = theta == math.pi / 2
        sin_t, cos_t = (1.0, 0.0) if vertical else (math.sin(theta), math.cos(theta))
        if not vertical and a is not None:
            c.eq("mu_min g cos θ = g sin θ − a needed (f = m(g sin θ − a))", res["mu_min"] * g * cos_t, g * sin_t * k2 / (1 + k2), g * sin_t)
        if res.get("rolls") and a is not None:
            c.eq("m a = m g sin θ − f (rolling)", a, g * sin_t - friction / m if friction is not None else None, g * sin_t)
            if R is not None:
                c.eq("alpha = a/R (rolling)", alpha, a / R)
            if friction is not None and moment is not None and alpha is not None:
                c.eq("I α = f R (rolling)", moment * alpha, friction * R)
        elif a is not None and not vertical:
            mu_k = inp["mu_k"]
            if m is not None:
                c.eq("friction = μk m g cos θ (slipping)", friction, mu_k * m * g * cos_t)
            c.eq("a = g sin θ − μk g cos θ (slipping)", a, g * sin_t - mu_k * g * cos_t, g * sin_t)
            if friction is not None and moment is not None and moment > 0:
                c.eq("I α = f R (slipping)", moment * alpha if alpha is not None else None, friction * R)
        if ("mu_s" in inp or "mu_k" in inp) and not vertical:
            mu_s = inp.get("mu_s", inp.get("mu_k"))
            c.true("rolls ⇔ μs ≥ mu_min", res["rolls"] == (mu_s >= res["mu_min"]), f"rolls {res['rolls']}, μs {mu_s}, μ_min {res['mu_min']}")
        length = inp.get("length", None if "height" not in inp else inp["height"] / sin_t)
        if length is not None and v is not None:
            c.eq("v² = 2aL from rest", v * v, 2 * a * length)
            c.eq("t = 2L/v", t, 2 * length / v)
            rim_speed = v if res.get("rolls") else (alpha * R * t if alpha is not None and R is not None else None)
            energies(v, rim_speed=rim_speed)
        v0 = inp.get("v0", 0.0)
        if v0 > 0 and res.get("d_climb") is not None:
            c.eq("d_climb = v₀²/2a", res["d_climb"], v0 * v0 / (2 * a))
            c.eq("h_climb = d_climb sin θ", res.get("h_climb"), res["d_climb"] * sin_t)
            c.eq("t_climb = v₀/a", res.get("t_climb"), v0 / a)

    if kw.get("at") is not None:
        r = R if kw["at"] == "rim" else inp["at"]
        check_rolling_point(kw, res, inp, r, R, c)

def check_rolling_point(kw, res, inp, r, R, c: Checker) -> None:
    """The point's ω and α about the centre: ω₀ (--omega0; a body set rolling at v₀/R, a yo-yo's at v₀/r;
    a skid with no spin 0), then ω = ω₀ + αt and θ = ω₀t + ½αt² at the end; a skid's ω_roll, its α
    while it slides (ω_roll − ω₀)/t_roll and 0 once it rolls."""
    v0 = inp.get("v0", 0.0)
    rolling_radius = inp.get("axle_radius", R) if kw.get("yoyo") else R
    skid = res.get("omega_roll") is not None and res.get("t_roll") is not None
    if "omega0" in inp:
        w0 = inp["omega0"]
    elif skid or not v0:
        w0 = 0.0
    else:
        w0 = v0 / rolling_radius
    if skid and res["t_roll"] > 0:
        omega, tr = res["omega_roll"], res["t_roll"]
        point_checks(c, res, r, omega, 0.0, (w0 + omega) * tr / 2, start=(w0, (omega - w0) / tr))
        return
    alpha, t = res.get("alpha"), res.get("t")
    if alpha is not None and t is not None:
        point_checks(c, res, r, w0 + alpha * t, alpha, w0 * t + alpha * t * t / 2, start=(w0, alpha))
    else:
        point_checks(c, res, r, w0, alpha, 0.0)
