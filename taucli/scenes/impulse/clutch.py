"""Two bodies on one axis brought together through a clutch that slips (#35): ``--couple "… torque=T"``.

While the speeds differ the clutch passes its torque T (its capacity, kinetic), slowing the faster
body and speeding the slower, and nothing else acts about the axis:

    I₁ dω₁/dt = −T·s,   I₂ dω₂/dt = +T·s,   s = sgn(ω₁ − ω₂)

so each speed changes linearly until they meet at the common speed the angular momentum keeps,

    ω_f = (I₁ω₁ + I₂ω₂)/(I₁ + I₂),   t_slip = I₁|ω₁ − ω_f|/T = I₂|ω_f − ω₂|/T = I₁I₂|ω₁ − ω₂|/(T(I₁ + I₂))

(each body's angular impulse T·t_slip is its own change of L); after that they turn together and
the clutch, holding no torque, does not slip again. The clutch turns into heat the work of its
torque over the angle slipped, T·|ω₁ − ω₂|·t_slip/2 = ½·I₁I₂/(I₁ + I₂)·(ω₁ − ω₂)², the kinetic
energy lost (as with a clutch that locks at once: the torque sets only how long it takes).
"""

from __future__ import annotations

from taucli.core.errors import InputError
from taucli.options.impulse import COMMAND as TABLE
from taucli.writing.report import Report, Step, Table, Trajectory, quantity_text, term
from taucli.scenes.given import Couple
from taucli.scenes.inertia import part_inertia
from taucli.options.table import Results


def solve_clutch(inertia: float, omega0: float, couple: Couple, *, inertia_steps=()) -> Report:
    """The body (I₁, ω₁) and the couple (I₂, ω₂) through a clutch of torque T (module docstring)."""
    steps = list(inertia_steps)
    notes: list[str] = []
    other = part_inertia(couple.part).inertia if couple.part is not None else couple.inertia
    if not other:
        raise InputError(couple.source, "needs inertia= above 0 with torque=: a body with no inertia takes the other's speed at once",
                         example='{couple} "inertia=3kg*m^2 omega0=0 torque=50N*m"')
    if not inertia:
        raise InputError("inertia", "must be more than zero with a clutch that slips", example="{inertia} '2kg*m^2'")
    omega_other = 0.0 if couple.omega0 is None else couple.omega0
    if couple.omega0 is None:
        notes.append(f"{couple.source}: no omega0=, taken at rest (ω = 0)")
    torque = couple.torque
    total = inertia + other
    difference = omega0 - omega_other
    common = (inertia * omega0 + other * omega_other) / total
    reduced = inertia * other / total  # I₁I₂/(I₁ + I₂): the pair's inertia for their relative turning
    slip = reduced * abs(difference) / torque
    heat = 0.5 * reduced * difference * difference
    sense = (difference > 0) - (difference < 0)
    energy0 = 0.5 * (inertia * omega0 * omega0 + other * omega_other * omega_other)
    energy1 = 0.5 * total * common * common

    results = Results(TABLE)
    results.put("omega1", common, " the clutch stops slipping: the common speed")
    # each body's change from what the clutch passes it, not ω_f − ω₀ (which loses a small change beside a large ω)
    change = -other * difference / total
    results.put("delta_omega", change)
    results.put("inertia", inertia)
    results.put("omega0", omega0, "")
    results.put("J", -reduced * difference, " the body receives, −T·t_slip in its sense of slipping")
    results.put("t_slip", slip)
    results.put("heat", heat)
    results.put("L0", inertia * omega0 + other * omega_other)
    results.put("L1", total * common, " (both bodies)")
    results.put("KE0", energy0, " (both bodies)")
    results.put("KE1", energy1, " (both bodies)")
    results.put("KE_lost", heat, " (turned to heat in the clutch)")
    results.put("KE_lost_fraction", heat / energy0 if energy0 else None)
    if not energy0:
        notes.append("KE_lost_fraction: null, because nothing turns before (KE0 = 0)")
    if not difference:
        notes.append("the two bodies turn at the same speed already: the clutch does not slip")

    steps += [
        Step("Common speed (no external torque about the axis: L conserved)", "ω_f = (I₁ω₁ + I₂ω₂)/(I₁ + I₂)",
             f"({term(inertia, 'kg*m**2')} × {term(omega0, 'rad/s')} + {term(other, 'kg*m**2')} × {term(omega_other, 'rad/s')}) / "
             f"({term(inertia, 'kg*m**2')} + {term(other, 'kg*m**2')})", quantity_text(common, "rad/s"),
             "the clutch's torque on one body is equal and opposite to its torque on the other"),
        Step("Slip time (each body's angular impulse)", "T·t_slip = I₁|ω₁ − ω_f| = I₂|ω_f − ω₂|  →  t_slip = I₁I₂|ω₁ − ω₂|/(T(I₁ + I₂))",
             f"{term(inertia, 'kg*m**2')} × |{term(omega0, 'rad/s')} − {term(common, 'rad/s')}| / {term(torque, 'N*m')}", quantity_text(slip, "s"),
             "while it slips the clutch passes its full torque T, changing each body's speed at T/I until they meet"),
        Step("Heat in the clutch", "Q = T·|ω₁ − ω₂|·t_slip/2 = ½·I₁I₂/(I₁ + I₂)·(ω₁ − ω₂)²",
             f"{term(torque, 'N*m')} × {term(abs(difference), 'rad/s')} × {term(slip, 's')} / 2", quantity_text(heat, "J"),
             "the torque's work over the angle slipped, which falls linearly to 0: the kinetic energy the two bodies lose"),
    ]

    def state(t: float) -> tuple[float, float]:
        if t >= slip:
            return common, common
        return omega0 - sense * torque / inertia * t, omega_other + sense * torque / other * t

    horizon = 2 * slip if slip else 1.0
    curves = (("omega_body", "rad/s", "ω of the body"), ("omega_couple", "rad/s", "ω of the couple"))
    trajectory = Trajectory(curves, horizon, state, marks=((slip, "the clutch stops slipping"),) if slip else (),
                            note=f"plotted to twice the slip time, {quantity_text(horizon, 's')}")
    # each body's L before and after and the angular impulse the clutch gives it: ∓T·t_slip
    columns = (("part", None, "part"), ("L0", "kg*m**2/s", "L₀"), ("L1", "kg*m**2/s", "L₁"), ("J", "N*m*s", "J = ΔL"), ("speed_after", "m/s", "v after"))
    rows = (("body", inertia * omega0, inertia * common, -reduced * difference, None),
            ("couple", other * omega_other, other * common, reduced * difference, None))
    model = "a clutch that slips: constant torque T between the bodies until their speeds meet (L conserved)"
    return Report("impulse", model, "closed form", results, steps, notes, {}, {"parts": Table(columns, rows)}, trajectory=lambda: trajectory)
