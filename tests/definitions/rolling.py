"""rolling: the draws (an incline, the flat, a pull, a spool, a yo-yo, a yo-yo spun in place, a
body joined to a hanging mass, a point on the rim seen from the ground) and the definitions."""

from __future__ import annotations

import math
import random

from definitions.check import G0, Checker, inputs, mag, point_checks, signed, values
from definitions.rolling_drum import check_drum_yoyo

ROLLING_K2 = {"sphere": 0.4, "shell": 2 / 3, "disc": 0.5, "cylinder": 0.5, "ring": 1.0, "hoop": 1.0}

def draw_rolling(rng: random.Random) -> tuple[dict, list[str]]:
    """A rolling body: down an incline (rolling or slipping, to the bottom, or climbing), skidding
    or rolling on the flat, pulled (through the centre, above or below it, a spool), a yo-yo."""
    mode = rng.choice(("incline", "incline", "flat", "pull", "pull", "yoyo", "hanging", "hanging", "in place"))
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
        if y < 0.6 and rng.random() < 0.35:  # set rolling up (or down) the slope, L from the bottom
            kw["v0"] = signed(rng, speed, 0.3)
            tags.append("climb and back")
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
    elif mode == "hanging":
        kw.setdefault("mass", mass)
        kw["hanging_mass"] = mass * mag(rng, -1.5, 1)
        if rng.random() < 0.5:
            kw["string"] = "top"
            tags.append("string top")
        elif rng.random() < 0.3:
            kw["string"] = "centre"
        if rng.random() < 0.5:
            kw["pulley_mass"] = mass * mag(rng, -1.5, 0.5)
            tags.append("pulley mass")
        if rng.random() < 0.4:
            kw["pulley_radius"] = radius * mag(rng, -1, 0.5)
        if rng.random() < 0.4:
            kw["angle"] = rng.uniform(0, math.pi / 2) if rng.random() < 0.95 else math.pi / 2
            tags.append("hanging slope")
        if rng.random() < 0.6:
            kw["mu_s"] = rng.uniform(0, 1)
        if rng.random() < 0.5:
            kw["mu_k"] = rng.uniform(0, kw.get("mu_s", 1))
        if rng.random() < 0.5:
            kw["length"] = radius * mag(rng, 0, 2)
            tags.append("length")
    elif mode == "in place":
        kw["in_place"] = True
        if "inertia" in kw and rng.random() < 0.5:
            kw.pop("radius", None)
            tags.append("in place by I")
        else:
            kw.setdefault("radius", radius)
        if rng.random() < 0.5:
            kw["axle_radius"] = radius * rng.uniform(0.05, 1)
        if rng.random() < 0.5:
            kw["omega0"] = math.sqrt(G0 / radius) * mag(rng, -1, 1)
        if rng.random() < 0.6:
            kw["length"] = radius * mag(rng, 0, 2)
            tags.append("string pulled")
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
    if rng.random() < 0.45:
        y = rng.random()
        if y < 0.2:
            kw["at"] = "rim"
        elif y < 0.45:
            kw["at"] = radius * rng.uniform(0, 1.2)
        elif y < 0.75:
            kw["at"] = rng.choice(("top", "bottom", "bottom", "front", "back"))
            tags.append("on the rim")
        else:
            kw["at"] = f"{rng.uniform(-360, 360)!r} deg"
            tags.append("on the rim")
        tags.append("at")
    if rng.random() < 0.05:
        name = rng.choice(("pull", "v0", "omega0", "length", "height", "angle", "axle_radius"))
        kw.setdefault(name, mag(rng, -1, 0))
        tags.append("stray")
    return kw, tags

def draw_pulled_yoyo(rng: random.Random) -> tuple[dict, list[str]]:
    """A yo-yo pulled or held besides by a vertical force (#46 item 1): through its centre, on the
    far side (a rope run under it), on the string's side; after a drop or a time; thrown down or up."""
    tags = ["pulled yoyo"]
    mass, radius = mag(rng, -1.5, 1.5), mag(rng, -2, 0)
    kw: dict = {"yoyo": True, "mass": mass}
    if rng.random() < 0.6:
        kw.update(shape=rng.choice(tuple(ROLLING_K2)), radius=radius)
    else:
        kw.update(inertia=mass * radius * radius * rng.uniform(0.05, 1.2), radius=radius)
        tags.append("inertia")
    if rng.random() < 0.5:
        kw["axle_radius"] = radius * rng.uniform(0.05, 1)
        tags.append("axle")
    if rng.random() < 0.2:
        kw["g"] = rng.uniform(1, 25)
    kw["pull"] = mass * G0 * mag(rng, -1.5, 0.3)
    y = rng.random()
    if y < 0.6:
        kw["pull_at"] = signed(rng, radius * rng.uniform(0, 1.2), 0.3)
        tags.append("pull at")
    if rng.random() < 0.5:
        kw["time"] = mag(rng, -1, 1)
        tags.append("time")
    elif rng.random() < 0.6:
        kw["height"] = radius * mag(rng, 0, 2)
        tags.append("drop")
    if rng.random() < 0.3:
        kw["v0"] = signed(rng, math.sqrt(G0 * radius) * mag(rng, -1, 1), 0.5)
        tags.append("v0")
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

    if model.startswith("yo-yo spun in place"):
        check_in_place(kw, res, inp, k2, m, R, g, c)
    elif "hanging mass" in model:
        check_hanging(kw, res, inp, k2, m, R, g, c, energies)
    elif model.startswith("yo-yo"):
        r = inp.get("axle_radius", R)
        if "radius" not in inp and "inertia" in inp:
            q = inp["inertia"] / (m * r * r)  # I/(m r²) about the axle: no outer radius needed
        else:
            q = k2 if "axle_radius" not in inp else k2 * (R / r) ** 2
        body_moment_ = q * m * r * r if m is not None and r is not None else None
        if "drum_mass" in inp or "drum_inertia" in inp:
            check_drum_yoyo(kw, res, inp, q, m, r, g, c)
            return
        F, d = inp.get("pull", 0.0), inp.get("pull_at", 0.0)
        if m is not None:
            c.eq("T = m(g − a) − F", res.get("T"), m * (g - a) - F, m * g, m * a, F)
            if body_moment_ is not None:
                c.eq("I α = T r − F d", body_moment_ * res["alpha"] if res.get("alpha") is not None else None, res["T"] * r - F * d, res["T"] * r, F * d)
            c.true("T ≥ 0 (a string only pulls)", res["T"] >= 0, f"T = {res['T']}")
        c.eq("alpha = a/r", alpha, a / r if r is not None else None)
        if "pull" in inp and r is not None:
            c.eq("a_hand = −a − α d (the pulled point, upward)", res.get("a_hand"), -a - alpha * d, a, alpha * d)
        h, v0 = inp.get("height"), inp.get("v0", 0.0)
        if "time" in inp:
            tt, x = inp["time"], res["drop"]
            c.eq("v = v₀ + a t", v, v0 + a * tt, v0, a * tt)
            c.eq("x = v₀t + ½at²", x, v0 * tt + a * tt * tt / 2, v0 * tt, a * tt * tt / 2)
            c.eq("v² = v₀² + 2ax", v * v, v0 * v0 + 2 * a * x, v0 * v0, 2 * a * x)
            c.eq("omega = v/r", omega, v / r if r is not None else None)
            energies(v, spin=omega, rotational=body_moment_)
            if m is not None:
                work = res.get("work_pull", 0.0)
                c.eq("KE − KE₀ = m g x + W_pull", res["KE"] - (1 + q) * m * v0 * v0 / 2, m * g * x + work, res["KE"], m * g * x, work)
                if "pull" in inp and r is not None:
                    c.eq("W_pull = F × the pulled point's rise", work, -F * (x + d * x / r), F * x)
        if h is not None:
            c.eq("v² = v₀² + 2ah", v * v, v0 * v0 + 2 * a * h, v0 * v0, 2 * a * h)
            c.eq("h = v₀t + ½at²", v0 * t + a * t * t / 2, h, v0 * t, a * t * t / 2)
            c.eq("omega = v/r", omega, v / r if r is not None else None)  # (r the axle's; R when none is given)
            energies(v, spin=omega, rotational=body_moment_)
            if m is not None:
                c.eq("KE − KE₀ = m g h + W_pull", res["KE"] - (1 + q) * m * v0 * v0 / 2, m * g * h + res.get("work_pull", 0.0), res["KE"], m * g * h)
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
        v0 = inp.get("v0", 0.0)  # up the slope, set rolling: it climbs, comes back, and reaches the bottom under the same a
        if length is not None and v is not None:
            c.eq("v² = v₀² + 2aL", v * v, v0 * v0 + 2 * a * length, v0 * v0, 2 * a * length)
            c.eq("L = −v₀t + ½at² (v₀ up the slope)", -v0 * t + a * t * t / 2, length, v0 * t, a * t * t / 2)
            c.eq("v = −v₀ + at at the bottom", v, -v0 + a * t, v0, a * t)
            rim_speed = v if res.get("rolls") else (-v0 + alpha * R * t if alpha is not None and R is not None else None)
            energies(v, rim_speed=rim_speed)
        if v0 > 0 and res.get("d_climb") is not None:
            c.eq("d_climb = v₀²/2a", res["d_climb"], v0 * v0 / (2 * a))
            c.eq("h_climb = d_climb sin θ", res.get("h_climb"), res["d_climb"] * sin_t)
            c.eq("t_climb = v₀/a", res.get("t_climb"), v0 / a)

    if kw.get("at") is not None:
        check_rolling_point(kw, res, inp, R, c, model, g)


def check_hanging(kw, res, inp, k2, M, R, g, c: Checker, energies) -> None:
    """The body (M a = T − M g sin θ − f, I α = f R + c T R), the hanging mass (m a_h = m g − T₂),
    the pulley, a uniform disc (T₂ − T = ½ m_p a_h), the string (a_h = a + c R α), with c = 1 for a
    string from the top, 0 from the centre; rolling a = Rα, μ_min = |f|/N; slipping |f| = μk N."""
    m, m_p = inp["hanging_mass"], inp.get("pulley_mass", 0.0)
    lever = 1 if kw.get("string") == "top" else 0
    theta = inp.get("angle", 0.0)
    sin_t, cos_t = (1.0, 0.0) if theta == math.pi / 2 else (math.sin(theta), math.cos(theta))
    normal = M * g * cos_t
    a, alpha, f, T, T2, a_h = (res.get(key) for key in ("a", "alpha", "friction", "T", "T2", "a_hanging"))
    if a is None:
        return
    c.eq("M a = T − M g sin θ − f", M * a, T - M * g * sin_t - f, T, M * g * sin_t, f)
    c.eq("m a_h = m g − T₂", m * a_h, m * g - T2, m * g, T2)
    c.eq("T₂ − T = ½ m_p a_h (the pulley)", T2 - T, m_p * a_h / 2, T2, T)
    if alpha is not None and R is not None:
        c.eq("I α = f R + c T R", k2 * M * R * R * alpha, f * R + lever * T * R, f * R, T * R)
        c.eq("a_h = a + c R α (the string)", a_h, a + lever * R * alpha, a, R * alpha)
    if res.get("rolls"):
        c.eq("k² M a = f + c T (rolling: Iα/R with α = a/R)", k2 * M * a, f + lever * T, f, T)
        c.eq("a_h = (1 + c) a (rolling)", a_h, (1 + lever) * a)
        if R is not None:
            c.eq("alpha = a/R (rolling)", alpha, a / R)
        if normal > 0:
            c.eq("mu_min = |f|/N", res.get("mu_min"), abs(f) / normal)
    else:
        c.eq("|f| = μk N (slipping)", abs(f), inp.get("mu_k", 0.0) * normal)
    if ("mu_s" in inp or "mu_k" in inp) and res.get("mu_min") is not None:
        mu_s = inp.get("mu_s", inp.get("mu_k"))
        c.true("rolls ⇔ μs ≥ mu_min", res["rolls"] == (mu_s * normal >= abs(res["mu_min"] * normal) * (1 - 1e-14)) or abs(mu_s - res["mu_min"]) < 1e-12,
               f"rolls {res['rolls']}, μs {mu_s}, μ_min {res['mu_min']}")
    c.true("T ≥ 0, T₂ ≥ 0 (a taut string)", T >= -1e-12 * m * g and T2 >= -1e-12 * m * g, f"T {T}, T₂ {T2}")
    if "pulley_radius" in inp:
        c.eq("alpha_pulley = a_h / r_p", res.get("alpha_pulley"), a_h / inp["pulley_radius"])
    L, t = inp.get("length"), res.get("t")
    if L is not None and t is not None:
        c.eq("|a| t²/2 = L", abs(a) * t * t / 2, L)
        c.eq("v = a t", res.get("v"), a * t)
        c.eq("v_hanging = a_h t", res.get("v_hanging"), a_h * t)
        if alpha is not None:
            c.eq("omega = α t", res.get("omega"), alpha * t)
        energies(res.get("v"), spin=res.get("omega"))


def check_in_place(kw, res, inp, k2, m, R, g, c: Checker) -> None:
    """The centre held still: T = m g, I α = T r, the hand's a = r α; after the hand pulls L,
    ½ I (ω² − ω₀²) = T L, ω = ω₀ + α t, KE_rot = ½ I ω²."""
    if "radius" not in inp and "inertia" in inp:
        per_mass = inp["inertia"] / m  # I/m
    else:
        per_mass = k2 * R * R
    r = inp.get("axle_radius", R)
    c.eq("a = 0 (the centre stays put)", res["a"], 0.0, 1.0)
    if m is not None:
        c.eq("T = m g", res.get("T"), m * g)
    if r is not None:
        c.eq("I α = T r", per_mass * res["alpha"], g * r)
        c.eq("a_hand = r α", res.get("a_hand"), r * res["alpha"])
    L, w0, omega = inp.get("length"), inp.get("omega0", 0.0), res.get("omega")
    if L is not None:
        c.eq("½ I (ω² − ω₀²) = T L", per_mass * (omega * omega - w0 * w0) / 2, g * L, per_mass * omega * omega / 2)
        if res.get("t") is not None:
            c.eq("ω = ω₀ + α t", omega, w0 + res["alpha"] * res["t"], w0)
        if m is not None:
            c.eq("KE_rot = ½ I ω²", res.get("KE_rot"), m * per_mass * omega * omega / 2)


def _instant(kw, res, inp, R, model):
    """The body at the point's instant, from the report and the physics: (v, ω, a, α, θ, end)
    with x forward (the sense a is positive in), ω and α in the rolling sense of x; θ the angle
    turned by the end; end: whether it is the end of the run (else the start)."""
    v0 = inp.get("v0", 0.0)
    a, alpha = res.get("a"), res.get("alpha")
    if "skidding" in model:
        w0 = inp.get("omega0", 0.0)
        tr, v_roll, w_roll = res.get("t_roll"), res.get("v_roll"), res.get("omega_roll")
        if tr is None or tr == 0:
            return v0, w0, 0.0, 0.0, 0.0, False
        if w_roll is None:
            return v0, w0, (v_roll - v0) / tr, None, 0.0, False
        return v_roll, w_roll, 0.0, 0.0, (w0 + w_roll) * tr / 2, True, (w0, (w_roll - w0) / tr)
    if model.startswith("yo-yo spun in place"):
        w0, v_start = inp.get("omega0", 0.0), 0.0
    elif model.startswith("yo-yo"):
        r = inp.get("axle_radius", R)
        w0, v_start = (0.0 if not v0 else v0 / r), v0
    elif "on the flat" in model and "rolling without slipping" in model and "pull" not in kw and "hanging_mass" not in kw:
        return v0, v0 / R if R is not None else None, 0.0, 0.0, 0.0, False
    elif "pull" in kw or "hanging_mass" in kw:
        w0, v_start = 0.0, 0.0
    else:  # an incline: v0 up the slope, x down it
        w0, v_start = (0.0 if not v0 else -v0 / R if R is not None else None), -v0
    t = res.get("t")
    if t is None or a is None or alpha is None or w0 is None:
        return v_start, w0, a, alpha, 0.0, False
    v_end = v_start + a * t
    return v_end, w0 + alpha * t, a, alpha, w0 * t + alpha * t * t / 2, True, (w0, alpha)


def check_rolling_point(kw, res, inp, R, c: Checker, model, g) -> None:
    """At a radius: the point's ω and α about the centre (ω₀ --omega0; a body set rolling at
    v₀/R, on a slope −v₀/R as x points down it; a yo-yo's v₀/r; a skid's 0), then ω = ω₀ + αt and
    θ = ω₀t + ½αt² at the end; a skid's α while it slides, 0 once it rolls. On the rim seen from
    the ground: v + ω × r and a + α × r − ω² r, with the bottom at rest while it rolls."""
    at = kw["at"]
    found = _instant(kw, res, inp, R, model)
    v, omega, a, alpha, theta, end = found[:6]
    if at in ("top", "bottom", "front", "back") or (isinstance(at, str) and at.endswith("deg")):
        if omega is None or v is None:
            return
        phi = {"top": 0.0, "front": math.pi / 2, "bottom": math.pi, "back": -math.pi / 2}.get(at)
        phi = inp["at"] if phi is None else phi
        r = (R * math.sin(phi), R * math.cos(phi))
        # ω as a vector: −ω ẑ (the rolling sense of +x when y is up); ω × r = −ω (ẑ × r) = −ω (−r_y, r_x) = ω (r_y, −r_x)
        vx, vy = v + omega * r[1], -omega * r[0]
        c.eq("v_ground = |v + ω × r|", res.get("v_ground"), math.hypot(vx, vy), abs(v), abs(omega * R))
        if res.get("v_ground"):
            c.eq("v_ground_angle = atan2(v_y, v_x) (on the circle)", math.remainder(res["v_ground_angle"] - math.atan2(vy, vx), 2 * math.pi), 0.0, 1.0)
        if res.get("rolls") and at == "bottom" and "skidding" not in model:
            c.eq("v_ground = 0 at the bottom while it rolls", res.get("v_ground"), 0.0, abs(v))
        if a is not None and alpha is not None:
            ax = a + alpha * r[1] - omega * omega * r[0]
            ay = -alpha * r[0] - omega * omega * r[1]
            scale = max(abs(a), abs(alpha * R), omega * omega * R)
            c.eq("a_ground = |a + α × r − ω² r|", res.get("a_ground"), math.hypot(ax, ay), scale)
            if res.get("a_ground") and res["a_ground"] > 1e-9 * scale:
                c.eq("a_ground_angle = atan2(a_y, a_x) (on the circle)", math.remainder(res["a_ground_angle"] - math.atan2(ay, ax), 2 * math.pi), 0.0, 1.0)
        return
    r = R if at == "rim" else inp["at"]
    if end:
        point_checks(c, res, r, omega, alpha if "skidding" not in model else 0.0, theta, start=found[6])
    else:
        point_checks(c, res, r, omega, alpha, 0.0)
