"""The fast reader (simple statements by one regex, the rest by Lark) against Lark reading everything.

``edsconv.parse`` matches section headers and entries without braces with a regex composed
from the grammar's terminals, and gives Lark only statements with braces and syntax errors.
``parse_with_lark`` reads every statement with Lark, as the reader did before: it is the
reference. Both must give the same model, the same positions of every node and comment, and
the same diagnostics in the same order, on every corpus file and on generated, random and
mutated text (errors included).
"""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import example, given
from hypothesis import strategies as st

import edsconv
from conftest import REAL_EDS, REPO, needs_real_corpus
from edsconv.eds.reader import parse_with_lark
from edsconv.eds.syntax import Comment, EdsFile, Entry, Field, Group, Scalar, Section, String, Unparsed
from edsconv.eds.writer import write
from test_properties import FRAGMENTS, SAMPLE, SETTINGS, eds_model

#: more pieces of statements than test_properties' FRAGMENTS: the shapes the fast path tells apart
PIECES = [*FRAGMENTS, "A = 1;", "B = {1,2};", "$x\n", '"b" "c"', ",,", " = ", "1 2", '"\\u0041"', "\f", "\v",
          '"a,b"', '"a;b"', "\x1c", "\x85", "C\n$ k = 1\n= 2;", "D $=\n\n="]

OWN = sorted(p for p in (REPO / "corpus").rglob("*") if p.suffix.lower() == ".eds")


def _comments(comments: list[Comment]) -> list:
    return [(c.text, c.offset, c.line, c.column) for c in comments]


def _value(value) -> object:
    if isinstance(value, Group):
        return ("group", [_field(f) for f in value.fields])
    if isinstance(value, String):
        return ("string", value.parts)
    if isinstance(value, Scalar):
        return ("scalar", value.raw)
    assert value is None
    return None


def _field(field: Field) -> tuple:
    return field.offset, field.line, field.column, _value(field.value), _comments(field.comments)


def _item(item: Entry | Unparsed) -> tuple:
    if isinstance(item, Unparsed):
        return ("unparsed", item.text, item.offset, _comments(item.comments), _comments(item.leading_comments))
    return (item.keyword, item.offset, item.line, item.column, item.end_offset, item.end_line, item.end_column,
            _comments(item.comments), _comments(item.leading_comments), [_field(f) for f in item.fields])


def _section(section: Section | None) -> tuple | None:
    if section is None:
        return None
    return (section.name, section.offset, section.line, _comments(section.comments),
            _comments(section.leading_comments), [_item(item) for item in section.items()],
            [index for index, _ in section.unparsed])


def dump(eds: EdsFile) -> tuple:
    """Everything the syntax model holds, positions included (equality leaves them out)."""
    return (eds.encoding, eds.newline, _section(eds.preamble), [_section(s) for s in eds.sections],
            _comments(eds.trailing_comments),
            [(d.code, d.severity, d.line, d.column, d.message) for d in eds.diagnostics])


def assert_same_reading(data: str | bytes) -> EdsFile:
    fast = edsconv.parse(data)
    assert dump(fast) == dump(parse_with_lark(data)), data
    return fast


def unread_entries(eds: EdsFile) -> int:
    return sum(not entry.is_read for section in eds.sections for entry in section.entries)


# --- every file we hold -------------------------------------------------------------------------


@pytest.mark.parametrize("path", OWN, ids=lambda p: str(p.relative_to(REPO)))
def test_own_corpus_reads_the_same_both_ways(path: Path):
    assert_same_reading(path.read_bytes())


@needs_real_corpus
@pytest.mark.parametrize("path", REAL_EDS, ids=lambda p: p.name)
def test_real_corpus_reads_the_same_both_ways(path: Path):
    assert_same_reading(path.read_bytes())


def test_the_fast_path_reads_the_simple_statements_and_lark_the_rest():
    eds = edsconv.parse(SAMPLE)
    entries = [entry for section in eds.sections for entry in section.entries]
    assert unread_entries(eds) == len(entries) - 1  # all but Connection1, which has braces
    assert [entry.keyword for entry in entries if entry.is_read] == ["Connection1"]
    assert eds == parse_with_lark(SAMPLE)
    assert unread_entries(eds) == 0  # comparing read them


def test_an_entry_makes_its_fields_once_and_keeps_them():
    eds = edsconv.parse("[S]\nA = 1, 0x2, ,  $ note\n  ; $ after\n")
    entry = eds.sections[0].entries[0]
    assert not entry.is_read
    fields = entry.fields
    assert entry.fields is fields
    assert [f.raw for f in fields] == ["1", "0x2", None, None]
    assert [(f.line, f.column) for f in fields] == [(2, 5), (2, 8), (2, 13), (3, 3)]
    assert [[c.text for c in f.comments] for f in fields] == [[], [], [" note"], [" after"]]
    fields[0].comments.append(Comment("added"))
    assert eds.sections[0].entries[0].fields[0].comments[-1].text == "added"


# --- generated, random and mutated text ---------------------------------------------------------


@SETTINGS
@given(eds_model)
def test_written_models_read_the_same_both_ways(model):
    assert_same_reading(write(model))


@SETTINGS
@given(st.one_of(st.text(max_size=300), st.lists(st.sampled_from(PIECES), max_size=60).map("".join)))
@example("[S]\nA = {1\n")
@example('[S]\nA =\x1a"x", 1 \x1a;\nB = 1 \x1a, 2;\n')
@example("[S]\nA = 1 B = 2;\n")
@example("[S]\nA = 1\n[T]\nB = {2}, 3 $c\n;$d\n")
@example("[S]\nA = 1, $c\n\x1a;\n")
@example('A = "x\\q" "y" L"z";')
def test_random_text_reads_the_same_both_ways(text):
    assert_same_reading(text)


#: pieces of entries with comments, strings with '$' and ',' among them (runs.entry_contents scans them)
COMMENTED = ["$ c\n", " $c,d\n", '"a$b"', '"a" $ c\n "b"', '"x,y"', ",", ", ", ",,", "0x10", "Param1", " ", "\n",
             '""', '"q" "r"', "\x1a", "1", '"$"', '"\\n"']


@SETTINGS
@given(st.lists(st.sampled_from(COMMENTED), max_size=20).map("".join))
@example('"a" $ c\n "b", 1 $d\n,')
@example('$ lead\n , 2 $ c\n')
@example('"US$", 1 $ price\n')
def test_commented_entries_read_the_same_both_ways(body):
    """An entry whose fields carry comments (EZ-EDS), its fields made on first use, against Lark."""
    assert_same_reading(f"[S]\nA = {body};  $ after\nB = 1;\n")


@SETTINGS
@given(st.lists(st.tuples(st.integers(0, len(SAMPLE)), st.integers(0, 12), st.sampled_from([*PIECES, ""])),
                min_size=1, max_size=4))
def test_mutated_eds_reads_the_same_both_ways(mutations):
    text = SAMPLE
    for at, length, insert in mutations:
        at = min(at, len(text))
        text = text[:at] + insert + text[at + length:]
    assert_same_reading(text)


def test_many_errors_stop_both_ways_alike():
    text = "[File]\n" + "Revision 1.1;\n" * 120 + "A = 1;\n"
    eds = assert_same_reading(text)
    assert eds.diagnostics[-1].code == "EDS014"
