"""Random spin-down scenes with --power and --in-time, compared with references.spin."""

from __future__ import annotations

import taucli
from references import DPS, mp, mpf
from references.compare import Row, log_uniform, rad_s, value
from references.spin import PowerMotion, in_time_torque

STEPPED = 1e-8  # rk45 at rtol 1e-10 (a power against losses has no closed form)
CLOSED = 1e-13
KINDS = ("power_until", "power_time", "power_near_steady", "load_stop", "power_lossless", "in_time", "in_time_friction")


def _losses(rng):
    tf = 0.0 if rng.random() < 0.4 else log_uniform(rng, -3, 1)
    b = 0.0 if rng.random() < 0.4 else log_uniform(rng, -4, 0)
    k = 0.0 if rng.random() < 0.4 else log_uniform(rng, -6, -1)
    if not (tf or b or k):
        b = log_uniform(rng, -4, 0)
    return tf, b, k


def draw_spin(rng, kind=None):
    kind = kind or rng.choice(KINDS)
    I = log_uniform(rng, -2, 2)
    if kind.startswith("in_time"):
        tf, b, k = _losses(rng)
        if kind == "in_time_friction":
            b = k = 0.0
        w0 = 0.0 if rng.random() < 0.5 else log_uniform(rng, -1, 2)
        w1 = w0 + log_uniform(rng, -1, 2.5)
        T = log_uniform(rng, -1, 1.5)
        kw = dict(inertia=I, omega0=rad_s(w0), until_omega=rad_s(w1), in_time=T)
        for name, x in (("friction", tf), ("viscous", b), ("drag", k)):
            if x:
                kw[name] = x
        return kw, dict(kind=kind, I=I, w0=w0, w1=w1, T=T, tf=tf, b=b, k=k)
    P = log_uniform(rng, -1, 4)
    tf, b, k = _losses(rng)
    if kind == "power_lossless":
        tf = b = k = 0.0
    if kind == "load_stop":
        P = -P
    motion = PowerMotion(I, P, tf, b, k, 1.0)
    steady = motion.omega_inf()
    if kind == "load_stop":
        w0 = log_uniform(rng, -1, 3)
    elif steady is None:
        w0 = log_uniform(rng, -1, 2)
    else:
        w0 = float(steady) * log_uniform(rng, -2, -0.05)
    kw = dict(inertia=I, power=P, omega0=rad_s(w0))
    for name, x in (("friction", tf), ("viscous", b), ("drag", k)):
        if x:
            kw[name] = x
    extra = dict(kind=kind, I=I, P=P, tf=tf, b=b, k=k, w0=w0)
    if kind == "power_until":
        top = float(steady) if steady is not None else w0 * 10
        extra["w1"] = w0 + (top - w0) * rng.uniform(0.05, 0.95)
        kw["until_omega"] = rad_s(extra["w1"])
    elif kind == "power_near_steady":
        extra["w1"] = w0 + (float(steady) - w0) * (1 - log_uniform(rng, -8, -2))
        kw["until_omega"] = rad_s(extra["w1"])
    elif kind in ("power_time", "power_lossless"):
        scale = I * w0 * w0 / abs(P)  # the time the power takes to double the energy
        extra["T"] = scale * log_uniform(rng, -2, 1)
        kw["time"] = extra["T"]
    return kw, extra


def check_spin(kw, extra):
    report = taucli.spin_down(**kw)
    kind = extra["kind"]
    rows = []
    with mp.workdps(DPS):
        if kind.startswith("in_time"):
            ref = in_time_torque(extra["I"], extra["w0"], extra["w1"], extra["T"], extra["tf"], extra["b"], extra["k"])
            budget = CLOSED if kind == "in_time_friction" else STEPPED
            for name in ("torque", "torque_net", "theta", "work_drive", "KE", "alpha0"):
                if name == "work_friction" and not extra["tf"]:
                    continue
                rows.append(Row(name, value(report, name), ref[name], budget))
            return rows
        motion = PowerMotion(extra["I"], extra["P"], extra["tf"], extra["b"], extra["k"], extra["w0"])
        w0 = mpf(extra["w0"])
        steady = motion.omega_inf()
        alpha0 = motion.rate(w0)
        rows.append(Row("alpha0", value(report, "alpha0"), alpha0, CLOSED * _cond_alpha(motion, w0)))
        if steady is not None:
            rows.append(Row("omega_inf", value(report, "omega_inf"), steady, CLOSED))
        rows.append(Row("KE0", value(report, "KE0"), motion.I * w0 * w0 / 2, CLOSED))
        lossless = kind == "power_lossless"
        budget = CLOSED if lossless else STEPPED
        if kind in ("power_until", "power_near_steady"):
            ref = motion.to_omega(extra["w1"])
            names = ("work_drive", "work_friction", "work_viscous", "work_drag", "KE")
            keys = (("t_until", "t"), ("theta_until", "theta"))
        elif kind == "load_stop":
            ref = motion.to_omega(0)
            names = ("work_drive", "work_friction", "work_viscous", "work_drag")
            keys = (("t_stop", "t"), ("theta_stop", "theta"))
        else:
            ref = motion.at_time(extra["T"])
            names = ("work_drive", "work_friction", "work_viscous", "work_drag", "KE")
            keys = (("omega", "omega"), ("theta", "theta"))
        # an rk45 step holds ω to rtol·ω; near a steady speed that moves the time by rtol·ω/|dω/dt|
        w1 = ref["omega"]
        if kind != "load_stop" and not lossless and ref["t"]:
            rate = abs(motion.rate(w1)) if w1 else 0
            slow = max(1.0, float(w1 / (rate * ref["t"]))) if rate else 1.0
        else:
            slow = 1.0
        for key, name in keys:
            rows.append(Row(key, value(report, key), ref[name], budget * slow))
        energy = max(abs(motion.I * w0 * w0 / 2), abs(ref["KE"]), abs(ref["work_drive"]))
        for name in names:  # each work is held to the budget of the whole energy (the stepper's norm)
            if ref[name] != 0:
                rows.append(Row(name, value(report, name), ref[name], budget * slow, floor=energy if not lossless else 0))
    return rows


def _cond_alpha(motion, w):
    terms = (motion.P / w, motion.tf, motion.b * w, motion.k * w * w)
    total = terms[0] - sum(terms[1:])
    return max(1.0, float(sum(abs(x) for x in terms) / abs(total))) if total else 1.0
