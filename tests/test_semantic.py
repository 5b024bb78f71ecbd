"""The typed semantic model: values by their data types, references resolved, nothing dropped."""

from __future__ import annotations

import datetime
import math

import pytest

import edsconv
from conftest import REPO
from edsconv.model import MODULE, Reference
from edsconv.model.values import PathItem, Revision

EXAMPLE = REPO / "corpus" / "examples" / "io_adapter.eds"


@pytest.fixture(scope="module")
def device():
    return edsconv.build(edsconv.load(EXAMPLE))


def build(text: str):
    return edsconv.build(edsconv.parse(text))


def codes(device) -> list[str]:
    return [d.code for d in device.diagnostics]


def test_file_and_identity(device):
    assert device.file.create_date == datetime.date(2026, 11, 22)
    assert device.file.mod_time == datetime.time(10, 15)
    assert device.file.revision == Revision(1, 1)
    assert device.file.home_url == "http://www.example.com/eds/io_adapter.eds"
    identity = device.identity
    assert (identity.vendor_code, identity.product_type, identity.product_code) == (65535, 12, 1001)
    assert (identity.major_revision, identity.minor_revision) == (1, 2)
    assert device.networks == ["EtherNetIP"] and device.is_ethernetip
    assert device.diagnostics == []


def test_parameters_are_typed_by_their_data_type(device):
    rpi = device.parameters["Param1"]
    assert rpi.data_type.name == "UDINT" and rpi.data_size == 4
    assert (rpi.minimum, rpi.maximum, rpi.default) == (2000, 1000000, 10000)
    temperature = device.parameters["Param4"]
    assert temperature.data_type.name == "REAL"
    assert (temperature.minimum, temperature.maximum, temperature.default) == (-40.0, 85.0, 70.0)
    assert temperature.scaling.decimal_precision == 1
    filter_time = device.parameters["Param2"]
    assert filter_time.link_path == tuple(PathItem(byte) for byte in (0x20, 0x04, 0x24, 0x96, 0x30, 0x03))
    assert filter_time.descriptor_flags() == ["Read only parameter"]
    assert device.parameters["Param3"].enum == {0: "Clear", 1: "Hold last state", 2: "Use fault value"}


def test_references_resolve_to_their_entries(device):
    connection = device.connections["Connection1"]
    assert connection.o_to_t.rpi == Reference("Param1", "Param", 1)
    assert connection.o_to_t.rpi.target is device.parameters["Param1"]
    assert connection.t_to_o.format.target is device.assemblies["Assem100"]
    member = device.assemblies["Assem100"].members[0]
    assert (member.size, member.reference.target) == (8, device.parameters["Param2"])
    assert device.assemblies["Assem100"].members[1].is_pad
    assert [m.keyword for m in device.groups[0].members] == ["Param2", "Param3"]


def test_connection_bits_decode_in_words(device):
    connection = device.connections["Connection1"]
    set_bits = {field.name: meaning for field, value, meaning in connection.trigger_transport_bits() if value}
    assert set_bits["class 1"] == "class 1: duplicate detect"
    assert set_bits["trigger cyclic"] == "trigger: cyclic"
    assert set_bits["exclusive-owner"] == "transport type: exclusive-owner"
    assert device.ports[0].type_name == "TCP" and device.ports[0].port_number == 2


def test_engineering_value_uses_the_precision_only_with_extended_scaling():
    text = """[Params]
    Param1 = 0,,,0x0004, 0xC7, 2, "a", "", "", 0, 1000, 0, 2, 1, 1, 0, ,,,, 1;
    Param2 = 0,,,0x0044, 0xC7, 2, "b", "", "", 0, 1000, 0, 2, 1, 1, 0, ,,,, 1;
    """
    parameters = build(text).parameters
    assert parameters["Param1"].engineering_value(5) == 10
    assert parameters["Param2"].engineering_value(5) == 1


def test_sections_and_keywords_the_2003_text_lacks_are_kept_as_written():
    device = build('[Device]\nVendCode = 1;\nIconContents = "abc" "def";\n'
                   '[Capacity]\nMaxMsgConnections = 6;\nTSpec1 = TxRx, 32, 100;\n')
    (extra,) = device.extra_entries["Device"]
    assert extra.keyword == "IconContents" and [v.text for v in extra.values] == ["abcdef"]
    (capacity,) = device.other_sections
    assert capacity.name == "Capacity"
    assert [(e.keyword, [v.raw for v in e.values]) for e in capacity.entries] == [
        ("MaxMsgConnections", ["6"]), ("TSpec1", ["TxRx", "32", "100"])]


def test_newer_references_parameter_bits_and_extended_assemblies():
    device = build("""[Params]
    Param10 = 0,,,0x0000, 0xD1, 1, "bits", "", "", , , 0;
    [Assembly]
    Assem1 = "a", , 1, , , , 1, Param10:0, 1, Param10:1, 6, ;
    AssemExa2 = "extended", , Param10, 0x0000, , , 8, Param10;
    [Connection Manager]
    Connection1 = 0x04010002, 0x44640405, , 1, Assem1, , 1, AssemExa2, , , , , "c", "", "20 04 24 01";
    """)
    bit = device.assemblies["Assem1"].members[1].reference
    assert (bit.keyword, bit.bit, bit.target) == ("Param10", 1, device.parameters["Param10"])
    newer = device.connections["Connection1"].t_to_o.format
    assert newer.family == "AssemExa" and newer.target.keyword == "AssemExa2"
    assert "EDS101" not in codes(device)


def test_notation_faults_become_diagnostics_on_the_field():
    device = build('[File]\nCreateDate = 13-11-2008;\nRevision = 2.11;\n[Device]\nMinRev = 02;\n'
                   '[Params]\nParam1 = 0,,,0x0000, 2, 2, "x", "", "", 0, 70000, 0;\n'
                   'Param2 = 0,,,0x0000, 0xEE, 2, "y", "", "", 0, 1, 0;\n')
    found = [(d.code, d.line) for d in device.diagnostics]
    assert ("EDS105", 2) in found          # month 13
    assert ("EDS115", 3) in found          # revision 2.11, read with a warning
    assert ("EDS103", 5) in found          # leading zero
    assert ("EDS112", 7) in found          # obsolete data type 2 = UINT ...
    assert ("EDS102", 7) in found          # ... whose maximum 70000 does not fit
    assert ("EDS113", 8) in found          # 0xEE is no data type
    assert device.file.create_date is None and device.file.revision == Revision(2, 11)
    assert device.parameters["Param1"].data_type.name == "UINT"


def test_proxy_fields_defer_to_the_module():
    device = build('[Params]\nProxyParam1 = 0,,,0x0000, 0xC7, 2, "in", "", "", Module, Module, Module;\n'
                   'ProxyParamSizeAdder1 = 4, 4, 4;\n'
                   '[Assembly]\nProxyAssem1 = "x", "20 7D 24 SLOT 30 0A", , , , , ModuleMemberList;\n')
    proxy = device.parameters["ProxyParam1"]
    assert (proxy.minimum, proxy.maximum, proxy.default) == (MODULE, MODULE, MODULE)
    assert proxy.size_adder == (4, 4, 4)
    assembly = device.assemblies["ProxyAssem1"]
    assert assembly.module_member_list and assembly.path[3] == PathItem(keyword="SLOT")


def test_real_words_and_nan():
    device = build('[Params]\nParam1 = 0,,,0x0000, 0xCA, 4, "r", "", "", -INFINITY, INFINITY, QUIET-NAN;\n')
    parameter = device.parameters["Param1"]
    assert parameter.minimum == -math.inf and parameter.maximum == math.inf and math.isnan(parameter.default)
