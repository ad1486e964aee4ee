"""spin-down with --power and --in-time against 50-digit references (tests/references/spin.py).

A constant power P against τ_f + bω + kω² by quadrature over ω (the steady speed's pole taken
away by ω = ω∞ − (ω∞ − ω₀)e^{−s}); the drive torque of --in-time by solving
T = ∫ I dω/(τ − L(ω)) for τ. taucli integrates these with rk45 (rtol 1e-10): budget 1e-8,
times the slowness of the approach to a steady speed (an error rtol·ω in ω moves the time by
rtol·ω/|dω/dt|); each work is held relative to the scene's whole energy, as the stepper's
norm holds it. Closed forms (no losses; friction alone) are held to 1e-13.
"""

from __future__ import annotations

import random

import mpmath
import pytest

import taucli
from references.spin import PowerMotion

from references.scenes_spin import check_spin, draw_spin

COUNTS = {"power_until": 12, "power_time": 8, "power_near_steady": 10, "load_stop": 10, "power_lossless": 20, "in_time": 3, "in_time_friction": 30}


@pytest.mark.parametrize("kind", sorted(COUNTS))
def test_random_scenes_within_budget(kind):
    rng = random.Random(f"spin-{kind}")
    bad = []
    for _ in range(COUNTS[kind]):
        kw, extra = draw_spin(rng, kind)
        bad += [f"{kw}: {r.name}: taucli {r.got!r}, reference {mpmath.nstr(r.exact, 17)}, error {r.error:.3g} > {r.budget:.3g}"
                for r in check_spin(kw, extra) if not r.known and not r.ok]
    assert not bad, "\n".join(bad)


@pytest.mark.xfail(strict=True, reason="under --power, work_viscous and work_drag are split wrongly where both act: 7806.06 J and 748405.58 J for 7826.42 J and 748385.22 J (0.26%; their sum holds)")
def test_the_works_of_viscous_and_drag_under_a_load():
    kw = dict(inertia=1.7599471323725313, power=-0.16652331956453104, viscous=0.014962693871135892, drag=0.0030283791411783215)
    report = taucli.spin_down(**kw, omega0="927.0286450082666 rad/s")
    exact = PowerMotion(kw["inertia"], kw["power"], 0, kw["viscous"], kw["drag"], 927.0286450082666).to_omega(0)
    assert report.results["work_viscous"].value == pytest.approx(float(exact["work_viscous"]), rel=1e-8, abs=0)
    assert report.results["work_drag"].value == pytest.approx(float(exact["work_drag"]), rel=1e-8, abs=0)
