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


def test_a_comment_on_a_field_far_beyond_the_entry_stays_with_the_entry() -> None:
    # found by fuzzing xml2eds: field="666...6" padded the entry with that many empty fields (24 GB)
    from edsconv.eds.from_model import MAX_DROPPED_FIELDS, attach_comments
    from edsconv.model import CommentNote

    eds = edsconv.parse("[Device]\n        VendCode = 1;\n")
    attach_comments(eds, [CommentNote("Device", "VendCode", 10**36, "far", False),
                          CommentNote("Device", "VendCode", MAX_DROPPED_FIELDS - 1, "near", False)])
    entry = eds.sections[0].entries[0]
    assert [c.text for c in entry.comments] == ["far"]
    assert len(entry.fields) == MAX_DROPPED_FIELDS and [c.text for c in entry.fields[-1].comments] == ["near"]



def test_a_port_path_xml_cannot_hold_is_kept_in_an_extension_and_read_back(tmp_path) -> None:
    # found by fuzzing eds2xml: NUL characters in Port1's path made lxml refuse the PortObject text
    from pathlib import Path

    from edsconv.xml.common import Header
    from edsconv.xml.convert import device_from_profiles, profile_documents

    text = (Path(__file__).parent.parent / "corpus" / "examples" / "io_adapter.eds").read_text()
    device, _ = edsconv.analyse(edsconv.parse(text.replace('"20 F5 24 01"', '"20 F\x00 24 01"')))
    assert device.ports[0].object_path == "20 F\x00 24 01"  # kept as written: not a path
    paths = []
    for document in profile_documents(device, Header.derive(device, "x"), "x"):
        paths.append(tmp_path / document.name)
        paths[-1].write_bytes(document.data)
    back, problems = device_from_profiles(paths)
    assert problems == [] and back is not None and back.ports[0].object_path == device.ports[0].object_path
