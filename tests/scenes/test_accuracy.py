"""The accuracy budget: every closed form within 1e-14 of a 50-digit evaluation, over the valid
input space, limits drawn on purpose. (Spin-down's closed forms are in test_spin.py, the thick
shell and tube in test_inertia.py, near-equal Atwood masses in test_atwood.py.)

Correctness of each formula is tested elsewhere against independent references; here the
50-digit evaluation of the same physics measures only the floating-point error of taucli's
arithmetic. Figures in the docstrings were measured with 20,000 draws per test
(tests/benchmarks/accuracy_budget.py).
"""

from __future__ import annotations

import math

import mpmath
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from taucli.scenes.atwood import HANGING, Pulley, Slope
from taucli.scenes.atwood import solve as atwood
from taucli.scenes.impulse import solve_balance, solve_changing_inertia
from taucli.scenes.inertia import SHAPES, Part, part_inertia
from taucli.scenes.rolling import K2, Roller, solve_incline

BUDGET = 1e-14
mp = mpmath.mp


def relative(got: float, exact) -> float:
    return float(abs(mpmath.mpf(got) - exact) / abs(exact)) if exact else abs(got)


sizes = st.one_of(st.floats(1e-3, 1e3), st.integers(-30, 30).map(lambda e: 10.0**e))
masses = st.one_of(st.floats(1e-3, 1e3), st.integers(-20, 20).map(lambda e: 10.0**e))

EXACT_INERTIA = {  # the textbook forms, evaluated at 50 digits
    ("ring", "central"): lambda m, d: m * d["radius"] ** 2,
    ("ring", "diameter"): lambda m, d: m * d["radius"] ** 2 / 2,
    ("disc", "central"): lambda m, d: m * d["radius"] ** 2 / 2,
    ("disc", "diameter"): lambda m, d: m * (d["radius"] ** 2 / 4 + d.get("length", 0) ** 2 / 12),
    ("sphere", "central"): lambda m, d: 2 * m * d["radius"] ** 2 / 5,
    ("shell", "central"): lambda m, d: 2 * m * d["radius"] ** 2 / 3,
    ("rod", "center"): lambda m, d: m * d["length"] ** 2 / 12,
    ("rod", "end"): lambda m, d: m * d["length"] ** 2 / 3,
    ("plate", "normal"): lambda m, d: m * (d["width"] ** 2 + d["height"] ** 2) / 12,
    ("plate", "edge-width"): lambda m, d: m * d["height"] ** 2 / 3,
    ("box", "height"): lambda m, d: m * (d["width"] ** 2 + d["depth"] ** 2) / 12,
    ("cone", "central"): lambda m, d: 3 * m * d["radius"] ** 2 / 10,
    ("point", "distance"): lambda m, d: m * d["radius"] ** 2,
}


@settings(max_examples=400, deadline=None)
@given(case=st.sampled_from(sorted(EXACT_INERTIA)), mass=masses, a=sizes, b=sizes, c=sizes, offset=st.one_of(st.none(), sizes))
def test_shape_formulas_and_the_parallel_axis_shift(case, mass, a, b, c, offset):
    """Measured: at most 1.32 ulp without a shift, 1.27 ulp with one."""
    shape, axis = case
    names = SHAPES[shape].dims or ("radius",)
    extra = {"disc": ("length",)}.get(shape, ())
    dims = dict(zip((*names, *extra), (a, b, c)))
    if not SHAPES[shape].axis(axis).through_centre or shape == "point":
        offset = None
    got = part_inertia(Part(shape, mass, dims, axis, offset)).inertia
    with mp.workdps(50):
        exact = EXACT_INERTIA[case](mpmath.mpf(mass), {k: mpmath.mpf(v) for k, v in dims.items()})
        if offset is not None:
            exact += mpmath.mpf(mass) * mpmath.mpf(offset) ** 2
        assert relative(got, exact) <= BUDGET


@settings(max_examples=400, deadline=None)
@given(
    m1=masses,
    m2=st.one_of(st.just(0.0), masses),
    pulley_mass=st.one_of(st.just(0.0), masses),
    angle=st.one_of(st.just(HANGING), st.floats(0, HANGING)),
    mu=st.floats(0, 1),
)
def test_atwood_acceleration_and_tensions(m1, m2, pulley_mass, angle, mu):
    """a, T1, T2 against (m1 − m2 sin θ − μ m2 cos θ)g/(m1 + m2 + M/2) and the body equations.

    Near-critical friction is in the draw: there the net pull cancels by a factor
    κ = (m1 + m2 sin θ + μ m2 cos θ)/|pull|, and the rounding of sin θ and cos θ alone is
    amplified by κ. The budget is 1e-14 where κ ≤ 10, and 8 ulp × κ beyond; near-equal hanging
    masses, where (m1 − m2) is exact, stay within 4 ulp (test_atwood.py). Measured: at most
    2.16 ulp × max(κ, 1).
    """
    hanging = angle == HANGING
    mu = 0.0 if hanging else mu
    g = 9.80665
    report = atwood(m1, m2, Pulley(pulley_mass), g, slope=Slope(angle, mu, mu))
    a = report.results["a"].value
    assume(a != 0)
    with mp.workdps(100):  # masses span 40 decades: g − a needs more than 50 digits to resolve
        m1_, m2_, M_, g_ = (mpmath.mpf(x) for x in (m1, m2, pulley_mass, g))
        sin_a = 1 if hanging else mpmath.sin(mpmath.mpf(angle))
        normal = 0 if hanging else m2_ * g_ * mpmath.cos(mpmath.mpf(angle))
        direction = 1 if a > 0 else -1
        pull = m1_ * g_ - m2_ * g_ * sin_a - direction * mu * normal
        cancellation = 1 if hanging else (m1_ * g_ + m2_ * g_ * sin_a + mu * normal) / abs(pull)
        budget = max(BUDGET, 8 * 2.0**-52 * float(cancellation))
        exact_a = pull / (m1_ + m2_ + M_ / 2)
        assert relative(a, exact_a) <= budget
        assert relative(report.results["T1"].value, m1_ * (g_ - exact_a)) <= budget
        if m2:
            tension_low = m2_ * (exact_a + g_ * sin_a) + direction * mu * normal
            assert relative(report.results["T2"].value, tension_low) <= budget


@settings(max_examples=400, deadline=None)
@given(
    shape=st.sampled_from(sorted(K2)),
    angle=st.one_of(st.floats(1e-300, 1.5707), st.integers(1, 300).map(lambda e: 10.0**-e)),
    ratio=st.floats(0, 0.999),
)
def test_rolling_and_slipping_accelerations_down_to_tiny_angles(shape, angle, ratio):
    """a = g sin θ/(1+k²) rolling; g(sin θ − μk cos θ) slipping (μk = ratio × μ_min, so the
    difference never cancels by more than a factor 1 + k²). Measured: at most 1.47 ulp."""
    k2, g = K2[shape], 9.80665
    mu_min = math.tan(angle) * k2 / (1 + k2)
    rolling = solve_incline(Roller(k2, shape, 1.0, 0.1), angle, g).results
    slipping = solve_incline(Roller(k2, shape, 1.0, 0.1), angle, g, mu_s=mu_min * ratio, mu_k=mu_min * ratio).results
    with mp.workdps(50):
        theta = mpmath.mpf(angle)
        assert relative(rolling["a"].value, g * mpmath.sin(theta) / (1 + mpmath.mpf(k2))) <= BUDGET
        assert relative(rolling["mu_min"].value, mpmath.tan(theta) * k2 / (1 + mpmath.mpf(k2))) <= BUDGET
        if not slipping["rolls"].value:
            exact = g * (mpmath.sin(theta) - mpmath.mpf(mu_min * ratio) * mpmath.cos(theta))
            assert relative(slipping["a"].value, exact) <= BUDGET


normal_floats = st.floats(-1e3, 1e3).filter(lambda x: x == 0 or abs(x) > 1e-100)  # no subnormal underflow


@settings(max_examples=400, deadline=None)
@given(inertia=masses, omega0=normal_floats, torque=normal_floats, duration=sizes, inertia1=masses)
def test_impulse_closed_forms(inertia, omega0, torque, duration, inertia1):
    """ω₁ = ω₀ + τΔt/I, and ω₁ = I₀ω₀/I₁ with KE₁ = ½I₀ω₀·ω₁.

    Where ω₀ and τΔt/I nearly cancel, κ = (|ω₀| + |τΔt/I|)/|ω₁| amplifies their rounding, and
    the budget is 8 ulp × κ there (1e-14 where κ ≤ 10). Measured: at most 1.71 ulp × max(κ, 1).
    """
    with mp.workdps(100):
        i, w0, tau, dt = (mpmath.mpf(x) for x in (inertia, omega0, torque, duration))
        exact = w0 + tau * dt / i
        if exact:
            cancellation = (abs(w0) + abs(tau * dt / i)) / abs(exact)
            budget = max(BUDGET, 8 * 2.0**-52 * float(cancellation))
            assert relative(solve_balance(inertia, omega0, None, torque, duration).results["omega1"].value, exact) <= budget
        if omega0:
            changed = solve_changing_inertia(inertia, inertia1, omega0).results
            assert relative(changed["omega1"].value, i * w0 / mpmath.mpf(inertia1)) <= BUDGET
            assert relative(changed["KE1"].value, (i * w0) ** 2 / (2 * mpmath.mpf(inertia1))) <= BUDGET
