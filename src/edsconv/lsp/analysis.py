"""One analysis of one version of a document: the syntax model, the typed model, every diagnostic
and every place that names an entry.

:class:`Analyses` keeps the latest analysis of each open document and runs new
ones in a worker thread, so that reading a large file never holds up the
messages the editor sends meanwhile. An analysis asked for twice (diagnostics
and a hover on the same version) runs once.
"""

from __future__ import annotations

import asyncio
import functools
import re
import traceback
from dataclasses import dataclass, field

import edsconv
from edsconv.diagnostics import Diagnostic
from edsconv.eds.syntax import EdsFile, Entry
from edsconv.model import Device
from edsconv.model.references import Occurrence, definitions, occurrences

#: A line and its line end: LSP breaks lines at \r\n, \r and \n only (as the EDS reader does).
_LINE = re.compile(r"[^\r\n]*(?:\r\n|\r|\n)|[^\r\n]+$")


@dataclass(slots=True)
class Analysis:
    version: int | None
    text: str
    #: the lines of ``text`` with their line ends, as LSP counts them
    lines: tuple[str, ...]
    eds: EdsFile
    device: Device
    diagnostics: list[Diagnostic]
    #: every place that names an entry (hover and navigation)
    spans: list[Occurrence] = field(repr=False)
    #: the entries references can name, by keyword
    definitions: dict[str, Entry] = field(repr=False)

    def line_text(self, line: int) -> str:
        """Line ``line`` (1-based) without its line end; "" beyond the end."""
        return self.lines[line - 1].rstrip("\r\n") if 0 < line <= len(self.lines) else ""


def split_lines(text: str) -> tuple[str, ...]:
    """The lines of ``text`` with their line ends, as LSP counts them."""
    return tuple(_LINE.findall(text))


def analyse(text: str, version: int | None = None, path: str | None = None) -> Analysis:
    """Read and check ``text``; a failure of edsconv itself becomes an EDS000 diagnostic, never an exception."""
    from edsconv.lint import INTERNAL_ERROR

    lines = split_lines(text)
    eds = edsconv.parse(text, path)
    try:
        device, diagnostics = edsconv.analyse(eds)
    except Exception as error:  # noqa: BLE001 - the editor gets a diagnostic, the server keeps running
        where = traceback.extract_tb(error.__traceback__)[-1]
        message = f"internal error {type(error).__name__}: {error} (at {where.name}:{where.lineno}); please report it"
        device, diagnostics = Device(eds=eds), [*eds.diagnostics, Diagnostic.of(INTERNAL_ERROR, message, 1, 1, path)]
    diagnostics.sort(key=lambda d: (d.line, d.column))
    return Analysis(version, text, lines, eds, device, diagnostics, occurrences(eds, device, lines),
                    definitions(device))


class Analyses:
    """The latest analysis of each document, by URI."""

    def __init__(self) -> None:
        self._latest: dict[str, tuple[str, asyncio.Future[Analysis]]] = {}

    def of(self, uri: str, text: str, version: int | None, path: str | None) -> asyncio.Future[Analysis]:
        """The analysis of this text, started in a worker thread unless it already runs or ran."""
        known = self._latest.get(uri)
        if known is not None and known[0] == text and not known[1].cancelled():
            return known[1]
        loop = asyncio.get_running_loop()
        future = loop.run_in_executor(None, functools.partial(analyse, text, version, path))
        self._latest[uri] = (text, future)
        return future

    def forget(self, uri: str) -> None:
        self._latest.pop(uri, None)
