"""The VS Code extension under node: its TextMate grammar tokenised by vscode-textmate
(editors/vscode/test/grammar.test.js) and its activation with stand-ins for the vscode API
(test/extension.test.js). Skipped unless ``npm ci`` has run in editors/vscode."""

from __future__ import annotations

import shutil
import subprocess
import zipfile

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
    assert "# pass 6" in run.stdout and "# fail 0" in run.stdout


@pytest.mark.skipif(NODE is None or not (EXTENSION / "node_modules" / "esbuild").is_dir(),
                    reason="needs node and `npm ci` in editors/vscode")
def test_the_package_holds_one_bundle_not_the_node_modules(tmp_path):
    npm = shutil.which("npm")
    assert npm is not None
    vsix = tmp_path / "edsconv-eds.vsix"
    run = subprocess.run([npm, "run", "package", "--", "--out", str(vsix)], cwd=EXTENSION, capture_output=True,
                         text=True, timeout=300)
    assert run.returncode == 0, run.stdout + run.stderr
    with zipfile.ZipFile(vsix) as package:
        files = sorted(name for name in package.namelist() if name.startswith("extension/"))
        bundle = package.read("extension/dist/extension.js").decode()
    assert files == ["extension/dist/extension.js", "extension/language-configuration.json",
                     "extension/package.json", "extension/readme.md", "extension/syntaxes/eds.tmLanguage.json"]
    # the language client is inside (its JSON-RPC framing), the vscode module stays the editor's
    assert "Content-Length" in bundle and 'require("vscode")' in bundle and "edsconv.restartServer" in bundle
