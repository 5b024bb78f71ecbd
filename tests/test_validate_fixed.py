"""The fixed attribute uses by reference (issue 20 item 4): the fast path never calls a document valid that
the restored schema rejects.

libxml2 ignores ``fixed`` on an attribute use that references a global attribute
(``<attribute ref="SupportedService" fixed="true"/>``, 19 uses in the two CIP schemas);
schemas/derive_xsd10.py (rewrite 4) declares them locally in the XSD 1.0 renditions.
Each use is broken in turn in one valid profile per schema; lxml, xmlschema, ``validate``
and ``xml2eds`` must all refuse it, and the unbroken profile stays valid everywhere.
"""

from __future__ import annotations

import copy
from pathlib import Path

import pytest
from lxml import etree

from conftest import REPO
from edsconv.xml.convert import device_from_profiles
from edsconv.xml.schemas import kind_named, load_schema, load_write_validator
from edsconv.xml.validate import validate_file

XSD = "{http://www.w3.org/2001/XMLSchema}"
VALID = {"cip-device": REPO / "corpus" / "xml" / "cip-device" / "valid-complete.xml",
         "ethernetip-commnet": REPO / "corpus" / "xml" / "ethernetip-commnet" / "valid-complete.xml"}


def fixed_uses(kind: str) -> list[tuple[str, str]]:
    """(operations element, service element) of each fixed ``SupportedService`` use the restored schema declares."""
    schema = etree.parse(str(REPO / "schemas" / kind_named(kind).xsd))
    uses = []
    for use in schema.iter(XSD + "attribute"):
        if use.get("ref") == "SupportedService" and use.get("fixed") is not None:
            names = [e.get("name") for e in use.iterancestors(XSD + "element")]
            uses.append((names[1], names[0]))
    return uses


USES = [(kind, *use) for kind in VALID for use in fixed_uses(kind)]


def test_the_schemas_fix_19_attribute_uses_by_reference():
    assert len(USES) == 19
    assert len(set(USES)) == 19


def base_profile(kind: str) -> etree._ElementTree:
    """The valid profile, its unqualified VendorNote put in a namespace (the renditions' one deviation)."""
    tree = etree.parse(str(VALID[kind]))
    for note in tree.getroot().iter("VendorNote"):
        note.tag = "{urn:x-test:extension}VendorNote"
    return tree


def with_service(kind: str, operations: str, service: str, value: str) -> etree._ElementTree:
    tree = copy.deepcopy(base_profile(kind))
    found = tree.getroot().xpath(f"//{operations}/{service}")
    assert found, f"{VALID[kind].name} has no {operations}/{service} to break"
    found[0].set("SupportedService", value)
    return tree


@pytest.mark.parametrize("kind", VALID)
def test_the_base_profiles_are_valid_for_both_validators(kind):
    tree = base_profile(kind)
    assert load_write_validator(kind_named(kind).xsd).validate(tree)
    assert load_schema(kind_named(kind).xsd).is_valid(tree)


@pytest.mark.parametrize(("kind", "operations", "service"), USES)
def test_each_fixed_use_holds_in_the_fast_path(kind, operations, service):
    xsd = kind_named(kind).xsd
    assert load_write_validator(xsd).validate(with_service(kind, operations, service, "true"))
    broken = with_service(kind, operations, service, "false")
    assert not load_schema(xsd).is_valid(broken)
    assert not load_write_validator(xsd).validate(broken)


@pytest.mark.parametrize(("kind", "operations", "service"), USES[::6])
def test_validate_and_xml2eds_refuse_a_broken_fixed_use(kind, operations, service, tmp_path: Path):
    path = tmp_path / "profile.xml"
    with_service(kind, operations, service, "false").write(str(path))
    codes = [(d.code, "fixed value 'true'" in d.message) for d in validate_file(path).diagnostics]
    assert codes == [("XML003", True)]
    device, diagnostics = device_from_profiles([path])
    assert device is None
    assert [d.code for d in diagnostics] == ["XML003"]
