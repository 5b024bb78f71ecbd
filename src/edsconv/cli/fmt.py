"""``edsconv fmt``: rewrite EDS files in canonical order and layout, or show what would change."""

from __future__ import annotations

import difflib
from pathlib import Path

import click

from edsconv.atomic import write_atomically
from edsconv.cli.common import EXIT_CLEAN, EXIT_FINDINGS, EXIT_USAGE, CannotRun, documentation, reading, writing
from edsconv.eds.canonical import format_bytes
from edsconv.eds.reader import parse
from edsconv.eds.refusals import read_bytes
from edsconv.eds.syntax import EdsFile

#: what became of one file
CHANGED, UNCHANGED, NOT_FORMATTED = "changed", "unchanged", "not formatted"


@click.command("fmt", epilog=documentation("fmt.md"))
@click.argument("files", nargs=-1, required=True, type=click.Path(dir_okay=False, path_type=Path))
@click.option("--check", is_flag=True, help="Write nothing; exit 1 when a file is not in canonical form.")
@click.option("--diff", "show_diff", is_flag=True, help="Write nothing; print a unified diff of each change.")
def fmt_command(files: tuple[Path, ...], check: bool, show_diff: bool) -> int:
    """Rewrite EDS files in canonical order and layout.

    Values keep their spelling and comments stay with their fields. A file with
    syntax errors is not rewritten (its unparsed text cannot be laid out). Exit 0
    when every file is (or now is) canonical, 1 when --check / --diff found a file
    to change or a file has syntax errors, 2 when a file cannot be read or written.
    """
    outcomes = []
    for path in files:
        try:
            outcomes.append(format_file(path, write=not (check or show_diff), show_diff=show_diff))
        except CannotRun as error:  # the other files are still formatted
            error.show()
            outcomes.append((NOT_FORMATTED, EXIT_USAGE))
    verb = "would be reformatted" if check or show_diff else "reformatted"
    changed = sum(outcome == CHANGED for outcome, _ in outcomes)
    unchanged = sum(outcome == UNCHANGED for outcome, _ in outcomes)
    failed = len(outcomes) - changed - unchanged
    click.echo(f"{changed} file(s) {verb}, {unchanged} unchanged" + (f", {failed} not formatted" if failed else ""),
               err=True)
    return max((code for _, code in outcomes), default=EXIT_CLEAN)


def format_file(path: Path, write: bool, show_diff: bool) -> tuple[str, int]:
    """Format one file (or, unless ``write``, say that it would change); what became of it and its exit code."""
    with reading(path):
        original = read_bytes(path)  # never more than one byte past the size limit (EDS025)
        eds = parse(original, str(path))
    errors = [d for d in eds.diagnostics if d.severity.name == "ERROR"]
    if errors:
        click.echo(f"{path}: not formatted: {len(errors)} syntax error(s) leave text that cannot be laid "
                   f"out; first: {errors[0].format()}", err=True)
        return NOT_FORMATTED, EXIT_FINDINGS
    data = format_bytes(eds)
    if data == original:
        return UNCHANGED, EXIT_CLEAN
    if show_diff:
        click.echo(unified_diff(path, eds, original, data), nl=False)
    if not write:
        click.echo(f"would reformat {path}", err=True)
        return CHANGED, EXIT_FINDINGS
    with writing(path):
        write_atomically(path, data, force=True)
    click.echo(f"reformatted {path}", err=True)
    return CHANGED, EXIT_CLEAN


def unified_diff(path: Path, eds: EdsFile, original: bytes, formatted: bytes) -> str:
    """The change from ``original`` to ``formatted``, decoded as the file is."""
    old = original.decode(eds.encoding, errors="replace").splitlines(keepends=True)
    new = formatted.decode(eds.encoding, errors="replace").splitlines(keepends=True)
    return "".join(difflib.unified_diff(old, new, f"{path}", f"{path} (canonical)"))
