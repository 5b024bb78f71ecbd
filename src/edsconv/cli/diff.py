"""``edsconv diff``: compare two EDS files by meaning."""

from __future__ import annotations

import json
from pathlib import Path

import click

from edsconv.cli.common import EXIT_CLEAN, EXIT_FINDINGS, CannotRun, documentation, emit, read_eds
from edsconv.diff import diff, format_text
from edsconv.eds.syntax import EdsFile
from edsconv.model import Device
from edsconv.model.build import build


@click.command("diff", epilog=documentation("diff.md"))
@click.argument("old_file", type=click.Path(dir_okay=False, path_type=Path))
@click.argument("new_file", type=click.Path(dir_okay=False, path_type=Path))
@click.option("--format", "output_format", type=click.Choice(["text", "json", "html"]), default="text",
              help="text: changes grouped by category; json: a list of changes; html: the two devices side by "
                   "side, the changes marked.")
@click.option("-o", "--output", "output", type=click.Path(dir_okay=False, path_type=Path), metavar="FILE",
              help="With --format html: write the page to FILE instead of standard output.")
@click.option("--force", is_flag=True, help="Overwrite an existing FILE (never one of the compared files).")
def diff_command(old_file: Path, new_file: Path, output_format: str, output: Path | None, force: bool) -> int:
    """Compare two EDS files by meaning.

    Exit 0 when they describe the same device, 1 when they differ, 2 when a file
    cannot be read or holds no section (an empty file, binary, XML). A file with
    syntax errors is compared with a warning: the text they hide is not.
    """
    old, new = build(_comparable(old_file)), build(_comparable(new_file))
    changes = diff(old, new)
    if output_format == "html":
        _html(old, new, [c.as_dict() for c in changes], (old_file, new_file), output, force)
    elif output_format == "json":
        click.echo(json.dumps({"old": str(old_file), "new": str(new_file), "equal": not changes,
                               "changes": [c.as_dict() for c in changes]}, indent=2))
    elif changes:
        click.echo(f"{old_file} -> {new_file}: {len(changes)} change(s)")
        click.echo(format_text(changes))
    else:
        click.echo(f"{old_file} and {new_file} describe the same device")
    return EXIT_FINDINGS if changes else EXIT_CLEAN


def _html(old: Device, new: Device, changes: list[dict], files: tuple[Path, Path], output: Path | None,
          force: bool) -> None:
    from edsconv.describe import describe
    from edsconv.html import diff_page

    emit(diff_page(describe(old), describe(new), changes, str(files[0]), str(files[1])), output, files, force)


def _comparable(path: Path) -> EdsFile:
    """The syntax model of ``path``; :class:`CannotRun` when it has no section to compare (two such
    files would "describe the same device"), a warning when syntax errors hide some of its text."""
    eds = read_eds(path)
    errors = [d for d in eds.diagnostics if d.severity.name == "ERROR"]
    if not eds.sections:
        reason = errors[0].format() if errors else "it holds no [Section]"
        raise CannotRun(f"{path}: cannot compare: no section could be read; {reason}")
    if errors:
        click.echo(f"{path}: warning: {len(errors)} syntax error(s); the text they hide is not compared "
                   f"(first: {errors[0].format()}; 'edsconv lint {path}' lists them)", err=True)
    return eds
