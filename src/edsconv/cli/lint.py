"""``edsconv lint`` (check EDS files and directories) and ``edsconv rules`` (list the rules)."""

from __future__ import annotations

import sys
from pathlib import Path

import click

from edsconv.cli.common import (
    EXIT_CLEAN,
    EXIT_FINDINGS,
    EXIT_USAGE,
    cannot_write,
    configuration,
    documentation,
    existing_paths,
    exit_status,
    files_to_work_on,
    rule_codes,
)
from edsconv.config import Overrides, Resolver
from edsconv.diagnostics import Severity
from edsconv.lint import FixMode, at_least, lint_paths
from edsconv.paths import discover
from edsconv.report import FORMATTERS, FileReport, counts


@click.command("lint", epilog=documentation("lint.md"))
@click.argument("paths", nargs=-1, required=True, type=click.Path(readable=False, path_type=Path),
                callback=existing_paths)
@click.option("--format", "output_format", type=click.Choice(list(FORMATTERS)), default="text", show_default=True,
              help="text: path:line:col: severity: CODE message [clause]; json; sarif (2.1.0, for code scanning); "
              "github (workflow annotations, errors first, and a summary line).")
@click.option("--select", multiple=True, callback=rule_codes, metavar="CODES",
              help="Report only these codes or code prefixes (comma-separated, e.g. EDS0,EDS101); replaces the "
              "configuration's select and extend-select.")
@click.option("--ignore", multiple=True, callback=rule_codes, metavar="CODES",
              help="Do not report these codes or code prefixes (added to the configuration's ignore); the longer "
              "matching prefix wins over --select.")
@click.option("--warnings-as-errors/--no-warnings-as-errors", default=None,
              help="Report warnings as errors, and fail on them [default: as the configuration says, else no].")
@click.option("--min-severity", type=click.Choice([str(s) for s in Severity]), default=str(Severity.INFO),
              show_default=True, help="Leave out diagnostics below this severity (in every format).")
@click.option("--fix", "fix", flag_value=FixMode.FIX, default=None, type=click.UNPROCESSED,
              help="Repair the faults that have a safe fix, write the files, and report what is left.")
@click.option("--diff", "fix", flag_value=FixMode.DIFF, type=click.UNPROCESSED,
              help="Print the repairs --fix would make as a unified diff; write nothing (exit 1 when a file "
              "would change).")
@click.option("--config", "config_file", type=click.Path(exists=True, dir_okay=False, path_type=Path),
              help="Use this configuration file for every path instead of searching for one.")
@click.option("--isolated", is_flag=True, help="Read no configuration file (not with --config).")
@click.option("--force-exclude", is_flag=True,
              help="Leave out files named on the command line that a directory search would leave out (the "
              "configuration's exclude, hidden directories); for pre-commit, which names every file.")
@click.option("--show-settings", is_flag=True,
              help="Print the settings in force for each path and where they come from; check nothing.")
@click.option("--jobs", "-j", type=click.IntRange(min=1), default=None,
              help="Worker processes for many files [default: every core].")
def lint_command(paths: tuple[Path, ...], output_format: str, select: tuple[str, ...], ignore: tuple[str, ...],
                 warnings_as_errors: bool | None, min_severity: str, fix: FixMode | None, config_file: Path | None,
                 isolated: bool, force_exclude: bool, show_settings: bool, jobs: int | None) -> int:
    """Check EDS files, and directories recursively for *.eds files (any letter case).

    Settings come from [tool.edsconv] in pyproject.toml or from edsconv.toml, found
    by walking up from each file; options override them. Exit status: 0 no errors,
    1 errors found (--diff: a file would change), 2 could not run (a bad option, a
    bad configuration file, a path without any EDS file, a fixed file that cannot be written).
    """
    if config_file is not None and isolated:
        raise click.UsageError("--isolated reads no configuration file: it cannot be used with --config")
    overrides = Overrides(select, ignore, warnings_as_errors, config_file, isolated)
    with configuration():
        resolver = Resolver(overrides)
        if show_settings:
            click.echo("\n".join(resolver.settings_for(p).describe(p) for p in paths), nl=False)
            return EXIT_CLEAN
        found = files_to_work_on(discover(paths, resolver, force_exclude=force_exclude), paths)
        reports = lint_paths(paths, jobs=jobs, overrides=overrides, fix=fix or FixMode.REPORT, found=found)
    at_least(reports, Severity[min_severity.upper()])
    if fix is FixMode.DIFF:
        return _print_diffs(reports)
    sys.stdout.write(FORMATTERS[output_format](reports))
    sys.stdout.flush()
    if output_format == "text":
        click.echo(summary(reports), err=True)
    return _unwritten(reports) or exit_status(d for r in reports for d in r.diagnostics)


def _unwritten(reports: list[FileReport]) -> int:
    """``--fix``: a line for each fixed file that could not be written, after the findings; exit 2 if any."""
    unwritten = [r for r in reports if r.write_error is not None]
    for report in unwritten:
        click.echo(cannot_write(report.path, str(report.write_error)), err=True)
    return EXIT_USAGE if unwritten else EXIT_CLEAN


def _print_diffs(reports: list[FileReport]) -> int:
    """``--diff``: every file's repair as a unified diff on stdout, a count on stderr; 1 when one would change."""
    changed = [r for r in reports if r.diff]
    sys.stdout.write("".join(r.diff for r in changed))
    sys.stdout.flush()
    fixes = sum(len(r.fixed) for r in changed)
    click.echo(f"would fix {fixes} problem{'s' if fixes != 1 else ''} in {len(changed)} "
               f"file{'s' if len(changed) != 1 else ''}", err=True)
    return EXIT_FINDINGS if changed else EXIT_CLEAN


def summary(reports: list[FileReport]) -> str:
    """The last line of the text output: files, diagnostics by severity, what was fixed, what could not be checked."""
    failed = sum(r.error is not None for r in reports)
    fixed = sum(len(r.fixed) for r in reports)
    return counts(reports) + (f"; fixed {fixed}" if fixed else "") + \
        (f"; {failed} could not be checked" if failed else "")


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
