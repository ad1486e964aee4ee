"""A centrifugal clutch (#48 item 5): n shoes of mass m ride on a spider turning at ω, their
centres of mass at r from the axis when they touch the drum, each held in by a spring that pulls
it with S there; the drum's inner radius is R. Each shoe presses the drum with what its
centrifugal force has left over the spring's pull,

    N = m·ω²·r − S        (none below the engagement speed ω_e = √(S/(m·r)), where the two balance)

and rubs it with μN at R, so the clutch passes (slipping, the drum slower than the spider)

    τ = n·μ·(m·ω²·r − S)·R,        P = τ·|ω|.

The clutch is read at the spider's speed, the scene's ω₀ (its own, or one found from a rim speed
or KE0): ω₀ is the speed a book gives ("the power transmitted at 500 rpm"). Its torque is
reported, not applied to the scene's motion: a clutch passes torque from one member to the other
(it drives the drum and loads the spider), and which of them the scene's body is, and whether the
drum turns, the spec does not say; treating it as a loss would be a guess. Give the torque to the
member it acts on as --torque or --friction in a run of its own.
"""

from __future__ import annotations

import functools
import inspect
import math
from collections.abc import Callable, Sequence

from taucli.options.table import Command, Results
from taucli.scenes.given import Centrifugal
from taucli.writing.report import Report, Step, fmt, quantity_text, term


def engagement_speed(clutch: Centrifugal) -> float:
    """ω_e = √(S/(m·r)): where a shoe's centrifugal force m·ω²·r meets the spring's pull S."""
    return math.sqrt(clutch.spring_force / (clutch.mass * clutch.radius))


def shoe_force(clutch: Centrifugal, omega: float) -> float:
    """N = m·ω²·r − S on the drum from each shoe at ω, or 0 below engagement (the springs hold it off).
    Written as m·r·(ω − ω_e)(ω + ω_e), which keeps its digits near engagement."""
    speed, engage = abs(omega), engagement_speed(clutch)
    if speed <= engage:
        return 0.0
    return clutch.mass * clutch.radius * (speed - engage) * (speed + engage)


def clutch_torque(clutch: Centrifugal, omega: float) -> float:
    """τ = n·μ·N·R: the torque the clutch passes at the spider's speed ω."""
    return clutch.shoes * clutch.mu * shoe_force(clutch, omega) * clutch.drum_radius


def clutch_report(command: Command, clutch: Centrifugal, speed: float | None, alone: bool = False) -> tuple[Results, list[Step], list[str]]:
    """The clutch's results (omega_engage, torque_centrifugal and power_centrifugal at ``speed``,
    None where no speed is known), its steps and notes."""
    results, steps, notes = Results(command), [], []
    name = clutch.source.replace("{", "").replace("}", "").replace("centrifugal", "centrifugal clutch")
    engage = engagement_speed(clutch)
    results.put("omega_engage", engage)
    steps.append(Step(f"Engagement speed of the {name}", "m·ω_e²·r = S  ⇒  ω_e = √(S/(m·r))",
                      f"√({term(clutch.spring_force, 'N')} / ({term(clutch.mass, 'kg')} × {term(clutch.radius, 'm')}))", quantity_text(engage, "rad/s"),
                      "a shoe touches the drum once its centrifugal force m·ω²·r (r: its centre of mass when it touches) reaches the spring's pull S"))
    if speed is None:
        results.put("torque_centrifugal", None)
        results.put("power_centrifugal", None)
        notes.append("torque_centrifugal: null, because the clutch's speed is not known: give {omega0} (the spider's speed, e.g. {omega0} 500rpm)")
        return results, steps, notes
    speed = abs(speed)
    force = shoe_force(clutch, speed)
    torque = clutch_torque(clutch, speed)
    results.put("torque_centrifugal", torque)
    results.put("power_centrifugal", torque * speed)
    if force == 0.0:
        steps.append(Step(f"Force of each shoe on the drum at ω₀ (the {name})", "N = 0 for ω₀ ≤ ω_e",
                          f"ω₀ = {quantity_text(speed, 'rad/s')} ≤ ω_e = {quantity_text(engage, 'rad/s')}", quantity_text(0.0, "N"),
                          "below the engagement speed the springs hold the shoes off the drum"))
        notes.append(f"{clutch.source}: ω₀ = {quantity_text(speed, 'rad/s')} is not above the engagement speed ω_e = {quantity_text(engage, 'rad/s')}: "
                     "the springs hold the shoes off the drum, and the clutch passes no torque")
    else:
        steps.append(Step(f"Force of each shoe on the drum at ω₀ (the {name})", "N = m·ω₀²·r − S",
                          f"{term(clutch.mass, 'kg')} × ({term(speed, 'rad/s')})² × {term(clutch.radius, 'm')} − {term(clutch.spring_force, 'N')}",
                          quantity_text(force, "N"),
                          "the clutch is read at the spider's speed ω₀, the speed given: the drum takes what each shoe's centrifugal force has left "
                          "over its spring's pull"))
    steps.append(Step(f"Torque the {name} passes", "τ = n·μ·N·R",
                      f"{clutch.shoes} × {fmt(clutch.mu)} × {term(force, 'N')} × {term(clutch.drum_radius, 'm')}", quantity_text(torque, "N*m"),
                      "each of the n shoes rubs the drum with the friction force μN at the drum's radius R"))
    steps.append(Step(f"Power the {name} passes", "P = τ·ω₀", f"{term(torque, 'N*m')} × {term(speed, 'rad/s')}", quantity_text(torque * speed, "W"),
                      "power is torque times angular speed (the spider's)"))
    if not alone:
        notes.append("torque_centrifugal: the torque the clutch passes at ω₀, reported beside the motion and not applied to it "
                     "(it drives the drum and loads the spider): give it as a {torque} of its own to the member it acts on, in a run of its own")
    return results, steps, notes


def with_centrifugal(command: Command) -> Callable[[Callable[..., Report]], Callable[..., Report]]:
    """A scene's solver that also reads a --centrifugal clutch at its ω₀: the clutch's results,
    steps and notes before the scene's own; the clutch alone (with no other input than ω₀)
    is a report of its own."""

    def wrap(solver: Callable[..., Report]) -> Callable[..., Report]:
        @functools.wraps(solver)
        def run(*, centrifugal: Sequence[Centrifugal] | Centrifugal | None = None, **arguments) -> Report:
            if not centrifugal:
                return solver(**arguments)
            clutch = centrifugal[0] if isinstance(centrifugal, (list, tuple)) else centrifugal
            alone = set(arguments) <= {"omega0"}
            report = None if alone else solver(**arguments)
            speed = arguments.get("omega0")
            if speed is None and report is not None and getattr(report.results.get("omega0"), "value", None) is not None:
                speed = report.results["omega0"].value  # ω₀ the scene found (from a rim speed, KE0)
            results, steps, notes = clutch_report(command, clutch, speed, alone)
            model = "centrifugal clutch N = mω²r − S, read at ω₀"
            if report is None:
                return Report(command.name, model, "closed form", results, steps, notes)
            results.update(report.results)
            return Report(report.scene, f"{report.model}; {model}", report.method, results, [*steps, *report.steps], [*notes, *report.notes],
                          report.inputs, report.tables, report.trajectory, report.needs)

        signature = inspect.signature(solver)
        keywords = [p for p in signature.parameters.values() if p.kind is not inspect.Parameter.VAR_KEYWORD]
        rest = [p for p in signature.parameters.values() if p.kind is inspect.Parameter.VAR_KEYWORD]
        clutch = inspect.Parameter("centrifugal", inspect.Parameter.KEYWORD_ONLY, default=None)
        run.__signature__ = signature.replace(parameters=[*keywords, clutch, *rest])  # the table's names, the clutch's among them
        return run

    return wrap
