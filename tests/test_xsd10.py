"""The XSD 1.0 renditions of the two XSD 1.1 profile schemas (schemas/xsd10/) against the restored 1.1 schemas.

edsconv validates what it writes with lxml against the renditions; the restored
schemas, read by xmlschema as XSD 1.1, stay the reference. Proven here:

- the renditions are what schemas/derive_xsd10.py derives from the 1.1 files now;
- they are XSD 1.0 for two implementations (libxml2 and xmlschema's 1.0 reader);
- on every instance of corpus/xml, on mutants of the valid ones and on every
  document eds2xml writes for corpus/ and the real files, lxml accepts only what
  the 1.1 schema accepts (never more), and rejects what it rejects; the only
  documents where they differ are the deviation of schemas/xsd10/README.md: an
  element without namespace that the 1.1 schema gives to a competing wildcard;
- eds2xml's documents never hold such an element, so their verdicts agree.
"""

from __future__ import annotations

import copy
import importlib.util
from pathlib import Path

import pytest
import xmlschema
from lxml import etree

import edsconv
from conftest import REAL_EDS, REPO
from edsconv.resources import data_dir
from edsconv.xml.commnet import commnet_profile
from edsconv.xml.common import Header, InvalidProfile, serialise
from edsconv.xml.device_write import device_profile
from edsconv.xml.schemas import PROFILE_KINDS, kind_named, load_schema, load_write_validator, write_validator_path

CORPUS_XML = REPO / "corpus" / "xml"
RENDERED = [kind for kind in PROFILE_KINDS if kind.xsd_version == "1.1"]
VALIDATED = [kind for kind in PROFILE_KINDS if kind.xsd]
OWN_EDS = sorted(p for p in (REPO / "corpus").rglob("*.eds") if "broken" not in p.parts)
FOREIGN = "urn:x-test:extension"


def derive_module():
    spec = importlib.util.spec_from_file_location("derive_xsd10", data_dir("schemas") / "derive_xsd10.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def verdicts(kind_name: str, root: etree._Element) -> tuple[bool, bool]:
    """(restored schema by xmlschema, write validator by lxml) on ``root``."""
    xsd = kind_named(kind_name).xsd
    return load_schema(xsd).is_valid(root), load_write_validator(xsd).validate(root)


def declared_names(kind_name: str) -> set[str]:
    """Every element name the restored schema declares, globally or locally."""
    schema = load_schema(kind_named(kind_name).xsd)
    return {component.local_name for component in schema.maps.iter_components(xmlschema.XsdElement)}


def qualify_undeclared(root: etree._Element, kind_name: str) -> etree._Element:
    """A copy of ``root`` whose elements without namespace that the schema never declares have a namespace.

    Such elements can only stand in a wildcard: this takes a document out of the deviation.
    """
    names = declared_names(kind_name)
    result = copy.deepcopy(root)
    for element in result.iter(etree.Element):
        if not element.tag.startswith("{") and element.tag not in names:
            element.tag = f"{{{FOREIGN}}}{element.tag}"
    return result


def corpus_documents() -> list[tuple[Path, str]]:
    paths = sorted(p for p in CORPUS_XML.glob("*/*.xml") if p.parent.name not in ("broken", "security"))
    return [(path, kind.name) for path in paths for kind in VALIDATED]


def test_renditions_are_current():
    """Edit a 1.1 schema without running schemas/derive_xsd10.py and this fails."""
    assert derive_module().stale() == []


@pytest.mark.parametrize("kind", RENDERED, ids=lambda kind: kind.name)
def test_renditions_are_xsd10(kind):
    """libxml2 loads the rendition (it rejects any content model that is not deterministic), and so does
    xmlschema's XSD 1.0 reader, which checks Unique Particle Attribution on its own."""
    path = write_validator_path(kind.xsd)
    assert path.parent.name == "xsd10"
    etree.XMLSchema(etree.parse(str(path)))
    xmlschema.XMLSchema10(str(path))


def test_derivation_refuses_shapes_it_does_not_know(tmp_path):
    module = derive_module()
    source = (data_dir("schemas") / "CIP_Device_Profile.xsd").read_text(encoding="utf-8")
    changed = source.replace('<xsd:assert test="MemberSize or MemberReference or VariantReference"/>',
                             '<xsd:assert test="count(MemberSize) = 1"/>')
    assert changed != source
    target = tmp_path / "changed.xsd"
    target.write_text(changed, encoding="utf-8")
    with pytest.raises(module.SchemaShapeError, match="assertion"):
        module.derive(target)


@pytest.mark.parametrize(("path", "kind_name"), corpus_documents(),
                         ids=lambda value: value if isinstance(value, str) else f"{value.parent.name}/{value.name}")
def test_corpus_instances(path, kind_name):
    """Every corpus/xml instance, against every validated kind (lxml reads the 1.0 schemas directly)."""
    root = etree.parse(str(path)).getroot()
    reference, fast = verdicts(kind_name, root)
    assert fast <= reference, "the write validator accepted what the reference rejects"
    if fast != reference:
        assert kind_named(kind_name).xsd_version == "1.1"
        qualified = qualify_undeclared(root, kind_name)
        assert etree.tostring(qualified) != etree.tostring(root), "a difference outside the deviation"
        root = qualified
        reference, fast = verdicts(kind_name, root)
    assert fast == reference


def test_corpus_deviation_is_the_vendor_note():
    """The two valid device profiles of the corpus put an unqualified <VendorNote> in a competing wildcard:
    the 1.1 schema accepts them, the rendition does not; with a namespace both accept."""
    for name in ("valid-complete.xml", "valid-chassis.xml"):
        root = etree.parse(str(CORPUS_XML / "cip-device" / name)).getroot()
        assert verdicts("cip-device", root) == (True, False)
        assert "VendorNote" in str(load_write_validator(kind_named("cip-device").xsd).error_log.last_error)
        assert verdicts("cip-device", qualify_undeclared(root, "cip-device")) == (True, True)


CHANGES = ("delete", "duplicate", "qualified", "unqualified", "earlier")


def mutants(root: etree._Element, every_change: bool = False):
    """(description, mutant, element a 1.1 wildcard may take): one change per element, the kinds in turn
    (all five per element with ``every_change``, as for the counts in schemas/xsd10/README.md)."""
    count = sum(1 for _ in root.iter(etree.Element)) - 1
    for index in range(count):
        for change in CHANGES if every_change else CHANGES[index % 5:index % 5 + 1]:
            mutant = copy.deepcopy(root)
            target = list(mutant.iter(etree.Element))[index + 1]
            added = None
            if change == "delete":
                target.getparent().remove(target)
            elif change == "duplicate":
                added = copy.deepcopy(target)
                target.addnext(added)
            elif change in ("qualified", "unqualified"):
                added = etree.Element(f"{{{FOREIGN}}}Extra" if change == "qualified" else "Extra")
                target.addnext(added)
            elif target.getprevious() is not None:
                target.getprevious().addprevious(target)
            else:
                continue
            yield f"{change} {target.tag} #{index}", mutant, added


@pytest.mark.parametrize("kind_name", [kind.name for kind in RENDERED])
def test_mutants_of_the_valid_corpus_instances(kind_name):
    """Delete, duplicate, move each element, add an extension element after it: the verdicts agree, except
    where the 1.1 schema gives an added element without namespace to a wildcard (the deviation); there the
    rendition rejects, and both accept once that element has a namespace. xmlschema's 1.0 reading of the
    rendition agrees with lxml on every mutant (a check on libxml2 itself)."""
    base = qualify_undeclared(etree.parse(str(CORPUS_XML / kind_name / "valid-complete.xml")).getroot(), kind_name)
    rendition_by_xmlschema = xmlschema.XMLSchema10(str(write_validator_path(kind_named(kind_name).xsd)))
    compared = deviations = 0
    for description, mutant, added in mutants(base):
        reference, fast = verdicts(kind_name, mutant)
        assert rendition_by_xmlschema.is_valid(mutant) == fast, description
        compared += 1
        if fast != reference:
            assert (reference, fast) == (True, False), description
            assert added is not None and not added.tag.startswith("{"), description
            added.tag = f"{{{FOREIGN}}}{added.tag}"
            assert verdicts(kind_name, mutant) == (True, True), description
            deviations += 1
    assert compared > 100 and 0 < deviations < compared // 10


def eds2xml_documents(path: Path) -> list[tuple[str, etree._Element]]:
    device, _ = edsconv.analyse(edsconv.parse(path.read_bytes()))
    header = Header.derive(device)
    return [("cip-device", etree.fromstring(etree.tostring(device_profile(device, header)))),
            ("ethernetip-commnet", etree.fromstring(etree.tostring(commnet_profile(device, header))))]


def assert_outside_the_deviation(root: etree._Element) -> None:
    """No element without namespace inside an extension element (libxml2 would validate it laxly against a
    global declaration of the same name, xmlschema would not: README.md, "libxml2 and xmlschema")."""
    for element in root.iter(etree.Element):
        parent = element.getparent()
        if not element.tag.startswith("{"):
            assert parent is None or not parent.tag.startswith("{"), element.tag


@pytest.mark.parametrize("path", OWN_EDS + REAL_EDS, ids=lambda p: p.name)
def test_eds2xml_documents_get_the_same_verdicts(path):
    for kind_name, root in eds2xml_documents(path):
        assert_outside_the_deviation(root)
        assert [e.tag for e in qualify_undeclared(root, kind_name).iter(f"{{{FOREIGN}}}*")] == []
        assert verdicts(kind_name, root) == (True, True)


def test_serialise_writes_a_valid_document_the_rendition_rejects():
    """The deviation costs speed, never a valid document: the restored schema decides."""
    root = etree.parse(str(CORPUS_XML / "cip-device" / "valid-complete.xml")).getroot()
    assert verdicts("cip-device", root) == (True, False)
    assert etree.fromstring(serialise(root, "cip-device")).find(".//VendorNote") is not None


def test_serialise_reports_an_invalid_document_as_validate_words_it():
    root = etree.parse(str(CORPUS_XML / "cip-device" / "invalid-eds-revision.xml")).getroot()
    with pytest.raises(InvalidProfile) as raised:
        serialise(root, "cip-device")
    schema = load_schema(kind_named("cip-device").xsd)
    expected = [f"{error.path}: {error.reason}" for error in schema.iter_errors(root)]
    assert raised.value.problems == expected and expected
    assert any("Revision" in problem for problem in raised.value.problems)
