"""What taucli keeps between runs: its cache folder, and the SI factors pint gave for unit texts.

A one-off run spends most of its time importing pint and loading its registry (~150 ms) to read
"4 kg". pint's answer for a unit text ("kg", "rpm", "N*m") never changes for one pint and one
taucli, so it is kept in ``units.json`` and pint is asked again only for a text not seen before.

Nothing here may cost an answer: a missing, unreadable, corrupt, stale or read-only cache is
ignored (and rewritten when it can be). The folder is ``$TAUCLI_CACHE_DIR`` if set (empty: keep
nothing), else the platform's user cache folder with ``taucli`` appended.
"""

from __future__ import annotations

import json
import math
import os
import sys
from functools import lru_cache
from pathlib import Path

MAX_ENTRIES = 512  # unit texts kept, in memory and on disk; the rest are read by pint each time
FILE_NAME = "units.json"


@lru_cache(maxsize=1)
def folder() -> Path | None:
    """taucli's cache folder (not created here), or None when caching is turned off."""
    chosen = os.environ.get("TAUCLI_CACHE_DIR")
    if chosen is not None:
        return Path(chosen) if chosen.strip() else None
    if sys.platform == "win32":
        base = os.environ.get("LOCALAPPDATA") or str(Path.home() / "AppData" / "Local")
    elif sys.platform == "darwin":
        base = str(Path.home() / "Library" / "Caches")
    else:
        base = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(base) / "taucli"


def _stamp() -> str:
    """What the stored factors depend on: taucli's version and units.py, and the pint installed."""
    import importlib.util

    from taucli import __version__

    parts = [__version__]
    for origin in (os.path.join(os.path.dirname(__file__), "units.py"), getattr(importlib.util.find_spec("pint"), "origin", None)):
        try:
            info = os.stat(origin)
            parts.append(f"{origin}:{info.st_mtime_ns}:{info.st_size}")
        except (OSError, TypeError):
            parts.append("?")
    return "|".join(parts)


class UnitFactors:
    """(unit text, kind) -> (SI factor, power of Hz in the text): pint's answers, remembered."""

    def __init__(self, path: Path | None):
        self.path = path
        self.entries: dict[str, list[float]] = {}
        self.stamp = ""
        if path is not None:
            self._load()

    @staticmethod
    def key(unit_text: str, kind: str) -> str:
        return f"{kind}|{unit_text}"

    def get(self, unit_text: str, kind: str) -> tuple[float, int] | None:
        found = self.entries.get(self.key(unit_text, kind))
        return None if found is None else (found[0], int(found[1]))

    def put(self, unit_text: str, kind: str, factor: float, hertz_power: int) -> None:
        if len(self.entries) >= MAX_ENTRIES:
            return
        self.entries[self.key(unit_text, kind)] = [factor, hertz_power]
        self._save()

    def _load(self) -> None:
        try:
            with open(self.path / FILE_NAME, encoding="utf-8") as handle:
                stored = json.load(handle)
            self.stamp = _stamp()
            if not isinstance(stored, dict) or stored.get("stamp") != self.stamp:
                return
            entries = stored.get("units", {})
            self.entries = {
                key: [float(value[0]), int(value[1])]
                for key, value in list(entries.items())[:MAX_ENTRIES]
                if isinstance(key, str) and isinstance(value, list) and len(value) == 2 and isinstance(value[0], float) and math.isfinite(value[0]) and isinstance(value[1], int)
            }
        except (OSError, ValueError, TypeError, AttributeError):
            self.entries = {}

    def _save(self) -> None:
        if self.path is None:
            return
        temporary = self.path / f".{FILE_NAME}.{os.getpid()}"
        try:
            self.path.mkdir(parents=True, exist_ok=True)
            with open(temporary, "w", encoding="utf-8") as handle:
                json.dump({"stamp": self.stamp or _stamp(), "units": self.entries}, handle)
            os.replace(temporary, self.path / FILE_NAME)
        except OSError:
            try:
                temporary.unlink()
            except OSError:
                pass


@lru_cache(maxsize=1)
def unit_factors() -> UnitFactors:
    """The factors for this process, loaded from disk once."""
    return UnitFactors(folder())
