"""The tables of ISO 15745-4:2003 Annex C.4 (the CIP EDS format) as data.

The checker and the typed semantic model are driven by this module: every
section, entry, field, data type and bit assignment the spec defines is a
frozen record here, and each record carries the clause and table it comes from
so that a diagnostic can cite it.

The source text (a PDF extraction) is damaged in places. Where a table had to
be restored, a ``# restored:`` comment says what and why; docs/spec_tables.md
lists them all.

Vocabulary of :attr:`FieldSpec.eds_type` (alternatives are joined by ``|``):
the names of :data:`DATA_TYPES` (``USINT``, ``EDS_Char_Array``, ``EPATH`` ...)
plus the reference and keyword kinds of :data:`FIELD_VALUE_KINDS`.
"""

from __future__ import annotations

import enum
import functools
import math
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType

from edsconv.limits import decimal

# ---------------------------------------------------------------------------
# Presence
# ---------------------------------------------------------------------------


class Presence(enum.Enum):
    REQUIRED = "required"
    OPTIONAL = "optional"
    CONDITIONAL = "conditional"
    #: The field is reserved and shall be empty (Tables C.20, C.25, C.26).
    RESERVED = "reserved"
    #: Shall not be specified (Table C.17, min/max of bit strings).
    NOT_ALLOWED = "not allowed"

    def __str__(self) -> str:
        return self.value


# the spec tables' own column letters
R, O, C, X = Presence.REQUIRED, Presence.OPTIONAL, Presence.CONDITIONAL, Presence.RESERVED  # noqa: E741 - see above

# ---------------------------------------------------------------------------
# Data types: CIP elementary types (C.4.1.3.3 - C.4.1.3.10) and EDS-only types
# (C.4.1.3.11 - C.4.1.3.14)
# ---------------------------------------------------------------------------

#: Where the identification codes come from. The seed only shows 0xD0 (STRING)
#: and 0xD5 (STRING2), in the STRINGI example of C.4.1.3.5; every other code is
#: the CIP Common specification's (Volume 1, Appendix C, data type reporting),
#: which the seed cites as IEC 61158-6:2003 Type 2.
CIP_VOL1 = "CIP Vol1 App. C"


#: C.4.1.3.10 conflicts with itself for LREAL: it allows "16" digits in the decimal notation and in the
#: scientific mantissa, but also every double up to 1.7976e308, and a double needs 17 significant digits
#: to be written exactly (IEEE 754: DBL_DECIMAL_DIG = 17; the largest, 1.7976931348623157e308, has no
#: 16-digit spelling below the overflow). Real tools write doubles with 17 significant digits (C's
#: "%.17g", Python's repr): edsconv reads 17 as the limit for both notations, so that every LREAL value
#: has a spelling lint accepts and xml2eds writes it (docs/rules.md, EDS108).
LREAL_SIGNIFICANT_DIGITS = 17


@dataclass(frozen=True, slots=True)
class FloatLimits:
    """EDS notation limits of REAL / LREAL (C.4.1.3.10)."""

    integer_min: int
    integer_max: int
    #: Total digits of the decimal (fixed point) notation, sign and point excluded.
    decimal_digits: int
    #: Digits of the mantissa of the scientific notation.
    mantissa_digits: int
    #: Digits of the exponent of the scientific notation.
    exponent_digits: int


@dataclass(frozen=True, slots=True)
class DataType:
    code: int | None
    name: str
    #: Size in bytes of the encoded value; None for variable-size types.
    size: int | None
    #: "bool", "unsigned", "signed", "bits", "real", "time", "date",
    #: "string", "stringi", "epath", "engunit", "eds".
    kind: str
    description: str
    minimum: int | float | None = None
    maximum: int | float | None = None
    #: Maximum number of digits after ``0x`` (C.4.1.3.7 - C.4.1.3.9).
    hex_digits: int | None = None
    #: Maximum number of digits after ``0b`` (bit strings only, C.4.1.3.9).
    binary_digits: int | None = None
    #: Clause that defines the EDS notation / range.
    source: str = ""
    #: Where the code comes from (the seed's clause or :data:`CIP_VOL1`).
    code_source: str = ""
    #: Table C.16 obsolete data type identifier, if any.
    obsolete_id: int | None = None
    #: Bytes per character (strings) or per entry (EPATH): the Data Size of a
    #: ParamN (Table C.14). None for STRINGN, where it is N.
    char_size: int | None = None
    floats: FloatLimits | None = None

    @property
    def numeric(self) -> bool:
        """True for the types of Table C.18 (scaling fields allowed)."""
        return self.name in NUMERIC_PARAM_TYPES

    def from_hex(self, raw: int) -> int | None:
        """Value of a hexadecimal literal's digits ``raw`` for this type.

        Signed types read hex as two's complement over their width (C.4.1.3.8:
        SINT ``0x80`` is -128). Returns None when ``raw`` does not fit.
        """
        if self.size is None or raw < 0 or raw >= 1 << (8 * self.size):
            return None
        if self.kind == "signed" and raw >= 1 << (8 * self.size - 1):
            return raw - (1 << (8 * self.size))
        return raw

    def in_range(self, value: int | float) -> bool:
        if self.minimum is not None and value < self.minimum:
            return False
        return self.maximum is None or value <= self.maximum


def _int(code, name, size, kind, description, obsolete, *, source, code_source=CIP_VOL1):
    bits = 8 * size
    lo, hi = (-(1 << (bits - 1)), (1 << (bits - 1)) - 1) if kind == "signed" else (0, (1 << bits) - 1)
    return DataType(
        code, name, size, kind, description, lo, hi,
        # restored: the seed prints 14 hex digits for the 64-bit maxima
        # (0xFFFFFFFFFFFFFF, 0x7FFFFFFFFFFFFF) but allows "0x plus 16 more";
        # the ranges here are the full 64-bit ones.
        hex_digits=16 if size == 8 else 8,
        # restored: the DWORD / LWORD binary ranges print 30 / 60 digits; a
        # bit string has one binary digit per bit.
        binary_digits=bits if kind == "bits" else None,
        source=source, code_source=code_source, obsolete_id=obsolete,
    )


_U, _S, _W, _F = "C.4.1.3.7", "C.4.1.3.8", "C.4.1.3.9", "C.4.1.3.10"

DATA_TYPES: tuple[DataType, ...] = (
    DataType(0xC1, "BOOL", 1, "bool", "Boolean", 0, 1, source=CIP_VOL1, code_source=CIP_VOL1, obsolete_id=4),
    _int(0xC2, "SINT", 1, "signed", "Short integer", 5, source=_S),
    _int(0xC3, "INT", 2, "signed", "16-bit signed integer", 3, source=_S),
    _int(0xC4, "DINT", 4, "signed", "Double integer", 6, source=_S),
    _int(0xC5, "LINT", 8, "signed", "Long integer", 7, source=_S),
    _int(0xC6, "USINT", 1, "unsigned", "Unsigned short integer", 8, source=_U),
    _int(0xC7, "UINT", 2, "unsigned", "16-bit unsigned integer", 2, source=_U),
    _int(0xC8, "UDINT", 4, "unsigned", "Unsigned double integer", 9, source=_U),
    _int(0xC9, "ULINT", 8, "unsigned", "Unsigned long integer", 10, source=_U),
    DataType(0xCA, "REAL", 4, "real", "Single floating point format (IEEE 754)",
             -3.4028234663852886e38, 3.4028234663852886e38, source=_F, code_source=CIP_VOL1, obsolete_id=11,
             floats=FloatLimits(-16777215, 16777215, 16, 11, 4)),
    DataType(0xCB, "LREAL", 8, "real", "Double floating point format (IEEE 754)",
             -1.7976931348623157e308, 1.7976931348623157e308, source=_F, code_source=CIP_VOL1, obsolete_id=12,
             # 17 digits, not the text's 16: see LREAL_SIGNIFICANT_DIGITS
             floats=FloatLimits(-9007199254740991, 9007199254740991, LREAL_SIGNIFICANT_DIGITS,
                                LREAL_SIGNIFICANT_DIGITS, 4)),
    # Time and date types: the seed names them (Table C.16) but gives no EDS
    # notation; sizes and ranges are those of the CIP integer they are made of.
    DataType(0xCC, "STIME", 4, "time", "Synchronous time information (DINT)",
             -(1 << 31), (1 << 31) - 1, hex_digits=8, source=CIP_VOL1, code_source=CIP_VOL1),
    DataType(0xCD, "DATE", 2, "date", "Date: days since 1972-01-01 (UINT)", 0, 65535,
             hex_digits=8, source=CIP_VOL1, code_source=CIP_VOL1, obsolete_id=17),
    DataType(0xCE, "TIME_OF_DAY", 4, "time", "Time of day: milliseconds since midnight (UDINT)", 0, 86_399_999,
             hex_digits=8, source=CIP_VOL1, code_source=CIP_VOL1, obsolete_id=18),
    DataType(0xCF, "DATE_AND_TIME", 6, "date", "Date and time: TIME_OF_DAY then DATE",
             source=CIP_VOL1, code_source=CIP_VOL1, obsolete_id=19),
    DataType(0xD0, "STRING", None, "string", "8-bit per character string (UINT length)",
             source="C.4.1.3.4", code_source="C.4.1.3.5", obsolete_id=20, char_size=1),
    _int(0xD1, "BYTE", 1, "bits", "Bit string - 8 bits", 24, source=_W),
    _int(0xD2, "WORD", 2, "bits", "Bit string - 16 bits", 1, source=_W),
    _int(0xD3, "DWORD", 4, "bits", "Bit string - 32 bits", 25, source=_W),
    _int(0xD4, "LWORD", 8, "bits", "Bit string - 64 bits", 26, source=_W),
    DataType(0xD5, "STRING2", None, "string", "16-bit per character string (UINT length)",
             source="C.4.1.3.4", code_source="C.4.1.3.5", obsolete_id=21, char_size=2),
    DataType(0xD6, "FTIME", 4, "time", "Duration, high resolution: microseconds (DINT)",
             -(1 << 31), (1 << 31) - 1, hex_digits=8, source=CIP_VOL1, code_source=CIP_VOL1, obsolete_id=15),
    DataType(0xD7, "LTIME", 8, "time", "Duration, long: microseconds (LINT)",
             -(1 << 63), (1 << 63) - 1, hex_digits=16, source=CIP_VOL1, code_source=CIP_VOL1, obsolete_id=16),
    DataType(0xD8, "ITIME", 2, "time", "Duration, short: milliseconds (INT)",
             -(1 << 15), (1 << 15) - 1, hex_digits=8, source=CIP_VOL1, code_source=CIP_VOL1, obsolete_id=13),
    DataType(0xD9, "STRINGN", None, "string", "N-byte per character string (UINT length)",
             source="C.4.1.3.4", code_source=CIP_VOL1, obsolete_id=22, char_size=None),
    DataType(0xDA, "SHORT_STRING", None, "string", "Character string, USINT length, 1 byte per character",
             source="C.4.1.3.4", code_source=CIP_VOL1, obsolete_id=23, char_size=1),
    DataType(0xDB, "TIME", 4, "time", "Duration: milliseconds (DINT)",
             -(1 << 31), (1 << 31) - 1, hex_digits=8, source=CIP_VOL1, code_source=CIP_VOL1, obsolete_id=14),
    DataType(0xDC, "EPATH", None, "epath", "CIP path segments; in an EDS a string of hex byte pairs",
             source="C.4.1.3.6", code_source=CIP_VOL1, char_size=1),
    DataType(0xDD, "ENGUNIT", 2, "engunit", "Engineering units (WORD)", 0, 65535, hex_digits=8,
             source=CIP_VOL1, code_source=CIP_VOL1),
    DataType(0xDE, "STRINGI", None, "stringi", "International character string; in an EDS a braced list",
             source="C.4.1.3.5", code_source=CIP_VOL1),
    # EDS-only types: no CIP code.
    DataType(None, "EDS_Char_Array", None, "eds", "Double-quoted character array, L\"...\" for 16-bit",
             source="C.4.1.3.3", char_size=1),
    DataType(None, "EDS_Date", None, "eds", "mm-dd-yyyy (or mm-dd-yy, 19yy implied)", source="C.4.1.3.11"),
    DataType(None, "EDS_Time_Of_Day", None, "eds", "hh:mm:ss", source="C.4.1.3.12"),
    DataType(None, "EDS_Revision", None, "eds", "Major.Minor, each 0-9, 0.0 invalid", source="C.4.1.3.13"),
    DataType(None, "EDS_URL", None, "eds", "EDS_Char_Array holding an RFC 1738 http, ftp or file URL",
             source="C.4.1.3.14"),
)

DATA_TYPES_BY_NAME: Mapping[str, DataType] = MappingProxyType({t.name: t for t in DATA_TYPES})
DATA_TYPES_BY_CODE: Mapping[int, DataType] = MappingProxyType({t.code: t for t in DATA_TYPES if t.code is not None})
#: Table C.16: obsolete USINT data type identifiers of old EDS files.
OBSOLETE_DATA_TYPE_IDS: Mapping[int, DataType] = MappingProxyType(
    dict(sorted((t.obsolete_id, t) for t in DATA_TYPES if t.obsolete_id is not None))
)

#: Table C.18: the data types for which the scaling / precision fields (13-21)
#: of a ParamN entry are meaningful; specifying them for others is prohibited.
NUMERIC_PARAM_TYPES = frozenset({"SINT", "INT", "DINT", "LINT", "USINT", "UINT", "UDINT", "ULINT", "REAL", "LREAL"})

#: C.4.1.3.10: reserved words for floating point specials.
FLOAT_SPECIAL_WORDS: Mapping[str, float] = MappingProxyType({
    "QUIET-NAN": math.nan,
    "SIGNAL-NAN": math.nan,
    "INFINITY": math.inf,
    "+INFINITY": math.inf,
    "-INFINITY": -math.inf,
})

#: Limits of the EDS-only date/time/revision notations (C.4.1.3.11 - C.4.1.3.13).
EDS_DATE_LIMITS = MappingProxyType({"month": (1, 12), "day": (1, 31), "year": (1996, 9999), "short_year": (96, 99)})
EDS_TIME_OF_DAY_LIMITS = MappingProxyType({"hour": (0, 23), "minute": (0, 59), "second": (0, 59)})
EDS_REVISION_LIMITS = MappingProxyType({"major": (0, 9), "minor": (0, 9)})
#: C.4.1.3.14: the URL schemes an EDS_URL may use.
EDS_URL_SCHEMES = ("http", "ftp", "file")

#: C.4.1.3.5: the string type codes a STRINGI language member may name.
STRINGI_STRING_TYPES = frozenset({0xD0, 0xD5, 0xD9, 0xDA})

#: Table C.4: the named string escape sequences -> the character each stands for.
ESCAPE_SEQUENCES: Mapping[str, str] = MappingProxyType({
    "\\\\": "\\",
    "\\n": "\n",
    "\\t": "\t",
    "\\v": "\v",
    "\\b": "\b",
    "\\r": "\r",
    "\\f": "\f",
    "\\a": "\a",
    '\\"': '"',
    "\\'": "'",
})
#: Table C.4: the numeric escapes -> their count of hex digits: ``\xnn`` a byte,
#: ``\unnnn`` a 16-bit character (only in L"..." strings).
NUMERIC_ESCAPES: Mapping[str, int] = MappingProxyType({"\\x": 2, "\\u": 4})


@dataclass(frozen=True, slots=True)
class MinMaxRule:
    """Table C.17: what fields 10/11 (Minimum / Maximum Value) of a ParamN mean."""

    presence: Presence
    #: "value" (numeric bounds), "length" (string / path length) or None.
    meaning: str | None
    note: str = ""


_LENGTH = MinMaxRule(R, "length", "minimum / maximum string length; Data Size gives bytes per character")
# restored: the seed's Table C.17 merges the BYTE..LWORD rows into one "Not
# allowed" cell, and prints EPATH as "EPAUTH" ("Enumerated Path").
MIN_MAX_RULES: Mapping[str, MinMaxRule] = MappingProxyType({
    **{n: MinMaxRule(Presence.NOT_ALLOWED, None, "bit strings have no min/max")
       for n in ("BYTE", "WORD", "DWORD", "LWORD")},
    **{n: _LENGTH for n in ("STRING", "STRING2", "STRINGN", "SHORT_STRING")},
    "EPATH": MinMaxRule(O, "length", "minimum / maximum path length"),
})
#: Table C.17 "All Other Data Types": optional; if absent the type's own range applies.
DEFAULT_MIN_MAX_RULE = MinMaxRule(O, "value", "absent bounds default to the data type's range")


def min_max_rule(type_name: str) -> MinMaxRule:
    return MIN_MAX_RULES.get(type_name, DEFAULT_MIN_MAX_RULE)


# ---------------------------------------------------------------------------
# Field value kinds beyond data types, and field keywords
# ---------------------------------------------------------------------------

#: An entry's instance number as the C.3 XSD patterns write it (1 .. 99999).
INSTANCE_NUMBER = "[1-9][0-9]{0,4}"
_N = INSTANCE_NUMBER
#: Non-data-type values a field may hold: kind -> regular expression of the
#: value (None when it is not a lexical form), following the C.3 XSD patterns.
FIELD_VALUE_KINDS: Mapping[str, str | None] = MappingProxyType({
    "ParamRef": f"Param{_N}",
    "ProxyParamRef": f"ProxyParam{_N}",
    "AssemRef": f"Assem{_N}",
    "ProxyAssemRef": f"ProxyAssem{_N}",
    #: A field keyword (C.4.1.2.2.13); see FieldSpec.choices.
    "Keyword": "[A-Za-z0-9_]+",
    #: Assembly member keywords of C.4.1.5.3.2 (ExternalID, slot masks).
    "MemberKeyword": "ExternalID(?:[1-9][0-9]*)?|(?:Input|Output|Config)SlotMask[01]",
    #: A value of the data type given by field 5 of the same ParamN.
    "ParamDataType": None,
    #: An integer of the data type of the corresponding ParamN (EnumN values).
    "Integer": None,
    #: Defined by the port type (Table C.25, fields 7...).
    "PortSpecific": None,
    #: Nothing: reserved fields and pads.
    "Empty": None,
})

#: Every keyword an EDS field may name another entry by: ParamN, ProxyParamN, AssemN,
#: ProxyAssemN (C.4.1.4.8, C.4.1.4.9, C.4.1.5.3), AssemExaN (the extended assembly of CIP
#: editions after 2003, which real files name where an AssemN may stand) and a bit of a
#: parameter (``Param10:0``, newer files). Groups: family, number, bit.
REFERENCE_RE = re.compile(r"(ProxyParam|ProxyAssem|Param|AssemExa|Assem)([1-9][0-9]*)(?::([0-9]+))?")
#: C.4.1.4.9.13: a parameter substituted into a path, ``[ParamN]`` or ``ProxyParamN``.
PATH_REFERENCE_RE = re.compile(r"(?:Proxy)?Param[1-9][0-9]*")
#: The lexical spaces of references in CIPDataTypes.xsd (C.3): et_ParamReference,
#: et_AssemReference, and the parameter items of et_EPATH_item.
XSD_PARAM_REFERENCE_RE = re.compile(f"(?:Proxy)?Param{INSTANCE_NUMBER}(?::[0-9]{{1,2}})*")
XSD_ASSEM_REFERENCE_RE = re.compile(f"(?:Proxy)?Assem{INSTANCE_NUMBER}")
XSD_PATH_REFERENCE_RE = re.compile(rf"\[?(?:Proxy)?Param{INSTANCE_NUMBER}\]?")
#: A vendor-specific keyword as the C.2/C.3 XSD patterns write it (main classification, port type).
XSD_VENDOR_KEYWORD = f"{INSTANCE_NUMBER}_[A-Za-z0-9][A-Za-z0-9_]*"

#: C.4.1.2.2.11: vendor-specific keywords (entries, sections, field keywords).
VENDOR_KEYWORD_RE = re.compile(r"[1-9][0-9]*_[A-Za-z0-9_]+")
#: A vendor-specific section keyword: C.4.1.2.2.3 allows single inner spaces in section keywords.
VENDOR_SECTION_KEYWORD_RE = re.compile(r"[1-9][0-9]*_[A-Za-z0-9_]+(?: [A-Za-z0-9_]+)*")
#: C.4.1.2.2.3: characters of keywords; a space only inside section keywords.
KEYWORD_RE = re.compile(r"[A-Za-z0-9_]+")
SECTION_KEYWORD_RE = re.compile(r"[A-Za-z0-9_]+(?: [A-Za-z0-9_]+)*")

#: C.4.1.4.4: first field of a ClassN entry (or a vendor-specific keyword).
CLASSIFICATION_KEYWORDS = ("ControlNet", "DeviceNet", "EtherNetIP")
#: C.4.1.4.10: first field of a PortN entry (or a vendor-specific keyword).
PORT_TYPE_KEYWORDS = ("ControlNet", "ControlNet_Redundant", "TCP", "DeviceNet")
#: C.4.1.4.9.13: keywords allowed inside a connection path.
PATH_KEYWORDS = ("SLOT", "SLOT_MINUS_ONE", "SYMBOL_ANSI")
#: C.4.1.5.3.2: Member Reference keywords; each pair is mutually exclusive in one assembly.
SLOT_MASK_PAIRS = (
    ("InputSlotMask0", "InputSlotMask1"),
    ("OutputSlotMask0", "OutputSlotMask1"),
    ("ConfigSlotMask0", "ConfigSlotMask1"),
)
MEMBER_REFERENCE_KEYWORDS = ("ExternalID",) + tuple(k for pair in SLOT_MASK_PAIRS for k in pair)
#: C.4.1.5.3: field values of Proxy* entries that defer to the Proxied* entry.
MODULE_KEYWORD = "Module"
MODULE_MEMBER_LIST_KEYWORD = "ModuleMemberList"
#: C.4.1.4.8 NOTE: numbered keyword reserved for future Assembly entry types.
RESERVED_ENTRY_KEYWORDS: Mapping[str, tuple[str, ...]] = MappingProxyType({"Assembly": ("Variant",)})

# ---------------------------------------------------------------------------
# Bit tables: C.12, C.15, C.21, C.23, C.24
# ---------------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class BitField:
    name: str
    first_bit: int
    width: int
    #: Field value -> meaning. Values missing here are undefined.
    meanings: Mapping[int, str]
    reserved: bool
    clause: str
    description: str
    #: Group of related bits, e.g. "class", "trigger", "transport" (Table C.23).
    group: str = ""
    #: Values of a multi-bit field that the spec reserves.
    reserved_values: frozenset[int] = frozenset()

    @property
    def mask(self) -> int:
        return ((1 << self.width) - 1) << self.first_bit

    def extract(self, value: int) -> int:
        return (value & self.mask) >> self.first_bit


@dataclass(frozen=True, slots=True)
class BitTable:
    name: str
    table: str
    clause: str
    #: Width in bits of the field holding the value (16 for WORD, 32 for DWORD).
    width: int
    fields: tuple[BitField, ...]
    #: Groups of which at most one bit may be set (Table C.23 transport types).
    exclusive_groups: frozenset[str] = frozenset()

    @property
    def assigned_mask(self) -> int:
        """Bits with a defined, non-reserved meaning."""
        mask = 0
        for f in self.fields:
            if not f.reserved:
                mask |= f.mask
        return mask

    def field(self, name: str) -> BitField:
        for f in self.fields:
            if f.name == name:
                return f
        raise KeyError(name)

    def group(self, group: str) -> tuple[BitField, ...]:
        return tuple(f for f in self.fields if f.group == group)


def _flag(bit, name, clause, off, on, group=""):
    return BitField(name, bit, 1, MappingProxyType({0: off, 1: on}), False, clause, name, group)


def _reserved(first, last, clause, group="reserved"):
    return BitField(f"reserved bits {first}-{last}" if last > first else f"reserved bit {first}",
                    first, last - first + 1, MappingProxyType({}), True, clause,
                    "reserved; shall be 0", group)


def _field(first, width, name, clause, meanings, group="", reserved_values=()):
    return BitField(name, first, width, MappingProxyType(dict(meanings)), False, clause, name, group,
                    frozenset(reserved_values))


def _descriptor(name: str, table: str, clause: str, rows) -> BitTable:
    """A WORD descriptor whose bits 0.. are ``rows`` of (name, meaning of 0,
    meaning of 1) and whose remaining bits are reserved (shall be 0)."""
    flags = tuple(_flag(bit, name, clause, off, on) for bit, (name, off, on) in enumerate(rows))
    return BitTable(name, table, clause, 16, (*flags, _reserved(len(rows), 15, clause)))


# Table C.12; "Bits not defined in Table C.12 shall not be used and shall be set to zero".
PARAMCLASS_DESCRIPTOR_BITS = _descriptor("Parameter class descriptor", "C.12", "C.4.1.4.5", (
    ("Supports individual parameter access",
     "No parameter can be individually accessed; only the configuration assembly is used",
     "Parameters can be individually accessed"),
    ("Supports full attributes",
     "Only the current value of a parameter is available within the device",
     "All configuration data for a parameter is available within the device itself"),
    ("Non-volatile storage save command",
     "Parameters saved automatically",
     "Parameters not saved automatically; a non-volatile storage save command is needed"),
    ("Params are stored in non-volatile storage",
     "Parameters are not stored in non-volatile storage",
     "All full parameters are stored in non-volatile storage"),
))

PARAM_DESCRIPTOR_BITS = _descriptor("Parameter descriptor", "C.15", "C.4.1.4.6", (
    ("Supports settable path", "Link path cannot be set", "Link path can be set"),
    ("Supports enumerated strings", "Enumerated strings are not supported",
     "Enumerated strings are supported and may be read"),
    ("Supports scaling", "Scaling not supported",
     "Scaling is supported; the value is presented to the user in engineering units"),
    ("Supports scaling links", "Scaling links not supported",
     "The values for the scaling attributes may be retrieved from other parameters"),
    ("Read only parameter", "Parameter value can be written (set) and read (get)",
     "The parameter value can only be read (get), and not set"),
    ("Monitor parameter", "Parameter value is not updated in real time by the device",
     "The parameter value is updated in real time by the device"),
    ("Supports extended precision scaling", "Extended precision scaling not supported",
     "Extended precision scaling should be implemented; value presented in engineering units"),
    ("Supports non-consecutive enumerated strings",
     "Non-consecutive enumerated strings not supported", "Non-consecutive enumerated strings are supported"),
    ("Allow both enumeration and individual values",
     "Both enumeration and individual values are not supported",
     "Both enumeration and individual values are supported"),
))

# Table C.21 gives no meanings for bits 1-15 ("Reserved").
ASSEM_DESCRIPTOR_BITS = _descriptor("Assembly descriptor", "C.21", "C.4.1.4.8", (
    ("Allow value edit",
     "Member references defined as values may not be edited (also when the field is empty)",
     "Member references defined as values (UDINT constants, data segment paths) may be edited"),
))

_C23 = "C.4.1.4.9.2"
# restored: Figure C.15 prints the trigger of a "Listen Only" ProxyConnect as
# 0x010100002 (nine hex digits, too many for a DWORD); it is 0x01010002.
_CLASSES = ("null", "duplicate detect", "acknowledged", "verified", "non-blocking",
            "non-blocking, fragmenting", "multicast, fragmenting")
_TRIGGERS = ("cyclic", "change of state", "application")
_TRANSPORTS = ("listen-only", "input-only", "exclusive-owner", "redundant-owner")
TRIGGER_TRANSPORT_BITS = BitTable("Trigger and transport mask", "C.23", _C23, 32, (
    *(_flag(i, f"class {i}", _C23, "not supported", f"class {i}: {d}", "class") for i, d in enumerate(_CLASSES)),
    _reserved(7, 15, _C23, "class"),
    *(_flag(16 + i, f"trigger {d}", _C23, "not supported", f"trigger: {d}", "trigger")
      for i, d in enumerate(_TRIGGERS)),
    _reserved(19, 23, _C23, "trigger"),
    *(_flag(24 + i, d, _C23, "not set", f"transport type: {d}", "transport") for i, d in enumerate(_TRANSPORTS)),
    _reserved(28, 30, _C23),
    _flag(31, "client/server", _C23, "client", "server", "role"),
), exclusive_groups=frozenset({"transport"}))

_C24 = "C.4.1.4.9.3"
_SLOT_BYTES = {0: "1 byte", 1: "2 bytes", 2: "4 bytes", 3: "8 bytes"}
_RT_FORMATS = {0: "pure data, modeless", 1: "zero data length packet indicates idle mode", 2: "reserved",
               3: "heartbeat", 4: "32-bit run/idle header", 5: "reserved", 6: "reserved", 7: "reserved"}


def _direction_bits(d: str, fixed_bit: int, slot_bit: int, fmt_bit: int, type_bit: int, prio_bit: int):
    return (
        _flag(fixed_bit, f"{d} fixed size", _C24, "not supported", f"{d} fixed size supported", "size"),
        _flag(fixed_bit + 1, f"{d} variable size", _C24, "not supported", f"{d} variable size supported", "size"),
        _field(slot_bit, 2, f"{d} bytes per slot", _C24, _SLOT_BYTES, "slot"),
        _field(fmt_bit, 3, f"{d} real time format", _C24, _RT_FORMATS, "format", (2, 5, 6, 7)),
        *(_flag(type_bit + i, f"{d} {t}", _C24, "not supported", f"{d} connection type: {t}", "type")
          for i, t in enumerate(("NULL", "MULTICAST", "POINT2POINT"))),
        _reserved(type_bit + 3, type_bit + 3, _C24, "type"),
        *(_flag(prio_bit + i, f"{d} {p}", _C24, "not supported", f"{d} priority: {p}", "priority")
          for i, p in enumerate(("LOW", "HIGH", "SCHEDULED"))),
        _reserved(prio_bit + 3, prio_bit + 3, _C24, "priority"),
    )


CONNECTION_PARAMETER_BITS = BitTable("Connection parameters", "C.24", _C24, 32, tuple(sorted(
    (*_direction_bits("O=>T", 0, 4, 8, 16, 24),
     *_direction_bits("T=>O", 2, 6, 12, 20, 28),
     _reserved(11, 11, _C24), _reserved(15, 15, _C24)),
    key=lambda f: f.first_bit,
)))

#: Bit tables by table number, as cited by FieldSpec.bits.
BIT_TABLES: Mapping[str, BitTable] = MappingProxyType({
    t.table: t for t in (PARAMCLASS_DESCRIPTOR_BITS, PARAM_DESCRIPTOR_BITS, ASSEM_DESCRIPTOR_BITS,
                         TRIGGER_TRANSPORT_BITS, CONNECTION_PARAMETER_BITS)
})


def decode_bits(value: int, table: BitTable) -> list[tuple[BitField, int, str]]:
    """Every defined field of ``table`` with its value and meaning, plus the
    reserved fields that are (wrongly) non-zero, in bit order."""
    out = []
    for f in table.fields:
        v = f.extract(value)
        if f.reserved and not v:
            continue
        meaning = "reserved" if f.reserved else f.meanings.get(v, "undefined")
        out.append((f, v, meaning))
    return out


def flags_set(value: int, table: BitTable) -> list[str]:
    """Names of the non-reserved fields whose value is non-zero."""
    return [f.name for f, v, _ in decode_bits(value, table) if v and not f.reserved]


def reserved_bits_set(value: int, table: BitTable) -> int:
    """Mask of set bits that have no defined meaning (reserved or beyond the table)."""
    return value & ~table.assigned_mask


def reserved_values_set(value: int, table: BitTable) -> list[tuple[BitField, int]]:
    """Multi-bit fields holding a value the spec reserves (e.g. format 2 of C.24)."""
    return [(f, f.extract(value)) for f in table.fields if f.extract(value) in f.reserved_values]


def exclusive_violations(value: int, table: BitTable) -> list[str]:
    """Exclusive groups with more than one bit set (Table C.23: one transport type)."""
    return [g for g in sorted(table.exclusive_groups)
            if sum(1 for f in table.group(g) if not f.reserved and f.extract(value)) > 1]


# ---------------------------------------------------------------------------
# Scaling (Figure C.5)
# ---------------------------------------------------------------------------


def scale(value: float, multiplier: float = 1, divisor: float = 1, base: float = 1, offset: float = 0,
          precision: int = 0) -> float:
    """Engineering value of a parameter's actual value, Figure C.5::

        EngValue = (ActualValue + Offset) * Mult * Base / (Div * 10**DecimalPrecision)

    ``precision`` is 0 when extended precision scaling (descriptor bit 6) is not supported.
    """
    if divisor == 0:
        raise ValueError("scaling divisor is 0")
    return (value + offset) * multiplier * base / (divisor * 10**precision)


def unscale(eng_value: float, multiplier: float = 1, divisor: float = 1, base: float = 1, offset: float = 0,
            precision: int = 0) -> float:
    """Inverse of :func:`scale`: the actual value for an engineering value."""
    if multiplier == 0 or base == 0:
        raise ValueError("scaling multiplier or base is 0")
    return eng_value * divisor * 10**precision / (multiplier * base) - offset


# ---------------------------------------------------------------------------
# Sections, entries, fields
# ---------------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class Provenance:
    """Where a fact beyond the 2003 text comes from (edsconv.cip_tables).

    The 2003 tables cite their clause instead and leave ``provenance`` None.
    """

    #: eds-pie 1.2.0 ``references/*.json`` file and key that state the fact;
    #: "" when eds-pie does not state it.
    eds_pie: str = ""
    #: Real files (shared/corpus/real) that write it this way; 0 when none does.
    files: int = 0
    #: How the real files write it: notations, values, generators.
    practice: str = ""
    #: Where eds-pie and the real files disagree: both readings, which the table
    #: follows and why.
    disagreement: str = ""

    @property
    def practice_only(self) -> bool:
        """Known only from how real files write it: a check on it is at most a warning."""
        return not self.eds_pie


@dataclass(frozen=True, slots=True)
class FieldSpec:
    #: 1-based field position; for a repeating tail, the first position.
    number: int
    name: str
    #: Alternatives joined by "|": data type names or FIELD_VALUE_KINDS.
    eds_type: str
    presence: Presence
    clause: str
    table: str
    note: str = ""
    #: True for the fields of a repeating tail (assembly members, enum pairs,
    #: group members, legal slots, port-specific fields, sub-classifications).
    repeats: bool = False
    #: Allowed literal values (field keywords, Yes/No, service codes ...).
    choices: tuple[str | int, ...] = ()
    #: A vendor-specific keyword (VENDOR_KEYWORD_RE) is also allowed.
    vendor_keywords: bool = False
    value_range: tuple[int, int] | None = None
    #: Key in BIT_TABLES when the field is a bit mask.
    bits: str = ""
    #: Source of a field beyond the 2003 text (None: the 2003 clause).
    provenance: Provenance | None = None

    @property
    def alternatives(self) -> tuple[str, ...]:
        return tuple(self.eds_type.split("|"))


# eq=False: specs are singletons, compared and hashed by identity (value hashing
# would walk every FieldSpec each time a spec goes into a set).
@dataclass(frozen=True, slots=True, eq=False)
class EntrySpec:
    keyword: str
    #: True for a family "<keyword>N" (Param1, Assem3 ...).
    numbered: bool
    section: str
    fields: tuple[FieldSpec, ...]
    presence: Presence
    clause: str
    table: str
    description: str
    #: Numbers shall start at 1 and increase by one (ClassN, GroupN, ConnectionN, RackN).
    sequential: bool = False
    #: The family whose number this entry's number names (EnumN -> ParamN).
    pairs_with: str | None = None
    #: Field keywords standing for "take it from the Proxied* entry" (C.4.1.5.3).
    proxy_keywords: tuple[str, ...] = ()
    aliases: tuple[str, ...] = ()
    note: str = ""
    #: Source of an entry beyond the 2003 text (None: the 2003 clause).
    provenance: Provenance | None = None
    #: the repeating tail, computed once (field_at runs for every field read)
    repeating: tuple[FieldSpec, ...] = field(init=False, repr=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "repeating", tuple(f for f in self.fields if f.repeats))

    @property
    def max_fields(self) -> int | None:
        """Largest field count, None when the entry has a repeating tail."""
        return None if self.repeating else len(self.fields)

    @property
    def required_count(self) -> int:
        """Position of the last required field (fewer fields is an error)."""
        return max((f.number for f in self.fields if f.presence is R and not f.repeats), default=0)

    def field_at(self, position: int) -> FieldSpec | None:
        """The spec of the field at 1-based ``position``, following a repeating tail."""
        if position < 1:
            return None
        if position <= len(self.fields):
            return self.fields[position - 1]
        tail = self.repeating
        if not tail:
            return None
        return tail[(position - tail[0].number) % len(tail)]


@dataclass(frozen=True, slots=True, eq=False)
class SectionSpec:
    #: The keyword between brackets: "File", "Device Classification" ...
    name: str
    #: Section name column of Table C.3.
    title: str
    #: 1 or 2 for [File] / [Device]; None for "after the required sections".
    placement: int | None
    presence: Presence
    clause: str
    entries: tuple[EntrySpec, ...]
    #: Presence where a network's table (C.27 for EtherNet/IP) differs or
    #: confirms; the keys are the networks with their own section table.
    network_presence: Mapping[str, Presence] = field(default_factory=dict)
    #: Vendor-specific sections come last (Table C.3).
    last: bool = False
    note: str = ""
    #: CIP class ID of the object the section describes (None: not an object class).
    class_id: int | None = None
    #: Source of a section beyond the 2003 text (None: the 2003 clause).
    provenance: Provenance | None = None

    @property
    def networks(self) -> frozenset[str]:
        return frozenset(self.network_presence)

    def presence_for(self, network: str | None = None) -> Presence:
        return self.network_presence.get(network, self.presence) if network else self.presence

    def entry(self, keyword: str) -> EntrySpec | None:
        if SECTIONS.get(self.name) is self:
            return entry_spec(self.name, keyword)
        # sections of edsconv.cip_tables: looked up in their own entries
        return find_entry(self.entries, keyword)


def _fields(clause: str, table: str, *rows) -> tuple[FieldSpec, ...]:
    """FieldSpecs numbered from 1 in order. Each row is (name, eds_type,
    presence) optionally followed by a dict of FieldSpec keywords."""
    out = []
    for number, row in enumerate(rows, 1):
        extra = row[3] if len(row) > 3 else {}
        out.append(FieldSpec(number, row[0], row[1], row[2], extra.pop("clause", clause), table, **extra))
    return tuple(out)


def _single(section, keyword, name, eds_type, presence, clause, table, description, **kw) -> EntrySpec:
    """An entry with one field whose name is the entry name (Tables C.6, C.8, C.10)."""
    field_kw = {k: kw.pop(k) for k in ("choices", "bits", "value_range") if k in kw}
    return EntrySpec(keyword, False, section, _fields(clause, table, (name, eds_type, presence, field_kw)),
                     presence, clause, table, description, **kw)


def _singles(section: str, clause: str, table: str, rows) -> tuple[EntrySpec, ...]:
    """Single-field entries of a section; each row is ((keyword, name,
    eds_type, presence), description[, keywords for _single])."""
    entries = []
    for row in rows:
        keyword, name, eds_type, presence = row[0]
        entries.append(_single(section, keyword, name, eds_type, presence, clause, table, row[1],
                               **(row[2] if len(row) > 2 else {})))
    return tuple(entries)


# --- [File] (Tables C.6, C.7) ----------------------------------------------

_FILE = "C.4.1.4.2"
FILE_ENTRIES = _singles("File", _FILE, "C.6", (
    (("DescText", "File Description Text", "EDS_Char_Array", R),
     "A single line of text displayed by the configuration tool"),
    (("CreateDate", "File Creation Date", "EDS_Date", R), "Creation date of the EDS; not for version control"),
    (("CreateTime", "File Creation Time", "EDS_Time_Of_Day", R), "Creation time of the EDS; not for version control"),
    (("ModDate", "Last Modification Date", "EDS_Date", C),
     "Date of the last modification; required if a tool modified the EDS or ModTime is present"),
    # C.7 gives no condition for ModTime; it mirrors ModDate (the date is
    # required when the time is present, so the time goes with a date).
    (("ModTime", "Last Modification Time", "EDS_Time_Of_Day", C),
     "Time of the last modification; updated with ModDate"),
    (("Revision", "EDS Revision", "EDS_Revision", R), "Revision of the EDS file itself"),
    (("HomeURL", "Home URL", "EDS_URL", O), "URL of the master EDS; its folder holds the icon and related files"),
))

# --- [Device] (Tables C.8, C.9) ---------------------------------------------

_DEV = "C.4.1.4.3"
_IDENT = "represents an Identity Object attribute and is used to match an EDS with a product/revision"
DEVICE_ENTRIES = _singles("Device", _DEV, "C.8", (
    (("VendCode", "Vendor Id", "UINT", R), f"Vendor ID (Identity attribute 1); {_IDENT}"),
    (("VendName", "Vendor Name", "EDS_Char_Array", R), "Textual vendor name"),
    (("ProdType", "Device Type", "UINT", R), f"Device type (Identity attribute 2); {_IDENT}"),
    (("ProdTypeStr", "Device Type String", "EDS_Char_Array", R), "Device type exactly as in the CIP device profile"),
    (("ProdCode", "Product Code", "UINT", R), f"Product code (Identity attribute 3); {_IDENT}"),
    (("MajRev", "Major Revision", "USINT", R), f"Major revision (Identity attribute 4); {_IDENT}"),
    (("MinRev", "Minor Revision", "USINT", R), "Minor revision (Identity attribute 4); not used to match an EDS"),
    (("ProdName", "Product Name", "EDS_Char_Array", R), "Product name (Identity attribute 7)"),
    (("Catalog", "Catalog Number", "EDS_Char_Array", O), "Textual catalog or model number"),
    (("ExcludeFromAdapterRackConnection", "Exclude from Adapter Rack Connection", "EDS_Char_Array", O),
     'String "Yes" excludes a rack module from adapter rack connections; "No" or absent allows it',
     {"choices": ("Yes", "No")}),
    (("Icon", "Icon File Name", "EDS_Char_Array", O),
     "*.ICO file name, relative to the HomeURL folder; only present when HomeURL exists"),
))

# --- [Device Classification] (C.4.1.4.4, C.4.2.2.1) -------------------------

_CLS = "C.4.1.4.4"
CLASSIFICATION_ENTRIES = (
    EntrySpec("Class", True, "Device Classification", _fields(_CLS, "",
        ("Classification", "Keyword", R, {"choices": CLASSIFICATION_KEYWORDS, "vendor_keywords": True}),
        ("Sub-classification", "Keyword", O, {"repeats": True,
            "note": "public classifications shall not be sub-classified (reserved); vendor ones may be"}),
    ), R, _CLS, "", "Classifies the device into a tree of categories", sequential=True),
)

# --- [ParamClass] (Tables C.10 - C.12) --------------------------------------

_PC = "C.4.1.4.5"
PARAMCLASS_ENTRIES = (
    _single("ParamClass", "MaxInst", "Max Instances", "UINT", R, _PC, "C.10",
            "Total number of configuration parameters in the device"),
    _single("ParamClass", "Descriptor", "Parameter Class Descriptor", "WORD", R, _PC, "C.10",
            "Bit flags describing the behaviour of the parameter objects", bits="C.12"),
    _single("ParamClass", "CfgAssembly", "Configuration Assembly Instance", "UINT", R, _PC, "C.10",
            "Instance of the Assembly object holding the configuration data"),
)

# --- [Params] (Tables C.13 - C.18, C.4.1.5.3.1) ----------------------------

_P = "C.4.1.4.6"
_MINMAX = {"note": "meaning and presence by data type: Table C.17 (min_max_rule)"}
_NUM = {"note": "only for numeric data types (Table C.18)"}
# restored: Table C.13 prints EPATH as "EPAUTH" (Link Path, Data Type).
PARAM_FIELDS = _fields(_P, "C.13",
    ("Reserved", "USINT", R, {"choices": (0,), "note": "shall contain 0"}),
    ("Link Path Size", "USINT", O, {"note": "bytes in Link Path; empty if not addressable; ignored if it disagrees"}),
    ("Link Path", "EPATH", O, {"note": 'empty: not addressable; "": data attribute of Parameter instance N'}),
    ("Descriptor", "WORD", R, {"bits": "C.15"}),
    ("Data Type", "USINT|EPATH", R, {"note": "a CIP data type code, or an obsolete Table C.16 identifier"}),
    ("Data Size", "USINT", R, {"note": "bytes; per character for strings (STRINGN: N), 1 for EPATH"}),
    ("Parameter Name", "EDS_Char_Array", R),
    ("Units String", "EDS_Char_Array", R),
    ("Help String", "EDS_Char_Array", R),
    ("Minimum Value", "ParamDataType", C, dict(_MINMAX)),
    ("Maximum Value", "ParamDataType", C, dict(_MINMAX)),
    ("Default Value", "ParamDataType", R),
    ("Scaling Multiplier", "UINT", O, dict(_NUM)),
    ("Scaling Divider", "UINT", O, dict(_NUM)),
    ("Scaling Base", "UINT", O, dict(_NUM)),
    ("Scaling Offset", "INT", O, dict(_NUM)),
    ("Multiplier Link", "UINT", O, dict(_NUM)),
    ("Divisor Link", "UINT", O, dict(_NUM)),
    ("Base Link", "UINT", O, dict(_NUM)),
    ("Offset Link", "UINT", O, dict(_NUM)),
    ("Decimal Precision", "USINT", O, dict(_NUM)),
    ("International Parameter Name", "STRINGI", O),
    # Table C.14 calls this one "International Engineering Name"; C.13's name is kept.
    ("International Engineering Units", "STRINGI", O),
    ("International Help String", "STRINGI", O),
)
#: Table C.18: the ParamN fields reserved for numeric data types, by name and number.
NUMERIC_ONLY_FIELD_NAMES = ("Scaling Multiplier", "Scaling Divider", "Scaling Base", "Scaling Offset",
                            "Multiplier Link", "Divisor Link", "Base Link", "Offset Link", "Decimal Precision")
NUMERIC_ONLY_PARAM_FIELDS = frozenset(f.number for f in PARAM_FIELDS if f.name in NUMERIC_ONLY_FIELD_NAMES)

ENUM_FIELDS = _fields(_P, "",
    ("Enum Value", "Integer", R, {"repeats": True}),
    ("Enum String", "EDS_Char_Array", R, {"repeats": True}),
)
_MOD = "C.4.1.5.3.1"
PARAMS_ENTRIES = (
    EntrySpec("Param", True, "Params", PARAM_FIELDS, O, _P, "C.13",
              "A configuration parameter; N is the Parameter object instance"),
    EntrySpec("Enum", True, "Params", ENUM_FIELDS, O, _P, "",
              "Enumeration of ParamN: pairs of integer value and string", pairs_with="Param"),
    EntrySpec("ProxyParam", True, "Params", PARAM_FIELDS, O, _MOD, "C.13",
              "Parameter of the proxying device; 'Module' fields come from the matching ProxiedParam",
              proxy_keywords=(MODULE_KEYWORD,)),
    # restored: the seed prints "ProxyedParam" once; the keyword is ProxiedParam.
    EntrySpec("ProxiedParam", True, "Params", PARAM_FIELDS, O, _MOD, "C.13",
              "Parameter of the proxied device, matched to ProxyParamN by number"),
    # restored: the seed says "Each ProxyParam entry shall consist of" min,
    # max, default; it means each ProxyParamSizeAdder entry.
    EntrySpec("ProxyParamSizeAdder", True, "Params", _fields(_MOD, "",
        ("Minimum Value", "ParamDataType", R), ("Maximum Value", "ParamDataType", R),
        ("Default Value", "ParamDataType", R)), O, _MOD, "",
              "Values added to ProxyParamN's minimum, maximum and default", pairs_with="ProxyParam"),
    # restored: the seed puts ProxyEnum / ProxiedEnum in a "[Param] section": [Params].
    EntrySpec("ProxyEnum", True, "Params", ENUM_FIELDS, O, _MOD, "",
              "Enumeration of ProxyParamN", pairs_with="ProxyParam"),
    EntrySpec("ProxiedEnum", True, "Params", ENUM_FIELDS, O, _MOD, "",
              "Enumeration of ProxiedParamN", pairs_with="ProxiedParam"),
)
#: The EnumN family of each parameter family: Param -> Enum, ProxyParam -> ProxyEnum ...
ENUM_FAMILIES: Mapping[str, str] = MappingProxyType({
    e.pairs_with: e.keyword for e in PARAMS_ENTRIES if e.pairs_with and e.fields is ENUM_FIELDS})

# --- [Groups] (Table C.19) ---------------------------------------------------

_G = "C.4.1.4.7"
GROUPS_ENTRIES = (
    EntrySpec("Group", True, "Groups", _fields(_G, "C.19",
        ("Group Name String", "EDS_Char_Array", R),
        ("Number of Members", "UINT", R),
        ("Parameter", "UINT", R, {"repeats": True, "note": "ParamN instance numbers, fields 3 .. members + 2"}),
    ), O, _G, "C.19", "A parameter group; N is the Parameter Group object instance", sequential=True),
)

# --- [Assembly] (Tables C.20, C.21, C.4.1.5.3.2) ----------------------------

_A = "C.4.1.4.8"
ASSEM_FIELDS = _fields(_A, "C.20",
    ("Name", "EDS_Char_Array", O),
    ("Path", "EPATH", O, {"note": 'logical path (table type EDS_Char_Array); "": attribute 3 of Assembly instance N'}),
    ("Size", "UINT", C, {"note": "bytes; must agree with the member sizes; 0 when neither is given"}),
    ("Descriptor", "WORD", O, {"bits": "C.21"}),
    ("Reserved", "Empty", X),
    ("Reserved", "Empty", X),
    ("Member Size", "UINT", C, {"repeats": True, "note": "bits; empty: the referenced entry's size"}),
    ("Member Reference", "AssemRef|ProxyAssemRef|ParamRef|ProxyParamRef|UDINT|EPATH|MemberKeyword|Empty", C,
     {"repeats": True, "note": "empty or \"\": a pad of Member Size bits; not both empty"}),
)
_AM = "C.4.1.5.3.2"
ASSEMBLY_ENTRIES = (
    _single("Assembly", "Revision", "Revision", "UINT", O, _A, "",
            "Assembly object class revision (class attribute 1); 2 when absent"),
    EntrySpec("Assem", True, "Assembly", ASSEM_FIELDS, O, _A, "C.20",
              "A data block; N is the Assembly object instance when addressable"),
    EntrySpec("ProxyAssem", True, "Assembly", ASSEM_FIELDS, O, _AM, "C.20",
              "Assembly of the proxying device; 'Module' / 'ModuleMemberList' defer to ProxiedAssemN",
              proxy_keywords=(MODULE_KEYWORD, MODULE_MEMBER_LIST_KEYWORD),
              note="'Module' is not allowed in member fields; 'ModuleMemberList' replaces a member pair"),
    EntrySpec("ProxiedAssem", True, "Assembly", ASSEM_FIELDS, O, _AM, "C.20",
              "Assembly of the proxied device, matched to ProxyAssemN by number"),
)

# --- [Connection Manager] (Tables C.22 - C.24, C.4.1.5.3.3) ----------------

_CM = "C.4.1.4.9.1"
_RPI = "UDINT|ParamRef|ProxyParamRef"
_SIZE = "UINT|ParamRef|ProxyParamRef"
_FMT = "ParamRef|ProxyParamRef|AssemRef|ProxyAssemRef"
CONNECTION_FIELDS = _fields(_CM, "C.22",
    ("Trigger and transport", "DWORD", R, {"bits": "C.23"}),
    ("Connection parameters", "DWORD", R, {"bits": "C.24"}),
    ("O=>T RPI", _RPI, O, {"clause": "C.4.1.4.9.4", "note": "microseconds; empty: unconstrained"}),
    ("O=>T size", _SIZE, C, {"clause": "C.4.1.4.9.5", "note": "bytes; empty: size of the O=>T format"}),
    ("O=>T format", _FMT, C, {"clause": "C.4.1.4.9.6", "note": "shall not be empty if O=>T size is empty"}),
    ("T=>O RPI", _RPI, O, {"clause": "C.4.1.4.9.7", "note": "microseconds; empty: unconstrained"}),
    ("T=>O size", _SIZE, C, {"clause": "C.4.1.4.9.8", "note": "bytes; empty: size of the T=>O format"}),
    ("T=>O format", _FMT, C, {"clause": "C.4.1.4.9.9", "note": "shall not be empty if T=>O size is empty"}),
    ("config #1 size", _SIZE, O, {"clause": "C.4.1.4.9.10"}),
    ("config #1 format", _FMT, O, {"clause": "C.4.1.4.9.10"}),
    ("config #2 size", _SIZE, O, {"clause": "C.4.1.4.9.10"}),
    ("config #2 format", _FMT, O, {"clause": "C.4.1.4.9.10"}),
    ("Connection name string", "EDS_Char_Array", R, {"clause": "C.4.1.4.9.11", "note": "unique among connections"}),
    ("Help string", "EDS_Char_Array", R, {"clause": "C.4.1.4.9.12", "note": '"" when there is no help'}),
    ("Path", "EPATH", R, {"clause": "C.4.1.4.9.13",
        "note": "table type EDS_Char_Array; an EPATH that may hold [ParamN] / ProxyParamN and PATH_KEYWORDS"}),
)
_CMM = "C.4.1.5.3.3"
CONNECTION_ENTRIES = (
    EntrySpec("Connection", True, "Connection Manager", CONNECTION_FIELDS, O, _CM, "C.22",
              "An application connection the device supports", sequential=True),
    EntrySpec("ProxyConnect", True, "Connection Manager", CONNECTION_FIELDS, O, _CMM, "C.22",
              "Connection of the proxying device; 'Module' fields come from ProxiedConnectN",
              proxy_keywords=(MODULE_KEYWORD,), note="the connection name string shall not be 'Module'"),
    EntrySpec("ProxiedConnect", True, "Connection Manager", CONNECTION_FIELDS, O, _CMM, "C.22",
              "Connection of the proxied device, matched to ProxyConnectN by number"),
)

# --- [Port] (Table C.25) ----------------------------------------------------

_PT = "C.4.1.4.10"
PORT_ENTRIES = (
    EntrySpec("Port", True, "Port", _fields(_PT, "C.25",
        ("Port Type Name", "Keyword", R, {"choices": PORT_TYPE_KEYWORDS, "vendor_keywords": True}),
        ("Port Name", "EDS_Char_Array", O),
        ("Port Object", "EPATH", O, {"note": "table type EDS_Char_Array; path of the port's link object"}),
        ("Port Number", "UINT", R, {"note": "1 is the backplane port"}),
        ("Reserved", "Empty", X),
        ("Reserved", "Empty", X),
        ("Port Specific", "PortSpecific", O, {"repeats": True}),
    ), O, _PT, "C.25", "A CIP routable port; N is the Port object instance"),
)

# --- [Modular] (C.4.1.5.2, Table C.26) --------------------------------------

_CH, _MD, _MA = "C.4.1.5.2.2", "C.4.1.5.2.3", "C.4.1.5.2.4"
MODULAR_ENTRIES = (
    _single("Modular", "DefineSlotsInRack", "Number of slots", "UINT", C, _CH, "",
            "Number of slots of a chassis; required in a chassis EDS"),
    _single("Modular", "SlotDisplayRule", "Slot display rule", "ParamRef", O, _CH, "",
            "ParamN translating internal to external slot numbers (chassis)"),
    _single("Modular", "Width", "Width", "UINT", C, _MD, "",
            "Slots consumed by a module; required in a module EDS"),
    EntrySpec("Rack", True, "Modular", _fields(_MD, "C.26",
        ("Vendor ID", "UINT", R), ("Product Type", "UINT", R), ("Product Code", "UINT", R),
        ("Major Revision", "USINT", R), ("Minor Revision", "USINT", R),
        ("Reserved", "Empty", X), ("Reserved", "Empty", X), ("Reserved", "Empty", X),
        ("Legal Slot", "UINT", R, {"repeats": True}),
    ), C, _MD, "C.26", "Electronic key of a chassis the module fits and its legal slots; required in a module EDS",
              sequential=True),
    _single("Modular", "ExternalID", "External ID", "EPATH", O, _MA, "",
            "Byte string identifying a module without a link addressable Identity object"),
    _single("Modular", "GenericID", "Generic ID", "EPATH", O, _MA, "",
            "Byte string sent instead of the ExternalID when no module keying is desired (slot 0 module)"),
    # restored: Figure C.14 spells it ExternalIDExactMatch; the text's keyword is ExternIDExactMatch.
    _single("Modular", "ExternIDExactMatch", "External ID exact match", "Keyword", O, _MA, "",
            "Yes: ExternalID names one device; No: one of a compatible set (default Yes)",
            choices=("Yes", "No"), aliases=("ExternalIDExactMatch",)),
    EntrySpec("Query", False, "Modular", _fields(_MA, "",
        ("Query path", "EPATH", R, {"note": "attribute holding the external IDs of slots 1.."}),
        ("Service", "USINT", R, {"choices": (1, 14), "note": "1 Get_Attributes_All, 14 Get_Attribute_Single"}),
        ("ID size", "USINT", R, {"value_range": (1, 16), "note": "bytes identifying each module"}),
        ("Empty slot ID", "EPATH", R, {"note": "ExternalID returned for an empty slot"}),
    ), O, _MA, "", "How a slot 0 module queries the external IDs of the rack"),
)

_SECTION_ROWS = (
    # name, title, placement, presence, clause, entries, EtherNet/IP presence (Table C.27)
    ("File", "File Description", 1, R, _FILE, FILE_ENTRIES, R),
    ("Device", "Device Description", 2, R, _DEV, DEVICE_ENTRIES, R),
    ("Device Classification", "Device Classification", None, O, _CLS, CLASSIFICATION_ENTRIES, R),
    ("ParamClass", "Parameter Class", None, O, _PC, PARAMCLASS_ENTRIES, O),
    ("Params", "Parameters", None, O, _P, PARAMS_ENTRIES, O),
    ("Groups", "Parameter Groups", None, O, _G, GROUPS_ENTRIES, O),
    ("Assembly", "Assembly", None, O, _A, ASSEMBLY_ENTRIES, O),
    # Table C.27 b: required if the functionality is implemented.
    ("Connection Manager", "Connection Characteristics", None, O, _CM, CONNECTION_ENTRIES, C),
    ("Port", "Port", None, O, _PT, PORT_ENTRIES, O),
    ("Modular", "Modular", None, O, "C.4.1.5.2", MODULAR_ENTRIES, O),
)

#: Table C.3 (with C.5 clauses and C.27 EtherNet/IP presence), in table order.
SECTIONS: Mapping[str, SectionSpec] = MappingProxyType({
    name: SectionSpec(name, title, placement, presence, clause, entries,
                      MappingProxyType({"EtherNetIP": enip}))
    for name, title, placement, presence, clause, entries, enip in _SECTION_ROWS
})

#: Table C.3 last row: [VendorID_vendorspecifickeyword], after all spec sections.
VENDOR_SECTION = SectionSpec(
    "VendorID_vendorspecifickeyword", "Vendor Specific", None, O, "C.4.1.2.2.11", (),
    MappingProxyType({"EtherNetIP": O}), last=True,
    note="any number of sections named <VendorID>_<keyword>, placed after all the sections of this spec",
)

#: Networks with an EDS section table of their own (C.4.2 / Table C.27).
ETHERNETIP = "EtherNetIP"
#: C.4.2.2.1: an EtherNet/IP EDS has a ClassN whose first field is this, with no sub-classification.
ETHERNETIP_CLASSIFICATION = "EtherNetIP"
#: C.4.2.2.2: Port Type Name of an EtherNet/IP port; its Port Object is the
#: TCP/IP Interface object (class 0xF5, a CIP Vol2 code, not in the seed).
ETHERNETIP_PORT_TYPE = "TCP"
TCPIP_INTERFACE_CLASS = 0xF5

# Table C.27 footnote a says the optional sections follow [Device] and
# [Device Classification], but its normative list says [Device
# Classification] "may be placed anywhere after the File Description section".
# The list is kept: [Device Classification] has no fixed placement.

#: CIP object classes most often named in EDS paths, by class code: how ``edsconv show`` names the
#: class of a logical segment. Not in the 2003 text: the codes are those of the CIP object library
#: (CIP Vol 1 ch. 5 and the network volumes); eds-pie 1.2.0's references/ethernetip_lib.json gives the
#: same codes for the classes it lists (``class_id``: Identity 1, ..., TCP/IP Interface 245).
CIP_CLASSES: Mapping[int, str] = MappingProxyType({
    0x01: "Identity", 0x02: "Message Router", 0x03: "DeviceNet", 0x04: "Assembly", 0x05: "Connection",
    0x06: "Connection Manager", 0x07: "Register", 0x08: "Discrete Input Point", 0x09: "Discrete Output Point",
    0x0A: "Analog Input Point", 0x0B: "Analog Output Point", 0x0E: "Presence Sensing", 0x0F: "Parameter",
    0x10: "Parameter Group", 0x12: "Group", 0x1D: "Discrete Input Group", 0x1E: "Discrete Output Group",
    0x1F: "Discrete Group", 0x20: "Analog Input Group", 0x21: "Analog Output Group", 0x22: "Analog Group",
    0x23: "Position Sensor", 0x24: "Position Controller Supervisor", 0x25: "Position Controller",
    0x26: "Block Sequencer", 0x27: "Command Block", 0x28: "Motor Data", 0x29: "Control Supervisor",
    0x2A: "AC/DC Drive", 0x2B: "Acknowledge Handler", 0x2C: "Overload", 0x2D: "Softstart", 0x2E: "Selection",
    0x30: "S-Device Supervisor", 0x31: "S-Analog Sensor", 0x32: "S-Analog Actor", 0x33: "S-Single Stage Controller",
    0x34: "S-Gas Calibration", 0x35: "Trip Point", 0x37: "File", 0x38: "S-Partial Pressure",
    0x39: "Safety Supervisor", 0x3A: "Safety Validator", 0x3B: "Safety Discrete Output Point",
    0x3C: "Safety Discrete Output Group", 0x3D: "Safety Discrete Input Point", 0x3E: "Safety Discrete Input Group",
    0x3F: "Safety Dual Channel Output", 0x40: "S-Sensor Calibration", 0x41: "Event Log", 0x42: "Motion Axis",
    0x43: "Time Sync", 0x44: "Modbus", 0x45: "Originator Connection List", 0x46: "Modbus Serial Link",
    0x47: "Device Level Ring", 0x48: "QoS", 0x4D: "Energy", 0x4E: "Base Energy", 0x4F: "Electrical Energy",
    0x50: "Non-Electrical Energy", 0x51: "Base Switch", 0x52: "SNMP", 0x53: "Power Management",
    0x54: "RSTP Bridge", 0x55: "RSTP Port", 0x56: "PRP/HSR Protocol", 0x57: "PRP/HSR Nodes Table",
    0x58: "Safety Feedback", 0x59: "Safety Dual Channel Feedback", 0x5A: "Safety Stop Functions",
    0x5B: "Safety Limit Functions", 0x5C: "Power Curtailment", 0x5D: "CIP Security", 0x5E: "EtherNet/IP Security",
    0x5F: "Certificate Management", 0x67: "PCCC", 0xF0: "ControlNet", 0xF1: "ControlNet Keeper",
    0xF2: "ControlNet Scheduling", 0xF3: "Connection Configuration", 0xF4: "Port", 0xF5: "TCP/IP Interface",
    0xF6: "Ethernet Link", 0xF7: "CompoNet Link", 0xF8: "CompoNet Repeater",
})

_ENTRY_INDEX: Mapping[tuple[str, str], EntrySpec] = MappingProxyType({
    (s.name, name): e for s in SECTIONS.values() for e in s.entries for name in (e.keyword, *e.aliases)
})
_NUMBERED = re.compile(r"([A-Za-z_]*[A-Za-z_])([1-9][0-9]*)")


def section_spec(name: str) -> SectionSpec | None:
    """Spec of a section by its keyword, with or without brackets; vendor
    sections (``[65535_Foo]``) resolve to :data:`VENDOR_SECTION`."""
    name = name.strip().removeprefix("[").removesuffix("]").strip()
    if name in SECTIONS:
        return SECTIONS[name]
    return VENDOR_SECTION if VENDOR_SECTION_KEYWORD_RE.fullmatch(name) else None


# cached, as entry_spec: every consumer of an entry (model, checks, show) asks again
@functools.lru_cache(maxsize=1 << 16)
def split_numbered(keyword: str) -> tuple[str, int | None]:
    """``"Param12"`` -> ``("Param", 12)``; un-numbered keywords -> ``(keyword, None)``."""
    m = _NUMBERED.fullmatch(keyword)
    return (m.group(1), decimal(m.group(2))) if m else (keyword, None)


def instance_number(keyword: str) -> int:
    """The N of a numbered keyword (``"Param12"`` -> 12); 0 for a keyword without one."""
    return split_numbered(keyword)[1] or 0


@functools.lru_cache(maxsize=1 << 16)
def entry_spec(section: str, keyword: str) -> EntrySpec | None:
    """Spec of an entry keyword in a section, resolving numbered families
    (``"Param12"`` -> Param, ``"ProxyParamSizeAdder4"``, ``"Rack1"`` ...)."""
    sec = section_spec(section)
    if sec is None:
        return None
    exact = _ENTRY_INDEX.get((sec.name, keyword))
    if exact is not None and not exact.numbered:
        return exact
    prefix, number = split_numbered(keyword)
    if number is None:
        return None
    spec = _ENTRY_INDEX.get((sec.name, prefix))
    return spec if spec is not None and spec.numbered else None


def known_entry(section: str, keyword: str) -> EntrySpec:
    """The spec of an entry the code names itself; KeyError when the tables lack it."""
    spec = entry_spec(section, keyword)
    if spec is None:
        raise KeyError(f"[{section}] {keyword}")
    return spec


def find_entry(entries: tuple[EntrySpec, ...], keyword: str) -> EntrySpec | None:
    """The spec among ``entries`` that ``keyword`` names, by name or alias, or by
    numbered family (``"TSpec3"`` -> TSpec), as :func:`entry_spec` resolves."""
    for spec in entries:
        if not spec.numbered and keyword in (spec.keyword, *spec.aliases):
            return spec
    prefix, number = split_numbered(keyword)
    if number is None:
        return None
    return next((spec for spec in entries if spec.numbered and spec.keyword == prefix), None)


def entries_named(keyword: str) -> tuple[EntrySpec, ...]:
    """All entry specs a keyword can name, in any section (keywords are global
    in scope, C.4.1.2.2.8; ``Revision`` is both a [File] and an [Assembly] entry)."""
    return tuple(e for s in SECTIONS.values() if (e := entry_spec(s.name, keyword)) is not None)


def is_vendor_keyword(keyword: str) -> bool:
    return VENDOR_KEYWORD_RE.fullmatch(keyword) is not None


def all_entries() -> tuple[EntrySpec, ...]:
    return tuple(e for s in SECTIONS.values() for e in s.entries)
