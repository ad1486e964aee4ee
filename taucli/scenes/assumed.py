"""What a scene takes when the user does not say: the value, recorded as an input, and a note."""

from __future__ import annotations

from dataclasses import dataclass, field

from taucli.writing.report import Report, Value

STANDARD_GRAVITY = 9.80665  # m/s², the conventional value (CGPM 1901)
GRAVITY_NOTE = f"g = {STANDARD_GRAVITY} m/s² (standard gravity); --g to change it"  # written once: every run that takes g says it


@dataclass
class Assumed:
    """The values a scene assumed, each with the note that says so, to add to its report."""

    values: dict[str, Value] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)

    def value(self, name: str, value: float, unit: str, note: str) -> float:
        self.values[name] = Value(value, unit, "")
        self.notes.append(note)
        return value

    def gravity(self, g: float | None) -> float:
        """--g, or standard gravity with a note that says so."""
        if g is not None:
            return g
        return self.value("g", STANDARD_GRAVITY, "m/s**2", GRAVITY_NOTE)

    def applied(self, report: Report) -> Report:
        """The report with the assumed values among its inputs and their notes first."""
        if not self.values and not self.notes:
            return report
        report.notes = [*self.notes, *report.notes]  # in place: the report was made for this call alone
        report.inputs = {**report.inputs, **self.values}
        return report
