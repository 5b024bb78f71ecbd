"""Field values to Python values, by the notation rules of C.4.1.3.

Each converter takes the syntax value of one field and the name of the type the
spec gives the field (a :data:`~edsconv.spec_tables.DATA_TYPES` name or an
EDS-only type) and returns the Python value, or raises :class:`ValueProblem`
naming the rule the notation breaks. The limits themselves (ranges, digit
counts) come from :mod:`edsconv.spec_tables`.
"""

from __future__ import annotations

import datetime
import re
import struct
from collections.abc import Mapping
from dataclasses import dataclass

from edsconv import spec_tables as tables
from edsconv.diagnostics import Rule, Severity, block, rule
from edsconv.eds.syntax import Group, Scalar, String, Value, ValueKind

WRONG_KIND = rule(
    "EDS101", Severity.ERROR, "C.4.1.3", "A field holds a value of the wrong kind for its data type",
    explanation="""
        The field holds a value of the wrong kind: a string where a number is needed, a
        number where a string is needed, a keyword that is no reference.
    """,
    bad=block("""
        [Device]
                VendCode = "65535";
    """),
    good=block("""
        [Device]
                VendCode = 65535;
    """),
)
OUT_OF_RANGE = rule(
    "EDS102", Severity.ERROR, "C.4.1.3.7", "A number lies outside the range of its data type",
    explanation="""
        A number lies outside the range of its data type (USINT 0 to 255, INT -32768 to
        32767, ...).
    """,
    bad="`MajRev = 256;` (USINT).",
    good="`MajRev = 255;`",
)
LEADING_ZERO = rule(
    "EDS103", Severity.ERROR, "C.4.1.3.7", "A decimal number is written with leading zeros",
    explanation="""
        A decimal number is written with leading zeros (`0254`), which C.4.1.3.7 forbids;
        hexadecimal may have them (`0x00FE`).
    """,
    bad="`ProdCode = 06402;`.",
    good="`ProdCode = 6402;`",
)
HEX_TOO_LONG = rule(
    "EDS104", Severity.ERROR, "C.4.1.3.7", "A hexadecimal number has more digits than its data type allows",
    explanation="""
        A hexadecimal number has more digits than allowed: `0x` and at most 8 digits
        (16 for 64-bit types).
    """,
    bad="`VendCode = 0x0000000FE;`.",
    good="`VendCode = 0x000000FE;`",
)
BAD_DATE = rule(
    "EDS105", Severity.ERROR, "C.4.1.3.11", "A date is not a valid mm-dd-yyyy EDS_Date",
    explanation="""
        A date is not an EDS_Date `mm-dd-yyyy` (or `mm-dd-yy` with 96 to 99), or not a
        day of the calendar.
    """,
    bad="`CreateDate = 13-11-2008;`.",
    good="`CreateDate = 11-13-2008;`",
)
BAD_TIME = rule(
    "EDS106", Severity.ERROR, "C.4.1.3.12", "A time is not a valid hh:mm:ss EDS_Time_Of_Day",
    explanation="A time is not an EDS_Time_Of_Day `hh:mm:ss` from 00:00:00 to 23:59:59.",
    bad="`CreateTime = 24:00:00;`.",
    good="`CreateTime = 23:59:59;`",
)
BAD_REVISION = rule(
    "EDS107", Severity.ERROR, "C.4.1.3.13", "A revision is not a valid Major.Minor EDS_Revision",
    explanation="A revision is not `Major.Minor`, or is 0.0, which the spec declares invalid.",
    bad="`Revision = 0.0;`.",
    good="`Revision = 1.0;`",
)
REAL_NOTATION = rule(
    "EDS108", Severity.ERROR, "C.4.1.3.10", "A floating point value breaks the digit limits of the REAL/LREAL notation",
    explanation="""
        A REAL or LREAL value breaks the digit limits of its notation: 16 digits in
        decimal notation; 11 (REAL) or 16 (LREAL) mantissa digits and 4 exponent
        digits in scientific notation.
    """,
    bad="`1.23456789012345678` for a REAL.",
    good="`1.234567`",
)
BAD_EPATH = rule(
    "EDS109", Severity.ERROR, "C.4.1.3.6", "A path is not groups of two hexadecimal digits",
    explanation="""
        A path (EPATH) is not groups of two hexadecimal digits separated by spaces
        (connection and assembly paths may also hold `[ParamN]` and SLOT keywords).
    """,
    bad='`"20 4 24 01"`.',
    good='`"20 04 24 01"`',
)
BAD_URL = rule(
    "EDS110", Severity.WARNING, "C.4.1.3.14", "A URL does not use the http, https, ftp or file scheme",
    explanation="""
        A URL has no `http://`, `https://`, `ftp://` or `file://` scheme (https postdates
        the 2003 text and is accepted).
    """,
    bad='`HomeURL = "www.example.com";`.',
    good='`HomeURL = "https://www.example.com";`',
)
BAD_STRINGI = rule(
    "EDS111", Severity.ERROR, "C.4.1.3.5", "A STRINGI value is not shaped as the spec defines",
    explanation="""
        A STRINGI value is not `{count, {"lng", type, charset, "text"}, ...}` with a
        three-letter language code, a string type code (0xD0, 0xD5, 0xD9, 0xDA) and as
        many languages as the count says.
    """,
    bad='`{2, {"eng",0xD0,4,"Speed"}}`.',
    good='`{1, {"eng",0xD0,4,"Speed"}}`',
)
DATE_BEYOND_2003 = rule(
    "EDS114", Severity.WARNING, "C.4.1.3.11",
    "A date is readable but breaks the 2003 EDS_Date notation (one-digit parts, year before 1996)",
    explanation="""
        A date is readable but breaks the 2003 notation: a one-digit month or day, or a
        year before 1996. The date is used as written.
    """,
    bad="`CreateDate = 06-6-2001;`.",
    good="`CreateDate = 06-06-2001;`",
)
REVISION_BEYOND_2003 = rule(
    "EDS115", Severity.WARNING, "C.4.1.3.13",
    "A revision has more than one digit per part, beyond the 2003 EDS_Revision limit",
    explanation="""
        A revision has more than one digit in a part (`2.11`); the 2003 text allows 0 to
        9 each. Read as major 2, minor 11, as configuration tools do.
    """,
    bad="`Revision = 2.11;`.",
    good="`Revision = 2.1;`",
)


class ValueProblem(ValueError):
    """A value that breaks a notation rule; ``rule`` says which."""

    def __init__(self, rule_: Rule, message: str) -> None:
        super().__init__(message)
        self.rule = rule_
        self.message = message


class ValueNote(ValueProblem):
    """A value that breaks the letter of the 2003 text but that real tools read:
    ``value`` is what it means, ``rule`` a warning."""

    def __init__(self, rule_: Rule, message: str, value) -> None:
        super().__init__(rule_, message)
        self.value = value


@dataclass(frozen=True, slots=True, order=True)
class Revision:
    major: int
    minor: int

    def __str__(self) -> str:
        return f"{self.major}.{self.minor}"


def _describe(value: Value | None) -> str:
    if value is None:
        return "an empty field"
    if isinstance(value, Group):
        return "a brace group"
    if isinstance(value, String):
        return f"the string {value.raw}"
    return repr(value.raw)


def _scalar(value: Value | None, expected: str) -> str:
    if not isinstance(value, Scalar):
        raise ValueProblem(WRONG_KIND, f"expected {expected}, found {_describe(value)}")
    return value.raw


def _sign_and_digits(raw: str) -> tuple[int, str]:
    if raw[:1] in "+-":
        return (-1 if raw[0] == "-" else 1), raw[1:]
    return 1, raw


def to_integer(value: Value | None, type_name: str) -> int:
    """USINT ... ULINT, SINT ... LINT, BYTE ... LWORD, BOOL and the CIP time types.

    Decimal without leading zeros; ``0x`` hexadecimal with at most the digits the
    type allows (signed types read it as two's complement); ``0b`` binary for
    bit strings only (C.4.1.3.7 - C.4.1.3.9).
    """
    data_type = tables.DATA_TYPES_BY_NAME[type_name]
    raw = _scalar(value, f"an integer ({type_name})")
    kind = Scalar(raw).kind
    if kind is ValueKind.HEX:
        digits = raw[2:]
        limit = data_type.hex_digits or 8
        if len(digits) > limit:
            raise ValueProblem(HEX_TOO_LONG, f"{raw} has {len(digits)} hexadecimal digits; {type_name} allows "
                               f"at most {limit} after 0x")
        number = data_type.from_hex(int(digits, 16))
        if number is None:
            raise ValueProblem(OUT_OF_RANGE, f"{raw} does not fit in {type_name}")
        return number
    if kind is ValueKind.BINARY:
        if data_type.kind != "bits":
            raise ValueProblem(WRONG_KIND, f"binary notation {raw} is allowed only for BYTE, WORD, DWORD and LWORD")
        digits = raw[2:]
        if data_type.binary_digits and len(digits) > data_type.binary_digits:
            raise ValueProblem(OUT_OF_RANGE, f"{raw} has more than {data_type.binary_digits} binary digits")
        return int(digits, 2)
    if kind is not ValueKind.INTEGER:
        raise ValueProblem(WRONG_KIND, f"expected an integer ({type_name}), found {raw!r}")
    sign, digits = _sign_and_digits(raw)
    if len(digits) > 1 and digits.startswith("0"):
        raise ValueProblem(LEADING_ZERO, f"{raw} has leading zeros, which decimal notation does not allow "
                           f"(write {sign * int(digits)} or use 0x)")
    number = sign * int(digits)
    if not data_type.in_range(number):
        raise ValueProblem(OUT_OF_RANGE, f"{raw} is outside the {type_name} range {data_type.minimum} to "
                           f"{data_type.maximum}")
    return number


_DECIMAL = re.compile(r"[+-]?(?P<whole>[0-9]*)\.(?P<fraction>[0-9]*)")
_SCIENTIFIC = re.compile(r"[+-]?(?P<mantissa>[0-9]*\.?[0-9]*)[eE][+-]?(?P<exponent>[0-9]+)")


def to_real(value: Value, type_name: str) -> float:
    """REAL / LREAL: integer, decimal or scientific notation, or a reserved word (C.4.1.3.10)."""
    data_type = tables.DATA_TYPES_BY_NAME[type_name]
    limits = data_type.floats
    if limits is None:
        raise KeyError(f"{type_name} is not a floating point type")
    raw = _scalar(value, f"a floating point value ({type_name})")
    kind = value.kind
    if kind is ValueKind.REAL_WORD:
        return tables.FLOAT_SPECIAL_WORDS[raw]
    if kind is ValueKind.INTEGER:
        number = to_integer(Scalar(raw), "LINT")
        if not limits.integer_min <= number <= limits.integer_max:
            raise ValueProblem(REAL_NOTATION, f"{raw} is outside the integer notation range of {type_name} "
                               f"({limits.integer_min} to {limits.integer_max})")
        return float(number)
    if kind is not ValueKind.REAL:
        raise ValueProblem(WRONG_KIND, f"expected a floating point value ({type_name}), found {raw!r}")
    scientific = _SCIENTIFIC.fullmatch(raw)
    if scientific:
        mantissa_digits = sum(c.isdigit() for c in scientific["mantissa"])
        if mantissa_digits > limits.mantissa_digits or len(scientific["exponent"]) > limits.exponent_digits:
            raise ValueProblem(REAL_NOTATION, f"{raw} exceeds {limits.mantissa_digits} mantissa digits or "
                               f"{limits.exponent_digits} exponent digits ({type_name})")
    else:
        decimal = _DECIMAL.fullmatch(raw)
        if decimal and len(decimal["whole"]) + len(decimal["fraction"]) > limits.decimal_digits:
            raise ValueProblem(REAL_NOTATION, f"{raw} has more than {limits.decimal_digits} digits ({type_name})")
    real = float(raw)
    if not data_type.in_range(real) and not _rounds_to_single(real, data_type):
        raise ValueProblem(OUT_OF_RANGE, f"{raw} is outside the {type_name} range")
    return real


def _rounds_to_single(number: float, data_type: tables.DataType) -> bool:
    """True for a REAL written just beyond the largest single (``3.4028235e38``,
    the usual 8-digit spelling): IEEE 754 rounds it to that largest finite value."""
    if data_type.size != 4:
        return False
    try:
        struct.pack("<f", number)
    except OverflowError:
        return False
    return True


_DATE = re.compile(r"(?P<month>[0-9]{1,2})-(?P<day>[0-9]{1,2})-(?P<year>[0-9]{4}|[0-9]{2})")
_TIME = re.compile(r"(?P<hour>[0-9]{2}):(?P<minute>[0-9]{2}):(?P<second>[0-9]{2})")
_REVISION = re.compile(r"(?P<major>[0-9]+)\.(?P<minor>[0-9]+)")


def to_date(value: Value) -> datetime.date:
    """EDS_Date: mm-dd-yyyy (1996-9999) or mm-dd-yy (96-99 meaning 19yy).

    One-digit month or day and years before 1996 are read, with a warning.
    """
    raw = _scalar(value, "a date mm-dd-yyyy")
    match = _DATE.fullmatch(raw)
    if not match:
        raise ValueProblem(BAD_DATE, f"{raw!r} is not written mm-dd-yyyy")
    month, day, year_text = int(match["month"]), int(match["day"]), match["year"]
    year = int(year_text)
    if len(year_text) == 2:
        low, high = tables.EDS_DATE_LIMITS["short_year"]
        if not low <= year <= high:
            raise ValueProblem(BAD_DATE, f"two-digit year {year_text} must be 96 to 99 (19yy); write four digits")
        year += 1900
    try:
        date = datetime.date(year, month, day)
    except ValueError as error:
        raise ValueProblem(BAD_DATE, f"{raw} is not a calendar date ({error})") from None
    low, high = tables.EDS_DATE_LIMITS["year"]
    if not low <= year <= high:
        raise ValueNote(DATE_BEYOND_2003, f"year {year} is outside {low} to {high}", date)
    if len(match["month"]) < 2 or len(match["day"]) < 2:
        raise ValueNote(DATE_BEYOND_2003, f"{raw!r}: write month and day with two digits (mm-dd-yyyy)", date)
    return date


def to_time(value: Value) -> datetime.time:
    """EDS_Time_Of_Day: hh:mm:ss, 00:00:00 to 23:59:59."""
    raw = _scalar(value, "a time hh:mm:ss")
    match = _TIME.fullmatch(raw)
    if not match:
        raise ValueProblem(BAD_TIME, f"{raw!r} is not written hh:mm:ss")
    parts = {name: int(match[name]) for name in tables.EDS_TIME_OF_DAY_LIMITS}
    if not _within(tables.EDS_TIME_OF_DAY_LIMITS, parts):
        raise ValueProblem(BAD_TIME, f"{raw} is not a time of day (hours 00-23, minutes and seconds 00-59)")
    return datetime.time(parts["hour"], parts["minute"], parts["second"])


def _within(limits: Mapping[str, tuple[int, int]], values: Mapping[str, int]) -> bool:
    return all(low <= values[name] <= high for name, (low, high) in limits.items())


def to_revision(value: Value) -> Revision:
    """EDS_Revision: Major.Minor, each 0 to 9; 0.0 is invalid.

    Real files write ``2.11``: read as major 2, minor 11, with a warning.
    """
    raw = _scalar(value, "a revision Major.Minor")
    match = _REVISION.fullmatch(raw)
    if not match:
        raise ValueProblem(BAD_REVISION, f"{raw!r} is not a revision Major.Minor")
    revision = Revision(int(match["major"]), int(match["minor"]))
    if revision == Revision(0, 0):
        raise ValueProblem(BAD_REVISION, "revision 0.0 is invalid")
    # one digit each: within the limits and without leading zeros
    if not _within(tables.EDS_REVISION_LIMITS, {"major": revision.major, "minor": revision.minor}) \
            or len(match["major"]) > 1 or len(match["minor"]) > 1:
        raise ValueNote(REVISION_BEYOND_2003, f"revision {raw}: the 2003 text allows one digit per part "
                        f"(read as major {revision.major}, minor {revision.minor})", revision)
    return revision


def to_text(value: Value | None) -> str:
    """EDS_Char_Array: the characters of a (possibly concatenated) string."""
    if not isinstance(value, String):
        raise ValueProblem(WRONG_KIND, f"expected a quoted string, found {_describe(value)}")
    return value.text


# https postdates the 2003 text and is what every vendor site uses now.
_URL = re.compile(rf"(?i)(?:{'|'.join(tables.EDS_URL_SCHEMES)}|https)://")


def to_url(value: Value) -> str:
    text = to_text(value)
    if not _URL.match(text.strip()):
        raise ValueNote(BAD_URL, f"{text!r} is not an http(s)://, ftp:// or file:// URL", text)
    return text


def to_keyword(value: Value) -> str:
    raw = _scalar(value, "a keyword")
    if value.kind is not ValueKind.WORD:
        raise ValueProblem(WRONG_KIND, f"expected a keyword, found {raw!r}")
    return raw


@dataclass(frozen=True, slots=True)
class StringIMember:
    language: str
    type_code: int
    charset: int
    text: str


def to_stringi(value: Value) -> tuple[StringIMember, ...]:
    """STRINGI: ``{n, {"eng", 0xD0, 4, "text"}, ...}`` (C.4.1.3.5)."""
    if not isinstance(value, Group) or not value.fields or value.fields[0].value is None:
        raise ValueProblem(BAD_STRINGI, "a STRINGI is a brace group starting with the number of languages")
    count = to_integer(value.fields[0].value, "USINT")
    members = []
    for member_field in value.fields[1:]:
        member = member_field.value
        if not isinstance(member, Group) or len(member.fields) != 4 or any(f.value is None for f in member.fields):
            raise ValueProblem(BAD_STRINGI, "each STRINGI language is {\"lang\", type, charset, \"text\"}")
        language, type_code, charset, text = (f.value or Scalar("") for f in member.fields)  # none is empty
        language_text = to_text(language)
        if len(language_text) != 3:
            raise ValueProblem(BAD_STRINGI, f"language code {language_text!r} is not three letters (ISO 639-2/T)")
        code = to_integer(type_code, "USINT")
        if code not in tables.STRINGI_STRING_TYPES:
            raise ValueProblem(BAD_STRINGI, f"0x{code:02X} is not a STRING, STRING2, STRINGN or SHORT_STRING code")
        members.append(StringIMember(language_text, code, to_integer(charset, "UINT"), to_text(text)))
    if count != len(members):
        raise ValueProblem(BAD_STRINGI, f"the STRINGI declares {count} languages but lists {len(members)}")
    return tuple(members)


# --- EPATH -----------------------------------------------------------------------------

_PATH_TOKEN = re.compile(r"\s*(?:(?P<byte>[0-9A-Fa-f]{2})(?![0-9A-Fa-f])|\[(?P<bracketed>[A-Za-z]+[0-9]+)\]"
                         r"|(?P<word>[A-Za-z_][A-Za-z0-9_]*))")


@dataclass(frozen=True, slots=True)
class PathItem:
    """One element of an EDS path: a byte, a parameter substitution or a keyword."""

    byte: int | None = None
    #: ``Param2`` / ``ProxyParam2``: the value of that parameter goes here
    reference: str | None = None
    #: SLOT, SLOT_MINUS_ONE, SYMBOL_ANSI
    keyword: str | None = None
    #: True for ``[Param2]``: the value is local to this path; a bare ``Param2``
    #: has the same value everywhere in the EDS (C.4.1.4.9.13)
    local: bool = False

    def __str__(self) -> str:
        if self.byte is not None:
            return f"{self.byte:02X}"
        if self.reference:
            return f"[{self.reference}]" if self.local else self.reference
        return str(self.keyword)


def to_path(value: Value, allow_references: bool = False) -> tuple[PathItem, ...]:
    """EPATH: hex byte pairs separated by spaces (C.4.1.3.6); connection paths may
    also hold ``[ParamN]`` / ``ProxyParamN`` and SLOT keywords (C.4.1.4.9.13)."""
    return path_items(to_text(value), allow_references)


def path_items(text: str, allow_references: bool = True) -> tuple[PathItem, ...]:
    """The items of a path's text, as an EDS string or an XML profile holds it."""
    items: list[PathItem] = []
    position = 0
    stripped_end = len(text.rstrip())
    while position < stripped_end:
        match = _PATH_TOKEN.match(text, position)
        if not match:
            raise ValueProblem(BAD_EPATH, f"path {text!r}: {text[position:].strip()[:12]!r} is not a "
                               "two-digit hexadecimal byte")
        position = match.end()
        if match["byte"]:
            items.append(PathItem(byte=int(match["byte"], 16)))
            continue
        if not allow_references:
            raise ValueProblem(BAD_EPATH, f"path {text!r}: only hexadecimal bytes are allowed here")
        name = match["bracketed"] or match["word"]
        if name in tables.PATH_KEYWORDS and not match["bracketed"]:
            items.append(PathItem(keyword=name))
        elif tables.PATH_REFERENCE_RE.fullmatch(name):
            items.append(PathItem(reference=name, local=bool(match["bracketed"])))
        else:
            raise ValueProblem(BAD_EPATH, f"path {text!r}: {name!r} is neither a byte, [ParamN], ParamN nor "
                               "SLOT / SLOT_MINUS_ONE / SYMBOL_ANSI")
    return tuple(items)


def epath_bytes(items: tuple[PathItem, ...]) -> bytes | None:
    """The bytes of a path made only of bytes; None when it holds substitutions."""
    data = [item.byte for item in items]
    return None if None in data else bytes(b for b in data if b is not None)


#: Converter of each type name a FieldSpec can give, for the value-only types.
CONVERTERS = {
    "EDS_Char_Array": to_text,
    "EDS_Date": to_date,
    "EDS_Time_Of_Day": to_time,
    "EDS_Revision": to_revision,
    "EDS_URL": to_url,
    "EPATH": to_path,
    "STRINGI": to_stringi,
    "Keyword": to_keyword,
}


def convert(value: Value, type_name: str):
    """Convert a field value to the Python value of ``type_name``."""
    converter = CONVERTERS.get(type_name)
    if converter is not None:
        return converter(value)
    data_type = tables.DATA_TYPES_BY_NAME.get(type_name)
    if data_type is None:
        raise KeyError(f"no converter for type {type_name}")
    if data_type.kind == "real":
        return to_real(value, type_name)
    if data_type.kind in ("string",):
        return to_text(value)
    if data_type.kind == "epath":
        return to_path(value)
    if data_type.kind == "stringi":
        return to_stringi(value)
    return to_integer(value, type_name)
