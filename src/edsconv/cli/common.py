"""What every command shares: exit codes, the one way a command gives up, option callbacks and the
way diagnostics and their counts are printed.

A command that cannot go on (a file it cannot read or write, a file it must not overwrite) raises
:class:`CannotRun`, most often through :func:`reading` or :func:`writing`; it never prints and
returns a code itself. click's standalone mode (``CliRunner``) and :func:`edsconv.cli.main` both
print the message and exit with :data:`EXIT_USAGE`.

This module is loaded by every command, ``parse`` included: keep its imports light.
"""

from __future__ import annotations

import io
import os
from collections import Counter
from collections.abc import Iterable, Iterator
from contextlib import contextmanager, suppress
from pathlib import Path
from typing import IO, TYPE_CHECKING, Any

import click

from edsconv.diagnostics import Diagnostic, Severity, has_errors

if TYPE_CHECKING:
    from edsconv.eds.syntax import EdsFile
    from edsconv.paths import Found

#: ran and found no errors (warnings may have been printed)
EXIT_CLEAN = 0
#: ran and found errors (or, for ``--check`` style options, a change is needed)
EXIT_FINDINGS = 1
#: could not run: missing file, bad option, refusing to overwrite, internal failure
EXIT_USAGE = 2


class CannotRun(click.ClickException):
    """The command cannot go on; its message names the file and the reason."""

    exit_code = EXIT_USAGE

    def show(self, file: IO[Any] | None = None) -> None:
        # click would prefix "Error: "; the message already starts with the file it is about
        click.echo(self.message, err=True)


def cannot_write_standard_output(reason: str) -> str:
    """The one line every command prints when its standard output is closed or its reader has gone."""
    return f"edsconv: cannot write to standard output: {reason}"


class ClosedOutput(io.TextIOBase):
    """Standard output when the command was started without one (``>&-``): writing to it cannot run."""

    def __init__(self) -> None:
        super().__init__()
        with suppress(OSError):  # keep descriptor 1 taken, so that no file the command opens becomes it
            os.fstat(1)
            return
        os.open(os.devnull, os.O_WRONLY)

    def writable(self) -> bool:
        return True

    def write(self, text: str) -> int:
        raise CannotRun(cannot_write_standard_output("it is closed"))


@contextmanager
def reading(path: object | None = None) -> Iterator[None]:
    """``path: cannot read: reason`` for an OSError inside (the file the error names when no path is given)."""
    try:
        yield
    except OSError as error:
        raise CannotRun(f"{path if path is not None else error.filename}: cannot read: "
                        f"{error.strerror or error}") from error


@contextmanager
def writing(path: object | None = None) -> Iterator[None]:
    """``path: cannot write: reason`` for an OSError inside (the file the error names, else ``path``);
    a refusal of :mod:`edsconv.atomic`'s rule (an existing file without --force, an input) says itself why."""
    from edsconv.atomic import Refused

    try:
        yield
    except Refused as refused:
        raise CannotRun(str(refused)) from refused
    except OSError as error:
        raise CannotRun(cannot_write(error.filename if error.filename is not None else path,
                                     error.strerror or str(error))) from error


def emit(text: str, output: Path | None, inputs: Iterable[Path], force: bool) -> None:
    """``text`` on standard output, or as the whole of ``output`` (never half of it), by the write rule:
    an existing file only with ``force``, never one of the command's ``inputs``."""
    if output is None:
        click.echo(text)
        return
    from edsconv.atomic import write_atomically

    with writing(output):
        write_atomically(output, (text + "\n").encode("utf-8"), inputs=list(inputs), force=force)


def cannot_write(path: object, reason: str) -> str:
    """The one line every command prints for a file it cannot write."""
    return f"{path}: cannot write: {reason}"


@contextmanager
def configuration() -> Iterator[None]:
    """A bad configuration file cannot run: ``path:line: reason``, exit 2."""
    from edsconv.config import ConfigError

    try:
        yield
    except ConfigError as error:
        raise CannotRun(str(error)) from error


def existing_paths(ctx: click.Context, param: click.Parameter, value: tuple[Path, ...]) -> tuple[Path, ...]:
    """Argument callback: paths that exist (a dangling link or an unreadable file exists: the command
    reports it and goes on; a path that is not there at all is a typo, exit 2)."""
    from edsconv.paths import missing

    gone = missing(value)
    if gone:
        raise click.BadParameter(f"Path {gone[0]!r} does not exist.")
    return value


def files_to_work_on(found: Found, paths: Iterable[Path]) -> Found:
    """What :func:`edsconv.paths.discover` found, after the rule's messages: a warning for each named
    directory without an EDS file; :class:`CannotRun` when nothing at all was found (files that
    ``--force-exclude`` left out are not nothing: pre-commit names only excluded files in some commits)."""
    if not (found.files or found.unsearchable or found.excluded):  # a CI job pointed at the wrong folder fails
        raise CannotRun(f"no EDS file (*.eds) found in {', '.join(str(p) for p in paths)}; nothing checked")
    for directory in found.empty:
        click.echo(f"edsconv: warning: no EDS file (*.eds) found in {directory}", err=True)
    return found


def read_eds(path: Path) -> EdsFile:
    """The syntax model of the EDS at ``path`` (:class:`CannotRun` when it cannot be read)."""
    from edsconv.eds.reader import load

    with reading(path):
        return load(path)


def exit_status(diagnostics: Iterable[Diagnostic]) -> int:
    """:data:`EXIT_FINDINGS` when a diagnostic is an error, else :data:`EXIT_CLEAN`."""
    return EXIT_FINDINGS if has_errors(list(diagnostics)) else EXIT_CLEAN


def echo_diagnostics(diagnostics: Iterable[Diagnostic], err: bool = False) -> None:
    """One ``path:line:col: CODE message [clause]`` line per diagnostic."""
    for diagnostic in diagnostics:
        click.echo(diagnostic.format(), err=err)


def counts_line(subject: str, diagnostics: Iterable[Diagnostic], notes: bool = True) -> str:
    """``subject: 2 errors, 1 warning[, 0 notes]``: the summary validate and show print on stderr."""
    from edsconv.report import plural

    counts = Counter(d.severity for d in diagnostics)
    line = f"{subject}: {plural(counts[Severity.ERROR], 'error')}, {plural(counts[Severity.WARNING], 'warning')}"
    return line + (f", {plural(counts[Severity.INFO], 'note')}" if notes else "")


def split_list(values: Iterable[str]) -> list[str]:
    """The items of repeated, comma-separated option values, stripped, empty ones dropped."""
    return [item.strip() for value in values for item in value.split(",") if item.strip()]


def rule_codes(ctx: click.Context, param: click.Parameter, value: tuple[str, ...]) -> tuple[str, ...]:
    """Option callback: comma-separated rule codes or code prefixes, each matching at least one rule (or alias)."""
    from edsconv.diagnostics import load_rules

    codes = tuple(code.upper() for code in split_list(value))
    if codes:
        unknown = [c for c in codes if not load_rules().knows_prefix(c)]
        if unknown:
            raise click.BadParameter(f"no rule code starts with {', '.join(unknown)} (see 'edsconv rules')")
    return codes


def documentation(page: str) -> str | None:
    """A help epilog naming the installed copy of ``docs/<page>`` (the wheel ships docs/)."""
    from edsconv.resources import data_dir

    try:
        return f"\b\nDocumentation: {data_dir('docs') / page}"  # \b: click keeps the line as it is
    except FileNotFoundError:
        return None
