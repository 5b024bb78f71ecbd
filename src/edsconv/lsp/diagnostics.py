"""edsconv diagnostics as LSP diagnostics, and their publication: on open and save at once,
on change after a pause in typing (the latest text wins; an older analysis is never published)."""

from __future__ import annotations

import asyncio
import functools
from collections.abc import Callable

from lsprotocol import types
from pygls.lsp.server import LanguageServer

from edsconv.diagnostics import Diagnostic, Severity
from edsconv.eds.locate import value_end
from edsconv.lsp.analysis import Analyses, Analysis, Superseded
from edsconv.lsp.positions import Positions
from edsconv.lsp.settings import Settings

SOURCE = "edsconv"
#: Seconds without a change before a changed document is checked again: short, since a newer change
#: stops the check of an older text (lsp.analysis) and clients wait for a pause in typing themselves
#: (Neovim 150 ms, eglot 0.5 s) before they send the change.
CHANGE_DELAY = 0.05
_SEVERITY = {Severity.ERROR: types.DiagnosticSeverity.Error, Severity.WARNING: types.DiagnosticSeverity.Warning,
             Severity.INFO: types.DiagnosticSeverity.Information}


@functools.cache
def rule_documentation_url(code: str) -> str:
    """Where a rule is documented (the ``codeDescription`` link): :func:`edsconv.report.rule_help_uri`."""
    from edsconv.report import rule_help_uri

    return rule_help_uri(code)


def to_lsp(diagnostic: Diagnostic, analysis: Analysis, positions: Positions) -> types.Diagnostic:
    line = max(diagnostic.line, 1)
    column = max(diagnostic.column, 1)
    if diagnostic.end_line:
        end_line, end_column = diagnostic.end_line, diagnostic.end_column or column + 1
    else:
        end_line, end_column = line, max(value_end(analysis.line_text(line), column), column + 1)
    message = f"{diagnostic.message} [{diagnostic.clause}]" if diagnostic.clause else diagnostic.message
    return types.Diagnostic(
        range=positions.range(line, column, end_line, end_column),
        message=message,
        severity=_SEVERITY[diagnostic.severity],
        code=diagnostic.code,
        code_description=types.CodeDescription(href=rule_documentation_url(diagnostic.code)),
        source=SOURCE,
        data={"clause": diagnostic.clause},
    )


class Publisher:
    """Publishes the diagnostics of each document once its text has settled."""

    def __init__(self, server: LanguageServer, analyses: Analyses,
                 settings: Callable[[str], Settings], pulls: Callable[[], bool] = lambda: False) -> None:
        self._server = server
        self._analyses = analyses
        self._settings = settings
        #: True when the client pulls the diagnostics of its documents (``textDocument/diagnostic``):
        #: then nothing is pushed, or each problem would be shown twice
        self._pulls = pulls
        self._pending: dict[str, asyncio.Task] = {}
        #: the configuration errors already shown (each once, not on every keystroke)
        self._reported: set[str] = set()

    def schedule(self, uri: str, delay: float = 0.0) -> None:
        """Check ``uri`` after ``delay`` seconds; a newer call for the same document replaces this one."""
        if self._pulls():
            return
        pending = self._pending.pop(uri, None)
        if pending is not None:
            pending.cancel()
        self._pending[uri] = asyncio.ensure_future(self._publish(uri, delay))

    def clear(self, uri: str) -> None:
        pending = self._pending.pop(uri, None)
        if pending is not None:
            pending.cancel()
        if not self._pulls():
            self._server.text_document_publish_diagnostics(types.PublishDiagnosticsParams(uri=uri, diagnostics=[]))

    async def _publish(self, uri: str, delay: float) -> None:
        await asyncio.sleep(delay)
        if uri not in self._server.workspace.text_documents:
            return  # closed meanwhile
        document = self._server.workspace.get_text_document(uri)
        text, version = document.source, document.version
        try:
            analysis = await asyncio.shield(self._analyses.of(uri, text, version, document.path))
        except Superseded:
            return  # a newer text's own check publishes
        documents = self._server.workspace.text_documents
        if uri not in documents or documents[uri].source != text:
            return  # changed while it was being checked: the newer text's own check publishes
        items = self.items(uri, analysis)
        self._server.text_document_publish_diagnostics(
            types.PublishDiagnosticsParams(uri=uri, diagnostics=items, version=version))
        if self._pending.get(uri) is asyncio.current_task():
            del self._pending[uri]

    def items(self, uri: str, analysis: Analysis) -> list[types.Diagnostic]:
        """The LSP diagnostics of ``analysis`` that the document's settings report (pushed or pulled);
        a configuration that cannot be read is said once."""
        positions = Positions(self._server.workspace.position_codec, analysis.lines)
        settings = self._settings(uri)
        if settings.error is not None and settings.error not in self._reported:
            self._reported.add(settings.error)
            self._server.window_show_message(types.ShowMessageParams(
                types.MessageType.Warning, f"edsconv: the configuration cannot be read, the defaults apply: "
                                           f"{settings.error}"))
        shown = settings.kept(analysis.eds, analysis.diagnostics, analysis.directives)
        return [to_lsp(d, analysis, positions) for d in shown]
