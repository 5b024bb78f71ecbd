"""Canonical EDS: device_to_eds round trips through the semantic model, canonical()
and write_canonical() keep a syntax model's content, only reordered and laid out."""

from __future__ import annotations

import dataclasses
import math
from collections import defaultdict
from pathlib import Path

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from tests.conftest import REAL_EDS, REPO, needs_real_corpus

import edsconv
from edsconv import spec_tables as tables
from edsconv.diff import diff
from edsconv.eds.canonical import canonical, write_canonical
from edsconv.eds.from_model import device_to_eds, quote, real_text
from edsconv.eds.syntax import Scalar
from edsconv.eds.writer import write
from edsconv.model import Device, Parameter, Scaling
from edsconv.model.build import build
from edsconv.model.values import PathItem, StringIMember, to_real

#: corpus/shall and corpus/allowed are one base file changed in one place each (test_shall_probes.py reads them).
CORPUS = sorted(p for p in (REPO / "corpus").rglob("*")
                if p.suffix.lower() == ".eds" and not {"shall", "allowed"} & set(p.parts))


def round_trip(device: Device) -> Device:
    return build(edsconv.parse(write(device_to_eds(device))))


def same(a: object, b: object) -> bool:
    """``a == b`` for models, where a NaN equals a NaN in the same place.

    A REAL value may be NaN (C.4.1.3.10). Python 3.13's dataclass ``__eq__`` compares field by field,
    so NaN != NaN makes two equal models unequal; 3.11 and 3.12 compared tuples of fields, whose
    identity shortcut hid that only when both sides held the same float object.
    """
    if dataclasses.is_dataclass(a) and not isinstance(a, type):
        return type(a) is type(b) and all(same(getattr(a, f.name), getattr(b, f.name))
                                          for f in dataclasses.fields(a) if f.compare)
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(same(a[key], b[key]) for key in a)
    if isinstance(a, list | tuple) and isinstance(b, list | tuple):
        return type(a) is type(b) and len(a) == len(b) and all(map(same, a, b))
    if isinstance(a, float) and isinstance(b, float) and math.isnan(a):
        return math.isnan(b)
    return a == b


def assert_round_trip(path: Path) -> None:
    device = build(edsconv.load(path))
    assert same(round_trip(device), device), path.name


# --- device_to_eds ------------------------------------------------------------------------


@pytest.mark.parametrize("path", CORPUS, ids=lambda p: str(p.relative_to(REPO / "corpus")))
def test_device_to_eds_round_trips_the_corpus(path: Path) -> None:
    assert_round_trip(path)


@needs_real_corpus
@pytest.mark.parametrize("path", REAL_EDS, ids=lambda p: p.name[:60])
def test_device_to_eds_round_trips_real_files(path: Path) -> None:
    assert_round_trip(path)


def test_corpus_is_not_empty() -> None:
    assert len(CORPUS) >= 20


def test_device_to_eds_order_spelling_and_comments() -> None:
    text = """
[Params]
Enum2 = 0, "a", 1, "b";
Param2 = 0,,, 16, 0xD1, 1, "P2", "", "", ,, 255;  $ the second
Param1 = 0,,, 0, 199, 2, "P1", "", "", 0, 100, 5;
[Device]
ProdCode = 0x0010;
VendCode = 1;
[File]
DescText = "x";
[65535_Vendor]
Foo = 0x1, bar, "baz";
[Other]
Bar = 1;
"""
    device = build(edsconv.parse(text))
    eds = device_to_eds(device)
    assert [s.name for s in eds.sections] == ["File", "Device", "Params", "Other", "65535_Vendor"]
    params = eds.section("Params")
    assert [e.keyword for e in params.entries] == ["Param1", "Param2", "Enum2"]
    param1, param2 = params.entries[:2]
    # descriptor and data type code in hex, the rest decimal; trailing optional fields dropped
    assert [f.raw for f in param1.fields] == ["0", None, None, "0x0000", "0xC7", "2", '"P1"', '""', '""',
                                              "0", "100", "5"]
    # a BYTE parameter's default is a bit string: hex
    assert param2.fields[11].raw == "0xFF"
    assert [c.text for c in param2.fields[11].comments] == [" the second"]
    assert [f.raw for f in eds.section("Device").entries[0].fields] == ["1"]
    assert [f.raw for f in eds.section("Device").entries[1].fields] == ["16"]
    # generic entries as written
    assert [f.raw for f in eds.section("65535_Vendor").entries[0].fields] == ["0x1", "bar", '"baz"']
    # the vendor section moved last: the same device, other_sections (a list) in canonical order
    again = round_trip(device)
    assert diff(device, again) == []
    assert [s.name for s in again.other_sections] == ["Other", "65535_Vendor"]
    assert same(round_trip(again), again)


def test_quote_escapes() -> None:
    assert quote('a"b\\c').raw == '"a\\"b\\\\c"'
    assert quote("tab\there\n").raw == '"tab\\there\\n"'
    assert quote("caf\u00e9\x01").raw == '"caf\\xE9\\x01"'
    assert quote("\u20ac").raw == 'L"\\u20AC"'


@given(st.text(alphabet=st.characters(max_codepoint=0xFFFF, blacklist_categories=("Cs",)), max_size=30))
def test_quoted_text_reads_back(text: str) -> None:
    (section,) = edsconv.parse(f"[File]\nDescText = {quote(text).raw};\n").sections
    assert section.entries[0].fields[0].value.text == text


def representable(value: float, type_name: str) -> bool:
    """Some notation within the C.4.1.3.10 digit limits reads back as ``value``
    (a double that needs 17 significant digits has none: an LREAL mantissa has 16)."""
    if math.isnan(value) or math.isinf(value):
        return True
    digits = tables.DATA_TYPES_BY_NAME[type_name].floats.mantissa_digits
    return float(f"{value:.{digits - 1}e}") == value and tables.DATA_TYPES_BY_NAME[type_name].in_range(value)


@given(st.floats(allow_nan=True, allow_infinity=True), st.sampled_from(["REAL", "LREAL"]))
def test_real_text_reads_back(value: float, type_name: str) -> None:
    assume(representable(value, type_name))
    text = real_text(value, type_name).raw
    back = to_real(Scalar(text), type_name)
    assert (math.isnan(value) and math.isnan(back)) or back == value


def test_real_text_special_words() -> None:
    assert [real_text(v).raw for v in (math.nan, math.inf, -math.inf, 1e-05, 0.5)] == [
        "QUIET-NAN", "INFINITY", "-INFINITY", "1e-05", "0.5"]
    # too many digits for the decimal notation: the scientific one
    assert real_text(0.1 + 0.2).raw == "3.0000000000000004e-01"


_INT_TYPES = [t for t in tables.DATA_TYPES if t.kind in ("unsigned", "signed", "bits") and t.size]


@st.composite
def parameters(draw) -> Parameter:
    data_type = draw(st.sampled_from([*_INT_TYPES, tables.DATA_TYPES_BY_NAME["REAL"],
                                      tables.DATA_TYPES_BY_NAME["LREAL"], tables.DATA_TYPES_BY_NAME["STRING"]]))
    if data_type.kind == "real":
        # the reader's NaN is math.nan itself: dataclass equality finds NaN equal only to itself
        value = st.floats().filter(lambda v, name=data_type.name: representable(v, name)).map(
            lambda v: math.nan if math.isnan(v) else v)
    elif data_type.kind == "string":
        value = st.integers(0, 65535)
    else:
        value = st.integers(data_type.minimum, data_type.maximum)
    text = st.text(alphabet=st.characters(max_codepoint=0x2FF, blacklist_categories=("Cs",)), max_size=12)
    number = draw(st.integers(1, 9999))
    is_bits = data_type.kind == "bits"
    default = draw(text) if data_type.kind == "string" else draw(value)
    parameter = Parameter(
        f"Param{number}", "Param", number,
        link_path_size=draw(st.none() | st.integers(0, 255)),
        link_path=draw(st.none() | st.lists(st.integers(0, 255), max_size=6).map(
            lambda b: tuple(PathItem(byte=x) for x in b))),
        descriptor=draw(st.integers(0, 0xFFFF)),
        data_type=data_type, data_type_code=data_type.code, data_size=data_type.size or 1,
        name=draw(text), units=draw(text), help=draw(st.none() | text),
        minimum=None if is_bits else draw(st.none() | value), maximum=None if is_bits else draw(st.none() | value),
        default=default,
        scaling=Scaling(*draw(st.lists(st.none() | st.integers(0, 65535), min_size=9, max_size=9).map(
            lambda v: [*v[:3], None if v[3] is None else v[3] - 32768, *v[4:8],
                       None if v[8] is None else v[8] % 256]))) if data_type.numeric else Scaling(),
        international_name=draw(st.none() | st.lists(st.tuples(st.sampled_from(["eng", "deu"]), text), min_size=1,
                                                     max_size=2).map(
            lambda m: tuple(StringIMember(lang, 0xD0, 4, t) for lang, t in m))),
    )
    if data_type.kind in ("unsigned", "bits") and draw(st.booleans()):
        parameter.enum = {draw(value): draw(text) for _ in range(draw(st.integers(1, 3)))}
    return parameter


@settings(max_examples=150, deadline=None)
@given(st.lists(parameters(), max_size=3, unique_by=lambda p: p.number))
def test_generated_parameters_round_trip(generated: list[Parameter]) -> None:
    device = Device(parameters={p.keyword: p for p in generated})
    assert same(round_trip(device), device)


# --- canonical() and write_canonical() ---------------------------------------------------


def by_keyword(section) -> dict[str, list]:
    out = defaultdict(list)
    for entry in section.entries:
        out[entry.keyword].append(entry)
    return dict(out)


def assert_same_content(eds, ordered) -> None:
    """Same sections, each with the same entries (duplicates in file order), comments,
    unparsed text and preamble: only the order differs."""
    assert sorted(s.name for s in eds.sections) == sorted(s.name for s in ordered.sections)
    originals = defaultdict(list)
    for section in eds.sections:
        originals[section.name].append(section)
    for section in ordered.sections:
        original = originals[section.name].pop(0)
        assert by_keyword(original) == by_keyword(section)
        assert (original.comments, original.leading_comments) == (section.comments, section.leading_comments)
        assert sorted(u.text for _, u in original.unparsed) == sorted(u.text for _, u in section.unparsed)
    assert eds.preamble == ordered.preamble
    assert eds.trailing_comments == ordered.trailing_comments


def check_canonical(path: Path) -> None:
    eds = edsconv.load(path)
    ordered = canonical(eds)
    assert_same_content(eds, ordered)
    text = write_canonical(eds)
    again = edsconv.parse(text)
    assert again == ordered, path.name
    assert write_canonical(again) == text, "write_canonical is not idempotent"


@pytest.mark.parametrize("path", CORPUS, ids=lambda p: str(p.relative_to(REPO / "corpus")))
def test_canonical_keeps_content_corpus(path: Path) -> None:
    check_canonical(path)


@needs_real_corpus
@pytest.mark.parametrize("path", REAL_EDS, ids=lambda p: p.name[:60])
def test_canonical_keeps_content_real(path: Path) -> None:
    check_canonical(path)


MESSY = """$ header comment
[Device]
ProdName="Thing";VendCode=0x0001;
[65535_Vendor]
Foo=1;
[File]
Revision = 1.1; $ rev
DescText = "d";
[Connection Manager]
Connection1 = 0x04010002, 0x44640405, 10000, 2, Assem150, 10000, 2, Assem100, , , , , "EO", "", "20 04";
[Params]
Enum1 = 0, "Off", 1, "On";
Param1 = 0, , , 0x0002, 0xC6, 1, "Mode", "", "", 0, 1, 0;
[Assembly]
Assem100 = "In", "20 04 24 64 30 03", 2, , , , 8, Param1, 8, ;
Revision = 2;
"""

EXPECTED = """[File]
    DescText = "d";
    Revision = 1.1;  $ rev

$ header comment
[Device]
    VendCode = 0x0001;
    ProdName = "Thing";

[Params]
    Param1 =
        0,
        ,,
        0x0002,
        0xC6,
        1,
        "Mode",
        "",
        "",
        0, 1, 0;
    Enum1 = 0, "Off", 1, "On";

[Assembly]
    Revision = 2;
    Assem100 =
        "In",
        "20 04 24 64 30 03",
        2,
        ,
        ,,
        8, Param1,
        8,;

[Connection Manager]
    Connection1 =
        0x04010002,
        0x44640405,
        10000, 2, Assem150,
        10000, 2, Assem100,
        ,,
        ,,
        "EO",
        "",
        "20 04";

[65535_Vendor]
    Foo = 1;
"""


def test_layout_of_a_small_file() -> None:
    eds = edsconv.parse(MESSY)
    text = write_canonical(eds)
    assert text == EXPECTED
    assert_same_content(eds, edsconv.parse(text))


def test_layout_aligns_comments_of_a_long_entry() -> None:
    text = write_canonical(edsconv.parse(
        "[Params]\nParam1 = 0, , , 0x0000, $ descriptor\n 0xC7, 2, \"Long name\", \"\", \"\", 0, 10, 5; $ default\n"))
    lines = text.splitlines()
    assert lines[1] == "    Param1 ="
    commented = [line for line in lines if "$" in line]
    assert len({line.index("$") for line in commented}) == 1, commented
    assert commented[0].strip().startswith("0x0000,")
    assert commented[1].strip().startswith("0, 10, 5;")


def test_comments_inside_groups_and_on_empty_last_fields() -> None:
    text = """[Params]
Param1 = 0, , , 0x0000, 0xDA, 1, "n", "", "", 0, 5, "", , , , , , , , , , { $ group
  1, {"eng", 0xD0, 4, "x"} $ member
  }, , ; $ last empty
"""
    eds = edsconv.parse(text)
    out = write_canonical(eds)
    assert edsconv.parse(out) == canonical(eds)
    assert write_canonical(edsconv.parse(out)) == out


def test_section_order_and_families() -> None:
    eds = edsconv.parse("""[99_V]
A = 1;
[Other]
B = 1;
[Modular]
Rack2 = 1, 2, 3, 1, 1, , , , 1;
Width = 1;
Rack1 = 1, 2, 3, 1, 1, , , , 1;
[Params]
ProxyEnum1 = 0, "a";
ProxyParamSizeAdder1 = 1, 1, 1;
ProxyParam1 = 0, , , 0, 0xC7, 2, "p", "", "", 0, 1, 0;
Enum1 = 0, "x";
Param10 = 0, , , 0, 0xC7, 2, "p", "", "", 0, 1, 0;
Param2 = 0, , , 0, 0xC7, 2, "p", "", "", 0, 1, 0;
Unknown = 1;
Param1 = 0, , , 0, 0xC7, 2, "p", "", "", 0, 1, 0;
[Device]
VendCode = 1;
""")
    ordered = canonical(eds)
    assert [s.name for s in ordered.sections] == ["Device", "Params", "Modular", "Other", "99_V"]
    assert [e.keyword for e in ordered.section("Params").entries] == [
        "Param1", "Enum1", "Param2", "Param10", "ProxyParam1", "ProxyParamSizeAdder1", "ProxyEnum1", "Unknown"]
    assert [e.keyword for e in ordered.section("Modular").entries] == ["Width", "Rack1", "Rack2"]


@pytest.mark.parametrize("name", ["C.4.1.3.10_real_quiet_nan_default.eds", "C.4.1.3.10_real_signal_nan_default.eds"])
def test_a_nan_default_round_trips_on_every_python(name: str):
    """NaN defaults compare equal by ``same`` on 3.13 too, where the dataclass ``__eq__`` says they differ."""
    assert_round_trip(REPO / "corpus" / "allowed" / name)


@given(st.floats(allow_nan=False, allow_infinity=False))
def test_every_double_has_an_lreal_spelling_within_the_limits(value: float) -> None:
    """C.4.1.3.10 allows every double as an LREAL; its 17 significant digits are within the limit
    edsconv reads (tables.LREAL_SIGNIFICANT_DIGITS), so to_real reads real_text's spelling without EDS108."""
    assert to_real(real_text(value, "LREAL"), "LREAL") == value


@pytest.mark.parametrize("value", [1.7976931348623157e308, -2.2250738585072014e-308, 0.1 + 0.2, 1 / 3])
def test_xml2eds_writes_lreal_values_that_lint_accepts(value: float) -> None:
    """What xml2eds writes (device_to_eds of a model) and what lint reads agree on the LREAL digit limits."""
    device = Device()
    device.parameters["Param1"] = Parameter(
        "Param1", "Param", 1, descriptor=0, data_type=tables.DATA_TYPES_BY_NAME["LREAL"], data_type_code=0xCB,
        data_size=8, name="X", units="", help="", minimum=-abs(value), maximum=abs(value), default=value)
    text = write(device_to_eds(device))
    read, diagnostics = edsconv.analyse(edsconv.parse(text))
    assert "EDS108" not in {d.code for d in diagnostics}
    assert read.parameters["Param1"].default == value


def test_an_18th_lreal_digit_is_eds108() -> None:
    text = '[Params]\nParam1 = 0,,,0x0000,0xCB,8,"X","","",0.0,1.79769313486231570e308,0.5;\n'
    assert "EDS108" in {d.code for d in edsconv.analyse(edsconv.parse(text))[1]}
