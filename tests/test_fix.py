"""``edsconv lint --fix`` and ``--diff``: the safe fixes, line ends, comments, encodings, atomic writes."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from click.testing import CliRunner

from conftest import REPO
from edsconv import fix, lint
from edsconv.cli import cli
from edsconv.diagnostics import FixSafety, all_rules
from edsconv.eds.reader import parse

GOOD = (REPO / "corpus" / "examples" / "io_adapter.eds").read_text(encoding="ascii")
#: One fault of each fixable rule, each on its own line
FAULTS = {
    "EDS002": ('DescText = "edsconv example I/O adapter";', 'DescText = "edsconv example I/O adapter"'),
    "EDS099": ("VendCode = 65535;", "VendCode = 65535;   $ edsconv: ignore[EDS102]"),
    "EDS103": ("ProdCode = 1001;", "ProdCode = 01001;"),
    "EDS207": ('"",                     $ help string', ',                     $ help string'),
    "EDS228": ("[Device Classification]", "[DEVICE classification]"),
}


def broken(codes=tuple(FAULTS)) -> str:
    text = GOOD
    for code in codes:
        good, bad = FAULTS[code]
        text = text.replace(good, bad, 1)
    return text


def run(*args: str):
    return CliRunner().invoke(cli, ["lint", "--isolated", *args], standalone_mode=False, catch_exceptions=False)


def test_every_safe_rule_has_a_fixer_and_every_fixer_a_safe_rule():
    safe = {r.code for r in all_rules() if r.fix is FixSafety.SAFE}
    assert safe == set(fix.FIXERS) == set(FAULTS)
    assert all(fix.fix_documentation(code) for code in safe)


@pytest.mark.parametrize("code", sorted(FAULTS))
def test_each_fix_repairs_its_fault_and_leaves_the_rest_of_the_file_as_it_was(code: str):
    text = broken([code])
    before = [d.code for d in lint.check(parse(text, "x.eds"))]
    assert code in before
    outcome = fix.fix_source(text.encode(), "x.eds", lint.check)
    assert [d.code for d in outcome.fixed] == [code]
    assert code not in [d.code for d in outcome.diagnostics]
    assert outcome.diagnostics == []
    # EDS099: the comment held only the suppression, so it goes with the space before it
    assert outcome.data.decode() == GOOD


def test_faults_without_a_single_repair_are_left_alone():
    # a required field other than the help string: only the author knows its value
    text = GOOD.replace('"Exclusive Owner",', ",", 1)
    outcome = fix.fix_source(text.encode(), "x.eds", lint.check)
    assert "EDS207" in [d.code for d in outcome.diagnostics] and outcome.fixed == []
    # [DEVICE] when the file already has a [Device]: renaming would make a duplicate (EDS230 says what it is)
    text = GOOD + "\n[DEVICE]\n        Extra = 1;\n"
    outcome = fix.fix_source(text.encode(), "x.eds", lint.check)
    assert "EDS230" in [d.code for d in outcome.diagnostics] and outcome.data == text.encode()


def test_unused_code_among_several_is_removed_from_the_list():
    text = GOOD.replace("ProdCode = 1001;", "ProdCode = 01001;   $ vendor note; edsconv: ignore[EDS998, EDS103]")
    outcome = fix.fix_source(text.encode(), "x.eds", lint.check)
    assert b"ProdCode = 01001;   $ vendor note; edsconv: ignore[EDS103]\n" in outcome.data
    assert outcome.diagnostics == []


def test_fix_writes_the_file_keeping_crlf_comments_encoding_and_mode(tmp_path: Path):
    path = tmp_path / "device.eds"
    text = broken().replace("\n", "\r\n").replace("$ Example EtherNet/IP", "$ Exempel f\u00f6r EtherNet/IP")
    path.write_bytes(text.encode("cp1252"))
    os.chmod(path, 0o640)
    result = run("--fix", str(path))
    assert result.return_value == 0
    assert result.stdout.splitlines() == [f"{path}:1:1: warning: EDS005 the file is not plain ASCII (read as "
                                          "cp1252); the first character outside ASCII is on line 1 [C.4.1.3.2]"]
    expected = GOOD.replace("\n", "\r\n").replace("$ Example EtherNet/IP", "$ Exempel f\u00f6r EtherNet/IP")
    assert path.read_bytes() == expected.encode("cp1252")
    assert oct(path.stat().st_mode & 0o777) == "0o640"
    assert [p.name for p in tmp_path.iterdir()] == ["device.eds"]  # no temporary file left


def test_diff_shows_the_fix_and_writes_nothing(tmp_path: Path, capsys):
    path = tmp_path / "device.eds"
    path.write_text(broken(["EDS103", "EDS002"]), encoding="ascii")
    result = run("--diff", str(path))
    assert result.return_value == 1
    changed = [line for line in result.stdout.splitlines() if line[:1] in "+-" and line[:3] not in ("+++", "---")]
    assert changed == ['-        DescText = "edsconv example I/O adapter"',
                       '+        DescText = "edsconv example I/O adapter";',
                       "-        ProdCode = 01001;", "+        ProdCode = 1001;"]
    assert path.read_text(encoding="ascii") == broken(["EDS103", "EDS002"])
    path.write_text(GOOD, encoding="ascii")
    assert run("--diff", str(path)).return_value == 0


def test_fix_honours_the_selection_and_reports_what_remains(tmp_path: Path):
    path = tmp_path / "device.eds"
    path.write_text(broken(["EDS103", "EDS002"]), encoding="ascii")
    result = run("--fix", "--ignore", "EDS103", str(path))
    assert result.return_value == 0
    text = path.read_text(encoding="ascii")
    assert "ProdCode = 01001;" in text and 'DescText = "edsconv example I/O adapter";' in text
    assert run(str(path)).return_value == 1  # EDS103 is still there


def test_fix_through_a_symbolic_link_fixes_the_target_and_keeps_the_link(tmp_path: Path):
    target = tmp_path / "real.eds"
    target.write_text(broken(["EDS103"]), encoding="ascii")
    link = tmp_path / "link.eds"
    link.symlink_to(target)
    assert run("--fix", str(link)).return_value == 0
    assert link.is_symlink() and target.read_text(encoding="ascii") == GOOD


def test_a_fix_that_would_overlap_another_waits_for_the_next_round():
    edits = fix._disjoint([fix.Fix("a", (fix.Edit(1, 1, 1, 5, "x"),)), fix.Fix("b", (fix.Edit(1, 3, 1, 4, "y"),)),
                           fix.Fix("c", (fix.Edit(2, 1, 2, 1, "z"),))])
    assert [e.text for e in edits] == ["x", "z"]
    assert fix.apply_edits("abcdef\r\nline\rend", edits) == "xef\r\nzline\rend"


def test_the_editor_gets_the_same_fix_for_an_unused_suppression():
    from edsconv.lsp.actions import lint_fixes
    from edsconv.lsp.analysis import analyse

    text = broken(["EDS099"])
    analysis = analyse(text, 1, "x.eds")
    line = text.splitlines().index("        VendCode = 65535;   $ edsconv: ignore[EDS102]") + 1
    (fix_,) = lint_fixes(analysis, "EDS099", line, text.splitlines()[line - 1].index("EDS102") + 1)
    assert fix.apply_edits(text, fix_.edits) == GOOD


def test_a_fixer_is_used_only_for_a_rule_whose_fix_is_safe(monkeypatch):
    """A rule without a safe fix (none, or unsafe) is never repaired, even if a fixer were registered."""
    import dataclasses

    from edsconv.diagnostics import load_rules

    text = broken(["EDS103"])
    eds = parse(text, "x.eds")
    (diagnostic,) = [d for d in lint.check(eds) if d.code == "EDS103"]
    lines = fix.split_lines(text)
    assert fix.fix_for(eds, lines, diagnostic) is not None
    rules = dict(load_rules().rules)
    rules["EDS103"] = dataclasses.replace(rules["EDS103"], fix=FixSafety.UNSAFE)
    monkeypatch.setattr(fix, "load_rules", lambda: dataclasses.replace(load_rules(), rules=rules))
    assert fix.fix_for(eds, lines, diagnostic) is None
    outcome = fix.fix_source(text.encode(), "x.eds", lint.check)
    assert outcome.data == text.encode() and outcome.fixed == []
