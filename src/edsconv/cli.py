"""The ``edsconv`` command line.

Exit codes, shared by every subcommand:
  0  ran and found no errors
  1  ran and found errors (or, for ``--check`` style options, a change is needed)
  2  could not run: missing file, bad option, internal failure
"""

from __future__ import annotations

import sys

import click

EXIT_CLEAN = 0
EXIT_FINDINGS = 1
EXIT_USAGE = 2


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(package_name="edsconv")
def cli() -> None:
    """Parse, check and convert CIP Electronic Data Sheets (EDS) and ISO 15745-4 XML profiles."""


def main() -> None:
    """Entry point: every subcommand returns its exit code (see the module docstring)."""
    try:
        code = cli.main(standalone_mode=False)
    except click.exceptions.Exit as exit_:
        sys.exit(exit_.exit_code)
    except click.ClickException as error:
        error.show()
        sys.exit(EXIT_USAGE)
    except click.exceptions.Abort:
        sys.exit(EXIT_USAGE)
    sys.exit(code if isinstance(code, int) else EXIT_CLEAN)
