"""Language server latency: diagnostics, hover and completion after a one-character change, beside a
full re-check; hover and definition on unchanged text.

    python benchmarks/bench_lsp.py [--repeat N] [--corpus DIR] [--dense NAME] [--json PATH]

Drives ``edsconv lsp`` over stdio with pygls' own client, as an editor does.
After a keystroke: the largest real file and a generated dense file
(benchmarks/generate.py, default dense-params-40k.eds, 2.7 MB) are opened, then
one character of a value is changed, N times; the time runs from the didChange
notification (the change is made before) to the publishDiagnostics that answers it, the pause the server
waits for typing to settle (CHANGE_DELAY) included. Hover and completion right
after a change are timed from the didChange to the answer. "new line": the
diagnostics after a blank line is typed at the top, and "(completion)" the
completion right after it is deleted again: edits that move every line, every
position the last analysis holds (edsconv.lsp.incremental.respaced). "keyword":
the same for a character typed before the first entry's keyword and deleted
again, and "entry" for a new entry and its line break typed before the first
entry and deleted again: edits that change where statements begin and end, which
the server reads again from the entry before them until its reading meets the
last one (edsconv.lsp.region).
Beside them, the time of one full re-check of the file in this process
(``analyse``, warm, without what an earlier analysis left), which is what the
server did per change before. Hover and definition: on every real
file, N requests on each of up to 20 references (analysis already done).
Targets (issue 21): diagnostics <= 150 ms after a keystroke on the largest real
file, <= 1 s on a 3 MB dense file; hover and completion <= 50 ms after an edit.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import statistics
import sys
import time
from pathlib import Path

from lsprotocol import types
from pygls.lsp.client import LanguageClient

from common import CORPUS, best_of, corpus_files
from edsconv.eds.source import decode
from edsconv.lsp.analysis import analyse
from edsconv.lsp.diagnostics import CHANGE_DELAY
from generate import generate

#: References asked about per file
SPOTS = 20


class Client(LanguageClient):
    def __init__(self) -> None:
        super().__init__("edsconv-bench", "1")
        self.published: asyncio.Queue[types.PublishDiagnosticsParams] = asyncio.Queue()

        @self.feature(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
        def on_diagnostics(params: types.PublishDiagnosticsParams) -> None:
            self.published.put_nowait(params)

    async def next_diagnostics(self, uri: str) -> types.PublishDiagnosticsParams:
        while True:
            params = await self.published.get()
            if params.uri == uri:
                return params


def reference_positions(text: str) -> list[types.Position]:
    """Up to SPOTS positions on references (not definitions), spread over the file."""
    spans = [s for s in analyse(text).spans if s.kind != "definition"]
    step = max(len(spans) // SPOTS, 1)
    return [types.Position(s.line - 1, s.column) for s in spans[::step][:SPOTS]]


async def timed(request) -> float:
    start = time.perf_counter()
    await request
    return time.perf_counter() - start


async def open_file(client: Client, path: Path) -> tuple[str, str, float]:
    text = decode(path.read_bytes()).text
    uri = path.resolve().as_uri()
    start = time.perf_counter()
    client.text_document_did_open(types.DidOpenTextDocumentParams(types.TextDocumentItem(uri, "eds", 1, text)))
    await client.next_diagnostics(uri)
    return uri, text, time.perf_counter() - start


def one_character_change(uri: str, text: str, version: int) -> types.DidChangeTextDocumentParams:
    """Replace the last digit of the file by 1 or 2, by turns: each version differs from the one before."""
    offset = max(i for i, c in enumerate(text) if c.isdigit())
    line = text.count("\n", 0, offset)
    character = offset - (text.rfind("\n", 0, offset) + 1)
    digit = [d for d in "123" if d != text[offset]][version % 2]
    where = types.Range(types.Position(line, character), types.Position(line, character + 1))
    return types.DidChangeTextDocumentParams(types.VersionedTextDocumentIdentifier(version=version, uri=uri),
                                             [types.TextDocumentContentChangePartial(range=where, text=digit)])


def typed_or_deleted(uri: str, version: int, at: types.Position, text: str,
                     typed: bool) -> types.DidChangeTextDocumentParams:
    """``text`` typed at ``at`` (``typed``), or deleted again."""
    lines = text.split("\n")
    end = types.Position(at.line + len(lines) - 1, (at.character if len(lines) == 1 else 0) + len(lines[-1]))
    where = types.Range(at, at if typed else end)
    return types.DidChangeTextDocumentParams(types.VersionedTextDocumentIdentifier(version=version, uri=uri),
                                             [types.TextDocumentContentChangePartial(range=where,
                                                                                    text=text if typed else "")])


def first_keyword(text: str) -> types.Position:
    """Where the first entry's keyword starts: typing before it makes another keyword of it."""
    line = next(number for number, content in enumerate(text.splitlines()) if "=" in content
                and not content.lstrip().startswith("$"))
    content = text.splitlines()[line]
    return types.Position(line, len(content) - len(content.lstrip()))


async def there_and_back(client: Client, uri: str, position: types.Position, version: int, repeat: int,
                         at: types.Position, typed: str) -> tuple[float, float]:
    """Median times from typing ``typed`` at ``at`` to its diagnostics, and from deleting it again to
    the completion at ``position`` (which stands where it did once it is deleted)."""
    diagnostics, completions = [], []
    document = types.TextDocumentIdentifier(uri)
    for number in range(version, version + 2 * repeat, 2):
        start = time.perf_counter()
        client.text_document_did_change(typed_or_deleted(uri, number, at, typed, True))
        await client.next_diagnostics(uri)
        diagnostics.append(time.perf_counter() - start)
        start = time.perf_counter()
        client.text_document_did_change(typed_or_deleted(uri, number + 1, at, typed, False))
        await client.text_document_completion_async(types.CompletionParams(document, position))
        completions.append(time.perf_counter() - start)
        await client.next_diagnostics(uri)
    return statistics.median(diagnostics), statistics.median(completions)


async def change_latency(client: Client, path: Path, repeat: int) -> dict:
    uri, text, opened = await open_file(client, path)
    document = types.TextDocumentIdentifier(uri)
    # a reference, else (a file of parameters only) the keyword of the second line
    position = next(iter(reference_positions(text)), types.Position(1, 10))
    changes, hovers, completions = [], [], []
    for version in range(2, 2 + 3 * repeat, 3):
        # each change is made before its timing starts: finding the file's last digit takes a 3 MB file
        # 150 ms here, which an editor does not spend
        edit, edit_before_hover, edit_before_completion = (one_character_change(uri, text, version + n)
                                                           for n in range(3))
        start = time.perf_counter()
        client.text_document_did_change(edit)
        await client.next_diagnostics(uri)
        changes.append(time.perf_counter() - start)
        start = time.perf_counter()
        client.text_document_did_change(edit_before_hover)
        await client.text_document_hover_async(types.HoverParams(document, position))
        hovers.append(time.perf_counter() - start)
        await client.next_diagnostics(uri)
        start = time.perf_counter()
        client.text_document_did_change(edit_before_completion)
        await client.text_document_completion_async(types.CompletionParams(document, position))
        completions.append(time.perf_counter() - start)
        await client.next_diagnostics(uri)
    first = 2 + 3 * repeat
    line_break = await there_and_back(client, uri, position, first, repeat, types.Position(0, 0), "\n")
    keyword = await there_and_back(client, uri, position, first + 2 * repeat, repeat, first_keyword(text), "X")
    entry = await there_and_back(client, uri, position, first + 4 * repeat, repeat, first_keyword(text),
                                 "Typed = 1;\n")
    client.text_document_did_close(types.DidCloseTextDocumentParams(document))
    full, _ = best_of(repeat, analyse, text)
    return {"file": path.name, "bytes": path.stat().st_size, "open_to_diagnostics_s": opened,
            "change_to_diagnostics_s": statistics.median(changes), "change_to_diagnostics_max_s": max(changes),
            "hover_after_change_s": statistics.median(hovers),
            "completion_after_change_s": statistics.median(completions),
            "line_break_to_diagnostics_s": line_break[0], "completion_after_line_break_s": line_break[1],
            "keyword_to_diagnostics_s": keyword[0], "completion_after_keyword_s": keyword[1],
            "entry_to_diagnostics_s": entry[0], "completion_after_entry_s": entry[1], "full_recheck_s": full}


async def request_latency(client: Client, files: list[Path], repeat: int) -> dict:
    hovers: list[float] = []
    definitions: list[float] = []
    for path in files:
        uri, text, _ = await open_file(client, path)
        document = types.TextDocumentIdentifier(uri)
        for position in reference_positions(text):
            hovers.append(min([await timed(client.text_document_hover_async(types.HoverParams(document, position)))
                               for _ in range(repeat)]))
            definitions.append(min([await timed(client.text_document_definition_async(
                types.DefinitionParams(document, position))) for _ in range(repeat)]))
        client.text_document_did_close(types.DidCloseTextDocumentParams(document))
    return {"files": len(files), "requests": len(hovers),
            "hover_median_s": statistics.median(hovers), "hover_max_s": max(hovers),
            "definition_median_s": statistics.median(definitions), "definition_max_s": max(definitions)}


async def run(corpus: Path, repeat: int, dense: str, requests: bool = True) -> dict:
    files = corpus_files(corpus)
    client = Client()
    await client.start_io(sys.executable, "-m", "edsconv", "lsp")
    await client.initialize_async(types.InitializeParams(capabilities=types.ClientCapabilities()))
    client.initialized(types.InitializedParams())
    largest = max(files, key=lambda p: p.stat().st_size)
    result = {"change": [await change_latency(client, largest, repeat),
                         await change_latency(client, generate(dense), repeat)],
              "requests": await request_latency(client, files, repeat) if requests else None}
    await client.shutdown_async(None)
    client.exit(None)
    await client.stop()
    return result


def options() -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5, help="timings per request; the best counts (default 5)")
    parser.add_argument("--corpus", type=Path, default=CORPUS, help=f"real EDS files (default {CORPUS})")
    parser.add_argument("--dense", default="dense-params-40k.eds", help="the generated dense file (generate.py)")
    parser.add_argument("--changes-only", action="store_true", help="skip hover and definition on unchanged text")
    parser.add_argument("--json", type=Path, help="also write the numbers to this JSON file")
    return parser.parse_args()


def main() -> None:
    arguments = options()
    result = asyncio.run(run(arguments.corpus, arguments.repeat, arguments.dense, not arguments.changes_only))
    requests = result["requests"]
    if arguments.json:
        arguments.json.write_text(json.dumps(result, indent=2) + "\n")
    print(f"after a one-character change (median of {arguments.repeat}; the {CHANGE_DELAY * 1000:.0f} ms pause "
          "included), beside one full re-check")
    print(f"  {'file':<34} {'bytes':>10} {'diagnostics':>12} {'(max)':>7} {'hover':>7} {'completion':>11} "
          f"{'new line':>9} {'(completion)':>13} {'keyword':>8} {'(completion)':>13} {'entry':>7} {'(completion)':>13} "
          f"{'full re-check':>14}")
    for change in result["change"]:
        ms = {key: f"{value * 1000:.0f} ms" for key, value in change.items() if key.endswith("_s")}
        print(f"  {change['file'][-34:]:<34} {change['bytes']:>10,} {ms['change_to_diagnostics_s']:>12} "
              f"{ms['change_to_diagnostics_max_s']:>7} {ms['hover_after_change_s']:>7} "
              f"{ms['completion_after_change_s']:>11} {ms['line_break_to_diagnostics_s']:>9} "
              f"{ms['completion_after_line_break_s']:>13} {ms['keyword_to_diagnostics_s']:>8} "
              f"{ms['completion_after_keyword_s']:>13} {ms['entry_to_diagnostics_s']:>7} "
              f"{ms['completion_after_entry_s']:>13} {ms['full_recheck_s']:>14}")
    if requests is None:
        return
    print(f"{requests['requests']} references on {requests['files']} files (best of {arguments.repeat} each)")
    print(f"  hover      median {requests['hover_median_s'] * 1000:6.1f} ms, "
          f"max {requests['hover_max_s'] * 1000:6.1f} ms")
    print(f"  definition median {requests['definition_median_s'] * 1000:6.1f} ms, "
          f"max {requests['definition_max_s'] * 1000:6.1f} ms")


if __name__ == "__main__":
    main()
