"""Profiles written by hand from the schemas, not by edsconv's writer (corpus/xml/handwritten).

They are valid ISO 15745-4 documents that use what the XML data model and the schema types
allow and edsconv's writer never writes: white space around values, comments and processing
instructions anywhere (also inside values), CDATA, character references, time zones, byte
order marks, the spellings of a DEVICEINFO wrapper reference. MANIFEST.tsv says, for each,
what `edsconv validate` must say (nothing) and which EDS entries `edsconv xml2eds` must
produce; a filled ``validate_gap`` or ``xml2eds_gap`` column states what edsconv does not do
yet (issue 9), and the test is then a strict xfail.
"""

from __future__ import annotations

import csv
from pathlib import Path

import pytest
import xmlschema
from click.testing import CliRunner

import edsconv
from conftest import REPO
from edsconv.cli import cli
from edsconv.diagnostics import Severity
from edsconv.eds.from_model import device_to_eds
from edsconv.eds.syntax import EdsFile, String
from edsconv.eds.writer import write
from edsconv.model import Device
from edsconv.resources import data_dir
from edsconv.xml.commnet import read_commnet_profile
from edsconv.xml.convert import device_from_profiles
from edsconv.xml.datamodel import without_comments
from edsconv.xml.device_read import read_device_profile
from edsconv.xml.safe import read_xml
from edsconv.xml.validate import validate_file

HANDWRITTEN = REPO / "corpus" / "xml" / "handwritten"
#: The folder of a profile names its kind; the schema it was written from (as restored).
SCHEMAS = {"cip-device": (xmlschema.XMLSchema11, "CIP_Device_Profile.xsd"),
           "ethernetip-commnet": (xmlschema.XMLSchema11, "ENet_CommNet_Profile.xsd"),
           "eds-device-wrapper": (xmlschema.XMLSchema10, "EDS_Device_Profile_wrapper.xsd")}


def manifest() -> list[dict[str, str]]:
    with (HANDWRITTEN / "MANIFEST.tsv").open(encoding="utf-8", newline="") as table:
        return list(csv.DictReader(table, delimiter="\t", quoting=csv.QUOTE_NONE))


def cases(gap: str) -> list:
    return [pytest.param(row, id=row["file"],
                         marks=[pytest.mark.xfail(strict=True, reason=row[gap])] if row[gap] else [])
            for row in manifest()]


def field_values(fields) -> tuple:
    """What a field list says, independent of how strings are escaped: a string by its text."""
    return tuple(("string", field.value.text) if isinstance(field.value, String) else ("raw", field.raw)
                 for field in fields)


def entries(eds: EdsFile) -> dict[tuple[str, str], tuple]:
    return {(section.name, entry.keyword): field_values(entry.fields)
            for section in eds.sections for entry in section.entries}


def xml2eds(path: Path) -> tuple[EdsFile | None, list[str]]:
    """The EDS xml2eds writes for one profile, and its diagnostics of warning severity or worse."""
    device, diagnostics = device_from_profiles([path], network_alone=True)
    problems = [d.format() for d in diagnostics if d.severity >= Severity.WARNING]
    return (None if device is None else edsconv.parse(write(device_to_eds(device)))), problems


@pytest.mark.parametrize("row", cases("validate_gap"))
def test_validate_accepts_the_profile(row):
    report = validate_file(HANDWRITTEN / row["file"])
    assert [d.format() for d in report.diagnostics] == []


@pytest.mark.parametrize("row", cases("xml2eds_gap"))
def test_xml2eds_reads_every_value(row):
    eds, problems = xml2eds(HANDWRITTEN / row["file"])
    assert problems == []
    assert eds is not None
    produced = entries(eds)
    expected = entries(edsconv.parse(row["eds"]))
    assert {key: produced.get(key) for key in expected} == expected


@pytest.mark.parametrize("row", [row for row in manifest() if row["reference"] == "restored"], ids=lambda r: r["file"])
def test_profile_is_valid_in_the_xml_data_model(row):
    """The corpus itself: valid by the restored schema for a validator that reads the XML data
    model (xmlschema on ElementTree drops comments and processing instructions, joins text)."""
    schema_class, xsd = SCHEMAS[row["file"].split("/")[0]]
    schema_class(str(data_dir("schemas") / xsd)).validate(str(HANDWRITTEN / row["file"]))


def test_manifest_lists_every_profile():
    assert sorted(row["file"] for row in manifest()) == sorted(
        str(path.relative_to(HANDWRITTEN)) for path in HANDWRITTEN.glob("*/*.xml"))
    assert {row["reference"] for row in manifest()} <= {"restored", "printed"}
    assert all(edsconv.parse(row["eds"]).diagnostics == [] for row in manifest())


# --- valid profiles with a value xml2eds cannot read: an error at the value and exit 1, never a silent loss ---

UNREADABLE = [
    pytest.param("cip-device/ids_and_group_references.xml", "            Param2\n", "            ProxyParam2\n",
                 "<VariantRef>", ("Groups", "Group1"), id="group-member-proxyparam"),
    pytest.param("cip-device/time_zones.xml", 'CreateTime="23:30:00-05:00"', 'CreateTime="24:00:00"',
                 "<ProfileBody", ("File", "CreateTime"), id="time-24-00-00"),
    pytest.param("cip-device/time_zones.xml", 'CreateDate="2024-05-01Z"', 'CreateDate="0000-01-01"',
                 "<ProfileBody", ("File", "CreateDate"), id="date-year-zero"),
]


@pytest.mark.parametrize(("name", "old", "new", "element", "entry"), UNREADABLE)
def test_a_value_that_cannot_be_read_is_an_error_and_exit_1(tmp_path, name, old, new, element, entry):
    """The edited profile stays valid (XSD 1.1 allows 24:00:00 and the year 0000; a VariantRef is
    any NMTOKEN), but the EDS cannot hold the value: xml2eds reports XML201 at the element that
    holds it, leaves the value out and exits 1."""
    source = (HANDWRITTEN / name).read_text(encoding="utf-8")
    assert source.count(old) == 1
    path = tmp_path / Path(name).name
    path.write_text(source.replace(old, new), encoding="utf-8")
    assert validate_file(path).diagnostics == []
    line = source[:source.index(old)][:source[:source.index(old)].rindex(element)].count("\n") + 1
    _, problems = xml2eds(path)
    assert [problem.split(" ")[2] for problem in problems] == ["XML201"]
    assert problems[0].startswith(f"{path}:{line}:")
    result = CliRunner().invoke(cli, ["xml2eds", str(path)])
    assert result.exit_code == 1
    written = entries(edsconv.parse(result.stdout))
    if entry == ("Groups", "Group1"):  # the group stays, without the member
        assert written[entry] == (("string", "Setup"), ("raw", "2"), ("raw", "1"))
    else:
        assert entry not in written


@pytest.mark.parametrize("row", [row for row in manifest() if not row["file"].startswith("eds-")],
                         ids=lambda r: r["file"])
def test_the_readers_need_no_cleaned_tree(row):
    """The readers take the text of each value themselves (comments and processing instructions skipped),
    so the library functions read the document as parsed, with its comments, as xml2eds reads the
    validated copy without them."""
    document = read_xml(HANDWRITTEN / row["file"])
    reader = read_device_profile if row["file"].startswith("cip-") else read_commnet_profile
    as_parsed, cleaned = Device(), Device()
    assert reader(document, as_parsed) == reader(without_comments(document), cleaned) == []
    assert as_parsed == cleaned
