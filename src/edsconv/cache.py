"""A per-user disk cache for what is costly to compute at start-up.

The built schemas (:mod:`edsconv.xml.schemas`, pickled) and the grammar's terminal
patterns (:mod:`edsconv.eds.lexicon`, JSON) are kept here between processes. What
the cache holds decides how edsconv reads files (a pickle even runs code when it is
loaded), so a file is only read when nobody else could have put it there: the
directory is created 0o700 and must belong to the current user and not be group-
or world-writable; the file must belong to the current user, not be group- or
world-writable, and not be a symbolic link (checked on the opened descriptor).
On systems without ``os.getuid`` (Windows) the temp dir is already per-user and
the ownership checks are skipped. Any trouble reads as a miss and a failed write
only costs time later: callers then compute the value again.
"""

from __future__ import annotations

import contextlib
import os
import tempfile
from pathlib import Path


def cache_dir() -> Path:
    """``$XDG_CACHE_HOME/edsconv`` when that variable is set, else a per-user directory in the temp dir."""
    xdg = os.environ.get("XDG_CACHE_HOME")
    if xdg and os.path.isabs(xdg):
        return Path(xdg) / "edsconv"
    user = os.getuid() if hasattr(os, "getuid") else "user"
    return Path(tempfile.gettempdir()) / f"edsconv-{user}"


def _owned_and_private(status: os.stat_result) -> bool:
    if not hasattr(os, "getuid"):
        return True
    return status.st_uid == os.getuid() and not status.st_mode & 0o022


def trusted_dir(directory: Path) -> bool:
    """Create ``directory`` (0o700) if needed; True when it belongs to the current user alone."""
    try:
        os.makedirs(directory, mode=0o700, exist_ok=True)
        return _owned_and_private(os.stat(directory))
    except OSError:
        return False


def read_file(path: Path) -> bytes | None:
    """The content of a cache file; None when absent, unreadable or not trusted."""
    if not trusted_dir(path.parent):
        return None
    try:
        descriptor = os.open(path, os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_BINARY", 0))
    except OSError:
        return None
    try:
        with os.fdopen(descriptor, "rb") as stream:
            if not _owned_and_private(os.fstat(stream.fileno())):
                return None
            return stream.read()
    except OSError:
        return None


def write_file(path: Path, data: bytes) -> None:
    """Store atomically (a 0o600 temporary file renamed into place); failures are ignored."""
    if not trusted_dir(path.parent):
        return
    temporary = None
    try:
        with tempfile.NamedTemporaryFile("wb", dir=path.parent, prefix=".tmp-", delete=False) as stream:
            temporary = stream.name
            stream.write(data)
        os.replace(temporary, path)
    except OSError:  # read-only or full disk: the value is computed again next time
        if temporary is not None:
            with contextlib.suppress(OSError):
                os.unlink(temporary)


__all__ = ["cache_dir", "read_file", "trusted_dir", "write_file"]
