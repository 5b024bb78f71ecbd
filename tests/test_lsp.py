"""``edsconv lsp`` end to end: a real LSP client (pytest-lsp) drives the server over stdio."""

from __future__ import annotations

import asyncio

import pytest

pytest.importorskip("pygls")
pytest_lsp = pytest.importorskip("pytest_lsp")

from lsprotocol import types  # noqa: E402
from pygls.exceptions import JsonRpcContentModified, JsonRpcException, JsonRpcRequestCancelled  # noqa: E402
from pytest_lsp import LanguageClient  # noqa: E402

import edsconv  # noqa: E402
from conftest import REPO  # noqa: E402
from edsconv.eds.canonical import write_canonical  # noqa: E402
from lsp_support import BROKEN, EXAMPLE, SERVER  # noqa: E402

pytestmark = pytest.mark.asyncio(loop_scope="module")

INITIALIZE: dict[str, types.InitializeResult] = {}




@pytest_lsp.fixture(scope="module", config=SERVER)
async def client(lsp_client: LanguageClient):
    capabilities = types.ClientCapabilities(text_document=types.TextDocumentClientCapabilities(
        rename=types.RenameClientCapabilities(prepare_support=True)))
    INITIALIZE["result"] = await lsp_client.initialize_session(types.InitializeParams(
        capabilities=capabilities, root_uri=REPO.as_uri()))
    yield
    await lsp_client.shutdown_session()


async def open_document(client: LanguageClient, name: str, text: str) -> tuple[str, list[types.Diagnostic]]:
    """Open ``text`` as a new document and wait for its first diagnostics."""
    uri = f"file:///edsconv-lsp-test/{name}.eds"
    client.text_document_did_open(types.DidOpenTextDocumentParams(
        types.TextDocumentItem(uri=uri, language_id="eds", version=1, text=text)))
    return uri, await diagnostics_of(client, uri)


async def diagnostics_of(client: LanguageClient, uri: str) -> list[types.Diagnostic]:
    while True:
        params = await client.wait_for_notification(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
        if params.uri == uri:
            return list(params.diagnostics)


def replace(uri: str, version: int, line: int, start: int, end: int, text: str) -> types.DidChangeTextDocumentParams:
    return types.DidChangeTextDocumentParams(
        types.VersionedTextDocumentIdentifier(version=version, uri=uri),
        [types.TextDocumentContentChangePartial(
            range=types.Range(types.Position(line, start), types.Position(line, end)), text=text)])


def doc(uri: str) -> types.TextDocumentIdentifier:
    return types.TextDocumentIdentifier(uri=uri)


async def test_initialize_announces_every_feature(client: LanguageClient):
    capabilities = INITIALIZE["result"].capabilities
    assert INITIALIZE["result"].server_info.name == "edsconv"
    assert capabilities.hover_provider and capabilities.definition_provider and capabilities.references_provider
    assert capabilities.rename_provider.prepare_provider
    assert capabilities.document_formatting_provider and capabilities.document_symbol_provider
    assert capabilities.document_range_formatting_provider
    assert "[" in capabilities.completion_provider.trigger_characters
    assert list(capabilities.code_action_provider.code_action_kinds) == [types.CodeActionKind.QuickFix]
    assert capabilities.text_document_sync.change is types.TextDocumentSyncKind.Incremental
    assert capabilities.text_document_sync.save


async def test_a_broken_file_gets_its_diagnostic_with_code_clause_range_and_link(client: LanguageClient):
    uri, diagnostics = await open_document(client, "broken", BROKEN)
    (diagnostic,) = diagnostics
    assert diagnostic.code == "EDS301"
    assert diagnostic.severity is types.DiagnosticSeverity.Error
    assert diagnostic.source == "edsconv"
    assert diagnostic.message == "Assem100 names Param9, which is not defined [C.4.1.4.8]"
    assert diagnostic.range == types.Range(types.Position(94, 18), types.Position(94, 24))
    assert diagnostic.code_description.href.endswith("rules.md#eds301")


async def test_a_change_that_fixes_the_fault_clears_it_and_the_latest_text_wins(client: LanguageClient):
    uri, diagnostics = await open_document(client, "fixed-by-change", BROKEN)
    assert [d.code for d in diagnostics] == ["EDS301"]
    # Two quick changes: the first breaks another reference, the second repairs both. Only the
    # text after the last one is checked: one publication, for version 3, with nothing in it.
    client.text_document_did_change(replace(uri, 2, 108, 18, 24, "Param8"))
    client.text_document_did_change(types.DidChangeTextDocumentParams(
        types.VersionedTextDocumentIdentifier(version=3, uri=uri),
        [types.TextDocumentContentChangePartial(
            range=types.Range(types.Position(94, 18), types.Position(94, 24)), text="Param2"),
         types.TextDocumentContentChangePartial(
            range=types.Range(types.Position(108, 18), types.Position(108, 24)), text="Param2")]))
    params = await client.wait_for_notification(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
    assert (params.uri, params.version, list(params.diagnostics)) == (uri, 3, [])


async def test_save_checks_again(client: LanguageClient):
    uri, _ = await open_document(client, "saved", EXAMPLE)
    client.text_document_did_change(replace(uri, 2, 94, 18, 24, "Param9"))
    client.text_document_did_save(types.DidSaveTextDocumentParams(doc(uri)))
    assert [d.code for d in await diagnostics_of(client, uri)] == ["EDS301"]


async def test_hover_explains_references_fields_and_bits(client: LanguageClient):
    uri, _ = await open_document(client, "hover", EXAMPLE)
    on_reference = await client.text_document_hover_async(types.HoverParams(doc(uri), types.Position(94, 20)))
    assert "**Param2** 'Input Filter': USINT 0xC6" in on_reference.contents.value
    assert "Member Reference" in on_reference.contents.value
    assert on_reference.range == types.Range(types.Position(94, 18), types.Position(94, 24))
    on_trigger = await client.text_document_hover_async(types.HoverParams(doc(uri), types.Position(113, 20)))
    assert "- transport type: exclusive-owner" in on_trigger.contents.value
    on_keyword = await client.text_document_hover_async(types.HoverParams(doc(uri), types.Position(28, 10)))
    assert on_keyword.contents.value.startswith("**ParamN** (C.4.1.4.6, Table C.13)")
    on_field = await client.text_document_hover_async(types.HoverParams(doc(uri), types.Position(15, 20)))
    assert on_field.contents.value.startswith("**ProdType field 1: Device Type** (UINT), required")
    assert "Range: 0 .. 65535 (UINT)" in on_field.contents.value
    on_path = await client.text_document_hover_async(types.HoverParams(doc(uri), types.Position(121, 22)))
    assert "Path: class 0x04 (Assembly), instance 0x97, connection point 0x96" in on_path.contents.value
    on_data_type = await client.text_document_hover_async(types.HoverParams(doc(uri), types.Position(32, 18)))
    assert "`0xC8`: **UDINT**" in on_data_type.contents.value
    nothing = await client.text_document_hover_async(types.HoverParams(doc(uri), types.Position(2, 0)))
    assert nothing is None


async def test_definition_and_references_across_sections(client: LanguageClient):
    uri, _ = await open_document(client, "navigation", EXAMPLE)
    found = await client.text_document_definition_async(types.DefinitionParams(doc(uri), types.Position(94, 20)))
    assert found == types.Location(uri, types.Range(types.Position(41, 8), types.Position(41, 14)))
    locations = await client.text_document_references_async(types.ReferenceParams(
        text_document=doc(uri), position=types.Position(41, 10),
        context=types.ReferenceContext(include_declaration=True)))
    assert [(loc.range.start.line, loc.range.start.character) for loc in locations] == [
        (41, 8), (83, 37), (94, 18), (108, 18)]
    format_reference = await client.text_document_definition_async(
        types.DefinitionParams(doc(uri), types.Position(116, 28)))
    assert format_reference.range.start == types.Position(88, 8)  # Assem100


async def test_rename_rewrites_every_reference_and_refuses_an_existing_name(client: LanguageClient):
    uri, _ = await open_document(client, "rename", EXAMPLE)
    prepared = await client.text_document_prepare_rename_async(
        types.PrepareRenameParams(doc(uri), types.Position(67, 10)))
    assert prepared.placeholder == "Param3"  # on Enum3: its parameter
    edit = await client.text_document_rename_async(types.RenameParams(
        text_document=doc(uri), position=types.Position(67, 10), new_name="Param12"))
    edits = sorted(((e.range.start.line, e.range.start.character), e.new_text) for e in edit.changes[uri])
    assert edits == [((54, 8), "Param12"), ((67, 8), "Enum12"), ((83, 40), "12"), ((109, 18), "Param12")]
    with pytest.raises(JsonRpcException, match="Param2 exists already") as refused:
        await client.text_document_rename_async(types.RenameParams(
            text_document=doc(uri), position=types.Position(67, 10), new_name="Param2"))
    assert refused.value.code == types.LSPErrorCodes.RequestFailed == -32803
    connection = EXAMPLE.splitlines().index("        Connection1 =")
    with pytest.raises(JsonRpcException, match=r"ConnectionN numbers start at 1 and go up by one \(C.4.1.4.9") as gap:
        await client.text_document_rename_async(types.RenameParams(
            text_document=doc(uri), position=types.Position(connection, 10), new_name="Connection9"))
    assert gap.value.code == -32803


def applied(text: str, edits: list[types.TextEdit]) -> str:
    """``text`` after the client applies ``edits`` (positions in ASCII text: characters)."""
    lines = text.splitlines(keepends=True)
    offset = lambda position: sum(len(line) for line in lines[:position.line]) + position.character  # noqa: E731
    for edit in sorted(edits, key=lambda e: (e.range.start.line, e.range.start.character), reverse=True):
        text = text[:offset(edit.range.start)] + edit.new_text + text[offset(edit.range.end):]
    return text


CANONICAL = write_canonical(edsconv.parse(EXAMPLE))
#: the canonical text with two lines laid out otherwise: a one-line entry and one line of Param2
UNTIDY = CANONICAL.replace("    ProdCode = 1001;", "        ProdCode =1001 ;").replace(
    "        0, 255, 3,\n", "        0,255,3,\n")
FORMATTING = types.FormattingOptions(tab_size=4, insert_spaces=True)


async def test_formatting_rewrites_only_the_lines_that_change(client: LanguageClient):
    uri, _ = await open_document(client, "format", UNTIDY)
    edits = await client.text_document_formatting_async(types.DocumentFormattingParams(doc(uri), FORMATTING))
    assert applied(UNTIDY, edits) == CANONICAL
    lines = UNTIDY.splitlines()
    changed = [lines.index("        ProdCode =1001 ;"), lines.index("        0,255,3,")]
    assert [(e.range.start.line, e.range.end.line) for e in edits] == [(line, line + 1) for line in changed]


async def test_range_formatting_lays_out_the_entries_in_the_range_in_place(client: LanguageClient):
    uri, _ = await open_document(client, "format-range", UNTIDY)
    lines = UNTIDY.splitlines()
    prod_code = lines.index("        ProdCode =1001 ;")
    in_device = types.Range(types.Position(prod_code - 1, 0), types.Position(prod_code + 1, 0))
    (edit,) = await client.text_document_range_formatting_async(types.DocumentRangeFormattingParams(
        doc(uri), in_device, FORMATTING))
    assert (edit.range.start.line, edit.range.end.line, edit.new_text) == (prod_code, prod_code + 1,
                                                                            "    ProdCode = 1001;\n")
    param2 = lines.index("    Param2 =")  # the range covers one line of the entry: the entry is laid out
    (edit,) = await client.text_document_range_formatting_async(types.DocumentRangeFormattingParams(
        doc(uri), types.Range(types.Position(param2 + 1, 0), types.Position(param2 + 1, 3)), FORMATTING))
    assert edit.new_text == "        0, 255, 3,\n"
    # a range over the whole of an untidy file gives every entry its layout; nothing moves
    whole = types.Range(types.Position(0, 0), types.Position(len(EXAMPLE.splitlines()), 0))
    edits = await client.text_document_range_formatting_async(types.DocumentRangeFormattingParams(
        doc((await open_document(client, "format-range-all", EXAMPLE))[0]), whole, FORMATTING))
    laid_out = applied(EXAMPLE, edits)
    assert write_canonical(edsconv.parse(laid_out)) == CANONICAL
    assert "        0, 255, 3,\n" in laid_out and "    ProdCode = 1001;\n" in laid_out
    keywords = lambda text: [line.split("=")[0].strip() for line in text.splitlines() if " =" in line]  # noqa: E731
    assert keywords(laid_out) == keywords(EXAMPLE)


async def test_formatting_refused_for_a_syntax_error_says_why(client: LanguageClient):
    broken_uri, _ = await open_document(client, "format-broken", EXAMPLE.replace("Revision = 1.1;", "Revision = 1.1"))
    client.messages.clear()
    assert not await client.text_document_formatting_async(types.DocumentFormattingParams(
        doc(broken_uri), FORMATTING))
    assert not await client.text_document_range_formatting_async(types.DocumentRangeFormattingParams(
        doc(broken_uri), types.Range(types.Position(0, 0), types.Position(3, 0)), FORMATTING))
    first, second = client.messages
    assert first.type is types.MessageType.Warning and first == second
    assert first.message.startswith("edsconv: not formatted: 1 syntax error(s) leave text that cannot be laid out")
    assert "EDS002" in first.message


async def completion_labels(client: LanguageClient, uri: str, line: int, character: int) -> dict[str, str | None]:
    found = await client.text_document_completion_async(
        types.CompletionParams(doc(uri), types.Position(line, character)))
    return {item.label: item.detail for item in found.items}


async def test_completion_offers_sections_keywords_numbers_types_and_references(client: LanguageClient):
    blank = "        \n"
    text = EXAMPLE.replace("[Port]", "[")
    for entry in ("        Enum3 = 0,", "        Assem150 =", "        Connection2 ="):  # a blank line before each
        text = text.replace(entry, blank + entry)
    lines = text.splitlines()
    uri, _ = await open_document(client, "completion", text)
    blanks = [index for index, line in enumerate(lines) if line == blank.rstrip("\n")]
    in_params, in_assembly, in_connections = [await completion_labels(client, uri, line, 8) for line in blanks]
    assert {"Param5", "Enum4", "ProxyParam1"} <= set(in_params)
    assert "Assem152" in in_assembly and "Revision" not in in_assembly
    assert "Connection3" in in_connections
    sections = await completion_labels(client, uri, lines.index("["), 1)
    assert {"Port", "Modular"} <= set(sections) and "Params" not in sections
    data_types = await completion_labels(client, uri, 32, 18)  # Param1 field 5, Data Type
    assert data_types["0xC8"] == "UDINT" and data_types["0xCA"] == "REAL"
    format_line = lines.index("                Param1,2,Assem150,      $ O=>T RPI, size, format")
    formats = await completion_labels(client, uri, format_line, 28)  # Connection1 O=>T format
    assert formats["Assem100"] == "Inputs" and formats["Param1"] == "RPI"


async def test_code_action_suppresses_the_rule_on_the_entry(client: LanguageClient):
    uri, (diagnostic,) = await open_document(client, "actions", BROKEN)
    actions = await client.text_document_code_action_async(types.CodeActionParams(
        text_document=doc(uri), range=diagnostic.range, context=types.CodeActionContext(diagnostics=[diagnostic])))
    (action,) = actions
    assert action.title.startswith("Suppress EDS301 here")
    (edit,) = action.edit.changes[uri]
    assert edit.range.start == types.Position(88, len("        Assem100 ="))
    assert edit.new_text == " $ edsconv: ignore[EDS301]"


async def test_code_action_applies_the_fix_lint_makes_and_the_fault_goes(client: LanguageClient):
    fixable = EXAMPLE.replace("ProdCode = 1001;", "ProdCode = 01001;")
    uri, (diagnostic,) = await open_document(client, "fixable", fixable)
    assert diagnostic.code == "EDS103"
    actions = await client.text_document_code_action_async(types.CodeActionParams(
        text_document=doc(uri), range=diagnostic.range, context=types.CodeActionContext(diagnostics=[diagnostic])))
    fix, suppress = actions
    assert (fix.title, fix.is_preferred) == ("Write 1001 without leading zeros", True)
    assert suppress.title.startswith("Suppress EDS103 here")
    (edit,) = fix.edit.changes[uri]
    line = EXAMPLE.splitlines().index("        ProdCode = 1001;")
    assert (edit.range, edit.new_text) == (types.Range(types.Position(line, 19), types.Position(line, 24)), "1001")
    client.text_document_did_change(types.DidChangeTextDocumentParams(
        types.VersionedTextDocumentIdentifier(version=2, uri=uri),
        [types.TextDocumentContentChangePartial(range=edit.range, text=edit.new_text)]))
    assert await diagnostics_of(client, uri) == []


async def test_an_inline_suppression_silences_the_rule_in_the_editor(client: LanguageClient):
    suppressed = BROKEN.replace("        Assem100 =", "        Assem100 = $ edsconv: ignore[EDS301]")
    _, diagnostics = await open_document(client, "suppressed", suppressed)
    assert "EDS301" not in [d.code for d in diagnostics]
    assert diagnostics == []
    _, unused = await open_document(client, "unused", EXAMPLE.replace("        Assem100 =",
                                                                       "        Assem100 = $ edsconv: ignore[EDS301]"))
    assert [d.code for d in unused] == ["EDS099"]


async def test_the_lint_configuration_beside_the_file_applies_in_the_editor(client: LanguageClient, tmp_path):
    (tmp_path / "edsconv.toml").write_text('ignore = ["EDS301"]\n', encoding="utf-8")
    (tmp_path / "sub").mkdir()
    uri = (tmp_path / "sub" / "configured.eds").as_uri()  # walked up from the file, as lint does
    client.text_document_did_open(types.DidOpenTextDocumentParams(
        types.TextDocumentItem(uri=uri, language_id="eds", version=1, text=BROKEN)))
    assert await diagnostics_of(client, uri) == []
    _, unconfigured = await open_document(client, "unconfigured", BROKEN)
    assert [d.code for d in unconfigured] == ["EDS301"]


async def test_document_symbols_name_parameters_and_assemblies(client: LanguageClient):
    uri, _ = await open_document(client, "symbols", EXAMPLE)
    found = await client.text_document_document_symbol_async(types.DocumentSymbolParams(doc(uri)))
    assert [s.name for s in found][:4] == ["[File]", "[Device]", "[Device Classification]", "[Params]"]
    params = {s.name: s.detail for s in found[3].children}
    assert params == {"Param1": "RPI", "Param2": "Input Filter", "Param3": "Fault Action", "Enum3": None,
                      "Param4": "Temperature Limit"}


async def test_shutdown_ends_the_server():
    own = await SERVER.start()
    await own.initialize_session(types.InitializeParams(capabilities=types.ClientCapabilities()))
    await own.shutdown_session()
    assert own._server.returncode == 0
    await own.stop()


#: io_adapter.eds with 3,000 more parameters: an analysis long enough for a burst of changes to overtake it
LARGE = EXAMPLE.replace("[Groups]", "".join(
    f'        Param{n} = 0,,,0x0000,0xC8,4,"P{n}","","",0,100,1,,,,,,,,,;\n' for n in range(5, 3005)) + "\n[Groups]")


async def test_a_burst_of_changes_and_requests_builds_no_backlog(client: LanguageClient):
    uri, _ = await open_document(client, "burst", LARGE)
    line = LARGE.splitlines().index("        Param2 =")
    hovers = []
    for version in range(2, 12):  # a change and a hover per keystroke, faster than one analysis
        client.protocol.notify(types.TEXT_DOCUMENT_DID_CHANGE,
                               replace(uri, version, line + 6, 17, 18, "ABCDEFGHIJ"[version - 2]))
        hovers.append(asyncio.ensure_future(client.text_document_hover_async(
            types.HoverParams(doc(uri), types.Position(line, 10)))))
        await asyncio.sleep(0)  # the request goes out now, before the next change
    answers = await asyncio.gather(*hovers, return_exceptions=True)
    superseded = [a for a in answers[:-1] if getattr(a, "code", None) == JsonRpcContentModified.CODE]
    assert superseded and all(a in superseded or isinstance(a, types.Hover) for a in answers[:-1])
    assert "**ParamN**" in answers[-1].contents.value  # the last text's request is answered
    published = await client.wait_for_notification(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
    assert (published.uri, published.version) == (uri, 11)  # one publication, for the last text


async def test_a_cancelled_request_answers_request_cancelled_and_cancels_nothing_shared(client: LanguageClient):
    uri, _ = await open_document(client, "cancel", LARGE)
    client.text_document_did_change(replace(uri, 2, 3, 0, 0, " "))
    cancelled = asyncio.ensure_future(client.protocol.send_request_async(
        types.TEXT_DOCUMENT_HOVER, types.HoverParams(doc(uri), types.Position(28, 10)), msg_id="x"))
    await asyncio.sleep(0)  # sent: the server waits for the changed text's analysis
    client.protocol.notify(types.CANCEL_REQUEST, types.CancelParams(id="x"))
    with pytest.raises(JsonRpcRequestCancelled):
        await cancelled
    after = await client.text_document_hover_async(types.HoverParams(doc(uri), types.Position(28, 10)))
    assert after.contents.value.startswith("**ParamN**")
    published = await asyncio.wait_for(client.wait_for_notification(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS), 30)
    assert published.version == 2  # the diagnostics of the text the cancelled request waited for


#: io_adapter.eds with a [Capacity] section (newer CIP tables) holding an entry, a blank line and a comment
NEWER = EXAMPLE.replace("[Port]", "[Capacity]\n        MaxMsgConnections = 6;\n        \n"
                                  "        $ see the notes,\n\n[Port]")


async def test_hover_and_completion_know_the_newer_cip_tables_the_linter_uses(client: LanguageClient):
    uri, diagnostics = await open_document(client, "newer", NEWER)
    lines = NEWER.splitlines()
    capacity = lines.index("[Capacity]")
    section = await client.text_document_hover_async(types.HoverParams(doc(uri), types.Position(capacity, 3)))
    assert section.contents.value.startswith("**[Capacity]** Capacity: optional (not in ISO 15745-4:2003; a later "
                                             "CIP edition, as eds-pie `meta_eds_lib.json: Capacity`")
    entry = await client.text_document_hover_async(types.HoverParams(doc(uri), types.Position(capacity + 1, 12)))
    assert entry.contents.value.startswith("**MaxMsgConnections** (not in ISO 15745-4:2003; a later CIP edition")
    assert "Maximum explicit connections" in entry.contents.value
    keywords = await completion_labels(client, uri, capacity + 2, 8)
    assert {"TSpec1", "ConnOverhead", "MaxIOConnections"} <= set(keywords) and "MaxMsgConnections" not in keywords
    sections = await completion_labels(client, uri, capacity + 5, 1)  # after the "[" of [Port]
    assert {"TCP/IP Interface Class", "Ethernet Link Class"} <= set(sections) and "Capacity" not in sections


async def test_no_completion_or_hover_in_comments_and_parameters_in_a_path_after_a_bracket(client: LanguageClient):
    text = NEWER.replace('"20 04 24 97 2C 96 2C 64";', '"20 04 24 97 2C [ 2C 64";')
    uri, _ = await open_document(client, "comments", text)
    lines = text.splitlines()
    comment = lines.index("        $ see the notes,")
    assert not (await client.text_document_completion_async(types.CompletionParams(
        doc(uri), types.Position(comment, len(lines[comment]))))).items
    rpi = lines.index("                Param1,2,Assem150,      $ O=>T RPI, size, format")
    assert await completion_labels(client, uri, rpi, len(lines[rpi])) == {}  # after the comment's last ','
    assert await client.text_document_hover_async(types.HoverParams(doc(uri), types.Position(rpi, 44))) is None
    path = next(index for index, line in enumerate(lines) if '2C [ 2C 64"' in line)
    in_brackets = await completion_labels(client, uri, path, lines[path].index("[") + 1)
    assert set(in_brackets) == {"Param1", "Param2", "Param3", "Param4"} and in_brackets["Param1"] == "RPI"
    assert await completion_labels(client, uri, path, lines[path].index("24")) == {}  # elsewhere in the string


async def test_hover_is_plain_text_for_a_client_that_asks_for_it():
    own = await SERVER.start()  # eglot without markdown-mode declares plaintext only
    await own.initialize_session(types.InitializeParams(capabilities=types.ClientCapabilities(
        text_document=types.TextDocumentClientCapabilities(hover=types.HoverClientCapabilities(
            content_format=[types.MarkupKind.PlainText])))))
    uri, _ = await open_document(own, "plain", EXAMPLE)
    found = await own.text_document_hover_async(types.HoverParams(doc(uri), types.Position(94, 20)))
    assert found.contents.kind is types.MarkupKind.PlainText
    assert "Param2 'Input Filter': USINT 0xC6" in found.contents.value
    assert not any(mark in found.contents.value for mark in ("**", "`", "---"))
    await own.shutdown_session()
    await own.stop()


async def test_a_changed_configuration_applies_at_once_and_a_broken_one_is_reported(tmp_path):
    own = await SERVER.start()
    registrations: list[types.Registration] = []

    @own.feature(types.CLIENT_REGISTER_CAPABILITY)
    def register(params: types.RegistrationParams) -> None:
        registrations.extend(params.registrations)

    await own.initialize_session(types.InitializeParams(capabilities=types.ClientCapabilities(
        workspace=types.WorkspaceClientCapabilities(
            did_change_watched_files=types.DidChangeWatchedFilesClientCapabilities(dynamic_registration=True)))))
    uri = (tmp_path / "watched.eds").as_uri()
    own.text_document_did_open(types.DidOpenTextDocumentParams(
        types.TextDocumentItem(uri=uri, language_id="eds", version=1, text=BROKEN)))
    assert [d.code for d in await diagnostics_of(own, uri)] == ["EDS301"]
    (registration,) = registrations
    assert registration.method == types.WORKSPACE_DID_CHANGE_WATCHED_FILES
    assert [w["globPattern"] for w in registration.register_options["watchers"]] == ["**/edsconv.toml",
                                                                                    "**/pyproject.toml"]
    config = tmp_path / "edsconv.toml"

    def changed(text: str) -> None:
        config.write_text(text, encoding="utf-8")
        own.workspace_did_change_watched_files(types.DidChangeWatchedFilesParams(
            [types.FileEvent(config.as_uri(), types.FileChangeType.Changed)]))

    changed('ignore = ["EDS301"]\n')
    assert await diagnostics_of(own, uri) == []  # no edit needed
    changed('ignore = "EDS301"\n')
    assert [d.code for d in await diagnostics_of(own, uri)] == ["EDS301"]  # the defaults, and a message why
    (message,) = own.messages
    assert message.type is types.MessageType.Warning
    assert message.message.startswith("edsconv: the configuration cannot be read, the defaults apply:")
    assert "edsconv.toml" in message.message
    await own.shutdown_session()
    await own.stop()
