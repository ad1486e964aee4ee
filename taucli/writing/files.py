"""Files an answer writes beside itself (--out's chart, fit's --residuals): checked before the work,
so that one that cannot be written is refused before any answer, and written whole or not at all.

``check`` refuses a name without the suffix asked for, a symbolic link, a folder, and a folder that
cannot be written (tried with a temporary file of its own: nothing is made or removed at the path).
``replace_atomically`` writes a temporary file beside the path and renames it onto the path in one
step: a reader sees the old file or the whole new one, a failed write (a full disk) leaves the path
as it was, and a link made at the path meanwhile is replaced, never followed.
"""

from __future__ import annotations

import os
import stat
import tempfile
from collections.abc import Sequence

from taucli.core.errors import InputError


def check(path: str, option: str, suffixes: Sequence[str], example: str) -> None:
    """``path`` names a file ending in one of ``suffixes`` (".csv") with a name before it, not a link
    or a folder, in a folder that can be written; else a usage error of ``option`` (--out)."""
    folder, name = os.path.split(path)
    suffix = next((end for end in suffixes if name.lower().endswith(end)), None)
    if suffix is None:
        endings = " or ".join(suffixes)
        raise InputError(option, f"expected a file name ending in {endings}", example=example, got=repr(path))
    if len(name) == len(suffix):  # ".svg" alone: a suffix with no name (it was written as .svg.png)
        raise InputError(option, f"expected a name before {name}", example=example.rsplit(".", 1)[0] + name, got=repr(path))
    if os.path.islink(path):
        raise InputError(option, "expected a file, not a symbolic link: taucli does not write through links", example=example,
                         got=f"{path!r} -> {os.readlink(path)!r}")
    if os.path.isdir(path):
        raise InputError(option, "expected a file, not a folder", example=example, got=repr(path))
    try:
        handle, temporary = tempfile.mkstemp(prefix=f".{name}.", suffix=".tmp", dir=folder or ".")
    except OSError as err:
        raise unwritable(path, err, option, example) from None
    os.close(handle)
    os.unlink(temporary)


def unwritable(path: str, err: OSError, option: str, example: str) -> InputError:
    return InputError(option, "expected a file that can be written", example=example, got=f"{path!r}: {err.strerror or err}")


def replace_atomically(path: str, write, option: str, example: str) -> None:
    """``write(temporary)`` a file beside ``path``, then rename it onto ``path`` in one step."""
    folder, name = os.path.split(path)
    try:
        handle, temporary = tempfile.mkstemp(prefix=f".{name}.", suffix=".tmp", dir=folder or ".")
    except OSError as err:
        raise unwritable(path, err, option, example) from None
    os.close(handle)
    try:
        write(temporary)
        os.chmod(temporary, _new_file_mode(path))
        os.replace(temporary, path)
    except OSError as err:
        _remove(temporary)
        raise unwritable(path, err, option, example) from None
    except BaseException:
        _remove(temporary)
        raise


def _new_file_mode(path: str) -> int:
    """The mode a file written at ``path`` would have: an existing file's, else 0666 less the umask
    (mkstemp makes its files 0600)."""
    try:
        info = os.lstat(path)
        if stat.S_ISREG(info.st_mode):
            return stat.S_IMODE(info.st_mode)
    except OSError:
        pass
    umask = os.umask(0)
    os.umask(umask)
    return 0o666 & ~umask


def _remove(path: str) -> None:
    try:
        os.unlink(path)
    except OSError:
        pass
