"""docs/validate.md works as written (issue 18 item 18: its examples showed an output format and a
message that the command no longer printed). Its console blocks run from the repository root."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from conftest import REPO
from test_docs_lint import blocks, sessions

PAGE = REPO / "docs" / "validate.md"


def test_the_console_sessions_of_validate_md_print_what_the_page_shows() -> None:
    env = {**os.environ, "PATH": os.pathsep.join([str(Path(sys.executable).parent), os.environ.get("PATH", "")]),
           "NO_COLOR": "1"}
    pairs = [pair for info, body in blocks(PAGE.read_text(encoding="utf-8")) if info == "console"
             for pair in sessions(body)]
    assert len(pairs) >= 2
    for command, expected in pairs:
        result = subprocess.run(["bash", "-c", command + " 2>&1"], cwd=REPO, env=env, capture_output=True, text=True,
                                timeout=120)
        assert result.stdout == expected, f"$ {command}"
    assert "namespace/s" not in PAGE.read_text(encoding="utf-8")
