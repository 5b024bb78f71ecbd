"""Property tests: writer/reader round trip, and the reader never raises on any input."""

from __future__ import annotations

import string

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

import edsconv
from edsconv.eds.syntax import Comment, EdsFile, Entry, Field, Group, Scalar, Section, String, ValueKind
from edsconv.eds.writer import write

SETTINGS = settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])

# --- generated syntax models ------------------------------------------------------------------

comment = st.builds(Comment, st.text(st.sampled_from(string.printable.replace("\n", "").replace("\r", "")
                                                     .replace("\x0b", "").replace("\x0c", "")), max_size=12))
comments = st.lists(comment, max_size=2)

#: (kind, spelling) of every scalar kind of C.4.1.3, valid spellings only.
SCALARS = {
    ValueKind.INTEGER: st.from_regex(r"[+-]?(0|[1-9][0-9]{0,8})", fullmatch=True),
    ValueKind.HEX: st.from_regex(r"0[xX][0-9A-Fa-f]{1,16}", fullmatch=True),
    ValueKind.BINARY: st.from_regex(r"0[bB][01]{1,16}", fullmatch=True),
    ValueKind.REAL: st.from_regex(r"[+-]?([0-9]{1,4}\.[0-9]{0,4}|\.[0-9]{1,4})([eE][+-]?[0-9]{1,4})?"
                                  r"|[+-]?[0-9]{1,4}[eE][+-]?[0-9]{1,4}", fullmatch=True),
    ValueKind.REAL_WORD: st.sampled_from(["QUIET-NAN", "SIGNAL-NAN", "INFINITY", "+INFINITY", "-INFINITY"]),
    ValueKind.DATE: st.from_regex(r"(0[1-9]|1[0-2])-(0[1-9]|[12][0-9]|3[01])-([0-9]{2}|[0-9]{4})", fullmatch=True),
    ValueKind.TIME: st.from_regex(r"([01][0-9]|2[0-3]):[0-5][0-9]:[0-5][0-9]", fullmatch=True),
    ValueKind.WORD: st.from_regex(r"[A-Za-z_][A-Za-z0-9_]{0,10}(:[0-9]{1,2})?|[1-9][0-9]{0,4}_[A-Za-z0-9_]{1,8}",
                                  fullmatch=True),
    ValueKind.WILDCARD: st.just("*"),
}
scalar = st.one_of(*SCALARS.values()).map(Scalar)

ESCAPES = [r"\\", r"\n", r"\t", r"\v", r"\b", r"\r", r"\f", r"\a", r"\"", r"\'", r"\x41", r"\xfF"]
_CHARS = st.sampled_from(string.ascii_letters + string.digits + " !#$%&'()*+,-./:;<=>?@[]^_`{|}~")
part_body = st.lists(st.one_of(_CHARS, _CHARS, st.sampled_from(ESCAPES)), max_size=8).map("".join)
long_part_body = st.lists(st.one_of(_CHARS, st.sampled_from(ESCAPES), st.from_regex(r"\\u[0-9A-F]{4}", fullmatch=True)),
                          max_size=8).map("".join)


@st.composite
def eds_string(draw) -> String:
    unicode = draw(st.booleans())
    body = long_part_body if unicode else part_body
    parts = [f'{"L" if unicode else ""}"{draw(body)}"']
    parts += [f'"{draw(body)}"' for _ in range(draw(st.integers(0, 2)))]
    return String(tuple(parts))


def fields_of(value) -> st.SearchStrategy[list[Field]]:
    return st.lists(st.builds(Field, value, comments), min_size=1, max_size=4)


values = st.recursive(st.one_of(st.none(), scalar, eds_string()),
                      lambda inner: st.builds(Group, fields_of(inner)), max_leaves=12)

keyword = st.from_regex(r"[A-Za-z_][A-Za-z0-9_]{0,12}|[1-9][0-9]{0,4}_[A-Za-z0-9_]{1,10}", fullmatch=True)


@st.composite
def entry(draw) -> Entry:
    fields = draw(fields_of(values))
    # writer limit: one comment at most on an empty last field (a second one would lead the next line)
    if fields[-1].value is None:
        del fields[-1].comments[1:]
    return Entry(draw(keyword), fields, draw(comments), draw(comments))


_CANOPEN_NAME = r"(?i:FileInfo|DeviceInfo|MandatoryObjects|[0-9A-F]{4})"
section_name = st.from_regex(r"[A-Za-z0-9_]{1,10}( [A-Za-z0-9_]{1,8}){0,2}", fullmatch=True).filter(
    lambda name: not __import__("re").fullmatch(_CANOPEN_NAME, name))
section = st.builds(Section, section_name, st.lists(entry(), max_size=3),
                    st.lists(comment, max_size=1), comments)  # writer limit: one header comment
eds_model = st.builds(EdsFile, st.lists(section, min_size=1, max_size=3), st.none(), comments)


@SETTINGS
@given(eds_model)
def test_written_model_reads_back_equal(model):
    text = write(model)
    back = edsconv.parse(text)
    assert back == model, text
    assert {d.code for d in back.diagnostics} <= {"EDS008", "EDS009", "EDS004"}, text


@SETTINGS
@given(st.sampled_from(list(SCALARS)).flatmap(lambda kind: st.tuples(st.just(kind), SCALARS[kind])))
def test_generated_scalar_spellings_have_their_kind(kind_and_raw):
    kind, raw = kind_and_raw
    assert Scalar(raw).kind is kind


# --- random text and bytes ------------------------------------------------------------------------

FRAGMENTS = ["[", "]", "{", "}", ",", ";", "=", '"', 'L"', "\\", "$", "\n", "\r", " ", "\t", "\x00", "\x1a",
             "\xe9", "\x80", "[File]", "[S]", "Key =", "65535_K=", "0x1F", "1.5", "12-31-2003", "Param1", "*",
             '"a\\qb"', "QUIET-NAN", "\\u0041", "@", "#"]



@SETTINGS
@given(st.one_of(st.text(max_size=300), st.lists(st.sampled_from(FRAGMENTS), max_size=60).map("".join)))
@example("[S]\nA = {1\n")
@example('[S]\nA = "\\')
@example("\x00\x00[\x00]")
def test_random_text_never_raises(text):
    eds = edsconv.parse(text)
    assert isinstance(eds.diagnostics, list)
    for diagnostic in eds.diagnostics:
        assert diagnostic.code.startswith("EDS") and diagnostic.line >= 1 and diagnostic.column >= 1


@SETTINGS
@given(st.binary(max_size=300))
@example(b"\xef\xbb\xbf\xff\xfe[S]\nA=\"\x81\";")
def test_random_bytes_never_raise(data):
    eds = edsconv.parse(data)
    assert all(d.line >= 1 for d in eds.diagnostics)


# --- mutations of a real-looking EDS -------------------------------------------------------------

SAMPLE = """$ EDS for a test adapter
[File]
        DescText = "Test Adapter EDS";
        CreateDate = 04-20-2004;
        CreateTime = 10:51:51;
        Revision = 1.4;                 $ EDS revision
[Device]
        VendCode = 65535;
        ProdName = "Adapter" " 1";
        Icon = "adapter.ico";
[Params]
        Param1 =
                0,                      $ reserved
                ,,                      $ link path
                0x0000,                 $ descriptor
                0xC7, 2,
                "Output", "bytes", "Output",
                0,128,8,
                ,,,,
                ,,,,
                ;
        Enum1 = 0, "Off", 1, "On";
[Assembly]
        Assem100 = "Out", "20 04 24 64 30 03", 4, 0x0000,,,
                16, Param1, 16, ;
[Port]
        Port1 = TCP, "EtherNet/IP", "20 F5 24 01", 2;
[Connection Manager]
        Connection1 = 0x04010002, 0x44640405, Param1, Assem100, , ,
                {0x0E,*}, { 44, {22,33,11} }, "Exclusive Owner",
                L"X\\u03C0" "y", "", 1.5E-3, QUIET-NAN;
[65535_Vendor Data]
        65535_Feature = Yes, SLOT_MINUS_ONE, Param10:0;
$ end
"""

mutation = st.tuples(st.integers(0, len(SAMPLE)), st.integers(0, 12), st.sampled_from(FRAGMENTS + [""]))


@SETTINGS
@given(st.lists(mutation, min_size=1, max_size=4))
def test_mutated_eds_reads_back_equal_after_writing(mutations):
    text = SAMPLE
    for at, length, insert in mutations:
        at = min(at, len(text))
        text = text[:at] + insert + text[at + length:]
    eds = edsconv.parse(text)
    assert edsconv.parse(write(eds)) == eds, text


@pytest.mark.parametrize("text", ["$c\njunk\n[File]\nA = 1;\n", "[S]\nA = 1;\n$c\nB = @\nC = 3;\n"])
def test_comment_before_unparsed_text_round_trips(text):
    eds = edsconv.parse(text)
    assert edsconv.parse(write(eds)) == eds


def test_sample_is_clean():
    eds = edsconv.parse(SAMPLE)
    assert eds.diagnostics == []
    assert len(eds.sections) == 7
