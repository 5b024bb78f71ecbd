"""Issue 5's measure: xml2eds(eds2xml(x)) is semantically equal to x, and both XML documents are valid.

For every EDS of corpus/ and of the real corpus (skipped when absent): the EDS
is converted to the two profiles, each profile is validated against its schema
(by ``serialise``, which refuses an invalid document), the profiles are read
back into a Device, the Device is written as canonical EDS text, and that text
read again must be semantically equal to the original (``edsconv.diff`` finds
no change). The same runs through the commands, with files on disk.
"""

from __future__ import annotations

import datetime
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from lxml import etree

import edsconv
from conftest import REAL_EDS, REPO, needs_real_corpus
from edsconv.diff import diff
from edsconv.eds.from_model import device_to_eds
from edsconv.eds.writer import write
from edsconv.model import Device, Parameter
from edsconv.spec_tables import DATA_TYPES_BY_NAME
from edsconv.xml.commnet import read_commnet_profile
from edsconv.xml.common import Header
from edsconv.xml.convert import profile_documents

#: corpus/shall and corpus/allowed are one base file changed in one place each (test_shall_probes.py reads them).
OWN = sorted(p for p in (REPO / "corpus").rglob("*")
             if p.suffix.lower() == ".eds" and not {"broken", "shall", "allowed"} & set(p.parts))


def round_trip(device: Device, stem: str = "x") -> Device:
    """Device -> both profiles (validated) -> Device -> canonical EDS text -> Device."""
    from edsconv.xml.device_read import read_device_profile

    header = Header.derive(device, stem)
    device_xml, commnet_xml = profile_documents(device, header, stem)  # raises if either is invalid
    back = Device()
    problems = read_device_profile(etree.fromstring(device_xml.data), back)
    problems += read_commnet_profile(etree.fromstring(commnet_xml.data), back)
    assert problems == [], [p.format() for p in problems]
    return edsconv.build(edsconv.parse(write(device_to_eds(back))))


def assert_round_trips(path: Path) -> None:
    original = edsconv.build(edsconv.load(path))
    changes = diff(original, round_trip(original, path.stem))
    assert not changes, "\n".join(str(change) for change in changes[:20])


@pytest.mark.parametrize("path", OWN, ids=lambda p: str(p.relative_to(REPO)))
def test_own_corpus_round_trips(path: Path):
    assert_round_trips(path)


@needs_real_corpus
@pytest.mark.parametrize("path", REAL_EDS, ids=lambda p: p.name)
def test_real_corpus_round_trips(path: Path):
    assert_round_trips(path)


def test_commands_round_trip_through_files(tmp_path: Path):
    source = REPO / "corpus" / "examples" / "io_adapter.eds"

    def edsconv_command(*args: str) -> subprocess.CompletedProcess:
        return subprocess.run([sys.executable, "-m", "edsconv", *args], capture_output=True, text=True,
                              timeout=120, cwd=tmp_path)

    made = edsconv_command("eds2xml", str(source), "-o", "xml")
    assert made.returncode == 0, made.stderr
    device_xml, commnet_xml = tmp_path / "xml" / "io_adapter_device.xml", tmp_path / "xml" / "io_adapter_commnet.xml"
    assert made.stdout.split() == ["xml/io_adapter_device.xml", "xml/io_adapter_commnet.xml"]
    assert edsconv_command("validate", str(device_xml), str(commnet_xml)).returncode == 0
    back = edsconv_command("xml2eds", str(device_xml), str(commnet_xml), "-o", "back.eds")
    assert back.returncode == 0, back.stderr
    assert edsconv_command("diff", str(source), "back.eds").returncode == 0
    # nothing is overwritten without --force, and a refusal writes nothing
    again = edsconv_command("eds2xml", str(source), "-o", "xml")
    assert again.returncode == 2 and "--force" in again.stderr
    assert edsconv_command("xml2eds", str(device_xml), "-o", "back.eds").returncode == 2


def test_wrapper_profiles_resolve_to_the_eds_beside_them(tmp_path: Path):
    source = REPO / "corpus" / "examples" / "io_adapter.eds"
    (tmp_path / "io_adapter.eds").write_bytes(source.read_bytes())

    def edsconv_command(*args: str) -> subprocess.CompletedProcess:
        return subprocess.run([sys.executable, "-m", "edsconv", *args], capture_output=True, text=True,
                              timeout=120, cwd=tmp_path)

    for reference in ("fileinfo", "deviceinfo"):
        made = edsconv_command("eds2xml", "--wrapper", "--reference", reference, "--force", "io_adapter.eds")
        assert made.returncode == 0, made.stderr
        assert edsconv_command("validate", "io_adapter_device_wrapper.xml",
                               "io_adapter_commnet_wrapper.xml").returncode == 0
        # outside the wrapper's directory, so that only the original can be found
        back = edsconv_command("xml2eds", "io_adapter_device_wrapper.xml", "-o", f"out/{reference}.eds")
        assert back.returncode == 0, back.stderr
        assert edsconv_command("diff", "io_adapter.eds", f"out/{reference}.eds").returncode == 0
    (tmp_path / "io_adapter.eds").unlink()
    lost = edsconv_command("xml2eds", "io_adapter_device_wrapper.xml")
    assert lost.returncode == 1
    assert "XML101" in lost.stderr and "65535 12 1001" in lost.stderr


# --- generated models ------------------------------------------------------------------------

_INTEGER_TYPES = ["USINT", "UINT", "UDINT", "SINT", "INT", "DINT"]


@st.composite
def parameters(draw, number: int) -> Parameter:
    type_name = draw(st.sampled_from(_INTEGER_TYPES))
    data_type = DATA_TYPES_BY_NAME[type_name]
    low, high = sorted(draw(st.integers(data_type.minimum, data_type.maximum)) for _ in range(2))
    text = st.text(st.characters(min_codepoint=32, max_codepoint=126), max_size=24)
    return Parameter(
        f"Param{number}", "Param", number, descriptor=draw(st.sampled_from([0, 0x10, 0x20])),
        data_type=data_type, data_type_code=data_type.code, data_size=data_type.size,
        name=draw(text), units=draw(text), help=draw(text),
        minimum=low, maximum=high, default=draw(st.integers(low, high)))


@st.composite
def devices(draw) -> Device:
    device = edsconv.build(edsconv.load(REPO / "corpus" / "examples" / "io_adapter.eds"))
    identity = device.identity
    identity.vendor_code = draw(st.integers(1, 65535))
    identity.product_code = draw(st.integers(0, 65535))
    identity.major_revision = draw(st.integers(1, 127))
    identity.minor_revision = draw(st.integers(1, 255))
    identity.product_name = draw(st.text(st.characters(min_codepoint=32, max_codepoint=126), min_size=1,
                                         max_size=32))
    device.file.create_date = draw(st.dates(datetime.date(1996, 1, 1), datetime.date(2099, 12, 31)))
    count = draw(st.integers(0, 6))
    for number in range(10, 10 + count):
        device.parameters[f"Param{number}"] = draw(parameters(number))
    return device


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(devices())
def test_generated_devices_round_trip(device: Device):
    changes = diff(device, round_trip(device))
    assert not changes, [str(change) for change in changes]


def test_diff_sees_a_changed_value():
    """The comparison the round trip relies on is not blind."""
    original = edsconv.build(edsconv.load(REPO / "corpus" / "examples" / "io_adapter.eds"))
    changed = edsconv.build(edsconv.load(REPO / "corpus" / "examples" / "io_adapter.eds"))
    changed.parameters["Param1"].default = 20000
    changed.identity.product_code = 1002
    assert len(diff(original, changed)) == 2
    assert diff(original, original) == []
