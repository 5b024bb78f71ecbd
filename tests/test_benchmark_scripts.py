"""The benchmark scripts start (they are run by hand, not by the suite: a renamed helper broke
bench_lsp.py's import once without any test noticing). Only --help runs: no timing here."""

from __future__ import annotations

import subprocess
import sys

import pytest

from conftest import REPO


@pytest.mark.parametrize("script", ["run_all.py", "bench_lsp.py", "bench_html.py"])
def test_the_script_starts_and_explains_its_options(script: str) -> None:
    pytest.importorskip("pygls" if script == "bench_lsp.py" else "eds_pie")  # the bench extra's comparison
    result = subprocess.run([sys.executable, str(REPO / "benchmarks" / script), "--help"], capture_output=True,
                            text=True, timeout=120, cwd=REPO)
    assert result.returncode == 0, result.stderr
    assert "--" in result.stdout and "usage" in result.stdout
