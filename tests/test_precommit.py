"""The pre-commit hook as a vendor uses it: pre-commit (from PyPI) installs the hook from a clone of this
repository into a fresh git repository, and a commit of a broken EDS is blocked until it is fixed.

Skips cleanly where pre-commit cannot be installed or the repository is not a git checkout. pre-commit
and its hook environment are kept in the test tool cache, so later runs reuse them.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import REPO
from test_packaging import TOOL_CACHE

GOOD = (REPO / "corpus" / "examples" / "io_adapter.eds").read_bytes()
_DESC_TEXT = b'DescText = "edsconv example I/O adapter"'
BROKEN = GOOD.replace(_DESC_TEXT + b";", _DESC_TEXT)


def pre_commit() -> Path:
    """The pre-commit executable of a virtual environment in the tool cache (installed from PyPI once)."""
    venv = TOOL_CACHE / "pre-commit-venv"
    executable = venv / "bin" / "pre-commit"
    if not executable.exists():
        made = subprocess.run([sys.executable, "-m", "venv", "--clear", str(venv)], capture_output=True, text=True)
        installed = made.returncode == 0 and subprocess.run(
            [str(venv / "bin" / "python"), "-m", "pip", "install", "-q", "--disable-pip-version-check",
             "pre-commit>=3"], capture_output=True, text=True, timeout=300).returncode == 0
        if not installed or not executable.exists():
            pytest.skip("pre-commit cannot be installed from PyPI here")
    return executable


def git(*args: str, cwd: Path) -> subprocess.CompletedProcess:
    return subprocess.run(["git", "-c", "user.name=Vendor", "-c", "user.email=vendor@example.invalid",
                           "-c", "init.defaultBranch=main", *args], cwd=cwd, capture_output=True, text=True,
                          timeout=600)


@pytest.mark.tools
def test_the_hook_from_a_local_clone_blocks_a_broken_commit_and_lets_the_fixed_one_through(tmp_path: Path):
    head = git("rev-parse", "HEAD", cwd=REPO)
    if head.returncode != 0:
        pytest.skip("the repository is not a git checkout")
    hook = pre_commit()
    vendor = tmp_path / "vendor"
    vendor.mkdir()
    assert git("init", "-q", cwd=vendor).returncode == 0
    (vendor / ".pre-commit-config.yaml").write_text(
        f"repos:\n  - repo: {REPO}\n    rev: {head.stdout.strip()}\n    hooks:\n      - id: edsconv-lint\n",
        encoding="utf-8")
    (vendor / "Device.Eds").write_bytes(BROKEN)  # a letter case the hook's pattern must take
    env = {**os.environ, "PRE_COMMIT_HOME": str(TOOL_CACHE / "pre-commit-home")}
    installed = subprocess.run([str(hook), "install"], cwd=vendor, env=env, capture_output=True, text=True)
    assert installed.returncode == 0, installed.stderr
    git("add", ".", cwd=vendor)
    blocked = subprocess.run(["git", "-c", "user.name=Vendor", "-c", "user.email=vendor@example.invalid",
                              "commit", "-q", "-m", "add the EDS"], cwd=vendor, env=env, capture_output=True,
                             text=True, timeout=900)
    output = blocked.stdout + blocked.stderr
    if blocked.returncode != 0 and "edsconv lint" not in output:
        pytest.skip(f"the hook environment could not be set up here: {output.strip()[-300:]}")
    assert blocked.returncode != 0
    assert "Device.Eds:5:49: error: EDS002 the entry is not ended by ';'" in output
    assert git("rev-parse", "--verify", "HEAD", cwd=vendor).returncode != 0  # nothing was committed
    (vendor / "Device.Eds").write_bytes(GOOD)
    git("add", ".", cwd=vendor)
    passed = subprocess.run(["git", "-c", "user.name=Vendor", "-c", "user.email=vendor@example.invalid",
                             "commit", "-q", "-m", "add the EDS"], cwd=vendor, env=env, capture_output=True,
                            text=True, timeout=900)
    assert passed.returncode == 0, passed.stdout + passed.stderr
