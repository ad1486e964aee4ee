"""A model that is linear in the fitted inputs is solved as such: no start, no iteration.

f(xᵢ; p) = f(xᵢ; p₀) + Σⱼ Xᵢⱼ (pⱼ − p₀ⱼ) holds for every p exactly when f is affine in p. That is
checked on the scene itself, not assumed: f at p₀, at p₀ + Δⱼ and p₀ + 2Δⱼ along each input, and at
p₀ + ΣⱼΔⱼ; the second differences along each input and the cross term are rounding (below
``TOLERANCE`` of f) only for an affine f. Then Xᵢⱼ = (f(p₀ + Δⱼ) − f(p₀))/Δⱼ is exact, and the
weighted least squares min Σ wᵢ²(yᵢ − f(xᵢ; p))² is the linear problem (WX)δ = W(y − f(p₀)), solved
by the singular value decomposition (numpy.linalg.lstsq), p = p₀ + δ. The forward solve at p must
give f(p₀) + Xδ again (a model linear only in a region, as a coast-down is until it stops, falls
back to the nonlinear fit).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from taucli.fit.model import Model

TOLERANCE = 1e-9  # of the largest |f| seen: second differences below this are rounding
STEP = 0.05  # Δⱼ, of |p₀ⱼ|: small enough to stay where the model's form holds (before a stop), large enough to show a curve

# How a scene's result reads as a linear function of its inputs, where it is one (the others held).
FORMS = {
    ("spin-down", "omega"): "ω(t) = ω₀ + ((τ − τ_f)/I)·t (τ the drive, τ_f the friction torque)",
    ("spin-down", "theta"): "θ(t) = ω₀t + ½((τ − τ_f)/I)·t²",
    ("spin-down", "revs"): "n(t) = (ω₀t + ½((τ − τ_f)/I)·t²)/2π",
    ("spin-down", "alpha0"): "α₀ = (τ − τ_f − bω₀ − kω₀²)/I",
    ("atwood", "a"): "a = ((m₁ − m₂)g − τ_f/R)/M, M = m₁ + m₂ + I/R²",
    ("atwood", "T1"): "T₁ = m₁(g − a)",
    ("atwood", "distance"): "d(t) = v₀t + ½at², a = ((m₁ − m₂)g − τ_f/R)/M",
    ("atwood", "v"): "v(t) = v₀ + at, a = ((m₁ − m₂)g − τ_f/R)/M",
    ("rolling", "a"): "a = g sin θ/(1 + k²)",
    ("impulse", "omega1"): "ω₁ = ω₀ + τΔt/I",
    ("impulse", "J"): "J = τΔt",
    ("torque", "tau_z"): "τ_z = r_x F_y − r_y F_x",
    ("inertia", "I"): "I = Σ mᵢ kᵢ² (each part's mass times its squared radius of gyration)",
}


@dataclass
class Linear:
    p0: np.ndarray
    f0: np.ndarray
    X: np.ndarray  # ∂f/∂p: exact for an affine f
    largest_curvature: float  # the largest second difference or cross term, of the largest |f|
    evaluations: int


def affine(model: Model, p0: np.ndarray, steps: np.ndarray) -> Linear | None:
    """f as f₀ + X(p − p₀), where the scene's f is affine in p (checked), else None."""
    f0 = model.predict(p0)
    if not np.all(np.isfinite(f0)):
        return None
    columns, worst, seen, evaluations = [], 0.0, [f0], 1
    for j, step in enumerate(steps):
        one, two = np.array(p0, dtype=float), np.array(p0, dtype=float)
        one[j] += step
        two[j] += 2 * step
        f1, f2 = model.predict(one), model.predict(two)
        evaluations += 2
        if not (np.all(np.isfinite(f1)) and np.all(np.isfinite(f2))):
            return None
        seen += [f1, f2]
        worst = max(worst, float(np.max(np.abs(f2 - 2 * f1 + f0))))
        columns.append((f1 - f0) / step)
    if len(steps) > 1:
        together = model.predict(np.asarray(p0, dtype=float) + steps)
        evaluations += 1
        if not np.all(np.isfinite(together)):
            return None
        seen.append(together)
        worst = max(worst, float(np.max(np.abs(together - f0 - sum(column * step for column, step in zip(columns, steps))))))
    scale = max(float(np.max(np.abs(values))) for values in seen) or 1.0
    if worst > TOLERANCE * scale:
        return None
    return Linear(np.asarray(p0, dtype=float), f0, np.column_stack(columns), worst / scale, evaluations)


def solve(linear: Linear, y: np.ndarray, sigma: np.ndarray | None) -> np.ndarray:
    """p minimising Σ wᵢ²(yᵢ − f₀ᵢ − Xᵢ(p − p₀))², wᵢ = 1/σᵢ (or 1)."""
    weights = 1.0 / sigma if sigma is not None else np.ones(len(y))
    delta = np.linalg.lstsq(linear.X * weights[:, None], (y - linear.f0) * weights, rcond=None)[0]
    return linear.p0 + delta


def holds(model: Model, linear: Linear, p: np.ndarray) -> bool:
    """The forward solve at p gives f₀ + X(p − p₀) (to TOLERANCE): the model is linear out to p."""
    predicted = linear.f0 + linear.X @ (p - linear.p0)
    found = model.predict(p)
    scale = max(float(np.max(np.abs(found))) if np.all(np.isfinite(found)) else 0.0, float(np.max(np.abs(linear.f0))), 1e-300)
    return bool(np.all(np.isfinite(found)) and np.max(np.abs(found - predicted)) <= 1e3 * TOLERANCE * scale)


def form(scene: str, result: str) -> str:
    """The scene's result written as linear in its inputs, where the table above has it."""
    return FORMS.get((scene, result), f"{result} = {result}(p₀) + Σⱼ ∂{result}/∂pⱼ·(pⱼ − p₀ⱼ)")
