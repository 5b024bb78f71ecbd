"""edsconv diff: semantic changes between two EDS texts, NaN, exit codes, JSON."""

from __future__ import annotations

import json
from pathlib import Path

from click.testing import CliRunner

import edsconv
from edsconv.cli import cli
from edsconv.diff import Change, diff, format_text
from edsconv.model.build import build

BASE = """[File]
DescText = "Demo"; CreateDate = 01-02-2024; CreateTime = 10:00:00; Revision = 1.0;
[Device]
VendCode = 65535; VendName = "V"; ProdType = 12; ProdTypeStr = "Adapter"; ProdCode = 7;
MajRev = 1; MinRev = 1; ProdName = "Thing";
[Params]
Param1 = 0, , , 0x0000, 0xC8, 4, "RPI", "us", "", 1000, 100000, 10000;
Param2 = 0, , , 0x0002, 0xC6, 1, "Mode", "", "", 0, 2, 0;
Enum2 = 0, "Off", 1, "On", 2, "Auto";
Param3 = 0, , , 0x0000, 0xCA, 4, "Limit", "", "", , , QUIET-NAN;
[Assembly]
Assem100 = "In", "20 04 24 64 30 03", 2, , , , 8, Param2, 8, ;
[Connection Manager]
Connection1 = 0x04010002, 0x44640405, Param1, 1, Assem100, Param1, 2, Assem100, , , , ,
    "Exclusive Owner", "", "20 04 24 64";
[65535_Vendor]
Foo = 1;
"""


def changed(text: str, old: str, new: str) -> str:
    assert old in text, old
    return text.replace(old, new)


def device(text: str):
    eds = edsconv.parse(text)
    assert not eds.has_errors, [d.format() for d in eds.diagnostics]
    return build(eds)


def test_identical_meaning_in_other_spelling_order_and_comments() -> None:
    other = """$ a comment
[Device]
ProdName = "Thing"; MajRev = 1; MinRev = 1; ProdCode = 0x0007;
VendCode = 0xFFFF; VendName = "V"; ProdType = 12; ProdTypeStr = "Adapter";
[File]
DescText = "Demo"; CreateDate = 01-02-2024; CreateTime = 10:00:00; Revision = 1.0;
[Params]
Param3 = 0, , , 0, 202, 4, "Limit", "", "", , , QUIET-NAN;  $ NaN equals NaN
Enum2 = 0x00, "Off", 1, "On", 2, "Auto";
Param2 = 0, , , 2, 0xC6, 1, "Mode", "", "", 0, 2, 0;
Param1 = 0, , , 0x0000, 0xC8, 4, "RPI", "us", "", 1000, 100000, 10000;
[Assembly]
Assem100 = "In", "20 04 24 64 30 03", 2, , , , 8, Param2, 8, "";
[Connection Manager]
Connection1 = 0x04010002, 0x44640405, Param1, 1, Assem100, Param1, 2, Assem100, , , , ,
    "Exclusive Owner", "", "20 04 24 64";
[65535_Vendor]
Foo = 1;
"""
    assert diff(device(BASE), device(other)) == []


def test_nan_equals_nan_but_not_a_number() -> None:
    base = device(BASE)
    assert diff(base, device(BASE)) == []
    changes = diff(base, device(changed(BASE, "QUIET-NAN", "1.5")))
    assert changes == [Change("changed", "Param3 default", "QUIET-NAN", "1.5", "params")]


def test_params_added_removed_changed() -> None:
    text = changed(BASE, '"RPI", "us", "", 1000, 100000, 10000', '"RPI", "ms", "", 1000, 100000, 20000')
    text = changed(text, 'Param3 = 0, , , 0x0000, 0xCA, 4, "Limit", "", "", , , QUIET-NAN;\n',
                   'Param4 = 0, , , 0x0010, 0xC7, 2, "New", "", "", 0, 9, 1;\n')
    text = changed(text, '2, "Auto"', '3, "Manual"')
    changes = diff(device(BASE), device(text))
    assert Change("changed", "Param1 units", '"us"', '"ms"', "params") in changes
    assert Change("changed", "Param1 default", "10000", "20000", "params") in changes
    assert Change("removed", "Param3", '"Limit"', None, "params") in changes
    assert Change("added", "Param4", None, '"New"', "params") in changes
    assert Change("removed", "Param2 enum 2", '"Auto"', None, "params") in changes
    assert Change("added", "Param2 enum 3", None, '"Manual"', "params") in changes
    assert len(changes) == 6, changes


def test_assembly_members_and_descriptor() -> None:
    text = changed(BASE, '2, , , , 8, Param2, 8, ;', '3, 0x0001, , , 8, Param1, 8, , 8, Param2;')
    changes = diff(device(BASE), device(text))
    assert changes == [
        Change("changed", "Assem100 size", "2", "3", "assemblies"),
        Change("added", "Assem100 descriptor", None, "0x0001", "assemblies"),
        Change("changed", "Assem100 member 1", "8, Param2", "8, Param1", "assemblies"),
        Change("added", "Assem100 member 3", None, "8, Param2", "assemblies"),
    ]


def test_connection_fields() -> None:
    text = changed(BASE, "Param1, 1, Assem100, Param1, 2", "5000, 1, Assem100, Param1, 4")
    text = changed(text, '"Exclusive Owner"', '"Owner"')
    changes = diff(device(BASE), device(text))
    assert changes == [
        Change("changed", "Connection1 O=>T RPI", "Param1", "5000", "connections"),
        Change("changed", "Connection1 T=>O size", "2", "4", "connections"),
        Change("changed", "Connection1 name", '"Exclusive Owner"', '"Owner"', "connections"),
    ]


def test_identity_and_others_and_grouped_text() -> None:
    text = changed(BASE, "MajRev = 1", "MajRev = 2")
    text = changed(text, "Foo = 1;", "Foo = 0x1;\nBar = x;")
    text += "[Other]\nA = 1;\n"
    changes = diff(device(BASE), device(text))
    assert changes == [
        Change("changed", "identity.major_revision", "1", "2", "identity"),
        Change("changed", "[65535_Vendor] Foo", "1", "0x1", "others"),
        Change("added", "[65535_Vendor] Bar", None, "x", "others"),
        Change("added", "[Other]", None, None, "others"),
    ]
    assert format_text(changes).splitlines() == [
        "identity:", "  ~ identity.major_revision: 1 -> 2",
        "others:", "  ~ [65535_Vendor] Foo: 1 -> 0x1", "  + [65535_Vendor] Bar: x", "  + [Other]",
    ]


def test_references_compare_by_keyword() -> None:
    # Param1 changes, but the connection still names Param1: no connection change
    text = changed(BASE, '"RPI", "us"', '"Interval", "us"')
    assert [c.what for c in diff(device(BASE), device(text))] == ["Param1 name"]


# --- the command ----------------------------------------------------------------------------


def files(tmp_path: Path, new_text: str) -> tuple[str, str]:
    old, new = tmp_path / "old.eds", tmp_path / "new.eds"
    old.write_text(BASE)
    new.write_text(new_text)
    return str(old), str(new)


def test_command_exit_codes(tmp_path: Path) -> None:
    runner = CliRunner()
    same = runner.invoke(cli, ["diff", *files(tmp_path, BASE)])
    assert same.exit_code == 0, same.output
    assert "describe the same device" in same.output
    different = runner.invoke(cli, ["diff", *files(tmp_path, changed(BASE, "ProdCode = 7", "ProdCode = 8"))])
    assert different.exit_code == 1
    assert "identity:\n  ~ identity.product_code: 7 -> 8" in different.output
    missing = runner.invoke(cli, ["diff", str(tmp_path / "old.eds"), str(tmp_path / "nope.eds")])
    assert missing.exit_code == 2
    assert "cannot read" in missing.output


def test_command_json(tmp_path: Path) -> None:
    result = CliRunner().invoke(cli, ["diff", "--format", "json",
                                      *files(tmp_path, changed(BASE, "MinRev = 1", "MinRev = 3"))])
    assert result.exit_code == 1
    data = json.loads(result.output)
    assert data["equal"] is False
    assert data["changes"] == [{"kind": "changed", "category": "identity", "what": "identity.minor_revision",
                                "old": "1", "new": "3"}]


def test_inputs_without_a_section_are_not_the_same_device(tmp_path):
    """Issue 18 item 23: "hello" and an empty file "described the same device", exit 0."""
    from click.testing import CliRunner

    from edsconv.cli import cli

    (tmp_path / "a.eds").write_text("hello\n")
    (tmp_path / "b.eds").write_text("")
    result = CliRunner().invoke(cli, ["diff", str(tmp_path / "a.eds"), str(tmp_path / "b.eds")])
    assert result.exit_code == 2 and "same device" not in result.output
    assert result.stderr.startswith(f"{tmp_path / 'a.eds'}: cannot compare: no section could be read; ")
    assert "EDS001" in result.stderr


def test_syntax_errors_are_compared_with_a_warning(tmp_path):
    from click.testing import CliRunner

    from edsconv.cli import cli

    (tmp_path / "c.eds").write_text("[File]\nA = 1 ];\nB = 2;\n")
    result = CliRunner().invoke(cli, ["diff", str(tmp_path / "c.eds"), str(tmp_path / "c.eds")])
    assert result.exit_code == 0
    assert result.stderr.count("warning: 1 syntax error(s); the text they hide is not compared") == 2
