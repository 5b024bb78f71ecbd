"""The entity checks (EDS301-EDS337): each rule on a tiny EDS that breaks it and
on a near-identical one that does not, the example adapter, and the real corpus."""

from __future__ import annotations

import collections

import pytest

import edsconv
from conftest import REPO, SHARED_REAL, needs_real_corpus
from edsconv.diagnostics import load_rules

MARK = "$ HERE"
PARAM_RPI = 'Param1 = 0,,,0x0000,0xC8,4,"RPI","us","",1000,1000000,10000;'
PARAM_USINT = 'Param2 = 0,,,{descriptor},0xC6,{size},"Filter","ms","",{values}{scaling};'
ASSEM_IN = 'Assem100 = "In","",4,,,,32,Param1;'
CONNECTION = ('Connection{n} = {trigger}, {parameters}, {rpi},{size},Assem100, Param1,4,Assem100, ,, ,, '
              '{name}, "", "20 04 24 64 2C 64";')


def usint(descriptor="0x0000", size=1, values="0,255,3", scaling="", mark=""):
    return PARAM_USINT.format(descriptor=descriptor, size=size, values=values, scaling=scaling) + mark


def connection(n=1, trigger="0x04010002", parameters="0x44640405", rpi="Param1", size="4", name='"EO"', mark=""):
    return CONNECTION.format(n=n, trigger=trigger, parameters=parameters, rpi=rpi, size=size, name=name) + mark


DEFAULT_CONNECTIONS = (connection(),)


def eds(params=(PARAM_RPI,), groups=(), assembly=(ASSEM_IN,), connections=DEFAULT_CONNECTIONS, ports=(), modular=(),
        param_class=()):
    """A minimal valid EtherNet/IP EDS with the given entries, one per line."""
    lines = [
        "[File]", 'DescText = "test";', "CreateDate = 01-02-2024;", "CreateTime = 10:00:00;", "Revision = 1.1;",
        "[Device]", "VendCode = 65535;", 'VendName = "Test";', "ProdType = 12;", 'ProdTypeStr = "Adapter";',
        "ProdCode = 1;", "MajRev = 1;", "MinRev = 1;", 'ProdName = "Test adapter";',
        "[Device Classification]", "Class1 = EtherNetIP;",
    ]
    for name, entries in (("ParamClass", param_class), ("Params", params), ("Groups", groups), ("Assembly", assembly),
                          ("Connection Manager", connections), ("Port", ports), ("Modular", modular)):
        if entries:
            lines += [f"[{name}]", *entries]
    return "\n".join(lines) + "\n"


def found(text: str, code: str) -> list[int]:
    _, diagnostics = edsconv.analyse(edsconv.parse(text))
    return sorted({d.line for d in diagnostics if d.code == code})


def marked_line(text: str) -> int:
    return next(number for number, line in enumerate(text.splitlines(), 1) if MARK in line)


M = MARK
# code -> (text that breaks the rule on the line marked $ HERE, near-identical text that does not)
CASES = {
    "EDS301": (eds(assembly=['Assem100 = "In","",4,,,,32,Param9;' + M]), eds()),
    "EDS302": (eds(params=[PARAM_RPI, usint()], connections=[connection(rpi="Param2", mark=M)]),
               eds(params=[PARAM_RPI, usint()], connections=[connection(rpi="Param1")])),
    "EDS303": (eds(params=[PARAM_RPI, usint("0x0002"), 'Enum5 = 0,"Off",1,"On";' + M]),
               eds(params=[PARAM_RPI, usint("0x0002"), 'Enum2 = 0,"Off",1,"On";'])),
    "EDS304": (eds(groups=['Group1 = "Setup", 2, 1;' + M]), eds(groups=['Group1 = "Setup", 1, 1;'])),
    "EDS305": (eds(connections=[connection(1), connection(2, mark=M)]),
               eds(connections=[connection(1), connection(2, name='"EO 2"')])),
    "EDS306": (eds(connections=[connection(trigger="0x04010082", mark=M)]), eds()),
    "EDS307": (eds(connections=[connection(trigger="0x05010002", mark=M)]), eds()),
    "EDS308": (eds(connections=[connection(trigger="0x04010000", mark=M)]), eds()),
    "EDS309": (eds(connections=[connection(parameters="0x44640C05", mark=M)]), eds()),
    "EDS310": (eds(connections=[connection(parameters="0x44640205", mark=M)]), eds()),
    "EDS311": (eds(connections=[connection(size="", mark=M).replace("Assem100,", ",", 1)]),
               eds(connections=[connection().replace("Assem100,", ",", 1)])),
    "EDS312": (eds(connections=[connection(size="8", mark=M)]), eds()),
    "EDS313": (eds(connections=[connection(), connection(2, name="Module", mark=M).replace("Connection2",
                                                                                         "ProxyConnect2")]),
               eds(connections=[connection(), connection(2, name='"LO"').replace("Connection2", "ProxyConnect2")])),
    "EDS314": (eds(params=[PARAM_RPI, usint("0x0200", mark=M)]), eds(params=[PARAM_RPI, usint("0x0010")])),
    "EDS315": (eds(params=[PARAM_RPI, usint(values="10,5,7", mark=M)]),
               eds(params=[PARAM_RPI, usint(values="5,10,7")])),
    "EDS316": (eds(params=[PARAM_RPI, 'Param3 = 0,,,0x0000,0xD0,1,"Name","","",,,"abc";' + M]),
               eds(params=[PARAM_RPI, 'Param3 = 0,,,0x0000,0xD0,1,"Name","","",0,16,"abc";'])),
    "EDS317": (eds(params=[PARAM_RPI, 'Param3 = 0,,,0x0000,0xD2,2,"Word","","",0,0xFFFF,0;' + M]),
               eds(params=[PARAM_RPI, 'Param3 = 0,,,0x0000,0xD2,2,"Word","","",,,0;'])),
    "EDS318": (eds(params=[PARAM_RPI, 'Param3 = 0,,,0x0000,0xD2,2,"Word","","",,,0,1,1,1,0;' + M]),
               eds(params=[PARAM_RPI, 'Param3 = 0,,,0x0000,0xD2,2,"Word","","",,,0,,,,;'])),
    "EDS319": (eds(params=[PARAM_RPI, usint("0x0004", scaling=",1,0,1,0", mark=M)]),
               eds(params=[PARAM_RPI, usint("0x0004", scaling=",1,2,1,0")])),
    "EDS350": (eds(params=[PARAM_RPI, usint("0x0004", values="0,4,0", scaling=",0,0,0,0", mark=M)]),
               eds(params=[PARAM_RPI, usint("0x0000", values="0,4,0", scaling=",0,0,0,0")])),
    "EDS351": (eds(params=[PARAM_RPI, usint("0x0002", values="0,2,0"), 'Enum2 = 0,"Off",1,"On",3,"Test";' + M]),
               eds(params=[PARAM_RPI, usint("0x0002", values="0,3,0"), 'Enum2 = 0,"Off",1,"On",3,"Test";'])),
    "EDS320": (eds(params=[PARAM_RPI, usint(size=2, mark=M)]), eds(params=[PARAM_RPI, usint(size=1)])),
    "EDS321": (eds(params=[PARAM_RPI, usint("0x0000", mark=M), 'Enum2 = 0,"Off",1,"On";']),
               eds(params=[PARAM_RPI, usint("0x0002"), 'Enum2 = 0,"Off",1,"On";'])),
    "EDS322": (eds(assembly=['Assem100 = "In","",4,0x0002,,,32,Param1;' + M]),
               eds(assembly=['Assem100 = "In","",4,0x0001,,,32,Param1;'])),
    "EDS323": (eds(assembly=['Assem100 = "In","",4,,,,32,Param1,,;' + M]),
               eds(assembly=['Assem100 = "In","",5,,,,32,Param1,8,;'])),
    "EDS324": (eds(assembly=['Assem100 = "In","",5,,,,32,Param1;' + M]), eds()),
    "EDS325": (eds(assembly=[ASSEM_IN, 'Assem101 = "Pad","",,,,,4,;' + M]),
               eds(assembly=[ASSEM_IN, 'Assem101 = "Pad","",,,,,8,;'])),
    "EDS326": (eds(assembly=[ASSEM_IN, 'Assem101 = "Outer","",4,,,,,Assem100;' + M]),
               eds(assembly=[ASSEM_IN, 'Assem101 = "Outer","",4,,,,,Param1;'])),
    "EDS327": (eds(assembly=['Assem100 = "In","",8,,,,32,Param1,32,Assem100;' + M]),
               eds(assembly=[ASSEM_IN, 'Assem101 = "Outer","",4,,,,32,Assem100;'])),
    "EDS328": (eds(connections=[connection(mark=M).replace("24 64 2C 64", "25 64 00 2C 64")]),
               eds(connections=[connection().replace("24 64 2C 64", "25 00 64 00 2C 64")])),
    "EDS329": (eds(assembly=[ASSEM_IN, 'Assem101 = "Rack","",4,,,,16,InputSlotMask0,16,InputSlotMask1;' + M]),
               eds(assembly=[ASSEM_IN, 'Assem101 = "Rack","",4,,,,16,InputSlotMask0,16,OutputSlotMask1;'])),
    "EDS330": (eds(assembly=[ASSEM_IN, 'Assem101 = "Rack","",4,,,,,InputSlotMask1;' + M]),
               eds(assembly=[ASSEM_IN, 'Assem101 = "Rack","",4,,,,32,InputSlotMask1;'])),
    "EDS331": (eds(assembly=[ASSEM_IN, 'ProxyAssem1 = "Module data","",4,,,,32,Module;' + M]),
               eds(assembly=[ASSEM_IN, 'ProxyAssem1 = "Module data","",4,,,,32,Param1;'])),
    "EDS332": (eds(ports=['Port1 = TCP, "A", "20 F5 24 01", 2;', 'Port2 = TCP, "B", "20 F5 24 02", 2;' + M]),
               eds(ports=['Port1 = TCP, "A", "20 F5 24 01", 2;', 'Port2 = TCP, "B", "20 F5 24 02", 3;'])),
    "EDS333": (eds(ports=['Port1 = Ethernet, "A", "20 F5 24 01", 2;' + M]),
               eds(ports=['Port1 = 65535_Ethernet, "A", "20 F5 24 01", 2;'])),
    "EDS334": (eds(modular=["DefineSlotsInRack = 4;", "Width = 1;", "Rack1 = 65535,12,1,1,1,,,,1,4;" + M]),
               eds(modular=["DefineSlotsInRack = 4;", "Width = 1;", "Rack1 = 65535,12,1,1,1,,,,1,3;"])),
    "EDS335": (eds(modular=["Width = 0;" + M, "Rack1 = 65535,12,1,1,1,,,,1;"]),
               eds(modular=["Width = 1;", "Rack1 = 65535,12,1,1,1,,,,1;"])),
    "EDS336": (eds(modular=["Width = 1;", "Rack1 = 65535,12,1,1,1,,,,0;", 'Query = "20 04 24 07 30 03",3,2,"FF";' + M]),
               eds(modular=["Width = 1;", "Rack1 = 65535,12,1,1,1,,,,0;", 'Query = "20 04 24 07 30 03",14,2,"FF";'])),
    "EDS337": (eds(connections=[connection(parameters="0x44640505", mark=M)]), eds()),
    "EDS338": (eds(param_class=["MaxInst = 1;", "Descriptor = 0x0010;" + M, "CfgAssembly = 0;"]),
               eds(param_class=["MaxInst = 1;", "Descriptor = 0x000E;", "CfgAssembly = 0;"])),
    "EDS339": (eds(params=[PARAM_RPI, usint("0x0002"), 'Enum2 = 0,"Off",1;' + M]),
               eds(params=[PARAM_RPI, usint("0x0002"), 'Enum2 = 0,"Off",1,"On",;'])),
    "EDS340": (eds(assembly=['Assem100 = "In","",6,,,,32,Param1,16;' + M]),
               eds(assembly=['Assem100 = "In","",6,,,,32,Param1,16,;'])),
    "EDS341": (eds(assembly=['Assem100 = "In","01 00 20 04 24 64 30 03",4,,,,32,Param1;' + M]),
               eds(assembly=['Assem100 = "In","20 04 24 64 30 03",4,,,,32,Param1;'])),
    "EDS342": (eds(params=[PARAM_RPI.replace("0,,,", '0,6,"20 0F 24 02 30 01",') + M]),
               eds(params=[PARAM_RPI.replace("0,,,", '0,6,"20 0F 24 01 30 01",')])),
    "EDS343": (eds(assembly=['Assem100 = "In","20 04 24 65 30 03",4,,,,32,Param1;' + M]),
               eds(assembly=['Assem100 = "In","20 04 25 00 64 00 30 03",4,,,,32,Param1;'])),
    "EDS344": (eds(params=[PARAM_RPI.replace("0,,,", "0,6,,") + M]), eds(params=[PARAM_RPI.replace("0,,,", '0,,"",')])),
    "EDS345": (eds(ports=['Port1 = TCP, "A", "20 F5 24 01", 2;', 'Port2 = 1234_Chassis, "B", "20 9A 24 01", 1;' + M]),
               eds(ports=['Port1 = TCP, "A", "20 F5 24 01", 2;', 'Port2 = 65535_Chassis, "B", "20 9A 24 01", 1;'])),
    "EDS346": (eds(ports=['Port1 = TCP, "A", "20 F5 24 01", 1;' + M]),
               eds(ports=['Port1 = TCP, "A", "20 F5 24 01", 2;'])),
    "EDS347": (eds(modular=["Width = 1;", "Rack1 = 65535,12,1,1,1,,,,1;", "Rack2 = 65535,12,1,1,1,,,,2;" + M]),
               eds(modular=["Width = 1;", "Rack1 = 65535,12,1,1,1,,,,1;", "Rack2 = 65535,12,2,1,1,,,,2;"])),
    "EDS349": (eds(assembly=[ASSEM_IN, 'Assem101 = "Path","",4,,,,32,"20 04 25 64 00 30 03";' + M]),
               eds(assembly=[ASSEM_IN, 'Assem101 = "Path","",4,,,,32,"20 04 25 00 64 00 30 03";'])),
    "EDS348": (eds(modular=["Width = 1;", "Rack1 = 65535,12,1,1,1,,,,1;", 'Query = "20 04 24 07 30 03",1,2,"FF";' + M]),
               eds(modular=["Width = 1;", "Rack1 = 65535,12,1,1,1,,,,0;", 'Query = "20 04 24 07 30 03",1,2,"FF";'])),
}

OWN_CODES = sorted(code for code in load_rules().rules if code.startswith("EDS3"))


def test_every_rule_has_a_case():
    assert sorted(CASES) == OWN_CODES


@pytest.mark.parametrize("code", sorted(CASES))
def test_rule_triggers_on_the_marked_line(code):
    bad, _ = CASES[code]
    assert found(bad, code) == [marked_line(bad)]


@pytest.mark.parametrize("code", sorted(CASES))
def test_rule_quiet_on_the_good_variant(code):
    _, good = CASES[code]
    assert found(good, code) == []


def test_undefined_path_parameter_and_slot_display_rule():
    text = eds(connections=[connection().replace("2C 64", "2C [Param7]") + M],
               modular=["DefineSlotsInRack = 4;", "SlotDisplayRule = Param8;"])
    _, diagnostics = edsconv.analyse(edsconv.parse(text))
    messages = [d.message for d in diagnostics if d.code == "EDS301"]
    assert any("[Param7]" in m for m in messages) and any("Param8" in m for m in messages)


def test_undefined_references_cite_the_clause_of_their_field():
    text = eds(assembly=['Assem100 = "In","",4,,,,32,Param9;'],
               connections=[connection(rpi="Param8").replace("2C 64", "2C [Param7]")],
               modular=["DefineSlotsInRack = 4;", "SlotDisplayRule = Param6;"])
    _, diagnostics = edsconv.analyse(edsconv.parse(text))
    cited = {d.message.split(",")[0][-30:]: d.clause for d in diagnostics if d.code == "EDS301"}
    assert sorted(cited.values()) == ["C.4.1.4.8", "C.4.1.4.9.13", "C.4.1.4.9.4", "C.4.1.5.2.2"], cited


def test_wrong_parameter_types_cite_the_clause_of_their_field():
    real = 'Param3 = 0,,,0x0000,0xCA,4,"Value","","",,,0.0;'
    text = eds(params=[PARAM_RPI, usint(), real],
               connections=[connection(rpi="Param2", size="Param1").replace("2C 64", "2C [Param3]")])
    _, diagnostics = edsconv.analyse(edsconv.parse(text))
    assert sorted(d.clause for d in diagnostics if d.code == "EDS302") == ["C.4.1.4.9.13", "C.4.1.4.9.4",
                                                                           "C.4.1.4.9.5"]


def test_a_group_may_list_a_parameter_instance_without_a_paramn():
    # C.4.1.4.6: not every Parameter object instance needs a ParamN entry; a GroupN lists instances
    assert found(eds(groups=['Group1 = "Setup", 2, 1, 9;']), "EDS301") == []


@pytest.mark.parametrize("path", [
    "01 SLOT_MINUS_ONE 20 04 24 03 2C 04 2C 02",         # Figure C.15: a port segment, then 8-bit values
    "12 05 31 2E 32 2E 33 00 20 04 25 00 64 00 2C 64",   # an extended port segment with its pad, then padded
    "34 04 FF FF 0C 00 01 00 01 01 20 04 24 64 2C 64",   # an electronic key first
    "20 04 24 64 2C [Param1]", "20 04 25 00 [Param1] 2C 64", "20 04 24 64 2C 64 80 01 00 00",
])
def test_padded_connection_paths(path):
    assert found(eds(connections=[connection().replace("20 04 24 64 2C 64", path)]), "EDS328") == []


@pytest.mark.parametrize("path", ["01 00 20 04 25 64 00 2C 64", "20 04 24 64 2D 64 00", "20 04 25 [Param1] 2C 64"])
def test_packed_connection_paths(path):
    text = eds(connections=[connection(mark=M).replace("20 04 24 64 2C 64", path)])
    assert found(text, "EDS328") == [marked_line(text)]


def test_assembly_paths_with_values_in_place_of_bytes_are_logical():
    # Figure C.15 writes SLOT for the instance; a member path may hold data segments
    text = eds(assembly=[ASSEM_IN, 'ProxyAssem1 = "input format","20 7D 24 SLOT 30 0A",,,,,,ModuleMemberList;',
                         'Assem101 = "Value","",2,0x0001,,,16,"80 01 34 12";'])
    assert found(text, "EDS341") == []
    bad = eds(assembly=[ASSEM_IN, 'Assem101 = "Value","",2,,,,16,"20 04 24 64 62 41 42";' + M])
    assert found(bad, "EDS341") == [marked_line(bad)]


def test_safety_connection_may_leave_size_and_format_empty():
    # format 5 (CIP Safety in later editions): EDS337 says so, EDS311 stays quiet
    text = eds(connections=[connection(parameters="0x44645505", size="").replace("Assem100,", ",", 1)])
    assert found(text, "EDS311") == [] and found(text, "EDS337")


@pytest.mark.parametrize("members", ["16,ModuleMemberList", "ModuleMemberList,Param1"])
def test_lint_reports_a_module_member_list_beside_a_field_of_its_pair(members):
    # EDS406 is the merge's rule; lint reports it in the adapter's file alone
    bad = eds(assembly=[ASSEM_IN, f'ProxyAssem1 = "Module data",,,,,,{members};' + M])
    assert found(bad, "EDS406") == [marked_line(bad)]
    good = eds(assembly=[ASSEM_IN, 'ProxyAssem1 = "Module data",,,,,,,ModuleMemberList;'])
    assert found(good, "EDS406") == []


def test_module_member_list_in_a_reserved_field_is_one_fault_one_code():
    # Figure C.15 prints ModuleMemberList at field 6, a reserved field: EDS406, not EDS210 as well
    text = eds(assembly=[ASSEM_IN, 'ProxyAssem1 = "Module data",,,,,ModuleMemberList;' + M])
    assert found(text, "EDS406") == [marked_line(text)] and found(text, "EDS210") == []


def test_legal_slots_of_another_chassis_are_not_bounded_by_this_one():
    # Rack1 names product 2 (this file is product 1): its slots are that chassis'
    text = eds(modular=["DefineSlotsInRack = 4;", "Width = 1;", "Rack1 = 65535,12,2,1,1,,,,7,8;"])
    assert found(text, "EDS334") == []


def test_scaling_multiplier_and_base_may_be_0():
    # Figure C.5 divides only by the divisor; Figure C.11 sets the scaling bit with 0 in every field
    assert found(eds(params=[PARAM_RPI, usint("0x0004", scaling=",0,1,0,0")]), "EDS319") == []


def test_figure_c11_scaling_is_a_warning_naming_figure_and_formula():
    # Figure C.11 sets the scaling bit with 0 in every scaling field: not EDS319's error (issue 20 item 10)
    text = eds(params=[PARAM_RPI, usint("0x0004", values="0,4,0", scaling=",0,0,0,0")])
    assert found(text, "EDS319") == []
    (warning,) = [d for d in edsconv.analyse(edsconv.parse(text))[1] if d.code == "EDS350"]
    assert "Figure C.11" in warning.message and "Figure C.5" in warning.message
    assert found(eds(params=[PARAM_RPI, usint("0x0004", scaling=",0,0,1,0")]), "EDS319") != []


REAL_PARAM = 'Param3 = 0,,,0x0000,0xCA,4,"Value","","",{minimum},{maximum},{default};'


@pytest.mark.parametrize("default", ["QUIET-NAN", "SIGNAL-NAN", "INFINITY", "+INFINITY", "-INFINITY"])
def test_real_reserved_words_are_no_default_out_of_order(default):
    text = eds(params=[PARAM_RPI, REAL_PARAM.format(minimum="", maximum="", default=default)])
    assert found(text, "EDS315") == []


def test_an_infinite_default_beyond_a_stated_maximum_is_out_of_order():
    text = eds(params=[PARAM_RPI, REAL_PARAM.format(minimum="0.0", maximum="100.0", default="INFINITY") + M])
    assert found(text, "EDS315") == [marked_line(text)]


def test_checks_do_not_raise_on_odd_values():
    text = eds(params=[PARAM_RPI, "Param2 = 0,,,Module,Module,Module,Module,,,Module,Module,Module;",
                       'ProxyParam3 = 0,,,0x0000,2,Module,"x","","",Module,Module,Module;',
                       "ProxyParamSizeAdder3 = 4,4,4;", "ProxyParamSizeAdder9 = 4,4,4;" + M],
               groups=['Group1 = "G", x, 1;'],
               assembly=['Assem100 = "In",Module,x,y,,,z,Param1,,"";', 'ProxyAssem1 = Module,Module,Module,,,,'
                         'ModuleMemberList;'],
               connections=['Connection1 = x, y, Assem100, Param1, Param1;', 'ProxyConnect1 = Module, Module;'],
               ports=["Port1 = ;"], modular=["Width = x;", "Rack1 = ;", "Query = ;"])
    assert found(text, "EDS303") == [marked_line(text)]


def test_example_adapter_is_clean():
    _, diagnostics = edsconv.analyse(edsconv.load(REPO / "corpus" / "examples" / "io_adapter.eds"))
    assert [d.format() for d in diagnostics if d.code in OWN_CODES] == []


#: Per-code counts of EDS3xx over the shared real corpus. Errors, each a defect of its file:
#: EDS315 x4 (EnIP-QuinLED PentaPlus: BOOL Param10/14/15/16 with min 0, max 0, default 1);
#: EDS324 x20 (OpENer-based files and the eds_pie demo write Member Size in bytes, not bits;
#: Hilscher EIS_V5 demo Assem100/101 members add up to 48/80 bits for an 8-byte Size).
#: Warnings: EDS312 (FusionCore O=>T size 72 for a 40-byte Assem150), EDS314/EDS322 (descriptor
#: bits the 2003 text reserves, set by certified Murrelektronik files: later editions assign them),
#: EDS317 (min/max on bit strings), EDS318 (Decimal Precision on WORD/BOOL), EDS337 (CIP Safety
#: format 5 in the MVK ME FDI6/FDO2 safety module).
#: EDS343 (AssemN numbered apart from the instance its path addresses: the EZ-EDS files of the Schneider TM251
#: and the Mettler Toledo M800, and the eds_pie demo), EDS346 (TCP port numbered 1: six ESP32P4 OpENer files and
#: the M800, EZ-EDS 3.38 and 3.27).
#: Information: EDS321 (EnumN with descriptor bit 1 clear), EDS326 (nested assemblies, allowed by the spec).
REAL_COUNTS = {"EDS312": 1, "EDS314": 86, "EDS315": 4, "EDS317": 193, "EDS318": 21, "EDS321": 1861,
               "EDS322": 2, "EDS324": 20, "EDS326": 200, "EDS337": 4, "EDS343": 6, "EDS346": 7}


@needs_real_corpus
def test_real_corpus_counts():
    counts = collections.Counter()
    for path in sorted(SHARED_REAL.glob("*")):
        if path.suffix.lower() != ".eds":
            continue
        _, diagnostics = edsconv.analyse(edsconv.load(path))
        counts.update(d.code for d in diagnostics if d.code in OWN_CODES)
    assert dict(counts) == REAL_COUNTS


def test_enum_ranges_find_each_enum_once_not_by_a_search_per_parameter(monkeypatch: pytest.MonkeyPatch) -> None:
    """EDS351 looked up EnumN by a search of [Params] per parameter: quadratic (10,000 dense parameters took
    5 s of a 7 s check). Counting the searches catches that without a timing."""
    from edsconv.eds.syntax import Section

    params = [PARAM_RPI] + [f'Param{n} = 0,,,0x0002,0xC6,1,"P","","",0,2,0;' for n in range(2, 402)]
    enums = [f'Enum{n} = 0,"Off",1,"On",3,"Test";' for n in range(2, 402)]
    searches = collections.Counter()
    original = Section.entry

    def counted(self: Section, keyword: str):
        searches[self.name] += 1
        return original(self, keyword)

    monkeypatch.setattr(Section, "entry", counted)
    device, diagnostics = edsconv.analyse(edsconv.parse(eds(params=params + enums)))
    assert sum(d.code == "EDS351" for d in diagnostics) == 400  # 3 is outside 0..2 in each
    assert searches["Params"] <= 10
