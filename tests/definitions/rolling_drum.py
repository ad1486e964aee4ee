"""rolling: a yo-yo whose string is wound at its top on a drum that turns (#46 item 7): the draws
(over the pulled yo-yo's) and the definitions."""

from __future__ import annotations

import random

from definitions.check import G0, Checker, mag


def draw_drum_yoyo(rng: random.Random) -> tuple[dict, list[str]]:
    """A yo-yo whose string is wound at its top on a drum that turns (#46 item 7): the drum by its
    mass or its I, with or without axle friction (holding it or not), pulled or not, after a time
    or a drop."""
    from definitions.rolling import draw_pulled_yoyo  # deferred: rolling imports this module's check

    kw, tags = draw_pulled_yoyo(rng)
    tags[0] = "drum yoyo"
    kw.pop("v0", None)
    if "v0" in tags:
        tags.remove("v0")
    if rng.random() < 0.4:
        kw.pop("pull")
        kw.pop("pull_at", None)
        tags.append("no pull")
    mass, radius = kw["mass"], kw["radius"]
    drum_radius = radius * mag(rng, -1, 1)
    if rng.random() < 0.5:
        kw["drum_mass"] = mass * mag(rng, -1.5, 1.5)
        tags.append("drum mass")
        if rng.random() < 0.7:
            kw["drum_radius"] = drum_radius
    else:
        kw.update(drum_inertia=mass * drum_radius * drum_radius * mag(rng, -2, 2), drum_radius=drum_radius)
        tags.append("drum inertia")
    if "drum_radius" in kw and rng.random() < 0.4:
        kw["drum_friction"] = mass * G0 * kw["drum_radius"] * rng.uniform(0, 0.8)
        tags.append("drum friction")
    return kw, tags


def check_drum_yoyo(kw: dict, res: dict, inp: dict, q: float, m: float, r: float | None, g: float, c: Checker) -> None:
    """The body (m a = m g − T − F, I α = T r − F d), the drum (I_d α_d = T R − τ_f while it turns,
    α_d = 0 while its friction holds it: T R ≤ τ_f), the string (a = r α + R α_d); from rest, v = a t,
    ω = α t, ω_d = α_d t; KE = KE_trans + KE_rot + KE_drum = m g x + W_pull − W_friction."""
    a, T, alpha, alpha_d = res["a"], res["T"], res.get("alpha"), res.get("alpha_drum")
    F, d = inp.get("pull", 0.0), inp.get("pull_at", 0.0)
    R, tau = inp.get("drum_radius"), inp.get("drum_friction", 0.0)
    I_d = inp["drum_inertia"] if "drum_inertia" in inp else inp["drum_mass"] * R * R / 2 if R is not None else None
    I = q * m * r * r if r is not None else None
    c.eq("m a = m g − T − F", m * a, m * g - T - F, m * g, T, F)
    c.true("T ≥ 0 (a string only pulls)", T >= 0, f"T = {T}")
    if I is not None and alpha is not None:
        c.eq("I α = T r − F d", I * alpha, T * r - F * d, T * r, F * d)
        if R is not None and alpha_d is not None:
            c.eq("a = r α + R α_d (the string)", a, r * alpha + R * alpha_d, r * alpha, R * alpha_d)
    if R is not None and alpha_d is not None:
        if alpha_d == 0 and tau > 0:
            c.true("the drum held: T R ≤ τ_f", T * R <= tau * (1 + 1e-12), f"T R = {T * R}, τ_f = {tau}")
        else:
            c.eq("I_d α_d = T R − τ_f", I_d * alpha_d, T * R - tau, T * R, tau)
    if "drum_mass" in inp and F == 0 and tau == 0:  # I_d/(m R²) = M/(2m) for a uniform drum: no radius needed
        Q = inp["drum_mass"] / (2 * m)
        c.eq("a = g (q + Q)/(q Q + q + Q) (a uniform drum, no pull)", a, g * (q + Q) / (q * Q + q + Q))
    span = inp.get("time", res.get("t"))
    if span is None:
        return
    v = res["v"]
    c.eq("v = a t (from rest)", v, a * span)
    if "height" in inp:
        c.eq("h = ½ a t²", a * span * span / 2, inp["height"])
    x = inp.get("height", res.get("drop"))
    if alpha is not None:
        c.eq("omega = α t (the body's, not v/r)", res.get("omega"), alpha * span)
    if alpha_d is not None:
        c.eq("omega_drum = α_d t", res.get("omega_drum"), alpha_d * span)
    c.eq("KE = KE_trans + KE_rot + KE_drum", res["KE"], res["KE_trans"] + res["KE_rot"] + res["KE_drum"])
    c.eq("KE_trans = ½ m v²", res["KE_trans"], m * v * v / 2)
    if I is not None and res.get("omega") is not None:
        c.eq("KE_rot = ½ I ω²", res["KE_rot"], I * res["omega"] ** 2 / 2)
    if I_d is not None and res.get("omega_drum") is not None:
        c.eq("KE_drum = ½ I_d ω_d²", res["KE_drum"], I_d * res["omega_drum"] ** 2 / 2)
    work, lost = res.get("work_pull", 0.0), res.get("work_drum_friction", 0.0)
    c.eq("KE = m g x + W_pull − W_friction (body and drum)", res["KE"], m * g * x + work - lost, m * g * x, work, lost)
    if R is not None and alpha_d is not None and tau:
        c.eq("W_friction = τ_f θ_d", lost, tau * alpha_d * span * span / 2)
