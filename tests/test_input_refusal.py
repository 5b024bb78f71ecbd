"""Refusing input the same way in every command (issue 18: items 3, 22, 29, 31, 37 and their kin).

Each case runs every command a user reaches it with, and asserts one diagnostic with a stable code
where there was an internal error, a MemoryError or a hundred lines of escaped bytes.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner

import edsconv
from conftest import REPO
from edsconv.cli import cli
from edsconv.limits import cut, decimal, shown
from edsconv.lsp.analysis import analyse

EXAMPLE = REPO / "corpus" / "examples" / "io_adapter.eds"
NINES = "9" * 5000


def _example_with(old: str, new: str) -> str:
    text = EXAMPLE.read_text()
    assert old in text
    return text.replace(old, new, 1)


#: a 5000-digit number in a field, in a keyword number, and a second finding (a bad date) that must be kept
HUGE = {
    "field": _example_with("VendCode = 65535;", f"VendCode = {NINES};"),
    "revision": _example_with("MajRev = 1;", f"MajRev = {NINES};"),
    "keyword": _example_with("[Params]", f'[Params]\nParam{NINES} = 0,,,0x0000,0xC8,4,"P","","",0,100,1,,,,,,,,,;'),
}


@pytest.mark.parametrize("where", sorted(HUGE))
def test_a_number_of_5000_digits_is_eds102_and_the_other_findings_stay(where: str) -> None:
    text = HUGE[where].replace("CreateDate = ", "CreateDate = 13-45-2020; $ ", 1)
    _, diagnostics = edsconv.analyse(edsconv.parse(text))
    assert {"EDS102", "EDS105"} <= {d.code for d in diagnostics}
    (message,) = [d.message for d in diagnostics if d.code == "EDS102"]
    assert "(5000 characters)" in message or "(5005 characters)" in message
    assert len(message) < 200


@pytest.mark.parametrize("where", sorted(HUGE))
@pytest.mark.parametrize("command", [["lint"], ["show"], ["eds2xml", "-o", "{out}"], ["diff", str(EXAMPLE)],
                                     ["fmt", "--diff"], ["parse"]])
def test_no_command_fails_on_a_5000_digit_number(tmp_path: Path, where: str, command: list[str]) -> None:
    path = tmp_path / "h.eds"
    path.write_text(HUGE[where])
    arguments = [command[0], str(path), *(part.replace("{out}", str(tmp_path / "out")) for part in command[1:])]
    result = CliRunner().invoke(cli, arguments)
    assert "internal error" not in result.output + result.stderr, result.output
    assert result.exit_code in (0, 1), result.output
    if command[0] in ("lint", "eds2xml"):
        assert "EDS102" in result.output + result.stderr


def test_the_language_server_reports_eds102_for_a_5000_digit_keyword_number() -> None:
    codes = [d.code for d in analyse(HUGE["keyword"]).diagnostics]
    assert "EDS102" in codes and "EDS000" not in codes


def test_decimal_reads_leading_zeros_and_saturates_past_40_digits() -> None:
    assert decimal("0" * 5000 + "12") == 12
    assert decimal(NINES) == 10 ** 40 and decimal("9" * 40) == 10 ** 40 - 1


def test_messages_show_the_users_spelling_and_cut_long_values() -> None:
    assert shown("\\q") == "'\\q'"
    assert shown("a\x00b") == "'a\\x00b'"
    assert cut("x" * 5000) == "x" * 57 + "... (5000 characters)"


# --- files that are not EDS text: one diagnostic (items 22, 29, 37) -------------------------------------

def _refused_once(path: Path, code: str, *words: str) -> None:
    for command in (["lint"], ["eds2xml", "-o", str(path.parent / "out")], ["fmt", "--check"], ["parse"]):
        result = CliRunner().invoke(cli, [command[0], str(path), *command[1:]])
        lines = [line for line in (result.stdout + result.stderr).splitlines() if f" {code} " in line]
        assert result.exit_code == 1 and lines, (command, result.output)
        assert all(word in lines[0] for word in words), lines[0]
        assert "EDS001" not in result.output + result.stderr and len(result.stdout.splitlines()) <= 3
    assert not (path.parent / "out").exists()


def test_a_binary_file_is_one_eds026(tmp_path: Path) -> None:
    path = tmp_path / "ls.eds"
    path.write_bytes(Path("/bin/ls").read_bytes() if Path("/bin/ls").exists() else bytes(range(256)) * 64)
    _refused_once(path, "EDS026", "binary")


@pytest.mark.parametrize(("codec", "name"), [("utf-16-le", "UTF-16-LE"), ("utf-16-be", "UTF-16-BE")])
def test_utf16_without_a_bom_is_one_eds026(tmp_path: Path, codec: str, name: str) -> None:
    path = tmp_path / "wide.eds"
    path.write_bytes(EXAMPLE.read_text().encode(codec))
    _refused_once(path, "EDS026", f"looks like {name} text without a byte order mark")


def test_utf16_with_a_bom_and_a_stray_nul_in_a_string_are_still_read() -> None:
    wide = edsconv.parse(EXAMPLE.read_text().encode("utf-16"))
    assert "EDS026" not in [d.code for d in wide.diagnostics] and wide.sections
    stray = edsconv.parse(EXAMPLE.read_text().replace('VendName = "', 'VendName = "\x00', 1))
    _, diagnostics = edsconv.analyse(stray)
    assert "EDS116" in [d.code for d in diagnostics] and "EDS026" not in [d.code for d in diagnostics]


def test_an_xml_profile_given_as_an_eds_is_eds027_with_the_right_commands(tmp_path: Path) -> None:
    path = tmp_path / "device.eds"
    path.write_bytes((REPO / "corpus" / "xml" / "cip-device" / "valid-complete.xml").read_bytes())
    _refused_once(path, "EDS027", "`edsconv validate`", "`edsconv xml2eds`")
    assert "EDS027" not in [d.code for d in edsconv.parse(EXAMPLE.read_bytes()).diagnostics]


def test_an_eds_given_to_validate_or_xml2eds_gets_a_hint() -> None:
    for command in ("validate", "xml2eds"):
        result = CliRunner().invoke(cli, [command, str(EXAMPLE)])
        assert result.exit_code == 1
        assert "XML001" in result.output + result.stderr
        assert "this looks like an EDS file: `edsconv lint` checks it" in result.output + result.stderr


def test_deep_xml_is_refused_in_plain_words(tmp_path: Path) -> None:
    path = tmp_path / "deep.xml"
    path.write_text("<a>" * 1000 + "</a>" * 1000)
    result = CliRunner().invoke(cli, ["validate", str(path)])
    assert "elements nested deeper than 256 levels refused" in result.output
    assert "XML_PARSE_HUGE" not in result.output


def test_a_file_past_the_size_limit_is_eds025_without_reading_it(tmp_path: Path,
                                                                   monkeypatch: pytest.MonkeyPatch) -> None:
    import edsconv.eds.refusals as refusals

    monkeypatch.setattr(refusals, "MAX_EDS_BYTES", 4096)
    assert len(refusals.read_bytes("/dev/zero")) == 4097  # /dev/zero is never read to the end
    path = tmp_path / "big.eds"
    path.write_text(EXAMPLE.read_text() + "$ padding\n" * 1000)
    _refused_once(path, "EDS025", "EDS input limit")
    result = CliRunner().invoke(cli, ["lint", "/dev/zero"])
    assert result.exit_code == 1 and " EDS025 " in result.output and "MemoryError" not in result.output
    assert [d.code for d in analyse(path.read_text()).diagnostics] == ["EDS025"]
    monkeypatch.undo()
    assert [d.code for d in analyse(path.read_text()).diagnostics] == []


def test_an_undefined_escape_is_shown_as_written_not_as_a_python_repr() -> None:
    """Issue 18 item 31: the user wrote \\q and read '\\\\q'."""
    eds = edsconv.parse('[File]\nDescText = "a\\qb";\n')
    (message,) = [d.message for d in eds.diagnostics if d.code == "EDS003"]
    assert message.startswith("escape sequence '\\q' is not defined")
    long_date = edsconv.analyse(edsconv.parse(_example_with("CreateDate = ", "CreateDate = " + "x" * 5000 + "; $ ")))
    (date,) = [d.message for d in long_date[1] if "CreateDate" in d.message]
    assert "(5000 characters)" in date and len(date) < 200
