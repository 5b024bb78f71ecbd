"""The entity checks (EDS301-EDS337): each rule on a tiny EDS that breaks it and
on a near-identical one that does not, the example adapter, and the real corpus."""

from __future__ import annotations

import collections

import pytest

import edsconv
from conftest import REPO, SHARED_REAL
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


def eds(params=(PARAM_RPI,), groups=(), assembly=(ASSEM_IN,), connections=DEFAULT_CONNECTIONS, ports=(), modular=()):
    """A minimal valid EtherNet/IP EDS with the given entries, one per line."""
    lines = [
        "[File]", 'DescText = "test";', "CreateDate = 01-02-2024;", "CreateTime = 10:00:00;", "Revision = 1.1;",
        "[Device]", "VendCode = 65535;", 'VendName = "Test";', "ProdType = 12;", 'ProdTypeStr = "Adapter";',
        "ProdCode = 1;", "MajRev = 1;", "MinRev = 1;", 'ProdName = "Test adapter";',
        "[Device Classification]", "Class1 = EtherNetIP;",
    ]
    for name, entries in (("Params", params), ("Groups", groups), ("Assembly", assembly),
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
    "EDS328": (eds(assembly=[ASSEM_IN, 'Assem101 = "Path","",4,,,,32,"20 04 25 64 00 30 03";' + M]),
               eds(assembly=[ASSEM_IN, 'Assem101 = "Path","",4,,,,32,"20 04 25 00 64 00 30 03";'])),
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


def test_safety_connection_may_leave_size_and_format_empty():
    # format 5 (CIP Safety in later editions): EDS337 says so, EDS311 stays quiet
    text = eds(connections=[connection(parameters="0x44645505", size="").replace("Assem100,", ",", 1)])
    assert found(text, "EDS311") == [] and found(text, "EDS337")


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
#: Information: EDS321 (EnumN with descriptor bit 1 clear), EDS326 (nested assemblies, allowed by the spec).
REAL_COUNTS = {"EDS312": 1, "EDS314": 86, "EDS315": 4, "EDS317": 193, "EDS318": 21, "EDS321": 1861,
               "EDS322": 2, "EDS324": 20, "EDS326": 200, "EDS337": 4}


@pytest.mark.real_corpus
@pytest.mark.skipif(not SHARED_REAL.is_dir(), reason="shared real EDS corpus not present")
def test_real_corpus_counts():
    counts = collections.Counter()
    for path in sorted(SHARED_REAL.glob("*")):
        if path.suffix.lower() != ".eds":
            continue
        _, diagnostics = edsconv.analyse(edsconv.load(path))
        counts.update(d.code for d in diagnostics if d.code in OWN_CODES)
    assert dict(counts) == REAL_COUNTS
