"""A body on a pivot under gravity, a torsion spring, or both: the physical pendulum.

    I d²θ/dt² = −mgd sin θ − κθ        (θ from the downward vertical, d pivot to centre of mass)

Energy gives the speeds and the pivot's forces at any angle, exactly, for every method:
½Iω² + mgd(1 − cos θ) + ½κθ² is constant (swing.py, pivot.py). The motion in time is

- gravity alone (κ = 0): exact, with k = sin(θ_max/2): sin(θ/2) = k sn(ω₀t + u₀, k), ω = 2kω₀ cn,
  period 4K(k)/ω₀, ω₀ = √(mgd/I); over the top (k > 1) it circulates with modulus 1/k
  (taucli/elliptic.py, every function from k' = cos(θ_max/2) so that 179.999° keeps its digits)
  (exact.py);
- torsion alone (d = 0): exact, harmonic, period 2π√(I/κ) (harmonic.py);
- both: no closed form, but the energy integral t = ∫dθ/ω between the turning angles, by
  tanh-sinh quadrature (by_energy.py);
- euler, rk4, rk45, verlet on request: θ'' = α(θ) stepped, events located, each checked against
  the exact model (stepped.py);
- small-angle: the harmonic model sin θ ≈ θ at any amplitude, its period error stated
  (small_angle.py).

motion.py picks the model for --method and asks it; body.py reads the body, point.py the point at
--at, steps.py writes the worked steps.
"""

from __future__ import annotations

from collections.abc import Sequence

from taucli.options.pendulum import COMMAND as TABLE
from taucli.report import DeferredSteps, Report, deferred
from taucli.scenes.assumed import Assumed
from taucli.scenes.pendulum.body import on_pivot, read_body
from taucli.scenes.pendulum.exact import exact_model
from taucli.scenes.pendulum.harmonic import Harmonic
from taucli.scenes.pendulum.motion import choose, pick_model, put_motion, put_state, solve, trajectory
from taucli.scenes.pendulum.pivot import put_pivot
from taucli.scenes.pendulum.point import put_point
from taucli.scenes.pendulum.small_angle import small_angle_note
from taucli.scenes.pendulum.stepped import DEFAULT_DT, DEFAULT_RTOL, BlewUp, Stepped, withhold_if_off
from taucli.scenes.pendulum.steps import method_words, model_words, worked_steps
from taucli.scenes.pendulum.swing import Swing, put_energy
from taucli.table import Results

__all__ = ["BlewUp", "Harmonic", "Stepped", "Swing", "exact_model", "pendulum"]


def pendulum(
    *,
    inertia: float | None = None,
    shape: str | None = None,
    mass: float | None = None,
    axis: str | None = None,
    offset: float | None = None,
    part: Sequence = (),
    gyration: float | None = None,
    density=None,
    cm_distance: float | None = None,
    angle0: float | None = None,
    omega0: float | None = None,
    torsion: float | None = None,
    g: float | None = None,
    angle: float | None = None,
    time: float | None = None,
    at: float | None = None,
    method: str | None = None,
    dt: float | None = None,
    rtol: float | None = None,
    **dims: float | None,
) -> Report:
    """``taucli pendulum``: the body (--inertia with --mass and --cm-distance, or --shape ...), its
    start (--angle0 from the downward vertical, --omega0), gravity and --torsion, what to report."""
    assumed = Assumed()
    body = read_body(inertia, shape, mass, axis, offset, part, cm_distance, dims, torsion, assumed, gyration, density)
    swing, gravity = on_pivot(body, torsion, g, angle0, omega0, angle, assumed)
    method = choose(method or "auto", swing.gravity_torque > 0, swing.torsion > 0)
    dt, rtol = dt or DEFAULT_DT, rtol or DEFAULT_RTOL
    results = Results(TABLE)
    notes: list[str] = []

    exact = exact_model(swing)
    put_energy(results, notes, swing, body.cm_distance, angle, exact)  # energy and the exact motion: the same for every method
    model = pick_model(swing, method, exact, dt, rtol)
    motion = solve(model, exact, method, angle, time, notes)

    put_motion(results, notes, swing, exact, method, motion, angle)
    put_pivot(results, swing, body.mass, body.cm_distance, gravity)
    put_state(results, notes, motion.state, angle, time)
    if method == "small-angle" and swing.gravity_torque:
        notes.append(small_angle_note(swing, exact))
    if isinstance(model, Stepped):
        withhold_if_off(results, notes, model, exact, motion.period, motion.t_bottom, motion.state, time, angle)

    steps = DeferredSteps(worked_steps, swing, body.mass, body.cm_distance, gravity, body.steps, dict(results), exact, method, angle)
    report = Report(
        "pendulum", model_words(swing, method, exact, body.words), method_words(swing, method, dt, rtol), results, steps, notes,
        trajectory=deferred(trajectory, model, time, motion.period, motion.t_bottom),
    )
    if at is not None:
        put_point(report, swing, at, angle, gravity)
    return assumed.applied(report)
