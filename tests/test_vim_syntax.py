"""editors/vim: the syntax file colours an EDS as the grammar reads it, and the file type is found
whatever the letter case of the extension; checked in a real (Neo)Vim, headless."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

from conftest import REPO

EDITOR = shutil.which("nvim") or shutil.which("vim")
pytestmark = pytest.mark.skipif(EDITOR is None, reason="neither nvim nor vim is installed")
EXAMPLE = REPO / "corpus" / "examples" / "io_adapter.eds"
DOLLAR = REPO / "corpus" / "allowed" / "C.4.1.2.15_dollar_in_string.eds"


def syntax_at(path: Path, spots: list[tuple[int, int]], tmp_path: Path) -> tuple[list[str], str]:
    """The syntax group at each (line, column), and the file type the editor chose."""
    out = tmp_path / "syntax.out"
    calls = "".join(f"call add(g:found, synIDattr(synID({line}, {column}, 1), 'name'))\n" for line, column in spots)
    script = tmp_path / "probe.vim"
    script.write_text(f"let g:found = []\n{calls}call add(g:found, &filetype)\n"
                      f"call writefile(g:found, '{out}')\nqa!\n")
    assert EDITOR is not None
    subprocess.run([EDITOR, "-es" if EDITOR.endswith("/vim") else "--headless", "-u", "NONE", "-i", "NONE",
                    "--cmd", f"set rtp^={REPO / 'editors' / 'vim'}", "--cmd", "filetype on", "--cmd", "syntax on",
                    "-c", f"source {script}", str(path)], check=True, timeout=30, stdin=subprocess.DEVNULL,
                   capture_output=True)
    *groups, filetype = out.read_text().splitlines()
    return groups, filetype


def test_the_syntax_file_colours_each_kind_of_word(tmp_path: Path):
    lines = EXAMPLE.read_text().splitlines()
    member = lines.index("                8,Param2,") + 1
    groups, filetype = syntax_at(EXAMPLE, [(1, 1), (4, 1), (5, 9), (5, 20), (6, 22), (member, 19), (5, 18)], tmp_path)
    assert filetype == "eds"
    assert groups == ["edsComment", "edsSection", "edsKeyword", "edsString", "edsNumber", "edsReference",
                      "edsDelimiter"]


def test_a_dollar_inside_a_string_starts_no_comment(tmp_path: Path):
    line = DOLLAR.read_text().splitlines().index('        ProdName = "Probe $ Adapter";') + 1
    groups, _ = syntax_at(DOLLAR, [(line, 28), (line, 37)], tmp_path)
    assert groups == ["edsString", "edsDelimiter"]


def test_the_file_type_is_found_for_any_letter_case(tmp_path: Path):
    mixed = tmp_path / "Device.Eds"
    shutil.copy(EXAMPLE, mixed)
    assert syntax_at(mixed, [(4, 1)], tmp_path) == (["edsSection"], "eds")
