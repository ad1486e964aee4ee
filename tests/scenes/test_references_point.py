"""A point on a turning body (--at) in spin-down, impulse and atwood against 50-digit references
(tests/references/point.py; the pendulum's point is in test_references_pendulum.py).

v_t = |ω| r, a_t = r α along the motion (from rest: the sense α starts it in), a_c = ω² r,
a_total, a_angle = atan2(a_t, a_c), s = r θ, and the chord |r(cos θ, sin θ) − r(1, 0)| of the net
θ (#46 item 5), on closed-form motions (constant α; a drive against viscous drag,
α = (τ − bω₀)/I · e^{−bt/I}; the Atwood machine). Budget 1e-13, times the condition of
ω = ω₀ + αt where that sum cancels (and of the chord, |(θ/2)cot(θ/2)|, near whole turns).
"""

from __future__ import annotations

import math
import random

import mpmath
import pytest

import taucli
from references.point import point, viscous_drive
from references.scenes_point import KINDS, check_point, draw_point


@pytest.mark.parametrize("kind", KINDS)
def test_random_scenes_within_budget(kind):
    rng = random.Random(f"point-{kind}")
    bad = []
    for _ in range(120):
        kw, extra = draw_point(rng, kind)
        bad += [f"{kw}: {r.name}: taucli {r.got!r}, reference {mpmath.nstr(r.exact, 17)}, error {r.error:.3g} > {r.budget:.3g}"
                for r in check_point(kw, extra) if not r.known and not r.ok]
    assert not bad, "\n".join(bad)


def test_a_point_starting_from_rest_under_a_negative_torque():
    report = taucli.spin_down(inertia=2.0, torque=-3.0, time=2.0, at=0.5)
    assert float(point(0, -1.5, 0.5)["a_angle"]) == math.pi / 2  # the point starts moving the way α pushes it: a is all along the motion
    assert report.results["a_angle0"].value == pytest.approx(math.pi / 2, rel=1e-15, abs=0)


def test_a_t_near_a_steady_speed_keeps_its_digits():
    report = taucli.spin_down(inertia=2.0, torque=3.0, viscous=0.5, time=200.0, at=0.5)
    omega, alpha, theta = viscous_drive(2.0, 3.0, 0.5, 0.0, 200.0)
    exact = point(omega, alpha, 0.5, theta)["a_t"]  # 0.5 × 1.5 e^−50 = 1.4466e-22 m/s²
    assert report.results["a_t"].value == pytest.approx(float(exact), rel=1e-13, abs=0)
