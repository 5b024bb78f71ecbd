"""``edsconv show`` and ``edsconv diff`` on the content beyond the 2003 text (issue 10 items 5 and 7),
on our own files of corpus/cip."""

from __future__ import annotations

import base64
import json
from pathlib import Path

import pytest
from click.testing import CliRunner

import edsconv
from conftest import REPO
from edsconv.cli import cli
from edsconv.describe import describe
from edsconv.diff import diff

CIP = REPO / "corpus" / "cip"


def run(*args: str):
    return CliRunner().invoke(cli, list(args), catch_exceptions=False)


def document(name: str) -> dict:
    return describe(edsconv.analyse(edsconv.load(CIP / name))[0])


def text(name: str, section: str) -> str:
    result = run("show", str(CIP / name), "--section", section)
    assert result.exit_code == 0, result.output
    return result.output


def changes(old: str, new: str) -> list[tuple[str, str, str | None, str | None]]:
    def device(text_: str):
        return edsconv.build(edsconv.parse(text_))

    return [(c.kind, c.what, c.old, c.new) for c in diff(device(old), device(new))]


# --- show -----------------------------------------------------------------------------------


def test_capacity_as_a_table_in_json_and_text():
    capacity = document("capacity_clean.eds")["capacity"]
    assert capacity["traffic_specs"][1] == {"number": 2, "direction": "Rx", "connection_size": 400,
                                            "packets_per_second": 1200}
    assert capacity["max_io_connections"] == 4
    lines = text("capacity_clean.eds", "capacity").splitlines()
    assert "Maximum I/O connections (MaxIOConnections)                          4" in lines
    assert [line.split() for line in lines if line.split()[:1] in (["1"], ["2"], ["3"])] == [
        ["1", "TxRx", "16", "2500"], ["2", "Rx", "400", "1200"], ["3", "Tx", "400", "1000"]]


def test_network_objects_and_object_classes():
    found = document("network_objects_clean.eds")
    assert found["network"]["ethernet_link"]["interfaces"][1] == {"instance": 2, "label": "P2", "speed": None,
                                                                   "interface_type": 2}
    tcpip = next(r for r in found["object_classes"] if r["section"] == "TCP/IP Interface Class")
    assert (tcpip["class_id"], tcpip["class_name"], tcpip["instance_services"]) == (
        245, "TCP/IP Interface", ["{0x0E,*}", "{0x10,3,5,6}"])
    shown = text("network_objects_clean.eds", "network,objects")
    for words in ("ENetQCT1", "ready for connection 300", "P2", "Ring_Supervisor_Capable", "0xF5 TCP/IP",
                  "{0x10,3,5,6}", "max 32, static 0,"):
        assert words in shown


def test_devicenet_io_info():
    io = document("devicenet_io_info_clean.eds")["devicenet"]
    assert io["modes"][0] == {"keyword": "PollInfo", "combination_mask": "0x0005", "default_input": "Input1",
                              "default_output": "Output1"}
    assert io["enum_strings"] == {"Param1": ["Off", "3 ms", "10 ms"]}
    shown = text("devicenet_io_info_clean.eds", "devicenet")
    assert "Off / 3 ms / 10 ms" in shown and "2 bytes, 12 bits" in shown


def test_icon_is_described_and_written_out(tmp_path: Path):
    assert document("icon_clean.eds")["icon"] == {
        "kind": "ico", "valid_ico": True, "bytes": 198, "problem": None,
        "images": [{"width": 16, "height": 16, "bits_per_pixel": 1, "encoding": "bmp", "size": 176}]}
    target = tmp_path / "device.ico"
    result = run("show", str(CIP / "icon_clean.eds"), "--section", "icon", "--icon", str(target))
    assert result.exit_code == 0 and "16x16 BMP 1-bit" in result.output
    written = edsconv.load(CIP / "icon_clean.eds").section("Device").entry("IconContents").fields[0].value.text
    assert target.read_bytes() == base64.b64decode(written)
    broken = document("icon_not_ico.eds")["icon"]
    assert broken["valid_ico"] is False and "beyond the end" in broken["problem"]


def test_icon_option_without_an_icon_cannot_run(tmp_path: Path):
    result = run("show", str(CIP / "capacity_clean.eds"), "--icon", str(tmp_path / "x.ico"))
    assert result.exit_code == 2 and "no icon to write" in result.output
    assert not (tmp_path / "x.ico").exists()


def test_additions_and_extended_assemblies():
    safety = document("safety_clean.eds")["additions"]
    assert (safety["default_safety_connections"], safety["safety_cfg_assembly"], safety["safety_format"]) == (
        ["Connection1"], "Assem800", 2)
    assert "DefaultSafetyConnections" in text("safety_clean.eds", "identity")
    (exa,) = document("assembly_exa_clean.eds")["extended_assemblies"]
    assert (exa["keyword"], exa["size"], exa["total_bits"]) == ("AssemExa101", "Param2", 32)
    assert "AssemExa101  'Digital inputs and port data', size Param2" in text("assembly_exa_clean.eds", "assemblies")


def test_other_lists_only_what_no_table_defines():
    found = document("security_vendor_clean.eds")
    assert found["other_sections"] == [{"name": "65535_Example_Tool_Data", "entries": 1}]
    assert found["extra_entries"] == {"File": ["65535_Build_Tag"], "Class900_Vendor65535": ["65535_Diagnostic_Depth"]}
    assert document("network_objects_clean.eds")["extra_entries"] == {}


@pytest.mark.parametrize("name", sorted(p.name for p in CIP.glob("*.eds")))
def test_json_and_text_render_every_cip_file(name: str):
    result = run("show", str(CIP / name), "--format", "json")
    assert result.exit_code == 0 and json.loads(result.stdout)
    assert run("show", str(CIP / name)).exit_code == 0


# --- diff -----------------------------------------------------------------------------------

CAPACITY = "[Capacity]\nMaxIOConnections = 4;\nTSpec1 = TxRx, 16, 2500;\n"
TCPIP = "[TCP/IP Interface Class]\nObject_Class_Code = 0xF5;\nInstance_Services = 0x0E, {0x10,3};\n"


def test_newer_content_compares_by_meaning():
    assert changes(CAPACITY, CAPACITY.replace("= 4;", "= 0x4;")) == []
    assert changes(TCPIP, TCPIP.replace("0xF5", "245").replace("0x0E", "14")) == []
    assert changes(CAPACITY, CAPACITY.replace("2500", "3000")) == [
        ("changed", "[Capacity] TSpec1 PacketsPerSecond", "2500", "3000")]
    assert changes(TCPIP, TCPIP.replace("{0x10,3}", "{0x10,3,5}")) == [
        ("changed", "[TCP/IP Interface Class] Instance_Services", "0x0E, {0x10,3}", "0x0E, {0x10,3,5}")]


def test_added_and_removed_newer_entries_and_sections():
    assert changes(CAPACITY, CAPACITY + "MaxMsgConnections = 8;\n") == [
        ("added", "[Capacity] MaxMsgConnections", None, "8")]
    assert changes("", CAPACITY) == [("added", "[Capacity]", None, None)]
    assert changes(CAPACITY, "") == [("removed", "[Capacity]", None, None)]


def test_extended_assemblies_compare_member_by_member():
    old = (CIP / "assembly_exa_clean.eds").read_text()
    assert changes(old, old.replace("8,Param4;", "8,Param3;")) == [
        ("changed", "AssemExa101 member 3", "8, Param4", "8, Param3")]


def test_the_icon_compares_by_its_bytes():
    old = (CIP / "icon_clean.eds").read_text()
    start = old.index("IconContents =")
    written = old[start:old.index(";", start) + 1]
    whole = edsconv.load(CIP / "icon_clean.eds").section("Device").entry("IconContents").fields[0].value.text
    assert changes(old, old.replace(written, f'IconContents = "{whole[:10]}" "{whole[10:]}";')) == []
    other = base64.b64encode(base64.b64decode(whole)[:-1] + b"\x01").decode()
    (change,) = changes(old, old.replace(written, f'IconContents = "{other}";'))
    assert change[:2] == ("changed", "[Device] IconContents") and change[2].startswith("ICO, 198 bytes, sha256 ")


def test_vendor_entries_still_compare_as_written():
    old = "[Capacity]\n65535_Depth = 1;\n"
    assert changes(old, old.replace("= 1", "= 0x1")) == [("changed", "[Capacity] 65535_Depth", "1", "0x1")]
