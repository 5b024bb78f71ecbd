"""The causes the fuzzing campaign of issue 11 found (docs/fuzzing.md), each tested on its own: what a
kept input in tests/fuzz_regressions/ shows as a whole, these show rule by rule. Memory is counted with
tracemalloc (deterministic); time is measured in benchmarks/, never here."""

from __future__ import annotations

import tracemalloc

import pytest

import edsconv

#: A read of a plain file holds about 20 bytes per input byte at its peak; the bound leaves room.
BYTES_PER_INPUT_BYTE = 40


def peak_bytes_per_input_byte(data: bytes) -> float:
    edsconv.parse(b"[File]\n")  # the grammar and the lexicon are loaded once, outside the count
    tracemalloc.start()
    try:
        edsconv.parse(data)
        return tracemalloc.get_traced_memory()[1] / len(data)
    finally:
        tracemalloc.stop()


@pytest.mark.parametrize("data", [
    b'[File]\nDescText = "' + b"a" * 1_000_000 + b'";\n',  # one long string
    b'[File]\nDescText = "' + b"a" * 1_000_000 + b"\n",  # unterminated: the reader resynchronises past it
    b"[File]\n" + b" " * 1_000_000 + b"@;\n",  # blank text before a syntax error, kept verbatim
], ids=["string", "unterminated string", "blank before an error"])
def test_a_long_run_of_one_token_reads_in_memory_linear_in_a_small_factor(data: bytes) -> None:
    # an alternation repeated per character made the regex engine keep ~120 bytes per character
    # (an 11 MB string took 1.9 GB); possessive runs keep none
    assert peak_bytes_per_input_byte(data) < BYTES_PER_INPUT_BYTE
