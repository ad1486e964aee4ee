"""A sweep from Python: one keyword given a list of values, one Report per value (#46 item 10).

``taucli.atwood(m1="4 kg", m2=["0.5 kg", "1 kg", "2 kg"])`` returns a Sweep: a sequence of the
Reports that ``taucli.atwood(m1="4 kg", m2=x)`` returns for each x, in order. ``to_pandas()``
gives a DataFrame (pandas is imported then, and only then) with one row per report: the swept
keyword's value in SI, then each result's value in SI; ``frame.attrs["units"]`` names each
column's unit (None for a pure number or a flag). A result a row does not have is NaN (None
in a column of flags or texts).
"""

from __future__ import annotations

from collections.abc import Sequence

from taucli.writing.report import Report


class Sweep(Sequence[Report]):
    """The reports of one scene with one keyword, ``name``, taking each of ``values`` in turn."""

    def __init__(self, scene: str, name: str, values: Sequence, reports: Sequence[Report]):
        self.scene, self.name = scene, name
        self.values = tuple(values)  # as given: texts with units, or SI numbers
        self.rows = tuple(reports)

    def __getitem__(self, index):
        return self.rows[index]

    def __len__(self) -> int:
        return len(self.rows)

    def __repr__(self) -> str:
        return f"<Sweep {self.scene} over {self.name}: {len(self.rows)} reports, {', '.join(map(repr, self.values[:3]))}{', …' if len(self.values) > 3 else ''}>"

    def columns(self) -> tuple[list[str], dict[str, str | None]]:
        """The columns of ``to_pandas`` in order (the swept keyword, then every result any row
        has, in the order they first come), and each one's SI unit."""
        units: dict[str, str | None] = {}
        given = self.name if all(self.name not in report.results for report in self.rows) else self.name + " (given)"
        units[given] = next((report.inputs[self.name].unit for report in self.rows if self.name in report.inputs), None)
        for report in self.rows:
            for key, value in report.results.items():
                units.setdefault(key, value.unit)
        return list(units), units

    def records(self) -> list[dict]:
        """One dict per report: the column's name -> its value in SI (None where a row has none)."""
        names, _ = self.columns()
        records = []
        for value, report in zip(self.values, self.rows):
            echoed = report.inputs.get(self.name)
            row = {names[0]: echoed.value if echoed is not None else value}
            row.update((key, report.results[key].value if key in report.results else None) for key in names[1:])
            records.append(row)
        return records

    def plot(self):
        """The motion in time of every report, one curve per value, as a matplotlib Figure
        (report.plot() with the runs overlaid, as --plot draws a list on the command line)."""
        from taucli.writing.plot import motion_figure  # deferred: the charts and matplotlib, only when one is drawn

        return motion_figure([(f"{self.name} = {value}", report) for value, report in zip(self.values, self.rows)])

    def to_pandas(self):
        """A pandas DataFrame: one row per report, the swept keyword then the results, in SI;
        ``.attrs["units"]`` the unit of each column."""
        try:
            import pandas  # deferred: pandas, only when a sweep is made into a frame
        except ImportError:
            raise ImportError("Sweep.to_pandas() needs pandas: pip install pandas (or use Sweep.records(), a list of dicts)") from None
        names, units = self.columns()
        frame = pandas.DataFrame(self.records(), columns=names)
        frame.attrs["units"] = units
        return frame
