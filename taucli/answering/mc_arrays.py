"""--mc on arrays (#45 item 4): all the draws of a closed-form scene solved at once with numpy.

taucli.answering.propagate.monte_carlo draws N sets of inputs and, by default, solves the scene
once a draw (``pipeline.solve``: reading, the model, the report; about 80 µs for spin-down, so
10⁵ draws took 8 s). Where the scene has an array form (FORMS: a module's ``drawn(arguments)``,
beside the scene's own solver, written from the same closed forms) and numpy is importable, the
same draws, in the same order from the same seeded generator, go through it as arrays at once.

Held to the scene, as taucli.fit.arrays holds the fit's: the form says each draw's regime (the
scene's results differ between them: a stop or none, held or moving) and which draws it takes;
of each regime present, HELD draws (the first, the middle, the last) are solved by the scene
itself, and its numeric results there must be the form's (the same names; each within AGREE,
relative), else every draw of that regime is the scene's to solve. The draws the form does not
take are solved one by one, as before, under the same time budget (Scene.plan). The anchors'
own answers stand in their places.
"""

from __future__ import annotations

import importlib
import math
from collections.abc import Mapping

import numpy as np

from taucli.answering.inputs import read

FORMS = {"spin-down": "taucli.scenes.spin.arrays", "atwood": "taucli.scenes.atwood.arrays", "rolling": "taucli.scenes.rolling.arrays",
         "pendulum": "taucli.scenes.pendulum.arrays"}
AGREE = 1e-9  # the anchors' relative difference past which a regime is not taken from the arrays (they agree to about 1e-15)
HELD = 3  # draws of each regime solved by the scene itself


def solved(scene, columns: Mapping[str, list[float]], draws: int) -> tuple[dict[str, np.ndarray], np.ndarray] | None:
    """Each numeric result of each draw (NaN where the scene gives none) and the draws that gave
    no scene, or None where the scene has no array form for these options (the scalar path)."""
    module = FORMS.get(scene.command.name)
    if module is None or scene.unknowns:
        return None
    try:
        arguments, _ = read(scene.command, scene.given, stdin=scene.stdin)
    except Exception:  # noqa: BLE001 (the nominal solve read them: a reading that fails here is the scalar path's to give)
        return None
    if not columns.keys() <= {name for name, value in arguments.items() if isinstance(value, float)}:
        return None
    drawn = {name: np.asarray(values, dtype=float) for name, values in columns.items()}
    try:
        with np.errstate(all="ignore"):  # (a draw the form cannot take is NaN, and left to the scene)
            found = importlib.import_module(module).drawn({**arguments, **drawn})
    except Exception:  # noqa: BLE001 (a form that fails, whatever the reason: the scalar path, as before)
        return None
    if found is None:
        return None
    results, regime, taken = found
    # a result or regime no drawn input moves comes back as one number: one per draw (--mc with no σ given, a result of g alone)
    results = {key: np.array(np.broadcast_to(np.asarray(values, dtype=float), (draws,))) for key, values in results.items()}
    regime, taken = np.broadcast_to(np.asarray(regime), (draws,)), np.broadcast_to(np.asarray(taken, dtype=bool), (draws,))
    alone = ~taken  # the draws the scene solves one by one
    anchors = [(kind, int(i)) for kind in np.unique(regime[taken]) for i in _held(np.flatnonzero(taken & (regime == kind)))]
    failed = np.zeros(draws, dtype=bool)
    scene.plan(len(anchors), "mc")
    for kind, i in anchors:
        own = scene.results(_row(columns, i))
        if own is None or not _agrees(own, results, i):
            alone |= taken & (regime == kind)
        _put(results, failed, i, own)
    anchored = {i for _, i in anchors}
    rest = [int(i) for i in np.flatnonzero(alone) if int(i) not in anchored]
    scene.plan(len(rest), "mc")
    for i in rest:
        _put(results, failed, i, scene.results(_row(columns, i)))
    return results, failed


def summaries(results: Mapping[str, np.ndarray], failed: np.ndarray, keys) -> dict[str, tuple[float, float]]:
    """(mean, standard deviation) of each result in ``keys`` that two or more draws give: the mean
    as statistics.fmean gives it (a correctly rounded sum), σ = √(Σ(x − mean)²/(n − 1)) with the
    rounding of the mean taken back out (statistics.stdev's, to rounding)."""
    found = {}
    for key in keys:
        values = results.get(key)
        if values is None:
            continue
        values = values[~failed & np.isfinite(values)]
        if len(values) < 2:
            continue
        mean = math.fsum(values.tolist()) / len(values)
        deviations = values - mean
        squares = float(np.dot(deviations, deviations)) - float(np.sum(deviations)) ** 2 / len(values)
        found[key] = (mean, math.sqrt(max(squares, 0.0) / (len(values) - 1)))
    return found


def _held(indices: np.ndarray) -> list[int]:
    """The draws of a regime its anchors are: the first, the middle and the last (HELD at most)."""
    picked = dict.fromkeys(int(indices[j]) for j in (0, len(indices) // 2, len(indices) - 1))
    return list(picked)[:HELD]


def _row(columns: Mapping[str, list[float]], i: int) -> dict[str, float]:
    return {name: values[i] for name, values in columns.items()}


def _agrees(own: Mapping[str, float], results: Mapping[str, np.ndarray], i: int) -> bool:
    given = {key for key, values in results.items() if math.isfinite(values[i])}
    if set(own) != given:
        return False
    return all(abs(own[key] - float(results[key][i])) <= AGREE * max(abs(own[key]), abs(float(results[key][i]))) for key in own)


def _put(results: dict[str, np.ndarray], failed: np.ndarray, i: int, own: Mapping[str, float] | None) -> None:
    """The scene's own answer for draw i in its place (None: the scene refused it)."""
    if own is None:
        failed[i] = True
        return
    for key, values in results.items():
        values[i] = own.get(key, math.nan)
    for key in own.keys() - results.keys():
        results[key] = np.full(len(failed), math.nan)
        results[key][i] = own[key]
