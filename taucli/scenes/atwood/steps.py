"""The worked steps of the machine (machine.solve): the pulley as extra mass, one equation per
body, their sum, the massless pulley for comparison, the tensions and the check with the
pulley's equation, α = a/R. (The stepped pulley's and the sliding string's steps are beside
their solvers.)
"""

from __future__ import annotations

from taucli.writing.report import Step, fmt, quantity_text, term
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


def stepped_steps(m1, m2, inertia, g, r1, r2, axle_torque, a, results, held) -> list[Step]:
    axle_term = " − τ_a" if axle_torque else ""
    steps = [
        Step("For m₁ (moving down), wound at r₁", "m₁g − T₁ = m₁a₁,  a₁ = α r₁", "", "", "weight minus tension; its string unwinds from the step of radius r₁"),
        Step("For m₂ (moving up), wound at r₂ on the other side", "T₂ − m₂g = m₂a₂,  a₂ = α r₂", "", "", "tension minus weight; its string winds onto the step of radius r₂"),
        Step("For the pulley", f"T₁r₁ − T₂r₂{axle_term} = I α", "", "", "each string's torque is its tension times its own radius"),
        Step(
            "Put the tensions from the masses into the pulley's equation",
            f"α = (m₁g r₁ − m₂g r₂{axle_term}) / (I + m₁r₁² + m₂r₂²)",
            f"({term(m1 * g * r1, 'N*m')} − {term(m2 * g * r2, 'N*m')}{' − ' + term(axle_torque, 'N*m') if axle_torque else ''}) / ({term(inertia, 'kg*m**2')} + {term(m1 * r1 * r1, 'kg*m**2')} + {term(m2 * r2 * r2, 'kg*m**2')})",
            quantity_text(results["alpha"].value, "rad/s**2") + ("  (held: a = 0)" if held else ""),
            "each mass adds m r² at its own radius to the pulley's I; the larger torque wins",
        ),
        Step("Each mass's acceleration", "a₁ = α r₁,  a₂ = α r₂", "", f"{quantity_text(a, 'm/s**2')}, {quantity_text(results['a2'].value, 'm/s**2')}",
             "the two strings move at the speeds of their steps' rims"),
        Step("Tensions", "T₁ = m₁(g − a₁),  T₂ = m₂(g + a₂)", "", f"{quantity_text(results['T1'].value, 'N')}, {quantity_text(results['T2'].value, 'N')}",
             "from each mass's equation"),
    ]
    return steps


_SUB = {"1": "₁", "2": "₂"}


def general_steps(machine, f, mu_k: tuple[float | None, float | None], a: float | None, results: dict, held: bool, direction: int) -> list[Step]:
    """The steps of ``solve_machine``'s answer beyond the classic machine: each block where it is
    (hanging, on a table or a slope), the pulls on them, the drive, one equation per body, their
    sum along the string, and the tensions from each block's equation (a μk of None: not given,
    where the block slides)."""
    s = direction or 1
    steps: list[Step] = []
    stepped = machine.radii is not None
    tension_terms = []
    sides = (("1", machine.side1, machine.pull1, f.along1, f.normal1, mu_k[0]), ("2", machine.side2, machine.pull2, f.along2, f.normal2, mu_k[1]))
    for n, side, pull, along, normal, mu in sides:
        i = _SUB[n]
        pulled = pull != (0.0, 0.0)
        if not (f.mass1 if n == "1" else f.mass2) and not pulled and side.hanging:
            tension_terms.append(f"T{i} = 0")
            continue  # no block there: the string's end is wound on the pulley
        massless = not (f.mass1 if n == "1" else f.mass2)  # the string's end pulled by hand
        weight = "" if massless else f"m{i}g" + ("" if side.hanging else f" sin θ{i}")
        g_text = weight + (((" + " if weight else "") + (f"P{i} cos φ{i}" if pull[1] else f"P{i}")) if pulled else "")
        away = (s > 0) == (n == "1" or machine.same_side)  # does this block move away from the pulley?
        where = "the string's end, pulled" if massless and side.hanging else "hanging" if side.hanging else f"on {side.surface()}"
        if held:
            moving = "at rest"
        elif away:
            moving = "moving " + ("down" if side.hanging else "away from the pulley")
        else:
            moving = "moving " + ("up" if side.hanging else "towards the pulley")
        rubs = bool(not side.hanging and (mu is None or mu) and not held and normal)
        # kinetic friction opposes the sliding; m1's equation counts away from the pulley, m2's towards it
        against = "−" if away == (n == "1") else "+"
        friction = f" {against} μₖ{i}N{i}" if rubs else ""
        if n == "1":
            equation, accel = f"G₁ − T₁{friction} = m₁a", ""
            tension_terms.append(f"T₁ = G₁{friction} − m₁a")
        else:
            equation = f"T₂ − G₂{friction} = m₂a₂"
            accel = "a₂ = a" if not stepped and not machine.same_side else "a₂ = " + ("−" if machine.same_side else "") + "(r₂/r₁) a"
            flipped = friction.replace("−", "±").replace("+", "−").replace("±", "+")
            tension_terms.append(f"T₂ = G₂{flipped} + m₂a₂")
        table = not side.hanging and not side.angle
        if table and not pulled:
            why = f"G{i} = 0: on the table its weight pulls it no way along its path"
        else:
            what = "" if massless else "its weight" if side.hanging else "" if table else "gravity's component along the slope"
            if pulled:
                what = (what + " and " if what else "") + "the pull's component along it"
            g_text = g_text.replace(f"m{i}g sin θ{i} + ", "") if table else g_text
            why = f"G{i} = {g_text} = {quantity_text(along, 'N')} pulls it away from the pulley along its path ({what})"
        if not side.hanging:
            why += (f"; N{i} = m{i}g cos θ{i}" + (f" − P{i} sin φ{i}" if pull[1] else "") + f" = {quantity_text(normal, 'N')} presses it on its surface"
                    + ("" if not rubs else f", and kinetic friction μₖ{i}N{i} = {quantity_text(mu * normal, 'N')} opposes the sliding" if mu is not None
                       else f", and kinetic friction μₖ{i}N{i} opposes the sliding ("
                       + ("no --mu-k" if machine.options[int(n) - 1] == "incline" else f"no mu-k= in --{machine.options[int(n) - 1]}") + ")"))
        steps.append(Step(f"For m{i} ({where}, {moving})", equation + (f",  {accel}" if accel else ""), "", "", why))
    other = "+" if machine.same_side else "−"
    drive_term = " − τ_d" if machine.torque else ""
    axle_term = f" {'−' if s > 0 else '+'} τ_a" if machine.pulley.axle_friction and not held else ""
    if stepped:
        pulley_equation = f"T₁r₁ {other} T₂r₂{drive_term}{axle_term} = I α,  α = a/r₁"
    else:
        pulley_equation = f"(T₁ {other} T₂)R{drive_term}{axle_term} = I α,  α = a/R"
    steps.append(Step(
        "For the pulley", pulley_equation, "", "",
        "each string's torque is its tension times its radius" + (", both the same way (the strings are on one side)" if machine.same_side else "")
        + (f"; the drive τ_d = {quantity_text(machine.torque, 'N*m')} turns it the way that lifts m₁" if machine.torque else "")
        + ("; the axle friction τ_a opposes the turning" if axle_term else ""),
    ))
    rho = f.rho
    unknown = (mu_k[0] is None and f.normal1) or (mu_k[1] is None and f.normal2)
    friction = f.axle_force + (mu_k[0] or 0.0) * f.normal1 + abs(rho) * (mu_k[1] or 0.0) * f.normal2
    drive_force = f.along1 - rho * f.along2 - f.drive_force
    resist = "" if held or not (friction or unknown) else (" − friction" if s > 0 else " + friction")
    radius = "r₁" if stepped else "R"
    if rho == 1:
        equation = f"a = (G₁ − G₂{' − τ_d/R' if machine.torque else ''}{resist}) / (m₁ + m₂ + I/R²)"
    else:
        equation = f"a = (G₁ − ρG₂{' − τ_d/' + radius if machine.torque else ''}{resist}) / (m₁ + m₂ρ² + I/{radius}²),  ρ = a₂/a = {fmt(rho)}"
    friction_text = "friction" if unknown else term(friction, "N")
    numbers = (f"({term(drive_force, 'N')} {resist[1]} {friction_text})" if resist else term(drive_force, "N")) + f" / {term(f.moving_mass, 'kg')}"
    why = ["adding the equations eliminates the tensions"]
    if resist:
        why.append("friction is the kinetic friction under the blocks and at the axle, against the motion")
    if held:
        why.append(f"at rest static friction can hold up to {quantity_text(f.axle_force + grips(f, machine), 'N')}")
    if rho != 1:
        why.append("m₂ moves ρ times as fast as m₁, so its pull counts ρ times and its mass ρ² times")
    why.append("the pulley counts as I/" + radius + "²")
    steps.append(Step(
        "Add them along the string", equation, numbers,
        "needs μₖ" if a is None else quantity_text(a, "m/s**2") + ("  (held: static friction wins, a = 0)" if held else ""),
        "; ".join(why),
    ))
    tension1, tension2 = results["T1"].value, results["T2"].value
    if a is not None and not held:
        steps.append(Step("Tensions, from each block's equation", ",  ".join(tension_terms), "",
                          f"{quantity_text(tension1, 'N')}, {quantity_text(tension2, 'N')}", "each string pulls (neither would have to push: not slack)"))
    if f.r1 is not None and a is not None:
        steps.append(Step("Angular acceleration of the pulley", f"α = a/{radius}", f"{term(a, 'm/s**2')} / {term(f.r1, 'm')}",
                          quantity_text(a / f.r1, "rad/s**2"), "the string does not slip on the rim"))
    return steps


def grips(f, machine) -> float:
    """The most static friction under the blocks can hold, along the string (μs as friction.py takes it)."""
    mu1 = machine.side1.mu_s if machine.side1.mu_s is not None else (machine.side1.mu_k or 0.0)
    mu2 = machine.side2.mu_s if machine.side2.mu_s is not None else (machine.side2.mu_k or 0.0)
    return mu1 * f.normal1 + abs(f.rho) * mu2 * f.normal2
