"""Report, Value, Step, Table: the one contract between solvers and renderers.

A solver returns a Report and nothing else. Values are SI; ``unit`` is a string the unit parser
reads back ("kg*m**2", "N*m", "rad/s"). A result that does not exist is ``None`` with a note
(a NotApplicable one where the scene cannot have it: the human views leave its row out).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from functools import partial
from typing import NamedTuple

# How numbers and units are written (the solvers' steps import them from here)
from taucli.core.written import DIGITS as DIGITS, fmt as fmt, pretty_unit as pretty_unit, quantity_text as quantity_text, term as term
from taucli.core.written import printable

Number = float | bool | str | None


class Value(NamedTuple):
    """One named quantity: its SI value, unit and what it is.

    A NamedTuple rather than a frozen dataclass: as immutable, and a third of the cost to make,
    which counts in a batch of scenes (a dozen Values each).
    """

    value: Number
    unit: str | None
    label: str

    moot = False  # (not a field) True for a NotApplicable result: the human views leave its row out while it is null


# A Value made from its three fields as one tuple, in C (no Python frame, as a NamedTuple's __new__
# has): for the places that make several on every line of a batch (a result put, an input read).
made_value = partial(tuple.__new__, Value)


class NotApplicable(Value):
    """A result null only because the scene cannot have it: a wheel a drive keeps turning has no
    stop (t_stop, theta_stop, revs_stop), one that speeds up without bound no steady speed. JSON
    keeps it null (its key stable, a note saying why); the human views (the table, md, html,
    latex, a notebook) leave its row out, the note saying why in its stead (#42 item 23). A
    result null for another reason (an input it needs left out) is a plain Value: its row stays."""

    __slots__ = ()
    moot = True


@dataclass(frozen=True)
class Step:
    """One step of the worked solution, as the article writes it."""

    title: str
    equation: str
    numbers: str = ""  # the equation with the numbers substituted
    result: str = ""
    why: str = ""


class DeferredSteps(Sequence[Step]):
    """Worked steps written out when first read.

    Writing a step formats its numbers into text, which takes longer than the physics; a run
    that does not show the steps (``--no-steps``, a batch of scenes) never writes them. ``write``
    must read only values that do not change after the solver returns.
    """

    def __init__(self, write: Callable[..., Sequence[Step]], *args):
        self._write, self._args, self._steps = write, args, None

    def _written(self) -> list[Step]:
        if self._steps is None:
            self._steps = list(self._write(*self._args))
            self._args = ()
        return self._steps

    def __getitem__(self, index):
        return self._written()[index]

    def __len__(self) -> int:
        return len(self._written())


@dataclass(frozen=True)
class Table:
    """A small table of rows (the parts of a body, the points of a sweep)."""

    columns: tuple[tuple[str, str | None, str], ...]  # (key, unit, heading)
    rows: tuple[tuple[Number, ...], ...]


@dataclass(frozen=True)
class Trajectory:
    """How a scene evolves in time, for a plot: curves on [0, t_end] and the moments to mark.

    ``state(t)`` gives the value of each curve in ``curves`` at t, from the solver's own
    solution; a scene known only at samples (a torque profile) gives ``points`` instead.
    """

    curves: tuple[tuple[str, str, str], ...]  # (key, unit, label) of each curve
    t_end: float
    state: Callable[[float], tuple[float, ...]] | None = None
    points: tuple[tuple[float, ...], ...] = ()  # (t, *values) at known samples
    marks: tuple[tuple[float, str], ...] = ()  # (t, what happens then)
    note: str = ""  # how t_end was chosen, when the user did not say

    def sample(self, count: int) -> list[tuple[float, ...]]:
        """(t, *values) at ``count`` even times from 0 to t_end, and at each mark, in order."""
        if self.state is None:
            return [tuple(point) for point in self.points]
        times = {self.t_end * i / (count - 1) for i in range(count)}
        times.update(t for t, _ in self.marks if 0 <= t <= self.t_end)
        return [(t, *self.state(t)) for t in sorted(times)]


@dataclass
class Report:
    """What a solver found: the model it used, its results, the steps and the notes."""

    scene: str
    model: str
    method: str
    results: dict[str, Value]
    steps: list[Step] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    inputs: dict[str, Value] = field(default_factory=dict)
    tables: dict[str, Table] = field(default_factory=dict)
    trajectory: Callable[[], Trajectory] | None = None  # built when a plot asks for it (see deferred)
    needs: dict[str, tuple[str, str]] = field(default_factory=dict)  # a result left null for want of an input -> (its option, what it needs) (#42 item 14)
    chart: Callable[[], object] | None = None  # what --plot draws in place of the motion (an optimum's curve, #47 item 6), built when drawn

    # In Python and Jupyter (#36): a short repr, and the documents of --format md, html and latex.
    HEADLINES = 3  # results a repr names

    def __repr__(self) -> str:
        from taucli.writing.formats import sheet  # deferred: the writers, only when a report is shown in Python

        rows = [row for row in sheet(self, steps=False).results if row.value != "—"]
        named = ", ".join(f"{row.name} = {row.value} {pretty_unit(row.unit)}".rstrip() for row in rows[: self.HEADLINES])
        more = f", … ({len(rows) - self.HEADLINES} more)" if len(rows) > self.HEADLINES else ""
        return printable(f"<{type(self).__name__} {self.scene}: {self.model}; {named}{more}>")  # one line, no control character (#43)

    def _repr_markdown_(self) -> str:
        from taucli.writing.formats import markdown, sheet  # deferred: as in __repr__

        return markdown(sheet(self))

    def _repr_html_(self) -> str:
        from taucli.writing.formats import html_fragment, sheet  # deferred: as in __repr__

        return html_fragment(sheet(self))

    def plot(self):
        """The motion in time as a matplotlib Figure (#46 item 10): a panel per curve of the
        trajectory the scene gives --plot (spin-down: ω(t) and θ(t); atwood: x(t) and v(t); a
        pendulum: θ(t) and ω(t)), in SI, t in s, with its moments marked; where --plot draws
        something else (an optimum's result against its input), that. Needs matplotlib."""
        from taucli.writing.plot import figure, motion_figure  # deferred: the charts and matplotlib, only when one is drawn

        return figure(self.chart()) if self.chart is not None else motion_figure([("", self)])

    def _repr_latex_(self) -> str:
        from taucli.writing.formats import sheet  # deferred: as in __repr__
        from taucli.writing.latex import document

        return document(sheet(self))


@dataclass(repr=False)
class Measured(Report):
    """A report whose results carry standard uncertainties (SI, as the values): taucli.answering.propagate
    and taucli.answering.find make it; a renderer shows "uncertainty" beside "value"."""

    uncertainties: dict[str, float] = field(default_factory=dict)  # result key -> σ
    input_uncertainties: dict[str, float] = field(default_factory=dict)  # input name -> σ
    monte_carlo: dict[str, tuple[float, float]] = field(default_factory=dict)  # key -> (mean, σ)
    draws: int = 0


class deferred:
    """``build(*args, **kwargs)``, run when first called and kept: a trajectory's horizon may
    take an integration of its own, which a run that draws no plot must not pay for (or fail on).

    A class of its own rather than functools.cache(partial(...)): one of these is made on every
    run, batch lines included, and functools' wrapper costs several microseconds to make.
    """

    __slots__ = ("_build", "_args", "_kwargs", "_built")

    def __init__(self, build: Callable[..., Trajectory], *args, **kwargs):
        self._build, self._args, self._kwargs, self._built = build, args, kwargs, None

    def __call__(self) -> Trajectory:
        if self._built is None:
            self._built = self._build(*self._args, **self._kwargs)
            self._args, self._kwargs = (), {}
        return self._built
