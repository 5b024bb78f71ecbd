"""``edsconv parse``: output lines, exit codes 0/1/2 and the JSON model."""

from __future__ import annotations

import json
import re
import subprocess
import sys

import pytest
from click.testing import CliRunner

from edsconv.cli import cli

CLEAN = "[File]\nDescText = \"x\"; $ c\n[Device]\nK = 1, {2, *};\n"
BROKEN = '[File]\nA = 1 ];\nB = "a\\qb";\n'
WARNING_ONLY = "[File]\n[Diagnostics/Extra]\nA = 1;\n"
LINE = re.compile(r"^(?P<path>.+):(?P<line>\d+):(?P<col>\d+): (?P<severity>error|warning|info): (?P<code>EDS\d{3}) "
                  r"(?P<message>.+) \[(?P<clause>C\.[\d.]+)\]$")


@pytest.fixture
def files(tmp_path):
    paths = {}
    for name, text in {"clean": CLEAN, "broken": BROKEN, "warning": WARNING_ONLY}.items():
        paths[name] = tmp_path / f"{name}.eds"
        paths[name].write_text(text)
    paths["missing"] = tmp_path / "missing.eds"
    return paths


def run(*args) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "edsconv", "parse", *map(str, args)],
                          capture_output=True, text=True, timeout=60)


def test_clean_file_exit_0_and_no_output(files):
    result = run(files["clean"])
    assert (result.returncode, result.stdout) == (0, "")
    assert result.stderr == "1 file: 0 errors, 0 warnings, 0 notes\n"  # the summary, as lint and validate


def test_warnings_alone_exit_0(files):
    result = run(files["warning"])
    assert result.returncode == 0
    (line,) = result.stdout.splitlines()
    match = LINE.match(line)
    assert match and (match["line"], match["col"], match["severity"], match["code"]) == ("2", "1", "warning", "EDS006")


def test_broken_file_exit_1_with_one_line_per_diagnostic(files):
    result = run(files["clean"], files["broken"])
    assert result.returncode == 1
    matches = [LINE.match(line) for line in result.stdout.splitlines()]
    assert all(matches), result.stdout
    assert [(m["path"], m["line"], m["col"], m["code"], m["clause"]) for m in matches] == [
        (str(files["broken"]), "2", "7", "EDS001", "C.4.1.2.2"),
        (str(files["broken"]), "3", "7", "EDS003", "C.4.1.3.3.5"),
    ]
    assert "unexpected ']" in matches[0]["message"]


@pytest.mark.parametrize("args", [["{missing}"], ["{clean}", "{missing}"], ["--bogus", "{clean}"], [],
                                  ["--format", "xml", "{clean}"]])
def test_could_not_run_exit_2(files, args):
    result = run(*[a.format(**files) for a in args])
    assert result.returncode == 2
    assert result.stderr.strip()
    assert "Traceback" not in result.stderr


def test_missing_file_names_the_file(files):
    assert str(files["missing"]) in run(files["missing"]).stderr


def test_json_format(files):
    result = run("--format", "json", files["broken"])
    assert result.returncode == 1
    document = json.loads(result.stdout)
    assert document["summary"] == {"files": 1, "errors": 2, "warnings": 0, "notes": 0}
    (model,) = document["files"]
    section = model["sections"][0]
    assert section["name"] == "File"
    assert [e["keyword"] for e in section["entries"]] == ["B"]
    assert section["entries"][0]["fields"][0]["value"]["kind"] == "STRING"
    assert [u["text"] for u in section["unparsed"]] == ["A = 1 ];"]
    assert [(d["code"], d["line"], d["column"], d["severity"]) for d in model["diagnostics"]] == [
        ("EDS001", 2, 7, "error"), ("EDS003", 3, 7, "error")]


def test_json_format_has_one_shape_whatever_the_number_of_files(files):
    """Issue 18 item 24: one file gave an object, two a list; now always {"files": [...], "summary": ...}."""
    result = run("--format", "json", files["clean"], files["warning"])
    assert result.returncode == 0
    document = json.loads(result.stdout)
    one = json.loads(run("--format", "json", files["clean"]).stdout)
    assert sorted(document) == ["files", "summary"] == sorted(one)
    models = document["files"]
    assert [m["path"] for m in models] == [str(files["clean"]), str(files["warning"])]
    entry = models[0]["sections"][1]["entries"][0]
    group = entry["fields"][1]["value"]
    assert [f["value"]["raw"] for f in group["fields"]] == ["2", "*"]
    assert models[0]["sections"][0]["entries"][0]["fields"][0]["comments"] == [" c"]


# --- in process, with click's CliRunner ------------------------------------------------------------

@pytest.mark.parametrize("name, code", [("clean", 0), ("warning", 0), ("broken", 1), ("missing", 2)])
def test_cli_runner_exit_codes(files, name, code):
    result = CliRunner().invoke(cli, ["parse", str(files[name])])
    assert result.exit_code == code, result.output
    assert not isinstance(result.exception, Exception) or isinstance(result.exception, SystemExit)
    if name == "broken":
        lines = result.stdout.splitlines()
        assert len(lines) == 2 and all(LINE.match(line) for line in lines)


def test_cli_runner_bad_option_exit_2(files):
    result = CliRunner().invoke(cli, ["parse", "--bogus", str(files["clean"])])
    assert result.exit_code == 2
    assert "--bogus" in result.output
