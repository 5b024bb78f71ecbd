"""``edsconv lint`` (check EDS files and directories) and ``edsconv rules`` (list the rules)."""

from __future__ import annotations

import sys
from pathlib import Path

import click

from edsconv.cli.common import EXIT_CLEAN, CannotRun, counts_line, documentation, exit_status, rule_codes
from edsconv.lint import lint_paths, promote_warnings
from edsconv.report import FORMATTERS, FileReport


@click.command("lint", epilog=documentation("lint.md"))
@click.argument("paths", nargs=-1, required=True, type=click.Path(exists=True, path_type=Path))
@click.option("--format", "output_format", type=click.Choice(list(FORMATTERS)), default="text", show_default=True,
              help="text: path:line:col: CODE message [clause]; json; sarif (2.1.0, for code scanning); "
              "github (workflow annotations).")
@click.option("--select", multiple=True, callback=rule_codes, metavar="CODES",
              help="Report only these codes or code prefixes (comma-separated, e.g. EDS0,EDS101).")
@click.option("--ignore", multiple=True, callback=rule_codes, metavar="CODES",
              help="Do not report these codes or code prefixes; the longer matching prefix wins over --select.")
@click.option("--warnings-as-errors", is_flag=True, help="Report warnings as errors, and fail on them.")
@click.option("--jobs", "-j", type=click.IntRange(min=1), default=None,
              help="Worker processes for many files [default: every core].")
def lint_command(paths: tuple[Path, ...], output_format: str, select: tuple[str, ...], ignore: tuple[str, ...],
                 warnings_as_errors: bool, jobs: int | None) -> int:
    """Check EDS files, and directories recursively for *.eds/*.EDS files.

    Exit status: 0 no errors, 1 errors found, 2 could not run (a path without any EDS file too).
    """
    reports = lint_paths(paths, select, ignore, jobs)
    if not reports:  # a CI job pointed at the wrong folder must not pass
        raise CannotRun(f"no EDS file (*.eds) found in {', '.join(str(p) for p in paths)}; nothing checked")
    if warnings_as_errors:
        promote_warnings(reports)
    sys.stdout.write(FORMATTERS[output_format](reports))
    sys.stdout.flush()
    if output_format == "text":
        click.echo(summary(reports), err=True)
    return exit_status(d for r in reports for d in r.diagnostics)


def summary(reports: list[FileReport]) -> str:
    """The last line of the text output: files, diagnostics by severity, files that could not be checked."""
    failed = sum(r.error is not None for r in reports)
    line = counts_line(f"{len(reports)} file{'s' if len(reports) != 1 else ''}",
                       (d for r in reports for d in r.diagnostics))
    return line + (f"; {failed} could not be checked" if failed else "")


@click.command("rules", epilog=documentation("rules.md"))
@click.argument("codes", nargs=-1, callback=rule_codes)
@click.option("--format", "output_format", type=click.Choice(["text", "json", "markdown"]), default="text",
              show_default=True, help="text: a table, or each rule's explanation when CODES are given; json: the "
              "full records; markdown: the rules page of the documentation (or the sections of CODES).")
def rules_command(codes: tuple[str, ...], output_format: str) -> int:
    """List every rule (code, severity, clause, import-blocking mark (!) and summary), or explain CODES."""
    from edsconv.rule_docs import format_rules

    click.echo(format_rules(output_format, codes), nl=False)
    return EXIT_CLEAN
