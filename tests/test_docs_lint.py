"""docs/lint.md works as written: its console sessions are run, in order, and print what the page shows.

A fenced block ```` ```eds NAME ```` or ```` ```toml NAME ```` is a file the session writes; a
```` ```console ```` block holds ``$ command`` lines, each followed by the output it prints (stdout
and stderr, as a terminal shows them). The workflow the page shows is docs/examples/github-workflow.yml.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

from conftest import REPO

PAGE = REPO / "docs" / "lint.md"
_BLOCK = re.compile(r"^```(?P<info>[^\n]*)\n(?P<body>.*?)^```$", re.MULTILINE | re.DOTALL)
#: The time a run took (the last line of lint's summary) differs from run to run: compared as "N".
_TIME_TAKEN = re.compile(r"^checked in \d+\.\d\d s$", re.MULTILINE)


def timeless(output: str) -> str:
    return _TIME_TAKEN.sub("checked in N s", output)


def blocks(text: str) -> list[tuple[str, str]]:
    return [(m["info"].strip(), m["body"]) for m in _BLOCK.finditer(text)]


def sessions(body: str) -> list[tuple[str, str]]:
    """(command, expected output) pairs of a console block."""
    found: list[tuple[str, list[str]]] = []
    for line in body.splitlines(keepends=True):
        if line.startswith("$ "):
            found.append((line[2:].rstrip("\n"), []))
        else:
            found[-1][1].append(line)
    return [(command, "".join(output)) for command, output in found]


def test_the_console_sessions_print_what_the_page_shows(tmp_path: Path):
    bin_dir = str(Path(sys.executable).parent)  # the edsconv of this environment
    env = {**os.environ, "PATH": os.pathsep.join([bin_dir, os.environ.get("PATH", "")]), "NO_COLOR": "1"}
    ran = 0
    for info, body in blocks(PAGE.read_text(encoding="utf-8")):
        kind, _, name = info.partition(" ")
        if kind in ("eds", "toml") and name:
            (tmp_path / name).write_text(body, encoding="ascii")
        elif kind == "console":
            for command, expected in sessions(body):
                result = subprocess.run(["bash", "-c", command + " 2>&1"], cwd=tmp_path, env=env,
                                        capture_output=True, text=True, timeout=120)
                assert timeless(result.stdout) == timeless(expected), f"$ {command}"
                ran += 1
    assert ran >= 6


def test_the_console_session_of_the_readme_runs_as_written():
    env = {**os.environ, "PATH": os.pathsep.join([str(Path(sys.executable).parent), os.environ.get("PATH", "")])}
    consoles = [body for info, body in blocks((REPO / "README.md").read_text(encoding="utf-8")) if info == "console"]
    assert consoles
    for command, expected in (pair for body in consoles for pair in sessions(body)):
        result = subprocess.run(["bash", "-c", command + " 2>&1"], cwd=REPO, env=env, capture_output=True, text=True,
                                timeout=120)
        assert result.stdout == expected, f"$ {command}"


def test_the_workflow_on_the_page_is_the_example_that_actionlint_checks():
    workflow = (REPO / "docs" / "examples" / "github-workflow.yml").read_text(encoding="utf-8")
    body = workflow[workflow.index("name: EDS files"):]
    assert ("yaml", body) in blocks(PAGE.read_text(encoding="utf-8"))


def test_the_pre_commit_hook_on_the_page_matches_the_hook_definition():
    hooks = (REPO / ".pre-commit-hooks.yaml").read_text(encoding="utf-8")
    page = PAGE.read_text(encoding="utf-8")
    (pattern,) = re.findall(r"^  files: (.+)$", hooks, re.MULTILINE)
    assert f"        files: {pattern}\n" in page
    assert "      - id: edsconv-lint\n" in page and "- id: edsconv-lint\n" in hooks
