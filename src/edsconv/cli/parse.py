"""``edsconv parse``: the syntax diagnostics of EDS files, or their lossless syntax model as JSON."""

from __future__ import annotations

import json
from pathlib import Path

import click

from edsconv.cli.common import EXIT_CLEAN, EXIT_FINDINGS, echo_diagnostics, read_eds
from edsconv.eds.syntax import to_json


@click.command("parse")
@click.argument("files", nargs=-1, required=True, type=click.Path(dir_okay=False, path_type=Path))
@click.option("--format", "output_format", type=click.Choice(["text", "json"]), default="text",
              help="text: one diagnostic per line; json: the syntax model with its diagnostics.")
def parse_command(files: tuple[Path, ...], output_format: str) -> int:
    """Read EDS files and report their syntax diagnostics (or print the model as JSON)."""
    exit_code = EXIT_CLEAN
    models = []
    for path in files:
        eds = read_eds(path)
        if eds.has_errors:
            exit_code = EXIT_FINDINGS
        if output_format == "json":
            models.append(to_json(eds))
        else:
            echo_diagnostics(eds.diagnostics)
    if output_format == "json":
        click.echo(json.dumps(models[0] if len(models) == 1 else models, indent=2))
    return exit_code
