"""Each comparison of edsconv verify on its own: an EDS written from corpus/device/loopback_adapter.eds
with one deliberate fault per entry, against a cpppo device on 127.0.0.1 (tests/enip_device.py)."""

from __future__ import annotations

import copy
import json
from collections.abc import Iterator
from pathlib import Path

import pytest
from click.testing import CliRunner

pytest.importorskip("cpppo", reason="edsconv[device] is not installed")
pytest.importorskip("pycomm3", reason="edsconv[device] is not installed")

from edsconv.cli import cli  # noqa: E402
from verify_devices import EDS, MATCHING, line_of, running  # noqa: E402

#: the additions to the EDS: entries the device answers otherwise than they say
PARAMS = """
        Param2 = 0, 6, "20 64 24 01 30 02", 0x0000, 0xC8, 4, "Wrong size", "", "", 0, 100, 7, ,,,, ,,,, 0;
        Param3 = 0, 6, "20 64 24 02 30 01", 0x0000, 0xC7, 2, "No such instance", "", "", 0, 100, 7, ,,,, ,,,, 0;
        Param4 = 0, 4, "20 64 24 01", 0x0000, 0xC7, 2, "No attribute", "", "", 0, 100, 7, ,,,, ,,,, 0;
"""
#: every code verify reports: none of them on the device the EDS describes
VERIFY_CODES = ("EDS601", "EDS602", "EDS603", "EDS604", "EDS605", "EDS606", "EDS607", "EDS608", "EDS609", "EDS610",
                "EDS611", "EDS612", "EDS613")
CONNECTION = """
        Connection2 = 0x02010002, 0x44240305, 0, 0, , , 8, Assem100, ,, ,, "Input Only", "",
                "20 04 24 01 2C C6 2C 65";
"""


@pytest.fixture(scope="module")
def faulty_eds(tmp_path_factory: pytest.TempPathFactory) -> Path:
    text = EDS.read_text()
    text = text.replace("[Assembly]", PARAMS.strip("\n") + "\n\n[Assembly]")
    text = text.replace("\n[TCP/IP Interface Class]", CONNECTION.rstrip() + "\n\n[TCP/IP Interface Class]")
    text = text.replace("Instance_Attributes = 1;", "Instance_Attributes = 1, 99;")
    path = tmp_path_factory.mktemp("eds") / "faulty.eds"
    path.write_text(text)
    return path


@pytest.fixture(scope="module")
def device(tmp_path_factory: pytest.TempPathFactory) -> Iterator[str]:
    """MATCHING with the TCP/IP Interface at revision 3, Param1 at 2400 rpm, a QoS object (0x48) and the
    Ethernet Link interface labelled X2."""
    config = copy.deepcopy(MATCHING)
    config["objects"]["246"]["instances"]["1"]["10"] = ["SSTRING", "X2"]
    config["classes"]["245"] = 3
    config["objects"]["100"]["instances"]["1"]["1"] = ["UINT", 2400]
    config["objects"]["72"] = {"revision": 1, "instances": {"1": {"1": ["USINT", 0]}}}
    with running(config, tmp_path_factory.mktemp("device")) as port:
        yield f"127.0.0.1:{port}"


def run(eds: Path, *arguments: str) -> tuple[int, list[tuple[str, int, str]]]:
    result = CliRunner().invoke(cli, ["verify", str(eds), *arguments, "--format", "json"])
    diagnostics = json.loads(result.stdout)["files"][0]["diagnostics"]
    return result.exit_code, [(d["code"], d["line"], d["message"]) for d in diagnostics]


def test_each_entry_the_device_answers_otherwise(faulty_eds: Path, device: str):
    code, found = run(faulty_eds, "--device", device)
    at = lambda text: line_of(text, faulty_eds)  # noqa: E731
    assert code == 1
    assert [(c, line) for c, line, _ in found] == [
        ("EDS608", at("0, 1800, 1500")), ("EDS609", at("Param2 =")), ("EDS610", at("Param3 =")),
        ("EDS612", at("Param4 =")), ("EDS607", at("Connection2 =")), ("EDS603", at("[TCP/IP Interface Class]") + 1),
        ("EDS604", at("Instance_Attributes")), ("EDS613", at("InterfaceLabel1")),
    ]
    messages = dict(((c, m) for c, _, m in found))
    assert messages["EDS608"] == ("Param1: the device holds 2400, above the maximum 1800 (class 0x64 instance 1 "
                                  "attribute 1)")
    assert messages["EDS609"].startswith("Param2 is UDINT (4 bytes) but the device answers 2 bytes")
    assert messages["EDS603"] == "Revision is 4 but the device answers 3 (class attribute 1)"
    assert messages["EDS604"].startswith("the device does not support attribute 99 of instance 1: general status "
                                         "0x14 (Attribute not supported)")
    assert messages["EDS613"] == 'InterfaceLabel1 is "X1" but the device\'s instance 1 answers "X2" (attribute 10)'
    assert messages["EDS607"].startswith("the device has no assembly instance 101 (Connection2)")


def test_strict_reports_an_object_the_eds_does_not_declare(faulty_eds: Path, device: str):
    found = run(faulty_eds, "--device", device, "--strict")[1]
    assert [(c, line, m) for c, line, m in found if c == "EDS605"] == [
        ("EDS605", 1, "the device has a QoS object (class 0x48) but the EDS has no [QoS Class] section")]
    assert "EDS605" not in [c for c, _, _ in run(faulty_eds, "--device", device)[1]]


def test_connect_reports_a_connection_it_cannot_build(faulty_eds: Path, device: str):
    found = run(faulty_eds, "--device", device, "--connect")[1]
    assert ("EDS612", line_of("Connection2 =", faulty_eds),
            "Connection2: not opened: its T=>O size or RPI is not a number (a parameter or empty)") in found


def test_the_matching_device_gives_nothing_with_every_option(device: str, tmp_path_factory: pytest.TempPathFactory):
    with running(MATCHING, tmp_path_factory.mktemp("matching")) as port:
        exit_code, found = run(EDS, "--device", f"127.0.0.1:{port}", "--connect", "--strict")
    assert exit_code == 0
    assert all(code not in [c for c, _, _ in found] for code in VERIFY_CODES)
    assert found == []
