"""The commands that are not scenes: ``taucli bench``, ``taucli completions`` and ``taucli convert``."""

from __future__ import annotations

import json as encoder
import shutil

from taucli.front import bench as workbench
from taucli.front import completions as scripts
from taucli.core.errors import InputError
from taucli.core.names import SHELLS
from taucli.core.version import __version__
from taucli.core.written import fmt, pretty_unit
from taucli.options.tools import CONVERT_RESULTS


def bench(*, env, scene=None, quick: bool = False, out: str | None = None, json: bool = False) -> int:
    """Time per solve against error for every method, charted; see taucli.front.bench."""
    chosen = tuple(scene or workbench.SCENES)
    for name in chosen:
        if name not in workbench.SCENES:
            raise InputError("scene", f"expected one of {', '.join(workbench.SCENES)}", got=repr(name))
    if out is not None and not out.lower().endswith((".svg", ".png")):
        raise InputError("out", "expected a file name ending in .svg or .png", example="{out} chart.svg", got=repr(out))
    if out is not None:
        try:
            import matplotlib  # noqa: F401  # deferred: matplotlib, only asked whether it is there
        except ImportError:
            raise InputError("out", "needs matplotlib", hint="pip install 'taucli[plot]' (from a checkout: pip install '.[plot]')") from None
    points = workbench.run(chosen, quick=quick)
    if out is not None:
        workbench.write_image(points, out)
    if json:
        env.stdout.write(encoder.dumps(workbench.document(points), allow_nan=False) + "\n")
        return 0
    width = max(40, min(shutil.get_terminal_size((80, 24)).columns, 110))  # the terminal's width (a pipe: 80)
    for problem in dict.fromkeys(p.problem for p in points):
        env.stdout.write("\n".join(workbench.chart(points, problem, width=width)) + "\n\n")
    if out is not None:
        env.stdout.write(f"charts written to {out}\n")
    return 0


def completions(*, env, shell: str | None = None) -> int:
    """The completion script for SHELL, from the commands' tables."""
    if shell not in SHELLS:
        raise InputError("shell", f"expected one of {', '.join(SHELLS)}", example="taucli completions bash", got=None if shell is None else repr(shell))
    env.stdout.write(scripts.script(shell))
    return 0


def convert(*, env, quantity: str | None = None, unit: str | None = None, json: bool = False, get: list[str] | None = None) -> int:
    """QUANTITY in UNIT (else SI), with the notes of its reading: taucli.quantities.conversion."""
    from taucli.quantities.conversion import EXAMPLE, convert_quantity  # deferred: pint, only when converting

    if quantity is None:
        raise InputError("quantity", "is required: a number and its unit", example="taucli convert " + EXAMPLE)
    for name in get or ():
        if name not in CONVERT_RESULTS:
            raise InputError("get", f"expected one of {', '.join(CONVERT_RESULTS)}", example="{get} value", got=repr(name))
    if json and get:
        raise InputError("get", "does not combine with {json}: each writes the whole answer", example="{get} value")
    done = convert_quantity(quantity, unit)
    if json:
        document = {"taucli": __version__, "command": "convert", "given": done.given, "kind": done.kind, "value": done.value,
                    "unit": done.unit, "si": {"value": done.si_value, "unit": done.si_unit}, "notes": list(done.notes)}
        if done.uncertainty is not None:
            document.update(uncertainty=done.uncertainty)
            document["si"]["uncertainty"] = done.si_uncertainty
        env.stdout.write(encoder.dumps(document, ensure_ascii=False, allow_nan=False) + "\n")
        return 0
    if get:
        from taucli.writing.render import bare  # deferred: as the scenes' --get prints a number

        said = [getattr(done, name) for name in get]
        env.stdout.write(" ".join(value if isinstance(value, str) else bare(value) for value in said) + "\n")
        env.stderr.write("".join(f"taucli: note: {note}\n" for note in done.notes))
        return 0
    from taucli.quantities.measurement import with_uncertainty  # deferred: as above

    number = fmt(done.value) if done.uncertainty is None else with_uncertainty(done.value, done.uncertainty)
    env.stdout.write(f"{' '.join(quantity.split())} = {number} {pretty_unit(done.unit)}".rstrip() + f"  ({done.kind})\n")
    import textwrap  # deferred: as above

    width = max(40, shutil.get_terminal_size((80, 24)).columns)  # wrapped as the scenes' notes are
    env.stdout.write("".join(textwrap.fill(f"note: {note}", width, break_on_hyphens=False) + "\n" for note in done.notes))
    return 0
