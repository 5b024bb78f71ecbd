"""``edsconv parse``: the syntax diagnostics of EDS files, or their lossless syntax model as JSON."""

from __future__ import annotations

import sys
from dataclasses import dataclass
from pathlib import Path

import click

from edsconv.cli.common import counts_line, documentation, echo_diagnostics, exit_status, read_eds
from edsconv.diagnostics import Diagnostic
from edsconv.eds.syntax import EdsFile, to_json


@dataclass(slots=True)
class _Parsed:
    """One file's syntax model as a report (edsconv.report.Report): the JSON shape of lint and validate."""

    path: str
    diagnostics: list[Diagnostic]
    eds: EdsFile

    @classmethod
    def of(cls, eds: EdsFile) -> _Parsed:
        return cls(eds.path or "", eds.diagnostics, eds)

    def as_dict(self) -> dict:
        return to_json(self.eds)


@click.command("parse", epilog=documentation("architecture.md"))
@click.argument("files", nargs=-1, required=True, type=click.Path(dir_okay=False, path_type=Path))
@click.option("--format", "output_format", type=click.Choice(["text", "json"]), default="text",
              help="text: one diagnostic per line; json: {\"files\": [the syntax model of each file with its "
                   "diagnostics], \"summary\": {...}}, as lint and validate.")
def parse_command(files: tuple[Path, ...], output_format: str) -> int:
    """Read EDS files and report their syntax diagnostics (or print the model as JSON)."""
    from edsconv.report import format_json

    reports = [_Parsed.of(read_eds(path)) for path in files]
    diagnostics = [d for report in reports for d in report.diagnostics]
    if output_format == "json":
        sys.stdout.write(format_json(reports))
    else:
        echo_diagnostics(diagnostics)
        click.echo(counts_line(f"{len(reports)} file{'s' if len(reports) != 1 else ''}", diagnostics), err=True)
    return exit_status(diagnostics)
