"""The file-structure checks (EDS201-EDS249, src/edsconv/checks/structure.py).

Every rule has a tiny EDS that triggers it, checked at its exact line and
column, and a near-identical good variant that does not. The fixtures start
from a minimal valid EtherNet/IP EDS (:data:`MINIMAL`) with sections replaced,
added, dropped or reordered.
"""

from __future__ import annotations

import collections

import pytest

import edsconv
from conftest import REPO, SHARED_REAL, needs_real_corpus
from edsconv.diagnostics import Severity, load_rules

#: The smallest EDS these checks accept: Tables C.6, C.8 and C.27, nothing optional.
MINIMAL = {
    "File": 'DescText = "Test adapter";\nCreateDate = 01-02-2020;\nCreateTime = 10:00:00;\nRevision = 1.0;',
    "Device": 'VendCode = 65535;\nVendName = "Vendor";\nProdType = 12;\nProdTypeStr = "Communications Adapter";\n'
              'ProdCode = 1;\nMajRev = 1;\nMinRev = 1;\nProdName = "Adapter";',
    "Device Classification": "Class1 = EtherNetIP;",
}
ASSEMBLY = 'Assem1 = "In", "", 2, 0x0000, , , 16, ;\nAssem2 = "Out", "", 2, 0x0000, , , 16, ;'
CONNECTION = ('Connection1 = 0x04010002, 0x44640405, , 2, Assem2, , 2, Assem1, , , , , "Owner", "", '
              '"20 04 24 01 2C 02 2C 01";')
PORT = 'Port1 = TCP, "EtherNet/IP", "20 F5 24 01", 1;'


def eds(changes: dict[str, str | None] | None = None, order: list[str] | None = None) -> str:
    """MINIMAL with sections replaced or added (a body) or dropped (None), in ``order`` if given."""
    sections = {**MINIMAL, **(changes or {})}
    names = order or [name for name, body in sections.items() if body is not None]
    return "".join(f"[{name}]\n{sections[name]}\n" for name in names)


def structure(text: str) -> list[tuple[str, int, int]]:
    """(code, line, column) of every diagnostic of the structure checks."""
    _, diagnostics = edsconv.analyse(edsconv.parse(text))
    return [(d.code, d.line, d.column) for d in diagnostics if "EDS201" <= d.code <= "EDS249"]


def at(code: str, text: str, snippet: str) -> tuple[str, int, int]:
    """``code`` at the last place ``snippet`` appears in ``text`` (the fixtures add faults at the end)."""
    offset = text.rindex(snippet)
    line = text.count("\n", 0, offset) + 1
    return code, line, offset - text.rfind("\n", 0, offset)


def start(code: str) -> tuple[str, int, int]:
    return code, 1, 1


_MISPLACED_VENDOR = eds({"65535_Extra": "65535_Note = 1;", "Params": None}) + \
    '[Params]\nParam1 = 0, , , 0x0000, 0xC6, 1, "P", "", "", 0, 10, 1;\n'
_WITH_ICON = 'VendCode = 65535;\nVendName = "V";\nProdType = 12;\nProdTypeStr = "A";\nProdCode = 1;\nMajRev = 1;\n' \
             'MinRev = 1;\nProdName = "A";\nIcon = "a.ico";'
_FILE_WITH = MINIMAL["File"] + "\n{}"

# (code, bad text, snippet where the diagnostic stands, good text)
CASES = [
    ("EDS201", eds({"Device": None}), None, eds()),
    ("EDS201", eds({"Device Classification": None}), None, eds()),
    ("EDS202", eds(order=["File", "Device Classification", "Device"]), "[Device]\n", eds()),
    ("EDS202", eds(order=["Device", "File", "Device Classification"]), "[File]", eds()),
    ("EDS203", _MISPLACED_VENDOR, "[65535_Extra]",
     eds({"Params": 'Param1 = 0, , , 0x0000, 0xC6, 1, "P", "", "", 0, 10, 1;', "65535_Extra": "65535_Note = 1;"})),
    ("EDS204", eds({"Connection Manager": CONNECTION, "Assembly": ASSEMBLY}), "Assem2, , 2",
     eds({"Assembly": ASSEMBLY, "Connection Manager": CONNECTION})),
    ("EDS205", eds({"Device Classification": "Class1 = 65535_Tool;"}), "[Device Classification]", eds()),
    ("EDS206", eds({"File": MINIMAL["File"].replace("CreateTime = 10:00:00;\n", "")}), "[File]", eds()),
    ("EDS206", eds({"Device Classification": "65535_Tree = 1;"}), "[Device Classification]", eds()),
    ("EDS207", eds({"Port": 'Port1 = TCP, "EtherNet/IP", "20 F5 24 01", ;'}), ";", eds({"Port": PORT})),
    ("EDS207", eds({"Port": "Port1 = TCP;"}), "Port1", eds({"Port": PORT})),
    ("EDS207", eds({"Modular": "Width = 1;\nRack1 = 65535, 101, 1, 1, 1,,,;"}), "Rack1",
     eds({"Modular": "Width = 1;\nRack1 = 65535, 101, 1, 1, 1,,,, 1;"})),
    ("EDS206", eds({"Modular": "SlotDisplayRule = Param1;"}), "[Modular]", eds({"Modular": "DefineSlotsInRack = 5;"})),
    ("EDS206", eds({"Modular": "Rack1 = 65535, 101, 1, 1, 1,,,, 1;"}), "[Modular]",
     eds({"Modular": "Width = 1;\nRack1 = 65535, 101, 1, 1, 1,,,, 1;"})),
    ("EDS206", eds({"Modular": "Width = 1;"}), "[Modular]",
     eds({"Modular": "Width = 1;\nRack1 = 65535, 101, 1, 1, 1,,,, 1;"})),
    ("EDS208", eds({"File": MINIMAL["File"].replace('"Test adapter"', '"Test", "adapter"')}), '"adapter"', eds()),
    ("EDS209", eds({"Assembly": ASSEMBLY, "Connection Manager": CONNECTION.replace(";", ", 6, 1, 7;")}), "6, 1, 7;",
     eds({"Assembly": ASSEMBLY, "Connection Manager": CONNECTION})),
    ("EDS210", eds({"Port": PORT.replace("1;", "1, 0x00;")}), "0x00", eds({"Port": PORT.replace("1;", "1, ;")})),
    ("EDS210", eds({"Assembly": ASSEMBLY.replace("0x0000, , , 16", "0x0000, 8, , 16", 1)}), "8, , 16",
     eds({"Assembly": ASSEMBLY})),
    ("EDS211", eds({"Modular": "ExternIDExactMatch = Maybe;"}), "Maybe", eds({"Modular": "ExternIDExactMatch = No;"})),
    ("EDS211", eds({"Device": MINIMAL["Device"] + '\nExcludeFromAdapterRackConnection = "Never";'}), '"Never"',
     eds({"Device": MINIMAL["Device"] + '\nExcludeFromAdapterRackConnection = "Yes";'})),
    ("EDS211", eds({"Params": 'Param1 = 1, , , 0x0000, 0xC6, 1, "P", "", "", 0, 10, 1;'}), "1, , ,",
     eds({"Params": 'Param1 = 0, , , 0x0000, 0xC6, 1, "P", "", "", 0, 10, 1;'})),
    ("EDS212", eds({"Device Classification": "Class1 = EtherNetIP, Adapter;"}), "Adapter",
     eds({"Device Classification": "Class1 = EtherNetIP;\nClass2 = 65535_Tool, Adapter;"})),
    ("EDS213", eds({"Device Classification": "Class1 = EtherNetIP;\nClass3 = 65535_Tool;"}), "Class3",
     eds({"Device Classification": "Class1 = EtherNetIP;\nClass2 = 65535_Tool;"})),
    ("EDS213", eds({"Groups": 'Group2 = "G", 0;'}), "Group2", eds({"Groups": 'Group1 = "G", 0;'})),
    ("EDS214", eds({"File": _FILE_WITH.format("ModTime = 11:00:00;")}), "ModTime",
     eds({"File": _FILE_WITH.format("ModDate = 01-03-2020;\nModTime = 11:00:00;")})),
    ("EDS215", eds({"File": _FILE_WITH.format("ModDate = 01-01-2020;")}), "ModDate",
     eds({"File": _FILE_WITH.format("ModDate = 01-02-2020;")})),
    ("EDS215", eds({"File": _FILE_WITH.format("ModDate = 01-02-2020;\nModTime = 09:59:59;")}), "ModDate",
     eds({"File": _FILE_WITH.format("ModDate = 01-02-2020;\nModTime = 10:00:00;")})),
    ("EDS216", eds({"Device": _WITH_ICON}), "Icon",
     eds({"Device": _WITH_ICON, "File": _FILE_WITH.format('HomeURL = "http://example.com/a.eds";')})),
    ("EDS223", eds({"Device": _WITH_ICON.replace("a.ico", "a.png"),
                    "File": _FILE_WITH.format('HomeURL = "http://example.com/a.eds";')}), '"a.png"',
     eds({"Device": _WITH_ICON.replace("a.ico", "A.ICO"),
          "File": _FILE_WITH.format('HomeURL = "http://example.com/a.eds";')})),
    ("EDS217", eds({"0065_Extra": "Note = 1;"}), "[0065_Extra]", eds({"65_Extra": "Note = 1;"})),
    ("EDS217", eds({"Device": MINIMAL["Device"] + "\n0065_Note = 1;"}), "0065_Note",
     eds({"Device": MINIMAL["Device"] + "\n65_Note = 1;"})),
    ("EDS217", eds({"Device Classification": "Class1 = EtherNetIP;\nClass2 = 0065_Tool;"}), "0065_Tool",
     eds({"Device Classification": "Class1 = EtherNetIP;\nClass2 = 65_Tool;"})),
    ("EDS218", eds({"Device": MINIMAL["Device"] + "\n1Note = 1;"}), "1Note",
     eds({"Device": MINIMAL["Device"] + "\n1_Note = 1;"})),
    ("EDS218", eds({"2Extra": "Note = 1;"}), "[2Extra]", eds({"2_Extra": "Note = 1;"})),
    ("EDS218", eds({"2Extra Data": "Note = 1;"}), "[2Extra Data]", eds({"2_Extra Data": "Note = 1;"})),
    ("EDS217", eds({"0065_Extra Data": "Note = 1;"}), "[0065_Extra Data]", eds({"65_Extra Data": "Note = 1;"})),
    ("EDS219", eds({"Params": "MaxInst = 4;"}), "MaxInst",
     eds({"ParamClass": "MaxInst = 4;\nDescriptor = 0x0000;\nCfgAssembly = 0;"})),
    ("EDS219", eds({"Capacity": "MaxInst = 4;"}), "MaxInst", eds({"Capacity": "MaxIOConnections = 4;"})),
    ("EDS228", eds({"Connection Manger": "Connection1 = 0x04010002;"}), "[Connection Manger]",
     eds({"Capacity": "MaxIOConnections = 4;"})),
    ("EDS228", eds({"Diagnostics Extra": "MaxIOConnections = 4;"}), "[Diagnostics Extra]",
     eds({"65535_Capacity": "Max = 4;"})),
    ("EDS228", eds({"PARAMS": 'Param1 = 0, , , 0x0000, 0xC6, 1, "P", "", "", 0, 10, 1;'}), "[PARAMS]",
     eds({"Params": 'Param1 = 0, , , 0x0000, 0xC6, 1, "P", "", "", 0, 10, 1;'})),
    ("EDS230", eds({"Device": MINIMAL["Device"] + '\nProdname = "Adapter 2";'}), "Prodname",
     eds({"Device": MINIMAL["Device"] + '\nCatalog = "Adapter 2";'})),
    ("EDS222", eds({"Device": MINIMAL["Device"] + '\nCatalogue = "PRB-1";'}), "Catalogue",
     eds({"Device": MINIMAL["Device"] + '\nCatalog = "PRB-1";'})),
    ("EDS222", eds({"Device": MINIMAL["Device"] + '\nIconContent = "AA";'}), "IconContent",
     eds({"Device": MINIMAL["Device"] + '\nIconContents = "AA";'})),
    ("EDS222", eds({"Capacity": "MaxFoo = 4;"}), "MaxFoo", eds({"Capacity": "MaxIOConnections = 4;"})),
    ("EDS222", eds({"Params": 'Parameter1 = 0, , , 0x0000, 0xC6, 1, "P", "", "", 0, 10, 1;'}), "Parameter1",
     eds({"Params": 'Param1 = 0, , , 0x0000, 0xC6, 1, "P", "", "", 0, 10, 1;'})),
    ("EDS211", eds({"Device Classification": "Class1 = EtherNetIP;\nClass2 = Profibus;"}), "Profibus",
     eds({"Device Classification": "Class1 = EtherNetIP;\nClass2 = Safety;"})),
    ("EDS222", eds({"Assembly": ASSEMBLY + "\nVariantX1 = 1;"}), "VariantX1",
     eds({"Assembly": ASSEMBLY + "\nVariant1 = 1;"})),
    ("EDS221", eds({"Port": PORT.replace("TCP", "DeviceNet")}), "[Port]", eds({"Port": PORT})),
    # issue 20 item 1: the classification against the content, both directions
    ("EDS224", eds({"Device Classification": "Class1 = DeviceNet;", "Port": PORT}), "Port1",
     eds({"Device Classification": "Class1 = DeviceNet;\nClass2 = EtherNetIP;", "Port": PORT})),
    ("EDS224", eds({"Device Classification": "Class1 = ControlNet;", "TCP/IP Interface Class": "Revision = 4;"}),
     "[TCP/IP Interface Class]",
     eds({"Device Classification": "Class1 = ControlNet;\nClass2 = EtherNetIP;",
          "TCP/IP Interface Class": "Revision = 4;"})),
    ("EDS227", eds({"Assembly": 'Assem1 = "Outer", "", 2, , , , , Assem2;\nAssem2 = "Inner", "", 2, , , , 16, ;'}),
     "Assem2;", eds({"Assembly": 'Assem2 = "Inner", "", 2, , , , 16, ;\nAssem1 = "Outer", "", 2, , , , , Assem2;'})),
    ("EDS225", eds({"DeviceNet Class": "Revision = 2;"}), "[DeviceNet Class]",
     eds({"Device Classification": "Class1 = EtherNetIP;\nClass2 = DeviceNet;", "DeviceNet Class": "Revision = 2;"})),
    ("EDS226", eds({"Device Classification": "Class1 = EtherNetIP;\nClass2 = DeviceNet;", "Port": PORT}), "[Port]",
     eds({"Device Classification": "Class1 = EtherNetIP;\nClass2 = DeviceNet;",
          "Port": PORT + '\nPort2 = DeviceNet, "DeviceNet", "20 03 24 01", 2;'})),
]


@pytest.mark.parametrize(("code", "bad", "snippet", "good"), CASES,
                         ids=[f"{case[0]}-{n}" for n, case in enumerate(CASES)])
def test_rule_triggers_at_its_place_and_not_on_the_good_variant(code, bad, snippet, good):
    expected = start(code) if snippet is None else at(code, bad, snippet)
    assert expected in structure(bad)
    assert code not in [found for found, _, _ in structure(good)]


def test_every_structure_rule_has_a_case():
    registered = {code for code in load_rules().rules if "EDS201" <= code <= "EDS249"}
    assert registered == {case[0] for case in CASES}


def test_the_minimal_file_and_the_example_adapter_are_clean():
    assert structure(eds()) == []
    text = (REPO / "corpus" / "examples" / "io_adapter.eds").read_text(encoding="ascii")
    _, diagnostics = edsconv.analyse(edsconv.parse(text))
    assert [d.format() for d in diagnostics if "EDS201" <= d.code <= "EDS249" and d.severity > Severity.INFO] == []


def test_a_missing_section_is_reported_once_each_and_not_for_a_file_without_sections():
    assert structure(eds({"File": None, "Device": None})) == [start("EDS201"), start("EDS201")]
    assert structure("$ nothing but a comment\n") == []


def test_the_eds_of_another_network_needs_no_ethernetip_classification():
    devicenet = eds({"Device Classification": "Class1 = DeviceNet;"})
    legacy_devicenet = eds({"Device Classification": None, "IO_Info": "Default = 0x0001;"})
    assert structure(devicenet) == []
    assert structure(legacy_devicenet) == []


def test_forward_reference_is_reported_once_per_pair_of_sections():
    text = eds({"Connection Manager": CONNECTION, "Assembly": ASSEMBLY})
    assert [found for found in structure(text) if found[0] == "EDS204"] == [at("EDS204", text, "Assem2, , 2")]


def test_forward_reference_through_a_connection_path():
    param = 'Param1 = 0, , , 0x0000, 0xC6, 1, "Slot", "", "", 0, 10, 1;'
    connection = CONNECTION.replace("2C 01", "2C [Param1]")
    text = eds({"Assembly": ASSEMBLY, "Connection Manager": connection, "Params": param})
    assert [found for found in structure(text) if found[0] == "EDS204"] == [at("EDS204", text, '"20 04')]
    placed = eds({"Params": param, "Assembly": ASSEMBLY, "Connection Manager": connection})
    assert "EDS204" not in [found for found, _, _ in structure(placed)]


@pytest.mark.parametrize(("text", "meant"), [
    (eds({"Connection Manger": "Connection1 = 0x04010002;"}), "[Connection Manager]"),
    (eds({"Device": MINIMAL["Device"] + '\nCatalogue = "PRB-1";'}), "Catalog"),
    (eds({"Params": 'Parameter5 = 0, , , 0x0000, 0xC6, 1, "P", "", "", 0, 10, 1;'}), "Param5"),
    (eds({"Groups": 'Grp3 = "G", 0;'}), "Group3"),
    (eds({"Connection Manager": "Conn2 = 0x04010002;"}), "Connection2"),
])
def test_an_unknown_keyword_offers_the_closest_defined_one(text, meant):
    (message,) = [d.message for d in edsconv.analyse(edsconv.parse(text))[1] if d.code in ("EDS222", "EDS228")]
    assert message.endswith(f"did you mean {meant}?")


def test_keywords_defined_elsewhere_are_information_and_those_defined_in_place_draw_nothing():
    # MaxInst is a [ParamClass] entry of the 2003 text and an object-class entry of the newer tables
    # (keywords are global in scope, C.4.1.2.2.8), but neither defines it in [Params] or [Capacity];
    # IconContents, Variant1, MaxInst in [Connection Manager] and [DLR Class] are the newer tables' in place
    text = eds({"Device": MINIMAL["Device"] + '\nIconContents = "AA";', "Connection Manager": "MaxInst = 2;",
                "Assembly": ASSEMBLY + "\nVariant1 = 1;", "DLR Class": "Revision = 3;", "Params": "MaxInst = 4;",
                "Capacity": "MaxInst = 4;"})
    found = [(code, line) for code, line, _ in structure(text)]
    assert [code for code, _ in found if code in ("EDS219", "EDS220", "EDS222")] == ["EDS219", "EDS219"]


def test_one_fault_one_code_for_the_port_type_and_the_query_service():
    port = eds({"Port": PORT.replace("TCP", "Ethernet")})
    query = eds({"Modular": 'Width = 1;\nRack1 = 65535,12,1,1,1,,,,0;\nQuery = "20 04 24 07 30 03",3,2,"FF";'})
    found = [d.code for text in (port, query) for d in edsconv.analyse(edsconv.parse(text))[1]]
    assert "EDS333" in found and "EDS336" in found
    assert "EDS219" not in found and "EDS221" not in found and "EDS211" not in found


def test_modular_requirements_by_kind():
    def missing(body: str) -> list[tuple[str, str]]:
        found = edsconv.analyse(edsconv.parse(eds({"Modular": body})))[1]
        return [(d.message.split(" lacks ")[1], d.clause) for d in found if d.code == "EDS206"]

    assert missing("SlotDisplayRule = Param1;") == [("the required entry DefineSlotsInRack (C.4.1.5.2.2)",
                                                     "C.4.1.5.2.2")]
    assert missing('Query = "20 04 24 07 30 03",1,2,"FF FF";') == [
        ("the required entries Width, RackN (C.4.1.5.2.3)", "C.4.1.5.2.3")]
    # a chassis with modules of its own, and an empty section (C.4.1.2.2.7 allows empty place holders)
    assert missing("DefineSlotsInRack = 4;\nWidth = 1;\nRack1 = 65535,12,1,1,1,,,,1;") == []
    assert missing("") == []


def test_numbering_cites_the_clause_of_its_family():
    def clauses(text: str) -> list[str]:
        return [d.clause for d in edsconv.analyse(edsconv.parse(text))[1] if d.code == "EDS213"]

    assert clauses(eds({"Groups": 'Group2 = "G", 0;'})) == ["C.4.1.4.7"]
    assert clauses(eds({"Device Classification": "Class1 = EtherNetIP;\nClass3 = 65535_Tool;"})) == ["C.4.1.4.4"]
    assert clauses(eds({"Modular": "Width = 1;\nRack2 = 65535,12,1,1,1,,,,1;"})) == ["C.4.1.5.2.3"]


@pytest.mark.parametrize("text", [
    eds({"Device Classification": "Class1 = ;"}),
    eds({"Device Classification": "Class1 = {EtherNetIP, 1};"}),
    eds({"File": _FILE_WITH.format("ModDate = 13-45-2020;\nModTime = 25:00:00;")}),
    eds({"File": None, "Device": "[Device]"}),
    eds({"Port": 'Port1 = {1}, , , {2}, {3}, {4};', "Params": "Param1 = ;"}),
    eds({"Assembly": "Assem1 = \"A\", , , , , , 8, Param9;", "Connection Manager": "Connection1 = ;"}),
    eds({"Device Classification": "Class1 = EtherNetIP;\nClass1 = EtherNetIP;\n0_ = 1;"}),
    "[File]\nDescText = \"x\"\nbroken text here ; [Device]\n",
])
def test_odd_input_never_raises(text):
    structure(text)


# Over the real corpus, per code. The errors and warnings are real defects:
# - EDS204: demo.eds puts [Connection Manager] before the [Assembly] it uses.
# - EDS207: demo.eds leaves Param1000's units and help strings and Connection1's
#   help string empty; Tables C.13 and C.22 require them ("" when there is none).
# - EDS210: seven OpENer-based files and the ifm AL1322 write 0x00 / 0 in Port1's
#   field 5, which Table C.25 reserves ("empty, not used").
# - EDS215: two ESP32P4 OpENer files were modified 2 s before they were created,
#   ros_eip_device.eds modified in 2018 and created in 2019.
# - EDS216: t.eds names an Icon but has no HomeURL for it to be relative to.
# - EDS227 (a warning, not a defect the text settles): 18 files (17 of one vendor's
#   I/O modules, 1 of another's) name a later AssemN of [Assembly] in an assembly,
#   as Figure C.15 does.
# What later CIP editions added (CIP Safety connections with 17 fields, IconContents,
# AssemExaN, [Capacity], [TCP/IP Interface Class], the DeviceNet [IO_Info] ...) is in
# edsconv.cip_tables, so EDS209, EDS219 and EDS220 draw nothing.
REAL_CORPUS_COUNTS = {"EDS204": 1, "EDS207": 3, "EDS210": 8, "EDS215": 3, "EDS216": 1, "EDS227": 18}


@needs_real_corpus
def test_real_corpus_counts_per_code():
    counts: collections.Counter[str] = collections.Counter()
    for path in sorted(SHARED_REAL.glob("*")):
        if path.suffix.lower() == ".eds":
            _, diagnostics = edsconv.analyse(edsconv.load(path))
            counts.update(d.code for d in diagnostics if "EDS201" <= d.code <= "EDS249")
    assert dict(counts) == REAL_CORPUS_COUNTS


class _CountedSection:
    """A section whose name counts its readers: what a check reads per section shows its complexity."""

    reads = 0

    def __init__(self, name: str, line: int) -> None:
        self._name, self.line, self.column = name, line, 1

    @property
    def name(self) -> str:
        _CountedSection.reads += 1
        return self._name


def test_vendor_sections_last_reads_each_section_a_bounded_number_of_times() -> None:
    """Issue 18 item 9: 20,000 vendor sections took 8 s and 200,000 minutes, each rescanning the sections
    after it. Counting name reads catches that regression without a timing: a quadratic check reads
    about 4.5 million names here, a linear one a few per section."""
    from types import SimpleNamespace

    from edsconv.checks import Context
    from edsconv.checks.structure import vendor_sections_last

    count = 3000
    sections = [_CountedSection("File", 1), _CountedSection("65535_Early", 2), _CountedSection("Device", 3)]
    sections += [_CountedSection(f"65535_S{n}", 4 + n) for n in range(count)]
    _CountedSection.reads = 0
    context = Context(eds=SimpleNamespace(sections=sections, path="v.eds"), device=None)  # type: ignore[arg-type]
    found = list(vendor_sections_last.run(context))
    assert [(d.code, d.line) for d in found] == [("EDS203", 2)]
    assert _CountedSection.reads <= 4 * len(sections)
