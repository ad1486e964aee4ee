"""Independent references for the newer scenes, written from the physics at 50 digits.

Each module here is plain Python over mpmath: it takes a scene's inputs in SI (floats, read
exactly as binary numbers) and returns the scene's results as mpmath numbers, from the
equations of motion alone. None of it imports taucli's solvers (taucli/scenes/), so a result
that agrees with these is checked against the physics, not against the same arithmetic.

- pendulum: I θ'' = −m g d sin θ − κ θ, exactly (elliptic functions under gravity alone,
  quadrature of dθ/ω and a Taylor-series ODE solve with a spring).
- impulse: particles and couples meeting a body, L about the axis conserved.
- point: a point at radius r on a turning body (v_t, a_t, a_c, a_total, a_angle, s).
- spin: spin-down with a constant power and losses, and the drive torque of --in-time.

The helpers below are shared: the working precision and the relative error used by the tests.
"""

from __future__ import annotations

import mpmath

DPS = 50
mp = mpmath.mp


def mpf(x):
    """An input read exactly (a float is a binary number; mpf keeps every one of its bits)."""
    return x if isinstance(x, mpmath.mpf) else mpmath.mpf(x)


def relative_error(got, exact) -> float:
    """|got − exact| / |exact| at 50 digits; |got| where the exact value is 0."""
    with mp.workdps(DPS):
        exact = mpf(exact)
        if exact == 0:
            return float(abs(mpf(got)))
        return float(abs(mpf(got) - exact) / abs(exact))
