"""The device profile (xml_device): EDS -> model -> CIP_Device_Profile.xsd document -> model."""

from __future__ import annotations

import datetime

import pytest
from lxml import etree

import edsconv
from conftest import REAL_EDS, REPO, needs_real_corpus
from edsconv.model import MODULE, Device, Reference
from edsconv.model.values import PathItem, Revision
from edsconv.xml.common import EDSCONV, Header, serialise
from edsconv.xml.device_read import DEVICE_PROFILE_PARTS, equal_parts, read_device_profile
from edsconv.xml.device_write import device_profile
from edsconv.xml.safe import parse_xml

CORPUS = [REPO / "corpus" / "examples" / "io_adapter.eds", *sorted((REPO / "corpus" / "spec").glob("*.eds")),
          *sorted((REPO / "corpus" / "modular").glob("*.eds"))]


def round_trip(device: Device) -> tuple[Device, bytes, list]:
    """Write the profile (validated), read it back through the safe parser."""
    data = serialise(device_profile(device, Header.derive(device)), "cip-device")
    back = Device()
    diagnostics = read_device_profile(parse_xml(data).tree.getroot(), back)
    return back, data, diagnostics


def assert_round_trip(device: Device) -> bytes:
    back, data, diagnostics = round_trip(device)
    assert [d.format() for d in diagnostics] == []
    for part in DEVICE_PROFILE_PARTS + ("extra_entries", "other_sections"):
        assert getattr(back, part) == getattr(device, part), part
    assert back.comments == device.comments
    assert equal_parts(device, back) == []
    return data


def from_text(text: str) -> Device:
    return edsconv.build(edsconv.parse(text))


@pytest.mark.parametrize("path", CORPUS, ids=lambda p: p.name)
def test_corpus_round_trip(path):
    assert_round_trip(edsconv.build(edsconv.load(path)))


@needs_real_corpus
@pytest.mark.parametrize("path", REAL_EDS, ids=lambda p: p.name)
def test_real_round_trip(path):
    assert_round_trip(edsconv.build(edsconv.load(path)))


@pytest.fixture(scope="module")
def io_adapter():
    device = edsconv.build(edsconv.load(REPO / "corpus" / "examples" / "io_adapter.eds"))
    root = etree.fromstring(assert_round_trip(device))
    return device, root


def test_io_adapter_elements(io_adapter):
    _, root = io_adapter
    body = root.find("ProfileBody")
    assert body.get("DescText") == "edsconv example I/O adapter"
    assert (body.get("CreateDate"), body.get("CreateTime"), body.get("Revision")) == ("2026-11-22", "09:30:00", "1.1")
    assert root.findtext("ProfileHeader/ProfileIdentification") == "65535-12-1001-DEV"
    identity = body.find("DeviceIdentity/DeviceIdentity_InstanceAttributes")
    assert identity.findtext("VendCode") == "65535"
    assert identity.find("VendCode").get("Access_Rule") == "Get"
    assert identity.findtext("ProdRevision/MinRev") == "2"
    assert identity.findtext("DeviceClassification/Class[@id='Class1']/MainClass") == "EtherNetIP"
    param1 = body.find("ApplicationProcess/Parameter/Param[@id='Param1']")
    assert param1.findtext("DataType") == "200"  # 0xC8 UDINT, the USINT member of the union
    assert param1.findtext("ParamDescriptor") == "0000"
    assert [param1.findtext(t) for t in ("MinimumValue", "MaximumValue", "DefaultValue")] == \
        ["2000", "1000000", "10000"]
    assert param1.find("LinkPath") is None
    param2 = body.find("ApplicationProcess/Parameter/Param[@id='Param2']")
    assert param2.findtext("LinkPath") == "20 04 24 96 30 03"
    assert param2.findtext("ParamDescriptor") == "0010"
    enum = body.find("ApplicationProcess/Parameter/Param[@id='Param3']/Enum")
    assert [e.text for e in enum] == ["0", "Clear", "1", "Hold last state", "2", "Use fault value"]
    assert body.findtext("ApplicationProcess/Parameter/Param[@id='Param4']/MinimumValue") == "-40.0"
    members = body.findall("ApplicationProcess/Assembly/Assem[@id='Assem100']/AssemblyMember")
    assert [(m.findtext("MemberSize"), m.findtext("MemberReference")) for m in members] == \
        [("8", "Param2"), ("8", None)]
    group = body.find("ApplicationProcess/ParameterGroup/Group[@id='Group1']")
    assert [e.text for e in group] == ["Configuration", "2", "2", "3"]
    # what the schema has no place for: the [Assembly] Revision and the comments
    values = {v.get("path"): v for v in body.iter(EDSCONV + "Value")}
    assert values["assembly_revision"].get("kind") == "int" and values["assembly_revision"].text == "2"
    comments = body.findall(f"DeviceFunction/{EDSCONV}Comments/{EDSCONV}Comment")
    assert {"section": "Params", "keyword": "Param1", "field": "0"} in [dict(c.attrib) for c in comments]
    assert " reserved, shall equal 0" in [c.text for c in comments]


def test_io_adapter_read_back(io_adapter):
    device, root = io_adapter
    back = Device()
    read_device_profile(root, back)
    assert back.parameters["Param1"].data_type.name == "UDINT"
    assert back.parameters["Param3"].enum == {0: "Clear", 1: "Hold last state", 2: "Use fault value"}
    assert back.parameters["Param4"].minimum == -40.0
    member = back.assemblies["Assem100"].members[0]
    assert (member.size, member.reference) == (8, Reference("Param2", "Param", 2))
    assert member.reference.target is back.parameters["Param2"]
    assert back.file.create_date == datetime.date(2026, 11, 22) and back.file.revision == Revision(1, 1)
    assert back.assembly_revision == 2


EXTRAS = r"""
[File]
        DescText = "extras";
        CreateDate = 01-02-2020;
        CreateTime = 03:04:05;
        Revision = 2.11;                $ two-digit minor: beyond dt_EDS_Revision
[Device]
        VendCode = 65535; VendName = "V"; ProdType = 12; ProdTypeStr = "T"; ProdCode = 1;
        MajRev = 1; MinRev = 1; ProdName = "P";
        MaxMsgConnections = 6, "two" "parts", , {1, {L"x", 0x10}}, Keyword;
[Device Classification]
        Class1 = EtherNetIP;
        Class2 = Safety;
[ParamClass]
        MaxInst = 3; Descriptor = 0x0F; CfgAssembly = 0;
[Params]
        Param1 = 0, , , 0x0000, 0xD0, 1, "Text", "", "", 2, 10, "abc", , , , , , , , , ,
                 {1, {"deu", 0xD0, 4, "Text"}};
        Param2 = 0, 1, "20 01 [Param1] SLOT", 0x0000, 0xC6, 1, "p", "", "", 0, 255, 1;
        ProxyParam1 = 0, , , Module, Module, Module, "proxy", "", "", Module, Module, Module;
        ProxyParamSizeAdder1 = 1, 2, 3;
        ProxyEnum1 = 0, "zero";
        ProxiedParam1 = 0, , , 0x0000, 0xC7, 2, "proxied", "", "", 0, 9, 0;
        Param123456 = 0, , , 0x0000, 0xC6, 1, "high", "", "", 0, 1, 0;
[Groups]
        Group1 = "g", 2, 1, 2;
        Group1 = "duplicate", 0;
[Assembly]
        Revision = 3;
        Assem1 = "a", "20 04 24 01", 2, , , , 8, Param1:3, , , 8, "20 01", 8, 4294967295;
        ProxyAssem1 = Module, Module, Module, Module, , , ModuleMemberList;
[Modular]
        DefineSlotsInRack = 10;
        SlotDisplayRule = Param2;
        Width = 1;
[65535_Vendor]
        Thing = 1;
[Empty Section]
"""


def test_extras_round_trip():
    device = from_text(EXTRAS)
    assert device.extra_entries and device.other_sections and device.comments
    data = assert_round_trip(device)
    root = etree.fromstring(data)
    values = {v.get("path"): v for v in root.iter(EDSCONV + "Value")}
    # beyond the schema's types: each value kept with its model path
    assert {"file.revision", "param_class.max_instances", "assembly_revision", "classifications",
            "parameters.ProxyParam1.descriptor", "parameters.Param123456", "groups", "modular.width",
            "parameters.Param1.international_name"} <= set(values)
    assert values["parameters.ProxyParam1.descriptor"].get("kind") == "str"
    assert values["parameters.ProxyParam1.descriptor"].text == MODULE
    assert values["file.revision"].text == "2.11"
    assembly = root.find("ProfileBody/ApplicationProcess/Assembly")
    assert [m.findtext("MemberReference") for m in assembly.findall("Assem/AssemblyMember")] == \
        ["Param1:3", None, "20 01", "4294967295"]
    assert assembly.findtext("ProxyAssem/AssemblyMember/MemberReference") == "ModuleMemberList"
    param2 = root.find("ProfileBody/ApplicationProcess/Parameter/Param[@id='Param2']")
    assert param2.findtext("LinkPath") == "20 01 [Param1] SLOT"
    function = root.find("ProfileBody/DeviceFunction")
    entry = function.find(f"{EDSCONV}ExtraEntries[@section='Device']/{EDSCONV}Entry")
    assert entry.get("keyword") == "MaxMsgConnections"
    assert [f.get("kind") for f in entry] == ["scalar", "string", "empty", "group", "scalar"]
    assert [p.text for p in entry[1]] == ['"two"', '"parts"']
    assert [s.get("name") for s in function.findall(f"{EDSCONV}Section")] == ["65535_Vendor", "Empty Section"]


def test_extras_model_values():
    back, _, _ = round_trip(from_text(EXTRAS))
    assert back.parameters["Param2"].link_path == (PathItem(0x20), PathItem(0x01),
                                                  PathItem(reference="Param1", local=True), PathItem(keyword="SLOT"))
    assert back.parameters["ProxyParam1"].minimum == MODULE
    assert back.parameters["ProxyParam1"].size_adder == ("1", "2", "3")
    assert back.parameters["ProxyParam1"].enum == {0: "zero"}
    assert back.assemblies["ProxyAssem1"].module_member_list is True
    assert back.assemblies["Assem1"].members[0].reference == Reference("Param1", "Param", 1, bit=3)
    assert back.modular.slot_display_rule.target is back.parameters["Param2"]
    assert [g.name for g in back.groups] == ["g", "duplicate"]


def test_text_xml_cannot_carry():
    device = from_text('[File]\nDescText = "bell\\x07";\n[65535_V]\nX = "\\x01";\n$ comment \x0b here\n')
    assert "\x07" in device.file.description
    data = assert_round_trip(device)
    assert b'escaped="json"' in data


def test_reads_a_profile_written_elsewhere():
    device = Device()
    diagnostics = read_device_profile(
        parse_xml((REPO / "corpus" / "xml" / "cip-device" / "valid-complete.xml").read_bytes()).tree, device)
    assert diagnostics == []
    param = device.parameters["Param1"]
    assert (param.data_type_code, param.data_type.name, param.descriptor) == (0xC7, "UINT", 0x10)
    assert param.enum == {0: "Off", 10: "Normal"} and param.minimum == 0
    assert device.parameters["ProxyParam1"].size_adder == (0, 2, 0)
    assert device.identity.vendor_code == 65535 and device.param_class.descriptor == 0x0F
    assert device.modular.racks[0].legal_slots == (1, 2) and device.modular.query.id_size == 2
    assert [m.reference for m in device.assemblies["Assem100"].members] == \
        [Reference("Param1", "Param", 1), None, None]
    assert device.groups[0].members == [Reference("Param1", "Param", 1), Reference("Param1", "Param", 1)]


def test_unreadable_values_are_reported():
    data = serialise(device_profile(from_text(EXTRAS), Header.derive(from_text(EXTRAS))), "cip-device")
    root = etree.fromstring(data)
    root.find("ProfileBody/DeviceIdentity/DeviceIdentity_InstanceAttributes/VendCode").text = "many"
    next(v for v in root.iter(EDSCONV + "Value")).set("path", "parameters.Param999.minimum")
    device = Device()
    diagnostics = read_device_profile(root, device)
    assert [d.code for d in diagnostics] == ["XML201", "XML202"]
    assert device.identity.vendor_code is None


def test_commnet_handle():
    device = edsconv.build(edsconv.load(REPO / "corpus" / "examples" / "io_adapter.eds"))
    root = device_profile(device, Header.derive(device), commnet_handle=True)
    serialise(root, "cip-device")
    handle = root.find("ProfileBody/ExternalProfileHandle")
    assert [e.text for e in handle] == ["65535-12-1001-COMM", "1.1"]
