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


def test_an_assumed_semicolon_counts_towards_the_syntax_errors_that_stop_reading() -> None:
    # each assumed ';' restarts the parser: 20 us per byte of 'K1=1' lines, 44x the corpus average
    eds = edsconv.parse("[File]\n" + "".join(f"1_K{n} = 1\n" for n in range(150)))
    codes = [d.code for d in eds.diagnostics]
    assert codes == ["EDS002"] * 99 + ["EDS001", "EDS014"]
    assert eds.diagnostics[-1].message == "100 syntax errors; the rest of the file is not read"
    assert len(eds.sections[0].entries) == 99
    assert eds.sections[0].unparsed[0][1].text.startswith("1_K99 = 1\n1_K100 = 1\n")  # kept, not lost


def test_fewer_assumed_semicolons_do_not_stop_reading() -> None:
    eds = edsconv.parse("[File]\n" + "".join(f"1_K{n} = 1\n" for n in range(99)))
    assert [d.code for d in eds.diagnostics] == ["EDS002"] * 99
    assert len(eds.sections[0].entries) == 99


@pytest.mark.parametrize(("text", "problem"), [
    ("AAAB=AAA", "'=' pads only the end of base64 text"),
    ("AA*B", "'*' is not a base64 character"),
])
def test_icon_contents_that_is_not_base64_says_why(text: str, problem: str) -> None:
    # found by fuzzing eds2xml: padding before the end made the search for the bad character fail
    from edsconv.model.icon import decode_icon

    icon = decode_icon(text)
    assert (icon.kind, icon.problem) == ("not base64", problem)
