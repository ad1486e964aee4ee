"""Brakes, pressed faces and band brakes on a wheel (#24, #35): their Coulomb torques
(taucli.scenes.contact) added to the axle's friction before the motion, and their shares of its
work and power after it.
"""

from __future__ import annotations

from dataclasses import replace

from taucli.options.spin_down import COMMAND as TABLE
from taucli.writing.report import Report, Step, quantity_text
from taucli.scenes.assumed import Assumed
from taucli.scenes.inertia import body_mass
from taucli.scenes.contact import body_rim, contacts
from taucli.options.table import Results


def split_contacts(report: Report, axle: float, contact) -> Report:
    """The report with the friction's work and power shared out by torque among the axle, the
    brakes and the faces: each is a constant torque against the motion, so each takes its
    torque times the same angle swept (and times the same |ω|)."""
    if contact is None or not contact.kinetic:
        return report
    total = axle + contact.kinetic
    results = Results(TABLE)
    steps = list(report.steps)
    for key, value in report.results.items():
        if key not in ("work_friction", "power_friction"):
            results[key] = value
            continue
        kind = key.partition("_")[0]
        part = value.label.partition("takes")[2]
        if value.value is None:  # withheld (a stepper's error estimate): so is each share
            results[key] = value
            for name, _, _ in contact.shares:
                results.put(f"{kind}_{name}", None, part)
            continue
        share = value.value / total  # the angle swept, or |ω|
        if axle:
            results.put(key, axle * share, part)
        for name, symbol, torque in contact.shares:
            if torque:
                results.put(f"{kind}_{name}", torque * share, part)
                if kind == "work":
                    steps.append(Step(f"Energy the {name}s take", f"W_{name} = {symbol} × angle swept",
                                      f"{quantity_text(torque, 'N*m')} × {quantity_text(share, 'rad')}", quantity_text(torque * share, "J"),
                                      "a constant friction torque against the motion takes its torque for every radian swept"))
                else:
                    steps.append(Step(f"Power the {name}s take", f"P_{name} = {symbol}·|ω|",
                                      f"{quantity_text(torque, 'N*m')} × {quantity_text(share, 'rad/s')}", quantity_text(torque * share, "W"),
                                      "power is torque times angular speed"))
    steps = [replace(step, title="Energy all friction takes (axle, brakes, faces, bands, calipers)") if step.title == "Energy friction takes" else step for step in steps]
    return Report(report.scene, report.model, report.method, results, steps, report.notes, report.inputs, report.tables, report.trajectory)


def put_contacts(brakes, faces, body_options: dict, rim: float | None, assumed: Assumed, g: float | None, results: Results, steps: list[Step], notes: list[str],
                 axle: float, bands=(), calipers=()):
    """The brakes', faces' and bands' torques (contact.py), put among the results, steps and notes before the motion."""
    shape_rim = body_rim(body_options)
    options = body_options if shape_rim is not None or rim is None else {**body_options, "shape": "disc", "radius": rim}
    g = assumed.gravity(g) if any(face.by_weight for face in faces) else None
    contact = contacts(brakes, faces, options, body_mass(**body_options) if faces else body_options.get("mass"), g, bands, calipers)
    if brakes:
        results.put("torque_brake", contact.brake)
    if faces:
        results.put("torque_face", contact.face)
    if bands:
        results.put("torque_band", contact.band)
    if calipers:
        results.put("torque_caliper", contact.caliper)
    for key, value, part in contact.details:
        results.put(key, value, part)
    steps.extend(contact.steps)
    notes.extend(contact.notes)
    terms = [(symbol, value) for symbol, value in (("τ_axle", axle), ("τ_b", contact.brake), ("τ_face", contact.face), ("τ_band", contact.band),
                                                   ("τ_cal", contact.caliper)) if value]
    if terms:
        steps.append(Step("Friction torques add", "τ_f = " + " + ".join(symbol for symbol, _ in terms),
                          " + ".join(quantity_text(value, "N*m") for _, value in terms), quantity_text(axle + contact.kinetic, "N*m"),
                          "each is a constant torque against the motion, so together they act as one friction torque τ_f"))
    return contact


def with_contacts(report: Report, contact) -> Report:
    """The model line names the brakes' and faces' friction models."""
    if contact is None or not contact.models:
        return report
    return Report(report.scene, f"{report.model}; {', '.join(contact.models)}", report.method, report.results, report.steps,
                  report.notes, report.inputs, report.tables, report.trajectory)
