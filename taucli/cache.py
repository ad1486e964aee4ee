"""What taucli keeps between runs: its cache folder and pint's SI factors.

A one-off run spends most of its time importing pint and loading its registry (~150 ms) to read
"4 kg". pint's answer for a unit text ("kg", "rpm", "N*m") never changes for one pint and one
taucli, so it is kept in ``units-*.json`` and pint is asked again only for a text not seen before.

Nothing here may cost an answer: a missing, unreadable, corrupt, stale or read-only cache is
ignored (and rewritten when it can be). The folder is ``$TAUCLI_CACHE_DIR`` if set (empty: keep
nothing), else the platform's user cache folder with ``taucli`` appended.
"""

from __future__ import annotations

import importlib.util
import json
import os
import sys
import zlib  # not hashlib: its OpenSSL import costs 4 ms, and the file holds the full stamp
from functools import lru_cache

from taucli.version import __version__

MAX_ENTRIES = 512  # per store; beyond it, answers are worked out each time and not kept


@lru_cache(maxsize=1)
def folder() -> str | None:
    """taucli's cache folder (not created here), or None when caching is turned off."""
    chosen = os.environ.get("TAUCLI_CACHE_DIR")
    if chosen is not None:
        return chosen if chosen.strip() else None
    home = os.path.expanduser("~")
    if sys.platform == "win32":
        base = os.environ.get("LOCALAPPDATA") or os.path.join(home, "AppData", "Local")
    elif sys.platform == "darwin":
        base = os.path.join(home, "Library", "Caches")
    else:
        base = os.environ.get("XDG_CACHE_HOME") or os.path.join(home, ".cache")
    return os.path.join(base, "taucli")


def stamp(*origins: str | None) -> str:
    """What stored answers depend on: taucli's version, and the size and time of each file."""
    parts = [__version__]
    for origin in origins:
        try:
            info = os.stat(origin)
            parts.append(f"{origin}:{info.st_mtime_ns}:{info.st_size}")
        except (OSError, TypeError):
            parts.append("?")
    return "|".join(parts)


def package_file(name: str) -> str | None:
    """The file a package is imported from (found, not imported): pint's __init__.py."""
    try:
        return getattr(importlib.util.find_spec(name), "origin", None)
    except (ImportError, ValueError):
        return None


def own_file(name: str) -> str:
    return os.path.join(os.path.dirname(__file__), name)


class Store:
    """A small JSON file of key -> value in the cache folder, valid for one stamp only.

    ``depends_on`` gives the stamp, which names the file (``units-1a2b3c4d.json``): two
    environments with different pint or taucli share the folder without evicting each other.
    The name is only a hash: the stamp inside the file is what is checked.
    It is called only when a store is first used, so a process that never uses one pays nothing.
    """

    def __init__(self, path: str | None, name: str, depends_on):
        self.entries: dict[str, object] = {}
        self.stamp = depends_on() if path is not None else ""
        digest = f"{zlib.crc32(self.stamp.encode()):08x}"
        self.file = None if path is None else os.path.join(path, f"{name}-{digest}.json")
        if self.file is not None:
            self._load()

    def get(self, key: str):
        return self.entries.get(key)

    def put(self, key: str, value) -> None:
        if len(self.entries) >= MAX_ENTRIES:
            return
        self.entries[key] = value
        self._save()

    def _load(self) -> None:
        try:
            with open(self.file, encoding="utf-8") as handle:
                stored = json.load(handle, parse_constant=_no_constants)
            if isinstance(stored, dict) and stored.get("stamp") == self.stamp and isinstance(stored.get("entries"), dict):
                self.entries = dict(list(stored["entries"].items())[:MAX_ENTRIES])
        except (OSError, ValueError, TypeError, AttributeError):
            self.entries = {}

    def _save(self) -> None:
        if self.file is None:
            return
        folder_path, name = os.path.split(self.file)
        temporary = os.path.join(folder_path, f".{name}.{os.getpid()}")
        try:
            os.makedirs(folder_path, exist_ok=True)
            with open(temporary, "w", encoding="utf-8") as handle:
                json.dump({"stamp": self.stamp, "entries": self.entries}, handle, ensure_ascii=False)
            os.replace(temporary, self.file)
        except OSError:
            try:
                os.unlink(temporary)
            except OSError:
                pass


def _no_constants(name: str):
    raise ValueError(name)


# pint's answers for the units taucli's help, docs and kinds use, built when taucli is released
# and shipped in the package, so that a first run (an empty cache folder) reads "4 kg" without
# importing pint, as a warm run does. Used only for the exact rules and pint it was built with:
# the text of the modules that make a key and read a unit, and pint's version. Rebuilt by
# ``python -m taucli.cache``; tests/test_first_run.py checks it is current and agrees with pint.
SHIPPED = "units-shipped.json"
RULES = ("units.py", "registry.py", "screen.py", "spellings.py", "kinds.py")


def pint_version() -> str | None:
    """The installed pint's version, from its dist-info folder's name (importlib.metadata costs
    tens of milliseconds), or None where it cannot be found that way."""
    origin = package_file("pint")
    if origin is None:
        return None
    site = os.path.dirname(os.path.dirname(origin))
    try:
        names = os.listdir(site)
    except OSError:
        return None
    found = [name[5:-10] for name in names if name.startswith("pint-") and name.endswith(".dist-info")]
    return found[0] if len(found) == 1 else None


def rules_stamp() -> str:
    """What the shipped factors hold for: the text of taucli's reading rules, and pint's version."""
    parts = []
    for name in RULES:
        try:
            with open(own_file(name), "rb") as handle:
                parts.append(f"{name}:{zlib.crc32(handle.read()):08x}")
        except OSError:
            parts.append(f"{name}:?")
    return "|".join([*parts, f"pint {pint_version()}"])


@lru_cache(maxsize=1)
def shipped_unit_factors() -> dict:
    """The factors shipped in the package (key -> [SI factor, how]), or {} where they do not hold
    for these rules and this pint, or cannot be read."""
    try:
        with open(own_file(SHIPPED), encoding="utf-8") as handle:
            stored = json.load(handle, parse_constant=_no_constants)
    except (OSError, ValueError):
        return {}
    if not isinstance(stored, dict) or not isinstance(stored.get("entries"), dict) or stored.get("stamp") != rules_stamp():
        return {}
    return stored["entries"]


@lru_cache(maxsize=1)
def unit_factors() -> Store:
    """(unit text, kind) -> [SI factor, how it was read]: pint's answers under taucli's rules, for
    this pint and this units.py and registry.py (which holds the rules)."""
    return Store(folder(), "units", lambda: stamp(own_file("units.py"), own_file("registry.py"), package_file("pint")))


def build_shipped(texts: dict[str, list[str]]) -> dict:
    """The shipped table: pint's answer, under taucli's rules, for each unit text of each kind
    in ``texts`` (kind name -> unit texts) that reads as that kind; texts that do not are left out."""
    from taucli import units  # deferred: only when the table is built (units imports this module)

    entries: dict[str, object] = {}
    for kind_name, unit_texts in texts.items():
        for text in unit_texts:
            key_and_factor = units.factor_entry(f"1 {text}", kind_name)
            if key_and_factor is not None:
                entries[key_and_factor[0]] = key_and_factor[1]
    return {"stamp": rules_stamp(), "entries": dict(sorted(entries.items()))}


# Unit texts the shipped table holds for every kind they read as: each kind's common units, these,
# and every unit in README's and docs/'s examples (when built from a checkout).
COMMON_TEXTS = (
    "kg g mg lb lbs oz tonne t slug m cm mm km um µm in ft yd mi inch deg rad rev ° degree degrees turn "
    "s ms us min h hr sec rad/s rpm RPM rev/s rev/min rps deg/s Hz min^-1 1/min rad/s^2 rad/s**2 rpm/s "
    "rev/s^2 rev/min^2 deg/s^2 N*m N·m Nm N.m N-m mN*m mNm kN*m kNm lbf*ft lbf*in ft*lbf ft-lb ft-lbf lb-ft "
    "in-lb lb*ft lb*in in*lbf oz*in ozf*in kg*m^2 kg*m**2 kg·m² kgm^2 kgm2 g*cm^2 kg*cm^2 g*mm^2 lb*ft^2 lb*in^2 "
    "slug*ft^2 lb*in*s^2 lbf*in*s^2 oz*in^2 N kN mN lbf kgf lb-f m/s^2 m/s**2 m/s² cm/s^2 ft/s^2 g0 gravity m/s km/h "
    "kph ft/s mph cm/s mm/s N*m*s N*m*s^2 N*m*s**2 N*m/(rad/s) W kW MW mW hp J kJ MJ mJ kW*h kWh Wh cal kcal "
    "kg/m^3 g/cm^3 lb/ft^3 lb/in^3 kg/m^2 kg/m g/cm^2 N*m/rad N*m/deg mN*m/rad Nm/rad mm/rev in/rev"
).split()


def _document_units(root: str) -> set[str]:
    """The unit of every value typed in README's and docs/'s commands (a checkout's, if there)."""
    import glob  # deferred: only when the table is built
    import re
    import shlex

    found: set[str] = set()
    for path in [os.path.join(root, "README.md"), *glob.glob(os.path.join(root, "docs", "*.md"))]:
        try:
            with open(path, encoding="utf-8") as handle:
                text = handle.read()
        except OSError:
            continue
        for line in re.findall(r"^\$ (taucli .*)$", text, re.M):
            try:
                words = shlex.split(line)
            except ValueError:
                continue
            for word in words:
                for piece in re.split(r"\.\.|,|\s+|=|\+/-", word):
                    unit = re.sub(r"^[-+]?(\d+\.?\d*|\.\d+)(e[-+]?\d+)?", "", piece.strip())
                    if unit and unit != piece.strip() and len(unit) < 20:
                        found.add(unit)
    return found


def main() -> None:
    """Rebuild the shipped table (taucli/units-shipped.json) from pint, in a checkout."""
    from taucli.kinds import KINDS  # deferred: only when the table is built

    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    texts = sorted({*COMMON_TEXTS, *_document_units(root), *(unit for kind in KINDS.values() for unit in kind.common_units)})
    table = build_shipped({name: texts for name in KINDS})
    with open(own_file(SHIPPED), "w", encoding="utf-8") as handle:
        entries = ",\n".join(f"{json.dumps(key, ensure_ascii=False)}: {json.dumps(value)}" for key, value in table["entries"].items())
        handle.write(f'{{"stamp": {json.dumps(table["stamp"])},\n"entries": {{\n{entries}\n}}}}\n')
    print(f"{own_file(SHIPPED)}: {len(table['entries'])} unit factors for {table['stamp']}")


if __name__ == "__main__":
    main()
