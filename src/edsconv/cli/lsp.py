"""``edsconv lsp``: run the language server on stdin/stdout (docs/editors.md)."""

from __future__ import annotations

import click

from edsconv.cli.common import documentation


@click.command("lsp", epilog=documentation("editors.md"))
@click.option("--stdio", is_flag=True, help="Speak LSP on stdin/stdout (the default and only transport; "
              "accepted because editors pass it).")
def lsp_command(stdio: bool) -> int:
    """Run the EDS language server: diagnostics, hover, navigation, rename, formatting, completion."""
    from edsconv.cli import EXIT_CLEAN, EXIT_USAGE

    try:
        from edsconv.lsp.server import create_server
    except ImportError as error:
        click.echo(f"edsconv lsp needs the lsp extra (pygls, lsprotocol; {error}). edsconv is not on PyPI: "
                   f"install it from its clone, python3 -m pip install '/path/to/edsconv[lsp]', or as "
                   f"\"edsconv[lsp] @ git+URL\" (docs/editors.md)", err=True)
        return EXIT_USAGE
    create_server(show_renderer=_show_text).start_io()
    return EXIT_CLEAN


def _show_text(document: dict) -> str:
    """The show document as ``edsconv show`` prints it to a pipe (the ``edsconv.showDevice`` command)."""
    from edsconv.cli.show import plain_text

    return plain_text(document)
