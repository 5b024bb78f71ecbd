"""Reading paths: the one rule for which files a command given files and directories works on.

``edsconv lint`` and ``edsconv fmt`` (and the next command that takes directories) call
:func:`discover`; nothing else walks a directory. The rule:

- a path named on the command line that does not exist at all (not even as a dangling
  symbolic link) is a usage error (:func:`missing`, exit 2): a typo must not pass a CI job;
- a file named on the command line is taken whatever its suffix; one that cannot be read (a
  dangling link, no read permission) is taken too, and the command reports it and goes on;
- a directory is searched recursively for files ending in ``.eds`` in any letter case, in
  sorted order; symbolic links to directories are followed, each real directory searched
  once (a link loop ends there); a dangling link named ``*.eds`` is taken, never skipped;
- a directory search leaves out hidden directories (``.git``, ``.venv``, ``.tox`` ...),
  :data:`EXCLUDED_DIRECTORIES` and what the configuration's ``exclude`` matches; with
  ``force_exclude`` (``--force-exclude``, on in the pre-commit hook) the same applies to the
  files named on the command line. ``.gitignore`` is not read (see docs/lint.md, "Which files");
- a directory that cannot be searched (no permission) is returned in
  :attr:`Found.unsearchable`: the command reports it as it reports an unreadable file;
- a directory named on the command line in which nothing was found is returned in
  :attr:`Found.empty`, so that the command can name it;
- a file reached under several spellings (``d/x.eds``, ``d/../d/x.eds``, an absolute path, a
  link) is taken once, where it is first reached: its real path decides.
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path, PurePath
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from edsconv.config import Resolver

#: The suffix of the files a directory search takes, in any letter case.
EDS_SUFFIX = ".eds"
#: Directories a search leaves out besides hidden ones: other tools' environments and caches, which
#: hold copies of files that are not the project's own (ruff and eslint skip the same ones).
EXCLUDED_DIRECTORIES = frozenset({"node_modules", "venv", "site-packages", "__pypackages__", "__pycache__"})


@dataclass(slots=True)
class Found:
    """What :func:`discover` found."""

    #: the files, each once, in the order they were reached
    files: list[str] = field(default_factory=list)
    #: (directory, reason) for each directory that could not be searched
    unsearchable: list[tuple[str, str]] = field(default_factory=list)
    #: the directories named on the command line in which no EDS file was found
    empty: list[str] = field(default_factory=list)
    #: the files named on the command line that ``force_exclude`` left out
    excluded: list[str] = field(default_factory=list)


def missing(paths: Iterable[str | Path]) -> list[str]:
    """The paths that do not exist at all (a dangling symbolic link exists, and so does a path that cannot
    be looked at: both are reported when read)."""
    return [str(path) for path in paths if not _exists(path)]


def _exists(path: str | Path) -> bool:
    try:
        os.lstat(path)
    except (FileNotFoundError, NotADirectoryError):
        return False
    except OSError:
        return True
    return True


def discover(paths: Iterable[str | Path], resolver: Resolver | None = None, *,
             force_exclude: bool = False) -> Found:
    """The files below ``paths`` by the rule of this module's docstring."""
    found = Found()
    seen: set[str] = set()
    for path in map(Path, paths):
        if _is_named_directory(path):
            unsearchable = len(found.unsearchable)
            below = _search(path, resolver, found.unsearchable)
            if not below and not found.unsearchable[unsearchable:]:
                found.empty.append(str(path))
        elif force_exclude and _named_file_excluded(path, resolver):
            found.excluded.append(str(path))
            continue
        else:
            below = [str(path)]
        for name in below:
            real = os.path.realpath(name)
            if real not in seen:
                seen.add(real)
                found.files.append(name)
    return found


def _is_named_directory(path: Path) -> bool:
    try:
        return path.is_dir()
    except OSError:  # below a directory that cannot be searched: taken as a file, reported when read
        return False


def _search(directory: Path, resolver: Resolver | None, unsearchable: list[tuple[str, str]]) -> list[str]:
    """The EDS files below ``directory``, sorted, following links to directories once each."""
    files: list[str] = []
    visited: set[tuple[int, int]] = set()
    pending = [directory]
    while pending:
        current = pending.pop()
        try:
            status = os.stat(current)
            if (status.st_dev, status.st_ino) in visited:
                continue  # reached again through a link: a loop, or a directory already searched
            visited.add((status.st_dev, status.st_ino))
            with os.scandir(current) as scan:
                entries = list(scan)
        except OSError as error:
            unsearchable.append((str(current), error.strerror or str(error)))
            continue
        for entry in entries:
            path = Path(entry.path)
            if _is_directory(entry):
                if not _default_excluded(entry.name) and not _configured_exclude(path, resolver):
                    pending.append(path)
            elif _is_eds(entry) and not _configured_exclude(path, resolver):
                files.append(entry.path)
    return sorted(files)


def _is_directory(entry: os.DirEntry) -> bool:
    try:
        return entry.is_dir()  # follows a symbolic link
    except OSError:
        return False


def _is_eds(entry: os.DirEntry) -> bool:
    if not entry.name.lower().endswith(EDS_SUFFIX):
        return False
    try:
        return entry.is_file() or (entry.is_symlink() and not os.path.exists(entry.path))
    except OSError:
        return False


def _configured_exclude(path: Path, resolver: Resolver | None) -> bool:
    return resolver is not None and resolver.settings_for(path).excludes(path)


def _named_file_excluded(path: Path, resolver: Resolver | None) -> bool:
    """``--force-exclude``: a named file a search would leave out, because the configuration's ``exclude``
    matches it or it lies in a hidden or tool directory below the configuration's directory."""
    if resolver is None:
        return False
    settings = resolver.settings_for(path)
    return any(_default_excluded(part) for part in _relative_parts(path, settings.root)[:-1]) or \
        settings.excludes(path)


def _default_excluded(name: str) -> bool:
    return (name.startswith(".") and name not in (".", "..")) or name in EXCLUDED_DIRECTORIES


def _relative_parts(path: Path, root: Path) -> tuple[str, ...]:
    """The parts of ``path`` below ``root``; none when it does not lie below it."""
    try:
        return PurePath(os.path.abspath(path)).relative_to(os.path.abspath(root)).parts
    except ValueError:
        return ()
