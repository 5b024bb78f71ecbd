"""``edsconv lint`` and ``edsconv rules``: discovery, formats, filters, exit codes, parallel runs, failures."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from conftest import REPO, SHARED_REAL, needs_real_corpus
from edsconv import lint
from edsconv import parallel as workers
from edsconv.cli import cli
from test_report import validate_sarif

GOOD = (REPO / "corpus" / "examples" / "io_adapter.eds").read_bytes()
#: the good file with DescText's ';' dropped: one EDS002, and nothing else
_DESC_TEXT = b'DescText = "edsconv example I/O adapter"'
BROKEN = GOOD.replace(_DESC_TEXT + b";", _DESC_TEXT)
#: where the ';' is missing
BROKEN_LINE = GOOD[:GOOD.index(_DESC_TEXT)].count(b"\n") + 1
BROKEN_COLUMN = GOOD.index(_DESC_TEXT) - GOOD.rindex(b"\n", 0, GOOD.index(_DESC_TEXT)) + len(_DESC_TEXT)
CANOPEN = b"[FileInfo]\nFileName=drive.eds\n[DeviceInfo]\nVendorName=Someone\n[1000]\nParameterName=Device type\n"
#: only a warning: a character outside ASCII in a comment (EDS005)
WARNS = GOOD + "$ caf\u00e9\n".encode()


def run(*args: str):
    """The command in this process; ``return_value`` is its exit code."""
    return CliRunner().invoke(cli, list(args), standalone_mode=False, catch_exceptions=False)


def edsconv(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "edsconv", *args], capture_output=True, text=True, cwd=cwd,
                          timeout=120)


@pytest.fixture
def tree(tmp_path: Path) -> Path:
    """Good files with a broken one and a CANopen one among them, in nested directories."""
    (tmp_path / "sub" / "deeper").mkdir(parents=True)
    for name in ("a.eds", "sub/b.EDS", "sub/deeper/c.eds", "z.eds"):
        (tmp_path / name).write_bytes(GOOD)
    (tmp_path / "m_broken.eds").write_bytes(BROKEN)
    (tmp_path / "sub" / "n_canopen.eds").write_bytes(CANOPEN)
    (tmp_path / "notes.txt").write_bytes(BROKEN)
    (tmp_path / "odd.Eds").write_bytes(BROKEN)
    return tmp_path


def codes_by_file(reports) -> dict[str, list[str]]:
    return {Path(r.path).name: [d.code for d in r.diagnostics] for r in reports}


def test_discovery_is_recursive_sorted_and_takes_explicit_files_whatever_their_suffix(tree: Path):
    found = [str(Path(p).relative_to(tree)) for p in lint.discover([tree])]
    # any letter case of .eds: odd.Eds too; notes.txt is not an EDS
    assert found == ["a.eds", "m_broken.eds", "odd.Eds", "sub/b.EDS", "sub/deeper/c.eds", "sub/n_canopen.eds",
                     "z.eds"]
    assert lint.discover([tree / "notes.txt", tree / "a.eds", tree]) [:3] == [
        str(tree / "notes.txt"), str(tree / "a.eds"), str(tree / "m_broken.eds")]


def test_directory_with_a_broken_and_a_canopen_file_reports_every_file(tree: Path):
    result = run("lint", "--format", "json", str(tree))
    assert result.return_value == 1
    document = json.loads(result.stdout)
    by_name = {Path(f["path"]).name: [d["code"] for d in f["diagnostics"]] for f in document["files"]}
    assert by_name == {"a.eds": [], "m_broken.eds": ["EDS002"], "odd.Eds": ["EDS002"], "b.EDS": [], "c.eds": [],
                       "n_canopen.eds": ["EDS010"], "z.eds": []}
    assert document["summary"] == {"files": 7, "errors": 3, "warnings": 0, "notes": 0, "hidden_notes": 0,
                                   "fixable": 2, "fixed": 0}
    assert all(f["error"] is None for f in document["files"])


def test_text_format_and_exit_codes(tmp_path: Path):
    good, broken = tmp_path / "good.eds", tmp_path / "broken.eds"
    good.write_bytes(GOOD)
    broken.write_bytes(BROKEN)
    assert run("lint", str(good)).return_value == 0
    result = run("lint", str(good), str(broken))
    assert result.return_value == 1
    (line,) = result.stdout.splitlines()
    assert line.startswith(f"{broken}:{BROKEN_LINE}:{BROKEN_COLUMN}: error: EDS002 the entry is not ended by ';'")
    assert line.endswith("[C.4.1.2.2.8] [*]")  # --fix repairs it
    assert result.stderr.splitlines()[:2] == ["2 files: 1 error, 0 warnings, 0 notes", "1 file with errors"]
    assert "top rules" not in result.stderr  # one finding: read in full


def test_exit_codes_as_a_process(tmp_path: Path):
    (tmp_path / "good.eds").write_bytes(GOOD)
    (tmp_path / "broken.eds").write_bytes(BROKEN)
    assert edsconv("lint", "good.eds", cwd=tmp_path).returncode == 0
    assert edsconv("lint", ".", cwd=tmp_path).returncode == 1
    missing = edsconv("lint", "good.eds", "missing.eds", cwd=tmp_path)
    assert missing.returncode == 2
    assert "missing.eds" in missing.stderr
    assert edsconv("lint", "--select", "NOPE", "good.eds", cwd=tmp_path).returncode == 2
    assert edsconv("lint", "--jobs", "0", "good.eds", cwd=tmp_path).returncode == 2


def test_warnings_as_errors_fails_and_prints_errors(tmp_path: Path):
    path = tmp_path / "warns.eds"
    path.write_bytes(WARNS)
    plain = run("lint", "--format", "json", str(path))
    assert plain.return_value == 0
    assert [d["severity"] for d in json.loads(plain.stdout)["files"][0]["diagnostics"]] == ["warning"]
    strict = run("lint", "--format", "json", "--warnings-as-errors", str(path))
    assert strict.return_value == 1
    assert [d["severity"] for d in json.loads(strict.stdout)["files"][0]["diagnostics"]] == ["error"]
    sarif = json.loads(run("lint", "--format", "sarif", "--warnings-as-errors", str(path)).stdout)
    assert [r["level"] for r in sarif["runs"][0]["results"]] == ["error"]


@pytest.mark.parametrize(("options", "expected"), [
    ([], {"m_broken.eds": ["EDS002"], "odd.Eds": ["EDS002"], "n_canopen.eds": ["EDS010"]}),
    (["--select", "EDS010"], {"n_canopen.eds": ["EDS010"]}),
    (["--select", "eds01,XML"], {"n_canopen.eds": ["EDS010"]}),
    (["--ignore", "EDS0"], {}),
    (["--ignore", "EDS002", "--ignore", "EDS010"], {}),
    (["--ignore", "EDS0", "--select", "EDS002"], {"m_broken.eds": ["EDS002"], "odd.Eds": ["EDS002"]}),
    (["--select", "EDS0", "--ignore", "EDS01"], {"m_broken.eds": ["EDS002"], "odd.Eds": ["EDS002"]}),
    (["--select", "EDS010", "--ignore", "EDS010"], {}),
])
def test_select_and_ignore_take_codes_and_prefixes(tree: Path, options: list[str], expected: dict):
    result = run("lint", "--format", "json", *options, str(tree))
    found = {Path(f["path"]).name: [d["code"] for d in f["diagnostics"]]
             for f in json.loads(result.stdout)["files"] if f["diagnostics"]}
    assert found == expected
    assert result.return_value == (1 if expected else 0)


def test_parallel_results_equal_sequential_in_input_order(tmp_path: Path):
    for index in range(3 * workers.PARALLEL_THRESHOLD):
        content = (GOOD, BROKEN, CANOPEN, WARNS)[index % 4] * (1 + index % 3)
        (tmp_path / f"f{index:02}.eds").write_bytes(content)
    sequential = lint.lint_paths([tmp_path], jobs=1)
    parallel = lint.lint_paths([tmp_path], jobs=2)
    assert [r.as_dict() for r in parallel] == [r.as_dict() for r in sequential]
    assert [r.path for r in parallel] == lint.discover([tmp_path])


def test_an_exception_on_one_file_gives_eds000_and_the_run_goes_on(tree: Path, monkeypatch):
    real = lint.analyse

    def failing(eds, *selection):
        if eds.path.endswith("b.EDS"):
            raise RecursionError("maximum recursion depth exceeded")
        return real(eds, *selection)

    monkeypatch.setattr(lint, "analyse", failing)
    reports = lint.lint_paths([tree], jobs=1)
    assert codes_by_file(reports) == {"a.eds": [], "m_broken.eds": ["EDS002"], "odd.Eds": ["EDS002"],
                                      "b.EDS": ["EDS000"], "c.eds": [], "n_canopen.eds": ["EDS010"], "z.eds": []}
    failed = reports[3]
    assert failed.error.startswith("internal error RecursionError: maximum recursion depth exceeded")
    assert "please report it" in failed.diagnostics[0].message


def test_an_unreadable_file_gives_eds000(tree: Path, monkeypatch):
    import edsconv.lint

    real = edsconv.lint.read_bytes

    def read_bytes(path: str) -> bytes:
        if Path(path).name == "c.eds":
            raise PermissionError(13, "Permission denied")
        return real(path)

    monkeypatch.setattr(edsconv.lint, "read_bytes", read_bytes)
    result = run("lint", "--format", "json", str(tree))
    assert result.return_value == 1
    files = {Path(f["path"]).name: f for f in json.loads(result.stdout)["files"]}
    assert files["c.eds"]["error"] == "cannot read the file: Permission denied"
    assert [d["code"] for d in files["c.eds"]["diagnostics"]] == ["EDS000"]
    assert len(files) == 7


def test_a_dangling_symbolic_link_in_a_directory_is_reported_not_skipped(tmp_path: Path):
    (tmp_path / "good.eds").write_bytes(GOOD)
    (tmp_path / "gone.EDS").symlink_to(tmp_path / "deleted.eds")
    result = run("lint", str(tmp_path))
    assert result.return_value == 1
    (line,) = result.stdout.splitlines()
    assert line.startswith(f"{tmp_path / 'gone.EDS'}:1:1: error: EDS000 cannot read the file: it is a symbolic "
                           f"link to {tmp_path / 'deleted.eds'}, which does not exist")


def _die_on_broken(path: str, *selection):
    if "broken" in path:
        os._exit(3)
    return _REAL_LINT_FILE(path, *selection)


_REAL_LINT_FILE = lint.lint_file


def test_a_worker_that_dies_does_not_stop_the_run(tmp_path: Path, monkeypatch):
    for index in range(2 * workers.PARALLEL_THRESHOLD):
        (tmp_path / f"f{index:02}.eds").write_bytes(GOOD)
    (tmp_path / "broken.eds").write_bytes(BROKEN)
    monkeypatch.setattr(lint, "lint_file", _die_on_broken)
    reports = lint.lint_paths([tmp_path], jobs=2)
    assert len(reports) == 2 * workers.PARALLEL_THRESHOLD + 1
    assert reports[0].path.endswith("broken.eds")
    assert reports[0].error and "died" in reports[0].error
    assert all(not r.diagnostics or r.diagnostics[0].code == "EDS000" for r in reports)


def test_sarif_and_github_from_the_command(tree: Path, monkeypatch):
    monkeypatch.chdir(tree)
    sarif = json.loads(run("lint", "--format", "sarif", ".").stdout)
    validate_sarif(sarif)
    uris = [r["locations"][0]["physicalLocation"]["artifactLocation"]["uri"] for r in sarif["runs"][0]["results"]]
    assert uris == ["m_broken.eds", "odd.Eds", "sub/n_canopen.eds"]
    github = run("lint", "--format", "github", ".")
    assert github.return_value == 1
    assert github.stdout.splitlines()[0].startswith(
        f"::error file=m_broken.eds,line={BROKEN_LINE},col={BROKEN_COLUMN},title=EDS002::")


@pytest.mark.parametrize("output_format", ["text", "json", "sarif", "github"])
def test_min_severity_leaves_out_lower_diagnostics_in_every_format(tmp_path: Path, output_format: str):
    path = tmp_path / "warns.eds"
    path.write_bytes(WARNS.replace(b"ProdCode = 1001;", b"ProdCode = 01001;"))  # + EDS103, an error
    every = run("lint", "--isolated", "--format", "json", str(path))
    assert [d["code"] for d in json.loads(every.stdout)["files"][0]["diagnostics"]] == ["EDS103", "EDS005"]
    errors = run("lint", "--isolated", "--format", output_format, "--min-severity", "error", str(path))
    assert errors.return_value == 1
    assert reported(output_format, errors.stdout) == ["EDS103"]
    warnings = run("lint", "--isolated", "--format", output_format, "--min-severity", "warning", str(path))
    assert reported(output_format, warnings.stdout) == ["EDS103", "EDS005"]


def reported(output_format: str, output: str) -> list[str]:
    """The codes of the diagnostics in ``output``."""
    import re

    if output_format == "sarif":
        return [r["ruleId"] for r in json.loads(output)["runs"][0]["results"]]
    if output_format == "json":
        return [d["code"] for f in json.loads(output)["files"] for d in f["diagnostics"]]
    return re.findall(r"\b(EDS\d{3})\b", output)


def test_the_pre_commit_hook_pattern_takes_eds_in_any_letter_case():
    import re

    (pattern,) = re.findall(r"^  files: (.+)$", (REPO / ".pre-commit-hooks.yaml").read_text(), re.MULTILINE)
    assert [name for name in ("a.eds", "B.EDS", "Mixed.Eds", "c.eds.txt", "eds") if re.search(pattern, name)] == [
        "a.eds", "B.EDS", "Mixed.Eds"]


def test_no_progress_bar_when_piped(tmp_path: Path):
    for index in range(workers.PROGRESS_THRESHOLD + 1):
        (tmp_path / f"f{index:02}.eds").write_bytes(GOOD)
    result = edsconv("lint", str(tmp_path))
    assert result.returncode == 0
    assert result.stdout == ""
    assert result.stderr.splitlines()[0] == f"{workers.PROGRESS_THRESHOLD + 1} files: 0 errors, 0 warnings, 0 notes"
    assert result.stderr.splitlines()[-1].startswith("checked in ")


def test_rules_lists_every_rule_sorted():
    from edsconv.report import all_rules

    text = run("rules")
    assert text.return_value == 0
    listed = [line.split()[0] for line in text.stdout.splitlines()]
    assert listed == sorted(listed) == [r.code for r in all_rules()]
    assert {"EDS000", "EDS001", "EDS015", "XML001"} <= set(listed)
    eds015 = next(line for line in text.stdout.splitlines() if line.startswith("EDS015"))
    assert "error" in eds015 and "C.4.1.2.2.4" in eds015 and " ! " in eds015
    described = json.loads(run("rules", "--format", "json").stdout)
    assert {key: described[1][key] for key in ("code", "severity", "clause", "import_blocking", "summary")} == {
        "code": "EDS001", "severity": "error", "clause": "C.4.1.2.2", "import_blocking": False,
        "summary": "Text that does not follow the EDS syntax"}


def test_parse_does_not_import_what_only_other_commands_need(tmp_path: Path):
    probe = ("import sys\nfrom edsconv.cli import cli\n"
             "cli.main(['parse', sys.argv[1]], standalone_mode=False)\n"
             "print(sorted(m for m in ('xmlschema', 'rich', 'concurrent.futures', 'edsconv.lint') "
             "if m in sys.modules))")
    (tmp_path / "good.eds").write_bytes(GOOD)
    result = subprocess.run([sys.executable, "-c", probe, str(tmp_path / "good.eds")], capture_output=True,
                            text=True, timeout=60)
    assert result.stdout.strip() == "[]", result.stderr


def test_pre_commit_hook_definition():
    text = (REPO / ".pre-commit-hooks.yaml").read_text()
    assert "- id: edsconv-lint" in text
    assert "entry: edsconv lint" in text
    assert "language: python" in text
    assert "files: (?i)\\.eds$" in text


@needs_real_corpus
def test_real_corpus_runs_through_and_reports_every_file():
    result = edsconv("lint", "--format", "json", str(SHARED_REAL))
    assert result.returncode in (0, 1), result.stderr
    document = json.loads(result.stdout)
    expected = sorted(str(p) for p in SHARED_REAL.rglob("*") if p.suffix.lower() == ".eds")
    assert [f["path"] for f in document["files"]] == expected
