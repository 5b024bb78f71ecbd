"""Language server latency: diagnostics after a one-character change, hover and definition.

    python benchmarks/bench_lsp.py [--repeat N] [--corpus DIR] [--json PATH]

Drives ``edsconv lsp`` over stdio with pygls' own client, as an editor does.
Diagnostics: the largest real file is opened, then one character of a value
is changed; the time runs from the didChange notification to the
publishDiagnostics that answers it, the pause the server waits for typing to
settle (CHANGE_DELAY) included, and is also given without it. Hover and
definition: on every real file, N requests on each of up to 20 references
(analysis already done); and once right after a change, when the request
waits for the new text's analysis. Targets (issue 14): diagnostics under 1 s,
hover and definition under 100 ms.
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

from common import CORPUS, corpus_files
from edsconv.eds.source import decode
from edsconv.lsp.analysis import analyse
from edsconv.lsp.diagnostics import CHANGE_DELAY

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


async def change_latency(client: Client, path: Path, repeat: int) -> dict:
    uri, text, opened = await open_file(client, path)
    changes, hovers_after_change = [], []
    for version in range(2, 2 + repeat):
        start = time.perf_counter()
        client.text_document_did_change(one_character_change(uri, text, version))
        await client.next_diagnostics(uri)
        changes.append(time.perf_counter() - start)
    for version in range(2 + repeat, 2 + 2 * repeat):
        client.text_document_did_change(one_character_change(uri, text, version))
        position = reference_positions(text)[0]
        hovers_after_change.append(await timed(client.text_document_hover_async(
            types.HoverParams(types.TextDocumentIdentifier(uri), position))))
        await client.next_diagnostics(uri)
    best = min(changes)
    return {"file": path.name, "bytes": path.stat().st_size, "open_to_diagnostics_s": opened,
            "change_to_diagnostics_s": best, "change_to_diagnostics_without_delay_s": best - CHANGE_DELAY,
            "hover_right_after_change_s": min(hovers_after_change)}


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


async def run(corpus: Path, repeat: int) -> dict:
    files = corpus_files(corpus)
    client = Client()
    await client.start_io(sys.executable, "-m", "edsconv", "lsp")
    await client.initialize_async(types.InitializeParams(capabilities=types.ClientCapabilities()))
    client.initialized(types.InitializedParams())
    largest = max(files, key=lambda p: p.stat().st_size)
    result = {"change": await change_latency(client, largest, repeat),
              "requests": await request_latency(client, files, repeat)}
    await client.shutdown_async(None)
    client.exit(None)
    await client.stop()
    return result


def options() -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5, help="timings per request; the best counts (default 5)")
    parser.add_argument("--corpus", type=Path, default=CORPUS, help=f"real EDS files (default {CORPUS})")
    parser.add_argument("--json", type=Path, help="also write the numbers to this JSON file")
    return parser.parse_args()


def main() -> None:
    arguments = options()
    result = asyncio.run(run(arguments.corpus, arguments.repeat))
    change, requests = result["change"], result["requests"]
    print(f"largest file {change['file']} ({change['bytes']:,} bytes)")
    print(f"  open -> diagnostics            {change['open_to_diagnostics_s'] * 1000:8.0f} ms")
    print(f"  one-character change -> diags {change['change_to_diagnostics_s'] * 1000:8.0f} ms "
          f"({change['change_to_diagnostics_without_delay_s'] * 1000:.0f} ms after the "
          f"{CHANGE_DELAY * 1000:.0f} ms pause)")
    print(f"  hover right after a change     {change['hover_right_after_change_s'] * 1000:8.0f} ms")
    print(f"{requests['requests']} references on {requests['files']} files (best of {arguments.repeat} each)")
    print(f"  hover      median {requests['hover_median_s'] * 1000:6.1f} ms, "
          f"max {requests['hover_max_s'] * 1000:6.1f} ms")
    print(f"  definition median {requests['definition_median_s'] * 1000:6.1f} ms, "
          f"max {requests['definition_max_s'] * 1000:6.1f} ms")
    if arguments.json:
        arguments.json.write_text(json.dumps(result, indent=2) + "\n")


if __name__ == "__main__":
    main()
