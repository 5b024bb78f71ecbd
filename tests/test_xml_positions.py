"""Diagnostics of the XML readers name the file and the element's own line and column."""

from __future__ import annotations

import functools
from pathlib import Path

from lxml import etree

from edsconv.model import Device
from edsconv.xml import validate
from edsconv.xml.commnet import read_commnet_profile
from edsconv.xml.device_read import read_device_profile
from edsconv.xml.safe import XmlDocument, read_xml

XML = Path(__file__).resolve().parents[1] / "corpus" / "xml"
DEVICE = XML / "cip-device" / "valid-complete.xml"
COMMNET = XML / "ethernetip-commnet" / "valid-complete.xml"


def edited(tmp_path: Path, source: Path, old: str, new: str) -> tuple[Path, int, int]:
    """A copy of ``source`` with the first ``old`` replaced by ``new``; its line and column."""
    text = source.read_text(encoding="utf-8")
    assert old in text
    before = text[:text.index(old)]
    path = tmp_path / source.name
    path.write_text(before + new + text[len(before) + len(old):], encoding="utf-8")
    return path, before.count("\n") + 1, len(before) - before.rfind("\n")


def where(diagnostics) -> list[tuple[str, str | None, int, int]]:
    return [(d.code, d.path, d.line, d.column) for d in diagnostics]


def test_a_device_value_that_cannot_be_read_is_at_its_element(tmp_path):
    path, line, column = edited(tmp_path, DEVICE, "<DataType>C7</DataType>", "<DataType>word</DataType>")
    assert (line, column) == (150, 11)
    diagnostics = read_device_profile(read_xml(path), Device())
    assert where(diagnostics) == [("XML201", str(path), line, column)]
    assert diagnostics[0].format().startswith(f"{path}:150:11: error: XML201")


def test_an_extension_that_cannot_be_read_is_at_its_element(tmp_path):
    value = ('<DeviceFunction>\n      <edsconv:Values xmlns:edsconv="urn:x-edsconv:eds-extensions:1">\n'
             '        <edsconv:Value path="parameters.Param1.default" kind="nonsense">1</edsconv:Value>\n'
             '      </edsconv:Values>\n    </DeviceFunction>')
    path, line, _ = edited(tmp_path, DEVICE, "<DeviceFunction/>", value)
    diagnostics = read_device_profile(read_xml(path), Device())
    assert where(diagnostics) == [("XML202", str(path), line + 2, 9)]


def test_a_network_value_that_cannot_be_read_is_at_its_element(tmp_path):
    path, line, column = edited(tmp_path, COMMNET, "<Path>20 04 24 64 2C 65 2C 64</Path>", "<Path>20 XYZ</Path>")
    diagnostics = read_commnet_profile(read_xml(path), Device())
    assert where(diagnostics) == [("EDS109", str(path), line, column)]
    assert (line, column) == (68, 13)


def test_a_tree_without_its_text_keeps_the_line(tmp_path):
    path, line, _ = edited(tmp_path, DEVICE, "<DataType>C7</DataType>", "<DataType>word</DataType>")
    root = etree.fromstring(path.read_bytes())
    assert where(read_device_profile(root, Device())) == [("XML201", None, line, 1)]
    assert XmlDocument.of(root).path is None


def test_the_unchanged_profiles_read_cleanly():
    assert read_device_profile(read_xml(DEVICE), Device()) == []
    assert read_commnet_profile(read_xml(COMMNET), Device()) == []


def test_a_file_too_large_is_reported_at_its_start(monkeypatch):
    monkeypatch.setattr(validate, "read_xml", functools.partial(read_xml, max_bytes=100))
    assert where(validate.validate_file(DEVICE).diagnostics) == [("XML006", str(DEVICE), 1, 1)]
