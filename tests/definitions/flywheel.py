"""flywheel: the draws (the mean speed, the band or a rim's speed; two of I, ΔE, Cs; a punch's
energy; a rim with its density) and the definitions.

The definitions (docs/flywheel.md): ω_mean = (ω_max + ω_min)/2, Cs = (ω_max − ω_min)/ω_mean,
ΔE = ½I(ω_max² − ω_min²) (the kinetic energy between the ends), KE_mean = ½Iω_mean², a punch's
ΔE = E(1 − f), a rim's m = I/R² (ΔE = m(ω_max² − ω_min²)R²/2 for a rim alone), v = ω R,
σ = ρv², A = m/(2πRρ), margin = σ_allow/σ_max.
"""

from __future__ import annotations

import math
import random

from definitions.check import Checker, inputs, mag, values


def draw_flywheel(rng: random.Random) -> tuple[dict, list[str]]:
    kw: dict = {}
    tags: list[str] = []
    speed = mag(rng, 0, 3)
    which = rng.choice(("mean", "mean", "band", "rim"))
    tags.append(which)
    cs = mag(rng, -4, -0.5)
    if which == "band":
        kw["omega_max"], kw["omega_min"] = speed * (1 + cs / 2), speed * (1 - cs / 2)
    elif which == "rim":
        kw["rim_speed"] = mag(rng, 0, 2)
        if rng.random() < 0.5:
            kw["rim_radius"] = mag(rng, -1, 0.5)
            tags.append("rim radius")
    else:
        kw["omega_mean"] = speed
    unknown = rng.choice(("I", "energy", "cs"))
    tags.append("solve " + unknown)
    if unknown != "I" and not (which == "rim" and "rim_radius" not in kw):
        if rng.random() < 0.3:
            kw.update(shape="ring", mass=mag(rng, 0, 3), radius=mag(rng, -1, 0.5))
        else:
            kw["inertia"] = mag(rng, -1, 3)
    if unknown != "energy":
        if rng.random() < 0.3:
            kw["energy_per_cycle"], kw["punch_fraction"] = mag(rng, 2, 5), rng.uniform(0, 0.9)
            tags.append("punch")
        else:
            kw["energy_swing"] = mag(rng, 1, 5)
    if unknown != "cs" and which != "band":
        if rng.random() < 0.3:
            kw["speed_variation"] = cs / 2
            tags.append("±")
        else:
            kw["fluctuation"] = cs
    if which != "rim" and rng.random() < 0.5:
        kw["rim_radius"] = mag(rng, -1, 0.5)
    if ("rim_radius" in kw or which == "rim") and rng.random() < 0.6:
        kw["density"] = mag(rng, 3, 4)
        tags.append("density")
        if rng.random() < 0.5:
            kw["allowable_stress"] = mag(rng, 5, 8)
    return kw, tags


def check_flywheel(kw: dict, report, c: Checker) -> None:
    res, inp = values(report), inputs(report)
    cs, swing = res["cs"], res["energy_swing"]
    if "omega_max" in inp:
        c.eq("Cs = (ω_max − ω_min)/ω_mean", cs, (inp["omega_max"] - inp["omega_min"]) / ((inp["omega_max"] + inp["omega_min"]) / 2))
    if "speed_variation" in inp:
        c.eq("Cs = 2 × (±x)", cs, 2 * inp["speed_variation"])
    if "energy_per_cycle" in inp:
        c.eq("ΔE = E(1 − f)", swing, inp["energy_per_cycle"] * (1 - inp.get("punch_fraction", 0.0)))
    if "I" in res:
        top, bottom, mean = res["omega_max"], res["omega_min"], res["omega_mean"]
        c.eq("ω_mean = (ω_max + ω_min)/2", mean, (top + bottom) / 2, top)
        c.eq("Cs = (ω_max − ω_min)/ω_mean (results)", cs, (top - bottom) / mean, top / mean)
        c.eq("ΔE = ½I(ω_max² − ω_min²)", swing, 0.5 * res["I"] * (top * top - bottom * bottom), 0.5 * res["I"] * top * top)
        c.eq("KE_mean = ½Iω_mean²", res["KE_mean"], 0.5 * res["I"] * mean * mean)
        if "rim_radius" in inp:
            c.eq("mass = I/R²", res["mass"], res["I"] / inp["rim_radius"] ** 2)
            c.eq("rim_speed = ω_mean R", res["rim_speed"], mean * inp["rim_radius"])
    elif "mass" in res:
        v = inp["rim_speed"]
        c.eq("ΔE = ½m((v(1 + Cs/2))² − (v(1 − Cs/2))²)", swing, 0.5 * res["mass"] * ((v * (1 + cs / 2)) ** 2 - (v * (1 - cs / 2)) ** 2), 0.5 * res["mass"] * v * v)
    if "hoop_stress" in res:
        c.eq("hoop_stress = ρv²", res["hoop_stress"], inp["density"] * res["rim_speed"] ** 2)
        c.eq("hoop_stress_max = ρv_max²", res["hoop_stress_max"], inp["density"] * res["rim_speed_max"] ** 2)
        if "rim_area" in res:
            c.eq("mass = 2πR·A·ρ", res["mass"], 2 * math.pi * inp["rim_radius"] * res["rim_area"] * inp["density"])
        if "stress_margin" in res:
            c.eq("stress_margin = σ_allow/σ_max", res["stress_margin"], inp["allowable_stress"] / res["hoop_stress_max"])
