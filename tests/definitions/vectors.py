"""torque and gyro: the draws and the definitions of τ = r × F, L = r × mv and a top's precession."""

from __future__ import annotations

import math
import random

from definitions.check import (
    G0,
    TWO_PI,
    Checker,
    body_moment,
    inputs,
    mag,
    signed,
    values,
)


def draw_torque(rng: random.Random) -> tuple[dict, list[str]]:
    """Forces as vectors at points (some nearly along their lever), forces in the plane at a lever
    and an angle, particles' L = r × mv; one or several of each, or both kinds in one run."""
    kw: dict = {"r": [], "force": []}
    tags = []

    def vector(scale):
        return tuple(0.0 if rng.random() < 0.15 else signed(rng, scale * mag(rng, -1, 1), 0.5) for _ in range(3))

    mode = rng.choice(("vectors", "vectors", "plane", "particles", "both"))
    tags.append(mode)
    if mode in ("vectors", "both"):
        for _ in range(rng.choice((1, 1, 2, 3))):
            force = vector(mag(rng, -1, 3))
            where = vector(mag(rng, -2, 1))
            if rng.random() < 0.15:  # nearly along the force: the cross product cancels
                where = tuple(x * 0.37 + (1e-9 * x if i == 0 else 0.0) for i, x in enumerate(force))
                tags.append("nearly parallel")
            kw["r"].append(where)
            kw["force"].append(force)
    if mode == "plane":
        count = rng.choice((1, 1, 2))
        kw["force"] = [signed(rng, mag(rng, -1, 3), 0.2) for _ in range(count)]
        kw["lever"] = [mag(rng, -2, 1) for _ in range(count)]
        if rng.random() < 0.8:
            kw["angle"] = [rng.uniform(-math.pi, math.pi) for _ in range(count)]
    if mode in ("particles", "both"):
        count = rng.choice((1, 1, 2, 3))
        kw["mass"] = [mag(rng, -2, 2) for _ in range(count)]
        kw["velocity"] = [vector(mag(rng, -1, 2)) for _ in range(count)]
        kw["r"] += [vector(mag(rng, -2, 1)) for _ in range(count)]
        if mode == "both" and len(kw["force"]) == count and rng.random() < 0.5:
            kw["r"] = kw["r"][:count]  # one --r each, to both
            tags.append("shared r")
    for key in ("r", "force"):
        if not kw[key]:
            del kw[key]
    return kw, tags

def cross(u, v):
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])

def check_torque(kw: dict, report, c: Checker) -> None:
    res = values(report)
    forces = kw.get("force", [])
    vectors = [f for f in forces if isinstance(f, tuple)]
    planar = [f for f in forces if not isinstance(f, tuple)]
    rs = kw.get("r", [])
    velocities = kw.get("velocity", [])
    force_r, particle_r = (rs, rs) if vectors and velocities and len(rs) == len(vectors) == len(velocities) else (rs[:len(vectors)], rs[len(vectors):])
    if forces:
        terms = [cross(r, f) for r, f in zip(force_r, vectors)]
        sizes = [[abs(r[1] * f[2]) + abs(r[2] * f[1]), abs(r[2] * f[0]) + abs(r[0] * f[2]), abs(r[0] * f[1]) + abs(r[1] * f[0])] for r, f in zip(force_r, vectors)]
        angles = kw.get("angle") or [math.pi / 2] * len(planar)
        for f, lever, angle in zip(planar, kw.get("lever", []), angles):
            terms.append((0.0, 0.0, lever * f * math.sin(angle)))
            sizes.append([0.0, 0.0, abs(lever * f)])
        for i, key in enumerate(("tau_x", "tau_y", "tau_z")):
            c.eq(f"{key} = Σ (r × F){key[-1]}", res[key], math.fsum(t[i] for t in terms), *(math.fsum(s[i] for s in sizes),))
        c.eq("tau = |τ|", res["tau"], math.hypot(res["tau_x"], res["tau_y"], res["tau_z"]))
        if len(forces) == 1 and res.get("lever_arm") is not None:
            if vectors:
                c.eq("lever_arm = |r × F|/|F|", res["lever_arm"], res["tau"] / math.hypot(*vectors[0]))
            else:
                c.eq("lever_arm = r |sin θ|", res["lever_arm"], kw["lever"][0] * abs(math.sin(angles[0])), kw["lever"][0])
    if velocities:
        terms = [tuple(m * x for x in cross(r, v)) for r, m, v in zip(particle_r, kw["mass"], velocities)]
        scale = math.fsum(m * math.hypot(*r) * math.hypot(*v) for r, m, v in zip(particle_r, kw["mass"], velocities))
        for i, key in enumerate(("L_x", "L_y", "L_z")):
            c.eq(f"{key} = Σ m (r × v){key[-1]}", res[key], math.fsum(t[i] for t in terms), scale)
        c.eq("L = |L|", res["L"], math.hypot(res["L_x"], res["L_y"], res["L_z"]))
    for table in ("forces", "particles"):
        for row in report.tables[table].rows if table in report.tables else ():
            c.eq(f"a {table} row's size = |its vector|", row[4], math.hypot(*row[1:4]))

def draw_gyro(rng: random.Random) -> tuple[dict, list[str]]:
    """A top or gyroscope: given I or a shape, a spin, the weight at a distance (or a torque), a tilt
    from upright to hanging, I⊥ given or from the shape."""
    kw: dict = {}
    tags = []
    mass, radius = mag(rng, -1.5, 1), mag(rng, -2, 0)
    if rng.random() < 0.4:
        kw.update(inertia=mass * radius * radius * rng.uniform(0.2, 1), mass=mass)
        tags.append("inertia")
    else:
        kw.update(shape=rng.choice(("disc", "ring", "sphere", "cone")), mass=mass, radius=radius)
        if kw["shape"] == "cone" and rng.random() < 0.5:
            kw["height"] = radius * mag(rng, -0.5, 0.5)
        tags.append("shape")
    kw["spin"] = math.sqrt(G0 / radius) * mag(rng, -1, 3)
    if rng.random() < 0.2:
        kw["torque"] = mass * G0 * radius * mag(rng, -2, 0.5)
        if "inertia" in kw:
            del kw["mass"]
        tags.append("torque")
    else:
        kw["cm_distance"] = radius * mag(rng, -1, 0.5)
        if rng.random() < 0.35:
            kw["inertia_perp"] = mass * (kw["cm_distance"] ** 2 + radius * radius * rng.uniform(0.1, 1))
            tags.append("inertia_perp")
    x = rng.random()
    kw["tilt"] = 0.0 if x < 0.1 else math.pi / 2 if x < 0.25 else math.pi if x < 0.3 else rng.uniform(0, math.pi)
    if rng.random() < 0.15:
        kw.pop("tilt")
    if rng.random() < 0.15:
        kw["g"] = rng.uniform(1, 25)
    return kw, tags

def check_gyro(kw: dict, report, c: Checker) -> None:
    res, inp = values(report), inputs(report)
    spin, tilt, g = inp["spin"], inp.get("tilt", math.pi / 2), inp.get("g", G0)
    inertia = body_moment(kw, inp)
    L = res["L"]
    c.eq("L = I ω_s", L, inertia * spin)
    if "torque" in inp:
        c.eq("omega_p = τ/(L sin θ)", res.get("omega_p"), inp["torque"] / (L * math.sin(tilt)))
        if res.get("omega_p"):
            c.eq("period_p = 2π/|Ω|", res.get("period_p"), TWO_PI / abs(res["omega_p"]))
        return
    weight_torque = inp["mass"] * g * inp["cm_distance"]
    c.eq("omega_p = mgr/(I ω_s)", res.get("omega_p"), weight_torque / L)
    slow, fast = res.get("omega_p_slow"), res.get("omega_p_fast")
    if slow is not None:
        c.eq("period_p = 2π/|Ω_slow|", res.get("period_p"), TWO_PI / abs(slow))
    elif "omega_p_slow" not in res and res.get("omega_p"):
        c.eq("period_p = 2π/|Ω| (no exact rates)", res.get("period_p"), TWO_PI / abs(res["omega_p"]))
    perp = inp.get("inertia_perp")
    if perp is None:
        return
    cos_t = 0.0 if abs(tilt - math.pi / 2) <= 4.5e-16 else math.cos(tilt)
    a = perp * cos_t
    if slow is not None:
        c.eq("I⊥cos θ Ω_slow² − L Ω_slow + mgr = 0", a * slow * slow - L * slow + weight_torque, 0.0, a * slow * slow, L * slow, weight_torque)
    if fast is not None:
        c.eq("Ω_slow + Ω_fast = L/(I⊥ cos θ)", slow + fast, L / a, slow, fast)
        c.eq("Ω_slow Ω_fast = mgr/(I⊥ cos θ)", slow * fast, weight_torque / a)
    if cos_t > 0:
        c.eq("spin_min = √(4 I⊥ mgr cos θ)/I", res.get("spin_min"), math.sqrt(4 * perp * weight_torque * cos_t) / inertia)
        c.true("a steady precession ⇔ ω_s ≥ spin_min", (slow is not None) == (spin >= res["spin_min"]) or abs(spin / res["spin_min"] - 1) < 1e-12,
               f"slow {slow}, spin {spin}, spin_min {res['spin_min']}")
