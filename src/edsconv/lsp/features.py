"""The server's handlers for what an editor shows beside the text: semantic tokens, folding,
document highlight, reference counts, inlay hints, signature help, workspace symbols and
diagnostics, and the commands. Each hands over to its feature module."""

from __future__ import annotations

from typing import Any

from lsprotocol import types
from pygls.exceptions import JsonRpcInvalidParams, JsonRpcInvalidRequest
from pygls.uris import to_fs_path

from edsconv.lsp import commands, folding, inlay, semantic_tokens, signature, usage
from edsconv.lsp.positions import Positions
from edsconv.lsp.server import EdsLanguageServer
from edsconv.lsp.workspace import Symbol, matches, symbols_of

#: Pulled diagnostics: a document's depend on it alone; the workspace's files are reported too.
DIAGNOSTIC_OPTIONS = types.DiagnosticOptions(inter_file_dependencies=False, workspace_diagnostics=True,
                                             identifier="edsconv")


def register(server: EdsLanguageServer) -> None:
    _register_highlighting(server)
    _register_hints(server)
    _register_workspace(server)
    _register_commands(server)


def _register_highlighting(server: EdsLanguageServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_SEMANTIC_TOKENS_FULL, semantic_tokens.LEGEND)
    async def on_semantic_tokens(ls: EdsLanguageServer, params: types.SemanticTokensParams) -> types.SemanticTokens:
        analysis, positions = await ls.current(params.text_document.uri)
        return types.SemanticTokens(data=semantic_tokens.encode(semantic_tokens.tokens(analysis), positions))

    @server.feature(types.TEXT_DOCUMENT_SEMANTIC_TOKENS_RANGE, semantic_tokens.LEGEND)
    async def on_semantic_tokens_range(ls: EdsLanguageServer,
                                       params: types.SemanticTokensRangeParams) -> types.SemanticTokens:
        analysis, positions = await ls.current(params.text_document.uri)
        found = semantic_tokens.in_range(semantic_tokens.tokens(analysis), params.range.start.line + 1,
                                         params.range.end.line + 1)
        return types.SemanticTokens(data=semantic_tokens.encode(found, positions))

    @server.feature(types.TEXT_DOCUMENT_FOLDING_RANGE)
    async def on_folding(ls: EdsLanguageServer, params: types.FoldingRangeParams) -> list[types.FoldingRange]:
        analysis, _ = await ls.current(params.text_document.uri)
        return folding.folding_ranges(analysis)

    @server.feature(types.TEXT_DOCUMENT_DOCUMENT_HIGHLIGHT)
    async def on_highlight(ls: EdsLanguageServer,
                           params: types.DocumentHighlightParams) -> list[types.DocumentHighlight]:
        analysis, positions = await ls.current(params.text_document.uri)
        return usage.highlights(analysis, positions, *positions.from_client(params.position))


def _register_hints(server: EdsLanguageServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_CODE_LENS)
    async def on_code_lens(ls: EdsLanguageServer, params: types.CodeLensParams) -> list[types.CodeLens]:
        analysis, positions = await ls.current(params.text_document.uri)
        return usage.reference_lenses(analysis, positions)

    @server.feature(types.TEXT_DOCUMENT_INLAY_HINT)
    async def on_inlay_hint(ls: EdsLanguageServer, params: types.InlayHintParams) -> list[types.InlayHint]:
        analysis, positions = await ls.current(params.text_document.uri)
        return inlay.inlay_hints(analysis, positions, params.range.start.line + 1, params.range.end.line + 1)

    @server.feature(types.TEXT_DOCUMENT_SIGNATURE_HELP,
                    types.SignatureHelpOptions(trigger_characters=[",", "="], retrigger_characters=[","]))
    async def on_signature_help(ls: EdsLanguageServer,
                                params: types.SignatureHelpParams) -> types.SignatureHelp | None:
        analysis, positions = await ls.current(params.text_document.uri)
        return signature.signature_help(analysis, *positions.from_client(params.position))


def _register_workspace(server: EdsLanguageServer) -> None:
    @server.feature(types.INITIALIZED)
    def on_initialized(ls: EdsLanguageServer, params: types.InitializedParams) -> None:
        ls.workspace_checker.start(ls.folders(), lambda uri: uri in ls.workspace.text_documents)

    @server.feature(types.WORKSPACE_DID_CHANGE_WORKSPACE_FOLDERS)
    def on_folders_changed(ls: EdsLanguageServer, params: types.DidChangeWorkspaceFoldersParams) -> None:
        ls.workspace_checker.start(ls.folders(), lambda uri: uri in ls.workspace.text_documents)

    @server.feature(types.TEXT_DOCUMENT_DIAGNOSTIC, DIAGNOSTIC_OPTIONS)
    async def on_document_diagnostic(
            ls: EdsLanguageServer, params: types.DocumentDiagnosticParams) -> types.RelatedFullDocumentDiagnosticReport:
        analysis, _ = await ls.current(params.text_document.uri)
        return types.RelatedFullDocumentDiagnosticReport(items=ls.publisher.items(params.text_document.uri, analysis))

    @server.feature(types.WORKSPACE_DIAGNOSTIC)
    async def on_workspace_diagnostic(ls: EdsLanguageServer,
                                      params: types.WorkspaceDiagnosticParams) -> types.WorkspaceDiagnosticReport:
        previous = {p.uri: p.value for p in params.previous_result_ids}
        return types.WorkspaceDiagnosticReport(items=await ls.workspace_checker.reports(
            ls.folders(), lambda uri: uri in ls.workspace.text_documents, previous))

    @server.feature(types.WORKSPACE_SYMBOL)
    async def on_workspace_symbol(ls: EdsLanguageServer,
                                  params: types.WorkspaceSymbolParams) -> list[types.SymbolInformation]:
        found: list[tuple[str, Symbol, Positions | None]] = []
        for uri in list(ls.workspace.text_documents):
            analysis, positions = await ls.current(uri)
            found += [(uri, symbol, positions) for symbol in symbols_of(analysis)]
        found += [(uri, symbol, None) for uri, symbol in ls.workspace_checker.symbols()
                  if uri not in ls.workspace.text_documents]
        return [_symbol_information(uri, symbol, positions) for uri, symbol, positions in found
                if matches(params.query, symbol)]


def _symbol_information(uri: str, symbol: Symbol, positions: Positions | None) -> types.SymbolInformation:
    end = symbol.column + len(symbol.keyword)
    where = positions.range(symbol.line, symbol.column, symbol.line, end) if positions is not None else \
        types.Range(types.Position(symbol.line - 1, symbol.column - 1), types.Position(symbol.line - 1, end - 1))
    return types.SymbolInformation(name=f"{symbol.keyword} {symbol.name}".strip(), kind=symbol.kind,
                                   location=types.Location(uri, where))


def _register_commands(server: EdsLanguageServer) -> None:
    @server.command(commands.SHOW_DEVICE)
    async def show_device(ls: EdsLanguageServer, *args: Any) -> dict:
        analysis, _ = await ls.current(_uri(args))
        return commands.show_device(analysis, ls.show_renderer)

    @server.command(commands.CONVERT_TO_XML)
    async def convert_to_xml(ls: EdsLanguageServer, *args: Any) -> list[str]:
        uri = _uri(args)
        analysis, _ = await ls.current(uri)
        try:
            written = commands.convert_to_xml(analysis, to_fs_path(uri), force=len(args) > 1 and args[1] is True)
        except commands.CommandRefused as refusal:
            raise JsonRpcInvalidRequest(str(refusal)) from None
        ls.window_show_message(types.ShowMessageParams(types.MessageType.Info, "wrote " + ", ".join(written)))
        return written

    @server.command(commands.FIX_ALL)
    async def fix_all(ls: EdsLanguageServer, *args: Any) -> int:
        uri = _uri(args)
        analysis, positions = await ls.current(uri)
        edits = commands.fix_all(analysis, ls.settings(uri))
        if edits:
            text_edits = [types.TextEdit(positions.range(e.line, e.column, e.end_line, e.end_column), e.text)
                          for e in edits]
            ls.workspace_apply_edit(types.ApplyWorkspaceEditParams(
                types.WorkspaceEdit(changes={uri: text_edits}), label="edsconv: fix all"))
        return len(edits)


def _uri(args: tuple[Any, ...]) -> str:
    """The document URI a command names: its first argument, a string or ``{"uri": ...}``."""
    first = args[0] if args else None
    if isinstance(first, dict):
        first = first.get("uri")
    if not isinstance(first, str):
        raise JsonRpcInvalidParams("the command needs the document's URI as its first argument")
    return first
