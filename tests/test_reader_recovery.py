"""Input handling (encodings, line ends, Ctrl-Z) and recovery from syntax errors."""

from __future__ import annotations

import codecs

import pytest

import edsconv
from conftest import codes, parse_ok
from edsconv.eds.source import encode
from edsconv.eds.writer import write

# --- bytes and encodings (C.4.1.3.2) -----------------------------------------------------------

TEXT = '[File]\nDescText = "ascii";\n$ comment\nName = "Caf\u00e9 \u00b5";\nB = 1;\n'


@pytest.mark.parametrize("data, encoding", [
    (TEXT.encode("utf-8"), "utf-8"),
    (b"\xef\xbb\xbf" + TEXT.encode("utf-8"), "utf-8-sig"),
    (TEXT.encode("cp1252"), "cp1252"),
    (TEXT.replace("\u00e9 \u00b5", "\u00e9 \x81").encode("latin-1"), "latin-1"),
])
def test_non_ascii_encodings_warn_once_and_decode(data, encoding):
    eds = edsconv.parse(data)
    assert codes(eds) == [("EDS005", 4, 1)]
    assert "line 4" in eds.diagnostics[0].message
    assert not eds.has_errors
    assert eds.encoding == encoding
    name = eds.sections[0].entry("Name").fields[0].value.text
    assert name == ("Caf\u00e9 \x81" if encoding == "latin-1" else "Caf\u00e9 \u00b5")
    assert eds.sections[0].entry("B").line == 5


@pytest.mark.parametrize("encoding, bom", [
    ("utf-16-le", codecs.BOM_UTF16_LE), ("utf-16-be", codecs.BOM_UTF16_BE),
    ("utf-32-le", codecs.BOM_UTF32_LE), ("utf-32-be", codecs.BOM_UTF32_BE),
])
def test_wide_encodings_with_a_byte_order_mark_are_read_with_one_warning(encoding, bom):
    data = bom + TEXT.replace("\n", "\r\n").encode(encoding)
    eds = edsconv.parse(data)
    assert codes(eds) == [("EDS005", 1, 1)]
    assert encoding.upper() in eds.diagnostics[0].message
    assert not eds.has_errors
    assert (eds.encoding, eds.newline) == (encoding, "\r\n")
    assert eds.sections[0].entry("Name").fields[0].value.text == "Caf\u00e9 \u00b5"
    assert eds.sections[0].entry("B").line == 5
    assert edsconv.parse(encode(write(eds), eds.encoding)) == eds


def test_ascii_bytes_and_text_give_the_same_model():
    ascii_text = TEXT.replace("\u00e9 \u00b5", "e")
    eds = parse_ok(ascii_text.encode("ascii"))
    assert eds.encoding == "ascii"
    assert eds == parse_ok(ascii_text)


@pytest.mark.parametrize("newline", ["\r\n", "\r"])
def test_line_ends_give_the_same_model_and_lines(newline):
    text = "[File]\nA = 1,\n  2; $ c\n\nB = \"x\";\n"
    lf = parse_ok(text)
    other = parse_ok(text.replace("\n", newline).encode())
    assert other == lf
    assert other.newline == newline
    entry_a, entry_b = other.sections[0].entries
    assert [(f.line, f.column) for f in entry_a.fields] == [(2, 5), (3, 3)]
    assert (entry_b.line, entry_b.column) == (5, 1)
    assert (entry_a.fields[1].comments[0].line, entry_a.fields[1].comments[0].column) == (3, 6)
    assert write(other).count(newline) == write(lf).count("\n")


def test_mixed_line_ends_count_lines():
    eds = edsconv.parse(b"[File]\r\nA = 1;\rB = 2;\nC = 3 @;\r\n")
    assert [(e.keyword, e.line) for e in eds.sections[0].entries] == [("A", 2), ("B", 3)]
    assert [(d.code, d.line) for d in eds.diagnostics] == [("EDS001", 4)]


@pytest.mark.parametrize("tail", [b"\x1a", b"\x1a\x1a", b"\r\n\x1a", b"\x1a\n"])
def test_trailing_ctrl_z_is_white_space(tail):
    eds = parse_ok(b"[File]\r\nA = 1;" + tail)
    assert [e.keyword for e in eds.sections[0].entries] == ["A"]


# --- recovery ---------------------------------------------------------------------------------

BROKEN = """[S]
A = 1;
B = 1 ];
C = 3;
D = @;
E = 4;
[T]
F = ];
G = 5;
"""


def test_several_errors_are_all_reported_and_parsing_resumes():
    eds = edsconv.parse(BROKEN)
    assert codes(eds) == [("EDS001", 3, 7), ("EDS001", 5, 5), ("EDS001", 8, 5)]
    messages = [d.message for d in eds.diagnostics]
    assert "unexpected ']" in messages[0] and "expected" in messages[0] and "';'" in messages[0]
    assert "'@;'" in messages[1] and "a field value" in messages[1]
    assert [[e.keyword for e in s.entries] for s in eds.sections] == [["A", "C", "E"], ["G"]]
    assert [[(i, u.text, u.line) for i, u in s.unparsed] for s in eds.sections] == [
        [(1, "B = 1 ];", 3), (2, "D = @;", 5)], [(0, "F = ];", 8)]]


def test_unparsed_text_is_written_back_verbatim():
    eds = edsconv.parse(BROKEN)
    out = write(eds)
    for line in ("B = 1 ];", "D = @;", "F = ];"):
        assert f"\n{line}\n" in out
    assert edsconv.parse(out) == eds
    assert codes(edsconv.parse(out)) == [("EDS001", 3, 7), ("EDS001", 5, 5), ("EDS001", 8, 5)]


def test_resync_at_section_header_after_unterminated_string():
    eds = edsconv.parse('[S]\nA = "abc\n[T]\nB = 1;\n')
    assert codes(eds) == [("EDS013", 2, 5)]
    assert [(s.name, [e.keyword for e in s.entries]) for s in eds.sections] == [("S", []), ("T", ["B"])]


@pytest.mark.parametrize("text, where, following", [
    ("[S]\nA = 1\n[T]\nB = 2;\n", (2, 6), "'[T]'"),
    ("[S]\nA = {1, 2}  $ c\n\n[T]\nB = 2;\n", (2, 11), "'[T]'"),
])
def test_missing_semicolon_before_section_eds002(text, where, following):
    eds = edsconv.parse(text)
    assert codes(eds) == [("EDS002", *where)]
    assert following in eds.diagnostics[0].message
    assert [[e.keyword for e in s.entries] for s in eds.sections] == [["A"], ["B"]]
    assert eds.sections[0].entries[0].fields[-1].value is not None


def test_missing_semicolon_before_entry_eds002():
    eds = edsconv.parse("[S]\nA = 1\nB = 2;\n")
    assert codes(eds) == [("EDS002", 2, 6)]
    assert [e.keyword for e in eds.sections[0].entries] == ["A", "B"]


@pytest.mark.parametrize("text", ["[S]\nA = 1", "[S]\nA = 1\n", "[S]\nA = {1}", "[S]\nA = 1 $ c\n", "[S]\nA ="])
def test_missing_semicolon_at_end_of_file_eds002(text):
    eds = edsconv.parse(text)
    assert [d.code for d in eds.diagnostics] == ["EDS002"]
    assert [e.keyword for e in eds.sections[0].entries] == ["A"]


@pytest.mark.parametrize("text, expected", [
    ("[S]\nA = 1;\n}\nB = 2;\n", [("S", ["A", "B"])]),
    ("[S]\nA = 1;\n[T]\n]\nC = 3;\n", [("S", ["A"]), ("T", ["C"])]),
])
def test_statement_before_an_error_is_kept(text, expected):
    eds = edsconv.parse(text)
    assert [d.code for d in eds.diagnostics] == ["EDS001"]
    assert [(s.name, [e.keyword for e in s.entries]) for s in eds.sections] == expected


def test_unclosed_brace_before_section_header():
    eds = edsconv.parse("[S]\nA = {1,\n[T]\nB = 2;\n")
    assert len(eds.diagnostics) == 1
    assert [(s.name, [e.keyword for e in s.entries]) for s in eds.sections][-1] == ("T", ["B"])


def test_entry_before_first_section_eds011():
    eds = edsconv.parse("$ c\n  A = 1;\n[S]\nB = 2;\n")
    assert codes(eds) == [("EDS011", 2, 3)]
    assert [e.keyword for e in eds.preamble.entries] == ["A"]
    assert [e.keyword for e in eds.sections[0].entries] == ["B"]
    assert edsconv.parse(write(eds)) == eds


CANOPEN = """[FileInfo]
FileName=device.eds
FileVersion=1
[DeviceInfo]
VendorName=Acme
[MandatoryObjects]
SupportedObjects=1
1=0x1000
[1000]
ParameterName=Device Type
ObjectType=0x7
DataType=0x0007
AccessType=ro
DefaultValue=0x00000191
"""


def test_canopen_eds_gives_exactly_one_eds010():
    eds = edsconv.parse(CANOPEN)
    assert codes(eds) == [("EDS010", 1, 1)]
    assert "CANopen" in eds.diagnostics[0].message


@pytest.mark.parametrize("text", ["", "\n\n", "  $ only a comment\n", b"\x1a"])
def test_empty_file_eds015(text):
    eds = edsconv.parse(text)
    assert codes(eds) == [("EDS015", 1, 1)]
    assert eds.sections == []


def test_moderately_nested_braces_round_trip():
    depth = 40
    text = "[S]\nA = " + "{" * depth + "1" + "}" * depth + ";\n"
    eds = parse_ok(text)
    value = eds.sections[0].entries[0].fields[0].value
    for _ in range(depth):
        (field,) = value.fields
        value = field.value
    assert value.raw == "1"
    assert edsconv.parse(write(eds)) == eds


def test_deeply_nested_braces_do_not_crash():
    depth = 5000
    eds = edsconv.parse("[S]\nA = " + "{" * depth + "1" + "}" * depth + ";\nB = 2;\n")
    section = eds.sections[0]
    assert section.entries[-1].keyword == "B"
    # read as an entry, or reported and kept verbatim: never lost
    assert section.entry("A") or (eds.has_errors and section.unparsed[0][1].text.startswith("A = {{{"))


def test_too_many_errors_eds014_stops_reading():
    text = "[S]\n" + "A = 1 @;\n" * 120
    eds = edsconv.parse(text)
    assert [d.code for d in eds.diagnostics] == ["EDS001"] * 100 + ["EDS014"]
    assert edsconv.parse(write(eds)) == eds
