"""Pulled diagnostics (LSP 3.17), end to end through a real client that declares it pulls them: the
server answers ``textDocument/diagnostic`` and ``workspace/diagnostic`` and pushes nothing, so no
problem is shown twice; a client that does not pull gets pushes (tests/test_lsp_features.py)."""

from __future__ import annotations

import pytest

pytest.importorskip("pygls")
pytest_lsp = pytest.importorskip("pytest_lsp")

from lsprotocol import types  # noqa: E402
from pytest_lsp import LanguageClient  # noqa: E402

from lsp_support import BROKEN, EXAMPLE, SERVER, open_workspace  # noqa: E402

pytestmark = pytest.mark.asyncio(loop_scope="module")

STATE: dict = {}


@pytest_lsp.fixture(scope="module", config=SERVER)
async def client(lsp_client: LanguageClient, tmp_path_factory: pytest.TempPathFactory):
    folder = STATE["folder"] = tmp_path_factory.mktemp("pulled")
    capabilities = types.ClientCapabilities(
        text_document=types.TextDocumentClientCapabilities(diagnostic=types.DiagnosticClientCapabilities()),
        workspace=types.WorkspaceClientCapabilities(diagnostics=types.DiagnosticWorkspaceClientCapabilities(
            refresh_support=True)))
    STATE["initialize"] = await open_workspace(lsp_client, folder, "broken.eds", capabilities)
    yield
    await lsp_client.shutdown_session()


async def test_the_server_offers_document_and_workspace_pulls(client: LanguageClient):
    provider = STATE["initialize"].capabilities.diagnostic_provider
    assert provider.workspace_diagnostics and not provider.inter_file_dependencies
    assert provider.identifier == "edsconv"


async def test_a_document_is_pulled_not_pushed(client: LanguageClient):
    uri = "file:///edsconv-lsp-pull/open.eds"
    client.text_document_did_open(types.DidOpenTextDocumentParams(
        types.TextDocumentItem(uri=uri, language_id="eds", version=1, text=BROKEN)))
    report = await client.text_document_diagnostic_async(types.DocumentDiagnosticParams(
        types.TextDocumentIdentifier(uri)))
    assert [(d.code, d.range.start.line) for d in report.items] == [("EDS301", 94)]
    assert uri not in client.diagnostics  # nothing was pushed beside the pull


async def test_the_workspace_files_are_pulled_with_unchanged_reports_for_unchanged_files(client: LanguageClient):
    broken, adapter = (STATE["folder"] / "broken.eds").as_uri(), (STATE["folder"] / "adapter.eds").as_uri()
    report = await client.workspace_diagnostic_async(types.WorkspaceDiagnosticParams(previous_result_ids=[]))
    by_uri = {item.uri: item for item in report.items}
    assert sorted(by_uri) == sorted([adapter, broken])
    assert [d.code for d in by_uri[broken].items] == ["EDS301"] and list(by_uri[adapter].items) == []
    again = await client.workspace_diagnostic_async(types.WorkspaceDiagnosticParams(previous_result_ids=[
        types.PreviousResultId(uri, item.result_id) for uri, item in by_uri.items()]))
    assert {item.uri: item.kind for item in again.items} == {adapter: "unchanged", broken: "unchanged"}
    (STATE["folder"] / "broken.eds").write_text(EXAMPLE)  # fixed on disk: a full report again, now empty
    fixed = await client.workspace_diagnostic_async(types.WorkspaceDiagnosticParams(previous_result_ids=[
        types.PreviousResultId(uri, item.result_id) for uri, item in by_uri.items()]))
    kinds = {item.uri: (item.kind, list(getattr(item, "items", []))) for item in fixed.items}
    assert kinds == {adapter: ("unchanged", []), broken: ("full", [])}
    assert broken not in client.diagnostics and adapter not in client.diagnostics  # never pushed
