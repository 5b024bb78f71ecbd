"""Inline suppression: ``$ edsconv: ignore[CODE]`` on an entry or header, ``ignore-file[...]``, and EDS099."""

from __future__ import annotations

from pathlib import Path

from conftest import REPO
from edsconv import lint
from edsconv.config import FileRules
from edsconv.diagnostics import Selection
from edsconv.eds.reader import parse

GOOD = (REPO / "corpus" / "examples" / "io_adapter.eds").read_text(encoding="ascii")
#: ProdCode with leading zeros (EDS103) and a CreateDate before 1996 (EDS114, a warning)
FAULTY = GOOD.replace("ProdCode = 1001;", "ProdCode = 01001;").replace("CreateDate = 11-22-2026;",
                                                                       "CreateDate = 11-22-1994;")


def codes(text: str, rules: FileRules = lint.EVERY_RULE) -> list[str]:
    return [d.code for d in lint.check(parse(text, "x.eds"), rules)]


def test_the_faults_without_suppression():
    assert codes(FAULTY) == ["EDS114", "EDS103"]


def test_ignore_on_the_entry_line_silences_that_entry_only():
    text = FAULTY.replace("ProdCode = 01001;", "ProdCode = 01001;   $ edsconv: ignore[EDS103]")
    assert codes(text) == ["EDS114"]
    # the same code on another entry does not reach ProdCode, and is itself reported as unused
    elsewhere = FAULTY.replace("MajRev = 1;", "MajRev = 1;   $ edsconv: ignore[EDS103]")
    assert codes(elsewhere) == ["EDS114", "EDS103", "EDS099"]


def test_ignore_on_a_comment_line_above_or_on_a_field_of_a_multi_line_entry():
    above = FAULTY.replace("        ProdCode = 01001;", "        $ edsconv: ignore[EDS103]\n        ProdCode = 01001;")
    assert "EDS103" not in codes(above)
    param = GOOD.replace("2000,1000000,10000,     $ min, max, default data values",
                         "2000,1000000,010000,    $ min, max, default data values; edsconv: ignore[EDS103]")
    assert codes(param) == []
    assert codes(param.replace("edsconv: ignore[EDS103]", "")) == ["EDS103"]


def test_several_codes_prefixes_and_aliases():
    text = FAULTY.replace("ProdCode = 01001;", "ProdCode = 01001;   $ edsconv: ignore[EDS114, EDS1]")
    # EDS1 covers EDS103 on this entry; EDS114 is on another entry, so that code is unused here
    assert codes(text) == ["EDS114", "EDS099"]


def test_file_level_suppression_anywhere_in_the_file():
    text = FAULTY + "$ edsconv: ignore-file[EDS114, EDS103]\n"
    assert codes(text) == []
    assert codes(GOOD + "$ edsconv: ignore-file[EDS114]\n") == ["EDS099"]


def test_unused_and_unknown_codes_are_eds099_at_the_code():
    text = GOOD.replace("VendCode = 65535;", "VendCode = 65535;   $ edsconv: ignore[EDS102, EDS998]")
    found = lint.check(parse(text, "x.eds"))
    line = next(line for line in text.splitlines() if "VendCode" in line)
    at = line.index("EDS102") + 1, line.index("EDS998") + 1
    assert [(d.code, d.column, d.end_column) for d in found] == [("EDS099", at[0], at[0] + 6),
                                                                ("EDS099", at[1], at[1] + 6)]
    assert "suppresses nothing: no EDS102 diagnostic in this entry" in found[0].message
    assert "EDS998] names no rule" in found[1].message


def test_a_code_that_is_not_selected_is_not_judged_and_eds099_can_be_ignored():
    text = GOOD.replace("VendCode = 65535;", "VendCode = 65535;   $ edsconv: ignore[EDS102]")
    assert "EDS099" in codes(text)
    assert "EDS099" not in codes(text, FileRules(Selection.of(ignore=["EDS102"])))
    assert "EDS099" not in codes(text, FileRules(Selection.of(ignore=["EDS099"])))
    assert "EDS099" not in codes(text, FileRules(dropped=("EDS1",)))


def test_the_command_honours_suppressions(tmp_path: Path):
    from click.testing import CliRunner

    from edsconv.cli import cli

    path = tmp_path / "device.eds"
    path.write_text(FAULTY.replace("ProdCode = 01001;", "ProdCode = 01001; $ edsconv: ignore[EDS103]"))
    result = CliRunner().invoke(cli, ["lint", "--isolated", str(path)], standalone_mode=False)
    assert result.return_value == 0
    assert [line.split()[2] for line in result.stdout.splitlines()] == ["EDS114"]


def test_the_directive_is_read_in_any_case_and_with_blanks():
    """Issue 18 item 21: these were silently no suppression at all."""
    for comment in ("$ EDSCONV: IGNORE[EDS103]", "$ edsconv: ignore [EDS103]", "$ Edsconv : Ignore [ eds103 ]"):
        assert codes(FAULTY.replace("ProdCode = 01001;", f"ProdCode = 01001;   {comment}")) == ["EDS114"]
    assert codes(FAULTY.replace("MajRev = 1;", "MajRev = 1;   $ EDSCONV: IGNORE-FILE [EDS103]")) == ["EDS114"]


def test_an_unknown_or_bracketless_directive_is_eds099_malformed():
    for comment in ("$ edsconv: ignore-next[EDS103]", "$ edsconv: ignore EDS103", "$ edsconv: noqa[EDS103]"):
        text = FAULTY.replace("ProdCode = 01001;", f"ProdCode = 01001;   {comment}")
        found = lint.check(parse(text, "x.eds"), lint.EVERY_RULE)
        assert [d.code for d in found] == ["EDS114", "EDS103", "EDS099"]
        assert found[-1].message.startswith(f"malformed edsconv comment '{comment[2:]}': the directives are")
    # a comment that merely mentions edsconv is no directive
    assert codes(FAULTY.replace("MajRev = 1;", "MajRev = 1;   $ checked by edsconv: 0.2")) == ["EDS114", "EDS103"]


def test_a_text_that_never_says_edsconv_is_not_walked_for_directives():
    """The fast path: no comment can hold a directive, so no entry's fields are made to look for one
    (the language server's largest per-keystroke cost on a large file); one mention anywhere walks them."""
    from edsconv.suppress import apply_suppressions

    def unread_after(text: str) -> int:
        eds = parse(text, "x.eds")
        apply_suppressions(eds, [], lambda code: True)
        return sum(not entry.is_read for section in eds.sections for entry in section.entries)

    silent = GOOD.replace("edsconv", "an")  # the example names edsconv in a comment and two strings
    assert unread_after(silent) > 0
    assert unread_after(silent + "$ EDSCONV was here\n") == 0
