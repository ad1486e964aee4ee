"""A body on the flat: a ball skidding until it rolls (skid to roll), and a body already rolling
without slipping at v0, whose motion nothing changes.
"""

from __future__ import annotations

import math
from fractions import Fraction

from taucli.core.errors import InputError
from taucli.options.rolling import COMMAND as TABLE
from taucli.writing.report import Report, Step, Trajectory, deferred, fmt, quantity_text, term
from taucli.scenes.rolling.body import Roller, check_friction
from taucli.options.table import Results


def solve_flat(roller: Roller, g: float, *, mu_k: float | None, v0: float, omega0: float = 0.0, mu_s: float | None = None) -> Report:
    """A ball skidding on the flat: friction μk m g acts against the slip v − Rω until it vanishes.

    slip s(t) = s₀ − μk g (1 + 1/k2) t, so t_roll = |s₀| k2 / (μk g (1 + k2));
    v_roll = (v₀ + k2 R ω₀)/(1 + k2) (angular momentum about the contact point is conserved).
    """
    check_friction(mu_s, mu_k)  # μs plays no part in skidding, but a μk above it is still a mistake
    k2, mass, radius = roller.k2, roller.mass, roller.radius
    if omega0 and radius is None:
        raise InputError("radius", "is required with {omega0} (the slip is v − Rω)", example="{radius} 0.11m")
    rim_speed = 0.0 if not omega0 else radius * omega0
    slip = v0 - rim_speed
    if slip and omega0:  # v₀ − Rω₀ without the rounding of Rω₀, which is all of a slip much smaller than v₀ (#42 item 8)
        slip = float(Fraction(v0) - Fraction(radius) * Fraction(omega0))
    notes: list[str] = []
    if slip != 0 and mu_k is None:
        raise InputError("mu_k", "is required: the ball skids (v ≠ Rω) and kinetic friction brings it to rolling", example="{mu_k} 0.2")
    if slip != 0 and mu_k == 0:
        return _skids_forever(roller, v0, rim_speed)
    v_roll = (v0 + k2 * rim_speed) / (1 + k2)
    if slip == 0:
        t_roll = 0.0
        d_roll = 0.0
        notes.append("it already rolls (v = Rω): nothing changes on the flat")
    else:
        t_roll = abs(slip) * k2 / (mu_k * g * (1 + k2))
        d_roll = (v0 + v_roll) / 2 * t_roll  # uniform deceleration: the mean speed times the time
    # KE before − KE after = ½m(v₀² + k²u²) − ½m(1 + k²)v_roll², u = Rω₀, v_roll = (v₀ + k²u)/(1 + k²),
    # = ½m[(1 + k²)(v₀² + k²u²) − (v₀ + k²u)²]/(1 + k²) = ½m k²(v₀ − u)²/(1 + k²): the difference
    # cancels as the ball nearly rolls (it came out negative); this form is ≥ 0 and keeps its digits.
    energy_lost = None if mass is None else 0.5 * mass * k2 / (1 + k2) * slip * slip
    results = _skid_results(t_roll, d_roll, v_roll, None if radius is None else v_roll / radius, energy_lost)
    steps = [
        Step("While it skids, kinetic friction acts against the slip", "m dv/dt = −μₖ m g·sgn s,  I dω/dt = +μₖ m g R·sgn s,  s = v − Rω", "", "",
             "friction slows the centre and spins the ball up (or the reverse, for backspin)"),
        Step("The slip closes at a constant rate", "ds/dt = −μₖ g (1 + 1/k²)·sgn s  ⇒  t_roll = |s₀| k² / (μₖ g (1 + k²))",
             "" if slip == 0 else f"{term(abs(slip), 'm/s')} × {fmt(k2)} / ({fmt(mu_k)} × {term(g, 'm/s**2')} × (1 + {fmt(k2)}))", quantity_text(t_roll, "s"),
             "once s = 0 the contact is at rest and friction stops acting: it rolls"),
        Step("Speed once it rolls", "v_roll = (v₀ + k² R ω₀) / (1 + k²)", f"({term(v0, 'm/s')} + {fmt(k2)} × {term(rim_speed, 'm/s')}) / (1 + {fmt(k2)})",
             quantity_text(v_roll, "m/s"), "friction acts at the contact, so angular momentum about the contact point is conserved"),
    ]
    model = f"{roller.description} (k² = {fmt(k2)}) skidding on the flat until it rolls"
    return Report("rolling", model, "closed form", results, steps, notes, trajectory=deferred(_skid_trajectory, v0, v_roll, t_roll))


def _skid_results(t_roll, d_roll, v_roll, omega_roll, energy_lost: float | None) -> Results:
    """The skidding ball's results (energy_lost only when the mass is known)."""
    results = Results(TABLE)
    for name, value in (("t_roll", t_roll), ("d_roll", d_roll), ("v_roll", v_roll), ("omega_roll", omega_roll)):
        results.put(name, value)
    if energy_lost is not None:
        results.put("energy_lost", energy_lost)
    return results


def _skids_forever(roller: Roller, v0: float, rim_speed: float) -> Report:
    """μk = 0 with v ≠ Rω: no force at the contact, so v and ω never change and it never rolls."""
    results = _skid_results(None, None, None, None, None if roller.mass is None else 0.0)
    notes = [f"μk = 0: no friction at the contact, so it skids for ever at v = {quantity_text(v0, 'm/s')} with the slip it started with, and never rolls"]
    steps = [
        Step("With no friction nothing acts at the contact", "m dv/dt = 0,  I dω/dt = 0", "", "",
             f"the slip s = v − Rω = {fmt(v0 - rim_speed)} m/s stays as it is"),
    ]
    model = f"{roller.description} (k² = {fmt(roller.k2)}) skidding on a frictionless flat"
    return Report("rolling", model, "closed form", results, steps, notes, trajectory=deferred(_skid_trajectory, v0, v0, math.inf))


def _skid_trajectory(v0: float, v_roll: float, t_roll: float) -> Trajectory:
    """Distance and speed of the centre: uniform change while it skids, then steady rolling."""
    change = 0.0 if t_roll == 0 else (v_roll - v0) / t_roll  # ±μk g while it skids

    def state(t: float) -> tuple[float, float]:
        if t <= t_roll:
            return v0 * t + change * t * t / 2, v0 + change * t
        return (v0 + v_roll) / 2 * t_roll + v_roll * (t - t_roll), v_roll

    curves = (("x", "m", "distance travelled"), ("v", "m/s", "speed of the centre"))
    if math.isinf(t_roll):
        return Trajectory(curves, 1.0, lambda t: (v0 * t, v0), note="plotted for 1 s: it never rolls")
    if t_roll == 0:
        return Trajectory(curves, 1.0, state, note="plotted for 1 s: it rolls from the start")
    return Trajectory(curves, 1.5 * t_roll, state, marks=((t_roll, "rolls without slipping"),))


def solve_rolling_flat(roller: Roller, v0: float) -> Report:
    """A body rolling without slipping on the flat at v0: nothing changes (a = 0, α = 0, no friction
    needed), ω = v/R, KE = ½ m v² (1 + k²) where the mass is given."""
    k2, mass, radius = roller.k2, roller.mass, roller.radius
    results = Results(TABLE)
    results.put("a", 0.0)
    results.put("alpha", 0.0)
    results.put("omega", None if radius is None else v0 / radius, ", rolling")
    ke_trans = None if mass is None else 0.5 * mass * v0 * v0
    results.put("KE_trans", ke_trans, ", rolling")
    results.put("KE_rot", None if mass is None else k2 * ke_trans, ", rolling")
    results.put("KE", None if mass is None else (1 + k2) * ke_trans, ", rolling")
    notes = ["on the flat, {v0} alone: rolling without slipping (ω = v/R); with {mu_k} it skids from no spin ({omega0} for a spin)"]
    if radius is None:
        notes.append("omega: give --radius (the energies do not need it)")
    if mass is None:
        notes.append("KE_trans, KE_rot, KE: give --mass (the motion does not need it)")
    steps = [
        Step("Rolling steadily", "a = 0,  α = a/R = 0", "", "a = 0 m/s², α = 0 rad/s²", "on the flat nothing pushes the body along: it rolls at a steady speed, and friction has nothing to do"),
        Step("Rolling without slipping", "ω = v / R", "", "" if radius is None else quantity_text(v0 / radius, "rad/s"), "the contact point is at rest"),
    ]
    if mass is not None:
        steps.append(Step("Kinetic energy", "KE = ½ m v² + ½ I ω² = ½ m v² (1 + k²)", f"½ × {term(mass, 'kg')} × ({term(v0, 'm/s')})² × (1 + {fmt(k2)})",
                          quantity_text((1 + k2) * ke_trans, "J"), f"I ω² = k² m R² (v/R)² = k² m v²: a share k²/(1 + k²) = {fmt(100 * k2 / (1 + k2), 3)}% is rotation"))
    model = f"{roller.description} (k² = {fmt(k2)}) rolling without slipping on the flat"
    return Report("rolling", model, "closed form", results, steps, notes)

