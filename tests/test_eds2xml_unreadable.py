"""eds2xml converts an EDS with unreadable values (issue 20 item 9): every readable value is stated, a
value without a reading is kept with its exact spelling in an ``edsconv:Unreadable`` of the device
profile, and xml2eds writes it back; only the identity cannot be missing."""

from __future__ import annotations

from pathlib import Path

from lxml import etree

import edsconv
from conftest import REAL_EDS, REPO, needs_real_corpus
from edsconv.diff import diff
from edsconv.eds.from_model import device_to_eds
from edsconv.eds.writer import write
from edsconv.model import Device, Unreadable
from edsconv.xml.common import EDSCONV, Header
from edsconv.xml.convert import conversion_refusals, profile_documents
from edsconv.xml.device_read import read_device_profile

TEXT = (REPO / "corpus" / "examples" / "io_adapter.eds").read_text()
#: one of each kind the real files have: a date day-month-year, a BOOL default 255, a word where a
#: string stands, a stray word, an entry whose path lacks quotes (its fields lack commas)
UNREADABLE = (TEXT.replace("CreateDate = 11-22-2026;", "CreateDate = 22-11-2026;")
              .replace("[Params]", "[Params]\n    Param90 = 0,,,0x0000,0xC1,1,\"On\",\"\",\"\",0,1,255;\n"
                                   "    StrayWord\n")
              .replace("[Port]", "[Port]\n    Port8 = TCP, A, \"20 F5 24 01\", 8;\n"
                                 "    Port9 = TCP, \"B\", 20 F5 24 01, 9; $ kept\n"))


def profiles(device: Device) -> list[bytes]:
    return [output.data for output in profile_documents(device, Header.derive(device, "x"), "x")]


def test_each_unreadable_value_is_kept_as_written():
    device, diagnostics = edsconv.analyse(edsconv.parse(UNREADABLE))
    assert {"EDS105", "EDS102", "EDS101", "EDS001"} <= {d.code for d in diagnostics}
    assert device.unreadable == [
        Unreadable("File", "CreateDate", 0, "22-11-2026"),
        Unreadable("Params", "Param90", 11, "255"),
        Unreadable("Port", "Port8", 1, "A"),
        Unreadable("Params", None, None, "StrayWord", "Param1"),
        Unreadable("Port", None, None, 'Port9 = TCP, "B", 20 F5 24 01, 9;', "Port1", (" kept",)),
    ]
    assert conversion_refusals(edsconv.parse(UNREADABLE), device) == []


def test_the_device_profile_marks_them_and_reads_them_back():
    device = edsconv.build(edsconv.parse(UNREADABLE))
    device_xml, _ = profiles(device)
    root = etree.fromstring(device_xml)
    marked = root.findall(f".//{EDSCONV}Unreadable")
    assert [(m.get("keyword"), m.get("field"), m.findtext(f"{EDSCONV}Text")) for m in marked][:3] == [
        ("CreateDate", "1", "22-11-2026"), ("Param90", "12", "255"), ("Port8", "2", "A")]
    back = Device()
    assert read_device_profile(root, back) == []
    assert back.unreadable == device.unreadable
    assert back.file.create_date is None  # the required CreateDate attribute stands in; the model has no date


def test_xml2eds_writes_the_exact_spelling_back():
    device = edsconv.build(edsconv.parse(UNREADABLE))
    written = write(device_to_eds(device))
    for spelling in ("CreateDate = 22-11-2026;", "255", "Port8 = TCP, A,", "StrayWord", "20 F5 24 01, 9;"):
        assert spelling in written
    assert diff(device, edsconv.build(edsconv.parse(written))) == []


def test_diff_compares_unreadable_text_as_written():
    one = edsconv.build(edsconv.parse(UNREADABLE))
    other = edsconv.build(edsconv.parse(UNREADABLE.replace("22-11-2026", "23-11-2026")))
    (change,) = diff(one, other)
    assert (change.what, change.old, change.new) == (
        "[File] CreateDate field 1 (unreadable)", '"22-11-2026"', '"23-11-2026"')


def test_an_unreadable_identity_is_still_refused():
    eds = edsconv.parse(UNREADABLE.replace("ProdCode = 1001;", "ProdCode = 1001x;"))
    device = edsconv.build(eds)
    (refusal,) = conversion_refusals(eds, device)
    assert refusal.code == "XML103" and "ProdCode" in refusal.message


@needs_real_corpus
def test_every_real_file_is_converted():
    refused = {}
    for path in REAL_EDS:
        eds = edsconv.load(path)
        device = edsconv.build(eds)
        refusals = conversion_refusals(eds, device)
        if refusals:
            refused[path.name] = [d.message for d in refusals]
    assert refused == {}


def test_a_file_without_unreadable_text_has_none(tmp_path: Path):
    assert edsconv.build(edsconv.parse(TEXT)).unreadable == []
    assert b"Unreadable" not in profiles(edsconv.build(edsconv.parse(TEXT)))[0]
