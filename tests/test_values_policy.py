"""The values policy (src/edsconv/model/device.py): a value that breaks a notation rule stays in the
typed model when the text allows exactly one reading of it, marked erroneous, with its diagnostic;
where no reading exists the model holds no value. Checked on written EDS text and, against eds-pie
1.2.0, on the real files where the two readers once differed.
"""

from __future__ import annotations

import datetime
import logging

import pytest

import edsconv
from conftest import SHARED_REAL, needs_real_corpus
from edsconv.model.values import StringIMember


def build(text: str):
    eds = edsconv.parse(text)
    device = edsconv.build(eds)
    return device, [d.code for d in (*eds.diagnostics, *device.diagnostics)]


def test_a_decimal_with_leading_zeros_keeps_its_one_reading():
    device, found = build("[Device]\nProdCode = 06402;\nMinRev = 02;\nMajRev = 3;\n")
    assert (device.identity.product_code, device.identity.minor_revision) == (6402, 2)
    assert device.erroneous == {("Device", "ProdCode", 0): "EDS103", ("Device", "MinRev", 0): "EDS103"}
    assert found == ["EDS103", "EDS103"]


def test_a_value_without_a_reading_is_not_held():
    device, found = build('[Device]\nMajRev = 256;\n[Params]\nParam1 = 0,,,0x0000,0xC1,1,"Bool","","",0,1,255;\n')
    assert device.identity.major_revision is None and device.parameters["Param1"].default is None
    assert device.erroneous == {} and found == ["EDS102", "EDS102"]


def test_a_string_rejected_for_its_escape_holds_no_value():
    device, found = build('[Device]\nProdName = "unknown \\q escape";\nVendName = "known \\t escape";\n')
    assert device.identity.product_name is None and device.identity.vendor_name == "known \t escape"
    assert found == ["EDS003"]  # reported once, by the reader


@pytest.mark.parametrize(("entry", "code", "attribute", "expected"), [
    ('ProdName = "Caf\\u00e9";', "EDS004", "product_name", "Caf\u00e9"),
    ('ProdName = "Probe\x01Adapter";', "EDS116", "product_name", "Probe\x01Adapter"),
    ('ProdName = "Probe\\x00";', "EDS117", "product_name", "Probe\x00"),
])
def test_a_string_with_one_reading_keeps_it_marked(entry, code, attribute, expected):
    device, _ = build(f"[Device]\n{entry}\n")
    assert getattr(device.identity, attribute) == expected
    assert device.erroneous == {("Device", "ProdName", 0): code}


def test_a_stringi_keeps_its_one_reading():
    device, _ = build('[Params]\nParam1 = 0,,,0x0000,0xC7,2,"Speed","","",0,100,0,,,,,,,,,,'
                      '{1, {"eng",0xD0,4,"Speed\\x00"}};\n')
    assert device.parameters["Param1"].international_name == (StringIMember("eng", 0xD0, 4, "Speed\x00"),)
    assert device.erroneous == {("Params", "Param1", 21): "EDS117"}


def test_a_date_with_one_reading_keeps_it_and_a_warning_is_not_marked():
    device, found = build("[File]\nCreateDate = 06-6-2001;\nModDate = 01-01-1994;\nCreateTime = 9:30:00;\n")
    assert device.file.create_date == datetime.date(2001, 6, 6)
    assert device.file.mod_date == datetime.date(1994, 1, 1)
    assert device.file.create_time == datetime.time(9, 30)
    assert device.erroneous == {("File", "CreateDate", 0): "EDS105", ("File", "CreateTime", 0): "EDS106"}
    assert sorted(found) == ["EDS105", "EDS106", "EDS114"]


def test_the_same_keyword_in_two_sections_is_marked_in_its_own():
    device, _ = build("[File]\nRevision = 1.0;\n[Assembly]\nRevision = 02;\n")
    assert device.assembly_revision == 2 and device.erroneous == {("Assembly", "Revision", 0): "EDS103"}


# --- against eds-pie: the values where the two readers once differed ---------------------------------------
TI_DISCRETE_IO = "TexasInstruments__ind-comms-sdk__am64x-evm_tiEtherNetIP_freeRTOS__discrete_io_device.eds"
METTLER_IND131 = "SerafinTech__node-st-eds-parse__IND131_ETHIP_V2_02.eds"
QUINLED = "AGSweeney__EnIP-QuinLED_PentaPlus__ESP32P4_OPENER.eds"


def eds_pie_field(name: str, section: str, keyword: str, index: int):
    logging.disable(logging.CRITICAL)  # eds-pie logs every token
    try:
        from eds_pie.eds_pie import Parser
        parsed = Parser((SHARED_REAL / name).read_text(encoding="utf-8", errors="replace")).parse()
        parsed.validate()  # types the fields
        return parsed.get_field(section, keyword, index)
    finally:
        logging.disable(logging.NOTSET)


@needs_real_corpus
@pytest.mark.parametrize(("name", "keyword", "attribute", "expected"), [
    (TI_DISCRETE_IO, "ProdCode", "product_code", 6402), (METTLER_IND131, "MinRev", "minor_revision", 2)])
def test_edsconv_and_eds_pie_read_the_same_identity(name, keyword, attribute, expected):
    pytest.importorskip("eds_pie")
    device = edsconv.build(edsconv.load(SHARED_REAL / name))
    assert getattr(device.identity, attribute) == expected == eds_pie_field(name, "Device", keyword, 0).value
    assert device.erroneous[("Device", keyword, 0)] == "EDS103"


@needs_real_corpus
def test_a_bool_default_255_is_no_bool_where_eds_pie_keeps_the_text():
    # the one difference left, by decision: a BOOL holds 0 or 1, so 255 has no reading as a BOOL
    # (EDS102); eds-pie leaves the field untyped and keeps the text
    pytest.importorskip("eds_pie")
    device = edsconv.build(edsconv.load(SHARED_REAL / QUINLED))
    assert device.parameters["Param4"].data_type.name == "BOOL" and device.parameters["Param4"].default is None
    assert eds_pie_field(QUINLED, "Params", "Param4", 11).value == "255"
