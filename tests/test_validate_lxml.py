"""``edsconv validate`` accepts through lxml and the XSD 1.0 rendition, and words every rejection with xmlschema.

A profile of a kind whose schema needs XSD 1.1 is first validated by lxml against the
rendition (schemas/xsd10/), which is never more permissive: a document it accepts is valid and
xmlschema is not loaded. Any other document gets exactly the report xmlschema gives.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

import edsconv.xml.validate as validate
from conftest import REPO
from edsconv.xml.schemas import PROFILE_KINDS

CORPUS = REPO / "corpus" / "xml"
INSTANCES = sorted(p for p in CORPUS.glob("*/*.xml") if p.parent.name not in ("broken", "security"))
KINDS = [kind for kind in PROFILE_KINDS if kind.xsd]


class _Rejecting:
    def validate(self, document) -> bool:
        return False


def report(path: Path, kind) -> list[tuple]:
    return [(d.code, d.line, d.column, d.message, d.clause) for d in validate.validate_file(path, kind).diagnostics]


@pytest.mark.parametrize("path", INSTANCES, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_every_verdict_and_message_is_xmlschemas(path: Path, monkeypatch):
    found = {kind.name: report(path, kind) for kind in KINDS}
    monkeypatch.setattr(validate, "load_write_validator", lambda xsd: _Rejecting())  # xmlschema decides all
    assert found == {kind.name: report(path, kind) for kind in KINDS}


def _modules_after_validating(path: Path) -> tuple[int, bool]:
    code = ("import sys; from edsconv.cli import main; sys.argv = ['edsconv', 'validate', sys.argv[1]]\n"
            "try:\n    main()\nexcept SystemExit as end:\n    print(end.code, 'xmlschema' in sys.modules)")
    completed = subprocess.run([sys.executable, "-c", code, str(path)], capture_output=True, text=True, timeout=120)
    status, loaded = completed.stdout.split()[-2:]
    return int(status), loaded == "True"


def test_a_valid_profile_the_rendition_accepts_does_not_load_xmlschema():
    assert _modules_after_validating(CORPUS / "ethernetip-commnet" / "valid-complete.xml") == (0, False)


def test_a_profile_the_rendition_rejects_is_judged_by_xmlschema():
    # valid under the 1.1 schema: its unqualified VendorNote is the rendition's deviation
    assert _modules_after_validating(CORPUS / "cip-device" / "valid-complete.xml") == (0, True)
    assert _modules_after_validating(CORPUS / "cip-device" / "invalid-technology.xml") == (1, True)
