"""The language server's incremental analysis (edsconv.lsp.incremental): after any edit, what it
answers is what a fresh analysis of the new text answers, and an edit inside a line re-reads
only the entry it touched."""

from __future__ import annotations

import random
import re

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from conftest import REAL_EDS, REPO, SHARED_REAL, needs_real_corpus
from edsconv.lsp.analysis import Analysis, Superseded, analyse
from edsconv.lsp.incremental import FULL_READ_EVERY, Carried, changed_lines
from edsconv.model import Reference
from edsconv.model.build import iter_references

#: with a suppression on an entry, so that the suppressions' lines are compared too
EXAMPLE = (REPO / "corpus" / "examples" / "io_adapter.eds").read_text(encoding="ascii").replace(
    "ProdCode = 1001;", "ProdCode = 1001;   $ edsconv: ignore[EDS103]")
#: the typed view of the content beyond the 2003 text (model.cip), which the model's equality leaves out
NEWER_CONTENT = ("capacity", "object_classes", "tcpip_interface", "ethernet_link", "dlr", "ingress_egress",
                 "devicenet", "extended_assemblies", "icon_contents", "additions")
#: what an edit may type or delete: the characters that change how an EDS reads
TYPED = [*';,"$[]{}=0123456789xAZaz -.\\\t', "\u00e9"]


def positions(analysis: Analysis) -> list:
    """Where every section, entry, field, comment and unreadable statement of the syntax model stands."""
    eds = analysis.eds
    return [*((section.line, section.column, [entry_positions(entry) for entry in section.entries],
               [(c.line, c.column) for c in (*section.leading_comments, *section.comments)],
               [(u.line, u.column) for _, u in section.unparsed]) for section in eds.holders()),
            [(c.line, c.column) for c in eds.trailing_comments]]


def entry_positions(entry) -> tuple:
    comments = [*entry.leading_comments, *entry.comments, *(c for f in entry.fields for c in f.comments)]
    return (entry.line, entry.column, [(f.line, f.column) for f in entry.fields],
            [(c.line, c.column) for c in comments])


def answers(analysis: Analysis) -> tuple:
    """Everything an analysis answers with: diagnostics, the places naming entries, the models, the lines."""
    return (analysis.lines, analysis.eds, positions(analysis),
            [(d.code, d.severity, d.line, d.column, d.end_line, d.end_column, d.message) for d in analysis.diagnostics],
            sorted((s.target, s.line, s.column, s.end_column, s.kind, s.entry) for s in analysis.spans),
            {keyword: (entry.line, entry.column) for keyword, entry in analysis.definitions.items()},
            analysis.device, analysis.device.comments, analysis.device.unreadable, analysis.device.erroneous,
            [(c.text, c.line, c.column, reach) for c, reach in analysis.directives or []])


def readable_answers(analysis: Analysis) -> tuple:
    """What hover, completion and navigation read: the lines, the syntax model, the places naming
    entries in their order, the definitions, the model (records with their enums and size adders,
    the references' targets, the typed view of the newer content)."""
    device = analysis.device
    return (analysis.lines, analysis.eds, positions(analysis), analysis.spans,
            {keyword: (entry, entry.line, entry.column) for keyword, entry in analysis.definitions.items()}, device,
            device.eds is analysis.eds,
            [(reference.keyword, reference.target) for reference in iter_references(device)],
            [getattr(device, name) for name in NEWER_CONTENT],
            [(reference.keyword, reference.target) for assembly in device.extended_assemblies.values()
             for reference in (assembly.size, *(member.reference for member in assembly.members))
             if isinstance(reference, Reference)])


def assert_exact(text: str, carried: Carried, message: str = "") -> bool:
    """Analyse ``text`` with what ``carried`` holds: it answers as a fresh analysis, and so does the
    analysis it handed hover and completion first; True when that one was made before the whole
    model (an entry's record made again: lsp.analysis)."""
    handed: list[Analysis] = []
    analysis = analyse(text, carried=carried, readable=handed.append)
    fresh = analyse(text)
    assert answers(analysis) == answers(fresh), message or text
    assert readable_answers(handed[0]) == readable_answers(fresh), message or text
    return handed[0] is not analysis


def edited(text: str, rng: random.Random, *, inside_a_line: bool = True) -> str:
    """``text`` with one character typed, replaced or deleted somewhere (a line break too, unless
    ``inside_a_line``)."""
    position = rng.randrange(len(text))
    typed = rng.choice(TYPED if inside_a_line else [*TYPED, "\n"])
    if inside_a_line:
        while text[position] in "\r\n":
            position = rng.randrange(len(text))
    kind = rng.choice("itd")
    if kind == "i":
        return text[:position] + typed + text[position:]
    return text[:position] + (typed if kind == "t" else "") + text[position + 1:]


def assert_incremental_is_exact(text: str, seed: int, edits: int, *, inside_a_line: bool = True) -> Carried:
    carried = Carried()
    analyse(text, carried=carried)
    rng = random.Random(seed)
    for _ in range(edits):
        text = edited(text, rng, inside_a_line=inside_a_line)
        assert_exact(text, carried, text)
    return carried


@pytest.mark.parametrize("seed", range(4))
def test_random_edits_of_the_example_answer_as_a_fresh_analysis(seed):
    assert_incremental_is_exact(EXAMPLE, seed, 40)


def test_edits_that_add_and_remove_lines_answer_as_a_fresh_analysis():
    assert_incremental_is_exact(EXAMPLE, 11, 60, inside_a_line=False)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.tuples(st.integers(0, len(EXAMPLE)), st.sampled_from(TYPED), st.sampled_from("itd")),
                min_size=1, max_size=6))
def test_any_sequence_of_edits_inside_lines_answers_as_a_fresh_analysis(edits):
    carried = Carried()
    text = EXAMPLE
    analyse(text, carried=carried)
    for position, typed, kind in edits:
        position = min(position, len(text) - 1)
        if text[position] in "\r\n":
            continue
        cut = position + (kind != "i")
        text = text[:position] + ("" if kind == "d" else typed) + text[cut:]
        assert_exact(text, carried)


def largest_real_file() -> str:
    path = max(SHARED_REAL.glob("*.eds"), key=lambda p: p.stat().st_size)
    return path.read_text(encoding="latin-1")


@needs_real_corpus
def test_random_edits_of_the_largest_real_file_answer_as_a_fresh_analysis():
    assert_incremental_is_exact(largest_real_file(), 5, 8)


@needs_real_corpus
def test_a_keystroke_inside_a_value_reads_only_its_entry_and_builds_only_its_record():
    text = largest_real_file()
    carried = Carried()
    analyse(text, carried=carried)
    offset = text.index("Param1 ")
    offset = text.index(",", offset) - 1  # the last character of Param1's first field
    changed = text[:offset] + ("7" if text[offset] != "7" else "8") + text[offset + 1:]
    hits, misses = carried.memo.hits, carried.memo.misses
    checks_hits, checks_misses = carried.checks.hits, carried.checks.misses
    analyse(changed, carried=carried)
    assert carried.read == 1 and carried.reused > 500
    # Param1's record, comments and spans are made anew (3 misses); everything else is found
    assert carried.memo.misses - misses == 3 and carried.memo.hits - hits > 1000
    # the checks look again only at the blocks of units Param1 is in (a block a check)
    assert 0 < carried.checks.misses - checks_misses <= 15 < carried.checks.hits - checks_hits


PRODUCT_CODE_LINE = "ProdCode = 1001;   $ edsconv: ignore[EDS103]\n"


@pytest.mark.parametrize("text", [
    "\n" + EXAMPLE,  # a line typed at the top: every line moves
    EXAMPLE.replace(PRODUCT_CODE_LINE, PRODUCT_CODE_LINE + "\n\n\n"),  # lines pasted in the middle
    EXAMPLE.replace(PRODUCT_CODE_LINE, ""),  # a line deleted: the entry on it is gone
])
def test_lines_typed_or_deleted_move_the_entries_after_them_and_everything_made_of_them(text):
    carried = Carried()
    analyse(EXAMPLE, carried=carried)
    entries, records = carried.read, carried.memo.misses
    checks = carried.checks.misses
    for version in (text, EXAMPLE, text):  # there and back: the entries of three texts, moved twice
        assert_exact(version, carried)
        # read again: the line typed back, and the entry after it when it begins alike ("ProdCode",
        # "ProdType"), where the changed text runs into it
        assert carried.reused + carried.read == entries - (PRODUCT_CODE_LINE not in version) and carried.read <= 2
    if PRODUCT_CODE_LINE in text:  # nothing is made again: every record, span and check finding moved
        assert (carried.memo.misses, carried.checks.misses) == (records, checks)


#: an entry with a leading comment, and a blank line between them
COMMENTED = EXAMPLE.replace("        HomeURL", "        $ where the file is\n\n        HomeURL")
DESCRIPTOR_LINE = "                0x0000,                 $ Descriptor\n"
#: an entry written twice, which the reader reports
DUPLICATED = EXAMPLE.replace(PRODUCT_CODE_LINE, PRODUCT_CODE_LINE + "        ProdCode = 1002;\n")
#: a string with an escape Table C.4 does not define, which the reader reports
ESCAPED = EXAMPLE.replace('"edsconv example I/O adapter"', '"edsconv \\q example"')
#: CR LF line ends, and one LF
MIXED = EXAMPLE.replace("\n", "\r\n").replace("\r\n\r\n[Device]", "\r\n\n[Device]")


@pytest.mark.parametrize(("name", "base", "text", "splice"), [
    ("a blank line typed at the top", EXAMPLE, "\n" + EXAMPLE, "respaced"),
    ("Enter at the end of an entry's line", EXAMPLE, EXAMPLE.replace(PRODUCT_CODE_LINE, PRODUCT_CODE_LINE + "\n"),
     "respaced"),
    ("blank lines with blanks pasted", EXAMPLE, EXAMPLE.replace("\n[Device]", "\n  \n\t\n\n[Device]"), "respaced"),
    ("a blank line deleted", EXAMPLE, EXAMPLE.replace("\n\n[Device]", "\n[Device]"), "respaced"),
    ("between two comments", EXAMPLE, EXAMPLE.replace(".\n$ It", ".\n\n$ It"), "respaced"),
    ("between a leading comment and its entry", COMMENTED, COMMENTED.replace("is\n\n", "is\n\n\n"), "respaced"),
    ("the blank line there deleted", COMMENTED, COMMENTED.replace("is\n\n", "is\n"), "respaced"),
    ("at the end of the file", EXAMPLE, EXAMPLE + "\n\n", "respaced"),
    ("before the comments after the last statement", EXAMPLE + "$ the end\n", EXAMPLE + "\n$ the end\n", "respaced"),
    ("before what the reader reports", ESCAPED, "\n" + ESCAPED, "respaced"),
    ("a CR LF file", EXAMPLE.replace("\n", "\r\n"), "\r\n" + EXAMPLE.replace("\n", "\r\n"), "respaced"),
    # the reader reads every line end, and keeps the file's first
    ("a LF typed into a CR LF file", EXAMPLE.replace("\n", "\r\n"), "\n" + EXAMPLE.replace("\n", "\r\n"), "respaced"),
    ("a CR file", EXAMPLE.replace("\n", "\r"), EXAMPLE.replace("\n", "\r").replace("\r\r", "\r\r\r", 1), "respaced"),
    # read whole (the entries are re-used)
    # inside an entry's fields: that entry is read again, the nodes after it move
    ("a blank line inside an entry", EXAMPLE, EXAMPLE.replace(DESCRIPTOR_LINE, "\n" + DESCRIPTOR_LINE), "reread"),
    ("a line broken inside an entry", EXAMPLE, EXAMPLE.replace("0,255,3,", "0,\n255,3,"), "reread"),
    ("two lines of an entry joined", EXAMPLE, EXAMPLE.replace("0,255,3,\n", "0,255,3,"), "reread"),
    ("a line broken inside an entry of a CR LF file", EXAMPLE.replace("\n", "\r\n"),
     EXAMPLE.replace("\n", "\r\n").replace("0,255,3,", "0,\r\n255,3,"), "reread"),
    ("a blank typed between a CR and its LF", EXAMPLE.replace("\n", "\r\n"),
     EXAMPLE.replace("\n", "\r\n").replace("0,255,3,\r\n", "0,255,3,\r \n"), ""),
    ("a CR LF typed inside an entry of a LF file: its first line end", EXAMPLE,
     EXAMPLE.replace("0,255,3,", "0,\r\n255,3,"), ""),
    ("a line broken inside an entry before what the reader reports", EXAMPLE.replace("EtherNet/IP Port", "EtherNet\\q"),
     EXAMPLE.replace("EtherNet/IP Port", "EtherNet\\q").replace("0,255,3,", "0,\n255,3,"), "reread"),
    ("a line broken inside an entry where the reader names a line", DUPLICATED,
     DUPLICATED.replace("0,255,3,", "0,\n255,3,"), ""),
    # the comment leads the next entry now: both read again (lsp.region)
    ("a line break before a comment on a statement's line", EXAMPLE,
     EXAMPLE.replace("ProdCode = 1001;", "ProdCode = 1001;\n"), "region"),
    ("a CR LF typed into a LF file: its first line end", EXAMPLE, "\r\n" + EXAMPLE, ""),
    ("a CR typed before a LF: one line end", MIXED, MIXED.replace("\r\n\n[Device]", "\r\n\r\n[Device]"), ""),
    ("a line with text", EXAMPLE, "$\n" + EXAMPLE, ""),
    ("a file where the reader names a line (the first ProdCode)", DUPLICATED, "\n" + DUPLICATED, ""),
    ("a file with text the reader could not parse", EXAMPLE + "what is this\n",
     "\n" + EXAMPLE + "what is this\n", ""),
])
def test_blank_lines_typed_or_deleted_between_statements_move_the_last_model(name, base, text, splice):
    carried = Carried()
    analyse(base, carried=carried)
    entries = carried.read
    assert assert_exact(text, carried, name) == (splice != "")  # hover answered at once
    assert carried.splice == splice, name
    if splice:  # the entries the line was typed into are read again
        read = {"respaced": 0, "reread": 1, "region": 2}[splice]
        assert (carried.read, carried.reused) == (read, entries - read)
    assert_exact(base, carried)  # and back again


def test_an_entry_after_a_blank_line_typed_below_its_leading_comment_is_re_used_later():
    carried = Carried()
    analyse(COMMENTED, carried=carried)
    entries = carried.read
    text = COMMENTED.replace("is\n\n", "is\n\n\n")
    analyse(text, carried=carried)
    assert carried.splice == "respaced"
    text = text.replace("[Device]", "[DEVICE]")  # read whole: the entry stands where its places say
    assert_exact(text, carried)
    assert carried.splice == "" and carried.reused == entries


def test_a_line_typed_before_a_re_read_entry_with_a_leading_comment_moves_both():
    # the re-read entry is read from a newer text than its leading comment: each text's lines move
    carried = Carried()
    analyse(COMMENTED, carried=carried)
    text = COMMENTED.replace("/eds/io_adapter", "/eds/io-adapter")
    assert_exact(text, carried)
    assert carried.splice == "reread"
    for moved in ("\n" + text, "\n\n$ x\n" + text, text.replace("        $ where", "\n        $ where"),
                  text.replace("[Device]", "\n[Device]")):
        assert_exact(moved, carried)


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.tuples(st.sampled_from(["blank line", "blank line deleted", "typed", "line break"]),
                          st.integers(0, 10 ** 6), st.sampled_from(TYPED)), min_size=1, max_size=8),
       st.sampled_from(["\n", "\r\n"]))
def test_any_sequence_of_blank_lines_and_keystrokes_answers_as_a_fresh_analysis(edits, newline):
    text = COMMENTED.replace("\n", newline)
    carried = Carried()
    analyse(text, carried=carried)
    for kind, where, typed in edits:
        lines = text.splitlines(keepends=True)
        line = where % len(lines)
        if kind == "blank line":
            lines.insert(line, newline)
        elif kind == "blank line deleted" and not lines[line].strip():
            del lines[line]
        else:
            position = where % len(lines[line].rstrip("\r\n") or " ")
            lines[line] = lines[line][:position] + (newline if kind == "line break" else typed) + lines[line][position:]
        text = "".join(lines)
        assert_exact(text, carried)


def test_a_new_line_in_an_entry_keeps_the_others_and_every_sixteenth_edit_reads_the_whole_text_again():
    carried = Carried()
    analyse(EXAMPLE, carried=carried)
    entries = carried.read
    line_break = EXAMPLE.replace("ProdCode = 1001;", "ProdCode =\n 1001;")
    assert_exact(line_break, carried)
    assert carried.read == 1 and carried.reused == entries - 1
    text = EXAMPLE
    assert_exact(text, carried)  # a line fewer
    assert carried.read == 1
    carried = Carried()
    analyse(text, carried=carried)
    for step in range(FULL_READ_EVERY + 1):
        text = text.replace("MajRev = 1;", "MajRev = 1; ") if step % 2 else text.replace("MajRev = 1; ", "MajRev = 1;")
        analyse(text, carried=carried)
        assert (carried.reused == 0) == (step == FULL_READ_EVERY), step


@pytest.mark.parametrize(("old", "new", "expected"), [
    ("a\nbc\nd\n", "a\nbXc\nd\n", (2, 6, 1, 0)),  # the whole second line, past its break
    ("a\nbc\nd", "a\nbc\nd!", (5, 7, 1, 0)),  # the last line, to the end
    ("ab\ncd\n", "ab\ncd\n", (6, 6, 0, 0)),  # nothing changed
    ("a\r\nbc\r\n", "a\r\nc\r\n", (3, 6, -1, 0)),  # CR LF lines
    ("a\nb\n", "a\n\nb\n", (2, 3, 1, 1)),  # a line added
    ("a\n\n\nb\n", "a\nb\n", (2, 2, -2, -2)),  # two removed: the next line is not touched
    ("a\nb\n", "a\nXb\n", (2, 5, 1, 0)),  # typed at a line start: that line is touched
    ("a\rb\n", "a\r\nb\n", (2, 3, 1, 0)),  # a CR became a CR LF: still one line break
    ("a\nb\n", "a\r\nb\n", (0, 3, 1, 0)),  # a LF became a CR LF
    ("a\r\nb\n", "a\r\r\nb\n", (2, 4, 1, 1)),  # a CR typed before a CR LF: a line more
])
def test_changed_lines(old, new, expected):
    assert changed_lines(old, new) == expected


def test_changed_lines_past_the_first_compared_chunk():
    line = "Param1 = 0,,,0x0000,0xC7,2,\"x\",\"\",\"\",0,100,0;\n"
    old = line * 5000  # 240 KB: several chunks
    at = len(line) * 3000 + 5
    new = old[:at] + "9" + old[at + 1:]
    assert changed_lines(old, new) == (len(line) * 3000, len(line) * 3001, 0, 0)


#: (what to find in EXAMPLE, what to put instead, whether only that entry is read again)
EDITS = [
    ('"microseconds",', '"milliseconds",', True),  # inside a string
    ("$ Data Type: UDINT", "$ Data Type: UINT", True),  # a comment between the fields
    ("ProdCode = 1001;   $ edsconv: ignore[EDS103]", "ProdCode = 1002;   $ edsconv: ignore[EDS103]", True),
    ("ProdCode = 1001;   $ edsconv: ignore[EDS103]", "ProdCode = 1001;   $ edsconv: ignore[EDS104]", False),
    ("ProdCode = 1001;", "ProdCodes = 1001;", False),  # the keyword
    ("ProdCode = 1001;", "ProdCode = 10;01;", False),  # a ';' ends the entry earlier
    ('"microseconds",', '"micro"seconds",', False),  # a string left open reads on
    ('"microseconds",', '"micros\u00e9conds",', False),  # not ASCII: the whole text decodes otherwise
    ('"microseconds",', '"micro\\qseconds",', False),  # a string with a problem the reader reports
    ("MajRev = 1;", "MajRev = 1; MinRev = 1;", False),  # another statement on the entry's last line
    ("MajRev = 1;", "MajRev = {1};", False),  # braces: read by Lark
    ("$ It uses every basic", "$ It uses each basic", False),  # a comment outside the entries
]


@pytest.mark.parametrize(("find", "replace", "reread"), EDITS)
def test_an_edit_inside_one_entry_reads_only_that_entry_and_answers_as_a_fresh_analysis(find, replace, reread):
    carried = Carried()
    analyse(EXAMPLE, carried=carried)
    assert find in EXAMPLE
    text = EXAMPLE.replace(find, replace, 1)
    assert_exact(text, carried)
    assert (carried.splice == "reread") == reread
    assert carried.read == 1 or not reread
    back = analyse(EXAMPLE, carried=carried)  # and back again
    assert answers(back) == answers(analyse(EXAMPLE))


def test_a_keystroke_in_a_dense_section_reads_only_its_entry():
    line = "$ parameter {0}\nParam{0} = 0,,,0x0000,0xC7,2,\"P{0}\",\"\",\"\",0,100,{0};   $ the {0}th\n"
    text = "[File]\nDescText = \"x\";\n[Params]\n" + "".join(line.format(n) for n in range(1, 801))
    carried = Carried()
    analyse(text, carried=carried)
    for typed in "12345":  # a value one character longer each time: the entries after it move
        text = text.replace('"P400"', f'"P400{typed}"') if typed == "1" else text.replace(
            f'"P400{int(typed) - 1}"', f'"P400{typed}"')
        assert assert_exact(text, carried)  # and hover answered before the whole model was made
        assert carried.splice == "reread" and carried.read == 1
    # an edit of a leading comment reads its entry again (lsp.region); every other one is the one read before
    text = text.replace("$ parameter 600\n", "$ parameter 600!\n")
    assert_exact(text, carried)
    assert carried.splice == "region" and (carried.read, carried.reused) == (1, 800)


def test_hover_answers_at_once_when_a_parameter_s_data_type_changes_with_its_enum_read_anew():
    # the data type types the parameter's EnumN keys: USINT has no 300, UINT has
    base = EXAMPLE.replace('Enum3 = 0,"Clear",', 'Enum3 = 300,"Far", 0,"Clear",')
    carried = Carried()
    analyse(base, carried=carried)
    typed = base.replace("values\n                0xC6,", "values\n                0xC7,")
    assert assert_exact(typed, carried)
    assert carried.splice == "reread" and 300 in carried.last.device.parameters["Param3"].enum
    assert assert_exact(typed.replace('"Input Filter"', '"Input filter"'), carried)  # Param2's name


def test_hover_answers_at_once_for_an_entry_that_shares_its_first_line():
    # Enum3's span (it pairs with Param3) stands before Param4's on their line
    base = EXAMPLE.replace('"Use fault value";\n        Param4 =', '"Use fault value"; Param4 =')
    carried = Carried()
    analyse(base, carried=carried)
    assert assert_exact(base.replace('"Temperature Limit"', '"Temperature limit"'), carried)


def test_hover_answers_at_once_for_a_parameter_an_extended_assembly_names():
    # AssemExa101 (the typed view of the newer content) has Param2 for its size and Param4 for members
    base = (REPO / "corpus" / "cip" / "assembly_exa_clean.eds").read_text(encoding="ascii")
    carried = Carried()
    analyse(base, carried=carried)
    for find, typed in (('"Port data"', '"Port Data"'), ('"Input size"', '"Input Size"')):
        base = base.replace(find, typed)
        assert assert_exact(base, carried)


def test_hover_waits_for_the_whole_model_after_an_analysis_that_stopped_half_way():
    carried = Carried()
    analyse(EXAMPLE, carried=carried)
    steps = iter([False, True])  # stopped just after reading (a newer text came)
    first = EXAMPLE.replace('"Input Filter"', '"Input filter"')
    with pytest.raises(Superseded):
        analyse(first, carried=carried, superseded=lambda: next(steps))
    second = first.replace('"Temperature Limit"', '"Temperature limit"')
    assert not assert_exact(second, carried)  # the last whole analysis is of a text before the first
    assert carried.splice == "reread"


def test_a_size_adder_deleted_leaves_its_proxy_parameter_without_one():
    param1 = EXAMPLE[EXAMPLE.index("        Param1 ="):EXAMPLE.index("        Param2 =")]
    proxy = param1.replace("Param1 =", "ProxyParam1 =") + "        ProxyParamSizeAdder1 = 1,2,3;\n"
    base = EXAMPLE.replace("        Param2 =", proxy + "        Param2 =")
    carried = Carried()
    analyse(base, carried=carried)
    assert carried.last is not None and carried.last.device.parameters["ProxyParam1"].size_adder is not None
    assert assert_exact(base.replace("        ProxyParamSizeAdder1 = 1,2,3;\n", ""), carried)  # hover at once
    assert carried.last.device.parameters["ProxyParam1"].size_adder is None


@settings(max_examples=300, deadline=None)
@given(st.text("ab\n", max_size=40), st.text("ab", max_size=4), st.integers(0, 40), st.integers(0, 40),
       st.sampled_from([2, 3, 1 << 16]))
def test_changed_span_is_the_shortest_span_outside_the_common_prefix_and_suffix(base, typed, cut, resume, chunk):
    from edsconv.lsp import incremental

    old, new = base, base[:cut] + typed + base[max(cut, resume):]
    prefix = next((i for i, (x, y) in enumerate(zip(old, new, strict=False)) if x != y), min(len(old), len(new)))
    suffix = 0
    while suffix < min(len(old), len(new)) - prefix and old[-1 - suffix] == new[-1 - suffix]:
        suffix += 1
    original = incremental._CHUNK
    incremental._CHUNK = chunk  # small chunks: the chunked comparison and the halving both run
    try:
        assert incremental.changed_span(old, new) == (prefix, len(old) - suffix, len(new) - suffix)
    finally:
        incremental._CHUNK = original


def test_a_suppression_typed_into_an_entry_of_a_file_that_never_named_edsconv_is_found():
    text = re.sub("edsconv", "this tool", EXAMPLE.replace("   $ edsconv: ignore[EDS103]", ""), flags=re.IGNORECASE)
    assert "edsconv" not in text.lower()
    carried = Carried()
    analyse(text, carried=carried)
    typed = text.replace("$ Data Type: UDINT", "$ edsconv: ignore[EDS321]", 1)
    incremental = analyse(typed, carried=carried)
    assert carried.splice == "reread"
    assert answers(incremental) == answers(analyse(typed))
    assert [c.text for c, _ in incremental.directives or []] == [" edsconv: ignore[EDS321]"]


@pytest.mark.parametrize(("name", "variant"), [
    ("CR LF line ends", EXAMPLE.replace("\n", "\r\n")),
    ("CR line ends", EXAMPLE.replace("\n", "\r")),
    ("a byte order mark", "\ufeff" + EXAMPLE),
])
def test_edits_of_a_text_the_reader_normalises_answer_as_a_fresh_analysis(name, variant):
    # the reader counts offsets in the text without its byte order mark and with "\n" line ends:
    # a comment on an entry's last line, 40 lines down, is where the two counts part most visibly
    carried = Carried()
    analyse(variant, carried=carried)
    text = variant.replace("$ decimal places", "$ decimal placez", 1)
    assert_exact(text, carried)
    # inside an entry: that entry alone is read again, unless a byte order mark makes the text not ASCII
    text = text.replace("$ Data Type: UDINT", "$ Data Type: UINT", 1)
    assert_exact(text, carried)
    assert (carried.splice == "reread") == (not variant.startswith("\ufeff"))
    assert_incremental_is_exact(variant, 3, 25)
    assert_incremental_is_exact(variant, 4, 25, inside_a_line=False)


def test_a_byte_order_mark_typed_at_the_start_is_read_whole():
    carried = Carried()
    analyse(EXAMPLE, carried=carried)
    assert_exact("\ufeff" + EXAMPLE, carried)
    assert carried.splice == ""


@needs_real_corpus
@pytest.mark.parametrize("index", range(len(REAL_EDS)))
def test_edits_of_every_real_file_answer_as_a_fresh_analysis(index):
    # line ends, encodings and layouts as the vendors wrote them (CR LF files found the reader's
    # offsets counted apart from the editor's); `python tests/test_lsp_incremental.py SEED EDITS`
    # runs more of these edits on every file
    text = REAL_EDS[index].read_bytes().decode("latin-1")
    carried = assert_incremental_is_exact(text, index, 2)
    assert_incremental_is_exact(text, index, 1, inside_a_line=False)
    assert carried.steps == 2


if __name__ == "__main__":  # the long run the test above samples: seed, then edits per file
    import sys

    seed, edits = (int(argument) for argument in sys.argv[1:3])
    for number, path in enumerate(REAL_EDS):
        text = path.read_bytes().decode("latin-1")
        assert_incremental_is_exact(text, seed * 1000 + number, edits)
        assert_incremental_is_exact(text, seed * 1000 + number, max(edits // 4, 1), inside_a_line=False)
        print(f"{path.name}: {edits + max(edits // 4, 1)} edits answer as fresh analyses")
