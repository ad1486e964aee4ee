"""Random impulse scenes with particles and couples, and their comparison with references.impulse."""

from __future__ import annotations

import math

import mpmath

import taucli
from references import DPS, mp, mpf
from references.compare import Row, log_uniform, rad_s, value
from references.impulse import Couple, Particle, meet

CLOSED = 1e-13
KINDS = ("stick", "stick_angle", "leave", "bounce", "bounce_elastic", "ride", "couple", "heavy_couple", "small", "mixed", "walk", "walk_moving", "walkers")


def particle_text(p: Particle) -> str:
    words = [f"mass={p.mass!r}kg", f"radius={p.radius!r}m"]
    if p.speed is not None:
        words.append(f"speed={p.speed!r}m/s")
    if p.angle is not None:
        words.append(f"angle={p.angle!r}rad")
    if p.speed_after is not None:
        words.append(f"speed-after={p.speed_after!r}m/s")
    if p.e is not None:
        words.append(f"e={p.e!r}")
    if p.radius_after is not None:
        words.append(f"radius-after={p.radius_after!r}m")
    if p.speed_relative is not None:
        words.append(f"speed-relative={p.speed_relative!r}m/s")
    return " ".join(words)


def couple_text(c: Couple) -> str:
    return f"inertia={c.inertia!r}kg*m^2 omega0={c.omega0!r}rad/s"


def draw_impulse(rng, kind=None):
    kind = kind or rng.choice(KINDS)
    inertia = log_uniform(rng, -3, 4)
    omega0 = rng.choice((0.0, 1.0, -1.0)) * log_uniform(rng, -3, 3)
    r = log_uniform(rng, -2, 1)
    ratio = log_uniform(rng, -12, 3)
    m = ratio * inertia / (r * r)
    v = rng.choice((-1, 1)) * log_uniform(rng, -2, 2) * max(abs(omega0) * r, 1e-3)
    particles, couples = [], []
    if kind == "stick":
        particles.append(Particle(m, r, speed=v))
    elif kind == "stick_angle":
        particles.append(Particle(m, r, speed=v, angle=rng.uniform(0.05, math.pi - 0.05)))
    elif kind == "leave":
        particles.append(Particle(m, r, speed=v, speed_after=v * rng.uniform(-1, 1)))
    elif kind == "bounce":
        particles.append(Particle(m, r, speed=v, e=rng.uniform(0, 1), angle=rng.choice((None, rng.uniform(0.05, 3.09)))))
    elif kind == "bounce_elastic":
        particles.append(Particle(m, r, speed=v, e=1 - log_uniform(rng, -12, -1)))
    elif kind == "ride":
        particles.append(Particle(m, r, radius_after=r * log_uniform(rng, -1, 1)))
    elif kind == "couple":
        couples.append(Couple(inertia * log_uniform(rng, -6, 6), omega0 + rng.choice((-1, 1)) * log_uniform(rng, -3, 3)))
    elif kind == "heavy_couple":
        couples.append(Couple(inertia * log_uniform(rng, 3, 12), omega0 * (1 + log_uniform(rng, -12, 0)) + rng.choice((0, 1e-3))))
    elif kind == "small":  # a particle whose speed nearly matches the body's: a small exchange
        if omega0 == 0:
            omega0 = 1.0
        particles.append(Particle(m, r, speed=omega0 * r * (1 + rng.choice((-1, 1)) * log_uniform(rng, -12, -3))))
    elif kind == "walk":  # a train on a track on a free wheel, a person walking on a turntable: it rode before
        particles.append(Particle(m, r, speed_relative=v, radius_after=rng.choice((None, r * log_uniform(rng, -1, 0.5)))))
    elif kind == "walk_moving":  # it meets the body at speed=, then moves along it at speed-relative=
        particles.append(Particle(m, r, speed=v * rng.uniform(-1, 1), speed_relative=v * rng.uniform(-1, 1),
                                  angle=rng.choice((None, rng.uniform(0.05, 3.09)))))
    elif kind == "walkers":  # several, with a couple or a rider beside them
        for _ in range(rng.randint(2, 3)):
            particles.append(Particle(m * log_uniform(rng, -1, 1), r * rng.uniform(0.1, 1), speed_relative=v * rng.uniform(-1, 1)))
        if rng.random() < 0.5:
            couples.append(Couple(inertia * log_uniform(rng, -3, 3), omega0 + rng.uniform(-1, 1)))
        else:
            particles.append(Particle(m, r, radius_after=r * rng.uniform(0.1, 2)))
    else:
        for _ in range(rng.randint(2, 3)):
            choice = rng.choice(("stick", "leave", "ride", "couple"))
            mm = m * log_uniform(rng, -1, 1)
            if choice == "stick":
                particles.append(Particle(mm, r, speed=v * rng.uniform(-1, 1)))
            elif choice == "leave":
                particles.append(Particle(mm, r, speed=v, speed_after=v * rng.uniform(-1, 1)))
            elif choice == "ride":
                particles.append(Particle(mm, r, radius_after=r * rng.uniform(0.1, 2)))
            else:
                couples.append(Couple(inertia * log_uniform(rng, -3, 3), omega0 + rng.uniform(-1, 1)))
    kw = dict(inertia=inertia, omega0=rad_s(omega0))
    if particles:
        kw["particle"] = [particle_text(p) for p in particles]
    if couples:
        kw["couple"] = [couple_text(c) for c in couples]
    return kw, (inertia, omega0, particles, couples), dict(kind=kind)


def check_impulse(kw, scene, extra):
    inertia, omega0, particles, couples = scene
    report = taucli.impulse(**kw)
    exact = meet(inertia, omega0, particles, couples)
    rows = []
    with mp.workdps(DPS):
        # the physics allows the budget times the condition of the small speeds the inputs make
        cond = _condition(omega0, particles, couples)
        w1 = exact["omega1"]
        w1_cond = max(1.0, float((abs(mpf(omega0)) + abs(exact["delta_omega"]) * cond) / abs(w1))) if w1 else 1.0
        budgets = dict(J=cond, delta_omega=cond, omega1=w1_cond, KE1=2 * w1_cond, KE_lost=cond, KE_lost_fraction=cond,
                       L0=_l_scale(inertia, omega0, particles, couples, exact["L0"]))
        budgets["L1"] = budgets["L0"]
        for name in ("J", "delta_omega", "omega1", "L0", "L1", "KE0", "KE1", "KE_lost", "KE_lost_fraction"):
            rows.append(Row(name, value(report, name), exact[name], CLOSED * budgets.get(name, 1.0)))
    return rows


def _condition(omega0, particles, couples) -> float:
    """The largest condition of the small differences of inputs the exchange is made of."""
    w0 = mpf(omega0)
    worst = mpf(1)

    def ratio(parts, total):
        nonlocal worst
        if total:
            worst = max(worst, sum(abs(x) for x in parts) / abs(total))

    for c in couples:
        ratio((mpf(c.omega0), w0), mpf(c.omega0) - w0)
    for p in particles:
        m, r = mpf(p.mass), mpf(p.radius)
        if p.speed_relative is not None:  # I₁Δω gains m (L/m before − ρ²ω₀ − ρ v_rel)
            r2 = mpf(p.radius_after) if p.radius_after is not None else r
            vr = mpf(p.speed_relative)
            before = mpf(p.speed) * r * (mpmath.sin(mpf(p.angle)) if p.angle is not None else 1) if p.speed is not None else r * r * w0
            ratio((before, r2 * r2 * w0, r2 * vr), before - r2 * r2 * w0 - r2 * vr)
            continue
        if p.speed is None:
            r2 = mpf(p.radius_after) if p.radius_after is not None else r
            ratio((r, r2), r - r2)
            continue
        v = mpf(p.speed)
        perp = r * (mpmath.sin(mpf(p.angle)) if p.angle is not None else 1)
        ratio((v, w0 * perp), v - w0 * perp)
        ratio((v * perp / r, w0 * r), v * perp / r - w0 * r)
        if p.speed_after is not None:
            v2 = mpf(p.speed_after)
            ratio((v, v2), v - v2)
            ratio((v, v2, 2 * w0 * perp), v + v2 - 2 * w0 * perp)
        del m
    return float(worst)


def _l_scale(inertia, omega0, particles, couples, total):
    """L₀ is a sum of signed terms: its condition Σ|terms| / |Σ|."""
    terms = [abs(mpf(inertia) * mpf(omega0))]
    terms += [abs(mpf(c.inertia) * mpf(c.omega0)) for c in couples]
    for p in particles:
        terms.append(abs(mpf(p.mass) * mpf(p.radius) * (mpf(p.speed) if p.speed is not None else mpf(p.radius) * mpf(omega0))))
    return max(1.0, float(sum(terms) / abs(total))) if total else 1.0
