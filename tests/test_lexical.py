"""One test per lexical rule of ISO 15745-4 C.4.1.2 / C.4.1.3: accepted and rejected forms."""

from __future__ import annotations

import pytest

import edsconv
from conftest import codes, parse_ok, values
from edsconv.eds.syntax import Group, Scalar, String, ValueKind
from edsconv.model.values import to_stringi

# --- C.4.1.2.2.5 / .6 sections -------------------------------------------------------------

@pytest.mark.parametrize("header, name", [
    ("[File]", "File"),
    ("[Device Classification]", "Device Classification"),
    ("[Connection Manager]", "Connection Manager"),
    ("[65535_Foo]", "65535_Foo"),
    ("[Class178_Vendor1]", "Class178_Vendor1"),
])
def test_valid_section_names(header, name):
    eds = parse_ok(f"{header}\n")
    assert [(s.name, s.line, s.column) for s in eds.sections] == [(name, 1, 1)]


@pytest.mark.parametrize("header, name", [
    ("[Diagnostics/Extra Class]", "Diagnostics/Extra Class"),
    ("[Device  Classification]", "Device  Classification"),
    ("[Device-Info]", "Device-Info"),
])
def test_section_names_outside_the_keyword_rules_are_kept_with_eds006(header, name):
    eds = edsconv.parse(f"[File]\n  {header}\nA = 1;\n")
    assert codes(eds) == [("EDS006", 2, 3)]
    assert eds.sections[1].name == name
    assert eds.sections[1].entries[0].keyword == "A"
    assert not eds.has_errors


def test_empty_sections_are_kept():
    eds = parse_ok("[File]\n[Device]\n\n[Params]\n")
    assert [(s.name, s.entries, s.line) for s in eds.sections] == [("File", [], 1), ("Device", [], 2),
                                                                   ("Params", [], 4)]


def test_duplicate_section_eds008_keeps_both():
    eds = edsconv.parse("[File]\nA = 1;\n[Device]\n[File]\nA = 2;\n")
    assert codes(eds) == [("EDS008", 4, 1)]
    assert "line 1" in eds.diagnostics[0].message
    assert [s.name for s in eds.sections] == ["File", "Device", "File"]
    assert [s.entries[0].fields[0].value for s in (eds.sections[0], eds.sections[2])] == [Scalar("1"), Scalar("2")]


def test_duplicate_entry_eds009_keeps_both():
    eds = edsconv.parse("[File]\nA = 1;\nB = 0;\n  A = 2;\n[Device]\nA = 3;\n")
    assert codes(eds) == [("EDS009", 4, 3)]
    assert [(e.keyword, e.fields[0].value.raw) for e in eds.sections[0].entries] == [("A", "1"), ("B", "0"),
                                                                                     ("A", "2")]


# --- C.4.1.2.2.8 - .12 entries and fields ------------------------------------------------------

def test_entry_over_many_lines_with_positions():
    eds = parse_ok("[S]\nEntry3 =\n    1,\n\n  0x2,\n    \"x\";\n")
    entry = eds.sections[0].entries[0]
    assert [(f.value.raw, f.line, f.column) for f in entry.fields] == [("1", 3, 5), ("0x2", 5, 3), ('"x"', 6, 5)]
    assert (entry.line, entry.column, entry.end_line, entry.end_column) == (2, 1, 6, 9)


@pytest.mark.parametrize("body, expected", [
    ("1,,3", ["1", None, "3"]),
    ("1, \t ,3", ["1", None, "3"]),
    (",,", [None, None, None]),
    (" ", [None]),
    ("1,", ["1", None]),
    (",1", [None, "1"]),
    ("1,\n ,\n 3", ["1", None, "3"]),
])
def test_empty_fields(body, expected):
    assert [v.raw if v else None for v in values(f"[S]\nK = {body};\n")] == expected


def test_empty_field_position_is_its_delimiter():
    entry = parse_ok("[S]\nK = 1, ,3;\n").sections[0].entries[0]
    assert (entry.fields[1].line, entry.fields[1].column) == (2, 8)


def test_semicolon_drops_trailing_fields():
    assert [v.raw for v in values("[S]\nK = 1,2;\n")] == ["1", "2"]


@pytest.mark.parametrize("keyword", ["1_EDS_AOP_Support", "65535_Entry", "Param1", "_x", "Entry_2"])
def test_keywords(keyword):
    assert parse_ok(f"[S]\n{keyword}= 1;\n").sections[0].entries[0].keyword == keyword


def test_nested_braces():
    (group,) = values("[S]\nEntry6= { 44, {22,33,11} };\n")
    assert isinstance(group, Group)
    first, inner = group.fields
    assert first.value == Scalar("44")
    assert [f.value.raw for f in inner.value.fields] == ["22", "33", "11"]
    assert (inner.line, inner.column) == (2, 15)


def test_wildcard_in_group():
    (group,) = values("[S]\nK = {0x0E,*};\n")
    assert [(f.value.raw, f.value.kind) for f in group.fields] == [("0x0E", ValueKind.HEX), ("*", ValueKind.WILDCARD)]


def test_empty_group_and_group_with_empty_fields():
    empty, sparse = values("[S]\nK = {}, {,};\n")
    assert [f.value for f in empty.fields] == [None]
    assert [f.value for f in sparse.fields] == [None, None]


def test_missing_comma_before_group_eds012():
    eds = edsconv.parse("[S]\nK = 1 {2};\n")
    assert codes(eds) == [("EDS012", 2, 7)]


# --- C.4.1.2.15 comments ----------------------------------------------------------------

def test_comments_where_white_space_may_stand():
    text = ("$ leading\n[S] $ header\nK = $ after equals\n 1, $ after one\n"
            " { $ in brace\n 2 $ after two\n }, \"a\" $ between strings\n \"b\" ; $ end\n$ trailing\n")
    eds = parse_ok(text)
    section = eds.sections[0]
    entry = section.entries[0]
    one, group, string = entry.fields
    assert [c.text for c in section.leading_comments] == [" leading"]
    assert [c.text for c in section.comments] == [" header"]
    assert [c.text for c in entry.comments] == [" after equals"]
    assert [c.text for c in one.comments] == [" after one"]
    assert [c.text for c in group.comments] == [" in brace"]
    assert [c.text for c in group.value.fields[0].comments] == [" after two"]
    assert [c.text for c in string.comments] == [" between strings", " end"]
    assert string.value.text == "ab"
    assert [c.text for c in eds.trailing_comments] == [" trailing"]
    assert [(c.line, c.column) for c in string.comments] == [(7, 9), (8, 8)]


@pytest.mark.parametrize("raw, text", [('"a$b"', "a$b"), ('"$"', "$"), ('"a $ b" "c"', "a $ bc")])
def test_dollar_inside_string_is_text(raw, text):
    eds = parse_ok(f"[S]\nK = {raw};\n")
    field = eds.sections[0].entries[0].fields[0]
    assert (field.value.text, field.comments) == (text, [])


def test_comment_between_fields_on_own_line():
    entry = parse_ok("[S]\nK = 1,\n$ own line\n 2;\n").sections[0].entries[0]
    assert [c.text for c in entry.fields[0].comments] == [" own line"]
    assert entry.fields[0].comments[0].own_line


# --- C.4.1.3.3 strings ----------------------------------------------------------------------

@pytest.mark.parametrize("raw, text, unicode", [
    ('"abc"', "abc", False),
    ('""', "", False),
    ('L"abc"', "abc", True),
    ('"ABC" "123" "XYZ"', "ABC123XYZ", False),
    ('L"ABC" "123" "XYZ"', "ABC123XYZ", True),
    ('"ABC" $this is a comment\n"123"\n   "XYZ"', "ABC123XYZ", False),
    ('"ABC""123"', "ABC123", False),
])
def test_strings_and_concatenation(raw, text, unicode):
    (value,) = values(f"[S]\nK = {raw};\n")
    assert isinstance(value, String)
    assert (value.text, value.unicode, value.kind) == (text, unicode, ValueKind.STRING)


@pytest.mark.parametrize("escape, char", [
    (r"\\", "\\"), (r"\n", "\n"), (r"\t", "\t"), (r"\v", "\v"), (r"\b", "\b"), (r"\r", "\r"),
    (r"\f", "\f"), (r"\a", "\a"), (r"\"", '"'), (r"\'", "'"), (r"\x41", "A"), (r"\x7f", "\x7f"),
])
def test_escapes_of_table_c4(escape, char):
    (value,) = values(f'[S]\nK = "<{escape}>";\n')
    assert value.text == f"<{char}>"


@pytest.mark.parametrize("raw, text", [
    ('"\\x41" "\\x42"', "AB"),
    ('"\\\\" "n"', "\\n"),
    ('"\\\\" "x41"', "\\x41"),
])
def test_escapes_are_decoded_in_each_part_before_joining(raw, text):
    """An escape never spans two parts: a part's text is the text of that part alone (C.4.1.3.3)."""
    (value,) = values(f"[S]\nK = {raw};\n")
    assert value.text == text
    assert value.text == "".join(String((part,)).text for part in value.parts)


def test_a_numeric_escape_split_over_two_parts_is_not_joined():
    eds = edsconv.parse('[S]\nK = "\\x4" "1";\n')
    assert eds.sections[0].entries[0].fields[0].value.text != "A"
    assert ("EDS003", 2, 6) in codes(eds)


def test_unicode_escape_in_long_string():
    (value,) = values('[S]\nK = L"Pi \\u03C0";\n')
    assert value.text == "Pi \u03c0"


@pytest.mark.parametrize("text, expected", [
    ('[S]\nK = "a\\qb";\n', [("EDS003", 2, 7)]),
    ('[S]\nK = 1,\n  "ok" "x\\%";\n', [("EDS003", 3, 10)]),
    ('[S]\nK = "\\u0041";\n', [("EDS004", 2, 6)]),
    ('[S]\nK = "a" L"b";\n', [("EDS016", 2, 9)]),
    ('[S]\nK = L"a"\n  L"b";\n', [("EDS016", 3, 3)]),
])
def test_rejected_string_forms(text, expected):
    eds = edsconv.parse(text)
    assert codes(eds) == expected
    # the entry is kept all the same
    assert isinstance(eds.sections[0].entries[0].fields[-1].value, String)


def test_unterminated_string_eds013_and_next_entry_is_read():
    eds = edsconv.parse('[S]\nA = 1;\nK = "abc;\nB = 2;\n')
    assert codes(eds) == [("EDS013", 3, 5)]
    assert [e.keyword for e in eds.sections[0].entries] == ["A", "B"]


# --- C.4.1.3.7 - C.4.1.3.13 scalars --------------------------------------------------------

@pytest.mark.parametrize("raw, kind", [
    ("0", "INTEGER"), ("254", "INTEGER"), ("-128", "INTEGER"), ("+7", "INTEGER"),
    ("18446744073709551615", "INTEGER"),
    ("0xFE", "HEX"), ("0x000000fe", "HEX"), ("0X1F", "HEX"),
    ("0b0101", "BINARY"), ("0B1", "BINARY"),
    ("1.5", "REAL"), ("-2.5", "REAL"), ("1.", "REAL"), (".004", "REAL"), ("-.5", "REAL"),
    ("1.5E+10", "REAL"), ("-2.5e-3", "REAL"), ("1E5", "REAL"), ("12.34567890E-1234", "REAL"),
    ("QUIET-NAN", "REAL_WORD"), ("SIGNAL-NAN", "REAL_WORD"), ("INFINITY", "REAL_WORD"),
    ("+INFINITY", "REAL_WORD"), ("-INFINITY", "REAL_WORD"),
    # illegal per C.4.1.3.7, kept with their spelling for the semantic layer to reject
    ("0254", "INTEGER"), ("0x0000000FE", "HEX"),
    ("12-31-2003", "DATE"), ("01-02-99", "DATE"),
    ("23:59:00", "TIME"), ("00:00:00", "TIME"),
    ("1.4", "REAL"),
    ("Param1", "WORD"), ("ProxyAssem2", "WORD"), ("SLOT", "WORD"), ("SLOT_MINUS_ONE", "WORD"),
    ("SYMBOL_ANSI", "WORD"), ("Module", "WORD"), ("ModuleMemberList", "WORD"), ("Yes", "WORD"),
    ("No", "WORD"), ("EtherNetIP", "WORD"), ("TCP", "WORD"), ("65535_Chassis", "WORD"),
    ("Param10:0", "WORD"), ("1_1756_Chassis", "WORD"),
    ("*", "WILDCARD"),
])
def test_scalar_kinds_keep_their_spelling(raw, kind):
    eds = parse_ok(f"[S]\nK = 0, {raw} ,1;\n")
    field = eds.sections[0].entries[0].fields[1]
    assert field.value == Scalar(raw)
    assert field.value.kind == ValueKind(kind)
    assert (field.line, field.column) == (2, 8)


@pytest.mark.parametrize("raw", ["1.2.3", "0x1.5", "12-31-2003x", "1:2:3:4", "QUIET_NAN-", "@", "a-b"])
def test_malformed_scalars_are_syntax_errors(raw):
    eds = edsconv.parse(f"[S]\nA = 1;\nK = {raw};\nB = 2;\n")
    assert [(d.code, d.line) for d in eds.diagnostics] == [("EDS001", 3)]
    assert [e.keyword for e in eds.sections[0].entries] == ["A", "B"]


def test_epath_string_is_kept_as_string():
    (value,) = values('[S]\nPath = "20 04 24 01 2C [Param2]";\n')
    assert isinstance(value, String)
    assert value.text == "20 04 24 01 2C [Param2]"


# --- C.4.1.3.5 STRINGI --------------------------------------------------------------------

STRINGI = """[S]
Field1 = { 3,
    {"eng",0xD0,4,"This is an ASCII English language string"},
    {"spa",0xD5,1000,L"Espa\\u00F1oles palabras"}, $ "Spanish words"
    {"deu",0xD0,4,"Spanische W" "\\xF6rter"} $ using UNICODE
}; $"Spanish words in German"
"""


def test_stringi_members():
    (group,) = values(STRINGI)
    members = to_stringi(group)
    assert [(m.language, m.type_code, m.charset, m.text) for m in members] == [
        ("eng", 0xD0, 4, "This is an ASCII English language string"),
        ("spa", 0xD5, 1000, "Espa\u00f1oles palabras"),
        ("deu", 0xD0, 4, "Spanische W\u00f6rter"),
    ]


@pytest.mark.parametrize("body", ['{2, {"eng",0xD0,4,"a"}}', '{1, {"eng",0xD0,4}}', '{"x"}',
                                  '{1, {eng,0xD0,4,"a"}}', '{1, 5}'])
def test_malformed_stringi_is_rejected(body):
    (group,) = values(f"[S]\nK = {body};\n")
    with pytest.raises(ValueError):
        to_stringi(group)
