"""What a run to a target reports about the target itself: the target given is the answer there
(ω, KE and each power at --until-omega, θ and revolutions at --until-angle, not the motion's value
with the search's rounding), and revs_until beside theta_until, in revolutions.
"""

from __future__ import annotations

import math

from taucli.writing.report import Report


def as_given(report: Report, inertia: float | None, until_omega: float | None, until_angle: float | None) -> Report:
    """At --in-time the wheel is at the target given (the drive was found to put it there): ω (and
    KE and each power, which follow from it) or θ is that target, not the motion's value at the
    time, which keeps the rounding of the search (1.4e-14 rad/s for --until-omega 0) (#42 item 22)."""
    results = report.results
    if until_angle is not None and results.get("theta") is not None and results["theta"].value is not None:
        results["theta"] = results["theta"]._replace(value=until_angle)
        if results.get("revs") is not None:
            results["revs"] = results["revs"]._replace(value=until_angle / (2 * math.pi))
    if until_omega is None:
        return report
    w = until_omega
    # ω, and KE = ½Iω², from the target; each power is a torque times ω (bω², k|ω|ⁿ⁺¹): 0 at a target of rest
    exact = {"omega": w, "KE": None if inertia is None else inertia * w * w / 2}
    if w == 0:
        exact.update(dict.fromkeys(("power", "power_friction", "power_viscous", "power_drag"), 0.0))
    for key, value in exact.items():
        if key in results and results[key].value is not None and value is not None:
            results[key] = results[key]._replace(value=value + 0.0)  # + 0.0: 0, not −0
    return report


def _put_after(results, after_key: str, key: str, of, prefix: str) -> None:
    """``key`` put just after ``after_key``, its value of(that value) (None stays None), its label's
    part the other's label without ``prefix``: where a Results has ``after_key`` and not ``key``."""
    found = results.get(after_key) if hasattr(results, "put") else None
    if found is None or key in results:
        return
    held = list(results.items())
    results.clear()
    for name, value in held:
        results[name] = value
        if name == after_key:
            results.put(key, None if value.value is None else of(value.value), value.label.removeprefix(prefix))


def with_revs_until(results) -> None:
    """revs_until beside theta_until, as revs_stop is beside theta_stop (#42): in revolutions."""
    _put_after(results, "theta_until", "revs_until", lambda theta: theta / (2 * math.pi), "angle turned until")


def with_momentum(results, inertia: float | None) -> None:
    """L = Iω beside ω at the target (#48 item 6: at t, at an angle, at a speed), where the body's I
    is known (no L for kinematics alone)."""
    if inertia is not None:
        _put_after(results, "omega", "L", lambda omega: inertia * omega, "angular velocity")
