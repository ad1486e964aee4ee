"""Random scenes with a point on a turning body (--at), compared with references.point."""

from __future__ import annotations

import math

import mpmath

import taucli
from references import DPS, mp, mpf
from references.compare import Row, log_uniform, rad_s, value
from references.point import atwood, chord, constant_alpha, point, viscous_drive

CLOSED = 1e-13
KINDS = ("torque", "torque_from_rest", "alpha", "steady", "impulse", "atwood_time", "atwood_distance")


def _cond(*terms) -> float:
    """Σ|terms| / |Σ terms|: how much a sum of these loses."""
    with mp.workdps(DPS):
        total = sum(mpf(x) for x in terms)
        return max(1.0, float(sum(abs(mpf(x)) for x in terms) / abs(total))) if total else 1.0


def draw_point(rng, kind=None):
    kind = kind or rng.choice(KINDS)
    r = log_uniform(rng, -3, 2)
    I = log_uniform(rng, -3, 3)
    sign = rng.choice((-1, 1))
    w0 = 0.0 if kind in ("torque_from_rest",) or rng.random() < 0.3 else rng.choice((-1, 1)) * log_uniform(rng, -3, 3)
    t = log_uniform(rng, -3, 2)
    if kind in ("torque", "torque_from_rest"):
        tau = sign * log_uniform(rng, -3, 3)
        kw = dict(inertia=I, torque=tau, omega0=rad_s(w0), time=t, at=r)
        w, a, th = constant_alpha(w0, mpf(tau) / mpf(I), t)
        start = (w0, mpf(tau) / mpf(I))
    elif kind == "alpha":
        alpha = sign * log_uniform(rng, -3, 3)
        kw = dict(alpha=f"{alpha!r} rad/s^2", omega0=rad_s(w0), time=t, at=r)
        w, a, th = constant_alpha(w0, alpha, t)
        start = (w0, mpf(alpha))
    elif kind == "steady":
        tau, b = log_uniform(rng, -3, 3), log_uniform(rng, -3, 3)
        t = I / b * log_uniform(rng, -1, math.log10(600))  # up to 600 time constants: α down to e^−600
        w0 = abs(w0)
        kw = dict(inertia=I, torque=tau, viscous=b, omega0=rad_s(w0), time=t, at=r)
        w, a, th = viscous_drive(I, tau, b, w0, t)
        start = (w0, (mpf(tau) - mpf(b) * mpf(w0)) / mpf(I))
    elif kind == "impulse":
        tau, dt = sign * log_uniform(rng, -3, 3), log_uniform(rng, -3, 1)
        kw = dict(inertia=I, torque=tau, duration=dt, omega0=rad_s(w0), at=r)
        w, a, th = constant_alpha(w0, mpf(tau) / mpf(I), dt)
        t = dt
        start = (w0, mpf(tau) / mpf(I))
    else:
        m1, m2 = log_uniform(rng, -2, 2), log_uniform(rng, -2, 2)
        if kind == "atwood_distance" and m1 <= m2:
            m1, m2 = m2 * 1.5, m1
        R = r * rng.uniform(1, 3)
        pulley = log_uniform(rng, -3, 1) * (m1 + m2) * R * R
        v0 = 0.0 if rng.random() < 0.5 else (log_uniform(rng, -2, 1) * (1 if kind == "atwood_distance" else rng.choice((-1, 1))))
        kw = dict(m1=m1, m2=m2, pulley_inertia=pulley, pulley_radius=R, v0=v0, at=r)
        if kind == "atwood_distance":
            D = log_uniform(rng, -2, 1)
            kw["distance"] = D
            w, a, th = atwood(m1, m2, pulley, R, 9.80665, v0, distance=D)
        else:
            kw["time"] = t
            w, a, th = atwood(m1, m2, pulley, R, 9.80665, v0, t=t)
        start = (mpf(v0) / mpf(R), a)
    return kw, dict(kind=kind, omega=w, alpha=a, theta=th, start=start, t=t, r=r)


def check_point(kw, extra):
    kind = extra["kind"]
    scene = taucli.atwood if kind.startswith("atwood") else taucli.impulse if kind == "impulse" else taucli.spin_down
    report = scene(**kw)
    r, w, a, th = extra["r"], extra["omega"], extra["alpha"], extra["theta"]
    w0, a0 = extra["start"]
    end = point(w, a, r, th)
    first = point(w0, a0, r)
    with mp.workdps(DPS):
        t = mpf(extra["t"])
        if kind == "steady":
            cw = _cond(mpf(w) - (mpf(w) - mpf(w0)), mpf(w) - mpf(w0))
            cth = 1.0
        elif kind == "atwood_distance":
            cw = cth = 1.0
        else:
            cw = _cond(w0, a * t)
            cth = _cond(mpf(w0) * t, a * t * t / 2)
        rows = []
        if kind not in ("atwood_time", "atwood_distance"):
            rows.append(Row("omega" if kind != "impulse" else "omega1", value(report, "omega" if kind != "impulse" else "omega1"), w, CLOSED * cw))
        rows += [Row("v_t", value(report, "v_t"), end["v_t"], CLOSED * cw), Row("a_c", value(report, "a_c"), end["a_c"], 2 * CLOSED * cw),
                 Row("a_t", value(report, "a_t"), end["a_t"], CLOSED),
                 Row("a_total", value(report, "a_total"), end["a_total"], 2 * CLOSED * cw),
                 Row("a_angle", value(report, "a_angle"), end["a_angle"], 2 * CLOSED * cw)]
        if "s" in end:
            rows.append(Row("s", value(report, "s"), end["s"], CLOSED * cth))
            # the chord 2r|sin(θ/2)| carries θ's error times its condition |(θ/2)cot(θ/2)| (large near whole turns)
            half = mpf(th) / 2
            bend = abs(half / mpmath.tan(half)) if half else 1
            rows.append(Row("chord", value(report, "chord"), chord(r, th), CLOSED * cth * max(1.0, float(bend))))
        rows += [Row("v_t0", value(report, "v_t0"), first["v_t"], CLOSED), Row("a_c0", value(report, "a_c0"), first["a_c"], CLOSED),
                 Row("a_total0", value(report, "a_total0"), first["a_total"], CLOSED),
                 Row("a_angle0", value(report, "a_angle0"), first["a_angle"], CLOSED)]
    return [row for row in rows if not (row.got is None and row.exact is not None and row.name in ("s", "chord") and kind == "impulse")]

