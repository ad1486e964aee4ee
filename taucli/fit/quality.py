"""How well the fitted inputs are known, and how well the model fits: the covariance and the
diagnostics.

- The Jacobian J = ∂f(xᵢ; p)/∂pⱼ at the solution, by central differences with Richardson
  extrapolation (one-sided where pⱼ is near its bound), each sample's row weighted by 1/σᵢ where
  uncertainties are given.
- Its singular values, the columns scaled to unit length: where the smallest is below
  ``DEGENERATE`` of the largest, the columns are dependent (the samples change the same way when
  some inputs move together) and those inputs cannot be told apart: refused, naming them. Below
  ``NEARLY`` a note says they are barely told apart.
- The covariance C = (JᵀWJ)⁻¹ with W = diag(1/σᵢ²) where the samples' uncertainties are given; else
  s²(JᵀJ)⁻¹, s² = Σrᵢ²/(n − m) the residual variance standing in for them. The correlation
  ρⱼₖ = Cⱼₖ/√(CⱼⱼCₖₖ).
- The residual RMS √(Σrᵢ²/n), R² = 1 − Σrᵢ²/Σ(yᵢ − ȳ)² (below 0: the model does worse than the
  samples' mean), and with uncertainties χ²/ν (ν = n − m) and the chance of a χ² this far from ν
  either way for a model that fits (too large: the residuals exceed the σ given; too small: the σ
  given exceed the scatter).
- Two tests of the residuals in the order of the samples' input, for a shape the model does not
  have, both two-sided: the runs test (Wald–Wolfowitz) of their signs, which change at random for
  a model that fits (too few runs: a curve the model lacks; too many: residuals that alternate, as
  two runs interleaved and fitted as one do), its chance from the exact distribution of the runs
  given the counts of each sign; and their lag-1 autocorrelation r₁, near −1/n for a model that
  fits (r₁ ~ N(−1/n, 1/n): z = (r₁ + 1/n)√n). Each flags at a chance below ``SHAPE_P`` both ways
  (0.1 %): a model that fits is seldom flagged, and one flagged is said to be wrong. A test that
  cannot reach that chance with these samples (the runs test with fewer than about 15, the
  autocorrelation with fewer than 10) is too weak to run: it is left out, and the fit says so.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from taucli.core.errors import InputError
from taucli.fit.model import Model

DEGENERATE = 1e-7  # smallest singular value / largest (columns scaled): below, the inputs cannot be told apart
NEARLY = 1e-3  # below: barely told apart (a note)
FLAT = 1e-9  # an input whose relative change moves f by less than this of f: the samples do not depend on it
INVOLVED = 1e-4  # of the weakest direction's largest component: an input it moves (one it leaves is rounding there)
SHAPE_P = 1e-3  # a test of the residuals' shape flags at a chance below this, both ways together
SHAPE_Z = 3.2905  # the normal's two-sided 0.1 % point: the lag-1 autocorrelation's |z| above which the residuals are structured
CHI2_P = 1e-3  # a χ² this unlikely for a model that fits, either way (each tail at half of it): a warning
RUNS_LEAST = 10  # fewer samples than this: neither shape test can reach SHAPE_P
STEP = 1e-3  # relative step of the differences for the Jacobian
FLOOR = 1e-3  # of an input's natural scale: the least size its step is taken at (an input at 0 has no size of its own)


def jacobian(model: Model, p: np.ndarray, moved=None, *, rough: bool = False, scale: np.ndarray | None = None) -> np.ndarray:
    """∂f(xᵢ; p)/∂pⱼ: n × m, by differences (central with Richardson; one-sided near a bound);
    ``rough``: forward differences, one solve per input (enough to see dependent columns). The step
    is STEP of |pⱼ|, and at least FLOOR of the input's natural scale (``scale``: the size its start
    had): an input at 0 (on its bound) is still moved by a step its samples feel."""
    columns = []
    base = model.predict(p, moved)
    for j in range(len(p)):
        h = max(STEP * abs(p[j]), STEP * FLOOR * (scale[j] if scale is not None else 0.0), 1e-300)

        def f(x: float) -> np.ndarray:
            q = np.array(p, dtype=float)
            q[j] = x
            return model.predict(q, moved)

        if rough:
            columns.append((f(p[j] + h) - base) / h)
            continue
        if model.allowed(j, p[j] - 2 * h):
            coarse = (f(p[j] + 2 * h) - f(p[j] - 2 * h)) / (4 * h)
            fine = (f(p[j] + h) - f(p[j] - h)) / (2 * h)
        else:
            coarse = (-3 * base + 4 * f(p[j] + 2 * h) - f(p[j] + 4 * h)) / (4 * h)
            fine = (-3 * base + 4 * f(p[j] + h) - f(p[j] + 2 * h)) / (2 * h)
        columns.append((4 * fine - coarse) / 3)
    return np.column_stack(columns) if columns else np.zeros((len(base), 0))


@dataclass
class Degeneracy:
    ratio: float  # smallest singular value / largest, columns scaled
    involved: list[str]  # the inputs of the weakest direction
    flat: list[str]  # inputs the samples do not depend on at all


def singular(A: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(the singular values of A, largest first; Vᵀ), from the triangle R of A = QR: A's n × m
    (n samples, m inputs) reduced to m × m first, the same singular values and vectors to rounding,
    without the n × m matrix U (a million samples: a third of the time and none of its 24 MB)."""
    if A.shape[0] > A.shape[1]:
        A = np.linalg.qr(A, mode="r")
    return np.linalg.svd(A)[1:]


def degeneracy(J: np.ndarray, names: list[str], p: np.ndarray, f: np.ndarray, scale: np.ndarray | None = None) -> Degeneracy:
    """How near the columns of J are to dependent (scaled to unit length: the ratio does not depend
    on the inputs' units), and which inputs the weakest direction moves (where the columns are
    dependent, an input outside the dependence has a component of rounding size there). An input
    that moves f (weighted as J is) by less than FLAT of f when it changes by its natural size
    (the larger of |pⱼ| and ``scale``, the size its start had: an input at or near 0 is not flat
    for being there) is one the samples do not depend on: its column is rounding."""
    norms = np.linalg.norm(J, axis=0)
    size = float(np.linalg.norm(f)) if np.all(np.isfinite(f)) else 0.0
    sizes = np.maximum(np.abs(p), scale if scale is not None else 0.0)
    flat = [name for name, norm, x in zip(names, norms, sizes) if not norm > 0 or (x != 0 and norm * x <= FLAT * size)]
    if flat or J.shape[1] == 0:
        return Degeneracy(0.0, flat, flat)
    s, vt = singular(J / norms)
    weakest = np.abs(vt[-1])
    involved = [name for name, v in zip(names, weakest) if v > INVOLVED * np.max(weakest)]
    if len(involved) < 2:  # a dependence takes two: the two that move most
        involved = [names[j] for j in sorted(np.argsort(weakest)[-2:])]
    return Degeneracy(float(s[-1] / s[0]), involved, [])


def refuse_degenerate(found: Degeneracy, what: str, said: str = "") -> None:
    """A usage error naming the inputs the samples cannot tell apart (``said``: what the scene gives there)."""
    if found.flat:
        names = _listed(found.flat)
        raise InputError("fit", f"the samples do not depend on {names}, so they cannot determine {'it' if len(found.flat) == 1 else 'them'}{said}",
                         hint=f"is an input missing? Else leave {names} out of --fit")
    names = _listed(found.involved)
    raise InputError("fit", f"the samples cannot tell {names} apart: they change the same way when these move together "
                     f"(the Jacobian's columns are dependent: smallest singular value {_ratio_text(found.ratio)})",
                     hint=f"give one of {names} (or samples where they act differently), and fit the others")


ROUNDING = 1e-10  # a singular value ratio below this is the Jacobian's rounding: its digits are noise


def _ratio_text(ratio: float) -> str:
    """The smallest singular value over the largest as a person reads it: its size where it is a
    measurement's, "below 1e-10 of the largest, rounding" where its digits are the arithmetic's noise."""
    return f"below {ROUNDING:g} of the largest, rounding" if ratio < ROUNDING else f"{ratio:.1e} of the largest"


def _listed(names: list[str]) -> str:
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


@dataclass
class Runs:
    """The runs test of the residuals' signs: the runs counted, their mean and σ for signs in a
    random order, z, the two-sided chance p of a count this far from the mean, and the least p
    any order of these signs could give (above SHAPE_P: the test is too weak to run)."""

    runs: int
    expected: float
    spread: float
    z: float
    p: float
    least: float
    plus: int
    minus: int


@dataclass
class Quality:
    n: int
    m: int
    residuals: np.ndarray  # measured − fitted, SI
    covariance: np.ndarray  # of the fitted inputs, from the samples' scatter alone
    scaled: bool  # the covariance is scaled by the residual variance (no uncertainties given)
    s2: float  # Σr²/ν (unweighted), or χ²/ν (weighted)
    rms: float
    r2: float | None
    chi2: float | None
    chi2_dof: float | None
    chi2_p: float | None
    runs: Runs | None  # the runs test of the residuals' signs (None: fewer than RUNS_LEAST samples)
    lag: tuple[float, float] | None  # (r₁, z)
    degeneracy: Degeneracy
    chi2_low: float | None = None  # the chance of a χ² this small or smaller
    rescaled: bool = False  # uncertainties given, and the covariance scaled by χ²/ν all the same (--scale-covariance)

    @property
    def runs_weak(self) -> bool:
        """The runs test cannot reach SHAPE_P with these samples: left out."""
        return self.runs is None or self.runs.least > SHAPE_P

    @property
    def lag_weak(self) -> bool:
        """The autocorrelation cannot reach SHAPE_Z with these samples: left out."""
        return self.lag is None or lag_reach(self.n) <= SHAPE_Z

    @property
    def shape_tested(self) -> bool:
        return not (self.runs_weak and self.lag_weak)

    @property
    def runs_flag(self) -> bool:
        return not self.runs_weak and self.runs.p < SHAPE_P

    @property
    def lag_flag(self) -> bool:
        return not self.lag_weak and abs(self.lag[1]) > SHAPE_Z

    @property
    def structured(self) -> bool:
        """The residuals have a shape: the runs test or the autocorrelation says so (either way)."""
        return self.runs_flag or self.lag_flag

    @property
    def alternating(self) -> bool:
        """Flagged for too many runs or a negative autocorrelation: residuals that alternate."""
        return (self.runs_flag and self.runs.z > 0) or (self.lag_flag and self.lag[1] < 0)

    @property
    def chi2_flag(self) -> str | None:
        """"high" or "low" where χ² is that unlikely for a model that fits with the σ given."""
        if self.chi2_p is not None and self.chi2_p < CHI2_P / 2:
            return "high"
        if self.chi2_low is not None and self.chi2_low < CHI2_P / 2:
            return "low"
        return None

    @property
    def dof(self) -> int:
        return self.n - self.m

    @property
    def sigma(self) -> np.ndarray:
        return np.sqrt(np.diag(self.covariance))

    @property
    def correlation(self) -> np.ndarray:
        s = self.sigma
        with np.errstate(divide="ignore", invalid="ignore"):
            rho = self.covariance / np.outer(s, s)
        return np.where(np.isfinite(rho), rho, 0.0)


def assess(y: np.ndarray, fitted: np.ndarray, J: np.ndarray, sigma: np.ndarray | None, order: np.ndarray, names: list[str], p: np.ndarray,
           scale: np.ndarray | None = None, *, rescale: bool = False) -> Quality:
    """The covariance and the diagnostics of a fit (J unweighted; ``sigma`` each sample's σ or None;
    ``scale`` each input's natural size, for the test of inputs the samples do not depend on;
    ``rescale``: with σ given, the covariance scaled by χ²/ν all the same, (χ²/ν)(JᵀWJ)⁻¹, as
    lmfit does by default: the σ given then weigh the samples, their scatter sets the size)."""
    n, m = J.shape
    r = y - fitted
    weights = 1.0 / sigma if sigma is not None else np.ones(n)
    Jw = J * weights[:, None]
    found = degeneracy(Jw, names, p, fitted * weights, scale)
    if found.flat or found.ratio < DEGENERATE:
        refuse_degenerate(found, "the result")
    norms = np.linalg.norm(Jw, axis=0)
    s, vt = singular(Jw / norms)
    inverse = (vt.T / s**2) @ vt / np.outer(norms, norms)  # (JᵀWJ)⁻¹, columns unscaled again
    rss = float(np.sum(r**2))
    chi2 = float(np.sum((r * weights) ** 2)) if sigma is not None else None
    dof = n - m
    s2 = (chi2 if chi2 is not None else rss) / dof
    rescaled = rescale and sigma is not None
    covariance = inverse if sigma is not None and not rescaled else inverse * s2
    tss = float(np.sum((y - np.mean(y)) ** 2))
    chi2_p = chi2_low = None
    if chi2 is not None:
        from scipy.special import chdtr, chdtrc  # deferred: χ²'s tails as scipy.stats.chi2 works them (its sf, cdf), without importing scipy.stats (a second or more)

        chi2_p, chi2_low = float(chdtrc(dof, chi2)), float(chdtr(dof, chi2))
    ordered = r[np.argsort(order, kind="stable")]
    return Quality(n, m, r, covariance, sigma is None, s2, math.sqrt(rss / n), 1.0 - rss / tss if tss > 0 else None, chi2,
                   chi2 / dof if chi2 is not None else None, chi2_p, runs_test(ordered), lag_test(ordered), found, chi2_low, rescaled)


INTERVAL = 0.95  # the two-sided interval given beside ±1σ where σ comes from the residuals' scatter


def student_t(dof: float, level: float = INTERVAL) -> float:
    """Student's t quantile: the half-width of a ``level`` interval in units of σ for ν = ``dof``
    (12.71 for ν = 1, 2.776 for 4, 2.228 for 10, 1.96 as ν → ∞)."""
    from scipy.stats import t as student  # deferred: scipy.stats, only where σ is from the scatter

    return float(student.ppf(0.5 + level / 2, dof))


def effective_dof(dof: int, scatter: float, total: float) -> float:
    """Welch–Satterthwaite: the degrees of freedom of a variance ``total`` whose part ``scatter``
    has ν = ``dof`` and the rest (held inputs' uncertainties, known) infinitely many:
    ν_eff = ν (total/scatter)²."""
    return math.inf if not scatter > 0 else dof * (total / scatter) ** 2


def lag_test(residuals: np.ndarray) -> tuple[float, float] | None:
    """(r₁, z) of the residuals in order, or None for fewer than RUNS_LEAST samples (or all 0)."""
    n = len(residuals)
    total = float(np.sum(residuals**2))
    if n < RUNS_LEAST or not total > 0:
        return None
    r1 = float(np.sum(residuals[1:] * residuals[:-1])) / total
    return r1, (r1 + 1 / n) * math.sqrt(n)


def lag_reach(n: int) -> float:
    """The largest |z| the lag-1 autocorrelation of n residuals can reach: |r₁| ≤ cos(π/(n + 1))."""
    return (math.cos(math.pi / (n + 1)) + 1 / n) * math.sqrt(n) if n > 1 else 0.0


def runs_test(residuals: np.ndarray) -> Runs | None:
    """The runs test of the signs of ``residuals`` in order (zeros left out), or None for fewer
    than RUNS_LEAST samples. Its chance is exact: for n₊ and n₋ signs in a random order,
    P(R = 2k) = 2C(n₊−1, k−1)C(n₋−1, k−1)/C(n, n₊) and P(R = 2k+1) = (C(n₊−1, k−1)C(n₋−1, k) +
    C(n₊−1, k)C(n₋−1, k−1))/C(n, n₊); p = 2 min(P(R ≤ r), P(R ≥ r)). Every residual of one sign has
    the chance 2^(1−n) of n fair coins landing alike."""
    signs = np.sign(residuals[residuals != 0])
    total = len(signs)
    if total < RUNS_LEAST:
        return None
    plus, minus = int(np.sum(signs > 0)), int(np.sum(signs < 0))
    if not plus or not minus:  # every residual of one sign: as structured as they come
        chance = 2.0 ** (1 - total)
        return Runs(1, 1.0, 0.0, -math.inf, chance, chance, plus, minus)
    runs = 1 + int(np.sum(signs[1:] != signs[:-1]))
    expected = 2 * plus * minus / total + 1
    spread = math.sqrt((expected - 1) * (expected - 2) / (total - 1))
    counts, chances = _runs_distribution(plus, minus)
    below, above = float(np.sum(chances[counts <= runs])), float(np.sum(chances[counts >= runs]))
    least = min(1.0, 2 * min(chances[0], chances[-1]))
    return Runs(runs, expected, spread, (runs - expected) / spread if spread > 0 else 0.0, min(1.0, 2 * min(below, above)), least, plus, minus)


def _runs_distribution(plus: int, minus: int) -> tuple[np.ndarray, np.ndarray]:
    """(each possible count of runs, its chance) for ``plus`` and ``minus`` signs in a random order
    (logarithms of the binomial coefficients, on arrays: exact to rounding for millions of samples)."""
    from scipy.special import gammaln  # deferred: scipy.special, only for the runs of a fit's residuals

    def log_choose(a: int, b: np.ndarray) -> np.ndarray:
        inside = (b >= 0) & (b <= a)
        b = np.where(inside, b, 0)
        return np.where(inside, gammaln(a + 1.0) - gammaln(b + 1.0) - gammaln(a - b + 1.0), -math.inf)

    whole = float(log_choose(plus + minus, np.array([plus]))[0])
    k = np.arange(1, min(plus, minus) + 2)
    even = math.log(2) + log_choose(plus - 1, k - 1) + log_choose(minus - 1, k - 1) - whole
    odd = np.logaddexp(log_choose(plus - 1, k - 1) + log_choose(minus - 1, k), log_choose(plus - 1, k) + log_choose(minus - 1, k - 1)) - whole
    counts, logs = np.column_stack([2 * k, 2 * k + 1]).ravel(), np.column_stack([even, odd]).ravel()
    kept = logs > -math.inf
    return counts[kept], np.exp(logs[kept])
