"""Field values to Python values, by the notation rules of C.4.1.3.

Each converter takes the syntax value of one field and the name of the type the
spec gives the field (a :data:`~edsconv.spec_tables.DATA_TYPES` name or an
EDS-only type) and returns the Python value, or raises :class:`ValueProblem`
naming the rule the notation breaks. The limits themselves (ranges, digit
counts) come from :mod:`edsconv.spec_tables`.

A value that breaks a rule is still read when the text allows exactly one
reading of it: :class:`ValueNote` carries that reading with the rule it breaks
(``ProdCode = 06402;`` is 6402 with EDS103, ``06-6-2001`` is June 6 with
EDS105). Where no reading exists (a number outside its type, a day 32, a string
rejected for an escape Table C.4 does not define) :class:`ValueProblem` carries
none. The typed model keeps the reading and marks the field erroneous when the
rule is an error (see :mod:`edsconv.model.device`).
"""

from __future__ import annotations

import datetime
import functools
import re
import struct
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

from edsconv import spec_tables as tables
from edsconv.diagnostics import Rule, Severity, block, rule
from edsconv.eds.lexicon import undefined_escapes
from edsconv.eds.reader_rules import BAD_ESCAPE, UNICODE_ESCAPE_IN_ASCII
from edsconv.eds.syntax import Group, Scalar, String, Value, ValueKind
from edsconv.limits import cut, decimal, shown

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
    clause_note="the clause of the type: C.4.1.3.7 unsigned, C.4.1.3.8 signed, C.4.1.3.9 bit strings, "
                "C.4.1.3.10 REAL/LREAL",
    explanation="""
        A number lies outside the range of its data type (USINT 0 to 255, INT -32768 to
        32767, ...). The diagnostic cites the clause that gives the range of its type.
        A binary number may have any number of leading zeros (C.4.1.3.9 limits only
        the hexadecimal notation's length): only its value counts. The value is not
        read: a USINT cannot hold 256.
    """,
    bad="`MajRev = 256;` (USINT).",
    good="`MajRev = 255;`",
)
LEADING_ZERO = rule(
    "EDS103", Severity.ERROR, "C.4.1.3.7", "A decimal number is written with leading zeros",
    clause_note="the clause of the type: C.4.1.3.7 unsigned, C.4.1.3.8 signed, C.4.1.3.9 bit strings",
    fix="safe",
    explanation="""
        A decimal number is written with leading zeros (`0254`), which C.4.1.3.7 - C.4.1.3.9
        forbid; hexadecimal may have them (`0x00FE`). EDS has no octal notation, so the
        value has one reading: the typed model holds it (`06402` is 6402), marked
        erroneous.
    """,
    bad="`ProdCode = 06402;`.",
    good="`ProdCode = 6402;`",
)
HEX_TOO_LONG = rule(
    "EDS104", Severity.ERROR, "C.4.1.3.7", "A hexadecimal number has more digits than its data type allows",
    clause_note="the clause of the type: C.4.1.3.7 unsigned, C.4.1.3.8 signed, C.4.1.3.9 bit strings",
    explanation="""
        A hexadecimal number has more digits than allowed: `0x` and at most 8 digits
        (16 for 64-bit types). When the value fits the type it has one reading, which
        the typed model holds, marked erroneous.
    """,
    bad="`VendCode = 0x0000000FE;`.",
    good="`VendCode = 0x000000FE;`",
)
BAD_DATE = rule(
    "EDS105", Severity.ERROR, "C.4.1.3.11", "A date is not a valid mm-dd-yyyy EDS_Date",
    explanation="""
        A date is not an EDS_Date `mm-dd-yyyy` (or `mm-dd-yy`), or not a day of the
        calendar: a one-digit month or day (`06-6-2001`), the year first
        (`2024-01-15`), a month 13. Where the date has one reading (the first two
        cases) the typed model holds it, marked erroneous. A year before 1996 is
        EDS114.
    """,
    bad="`CreateDate = 13-11-2008;`.",
    good="`CreateDate = 11-13-2008;`",
)
BAD_TIME = rule(
    "EDS106", Severity.ERROR, "C.4.1.3.12", "A time is not a valid hh:mm:ss EDS_Time_Of_Day",
    explanation="""
        A time is not an EDS_Time_Of_Day `hh:mm:ss` from 00:00:00 to 23:59:59. A time
        with one-digit parts (`9:30:00`) has one reading, which the typed model holds,
        marked erroneous.
    """,
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
        A REAL or LREAL value breaks the digit limits of its notation: 16 digits (REAL)
        or 17 (LREAL) in decimal notation, whose point may be omitted (so `20000000` is
        a REAL although the integer notation stops at 16777215); 11 (REAL) or 17
        (LREAL) mantissa digits and 4 exponent digits in scientific notation. The
        number still has one reading, which the typed model holds, marked erroneous.

        LREAL: the text conflicts with itself. It allows 16 digits in both notations,
        and also every double up to 1.7976e308, but a double needs 17 significant
        digits to be written exactly: the largest, `1.7976931348623157E308`, has no
        16-digit spelling (`1.797693134862316E308` overflows), and neither has
        `0.1 + 0.2`. Real tools write doubles with 17 significant digits (C's `%.17g`,
        IEEE 754's DBL_DECIMAL_DIG); edsconv takes 17 as the LREAL limit, so lint
        accepts every spelling xml2eds writes, and an 18th digit is the error.
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
    "EDS110", Severity.WARNING, "C.4.1.3.14",
    "A URL does not use the http, https, ftp or file scheme, or holds characters RFC 1738 does not allow",
    explanation="""
        A URL has no `http://`, `https://`, `ftp://` or `file://` scheme (https postdates
        the 2003 text and is accepted), or breaks RFC 1738, which C.4.1.3.14 names: it
        holds a character a URL writes only encoded (white space, a control character,
        `<`, `>`, `"`, `{`, `}`, `|`, `\\`, `^`, `[`, `]`, `` ` ``, or a `%` that does not
        begin a `%XX` escape). A warning, not an error: 18 of the 61 real files write
        their HomeURL without one of these schemes (`www.example.com`, `htts://`), the
        files of Texas Instruments, Hilscher and Murrelektronik products among them, and
        tools show it as text.
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
    "EDS114", Severity.WARNING, "C.4.1.3.11", "A date's year is before 1996, the first year of an EDS_Date",
    explanation="""
        A date's year is before 1996, written with four digits (`1994`) or two
        (`94`, read as 1994: the two digits have an implied leading 19). The date is
        used as written. A warning, not an error, although the text says "shall": its
        own Figure C.2 writes `04-03-94`, and a real file written by ODVA's EZ-EDS
        (3.31) dates itself 1994, so tools accept such years.
    """,
    bad="`CreateDate = 01-01-1994;`.",
    good="`CreateDate = 01-01-1996;`",
)
REVISION_BEYOND_2003 = rule(
    "EDS115", Severity.WARNING, "C.4.1.3.13",
    "A revision has more than one digit per part, beyond the 2003 EDS_Revision limit",
    explanation="""
        A revision has more than one digit in a part (`2.11`); the 2003 text allows 0 to
        9 each. Read as major 2, minor 11, as configuration tools do. A warning, not an
        error: 3 of the 61 real files, of products by Murrelektronik (Cube67), ifm (AL1322)
        and Mettler Toledo (IND131), write two-digit parts, and tools read them.
    """,
    bad="`Revision = 2.11;`.",
    good="`Revision = 2.1;`",
)
CONTROL_CHARACTER = rule(
    "EDS116", Severity.ERROR, "C.4.1.3.2", "A string holds a control character (0x00-0x1F other than tab, or 0x7F)",
    explanation="""
        A string holds a control character written as it is: a byte 0x00 to 0x1F other
        than tab, or 0x7F. The valid characters are newline, tab and 32 to 126
        (C.4.1.3.2); characters a terminal cannot display "shall not be used in data
        representations". Write the character as an escape of Table C.4 (`\\t`,
        `\\x07`) if it is meant. The string keeps its one reading in the typed model,
        marked erroneous.
    """,
    bad='`ProdName = "Probe<0x01>Adapter";` (the byte 0x01 in the file).',
    good='`ProdName = "Probe Adapter";`',
)
NULL_TERMINATOR = rule(
    "EDS117", Severity.ERROR, "C.4.1.3.3.1", "A string ends with a null terminator (\\x00)",
    explanation="""
        A string ends with the escape `\\x00`: EDS strings are "of fixed length, without
        null terminators" (C.4.1.3.3.1); the quotes end the string. The typed model keeps
        the text with the character, marked erroneous.
    """,
    bad='`ProdName = "Probe Adapter\\x00";`',
    good='`ProdName = "Probe Adapter";`',
)


class ValueProblem(ValueError):
    """A value that breaks a notation rule and has no reading; ``rule`` says which.

    ``clause`` names the clause of the case where it is more precise than the rule's
    (the range of an INT is C.4.1.3.8); ``reported`` is True when the reader already
    reported the fault (a string rejected for its escape), so the model does not again.
    """

    def __init__(self, rule_: Rule, message: str, *, clause: str = "", reported: bool = False) -> None:
        super().__init__(message)
        self.rule = rule_
        self.message = message
        self.clause = clause
        self.reported = reported


class ValueNote(ValueProblem):
    """A value that breaks a notation rule but has exactly one reading: ``value``.

    With a warning rule, the letter of the 2003 text is broken in a way real tools
    read; with an error rule, the model keeps the reading and marks the field erroneous.
    """

    def __init__(self, rule_: Rule, message: str, value, *, clause: str = "", reported: bool = False) -> None:
        super().__init__(rule_, message, clause=clause, reported=reported)
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


def _notation_clause(data_type: tables.DataType) -> str:
    """The clause of a type's EDS notation and range; C.4.1.3 for the types it does not list (BOOL, times)."""
    return data_type.source if data_type.source.startswith("C.4.1.3") else "C.4.1.3"


def to_integer(value: Value | None, type_name: str) -> int:
    """USINT ... ULINT, SINT ... LINT, BYTE ... LWORD, BOOL and the CIP time types.

    Decimal without leading zeros; ``0x`` hexadecimal with at most the digits the
    type allows (signed types read it as two's complement); ``0b`` binary, with
    any number of leading zeros, for bit strings only (C.4.1.3.7 - C.4.1.3.9).
    """
    if not isinstance(value, Scalar):
        raise ValueProblem(WRONG_KIND, f"expected an integer ({type_name}), found {_describe(value)}")
    return _integer(value.raw, type_name)


@functools.lru_cache(maxsize=4096)
def _integer(raw: str, type_name: str) -> int:
    """:func:`to_integer` of a scalar's spelling; cached (the few spellings of a file recur in every
    entry), a spelling that raises is read again each time (``lru_cache`` keeps no exception)."""
    data_type = tables.DATA_TYPES_BY_NAME[type_name]
    clause = _notation_clause(data_type)
    kind = Scalar(raw).kind
    if kind is ValueKind.HEX:
        digits = raw[2:]
        number = data_type.from_hex(int(digits, 16))
        if number is None:
            raise ValueProblem(OUT_OF_RANGE, f"{raw} does not fit in {type_name}", clause=clause)
        limit = data_type.hex_digits or 8
        if len(digits) > limit:
            raise ValueNote(HEX_TOO_LONG, f"{raw} has {len(digits)} hexadecimal digits; {type_name} allows "
                            f"at most {limit} after 0x", number, clause=clause)
        return number
    if kind is ValueKind.BINARY:
        if data_type.kind != "bits":
            raise ValueProblem(WRONG_KIND, f"binary notation {raw} is allowed only for BYTE, WORD, DWORD and LWORD")
        number = int(raw[2:], 2)
        if not data_type.in_range(number):
            raise ValueProblem(OUT_OF_RANGE, f"{raw} is outside the {type_name} range", clause=clause)
        return number
    if kind is not ValueKind.INTEGER:
        raise ValueProblem(WRONG_KIND, f"expected an integer ({type_name}), found {shown(raw)}")
    sign, digits = _sign_and_digits(raw)
    number = sign * decimal(digits)
    if not data_type.in_range(number):
        raise ValueProblem(OUT_OF_RANGE, f"{cut(raw)} is outside the {type_name} range {data_type.minimum} to "
                           f"{data_type.maximum}", clause=clause)
    if len(digits) > 1 and digits.startswith("0"):
        raise ValueNote(LEADING_ZERO, f"{raw} has leading zeros, which decimal notation does not allow "
                        f"(write {number} or use 0x)", number, clause=clause)
    return number


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
    if kind not in (ValueKind.REAL, ValueKind.INTEGER):
        raise ValueProblem(WRONG_KIND, f"expected a floating point value ({type_name}), found {shown(raw)}")
    number = float(raw)
    if not data_type.in_range(number) and not _rounds_to_single(number, data_type):
        raise ValueProblem(OUT_OF_RANGE, f"{raw} is outside the {type_name} range", clause=_F)
    problem = _real_digits_problem(raw, type_name, limits)
    if problem:
        raise ValueNote(REAL_NOTATION, problem, number)
    return number


_F = "C.4.1.3.10"


def _real_digits_problem(raw: str, type_name: str, limits: tables.FloatLimits) -> str:
    """What breaks the digit limits of C.4.1.3.10, or "". Digits alone are the decimal
    notation with the point omitted (up to 16 digits), not only the integer notation."""
    scientific = _SCIENTIFIC.fullmatch(raw)
    if scientific:
        mantissa_digits = sum(c.isdigit() for c in scientific["mantissa"])
        if mantissa_digits > limits.mantissa_digits or len(scientific["exponent"]) > limits.exponent_digits:
            return f"{raw} exceeds {limits.mantissa_digits} mantissa digits or {limits.exponent_digits} exponent " \
                   f"digits ({type_name})"
        return ""
    if sum(c.isdigit() for c in raw) > limits.decimal_digits:
        return f"{raw} has more than {limits.decimal_digits} digits ({type_name})"
    return ""


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
#: The year first (ISO 8601 order): no EDS_Date, but one reading.
_YEAR_FIRST_DATE = re.compile(r"(?P<year>[0-9]{4})-(?P<month>[0-9]{1,2})-(?P<day>[0-9]{1,2})")
_TIME = re.compile(r"(?P<hour>[0-9]{1,2}):(?P<minute>[0-9]{1,2}):(?P<second>[0-9]{1,2})")
_REVISION = re.compile(r"(?P<major>[0-9]+)\.(?P<minor>[0-9]+)")


def to_date(value: Value) -> datetime.date:
    """EDS_Date: mm-dd-yyyy (1996-9999) or mm-dd-yy (yy with an implied leading 19).

    A date with one reading that breaks the notation (one-digit parts, the year first)
    is an error with its value; a year before 1996 a warning with its value.
    """
    raw = _scalar(value, "a date mm-dd-yyyy")
    match = _DATE.fullmatch(raw) or _YEAR_FIRST_DATE.fullmatch(raw)
    if not match:
        raise ValueProblem(BAD_DATE, f"{shown(raw)} is not written mm-dd-yyyy")
    year_text = match["year"]
    year = int(year_text) + (1900 if len(year_text) == 2 else 0)
    try:
        date = datetime.date(year, int(match["month"]), int(match["day"]))
    except ValueError as error:
        raise ValueProblem(BAD_DATE, f"{raw} is not a calendar date ({error})") from None
    written = f"{date.month:02d}-{date.day:02d}-{year_text}"
    if match.re is _YEAR_FIRST_DATE:
        raise ValueNote(BAD_DATE, f"{shown(raw)} writes the year first; an EDS_Date is mm-dd-yyyy: {written}", date)
    if len(match["month"]) < 2 or len(match["day"]) < 2:
        raise ValueNote(BAD_DATE, f"{shown(raw)}: write month and day with two digits: {written}", date)
    low = tables.EDS_DATE_LIMITS["year"][0]
    if year < low:
        two_digits = f" ({year_text} has an implied leading 19)" if len(year_text) == 2 else ""
        raise ValueNote(DATE_BEYOND_2003, f"year {year}{two_digits} is before {low}", date)
    return date


def to_time(value: Value) -> datetime.time:
    """EDS_Time_Of_Day: hh:mm:ss, 00:00:00 to 23:59:59; one-digit parts are an error with their value."""
    raw = _scalar(value, "a time hh:mm:ss")
    match = _TIME.fullmatch(raw)
    if not match:
        raise ValueProblem(BAD_TIME, f"{shown(raw)} is not written hh:mm:ss")
    parts = {name: int(match[name]) for name in tables.EDS_TIME_OF_DAY_LIMITS}
    if not _within(tables.EDS_TIME_OF_DAY_LIMITS, parts):
        raise ValueProblem(BAD_TIME, f"{raw} is not a time of day (hours 00-23, minutes and seconds 00-59)")
    time = datetime.time(parts["hour"], parts["minute"], parts["second"])
    if any(len(part) < 2 for part in match.groups()):
        raise ValueNote(BAD_TIME, f"{shown(raw)}: write hours, minutes and seconds with two digits: "
                        f"{time.isoformat()}", time)
    return time


def _within(limits: Mapping[str, tuple[int, int]], values: Mapping[str, int]) -> bool:
    return all(low <= values[name] <= high for name, (low, high) in limits.items())


def to_revision(value: Value) -> Revision:
    """EDS_Revision: Major.Minor, each 0 to 9; 0.0 is invalid.

    Real files write ``2.11``: read as major 2, minor 11, with a warning.
    """
    raw = _scalar(value, "a revision Major.Minor")
    match = _REVISION.fullmatch(raw)
    if not match:
        raise ValueProblem(BAD_REVISION, f"{shown(raw)} is not a revision Major.Minor")
    revision = Revision(decimal(match["major"]), decimal(match["minor"]))
    if revision == Revision(0, 0):
        raise ValueProblem(BAD_REVISION, "revision 0.0 is invalid")
    # one digit each: within the limits and without leading zeros
    if not _within(tables.EDS_REVISION_LIMITS, {"major": revision.major, "minor": revision.minor}) \
            or len(match["major"]) > 1 or len(match["minor"]) > 1:
        raise ValueNote(REVISION_BEYOND_2003, f"revision {raw}: the 2003 text allows one digit per part "
                        f"(read as major {revision.major}, minor {revision.minor})", revision)
    return revision


def to_text(value: Value | None) -> str:
    """EDS_Char_Array: the characters of a (possibly concatenated) string.

    A string with an escape Table C.4 does not define is rejected (C.4.1.3.3.5): no value.
    A ``\\u`` escape in an 8-bit string, a control character and a null terminator leave
    one reading: the text, as an error. The reader and :func:`string_flaw` report them.
    """
    if not isinstance(value, String):
        raise ValueProblem(WRONG_KIND, f"expected a quoted string, found {_describe(value)}")
    return _text(value.parts)


@functools.lru_cache(maxsize=4096)
def _text(parts: tuple[str, ...]) -> str:
    """:func:`to_text` of a string's parts; cached like :func:`_integer`."""
    value = String(parts)
    misplaced = None
    for part in value.parts:
        for _, sequence, defined in undefined_escapes(part, value.unicode):
            if not defined:
                raise ValueProblem(BAD_ESCAPE, f"{shown(sequence)} is not in Table C.4: the string is rejected",
                                   reported=True)
            misplaced = misplaced or sequence
    text = value.text
    if misplaced:
        raise ValueNote(UNICODE_ESCAPE_IN_ASCII, f"{shown(misplaced)} in an 8-bit string", text, reported=True)
    flaw = string_flaw(value)
    if flaw is not None:
        raise ValueNote(flaw[0], flaw[1], text, reported=True)
    return text


_CONTROL = re.compile(r"[\x00-\x08\x0a-\x1f\x7f]")


def string_flaw(value: String) -> tuple[Rule, str] | None:
    """The rule a string breaks by its characters: a control character written as it is
    (C.4.1.3.2), or a null terminator (C.4.1.3.3.1); None when it breaks neither."""
    control = next(filter(None, (_CONTROL.search(part) for part in value.parts)), None)
    if control is not None:
        return CONTROL_CHARACTER, f"the string holds the control character 0x{ord(control.group()):02X}; " \
                                  "write it as an escape sequence (Table C.4) or leave it out"
    if "\\x00" in value.parts[-1] and value.text.endswith("\x00"):
        return NULL_TERMINATOR, "the string ends with \\x00; EDS strings have no null terminator"
    return None


# https postdates the 2003 text and is what every vendor site uses now.
_URL = re.compile(rf"(?i)(?:{'|'.join(tables.EDS_URL_SCHEMES)}|https)://")


#: RFC 1738 section 2.2: characters a URL holds only encoded ("%" only as the start of "%XX").
_URL_UNSAFE = re.compile(r'[\x00-\x20\x7f<>"{}|\\^\[\]`]|%(?![0-9A-Fa-f]{2})')


def to_url(value: Value) -> str:
    text = to_text(value)
    if not _URL.match(text.strip()):
        raise ValueNote(BAD_URL, f"{shown(text)} is not an http(s)://, ftp:// or file:// URL", text)
    unsafe = _URL_UNSAFE.search(text.strip())
    if unsafe:
        raise ValueNote(BAD_URL, f"{shown(text)} holds {shown(unsafe.group())}, which RFC 1738 allows in a URL only "
                        "encoded (%XX)", text)
    return text


def to_keyword(value: Value) -> str:
    raw = _scalar(value, "a keyword")
    if value.kind is not ValueKind.WORD:
        raise ValueProblem(WRONG_KIND, f"expected a keyword, found {shown(raw)}")
    return raw


@dataclass(frozen=True, slots=True)
class StringIMember:
    language: str
    type_code: int
    charset: int
    text: str


def _read(notes: list[ValueNote], convert, *args):
    """``convert(*args)``; a value with one reading is kept and its ValueNote collected in ``notes``."""
    try:
        return convert(*args)
    except ValueNote as note:
        notes.append(note)
        return note.value


def to_stringi(value: Value) -> tuple[StringIMember, ...]:
    """STRINGI: ``{n, {"eng", 0xD0, 4, "text"}, ...}`` (C.4.1.3.5). A part with one reading (a text
    with a control character, a number with leading zeros) leaves the STRINGI one reading too."""
    if not isinstance(value, Group) or not value.fields or value.fields[0].value is None:
        raise ValueProblem(BAD_STRINGI, "a STRINGI is a brace group starting with the number of languages")
    notes: list[ValueNote] = []
    count = _read(notes, to_integer, value.fields[0].value, "USINT")
    members = []
    for member_field in value.fields[1:]:
        member = member_field.value
        if not isinstance(member, Group) or len(member.fields) != 4 or any(f.value is None for f in member.fields):
            raise ValueProblem(BAD_STRINGI, "each STRINGI language is {\"lang\", type, charset, \"text\"}")
        language, type_code, charset, text = (f.value or Scalar("") for f in member.fields)  # none is empty
        language_text = _read(notes, to_text, language)
        if len(language_text) != 3:
            raise ValueProblem(BAD_STRINGI, f"language code {shown(language_text)} is not three letters (ISO 639-2/T)")
        code = _read(notes, to_integer, type_code, "USINT")
        if code not in tables.STRINGI_STRING_TYPES:
            raise ValueProblem(BAD_STRINGI, f"0x{code:02X} is not a STRING, STRING2, STRINGN or SHORT_STRING code")
        members.append(StringIMember(language_text, code, _read(notes, to_integer, charset, "UINT"),
                                     _read(notes, to_text, text)))
    if count != len(members):
        raise ValueProblem(BAD_STRINGI, f"the STRINGI declares {count} languages but lists {len(members)}")
    if notes:
        worst = max(notes, key=lambda note: note.rule.severity)
        raise ValueNote(worst.rule, worst.message, tuple(members), clause=worst.clause, reported=worst.reported)
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


#: the item of each two-digit hexadecimal byte, by its spelling (items are immutable: one of each)
_BYTE_ITEMS = {f"{high}{low}": PathItem(byte=int(f"{high}{low}", 16))
               for high in "0123456789ABCDEFabcdef" for low in "0123456789ABCDEFabcdef"}


def path_items(text: str, allow_references: bool = True) -> tuple[PathItem, ...]:
    """The items of a path's text, as an EDS string or an XML profile holds it."""
    tokens = text.split()  # the white space _PATH_TOKEN's \s skips
    if all(map(_BYTE_ITEMS.__contains__, tokens)):  # bytes only, as most paths: no regex per byte
        return tuple(map(_BYTE_ITEMS.__getitem__, tokens))
    items: list[PathItem] = []
    position = 0
    stripped_end = len(text.rstrip())
    while position < stripped_end:
        match = _PATH_TOKEN.match(text, position)
        if not match:
            raise ValueProblem(BAD_EPATH, f"path {shown(text)}: {shown(text[position:].strip()[:12])} is not a "
                               "two-digit hexadecimal byte")
        position = match.end()
        if match["byte"]:
            items.append(PathItem(byte=int(match["byte"], 16)))
            continue
        if not allow_references:
            raise ValueProblem(BAD_EPATH, f"path {shown(text)}: only hexadecimal bytes are allowed here")
        name = match["bracketed"] or match["word"]
        if name in tables.PATH_KEYWORDS and not match["bracketed"]:
            items.append(PathItem(keyword=name))
        elif tables.PATH_REFERENCE_RE.fullmatch(name):
            items.append(PathItem(reference=name, local=bool(match["bracketed"])))
        else:
            raise ValueProblem(BAD_EPATH, f"path {shown(text)}: {shown(name)} is neither a byte, [ParamN], ParamN nor "
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
    return converter_of(type_name)(value)


@functools.cache
def converter_of(type_name: str) -> Callable[[Value], Any]:
    """The function :func:`convert` calls for ``type_name``, chosen once per type."""
    converter = CONVERTERS.get(type_name)
    if converter is not None:
        return converter
    data_type = tables.DATA_TYPES_BY_NAME.get(type_name)
    if data_type is None:
        raise KeyError(f"no converter for type {type_name}")
    if data_type.kind == "real":
        return functools.partial(to_real, type_name=type_name)
    if data_type.kind in ("string",):
        return to_text
    if data_type.kind == "epath":
        return to_path
    if data_type.kind == "stringi":
        return to_stringi
    return functools.partial(to_integer, type_name=type_name)
