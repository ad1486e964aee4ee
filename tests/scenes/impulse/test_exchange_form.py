"""#42 item 8: every "after − before" of impulse formed from the exchange that makes it.

A change such as Δω = ω₁ − ω₀ written as the difference of two near-equal totals loses every
digit of a small change beside a large ω: a heavy body (I = 1e9 kg·m²) meeting a light one
(1e-9) changes its speed by about 1e-18 of it, which ω₁ − ω₀ rounds to 0. The references here are
the physics in 50 digits (mpmath), over random scenes with a body much larger than the other:

- bodies that lock, or a clutch that slips (L conserved): ω₁ = Σ I_k ω_k / Σ I_k, each body's
  angular impulse I_k(ω₁ − ω_k);
- a moment of inertia that changes (--inertia-final, --part-after): ω₁ = I₀ω₀/I₁, the work
  ½I₁ω₁² − ½I₀ω₀²;
- a particle m at r that sticks to a body (mass M, centre at d) across its radius: the pivot's
  impulse p₁ − p₀ = M d (ω₁ − ω₀) + m (ω₁ r − v)."""

from __future__ import annotations

import random

import mpmath
import pytest

import taucli

MP_DPS = 50  # conftest sets mpmath.mp.dps from it for each test
mpf = mpmath.mpf


def values(report):
    return {key: value.value for key, value in report.results.items()}


def parts(report):
    return {row[0]: row for row in report.tables["parts"].rows}


def close(got, want, rel=1e-13):
    want = float(want)
    assert got == pytest.approx(want, rel=rel, abs=0), (got, want)


def _draws(seed, n=40):
    rng = random.Random(seed)
    for _ in range(n):
        big = 10 ** rng.uniform(3, 12)
        small = 10 ** rng.uniform(-12, -2)
        yield rng, big, small


def test_the_issue_s_clutch_gives_the_small_change():
    r = values(taucli.impulse(inertia="1e9 kg*m^2", omega0="5 rad/s", couple="inertia=1e-9kg*m^2 omega0=0 torque=1N*m"))
    # ω₁ − ω₀ = I₂(ω₂ − ω₀)/(I + I₂) = −5e-18/(1 + 1e-18); J = I Δω
    close(r["delta_omega"], -mpf(5) * mpf("1e-9") / (mpf("1e9") + mpf("1e-9")))
    close(r["J"], -mpf(5) * mpf("1e-9") * mpf("1e9") / (mpf("1e9") + mpf("1e-9")))


@pytest.mark.parametrize("clutch", [False, True])
def test_two_bodies_on_one_axis_against_the_exchange(clutch):
    for rng, big, small in _draws(8 + clutch):
        w0, w2 = rng.uniform(-100, 100), rng.uniform(-100, 100)
        spec = f"inertia={small!r}kg*m^2 omega0={w2!r}rad/s" + (" torque=3N*m" if clutch else "")
        report = taucli.impulse(inertia=big, omega0=f"{w0!r} rad/s", couple=spec)
        r, rows = values(report), parts(report)
        i, i2, a, b = mpf(big), mpf(small), mpf(w0), mpf(w2)
        common = (i * a + i2 * b) / (i + i2)
        close(r["delta_omega"], common - a)
        close(r["J"], i * (common - a))
        close(rows["body"][3], i * (common - a))
        close(rows["couple"][3], i2 * (common - b))


def test_several_couples_each_one_s_impulse():
    for rng, big, small in _draws(81):
        w = [rng.uniform(-50, 50) for _ in range(3)]
        w[1] = w[0]  # a couple that turns with the body: its small impulse is the other couple's doing
        smalls = [small * rng.uniform(0.5, 2), small * rng.uniform(0.5, 2)]
        report = taucli.impulse(inertia=big, omega0=f"{w[0]!r} rad/s",
                                couple=[f"inertia={s!r}kg*m^2 omega0={x!r}rad/s" for s, x in zip(smalls, w[1:])])
        r, rows = values(report), parts(report)
        moments = [mpf(big), *(mpf(s) for s in smalls)]
        speeds = [mpf(x) for x in w]
        common = mpmath.fsum(i * x for i, x in zip(moments, speeds)) / mpmath.fsum(moments)
        close(r["delta_omega"], common - speeds[0])
        close(rows["couple 1"][3], moments[1] * (common - speeds[1]))
        close(rows["couple 2"][3], moments[2] * (common - speeds[2]))


def test_inertia_final_and_part_after_against_the_exchange():
    for rng, big, small in _draws(82):
        w0 = rng.uniform(-100, 100)
        r0, r1 = rng.uniform(0.1, 2), rng.uniform(0.1, 2)
        report = taucli.impulse(inertia=big, omega0=f"{w0!r} rad/s", part=f"point mass={small!r}kg offset={r0!r}m",
                                part_after=f"point mass={small!r}kg offset={r1!r}m")
        r = values(report)
        i0 = mpf(big) + mpf(small) * mpf(r0) ** 2
        i1 = mpf(big) + mpf(small) * mpf(r1) ** 2
        a = mpf(w0)
        close(r["delta_omega"], i0 * a / i1 - a)
        close(r["work"], (i0 * a) ** 2 / (2 * i1) - i0 * a * a / 2)
        # --inertia-final: the change of the two inputs as given
        f0, f1 = big, big * (1 + rng.uniform(-1e-9, 1e-9))
        r = values(taucli.impulse(inertia=f0, inertia_final=f1, omega0=f"{w0!r} rad/s"))
        close(r["delta_omega"], mpf(f0) * a / mpf(f1) - a, rel=1e-12)
        close(r["work"], (mpf(f0) * a) ** 2 / (2 * mpf(f1)) - mpf(f0) * a * a / 2, rel=1e-12)


def test_the_pivot_s_impulse_of_a_light_particle_on_a_heavy_rod():
    for rng, big, small in _draws(83):
        length, w0 = rng.uniform(0.5, 5), rng.uniform(-10, 10)
        r = rng.uniform(0.1, 1) * length
        v = rng.uniform(-10, 10) * r
        report = taucli.impulse(shape="rod", axis="end", mass=big, length=length, omega0=f"{w0!r} rad/s",
                                particle=f"mass={small!r}kg speed={v!r}m/s radius={r!r}m")
        got = values(report)
        M, L, m, R, V, a = (mpf(x) for x in (big, length, small, r, v, w0))
        inertia = M * L**2 / 3
        omega1 = (inertia * a + m * V * R) / (inertia + m * R**2)
        close(got["delta_omega"], omega1 - a)
        close(got["pivot_impulse"], M * L / 2 * (omega1 - a) + m * (omega1 * R - V), rel=1e-12)
        close(parts(report)["particle"][3], m * R * (omega1 * R - V), rel=1e-12)


def test_part_after_with_a_point_keeps_the_small_change():
    """--at r asks for a point of the body too: Δω is still ω₀(I₀ − I₁)/I₁ of the parts that moved,
    5 × 1e-9 × (1 − 4)/1e9 = −1.5e-17 rad/s (it printed −0)."""
    r = values(taucli.impulse(inertia="1e9 kg*m^2", omega0="5 rad/s", part="point mass=1e-9kg offset=1m", part_after="point mass=1e-9kg offset=2m",
                              at="1 m"))
    i0, i1 = mpf("1e9") + mpf("1e-9"), mpf("1e9") + 4 * mpf("1e-9")
    close(r["delta_omega"], 5 * i0 / i1 - 5)
