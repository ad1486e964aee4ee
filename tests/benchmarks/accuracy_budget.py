"""Measure the accuracy budget's figures (run by hand): 20,000 draws per closed form.

    python tests/benchmarks/accuracy_budget.py

Prints the largest error in ulp of each closed form in tests/scenes/test_accuracy.py against a
100-digit evaluation (Atwood and impulse: per unit of the cancellation factor κ of the data).
"""
import math, random, mpmath
from taucli.scenes.inertia import SHAPES, Part, part_inertia
from taucli.scenes.atwood import HANGING, Pulley, Slope, solve as atwood
from taucli.scenes.rolling import K2, Roller, solve_incline
from taucli.scenes.impulse import solve_balance, solve_changing_inertia
import sys; sys.path[:0] = [str(__import__('pathlib').Path(__file__).resolve().parents[1]), str(__import__('pathlib').Path(__file__).resolve().parents[1] / 'scenes')]  # tests/ and tests/scenes/ (test_accuracy)
from test_accuracy import EXACT_INERTIA
mpmath.mp.dps = 100
U = mpmath.mpf(2)**-52
rng = random.Random(7)
def ulps(got, exact): return float(abs(mpmath.mpf(got)-exact)/(abs(exact)*U)) if exact else 0.0
def size(): return rng.choice([10**rng.uniform(-3,3), 10.0**rng.randint(-30,30)])
def mass(): return rng.choice([10**rng.uniform(-3,3), 10.0**rng.randint(-20,20)])
N = 20000
w0 = w1 = 0
cases = sorted(EXACT_INERTIA)
for _ in range(N):
    shape, axis = rng.choice(cases); m = mass(); a, b, c = size(), size(), size()
    names = SHAPES[shape].dims or ("radius",); extra = {"disc": ("length",)}.get(shape, ())
    dims = dict(zip((*names, *extra), (a, b, c)))
    off = size() if rng.random() < 0.5 and SHAPES[shape].axis(axis).through_centre and shape != "point" else None
    got = part_inertia(Part(shape, m, dims, axis, off)).inertia
    ex = EXACT_INERTIA[(shape, axis)](mpmath.mpf(m), {k: mpmath.mpf(v) for k, v in dims.items()})
    if off is not None: ex += mpmath.mpf(m)*mpmath.mpf(off)**2; w1 = max(w1, ulps(got, ex))
    else: w0 = max(w0, ulps(got, ex))
print(f"inertia: {w0:.2f} ulp unshifted, {w1:.2f} ulp shifted")
worst = 0
for _ in range(N):
    m1 = mass(); m2 = rng.choice([0.0, mass()]); M = rng.choice([0.0, mass()])
    angle = rng.choice([HANGING, rng.uniform(0, HANGING)]); hanging = angle == HANGING
    mu = 0.0 if hanging else rng.random(); g = 9.80665
    r = atwood(m1, m2, Pulley(M), g, slope=Slope(angle, mu, mu)).results
    a = r["a"].value
    if a == 0: continue
    m1_, m2_, M_, g_ = map(mpmath.mpf, (m1, m2, M, g)); sa = 1 if hanging else mpmath.sin(mpmath.mpf(angle))
    N_ = 0 if hanging else m2_*g_*mpmath.cos(mpmath.mpf(angle)); s = 1 if a > 0 else -1
    pull = m1_*g_ - m2_*g_*sa - s*mu*N_
    kappa = 1 if hanging else float((m1_*g_ + m2_*g_*sa + mu*N_)/abs(pull))
    ea = pull/(m1_+m2_+M_/2)
    vals = [ulps(a, ea), ulps(r["T1"].value, m1_*(g_-ea))]
    if m2: vals.append(ulps(r["T2"].value, m2_*(ea+g_*sa)+s*mu*N_))
    worst = max(worst, max(vals)/max(kappa, 1))
print(f"atwood: {worst:.2f} ulp x max(kappa,1)")
worst = 0
for _ in range(N):
    shape = rng.choice(sorted(K2)); angle = rng.choice([rng.uniform(1e-300, 1.5707), 10.0**-rng.randint(1,300)]); ratio = rng.uniform(0, 0.999)
    k2 = K2[shape]; mu_min = math.tan(angle)*k2/(1+k2)
    r = solve_incline(Roller(k2, shape, 1.0, 0.1), angle, 9.80665).results
    s_ = solve_incline(Roller(k2, shape, 1.0, 0.1), angle, 9.80665, mu_s=mu_min*ratio, mu_k=mu_min*ratio).results
    th = mpmath.mpf(angle)
    vals = [ulps(r["a"].value, 9.80665*mpmath.sin(th)/(1+mpmath.mpf(k2))), ulps(r["mu_min"].value, mpmath.tan(th)*k2/(1+mpmath.mpf(k2)))]
    if not s_["rolls"].value: vals.append(ulps(s_["a"].value, 9.80665*(mpmath.sin(th) - mpmath.mpf(mu_min*ratio)*mpmath.cos(th))))
    worst = max(worst, max(vals))
print(f"rolling: {worst:.2f} ulp")
worst = 0
for _ in range(N):
    i = mass(); w = rng.uniform(-1e3, 1e3); tau = rng.uniform(-1e3, 1e3); dt = size(); i1 = mass()
    i_, w_, t_, d_ = map(mpmath.mpf, (i, w, tau, dt))
    ex = w_ + t_*d_/i_
    if ex: worst = max(worst, ulps(solve_balance(i, w, None, tau, dt).results["omega1"].value, ex) / max(float((abs(w_)+abs(t_*d_/i_))/abs(ex)), 1))
    c = solve_changing_inertia(i, i1, w).results
    worst = max(worst, ulps(c["omega1"].value, i_*w_/mpmath.mpf(i1)), ulps(c["KE1"].value, (i_*w_)**2/(2*mpmath.mpf(i1))))
print(f"impulse: {worst:.2f} ulp")
