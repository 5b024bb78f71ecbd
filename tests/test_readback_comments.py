"""xml2eds puts each comment back on the field it was written on, trailing empty fields included
(issue 11, defect 10: the read-back EDS kept the comments of the trailing empty fields it dropped,
as loose lines after the last value)."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner

import edsconv
from conftest import REPO
from edsconv.cli import cli

EXAMPLE = REPO / "corpus" / "examples" / "io_adapter.eds"


def field_comments(eds: edsconv.EdsFile) -> dict[tuple[str, str, int], list[str]]:
    return {(section.name, entry.keyword, index): [c.text for c in field.comments]
            for section in eds.sections for entry in section.entries
            for index, field in enumerate(entry.fields) if field.comments}


def test_every_field_comment_comes_back_on_its_field(tmp_path: Path) -> None:
    assert CliRunner().invoke(cli, ["eds2xml", str(EXAMPLE), "-o", str(tmp_path)]).exit_code == 0
    result = CliRunner().invoke(cli, ["xml2eds", str(tmp_path / "io_adapter_device.xml"),
                                      str(tmp_path / "io_adapter_commnet.xml")])
    assert result.exit_code == 0, result.output
    original, read_back = edsconv.load(EXAMPLE), edsconv.parse(result.stdout)
    assert field_comments(read_back) == field_comments(original)
    param1 = next(e for s in read_back.sections for e in s.entries if e.keyword == "Param1")
    assert [f.value for f in param1.fields[12:]] == [None] * 9  # the empty scaling, link and precision fields
    assert edsconv.analyse(read_back)[0].parameters["Param1"] == edsconv.analyse(original)[0].parameters["Param1"]
