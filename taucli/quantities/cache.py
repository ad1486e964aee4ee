"""What taucli keeps between runs: its cache folder and pint's SI factors.

A one-off run spends most of its time importing pint and loading its registry (~150 ms) to read
"4 kg". pint's answer for a unit text ("kg", "rpm", "N*m") never changes for one pint and one
taucli, so it is kept in ``units-*.json`` and pint is asked again only for a text not seen before.

Nothing here may cost an answer: a missing, unreadable, corrupt, stale or read-only cache is
ignored (and rewritten when it can be). Nor may it change one: the cache is a trust boundary
(the folder may be shared, or edited), so each file carries a checksum of its entries and of
what they were made from (taucli's rules, pint's version, a checksum of pint's definitions), and
a file that does not verify is not read. Every file is read with a size cap (MAX_FILE, MAX_CHECKED):
one past it, or one that is not a regular file (a link to /dev/zero, a FIFO), is not read but
rebuilt, so a cache costs time at most, never memory without end or a run that waits. The folder is ``$TAUCLI_CACHE_DIR`` if set (empty: keep
nothing), else ``$XDG_CACHE_HOME/taucli``, else the platform's user cache folder with ``taucli``
appended, in a home that exists.
"""

from __future__ import annotations

import importlib.util
import json
import os
import stat
import sys
import zlib  # not hashlib: its OpenSSL import costs 4 ms, and the file holds the full stamp
from functools import lru_cache

from taucli.core.version import __version__

MAX_ENTRIES = 512  # per store; beyond it, answers are worked out each time and not kept
MAX_FILE = 1024 * 1024  # bytes of a JSON file of the cache (512 entries are some 30 KB); a larger one is not read
MAX_CHECKED = 16 * 1024 * 1024  # bytes of a file whose checksum is taken (pint's pickles, some 150 KB); larger: no checksum


def _regular(path: str, limit: int) -> bool:
    """Whether ``path`` is a regular file of at most ``limit`` bytes (following a link): never a
    device (/dev/zero), a FIFO (which would wait for a writer) or a folder."""
    try:
        info = os.stat(path)
    except (OSError, ValueError, TypeError):
        return False
    return stat.S_ISREG(info.st_mode) and info.st_size <= limit


def small_text(path: str) -> str:
    """The UTF-8 text of the cache file ``path``, at most MAX_FILE bytes of it read; OSError where
    it is missing, not a regular file or larger (the caller ignores it and writes it afresh),
    ValueError where it is not UTF-8."""
    if not _regular(path, MAX_FILE):
        raise OSError(f"{path}: not a regular file of at most {MAX_FILE} bytes")
    with open(path, "rb") as handle:
        raw = handle.read(MAX_FILE + 1)  # (a file that grew since: still at most this)
    if len(raw) > MAX_FILE:
        raise OSError(f"{path}: larger than {MAX_FILE} bytes")
    return raw.decode("utf-8")


@lru_cache(maxsize=1)
def folder() -> str | None:
    """taucli's cache folder (not created here), or None when caching is turned off or there is
    no home to keep it in: ``$TAUCLI_CACHE_DIR``, else ``$XDG_CACHE_HOME/taucli`` (an absolute
    path), else the platform's cache folder in a home that exists (never one made up: ``HOME=``
    or ``HOME=/nonexistent`` keep nothing)."""
    chosen = os.environ.get("TAUCLI_CACHE_DIR")
    if chosen is not None:
        return chosen if chosen.strip() else None
    xdg = os.environ.get("XDG_CACHE_HOME", "")
    if sys.platform not in ("win32", "darwin") and os.path.isabs(xdg):
        return os.path.join(xdg, "taucli")
    if sys.platform == "win32" and os.environ.get("LOCALAPPDATA"):
        return os.path.join(os.environ["LOCALAPPDATA"], "taucli")
    home = os.path.expanduser("~")
    if not (os.path.isabs(home) and home != os.sep and os.path.isdir(home)):
        return None
    if sys.platform == "win32":
        base = os.path.join(home, "AppData", "Local")
    elif sys.platform == "darwin":
        base = os.path.join(home, "Library", "Caches")
    else:
        base = os.path.join(home, ".cache")
    return os.path.join(base, "taucli")


def made(path: str) -> bool:
    """Whether the folder ``path`` is there, made if need be: it, and its parent (~/.cache) where
    that is missing, but never a folder above (a home that does not exist stays so)."""
    if os.path.isdir(path):
        return True
    parent = os.path.dirname(path)
    try:
        if not os.path.isdir(parent):
            if not os.path.isdir(os.path.dirname(parent)):
                return False
            os.mkdir(parent, 0o700)
        os.mkdir(path, 0o700)
    except OSError:
        return os.path.isdir(path)
    return True


def checksum(*texts: str) -> str:
    """A checksum of ``texts`` (crc32, eight hex digits)."""
    value = 0
    for text in texts:
        value = zlib.crc32(text.encode("utf-8", "surrogatepass"), value)
    return f"{value:08x}"


def file_checksum(path: str | None) -> str:
    """The checksum of a file's content ("?" where it cannot be read, is not a regular file or is
    larger than MAX_CHECKED): pint's definitions, its pickles. Read a chunk at a time."""
    if not _regular(path, MAX_CHECKED):
        return "?"
    value = total = 0
    try:
        with open(path, "rb") as handle:
            while chunk := handle.read(1 << 20):
                total += len(chunk)
                if total > MAX_CHECKED:
                    return "?"
                value = zlib.crc32(chunk, value)
    except (OSError, TypeError):
        return "?"
    return f"{value:08x}"


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
        """The entries of the file, where its stamp is this one and its checksum verifies: an
        edited entry ("kg" as 2 kg) does not, and the store starts empty (rewritten as it fills)."""
        try:
            stored = json.loads(small_text(self.file), parse_constant=_no_constants)
            if isinstance(stored, dict) and stored.get("stamp") == self.stamp and isinstance(stored.get("entries"), dict):
                if stored.get("checksum") == _entries_checksum(self.stamp, stored["entries"]):
                    self.entries = dict(list(stored["entries"].items())[:MAX_ENTRIES])
        except (OSError, ValueError, TypeError, AttributeError, RecursionError):
            self.entries = {}

    def _save(self) -> None:
        if self.file is None:
            return
        folder_path, name = os.path.split(self.file)
        temporary = os.path.join(folder_path, f".{name}.{os.getpid()}")
        try:
            if not made(folder_path):
                return
            with open(temporary, "w", encoding="utf-8") as handle:
                json.dump({"stamp": self.stamp, "checksum": _entries_checksum(self.stamp, self.entries), "entries": self.entries}, handle, ensure_ascii=False)
            os.replace(temporary, self.file)
        except OSError:
            try:
                os.unlink(temporary)
            except OSError:
                pass


def checked_folder(path: str) -> bool:
    """Whether the folder ``path`` (pint's own cache of its parsed definitions, pickled) holds only
    files whose checksums match those taucli wrote down after pint last wrote there (``seal``);
    where it does not, its files are removed so that pint builds them afresh. False when the folder
    cannot be made or cleared: then pint is given no cache folder."""
    if not (made(os.path.dirname(path)) and made(path)):
        return False
    sums = _sums(path)
    try:
        # Every entry but a folder: a link to /dev/zero or a FIFO pint might open has no checksum ("?") and is removed.
        names = sorted(name for name in os.listdir(path) if not stat.S_ISDIR(os.lstat(os.path.join(path, name)).st_mode))
        if all(sums.get(name) == file_checksum(os.path.join(path, name)) for name in names):
            return True
        for name in names:
            os.unlink(os.path.join(path, name))
        os.unlink(path + ".sums")
    except FileNotFoundError:
        pass
    except OSError:
        return False
    return True


def seal(path: str) -> None:
    """Write down the checksum of each file in ``path``, for checked_folder."""
    try:
        sums = {name: file_checksum(os.path.join(path, name)) for name in sorted(os.listdir(path)) if os.path.isfile(os.path.join(path, name))}
        if sums == _sums(path):
            return
        temporary = f"{path}.sums.{os.getpid()}"
        with open(temporary, "w", encoding="utf-8") as handle:
            json.dump(sums, handle)
        os.replace(temporary, path + ".sums")
    except OSError:
        pass


def _sums(path: str) -> dict:
    try:
        sums = json.loads(small_text(path + ".sums"))
        return sums if isinstance(sums, dict) else {}
    except (OSError, ValueError, RecursionError):
        return {}


def _entries_checksum(stamp: str, entries: dict) -> str:
    return checksum(stamp, json.dumps(entries, sort_keys=True, ensure_ascii=False))


def _no_constants(name: str):
    raise ValueError(name)


# pint's answers for the units taucli's help, docs and kinds use, built when taucli is released
# and shipped in the package, so that a first run (an empty cache folder) reads "4 kg" without
# importing pint, as a warm run does. Used only for the exact rules and pint it was built with:
# the text of the modules that make a key and read a unit, and pint's version. Rebuilt by
# ``python -m taucli.quantities.shipped``; tests/quantities/test_first_run.py checks it is current and agrees with pint.
SHIPPED = "units-shipped.json"
RULES = ("units.py", "registry.py", "unit_text.py", "screen.py", "spellings.py", "kinds.py", "meanings.py")


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
    return Store(folder(), "units", _units_stamp)


def _units_stamp() -> str:
    """taucli's version and rules, pint's version, and a checksum of the definitions pint reads."""
    init = package_file("pint")
    definitions = [os.path.join(os.path.dirname(init), name) for name in ("default_en.txt", "constants_en.txt")] if init else []
    return "|".join([stamp(own_file("units.py"), own_file("registry.py"), init), f"pint {pint_version() or '?'}",
                     *(f"{os.path.basename(path)}:{file_checksum(path)}" for path in definitions)])
