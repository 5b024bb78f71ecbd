"""What the language server asks of the library: the node at a position (eds/locate.py), every place
naming an entry (model/references.py), and the rename and suppression edits built on them."""

from __future__ import annotations

import pytest

import edsconv
from conftest import REAL_EDS, REPO, needs_real_corpus
from edsconv.eds.locate import locate, value_end, word_at
from edsconv.lsp import actions, navigation
from edsconv.lsp.analysis import analyse
from edsconv.model.references import occurrence_at, references_to

EXAMPLE = (REPO / "corpus" / "examples" / "io_adapter.eds").read_text()


def apply(text: str, edits: list[tuple[tuple[int, int, int, int], str]]) -> str:
    """``text`` with one-line edits (1-based spans) applied, last first."""
    lines = text.split("\n")
    for (line, column, end_line, end_column), new in sorted(edits, reverse=True):
        assert line == end_line
        current = lines[line - 1]
        lines[line - 1] = current[:column - 1] + new + current[end_column - 1:]
    return "\n".join(lines)


def apply_fix(text: str, fix: actions.Fix) -> str:
    return apply(text, [((e.line, e.column, e.end_line, e.end_column), e.text) for e in fix.edits])


def test_locate_finds_header_keyword_and_nested_field():
    eds = edsconv.parse(EXAMPLE)
    header = locate(eds, 87, 3)
    assert header.on_header and header.section.name == "Assembly" and header.entry is None
    keyword = locate(eds, 89, 12)
    assert keyword.on_keyword and keyword.entry.keyword == "Assem100"
    member = locate(eds, 95, 21)
    assert (member.entry.keyword, member.field_path, member.field.raw) == ("Assem100", (7,), "Param2")
    assert locate(eds, 2, 5).section is None  # the comment lines before the first section
    stringi = edsconv.parse('[Params]\nParam1 = 0,,,0,0xC6,1,"a","","",0,1,0,,,,,,,,,,{1,{"eng",0xD0,4,"x"}};\n')
    nested = locate(stringi, 2, 63)
    assert nested.field_path == (21, 1, 2) and nested.field.raw == "4"


def test_words_and_value_ends():
    line = '        8,Param2, "a \\" b", 0x10;'
    assert word_at(line, 14) == (11, 17, "Param2")
    assert word_at(line, 17) == (11, 17, "Param2")  # just after the word still touches it
    assert word_at(line, 9) == (9, 10, "8")
    assert value_end(line, 19) == 27  # the escaped quote does not end the string
    assert value_end(line, 29) == 33


def test_references_cover_members_connections_groups_paths_and_paired_entries():
    analysis = analyse(EXAMPLE)
    kinds = {(o.kind, o.entry) for o in references_to("Param2", analysis.spans)}
    assert kinds == {("definition", "Param2"), ("group member", "Group1"), ("assembly member", "Assem100"),
                     ("assembly member", "Assem151")}
    assert {o.kind for o in references_to("Param3", analysis.spans)} >= {"paired entry", "group member"}
    assert {o.entry for o in references_to("Param1", analysis.spans)} == {"Param1", "Connection1", "Connection2"}
    broken = (REPO / "corpus" / "broken" / "figure_C09_as_printed.eds").read_text()
    in_path = references_to("Param1", analyse(broken).spans)
    assert [(o.kind, o.line, o.column) for o in in_path] == [("path", 39, 30)]
    assert occurrence_at(analysis.spans, 95, 25).target == "Param2"
    assert occurrence_at(analysis.spans, 95, 26) is None


@needs_real_corpus
@pytest.mark.parametrize("path", REAL_EDS[::7], ids=lambda p: p.name[:60])
def test_every_span_of_a_real_file_spells_what_it_names(path):
    text = edsconv.eds.source.decode(path.read_bytes()).text
    analysis = analyse(text)
    for span in analysis.spans:
        written = analysis.line_text(span.line)[span.column - 1:span.end_column - 1]
        family, number = edsconv.spec_tables.split_numbered(span.target)
        assert written.lstrip("0") == f"{span.prefix}{number}" or int(written, 0) == number, (span, written)


def test_rename_renumbers_every_place_and_the_file_stays_clean():
    analysis = analyse(EXAMPLE)
    edits = navigation.rename(analysis, 84, 38, "Param7")  # from the group member "2"
    renamed = analyse(apply(EXAMPLE, edits))
    assert "Param2" not in renamed.device.parameters and renamed.device.parameters["Param7"].name == "Input Filter"
    assert [d.code for d in renamed.diagnostics] == []
    assert renamed.device.groups[0].members[0].keyword == "Param7"


@pytest.mark.parametrize(("line", "column", "new_name", "reason"), [
    (95, 20, "Param3", "Param3 exists already"),
    (95, 20, "Assem7", "only be renumbered within its family"),
    (68, 10, "Param1", "Param1 exists already"),
    (14, 12, "VendCode2", "no numbered entry or reference here"),
])
def test_rename_is_refused_where_it_would_break_the_file(line, column, new_name, reason):
    with pytest.raises(navigation.RenameRefused, match=reason):
        navigation.rename(analyse(EXAMPLE), line, column, new_name)


def test_rename_is_refused_when_a_paired_entry_of_the_new_number_exists():
    text = EXAMPLE.replace('        Enum3 = 0,"Clear"', '        Enum9 = 0,"x";\n        Enum3 = 0,"Clear"')
    with pytest.raises(navigation.RenameRefused, match="Enum9 exists already"):
        navigation.rename(analyse(text), 55, 10, "Param9")


def test_suppression_comment_goes_on_the_entry():
    broken = EXAMPLE.replace("8,Param2,\n                8,;", "8,Param9,\n                8,;")  # Assem100
    first = actions.suppression(analyse(broken), "EDS301", 95, 19)
    assert first.edits == (actions.Edit(89, 19, 89, 19, " $ edsconv: ignore[EDS301]"),)
    suppressed = apply_fix(broken, first)
    second = actions.suppression(analyse(suppressed), "EDS302", 95, 19)
    assert apply_fix(suppressed, second).splitlines()[88] == "        Assem100 = $ edsconv: ignore[EDS301, EDS302]"
    assert actions.suppression(analyse(suppressed), "EDS301", 95, 19) is None
    commented = actions.suppression(analyse(EXAMPLE), "EDS999", 114, 20)  # Connection1's first line has no comment
    assert commented.edits[0].text == " $ edsconv: ignore[EDS999]"
    on_commented_line = actions.suppression(analyse(EXAMPLE), "EDS999", 30, 18)  # Param1: comment on field line only
    assert on_commented_line.edits[0].line == 29
    header = EXAMPLE.replace("[Port]", "[Port]  $ the port")
    own_line = actions.suppression(analyse(header), "EDS999", 134, 2)
    assert own_line.edits == (actions.Edit(134, 1, 134, 1, "$ edsconv: ignore[EDS999]\n"),)


def test_formatting_refuses_a_file_with_syntax_errors():
    broken = analyse(EXAMPLE.replace("Revision = 1.1;", "Revision = 1.1"))
    assert actions.formatting_edits(broken) == actions.range_formatting_edits(broken, 1, 200) == []
    assert "1 syntax error(s)" in (actions.format_refusal(broken) or "")
    assert actions.format_refusal(analyse(EXAMPLE)) is None and actions.formatting_edits(analyse(EXAMPLE))


def test_definitions_are_the_entries_of_the_records_and_skip_records_made_without_one():
    from edsconv.model import Device, Parameter
    from edsconv.model.references import definitions

    eds = edsconv.parse((REPO / "corpus" / "examples" / "io_adapter.eds").read_bytes())
    device = edsconv.build(eds)
    defined = definitions(device)
    assert list(defined)[:4] == ["Param1", "Param2", "Param3", "Param4"]
    assert defined["Assem100"] is eds.section("Assembly").entry("Assem100")
    made = Device(parameters={**device.parameters, "Param9": Parameter("Param9", "Param", 9)})  # as from XML
    assert "Param9" not in definitions(made) and definitions(made)["Param2"] is defined["Param2"]
