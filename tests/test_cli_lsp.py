"""``edsconv lsp`` on the command line: without the lsp extra it says what to install and exits 2."""

from __future__ import annotations

import subprocess
import sys

WITHOUT_PYGLS = ("import sys; sys.modules['pygls'] = sys.modules['lsprotocol'] = None; "
                 "from edsconv.cli import main; sys.argv = ['edsconv', 'lsp']; main()")


def test_lsp_without_the_extra_says_what_to_install():
    run = subprocess.run([sys.executable, "-c", WITHOUT_PYGLS], capture_output=True, text=True,
                         stdin=subprocess.DEVNULL, timeout=60)
    assert run.returncode == 2
    # edsconv is not on PyPI (issue 18 item 17): the advice installs from a clone, not from an index
    assert "python3 -m pip install '/path/to/edsconv[lsp]'" in run.stderr
    assert "pip install 'edsconv[lsp]'" not in run.stderr


def test_lsp_is_listed_with_the_other_commands():
    run = subprocess.run([sys.executable, "-m", "edsconv", "--help"], capture_output=True, text=True, timeout=60)
    assert run.returncode == 0
    assert "  lsp " in run.stdout
