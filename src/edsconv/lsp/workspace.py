"""The workspace: every EDS in the open folders, checked in the background, so that errors in
files no editor shows reach the problems list, and their entries reach workspace symbol search.

Files are found as ``edsconv lint DIR`` finds them (:func:`edsconv.paths.discover`, with the
``exclude`` of the configuration), checked one at a time in a worker thread (open documents
keep the editor's answers first), and their diagnostics are *pushed*
(``textDocument/publishDiagnostics``) under each file's URI: every client shows pushed
diagnostics, where pull (``workspace/diagnostic``) is asked for by few clients and, beside the
push the server makes for open documents, would show each problem twice in VS Code. A file
that is open is the editor's: its text, not the disk's, is checked, and closing it brings
back the check of the file on disk.

What is kept of a file between checks is its size and modification time, its diagnostics and
its symbols, never its analysis: a folder of many files costs little memory.
"""

from __future__ import annotations

import asyncio
import os
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from pathlib import Path

from lsprotocol import types
from pygls.uris import from_fs_path, to_fs_path
from pygls.workspace.position_codec import PositionCodec

from edsconv.config import ConfigError, Resolver
from edsconv.eds.source import decode
from edsconv.lsp.analysis import Analysis, analyse
from edsconv.lsp.diagnostics import to_lsp
from edsconv.lsp.positions import Positions
from edsconv.lsp.settings import Settings
from edsconv.paths import EDS_SUFFIX, discover

#: A folder with more EDS files than this is checked up to this many (the rest named in the log).
MAX_FILES = 2000
#: A file larger than this is left to the editor (opened, it is checked like any document).
MAX_FILE_BYTES = 8 * 1024 * 1024
#: Symbols named after what they describe; other entries are found by keyword.
_SYMBOL_KINDS = {"Param": types.SymbolKind.Variable, "Assem": types.SymbolKind.Struct,
                 "Connection": types.SymbolKind.Event}


@dataclass(frozen=True, slots=True)
class Symbol:
    """An entry worth finding across the workspace: its keyword, what it is called, where it is."""

    keyword: str
    name: str
    kind: types.SymbolKind
    line: int
    column: int


@dataclass(frozen=True, slots=True)
class Checked:
    """What is kept of one file on disk after its check."""

    stamp: tuple[int, int]
    diagnostics: list[types.Diagnostic]
    symbols: list[Symbol]


def eds_files(folders: Iterable[str]) -> list[str]:
    """The EDS files of the workspace folders, as ``edsconv lint`` finds them, at most :data:`MAX_FILES`."""
    existing = [folder for folder in folders if folder and os.path.isdir(folder)]
    try:
        found = discover(existing, Resolver()).files if existing else []
    except ConfigError:
        found = discover(existing).files if existing else []
    return found[:MAX_FILES]


def symbols_of(analysis: Analysis) -> list[Symbol]:
    """The sections' defined entries (parameters, assemblies, connections and other numbered entries)."""
    device = analysis.device
    found = []
    for keyword, entry in analysis.definitions.items():
        family = keyword.rstrip("0123456789")
        described = device.parameters.get(keyword) or device.assemblies.get(keyword) or \
            device.connections.get(keyword)
        name = getattr(described, "name", None) or ""
        found.append(Symbol(keyword, name, _SYMBOL_KINDS.get(family, types.SymbolKind.Field), entry.line,
                            entry.column))
    return found


def matches(query: str, symbol: Symbol) -> bool:
    """Every character of ``query`` in order, in the keyword or the name (case ignored): as editors filter."""
    text = f"{symbol.keyword} {symbol.name}".lower()
    position = 0
    for char in query.lower():
        position = text.find(char, position) + 1
        if position == 0:
            return False
    return True


def _stamp(path: str) -> tuple[int, int] | None:
    try:
        status = os.stat(path)
    except OSError:
        return None
    return status.st_mtime_ns, status.st_size


class WorkspaceChecker:
    """Checks the files of the workspace folders and keeps what their checks found."""

    def __init__(self, publish: Callable[[str, list[types.Diagnostic]], None],
                 settings: Callable[[str], Settings], position_codec: Callable[[], PositionCodec]) -> None:
        self._publish = publish
        self._settings = settings
        self._codec = position_codec
        self._checked: dict[str, Checked] = {}
        self._task: asyncio.Task | None = None

    def start(self, folders: list[str], is_open: Callable[[str], bool]) -> asyncio.Task:
        """Check every file of ``folders`` in the background (a check already running is replaced)."""
        if self._task is not None:
            self._task.cancel()
        self._task = asyncio.ensure_future(self._check_all(folders, is_open))
        return self._task

    def closed(self, uri: str, folders: list[str]) -> None:
        """A document was closed: a file of the folders is checked again as it is on disk."""
        path = to_fs_path(uri)
        if path and path.lower().endswith(EDS_SUFFIX) and \
                any(os.path.commonpath([folder, path]) == folder for folder in folders if folder):
            asyncio.ensure_future(self.check(path, changed=True))

    async def _check_all(self, folders: list[str], is_open: Callable[[str], bool]) -> list[str]:
        loop = asyncio.get_running_loop()
        paths = await loop.run_in_executor(None, eds_files, folders)
        for path in paths:
            if not is_open(self.uri(path)):
                await self.check(path)
        return paths

    async def reports(self, folders: list[str], is_open: Callable[[str], bool],
                      previous: dict[str, str]) -> list[types.WorkspaceDocumentDiagnosticReport]:
        """``workspace/diagnostic``: a report for each file of the folders no editor has open, "unchanged"
        where the client's ``previous`` result id (by URI) is the file's size and time of its last check."""
        if self._task is not None and not self._task.done():
            await asyncio.shield(self._task)  # the background check fills what the reports are made of
        found = []
        for path in await self._check_all(folders, is_open):
            uri, checked = self.uri(path), self._checked.get(path)
            if checked is None or is_open(uri):
                continue
            result_id = f"{checked.stamp[0]}-{checked.stamp[1]}"
            found.append(types.WorkspaceUnchangedDocumentDiagnosticReport(uri=uri, result_id=result_id)
                         if previous.get(uri) == result_id else
                         types.WorkspaceFullDocumentDiagnosticReport(uri=uri, items=checked.diagnostics,
                                                                     result_id=result_id))
        return found

    async def check(self, path: str, changed: bool = False) -> None:
        """Check the file at ``path`` as it is on disk and publish; unless ``changed``, a file whose
        size and time are those of its last check is not read again."""
        stamp = _stamp(path)
        if stamp is None or stamp[1] > MAX_FILE_BYTES:
            return
        known = self._checked.get(path)
        if known is None or known.stamp != stamp or changed:
            loop = asyncio.get_running_loop()
            known = await loop.run_in_executor(None, self._checked_file, path, stamp)
            if known is None:
                return
            self._checked[path] = known
        self._publish(self.uri(path), known.diagnostics)

    def _checked_file(self, path: str, stamp: tuple[int, int]) -> Checked | None:
        try:
            text = decode(Path(path).read_bytes()).text
        except OSError:
            return None
        analysis = analyse(text, None, path)
        positions = Positions(self._codec(), analysis.lines)
        uri = self.uri(path)
        shown = self._settings(uri).kept(analysis.eds, analysis.diagnostics, analysis.directives)
        return Checked(stamp, [to_lsp(d, analysis, positions) for d in shown], symbols_of(analysis))

    @staticmethod
    def uri(path: str) -> str:
        return from_fs_path(os.path.abspath(path)) or path

    def symbols(self) -> Iterable[tuple[str, Symbol]]:
        """Every symbol of every checked file on disk, with the file's URI."""
        for path, checked in self._checked.items():
            uri = self.uri(path)
            for symbol in checked.symbols:
                yield uri, symbol
