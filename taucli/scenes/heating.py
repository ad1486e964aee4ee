"""The temperature rise of a brake or a clutch (#47 item 2): the heat its friction makes, taken by
a mass m of specific heat c with no loss to the air (a short stop, the books' assumption):

    E = ∫ τ_f·|ω| dt  (the energy the brakes, faces and bands take; with none, the axle friction's)
    ΔT = E/(m·c)
"""

from __future__ import annotations

from taucli.core.errors import InputError
from taucli.options.spin_down import COMMAND as TABLE
from taucli.options.table import Results
from taucli.writing.report import Report, Step, quantity_text, term

CONTACT_WORKS = ("work_brake", "work_face", "work_band", "work_caliper")


def with_temperature_rise(report: Report, heat_mass: float | None, specific_heat: float | None) -> Report:
    """The report with ``temperature_rise`` after the works it comes from, and its step."""
    if heat_mass is None and specific_heat is None:
        return report
    if heat_mass is None or specific_heat is None:
        missing = "heat_mass" if heat_mass is None else "specific_heat"
        raise InputError(missing, "is needed with {heat_mass} and {specific_heat} together: ΔT = E/(m·c)",
                         example="{heat_mass} 12kg {specific_heat} '460 J/(kg*K)'")
    works = [key for key in CONTACT_WORKS if key in report.results] or [key for key in ("work_friction",) if key in report.results]
    if not works:
        raise InputError("heat_mass", "needs a friction that makes heat: a {brake}, {face}, {band}, {caliper} or {friction} (ΔT = E/(m·c), E the energy it takes)",
                         example="{brake} 'force=100N mu=0.4 radius=0.5m' {heat_mass} 12kg {specific_heat} '460 J/(kg*K)'")
    results = Results(TABLE)
    results.update(report.results)
    notes = list(report.notes)
    steps = list(report.steps)
    energies = [report.results[key].value for key in works]
    if any(value is None for value in energies):
        results.put("temperature_rise", None)
        notes.append(f"temperature_rise: null, because {', '.join(works)} is null")
    else:
        heat = sum(energies)
        rise = heat / (heat_mass * specific_heat)
        results.put("temperature_rise", rise)
        symbols = " + ".join("W_" + key.partition("_")[2] for key in works)
        steps.append(Step("Temperature rise of the mass that takes the heat", f"ΔT = E/(m·c),  E = {symbols}",
                          f"{quantity_text(heat, 'J')} / ({term(heat_mass, 'kg')} × {term(specific_heat, 'J/kg/K')})", quantity_text(rise, "K"),
                          "the friction's work turns to heat in the rubbing parts; with no time to lose it to the air, "
                          "it warms their mass m of specific heat c"))
    return Report(report.scene, report.model, report.method, results, steps, notes, report.inputs, report.tables, report.trajectory)
