"""edsconv verify against a real EtherNet/IP stack: cpppo's server on 127.0.0.1 (tests/enip_device.py),
once configured as corpus/device/loopback_adapter.eds describes the device and once differing in
revision, one assembly size and one object. No traffic leaves the loopback address."""

from __future__ import annotations

import json
from collections.abc import Iterator

import pytest
from click.testing import CliRunner

pytest.importorskip("cpppo", reason="edsconv[device] is not installed")
pytest.importorskip("pycomm3", reason="edsconv[device] is not installed")

from edsconv.cli import cli  # noqa: E402
from edsconv.eds.reader import load  # noqa: E402
from edsconv.model.build import build  # noqa: E402
from edsconv.verify.client import Session  # noqa: E402
from edsconv.verify.forward import forward_open  # noqa: E402
from edsconv.verify.io import segments  # noqa: E402
from verify_devices import EDS, MATCHING, differing, line_of, running  # noqa: E402


@pytest.fixture(scope="module")
def matching(tmp_path_factory: pytest.TempPathFactory) -> Iterator[str]:
    with running(MATCHING, tmp_path_factory.mktemp("matching")) as port:
        yield f"127.0.0.1:{port}"


@pytest.fixture(scope="module")
def other(tmp_path_factory: pytest.TempPathFactory) -> Iterator[str]:
    with running(differing(), tmp_path_factory.mktemp("differing")) as port:
        yield f"127.0.0.1:{port}"


def verify(*arguments: str):
    return CliRunner().invoke(cli, ["verify", str(EDS), *arguments])


def found(result) -> list[tuple[str, int]]:
    return [(d["code"], d["line"]) for d in json.loads(result.stdout)["files"][0]["diagnostics"]]


def test_the_matching_device_gives_nothing(matching: str):
    result = verify("--device", matching, "--format", "json")
    assert (result.exit_code, found(result)) == (0, [])
    text = verify("--device", matching)
    assert (text.exit_code, text.stdout) == (0, "")
    assert "read-only" in text.stderr and "0 errors, 0 warnings, 0 notes" in text.stderr


def test_the_differing_device_gives_exactly_its_three_differences(other: str):
    result = verify("--device", other, "--format", "json")
    assert result.exit_code == 1
    assert found(result) == [("EDS601", line_of("MinRev")), ("EDS606", line_of("Assem100 =")),
                             ("EDS602", line_of("[Ethernet Link Class]"))]
    messages = [d["message"] for d in json.loads(result.stdout)["files"][0]["diagnostics"]]
    assert messages[0] == "MinRev is 3 but the device answers 4 (List Identity) and 4 (Identity object)"
    assert messages[1] == "Assem100 is 8 bytes but the device's assembly instance 100 holds 10"
    assert messages[2].startswith("the device has no Ethernet Link object (class 0xF6): general status 0x05")


def test_connect_opens_and_closes_each_connection_of_the_matching_device(matching: str):
    result = verify("--device", matching, "--connect", "--format", "json")
    assert (result.exit_code, found(result)) == (0, [])
    assert "closed again at once" in verify("--device", matching, "--connect").stderr


def test_each_connection_opened_is_closed_at_once(matching: str):
    host, port = matching.split(":")
    device = build(load(EDS))
    (connection,) = device.connections.values()
    request, _ = forward_open(device, connection, 1, segments(connection.path))
    assert request is not None and request.transport == 0x01  # class 1, cyclic (0x04010002)
    assert (request.o_to_t_ncp & 0x1FF, request.t_to_o_ncp & 0x1FF) == (4 + 2 + 4, 8 + 2)
    with Session(host, int(port), 2.0) as session:
        opened = session.forward_open(request)
    assert opened.ok and opened.closed is not None and opened.closed.ok
    assert opened.closed.established.forward_close.connection_serial == 1


def test_connect_reports_the_refusal_in_words(other: str):
    result = verify("--device", other, "--connect", "--format", "json")
    assert ("EDS611", line_of("Connection1 =")) in found(result)
    (refusal,) = [d["message"] for d in json.loads(result.stdout)["files"][0]["diagnostics"] if d["code"] == "EDS611"]
    assert refusal == ("Connection1 (Exclusive Owner): the device refuses the Forward Open: general status 0x01 "
                       "(Connection failure (see extended status)), extended status 0x0109 (Invalid connection size)")


@pytest.mark.parametrize("output_format", ["text", "sarif", "github"])
def test_every_output_format_of_lint(other: str, output_format: str):
    result = verify("--device", other, "--format", output_format)
    assert result.exit_code == 1
    if output_format == "text":
        assert result.stdout.splitlines()[0] == (
            f"{EDS}:{line_of('MinRev')}:9: error: EDS601 MinRev is 3 but the device answers 4 (List Identity) "
            "and 4 (Identity object) [C.4.1.4.2]")
    elif output_format == "sarif":
        rules = [r["ruleId"] for r in json.loads(result.stdout)["runs"][0]["results"]]
        assert rules == ["EDS601", "EDS606", "EDS602"]
    else:
        assert [line.split(" ")[0] for line in result.stdout.splitlines() if line.startswith("::")] == \
            ["::error", "::error", "::error"]
