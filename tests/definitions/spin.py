"""spin-down: the draws (a model, then random subsets of its options) and the definitions its results keep."""

from __future__ import annotations

import math
import random

from definitions.check import (
    G0,
    REL,
    TWO_PI,
    Checker,
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


def draw_spin(rng: random.Random) -> tuple[dict, list[str]]:
    """A spin-down: a model (the torque laws, a constant α, kinematics alone, a motor, --in-time),
    then random subsets of its options."""
    kw: dict = {}
    mode = rng.choice(("laws",) * 5 + ("alpha", "kinematics", "power", "in_time"))
    tags = [mode]
    T, W = mag(rng, -1, 1), mag(rng, -1, 2.5)  # a time and a speed that set the scale of the rest
    inertia, rim = (None, None) if mode == "kinematics" or (mode == "alpha" and rng.random() < 0.4) else draw_body(rng, kw)
    torque_scale = (inertia or 1.0) * W / T

    def maybe(name, probability, value, tag=None):
        if rng.random() < probability:
            kw[name] = value
            tags.append(tag or name)

    def losses(p_friction, p_viscous, p_drag, exponent=True):
        maybe("friction", p_friction, torque_scale * mag(rng, -1, 0.3))
        maybe("viscous", p_viscous, (inertia or 1.0) / T * mag(rng, -1, 0.3))
        maybe("drag", p_drag, (inertia or 1.0) / (W * T) * mag(rng, -1, 0.3))
        if "drag" in kw and exponent and rng.random() < 0.15:
            kw["drag_exponent"] = rng.choice((1.0, 1.5, 3.0))
            tags.append("drag_exponent")

    def contacts():
        if inertia is None:
            return
        side = random.Random(str(rng.getstate()))  # #35's draws, leaving the stream the older draws see as it was
        if rng.random() < 0.15:
            mu = rng.uniform(0.1, 0.8)
            radius = rim if rim is not None and rng.random() < 0.5 else mag(rng, -1.5, 0)
            fields = {"force": (torque_scale / (mu * radius) * mag(rng, -1, 0), "N"), "mu": (mu, "")}
            if radius != rim:
                fields["radius"] = (radius, "m")
            if side.random() < 0.3:  # on a lever: N = F ℓ/(x − μc), not self-locking
                fields["lever"], fields["pivot"] = (mag(side, -0.5, 0.5), "m"), (mag(side, -0.5, 0.5), "m")
                fields["offset"] = (fields["pivot"][0] / mu * side.uniform(-1, 0.9), "m")
                tags.append("brake lever")
            kw["brake"] = [spec(**fields)]
            tags.append("brake")
        if rng.random() < 0.1:
            mu = rng.uniform(0.1, 0.8)
            if kw.get("shape") in ("disc", "ring", "tube") and rng.random() < 0.5:
                kw["face"] = [spec(mu=(mu, ""))]
                tags.append("face weight")
            else:
                outer = mag(rng, -1.5, 0)
                fields = {"mu": (mu, ""), "force": (torque_scale / (mu * outer) * mag(rng, -1, 0), "N"),
                          "inner_radius": (outer * rng.uniform(0, 0.9), "m"), "outer_radius": (outer, "m")}
                if rng.random() < 0.4:
                    fields["model"] = "wear"
                if rng.random() < 0.3:
                    fields["surfaces"] = "2"
                if side.random() < 0.3 and fields["inner_radius"][0] > 0:
                    del fields["force"]
                    fields["pmax"] = (torque_scale / (mu * outer ** 3) * mag(side, -1, 0), "Pa")
                    tags.append("face pmax")
                kw["face"] = [spec(**fields)]
                tags.append("face")

        if side.random() < 0.1 and mode == "laws":
            mu, wrap = side.uniform(0.05, 0.6), side.uniform(0.3, 2.5) * math.pi
            radius = rim if rim is not None and side.random() < 0.5 else mag(rng, -1.5, 0)
            fields = {"mu": (mu, ""), "wrap": (wrap, "rad")}
            if radius != rim:
                fields["radius"] = (radius, "m")
            pull = torque_scale / radius * mag(rng, -1, 0)
            if side.random() < 0.4:
                fields["tension"] = (pull, "N")
            else:
                fields["force"], fields["lever"] = (pull, "N"), (1.0, "m")
                arms = side.choice(("slack", "tight", "both"))
                if arms != "tight":
                    fields["slack_arm"] = (mag(rng, -0.5, 0.3), "m")
                if arms != "slack":
                    fields["tight_arm"] = (mag(rng, -0.5, 0.3) if arms == "tight" else fields["slack_arm"][0] / math.exp(mu * wrap) * side.uniform(0.1, 0.9), "m")
            if side.random() < 0.3:
                fields["width"] = (mag(rng, -2, 0.5), "m")
            kw["band"] = [spec(**fields)]
            tags.append("band")

        if side.random() < 0.1:  # a caliper disc brake (#48): an annular pad, n·μ·F·R_eff
            mu, outer = side.uniform(0.1, 0.8), mag(side, -1.5, 0)
            fields = {"mu": (mu, ""), "force": (torque_scale / (mu * outer) * mag(side, -1, 0), "N"),
                      "inner_radius": (outer * side.uniform(0, 0.95), "m"), "outer_radius": (outer, "m")}
            if side.random() < 0.5:
                fields["model"] = "wear"
            if side.random() < 0.3:
                fields["surfaces"] = "1"
            kw["caliper"] = [spec(**fields)]
            tags.append("caliper")

    def targets(p_time, p_omega, p_angle):
        maybe("time", p_time, T * mag(rng, -1, 0.5))
        maybe("until_omega", p_omega, signed(rng, W * mag(rng, -0.7, 0.5)))
        if rng.random() < p_angle:
            if rim is not None and rng.random() < 0.3:
                kw["until_arc"] = signed(rng, W * T * rim * mag(rng, -1, 0.3), 0.2)
                tags.append("until_arc")
                if "inertia" in kw:
                    kw["radius"] = rim
            else:
                kw["until_angle"] = signed(rng, W * T * mag(rng, -1, 0.3), 0.2)
                tags.append("until_angle")

    def start():
        x = rng.random()
        if x < 0.75:
            kw["omega0"] = signed(rng, W * mag(rng, -0.3, 0.3))
        elif x < 0.85:
            kw["omega0"] = 0.0
        elif inertia is not None and x < 0.92:
            kw["ke0"] = inertia * W * W / 2 * mag(rng, -0.5, 0.5)
            tags.append("ke0")
        elif inertia is not None and rim is not None or "inertia" in kw:
            rim_radius = rim if rim is not None else mag(rng, -1.5, 0)
            if "inertia" in kw and rim is None:
                kw["radius"] = rim_radius
            kw["rim_speed"] = signed(rng, W * rim_radius * mag(rng, -0.3, 0.3))
            tags.append("rim_speed")

    if mode == "laws":
        start()
        losses(0.45, 0.3, 0.25)
        if rng.random() < 0.35:
            kw["torque"] = signed(rng, torque_scale * mag(rng, -1, 0.5), 0.4)
            tags.append("torque")
        elif rng.random() < 0.15:
            lever = mag(rng, -1.5, 0)
            kw.update(force=signed(rng, torque_scale / lever * mag(rng, -1, 0.5), 0.3), lever=lever)
            maybe("push_angle", 0.5, rng.uniform(-3, 3))
            tags.append("push")
        contacts()
        targets(0.45, 0.2, 0.15)
        maybe("energy", 0.5, True)
        if rng.random() < 0.07:
            kw["method"] = rng.choice(("euler", "rk4", "rk45"))
            tags.append("stepper")
            if kw["method"] != "rk45":
                kw["dt"] = T / rng.choice((200, 2000))
    elif mode == "alpha":
        start()
        kw["alpha"] = 0.0 if rng.random() < 0.2 else signed(rng, W / T * mag(rng, -1, 0.3), 0.5)
        losses(0.3, 0.15 if kw["alpha"] == 0 else 0.03, 0.1 if kw["alpha"] == 0 else 0.02, exponent=False)
        contacts()
        targets(0.5, 0.25, 0.2)
        maybe("in_time", 0.05, T * mag(rng, -0.5, 0.5))
    elif mode == "kinematics":
        names = rng.sample(("omega0", "until_omega", "alpha", "time", "until_angle"), 3)
        for name in names:
            kw[name] = {
                "omega0": signed(rng, W * mag(rng, -0.5, 0.3), 0.2),
                "until_omega": signed(rng, W * mag(rng, -0.5, 0.3), 0.2),
                "alpha": signed(rng, W / T * mag(rng, -1, 0.3), 0.4),
                "time": T * mag(rng, -1, 0.3),
                "until_angle": signed(rng, W * T * mag(rng, -1, 0.3), 0.2),
            }[name]
        if "time" in kw and rng.random() < 0.2:
            kw["in_time"] = kw.pop("time")
        if rng.random() < 0.15:
            kw["friction"] = mag(rng, -1, 1)
            kw["alpha"] = 0.0
            tags.append("held")
    elif mode == "power":
        start()
        kw["power"] = signed(rng, (inertia or 1.0) * W * W / T * mag(rng, -1, 0.3), 0.25)
        losses(0.25, 0.2, 0.15)
        targets(0.4, 0.3, 0.15)
    else:  # in_time
        start()
        kw["in_time"] = T * mag(rng, -0.5, 0.5)
        if rng.random() < 0.6:
            kw["until_omega"] = signed(rng, W * mag(rng, -0.5, 0.5), 0.2)
        else:
            kw["until_angle"] = signed(rng, W * T * mag(rng, -1, 0.3), 0.2)
        losses(0.4, 0.25, 0.15, exponent=False)
        tags.append("bisection" if kw.get("viscous") or kw.get("drag") else "closed")
    if mode != "kinematics":
        maybe("energy", 0.3, True)
        if rng.random() < 0.3:
            kw["at"] = "rim" if rim is not None and rng.random() < 0.3 else mag(rng, -2, 0)
            tags.append("at")
    if rng.random() < 0.06:  # a stray option, for the combinations nobody thought of
        name = rng.choice(("torque", "friction", "viscous", "alpha", "power", "in_time", "time", "until_omega", "ke0", "at", "energy"))
        kw.setdefault(name, True if name == "energy" else mag(rng, -1, 1))
        tags.append("stray")
    return kw, tags

def draw_transfer(rng: random.Random) -> tuple[dict, list[str]]:
    """#34 item 2: a body and its start, then work added or taken (--work), or its stored energy
    put to a load (--lift-mass, --vehicle-mass; --efficiency, --until-omega)."""
    kw: dict = {}
    W = mag(rng, -1, 2.5)
    inertia, _ = draw_body(rng, kw)
    tags = ["transfer"]
    if rng.random() < 0.85:
        kw["omega0"] = signed(rng, W * mag(rng, -0.3, 0.3))
    else:
        kw["ke0"] = inertia * W * W / 2 * mag(rng, -0.5, 0.5)
    ke0 = kw.get("ke0", inertia * kw.get("omega0", 0.0) ** 2 / 2)
    use = rng.choice(("work", "lift_mass", "vehicle_mass", "both"))
    if use == "work":
        kw["work"] = -rng.uniform(0, 1) * ke0 if rng.random() < 0.4 else signed(rng, inertia * W * W / 2 * mag(rng, -1, 0.5), 0.2)
    else:
        if use in ("lift_mass", "both"):
            kw["lift_mass"] = mag(rng, -1, 2)
            if rng.random() < 0.3:
                kw["g"] = rng.uniform(1.6, 25)
        if use in ("vehicle_mass", "both"):
            kw["vehicle_mass"] = mag(rng, -1, 3)
        if rng.random() < 0.5:
            kw["efficiency"] = rng.uniform(0.05, 1.0)
        if "omega0" in kw and rng.random() < 0.3:
            kw["until_omega"] = kw["omega0"] * rng.uniform(-1, 1)
            tags.append("until_omega")
    tags.append(use)
    return kw, tags


def spin_mode(kw: dict) -> str:
    has_body = any(kw.get(name) is not None for name in ("inertia", "shape", "part"))
    if kw.get("alpha") is not None or not has_body:
        return "alpha"
    if kw.get("power"):
        return "power"
    if kw.get("in_time") is not None:
        return "bisection" if kw.get("viscous") or kw.get("drag") else "closed"
    return "laws"

def check_transfer(res: dict, inp: dict, c: Checker) -> None:
    """--work: ½Iω₁² = ½Iω₀² + W; a load: E = η·½I(ω₀² − ω₁²) = mgh = ½mv²."""
    inertia, ke0, ke1 = res["I"], res["KE0"], res["KE_after"]
    w0 = res["omega0"] if res.get("omega0") is not None else inp.get("omega0", 0.0)
    c.eq("KE0 = ½Iω₀²", ke0, inertia * w0 * w0 / 2)
    c.eq("KE_after = ½Iω₁²", ke1, inertia * res["omega_after"] ** 2 / 2)
    if "work" in inp:
        c.eq("KE_after = KE0 + W (work-energy)", ke1, ke0 + inp["work"], ke0, inp["work"])
        c.true("ω after turns the way ω₀ did", res["omega_after"] * w0 >= 0)
        return
    eta = inp.get("efficiency", 1.0)
    c.eq("energy_delivered = η(KE0 − KE_after)", res["energy_delivered"], eta * (ke0 - ke1), eta * ke0)
    if "lift_mass" in inp:
        c.eq("m g h = energy_delivered", inp["lift_mass"] * inp.get("g", G0) * res["lift_height"], res["energy_delivered"])
    if "vehicle_mass" in inp:
        c.eq("½ m v² = energy_delivered", inp["vehicle_mass"] * res["vehicle_speed"] ** 2 / 2, res["energy_delivered"])


def check_spin(kw: dict, report, c: Checker) -> None:
    res, inp = values(report), inputs(report)
    if any(name in kw for name in ("work", "lift_mass", "vehicle_mass")):
        check_transfer(res, inp, c)
        return
    mode = spin_mode(kw)
    uniform_family = mode in ("alpha", "closed")
    inertia = res.get("I")
    w0 = res["omega0"] if res.get("omega0") is not None else inp.get("omega0", 0.0)
    if mode == "alpha" and "omega0" not in inp and "omega0" not in res and "alpha" not in inp and None not in (inp.get("time", inp.get("in_time")), inp.get("until_omega"), inp.get("until_angle")):
        # t, ω₁ and θ given: ω₀ is fixed by θ = ½(ω₀ + ω₁)t (and not reported)
        w0 = 2 * inp["until_angle"] / inp.get("time", inp.get("in_time")) - inp["until_omega"]
    rim = rim_of(inp)
    if inp.get("until_arc") is not None and rim and kw.get("until_omega") is None:  # #34: the arc's angle is a result
        c.eq("theta_until = s/R (--until-arc)", res.get("theta_until"), inp["until_arc"] / rim)
    g = inp.get("g", G0)
    n = inp.get("drag_exponent", 2.0)
    b, k, axle = inp.get("viscous", 0.0), inp.get("drag", 0.0), inp.get("friction", 0.0)
    brake, face, band = res.get("torque_brake", 0.0), res.get("torque_face", 0.0), res.get("torque_band", 0.0)
    caliper = res.get("torque_caliper", 0.0)
    f = axle + brake + face + band + caliper
    if mode == "bisection":
        drive = res["torque"]
    elif "force" in inp:
        drive = inp["force"] * inp["lever"] * math.sin(inp.get("push_angle", math.pi / 2))
    else:
        drive = inp.get("torque", 0.0) if mode != "power" else 0.0
    power = inp.get("power") or None
    time = inp.get("time") if mode != "bisection" else inp["in_time"]
    if mode == "closed" or (mode == "alpha" and time is None):
        time = inp.get("in_time", time)
    until_omega, until_angle = inp.get("until_omega"), inp.get("until_angle")
    if inp.get("until_arc") is not None:
        until_angle = inp["until_arc"] / rim  # the target angle of an arc at the rim (checked below as the angle reached)
    sgn = lambda x: (x > 0) - (x < 0)

    def losses(omega):  # the torque of the losses against +ω, turning at ω
        return sgn(omega) * f + b * omega + sgn(omega) * k * abs(omega) ** n

    def loss_scale(omega):
        return max(f, abs(b * omega), k * abs(omega) ** n)

    # ω₀ from a stored energy or a rim speed; the contacts' torques
    if inp.get("ke0") is not None:
        c.eq("omega0 = √(2 KE0/I)", res.get("omega0"), math.sqrt(2 * inp["ke0"] / inertia))
        c.eq("KE0 = --ke0", res.get("KE0"), inp["ke0"])
    if inp.get("rim_speed") is not None:
        c.eq("omega0 = v/R", res.get("omega0"), inp["rim_speed"] / rim)
    if kw.get("brake") or kw.get("face"):
        want_brake, want_face = contact_torques(inp, kw, rim, total_mass(inp), g)
        if kw.get("brake"):
            c.eq("torque_brake = Σ μNr", res.get("torque_brake"), want_brake)
        if kw.get("face"):
            c.eq("torque_face = μF r_eff (its weight the body's)", res.get("torque_face"), want_face)
    if kw.get("caliper"):
        ri, ro = inp.get("caliper1_inner_radius", 0.0), inp["caliper1_outer_radius"]
        lever = (ro + ri) / 2 if "model=wear" in kw["caliper"][0] else 2 * (ro**3 - ri**3) / (3 * (ro**2 - ri**2))
        c.eq("torque_caliper = n μ F R_eff", res.get("torque_caliper"), inp.get("caliper1_surfaces", 2) * inp["caliper1_mu"] * inp["caliper1_force"] * lever)
        c.eq("radius_effective = τ/(n μ F)", res.get("radius_effective"), lever)
    if kw.get("band"):
        c.eq("torque_band = (T₁ − T₂) r, T₁ = T₂ e^{μθ}", res.get("torque_band"), band_torque(inp, kw, rim))
        mu, wrap = inp.get("band1_mu", inp.get("band1_mu_k")), inp["band1_wrap"]
        c.eq("tension_tight = tension_slack e^{μθ}", res.get("tension_tight"), res["tension_slack"] * math.exp(mu * wrap))
        c.eq("torque_band = (T₁ − T₂) r", res.get("torque_band"), (res["tension_tight"] - res["tension_slack"]) * inp.get("band1_radius", rim),
             res["tension_tight"] * inp.get("band1_radius", rim))
        if "band1_width" in inp:
            c.eq("pressure_band = T₁/(r w)", res.get("pressure_band"), res["tension_tight"] / (inp.get("band1_radius", rim) * inp["band1_width"]))

    # revolutions, and the angle both ways
    for revs, theta in (("revs", "theta"), ("revs_stop", "theta_stop"), ("revs_total", "theta_total")):
        if res.get(theta) is not None:
            c.eq(f"{revs} = {theta}/2π", res.get(revs), res[theta] / TWO_PI)
    if res.get("theta_total") is not None and res.get("theta_stop") is not None and res.get("theta") is not None:
        total = abs(res["theta_stop"]) + abs(res["theta"] - res["theta_stop"])
        c.eq("theta_total = |θ_stop| + |θ − θ_stop|", res["theta_total"], total, abs(res["theta_stop"]), abs(res["theta"]))
    if inertia is not None and res.get("alpha0") is not None:
        c.eq("torque_net = I α₀", res.get("torque_net"), inertia * res["alpha0"])

    # the instants: the drive's and the losses' power (ω_at), the energy's end (t_end, ω_end)
    if mode in ("laws", "bisection"):  # --time, else the target (DESIGN: energy at a target), else the stop
        if time is not None:
            omega_at, t_end, omega_end = res.get("omega"), time, res.get("omega")
        elif until_omega is not None or until_angle is not None:
            reached = res.get("t_until")
            omega_there = until_omega if until_omega is not None else res.get("omega")
            omega_at, t_end, omega_end = (omega_there, reached, omega_there) if reached is not None else (None, None, None)
        else:
            omega_at, t_end, omega_end = w0, res.get("t_stop"), 0.0
    elif mode == "power":  # a target reached is the instant, else --time (power_report: the last given wins)
        at = None
        if until_omega is not None and res.get("t_until") is not None:
            at = (res["t_until"], until_omega)
        elif until_angle is not None and res.get("t_until") is not None:
            at = (res["t_until"], res.get("omega"))
        elif time is not None:
            at = (time, res.get("omega"))
        omega_at = w0 if at is None else at[1]
        t_end, omega_end = at if at is not None else (res.get("t_stop"), 0.0)
    else:
        omega_at = res["omega"] if res.get("omega") is not None else w0
        t_end = time if time is not None else res.get("t_until")
        omega_end = res.get("omega")
        if time is None and until_omega is not None and res.get("t_until") is not None and res.get("omega") is None:
            omega_at = omega_end = until_omega  # a given α to a target speed: the energy at the target

    # energy: KE = ½Iω² at the start and at the end, the balance, the power at one instant
    if inertia is not None:
        c.eq("KE0 = ½ I ω₀²", res.get("KE0"), inertia * w0 * w0 / 2)
        if res.get("KE") is not None and omega_end is not None:
            c.eq("KE = ½ I ω² at the end", res["KE"], inertia * omega_end * omega_end / 2)
    works = [res.get(name) for name in ("work_friction", "work_viscous", "work_drag", "work_brake", "work_face", "work_band", "work_caliper")]
    # The balance is an identity of the exact motion. A stepped one (rk45: a motor against losses, a drag
    # exponent other than 1 or 2) keeps it to its own accuracy, rtol 1e-10 by default: 1e-9 here; euler and
    # rk4 answers are good to 1e-3 by design (their error estimate withholds worse), so not to this.
    stepped = report.method != "closed form"
    if res.get("KE0") is not None and res.get("KE") is not None and not (stepped and not report.method.startswith("rk45")):
        terms = [res["KE0"], res["KE"], res.get("work_drive") or 0.0, *(w or 0.0 for w in works)]
        c.eq("KE0 − KE = Σ losses − work_drive", res["KE0"] - res["KE"], math.fsum(w or 0.0 for w in works) - (res.get("work_drive") or 0.0), *terms,
             rel=1e-9 if stepped else REL)
    if res.get("work_drive") is not None and t_end:
        c.eq("power_mean = work_drive / t", res.get("power_mean"), res["work_drive"] / t_end)
    contact_work = [(torque, res.get(name)) for torque, name in ((axle, "work_friction"), (brake, "work_brake"), (face, "work_face"), (band, "work_band"),
                                                                 (caliper, "work_caliper")) if torque]
    if len(contact_work) > 1 and all(w is not None for _, w in contact_work):
        swept = math.fsum(w for _, w in contact_work) / f
        for torque, w in contact_work:
            c.eq("each contact's work = its torque × the angle swept", w, torque * swept)
    # the work of a constant torque is the torque times the angle: net for the drive, swept for friction
    if mode in ("laws", "bisection", "alpha", "closed"):
        if time is not None and res.get("theta") is not None:
            net, swept = res["theta"], res["theta_total"] if res.get("theta_total") is not None else abs(res["theta"])
        elif time is None and mode in ("laws", "bisection") and (until_omega is not None or until_angle is not None):
            reached, stop = res.get("t_until"), res.get("t_stop")
            net = (res.get("theta_until") if until_omega is not None else until_angle) if reached is not None else None
            turned_back = stop is not None and reached is not None and reached > stop
            swept = None if net is None or turned_back else abs(net)
            net = None if turned_back else net
        elif time is None and mode in ("laws", "bisection") and res.get("theta_stop") is not None:
            net, swept = res["theta_stop"], abs(res["theta_stop"])
        else:
            net = swept = None
        friction_work = [w for w in (res.get("work_friction"), res.get("work_brake"), res.get("work_face"), res.get("work_band"), res.get("work_caliper")) if w is not None]
        if swept is not None and friction_work:
            c.eq("the friction's work = τ_f × the angle swept", math.fsum(friction_work), f * swept)
        if net is not None and mode in ("laws", "bisection") and kw.get("method") is None:
            c.eq("work_drive = τ_drive θ", res.get("work_drive"), drive * net)
    if mode == "power" and res.get("work_drive") is not None and t_end is not None:
        driving = min(t_end, res["t_stop"]) if res.get("t_stop") is not None else t_end
        c.eq("work_drive = P t (while it turns)", res["work_drive"], power * driving)
    if omega_at is not None:
        for name, torque in (("power_friction", axle), ("power_brake", brake), ("power_face", face), ("power_band", band), ("power_caliper", caliper)):
            if torque:
                c.eq(f"{name} = τ |ω|", res.get(name), torque * abs(omega_at))
        c.eq("power_viscous = b ω²", res.get("power_viscous"), b * omega_at * omega_at)
        c.eq("power_drag = k |ω|ⁿ⁺¹", res.get("power_drag"), k * abs(omega_at) ** (n + 1))
        if mode in ("laws", "bisection"):
            c.eq("power = τ_drive ω", res.get("power"), drive * omega_at)
        elif mode == "power":
            if res.get("torque") is not None:
                c.eq("power = τ ω (a motor: τ = P/ω)", res.get("power"), res["torque"] * omega_at)
            if omega_at:
                c.eq("power = P", res.get("power"), power)
        elif res.get("power") is not None:
            net = res.get("torque_net") or 0.0
            c.eq("power = (Iα + losses) ω at one instant", res["power"], (net + losses(omega_at)) * omega_at,
                 abs(net * omega_at), loss_scale(omega_at) * abs(omega_at))

    # Newton's second law at the start; the steady speed
    if inertia is not None and res.get("alpha0") is not None and w0 != 0 and mode in ("laws", "bisection", "power"):
        push = power / w0 if mode == "power" else drive
        c.eq("I α₀ = τ_drive − τ_f − bω₀ − k|ω₀|ⁿ", inertia * res["alpha0"], push - losses(w0), push, loss_scale(w0))
    if res.get("omega_inf") and (b or k):
        w = res["omega_inf"]
        push = power / w if mode == "power" else drive
        c.eq("the torques balance at omega_inf", push, losses(w), loss_scale(w))

    # a constant α: the drive it takes, and its kinematics
    alpha = res.get("alpha") if uniform_family else (res.get("alpha0") if mode == "laws" and not (b or k) and kw.get("method") is None else None)
    if uniform_family and res.get("torque") is not None:
        sense = sgn(w0) if w0 else sgn(alpha)
        extra = sense * f + (b * w0 + sense * k * abs(w0) ** n if alpha == 0 else 0.0)
        c.eq("torque = Iα + the losses at the start", res["torque"], (res.get("torque_net") or 0.0) + extra, f, abs(b * w0), k * abs(w0) ** n)
    if alpha is not None:
        t_stop = res.get("t_stop")
        if t_stop is not None:
            c.eq("ω₀ + α t_stop = 0", w0 + alpha * t_stop, 0.0, w0)
            c.eq("theta_stop = ½ ω₀ t_stop", res.get("theta_stop"), w0 * t_stop / 2)
        before_stop = lambda t: t_stop is None or t <= t_stop
        if time is not None and res.get("omega") is not None and (uniform_family or before_stop(time)):
            c.eq("omega = ω₀ + α t", res["omega"], w0 + alpha * time, w0, alpha * time)
            c.eq("theta = ω₀t + ½αt²", res.get("theta"), w0 * time + alpha * time * time / 2, w0 * time, alpha * time * time / 2)
        t_until = res.get("t_until")
        if until_omega is not None and t_until is not None and (uniform_family or before_stop(t_until)):
            c.eq("ω₀ + α t_until = the target ω", w0 + alpha * t_until, until_omega, w0, alpha * t_until)
            c.eq("theta_until = ω₀t + ½αt²", res.get("theta_until"), w0 * t_until + alpha * t_until * t_until / 2, w0 * t_until, alpha * t_until ** 2 / 2)
        if until_angle is not None and t_until is not None and time is None and res.get("omega") is not None and (uniform_family or before_stop(t_until)):
            c.eq("ω² = ω₀² + 2αθ at the target angle", res["omega"] ** 2, w0 * w0 + 2 * alpha * until_angle, w0 * w0, 2 * alpha * until_angle)
            c.eq("ω₀t + ½αt² = the target angle", w0 * t_until + alpha * t_until * t_until / 2, until_angle, w0 * t_until, alpha * t_until ** 2 / 2)
    if mode in ("closed", "bisection") and res.get("omega") is not None:
        if until_omega is not None:
            c.eq("--in-time: ω = the target at t", res["omega"], until_omega, w0)
        elif res.get("theta") is not None:
            c.eq("--in-time: θ = the target at t", res["theta"], until_angle, w0 * inp["in_time"])

    # a point at r: at --time or the target, else the start
    if kw.get("at") is not None:
        r = rim if kw["at"] == "rim" else inp["at"]
        if r is None:
            r = inp.get("radius", inp.get("outer_radius"))

        def alpha_at(omega):
            if uniform_family and power is None and res.get("alpha") is not None:
                return res["alpha"]
            if inertia is None:
                return None
            if power is not None:
                return None if omega == 0 else (power / omega - losses(omega)) / inertia
            if omega == 0:
                return None  # held by static friction, or not: the static torque of the contacts is not echoed
            return (drive - losses(omega)) / inertia

        if time is not None:
            omega, theta = res.get("omega"), res.get("theta")
        elif until_angle is not None:
            omega = res.get("omega")
            theta = until_angle if omega is not None else None
        elif until_omega is not None:
            omega = until_omega if res.get("theta_until") is not None else None
            theta = res.get("theta_until")
        else:
            omega, theta = w0, 0.0
        later = time is not None or until_angle is not None or until_omega is not None
        start = (w0, res["alpha0"] if res.get("alpha0") is not None else alpha_at(w0)) if later else None
        point_checks(c, res, r, omega, None if omega is None else alpha_at(omega), theta, start=start)
