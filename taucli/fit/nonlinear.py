"""A model that is not linear in the fitted inputs: bounded nonlinear least squares.

min over p of Σᵢ wᵢ²(yᵢ − f(xᵢ; p))², wᵢ = 1/σᵢ (or 1), each pⱼ within the range its option
takes (a friction torque ≥ 0, a moment of inertia > 0): scipy.optimize.least_squares, trust region
reflective ("trf"), on p scaled by its start so that inputs of any size weigh alike. A sample the
scene gives no value for at a trial p counts as a large residual (as does one larger still), so the
search turns away from it. The fit is refused where the search stops without converging, and where an input ends on its
bound (the samples ask for a value the input cannot take).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from taucli.fit.model import Model

TOLERANCE = 1e-10  # scipy's ftol, xtol and gtol
MOST_EVALUATIONS = 300  # of f at every sample (the Jacobian's differences not counted)
AT_BOUND = 1e-6  # of an input's start: this near its bound, it ends on it
PENALTY = 1e6  # a sample without a value: this many times the largest weighted measurement


@dataclass
class Outcome:
    p: np.ndarray
    converged: bool
    message: str
    evaluations: int  # of f at every sample, the Jacobian's differences included
    iterations: int
    at_bound: list[int]  # the inputs that ended on their bounds


def minimize(model: Model, y: np.ndarray, sigma: np.ndarray | None, p0: np.ndarray) -> Outcome:
    from scipy.optimize import least_squares  # deferred: scipy.optimize (about 200 ms), only for a nonlinear fit

    weights = 1.0 / sigma if sigma is not None else np.ones(len(y))
    scale = np.where(np.abs(p0) > 0, np.abs(p0), 1.0)
    lower = np.array([model.lower(j) / scale[j] for j in range(len(p0))])
    upper = np.array([model.upper(j) / scale[j] for j in range(len(p0))])
    large = PENALTY * (float(np.max(np.abs(y * weights))) + 1.0)
    before = model.evaluations

    def residuals(u: np.ndarray) -> np.ndarray:
        r = (model.predict(u * scale) - y) * weights
        return np.where(np.isfinite(r) & (np.abs(r) < large), r, large)  # (no value, or past the penalty: the penalty, so that the search's differences stay finite)

    found = least_squares(residuals, p0 / scale, bounds=(lower, upper), method="trf", jac="2-point", diff_step=1e-7,
                          x_scale=1.0, ftol=TOLERANCE, xtol=TOLERANCE, gtol=TOLERANCE, max_nfev=MOST_EVALUATIONS)
    p = found.x * scale
    # on its bound, or within AT_BOUND of its start's size of it (the reflective search nears a bound without reaching it)
    # (a --bound the search ends on is said, not held: taucli.fit.solve)
    near = [AT_BOUND * scale[j] for j in range(len(p))]
    at_bound = [j for j in range(len(p)) if not model.on_user_bound(j, p[j], near[j])
                and (found.active_mask[j] != 0 or (model.sign(j) != "any" and p[j] <= lower[j] * scale[j] + near[j]))]
    evaluations = model.evaluations - before
    return Outcome(p, found.status > 0, str(found.message), evaluations, int(found.nfev), at_bound)


def stuck(model: Model, p: np.ndarray) -> int:
    """How many samples the scene gives no value for at p."""
    return int(np.sum(~np.isfinite(model.predict(p))))
