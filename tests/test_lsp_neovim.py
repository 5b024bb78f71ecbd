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
