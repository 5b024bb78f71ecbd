"""What the end-to-end language server tests share: the example document, a broken copy of it, and
the server command a pytest-lsp client starts. Imported after ``pytest.importorskip("pytest_lsp")``."""

from __future__ import annotations

import sys

from pytest_lsp import ClientServerConfig

from conftest import REPO

EXAMPLE_PATH = REPO / "corpus" / "examples" / "io_adapter.eds"
EXAMPLE = EXAMPLE_PATH.read_text()
#: io_adapter.eds with Assem100's member reference Param2 (line 95) changed to the undefined Param9
BROKEN = EXAMPLE.replace("8,Param2,\n                8,;", "8,Param9,\n                8,;")
#: ``edsconv lsp`` in this interpreter, over stdio
SERVER = ClientServerConfig(server_command=[sys.executable, "-m", "edsconv", "lsp"])
