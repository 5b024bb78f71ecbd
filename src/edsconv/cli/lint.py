"""``edsconv lint`` (check EDS files and directories) and ``edsconv rules`` (list the rules)."""

from __future__ import annotations

import json
import sys
import time
from collections.abc import Callable
from pathlib import Path

import click

from edsconv.cli.common import (
    EXIT_CLEAN,
    EXIT_FINDINGS,
    EXIT_USAGE,
    CannotRun,
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
from edsconv.report import FORMATTERS, FileReport, sarif_log
from edsconv.report_text import TEXT_FORMATS, Style, colour_wanted, format_statistics, format_text, summary
from edsconv.report_text import statistics as statistics_of

#: ``--format``: the text formats for people, then the formats of machines.
FORMATS = list(dict.fromkeys(["text", *TEXT_FORMATS, *FORMATTERS]))


def output_options(command: Callable) -> Callable:
    """What is shown and how: --format, --min-severity, --show-notes, --statistics, --color."""
    for option in reversed([
        click.option("--format", "output_format", type=click.Choice(FORMATS), default="text", show_default=True,
                     help="text: full on a terminal, concise otherwise; concise: path:line:col: severity: CODE message "
                     "[clause], one line each; full: each with the line at fault, a caret and its rule's link; json; "
                     "sarif (2.1.0, for code scanning); github (workflow annotations, errors first, a summary "
                     "line)."),
        click.option("--min-severity", type=click.Choice([str(s) for s in Severity]), default=None,
                     help="Leave out diagnostics below this severity (in every format) [default: warning: notes are "
                     "counted, not shown]."),
        click.option("--show-notes", is_flag=True, help="Show the notes too: --min-severity info."),
        click.option("--statistics", is_flag=True,
                     help="Print how often each rule was found (json with --format json) instead of the findings."),
        click.option("--color", "colour", type=click.Choice(["auto", "always", "never"]), default="auto",
                     show_default=True, help="Colour the text formats: auto colours a terminal unless NO_COLOR is set "
                     "(FORCE_COLOR colours a pipe too)."),
    ]):
        command = option(command)
    return command


@click.command("lint", epilog=documentation("lint.md"))
@click.argument("paths", nargs=-1, required=True, type=click.Path(readable=False, path_type=Path),
                callback=existing_paths)
@output_options
@click.option("--select", multiple=True, callback=rule_codes, metavar="CODES",
              help="Report only these codes or code prefixes (comma-separated, e.g. EDS0,EDS101); replaces the "
              "configuration's select and extend-select. A note named by its full code is shown.")
@click.option("--ignore", multiple=True, callback=rule_codes, metavar="CODES",
              help="Do not report these codes or code prefixes (added to the configuration's ignore); the longer "
              "matching prefix wins over --select.")
@click.option("--warnings-as-errors/--no-warnings-as-errors", default=None,
              help="Report warnings as errors, and fail on them [default: as the configuration says, else no].")
@click.option("--fix", "fix", flag_value=FixMode.FIX, default=None, type=click.UNPROCESSED,
              help="Repair the faults that have a safe fix ([*] in the text), write the files, and report what "
              "is left.")
@click.option("--diff", "fix", flag_value=FixMode.DIFF, type=click.UNPROCESSED,
              help="Print the repairs --fix would make as a unified diff; write nothing (exit 1 when a file "
              "would change). Text only.")
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
                 warnings_as_errors: bool | None, min_severity: str | None, show_notes: bool, fix: FixMode | None,
                 statistics: bool, colour: str, config_file: Path | None, isolated: bool, force_exclude: bool,
                 show_settings: bool, jobs: int | None) -> int:
    """Check EDS files, and directories recursively for *.eds files (any letter case).

    Settings come from [tool.edsconv] in pyproject.toml or from edsconv.toml, found
    by walking up from each file; options override them. Exit status: 0 no errors,
    1 errors found (--diff: a file would change), 2 could not run (a bad option, a
    bad configuration file, a path without any EDS file, a fixed file that cannot be written).
    """
    started = time.monotonic()
    _refuse_diff_as(output_format, fix)
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
    at_least(reports, shown_from(min_severity, show_notes), named=select)
    if fix is FixMode.DIFF:
        return _print_diffs(reports)
    return _print(reports, output_format, statistics, colour, started)


def _print(reports: list[FileReport], output_format: str, statistics: bool, colour: str, started: float) -> int:
    """The findings (or ``--statistics``) on stdout; for people, the summary on stderr; the exit status."""
    sys.stdout.write(_output(reports, output_format, statistics, colour))
    sys.stdout.flush()
    if output_format in ("text", *TEXT_FORMATS) and not statistics:
        style = Style(colour_wanted(colour, sys.stderr))
        click.echo(summary(reports, time.monotonic() - started, style), err=True, nl=False, color=style.colour)
    return _unwritten(reports) or exit_status(d for r in reports for d in r.diagnostics)


def _refuse_diff_as(output_format: str, fix: FixMode | None) -> None:
    if fix is FixMode.DIFF and output_format not in ("text", *TEXT_FORMATS):
        raise CannotRun(f"--diff prints a unified diff, not {output_format}: leave out --format {output_format}")


def shown_from(min_severity: str | None, show_notes: bool) -> Severity:
    """The least severity shown: ``--min-severity``, else info with ``--show-notes``, else warning."""
    if min_severity is not None:
        return Severity[min_severity.upper()]
    return Severity.INFO if show_notes else Severity.WARNING


def _output(reports: list[FileReport], output_format: str, statistics: bool, colour: str) -> str:
    """What goes to stdout: the findings (or ``--statistics``) in ``output_format``."""
    style = Style(colour_wanted(colour, sys.stdout))
    if statistics:
        rows = statistics_of(reports)
        return json.dumps(rows, indent=2) + "\n" if output_format == "json" else format_statistics(rows, style)
    if output_format == "text":
        return format_text(reports, style, terminal=sys.stdout.isatty())
    if output_format in TEXT_FORMATS:
        return TEXT_FORMATS[output_format](reports, style)
    if output_format == "sarif":  # a log code scanning takes: a CI log says what it left out
        text, left_out = sarif_log(reports)
        if left_out:
            click.echo(f"edsconv: {left_out}", err=True)
        return text
    return FORMATTERS[output_format](reports)


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
