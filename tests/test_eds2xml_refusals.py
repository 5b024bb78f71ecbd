"""eds2xml converts only what it can carry (issue 11, defects 1 and 4): no profile from garbage, no
value turned into another, no identity invented, never a profile edsconv's own reader cannot read."""

from __future__ import annotations

import functools
import random
import re
from pathlib import Path

import pytest
from click.testing import CliRunner
from lxml import etree

import edsconv
from conftest import REPO
from edsconv.cli import cli
from edsconv.xml import convert
from edsconv.xml.convert import NotConverted, conversion_refusals, readable_document
from edsconv.xml.safe import parse_xml

EXAMPLE = REPO / "corpus" / "examples" / "io_adapter.eds"
TEXT = EXAMPLE.read_text()


def garbage() -> dict[str, bytes]:
    generator = random.Random(11)
    return {
        "empty": b"",
        "png": b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR" + bytes(range(256)) * 4,
        "utf16_without_bom": TEXT.encode("utf-16-le"),
        "random": bytes(generator.randrange(256) for _ in range(200_000)),
        "vendcode_of_500_digits": re.sub(r"VendCode = \d+;", "VendCode = " + "9" * 500 + ";", TEXT).encode(),
        "no_majrev": TEXT.replace("MajRev = 1;", "").encode(),
        "control_character_in_a_section_name": (TEXT + "\n[Vendor\x1bSection]\n    65535_Thing = 1;\n").encode(),
        "unterminated_string": TEXT.replace('ProdName = "Example IO Adapter 8DI/8DO";', 'ProdName = "x;').encode(),
    }


#: errors of reading whose text the profiles keep (issue 20 item 9): converted, refused with --strict
KEPT = {
    "leading_zeros": TEXT.replace("ProdCode = 1001;", "ProdCode = 01001;"),
    "syntax_error": TEXT.replace('ProdName = "Example IO Adapter 8DI/8DO";', 'ProdName = "x" "y" ]]];'),
    "date_day_first": TEXT.replace("CreateDate = ", "CreateDate = 13-11-2008; $ was ", 1),
}


def eds2xml(tmp_path: Path, name: str, data: bytes, *options: str):
    source = tmp_path / f"{name}.eds"
    source.write_bytes(data)
    out = tmp_path / "out"
    return CliRunner().invoke(cli, ["eds2xml", str(source), "-o", str(out), *options]), out


@pytest.mark.parametrize("name", sorted(garbage()))
@pytest.mark.parametrize("options", [(), ("--wrapper",)])
def test_garbage_and_lost_values_are_not_converted(tmp_path: Path, name: str, options: tuple[str, ...]) -> None:
    result, out = eds2xml(tmp_path, name, garbage()[name], *options)
    assert result.exit_code == 1, result.output
    assert not out.exists()
    assert "XML103" in result.stderr and "Traceback" not in result.stderr
    assert result.stdout == ""


def test_the_refusal_says_which_identity_is_missing_and_where() -> None:
    eds = edsconv.parse(TEXT.replace("MajRev = 1;", "").replace("VendCode = 65535;", "VendCode = 70000;"))
    device, _ = edsconv.analyse(eds)
    refusals = conversion_refusals(eds, device)
    assert [(d.code, d.line, d.message) for d in refusals] == [("XML103", 13, (
        "not converted: [Device] gives no readable VendCode, MajRev, which the profiles' identity is made of"))]
    strict = conversion_refusals(eds, device, strict=True)
    assert [(d.code, d.line) for d in strict] == [("XML103", 14), ("XML103", 13)]
    assert strict[0].message == ("not converted (--strict): the profiles would lose what 1 error(s) could not "
                                 "read (the first: EDS102 at line 14)")


@pytest.mark.parametrize("name", sorted(KEPT))
def test_errors_whose_text_is_kept_are_converted_and_written_back(tmp_path: Path, name: str) -> None:
    result, out = eds2xml(tmp_path, name, KEPT[name].encode())
    assert result.exit_code == 1 and "XML103" not in result.stderr, result.output
    assert sorted(p.name for p in out.iterdir()) == [f"{name}_commnet.xml", f"{name}_device.xml"]
    back = CliRunner().invoke(cli, ["xml2eds", str(out / f"{name}_device.xml"), str(out / f"{name}_commnet.xml")])
    assert back.exit_code == 0, back.output
    (tmp_path / "back.eds").write_text(back.stdout)
    same = CliRunner().invoke(cli, ["diff", str(tmp_path / f"{name}.eds"), str(tmp_path / "back.eds")])
    assert same.exit_code == 0, same.output


@pytest.mark.parametrize("name", sorted(KEPT))
def test_strict_refuses_any_error_of_reading(tmp_path: Path, name: str) -> None:
    result, out = eds2xml(tmp_path, name, KEPT[name].encode(), "--strict")
    assert result.exit_code == 1
    assert "XML103 not converted (--strict)" in result.stderr
    assert not out.exists()


def test_errors_of_the_checks_do_not_stop_the_conversion(tmp_path: Path) -> None:
    # EDS304: the group's member count is wrong; every value is still read and carried
    text = TEXT.replace('Group1 = "Configuration", 2, 2, 3;', 'Group1 = "Configuration", 5, 2, 3;')
    result, out = eds2xml(tmp_path, "checks", text.encode())
    assert result.exit_code == 1
    assert "EDS304" in result.stderr
    assert "XML103" not in result.stderr
    assert sorted(p.name for p in out.iterdir()) == ["checks_commnet.xml", "checks_device.xml"]


def test_a_clean_file_is_converted(tmp_path: Path) -> None:
    result, out = eds2xml(tmp_path, "clean", EXAMPLE.read_bytes())
    assert (result.exit_code, result.stderr) == (0, "")
    assert "XML103" not in result.stderr
    assert len(list(out.iterdir())) == 2


def test_a_comment_over_10_mb_is_refused_not_a_traceback(tmp_path: Path) -> None:
    text = TEXT.replace("[Device]", "[Device]\n$ " + "A" * 10_500_000, 1)
    result, out = eds2xml(tmp_path, "long_comment", text.encode())
    assert result.exit_code == 1
    assert not out.exists()
    (line,) = result.stderr.splitlines()
    assert "XML103 not converted: long_comment_device.xml would not be readable by XML parsers" in line


def test_the_writer_never_returns_what_the_reader_refuses(monkeypatch: pytest.MonkeyPatch) -> None:
    device, _ = edsconv.analyse(edsconv.load(EXAMPLE))
    root = etree.fromstring(b"<ISO15745Profile/>")
    monkeypatch.setattr(convert, "serialise", lambda root, kind: etree.tostring(root))
    assert readable_document("a.xml", root, "cip-device", device).data == b"<ISO15745Profile/>"
    monkeypatch.setattr(convert, "parse_xml", functools.partial(parse_xml, max_bytes=10))
    with pytest.raises(NotConverted, match="a.xml would not be readable by XML parsers"):
        readable_document("a.xml", root, "cip-device", device)
