"""The ``edsconv`` command line.

Exit codes, shared by every subcommand:
  0  ran and found no errors
  1  ran and found errors (or, for ``--check`` style options, a change is needed)
  2  could not run: missing file, bad option, internal failure
"""

from __future__ import annotations

import importlib
import json
import sys
from pathlib import Path

import click

EXIT_CLEAN = 0
EXIT_FINDINGS = 1
EXIT_USAGE = 2


class LazyGroup(click.Group):
    """A group whose commands named in :attr:`lazy` are imported only when they run (or help lists them).

    Start-up stays short: ``edsconv parse`` does not pay for xmlschema, rich or
    the process pool that other commands use.
    """

    #: command name -> "module:attribute" of its click command
    lazy = {
        "validate": "edsconv.xml.validate:validate_command",
        "lint": "edsconv.lint:lint_command",
        "rules": "edsconv.lint:rules_command",
        "merge": "edsconv.merge:merge_command",
        "fmt": "edsconv.eds.canonical:fmt_command",
        "diff": "edsconv.diff:diff_command",
        "show": "edsconv.show:show_command",
        "eds2xml": "edsconv.xml.convert:eds2xml_command",
        "xml2eds": "edsconv.xml.convert:xml2eds_command",
        "lsp": "edsconv.cli.lsp:lsp_command",
    }

    def list_commands(self, ctx: click.Context) -> list[str]:
        return sorted({*super().list_commands(ctx), *self.lazy})

    def get_command(self, ctx: click.Context, name: str) -> click.Command | None:
        if name in self.lazy and name not in self.commands:
            module, _, attribute = self.lazy[name].partition(":")
            self.add_command(getattr(importlib.import_module(module), attribute), name)
        return super().get_command(ctx, name)


@click.group(cls=LazyGroup, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(package_name="edsconv")
def cli() -> None:
    """Parse, check and convert CIP Electronic Data Sheets (EDS) and ISO 15745-4 XML profiles."""


@cli.result_callback()
@click.pass_context
def _exit_with(ctx: click.Context, code: int | None) -> None:
    """Every subcommand returns its exit code; exit with it however click was invoked."""
    ctx.exit(code if isinstance(code, int) else EXIT_CLEAN)


@cli.command("parse")
@click.argument("files", nargs=-1, required=True, type=click.Path(dir_okay=False, path_type=Path))
@click.option("--format", "output_format", type=click.Choice(["text", "json"]), default="text",
              help="text: one diagnostic per line; json: the syntax model with its diagnostics.")
def parse_command(files: tuple[Path, ...], output_format: str) -> int:
    """Read EDS files and report their syntax diagnostics (or print the model as JSON)."""
    from edsconv.eds.reader import load
    from edsconv.eds.syntax import to_json

    exit_code = EXIT_CLEAN
    models = []
    for path in files:
        try:
            eds = load(path)
        except OSError as error:
            click.echo(f"{path}: cannot read: {error.strerror or error}", err=True)
            return EXIT_USAGE
        if eds.has_errors:
            exit_code = EXIT_FINDINGS
        if output_format == "json":
            models.append(to_json(eds))
        else:
            for diagnostic in eds.diagnostics:
                click.echo(diagnostic.format())
    if output_format == "json":
        click.echo(json.dumps(models[0] if len(models) == 1 else models, indent=2))
    return exit_code


def main() -> None:
    """Entry point: exit codes as in the module docstring; usage errors are 2."""
    try:
        # Without standalone mode click returns the code of ctx.exit() ...
        code = cli.main(standalone_mode=False)
    except click.ClickException as error:  # ... and raises usage errors, which it would exit 2 with anyway
        error.show()
        sys.exit(EXIT_USAGE)
    except click.exceptions.Abort:
        sys.exit(EXIT_USAGE)
    sys.exit(code if isinstance(code, int) else EXIT_CLEAN)
