"""Value conversion by the C.4.1.3 notation rules, as properties.

Every legal notation of every type converts to the value it spells; illegal
ones raise ValueProblem with the rule they break. Values come from real EDS
text through the reader (a one-entry file), never built by hand.
"""

from __future__ import annotations

import datetime
import math

import pytest
from hypothesis import HealthCheck, assume, example, given, settings
from hypothesis import strategies as st
from tests.conftest import values

from edsconv import spec_tables as tables
from edsconv.model.values import (
    Revision,
    StringIMember,
    ValueNote,
    ValueProblem,
    epath_bytes,
    to_date,
    to_integer,
    to_path,
    to_real,
    to_revision,
    to_stringi,
    to_time,
)

SETTINGS = settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])

INTEGER_TYPES = [t for t in tables.DATA_TYPES if t.kind in ("unsigned", "signed", "bits")]
BIT_TYPES = [t for t in INTEGER_TYPES if t.kind == "bits"]
NON_BIT_TYPES = [t for t in INTEGER_TYPES if t.kind != "bits"]
REAL_TYPES = [tables.DATA_TYPES_BY_NAME["REAL"], tables.DATA_TYPES_BY_NAME["LREAL"]]


def value(text: str):
    """The value of field text ``text``, read by the real lexer from ``[S] K = text;``."""
    (only,) = values(f"[Section]\nKey = {text};\n")
    return only


def problem(convert, text: str, *args) -> ValueProblem:
    with pytest.raises(ValueProblem) as raised:
        convert(value(text), *args)
    return raised.value


def code(convert, text: str, *args) -> str:
    return problem(convert, text, *args).rule.code


def reading(convert, text: str, *args) -> tuple[str, object]:
    """(code, value) of a value that breaks a rule but has one reading (ValueNote)."""
    note = problem(convert, text, *args)
    assert isinstance(note, ValueNote), f"{text}: {note.rule.code} without a reading"
    return note.rule.code, note.value


def test_every_integer_type_is_covered():
    assert {t.name for t in INTEGER_TYPES} == {"USINT", "UINT", "UDINT", "ULINT", "SINT", "INT", "DINT", "LINT",
                                               "BYTE", "WORD", "DWORD", "LWORD"}


# --- integers (C.4.1.3.7 - C.4.1.3.9) ------------------------------------------------


@st.composite
def typed_value(draw, types=INTEGER_TYPES):
    data_type = draw(st.sampled_from(types))
    edge = st.sampled_from([data_type.minimum, data_type.maximum, 0, 1, data_type.maximum - 1])
    number = draw(st.one_of(edge, st.integers(data_type.minimum, data_type.maximum)))
    return data_type, number


@SETTINGS
@given(typed_value(), st.booleans())
def test_decimal(case, plus):
    data_type, number = case
    text = f"+{number}" if plus and number >= 0 else str(number)
    assert to_integer(value(text), data_type.name) == number


@SETTINGS
@given(typed_value(), st.data())
def test_hexadecimal_with_optional_leading_zeros_and_any_case(case, data):
    data_type, number = case
    bits = 8 * data_type.size
    digits = format(number & ((1 << bits) - 1), "x")  # two's complement for the signed types
    width = data.draw(st.integers(len(digits), data_type.hex_digits))
    digits = digits.rjust(width, "0")
    digits = "".join(data.draw(st.sampled_from([c.lower(), c.upper()])) for c in digits)
    prefix = data.draw(st.sampled_from(["0x", "0X"]))
    assert to_integer(value(prefix + digits), data_type.name) == number


@SETTINGS
@given(typed_value(BIT_TYPES), st.data())
def test_binary_for_bit_strings(case, data):
    data_type, number = case
    digits = format(number, "b")
    digits = digits.rjust(data.draw(st.integers(len(digits), data_type.binary_digits)), "0")
    prefix = data.draw(st.sampled_from(["0b", "0B"]))
    assert to_integer(value(prefix + digits), data_type.name) == number


@pytest.mark.parametrize(("type_name", "text", "expected"), [
    ("SINT", "0x80", -128), ("SINT", "0xFF", -1), ("SINT", "0x7F", 127), ("INT", "0x8000", -32768),
    ("DINT", "0xFFFFFFFF", -1), ("LINT", "0x8000000000000000", -(1 << 63)), ("USINT", "0x000000FF", 255),
    ("ULINT", "0xFFFFFFFFFFFFFFFF", (1 << 64) - 1), ("BYTE", "0b00000001", 1), ("INT", "-32768", -32768),
    ("UINT", "0", 0), ("DINT", "-0", 0),
])
def test_integer_examples(type_name, text, expected):
    assert to_integer(value(text), type_name) == expected


@SETTINGS
@given(st.sampled_from(INTEGER_TYPES), st.integers(1, 1 << 70), st.booleans())
def test_out_of_range_decimal_is_eds102(data_type, excess, below):
    number = data_type.minimum - excess if below else data_type.maximum + excess
    assert code(to_integer, str(number), data_type.name) == "EDS102"


@SETTINGS
@given(st.sampled_from([t for t in INTEGER_TYPES if 4 * t.hex_digits > 8 * t.size]), st.data())
def test_hex_wider_than_the_type_is_eds102(data_type, data):
    number = data.draw(st.integers(1 << (8 * data_type.size), (1 << (4 * data_type.hex_digits)) - 1))
    assert code(to_integer, f"0x{number:X}", data_type.name) == "EDS102"


@SETTINGS
@given(typed_value(), st.integers(1, 3))
def test_leading_zeros_are_eds103(case, zeros):
    data_type, number = case
    sign = "-" if number < 0 else ""
    assert code(to_integer, f"{sign}{'0' * zeros}{abs(number)}", data_type.name) == "EDS103"


@SETTINGS
@given(typed_value(), st.integers(1, 4))
def test_too_many_hex_digits_are_eds104(case, extra):
    data_type, number = case
    digits = format(number & ((1 << (8 * data_type.size)) - 1), "X").rjust(data_type.hex_digits + extra, "0")
    assert code(to_integer, "0x" + digits, data_type.name) == "EDS104"


@SETTINGS
@given(st.sampled_from(NON_BIT_TYPES), st.integers(0, 127))
def test_binary_for_other_types_is_eds101(data_type, number):
    assert code(to_integer, f"0b{number:b}", data_type.name) == "EDS101"


@SETTINGS
@given(st.sampled_from(BIT_TYPES), st.integers(1, 8))
def test_binary_beyond_the_bit_string_is_eds102(data_type, extra):
    assert code(to_integer, "0b1" + "0" * (data_type.binary_digits + extra - 1), data_type.name) == "EDS102"


@SETTINGS
@given(typed_value(BIT_TYPES), st.integers(1, 40))
def test_binary_may_have_any_number_of_leading_zeros(case, zeros):
    # C.4.1.3.9 allows leading zeros in binary notation and limits only the hexadecimal length
    data_type, number = case
    assert to_integer(value("0b" + "0" * (data_type.binary_digits + zeros) + format(number, "b")),
                      data_type.name) == number


@pytest.mark.parametrize(("type_name", "text", "clause"), [
    ("USINT", "256", "C.4.1.3.7"), ("INT", "40000", "C.4.1.3.8"), ("WORD", "0b10000000000000000", "C.4.1.3.9"),
    ("UINT", "0254", "C.4.1.3.7"), ("SINT", "-0012", "C.4.1.3.8"), ("DWORD", "0x0000000001", "C.4.1.3.9"),
    ("REAL", "1e39", "C.4.1.3.10"), ("BOOL", "2", "C.4.1.3"),
])
def test_integer_problems_cite_the_clause_of_their_type(type_name, text, clause):
    convert = to_real if type_name == "REAL" else to_integer
    assert problem(convert, text, type_name).clause == clause


@pytest.mark.parametrize(("type_name", "text", "code_", "expected"), [
    ("UINT", "06402", "EDS103", 6402), ("USINT", "02", "EDS103", 2), ("INT", "-007", "EDS103", -7),
    ("UINT", "0x0000000FE", "EDS104", 254), ("SINT", "0x00000000FF", "EDS104", -1),
])
def test_a_value_with_one_reading_keeps_it(type_name, text, code_, expected):
    assert reading(to_integer, text, type_name) == (code_, expected)


@pytest.mark.parametrize(("type_name", "text"), [("BOOL", "255"), ("USINT", "0256"), ("UINT", "0x1FFFF")])
def test_a_value_outside_its_type_has_no_reading(type_name, text):
    assert not isinstance(problem(to_integer, text, type_name), ValueNote)


@pytest.mark.parametrize("data_type", INTEGER_TYPES, ids=lambda t: t.name)
@pytest.mark.parametrize("text", ['"12"', "1.5", "Param1", "12-01-2000", "{ 1 }"])
def test_other_kinds_are_eds101(data_type, text):
    assert code(to_integer, text, data_type.name) == "EDS101"


# --- REAL / LREAL (C.4.1.3.10) -------------------------------------------------------


@SETTINGS
@given(st.sampled_from(REAL_TYPES), st.data())
def test_real_integer_notation(data_type, data):
    limits = data_type.floats
    number = data.draw(st.integers(limits.integer_min, limits.integer_max))
    assert to_real(value(str(number)), data_type.name) == float(number)


@SETTINGS
@given(st.sampled_from(REAL_TYPES), st.integers(1, 16), st.sampled_from(["", "-", "+"]), st.data())
def test_real_decimal_notation_may_omit_the_point(data_type, digits, sign, data):
    # C.4.1.3.10: up to 16 digits, "both the decimal point character and the sign character may be omitted"
    raw = sign + data.draw(st.text("0123456789", min_size=digits, max_size=digits))
    assert to_real(value(raw), data_type.name) == float(raw)


@pytest.mark.parametrize("data_type", REAL_TYPES, ids=lambda t: t.name)
def test_real_digits_beyond_the_limit_are_eds108_with_the_value(data_type):
    raw = "1234567890123456789"[:data_type.floats.decimal_digits + 1]
    assert reading(to_real, raw, data_type.name) == ("EDS108", float(raw))


@st.composite
def fixed_notation(draw, total):
    whole = draw(st.integers(1, total - 1))
    fraction = draw(st.integers(0, total - whole))
    sign = draw(st.sampled_from(["", "-", "+"]))
    digits = st.text("0123456789", min_size=fraction, max_size=fraction)
    first = draw(st.text("123456789", min_size=1, max_size=1))
    rest = draw(st.text("0123456789", min_size=whole - 1, max_size=whole - 1))
    whole_text = "0" if whole == 1 and draw(st.booleans()) else first + rest
    return f"{sign}{whole_text}.{draw(digits)}"


@SETTINGS
@given(st.sampled_from(REAL_TYPES), st.data())
def test_real_fixed_notation(data_type, data):
    raw = data.draw(fixed_notation(data_type.floats.decimal_digits))
    assert to_real(value(raw), data_type.name) == float(raw)


@SETTINGS
@given(st.sampled_from(REAL_TYPES), st.data())
def test_real_scientific_notation(data_type, data):
    limits = data_type.floats
    mantissa_digits = data.draw(st.integers(1, limits.mantissa_digits))
    mantissa = data.draw(st.text("0123456789", min_size=mantissa_digits, max_size=mantissa_digits))
    point = data.draw(st.integers(1, mantissa_digits))
    mantissa = mantissa[:point] + ("." + mantissa[point:] if point < mantissa_digits else "")
    exponent = data.draw(st.integers(-30, 30))
    e = data.draw(st.sampled_from(["e", "E"]))
    raw = f"{data.draw(st.sampled_from(['', '-']))}{mantissa}{e}{exponent:+d}"
    assume(data_type.in_range(float(raw)))  # 9 digits and e+30 exceed REAL (3.4e38): EDS102, tested elsewhere
    assert to_real(value(raw), data_type.name) == float(raw)


@pytest.mark.parametrize("text", [".5", "5.", "-.25", "+1.5e-3", "1e3", "0.0", "3.4e38", "-1.0E+10"])
def test_real_notation_examples(text):
    assert to_real(value(text), "REAL") == float(text)


@pytest.mark.parametrize("data_type", REAL_TYPES, ids=lambda t: t.name)
@pytest.mark.parametrize(("word", "expected"), [("INFINITY", math.inf), ("+INFINITY", math.inf),
                                                ("-INFINITY", -math.inf)])
def test_real_reserved_words(data_type, word, expected):
    assert to_real(value(word), data_type.name) == expected


@pytest.mark.parametrize("data_type", REAL_TYPES, ids=lambda t: t.name)
@pytest.mark.parametrize("word", ["QUIET-NAN", "SIGNAL-NAN"])
def test_real_nan_words(data_type, word):
    assert math.isnan(to_real(value(word), data_type.name))


@SETTINGS
@given(st.sampled_from(REAL_TYPES), st.integers(1, 5), st.data())
def test_real_too_many_fixed_digits_is_eds108(data_type, extra, data):
    total = data_type.floats.decimal_digits + extra
    whole = data.draw(st.integers(1, total - 1))
    raw = "1" * whole + "." + "5" * (total - whole)
    assert code(to_real, raw, data_type.name) == "EDS108"


@SETTINGS
@given(st.sampled_from(REAL_TYPES), st.integers(1, 5))
def test_real_too_many_mantissa_digits_is_eds108(data_type, extra):
    raw = "1." + "2" * (data_type.floats.mantissa_digits + extra - 1) + "e3"
    assert code(to_real, raw, data_type.name) == "EDS108"


@pytest.mark.parametrize("data_type", REAL_TYPES, ids=lambda t: t.name)
def test_real_too_many_exponent_digits_is_eds108(data_type):
    assert code(to_real, "1.5e" + "0" * data_type.floats.exponent_digits + "1", data_type.name) == "EDS108"


@pytest.mark.parametrize("text", ["3.4028235e38", "-3.4028235e38", "3.40282346e38"])
def test_real_largest_single_as_usually_written(text):
    # IEEE 754 rounds these to the largest finite single: they are REAL values
    assert to_real(value(text), "REAL") == float(text)


@pytest.mark.parametrize(("type_name", "text"), [("REAL", "3.4028236e38"), ("REAL", "1e39"), ("REAL", "-1E39"),
                                                 ("LREAL", "1.8e308"), ("LREAL", "-1e309")])
def test_real_beyond_the_range_is_eds102(type_name, text):
    assert code(to_real, text, type_name) == "EDS102"


@pytest.mark.parametrize("text", ['"1.5"', "0x10", "Param1"])
def test_real_other_kinds_are_eds101(text):
    assert code(to_real, text, "REAL") == "EDS101"


# --- dates, times, revisions (C.4.1.3.11 - C.4.1.3.13) --------------------------------


@SETTINGS
@given(st.dates(datetime.date(1996, 1, 1), datetime.date(9999, 12, 31)))
@example(datetime.date(2000, 2, 29))
def test_every_date_in_range(date):
    assert to_date(value(f"{date.month:02d}-{date.day:02d}-{date.year:04d}")) == date


@SETTINGS
@given(st.dates(datetime.date(1996, 1, 1), datetime.date(1999, 12, 31)))
def test_two_digit_years_are_19yy(date):
    assert to_date(value(f"{date.month:02d}-{date.day:02d}-{date.year % 100:02d}")) == date


@SETTINGS
@given(st.integers(13, 99) | st.just(0), st.integers(1, 28), st.integers(1996, 9999))
def test_invalid_month_is_eds105(month, day, year):
    assert code(to_date, f"{month:02d}-{day:02d}-{year}") == "EDS105"


@SETTINGS
@given(st.dates(datetime.date(1996, 1, 1), datetime.date(9999, 12, 31)), st.integers(1, 40))
def test_invalid_day_is_eds105(date, past):
    day = {1: 31, 3: 31, 5: 31, 7: 31, 8: 31, 10: 31, 12: 31, 4: 30, 6: 30, 9: 30, 11: 30}.get(date.month)
    if day is None:
        day = 29 if date.year % 4 == 0 and (date.year % 100 != 0 or date.year % 400 == 0) else 28
    bad = day + past
    assume(bad <= 99)
    assert code(to_date, f"{date.month:02d}-{bad:02d}-{date.year}") == "EDS105"


@pytest.mark.parametrize("text", ["02-29-1997", "00-10-2000", "12-00-2000", "1-1-123", "2024-13-01", "24-01-15"])
def test_date_examples_eds105_without_a_value(text):
    found = problem(to_date, text)
    assert found.rule.code == "EDS105" and not isinstance(found, ValueNote)


@SETTINGS
@given(st.dates(datetime.date(1996, 1, 1), datetime.date(9999, 12, 31)), st.booleans())
def test_one_digit_parts_are_eds105_with_the_value(date, one_digit_month):
    assume(date.month < 10 if one_digit_month else date.day < 10)
    month = f"{date.month}" if one_digit_month else f"{date.month:02d}"
    day = f"{date.day:02d}" if one_digit_month else f"{date.day}"
    assert reading(to_date, f"{month}-{day}-{date.year}") == ("EDS105", date)


@SETTINGS
@given(st.dates(datetime.date(1996, 1, 1), datetime.date(9999, 12, 31)))
def test_the_year_first_is_eds105_with_the_value(date):
    assert reading(to_date, f"{date.year}-{date.month:02d}-{date.day:02d}") == ("EDS105", date)


@SETTINGS
@given(st.dates(datetime.date(1000, 1, 1), datetime.date(1995, 12, 31)))
def test_years_before_1996_are_eds114_with_the_value(date):
    assert reading(to_date, f"{date.month:02d}-{date.day:02d}-{date.year}") == ("EDS114", date)


@SETTINGS
@given(st.dates(datetime.date(1900, 1, 1), datetime.date(1995, 12, 31)))
def test_two_digit_years_before_96_are_eds114_like_four_digit_ones(date):
    # one fault, one severity: 94 is 1994 (an implied leading 19), as Figure C.2's 04-03-94
    assert reading(to_date, f"{date.month:02d}-{date.day:02d}-{date.year % 100:02d}") == ("EDS114", date)


@SETTINGS
@given(st.times())
def test_every_time(time):
    time = time.replace(microsecond=0)
    assert to_time(value(f"{time.hour:02d}:{time.minute:02d}:{time.second:02d}")) == time


@pytest.mark.parametrize(("text", "expected"), [("9:30:00", datetime.time(9, 30)), ("09:5:07", datetime.time(9, 5, 7))])
def test_one_digit_time_parts_are_eds106_with_the_value(text, expected):
    assert reading(to_time, text) == ("EDS106", expected)


@SETTINGS
@given(st.integers(0, 99), st.integers(0, 99), st.integers(0, 99))
def test_times_out_of_range_are_eds106(hour, minute, second):
    assume(hour > 23 or minute > 59 or second > 59)
    assert code(to_time, f"{hour:02d}:{minute:02d}:{second:02d}") == "EDS106"


@pytest.mark.parametrize("text", ["1:02:03", "01:2:03", "12-00-00", '"12:00:00"'])
def test_time_notation_problems(text):
    assert code(to_time, text) in ("EDS106", "EDS101")


@SETTINGS
@given(st.integers(0, 9), st.integers(0, 9))
def test_every_one_digit_revision(major, minor):
    assume((major, minor) != (0, 0))
    assert to_revision(value(f"{major}.{minor}")) == Revision(major, minor)


def test_revision_examples():
    assert to_revision(value("1.4")) == Revision(1, 4)
    assert code(to_revision, "0.0") == "EDS107"
    assert reading(to_revision, "2.11") == ("EDS115", Revision(2, 11))
    assert code(to_revision, "2") == "EDS107"
    assert code(to_revision, '"1.1"') == "EDS101"


@SETTINGS
@given(st.integers(0, 999), st.integers(0, 999))
def test_multi_digit_revisions_are_eds115_with_the_value(major, minor):
    assume(major > 9 or minor > 9)
    assert reading(to_revision, f"{major}.{minor}") == ("EDS115", Revision(major, minor))


# --- EPATH (C.4.1.3.6) ---------------------------------------------------------------


@SETTINGS
@given(st.lists(st.integers(0, 255), max_size=24), st.booleans())
def test_epath_bytes_round_trip(data, lower):
    text = " ".join(f"{b:02x}" if lower else f"{b:02X}" for b in data)
    assert epath_bytes(to_path(value(f'"{text}"'))) == bytes(data)


@pytest.mark.parametrize("text", ["2004", "20 4", "20 0G", "20 04 Param1", "20,04", "[Param1]"])
def test_bad_epath_tokens_are_eds109(text):
    assert code(to_path, f'"{text}"') == "EDS109"


@SETTINGS
@given(st.lists(st.integers(0, 255), min_size=1, max_size=8), st.sampled_from(["2", "204", "GG", "x1", "-1"]))
def test_a_bad_token_anywhere_is_eds109(data, bad):
    tokens = [f"{b:02X}" for b in data]
    tokens.insert(len(tokens) // 2, bad)
    assert code(to_path, f'"{" ".join(tokens)}"') == "EDS109"


def test_path_references_only_where_allowed():
    items = to_path(value('"20 04 24 [Param1] SLOT"'), allow_references=True)
    assert [str(item) for item in items] == ["20", "04", "24", "[Param1]", "SLOT"]
    assert epath_bytes(items) is None


# --- STRINGI (C.4.1.3.5) -------------------------------------------------------------

member = st.builds(
    StringIMember,
    language=st.text("abcdefghijklmnopqrstuvwxyz", min_size=3, max_size=3),
    type_code=st.sampled_from(sorted(tables.STRINGI_STRING_TYPES)),
    charset=st.integers(0, 65535),
    text=st.text("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789 .,:;-_/()", max_size=20),
)


@SETTINGS
@given(st.lists(member, min_size=1, max_size=4), st.booleans())
def test_stringi_round_trip(members, hex_codes):
    rendered = ", ".join(
        f'{{"{m.language}", {f"0x{m.type_code:X}" if hex_codes else m.type_code}, {m.charset}, "{m.text}"}}'
        for m in members)
    assert to_stringi(value(f"{{{len(members)}, {rendered}}}")) == tuple(members)


@pytest.mark.parametrize("text", [
    '{2, {"eng", 0xD0, 4, "a"}}',             # declares 2, lists 1
    '{1, {"en", 0xD0, 4, "a"}}',              # two-letter language code
    '{1, {"eng", 0xC7, 4, "a"}}',             # not a string type
    '{1, {"eng", 0xD0, 4}}',                  # three fields
    '"eng"',                                   # not a group
])
def test_bad_stringi_is_eds111(text):
    assert code(to_stringi, text) == "EDS111"


def _path_items_token_by_token(text: str) -> tuple | None:
    """The items _PATH_TOKEN reads from a path of bytes only (path_items' general loop); None otherwise."""
    from edsconv.model.values import _PATH_TOKEN, PathItem

    items, position = [], 0
    while position < len(text.rstrip()):
        match = _PATH_TOKEN.match(text, position)
        if not match or not match["byte"]:
            return None
        items.append(PathItem(byte=int(match["byte"], 16)))
        position = match.end()
    return tuple(items)


@given(st.lists(st.sampled_from(["20", "2C", "af", "F", "123", "Param1", "[Param2]", "SLOT", "G1", " ", "\t", "\n",
                                 "\x1c", "\x85", "\xa0", "\u2003", "\u200b"]), max_size=10).map("".join))
@example("20 04 24 01 2C 96 2C 64")
@example("2004")
def test_path_of_bytes_reads_as_the_token_loop(text: str) -> None:
    """path_items reads a path of bytes only without a regex per byte: the same items, the same refusals."""
    from edsconv.model.values import path_items

    expected = _path_items_token_by_token(text)
    try:
        found = path_items(text)
    except ValueProblem:
        found = None
    if expected is not None:
        assert found == expected
    else:
        assert found is None or any(item.byte is None for item in found)
