"""What the language server shows beside the text, end to end through a real LSP client (pytest-lsp):
semantic tokens, folding, document highlight, reference counts, inlay hints, signature help, workspace
symbols and diagnostics of files no editor has open, and the commands."""

from __future__ import annotations

from pathlib import Path

import pytest

pytest.importorskip("pygls")
pytest_lsp = pytest.importorskip("pytest_lsp")

from lsprotocol import types  # noqa: E402
from pytest_lsp import LanguageClient  # noqa: E402

from edsconv.lsp.semantic_tokens import TOKEN_MODIFIERS, TOKEN_TYPES  # noqa: E402
from lsp_support import EXAMPLE, SERVER, open_workspace  # noqa: E402

pytestmark = pytest.mark.asyncio(loop_scope="module")

STATE: dict = {}


@pytest_lsp.fixture(scope="module", config=SERVER)
async def client(lsp_client: LanguageClient, tmp_path_factory: pytest.TempPathFactory):
    folder = STATE["folder"] = tmp_path_factory.mktemp("workspace")
    STATE["edits"] = []

    @lsp_client.feature(types.WORKSPACE_APPLY_EDIT)
    def apply_edit(params: types.ApplyWorkspaceEditParams) -> types.ApplyWorkspaceEditResult:
        STATE["edits"].append(params)
        return types.ApplyWorkspaceEditResult(applied=True)

    STATE["initialize"] = await open_workspace(lsp_client, folder, "sub/broken.eds", types.ClientCapabilities())
    yield
    await lsp_client.shutdown_session()


async def opened(client: LanguageClient, name: str, text: str = EXAMPLE) -> str:
    uri = f"file:///edsconv-lsp-features/{name}.eds"
    client.text_document_did_open(types.DidOpenTextDocumentParams(
        types.TextDocumentItem(uri=uri, language_id="eds", version=1, text=text)))
    return uri


def doc(uri: str) -> types.TextDocumentIdentifier:
    return types.TextDocumentIdentifier(uri=uri)


def whole(lines: int = 200) -> types.Range:
    return types.Range(types.Position(0, 0), types.Position(lines, 0))


async def test_initialize_announces_the_features_and_commands(client: LanguageClient):
    capabilities = STATE["initialize"].capabilities
    legend = capabilities.semantic_tokens_provider.legend
    assert (tuple(legend.token_types), tuple(legend.token_modifiers)) == (TOKEN_TYPES, TOKEN_MODIFIERS)
    assert capabilities.semantic_tokens_provider.range
    assert capabilities.folding_range_provider and capabilities.document_highlight_provider
    assert capabilities.code_lens_provider is not None and capabilities.inlay_hint_provider
    assert tuple(capabilities.signature_help_provider.trigger_characters) == (",", "=")
    assert capabilities.workspace_symbol_provider
    assert sorted(capabilities.execute_command_provider.commands) == [
        "edsconv.convertToXml", "edsconv.fixAll", "edsconv.showDevice"]


def decoded(data: list[int], lines: list[str]) -> list[tuple[int, str, str, set[str]]]:
    """(0-based line, the token's text, type, modifiers) of LSP's relative encoding."""
    found, line, start = [], 0, 0
    for index in range(0, len(data), 5):
        delta_line, delta_start, length, kind, modifiers = data[index:index + 5]
        line, start = line + delta_line, (start + delta_start if delta_line == 0 else delta_start)
        names = {name for bit, name in enumerate(TOKEN_MODIFIERS) if modifiers >> bit & 1}
        found.append((line, lines[line][start:start + length], TOKEN_TYPES[kind], names))
    return found


async def test_semantic_tokens_name_each_word_as_the_reader_reads_it(client: LanguageClient):
    text = EXAMPLE.replace("        Revision = 2;\n        Assem100 =",
                           "        Revision = 2;\n        Assem100\n        =   $ its = on the next line\n")
    uri = await opened(client, "tokens", text)
    result = await client.text_document_semantic_tokens_full_async(types.SemanticTokensParams(doc(uri)))
    tokens = decoded(result.data, text.splitlines())
    assert (3, "[File]", "namespace", set()) in tokens
    assert (4, "DescText", "property", set()) in tokens
    assert (4, "=", "operator", set()) in tokens
    assert (4, '"edsconv example I/O adapter"', "string", set()) in tokens
    assert (0, tokens[0][1], "comment", set()) == tokens[0]
    assert (5, "11-22-2026", "number", set()) in tokens
    assert any(t[1:3] == ("Assem100", "property") for t in tokens)  # its = on the next line
    assert any(t[1:] == ("Param1", "property", {"declaration"}) for t in tokens)
    assert any(t[1:] == ("$ its = on the next line", "comment", set()) for t in tokens)
    assert any(t[1:] == ("Param2", "variable", set()) for t in tokens)  # a reference
    ranged = await client.text_document_semantic_tokens_range_async(types.SemanticTokensRangeParams(
        doc(uri), types.Range(types.Position(3, 0), types.Position(4, 80))))
    assert [t[1] for t in decoded(ranged.data, text.splitlines())] == [
        "[File]", "DescText", "=", '"edsconv example I/O adapter"']


async def test_folding_ranges_cover_sections_entries_and_comment_blocks(client: LanguageClient):
    uri = await opened(client, "folding")
    ranges = await client.text_document_folding_range_async(types.FoldingRangeParams(doc(uri)))
    found = {(r.start_line, r.end_line, r.kind) for r in ranges}
    lines = EXAMPLE.splitlines()
    assembly = lines.index("[Assembly]")
    assert (0, 1, types.FoldingRangeKind.Comment) in found
    assert (assembly, lines.index("                8,Param3;"), types.FoldingRangeKind.Region) in found
    assert (assembly + 2, assembly + 9, None) in found  # Assem100, written over eight lines
    assert all(r.end_line > r.start_line for r in ranges)


async def test_document_highlight_marks_every_use_of_the_parameter(client: LanguageClient):
    uri = await opened(client, "highlight")
    lines = EXAMPLE.splitlines()
    member = lines.index("                8,Param2,")
    highlights = await client.text_document_document_highlight_async(types.DocumentHighlightParams(
        doc(uri), types.Position(member, 20)))
    kinds = {(h.range.start.line, h.kind) for h in highlights}
    assert (lines.index("        Param2 ="), types.DocumentHighlightKind.Write) in kinds
    assert (member, types.DocumentHighlightKind.Read) in kinds
    assert len(highlights) == 4
    nothing = await client.text_document_document_highlight_async(types.DocumentHighlightParams(
        doc(uri), types.Position(4, 30)))
    assert not nothing


async def test_code_lenses_count_the_references_of_each_definition(client: LanguageClient):
    uri = await opened(client, "lens")
    lenses = await client.text_document_code_lens_async(types.CodeLensParams(doc(uri)))
    lines = EXAMPLE.splitlines()
    by_line = {lens.range.start.line: lens.command.title for lens in lenses}
    assert by_line[lines.index("        Param1 =")] == "4 references"
    assert by_line[lines.index("        Param4 =")] == "1 reference"
    assert by_line[lines.index("        Connection1 =")] == "no references"


async def test_inlay_hints_name_references_types_and_bits(client: LanguageClient):
    uri = await opened(client, "inlay")
    hints = await client.text_document_inlay_hint_async(types.InlayHintParams(doc(uri), whole()))
    lines = EXAMPLE.splitlines()
    by_line: dict[int, list[str]] = {}
    for hint in hints:
        by_line.setdefault(hint.position.line, []).append(hint.label)
    assert by_line[lines.index("                8,Param2,")] == ["'Input Filter'"]
    assert "UDINT" in by_line[lines.index("                0xC8,                   $ Data Type: UDINT")]
    trigger = next(i for i, line in enumerate(lines) if line.strip().startswith("0x04010002"))
    assert by_line[trigger] == ["class 1, cyclic, exclusive-owner"]
    assert lines.index("                0x0000,") not in by_line  # a descriptor setting no bit says nothing
    ranged = await client.text_document_inlay_hint_async(types.InlayHintParams(doc(uri), types.Range(
        types.Position(trigger, 0), types.Position(trigger, 80))))
    assert [h.label for h in ranged] == ["class 1, cyclic, exclusive-owner"]


async def test_signature_help_names_the_field_under_the_cursor(client: LanguageClient):
    typed = '        Assem7 = "x", , 16, 0x0000'
    text = EXAMPLE.replace("                8,Param3;", f"                8,Param3;\n{typed}")
    uri = await opened(client, "signature", text)
    lines = text.splitlines()
    data_type = lines.index("                0xC8,                   $ Data Type: UDINT")
    help_ = await client.text_document_signature_help_async(types.SignatureHelpParams(
        doc(uri), types.Position(data_type, 18)))
    (signature,) = help_.signatures
    start, end = signature.parameters[help_.active_parameter].label
    assert signature.label[start:end] == "Data Type"
    assert "C.4.1.4.6" in signature.parameters[help_.active_parameter].documentation.value
    typing = lines.index(typed)
    help_ = await client.text_document_signature_help_async(types.SignatureHelpParams(
        doc(uri), types.Position(typing, len(lines[typing]))))
    start, end = help_.signatures[0].parameters[help_.active_parameter].label
    assert help_.signatures[0].label[start:end] == "Descriptor"  # an entry not yet ended by ';'
    on_keyword = await client.text_document_signature_help_async(types.SignatureHelpParams(
        doc(uri), types.Position(data_type - 5, 10)))
    assert on_keyword is None


async def test_unopened_files_of_the_workspace_are_checked_in_the_background(client: LanguageClient):
    broken = (STATE["folder"] / "sub" / "broken.eds").as_uri()
    while broken not in client.diagnostics:
        await client.wait_for_notification(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
    assert [d.code for d in client.diagnostics[broken]] == ["EDS301"]
    assert list(client.diagnostics[(STATE["folder"] / "adapter.eds").as_uri()]) == []


async def test_workspace_symbols_find_entries_in_open_and_unopened_files(client: LanguageClient):
    uri = await opened(client, "symbols")
    unopened = (STATE["folder"] / "adapter.eds").as_uri()
    while unopened not in client.diagnostics:  # its symbols are known once the background check read it
        await client.wait_for_notification(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
    symbols = await client.workspace_symbol_async(types.WorkspaceSymbolParams(query="inflt"))
    places = {(s.location.uri, s.name) for s in symbols}
    assert (uri, "Param2 Input Filter") in places
    assert (unopened, "Param2 Input Filter") in places
    assert all("Input Filter" in name for _, name in places)


async def test_show_device_command_answers_with_the_show_text(client: LanguageClient):
    uri = await opened(client, "show")
    result = await client.workspace_execute_command_async(types.ExecuteCommandParams(
        "edsconv.showDevice", [uri]))
    assert "edsconv Example Vendor" in result["text"]
    assert result["document"]["parameters"][0]["keyword"] == "Param1"


async def test_convert_command_writes_the_profiles_beside_the_file_and_refuses_to_overwrite(
        client: LanguageClient):
    path = STATE["folder"] / "adapter.eds"
    client.text_document_did_open(types.DidOpenTextDocumentParams(
        types.TextDocumentItem(uri=path.as_uri(), language_id="eds", version=1, text=EXAMPLE)))
    written = await client.workspace_execute_command_async(types.ExecuteCommandParams(
        "edsconv.convertToXml", [path.as_uri()]))
    assert sorted(Path(p).name for p in written) == ["adapter_commnet.xml", "adapter_device.xml"]
    assert (STATE["folder"] / "adapter_device.xml").read_bytes().startswith(b"<?xml")
    with pytest.raises(Exception, match="use --force"):
        await client.workspace_execute_command_async(types.ExecuteCommandParams(
            "edsconv.convertToXml", [path.as_uri()]))
    again = await client.workspace_execute_command_async(types.ExecuteCommandParams(
        "edsconv.convertToXml", [path.as_uri(), True]))
    assert len(again) == 2


async def test_fix_all_command_asks_the_client_to_apply_the_fixes(client: LanguageClient):
    text = EXAMPLE.replace('        ProdCode = 1001;', '        ProdCode = 1001')  # EDS002: no ';'
    uri = await opened(client, "fix-all", text)
    count = await client.workspace_execute_command_async(types.ExecuteCommandParams("edsconv.fixAll", [uri]))
    assert count == 1
    (params,) = STATE["edits"]
    (edit,) = params.edit.changes[uri]
    assert edit.new_text == "        ProdCode = 1001;\n"
    assert (edit.range.start.line, edit.range.end.line) == (17, 18)
    clean = await opened(client, "fix-all-clean")
    assert await client.workspace_execute_command_async(types.ExecuteCommandParams("edsconv.fixAll", [clean])) == 0


async def test_convert_command_refuses_what_eds2xml_refuses(client: LanguageClient):
    path = STATE["folder"] / "no_identity.eds"
    text = EXAMPLE.replace("        VendCode = 65535;\n", "")  # no VendCode: the profiles would invent one (XML103)
    path.write_text(text)
    client.text_document_did_open(types.DidOpenTextDocumentParams(
        types.TextDocumentItem(uri=path.as_uri(), language_id="eds", version=1, text=text)))
    with pytest.raises(Exception, match="not converted: .*VendCode"):
        await client.workspace_execute_command_async(types.ExecuteCommandParams(
            "edsconv.convertToXml", [path.as_uri()]))
    assert not (STATE["folder"] / "no_identity_device.xml").exists()
