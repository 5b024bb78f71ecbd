"""Output files written whole or not at all, with the modes a user expects.

This module is the one rule for writing files. Every file edsconv writes (``eds2xml``'s two
profiles, ``xml2eds -o``, ``merge -o``, ``show --icon``) goes through :func:`write_all_atomically`,
and the files ``fmt`` and ``lint --fix`` rewrite go through :func:`rewrite_in_place`:

- an output file is never one of the command's inputs (under any name, ``--force`` or not), and an
  existing file is replaced only with ``--force`` (:class:`Refused`, before anything is written);
- each file is first written completely, and flushed to disk, as a temporary
  ``.NAME.XXXX.tmp`` beside its target; only when every temporary file is
  complete are they renamed over their targets, one after another, with SIGINT,
  SIGTERM and SIGHUP held back (so a signal comes either before the first rename,
  and nothing is written, or after the last);
- any failure or signal before the renames removes the temporary files (with the signals held
  back, so that a second signal cannot cut that short);
- a new file gets the mode the umask gives (``0o666 & ~umask``), a replaced file
  keeps its mode (and, where the user may set them, its owner and group);
- a symbolic link is written through: its target is replaced, the link stays;
- a device or a named pipe (``-o /dev/stdout``) is written to, never replaced;
- a file with other hard links is replaced like any other: the new file has one link, the
  other names keep the old text (docs/lint.md, docs/fmt.md: a file is never half-written, which
  writing in place could not promise).

What a SIGKILL (or a power loss) can still leave is said in docs/mapping.md
("Output files"): stray temporary files, and, between the renames of a pair,
the first file new and the second old or absent.
"""

from __future__ import annotations

import errno
import os
import tempfile
from collections.abc import Collection, Iterator, Sequence
from contextlib import contextmanager, suppress
from pathlib import Path

from edsconv.signals import signals_held


class Refused(Exception):
    """A write the rule forbids: an existing file without ``--force``, or one of the command's inputs."""


def rewrite_in_place(path: Path, data: bytes) -> None:
    """Replace the file a command was asked to rewrite (``fmt``, ``lint --fix``): the one writer whose
    output is its input."""
    write_all_atomically([(path, data)], inputs=(), force=True)


def write_atomically(path: Path, data: bytes, *, inputs: Collection[Path], force: bool = False) -> None:
    """Write one output file (see :func:`write_all_atomically`)."""
    write_all_atomically([(path, data)], inputs=inputs, force=force)


def write_all_atomically(files: Sequence[tuple[Path, bytes]], *, inputs: Collection[Path],
                         force: bool = False) -> None:
    """Write every ``(path, data)`` or none of them; ``inputs``: the files the command reads.

    Raises :class:`Refused` (before anything is written) when a file is one of ``inputs``, whatever
    ``force`` says, or exists and ``force`` is false; else the OSError of the first step that
    fails, naming its file.
    """
    _refusal(files, inputs, force)
    targets = [_written_path(path) for path, _ in files]
    # a device or a pipe (-o /dev/stdout) is written to, never replaced by a file
    special = [(path, target, data) for target, (path, data) in zip(targets, files, strict=True)
               if target.exists() and not target.is_file()]
    regular = [(path, target, data) for target, (path, data) in zip(targets, files, strict=True)
               if not (target.exists() and not target.is_file())]
    temporaries: list[Path] = []
    try:
        for path, target, data in regular:
            with _naming(path):
                _complete_temporary(target, data, temporaries)
        with signals_held():
            for temporary, (path, target, _) in zip(temporaries, regular, strict=True):
                with _naming(path):
                    os.replace(temporary, target)
    except BaseException:
        # a second signal must not cut the cleanup short: a pool ending its workers sends SIGTERM
        # again when the first one exits (concurrent.futures' terminate_broken), a user presses Ctrl-C twice
        with signals_held():
            for temporary in temporaries:
                temporary.unlink(missing_ok=True)
        raise
    for path, target, data in special:
        with _naming(path), open(target, "wb") as stream:
            stream.write(data)


def _refusal(files: Sequence[tuple[Path, bytes]], inputs: Collection[Path], force: bool) -> None:
    """The rule every writer follows: never over an input (a command must not destroy what it reads,
    and with ``--force`` least of all), never over an existing file without ``--force``."""
    overwritten = [path for path, _ in files if _same_file_as_any(path, inputs)]
    if overwritten:
        raise Refused(f"{overwritten[0]}: not written: it is an input of this command (name another output file)")
    existing = [str(path) for path, _ in files if path.is_file()]
    if existing and not force:
        one = len(existing) == 1
        raise Refused(f"{', '.join(existing)} exist{'s' if one else ''} "
                      f"(use --force to overwrite {'it' if one else 'them'})")


def _same_file_as_any(path: Path, inputs: Collection[Path]) -> bool:
    """Whether ``path`` is one of ``inputs`` under any name (a link, a hard link, another spelling)."""
    for candidate in inputs:
        try:
            if os.path.samefile(path, candidate):
                return True
        except OSError:  # one of them does not exist (yet): not the same file
            continue
    return False


@contextmanager
def _naming(path: Path) -> Iterator[None]:
    """An OSError inside names ``path``, the file the user asked for, not a temporary file."""
    try:
        yield
    except OSError as error:
        if error.errno is None:
            raise
        raise type(error)(error.errno, error.strerror, str(path)) from error


def _written_path(path: Path) -> Path:
    """The file that is replaced: the target of a symbolic link, else ``path``; never a directory.
    A device or a pipe is ``path`` itself (``/dev/stdout`` links to a name that cannot be opened)."""
    if path.exists() and not path.is_file() and not path.is_dir():
        return path
    target = Path(os.path.realpath(path)) if path.is_symlink() else path
    if target.is_dir():
        raise IsADirectoryError(errno.EISDIR, os.strerror(errno.EISDIR), str(path))
    existing = next(parent for parent in target.parents if parent.exists())
    if not existing.is_dir():
        raise NotADirectoryError(errno.ENOTDIR, f"{existing} is not a directory", str(path))
    return target


def _complete_temporary(target: Path, data: bytes, temporaries: list[Path]) -> None:
    """Write ``data`` to a new temporary file beside ``target`` (added to ``temporaries`` at once),
    with the mode ``target`` will have, flushed to disk."""
    previous = _status(target)
    target.parent.mkdir(parents=True, exist_ok=True)
    with signals_held():  # a signal between the two would leave a temporary file no one knows of
        descriptor, name = tempfile.mkstemp(dir=target.parent, prefix=f".{target.name}.", suffix=".tmp")
        temporaries.append(Path(name))
    with os.fdopen(descriptor, "wb") as stream:
        stream.write(data)
        stream.flush()
        os.fsync(stream.fileno())
    if previous is None:
        os.chmod(name, 0o666 & ~current_umask())
        return
    os.chmod(name, previous.st_mode & 0o7777)
    if hasattr(os, "chown"):
        with suppress(OSError):  # root replacing another user's file; a user keeping a group of theirs
            os.chown(name, previous.st_uid, previous.st_gid)


def _status(path: Path) -> os.stat_result | None:
    try:
        return os.stat(path)
    except FileNotFoundError:
        return None


def current_umask() -> int:
    """The process's umask (read by setting it and setting it back)."""
    mask = os.umask(0o022)
    os.umask(mask)
    return mask
