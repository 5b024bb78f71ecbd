"""The as-printed schema variants (schemas/as_printed/) and ``edsconv validate --as-printed``.

Our restored schemas deviate from the listings in their wildcards (ERRATA.md, deviations
wildcard-lax and wildcard-bounds). The variants take both deviations back: proven here,
they are current, each of their ``xsd:any`` has the attributes the listing prints (with the
damage repair ``#any`` -> ``##any``), and nothing else differs from the restored schema.
``validate --as-printed`` uses them and tells a document that needs the deviations.
"""

from __future__ import annotations

import importlib.util
import json

import pytest
from click.testing import CliRunner

from conftest import REPO
from edsconv.cli import cli
from edsconv.resources import data_dir
from edsconv.xml.schemas import AS_PRINTED, as_printed, kind_named, load_schema
from edsconv.xml.validate import validate_file
from test_schemas_errata import LISTINGS, tags

SEED = REPO.parent / "shared" / "seeds" / "001_4555913419fc9159.txt"
CORPUS_XML = REPO / "corpus" / "xml"


def derive_module():
    spec = importlib.util.spec_from_file_location("derive_as_printed", data_dir("schemas") / "derive_as_printed.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


VARIANTS = sorted(derive_module().PRINTED_SINGLE)


def test_variants_are_current():
    """Edit a restored schema with wildcards without running schemas/derive_as_printed.py and this fails."""
    assert derive_module().stale() == []
    assert sorted(p.name for p in (data_dir("schemas") / AS_PRINTED).glob("*.xsd")) == VARIANTS


def test_every_schema_with_a_wildcard_has_a_variant():
    with_wildcards = sorted(p.name for p in data_dir("schemas").glob("*.xsd") if "<xsd:any" in p.read_text())
    assert with_wildcards == VARIANTS


def wildcards(located) -> list[tuple[int, dict[str, str]]]:
    return [(item.line, dict(item.tag[2])) for item in located if item.tag[:2] == ("open", "any")]


@pytest.mark.parametrize("xsd", VARIANTS)
def test_wildcards_are_as_the_listing_prints_them(xsd):
    if not SEED.is_file():
        pytest.skip(f"spec text {SEED} not available")
    first, last = LISTINGS[xsd]
    listing = "\n".join(SEED.read_text(encoding="utf-8").split("\n")[first - 1:last])
    printed = wildcards(tags(listing, first))
    ours = wildcards(tags((data_dir("schemas") / AS_PRINTED / xsd).read_text(encoding="utf-8")))
    assert len(printed) == len(ours)
    for (line, printed_attributes), (_, our_attributes) in zip(printed, ours, strict=True):
        if printed_attributes.get("namespace") == "#any":  # the damage repair of ERRATA.md
            printed_attributes["namespace"] = "##any"
        assert our_attributes == printed_attributes, f"seed line {line}"


@pytest.mark.parametrize("xsd", VARIANTS)
def test_only_the_wildcards_differ_from_the_restored_schema(xsd):
    def without_wildcards(text: str) -> list:
        return [item.tag for item in tags(text) if item.tag[1] != "any"]

    restored = (data_dir("schemas") / xsd).read_text(encoding="utf-8")
    variant = (data_dir("schemas") / AS_PRINTED / xsd).read_text(encoding="utf-8")
    changed = restored.replace('schemaLocation="', 'schemaLocation="../')
    assert without_wildcards(variant) == without_wildcards(changed)


def test_kinds_without_wildcards_are_validated_as_they_are():
    assert as_printed(kind_named("adsnet-device")) == kind_named("adsnet-device")
    assert as_printed(kind_named("cip-device")).xsd == "as_printed/CIP_Device_Profile.xsd"
    assert load_schema("as_printed/CIP_Device_Profile.xsd").XSD_VERSION == "1.1"


def test_a_profile_without_extensions_where_the_listing_prints_one_is_invalid_as_printed():
    """The wrapper's DeviceFunction is printed as exactly one element of a strict wildcard: an empty one
    (which eds2xml writes, and the hand-written wrappers use) is valid here, invalid as printed."""
    path = CORPUS_XML / "handwritten" / "eds-device-wrapper" / "fileinfo.xml"
    assert validate_file(path).diagnostics == []
    report = validate_file(path, printed=True)
    assert report.kind is not None and report.kind.xsd == "as_printed/EDS_Device_Profile_wrapper.xsd"
    assert [(d.code, d.line, "DeviceFunction" in d.message) for d in report.diagnostics] == [("XML003", 19, True)]


def test_an_undeclared_extension_element_is_invalid_as_printed():
    """A strict wildcard takes only elements the schema declares globally: the undeclared
    Connector of ENPhysicalLayer and LinkAddress of PortSpecific are errors as printed."""
    path = CORPUS_XML / "ethernetip-commnet" / "valid-complete.xml"
    assert validate_file(path).diagnostics == []
    messages = [d.message for d in validate_file(path, printed=True).diagnostics]
    assert len(messages) == 2 and "'Connector'" in messages[0] and "'LinkAddress'" in messages[1]


def test_a_profile_valid_as_printed_stays_valid():
    """A network profile with no extension element: the wildcards there are optional as printed."""
    path = CORPUS_XML / "handwritten" / "ethernetip-commnet" / "services_without_supportedservice.xml"
    assert validate_file(path, printed=True).diagnostics == []


def test_command_line_option():
    path = CORPUS_XML / "handwritten" / "eds-device-wrapper" / "fileinfo.xml"
    runner = CliRunner()
    assert runner.invoke(cli, ["validate", str(path)], standalone_mode=False).return_value == 0
    result = runner.invoke(cli, ["validate", "--as-printed", "--format", "json", str(path)], standalone_mode=False)
    assert result.return_value == 1
    (report,) = json.loads(result.output)["files"]
    assert report["schema"] == "as_printed/EDS_Device_Profile_wrapper.xsd"
    assert [d["code"] for d in report["diagnostics"]] == ["XML003"]
