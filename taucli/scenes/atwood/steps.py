"""The worked steps of the machine (machine.solve): the pulley as extra mass, one equation per
body, their sum, the massless pulley for comparison, the tensions and the check with the
pulley's equation, α = a/R. (The stepped pulley's and the sliding string's steps are beside
their solvers.)
"""

from __future__ import annotations

from taucli.report import Step, fmt, quantity_text, term
from taucli.scenes.atwood.pulley import Pulley
from taucli.scenes.atwood.slope import Slope


def machine_steps(
    m1: float, m2: float, pulley: Pulley, g: float, slope: Slope, sin_angle: float, normal: float,
    a: float | None, a_massless: float | None, results: dict, held: bool, direction: int,
) -> list[Step]:
    """The steps of ``solve``'s answer, from its inputs and results (a None where μk is not given)."""
    steps: list[Step] = []
    if pulley.mass and pulley.inertia is None:
        factor = "½" if (pulley.shape or "disc") == "disc" else ""
        steps.append(
            Step(
                "The pulley's rotational inertia as extra mass",
                f"I/R² = {factor}M" if factor else "I/R² = M",
                f"{factor} × {quantity_text(pulley.mass, 'kg')}" if factor else quantity_text(pulley.mass, "kg"),
                quantity_text(pulley.effective_mass(), "kg"),
                f"I = {factor}MR² and α = a/R, so the torque equation (T₁ − T₂)R = Iα becomes T₁ − T₂ = {factor}Ma: "
                "R cancels",
            )
        )
    steps.append(Step("For m₁ (moving down)", "m₁g − T₁ = m₁a", "", "", "the net downward force on m₁ is its weight minus the upward string tension"))
    if slope.hanging:
        steps.append(Step("For m₂ (moving up)", "T₂ − m₂g = m₂a", "", "", "the net upward force on m₂ is the string tension minus its weight"))
    else:
        friction_term = " − μₖm₂g cos θ" if slope.mu_k != 0 else ""  # None: not given, but acting
        steps.append(
            Step(
                f"For m₂ (pulled along the {'table' if slope.angle == 0 else 'slope'})",
                f"T₂ − m₂g sin θ{friction_term} = m₂a",
                "",
                "",
                "along the surface: the tension pulls m₂ on, gravity's component m₂g sin θ pulls it back, and "
                "kinetic friction μₖN opposes the sliding, N = m₂g cos θ",
            )
        )
    axle_term = " − τ_a/R" if pulley.axle_friction else ""
    steps.append(
        Step(
            "For the pulley (rotating; the string does not slip, α = a/R)",
            f"T₁ − T₂{axle_term} = ({pulley.symbol()})a",
            "",
            "",
            "the net torque on the pulley is (T₁ − T₂)R" + (" less the axle friction τ_a" if pulley.axle_friction else "")
            + "; dividing by R, the pulley acts on the string like extra mass",
        )
    )
    pulley_term = f" + {pulley.symbol()}" if pulley.effective_mass() else ""
    drive_text = "m₁g − m₂g" if slope.hanging else "m₁g − m₂g sin θ"
    resist = (" − μₖm₂g cos θ" if slope.mu_k != 0 and not slope.hanging else "") + (" − τ_a/R" if pulley.axle_friction else "")
    numbers = (
        f"({quantity_text(m1 * g, 'N')} − {quantity_text(m2 * g * sin_angle, 'N')}"
        + (f" − {quantity_text((slope.mu_k or 0.0) * normal + pulley.axle_force(), 'N')}" if resist and slope.mu_k is not None else " − friction" if resist else "")
        + f") / ({term(m1, 'kg')} + {term(m2, 'kg')}"
        + (f" + {term(pulley.effective_mass(), 'kg')}" if pulley_term else "")
        + ")"
    )
    steps.append(
        Step(
            "Add the three equations: the tensions cancel",
            f"a = ({drive_text}{resist}) / (m₁ + m₂{pulley_term})",
            numbers,
            "needs μₖ (--mu-k)" if a is None else quantity_text(a, "m/s**2") + ("  (held: static friction wins, a = 0)" if held else ""),
            "adding the equations eliminates T₁ and T₂; the pulley's "
            f"{pulley.symbol()} in the denominator slows the system, as extra mass would"
            if pulley_term
            else "adding the equations eliminates T₁ and T₂",
        )
    )
    if pulley_term and a_massless is not None:
        steps.append(
            Step(
                "Compare: the same machine with a massless pulley",
                f"a₀ = ({drive_text}{resist}) / (m₁ + m₂)",
                f"{term(m1 * g - m2 * g * sin_angle, 'N')}{' − friction' if resist else ''} / {term(m1 + m2, 'kg')}",
                quantity_text(a_massless, "m/s**2"),
                f"the massive pulley costs {fmt(abs(a_massless - a))} m/s² of acceleration: part of gravity's work goes into spinning it",
            )
        )
    tension1, tension2 = results["T1"].value, results["T2"].value
    if not held and a is not None:
        steps.append(Step("Tension on m₁'s side", "T₁ = m₁(g − a)", f"{term(m1, 'kg')} × ({term(g, 'm/s**2')} − {term(a, 'm/s**2')})", quantity_text(tension1, "N"), "from m₁'s equation"))
        if slope.hanging:
            steps.append(Step("Tension on m₂'s side", "T₂ = m₂(g + a)", f"{term(m2, 'kg')} × ({term(g, 'm/s**2')} + {term(a, 'm/s**2')})", quantity_text(tension2, "N"), "from m₂'s equation"))
        else:
            steps.append(
                Step("Tension on m₂'s side", "T₂ = m₂(a + g sin θ) + μₖN", "", quantity_text(tension2, "N"), "from m₂'s equation")
            )
        if pulley.effective_mass() or pulley.axle_friction:
            needed = pulley.effective_mass() * a + direction * pulley.axle_force()
            steps.append(
                Step(
                    "Check with the pulley's equation",
                    f"T₁ − T₂ = ({pulley.symbol()})a" + (" + τ_a/R" if pulley.axle_friction else ""),
                    f"{quantity_text(tension1, 'N')} − {quantity_text(tension2, 'N')}",
                    quantity_text(tension1 - tension2, "N"),
                    f"and ({pulley.symbol()})a{' + τ_a/R' if pulley.axle_friction else ''} = {quantity_text(needed, 'N')}: the tension "
                    "difference is exactly the force needed to turn the pulley",
                )
            )
    if pulley.radius is not None and a is not None:
        steps.append(Step("Angular acceleration of the pulley", "α = a/R", f"{term(a, 'm/s**2')} / {term(pulley.radius, 'm')}", quantity_text(a / pulley.radius, "rad/s**2"), "the string does not slip on the rim"))
    return steps
