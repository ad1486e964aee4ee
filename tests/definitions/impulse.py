"""impulse: the draws (τΔt = IΔω each way, the skater, what meets the body, a brake, a sampled torque) and the definitions."""

from __future__ import annotations

import math
import random
from itertools import pairwise
from pathlib import Path

from definitions.check import (
    BODY_KEYS,
    G0,
    Checker,
    body_moment,
    band_torque,
    contact_torques,
    draw_body,
    inputs,
    mag,
    point_checks,
    rim_of,
    signed,
    spec,
    total_mass,
    values,
)


def draw_impulse(rng: random.Random, folder) -> tuple[dict, list[str]]:
    """An impulse: τΔt = IΔω with each unknown (or all five, or too few), the skater, particles and
    couples, a brake or a face, a sampled torque; --at on any."""
    kw: dict = {}
    mode = rng.choice(("balance",) * 4 + ("skater", "meeting", "meeting", "braked", "profile"))
    tags = [mode]
    inertia, rim = draw_body(rng, kw)
    T, W = mag(rng, -2, 1), mag(rng, -1, 2.5)
    if mode == "balance":
        w0 = 0.0 if rng.random() < 0.15 else signed(rng, W * mag(rng, -0.5, 0.3))
        torque = signed(rng, inertia * W / T * mag(rng, -1, 0.5), 0.4)
        duration = T * mag(rng, -0.5, 0.5)
        w1 = w0 + torque * duration / inertia
        given = {"omega0": w0, "omega1": w1, "torque": torque, "duration": duration}
        x = rng.random()
        if x < 0.15:
            leave = []  # all five given
            tags.append("all five")
        elif x < 0.8:
            leave = [rng.choice(("inertia", "omega0", "omega1", "torque", "duration"))]
            tags.append("solve " + leave[0])
        else:
            leave = rng.sample(("inertia", "omega0", "omega1", "torque", "duration"), 2)
            tags.append("partial")
        for name, value in given.items():
            if name not in leave:
                kw[name] = value
        if "inertia" in leave:
            for key in BODY_KEYS:
                kw.pop(key, None)
    elif mode == "skater":
        kw["inertia_final"] = (inertia if "inertia" in kw else body_moment(kw)) * mag(rng, -1, 1)
        if rng.random() < 0.9:
            kw["omega0"] = signed(rng, W * mag(rng, -0.5, 0.5))
    elif mode == "meeting":
        if rng.random() < 0.85:
            kw["omega0"] = 0.0 if rng.random() < 0.2 else signed(rng, W * mag(rng, -0.5, 0.3))
        reach = rim or math.sqrt(inertia) * mag(rng, -0.5, 0.5)
        particles, couples = [], []
        for _ in range(rng.choice((0, 1, 1, 1, 2, 3))):
            m = inertia / reach ** 2 * mag(rng, -2, 0.5)
            fields = {"mass": (m, "kg"), "radius": (reach * rng.uniform(0.05, 1), "m")}
            kind = rng.choice(("stick", "stick", "angle", "ride", "leave", "rebound"))
            if kind != "ride":
                fields["speed"] = (signed(rng, W * reach * mag(rng, -0.5, 0.5)), "m/s")
            if kind == "angle":
                fields["angle"] = (rng.uniform(0, 180), "deg")
            elif (kind == "ride" and rng.random() < 0.6) or (kind == "stick" and rng.random() < 0.2):
                fields["radius_after"] = (reach * rng.uniform(0, 1), "m")
            elif kind == "leave":
                fields["speed_after"] = (signed(rng, W * reach * mag(rng, -1, 0.3), 0.4), "m/s")
            elif kind == "rebound":
                fields["e"] = (rng.uniform(0, 1), "")
            particles.append(spec(**fields))
            tags.append("particle " + kind)
        for _ in range(rng.choice((0, 0, 1, 2)) if particles else rng.choice((1, 1, 2))):
            omega = (signed(rng, W * mag(rng, -0.5, 0.3)), "rad/s")
            if rng.random() < 0.5:
                couples.append(spec(inertia=(inertia * mag(rng, -1, 1), "kg*m^2"), omega0=omega))
            else:
                couples.append("disc " + spec(mass=(mag(rng, -1, 1), "kg"), radius=(mag(rng, -1.5, 0), "m"), omega0=omega))
            tags.append("couple")
        walk = random.Random("walk" + str(rng.getstate()))  # #46's draws, beside the stream as it was
        staying = [n for n, tag in enumerate(t for t in tags if t.startswith("particle ")) if tag in ("particle stick", "particle angle", "particle ride")]
        if staying and not any(t in ("particle leave", "particle rebound") for t in tags) and walk.random() < 0.4:
            n = walk.choice(staying)  # it moves along the rim after, at a speed relative to the body (a toy train, a walker)
            particles[n] += " " + spec(speed_relative=(signed(walk, W * reach * mag(walk, -0.5, 0.5)), "m/s"))
            tags.append("particle walks")
        side = random.Random(str(rng.getstate()))  # #35's draws, leaving the stream the older draws see as it was
        if len(couples) == 1 and not particles and side.random() < 0.4:  # through a clutch that slips
            couples[0] += " " + spec(torque=(inertia * W / T * mag(side, -1, 0.5), "N*m"))
            tags.append("clutch")
        if particles:
            kw["particle"] = particles
        if couples:
            kw["couple"] = couples
    elif mode == "braked":
        kw["omega0"] = 0.0 if rng.random() < 0.15 else signed(rng, W * mag(rng, -0.5, 0.3))
        kw["torque"] = signed(rng, inertia * W / T * mag(rng, -1, 0.5), 0.4)
        kw["duration"] = T * mag(rng, -0.5, 0.5)
        scale = inertia * W / T
        if rng.random() < 0.75:
            mu = rng.uniform(0.1, 0.8)
            radius = rim if rim is not None and rng.random() < 0.5 else mag(rng, -1.5, 0)
            fields = {"force": (scale / (mu * radius) * mag(rng, -1, 0.3), "N"), "mu": (mu, "")}
            if radius != rim:
                fields["radius"] = (radius, "m")
            kw["brake"] = [spec(**fields)]
            tags.append("brake")
        if "brake" not in kw or rng.random() < 0.3:
            mu, outer = rng.uniform(0.1, 0.8), mag(rng, -1.5, 0)
            if kw.get("shape") in ("disc", "ring", "tube") and rng.random() < 0.4:
                kw["face"] = [spec(mu=(mu, ""))]  # the body lying on its face: its weight, its radii
                tags.append("face weight")
            else:
                kw["face"] = [spec(mu=(mu, ""), force=(scale / (mu * outer) * mag(rng, -1, 0.3), "N"), outer_radius=(outer, "m"))]
                tags.append("face")
        side = random.Random(str(rng.getstate()))  # #35's draws, leaving the stream the older draws see as it was
        if side.random() < 0.3 and kw["omega0"] * kw["torque"] >= 0:  # a band brake's geometry is for one sense of turning
            mu, wrap, radius = side.uniform(0.05, 0.6), side.uniform(0.3, 2.5) * math.pi, mag(rng, -1.5, 0)
            fields = {"mu": (mu, ""), "wrap": (wrap, "rad"), "radius": (radius, "m")}
            pull = scale / radius * mag(rng, -1, 0.3)
            if side.random() < 0.5:
                fields["tension"] = (pull, "N")
            else:
                fields.update(force=(pull, "N"), lever=(1.0, "m"), slack_arm=(mag(rng, -0.5, 0.3), "m"))
            kw["band"] = [spec(**fields)]
            tags.append("band")
    else:  # a sampled torque
        count = rng.randint(2, 12)
        start = rng.choice((0.0, T * rng.random()))
        times = sorted({start, *(start + T * rng.random() for _ in range(count - 1))})
        quadratic = rng.random() < 0.5
        a, b, q = (signed(rng, inertia * W / T * mag(rng, -1, 0.5), 0.5) for _ in range(3))
        torques = [a + b * (t - start) / T + q * ((t - start) / T) ** 2 if quadratic else signed(rng, inertia * W / T * mag(rng, -1, 0.5), 0.4) for t in times]
        path = folder / f"profile{rng.randrange(10**9)}.csv"
        path.write_text("t [s], torque [N*m]\n" + "".join(f"{t!r}, {torque!r}\n" for t, torque in zip(times, torques)))
        if quadratic:
            QUADRATICS[str(path)] = (start, T, a, b, q)
        kw["torque_profile"] = str(path)
        kw["method"] = rng.choice(("auto", "trapezoid", "simpson"))
        if rng.random() < 0.8:
            kw["omega0"] = signed(rng, W * mag(rng, -0.5, 0.3))
        tags.append("quadratic" if quadratic else "samples")
    if rng.random() < 0.3:
        kw["at"] = "rim" if rim is not None and rng.random() < 0.3 else mag(rng, -2, 0)
        tags.append("at")
    if rng.random() < 0.05:
        name = rng.choice(("omega1", "torque", "duration", "inertia_final", "omega0"))
        kw.setdefault(name, mag(rng, -1, 1))
        tags.append("stray")
    return kw, tags

def braked_motion(inertia, omega0, torque, duration, kinetic, static):
    """ω and θ after Δt under a constant torque and a Coulomb torque (constant α in each stretch one way,
    static friction holding at rest), and the angle swept both ways."""
    sgn = lambda x: (x > 0) - (x < 0)
    t, omega, theta, swept = 0.0, omega0, 0.0, 0.0
    for _ in range(3):
        if omega == 0:
            if abs(torque) <= static:
                return omega, theta, swept, 0.0
            alpha = (torque - sgn(torque) * kinetic) / inertia
        else:
            alpha = (torque - sgn(omega) * kinetic) / inertia
        left = duration - t
        if omega != 0 and omega * alpha < 0 and -omega / alpha < left:
            stop = -omega / alpha
            theta += omega * stop / 2
            swept += abs(omega * stop / 2)
            t, omega = t + stop, 0.0
            continue
        theta += omega * left + alpha * left * left / 2
        swept += abs(omega * left + alpha * left * left / 2)
        return omega + alpha * left, theta, swept, alpha
    raise AssertionError("more than two stretches")

def check_impulse(kw: dict, report, c: Checker) -> None:
    res, inp = values(report), inputs(report)
    model = report.model
    w0 = res["omega0"] if res.get("omega0") is not None else inp.get("omega0", 0.0)
    w1 = res.get("omega1")
    has_body = any(key in kw for key in ("inertia", "shape"))
    inertia = res.get("inertia") if res.get("inertia") is not None else (body_moment(kw, inp) if has_body else None)
    if w1 is not None and w0 is not None:
        c.eq("delta_omega = ω₁ − ω₀", res.get("delta_omega"), w1 - w0, w0, w1)
    if w1:  # #34: the period of a turn after
        c.eq("period = 2π/|ω₁|", res.get("period"), 2 * math.pi / abs(w1))
    if res.get("omega_impact") is not None:  # #34: a torque after a collision: the blow keeps L, then τΔt = ΔL
        c.eq("J = L1 − L0 after a collision", res["J"], res["L1"] - res["L0"], res["L0"], res["L1"])
        return
    if res.get("pivot_impulse") is not None:  # #34: the pivot's impulse is the change of the system's linear momentum
        c.eq("pivot_impulse = p1 − p0", res["pivot_impulse"], res["p1"] - res["p0"], res["p0"], res["p1"])
    if inertia is not None and w0 is not None and w1 is not None and not kw.get("particle") and not kw.get("couple"):
        final = inp.get("inertia_final", inertia)
        c.eq("L0 = I ω₀", res.get("L0"), inertia * w0)
        c.eq("L1 = I₁ ω₁", res.get("L1"), final * w1)
        c.eq("KE0 = ½ I ω₀²", res.get("KE0"), inertia * w0 * w0 / 2)
        c.eq("KE1 = ½ I₁ ω₁²", res.get("KE1"), final * w1 * w1 / 2)
    if res.get("KE0") is not None and res.get("KE1") is not None:
        c.eq("work = KE1 − KE0", res.get("work"), res["KE1"] - res["KE0"], res["KE1"], res["KE0"])
        c.eq("KE_lost = KE0 − KE1", res.get("KE_lost"), res["KE0"] - res["KE1"], res["KE1"], res["KE0"])
        if res.get("KE_lost") is not None and res["KE0"] > 0:
            c.eq("KE_lost_fraction = KE_lost / KE0", res.get("KE_lost_fraction"), res["KE_lost"] / res["KE0"])
    if res.get("L0") is not None and res.get("L1") is not None and res.get("J") is not None and not kw.get("brake") and not kw.get("face") and not kw.get("band"):
        if kw.get("particle") or kw.get("couple"):
            c.eq("J = I(ω₁ − ω₀), the body's", res["J"], inertia * (w1 - w0), inertia * w0, inertia * w1)
        elif model.startswith("changing"):
            c.eq("J = 0 with no torque", res["J"], 0.0)
        else:
            c.eq("J = ΔL = L1 − L0", res["J"], res["L1"] - res["L0"], res["L0"], res["L1"])
    if res.get("torque") is not None and res.get("duration") is not None:
        c.eq("J = τ Δt", res.get("J"), res["torque"] * res["duration"])
    if model.startswith(("changing", "no external")):
        parts = report.tables["parts"].rows if "parts" in report.tables else ()
        c.eq("L0 = L1 with no torque about the axis", res.get("L1"), res.get("L0"), *(abs(row[1]) for row in parts), *(abs(row[2]) for row in parts))

    if kw.get("brake") or kw.get("face") or kw.get("band"):
        c.eq("J = τ Δt", res.get("J"), inp["torque"] * inp["duration"])
        c.eq("J_net = I Δω", res.get("J_net"), inertia * (w1 - w0), inertia * w0, inertia * w1)
        c.eq("L0 = I ω₀", res.get("L0"), inertia * w0)
        c.eq("L1 = I ω₁", res.get("L1"), inertia * w1)
        c.eq("KE0 = ½ I ω₀²", res.get("KE0"), inertia * w0 * w0 / 2)
        c.eq("KE1 = ½ I ω₁²", res.get("KE1"), inertia * w1 * w1 / 2)
        brake, face = contact_torques(inp, kw, rim_of(inp), total_mass(inp), inp.get("g", G0))
        c.eq("torque_brake = Σ μNr", res.get("torque_brake"), brake if kw.get("brake") else None)
        c.eq("torque_face = μF r_eff", res.get("torque_face"), face if kw.get("face") else None)
        band = band_torque(inp, kw, rim_of(inp))
        c.eq("torque_band = (T₁ − T₂) r, T₁ = T₂ e^{μθ}", res.get("torque_band"), band if kw.get("band") else None)
        kinetic = brake + face + band
        omega, theta, swept, alpha_end = braked_motion(inertia, w0, inp["torque"], inp["duration"], kinetic, kinetic)
        c.eq("omega1: constant α in each stretch, held at rest", w1, omega, w0, inp["torque"] * inp["duration"] / inertia, kinetic * inp["duration"] / inertia)
        for name, torque in (("brake", brake), ("face", face), ("band", band)):
            if res.get(f"torque_{name}") is not None:
                c.eq(f"power_{name} = τ |ω₀|", res.get(f"power_{name}"), torque * abs(w0))
                c.eq(f"work_{name} = τ × the angle swept", res.get(f"work_{name}"), torque * swept, torque * abs(theta))
        works = [res.get("work_brake") or 0.0, res.get("work_face") or 0.0, res.get("work_band") or 0.0]
        c.eq("KE1 − KE0 = τθ − the friction's work", res["KE1"] - res["KE0"], inp["torque"] * theta - math.fsum(works),
             res["KE1"], res["KE0"], inp["torque"] * theta, *works)

    if kw.get("particle") or kw.get("couple"):
        check_meeting(kw, report, res, inp, inertia, w0, w1, c)

    if kw.get("torque_profile") is not None:
        c.true("a torque profile given is the impulse's torque (J = ∫τ dt)", model.startswith("sampled"), f"(the model: {model})")
    if model.startswith("sampled"):
        rows = report.tables["samples"].rows if "samples" in report.tables else ()
        text = Path(kw["torque_profile"]).read_text().splitlines()[1:]
        samples = [tuple(float(x) for x in line.split(",")) for line in text]
        trapezoid = math.fsum((t1 - t0) * (f0 + f1) / 2 for (t0, f0), (t1, f1) in pairwise(samples))
        size = math.fsum(abs(t1 - t0) * (abs(f0) + abs(f1)) / 2 for (t0, f0), (t1, f1) in pairwise(samples))
        if report.method == "trapezoid":
            c.eq("J = Σ ½(τᵢ + τᵢ₊₁)Δtᵢ (trapezoid)", res.get("J"), trapezoid, size)
        elif kw["torque_profile"] in QUADRATICS and len(samples) >= 3:  # (two samples: the trapezoid, whatever the rule's name)
            start, scale, a, b, q = QUADRATICS[kw["torque_profile"]]
            exact = [scale * (a * u + b * u * u / 2 + q * u ** 3 / 3) for u in ((samples[0][0] - start) / scale, (samples[-1][0] - start) / scale)]
            c.eq("J = ∫τ dt (Simpson, exact for a quadratic)", res.get("J"), exact[1] - exact[0], size, *exact)
        c.eq("duration = t_last − t_first", res.get("duration"), samples[-1][0] - samples[0][0], samples[-1][0])
        if res.get("J") is not None:  # (withheld where Simpson's rule asked for leaves what the samples allow)
            c.eq("delta_omega = J/I", res.get("delta_omega"), res["J"] / inertia)
        largest = max(samples, key=lambda s: abs(s[1]))
        c.true("peak_torque is the sample largest in size", abs(res["peak_torque"]) == abs(largest[1]), f"{res['peak_torque']} against {largest[1]}")
        for t, torque, omega in rows:
            done = [s for s in samples if s[0] <= t]
            if len(done) == 2 or report.method == "trapezoid":
                part = math.fsum((t1 - t0) * (f0 + f1) / 2 for (t0, f0), (t1, f1) in pairwise(done))
                c.eq("ω at a sample = ω₀ + ∫τ dt / I", omega, w0 + part / inertia, w0, size / inertia)

    if kw.get("at") is not None and w0 is not None and w1 is not None:
        r = rim_of(inp) if kw["at"] == "rim" else inp["at"]
        torque, duration = res.get("torque", inp.get("torque")), res.get("duration", inp.get("duration"))
        if kw.get("brake") or kw.get("face") or kw.get("band"):
            alpha, alpha0 = alpha_end, (inp["torque"] - ((w0 > 0) - (w0 < 0)) * kinetic) / inertia if w0 else None  # θ: braked_motion's
        elif torque is not None and inertia and duration is not None:
            alpha = alpha0 = torque / inertia
            theta = (w0 + w1) * duration / 2
        elif model.startswith("sampled"):
            alpha = alpha0 = theta = None
        else:
            alpha = alpha0 = 0.0
            theta = None
        point_checks(c, res, r, w1, alpha, theta, start=(w0, alpha0))

QUADRATICS: dict[str, tuple] = {}  # a profile's path -> (t₀, T, a, b, q): τ = a + bu + qu², u = (t − t₀)/T

def check_meeting(kw, report, res, inp, inertia, w0, w1, c: Checker) -> None:
    """L and KE before and after, of the whole system, from what meets the body (its inputs' echo)."""
    momentum0, momentum1, energy0, energy1 = [inertia * w0], [], [inertia * w0 * w0 / 2], []
    inertia1 = [inertia]
    for n, text in enumerate(kw.get("couple") or (), start=1):
        key = f"couple{n}_"
        moment = inp[key + "inertia"] if key + "inertia" in inp else inp[key + "mass"] * inp[key + "radius"] ** 2 / 2
        omega = inp.get(key + "omega0", 0.0)
        momentum0.append(moment * omega)
        energy0.append(moment * omega * omega / 2)
        inertia1.append(moment)
    after = {}
    for n, text in enumerate(kw.get("particle") or (), start=1):
        key = f"particle{n}_"
        m, r = inp[key + "mass"], inp[key + "radius"]
        arm = r * (math.sin(inp[key + "angle"]) if key + "angle" in inp else 1.0)
        rho = inp.get(key + "radius_after", r)
        if key + "speed_relative" in inp:  # it moves along the rim after at v_rel relative to the body: v′ = ω₁ρ + v_rel
            after[n] = (m, w1 * rho + inp[key + "speed_relative"], rho)
        if key + "speed" not in inp:  # it rides on the body
            momentum0.append(m * r * r * w0)
            energy0.append(m * r * r * w0 * w0 / 2)
            if n not in after:
                inertia1.append(m * rho * rho)
            continue
        v = inp[key + "speed"]
        momentum0.append(m * v * arm)
        energy0.append(m * v * v / 2)
        if key + "speed_after" in inp:
            after[n] = (m, inp[key + "speed_after"], arm)
        elif key + "e" in inp:
            after[n] = (m, w1 * arm - inp[key + "e"] * (v - w0 * arm), arm)  # v′ − ω₁r⊥ = −e(v − ω₀r⊥)
        elif n not in after:
            inertia1.append(m * rho * rho)
    i1 = math.fsum(inertia1)
    momentum1 = [i1 * w1, *(m * v1 * arm for m, v1, arm in after.values())]
    energy1 = [i1 * w1 * w1 / 2, *(m * v1 * v1 / 2 for m, v1, arm in after.values())]
    c.eq("L0 = Iω₀ + Σ I_c ω_c + Σ m v r⊥ (+ riders' m r² ω₀)", res.get("L0"), math.fsum(momentum0), *momentum0)
    c.eq("L1 = I₁ω₁ + Σ m v′ r⊥", res.get("L1"), math.fsum(momentum1), *momentum1)
    c.eq("KE0 = Σ ½Iω² + Σ ½mv²", res.get("KE0"), math.fsum(energy0))
    c.eq("KE1 = ½I₁ω₁² + Σ ½mv′²", res.get("KE1"), math.fsum(energy1))
    rows = report.tables["parts"].rows
    for name, l0, l1, j, speed_after in rows:
        c.eq("a part's J = L₁ − L₀", j, l1 - l0, l0, l1)
    c.eq("the parts' J add to zero", math.fsum(row[3] for row in rows), 0.0, *(row[1] for row in rows), *(row[2] for row in rows))
    if "couple1_torque" in inp:  # a clutch that slips: each body's angular impulse is the clutch's T t_slip
        torque, slip = inp["couple1_torque"], res.get("t_slip")
        c.eq("T t_slip = I₁|ω₁ − ω_f| (the body's angular impulse)", torque * slip, abs(rows[0][2] - rows[0][1]), abs(rows[0][1]), abs(rows[0][2]))
        c.eq("T t_slip = I₂|ω_f − ω₂| (the couple's)", torque * slip, abs(rows[1][2] - rows[1][1]), abs(rows[1][1]), abs(rows[1][2]))
        c.eq("heat = KE0 − KE1 (the clutch's work over the angle slipped)", res.get("heat"), res["KE0"] - res["KE1"], res["KE0"])
    for n, (m, v1, arm) in after.items():
        row = next(row for row in rows if row[0] in (f"particle {n}", "particle"))
        c.eq("a particle's speed after (given, or v′ = ω₁r⊥ − e(v − ω₀r⊥))", row[4], v1, w1 * arm)
