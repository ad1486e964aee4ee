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
    if mode in ("particles", "both") and rng.random() < 0.3:  # the particles by their momenta, p = mv
        kw["momentum"] = [tuple(m * x for x in v) for m, v in zip(kw.pop("mass"), kw.pop("velocity"))]
        tags.append("momentum")
    if mode != "plane" and rng.random() < 0.25:
        kw["about"] = vector(mag(rng, -2, 1))
        tags.append("about")
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
    about = kw.get("about", (0.0, 0.0, 0.0))
    rs = [tuple(x - a for x, a in zip(r, about)) for r in kw.get("r", [])]  # the positions from the point (--about)
    momenta = kw.get("momentum") or [tuple(m * x for x in v) for m, v in zip(kw.get("mass", []), kw.get("velocity", []))]
    velocities = momenta
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
        terms = [cross(r, p) for r, p in zip(particle_r, momenta)]
        scale = math.fsum(math.hypot(*r) * math.hypot(*p) for r, p in zip(particle_r, momenta))
        for i, key in enumerate(("L_x", "L_y", "L_z")):
            c.eq(f"{key} = Σ ((r − a) × p){key[-1]}", res[key], math.fsum(t[i] for t in terms), scale)
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
    if rng.random() < 0.25:  # a rotor on a machine: the vehicle turns its axis at a given rate
        for key in ("torque", "cm_distance", "inertia_perp", "g"):
            kw.pop(key, None)
        if "inertia" in kw:
            kw.pop("mass", None)
        kw["spin"] = signed(rng, kw["spin"], 0.2)
        kw["precession"] = mag(rng, -3, 1)
        if rng.random() < 0.6:
            kw.pop("tilt", None)
            kw["spin_sense"] = rng.choice([f"{t}-from-{e}" for t in ("cw", "ccw") for e in ("rear", "front", "left", "right", "above", "below")])
            kw["turn"] = rng.choice(("left", "right", "pitch-up", "pitch-down", "roll-left", "roll-right"))
            if rng.random() < 0.4:
                kw["lean"] = rng.uniform(-1.2, 1.2)
            tags.append("senses")
            if rng.random() < 0.3:
                sense = rng.choice([f"{t}-from-{e}" for t in ("cw", "ccw") for e in ("rear", "front", "left", "right", "above", "below")])
                kw["rotor"] = [f"inertia={mag(rng, -2, 1)!r}kg*m^2 spin={signed(rng, mag(rng, 0, 3), 0.2)!r}rad/s sense={sense}"]
                tags.append("rotors")
        if rng.random() < 0.5:
            kw["bearing_span"] = mag(rng, -1, 1)
        tags.append("precession")
    return kw, tags


# A rotor's spin axis, and the axis of each turn, in the vehicle's axes (x forward, y left, z up),
# by the right-hand rule: a rotor turning clockwise seen from behind spins forward.
VIEWER = {"rear": (-1, 0, 0), "front": (1, 0, 0), "left": (0, 1, 0), "right": (0, -1, 0), "above": (0, 0, 1), "below": (0, 0, -1)}
TURNED_ABOUT = {"left": (0, 0, 1), "right": (0, 0, -1), "pitch-up": (0, -1, 0), "pitch-down": (0, 1, 0), "roll-right": (1, 0, 0), "roll-left": (-1, 0, 0)}


def check_machine(kw: dict, inp: dict, res: dict, inertia: float, c: Checker) -> None:
    """C = |L × Ω| = Iω_sΩ sin θ, θ between the spin axis and the turn's; F = C/l at each bearing."""
    L, rate = res["L"], inp["precession"]
    if "spin_sense" in kw:
        turn, _, viewer = kw["spin_sense"].split("-", 2)
        axis = tuple((-1 if turn == "cw" else 1) * x for x in VIEWER[viewer])
        lean = inp.get("lean", 0.0)
        axis = (axis[0], axis[1] * math.cos(lean) - axis[2] * math.sin(lean), axis[1] * math.sin(lean) + axis[2] * math.cos(lean))
        momentum = [inertia * inp["spin"] * x for x in axis]
        scale = abs(L)
        for text in kw.get("rotor", []):  # "inertia=… spin=… sense=…": each rotor's Iω along its own sense, after the lean
            fields = dict(item.split("=") for item in text.split())
            turn, _, viewer = fields["sense"].split("-", 2)
            other = tuple((-1 if turn == "cw" else 1) * x for x in VIEWER[viewer])
            other = (other[0], other[1] * math.cos(lean) - other[2] * math.sin(lean), other[1] * math.sin(lean) + other[2] * math.cos(lean))
            spin_i = float(fields["inertia"].removesuffix("kg*m^2")) * float(fields["spin"].removesuffix("rad/s"))
            momentum = [m + spin_i * x for m, x in zip(momentum, other)]
            scale += abs(spin_i)
        c.eq("couple = |ΣL × Ω|", res.get("couple"), math.hypot(*cross(momentum, TURNED_ABOUT[kw["turn"]])) * rate, scale * rate)
    else:
        sine = math.sin(inp.get("tilt", math.pi / 2))
        c.eq("couple = Iω_sΩ sin θ", res.get("couple"), abs(inertia * inp["spin"]) * rate * sine, abs(L) * rate)
    if "bearing_span" in inp:
        c.eq("bearing_force = couple / span", res.get("bearing_force"), res["couple"] / inp["bearing_span"])


def check_gyro(kw: dict, report, c: Checker) -> None:
    res, inp = values(report), inputs(report)
    spin, tilt, g = inp["spin"], inp.get("tilt", math.pi / 2), inp.get("g", G0)
    inertia = body_moment(kw, inp)
    L = res["L"]
    c.eq("L = I ω_s", L, inertia * spin)
    if "precession" in inp:
        check_machine(kw, inp, res, inertia, c)
        return
    if "torque" in inp:
        c.eq("omega_p = τ/(L sin θ)", res.get("omega_p"), inp["torque"] / (L * math.sin(tilt)))
        if res.get("omega_p"):
            c.eq("period_p = 2π/|Ω|", res.get("period_p"), TWO_PI / abs(res["omega_p"]))
        return
    weight_torque = inp["mass"] * g * inp["cm_distance"]
    c.eq("omega_p = mgr/(I ω_s)", res.get("omega_p"), weight_torque / L)
    slow, fast = res.get("omega_p_slow"), res.get("omega_p_fast")
    steady = slow if "omega_p_slow" in res else res.get("omega_p")
    if steady is not None and res.get("L_orbital") is not None:
        # The centre of mass goes round a circle of radius r sin θ at Ω: L_orb = |r × mv| = m r (Ω r sin θ)
        circle, m = inp["cm_distance"] * math.sin(tilt), inp["mass"]
        # sin θ is taken exact at 180° (math.sin(π) is 1.2e-16): the scale is the size at sin θ = 1
        c.eq("L_orbital = m r (Ω r sin θ)", res["L_orbital"], m * inp["cm_distance"] * abs(steady) * circle, m * inp["cm_distance"] ** 2 * abs(steady))
        c.eq("pivot_force_vertical = mg", res["pivot_force_vertical"], m * g)
        c.eq("pivot_force_horizontal = mΩ²(r sin θ)", res["pivot_force_horizontal"], m * steady * steady * circle, m * steady * steady * inp["cm_distance"])
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
