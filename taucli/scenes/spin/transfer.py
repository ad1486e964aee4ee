"""Energy added to a wheel or taken from it, and a wheel's stored energy put to use.

A wheel on a fixed axle holds all its energy as rotation, KE = ½Iω². Work W done on it
(positive: added, by a motor; negative: taken, by water on a propeller, a tool) changes that
energy and nothing else (the work-energy theorem for rotation):

    ½Iω₁² = ½Iω₀² + W  ⇒  ω₁ = ±√(ω₀² + 2W/I)   (W ≥ −½Iω₀²: no more can be taken than is stored)

The energy a wheel gives up as it slows from ω₀ to ω₁ (to rest unless --until-omega), E = ½I(ω₀² − ω₁²),
reaches a load at an efficiency η (0 < η ≤ 1): it lifts a mass m through h = ηE/(mg) (its
potential energy mgh), or sets a vehicle of mass m moving from rest at v = √(2ηE/m) (its
kinetic energy ½mv²).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from taucli.core.errors import InputError
from taucli.options.spin_down import COMMAND as TABLE
from taucli.writing.report import Report, Step, quantity_text, term
from taucli.options.table import Results


def transfer_report(inertia: float, inertia_steps: Sequence[Step], omega0: float, *, work: float | None, lift_mass: float | None,
                    vehicle_mass: float | None, efficiency: float | None, until_omega: float | None, g: float,
                    front: tuple[list[Step], list[str], Results]) -> Report:
    """The wheel's energy before, after the work W (``work``), and what its stored energy does to a
    load (``lift_mass``: the height; ``vehicle_mass``: the speed) at the efficiency η."""
    front_steps, notes, front_results = front
    results = Results(TABLE)
    results.update(front_results)
    results.put("I", inertia)
    ke0 = inertia * omega0 * omega0 / 2
    results.put("KE0", ke0)
    steps = [*inertia_steps, *front_steps,
             Step("Kinetic energy stored", "KE₀ = ½Iω₀²", f"½ × {quantity_text(inertia, 'kg*m**2')} × ({term(omega0, 'rad/s')})²",
                  quantity_text(ke0, "J"), "a wheel on a fixed axle holds all its energy as rotation")]
    if work is not None:
        _after_work(inertia, omega0, ke0, work, results, steps)
        model = "work-energy theorem for rotation: ½Iω₁² = ½Iω₀² + W"
    else:
        model = _to_load(inertia, omega0, ke0, lift_mass, vehicle_mass, 1.0 if efficiency is None else efficiency, until_omega, g, results, steps, notes)
    return Report("spin-down", model, "closed form", results, steps, notes)


def _after_work(inertia: float, omega0: float, ke0: float, work: float, results: Results, steps: list[Step]) -> None:
    """ω₁ after the work W: ½Iω₁² = KE₀ + W, ω₁ turning the way ω₀ did (the way W drives a wheel at rest)."""
    ke1 = ke0 + work
    if ke1 < -1e-12 * max(ke0, abs(work)):
        raise InputError("work", f"takes more energy than the wheel stores (KE₀ = {quantity_text(ke0, 'J')}): expected at least {quantity_text(-ke0, 'J')}",
                         example="{work} -50kJ", got=quantity_text(work, "J"))
    ke1 = max(ke1, 0.0)
    speed = math.sqrt(ke1 * 2 / inertia)
    omega1 = math.copysign(speed, omega0 if omega0 else 1.0)
    results.put("KE_after", ke1, " the work")
    results.put("omega_after", omega1, " the work")
    how = "added to" if work >= 0 else "taken from"
    steps.append(Step("Kinetic energy after the work", "KE₁ = KE₀ + W", f"{quantity_text(ke0, 'J')} + {term(work, 'J')}", quantity_text(ke1, "J"),
                      f"the work-energy theorem: the work done on the wheel is the change of its kinetic energy ({quantity_text(abs(work), 'J')} {how} it)"))
    steps.append(Step("Angular velocity after", "½Iω₁² = KE₁  ⇒  ω₁ = √(2KE₁/I)", f"√(2 × {quantity_text(ke1, 'J')} / {quantity_text(inertia, 'kg*m**2')})",
                      quantity_text(omega1, "rad/s"), "the wheel keeps turning the way it turned; the energy fixes only the speed"))


def _to_load(inertia: float, omega0: float, ke0: float, lift_mass, vehicle_mass, efficiency: float, until_omega, g: float,
             results: Results, steps: list[Step], notes: list[str]) -> str:
    """The energy the wheel gives up (to rest, or to --until-omega), η of it reaching the load."""
    if until_omega is not None:
        if abs(until_omega) > abs(omega0):
            raise InputError("until_omega", f"is faster than ω₀ = {quantity_text(omega0, 'rad/s')}: a wheel giving up energy slows down",
                             example="{until_omega} 100rpm")
        ke1 = inertia * until_omega * until_omega / 2
        given_up = inertia * (abs(omega0) - abs(until_omega)) * (abs(omega0) + abs(until_omega)) / 2
        results.put("KE_after", ke1, " giving up its energy")
        results.put("omega_after", until_omega, " giving up its energy")
        steps.append(Step("Energy given up", "E = ½I(ω₀² − ω₁²)",
                          f"½ × {quantity_text(inertia, 'kg*m**2')} × (({term(omega0, 'rad/s')})² − ({term(until_omega, 'rad/s')})²)",
                          quantity_text(given_up, "J"), "the kinetic energy the wheel loses as it slows from ω₀ to ω₁"))
        until = f" as the wheel slows to ω = {quantity_text(until_omega, 'rad/s')}"
    else:
        given_up, until = ke0, " as the wheel comes to rest"
        results.put("KE_after", 0.0, " giving up its energy")
        results.put("omega_after", 0.0, " giving up its energy")
    delivered = efficiency * given_up
    results.put("energy_delivered", delivered)
    if efficiency != 1:
        steps.append(Step("Energy that reaches the load", "E_load = ηE", f"{efficiency:g} × {quantity_text(given_up, 'J')}", quantity_text(delivered, "J"),
                          "the rest is lost on the way (friction in the gears, heat)"))
    if lift_mass is not None:
        height = delivered / (lift_mass * g)
        results.put("lift_height", height)
        steps.append(Step("Height the mass is lifted", "mgh = E_load  ⇒  h = E_load/(mg)",
                          f"{quantity_text(delivered, 'J')} / ({quantity_text(lift_mass, 'kg')} × {quantity_text(g, 'm/s**2')})",
                          quantity_text(height, "m"), "the energy delivered becomes the mass's potential energy (lifted slowly, from rest to rest)"))
    if vehicle_mass is not None:
        speed = math.sqrt(2 * delivered / vehicle_mass)
        results.put("vehicle_speed", speed)
        steps.append(Step("Speed of the vehicle", "½mv² = E_load  ⇒  v = √(2E_load/m)",
                          f"√(2 × {quantity_text(delivered, 'J')} / {quantity_text(vehicle_mass, 'kg')})", quantity_text(speed, "m/s"),
                          "the energy delivered becomes the vehicle's kinetic energy, from rest on the level"))
    if lift_mass is not None and vehicle_mass is not None:
        notes.append("lift_height and vehicle_speed each take the whole of the energy delivered: they are two uses of it, not both at once")
    load = "lifts a mass" if vehicle_mass is None else "drives a vehicle" if lift_mass is None else "lifts a mass or drives a vehicle"
    return f"stored rotational energy put to use: the wheel {load}{until}" + (f", at efficiency η = {efficiency:g}" if efficiency != 1 else "")
