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
