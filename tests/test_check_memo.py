"""The checks' memo (edsconv.checks.CheckMemo): with it the checks say exactly what they say without it,
the first time, again over the same objects (without checking any unit again), and after one entry of
the file changed (checking again only the units of that entry)."""

from __future__ import annotations

from pathlib import Path

import pytest

import edsconv
from conftest import REPO, SHARED_REAL
from edsconv.checks import CheckMemo, Context, load_checks
from edsconv.eds.syntax import EdsFile
from edsconv.model import Device
from edsconv.model.build import build, iter_references

CORPUS = sorted((REPO / "corpus").rglob("*.eds"))
#: The largest real files, and those with the most findings of the converted checks.
REAL = ("ME-Catalyst__iodd-manager__54611_MVK_Pro_ME_DIO8_IOL8_5P__V1.8-03_Manufacturer_2.eds",  # the largest
        "ME-Catalyst__iodd-manager__55544_MVK_ME_DIO12_DIO4_IOL4_4P_AllenBradley_V1_15.eds",  # 56 findings
        "SerafinTech__node-st-eds-parse__00010003012C0100.eds",  # 34
        "ME-Catalyst__iodd-manager__54631_IMPACT67_Pro_E_DIO8_IOL8_5P_AB.eds")  # 30


def read(path: Path) -> tuple[EdsFile, Device]:
    eds = edsconv.parse(path.read_bytes(), str(path))
    return eds, build(eds)


def checked(eds: EdsFile, device: Device, memo: CheckMemo | None = None) -> list:
    """Every check's diagnostics, as one analysis of the language server with ``memo``."""
    if memo is not None:
        memo.start()
    context = Context(eds, device, memo)
    found = [diagnostic for check in load_checks() for diagnostic in check.run(context)]
    if memo is not None:
        memo.finish()
    return found


def rebuilt_reusing(eds: EdsFile, device: Device, text: str) -> tuple[EdsFile, Device]:
    """``text`` read and built as the language server's incremental analysis does: every entry equal to
    the one at its place in ``eds`` (same section, same position) is that very object, and every record
    of ``device`` built from such an entry is the record, its cross-entry attributes made anew."""
    new_eds = edsconv.parse(text, eds.path)
    for old_section, section in zip(eds.sections, new_eds.sections, strict=True):
        section.entries = [old if old == new and (old.line, old.column) == (new.line, new.column) else new
                           for old, new in zip(old_section.entries, section.entries, strict=True)]
    new_device = build(new_eds)
    for attribute in ("parameters", "assemblies", "connections"):
        old_records, records = getattr(device, attribute), getattr(new_device, attribute)
        for keyword, record in records.items():
            old = old_records.get(keyword)
            if old is not None and old.entry is record.entry:
                if attribute == "parameters":  # made from other entries: set on the reused record anew
                    old.enum, old.size_adder = record.enum, record.size_adder
                records[keyword] = old
    for reference in iter_references(new_device):
        reference.target = new_device.resolve(reference.keyword)
    return new_eds, new_device


def real_files() -> list[Path]:
    if not SHARED_REAL.is_dir():
        return []
    return [SHARED_REAL / name for name in REAL if (SHARED_REAL / name).is_file()]


@pytest.mark.parametrize("path", [*CORPUS, *real_files()], ids=lambda path: path.name)
def test_the_memo_changes_nothing_the_first_time_nor_again_over_the_same_objects(path):
    eds, device = read(path)
    expected = checked(eds, device)
    memo = CheckMemo()
    assert checked(eds, device, memo) == expected
    assert memo.hits == 0 and (memo.misses > 0) == any(section.entries for section in eds.sections)
    checked_blocks = memo.misses
    assert checked(eds, device, memo) == expected
    assert (memo.hits, memo.misses) == (checked_blocks, checked_blocks)  # not one unit checked again


def test_real_files_are_there_when_the_shared_corpus_is():
    if SHARED_REAL.is_dir():
        assert len(real_files()) == len(REAL)
    else:
        pytest.skip("../shared is absent")


#: Three parameters, the first with an enumeration; every converted check has units of them.
PARAMS = ("[File]\nDescText = \"t\";\nCreateDate = 01-02-2024;\nCreateTime = 10:00:00;\nRevision = 1.1;\n"
          "[Device]\nVendCode = 65535;\nVendName = \"T\";\nProdType = 12;\nProdTypeStr = \"A\";\nProdCode = 1;\n"
          "MajRev = 1;\nMinRev = 1;\nProdName = \"T\";\n[Device Classification]\nClass1 = EtherNetIP;\n"
          "[Params]\n"
          "Param1 = 0,,,0x0002,0xC6,1,\"A\",\"\",\"\",0,3,1;\n"
          "Enum1 = 0,\"Off\",1,\"On\";\n"
          "Param2 = 0,,,0x0000,0xC6,1,\"B\",\"\",\"\",0,10,1;\n"
          "Param3 = 0,,,0x0000,0xC6,1,\"C\",\"\",\"\",0,10,1;\n")
#: The per-record unit functions that a ParamN (without enumeration) is a unit of: field_counts,
#: field_keywords, string_characters, enum_pairs, entry_keywords, descriptors, parameter_value_order,
#: parameter_min_max_presence, parameter_scaling, parameter_data_sizes, instance_numbers.
PARAMETER_UNIT_FUNCTIONS = 11


@pytest.mark.parametrize(("old", "new", "missed"), [
    ("0,10,1;\nParam3", "0,11,1;\nParam3", PARAMETER_UNIT_FUNCTIONS),  # Param2's maximum
    ("0,3,1;", "0,9,1;", PARAMETER_UNIT_FUNCTIONS + 1),  # Param1's maximum: enum_ranges reads it too
    ("1,\"On\";", "7,\"On\";", 6),  # Enum1: its entry's five checks and enum_ranges
    ("1,\"On\";", "1,\"On\"   ;", 0),  # the same fields (the entry is reused: its place did not change)
])
def test_after_one_entry_changed_only_its_units_are_checked_again(old, new, missed):
    eds = edsconv.parse(PARAMS, "p.eds")
    device = build(eds)
    memo = CheckMemo()
    checked(eds, device, memo)
    edited, edited_device = rebuilt_reusing(eds, device, PARAMS.replace(old, new))
    before = memo.misses
    assert checked(edited, edited_device, memo) == checked(edited, edited_device)
    assert memo.misses - before == missed


def test_a_changed_range_reports_an_enumeration_out_of_it_through_the_memo():
    eds = edsconv.parse(PARAMS, "p.eds")
    device = build(eds)
    memo = CheckMemo()
    assert "EDS351" not in [d.code for d in checked(eds, device, memo)]
    edited, edited_device = rebuilt_reusing(eds, device, PARAMS.replace("0,3,1;", "0,0,0;"))
    assert "EDS351" in [d.code for d in checked(edited, edited_device, memo)]


#: The checks whose per-entry or per-record part goes through the memo.
MEMOIZED = ("field_counts", "field_keywords", "string_characters", "entry_keywords", "enum_pairs", "descriptors",
            "parameter_value_order", "parameter_min_max_presence", "parameter_scaling", "parameter_data_sizes",
            "instance_numbers", "enum_ranges")


def rule_fixtures() -> list[str]:
    """The texts of the structure and entity rule tests, each rule's bad and good variant."""
    from test_checks_entities import CASES as ENTITY_CASES
    from test_checks_structure import CASES as STRUCTURE_CASES

    return [*(text for bad, good in ENTITY_CASES.values() for text in (bad, good)),
            *(text for _, bad, _, good in STRUCTURE_CASES for text in (bad, good)),
            PARAMS.replace('"B"', '"B\\x00"').replace('"C"', '"C\x01D"')]  # EDS117, EDS116


@pytest.fixture(scope="module")
def fixture_runs() -> list[tuple[list, list]]:
    """(without memo, with the memo of an earlier analysis) for each rule fixture, the second analysis
    made of the first one's entries and records (as an edit elsewhere leaves them)."""
    runs = []
    for text in rule_fixtures():
        eds = edsconv.parse(text, "fixture.eds")
        device = build(eds)
        memo = CheckMemo()
        checked(eds, device, memo)
        again = rebuilt_reusing(eds, device, text)
        runs.append((checked(*again), checked(*again, memo)))
    return runs


def test_the_rule_fixtures_report_through_a_warm_memo_what_they_report_without(fixture_runs):
    assert [memoized for _, memoized in fixture_runs] == [plain for plain, _ in fixture_runs]


@pytest.mark.parametrize("name", MEMOIZED)
def test_each_memoized_check_still_reports_its_rules_through_the_memo(name, fixture_runs):
    (check,) = [check for check in load_checks() if check.name == name]
    reported = {diagnostic.code for _, memoized in fixture_runs for diagnostic in memoized}
    assert {rule.code for rule in check.rules} & reported


def test_a_forward_reference_within_a_section_is_told_by_lines_when_entries_come_from_two_texts():
    """After an incremental re-read, an entry of the older text (offsets of that text) stands beside one of
    the newer: Assem2 below Assem1 is still after it, whatever their offsets."""
    body = PARAMS + '[Assembly]\nAssem1 = "Outer", "", 2, , , , , Assem2;\nAssem2 = "Inner", "", 2, , , , 16, ;\n'
    eds = edsconv.parse("$ " + "long comment " * 400 + "\n" + body, "a.eds")
    older = edsconv.parse("$ short\n" + body, "a.eds")
    eds.sections[-1].entries[1] = older.sections[-1].entries[1]  # Assem2, at a smaller offset, the same line
    assert eds.sections[-1].entries[1].offset < eds.sections[-1].entries[0].offset
    (check,) = [check for check in load_checks() if check.name == "forward_references"]
    assert [d.code for d in check.run(Context(eds, build(eds)))] == ["EDS227"]


def test_an_abandoned_analysis_leaves_the_next_one_everything():
    eds = edsconv.parse(PARAMS, "p.eds")
    device = build(eds)
    memo = CheckMemo()
    checked(eds, device, memo)
    memo.start()
    list(load_checks()[0].run(Context(eds, device, memo)))  # a newer text arrives after the first check
    before = memo.misses
    assert checked(eds, device, memo) == checked(eds, device)
    assert memo.misses == before


def test_a_memo_bound_to_another_path_starts_afresh():
    """Diagnostics carry the path: the same objects under another path (a renamed document) are checked again."""
    eds = edsconv.parse(PARAMS.replace('"B"', '"B\\x00"'), "p.eds")
    device = build(eds)
    memo = CheckMemo()
    assert {d.path for d in checked(eds, device, memo)} == {"p.eds"}
    eds.path = "renamed.eds"
    assert {d.path for d in checked(eds, device, memo)} == {"renamed.eds"}


def test_what_a_finished_analysis_did_not_use_is_dropped():
    eds = edsconv.parse(PARAMS, "p.eds")
    device = build(eds)
    memo = CheckMemo()
    checked(eds, device, memo)
    first = memo.misses
    other = edsconv.parse(PARAMS, "p.eds")  # the same text read again: other objects
    checked(other, build(other), memo)
    before = memo.misses
    checked(eds, device, memo)
    assert memo.misses - before == first
