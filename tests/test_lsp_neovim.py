"""Neovim, a second real client: it opens a broken corpus file with ``edsconv lsp`` attached and
writes the diagnostics it receives to a file, compared here with what the library reports.

Skipped where ``nvim`` is not installed (Debian: ``apt-get install neovim``).
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import edsconv
from conftest import REPO
from edsconv.eds.canonical import write_canonical

pytest.importorskip("pygls")
NVIM = shutil.which("nvim")
pytestmark = pytest.mark.skipif(NVIM is None, reason="Neovim (nvim) is not installed")
BROKEN = REPO / "corpus" / "broken" / "figure_C09_as_printed.eds"


def expected_lines(path: Path) -> list[str]:
    """The library's diagnostics, written as tests/nvim/diagnostics.lua writes the ones Neovim receives."""
    _, diagnostics = edsconv.analyse(edsconv.load(path))
    severity = {"ERROR": 1, "WARNING": 2, "INFO": 3}
    return sorted(f"{max(d.line, 1) - 1}:{max(d.column, 1) - 1} {d.code} {severity[d.severity.name]} "
                  f"{d.message} [{d.clause}]" for d in diagnostics)


def test_neovim_receives_the_diagnostics_of_a_broken_file(tmp_path: Path):
    out = tmp_path / "diagnostics.txt"
    environment = {**os.environ, "EDSCONV_NVIM_OUT": str(out), "EDSCONV_PYTHON": sys.executable,
                   "XDG_CONFIG_HOME": str(tmp_path), "XDG_DATA_HOME": str(tmp_path), "XDG_STATE_HOME": str(tmp_path)}
    script = REPO / "tests" / "nvim" / "diagnostics.lua"
    run = subprocess.run([NVIM, "--headless", "--clean", "-n", str(BROKEN), "-c", f"luafile {script}"],
                         env=environment, cwd=tmp_path, capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    received = sorted(out.read_text().splitlines())
    assert received == expected_lines(BROKEN)
    assert any(" EDS301 " in line for line in received)


def run_neovim(script: str, path: Path, out: Path, **variables: str) -> None:
    """Neovim headless on ``path`` with ``tests/nvim/<script>`` and ``EDSCONV_NVIM_*`` ``variables``."""
    environment = {**os.environ, "EDSCONV_NVIM_OUT": str(out), "EDSCONV_PYTHON": sys.executable,
                   "XDG_CONFIG_HOME": str(out.parent), "XDG_DATA_HOME": str(out.parent),
                   "XDG_STATE_HOME": str(out.parent),
                   **{f"EDSCONV_NVIM_{name.upper()}": value for name, value in variables.items()}}
    run = subprocess.run([NVIM, "--headless", "--clean", "-n", str(path), "-c",
                          f"luafile {REPO / 'tests' / 'nvim' / script}"],
                         env=environment, cwd=out.parent, capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr


EXAMPLE = REPO / "corpus" / "examples" / "io_adapter.eds"


def test_gq_lays_out_entries_in_place_instead_of_reflowing_prose(tmp_path: Path):
    out = tmp_path / "buffer.txt"
    run_neovim("format.lua", EXAMPLE, out, action="gq", cursor="1")
    buffer = out.read_text().split("\n", 1)[1]
    canonical = write_canonical(edsconv.parse(EXAMPLE.read_text()))
    assert write_canonical(edsconv.parse(buffer)) == canonical  # nothing lost, nothing pushed into a comment
    assert "        0, 255, 3,\n" in buffer and "\n    ProdCode = 1001;\n" in buffer  # laid out as fmt does
    keywords = [line.split("=")[0].strip() for line in buffer.splitlines() if " =" in line]
    assert keywords == [line.split("=")[0].strip() for line in EXAMPLE.read_text().splitlines() if " =" in line]


def test_formatting_keeps_the_cursor_on_its_text(tmp_path: Path):
    canonical = write_canonical(edsconv.parse(EXAMPLE.read_text()))
    untidy = tmp_path / "untidy.eds"
    # a line laid out otherwise and a blank line fmt removes, both above the cursor
    untidy.write_text(canonical.replace("    ProdCode = 1001;", "\n        ProdCode =1001 ;"))
    cursor = untidy.read_text().splitlines().index('        "Debounce time of the digital inputs",') + 1
    out = tmp_path / "buffer.txt"
    run_neovim("format.lua", untidy, out, action="format", cursor=str(cursor))
    line, buffer = out.read_text().split("\n", 1)
    assert buffer == canonical
    assert line == '        "Debounce time of the digital inputs",'


def documented_config(version: tuple[int, int]) -> str:
    """The init.lua docs/editors.md gives for this Neovim version (the block after its marker)."""
    marker = "<!-- neovim>=0.10 -->" if version >= (0, 10) else "<!-- neovim 0.7 -->"
    text = (REPO / "docs" / "editors.md").read_text(encoding="utf-8")
    return text.split(marker, 1)[1].split("```lua\n", 1)[1].split("```", 1)[0]


def test_the_documented_config_attaches_to_an_eds_file_of_any_case(tmp_path: Path):
    version_line = subprocess.run([NVIM, "--version"], capture_output=True, text=True).stdout.splitlines()[0]
    major, minor = (int(part) for part in version_line.split("v", 1)[1].split(".")[:2])
    init = tmp_path / "init.lua"
    init.write_text(documented_config((major, minor)), encoding="utf-8")
    document = tmp_path / "Broken.Eds"  # neither .eds nor .EDS
    document.write_bytes(BROKEN.read_bytes())
    out = tmp_path / "out.txt"
    hover = next(f"{index}:{line.index('[Param2]') + 2}" for index, line in enumerate(BROKEN.read_text().splitlines())
                 if "[Param2]" in line)
    environment = {**os.environ, "EDSCONV_NVIM_OUT": str(out), "EDSCONV_NVIM_HOVER": hover,
                   "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}",
                   "XDG_CONFIG_HOME": str(tmp_path), "XDG_DATA_HOME": str(tmp_path), "XDG_STATE_HOME": str(tmp_path)}
    run = subprocess.run([NVIM, "--headless", "-n", "-i", "NONE", "-u", str(init), str(document), "-c",
                          f"luafile {REPO / 'tests' / 'nvim' / 'docs_config.lua'}"],
                         env=environment, cwd=tmp_path, capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    filetype, clients, codes, hover_text = out.read_text().splitlines()
    assert (filetype, clients) == ("eds", "edsconv")
    assert sorted(codes.split(",")) == sorted(line.split()[1] for line in expected_lines(BROKEN))
    assert hover_text == "**Param2** is not defined in this file."
