"""``edsconv validate``: kind detection, output formats, exit codes, start-up time."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner
from lxml import etree

from edsconv.cli import cli
from edsconv.xml.validate import detect_kind

REPO = Path(__file__).resolve().parents[1]
CORPUS = REPO / "corpus" / "xml"


def run(*args: str):
    return CliRunner().invoke(cli, ["validate", *args], standalone_mode=False)


def header(profile_class: str, technology: str) -> etree._Element:
    return etree.fromstring(
        f"<ISO15745Profile><ProfileHeader><ProfileClassID>{profile_class}</ProfileClassID><ISO15745Reference>"
        f"<ProfileTechnology> {technology} </ProfileTechnology></ISO15745Reference></ProfileHeader></ISO15745Profile>")


@pytest.mark.parametrize(("profile_class", "technology", "kind"), [
    ("Device", "CIP", "cip-device"),
    ("Device", "EDS", "eds-device-wrapper"),
    ("CommunicationNetwork", "EtherNet/IP", "ethernetip-commnet"),
    ("CommunicationNetwork", "EDS", "eds-commnet-wrapper"),
    ("Device", "ADS-net", "adsnet-device"),
    ("CommunicationNetwork", "ADS-net", "adsnet-commnet"),
    ("Device", "FL-net", "flnet-device"),
    ("CommunicationNetwork", "fl-net", "flnet-commnet"),
])
def test_kind_detected_from_header(profile_class, technology, kind):
    assert detect_kind(header(profile_class, technology)).name == kind


def test_unknown_header_and_foreign_roots_have_no_kind():
    assert detect_kind(header("Device", "PROFINET")) is None
    assert detect_kind(etree.fromstring("<html/>")) is None


def test_clean_files_print_only_the_summary_and_exit_0():
    result = run(str(CORPUS / "adsnet-device" / "valid-complete.xml"), str(CORPUS / "cip-device" / "valid-chassis.xml"))
    assert (result.return_value, result.stdout, result.stderr) == (0, "", "2 files: 0 errors, 0 warnings, 0 notes\n")


def test_problems_are_reported_as_path_line_col_code_message_xpath_clause():
    path = CORPUS / "flnet-device" / "invalid-node-number.xml"
    result = run(str(path))
    assert result.return_value == 1
    assert result.stdout == (
        f"{path}:40:11: error: XML003 value has to be greater or equal than 1 "
        "(at /ISO15745Profile/ProfileBody/DeviceManager/DeviceManager-Attributes/CommuServiceManager/DM-NodeNumber) "
        "[ISO 15745-4 B.1.5]\n")


def test_json_output_lists_files_with_kind_schema_and_summary():
    valid = CORPUS / "ethernetip-commnet" / "valid-complete.xml"
    invalid = CORPUS / "ethernetip-commnet" / "invalid-interface-type.xml"
    result = run("--format", "json", str(valid), str(invalid))
    report = json.loads(result.output)
    assert result.return_value == 1
    assert [(f["profile"], f["schema"], len(f["diagnostics"])) for f in report["files"]] == [
        ("ethernetip-commnet", "ENet_CommNet_Profile.xsd", 0), ("ethernetip-commnet", "ENet_CommNet_Profile.xsd", 1)]
    assert report["files"][1]["diagnostics"][0]["code"] == "XML003"
    assert report["summary"] == {"files": 2, "errors": 1, "warnings": 0, "notes": 0}


def test_schema_option_forces_a_schema():
    path = CORPUS / "adsnet-device" / "valid-complete.xml"
    result = run("--schema", "FL-net_Device_Profile.xsd", "--format", "json", str(path))
    report = json.loads(result.output)["files"][0]
    assert (result.return_value, report["profile"], report["schema"]) == (
        1, "flnet-device", "FL-net_Device_Profile.xsd")
    assert run("--schema", "adsnet-device", str(path)).return_value == 0


def test_powerlink_xdd_is_recognised_as_info_and_exits_0():
    result = run(str(CORPUS / "powerlink-xdd" / "container.xml"))
    assert result.return_value == 0
    assert "XML005 POWERLINK device description (XDD/XDC) recognised; not validated" in result.output


def test_unsafe_and_malformed_files_are_diagnostics_not_tracebacks():
    result = run(str(CORPUS / "security" / "xxe-file.xml"), str(CORPUS / "broken" / "not-well-formed.xml"))
    assert result.return_value == 1 and result.exception is None
    assert "xxe-file.xml:4:3: error: XML002 DOCTYPE declares entities" in result.output
    assert "not-well-formed.xml:6:19: error: XML001 not well-formed" in result.output


def test_missing_file_exits_2():
    completed = subprocess.run([sys.executable, "-m", "edsconv", "validate", "no-such-file.xml"],
                               capture_output=True, text=True, env=_env())
    assert completed.returncode == 2
    assert "no-such-file.xml" in completed.stderr


def _env() -> dict[str, str]:
    return {**os.environ, "PYTHONPATH": os.pathsep.join([str(REPO / "src"), os.environ.get("PYTHONPATH", "")])}


def test_validate_runs_as_a_module_in_a_fresh_process():
    """A fresh process builds or unpickles the schema it needs (start-up time is measured in benchmarks/)."""
    path = CORPUS / "eds-commnet-wrapper" / "valid-complete.xml"
    completed = subprocess.run([sys.executable, "-m", "edsconv", "validate", str(path)], env=_env(),
                               capture_output=True, text=True)
    assert completed.returncode == 0, completed.stderr
    assert completed.stdout == ""


def test_a_content_model_error_points_at_the_offending_child_not_its_parent(tmp_path: Path):
    text = (CORPUS / "cip-device" / "valid-chassis.xml").read_text(encoding="utf-8")
    lines = text.splitlines()
    date_line = next(i for i, line in enumerate(lines) if "<ProfileDate>" in line)
    lines.insert(date_line + 1, "")
    lines.insert(date_line + 2, "      <Bogus/>")
    path = tmp_path / "extra-child.xml"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    result = run(str(path))
    assert result.return_value == 1
    # the header starts 6 lines above; the child stands on line date_line + 3, column 7
    assert result.stdout == (
        f"{path}:{date_line + 3}:7: error: XML003 <Bogus> is not allowed here (child 7 of <ProfileHeader>); the "
        "schema expects <ISO15745Reference> (at /ISO15745Profile/ProfileHeader/Bogus) [ISO 15745-4 C.2.1.3.3]\n")


def test_a_bad_date_says_what_the_schema_expects_and_names_no_python_class(tmp_path: Path):
    text = (CORPUS / "cip-device" / "valid-chassis.xml").read_text(encoding="utf-8")
    path = tmp_path / "us-date.xml"
    path.write_text(text.replace("<ProfileDate>2024-05-01</ProfileDate>", "<ProfileDate>05-01-2024</ProfileDate>"),
                    encoding="utf-8")
    result = run(str(path))
    assert result.return_value == 1
    assert "'05-01-2024' is not a valid xsd:date (YYYY-MM-DD) (at /ISO15745Profile/ProfileHeader/ProfileDate)" \
        in result.output
    assert "class" not in result.output and "elementpath" not in result.output


def test_no_message_over_the_corpus_shows_python_internals():
    result = run(*map(str, sorted(CORPUS.glob("*/*.xml"))))
    assert result.return_value == 1
    for internal in ("<class", "elementpath", "Xsd11", "XsdKey", "',)"):
        assert internal not in result.output
