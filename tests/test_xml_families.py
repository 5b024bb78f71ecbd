"""Each ISO 15745 family is named by its own name, and said not to be validated when edsconv holds no
schema for it (issue 11, defect 9); validate prints its summary line (defect 10)."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner
from lxml import etree

from conftest import REPO
from edsconv.cli import cli
from edsconv.xml.convert import device_from_profiles
from edsconv.xml.validate import FAMILIES, detect_kind, validate_file

XML = REPO / "corpus" / "xml"
FAMILY_FILES = {
    "powerlink-xdd": [XML / "powerlink-xdd" / "container.xml", XML / "powerlink-xdd" / "xdc-configured.xml"],
    "canopen-xdd": [XML / "canopen-xdd" / "device-and-comm.xml"],
    "profinet-gsdml": [XML / "profinet-gsdml" / "device.xml"],
    "iolink-iodd": [XML / "iolink-iodd" / "device.xml"],
}
CIP_FILES = {"cip-device": XML / "cip-device" / "valid-complete.xml",
             "ethernetip-commnet": XML / "ethernetip-commnet" / "valid-complete.xml",
             "adsnet-device": XML / "adsnet-device" / "valid-complete.xml",
             "flnet-commnet": XML / "flnet-commnet" / "valid-complete.xml"}


def test_every_family_has_corpus_files_of_our_own() -> None:
    assert sorted(FAMILY_FILES) == sorted(f.kind for f in FAMILIES)


@pytest.mark.parametrize(("kind", "path"), [(k, p) for k, paths in FAMILY_FILES.items() for p in paths],
                         ids=lambda value: value if isinstance(value, str) else value.name)
def test_a_family_without_schema_is_named_and_not_validated(kind: str, path: Path) -> None:
    report = validate_file(path)
    assert report.kind is not None and report.kind.name == kind
    (diagnostic,) = report.diagnostics
    title = next(f.title for f in FAMILIES if f.kind == kind)
    assert (diagnostic.code, diagnostic.message) == (
        "XML005", f"{title} recognised; not validated (edsconv holds no schema for it)")
    others = [f.title for f in FAMILIES if f.kind != kind]
    assert not any(other in diagnostic.message for other in others)
    result = CliRunner().invoke(cli, ["validate", str(path)])
    assert result.exit_code == 0
    assert result.stderr == "1 file: 0 errors, 0 warnings, 1 note\n"


@pytest.mark.parametrize(("kind", "path"), sorted(CIP_FILES.items()))
def test_the_validated_families_keep_their_kinds(kind: str, path: Path) -> None:
    kind_found = detect_kind(etree.parse(str(path)).getroot())
    assert kind_found is not None and kind_found.name == kind
    assert "XML005" not in [d.code for d in validate_file(path).diagnostics]


@pytest.mark.parametrize(("namespace", "technology"), [
    ("http://www.canopen.org/xml/1.1", "Powerlink"),   # the namespace and the header disagree
    ("http://www.ethernet-powerlink.org", "CANopen"),
    ("urn:example:container", "SERCOS"),                # a container of a family edsconv does not know
    ("", ""),
])
def test_a_container_edsconv_cannot_place_is_called_by_no_family_name(namespace: str, technology: str) -> None:
    xmlns = f' xmlns="{namespace}"' if namespace else ""
    root = etree.fromstring(
        f"<ISO15745ProfileContainer{xmlns}><ISO15745Profile><ProfileHeader><ProfileClassID>Device</ProfileClassID>"
        f"<ISO15745Reference><ProfileTechnology>{technology}</ProfileTechnology></ISO15745Reference>"
        "</ProfileHeader></ISO15745Profile></ISO15745ProfileContainer>")
    assert detect_kind(root) is None


def test_the_canopen_technology_without_namespace_is_canopen_not_powerlink() -> None:
    root = etree.fromstring(
        "<ISO15745ProfileContainer><ISO15745Profile><ProfileHeader><ISO15745Reference>"
        "<ProfileTechnology>CANopen</ProfileTechnology></ISO15745Reference></ProfileHeader></ISO15745Profile>"
        "</ISO15745ProfileContainer>")
    kind = detect_kind(root)
    assert kind is not None and kind.name == "canopen-xdd"


def test_a_cip_technology_in_a_foreign_namespace_is_not_taken_for_cip() -> None:
    root = etree.fromstring(
        '<ISO15745Profile xmlns="http://www.profibus.com/GSDML/2003/11/DeviceProfile"><ProfileHeader>'
        "<ProfileClassID>Device</ProfileClassID><ISO15745Reference><ProfileTechnology>CIP</ProfileTechnology>"
        "</ISO15745Reference></ProfileHeader></ISO15745Profile>")
    assert detect_kind(root) is None


@pytest.mark.parametrize("path", [FAMILY_FILES["iolink-iodd"][0], CIP_FILES["flnet-commnet"]])
def test_xml2eds_names_the_family_it_does_not_read(path: Path) -> None:
    device, diagnostics = device_from_profiles([path])
    assert device is None
    refusal = diagnostics[-1]
    assert refusal.code == "XML102"
    assert refusal.message.endswith(("IO-Link device description (IODD)", "flnet-commnet profile"))


def test_validate_prints_the_summary_line_on_success_and_on_errors() -> None:
    good = CliRunner().invoke(cli, ["validate", str(CIP_FILES["cip-device"]), str(CIP_FILES["adsnet-device"])])
    assert (good.exit_code, good.stdout, good.stderr) == (0, "", "2 files: 0 errors, 0 warnings, 0 notes\n")
    bad = CliRunner().invoke(cli, ["validate", str(XML / "broken" / "not-well-formed.xml")])
    assert bad.exit_code == 1 and bad.stderr == "1 file: 1 error, 0 warnings, 0 notes\n"
    assert CliRunner().invoke(cli, ["validate", "--format", "json", str(CIP_FILES["cip-device"])]).stderr == ""


def test_a_value_the_validator_cannot_check_is_xml007_not_a_traceback() -> None:
    # found by fuzzing xml2eds: xmlschema raised OverflowError for a ProfileDate of a 40-digit year
    path = REPO / "tests" / "fuzz_regressions" / "xml2eds" / "profile_date_of_a_40_digit_year.xml"
    assert [d.code for d in validate_file(path).diagnostics] == ["XML007"]
    assert [d.code for d in validate_file(CIP_FILES["cip-device"]).diagnostics] == []
    device, diagnostics = device_from_profiles([path])
    assert device is None and [d.code for d in diagnostics] == ["XML007"]
