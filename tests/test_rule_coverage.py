"""Every rule has a test that triggers it and one that does not; this file holds the few that
no module's own tests name, and a guard that keeps it so for new rules."""

from __future__ import annotations

import functools
from pathlib import Path

from click.testing import CliRunner

import edsconv
from edsconv.xml import validate
from edsconv.cli import cli
from edsconv.report import all_rules
from edsconv.xml.safe import read_xml

from conftest import REPO

TESTS = Path(__file__).resolve().parent


def codes(diagnostics) -> list[str]:
    return [d.code for d in diagnostics]


def test_every_rule_code_is_named_by_a_test():
    text = "".join(path.read_text(encoding="utf-8") for path in TESTS.glob("test_*.py"))
    assert [rule.code for rule in all_rules() if rule.code not in text] == []


def test_eds017_braces_nested_too_deep():
    deep = edsconv.parse("[S]\nA = " + "{" * 65 + "1" + "}" * 65 + ";\n")
    assert codes(deep.diagnostics) == ["EDS017"]
    assert deep.sections[0].unparsed and not deep.sections[0].entries
    assert codes(edsconv.parse("[S]\nA = " + "{" * 64 + "1" + "}" * 64 + ";\n").diagnostics) == []


def test_eds110_url_without_a_scheme():
    def url_codes(url: str) -> list[str]:
        return codes(edsconv.build(edsconv.parse(f'[File]\nHomeURL = "{url}";\n')).diagnostics)

    assert url_codes("www.example.com") == ["EDS110"]
    assert url_codes("htts://www.example.com") == ["EDS110"]
    assert url_codes("https://www.example.com") == []
    assert url_codes("ftp://example.com/eds") == []


def test_xml004_unknown_profile_kind():
    assert codes(validate.validate_file(REPO / "corpus" / "xml" / "broken" / "unknown-kind.xml").diagnostics) == [
        "XML004"]
    assert codes(validate.validate_file(REPO / "corpus" / "xml" / "cip-device" / "valid-complete.xml")
                 .diagnostics) == []


def test_xml006_file_too_large(monkeypatch):
    path = REPO / "corpus" / "xml" / "cip-device" / "valid-complete.xml"
    monkeypatch.setattr(validate, "read_xml", functools.partial(read_xml, max_bytes=100))
    assert codes(validate.validate_file(path).diagnostics) == ["XML006"]
    monkeypatch.setattr(validate, "read_xml", read_xml)
    assert codes(validate.validate_file(path).diagnostics) == []


def test_xml102_profile_that_describes_no_eds():
    flnet = CliRunner().invoke(cli, ["xml2eds", str(REPO / "corpus" / "xml" / "flnet-device" / "valid-complete.xml")])
    assert flnet.exit_code == 1 and "XML102" in flnet.output
    cip = CliRunner().invoke(cli, ["xml2eds", str(REPO / "corpus" / "xml" / "cip-device" / "valid-complete.xml")])
    assert cip.exit_code == 0 and "XML102" not in cip.output
