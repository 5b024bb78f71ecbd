"""What the end-to-end language server tests share: the example document, a broken copy of it, and
the server command a pytest-lsp client starts. Imported after ``pytest.importorskip("pytest_lsp")``."""

from __future__ import annotations

import shutil
import sys
from pathlib import Path

from lsprotocol import types
from pytest_lsp import ClientServerConfig, LanguageClient

from conftest import REPO

EXAMPLE_PATH = REPO / "corpus" / "examples" / "io_adapter.eds"
EXAMPLE = EXAMPLE_PATH.read_text()
#: io_adapter.eds with Assem100's member reference Param2 (line 95) changed to the undefined Param9
BROKEN = EXAMPLE.replace("8,Param2,\n                8,;", "8,Param9,\n                8,;")
#: ``edsconv lsp`` in this interpreter, over stdio
SERVER = ClientServerConfig(server_command=[sys.executable, "-m", "edsconv", "lsp"])


async def open_workspace(client: LanguageClient, folder: Path, broken: str,
                         capabilities: types.ClientCapabilities) -> types.InitializeResult:
    """A workspace folder holding ``adapter.eds`` (the example) and, at ``broken`` below it, the broken copy,
    and the client's session started on it."""
    shutil.copy(EXAMPLE_PATH, folder / "adapter.eds")
    (folder / broken).parent.mkdir(parents=True, exist_ok=True)
    (folder / broken).write_text(BROKEN)
    return await client.initialize_session(types.InitializeParams(
        capabilities=capabilities, root_uri=folder.as_uri(),
        workspace_folders=[types.WorkspaceFolder(folder.as_uri(), folder.name)]))
