"""Every rule has a test that triggers it and one that does not; this file holds those that no
module's own tests assert both ways, and a guard that keeps it so for new rules."""

from __future__ import annotations

import ast
import functools
import re
import shutil
from dataclasses import dataclass, field
from pathlib import Path

import pytest
from click.testing import CliRunner
from lxml import etree

import edsconv
from conftest import REPO
from edsconv.cli import cli
from edsconv.diagnostics import load_rules
from edsconv.model import Device
from edsconv.report import all_rules
from edsconv.xml import validate
from edsconv.xml.common import EDSCONV
from edsconv.xml.convert import device_from_profiles
from edsconv.xml.device_read import read_device_profile
from edsconv.xml.safe import parse_xml, read_xml

TESTS = Path(__file__).resolve().parent


def codes(diagnostics) -> list[str]:
    return [d.code for d in diagnostics]


# --- the guard: every code has a test that asserts it is reported, and one that asserts it is not ---------
CODE = re.compile(r"\b(?:EDS|XML)[0-9]{3}\b")
#: Literal collections asserted equal to what a run reported: empty, or codes (in tuples with positions).
EXPECTED_SET = (ast.List, ast.Tuple, ast.Set)


@dataclass
class Evidence:
    """What the test functions of some source assert about rule codes."""

    reported: set[str] = field(default_factory=set)
    not_reported: set[str] = field(default_factory=set)


def codes_in(node: ast.AST) -> set[str]:
    """The codes in the string constants below ``node`` (comments are not in the tree)."""
    return {code for n in ast.walk(node) if isinstance(n, ast.Constant) and isinstance(n.value, str)
            for code in CODE.findall(n.value)}


def is_expected_set(node: ast.AST) -> bool:
    """An empty literal collection, or one whose strings are all rule codes: ``[]``, ``["EDS101"]``."""
    strings = [n.value for n in ast.walk(node) if isinstance(n, ast.Constant) and isinstance(n.value, str)]
    return isinstance(node, EXPECTED_SET) and all(CODE.fullmatch(s) for s in strings)


def lacks(node: ast.AST, code: str) -> bool:
    """``node`` is an expected set without ``code``, or a dict literal (file -> codes) with such a value."""
    if isinstance(node, ast.Dict):
        return any(is_expected_set(value) and code not in codes_in(value) for value in node.values)
    return is_expected_set(node) and code not in codes_in(node)


def absence_asserted(asserts: list[ast.Assert], code: str) -> bool:
    """``X not in Y`` with X the code or a variable (a table's code), ``not ...code...``, or an equality
    with an expected set (or a file -> expected set dict) that lacks the code."""
    for node in (n for a in asserts for n in ast.walk(a.test)):
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.Not) and code in codes_in(node.operand):
            return True
        if not isinstance(node, ast.Compare):
            continue
        for op, left, right in zip(node.ops, [node.left, *node.comparators[:-1]], node.comparators, strict=True):
            if isinstance(op, ast.NotIn) and (code in codes_in(left) or not codes_in(left)):
                return True
            if isinstance(op, ast.Eq) and (lacks(left, code) or lacks(right, code)):
                return True
    return False


def evidence(source: str, codes: list[str]) -> Evidence:
    """Codes asserted reported (in an assert, or in a table a test uses) and, by a test about the code,
    asserted not reported. Docstrings and comments do not count."""
    tree = ast.parse(source)
    tables = {target.id: codes_in(node.value) for node in tree.body if isinstance(node, ast.Assign)
              for target in node.targets if isinstance(target, ast.Name)}
    found = Evidence()
    for function in (n for n in ast.walk(tree) if isinstance(n, ast.FunctionDef) and n.name.startswith("test")):
        body = function.body[1:] if ast.get_docstring(function) is not None else function.body
        asserts = [n for statement in body for n in ast.walk(statement) if isinstance(n, ast.Assert)]
        named = {n.id for node in (*asserts, *function.decorator_list) for n in ast.walk(node)
                 if isinstance(n, ast.Name)}
        # codes in its asserts, its parametrize decorators, the module tables and the local names they use
        locals_ = [n.value for statement in body for n in ast.walk(statement) if isinstance(n, ast.Assign)
                   and any(isinstance(t, ast.Name) and t.id in named for t in n.targets)]
        asserted = set().union(*map(codes_in, (*asserts, *function.decorator_list, *locals_)),
                               *(tables[name] for name in named & tables.keys()))
        found.reported |= asserted
        about = asserted | {code for code in codes if code.lower() in function.name}
        found.not_reported |= {code for code in about if absence_asserted(asserts, code)}
    return found


def test_every_rule_code_has_a_test_that_it_is_reported_and_one_that_it_is_not():
    codes = [rule.code for rule in all_rules()]
    found = Evidence()
    for path in sorted(TESTS.glob("test_*.py")):
        one = evidence(path.read_text(encoding="utf-8"), codes)
        found.reported |= one.reported
        found.not_reported |= one.not_reported
    assert [code for code in codes if code not in found.reported] == []
    assert [code for code in codes if code not in found.not_reported] == []


def test_the_guard_counts_assertions_and_tables_not_comments_or_docstrings():
    source = '''
TABLE = {"EDS903": ("bad", "good")}

def test_mentions():
    """EDS901 is reported."""
    run()  # EDS901 too
    assert codes(run()) == ["EDS902"]

def test_table(code="EDS903"):
    assert code in TABLE and code not in run()

def test_eds904_both():
    assert "EDS904" in run("bad") and codes(run("good")) == []
'''
    found = evidence(source, ["EDS901", "EDS902", "EDS903", "EDS904"])
    assert found.reported == {"EDS902", "EDS903", "EDS904"}
    assert found.not_reported == {"EDS903", "EDS904"}


def test_eds017_braces_nested_too_deep():
    deep = edsconv.parse("[S]\nA = " + "{" * 65 + "1" + "}" * 65 + ";\n")
    assert codes(deep.diagnostics) == ["EDS017"]
    assert deep.sections[0].unparsed and not deep.sections[0].entries
    assert codes(edsconv.parse("[S]\nA = " + "{" * 64 + "1" + "}" * 64 + ";\n").diagnostics) == []


def test_eds110_url_without_a_scheme():
    def url_codes(url: str) -> list[str]:
        return codes(edsconv.build(edsconv.parse(f'[File]\nHomeURL = "{url}";\n')).diagnostics)

    assert url_codes("www.example.com") == ["EDS110"]
    assert url_codes("htts://www.example.com") == ["EDS110"]
    assert url_codes("http://www.example.com/probe eds/a.eds") == ["EDS110"]  # RFC 1738: a space only as %20
    assert url_codes("http://www.example.com/50%/a.eds") == ["EDS110"]
    assert url_codes("http://www.example.com/probe%20eds/~a.eds#top") == []
    assert url_codes("https://www.example.com") == []
    assert url_codes("ftp://example.com/eds") == []


def test_xml004_unknown_profile_kind():
    assert codes(validate.validate_file(REPO / "corpus" / "xml" / "broken" / "unknown-kind.xml").diagnostics) == [
        "XML004"]
    assert codes(validate.validate_file(REPO / "corpus" / "xml" / "cip-device" / "valid-complete.xml")
                 .diagnostics) == []


def test_xml006_file_too_large(monkeypatch):
    path = REPO / "corpus" / "xml" / "cip-device" / "valid-complete.xml"
    monkeypatch.setattr(validate, "read_xml", functools.partial(read_xml, max_bytes=100))
    assert codes(validate.validate_file(path).diagnostics) == ["XML006"]
    monkeypatch.setattr(validate, "read_xml", read_xml)
    assert codes(validate.validate_file(path).diagnostics) == []


def test_xml102_profile_that_describes_no_eds():
    flnet = CliRunner().invoke(cli, ["xml2eds", str(REPO / "corpus" / "xml" / "flnet-device" / "valid-complete.xml")])
    assert flnet.exit_code == 1 and "XML102" in flnet.output
    cip = CliRunner().invoke(cli, ["xml2eds", str(REPO / "corpus" / "xml" / "cip-device" / "valid-complete.xml")])
    assert cip.exit_code == 0 and "XML102" not in cip.output


# --- rules whose documented examples are whole EDS files: they do what docs/rules.md says -------------
#: The fenced bad and good examples of these rules parse as they are; the bad one triggers the rule, the
#: good one does not (the other rules' examples are single entries or elided).
RUNNABLE_EXAMPLES = ["EDS001", "EDS002", "EDS003", "EDS004", "EDS005", "EDS006", "EDS008", "EDS009", "EDS010",
                     "EDS011", "EDS012", "EDS013", "EDS015", "EDS016", "EDS101", "EDS205", "EDS207", "EDS208",
                     "EDS211", "EDS217"]


def analysed_codes(text: str) -> list[str]:
    return codes(edsconv.analyse(edsconv.parse(text))[1])


def fenced(example: str) -> str:
    match = re.fullmatch(r"```\n(.*)\n```", example, re.DOTALL)
    assert match, f"not a fenced EDS example: {example!r}"
    return match[1] + "\n"


@pytest.mark.parametrize("code", RUNNABLE_EXAMPLES)
def test_documented_examples_trigger_and_do_not(code):
    documented = load_rules().rules[code]
    assert code in analysed_codes(fenced(documented.bad))
    assert code not in analysed_codes(fenced(documented.good))


def test_eds014_reading_stops_at_the_100th_syntax_error():
    assert analysed_codes("[File]\n" + "Revision 1.1;\n" * 100).count("EDS014") == 1
    assert "EDS014" not in analysed_codes("[File]\n" + "Revision 1.1;\n" * 99)


# --- values (C.4.1.3): the inline examples of docs/rules.md, each in the section it belongs to ---------
PARAM = 'Param1 = 0,,,0x0000,{type},{size},"Speed","","",{values};'
STRINGI = PARAM.format(type="0xC7", size=2, values="0,100,0" + "," * 10 + '{{{count}, {{"eng",0xD0,4,"Speed"}}}}')
VALUE_CASES = {
    "EDS102": ("[Device]\nMajRev = 256;", "[Device]\nMajRev = 255;"),
    "EDS103": ("[Device]\nProdCode = 06402;", "[Device]\nProdCode = 6402;"),
    "EDS104": ("[Device]\nVendCode = 0x0000000FE;", "[Device]\nVendCode = 0x000000FE;"),
    "EDS105": ("[File]\nCreateDate = 13-11-2008;", "[File]\nCreateDate = 11-13-2008;"),
    "EDS106": ("[File]\nCreateTime = 24:00:00;", "[File]\nCreateTime = 23:59:59;"),
    "EDS107": ("[File]\nRevision = 0.0;", "[File]\nRevision = 1.0;"),
    "EDS108": ("[Params]\n" + PARAM.format(type="0xCA", size=4, values="0.0,1.23456789012345678,0.5"),
               "[Params]\n" + PARAM.format(type="0xCA", size=4, values="0.0,1.234567,0.5")),
    "EDS109": ('[Port]\nPort1 = TCP, "A", "20 F5 24 1", 2;', '[Port]\nPort1 = TCP, "A", "20 F5 24 01", 2;'),
    "EDS111": ("[Params]\n" + STRINGI.format(count=2), "[Params]\n" + STRINGI.format(count=1)),
    "EDS112": ("[Params]\n" + PARAM.format(type="2", size=2, values="0,100,0"),
               "[Params]\n" + PARAM.format(type="0xC7", size=2, values="0,100,0")),
    "EDS113": ("[Params]\n" + PARAM.format(type="0xEE", size=2, values="0,100,0"),
               "[Params]\n" + PARAM.format(type="0xC7", size=2, values="0,100,0")),
    "EDS114": ("[File]\nCreateDate = 01-01-1994;", "[File]\nCreateDate = 01-01-1996;"),
    "EDS116": ('[Device]\nProdName = "Probe\x01Adapter";', '[Device]\nProdName = "Probe\\x01Adapter";'),
    "EDS117": ('[Device]\nProdName = "Probe Adapter\\x00";', '[Device]\nProdName = "Probe\\x00Adapter";'),
    "EDS115": ("[File]\nRevision = 2.11;", "[File]\nRevision = 2.1;"),
}


@pytest.mark.parametrize("code", sorted(VALUE_CASES))
def test_value_rule_triggers_on_the_bad_value_only(code):
    bad, good = VALUE_CASES[code]
    assert analysed_codes(bad + "\n").count(code) == 1
    assert code not in analysed_codes(good + "\n")


# --- XML profiles -------------------------------------------------------------------------------------
XML = REPO / "corpus" / "xml"
VALID_DEVICE_PROFILE = XML / "cip-device" / "valid-complete.xml"
XML_CASES = {
    "XML001": XML / "broken" / "not-well-formed.xml",
    "XML002": XML / "security" / "xxe-file.xml",
    "XML003": XML / "cip-device" / "invalid-technology.xml",
    "XML005": XML / "powerlink-xdd" / "container.xml",
}


@pytest.mark.parametrize("code", sorted(XML_CASES))
def test_validate_reports_the_rule_on_its_file_only(code):
    assert codes(validate.validate_file(XML_CASES[code]).diagnostics) == [code]
    assert code not in codes(validate.validate_file(VALID_DEVICE_PROFILE).diagnostics)


def test_xml101_wrapper_without_its_eds(tmp_path):
    shutil.copy(REPO / "corpus" / "examples" / "io_adapter.eds", tmp_path)
    made = CliRunner().invoke(cli, ["eds2xml", "--wrapper", "-o", str(tmp_path), str(tmp_path / "io_adapter.eds")])
    assert made.exit_code == 0, made.output
    wrapper = tmp_path / "io_adapter_device_wrapper.xml"
    device, found = device_from_profiles([wrapper])
    assert device is not None and "XML101" not in codes(found)
    (tmp_path / "io_adapter.eds").unlink()
    device, found = device_from_profiles([wrapper])
    assert device is None and codes(found) == ["XML101"]


def read_profile(change=None) -> list[str]:
    """The codes of reading the valid device profile into a model, after ``change`` edits its tree."""
    root = parse_xml(VALID_DEVICE_PROFILE.read_bytes()).tree.getroot()
    if change is not None:
        change(root)
    return codes(read_device_profile(root, Device()))


def test_xml201_a_value_the_model_cannot_hold():
    def data_type(text):
        def change(root):
            root.find(".//Param[@id='Param1']/DataType").text = text
        return change

    assert read_profile(data_type("word")) == ["XML201"]
    assert read_profile(data_type("C7")) == []


def test_xml202_an_extension_value_that_cannot_be_decoded():
    def extension(kind):
        def change(root):
            values = etree.SubElement(root.find("ProfileBody/DeviceFunction"), EDSCONV + "Values")
            etree.SubElement(values, EDSCONV + "Value", path="parameters.Param1.default", kind=kind).text = "1"
        return change

    assert read_profile(extension("nonsense")) == ["XML202"]
    assert read_profile(extension("int")) == []
