"""The commands that are not scenes: ``taucli bench`` and ``taucli completions``."""

from __future__ import annotations

import json as encoder
import shutil

from taucli.front import bench as workbench
from taucli.front import completions as scripts
from taucli.core.errors import InputError
from taucli.core.names import SHELLS


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
