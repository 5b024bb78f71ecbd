"""Emacs with eglot, a third real client: the init file docs/editors.md gives, verbatim, attaches
``edsconv lsp`` to an EDS file; its diagnostics are the library's, and the hover is plain text
(eglot without markdown-mode asks for it).

Skipped where Emacs or eglot is missing (Debian 12: ``apt-get install emacs-nox elpa-eglot``).
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
EMACS = shutil.which("emacs")


def has_eglot() -> bool:
    if EMACS is None:
        return False
    run = subprocess.run([EMACS, "--batch", "--eval", "(progn (package-initialize) (require 'eglot))"],
                         capture_output=True, timeout=60)
    return run.returncode == 0


pytestmark = pytest.mark.skipif(not has_eglot(), reason="Emacs with eglot is not installed")
BROKEN = REPO / "corpus" / "broken" / "figure_C09_as_printed.eds"


def documented_init() -> str:
    text = (REPO / "docs" / "editors.md").read_text(encoding="utf-8")
    return text.split("## Emacs (eglot)", 1)[1].split("```elisp\n", 1)[1].split("```", 1)[0]


def test_the_documented_eglot_config_checks_and_explains_an_eds_file(tmp_path: Path):
    init = tmp_path / "init.el"
    init.write_text("(package-initialize)\n" + documented_init(), encoding="utf-8")
    document = tmp_path / "broken.EDS"
    document.write_bytes(BROKEN.read_bytes())
    line = next(index for index, text in enumerate(BROKEN.read_text().splitlines()) if "[Param2]" in text)
    hover = f"{line}:{BROKEN.read_text().splitlines()[line].index('[Param2]') + 2}"
    out = tmp_path / "out.txt"
    environment = {**os.environ, "EDSCONV_EMACS_FILE": str(document), "EDSCONV_EMACS_OUT": str(out),
                   "EDSCONV_EMACS_HOVER": hover, "HOME": str(tmp_path),
                   "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}"}
    run = subprocess.run([EMACS, "--batch", "-l", str(init), "-l", str(REPO / "tests" / "emacs" / "eglot.el")],
                         env=environment, cwd=tmp_path, capture_output=True, text=True, timeout=90)
    assert run.returncode == 0, run.stderr[-2000:]
    mode, codes, kind, first_line = out.read_text().splitlines()
    _, diagnostics = edsconv.analyse(edsconv.load(BROKEN))
    assert mode == "eds-mode"
    assert sorted(codes.split(",")) == sorted(d.code for d in diagnostics)
    assert (kind, first_line) == ("plaintext", "Param2 is not defined in this file.")
