"""The ``edsconv`` command line: a thin layer over the library, one module per command.

Exit codes, shared by every subcommand (:mod:`edsconv.cli.common`):
  0  ran and found no errors
  1  ran and found errors (or, for ``--check`` style options, a change is needed)
  2  could not run: missing file, bad option, internal failure

``edsconv show`` is the exception: it exits 0 on a file with errors (it shows what the file says
and counts the problems on stderr; ``edsconv lint`` is the command that judges).
"""

from __future__ import annotations

import importlib
import sys

import click

from edsconv.cli.common import EXIT_CLEAN, EXIT_FINDINGS, EXIT_USAGE


class LazyGroup(click.Group):
    """A group whose commands are imported only when they run (or help lists them).

    Start-up stays short: ``edsconv parse`` does not pay for xmlschema, rich or
    the process pool that other commands use.
    """

    #: command name -> "module:attribute" of its click command
    lazy = {
        "parse": "edsconv.cli.parse:parse_command",
        "lint": "edsconv.cli.lint:lint_command",
        "rules": "edsconv.cli.lint:rules_command",
        "show": "edsconv.cli.show:show_command",
        "eds2xml": "edsconv.cli.convert:eds2xml_command",
        "xml2eds": "edsconv.cli.convert:xml2eds_command",
        "validate": "edsconv.cli.validate:validate_command",
        "fmt": "edsconv.cli.fmt:fmt_command",
        "diff": "edsconv.cli.diff:diff_command",
        "merge": "edsconv.cli.merge:merge_command",
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


def main() -> None:
    """Entry point: exit codes as in the module docstring; usage errors and :class:`CannotRun` are 2."""
    try:
        # Without standalone mode click returns the code of ctx.exit() ...
        code = cli.main(standalone_mode=False)
    except click.ClickException as error:  # ... and raises usage errors, which it would exit 2 with anyway
        error.show()
        sys.exit(EXIT_USAGE)
    except click.exceptions.Abort:
        sys.exit(EXIT_USAGE)
    sys.exit(code if isinstance(code, int) else EXIT_CLEAN)


__all__ = ["EXIT_CLEAN", "EXIT_FINDINGS", "EXIT_USAGE", "cli", "main"]
