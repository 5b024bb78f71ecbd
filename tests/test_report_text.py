"""What ``edsconv lint`` shows by default and how: notes folded into a count, ``[*]`` and the fix in
SARIF, concise and full text with the source, colour, the closing summary, ``--statistics``, the rule
links, file names that are not UTF-8, and GitHub's SARIF limits (issue 19; issue 18 items 4, 10, 20, 25, 35)."""

from __future__ import annotations

import io
import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import REPO
from edsconv import report, report_text
from edsconv.cli.common import CannotRun
from edsconv.diagnostics import Diagnostic, Severity
from edsconv.fix import Edit, apply_edits
from edsconv.lint import lint_file
from edsconv.report import FileReport
from edsconv.resources import data_dir
from test_lint import GOOD, edsconv, run
from test_report import validate_sarif

#: one fixable error (EDS103, line 18), one note (EDS321, line 58), one warning (EDS005, line 140)
MIXED = (GOOD.replace(b"0x0002,                 $ Descriptor: enumerated values", b"0x0000, $ Descriptor")
         .replace(b"ProdCode = 1001;", b"ProdCode = 01001;") + "$ caf\u00e9\n".encode())
ANSI = re.compile(r"\x1b\[[0-9;]*m")


@pytest.fixture
def mixed(tmp_path: Path) -> Path:
    path = tmp_path / "mixed.eds"
    path.write_bytes(MIXED)
    return path


def codes(output_format: str, output: str) -> list[str]:
    if output_format == "json":
        return [d["code"] for f in json.loads(output)["files"] for d in f["diagnostics"]]
    if output_format == "sarif":
        return [r["ruleId"] for r in json.loads(output)["runs"][0]["results"]]
    if output_format == "github":
        return re.findall(r"^::\w+ .*title=(\w+)::", output, re.MULTILINE)
    return re.findall(r"\b(?:EDS|XML)\d{3}\b", output)


# --- 1. notes are counted, not shown, unless asked for -----------------------------------
@pytest.mark.parametrize("output_format", ["text", "json", "sarif", "github"])
def test_notes_are_hidden_by_default_in_every_format_and_shown_on_request(mixed: Path, output_format: str):
    default = run("lint", "--isolated", "--format", output_format, str(mixed))
    assert "EDS321" not in codes(output_format, default.stdout)
    assert {"EDS103", "EDS005"} <= set(codes(output_format, default.stdout))
    for asked in (["--show-notes"], ["--min-severity", "info"], ["--select", "EDS321"]):
        shown = run("lint", "--isolated", "--format", output_format, *asked, str(mixed))
        assert "EDS321" in codes(output_format, shown.stdout), asked


def test_hidden_notes_are_counted_in_each_summary(mixed: Path):
    text = run("lint", "--isolated", str(mixed))
    assert text.stderr.splitlines()[0] == "1 file: 1 error, 1 warning, 1 note hidden (show with --show-notes)"
    summary = json.loads(run("lint", "--isolated", "--format", "json", str(mixed)).stdout)["summary"]
    assert (summary["notes"], summary["hidden_notes"]) == (0, 1)
    sarif = json.loads(run("lint", "--isolated", "--format", "sarif", str(mixed)).stdout)
    assert sarif["runs"][0]["properties"] == {"hiddenNotes": 1}
    github = run("lint", "--isolated", "--format", "github", str(mixed)).stdout.splitlines()[-1]
    assert github == "edsconv: 1 file: 1 error, 1 warning, 1 note hidden (show with --show-notes)"


# --- 2. fixes: [*], the count, SARIF fixes ---------------------------------------------------
def test_fixable_findings_are_marked_and_counted(mixed: Path):
    result = run("lint", "--isolated", "--format", "concise", str(mixed))
    marked = [line for line in result.stdout.splitlines() if line.endswith(" [*]")]
    assert len(marked) == 1 and " EDS103 " in marked[0]
    assert "[*] 1 fixable with `edsconv lint --fix`" in result.stderr.splitlines()
    document = json.loads(run("lint", "--isolated", "--format", "json", str(mixed)).stdout)
    assert [d["fixable"] for d in document["files"][0]["diagnostics"]] == [True, False]
    assert document["summary"]["fixable"] == 1


def test_sarif_carries_the_fix_and_applying_it_is_what_fix_writes(mixed: Path):
    document = report.sarif_document([lint_file(str(mixed))], root=mixed.parent)
    validate_sarif(document)
    (fixed,) = [r for r in document["runs"][0]["results"] if "fixes" in r]
    (change,) = fixed["fixes"][0]["artifactChanges"]
    assert change["artifactLocation"] == {"uri": "mixed.eds", "uriBaseId": "%SRCROOT%"}
    (replacement,) = change["replacements"]
    assert replacement == {"deletedRegion": {"startLine": 18, "startColumn": 20, "endLine": 18, "endColumn": 25},
                           "insertedContent": {"text": "1001"}}
    region = replacement["deletedRegion"]
    repaired = apply_edits(MIXED.decode(), [Edit(region["startLine"], region["startColumn"], region["endLine"],
                                                 region["endColumn"], replacement["insertedContent"]["text"])])
    assert run("lint", "--isolated", "--fix", str(mixed)).return_value == 0
    assert mixed.read_text(encoding="utf-8") == repaired


def test_fix_is_reflected_in_json_and_diff_is_refused_with_it(mixed: Path):
    with pytest.raises(CannotRun, match="--diff prints a unified diff, not json"):
        run("lint", "--isolated", "--diff", "--format", "json", str(mixed))
    document = json.loads(run("lint", "--isolated", "--fix", "--format", "json", str(mixed)).stdout)
    assert [d["code"] for d in document["files"][0]["fixed"]] == ["EDS103"]
    assert document["summary"]["fixed"] == 1 and document["summary"]["errors"] == 0


# --- 3. concise and full text -----------------------------------------------------------------
def test_full_shows_the_line_with_a_caret_under_the_field_and_the_rule_link(mixed: Path):
    result = run("lint", "--isolated", "--format", "full", str(mixed))
    lines = result.stdout.splitlines()
    assert lines[:5] == [
        f"{mixed}:18:20: error: EDS103 ProdCode field 1: 01001 has leading zeros, which decimal notation does not "
        "allow (write 1001 or use 0x) [C.4.1.3.7] [*]",
        "   |",
        "18 |         ProdCode = 01001;",
        "   |                    ^^^^^",
        f"   = docs: {(data_dir('docs') / 'rules.md').as_uri()}#eds103",
    ]


def test_full_shows_the_part_of_a_long_line_around_the_field():
    d = Diagnostic("EDS103", "leading zeros", 1, 301, "long.eds", Severity.ERROR, "", 1, 305)
    _, line, caret = report_text.excerpt(["x" * 300 + "0042" + "y" * 300], d).splitlines()
    assert len(line) < 140 and line.startswith("1 | ...x") and line.endswith("y...")
    assert line[caret.index("^"):caret.index("^") + 4] == "0042" and caret.endswith("^^^^")


def test_text_is_concise_when_not_a_terminal(mixed: Path):
    """CliRunner's stdout is no terminal: CI logs and problem matchers get one line a finding."""
    text = run("lint", "--isolated", str(mixed)).stdout
    assert text == run("lint", "--isolated", "--format", "concise", str(mixed)).stdout
    assert len(text.splitlines()) == 2


def test_full_shows_no_excerpt_for_a_finding_about_the_whole_file(tmp_path: Path):
    d = Diagnostic("EDS000", "cannot read the file", path=str(tmp_path / "gone.eds"))
    out = report_text.format_full([FileReport(d.path or "", [d])]).splitlines()
    assert out[0] == f"{tmp_path / 'gone.eds'}:1:1: error: EDS000 cannot read the file"
    assert out[1].startswith("  = docs: ")


# --- 4. colour ----------------------------------------------------------------------------------
def test_colour_on_request_and_never_when_piped(mixed: Path):
    coloured = run("lint", "--isolated", "--color", "always", str(mixed))
    assert "\x1b[1;31merror\x1b[0m" in coloured.stdout and "\x1b[" in coloured.stderr
    assert ANSI.sub("", coloured.stdout) == run("lint", "--isolated", str(mixed)).stdout
    assert "\x1b[" not in run("lint", "--isolated", "--color", "never", str(mixed)).stdout
    piped = subprocess.run([sys.executable, "-m", "edsconv", "lint", "--isolated", str(mixed)], capture_output=True,
                           text=True, timeout=120, env={k: v for k, v in os.environ.items() if k != "FORCE_COLOR"})
    assert "\x1b[" not in piped.stdout + piped.stderr


class _Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_colour_auto_follows_the_terminal_no_color_and_force_color():
    wanted = report_text.colour_wanted
    assert wanted("auto", _Terminal(), {}) and not wanted("auto", io.StringIO(), {})
    assert not wanted("auto", _Terminal(), {"NO_COLOR": "1"})
    assert wanted("auto", io.StringIO(), {"FORCE_COLOR": "1"})
    assert not wanted("auto", io.StringIO(), {"FORCE_COLOR": ""})
    assert wanted("always", io.StringIO(), {"NO_COLOR": "1"}) and not wanted("never", _Terminal(), {})


def test_force_color_colours_a_pipe(mixed: Path):
    result = subprocess.run([sys.executable, "-m", "edsconv", "lint", "--isolated", str(mixed)], capture_output=True,
                            text=True, timeout=120, env={**os.environ, "FORCE_COLOR": "1", "NO_COLOR": ""})
    assert "\x1b[1;31merror\x1b[0m" in result.stdout


# --- 5. the closing summary and --statistics -------------------------------------------------
def test_summary_names_files_with_errors_top_rules_fixable_and_time(mixed: Path, tmp_path: Path):
    (tmp_path / "good.eds").write_bytes(GOOD)
    for index in range(4):
        (tmp_path / f"more{index}.eds").write_bytes(MIXED.replace(b"ProdCode = 01001;", b"ProdCode = 1001;"))
    lines = run("lint", "--isolated", str(tmp_path)).stderr.splitlines()
    assert lines[0] == "6 files: 1 error, 5 warnings, 5 notes hidden (show with --show-notes)"
    assert lines[1:4] == ["1 file with errors", "top rules: EDS005 (5), EDS103 (1)",
                          "[*] 1 fixable with `edsconv lint --fix`"]
    assert re.fullmatch(r"checked in \d+\.\d\d s", lines[-1])


def test_statistics_counts_each_rule_instead_of_listing_findings(mixed: Path):
    result = run("lint", "--isolated", "--statistics", "--show-notes", str(mixed))
    assert result.stdout.splitlines() == [
        "1  EDS103  [*] A decimal number is written with leading zeros",
        "1  EDS321      A parameter has an EnumN but its descriptor does not set bit 1 (supports enumerated strings)",
        "1  EDS005      The file holds characters outside ASCII",
    ]
    assert result.stderr == "" and result.return_value == 1
    rows = json.loads(run("lint", "--isolated", "--statistics", "--format", "json", str(mixed)).stdout)
    assert [(r["code"], r["count"], r["fixable"]) for r in rows] == [("EDS103", 1, 1), ("EDS005", 1, 0)]


# --- 6. links to the rules' documentation ---------------------------------------------------
def test_every_rule_link_opens_the_installed_rules_page():
    url = report.rule_help_uri("EDS311")
    page, _, anchor = url.partition("#")
    assert page.startswith("file:") and Path(page.removeprefix("file://")).is_file() and anchor == "eds311"
    assert f"### {anchor.upper()}" in Path(page.removeprefix("file://")).read_text(encoding="utf-8")


def test_rules_code_prints_explanation_examples_fix_and_the_link():
    text = run("rules", "EDS103").stdout
    assert text.startswith("### EDS103") and "Bad:" in text and "Good:" in text and "Fix:" in text
    assert text.rstrip().endswith(f"Documentation: {report.rule_help_uri('EDS103')}")


def test_the_language_server_links_where_the_reports_link():
    pytest.importorskip("pygls")
    from edsconv.lsp.diagnostics import rule_documentation_url

    assert rule_documentation_url("EDS301") == report.rule_help_uri("EDS301")


# --- issue 18: names, positions, counts, GitHub's limits ---------------------------------------------
def test_a_file_name_that_is_not_utf8_is_escaped_in_every_format(tmp_path: Path):
    name = os.fsdecode(b"caf\xe9.eds")
    (tmp_path / name).write_bytes(MIXED)
    text = edsconv("lint", "--isolated", name, cwd=tmp_path)
    assert text.stdout.startswith("caf\\xe9.eds:18:20: error: EDS103")
    document = json.loads(edsconv("lint", "--isolated", "--format", "json", name, cwd=tmp_path).stdout)
    assert document["files"][0]["path"] == "caf\\xe9.eds"
    sarif = edsconv("lint", "--isolated", "--format", "sarif", name, cwd=tmp_path)
    assert sarif.returncode == 1
    validate_sarif(json.loads(sarif.stdout))
    assert json.loads(sarif.stdout)["runs"][0]["results"][0]["locations"][0]["physicalLocation"][
        "artifactLocation"]["uri"] == "caf%E9.eds"
    github = edsconv("lint", "--isolated", "--format", "github", name, cwd=tmp_path).stdout
    assert github.startswith("::error file=caf\\xe9.eds,line=18,col=20,title=EDS103::")


def test_a_finding_about_the_whole_file_stands_at_1_1_in_every_command():
    """merge, validate and show print through Diagnostic.format: EDS401 and EDS000 were at 0:0."""
    assert Diagnostic("EDS401", "no rack", path="adapter.eds").format() == "adapter.eds:1:1: error: EDS401 no rack"
    document = json.loads(report.format_json([FileReport("a.eds", [Diagnostic("EDS000", "x", path="a.eds")])]))
    assert (document["files"][0]["diagnostics"][0]["line"], document["files"][0]["diagnostics"][0]["column"]) == (1, 1)


def test_singular_counts():
    d = Diagnostic("EDS001", "x", 1, 1, "a.eds")
    assert report.counts([FileReport("a.eds", [d])]) == "1 file: 1 error, 0 warnings, 0 notes"
    assert report.plural(1_234, "note") == "1,234 notes"


def _many(count: int) -> list[FileReport]:
    notes = [Diagnostic("EDS321", f"note {i}", i + 1, 1, "a.eds", Severity.INFO) for i in range(count)]
    return [FileReport("a.eds", [*notes, Diagnostic("EDS001", "the one error", count + 1, 1, "a.eds")])]


def test_sarif_keeps_the_most_severe_results_within_the_limit_and_says_how_many_it_left_out():
    document = report.sarif_document(_many(10), root=Path.cwd(), max_results=4)
    validate_sarif(document)
    (run_,) = document["runs"]
    assert [r["ruleId"] for r in run_["results"]] == ["EDS321"] * 3 + ["EDS001"]
    (notification,) = run_["invocations"][0]["toolExecutionNotifications"]
    assert notification["message"]["text"].startswith("7 results left out: GitHub code scanning accepts at most 25,000")


def test_lint_says_on_stderr_what_the_sarif_left_out(tmp_path: Path, monkeypatch):
    monkeypatch.setattr(report, "SARIF_MAX_RESULTS", 1)
    monkeypatch.setattr(report.sarif_log, "__defaults__", (None, 1, report.SARIF_MAX_GZIP_BYTES))
    (tmp_path / "mixed.eds").write_bytes(MIXED)
    result = run("lint", "--isolated", "--format", "sarif", str(tmp_path / "mixed.eds"))
    assert len(json.loads(result.stdout)["runs"][0]["results"]) == 1
    assert result.stderr.startswith("edsconv: 1 result left out: GitHub code scanning accepts at most 1 results")


def test_sarif_shrinks_to_stay_under_the_gzip_size_limit():
    text = report.format_sarif(_many(2_000), root=Path.cwd(), max_gzip_bytes=60_000)
    import gzip

    assert len(gzip.compress(text.encode(), 6)) <= 60_000
    results = json.loads(text)["runs"][0]["results"]
    assert 0 < len(results) < 2_001 and results[-1]["ruleId"] == "EDS001"


def test_the_action_does_not_fail_on_an_upload_that_cannot_happen():
    action = (REPO / "action.yml").read_text(encoding="utf-8")
    upload = action[action.index("- name: Upload to code scanning"):action.index("- name: Fail on errors")]
    assert "continue-on-error: true" in upload
    workflow = (REPO / "docs" / "examples" / "github-workflow.yml").read_text(encoding="utf-8")
    upload = workflow[workflow.index("upload-sarif"):workflow.index("- name: Fail")]
    assert "continue-on-error: true" in upload
