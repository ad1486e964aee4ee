"""Elliptic integrals of the first kind and Jacobi's elliptic functions, in double precision.

The pendulum's exact motion: with k = sin(θ_max/2), sin(θ/2) = k·sn(ω₀t, k), and its period is
4K(k)/ω₀. Near 180°, k -> 1 and K(k) grows like ln(4/k'): every function here takes the
complementary modulus k' = √(1 − k²) as given (the caller forms it as cos(θ_max/2), or from a
product of sums), never 1 − k², so an amplitude of 179.9999° keeps all its digits.

- ``complete_k(kc)``: K = π / (2·AGM(1, k')) (the arithmetic-geometric mean, quadratic).
- ``carlson_rf(x, y, z)``: Carlson's symmetric R_F by the duplication theorem (Carlson 1995).
- ``incomplete_f(s, c, kc)``: F(φ, k) = sin φ · R_F(cos²φ, cos²φ + k'² sin²φ, 1), from sin φ and
  cos φ (so that φ near π/2 loses nothing), for any φ in [−π, π].
- ``jacobi(u, kc)``: (sn, cn, dn) by the descending Landen transformation (Abramowitz & Stegun
  16.4), with u first reduced modulo the period 4K, polished by Newton's method on F(am u) = u
  (Landen alone loses digits as k -> 1), and dn formed as √(k'² + k²cn²), a sum of positive terms.

Checked against mpmath at 50 digits in tests/scenes/pendulum/test_pendulum.py.
"""

from __future__ import annotations

import math

EPSILON = 2.0**-52
_RF_TOLERANCE = (3 * 2.0**-53) ** (-1 / 6)  # Carlson's (3r)^(-1/6) for r at double precision


def agm(a: float, b: float) -> float:
    """The arithmetic-geometric mean of a, b > 0 (quadratic convergence)."""
    for _ in range(64):
        if abs(a - b) <= 2 * EPSILON * a:
            break
        a, b = (a + b) / 2, math.sqrt(a * b)
    return (a + b) / 2


def complete_k(kc: float) -> float:
    """K(k), the complete elliptic integral of the first kind, from k' = √(1 − k²) > 0."""
    if kc <= 0:
        return math.inf
    return math.pi / (2 * agm(1.0, kc))


def carlson_rf(x: float, y: float, z: float) -> float:
    """Carlson's R_F(x, y, z) = ½∫₀^∞ dt / √((t+x)(t+y)(t+z)), x, y, z ≥ 0, at most one zero."""
    a0 = a = (x + y + z) / 3
    q = _RF_TOLERANCE * max(abs(a0 - x), abs(a0 - y), abs(a0 - z))
    x0, y0 = x, y
    scale = 1.0
    for _ in range(64):
        if q * scale < abs(a):
            break
        sx, sy, sz = math.sqrt(x), math.sqrt(y), math.sqrt(z)
        lam = sx * sy + sx * sz + sy * sz
        a, x, y, z = (a + lam) / 4, (x + lam) / 4, (y + lam) / 4, (z + lam) / 4
        scale /= 4
    dx = (a0 - x0) * scale / a
    dy = (a0 - y0) * scale / a
    dz = -dx - dy
    e2 = dx * dy - dz * dz
    e3 = dx * dy * dz
    return (1 - e2 / 10 + e3 / 14 + e2 * e2 / 24 - 3 * e2 * e3 / 44) / math.sqrt(a)


def incomplete_f(s: float, c: float, kc: float) -> float:
    """F(φ, k) = ∫₀^φ dψ/√(1 − k² sin²ψ) for φ in [−π, π], given s = sin φ, c = cos φ, k' ≥ 0.

    Past π/2 (c < 0), F(φ) = 2K − F(π − φ); F is odd in φ. At k' = 0 and |φ| ≥ π/2 it is infinite.
    """
    if c < 0:
        big = complete_k(kc)
        return math.copysign(2 * big - incomplete_f(abs(s), -c, kc), s) if math.isfinite(big) else math.copysign(math.inf, s)
    if s == 0:
        return 0.0 * s
    c2 = c * c
    if c2 == 0 and kc == 0:
        return math.copysign(math.inf, s)
    return s * carlson_rf(c2, c2 + kc * kc * s * s, 1.0)


def jacobi(u: float, kc: float) -> tuple[float, float, float]:
    """(sn, cn, dn)(u, k) for 0 < k' ≤ 1 (k = √(1 − k'²)), by the descending Landen transformation."""
    k = math.sqrt((1 - kc) * (1 + kc))
    if k == 0:
        return math.sin(u), math.cos(u), 1.0
    quarter = complete_k(kc)
    period = 4 * quarter
    u = math.remainder(u, period)  # now in [−2K, 2K]
    # the AGM sequence: a_{n+1} = (a_n + b_n)/2, b_{n+1} = √(a_n b_n), c_{n+1} = c_n²/(4a_{n+1})
    a, b, c = 1.0, kc, k
    ratios = []
    for _ in range(64):
        if abs(c) <= EPSILON * a:
            break
        a, b, c = (a + b) / 2, math.sqrt(a * b), c * c / (4 * ((a + b) / 2))
        ratios.append(c / a)
    phi = 2 ** len(ratios) * a * u
    for ratio in reversed(ratios):
        phi = (phi + math.asin(ratio * math.sin(phi))) / 2
    # Near k = 1 the Landen steps lose digits (asin of nearly 1): a cn of 1e-6 came out 2e-5
    # off at k' = 1e-12. Newton on F(φ) = u puts them back, since dF/dφ = 1/dn and F is accurate.
    for _ in range(2):
        sn, cn = math.sin(phi), math.cos(phi)
        # F(φ) is taken on [−π, π]: at u = ±2K (φ = ±π) its branch can differ from u's by a whole
        # period 4K, which is no error at all
        phi -= math.remainder(incomplete_f(sn, cn, kc) - u, period) * math.hypot(cn, kc * sn)
    sn, cn = math.sin(phi), math.cos(phi)
    return sn, cn, math.hypot(kc, k * cn)


def amplitude(u: float, kc: float) -> float:
    """am(u, k), unwrapped: am(u + 2K) = am(u) + π (so that θ = 2 am grows with u in circulation)."""
    quarter = complete_k(kc)
    turns = math.floor((u + quarter) / (2 * quarter))
    sn, cn, _ = jacobi(u - 2 * quarter * turns, kc)
    return math.atan2(sn, cn) + math.pi * turns
