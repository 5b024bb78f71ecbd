"""The language server: documents in a workspace, diagnostics on open, change and save, and one
small handler per LSP method, each handing over to a feature module.

Every request works on the analysis of the document's current text (started
in a worker thread, shared with the diagnostics of the same text), so answers
never lag behind the text the editor shows; hover, completion and navigation
answer as soon as its models are made, before its checks. A request whose text
is superseded by a change before its analysis is done gets ContentModified
(the client asks again, or not); ``$/cancelRequest`` answers RequestCancelled
and leaves the shared analysis running for the others.
"""

from __future__ import annotations

import asyncio
import gc
import sys
from importlib import metadata

from lsprotocol import types
from pygls.exceptions import JsonRpcContentModified, JsonRpcException
from pygls.lsp.server import LanguageServer
from pygls.uris import to_fs_path

from edsconv.lsp import actions, completion, hover, navigation, symbols
from edsconv.lsp.analysis import Analyses, Analysis, Superseded
from edsconv.lsp.commands import ShowRenderer
from edsconv.lsp.diagnostics import CHANGE_DELAY, Publisher
from edsconv.lsp.document import LspProtocol
from edsconv.lsp.positions import Positions
from edsconv.lsp.settings import Settings, settings_for
from edsconv.lsp.workspace import WorkspaceChecker

NAME = "edsconv"
#: The configuration files edsconv lint reads (docs/lint.md): a change to one re-checks every open document.
CONFIGURATION_FILES = ("edsconv.toml", "pyproject.toml")


class RequestFailed(JsonRpcException):
    """LSP's RequestFailed: a valid request the server declines (a refused rename), the reason in the message."""

    CODE = types.LSPErrorCodes.RequestFailed.value


class EdsLanguageServer(LanguageServer):
    def __init__(self, show_renderer: ShowRenderer | None = None) -> None:
        try:
            version = metadata.version("edsconv")
        except metadata.PackageNotFoundError:
            version = "0"
        super().__init__(NAME, version, text_document_sync_kind=types.TextDocumentSyncKind.Incremental,
                         protocol_cls=LspProtocol)
        self.analyses = Analyses()
        self.publisher = Publisher(self, self.analyses, self.settings, lambda: self.pulls)
        self.show_renderer = show_renderer
        self.workspace_checker = WorkspaceChecker(self.publish_file, self.settings,
                                                  lambda: self.workspace.position_codec)
        self._watching = False

    @property
    def pulls(self) -> bool:
        """True when the client pulls diagnostics (``textDocument/diagnostic``, LSP 3.17): the server then
        answers its pulls and pushes nothing."""
        text_document = self.client_capabilities.text_document
        return text_document is not None and text_document.diagnostic is not None

    def refresh_pulled(self) -> None:
        """Ask a client that pulls diagnostics to pull them again (the configuration changed), if it can be asked."""
        workspace = self.client_capabilities.workspace
        if self.pulls and workspace is not None and workspace.diagnostics is not None and \
                workspace.diagnostics.refresh_support:
            self.workspace_diagnostic_refresh(None)

    def publish_file(self, uri: str, diagnostics: list[types.Diagnostic]) -> None:
        """Publish the diagnostics of a file no editor has open (the workspace's background check)."""
        if not self.pulls and uri not in self.workspace.text_documents:
            self.text_document_publish_diagnostics(types.PublishDiagnosticsParams(uri=uri, diagnostics=diagnostics))

    def folders(self) -> list[str]:
        """The paths of the workspace folders."""
        return [to_fs_path(folder.uri) or "" for folder in self.workspace.folders.values()]

    def settings(self, uri: str) -> Settings:
        return settings_for(to_fs_path(uri), self.folders())

    def watch_configuration(self) -> None:
        """Ask the client, once, to report changes of the configuration files (when it can watch files; else
        edits and saves re-read them). Asked at the first opened document, not on ``initialized``, which
        the workspace features handle."""
        workspace = self.client_capabilities.workspace
        watching = workspace and workspace.did_change_watched_files
        if self._watching or not (watching and watching.dynamic_registration):
            return
        self._watching = True
        watchers = [types.FileSystemWatcher(glob_pattern=f"**/{name}") for name in CONFIGURATION_FILES]
        self.client_register_capability(types.RegistrationParams([types.Registration(
            "edsconv-configuration", types.WORKSPACE_DID_CHANGE_WATCHED_FILES,
            types.DidChangeWatchedFilesRegistrationOptions(watchers))]))

    def formatting(self, analysis: Analysis, positions: Positions, edits: list[actions.Edit]) -> list[types.TextEdit]:
        """``edits`` as LSP text edits; when formatting is refused, the reason shown to the user instead."""
        refusal = actions.format_refusal(analysis)
        if refusal is not None:
            self.window_show_message(types.ShowMessageParams(types.MessageType.Warning, refusal))
        return [types.TextEdit(positions.range(e.line, e.column, e.end_line, e.end_column), e.text) for e in edits]

    async def current(self, uri: str, readable: bool = False) -> tuple[Analysis, Positions]:
        """The analysis of the document's text as it is now, and its position converter; with ``readable``
        as soon as its models and references are made (its diagnostics may still be empty)."""
        document = self.workspace.get_text_document(uri)
        analyses = self.analyses.readable if readable else self.analyses.of
        try:  # shielded: a cancelled request must not cancel what other requests and the diagnostics share
            analysis = await asyncio.shield(analyses(uri, document.source, document.version, document.path))
        except Superseded:
            raise JsonRpcContentModified(f"{uri} changed before its version {document.version} was read") from None
        return analysis, Positions(self.workspace.position_codec, analysis.lines)


def create_server(show_renderer: ShowRenderer | None = None) -> EdsLanguageServer:
    """A server with every feature registered; ``start_io()`` runs it on stdin/stdout.

    ``show_renderer`` lays out the show document as text for the ``edsconv.showDevice`` command
    (the command line's layout; without it the command answers with the document only).
    """
    from edsconv.lsp import features  # it names this module's server class in its handlers' annotations

    # The analysis thread holds the interpreter lock between the steps of reading a message, which pygls
    # does in a thread of its own: hand the lock over every 0.5 ms instead of 5 ms, so that the messages
    # a long analysis (which they may supersede) is running beside come in when sent.
    sys.setswitchinterval(0.0005)
    gc.disable()  # the analyses collect their garbage in the pauses of typing (lsp.analysis.Analyses)
    server = EdsLanguageServer(show_renderer)
    _register_documents(server)
    _register_reading(server)
    _register_editing(server)
    features.register(server)
    return server


def _register_documents(server: EdsLanguageServer) -> None:
    @server.feature(types.WORKSPACE_DID_CHANGE_WATCHED_FILES)
    def did_change_watched_files(ls: EdsLanguageServer, params: types.DidChangeWatchedFilesParams) -> None:
        if any(change.uri.rsplit("/", 1)[-1] in CONFIGURATION_FILES for change in params.changes):
            for uri in list(ls.workspace.text_documents):
                ls.publisher.schedule(uri)
            ls.refresh_pulled()

    @server.feature(types.TEXT_DOCUMENT_DID_OPEN)
    def did_open(ls: EdsLanguageServer, params: types.DidOpenTextDocumentParams) -> None:
        ls.watch_configuration()
        ls.publisher.schedule(params.text_document.uri)

    @server.feature(types.TEXT_DOCUMENT_DID_CHANGE)
    def did_change(ls: EdsLanguageServer, params: types.DidChangeTextDocumentParams) -> None:
        ls.analyses.forget(params.text_document.uri)
        ls.publisher.schedule(params.text_document.uri, CHANGE_DELAY)

    @server.feature(types.TEXT_DOCUMENT_DID_SAVE)
    def did_save(ls: EdsLanguageServer, params: types.DidSaveTextDocumentParams) -> None:
        ls.publisher.schedule(params.text_document.uri)

    @server.feature(types.TEXT_DOCUMENT_DID_CLOSE)
    def did_close(ls: EdsLanguageServer, params: types.DidCloseTextDocumentParams) -> None:
        ls.publisher.clear(params.text_document.uri)
        ls.analyses.forget(params.text_document.uri, closed=True)
        ls.workspace_checker.closed(params.text_document.uri, ls.folders())


def _register_reading(server: EdsLanguageServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_HOVER)
    async def on_hover(ls: EdsLanguageServer, params: types.HoverParams) -> types.Hover | None:
        analysis, positions = await ls.current(params.text_document.uri, readable=True)
        found = hover.hover(analysis, *positions.from_client(params.position))
        if found is None:
            return None
        text, span = found
        hover_capabilities = ls.client_capabilities.text_document and ls.client_capabilities.text_document.hover
        formats = (hover_capabilities and hover_capabilities.content_format) or [types.MarkupKind.Markdown]
        if formats[0] is types.MarkupKind.PlainText or types.MarkupKind.Markdown not in formats:
            return types.Hover(types.MarkupContent(types.MarkupKind.PlainText, hover.plain_text(text)),
                               positions.range(*span))
        return types.Hover(types.MarkupContent(types.MarkupKind.Markdown, text), positions.range(*span))

    @server.feature(types.TEXT_DOCUMENT_DEFINITION)
    async def on_definition(ls: EdsLanguageServer, params: types.DefinitionParams) -> types.Location | None:
        analysis, positions = await ls.current(params.text_document.uri, readable=True)
        span = navigation.definition(analysis, *positions.from_client(params.position))
        return None if span is None else types.Location(params.text_document.uri, positions.range(*span))

    @server.feature(types.TEXT_DOCUMENT_REFERENCES)
    async def on_references(ls: EdsLanguageServer, params: types.ReferenceParams) -> list[types.Location]:
        analysis, positions = await ls.current(params.text_document.uri, readable=True)
        spans = navigation.references(analysis, *positions.from_client(params.position),
                                      params.context.include_declaration)
        return [types.Location(params.text_document.uri, positions.range(*span)) for span in spans]

    @server.feature(types.TEXT_DOCUMENT_DOCUMENT_SYMBOL)
    async def on_symbols(ls: EdsLanguageServer, params: types.DocumentSymbolParams) -> list[types.DocumentSymbol]:
        analysis, positions = await ls.current(params.text_document.uri, readable=True)
        return symbols.document_symbols(analysis, positions)

    @server.feature(types.TEXT_DOCUMENT_COMPLETION, types.CompletionOptions(trigger_characters=["[", ","]))
    async def on_completion(ls: EdsLanguageServer, params: types.CompletionParams) -> types.CompletionList:
        analysis, positions = await ls.current(params.text_document.uri, readable=True)
        items = completion.completions(analysis, *positions.from_client(params.position))
        return types.CompletionList(is_incomplete=False, items=items)


def _register_editing(server: EdsLanguageServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_PREPARE_RENAME)
    async def on_prepare_rename(ls: EdsLanguageServer,
                                params: types.PrepareRenameParams) -> types.PrepareRenamePlaceholder | None:
        analysis, positions = await ls.current(params.text_document.uri, readable=True)
        found = navigation.target_at(analysis, *positions.from_client(params.position))
        if found is None:
            return None
        return types.PrepareRenamePlaceholder(positions.range(*navigation.span_of(found)), found.target)

    @server.feature(types.TEXT_DOCUMENT_RENAME)
    async def on_rename(ls: EdsLanguageServer, params: types.RenameParams) -> types.WorkspaceEdit:
        analysis, positions = await ls.current(params.text_document.uri, readable=True)
        try:
            edits = navigation.rename(analysis, *positions.from_client(params.position), params.new_name)
        except navigation.RenameRefused as refusal:
            raise RequestFailed(str(refusal)) from None
        return types.WorkspaceEdit(changes={params.text_document.uri: [
            types.TextEdit(positions.range(*span), text) for span, text in edits]})

    @server.feature(types.TEXT_DOCUMENT_FORMATTING)
    async def on_formatting(ls: EdsLanguageServer, params: types.DocumentFormattingParams) -> list[types.TextEdit]:
        analysis, positions = await ls.current(params.text_document.uri, readable=True)
        return ls.formatting(analysis, positions, actions.formatting_edits(analysis))

    @server.feature(types.TEXT_DOCUMENT_RANGE_FORMATTING)
    async def on_range_formatting(ls: EdsLanguageServer,
                                  params: types.DocumentRangeFormattingParams) -> list[types.TextEdit]:
        analysis, positions = await ls.current(params.text_document.uri, readable=True)
        first, _ = positions.from_client(params.range.start)
        last, column = positions.from_client(params.range.end)
        if column == 1 and last > first:  # a range ending at a line start leaves that line out
            last -= 1
        return ls.formatting(analysis, positions, actions.range_formatting_edits(analysis, first, last))

    @server.feature(types.TEXT_DOCUMENT_CODE_ACTION,
                    types.CodeActionOptions(code_action_kinds=[types.CodeActionKind.QuickFix]))
    async def on_code_action(ls: EdsLanguageServer, params: types.CodeActionParams) -> list[types.CodeAction]:
        analysis, positions = await ls.current(params.text_document.uri)
        found = []
        for diagnostic in params.context.diagnostics:
            if diagnostic.source != "edsconv" or not isinstance(diagnostic.code, str):
                continue
            line, column = positions.from_client(diagnostic.range.start)
            fixes = actions.lint_fixes(analysis, diagnostic.code, line, column)
            suppress = actions.suppression(analysis, diagnostic.code, line, column)
            found += [_code_action(fix, diagnostic, params.text_document.uri, positions, preferred=True)
                      for fix in fixes]
            if suppress is not None:
                found.append(_code_action(suppress, diagnostic, params.text_document.uri, positions))
        return found


def _code_action(fix: actions.Fix, diagnostic: types.Diagnostic, uri: str, positions: Positions,
                 preferred: bool = False) -> types.CodeAction:
    edits = [types.TextEdit(positions.range(e.line, e.column, e.end_line, e.end_column), e.text) for e in fix.edits]
    return types.CodeAction(title=fix.title, kind=types.CodeActionKind.QuickFix, diagnostics=[diagnostic],
                            edit=types.WorkspaceEdit(changes={uri: edits}), is_preferred=preferred or None)
