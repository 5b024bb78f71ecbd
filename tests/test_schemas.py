"""The restored ISO 15745-4 schemas load, and the corpus instances behave as their comments say."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
import xmlschema
from lxml import etree

from edsconv.resources import data_dir
from edsconv.xml.schemas import PROFILE_KINDS, load_schema
from edsconv.xml.validate import validate_file

CORPUS = Path(__file__).resolve().parents[1] / "corpus" / "xml"
VALIDATED_KINDS = [kind for kind in PROFILE_KINDS if kind.xsd]
EXPECT = re.compile(r"<!-- expect: (\w+) (.*?) -->")


def expectation(path: Path) -> tuple[str, str]:
    found = EXPECT.search(path.read_text(encoding="utf-8"))
    assert found, f"{path} has no '<!-- expect: CODE message -->' comment"
    return found.group(1), found.group(2)


@pytest.mark.parametrize("xsd", sorted(p.name for p in data_dir("schemas").glob("*.xsd")))
def test_every_schema_loads(xsd):
    """Each of the ten files is a valid schema (the two included ones load on their own too)."""
    version_11 = xsd in {kind.xsd for kind in PROFILE_KINDS if kind.xsd_version == "1.1"}
    schema_class = xmlschema.XMLSchema11 if version_11 else xmlschema.XMLSchema10
    schema_class(str(data_dir("schemas") / xsd))


@pytest.mark.parametrize("xsd", [kind.xsd for kind in PROFILE_KINDS if kind.xsd_version == "1.1"])
def test_the_xsd_11_schemas_are_not_valid_xsd_10(xsd):
    """The reason they are loaded as XSD 1.1 (see ERRATA.md): UPA between elements and wildcards."""
    with pytest.raises((xmlschema.XMLSchemaParseError, xmlschema.XMLSchemaModelError),
                       match="Unique Particle Attribution|assert"):
        xmlschema.XMLSchema10(str(data_dir("schemas") / xsd))


def test_ten_schemas_as_the_spec_names_them():
    assert sorted(p.name for p in data_dir("schemas").glob("*.xsd")) == sorted([
        "MasterTemplateTypes.xsd", "CIPDataTypes.xsd", "CIP_Device_Profile.xsd", "EDS_Device_Profile_wrapper.xsd",
        "ENet_CommNet_Profile.xsd", "EDS_CommNet_Profile_wrapper.xsd", "ADS-net_Device_Profile.xsd",
        "ADS-net_CommNet_Profile.xsd", "FL-net_Device_Profile.xsd", "FL-net_CommNet_Profile.xsd"])


@pytest.mark.parametrize("kind", VALIDATED_KINDS, ids=lambda kind: kind.name)
def test_valid_instances_use_every_declared_element_and_attribute(kind):
    schema = load_schema(kind.xsd)
    declared = {c.local_name for c in schema.iter_components((xmlschema.XsdElement, xmlschema.XsdAttribute))}
    used: set[str] = set()
    valid = sorted((CORPUS / kind.name).glob("valid-*.xml"))
    assert valid, f"no valid instance for {kind.name}"
    for path in valid:
        for element in etree.parse(str(path)).iter(etree.Element):
            used.add(etree.QName(element).localname)
            used.update(element.attrib)
    assert declared - used == set()


@pytest.mark.parametrize("path", sorted(CORPUS.glob("*/valid-*.xml")), ids=lambda p: f"{p.parent.name}/{p.name}")
def test_valid_instances_pass(path):
    report = validate_file(path)
    assert report.kind is not None and report.kind.name == path.parent.name
    assert report.diagnostics == []


@pytest.mark.parametrize("path", sorted(p for p in CORPUS.glob("*/*.xml") if not p.name.startswith("valid-")),
                         ids=lambda p: f"{p.parent.name}/{p.name}")
def test_every_other_instance_reports_its_expected_message(path):
    code, message = expectation(path)
    report = validate_file(path)
    assert [(d.code, message in d.message) for d in report.diagnostics] == [(code, True)], \
        [d.format() for d in report.diagnostics]


def test_every_profile_kind_has_invalid_variants():
    for kind in VALIDATED_KINDS:
        assert list((CORPUS / kind.name).glob("invalid-*.xml")), kind.name


def test_schemas_are_loaded_once_per_process():
    assert load_schema("ADS-net_Device_Profile.xsd") is load_schema("ADS-net_Device_Profile.xsd")
