"""``edsconv merge``: an adapter EDS and module EDS files -> the combined entries (C.4.1.5.3)."""

from __future__ import annotations

from pathlib import Path

import click

from edsconv.atomic import write_atomically
from edsconv.cli.common import documentation, echo_diagnostics, exit_status, read_eds, writing
from edsconv.merge import merge


@click.command("merge", epilog=documentation("merge.md"))
@click.argument("adapter", type=click.Path(dir_okay=False, path_type=Path))
@click.argument("modules", nargs=-1, required=True, type=click.Path(dir_okay=False, path_type=Path))
@click.option("-o", "--output", type=click.Path(dir_okay=False, path_type=Path),
              help="Write the combined entries to FILE (atomically) instead of standard output.")
@click.option("--force", is_flag=True, help="Overwrite an existing output file (never one of the inputs).")
def merge_command(adapter: Path, modules: tuple[Path, ...], output: Path | None, force: bool) -> int:
    """Merge an adapter EDS with module EDS files (C.4.1.5.3).

    Prints the combined Param / Enum / Assem / Connection entries as EDS text;
    diagnostics go to standard error. Exit 1 when a module has no matching Rack
    entry or an entry cannot be combined.
    """
    result = merge(read_eds(adapter), [read_eds(module) for module in modules])
    echo_diagnostics(result.diagnostics, err=True)
    text = result.text()
    if output is None:
        click.echo(text, nl=False)
    else:
        with writing(output):
            write_atomically(output, text.encode("utf-8"), inputs=[adapter, *modules], force=force)
    return exit_status(result.diagnostics)
