"""The VS Code extension under node: its TextMate grammar tokenised by vscode-textmate
(editors/vscode/test/grammar.test.js) and its activation with stand-ins for the vscode API
(test/extension.test.js). Skipped unless ``npm ci`` has run in editors/vscode."""

from __future__ import annotations

import shutil
import subprocess

import pytest

from conftest import REPO

EXTENSION = REPO / "editors" / "vscode"
NODE = shutil.which("node")


@pytest.mark.skipif(NODE is None or not (EXTENSION / "node_modules" / "vscode-textmate").is_dir(),
                    reason="needs node and `npm ci` in editors/vscode")
def test_grammar_and_activation():
    run = subprocess.run([NODE, "--test", "test/grammar.test.js", "test/extension.test.js"], cwd=EXTENSION,
                         capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stdout + run.stderr
    assert "# pass 4" in run.stdout and "# fail 0" in run.stdout
