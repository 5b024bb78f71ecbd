"""An edit that changes where statements begin or end is read again from the statement before it until
the reading meets the last one (edsconv.lsp.region): what the analysis answers is what a fresh one
answers, and hover and completion answer from the last model when the records are all that changed
(edsconv.model.rebuild.with_entries_rebuilt)."""

from __future__ import annotations

import random
import re
from collections import Counter

import pytest

from conftest import SHARED_REAL, needs_real_corpus
from edsconv.eds.lark_reader import MAX_SYNTAX_ERRORS
from edsconv.lsp.analysis import analyse
from edsconv.lsp.incremental import Carried
from test_lsp_incremental import EXAMPLE, assert_exact

PARAM2 = "        Param2 =\n                0,\n                6,"
NEW_PARAM = 'Param9 = 0,,,0x0000,0xC7,2,"Speed","rpm","",0,100,0;'


def edited(old: str, new: str, text: str = EXAMPLE) -> str:
    assert text.count(old) == 1, old
    return text.replace(old, new)


@pytest.mark.parametrize(("name", "text", "read", "early"), [
    # a section whose entries make no records: its part of the model is made again whole
    ("a character before a keyword of [File]", edited("        DescText", "        XDescText"), 1, True),
    ("a keyword of [Device] renamed to a known one", edited("ProdName =", "ProdNam ="), 1, True),
    ("two entries joined by a deleted ';'", edited("ProdCode = 1001;", "ProdCode = 1001"), 2, True),
    ("a ';' typed inside a value: the rest is text the reader cannot read",
     edited('Catalog = "EX-8DIO";', "Catalog = EX;-8DIO;"), 1, True),
    ("a '$' that makes the rest of an entry a comment",
     edited('ProdName = "Example IO Adapter 8DI/8DO";', 'ProdName = "Example IO Adapter 8DI/8DO" $;'), 2, True),
    ("an entry deleted with its line", edited("        MajRev = 1;\n", ""), 1, True),
    ("an entry typed on a new line", edited("        MajRev = 1;\n", "        MajRev = 1;\nFoo = 2;\n"), 2, True),
    ("the first characters of an entry typed on a new line",
     edited("        MajRev = 1;\n", "        MajRev = 1;\nFo\n"), 1, True),
    ("an entry with braces typed", edited("        MajRev = 1;\n", "        MajRev = 1;\nFoo = {1,{2}};\n"), 2, True),
    ("an unterminated string", edited('Icon = "io_adapter.ico";', 'Icon = "io_adapter.ico;'), 0, True),
    # a section of records: the records replaced and made
    ("a parameter renamed", edited("        Param1 =", "        XParam1 ="), 1, True),
    ("a parameter the assemblies and a group name renamed", edited("        Param2 =", "        XParam2 ="), 1, True),
    # the reading stops before the next section's header
    ("a parameter typed after the last one", edited("                1;\n\n[Groups]",
                                                    f"                1;\n{NEW_PARAM}\n\n[Groups]"), 1, True),
    ("an assembly renamed: the connections naming it no longer resolve",
     edited("        Assem150 =", "        Assem15 ="), 1, True),
    ("two parameters read as one", edited(f";                       $ decimal places\n{PARAM2}",
                                          f"                        $ decimal places\n{PARAM2}"), 0, True),
    ("a parameter with an enum renamed: its EnumN pairs with nothing", edited("        Param3 =", "        Param33 ="),
     1, True),
])
def test_an_edit_of_where_statements_end_reads_only_the_statements_it_touched(name, text, read, early):
    carried = Carried()
    analyse(EXAMPLE, carried=carried)
    before = carried.read
    assert assert_exact(text, carried, name) == early, name
    assert carried.splice == "region", name
    assert carried.read == read and carried.reused == before - sum(1 for _ in carried.edit.old), name
    assert_exact(EXAMPLE, carried, name)  # and back again


def test_a_new_parameter_is_given_its_enum_at_once():
    # Enum3 gives Param3 its enum: a parameter typed with that number has it in the early answer too
    base = edited("        Param3 =", "        XParam3 =")
    carried = Carried()
    analyse(base, carried=carried)
    assert assert_exact(EXAMPLE, carried)
    assert carried.splice == "region"


@pytest.mark.parametrize(("name", "text"), [
    ("an enum renamed", edited("        Enum3 =", "        XEnum3 =")),
    ("an enum deleted", edited('        Enum3 = 0,"Clear", 1,"Hold last state", 2,"Use fault value";\n', "")),
    ("an enum's value edited", edited('2,"Use fault value"', '2,"Use the fault value"')),
    ("a [Device] entry's value edited", edited("MajRev = 1;", "MajRev = 2;")),
])
def test_an_edit_of_an_entry_without_a_record_of_its_own_answers_hover_at_once(name, text):
    carried = Carried()
    analyse(EXAMPLE, carried=carried)
    assert assert_exact(text, carried, name), name


@pytest.mark.parametrize(("name", "text"), [
    ("[Assembly]'s Revision", edited("        Revision = 2;", "        Revision = 3;")),
    ("an entry of the typed view (AssemExaN)", edited("        Revision = 2;", "        Revision = 2;\n"
                                                     '        AssemExa1 = "x",,,0x0000,,,8,Param2;')),
    ("a section named twice", EXAMPLE.replace("[Groups]", "[Device]\n        X = 1;\n[Groups]")
     .replace("MajRev = 1;", "MajRev = 2;")),
])
def test_an_edit_of_what_other_entries_read_has_hover_wait_for_the_whole_model(name, text):
    carried = Carried()
    base = text.replace("MajRev = 2;", "MajRev = 1;").replace("Revision = 3;", "Revision = 2;") \
        .replace('        AssemExa1 = "x",,,0x0000,,,8,Param2;', "        AssemExa1 = 1;")
    analyse(base, carried=carried)
    assert not assert_exact(text, carried, name), name
    assert carried.splice in ("reread", "region"), name


def test_an_entry_typed_character_by_character_answers_as_a_fresh_analysis_at_every_step():
    carried = Carried()
    analyse(EXAMPLE, carried=carried)
    splices = set()
    for typed in range(1, len(NEW_PARAM) + 1):
        assert_exact(edited("\n[Groups]", f"{NEW_PARAM[:typed]}\n\n[Groups]"), carried, NEW_PARAM[:typed])
        splices.add(carried.splice)
    assert "region" in splices


@pytest.mark.parametrize(("name", "text"), [
    ("a section header typed", edited("        MajRev = 1;\n", "        MajRev = 1;\n[Other]\n")),
    ("a keyword another entry of the section has", edited("ProdName =", "MajRev =")),
    ("an entry renamed to what a duplicate was", edited("MinRev = 2;", "MinRev = 2;\nMajRev = 3;")),
    ("the section header's line", edited("[Device]\n", "[Device] X = 1;\n")),
    ("the text before the first section", "$ x\n" + EXAMPLE.replace("[File]", "X = 1;\n[File]", 1)),
    ("the last entry's ';' deleted at the end of the file", EXAMPLE.rstrip()[:-1]),
])
def test_an_edit_the_region_cannot_take_is_read_whole(name, text):
    carried = Carried()
    analyse(EXAMPLE, carried=carried)
    assert_exact(text, carried, name)
    assert carried.splice == "", name


def test_a_file_near_the_reader_s_limit_of_syntax_errors_is_read_whole():
    # the reader stops reading after MAX_SYNTAX_ERRORS; a region read counts from nothing
    missing = "".join(f"Group{number} = 1\n" for number in range(3, MAX_SYNTAX_ERRORS + 2))  # no ';': an error each
    broken = EXAMPLE.replace("[Groups]", "[Groups]\n" + missing)
    assert sum(d.code == "EDS002" for d in analyse(broken).diagnostics) == MAX_SYNTAX_ERRORS - 1
    carried = Carried()
    analyse(broken, carried=carried)
    assert_exact(broken.replace("        Param1 =", "        XParam1 ="), carried)
    assert carried.splice == ""
    few = EXAMPLE.replace("[Groups]", "[Groups]\n?\n")
    analyse(few, carried=carried)
    assert_exact(few.replace("        Param1 =", "        XParam1 ="), carried)
    assert carried.splice == "region"


def test_lines_typed_in_a_region_move_the_nodes_after_it():
    carried = Carried()
    analyse(EXAMPLE, carried=carried)
    text = edited("        Param1 =", "        Param1 =\n\n")
    assert_exact(text.replace("        Param1 =", "        XParam1 ="), carried)
    assert carried.splice == "region" and carried.edit.lines is not None and carried.edit.lines.moved == 2


def test_a_brace_left_open_makes_the_region_give_up_and_the_text_read_whole():
    # the '{' makes the reader look for the '}' to the end of the file: past 64 KB it gives up
    line = 'Param{0} = 0,,,0x0000,0xC7,2,"P{0}","","",0,100,{0};\n'
    text = '[File]\nDescText = "x";\n[Params]\n' + "".join(line.format(n) for n in range(1, 3001))
    carried = Carried()
    analyse(text, carried=carried)
    assert_exact(text.replace("Param10 = 0,", "Param10 = {0,"), carried)
    assert carried.splice == ""
    assert_exact(text.replace("Param10 = 0,", "Param10 = 0 ,"), carried)  # and a region again after it
    assert carried.splice == "region"


def test_a_blank_line_deleted_in_a_file_with_unreadable_text_is_read_again_on_the_right_lines():
    # blank lines typed inside unreadable text change it, so respaced() refuses such a file: the region
    # takes the blank line deleted, and the editor's lines are cut where the last text's lines were
    base = ";\n" + EXAMPLE
    carried = Carried()
    analyse(base, carried=carried)
    assert_exact(base.replace("1;\n\n[Groups]", "1;\n[Groups]"), carried)
    assert carried.splice == "region" and carried.edit.lines.moved == -1


#: Entries a random edit types, whole or their first characters
TYPED_ENTRIES = ('Param99 = 0,,,0x0000,0xC7,2,"x","","",0,1,0;', "Foo = 1;", 'Enum1 = 0,"a";',
                 'Assem9 = "a","",2,0x0000,,,16,Param1;', "Bar = {1,{2}};")


def structural_edit(text: str, rng: random.Random) -> str:
    """``text`` with one edit of where statements begin or end on a random line: a character typed
    before or deleted at its keyword, a ``;"$[]={},`` typed or one deleted, an entry typed (whole or
    its first characters) on a line of its own, the line deleted or doubled, broken in two, or a
    character typed."""
    starts = [0, *(match.end() for match in re.finditer("\n", text[:-1]))]
    line_start = rng.choice(starts)
    line_end = text.find("\n", line_start)
    line_end = len(text) if line_end < 0 else line_end
    keyword = line_start + len(text[line_start:line_end]) - len(text[line_start:line_end].lstrip())
    at = rng.randint(line_start, line_end)
    marks = [index for index in range(line_start, line_end) if text[index] in ';"$=,'] or [at]
    cut = rng.choice(marks)
    entry = rng.choice(TYPED_ENTRIES)
    return rng.choice([
        lambda: text[:keyword] + rng.choice("XPa1_") + text[keyword:],
        lambda: text[:keyword] + text[keyword + 1:],
        lambda: text[:at] + rng.choice(';"$[]={},') + text[at:],
        lambda: text[:cut] + text[cut + 1:],
        lambda: text[:line_start] + entry[:rng.randint(1, len(entry))] + "\n" + text[line_start:],
        lambda: text[:line_start] + text[line_end + 1:],
        lambda: text[:line_start] + text[line_start:line_end + 1] + text[line_start:],
        lambda: text[:at] + "\n" + text[at:],
        lambda: text[:at] + rng.choice("abc 012") + text[at:],
    ])()


def assert_structural_edits_are_exact(text: str, seed: int, edits: int) -> Counter:
    """``edits`` structural edits of ``text`` in a row, each analysis compared with a fresh one; how each
    was read (and whether hover answered early), counted."""
    rng = random.Random(seed)
    carried = Carried()
    analyse(text, carried=carried)
    made: Counter = Counter()
    for _ in range(edits):
        text = structural_edit(text, rng)
        early = assert_exact(text, carried)
        made[carried.splice + (" early" if early else "")] += 1
    return made


@pytest.mark.parametrize("seed", range(3))
def test_structural_edits_of_the_example_answer_as_a_fresh_analysis(seed):
    made = assert_structural_edits_are_exact(EXAMPLE, seed, 24)
    assert made["region early"] > 0


@needs_real_corpus
def test_structural_edits_of_the_largest_real_file_answer_as_a_fresh_analysis():
    path = max(SHARED_REAL.glob("*.eds"), key=lambda p: p.stat().st_size)
    made = assert_structural_edits_are_exact(path.read_bytes().decode("latin-1"), 3, 6)
    assert sum(made.values()) == 6


if __name__ == "__main__":  # the long run the tests above sample: seed, then edits per file
    import sys

    from test_lsp_incremental import real_files

    seed, edits = (int(argument) for argument in sys.argv[1:3])
    for number, real in enumerate(real_files()):
        print(real.name, dict(assert_structural_edits_are_exact(real.read_bytes().decode("latin-1"),
                                                                seed * 1000 + number, edits)))
