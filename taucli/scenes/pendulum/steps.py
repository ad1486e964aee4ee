"""The report's words: the model, the method, and the worked steps, written when first read.

The steps follow a worked solution: the restoring torque and α₀ = |τ₀|/I at the start; the speed
at the bottom (and at --angle) from energy, ½Iω² = ½Iω₀² + U(θ₀) − U(θ); the period of small
swings; the period by the method used (elliptic, harmonic, stepped or small-angle); the pivot's
force; the equivalent simple pendulum; whether it goes over the top.
"""

from __future__ import annotations

import math

from taucli.writing.report import Step, fmt, quantity_text
from taucli.scenes.pendulum.by_energy import ByEnergy
from taucli.scenes.pendulum.exact import Circulation, Libration, Separatrix
from taucli.scenes.pendulum.harmonic import Harmonic
from taucli.scenes.pendulum.stepped import STEPPERS
from taucli.scenes.pendulum.pivot import pivot_force
from taucli.scenes.pendulum.swing import Swing, sine


def model_words(swing: Swing, method: str, exact, body_words: str) -> str:
    """What swings under what, and how it moves (swings, goes over the top, just reaches it); or the small-angle model."""
    if swing.gravity_torque and swing.torsion:
        drive = "gravity and a torsion spring"
    elif swing.gravity_torque:
        drive = "gravity"
    else:
        drive = "a torsion spring"
    kind = {Circulation: "goes over the top", Separatrix: "just reaches the top", Libration: "swings", Harmonic: "swings", ByEnergy: "swings"}.get(type(exact), "swings or goes over")
    if method == "small-angle":
        return f"{body_words} on a pivot under {drive}: small-angle model (harmonic, sin θ ≈ θ)"
    return f"{body_words} on a pivot under {drive}; it {kind}"


def method_words(swing: Swing, method: str, dt: float, rtol: float) -> str:
    """The method as the report names it: the closed form, or the stepper with its dt (rk45: its rtol)."""
    exact = ("the energy integral t = ∫dθ/ω (tanh-sinh quadrature)" if swing.gravity_torque and swing.torsion
             else "closed form (elliptic integrals)" if swing.gravity_torque else "closed form (harmonic)")
    return {"exact": exact, "small-angle": "closed form (harmonic, small-angle)"}.get(
        method, f"{method} (dt = {fmt(dt)} s)" if method != "rk45" else f"rk45 (rtol = {fmt(rtol)})"
    )


def worked_steps(swing: Swing, mass, cm_distance, gravity, body_steps, results, exact, method, angle, zero) -> list[Step]:
    """The body's steps, then: τ₀ = −(mgd sin θ₀ + κθ₀) and α₀ = |τ₀|/I; ω at the bottom (and at
    --angle) from energy; T₀ = 2π√(I/(mgd + κ)); the period by the method used; the pivot's force
    at the start and at the bottom; L = I/(md); ω₀,over. Each shows the result as the solver put
    it in ``results`` (a withheld one as such)."""
    value = lambda key: results[key].value if key in results else None  # noqa: E731
    inertia, big_g, kappa, theta0, omega0 = swing.inertia, swing.gravity_torque, swing.torsion, swing.theta0, swing.omega0
    steps = list(body_steps)
    deg0 = f"{fmt(math.degrees(theta0))}°"
    if zero.top:
        steps.append(
            Step(
                "Angles from the top, worked from the bottom",
                "θ = φ − 180° (φ > 0), φ + 180° (φ ≤ 0)",
                f"φ₀ = {fmt(math.degrees(zero.outward(theta0)))}°",
                f"θ₀ = {deg0}",
                "the steps measure θ from the downward vertical, where the potential energy is least; "
                "the results give every angle from the top again, in the same sense (ω is the same in both)",
            )
        )
    terms, numbers = [], []
    if big_g:
        terms.append("mgd sin θ₀")
        numbers.append(f"{fmt(mass)} kg × {fmt(gravity)} m/s² × {fmt(cm_distance)} m × sin {deg0}")
    if kappa:
        terms.append("κθ₀")
        numbers.append(f"{fmt(kappa)} N·m/rad × {fmt(theta0)} rad")
    steps.append(
        Step(
            "Restoring torque at the start",
            "τ₀ = −(" + " + ".join(terms) + ")",
            "−(" + " + ".join(numbers) + ")",
            quantity_text(-(big_g * sine(theta0) + kappa * theta0), "N*m"),
            "; ".join(
                ["gravity acts at the centre of mass, a distance d from the pivot; its lever arm is d sin θ"] * bool(big_g)
                + ["the spring twists back in proportion to the angle"] * bool(kappa)
            ),
        )
    )
    steps.append(
        Step(
            "Angular acceleration at the start (τ = Iα about the pivot)",
            "α₀ = |τ₀| / I",
            f"{quantity_text(abs(big_g * sine(theta0) + kappa * theta0), 'N*m')} / {quantity_text(inertia, 'kg*m**2')}",
            quantity_text(value("alpha0"), "rad/s**2"),
            "I is about the pivot, not the centre of mass: the body turns about the pivot"
            + (f"; a point at r moves with a_t = rα₀, faster than g sin θ₀ beyond r = I/(md) = {fmt(inertia / (mass * cm_distance))} m"
               if big_g and theta0 else ""),
        )
    )
    potential = ("mgd(1 − cos θ₀)" if big_g else "") + (" + " if big_g and kappa else "") + ("½κθ₀²" if kappa else "")
    steps.append(
        Step(
            "Speed at the bottom (energy is conserved)",
            f"½Iω_b² = ½Iω₀² + {potential}",
            f"√(({fmt(omega0)} rad/s)² + 2 × {quantity_text(swing.potential(theta0), 'J')} / {quantity_text(inertia, 'kg*m**2')})",
            quantity_text(value("omega_bottom"), "rad/s"),
            "the pivot does no work (it does not move), so the potential energy lost becomes kinetic energy ½Iω²",
        )
    )
    if angle is not None and "omega" in results:
        speed = value("omega")
        steps.append(
            Step(
                f"Speed at θ = {fmt(math.degrees(angle))}° (energy)",
                "½Iω² = ½Iω₀² + U(θ₀) − U(θ)",
                f"√(({fmt(omega0)} rad/s)² + 2 × {quantity_text(swing.drop(angle), 'J')} / {quantity_text(inertia, 'kg*m**2')})",
                "never reached" if speed is None else quantity_text(speed, "rad/s"),
                "U(θ) = mgd(1 − cos θ) + ½κθ², the potential energy of gravity and the spring",
            )
        )
    steps += reach_steps(swing, cm_distance, results, zero)
    steps.append(
        Step(
            "Period of small swings",
            "T₀ = 2π√(I / (mgd + κ))",
            f"2π√({quantity_text(inertia, 'kg*m**2')} / {quantity_text(big_g + kappa, 'N*m')})",
            quantity_text(value("period_small"), "s"),
            "for small angles sin θ ≈ θ, so I θ'' = −(mgd + κ)θ: simple harmonic motion",
        )
    )
    if isinstance(exact, Libration) and method == "exact":
        k = exact.k
        steps.append(
            Step(
                "Exact period at this amplitude (complete elliptic integral)",
                "T = 4K(k)/ω₀ₙ, k = sin(θ_max/2), ω₀ₙ = √(mgd/I)",
                f"4 × {fmt(exact.quarter, 10)} / {quantity_text(exact.rate, 'rad/s')}",
                quantity_text(value("period"), "s") if value("period") is not None else "none",
                f"θ_max = {fmt(math.degrees(exact.amplitude), 6)}°, k = {fmt(k, 8)}, and K(k) = π/(2·AGM(1, cos(θ_max/2))); energy gives dθ/dt at each θ; the time for a quarter swing is ∫dθ/ω, which sin(θ/2) = k sin φ turns into K(k); "
                f"the exact period is {fmt(100 * (exact.period / value('period_small') - 1), 4)}% longer than the small-angle one",
            )
        )
        if value("t_bottom") is not None:
            steps.append(
                Step(
                    "Time to reach the bottom",
                    "t = (F(φ, k) measured from the start to the bottom) / ω₀ₙ",
                    "released from rest: a quarter period, K(k)/ω₀ₙ" if omega0 == 0 else "",
                    quantity_text(value("t_bottom"), "s"),
                    "sin(θ/2) = k sn(ω₀ₙt + u₀, k): the Jacobi elliptic function gives θ(t) exactly; it is at the bottom where sn = 0",
                )
            )
    elif isinstance(exact, Circulation) and method == "exact":
        steps.append(
            Step(
                "It goes over the top: time for one turn",
                "T = 2K(1/k)/(kω₀ₙ), k² = E/(2mgd) > 1",
                f"k = {fmt(exact.k, 8)}",
                quantity_text(value("period"), "s"),
                "with more energy than the top needs, θ keeps growing; sin(θ/2) = sn(kω₀ₙt, 1/k)",
            )
        )
    elif isinstance(exact, Harmonic) and method == "exact":
        steps.append(
            Step(
                "Period (exact at any amplitude)",
                "T = 2π√(I/κ)",
                f"2π√({quantity_text(inertia, 'kg*m**2')} / {fmt(kappa)} N·m/rad)",
                quantity_text(value("period"), "s"),
                "the spring's torque κθ is linear in θ, so the motion is simple harmonic however far it swings; "
                "the time to the bottom from rest is a quarter of it",
            )
        )
    elif method in STEPPERS:
        how = {
            "euler": "explicit Euler: θ += hω, ω += hα(θ) (first order; it gains energy every step)",
            "rk4": "classical Runge-Kutta, four stages (fourth order; it loses energy slowly)",
            "rk45": "Dormand-Prince 5(4), its step held to the tolerance",
            "verlet": "velocity Verlet: a half kick, a drift, a half kick (second order, symplectic: its energy stays bounded)",
        }[method]
        steps.append(
            Step(
                f"Period by stepping the motion ({method})",
                "θ' = ω, ω' = α(θ) = −(mgd sin θ + κθ)/I; T = 2 × (time between two turning points, ω = 0)",
                "",
                "withheld (see the notes)" if value("period") is None else quantity_text(value("period"), "s"),
                how + "; each turning point, the bottom and --angle are located by re-stepping the step that crosses them",
            )
        )
    elif method == "small-angle":
        steps.append(
            Step(
                "Small-angle model: the period at every amplitude",
                "T = T₀ = 2π√(I / (mgd + κ)), θ(t) = θ₀ cos Ωt + (ω₀/Ω) sin Ωt",
                "",
                quantity_text(value("period"), "s"),
                "sin θ ≈ θ makes the motion harmonic; the real period is longer, by about θ₀²/16 (see the note)",
            )
        )
    if mass is not None and value("pivot_force0") is not None:
        steps.append(
            Step(
                "Force of the pivot on the body at the start",
                "F_r = m(dω² + g cos θ), F_t = m(dα + g sin θ), F = √(F_r² + F_t²)",
                "√(({}N)² + ({}N)²)".format(*(fmt(x) + " " for x in pivot_force(swing, mass, cm_distance, gravity, theta0, abs(omega0))[:2])),
                quantity_text(value("pivot_force0"), "N"),
                f"with m = {fmt(mass)} kg, d = {fmt(cm_distance)} m, ω = {fmt(abs(omega0))} rad/s, θ = {deg0}; Newton's second law for the centre of mass, which moves on a circle of radius d: F + mg = m a_cm",
            )
        )
        if value("pivot_force_bottom") is not None:
            steps.append(
                Step(
                    "Force of the pivot at the bottom",
                    "F = m(dω_b² + g)",
                    f"{fmt(mass)} kg × ({fmt(cm_distance)} m × ({fmt(value('omega_bottom'))} rad/s)² + {fmt(gravity)} m/s²)",
                    quantity_text(value("pivot_force_bottom"), "N"),
                    "at the bottom α = 0 (gravity has no lever arm), so the pivot holds up the weight and supplies the centripetal force",
                )
            )
    for where, key in (("at the start", "0"), ("at the bottom", "_bottom"), ("at --angle", "")):
        if value("pivot_radial" + key) is not None:
            steps.append(
                Step(
                    f"The pivot's force as components {where}",
                    "F_h = F_t cos θ − F_r sin θ, F_v = F_r cos θ + F_t sin θ",
                    f"F_r = {quantity_text(value('pivot_radial' + key), 'N')} (towards the pivot), "
                    f"F_t = {quantity_text(value('pivot_tangential' + key), 'N')} (towards larger angles)",
                    f"F_h = {quantity_text(value('pivot_horizontal' + key), 'N')}, F_v = {quantity_text(value('pivot_vertical' + key), 'N')} (up)",
                    "F_r and F_t are along and across the line from the pivot to the centre of mass, which turns with the body; "
                    "F_h is positive towards the side of positive angles" + (" (from the top)" if zero.top else ""),
                )
            )
    if value("equivalent_length") is not None:
        steps.append(
            Step(
                "Equivalent simple pendulum and centre of percussion",
                "L = I / (md)",
                f"{quantity_text(inertia, 'kg*m**2')} / ({fmt(mass)} kg × {fmt(cm_distance)} m)",
                quantity_text(value("equivalent_length"), "m"),
                "a bob at L has the same period; struck there, the body turns about the pivot with no jolt at the pivot",
            )
        )
    if value("omega0_over") is not None:
        steps.append(
            Step(
                "Does it go over the top?",
                "½Iω₀,over² = U(180°) − U(θ₀)",
                f"ω₀,over = √(2 × {quantity_text(max(swing.potential(math.pi) - swing.potential(theta0), 0.0), 'J')} / {quantity_text(inertia, 'kg*m**2')})",
                quantity_text(value("omega0_over"), "rad/s") + (": it goes over the top" if value("goes_over") else ": it swings back"),
                f"against |ω₀| = {fmt(abs(omega0))} rad/s: it passes the top only with more kinetic energy at the start than the climb takes",
            )
        )
    return steps


def reach_steps(swing: Swing, cm_distance: float, results, zero) -> list[Step]:
    """The turning angle from energy, the rise of the centre of mass, KE at the bottom."""
    value = lambda key: results[key].value if key in results else None  # noqa: E731
    steps = []
    amplitude = value("amplitude")
    if amplitude is not None and (swing.omega0 or swing.theta0):
        steps.append(
            Step(
                "How far it swings: the turning angle (energy)",
                "U(θₐ) = ½Iω₀² + U(θ₀), the first θₐ along the motion",
                f"½ × {quantity_text(swing.inertia, 'kg*m**2')} × ({quantity_text(abs(swing.omega0), 'rad/s')})² + {quantity_text(swing.potential(swing.theta0), 'J')}",
                f"{'φ' if zero.top else 'θ'}ₐ = {fmt(math.degrees(amplitude))}°" + (" from the top" if zero.top else ""),
                "it turns where all its kinetic energy has gone into potential energy"
                + (": sin(θₐ/2) = k, k² = sin²(θ₀/2) + Iω₀²/(4mgd)" if swing.gravity_torque and not swing.torsion else ""),
            )
        )
        if value("rise") is not None:
            steps.append(
                Step(
                    "Rise of the centre of mass to the turning angle",
                    "h = d(cos θ₀ − cos θₐ)" + (" = Iω₀²/(2mg)" if not swing.torsion else ""),
                    f"{fmt(cm_distance)} m × (cos {_degrees(swing.theta0)} − cos {_degrees(zero.inward(amplitude))})",
                    quantity_text(value("rise"), "m"),
                    "measured from the start; under gravity alone mgh is the kinetic energy it started with",
                )
            )
    if value("KE_bottom") is not None:
        steps.append(
            Step("Kinetic energy at the bottom", "KE_b = ½Iω_b²",
                 f"½ × {quantity_text(swing.inertia, 'kg*m**2')} × ({quantity_text(value('omega_bottom'), 'rad/s')})²",
                 quantity_text(value("KE_bottom"), "J"), "all the potential energy it loses on the way down, beside what it started with")
        )
    return steps


def _degrees(angle: float) -> str:
    """An angle in degrees for a numbers line, a negative one in parentheses with a true minus."""
    text = f"{fmt(math.degrees(angle))}°"
    return f"(−{text[1:]})" if text.startswith("-") else text
