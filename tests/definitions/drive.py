"""drive: the draws (a rotating load, a mass on a drum or a screw, what resists; a run-up at a
constant α, on the motor's line or at a constant torque; a move profile) and the definitions.

The definitions (docs/drive.md): J_lin = m r² or m(p/2π)²; J_r = J_g + (J_body + J_lin)/N²;
J_total = J_m + J_r; inertia_ratio = J_r/J_m; ratio_optimal = √((J_body + J_lin)/J_m); the load
torque T = T_L + F·r with F = F_ext + μmg cos θ + mg sin θ; at the motor T/(Nη), or ηT/N where
T < 0; torque_hold = mg sin θ·r/N; at a constant α, τ = (J_m + J_g)α + G(Jα/N + T)/N with
G(x) = x/η (x ≥ 0), ηx (x < 0); t = ω₁/α, θ = ω₁t/2, revs = θ/2π, KE = ½J_total ω₁²,
work_load = Tθ/N, work_motor = KE + work_load + work_loss (= τθ at a constant α), the peak power
τω₁; on the line, α₀ = (τ_s − T_e)/J_e, ω_ss where τ_s(1 − ω/ω_nl) = T_e, τ_m = J_e ω_nl/τ_s;
a move: t_cycle = Σtᵢ, θ = ω(t_a/2 + t_r + t_d/2), travel = θr/N, speed_top = ωr/N,
α_a = ω/t_a, α_d = ω/t_d, the phase torques as above, torque_peak = max|τᵢ|, τ_rms² = Στᵢ²tᵢ/t_cycle,
P̄ = ω(τ_a t_a/2 + τ_r t_r + τ_d t_d/2)/t_cycle, rms_to_rated = τ_rms/τ_rated.
"""

from __future__ import annotations

import math
import random

import taucli
from definitions.check import G0, TWO_PI, Checker, inputs, mag, signed, values

DRUM, SCREW = "drum", "screw"


def draw_drive(rng: random.Random) -> tuple[dict, list[str]]:
    kw: dict = {}
    tags: list[str] = []
    kw["motor_inertia"] = mag(rng, -6, -2)
    stages = rng.choice((0, 1, 1, 1, 2, 3))
    if stages:
        kw["ratio"] = [mag(rng, -0.3, 1.3) for _ in range(stages)]
        tags.append("stages" if stages > 1 else "ratio")
    if rng.random() < 0.6:
        kw["efficiency"] = rng.uniform(0.3, 1.0)
        tags.append("efficiency")
    if rng.random() < 0.2:
        kw["gear_inertia"] = kw["motor_inertia"] * mag(rng, -2, 0)
        tags.append("gear")
    x = rng.random()
    if x < 0.35:
        kw["load_inertia"] = mag(rng, -4, 1)
        tags.append("load inertia")
    elif x < 0.5:
        kw.update(shape=rng.choice(("disc", "ring")), mass=mag(rng, -1, 2), radius=mag(rng, -2, 0))
        tags.append("body")
    mover = rng.choice((None, DRUM, SCREW)) if "load_inertia" in kw or "shape" in kw else rng.choice((DRUM, SCREW))
    if mover is not None:
        kw["drum_radius" if mover == DRUM else "lead"] = mag(rng, -2.5, -0.5)
        kw["load_mass"] = mag(rng, -1, 3)
        tags.append(mover)
        if rng.random() < 0.4:
            kw["incline"] = rng.choice((math.pi / 2, -math.pi / 2, rng.uniform(-math.pi / 2, math.pi / 2)))
            tags.append("incline")
        if rng.random() < 0.4:
            kw["mu"] = rng.uniform(0, 0.5)
            tags.append("mu")
        if ("incline" in kw or "mu" in kw) and rng.random() < 0.3:
            kw["g"] = rng.uniform(1, 25)
        if rng.random() < 0.3:
            kw["load_force"] = signed(rng, mag(rng, 0, 3))
            tags.append("force")
    if rng.random() < 0.4:
        kw["load_torque"] = signed(rng, mag(rng, -2, 1.5))
        tags.append("load torque")
    mode = rng.choice(("reflect", "alpha", "in_time", "line", "constant", "times", "trapezoid", "trapezoid"))
    tags.append(mode)
    top = mag(rng, 1, 3.5)
    if mode == "alpha":
        kw["alpha"] = mag(rng, 1, 4)
        if rng.random() < 0.6:
            kw["until_omega"] = top
    elif mode == "in_time":
        kw.update(until_omega=top, in_time=mag(rng, -2, 0.5))
    elif mode in ("line", "constant"):
        stall = mag(rng, -1.5, 1.5)
        if mode == "line":
            kw.update(stall_torque=stall, no_load_speed=top * mag(rng, 0, 0.5))
        else:
            kw["motor_torque"] = stall
        if rng.random() < 0.8:
            kw["until_omega"] = top * rng.uniform(0.05, 1.1)
    elif mode == "times":
        kw.update(accel_time=mag(rng, -2, 0), run_time=rng.choice((0.0, mag(rng, -2, 0.5))), dwell_time=rng.choice((0.0, mag(rng, -2, 0.5))))
        if rng.random() < 0.5:
            kw["decel_time"] = mag(rng, -2, 0)
        if rng.random() < 0.7:
            kw["until_omega"] = top
        else:
            kw["move_angle"] = top * mag(rng, -1.5, 0.5)
    elif mode == "trapezoid":
        kw.update(move_angle=top * mag(rng, -2, 1), alpha=mag(rng, 2, 4), dwell_time=rng.choice((0.0, mag(rng, -2, 0))))
        if rng.random() < 0.8:
            kw["until_omega"] = top
    if mode in ("alpha", "in_time", "line", "constant") and rng.random() < 0.6:
        kw["energy"] = True
        tags.append("energy")
    if mode in ("times", "trapezoid"):
        if rng.random() < 0.4:
            kw["rated_torque"] = mag(rng, -2, 1)
            tags.append("rated")
        if rng.random() < 0.2:
            kw["peak_torque"] = mag(rng, -1, 1.5)
    return kw, tags


def _train(kw: dict, inp: dict, res: dict) -> dict:
    """The train as the definitions see it, from the report's echo of its inputs (SI)."""
    stages = [value for key, value in inp.items() if key == "ratio" or (key.startswith("ratio") and key[5:].isdigit())]
    n = math.prod(stages) if stages else 1.0
    eta = inp.get("efficiency", 1.0)
    lever = inp["drum_radius"] if "drum_radius" in inp else inp["lead"] / TWO_PI if "lead" in inp else None
    body = 0.0
    if "load_inertia" in inp:
        body = inp["load_inertia"]
    elif kw.get("shape"):
        body = taucli.inertia(kw["shape"], mass=inp["mass"], radius=inp["radius"]).results["I"].value
    mass = inp.get("load_mass")
    linear = mass * lever * lever if mass is not None else 0.0
    g = inp.get("g", G0)
    theta = inp.get("incline", 0.0)
    cos, sin = (0.0, math.copysign(1.0, theta)) if abs(abs(theta) - math.pi / 2) <= 4.5e-16 else (math.cos(theta), math.sin(theta))
    friction = inp.get("mu", 0.0) * mass * g * cos if mass is not None else 0.0
    gravity = mass * g * sin if mass is not None else 0.0
    force = inp.get("load_force", 0.0) + friction + gravity
    torque = inp.get("load_torque", 0.0) + (force * lever if lever is not None else 0.0)
    return dict(n=n, eta=eta, lever=lever, body=body, linear=linear, load=body + linear, torque=torque, gravity_torque=gravity * (lever or 0.0),
                jm=inp.get("motor_inertia"), jg=inp.get("gear_inertia", 0.0), scale=max(abs(inp.get("load_torque", 0.0)), abs(force * (lever or 0.0))))


def _passed(t: dict, demand: float) -> float:
    return demand / (t["n"] * t["eta"]) if demand >= 0 else t["eta"] * demand / t["n"]


def _motor_torque(t: dict, alpha: float) -> float:
    return (t["jm"] + t["jg"]) * alpha + _passed(t, t["load"] * alpha / t["n"] + t["torque"])


def check_drive(kw: dict, report, c: Checker) -> None:
    res, inp = values(report), inputs(report)
    t = _train(kw, inp, res)
    n, jm = t["n"], t["jm"]
    reflected = t["jg"] + t["load"] / (n * n)
    if t["linear"]:
        c.eq("J_lin = m r² (m(p/2π)²)", res.get("linear_inertia"), t["linear"])
    c.eq("J_r = J_g + J/N²", res.get("reflected_inertia"), reflected, t["jg"], t["load"] / (n * n))
    if "ratio_total" in res:
        c.eq("N = ΠNᵢ", res["ratio_total"], n)
    if jm:
        c.eq("J_total = J_m + J_r", res.get("total_inertia"), jm + reflected, jm, reflected)
        c.eq("inertia_ratio = J_r/J_m", res.get("inertia_ratio"), res["reflected_inertia"] / jm)
        if t["load"]:
            c.eq("ratio_optimal = √(J/J_m)", res.get("ratio_optimal"), math.sqrt(t["load"] / jm))
    # the load's torque: a sum of terms, so its scale is the largest
    scale = t["scale"] / n
    c.eq("load_torque_motor = T/(Nη), ηT/N regenerating", res.get("load_torque_motor"), _passed(t, t["torque"]), scale / t["eta"])
    if t["gravity_torque"]:
        c.eq("torque_hold = mg sin θ r/N", res.get("torque_hold"), t["gravity_torque"] / n)
    if "alpha0" in res:
        _check_line(kw, inp, res, t, c)
    elif "omega_top" in res:
        _check_move(inp, res, t, c, scale)
    elif "torque_accel" in res:
        alpha = res["alpha"]
        if "in_time" in inp:
            c.eq("α = ω₁/t", alpha, inp["until_omega"] / inp["in_time"])
        tau = _motor_torque(t, alpha)
        c.eq("τ = (J_m + J_g)α + G(Jα/N + T)/N", res["torque_accel"], tau, (jm + t["jg"]) * alpha, t["load"] * alpha / (n * n * t["eta"]), scale / t["eta"])
        if res.get("t_accel") is not None:
            w = inp["until_omega"]
            c.eq("t = ω₁/α", res["t_accel"], w / alpha)
            c.eq("θ = ω₁t/2", res["theta_accel"], w * res["t_accel"] / 2)
            c.eq("power_peak = τω₁", res["power_peak"], max(res["torque_accel"] * w, 0.0))
            if "KE" in res:
                c.eq("work_motor = τθ", res["work_motor"], res["torque_accel"] * res["theta_accel"])
            _check_energy(res, inp["until_omega"], t, c)


def _check_energy(res: dict, omega: float, t: dict, c: Checker) -> None:
    if res.get("theta_accel") is None:
        return
    c.eq("revs = θ/2π", res["revs_accel"], res["theta_accel"] / TWO_PI)
    if "KE" not in res:
        return
    c.eq("KE = ½J_total ω²", res["KE"], ((t["jm"] or 0.0) + t["jg"] + t["load"] / t["n"] ** 2) * omega * omega / 2)
    c.eq("work_load = Tθ/N", res["work_load"], t["torque"] * res["theta_accel"] / t["n"])
    c.true("work_loss ≥ 0", res["work_loss"] >= -1e-12 * abs(res["work_motor"]), f"work_loss {res['work_loss']}")
    c.eq("work_motor = KE + work_load + work_loss", res["work_motor"], res["KE"] + res["work_load"] + res["work_loss"],
         res["KE"], res["work_load"], res["work_loss"])


def _check_line(kw: dict, inp: dict, res: dict, t: dict, c: Checker) -> None:
    stall = inp.get("stall_torque", inp.get("motor_torque"))
    n, eta = t["n"], t["eta"]
    j_in = t["jm"] + t["jg"]
    # from rest the motor gives τ_s; J_e, T_e of the way the power flows then
    drive = (j_in + t["load"] / (n * n * eta), t["torque"] / (n * eta))
    back = (j_in + eta * t["load"] / (n * n), eta * t["torque"] / n)
    switch = None if t["load"] == 0 else -j_in * t["torque"] * n / t["load"]
    driving = t["torque"] >= 0 if switch is None else stall >= switch
    j_e, t_e = drive if driving else back
    if stall <= t_e:
        # going down, friction (T less gravity's part) holds against gravity and the load drives the motor through η (#42 item 11)
        down = t["gravity_torque"] - (t["torque"] - t["gravity_torque"])
        if down > 0 and eta * down / n > stall:
            c.eq("α₀ = (τ_s − ηT_down/N)/(J_m + J_g + ηJ/N²), the load running back", res["alpha0"], (stall - eta * down / n) / back[0], stall / back[0],
                 eta * down / n / back[0])
            c.true("running back never reaches ω₁", res.get("t_accel") is None, str(res.get("t_accel")))
            return
        c.true("cannot start ⇔ τ_s ≤ T_e", res["alpha0"] == 0 and res.get("t_accel") is None, str(res.get("t_accel")))
        return
    c.eq("α₀ = (τ_s − T_e)/J_e", res["alpha0"], (stall - t_e) / j_e, stall / j_e, t_e / j_e)
    if "no_load_speed" in inp:
        w_nl = inp["no_load_speed"]
        c.eq("τ_m = J_e ω_nl/τ_s", res["time_constant"], j_e * w_nl / stall)
        final_e = back[1] if (driving and switch is not None and 0 < switch < stall) else t_e
        steady = res.get("omega_steady")
        if steady is not None:
            c.eq("τ_s(1 − ω_ss/ω_nl) = T_e", stall * (1 - steady / w_nl), final_e, stall, final_e)
    if res.get("t_accel") is not None:
        _check_energy(res, inp["until_omega"], t, c)
        if "motor_torque" in inp:
            c.eq("t = ω₁/α (constant torque)", res["t_accel"], inp["until_omega"] / res["alpha0"])


def _check_move(inp: dict, res: dict, t: dict, c: Checker, scale: float) -> None:
    w, ta, tr, td = res["omega_top"], res["t_accel"], res["t_run"], res["t_decel"]
    tw = inp.get("dwell_time", 0.0)
    c.eq("t_cycle = t_a + t_r + t_d + t_w", res["t_cycle"], ta + tr + td + tw, ta, tr, td, tw)
    c.eq("θ = ω(t_a/2 + t_r + t_d/2)", res["theta_move"], w * (ta / 2 + tr + td / 2), w * ta, w * tr, w * td)
    if "move_angle" in inp:
        c.eq("the move's angle is the one asked for", res["theta_move"], inp["move_angle"])
    if "until_omega" in inp and res["t_run"] > 0:
        c.eq("the top speed is the one asked for", w, inp["until_omega"])
    if t["lever"] is not None:
        c.eq("travel = θr/N", res.get("travel"), res["theta_move"] * t["lever"] / t["n"])
        c.eq("speed_top = ωr/N", res.get("speed_top"), w * t["lever"] / t["n"])
    c.eq("α_a = ω/t_a", res["alpha"], w / ta)
    c.eq("α_d = ω/t_d", res["alpha_decel"], w / td)
    up, down = _motor_torque(t, res["alpha"]), _motor_torque(t, -res["alpha_decel"])
    j_in = t["jm"] + t["jg"]
    c.eq("τ_a = (J_m + J_g)α_a + G(Jα_a/N + T)/N", res["torque_accel"], up, j_in * res["alpha"], t["load"] * res["alpha"] / (t["n"] ** 2 * t["eta"]), scale / t["eta"])
    c.eq("τ_d = −(J_m + J_g)α_d + G(−Jα_d/N + T)/N", res["torque_decel"], down, j_in * res["alpha_decel"], t["load"] * res["alpha_decel"] / t["n"] ** 2, scale / t["eta"])
    run = res["load_torque_motor"]
    hold = t["gravity_torque"] / t["n"]
    phases = [(res["torque_accel"], ta), (run, tr), (res["torque_decel"], td), (hold, tw)]
    c.eq("torque_peak = max |τᵢ|", res["torque_peak"], max(abs(tau) for tau, time in phases if time > 0))
    top = max(abs(tau) for tau, _ in phases)
    if top:
        rms = top * math.sqrt(math.fsum((tau / top) ** 2 * time for tau, time in phases) / res["t_cycle"])
        c.eq("τ_rms = √(Στᵢ²tᵢ/t_cycle)", res["torque_rms"], rms)
    terms = (res["torque_accel"] * ta / 2, run * tr, res["torque_decel"] * td / 2)
    c.eq("P̄ = ω(τ_a t_a/2 + τ_r t_r + τ_d t_d/2)/t_cycle", res["power_mean"], w * math.fsum(terms) / res["t_cycle"],
         *(w * x / res["t_cycle"] for x in terms))
    powers = [p for tau, time in phases[:3] if time > 0 for p in (tau * w,)]
    c.eq("power_peak = max(τᵢω, 0)", res["power_peak"], max(0.0, *powers))
    c.eq("power_regen = max(−τᵢω, 0)", res["power_regen"], max(0.0, *(-p for p in powers)))
    if "rated_torque" in inp:
        c.eq("rms_to_rated = τ_rms/τ_rated", res["rms_to_rated"], res["torque_rms"] / inp["rated_torque"])
    if "rated_torque" in inp or "peak_torque" in inp:
        within = (res.get("rms_to_rated") is None or res["rms_to_rated"] <= 1) and res["torque_peak"] <= inp.get("peak_torque", math.inf)
        c.true("within_rating ⇔ τ_rms ≤ τ_rated and τ_peak ≤ τ_max", res["within_rating"] == within, f"{res['within_rating']} {within}")
