"""A point at r from the pivot: every point of a rigid body has the same α and ω, so

    a_t = rα,   v_t = r|ω|,   a_c = rω²

at the start and at --angle (ω from energy there, with the sign it has when the body first gets
there; α from the torque there). a_t is taken along the motion, as everywhere
(taucli.scenes.point.along): negative while the body slows; from rest, the size of rα.
"""

from __future__ import annotations


from taucli.options.pendulum import COMMAND as TABLE
from taucli.writing.report import DeferredSteps, Report, Step, fmt, quantity_text
from taucli.scenes.pendulum.swing import Swing, sine
from taucli.scenes.pendulum.zero import Zero
from taucli.scenes.point import along
from taucli.options.table import Results


def put_point(report: Report, swing: Swing, r: float, angle: float | None, gravity: float, zero: Zero, accel=None) -> None:
    """A point at r from the pivot: a_t = rα along the motion, v_t = r|ω|, a_c = rω², at the start
    and at --angle; with a step that says why a rod's far end falls faster than g. ``accel(θ, ω)``:
    α where more than gravity and the spring turn the body (a couple at the pivot)."""
    accel = accel or (lambda theta, _: swing.accel(theta))
    results = Results(TABLE)
    where = f" {fmt(r)} m from the pivot"
    alpha0 = along(accel(swing.theta0, swing.omega0), swing.omega0)
    results.put("a_t0", r * alpha0, where)
    steps = [
        Step(
            f"Tangential acceleration at the start of the point{where}",
            "a_t = rα₀",
            f"{quantity_text(r, 'm')} × {quantity_text(alpha0, 'rad/s**2')}",
            quantity_text(r * alpha0, "m/s**2"),
            (
                f"every point of a rigid body has the same α; a point beyond I/(md) = {fmt(swing.inertia * gravity / swing.gravity_torque)} m "
                f"falls faster than a free body's g sin θ₀ = {quantity_text(gravity * abs(sine(swing.theta0)), 'm/s**2')}: the rest of the body, "
                "nearer the pivot, pulls it along (a rod's tip from the horizontal: a_t = 3g/2)"
            )
            if swing.gravity_torque and not swing.torsion
            else "every point of a rigid body has the same α, so a_t grows with r",
        )
    ]
    if angle is not None:
        omega = report.results["omega"].value  # signed: as the body first gets there; None where it never does
        where_at_angle = f"{where} at {zero.text(angle)}"
        alpha = None if omega is None else along(accel(angle, omega), omega)
        results.put("v_t", None if omega is None else r * abs(omega), where_at_angle)
        results.put("a_t", None if omega is None else r * alpha, where_at_angle)
        results.put("a_c", None if omega is None else r * omega * omega, where_at_angle)
        if omega is not None:
            steps.append(
                Step(
                    f"The point{where_at_angle}",
                    "v_t = r|ω|, a_t = rα (along the motion), a_c = rω²",
                    f"{quantity_text(r, 'm')} × {quantity_text(abs(omega), 'rad/s')}; α = {quantity_text(alpha, 'rad/s**2')}",
                    f"v_t = {quantity_text(r * abs(omega), 'm/s')}, a_t = {quantity_text(r * alpha, 'm/s**2')}, a_c = {quantity_text(r * omega * omega, 'm/s**2')}",
                    "ω from energy at that angle, α from the torque there, taken along the motion (negative: it slows)",
                )
            )
    report.results.update(results)
    report.steps = _Appended(report.steps, steps)


class _Appended(DeferredSteps):
    """A report's steps (written when first read) and more after them."""
    def __init__(self, first, more):
        super().__init__(lambda: [*first, *more])
