"""edsconv fmt: --check / --diff exit codes, atomic rewrite, refusal on syntax errors."""

from __future__ import annotations

import os
from pathlib import Path

from click.testing import CliRunner
from tests.conftest import REPO

import edsconv
from edsconv.cli import cli
from edsconv.eds.canonical import canonical, write_canonical

MESSY = """[Device]
VendCode = 1; $ vendor
[File]
DescText = "x";
Revision = 1.0;
"""
CANONICAL = """[File]
    DescText = "x";
    Revision = 1.0;

[Device]
    VendCode = 1;  $ vendor
"""


def run(*args: str):
    return CliRunner().invoke(cli, ["fmt", *args])


def test_check_reports_a_file_that_would_change_and_writes_nothing(tmp_path: Path) -> None:
    path = tmp_path / "a.eds"
    path.write_text(MESSY)
    result = run("--check", str(path))
    assert result.exit_code == 1
    assert f"would reformat {path}" in result.output
    assert path.read_text() == MESSY


def test_check_passes_on_a_canonical_file(tmp_path: Path) -> None:
    path = tmp_path / "a.eds"
    path.write_text(CANONICAL)
    result = run("--check", str(path))
    assert result.exit_code == 0, result.output
    assert "0 file(s) would be reformatted, 1 unchanged" in result.output


def test_rewrite_is_canonical_atomic_and_idempotent(tmp_path: Path) -> None:
    path = tmp_path / "a.eds"
    path.write_text(MESSY)
    os.chmod(path, 0o644)
    result = run(str(path))
    assert result.exit_code == 0, result.output
    assert f"reformatted {path}" in result.output
    assert path.read_text() == CANONICAL
    assert os.stat(path).st_mode & 0o777 == 0o644
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.eds"]  # no temporary file left
    assert edsconv.parse(path.read_text()) == canonical(edsconv.parse(MESSY))
    again = run(str(path))
    assert again.exit_code == 0
    assert "0 file(s) reformatted, 1 unchanged" in again.output
    assert run("--check", str(path)).exit_code == 0


def test_line_ends_are_kept(tmp_path: Path) -> None:
    path = tmp_path / "a.eds"
    path.write_bytes(MESSY.replace("\n", "\r\n").encode())
    assert run(str(path)).exit_code == 0
    assert path.read_bytes() == CANONICAL.replace("\n", "\r\n").encode()


def test_diff_prints_a_unified_diff_and_writes_nothing(tmp_path: Path) -> None:
    path = tmp_path / "a.eds"
    path.write_text(MESSY)
    result = run("--diff", str(path))
    assert result.exit_code == 1
    assert "@@" in result.output
    assert '+    DescText = "x";' in result.output
    assert path.read_text() == MESSY


def test_refuses_a_file_with_syntax_errors(tmp_path: Path) -> None:
    path = tmp_path / "bad.eds"
    text = "[File]\nDescText = \"x\"\n  this is ; not an entry\nRevision = 1.0;\n"
    path.write_text(text)
    assert edsconv.parse(text).has_errors
    result = run(str(path))
    assert result.exit_code == 1
    assert "not formatted" in result.output and "syntax error" in result.output
    assert path.read_text() == text


def test_unreadable_file_exits_2_and_the_others_are_still_done(tmp_path: Path) -> None:
    good = tmp_path / "good.eds"
    good.write_text(MESSY)
    result = run(str(tmp_path / "missing.eds"), str(good))
    assert result.exit_code == 2
    assert "cannot read" in result.output
    assert good.read_text() == CANONICAL


def test_corpus_files_format_to_their_canonical_text(tmp_path: Path) -> None:
    source = REPO / "corpus" / "examples" / "io_adapter.eds"
    path = tmp_path / source.name
    path.write_bytes(source.read_bytes())
    assert run("--check", str(path)).exit_code == 1
    assert run(str(path)).exit_code == 0
    assert path.read_text() == write_canonical(edsconv.load(source))
    assert run("--check", str(path)).exit_code == 0
