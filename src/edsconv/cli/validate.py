"""``edsconv validate``: check ISO 15745-4 XML profiles against the schemas restored from the spec."""

from __future__ import annotations

import sys
from pathlib import Path

import click

from edsconv.cli.common import counts_line, documentation, echo_diagnostics, exit_status, reading
from edsconv.report import format_json
from edsconv.xml.schemas import kind_named
from edsconv.xml.validate import SCHEMA_CHOICES, validate_file


@click.command("validate", epilog=documentation("validate.md"))
@click.argument("files", nargs=-1, required=True, type=click.Path(exists=True, dir_okay=False, path_type=Path))
@click.option("--schema", "schema_name", type=click.Choice(SCHEMA_CHOICES),
              help="Validate against this profile kind or schema file instead of the one the header names.")
@click.option("--format", "output_format", type=click.Choice(["text", "json"]), default="text", show_default=True)
def validate_command(files: tuple[Path, ...], schema_name: str | None, output_format: str) -> int:
    """Validate ISO 15745-4 XML profiles (EtherNet/IP, EDS wrappers, ADS-net, FL-net) against their schemas.

    POWERLINK and CANopen XDD/XDC, PROFINET GSDML and IO-Link IODD files are
    named (XML005) but not validated: edsconv holds no schema for them.
    """
    forced = kind_named(schema_name) if schema_name else None
    reports = []
    for path in files:
        with reading(path):
            reports.append(validate_file(path, forced))
    diagnostics = [d for report in reports for d in report.diagnostics]
    if output_format == "json":
        sys.stdout.write(format_json(reports))
    else:
        echo_diagnostics(diagnostics)
        click.echo(counts_line(f"{len(reports)} file{'s' if len(reports) != 1 else ''}", diagnostics), err=True)
    return exit_status(diagnostics)
