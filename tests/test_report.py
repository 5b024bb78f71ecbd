"""The shared output formats: text, json, SARIF 2.1.0 and GitHub workflow annotations."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from conftest import REPO
from edsconv import report, rule_docs
from edsconv.diagnostics import Diagnostic, Severity
from edsconv.report import FileReport
from edsconv.resources import data_dir


def diagnostic(code: str, message: str, line: int, column: int, severity: Severity, path: str) -> Diagnostic:
    return Diagnostic(code, message, line, column, path, severity, "C.4.1.2.2")


def sample(root: Path) -> list[FileReport]:
    bad = str(root / "dir" / "bad file.eds")
    return [
        FileReport(bad, [
            diagnostic("EDS001", "unexpected 'x': expected ';'", 3, 7, Severity.ERROR, bad),
            diagnostic("EDS005", "not plain ASCII", 9, 1, Severity.WARNING, bad),
            diagnostic("XML005", "a note", 1, 1, Severity.INFO, bad),
        ]),
        FileReport(str(root / "good.eds")),
        FileReport("/elsewhere/broken.eds", [Diagnostic("EDS000", "cannot read the file: Permission denied",
                                                        path="/elsewhere/broken.eds")], error="cannot read"),
    ]


def test_text_is_path_line_column_severity_code_message_clause(tmp_path: Path):
    lines = report.format_text(sample(tmp_path)).splitlines()  # what verify prints (lint: report_text)
    assert lines[0] == f"{tmp_path}/dir/bad file.eds:3:7: error: EDS001 unexpected 'x': expected ';' [C.4.1.2.2]"
    assert lines[1].startswith(f"{tmp_path}/dir/bad file.eds:9:1: warning: EDS005 ")
    assert lines[2].startswith(f"{tmp_path}/dir/bad file.eds:1:1: info: XML005 ")
    assert len(lines) == 4


def test_json_shape_is_files_with_diagnostics_and_a_summary(tmp_path: Path):
    document = json.loads(report.format_json(sample(tmp_path)))
    assert set(document) == {"files", "summary"}
    assert [f["path"] for f in document["files"]] == [r.path for r in sample(tmp_path)]
    first = document["files"][0]["diagnostics"][0]
    assert {"code", "severity", "line", "column", "message", "clause"} <= set(first)
    assert first["severity"] == "error"
    assert document["files"][2]["error"] == "cannot read"
    assert document["summary"] == {"files": 3, "errors": 2, "warnings": 1, "notes": 1, "hidden_notes": 0,
                                   "fixable": 0, "fixed": 0}


SARIF_SCHEMA = json.loads((REPO / "tests" / "sarif" / "sarif-2.1.0.json").read_text(encoding="utf-8"))


def validate_sarif(document: dict) -> None:
    """Valid by the SARIF 2.1.0 JSON schema, and carrying what GitHub code scanning requires of an upload
    (its "SARIF support" page: tool.driver.name, a rule per ruleId with its descriptions and help,
    results with message text, a location with an artifact uri and a start line, and fingerprints)."""
    import jsonschema

    jsonschema.Draft202012Validator(SARIF_SCHEMA, format_checker=jsonschema.FormatChecker()).validate(document)
    assert document["version"] == "2.1.0"
    assert document["$schema"].endswith("sarif-2.1.0.json")
    (run,) = document["runs"]
    driver = run["tool"]["driver"]
    assert driver["name"] == "edsconv" and driver["version"]
    rule_ids = [r["id"] for r in driver["rules"]]
    assert len(rule_ids) == len(set(rule_ids))
    for described in driver["rules"]:
        assert described["shortDescription"]["text"] and described["fullDescription"]["text"]
        assert described["help"]["text"] and described["help"]["markdown"]
        assert described["defaultConfiguration"]["level"] in {"error", "warning", "note"}
        assert len(described["shortDescription"]["text"]) <= 1024
    for result in run["results"]:
        assert result["ruleId"] in rule_ids
        assert driver["rules"][result["ruleIndex"]]["id"] == result["ruleId"]
        assert result["level"] in {"error", "warning", "note"}
        assert result["message"]["text"]
        assert result["partialFingerprints"]["primaryLocationLineHash"]
        (location,) = result["locations"]
        artifact = location["physicalLocation"]["artifactLocation"]
        assert artifact["uri"] and " " not in artifact["uri"]
        if "uriBaseId" in artifact:
            assert artifact["uriBaseId"] in run["originalUriBaseIds"]
            assert not artifact["uri"].startswith("/")
        region = location["physicalLocation"]["region"]
        assert region["startLine"] >= 1 and region.get("startColumn", 1) >= 1


def test_sarif_meets_the_schema_essentials(tmp_path: Path):
    document = report.sarif_document(sample(tmp_path), root=tmp_path)
    validate_sarif(document)
    results = document["runs"][0]["results"]
    assert [r["level"] for r in results] == ["error", "warning", "note", "error"]
    first = results[0]["locations"][0]["physicalLocation"]
    assert first["artifactLocation"] == {"uri": "dir/bad%20file.eds", "uriBaseId": "%SRCROOT%"}
    assert first["region"] == {"startLine": 3, "startColumn": 7}
    outside = results[3]["locations"][0]["physicalLocation"]
    assert outside == {"artifactLocation": {"uri": "file:///elsewhere/broken.eds"}, "region": {"startLine": 1}}
    assert document["runs"][0]["originalUriBaseIds"]["%SRCROOT%"]["uri"] == tmp_path.as_uri() + "/"


def test_sarif_lists_every_registered_rule():
    rules = report.sarif_document([])["runs"][0]["tool"]["driver"]["rules"]
    assert [r["id"] for r in rules] == [r.code for r in report.all_rules()]
    assert {"EDS000", "EDS001", "XML003"} <= {r["id"] for r in rules}


def test_sarif_rules_carry_their_documentation_and_the_declared_urls():
    driver = report.sarif_document([])["runs"][0]["tool"]["driver"]
    by_id = {r["id"]: r for r in driver["rules"]}
    eds002 = by_id["EDS002"]
    assert eds002["fullDescription"]["text"].startswith("An entry does not end with `;`.")
    assert eds002["help"]["markdown"] == rule_docs.rule_section(report.all_rules()[2])
    assert "Fix: safe" in eds002["help"]["text"] and "```" not in eds002["help"]["text"]
    assert eds002["properties"]["fix"] == "safe"
    # pyproject.toml's [project.urls] Repository, read from the installed metadata
    assert driver["informationUri"] == report.project_url() == "https://edsconv.invalid/edsconv"
    # no public repository (the .invalid placeholder): the link opens the installed docs/rules.md
    assert eds002["helpUri"] == (data_dir("docs") / "rules.md").as_uri() + "#eds002"  # the checkout's or the wheel's


def test_sarif_fingerprints_survive_moved_lines_and_tell_results_on_one_line_apart(tmp_path: Path):
    """Three EDS201 on line 1 get three fingerprints; lines inserted above EDS103 keep every fingerprint."""
    text = "$ header\n[Params]\n        Param1 = 0,,,0x0000,0xC6,1,\"A\",\"\",\"\",0,255,07;\n"
    path = tmp_path / "moved.eds"

    def fingerprints() -> dict[str, list[str]]:
        from edsconv.lint import lint_file

        results = report.sarif_document([lint_file(str(path))], root=tmp_path)["runs"][0]["results"]
        found: dict[str, list[str]] = {}
        for r in results:
            found.setdefault(r["ruleId"], []).append(r["partialFingerprints"]["primaryLocationLineHash"])
        return found

    path.write_text(text, encoding="ascii")
    before = fingerprints()
    assert len(before["EDS201"]) == 3 == len(set(before["EDS201"]))
    path.write_text(text.replace("[Params]", "$ one\n$ two\n[Params]"), encoding="ascii")
    assert fingerprints() == before
    path.write_text(text.replace("07;", "08;"), encoding="ascii")  # the line itself changed
    assert fingerprints()["EDS103"] != before["EDS103"]


def test_sarif_region_ends_where_the_diagnostic_has_a_span(tmp_path: Path):
    d = Diagnostic("EDS099", "unused", 4, 20, "a.eds", Severity.WARNING, "edsconv", 4, 26)
    document = report.sarif_document([FileReport("a.eds", [d])], root=Path.cwd())
    validate_sarif(document)
    region = document["runs"][0]["results"][0]["locations"][0]["physicalLocation"]["region"]
    assert region == {"startLine": 4, "startColumn": 20, "endLine": 4, "endColumn": 26}


def test_sarif_help_uri_points_at_the_rule_heading_in_docs(monkeypatch):
    monkeypatch.setattr(report, "project_url", lambda: "https://example.org/edsconv")
    driver = report.sarif_document([])["runs"][0]["tool"]["driver"]
    assert driver["informationUri"] == "https://example.org/edsconv"
    by_id = {r["id"]: r for r in driver["rules"]}
    assert by_id["EDS001"]["helpUri"] == "https://example.org/edsconv/blob/main/docs/rules.md#eds001"


def test_github_annotations_errors_first_then_warnings_then_notes_and_a_summary(tmp_path: Path):
    lines = report.format_github(sample(tmp_path), root=tmp_path).splitlines()
    assert lines[0] == ("::error file=dir/bad file.eds,line=3,col=7,title=EDS001::"
                        "unexpected 'x': expected ';' [C.4.1.2.2]")
    # no line: the annotation is on 1:1, as in SARIF; errors of later files still come before any warning
    assert lines[1] == ("::error file=/elsewhere/broken.eds,line=1,col=1,title=EDS000::"
                        "cannot read the file: Permission denied")
    assert lines[2].startswith("::warning file=dir/bad file.eds,line=9,col=1,title=EDS005::")
    assert lines[3].startswith("::notice ")
    assert lines[4] == "edsconv: 3 files: 2 errors, 1 warning, 1 note"
    assert len(lines) == 5


def test_github_annotation_carries_the_end_of_a_span():
    d = Diagnostic("EDS103", "leading zeros", 4, 20, "a.eds", Severity.ERROR, "", 4, 25)
    assert report.format_github([FileReport("a.eds", [d])]).splitlines()[0] == \
        "::error file=a.eds,line=4,col=20,endColumn=25,title=EDS103::leading zeros"


def test_github_escaping():
    assert report.escape_data("100% done\r\nnext: a,b") == "100%25 done%0D%0Anext: a,b"
    assert report.escape_property("C:\\x,y%\n") == "C%3A\\x%2Cy%25%0A"
    path = "odd,name: 50%.eds"
    d = Diagnostic("EDS001", "line one\nline two", 2, 3, path)
    (line, _) = report.format_github([FileReport(path, [d])]).splitlines()
    assert line == "::error file=odd%2Cname%3A 50%25.eds,line=2,col=3,title=EDS001::line one%0Aline two"


def test_docs_rules_md_is_what_the_registry_generates():
    page = (REPO / "docs" / "rules.md").read_text(encoding="utf-8")
    assert page == rule_docs.rules_page(), (
        "docs/rules.md differs from the rule definitions: run 'edsconv rules --format markdown > docs/rules.md'")
    headings = set(re.findall(r"^### (\S+)$", page, re.MULTILINE))
    missing = [r.code for r in report.all_rules() if r.code not in headings]
    assert not missing, f"docs/rules.md lacks a '### CODE' heading for {missing}"


#: Microsoft's SARIF validator, with GitHub's ingestion rules (GH1xxx) besides the SARIF ones
MULTITOOL_NPM = "@microsoft/sarif-multitool-linux@5.7.0"


def sarif_multitool() -> Path:
    import platform
    import shutil
    import subprocess

    from test_packaging import TOOL_CACHE

    if platform.system() != "Linux" or platform.machine() not in ("x86_64", "AMD64"):
        pytest.skip("the SARIF multitool package is built for Linux x64")
    prefix = TOOL_CACHE / "sarif-multitool"
    tool = prefix / "node_modules" / "@microsoft" / "sarif-multitool-linux" / "Sarif.Multitool"
    if not tool.exists():
        if not shutil.which("npm"):
            pytest.skip("npm is needed to install the SARIF multitool")
        prefix.mkdir(parents=True, exist_ok=True)
        installed = subprocess.run(["npm", "install", "--silent", "--no-save", "--prefix", str(prefix), MULTITOOL_NPM],
                                   capture_output=True, text=True, timeout=600)
        if installed.returncode != 0 or not tool.exists():
            pytest.skip(f"cannot install {MULTITOOL_NPM}: {installed.stderr.strip()[-300:]}")
    return tool


def multitool_findings(tool: Path, document: dict, where: Path) -> list[str]:
    """The rule ids Microsoft's validator reports for ``document`` with the GitHub and SARIF rules."""
    import subprocess

    log, out = where / "log.sarif", where / "validation.sarif"
    log.write_text(json.dumps(document), encoding="utf-8")
    subprocess.run([str(tool), "validate", "--rule-kind", "Gh;Sarif", "--log", "ForceOverwrite", "-o", str(out),
                    str(log)], capture_output=True, text=True, timeout=300, check=True)
    return [r["ruleId"] for r in json.loads(out.read_text(encoding="utf-8"))["runs"][0]["results"]]


@pytest.mark.tools
def test_microsofts_validator_with_githubs_rules_finds_nothing(tmp_path: Path):
    from edsconv.lint import lint_paths

    tool = sarif_multitool()
    (tmp_path / "broken.eds").write_bytes((REPO / "corpus" / "examples" / "io_adapter.eds").read_bytes()
                                         .replace(b"ProdCode = 1001;", b"ProdCode = 01001;"))
    (tmp_path / "gone.eds").symlink_to(tmp_path / "deleted.eds")
    document = report.sarif_document(lint_paths([tmp_path], jobs=1), root=tmp_path)
    assert len(document["runs"][0]["results"]) == 2
    assert "fixes" in document["runs"][0]["results"][0]  # EDS103's repair, judged by the validator too
    assert multitool_findings(tool, document, tmp_path) == []
    # the validator does judge: without informationUri and a region it warns (SARIF2005, SARIF2017)
    del document["runs"][0]["tool"]["driver"]["informationUri"]
    del document["runs"][0]["results"][0]["locations"][0]["physicalLocation"]["region"]
    assert sorted(multitool_findings(tool, document, tmp_path)) == ["SARIF2005", "SARIF2017"]
