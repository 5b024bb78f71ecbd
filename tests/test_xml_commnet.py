"""The EtherNet/IP communication network profile: EDS -> model -> XML -> model keeps connections and ports."""

from __future__ import annotations

import functools
from pathlib import Path

import pytest
from lxml import etree

import edsconv
from conftest import REAL_EDS, REPO, needs_real_corpus
from edsconv.model import MODULE, Connection, Device, Port, Reference
from edsconv.model.values import PathItem
from edsconv.xml.commnet import commnet_profile, read_commnet_profile
from edsconv.xml.common import EDSCONV, Header, serialise

CORPUS = sorted([REPO / "corpus" / "examples" / "io_adapter.eds", *(REPO / "corpus" / "spec").glob("*.eds"),
                 *(REPO / "corpus" / "modular").glob("*.eds")])
EDSCONV_PREFIX = {"e": EDSCONV[1:-1]}


def profile(device: Device) -> bytes:
    """The validated network profile of ``device`` (serialise raises when it does not validate)."""
    return serialise(commnet_profile(device, Header.derive(device)), "ethernetip-commnet")


def read_back(data: bytes) -> tuple[Device, list]:
    device = Device()
    diagnostics = read_commnet_profile(etree.fromstring(data), device)
    return device, diagnostics


def assert_round_trip(device: Device) -> etree._Element:
    data = profile(device)
    again, diagnostics = read_back(data)
    assert diagnostics == []
    assert again.connections == device.connections
    assert list(again.connections) == list(device.connections)
    assert again.ports == device.ports
    return etree.fromstring(data)


@functools.cache
def built(path: Path) -> Device:
    return edsconv.build(edsconv.load(path))


@pytest.mark.parametrize("path", CORPUS, ids=lambda p: p.name)
def test_corpus_round_trip(path):
    assert_round_trip(built(path))


@needs_real_corpus
def test_real_corpus_round_trip():
    assert len(REAL_EDS) >= 50
    failures = []
    for path in REAL_EDS:
        try:
            assert_round_trip(built(path))
        except Exception as error:  # collect every file, report them together
            failures.append(f"{path.name}: {type(error).__name__}: {str(error)[:300]}")
    assert not failures, "\n".join(failures)


# --- the example adapter ---------------------------------------------------------------------

@pytest.fixture(scope="module")
def io_adapter() -> etree._Element:
    return assert_round_trip(built(REPO / "corpus" / "examples" / "io_adapter.eds"))


def test_io_adapter_connection1(io_adapter):
    (connection,) = io_adapter.xpath("//ConnectionDescriptions/Connection[@id='Connection1']")
    assert [(child.tag, child.text) for child in connection] == [
        ("Trigger_Transport", "04010002"),
        ("Connection_Parameters", "44640405"),
        ("O-T_RPI", "Param1"), ("O-T_Size", "2"), ("O-T_Format", "Assem150"),
        ("T-O_RPI", "Param1"), ("T-O_Size", "2"), ("T-O_Format", "Assem100"),
        # config part 1 is empty: no elements
        ("Config2_Size", "2"), ("Config2_Format", "Assem151"),
        ("Name_String", "Exclusive Owner"),
        ("Help_String", None),
        ("Path", "20 04 24 97 2C 96 2C 64"),
    ]


def test_io_adapter_reads_back_typed_values(io_adapter):
    device, _ = read_back(etree.tostring(io_adapter))
    connection = device.connections["Connection1"]
    assert connection.trigger_transport == 0x04010002
    assert connection.parameters == 0x44640405
    assert connection.o_to_t.rpi == Reference("Param1", "Param", 1)
    assert connection.o_to_t.format == Reference("Assem150", "Assem", 150)
    assert connection.config1.size is None and connection.config2.size == 2
    assert connection.help == ""
    assert connection.path[:2] == (PathItem(byte=0x20), PathItem(byte=0x04))
    assert device.ports == [Port(1, "TCP", "EtherNet/IP Port", tuple(PathItem(byte=b) for b in (0x20, 0xF5, 0x24, 1)),
                                 2)]


def test_io_adapter_port_and_header(io_adapter):
    (port,) = io_adapter.xpath("//TransportLayers/Ports/Port")
    assert port.get("id") == "Port1"
    assert [(child.tag, child.text) for child in port] == [
        ("PortTypeName", "TCP"), ("PortName", "EtherNet/IP Port"), ("PortObject", "20 F5 24 01"),
        ("PortNumber", "2"), ("PortSpecific", None)]
    header = io_adapter.find("ProfileHeader")
    assert header.findtext("ProfileIdentification") == "65535-12-1001-COMM"
    assert header.findtext("IASInterfaceType") == "CSI"
    body = io_adapter.find("ProfileBody")
    assert body.get("Revision") == "1.1" and body.get("CreateDate") == "2026-11-22"


def test_io_adapter_states_no_service_or_attribute_the_eds_does_not(io_adapter):
    """An EtherNet/IP device's EDS says nothing about the services of its Connection Manager or the
    attributes of its EtherNet/IP objects: the profile has no SupportedService, no Access_Rule and
    none of the objects, only what the schema requires (ConnectionManager, MessageRouter,
    TransportLayers) around the connections and ports."""
    assert io_adapter.xpath("//@SupportedService | //@Access_Rule") == []
    body = io_adapter.find("ProfileBody")
    assert [child.tag for child in body] == ["ApplicationLayers", "TransportLayers"]
    assert [child.tag for child in body.find("ApplicationLayers")] == ["ConnectionManager", "MessageRouter"]
    assert [child.tag for child in body.find("ApplicationLayers/ConnectionManager")] == ["ConnectionDescriptions"]
    assert len(body.find("ApplicationLayers/MessageRouter")) == 0
    assert [child.tag for child in body.find("TransportLayers")] == ["Ports"]


# --- what the schema's types cannot hold -----------------------------------------------------

EDGE = """\
[File]
        DescText = "edge"; CreateDate = 01-02-2020; CreateTime = 10:00:00; Revision = 2.11;
[Device]
        VendCode = 65535; VendName = "V"; ProdType = 12; ProdTypeStr = "T"; ProdCode = 7;
        MajRev = 1; MinRev = 1; ProdName = "Edge";
[Device Classification]
        Class1 = EtherNetIP;
[Params]
        Param1 = 0,,,0x0000,0xC8,4,"RPI","","",0,100,10,,,,,,,,,;
[Connection Manager]
        ProxyConnect1 = 0x04010002, 0x44244401, 2, Module, , , Param1:3, AssemExa5, , , , , "Same", "",
                        "01 SLOT_MINUS_ONE 20 04 24 [Param1] 2C ProxyParam1";
        Connection1 = 0xFFFFFFFF, 0x44640405, , , Assem1, , , , , , , , "Same", "tab\\there \\x01 ctrl", "";
        Connection2 = 0x01010002, 0x44640305, , , , , , , , , , , "", ;
        Connection3 = 0x01010002, 0x44640305, , , , , , , , , , , , "", "20 04";
        Connection100000 = 0x01010002, 0x44640305, , , , , , , , , , , "Far", "", "20 04";
[Port]
        Port1 = TCP, "EtherNet/IP", "20 F5 24 01", 2, , , "link", 0x10, , {1, "a"};
        Port2 = "TCP", "quoted type", , 3;
        Port1 = 65535_Chassis, "again", "", 1;
        Port4 = DeviceNet, , , ;
"""


@pytest.fixture(scope="module")
def edge() -> tuple[Device, etree._Element]:
    device = edsconv.build(edsconv.parse(EDGE))
    return device, assert_round_trip(device)


def extensions(element: etree._Element) -> list[tuple[str, dict, str | None]]:
    return [(etree.QName(e).localname, dict(e.attrib), e.text) for e in element.iterfind("e:*", EDSCONV_PREFIX)]


def test_edge_model_is_what_the_test_means(edge):
    device, _ = edge
    proxy = device.connections["ProxyConnect1"]
    assert proxy.o_to_t.size == MODULE and proxy.t_to_o.size.bit == 3 and proxy.t_to_o.format.family == "AssemExa"
    assert device.connections["Connection2"].help is None and device.connections["Connection3"].name is None
    assert [p.type_name for p in device.ports] == ["TCP", None, "65535_Chassis", "DeviceNet"]


def test_module_newer_references_and_duplicate_names(edge):
    _, root = edge
    (proxy,) = root.xpath("//ProxyConnect[@id='ProxyConnect1']")
    assert proxy.findtext("O-T_Size") is None  # Module: no element, a marker
    assert proxy.findtext("T-O_Size") == "Param1:3"
    assert proxy.find("T-O_Format") is None
    # [Param1] is local to the path, ProxyParam1 shared across the EDS (C.4.1.4.9.13): both kept
    assert proxy.findtext("Path") == "01 SLOT_MINUS_ONE 20 04 24 [Param1] 2C ProxyParam1"
    # Connection1 was written first and keeps "Same"; the key ConnectionName wants unique names
    assert proxy.findtext("Name_String") == "Same [ProxyConnect1]"
    assert extensions(proxy) == [("Module", {"field": "O-T_Size"}, None),
                                 ("Value", {"field": "T-O_Format"}, "AssemExa5"),
                                 ("Value", {"field": "Name_String", "type": "string"}, "Same")]


def test_empty_required_fields_and_unsafe_characters(edge):
    _, root = edge
    (first,) = root.xpath("//Connection[@id='Connection1']")
    assert first.findtext("Trigger_Transport") == "FFFFFFFF"  # reserved bits are a DWORD like any other
    assert first.findtext("Help_String") == "tab\there \ufffd ctrl"
    assert first.findtext("Path") in ("", None)
    assert extensions(first) == [("Value", {"field": "Help_String", "type": "string", "escaped": "true"},
                                  "tab\there \\u0001 ctrl")]
    (second,) = root.xpath("//Connection[@id='Connection2']")
    assert extensions(second) == [("Empty", {"field": "Help_String"}, None), ("Empty", {"field": "Path"}, None)]
    (third,) = root.xpath("//Connection[@id='Connection3']")
    assert third.findtext("Name_String") == "[Connection3]"
    assert extensions(third) == [("Empty", {"field": "Name_String"}, None)]


def test_entries_outside_the_schema_and_their_order(edge):
    _, root = edge
    descriptions = root.find(".//ConnectionDescriptions")
    assert [c.get("id") for c in descriptions.iterfind("e:Connection", EDSCONV_PREFIX)] == ["Connection100000"]
    assert descriptions.find("e:EntryOrder", EDSCONV_PREFIX).text == \
        "ProxyConnect1 Connection1 Connection2 Connection3 Connection100000"
    transport = root.find(".//TransportLayers")
    assert [p.get("id") for p in transport.iterfind("Ports/Port")] == ["Port1"]
    assert [(p.get("id"), p.get("position")) for p in transport.iterfind("e:Port", EDSCONV_PREFIX)] == [
        ("Port2", "1"), ("Port1", "2"), ("Port4", "3")]
    specific = transport.find("Ports/Port/PortSpecific")
    assert etree.tostring(specific[3], encoding="unicode").count("Field") == 4  # a brace group of two fields
    assert [etree.QName(e).localname for e in specific] == ["Field", "Field", "Empty", "Group"]


def test_hand_built_values_beyond_the_eds_reader():
    device = Device(ports=[Port(7, "65535_Chassis\x02", "n\\x", None, 1, ("\x7f\x00",))])
    device.connections["ProxyConnect9"] = Connection(
        "ProxyConnect9", "ProxyConnect", 9, trigger_transport=MODULE, parameters=None, name="Module", help=None,
        path=MODULE)
    device.connections["Connection1"] = Connection("Connection1", "Connection", 1, 0, 0, name="x", help="", path=())
    device.connections["Connection1"].o_to_t.rpi = 1 << 32  # beyond UDINT: kept in an extension
    root = assert_round_trip(device)
    proxy = root.find(".//ProxyConnect")
    assert proxy.findtext("Trigger_Transport") in ("", None) and proxy.findtext("Name_String") == "Module"
    assert [(name, attrs.get("field")) for name, attrs, _ in extensions(proxy)] == [
        ("Module", "Trigger_Transport"), ("Empty", "Help_String"), ("Module", "Path")]
    # a type name XML cannot carry keeps the port out of the Port element
    assert root.find(".//Ports") is None and root.find(".//e:Port", EDSCONV_PREFIX) is not None


def test_a_device_without_connections_gets_no_descriptions():
    device = Device(ports=[Port(2, "DeviceNet", "A", None, 2)])
    root = assert_round_trip(device)
    assert root.find(".//NetworkManagement") is None and root.find(".//EtherNetIPLinkObject") is None
    assert root.find(".//ConnectionDescriptions") is None


# --- reading profiles edsconv did not write --------------------------------------------------

def test_reads_the_complete_example_profile():
    from edsconv.xml.safe import read_xml

    device = Device()
    root = read_xml(REPO / "corpus" / "xml" / "ethernetip-commnet" / "valid-complete.xml").tree.getroot()
    assert read_commnet_profile(root, device) == []
    assert list(device.connections) == ["Connection1", "ProxyConnect1", "ProxiedConnect1"]
    first = device.connections["Connection1"]
    assert (first.trigger_transport, first.t_to_o.rpi, first.config1.size) == (0x01030002, 10000, 0)
    assert first.t_to_o.size == Reference("Param1", "Param", 1)
    assert device.connections["ProxyConnect1"].path == (PathItem(keyword="SLOT"),)
    assert [(p.number, p.type_name, p.port_number) for p in device.ports] == [(1, "TCP", 2), (2, "65535_Backplane", 1)]


def test_unreadable_values_are_diagnosed():
    device = edsconv.build(edsconv.parse(EDGE))
    root = etree.fromstring(profile(device))
    root.xpath("//Connection[@id='Connection1']/Path")[0].text = "20 XYZ"
    root.xpath("//ProxyConnect/e:Value[@field='T-O_Format']", namespaces=EDSCONV_PREFIX)[0].text = "Assem"
    again = Device()
    diagnostics = read_commnet_profile(root, again)
    assert [d.code for d in diagnostics] == ["EDS109", "EDS101"]
    assert "Connection1 Path" in diagnostics[0].message and "'XYZ'" in diagnostics[0].message
    assert again.connections["Connection1"].path is None


def test_a_repeated_connection_id_is_diagnosed_and_the_first_kept():
    """Connection ids are xsd:IDs, unique among the schema's elements; an edsconv:Connection (an
    extension element, written for keywords beyond the id pattern) is not checked by the schema."""
    device = edsconv.build(edsconv.parse(EDGE))
    root = etree.fromstring(profile(device))
    descriptions = root.find(".//ConnectionDescriptions")
    first = descriptions.find("Connection")
    again = etree.SubElement(descriptions, EDSCONV + "Connection", id=first.get("id"))
    etree.SubElement(again, EDSCONV + "Name_String").text = "second"
    read = Device()
    diagnostics = read_commnet_profile(root, read)
    assert [d.code for d in diagnostics] == ["EDS009"]
    assert f"id {first.get('id')!r} repeats" in diagnostics[0].message
    assert read.connections[first.get("id")] == device.connections[first.get("id")]
