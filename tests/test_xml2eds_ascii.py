"""xml2eds writes ASCII only (C.4.1.3.2; issue 20 item 5).

Every character of a string outside ASCII becomes an escape of Table C.4: ``\\xnn``,
``\\unnnn`` in an L string, and a character beyond the BMP its two 16-bit UTF-16
characters, which the reader joins again. What no string holds (a comment) is refused
with XML104. The written EDS never draws EDS005 and reads back to the same text.
"""

from __future__ import annotations

import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st

import edsconv
from conftest import REPO
from edsconv.cli import cli
from edsconv.eds.from_model import quote
from edsconv.model import Device
from edsconv.model.device import CommentNote
from edsconv.xml.convert import NotConverted, eds_text

#: any character a string of the model can hold (surrogates are no characters of a text)
EXAMPLE = REPO / "corpus" / "examples" / "io_adapter.eds"
TEXT = st.text(st.characters(blacklist_categories=("Cs",)), max_size=40)


def device_with(text: str) -> Device:
    device = edsconv.build(edsconv.load(EXAMPLE))
    device.file.description = text
    device.identity.vendor_name = text
    return device


@settings(max_examples=150, deadline=None)
@given(TEXT)
def test_the_eds_of_any_text_is_ascii_lints_without_eds005_and_reads_back(text: str) -> None:
    written = eds_text(device_with(text), "\n")
    assert written.isascii()
    read, diagnostics = edsconv.analyse(edsconv.parse(written))
    assert "EDS005" not in {d.code for d in diagnostics}
    assert (read.file.description, read.identity.vendor_name) == (text, text)


@pytest.mark.parametrize(("text", "spelling"), [
    ("\U0001F600", 'L"\\uD83D\\uDE00"'),
    ("a\U00010348b", 'L"a\\uD800\\uDF48b"'),
    ("M\u00fcller", '"M\\xFCller"'),
    ("\u03c0", 'L"\\u03C0"'),
])
def test_characters_beyond_ascii_are_escaped_as_table_c4_allows(text: str, spelling: str) -> None:
    assert quote(text).raw == spelling
    (section,) = edsconv.parse(f"[File]\nDescText = {spelling};\n").sections
    assert section.entries[0].fields[0].value.text == text


def test_a_lone_surrogate_escape_stays_what_it_is() -> None:
    (section,) = edsconv.parse('[File]\nDescText = L"\\uD83D x";\n').sections
    assert section.entries[0].fields[0].value.text == "\ud83d x"


def test_a_comment_outside_ascii_is_refused_with_xml104() -> None:
    device = device_with("plain")
    device.comments.append(CommentNote("File", "DescText", None, " Gr\u00fc\u00dfe"))
    with pytest.raises(NotConverted) as refused:
        eds_text(device, "\n")
    (diagnostic,) = refused.value.diagnostics
    assert diagnostic.code == "XML104"
    assert "U+00FC" in diagnostic.message


def test_xml2eds_of_a_profile_with_a_character_beyond_the_bmp(tmp_path) -> None:
    runner = CliRunner()
    eds = tmp_path / "smile.eds"
    eds.write_text(EXAMPLE.read_text().replace('DescText = "edsconv example I/O adapter";',
                                                'DescText = L"smile \\uD83D\\uDE00";'))
    assert runner.invoke(cli, ["eds2xml", "-o", str(tmp_path), str(eds)]).exit_code == 0
    result = runner.invoke(cli, ["xml2eds", str(tmp_path / "smile_device.xml"), str(tmp_path / "smile_commnet.xml")])
    assert result.exit_code == 0 and "XML104" not in result.stderr
    assert result.stdout.isascii() and "\\uD83D\\uDE00" in result.stdout
    assert edsconv.build(edsconv.parse(result.stdout)).file.description == "smile \U0001F600"
