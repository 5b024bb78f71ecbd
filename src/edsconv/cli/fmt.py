"""``edsconv fmt``: rewrite EDS files in canonical order and layout, or show what would change."""

from __future__ import annotations

import difflib
import os
from dataclasses import dataclass, field
from pathlib import Path

import click

from edsconv.atomic import rewrite_in_place
from edsconv.cli.common import (
    EXIT_CLEAN,
    EXIT_FINDINGS,
    EXIT_USAGE,
    CannotRun,
    configuration,
    documentation,
    files_to_work_on,
    reading,
    writing,
)
from edsconv.config import Resolver
from edsconv.eds.canonical import format_bytes
from edsconv.eds.reader import parse
from edsconv.eds.refusals import read_bytes
from edsconv.eds.syntax import EdsFile
from edsconv.parallel import file_size, run_all
from edsconv.paths import discover

#: what became of one file
CHANGED, UNCHANGED, NOT_FORMATTED = "changed", "unchanged", "not formatted"


@dataclass(slots=True)
class Formatted:
    """What became of one file, its exit code and what to print (a worker returns it; the command prints)."""

    outcome: str
    code: int
    #: lines for standard error
    messages: list[str] = field(default_factory=list)
    #: ``--diff``: the unified diff, for standard output
    diff: str = ""


@click.command("fmt", epilog=documentation("fmt.md"))
@click.argument("paths", nargs=-1, required=True, type=click.Path(readable=False, path_type=Path))
@click.option("--check", is_flag=True, help="Write nothing; exit 1 when a file is not in canonical form.")
@click.option("--diff", "show_diff", is_flag=True, help="Write nothing; print a unified diff of each change.")
@click.option("--force-exclude", is_flag=True,
              help="Leave out files named on the command line that a directory search would leave out.")
@click.option("--jobs", "-j", type=click.IntRange(min=1), default=None,
              help="Worker processes for many files [default: every core].")
def fmt_command(paths: tuple[Path, ...], check: bool, show_diff: bool, force_exclude: bool, jobs: int | None) -> int:
    """Rewrite EDS files, and directories recursively for *.eds files, in canonical order and layout.

    Values keep their spelling and comments stay with their fields. A file with
    syntax errors is not rewritten (its unparsed text cannot be laid out). Exit 0
    when every file is (or now is) canonical, 1 when --check / --diff found a file
    to change or a file has syntax errors, 2 when a file cannot be read or written.
    """
    with configuration():  # the configuration's exclude applies to directory searches, as for lint
        found = files_to_work_on(discover(paths, Resolver(), force_exclude=force_exclude), paths)
    write = not (check or show_diff)
    results = run_all(format_file, [(Path(f), write, show_diff) for f in found.files], jobs or os.cpu_count() or 1,
                      "formatting", died=_died, sizes=[file_size(f) for f in found.files])
    results += [Formatted(NOT_FORMATTED, EXIT_USAGE, [f"{directory}: cannot read: {reason}"])
                for directory, reason in found.unsearchable]
    for result in results:
        if result.diff:
            click.echo(result.diff, nl=False)
        for message in result.messages:
            click.echo(message, err=True)
    verb = "would be reformatted" if not write else "reformatted"
    changed = sum(result.outcome == CHANGED for result in results)
    unchanged = sum(result.outcome == UNCHANGED for result in results)
    failed = len(results) - changed - unchanged
    click.echo(f"{changed} file(s) {verb}, {unchanged} unchanged" + (f", {failed} not formatted" if failed else ""),
               err=True)
    return max((result.code for result in results), default=EXIT_CLEAN)


def format_file(path: Path, write: bool, show_diff: bool) -> Formatted:
    """Format one file (or, unless ``write``, say that it would change); never raises for a problem of the file."""
    try:
        return _format(path, write, show_diff)
    except CannotRun as error:  # the other files are still formatted
        return Formatted(NOT_FORMATTED, EXIT_USAGE, [error.message])


def _format(path: Path, write: bool, show_diff: bool) -> Formatted:
    with reading(path):
        original = read_bytes(path)  # never more than one byte past the size limit (EDS025)
        eds = parse(original, str(path))
    errors = [d for d in eds.diagnostics if d.severity.name == "ERROR"]
    if errors:
        return Formatted(NOT_FORMATTED, EXIT_FINDINGS, [
            f"{path}: not formatted: {len(errors)} syntax error(s) leave text that cannot be laid out; "
            f"first: {errors[0].format()}{_fixable_hint(path, eds, original, errors)}"])
    data = format_bytes(eds)
    if data == original:
        return Formatted(UNCHANGED, EXIT_CLEAN)
    diff = unified_diff(path, eds, original, data) if show_diff else ""
    if not write:
        return Formatted(CHANGED, EXIT_FINDINGS, [f"would reformat {path}"], diff)
    with writing(path):
        rewrite_in_place(path, data)
    return Formatted(CHANGED, EXIT_CLEAN, [f"reformatted {path}"])


def _fixable_hint(path: Path, eds: EdsFile, original: bytes, errors: list) -> str:
    """Where some of the syntax errors have a safe fix: the command that makes it."""
    from edsconv.fix import fix_for, raw_text, split_lines

    lines = split_lines(raw_text(original, eds.encoding))
    fixable = sum(fix_for(eds, lines, error) is not None for error in errors)
    if not fixable:
        return ""
    return f"; 'edsconv lint --fix {path}' repairs {'it' if len(errors) == 1 else f'{fixable} of them'}"


def _died(task: tuple, message: str) -> Formatted:
    return Formatted(NOT_FORMATTED, EXIT_USAGE, [f"{task[0]}: not formatted: {message}"])


def unified_diff(path: Path, eds: EdsFile, original: bytes, formatted: bytes) -> str:
    """The change from ``original`` to ``formatted``, decoded as the file is."""
    old = original.decode(eds.encoding, errors="replace").splitlines(keepends=True)
    new = formatted.decode(eds.encoding, errors="replace").splitlines(keepends=True)
    return "".join(difflib.unified_diff(old, new, f"{path}", f"{path} (canonical)"))
