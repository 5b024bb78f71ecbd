"""The content beyond the 2003 text in the device profile: typed edsconv elements (issue 10 item 6).

Each typed element is checked on a file of corpus/cip: the profile holds it with the values the EDS
gives, and reading the profile back gives the same model (the entries as written and their typed view).
Profiles written before (opaque edsconv:Section / edsconv:ExtraEntries) still read.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

import edsconv
from conftest import REPO
from edsconv.eds.from_model import device_to_eds
from edsconv.model import Device
from edsconv.xml.common import EDSCONV, Header
from edsconv.xml.convert import profile_documents
from edsconv.xml.device_read import equal_parts, read_device_profile

CIP = REPO / "corpus" / "cip"
NS = {"e": EDSCONV.strip("{}")}
#: The typed view model.cip_build sets; reading a profile must give it back as building the EDS does.
TYPED = ("capacity", "object_classes", "tcpip_interface", "ethernet_link", "dlr", "ingress_egress", "devicenet",
         "extended_assemblies", "icon_contents", "additions")


def device_profile(path: Path) -> tuple[Device, etree._Element]:
    device = edsconv.build(edsconv.load(path))
    data = profile_documents(device, Header.derive(device, path.stem), path.stem)[0].data
    return device, etree.fromstring(data)


def read_back(root: etree._Element) -> Device:
    back = Device()
    assert read_device_profile(root, back) == []
    return back


def assert_same_model(device: Device, back: Device) -> None:
    assert equal_parts(device, back) == []
    for name in TYPED:
        assert getattr(back, name) == getattr(device, name), name


def test_capacity_is_typed():
    device, root = device_profile(CIP / "capacity_clean.eds")
    capacity = root.find("ProfileBody/DeviceFunction/e:Capacity", NS)
    assert capacity is not None and root.find(".//e:Section", NS) is None
    tspec = capacity.find("e:TSpec[@number='2']", NS)
    assert dict(tspec.attrib) == {"number": "2", "txRx": "Rx", "connSize": "400", "packetsPerSecond": "1200"}
    assert capacity.find("e:MaxIOConnections", NS).get("value") == "4"
    # .005 is the REAL 0.005; the EDS spelling is kept beside it
    overhead = capacity.find("e:ConnOverhead", NS)
    assert (overhead.get("value"), overhead.get("spelling")) == ("0.005", ".005")
    back = read_back(root)
    assert_same_model(device, back)
    assert back.capacity.traffic_specs[1].connection_size == 400


def test_object_classes_are_typed_with_their_services():
    device, root = device_profile(CIP / "network_objects_clean.eds")
    function = root.find("ProfileBody/DeviceFunction")
    tcpip = function.find("e:ObjectClass[@section='TCP/IP Interface Class']", NS)
    assert tcpip.get("classId") == "245"
    assert tcpip.find("e:Revision", NS).get("value") == "4"
    assert [a.text for a in tcpip.find("e:Class_Attributes", NS)] == ["1", "2", "3"]
    services = [dict(s.attrib) for s in tcpip.find("e:Instance_Services", NS)]
    assert services == [{"code": "14", "all": "true"}, {"code": "16", "attributes": "3 5 6"}]
    # Object_Class_Code is a UDINT that files write in hexadecimal: value and spelling
    code = tcpip.find("e:Object_Class_Code", NS)
    assert (code.get("value"), code.get("spelling")) == ("245", "0xF5")
    link = function.find("e:ObjectClass[@section='Ethernet Link Class']", NS)
    assert [(e.get("number"), e.get("value")) for e in link.findall("e:InterfaceLabel", NS)] == [("1", "P1"),
                                                                                               ("2", "P2")]
    # entries later editions add to 2003 sections stay in their section's ExtraEntries, typed
    manager = function.find("e:ExtraEntries[@section='Connection Manager']", NS)
    assert manager.find("e:PITNS", NS).get("value") == "Yes"
    back = read_back(root)
    assert_same_model(device, back)
    assert back.object_classes["TCP/IP Interface Class"].revision == 4


def test_identity_class_stands_in_device_manager():
    device, root = device_profile(CIP / "network_objects_clean.eds")
    identity = root.find("ProfileBody/DeviceManager/e:ObjectClass", NS)
    assert identity.get("section") == "Identity Class" and identity.get("classId") == "1"
    assert root.find("ProfileBody/DeviceFunction/e:ObjectClass[@section='Identity Class']", NS) is None
    back = read_back(root)
    assert [s.name for s in back.other_sections] == [s.name for s in device.other_sections]


def test_icon_contents_stands_in_device_identity():
    device, root = device_profile(CIP / "icon_clean.eds")
    icon = root.find("ProfileBody/DeviceIdentity/DeviceIdentity_InstanceAttributes/e:IconContents", NS)
    assert icon is not None and icon.get("value", "").startswith("AAABAAEAEBAC")
    back = read_back(root)
    assert_same_model(device, back)
    assert back.icon_contents == device.icon_contents is not None


def test_devicenet_io_info_and_enum_strings_are_typed():
    device, root = device_profile(CIP / "devicenet_io_info_clean.eds")
    function = root.find("ProfileBody/DeviceFunction")
    io_info = function.find("e:IOInfo", NS)
    default = io_info.find("e:Default", NS)
    assert default.get("value") == "1" and default.get("spelling") is None  # 0x0001: the WORD spelling
    data = io_info.find("e:Input[@number='1']", NS)
    assert (data.get("size"), data.get("sizeInBits"), data.get("connectionMask"), data.get("name"),
            data.get("path")) == ("2", "12", "5", "Inputs and status", "20 04 24 64 30 03")
    strings = function.find("e:EnumPar/e:Param[@number='1']", NS)
    assert [s.text for s in strings.findall("e:EnumString", NS)] == ["Off", "3 ms", "10 ms"]
    assert_same_model(device, read_back(root))


def test_extended_assembly_members_are_typed():
    device, root = device_profile(CIP / "assembly_exa_clean.eds")
    assembly = root.find("ProfileBody/DeviceFunction/e:ExtraEntries[@section='Assembly']/e:AssemExa", NS)
    assert (assembly.get("number"), assembly.get("name"), assembly.get("size")) == (
        "101", "Digital inputs and port data", "Param2")
    members = [(child.tag.split("}")[1], child.text) for child in assembly]
    assert members[:4] == [("MemberSize", "16"), ("MemberReference", "Assem100"), ("MemberSize", "8"),
                           ("MemberReference", "Param4")]
    back = read_back(root)
    assert_same_model(device, back)
    assert back.extended_assemblies["AssemExa101"].members[0].reference.keyword == "Assem100"


@pytest.mark.parametrize("name", ["safety_clean.eds", "security_vendor_clean.eds", "network_objects_clean.eds"])
def test_entries_come_back_as_written(name: str):
    """Spellings (hexadecimal, strings, empty fields) come back exactly, not only their values."""
    device, root = device_profile(CIP / name)
    back = read_back(root)
    assert back.extra_entries == device.extra_entries
    assert back.other_sections == device.other_sections
    assert_same_model(device, back)


def test_vendor_section_stays_opaque():
    device, root = device_profile(REPO / "corpus" / "allowed" / "C.4.1.2.2.11_vendor_keywords.eds")
    section = root.find("ProfileBody/DeviceFunction/e:Section[@name='65535_Probe Data']", NS)
    assert section is not None and section.find("e:Entry", NS) is not None
    assert read_back(root).other_sections == device.other_sections


def test_an_old_style_profile_still_reads():
    """A profile written before the typed elements: [Capacity] and [Device] IconContents as opaque entries."""
    device, root = device_profile(CIP / "capacity_clean.eds")
    function = root.find("ProfileBody/DeviceFunction")
    typed = function.find("e:Capacity", NS)
    old = etree.Element(EDSCONV + "Section", name="Capacity")
    for entry in device.other_sections[0].entries:
        element = etree.SubElement(old, EDSCONV + "Entry", keyword=entry.keyword)
        for value in entry.values:
            etree.SubElement(element, EDSCONV + "Field", kind="scalar").text = value.raw
    typed.addprevious(old)
    function.remove(typed)
    assert device.other_sections[0].name == "Capacity"
    back = read_back(root)
    assert_same_model(device, back)
    assert back.capacity.max_io_connections == 4


def test_a_typed_element_of_no_entry_is_reported():
    device, root = device_profile(CIP / "capacity_clean.eds")
    etree.SubElement(root.find("ProfileBody/DeviceFunction/e:Capacity", NS), EDSCONV + "NoSuchEntry", value="1")
    problems = read_device_profile(root, Device())
    assert [p.code for p in problems] == ["XML202"]
    assert "NoSuchEntry" in problems[0].message


@pytest.mark.parametrize("spelling", ["", "a;b", "1 2"])
def test_a_spelling_that_is_no_eds_scalar_is_reported_not_written(spelling: str):
    # found by fuzzing xml2eds: an empty spelling became an empty field the typed model could not read
    device, root = device_profile(CIP / "capacity_clean.eds")
    root.find("ProfileBody/DeviceFunction/e:Capacity/e:ConnOverhead", NS).set("spelling", spelling)
    back = Device()
    problems = read_device_profile(root, back)
    assert [p.code for p in problems] == ["XML202"]
    assert back.capacity is None or back.capacity.connection_overhead is None
    edsconv.analyse(device_to_eds(back))  # and what was read converts without a fault



def test_a_repeated_field_of_empty_text_is_reported():
    # found by fuzzing xml2eds: a service element of no code read as an empty field
    device, root = device_profile(CIP / "network_objects_clean.eds")
    service = root.find(".//e:ObjectClass[@section='TCP/IP Interface Class']/e:Instance_Services/e:Service", NS)
    service.tag = EDSCONV + "Other"
    service.attrib.clear()
    back = Device()
    assert [p.code for p in read_device_profile(root, back)] == ["XML202"]
    edsconv.analyse(device_to_eds(back))


@pytest.mark.parametrize("part", ["no quotes", '"open', '"a"b"'])
def test_a_string_field_that_is_no_quoted_eds_string_is_reported(part: str):
    # found by fuzzing xml2eds: a string part without its quotes reached the typed model, which failed on it
    from edsconv.xml.codec import read_field

    field = etree.Element(EDSCONV + "Field", kind="string")
    etree.SubElement(field, EDSCONV + "Part").text = part
    with pytest.raises(ValueError, match="is not a quoted EDS string"):
        read_field(field)
    etree.SubElement(field, EDSCONV + "Part").text = '"fine"'
    field[0].text = 'L"also fine"'
    assert read_field(field).parts == ('L"also fine"', '"fine"')
