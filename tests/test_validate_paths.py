"""The XPath of each schema error is found in size + errors, not size x errors (issue 20 item 6).

xmlschema's ``error.path`` walks the whole tree from the root for every error and counts the
siblings anew; :class:`edsconv.xml.validate.ElementPaths` numbers each parent's children once.
Proven without timing: every child is numbered at most once however many errors there are,
xmlschema's own whole-tree walk is never called, and the paths are the ones xmlschema gives.
benchmarks/bench_invalid_profile.py times the shape.
"""

from __future__ import annotations

from pathlib import Path

import pytest
import xmlschema.validators.exceptions
from lxml import etree

import edsconv
from conftest import REPO
from edsconv.xml import validate
from edsconv.xml.common import Header
from edsconv.xml.convert import profile_documents
from edsconv.xml.schemas import load_schema

PARAMS = 300


def broken_profile(tmp_path: Path, every: int) -> tuple[Path, int, int]:
    """The device profile of PARAMS parameters with every ``every``-th ParamDescriptor no hexBinary:
    its path, the number broken and the number of elements."""
    text = "[File]\nDescText = \"x\";\n[Device]\nVendCode = 1;\nProdType = 12;\nProdCode = 1;\nMajRev = 1;\n" \
           "MinRev = 1;\n[Params]\n" + "".join(f'Param{n} = 0,,,0x0000,0xC8,4,"P","","",0,100,1;\n'
                                               for n in range(1, PARAMS + 1))
    device, _ = edsconv.analyse(edsconv.parse(text))
    root = etree.fromstring(profile_documents(device, Header.derive(device), "t")[0].data)
    broken = 0
    for index, descriptor in enumerate(root.iter("ParamDescriptor")):
        if index % every == every - 1:
            descriptor.text = "ZZZZ"
            broken += 1
    path = tmp_path / "broken.xml"
    path.write_bytes(etree.tostring(root))
    return path, broken, sum(1 for _ in root.iter())


@pytest.fixture
def numbering(monkeypatch):
    """The ElementPaths of each validation; xmlschema's whole-tree path walk made to fail."""
    made: list[validate.ElementPaths] = []

    class Recorded(validate.ElementPaths):
        def __init__(self) -> None:
            super().__init__()
            made.append(self)

    def walk(*_args, **_kwargs):
        raise AssertionError("xmlschema walked the whole tree for an error's path")

    monkeypatch.setattr(validate, "ElementPaths", Recorded)
    monkeypatch.setattr(xmlschema.validators.exceptions, "etree_getpath", walk)
    return made


@pytest.mark.parametrize("every", [1, 7])
def test_each_child_is_numbered_at_most_once_however_many_errors(tmp_path, numbering, every):
    path, broken, elements = broken_profile(tmp_path, every)
    codes = [d.code for d in validate.validate_file(path).diagnostics]
    assert codes == ["XML003"] * broken
    (paths,) = numbering
    assert paths.visited < elements


def test_a_valid_profile_numbers_nothing(tmp_path, numbering):
    path, broken, _ = broken_profile(tmp_path, PARAMS + 1)
    assert broken == 0
    assert [d.code for d in validate.validate_file(path).diagnostics] == []
    assert all(paths.visited == 0 for paths in numbering)


@pytest.mark.parametrize("path", sorted((REPO / "corpus" / "xml").glob("*/invalid-*.xml"))
                         + [REPO / "corpus" / "xml" / "cip-device" / "valid-complete.xml"],
                         ids=lambda p: f"{p.parent.name}/{p.name}")
def test_the_paths_are_those_xmlschema_gives(path):
    report = validate.validate_file(path)
    if report.kind is None or report.kind.xsd is None:
        pytest.skip("no schema")
    tree = etree.parse(str(path))
    paths = validate.ElementPaths()
    for error in load_schema(report.kind.xsd).iter_errors(tree):
        assert paths.path(error.elem, error.namespaces) == error.path


def test_paths_of_numbered_and_namespaced_siblings(tmp_path):
    path, _, _ = broken_profile(tmp_path, 100)
    tree = etree.parse(str(path))
    paths = validate.ElementPaths()
    errors = load_schema("CIP_Device_Profile.xsd").iter_errors(tree)
    found = [(paths.path(e.elem, e.namespaces), e.path) for e in errors]
    assert [ours for ours, _ in found] == [theirs for _, theirs in found]
    assert found[0][0] == "/ISO15745Profile/ProfileBody/ApplicationProcess/Parameter/Param[100]/ParamDescriptor"
