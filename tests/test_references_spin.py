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
