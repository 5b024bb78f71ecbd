"""What every command shares: exit codes, the one way a command gives up, option callbacks and the
way diagnostics and their counts are printed.

A command that cannot go on (a file it cannot read or write, a file it must not overwrite) raises
:class:`CannotRun`, most often through :func:`reading` or :func:`writing`; it never prints and
returns a code itself. click's standalone mode (``CliRunner``) and :func:`edsconv.cli.main` both
print the message and exit with :data:`EXIT_USAGE`.

This module is loaded by every command, ``parse`` included: keep its imports light.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import IO, TYPE_CHECKING, Any

import click

from edsconv.diagnostics import Diagnostic, Severity, has_errors

if TYPE_CHECKING:
    from edsconv.eds.syntax import EdsFile

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


class Interrupted(BaseException):
    """A signal (SIGINT, SIGTERM, SIGHUP) ends the command: a BaseException, so that no handler of
    ``Exception`` stops it and every ``finally`` block runs."""

    def __init__(self, signal_number: int) -> None:
        super().__init__(signal_number)
        self.signal_number = signal_number


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
    a refusal to overwrite says itself why."""
    try:
        yield
    except OSError as error:
        if isinstance(error, FileExistsError) and error.errno is None:  # write_atomically without force
            raise CannotRun(str(error)) from error
        named = error.filename if error.filename is not None else path
        raise CannotRun(f"{named}: cannot write: {error.strerror or error}") from error


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
