"""The example figures of ISO 15745-4 C.4 (corpus/spec) read as the spec means them.

corpus/spec holds every figure that is EDS text (C.1-C.4, C.7-C.16; C.5 is a
formula and the text of C.6 is missing from our copy of the spec), the STRINGI
example of C.4.1.3.5 and the string examples of C.4.1.3.3. corpus/broken holds
the figures the PDF extraction damaged, as they stand in the spec text, to check
what the reader reports on them. See corpus/README.md.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import edsconv
from edsconv.diagnostics import Severity
from edsconv.eds.syntax import Comment, EdsFile, Entry, Field, Group, Scalar, String
from edsconv.eds.writer import write
from edsconv.model.values import StringIMember, to_stringi

ROOT = Path(__file__).resolve().parents[1]
SPEC = ROOT / "corpus" / "spec"
BROKEN = ROOT / "corpus" / "broken"

FIGURES = ["C01", "C02", "C03", "C04", "C07", "C08", "C09", "C10", "C11", "C12", "C13", "C14", "C15", "C16"]
SPEC_FILES = [f"figure_{n}.eds" for n in FIGURES] + ["stringi_C4135.eds", "strings_C4133.eds"]
#: Warnings a clean spec file may carry, as (code, line); none may carry an error.
EXPECTED_WARNINGS = {"stringi_C4135.eds": [("EDS005", 6)]}


def spec(name: str) -> EdsFile:
    return edsconv.load(SPEC / name)


def figure(number: str) -> EdsFile:
    return spec(f"figure_{number}.eds")


def broken(number: str) -> EdsFile:
    return edsconv.load(BROKEN / f"figure_{number}_as_printed.eds")


def diagnostics(eds: EdsFile) -> list[tuple[str, int]]:
    return [(d.code, d.line) for d in eds.diagnostics]


def entry(eds: EdsFile, section: str, keyword: str) -> Entry:
    found = eds.section(section).entry(keyword)
    assert found is not None, f"[{section}] has no {keyword}"
    return found


def shape(fields: list[Field]) -> list:
    """Fields as plain data: None for an empty field, the spelling of a value, a list for a group."""
    return [f.value and (shape(f.value.fields) if isinstance(f.value, Group) else f.value.raw) for f in fields]


def all_comments(eds: EdsFile) -> list[Comment]:
    """Every comment the model holds, wherever it is attached, in file order."""
    found = list(eds.trailing_comments)
    for section in eds.sections:
        found += section.leading_comments + section.comments
        for item in section.entries:
            found += item.leading_comments + item.comments
            for field in item.walk_fields():
                found += field.comments
    return sorted(found, key=lambda comment: comment.offset)


def field_comments(item: Entry) -> list[list[str]]:
    return [[c.text for c in field.comments] for field in item.fields]


# --- every file -------------------------------------------------------------------


@pytest.mark.parametrize("name", SPEC_FILES)
def test_clean_spec_file_has_no_errors(name):
    eds = spec(name)
    assert not [d for d in eds.diagnostics if d.severity is Severity.ERROR], [d.format() for d in eds.diagnostics]
    assert diagnostics(eds) == EXPECTED_WARNINGS.get(name, [])
    assert not any(section.unparsed for section in eds.sections)


@pytest.mark.parametrize("path", [SPEC / name for name in SPEC_FILES] + sorted(BROKEN.glob("figure_*.eds")),
                         ids=lambda path: f"{path.parent.name}/{path.name}")
def test_written_model_reads_back_equal(path):
    eds = edsconv.load(path)
    again = edsconv.parse(write(eds))
    assert again == eds
    assert [d.code for d in again.diagnostics] == [d.code for d in eds.diagnostics]


@pytest.mark.parametrize("name", SPEC_FILES)
def test_every_comment_is_kept_once_in_order(name):
    # No string in these files holds a '$', so every '$' starts a comment.
    text = (SPEC / name).read_text(encoding="utf-8")
    assert [c.text for c in all_comments(spec(name))] == re.findall(r"\$(.*)", text)


# --- field values, figure by figure -----------------------------------------------

PARAM_C08_1 = ["0", "6", '"20 0F 24 01 30 01"', "0x0000", "2", "2", '"Idle state"', '""', '"User Manual p48"',
               "0", "2", "1"] + ["0"] * 9
# Param2 leaves out the optional decimal precision: 20 fields.
PARAM_C08_2 = ["0", "6", '"20 0F 24 02 30 01"', "0x0000", "2", "2", '"Fault state"', '""', '"User Manual p49"',
               "0", "2", "2"] + ["0"] * 8
RACK_1 = ["65535", "101", "1", "1", "1", None, None, None]

ENTRY_VALUES = [
    ("C01", "section name", "Entry1", ["Field1", "Field2", "Field3"]),
    ("C01", "section name", "Entry2", ["Field1", "Field2", "Field3", "Field4"]),
    ("C01", "section name", "Entry3", ["Field1", "Field2", "Field3"]),
    ("C01", "section name", "Entry4", ["Field1", "Field2", "Field3", "Field4"]),
    ("C01", "section name", "Entry5", ["1", ["1", "2", "3"]]),
    ("C01", "section name", "Entry6", [["44", ["22", "33", "11"]]]),
    ("C01", "section name", "65535_Entry", ["Field1", "Field2"]),
    ("C02", "File", "DescText", ['"Smart Widget EDS File"']),
    ("C02", "File", "CreateDate", ["04-03-94"]),
    ("C02", "File", "CreateTime", ["17:51:44"]),
    ("C02", "File", "ModDate", ["04-06-94"]),
    ("C02", "File", "ModTime", ["22:07:30"]),
    ("C02", "File", "Revision", ["2.1"]),
    ("C02", "File", "HomeURL", ['"http://www.odva.org/EDS/example.eds"']),
    ("C03", "Device", "VendCode", ["65535"]),
    ("C03", "Device", "VendName", ['"Widget-Works, Inc."']),
    ("C03", "Device", "ProdType", ["0"]),
    ("C03", "Device", "ProdTypeStr", ['"Generic"']),
    ("C03", "Device", "ProdCode", ["42"]),
    ("C03", "Device", "MajRev", ["1"]),
    ("C03", "Device", "MinRev", ["1"]),
    ("C03", "Device", "ProdName", ['"Smart-Widget"']),
    ("C03", "Device", "Catalog", ['"1499-DVG"']),
    ("C03", "Device", "Icon", ['"example.ico"']),
    ("C04", "ParamClass", "MaxInst", ["3"]),
    ("C04", "ParamClass", "Descriptor", ["0x0E"]),
    ("C04", "ParamClass", "CfgAssembly", ["3"]),
    ("C07", "Groups", "Group1", ['"Setup"', "2", "1", "2"]),
    ("C07", "Groups", "Group2", ['"Monitor"', "2", "2", "3"]),
    ("C07", "Groups", "Group3", ['"Maintenance"', "2", "1", "3"]),
    ("C08", "Params", "Param1", PARAM_C08_1),
    ("C08", "Params", "Param2", PARAM_C08_2),
    ("C08", "Assembly", "Revision", ["2"]),
    ("C08", "Assembly", "Assem5", ['"configuration"', '"20 04 24 05 30 03"', "1", None, None,
                                   "4", "Param1", "3", "Param2", "1", None]),
    ("C09", "Params", "Param1", ["0", None, None, "0x0004", "8", "1", '"Read"', '""', '""',
                                 "64", "95", "64", "1", "1", "1", "-63"] + ["0"] * 5),
    ("C09", "Params", "Param2", ["0", None, None, "0x0004", "8", "1", '"Write"', '""', '""',
                                 "160", "191", "160", "1", "1", "1", "-159"] + ["0"] * 5),
    ("C09", "Connection Manager", "Connection1", ["0x04010002", "0x44244401", None, "16", None, None, "12", None,
                                                  None, None, None, None, '"read/write"', '""',
                                                  '"20 04 24 01 2C [Param2] 2C [Param1]"']),
    ("C10", "Port", "Port1", ["DeviceNet", '"Port A"', '"20 03 24 01"', "2"]),
    ("C10", "Port", "Port2", ["65535_Chassis", '"Chassis"', '"20 9A 24 01"', "1"]),
    ("C11", "File", "DescText", ['"Wonder Chassis EDS file"']),
    ("C11", "File", "CreateDate", ["09-01-1997"]),
    ("C11", "File", "CreateTime", ["17:23:00"]),
    ("C11", "File", "Revision", ["1.1"]),
    ("C11", "Device", "VendName", ['"Widget Works, Inc."']),
    ("C11", "Device", "ProdType", ["101"]),
    ("C11", "Device", "Catalog", ['"1234-chassis"']),
    ("C11", "Params", "Param1", ["0", None, None, "0x0004", "8", "1", '"Slot Naming Convention"', '""', '""',
                                 "0", "4", "0"] + ["0"] * 9),
    ("C11", "Params", "Enum1", ["0", '"n/a"', "1", '"0"', "2", '"1"', "3", '"2"', "4", '"3"']),
    ("C11", "Modular", "DefineSlotsInRack", ["5"]),
    ("C11", "Modular", "SlotDisplayRule", ["Param1"]),
    ("C12", "Modular", "Width", ["1"]),
    ("C12", "Modular", "Rack1", RACK_1 + ["1", "2", "3", "4"]),
    ("C13", "Modular", "Rack1", RACK_1 + ["1", "2", "3", "4"]),
    ("C13", "Modular", "Rack2", ["65535", "101", "2", "1", "1", None, None, None, "1", "2", "3", "4", "5", "6", "7"]),
    ("C13", "Modular", "ExternalID", ['"12 34"']),
    ("C14", "Modular", "Rack1", RACK_1 + ["0"]),
    ("C14", "Modular", "Rack2", ["65535", "101", "2", "1", "1", None, None, None, "0"]),
    ("C14", "Modular", "Query", ['"20 04 24 07 30 03"', "1", "2", '"FF FF"']),
    ("C14", "Modular", "GenericID", ['"00 00"']),
    ("C14", "Modular", "ExternalIDExactMatch", ["No"]),
    ("C15", "Params", "Param1", ["0", None, None, "0x0010", "2", "2", '" Target Error Codes"', '""', '""',
                                 "0", "0xFFFF"] + ["0"] * 12),
    ("C15", "Params", "ProxyParam1", ["0", None, None, "0x0000", "2", "2", '"input size"', '""', '""',
                                      "Module", "Module", "Module", "0", "0", "0", "0", None, None, "0"]),
    ("C15", "Params", "ProxyParamSizeAdder1", ["4", "4", "4"]),
    ("C15", "Assembly", "Assem1", ['"connection input format"', None, None, None, "32", "Param1",
                                   None, "ProxyAssem1", None, "ProxyAssem2"]),
    ("C15", "Assembly", "ProxyAssem1", ['"real time input format"', '"20 7D 24 SLOT 30 0A"', None, None, None,
                                        "ModuleMemberList"]),
    ("C15", "Assembly", "ProxyAssem2", ['"real time status format"', '"20 7D 24 SLOT 30 0B"', None, None, None,
                                        "ModuleMemberList"]),
    ("C15", "Connection Manager", "ProxyConnect1", ["0x010100002", "0x44244401", "2", "0", None, "2", "ProxyParam1",
                                                    "Assem1", None, None, None, '"Listen Only"', '""', None,
                                                    '"01 SLOT_MINUS_ONE 20 04 24 03 2C 04 2C 02"']),
    ("C16", "Params", "ProxiedParam1", [None, None, '"input size"', '""', '""', '""', "0", "2", "2", None, None,
                                        '""']),
    ("C16", "Assembly", "ProxiedAssem1", ['"real time input format"', None, None, None]),
    ("C16", "Assembly", "ProxiedAssem2", ['"real time status format"', None, None, "16", None]),
    ("C16", "Connection Manager", "ProxiedConnect1", [None, None, None, "0", None, None, '""']),
]


@pytest.mark.parametrize(("number", "section", "keyword", "expected"), ENTRY_VALUES,
                         ids=[f"{n}-{k}" for n, _, k, _ in ENTRY_VALUES])
def test_entry_values(number, section, keyword, expected):
    assert shape(entry(figure(number), section, keyword).fields) == expected


SECTIONS = {
    "C01": {"section name": ["Entry1", "Entry2", "Entry3", "Entry4", "Entry5", "Entry6", "65535_Entry"]},
    "C02": {"File": ["DescText", "CreateDate", "CreateTime", "ModDate", "ModTime", "Revision", "HomeURL"]},
    "C03": {"Device": ["VendCode", "VendName", "ProdType", "ProdTypeStr", "ProdCode", "MajRev", "MinRev",
                       "ProdName", "Catalog", "Icon"]},
    "C04": {"ParamClass": ["MaxInst", "Descriptor", "CfgAssembly"]},
    "C07": {"Groups": ["Group1", "Group2", "Group3"]},
    "C08": {"Params": ["Param1", "Param2"], "Assembly": ["Revision", "Assem5"]},
    "C09": {"Params": ["Param1", "Param2"], "Connection Manager": ["Connection1"]},
    "C10": {"Port": ["Port1", "Port2"]},
    "C11": {"File": ["DescText", "CreateDate", "CreateTime", "Revision"],
            "Device": ["VendCode", "VendName", "ProdType", "ProdTypeStr", "ProdCode", "MajRev", "MinRev",
                       "ProdName", "Catalog"],
            "Params": ["Param1", "Enum1"], "Modular": ["DefineSlotsInRack", "SlotDisplayRule"]},
    "C12": {"Modular": ["Width", "Rack1"]},
    "C13": {"Modular": ["Width", "Rack1", "Rack2", "ExternalID"]},
    "C14": {"Modular": ["Width", "Rack1", "Rack2", "Query", "GenericID", "ExternalIDExactMatch"]},
    "C15": {"Params": ["Param1", "ProxyParam1", "ProxyParamSizeAdder1"],
            "Assembly": ["Assem1", "ProxyAssem1", "ProxyAssem2"], "Connection Manager": ["ProxyConnect1"]},
    "C16": {"Params": ["ProxiedParam1"], "Assembly": ["ProxiedAssem1", "ProxiedAssem2"],
            "Connection Manager": ["ProxiedConnect1"]},
}


@pytest.mark.parametrize("number", FIGURES)
def test_sections_and_keywords_in_file_order(number):
    eds = figure(number)
    assert {s.name: [e.keyword for e in s.entries] for s in eds.sections} == SECTIONS[number]
    assert [s.name for s in eds.sections] == list(SECTIONS[number])
    assert eds.preamble is None


VALUE_KINDS = [
    ("C01", "section name", "Entry1", ["WORD", "WORD", "WORD"]),
    ("C01", "section name", "Entry5", ["INTEGER", "GROUP"]),
    ("C01", "section name", "Entry6", ["GROUP"]),
    ("C02", "File", "DescText", ["STRING"]),
    ("C02", "File", "CreateDate", ["DATE"]),
    ("C02", "File", "CreateTime", ["TIME"]),
    ("C02", "File", "Revision", ["REAL"]),
    ("C03", "Device", "VendCode", ["INTEGER"]),
    ("C04", "ParamClass", "Descriptor", ["HEX"]),
    ("C08", "Assembly", "Assem5", ["STRING", "STRING", "INTEGER", None, None,
                                   "INTEGER", "WORD", "INTEGER", "WORD", "INTEGER", None]),
    ("C09", "Params", "Param2", ["INTEGER", None, None, "HEX", "INTEGER", "INTEGER", "STRING", "STRING", "STRING"]
     + ["INTEGER"] * 12),
    ("C09", "Connection Manager", "Connection1", ["HEX", "HEX", None, "INTEGER"]),
    ("C10", "Port", "Port2", ["WORD", "STRING", "STRING", "INTEGER"]),
    ("C11", "File", "CreateDate", ["DATE"]),
    ("C11", "File", "CreateTime", ["TIME"]),
    ("C11", "Modular", "SlotDisplayRule", ["WORD"]),
    ("C14", "Modular", "ExternalIDExactMatch", ["WORD"]),
    ("C15", "Params", "Param1", ["INTEGER", None, None, "HEX", "INTEGER", "INTEGER", "STRING", "STRING", "STRING",
                                 "INTEGER", "HEX"]),
    ("C15", "Connection Manager", "ProxyConnect1", ["HEX", "HEX"]),
    ("C16", "Connection Manager", "ProxiedConnect1", [None, None, None, "INTEGER", None, None, "STRING"]),
]


@pytest.mark.parametrize(("number", "section", "keyword", "kinds"), VALUE_KINDS,
                         ids=[f"{n}-{k}" for n, _, k, _ in VALUE_KINDS])
def test_value_kinds(number, section, keyword, kinds):
    fields = entry(figure(number), section, keyword).fields
    assert [f.value and str(f.value.kind) for f in fields][:len(kinds)] == kinds


STRING_TEXTS = [
    ("C02", "File", "DescText", 0, "Smart Widget EDS File"),
    ("C03", "Device", "VendName", 0, "Widget-Works, Inc."),
    ("C08", "Assembly", "Assem5", 1, "20 04 24 05 30 03"),
    ("C09", "Params", "Param1", 7, ""),
    ("C09", "Connection Manager", "Connection1", 14, "20 04 24 01 2C [Param2] 2C [Param1]"),
    ("C15", "Params", "Param1", 6, " Target Error Codes"),
    ("C15", "Connection Manager", "ProxyConnect1", 14, "01 SLOT_MINUS_ONE 20 04 24 03 2C 04 2C 02"),
]


@pytest.mark.parametrize(("number", "section", "keyword", "index", "text"), STRING_TEXTS,
                         ids=[f"{n}-{k}-{i}" for n, _, k, i, _ in STRING_TEXTS])
def test_string_text(number, section, keyword, index, text):
    value = entry(figure(number), section, keyword).fields[index].value
    assert isinstance(value, String) and not value.unicode
    assert value.text == text


def test_c01_entry6_is_one_field_holding_a_value_and_a_group():
    (only,) = entry(figure("C01"), "section name", "Entry6").fields
    first, second = only.value.fields
    assert first.value == Scalar("44")
    assert isinstance(second.value, Group)
    assert [f.value for f in second.value.fields] == [Scalar("22"), Scalar("33"), Scalar("11")]


def test_c01_vendor_keyword_starts_with_the_vendor_id():
    item = entry(figure("C01"), "section name", "65535_Entry")
    assert item.keyword.split("_", 1) == ["65535", "Entry"]
    assert len(item.fields) == 2


COMMENTS_C01 = [
    ("Entry3", [" Multiple line entry"], [[" Field1"], [" Field2"], [" Field3"]]),
    ("Entry4", [" Combination"], [[], [" Fields 1 and 2 on one line"], [" Field3"], [" Field4"]]),
    ("Entry5", [], [[" Field 1 specifies the value 1"], []]),
    ("65535_Entry", [" Vendor Specific entry for"], [[], [" Vendor_ID 65535 with two fields"]]),
]


@pytest.mark.parametrize(("keyword", "own", "per_field"), COMMENTS_C01, ids=[k for k, _, _ in COMMENTS_C01])
def test_c01_comments_attach_to_their_entry_and_fields(keyword, own, per_field):
    item = entry(figure("C01"), "section name", keyword)
    assert [c.text for c in item.comments] == own
    assert field_comments(item) == per_field


def test_c01_comment_placement():
    eds = figure("C01")
    section = eds.section("section name")
    # A comment on a line of its own goes to the next statement.
    assert [c.text for c in entry(eds, "section name", "Entry1").leading_comments] == [
        " Comment - extends to end of line"]
    # Entry5's comment on the line after its ';' is such a comment, and so are Entry6's.
    assert [c.text for c in entry(eds, "section name", "Entry6").leading_comments] == [
        " structure with three values"]
    # Inside an entry a comment goes to the last field begun before it: in Entry6 the nested 11.
    entry6 = list(entry(eds, "section name", "Entry6").walk_fields())
    assert [f.raw for f in entry6] == [None, "44", None, "22", "33", "11"]
    assert [c.text for c in entry6[-1].comments] == [" Entry 6 specifies a single field."]
    assert section.comments == [] and eds.trailing_comments == []


def test_c02_file_section_comments():
    item = entry(figure("C02"), "File", "CreateDate")
    assert item.fields[0].comments[0].text == " created"
    assert field_comments(entry(figure("C02"), "File", "Revision")) == [[" Revision of EDS"]]


def test_c08_assem5_is_one_byte_with_default_0x21():
    # The figure says: "Assem5 is 1 byte long and has a default value of 0x21".
    eds = figure("C08")
    assem = entry(eds, "Assembly", "Assem5").fields
    members = [(assem[i].raw, assem[i + 1].raw) for i in range(5, len(assem), 2)]
    assert members == [("4", "Param1"), ("3", "Param2"), ("1", None)]
    assert sum(int(size) for size, _ in members) == 8 * int(assem[2].raw)
    default, shift = 0, 0
    for size, reference in members:
        if reference is not None:
            default |= int(entry(eds, "Params", reference).fields[11].raw) << shift
        shift += int(size)
    assert default == 0x21


def test_c09_connection_masks_and_path():
    item = entry(figure("C09"), "Connection Manager", "Connection1")
    assert int(item.fields[0].raw, 16) == 0x04010002
    assert int(item.fields[1].raw, 16) == 0x44244401
    assert re.findall(r"\[(\w+)\]", item.fields[14].value.text) == ["Param2", "Param1"]
    assert field_comments(item)[:2] == [
        [" trigger & transport", " class 1, cyclic, exclusive-owner"],
        [" point/multicast & priority & realtime format", " fixed, 32-bit headers, scheduled,",
         " O=>T point-to-point, T=>O multicast"]]


def test_c09_param_comments():
    eds = figure("C09")
    param1, param2 = eds.section("Params").entries
    assert [c.text for c in param1.comments] == [" specifies read buffer"]
    assert [c.text for c in param1.fields[6].comments] == [" name"]
    assert [c.text for c in param1.fields[8].comments] == [" units & help string"]
    # "$(not used)" stands on a line of its own after Param1's ';'.
    assert [c.text for c in param2.leading_comments] == ["(not used)"]
    assert int(param1.fields[15].raw) == -63


def test_c12_comments_after_the_last_entry_end_the_file():
    eds = figure("C12")
    assert field_comments(entry(eds, "Modular", "Rack1"))[-1] == [" this module can plug into"]
    assert [c.text for c in eds.trailing_comments] == [" slots 1, 2, 3 and 4 of", " this five slot chassis"]


def numbered(eds: EdsFile, section: str, prefix: str) -> list[str]:
    """The numbers N of the ``prefixN`` entries of a section."""
    entries = eds.section(section).entries
    return [e.keyword[len(prefix):] for e in entries if re.fullmatch(prefix + r"[0-9]+", e.keyword)]


@pytest.mark.parametrize(("section", "stem", "numbers"), [
    ("Params", "Param", ["1"]), ("Assembly", "Assem", ["1", "2"]), ("Connection Manager", "Connect", ["1"])])
def test_c15_c16_proxy_and_proxied_entries_pair_by_number(section, stem, numbers):
    assert numbered(figure("C15"), section, "Proxy" + stem) == numbers
    assert numbered(figure("C16"), section, "Proxied" + stem) == numbers


def test_c15_c16_module_fields():
    proxy, proxied = figure("C15"), figure("C16")
    for number in ("1", "2"):
        assert entry(proxy, "Assembly", f"ProxyAssem{number}").fields[-1].raw == "ModuleMemberList"
        assert (entry(proxy, "Assembly", f"ProxyAssem{number}").fields[0]
                == entry(proxied, "Assembly", f"ProxiedAssem{number}").fields[0])
    assert [f.raw for f in entry(proxy, "Params", "ProxyParam1").fields[9:12]] == ["Module"] * 3


# --- the damaged figures as printed (corpus/broken) -------------------------------

BROKEN_DIAGNOSTICS = [
    # C.1: comments moved down a line; the text still reads without a fault.
    ("C01", []),
    # C.9: "\$" for "$" (line 2); '", "",' lost a quote (line 20; the one on line 9
    # is inside the statement already skipped after line 2's error).
    ("C09", [("EDS001", 2), ("EDS013", 20)]),
    # C.10: the '.' lines standing for omitted entries.
    ("C10", [("EDS001", 6)]),
    # C.13: '...' for the three empty reserved fields of Rack1 and Rack2.
    ("C13", [("EDS001", 5), ("EDS001", 10)]),
    # C.14: the same in Rack1.
    ("C14", [("EDS001", 5)]),
    # C.16: a null string that lost a quote, twice.
    ("C16", [("EDS013", 2), ("EDS013", 9)]),
]


@pytest.mark.parametrize(("number", "expected"), BROKEN_DIAGNOSTICS, ids=[n for n, _ in BROKEN_DIAGNOSTICS])
def test_damaged_figure_diagnostics(number, expected):
    assert diagnostics(broken(number)) == expected


#: Entries of each damaged figure the damage does not touch: they read as in the clean file.
UNTOUCHED = [
    ("C01", "section name", ["Entry1", "Entry2", "Entry3", "Entry4", "Entry5", "Entry6", "65535_Entry"]),
    ("C09", "Connection Manager", []),
    ("C10", "Port", ["Port2"]),
    ("C13", "Modular", ["Width", "ExternalID"]),
    ("C14", "Modular", ["Width", "Rack2", "Query", "GenericID", "ExternalIDExactMatch"]),
    ("C16", "Assembly", ["ProxiedAssem1", "ProxiedAssem2"]),
]


@pytest.mark.parametrize(("number", "section", "keywords"), UNTOUCHED, ids=[n for n, _, _ in UNTOUCHED])
def test_damaged_figure_keeps_untouched_entries(number, section, keywords):
    printed = broken(number).section(section)
    clean = figure(number).section(section)
    kept = [e for e in printed.entries if e.keyword in keywords]
    assert [e.keyword for e in kept] == keywords
    assert [shape(e.fields) for e in kept] == [shape(clean.entry(k).fields) for k in keywords]


def test_c01_as_printed_attaches_the_shifted_comments_elsewhere():
    printed = broken("C01")
    entry3 = entry(printed, "section name", "Entry3")
    assert entry3.comments == []
    assert field_comments(entry3) == [[" Multiple line entry"], [], [" Field1"]]
    assert [c.text for c in entry(printed, "section name", "Entry4").leading_comments] == [" Field2", " Field3"]


def test_c09_as_printed_help_string_reads_silently_as_a_comma():
    # '", ",' for '"",' has its quotes paired: no diagnostic, but the text is ", ".
    connection = entry(broken("C09"), "Connection Manager", "Connection1")
    assert len(connection.fields) == 15
    assert connection.fields[13].value.text == ", "


UNPARSED = [
    ("C09", "Params", [2, 15]),
    ("C13", "Modular", [4, 9]),
    ("C14", "Modular", [4]),
    ("C16", "Connection Manager", [9]),
]


@pytest.mark.parametrize(("number", "section", "lines"), UNPARSED, ids=[n for n, _, _ in UNPARSED])
def test_damaged_statements_are_kept_verbatim(number, section, lines):
    printed = broken(number)
    kept = printed.section(section).unparsed
    assert [item.line for _, item in kept] == lines
    text = (BROKEN / f"figure_{number}_as_printed.eds").read_text().splitlines()
    assert [item.text.splitlines()[0] for _, item in kept] == [text[line - 1] for line in lines]


def test_c10_as_printed_keeps_the_entry_before_the_dots():
    port = broken("C10").section("Port")
    assert [e.keyword for e in port.entries] == ["Port1", "Port2"]
    assert port.entry("Port1").fields == figure("C10").section("Port").entry("Port1").fields


def test_section_header_before_unreadable_text_is_kept():
    eds = edsconv.parse("[Port]\n.\nPort2 = 1;\n")
    assert [s.name for s in eds.sections] == ["Port"]
    assert diagnostics(eds) == [("EDS001", 2)]


# --- strings: C.4.1.3.3 and STRINGI (C.4.1.3.5) -------------------------------------


def test_stringi_example_members():
    (field,) = entry(spec("stringi_C4135.eds"), "Example", "Field1").fields
    assert to_stringi(field.value) == (
        StringIMember("eng", 0xD0, 4, "This is an ASCII English language string"),
        StringIMember("spa", 0xD5, 1000, "Españoles palabras"),
        StringIMember("deu", 0xD0, 4, "Spanische Wörter auf Deutsch"),
    )
    contents = [member.value.fields[3].value for member in field.value.fields[1:]]
    assert [value.unicode for value in contents] == [False, True, False]
    assert [c.text for c in field.value.fields[2].value.fields[3].comments] == [' "Spanish words"']


@pytest.mark.parametrize("text", [
    '[A]\nX = {2, {"eng",0xD0,4,"a"}};\n',
    '[A]\nX = {1, {"eng",0xD0,4}};\n',
    '[A]\nX = {1, {eng,0xD0,4,"a"}};\n',
    '[A]\nX = {{"eng",0xD0,4,"a"}};\n',
])
def test_to_stringi_rejects_a_malformed_group(text):
    (field,) = edsconv.parse(text).sections[0].entries[0].fields
    with pytest.raises(ValueError):
        to_stringi(field.value)


STRINGS = [
    ("Ascii", False, "This results in a string composed by 8-bit characters", 1),
    ("Unicode", True, "A string of UNICODE characters, including the Greek character Pi \u03c0", 1),
    ("Concat1", False, "ABC123XYZ", 3),
    ("Concat2", False, "ABC123XYZ", 3),
    ("Concat3", True, "ABC123XYZ", 3),
    ("Concat3Same", True, "ABC123XYZ", 1),
]


@pytest.mark.parametrize(("keyword", "unicode", "text", "parts"), STRINGS, ids=[k for k, _, _, _ in STRINGS])
def test_string_examples(keyword, unicode, text, parts):
    (field,) = entry(spec("strings_C4133.eds"), "Example", keyword).fields
    assert isinstance(field.value, String)
    assert (field.value.unicode, field.value.text, len(field.value.parts)) == (unicode, text, parts)


def test_concatenation_keeps_the_comment_between_parts():
    (field,) = entry(spec("strings_C4133.eds"), "Example", "Concat2").fields
    assert field.value.parts == ('"ABC"', '"123"', '"XYZ"')
    assert [c.text for c in field.comments] == ["this is a comment"]


@pytest.mark.parametrize(("text", "expected", "codes"), [
    ('"ABC" "123" "XYZ"', "ABC123XYZ", []),
    ('"ABC""123"', "ABC123", []),
    ('L"ABC" L"123"', "ABC123", [("EDS016", 2)]),
])
def test_inline_concatenation(text, expected, codes):
    eds = edsconv.parse(f"[A]\nX = {text};\n")
    (field,) = eds.sections[0].entries[0].fields
    assert field.value.text == expected
    assert diagnostics(eds) == codes


def test_figure_c11_scaling_draws_a_warning_naming_figure_and_formula_not_an_error():
    """Issue 20 item 10: C.11 sets the scaling bit with 0 in every scaling field; Figure C.5 divides by the
    divisor. The figure is no error (only the sections a fragment lacks are): EDS350 names both."""
    _, found = edsconv.analyse(figure("C11"))
    assert [d.code for d in found if d.severity is Severity.ERROR and d.code != "EDS201"] == []
    assert [(d.code, d.line) for d in found if d.code in {"EDS319", "EDS350"}] == [("EDS350", 29)]
