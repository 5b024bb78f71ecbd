"""The ``edsconv`` command line: a thin layer over the library, one module per command.

Exit codes, shared by every subcommand (:mod:`edsconv.cli.common`):
  0  ran and found no errors
  1  ran and found errors (or, for ``--check`` style options, a change is needed)
  2  could not run: missing file, bad option, internal failure

``edsconv show`` is the exception: it exits 0 on a file with errors (it shows what the file says
and counts the problems on stderr; ``edsconv lint`` is the command that judges).

Nothing leaves as a traceback: an OSError no command expected is one line naming the file, any
other exception one line asking for a report (``--debug`` or ``EDSCONV_DEBUG=1`` adds the
traceback), both exit 2. SIGINT, SIGTERM and SIGHUP end the command with 128 + the signal's
number (130, 143, 129) after the files being written are cleaned up (:mod:`edsconv.signals`).
"""

from __future__ import annotations

import importlib
import os
import signal
import sys
import traceback
from typing import Any

import click

from edsconv.cli.common import (
    EXIT_CLEAN,
    EXIT_FINDINGS,
    EXIT_USAGE,
    CannotRun,
    ClosedOutput,
    cannot_write_standard_output,
)
from edsconv.signals import Interrupted, signals_interrupt

#: Set (to anything but empty or 0) to print the traceback of an unexpected error, as ``--debug`` does.
DEBUG_VARIABLE = "EDSCONV_DEBUG"


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
        "verify": "edsconv.cli.verify:verify_command",
    }

    def list_commands(self, ctx: click.Context) -> list[str]:
        return sorted({*super().list_commands(ctx), *self.lazy})

    def get_command(self, ctx: click.Context, name: str) -> click.Command | None:
        if name in self.lazy and name not in self.commands:
            module, _, attribute = self.lazy[name].partition(":")
            self.add_command(getattr(importlib.import_module(module), attribute), name)
        return super().get_command(ctx, name)

    def invoke(self, ctx: click.Context) -> Any:
        """Run the command; an exception it did not expect becomes one line and exit 2 (:class:`CannotRun`)."""
        try:
            return super().invoke(ctx)
        except (click.ClickException, click.exceptions.Exit, click.exceptions.Abort):
            raise
        except BrokenPipeError as error:  # the reader of standard output left: stop writing to it
            os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
            raise CannotRun(cannot_write_standard_output(error.strerror or "Broken pipe")) from error
        except OSError as error:  # reads and writes go through reading() / writing(); this is one they missed
            _print_traceback_if(ctx.params.get("debug", False))
            raise CannotRun(f"{error.filename if error.filename is not None else 'edsconv'}: "
                            f"{error.strerror or error}") from error
        except Exception as error:
            _print_traceback_if(ctx.params.get("debug", False))
            raise CannotRun(f"edsconv: internal error ({type(error).__name__}: {error}); this is a bug in edsconv, "
                            f"please report it with the command line and the input file (--debug or "
                            f"{DEBUG_VARIABLE}=1 shows the traceback)") from error


def _print_traceback_if(debug: bool) -> None:
    if debug or os.environ.get(DEBUG_VARIABLE, "") not in ("", "0"):
        traceback.print_exc()


@click.group(cls=LazyGroup, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(package_name="edsconv")
@click.option("--debug", is_flag=True, help=f"Print the traceback of an internal error (as {DEBUG_VARIABLE}=1 does).")
def cli(debug: bool) -> None:
    """Parse, check and convert CIP Electronic Data Sheets (EDS) and ISO 15745-4 XML profiles."""


@cli.result_callback()
@click.pass_context
def _exit_with(ctx: click.Context, code: int | None, **options: object) -> None:
    """Every subcommand returns its exit code; exit with it however click was invoked."""
    ctx.exit(code if isinstance(code, int) else EXIT_CLEAN)


def main() -> None:
    """Entry point: exit codes as in the module docstring; usage errors and :class:`CannotRun` are 2."""
    if sys.stdout is None:  # started with standard output closed (>&-): a write says so, whatever the command
        sys.stdout = ClosedOutput()
    try:
        with signals_interrupt():
            # Without standalone mode click returns the code of ctx.exit() ...
            code = cli.main(standalone_mode=False)
    except click.ClickException as error:  # ... and raises usage errors, which it would exit 2 with anyway
        error.show()
        sys.exit(EXIT_USAGE)
    except click.exceptions.Abort:
        sys.exit(EXIT_USAGE)
    except Interrupted as interruption:
        click.echo(f"edsconv: interrupted by {signal.Signals(interruption.signal_number).name}", err=True)
        sys.exit(128 + interruption.signal_number)
    sys.exit(code if isinstance(code, int) else EXIT_CLEAN)


__all__ = ["EXIT_CLEAN", "EXIT_FINDINGS", "EXIT_USAGE", "cli", "main"]
