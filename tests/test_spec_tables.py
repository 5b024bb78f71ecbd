"""Tests of edsconv.spec_tables against ISO 15745-4:2003 C.4 (tables and figures)."""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from edsconv import spec_tables as T
from edsconv.spec_tables import Presence as P


def names(entry):
    return [f.name for f in entry.fields]


# --- sections (Tables C.3, C.5, C.27) ---------------------------------------


def test_sections_follow_table_c3():
    assert list(T.SECTIONS) == [
        "File", "Device", "Device Classification", "ParamClass", "Params", "Groups",
        "Assembly", "Connection Manager", "Port", "Modular",
    ]
    assert [(s.name, s.placement) for s in T.SECTIONS.values() if s.placement] == [("File", 1), ("Device", 2)]
    assert {s.name for s in T.SECTIONS.values() if s.presence is P.REQUIRED} == {"File", "Device"}
    assert T.SECTIONS["Connection Manager"].title == "Connection Characteristics"
    assert T.SECTIONS["Modular"].clause == "C.4.1.5.2"
    assert T.SECTIONS["Port"].clause == "C.4.1.4.10"


def test_ethernetip_presence_follows_table_c27():
    dc = T.SECTIONS["Device Classification"]
    assert dc.presence_for() is P.OPTIONAL
    assert dc.presence_for("EtherNetIP") is P.REQUIRED
    assert T.SECTIONS["Connection Manager"].presence_for("EtherNetIP") is P.CONDITIONAL
    assert T.SECTIONS["Params"].presence_for("EtherNetIP") is P.OPTIONAL
    assert T.SECTIONS["Params"].networks == frozenset({"EtherNetIP"})
    assert T.ETHERNETIP_PORT_TYPE in T.PORT_TYPE_KEYWORDS
    assert T.ETHERNETIP_CLASSIFICATION in T.CLASSIFICATION_KEYWORDS


def test_section_lookup_accepts_brackets_and_vendor_sections():
    assert T.section_spec("[Connection Manager]") is T.SECTIONS["Connection Manager"]
    assert T.section_spec("65535_Widget") is T.VENDOR_SECTION
    assert T.VENDOR_SECTION.last
    assert T.section_spec("0123_Widget") is None  # no leading zeroes in a VendorID
    assert T.section_spec("Capacity") is None


# --- entries -------------------------------------------------------------------


def test_file_and_device_entries_follow_tables_c6_c8():
    file = T.SECTIONS["File"]
    assert [(e.keyword, e.fields[0].eds_type, e.presence) for e in file.entries] == [
        ("DescText", "EDS_Char_Array", P.REQUIRED),
        ("CreateDate", "EDS_Date", P.REQUIRED),
        ("CreateTime", "EDS_Time_Of_Day", P.REQUIRED),
        ("ModDate", "EDS_Date", P.CONDITIONAL),
        ("ModTime", "EDS_Time_Of_Day", P.CONDITIONAL),
        ("Revision", "EDS_Revision", P.REQUIRED),
        ("HomeURL", "EDS_URL", P.OPTIONAL),
    ]
    device = T.SECTIONS["Device"]
    assert [e.keyword for e in device.entries] == [
        "VendCode", "VendName", "ProdType", "ProdTypeStr", "ProdCode", "MajRev", "MinRev", "ProdName",
        "Catalog", "ExcludeFromAdapterRackConnection", "Icon",
    ]
    assert [e.keyword for e in device.entries if e.presence is P.OPTIONAL] == [
        "Catalog", "ExcludeFromAdapterRackConnection", "Icon"]
    assert T.entry_spec("Device", "MajRev").fields[0].eds_type == "USINT"
    assert T.entry_spec("Device", "VendCode").fields[0].eds_type == "UINT"
    assert all(e.table == "C.8" and e.clause == "C.4.1.4.3" for e in device.entries)


def test_param_has_the_24_fields_of_table_c13():
    param = T.entry_spec("Params", "Param1")
    assert len(param.fields) == 24 and param.max_fields == 24
    assert [f.number for f in param.fields] == list(range(1, 25))
    assert names(param)[:12] == [
        "Reserved", "Link Path Size", "Link Path", "Descriptor", "Data Type", "Data Size",
        "Parameter Name", "Units String", "Help String", "Minimum Value", "Maximum Value", "Default Value",
    ]
    assert names(param)[20:] == ["Decimal Precision", "International Parameter Name",
                                 "International Engineering Units", "International Help String"]
    types = [f.eds_type for f in param.fields]
    assert types[:6] == ["USINT", "USINT", "EPATH", "WORD", "USINT|EPATH", "USINT"]
    assert types[12:16] == ["UINT", "UINT", "UINT", "INT"]  # scaling offset is signed
    assert types[21:] == ["STRINGI"] * 3
    presence = [f.presence for f in param.fields]
    assert [i + 1 for i, p in enumerate(presence) if p is P.REQUIRED] == [1, 4, 5, 6, 7, 8, 9, 12]
    assert [i + 1 for i, p in enumerate(presence) if p is P.CONDITIONAL] == [10, 11]
    assert param.required_count == 12
    assert param.fields[0].choices == (0,)
    assert param.fields[3].bits == "C.15"
    assert frozenset(range(13, 22)) == T.NUMERIC_ONLY_PARAM_FIELDS
    assert all(f.table == "C.13" for f in param.fields)


@pytest.mark.parametrize(("section", "keyword", "family"), [
    ("Params", "Param17", "Param"),
    ("Params", "Enum5", "Enum"),
    ("Params", "ProxyParam4", "ProxyParam"),
    ("Params", "ProxiedParam4", "ProxiedParam"),
    ("Params", "ProxyParamSizeAdder4", "ProxyParamSizeAdder"),
    ("Params", "ProxyEnum2", "ProxyEnum"),
    ("[Assembly]", "Assem3", "Assem"),
    ("Assembly", "ProxyAssem12", "ProxyAssem"),
    ("Connection Manager", "Connection1", "Connection"),
    ("Connection Manager", "ProxiedConnect7", "ProxiedConnect"),
    ("Groups", "Group2", "Group"),
    ("Port", "Port1", "Port"),
    ("Modular", "Rack1", "Rack"),
    ("Device Classification", "Class3", "Class"),
    ("File", "DescText", "DescText"),
    ("Modular", "ExternalIDExactMatch", "ExternIDExactMatch"),  # Figure C.14 spelling
])
def test_entry_spec_resolves_keywords(section, keyword, family):
    spec = T.entry_spec(section, keyword)
    assert spec is not None and spec.keyword == family


@pytest.mark.parametrize(("section", "keyword"), [
    ("Params", "Param"),       # a family needs its number
    ("Params", "Param0"),      # numbers are decimal from 1
    ("Params", "Param012"),    # no leading zeroes
    ("File", "Param1"),        # wrong section
    ("File", "DescText1"),     # not a numbered entry
    ("Assembly", "Variant1"),  # reserved for the future (C.4.1.4.8 NOTE)
    ("Params", "65535_Foo"),
    ("Nowhere", "Param1"),
])
def test_entry_spec_rejects(section, keyword):
    assert T.entry_spec(section, keyword) is None


def test_revision_is_an_entry_of_two_sections():
    found = {e.section: e.fields[0].eds_type for e in T.entries_named("Revision")}
    assert found == {"File": "EDS_Revision", "Assembly": "UINT"}


def test_assembly_fields_follow_table_c20_with_a_member_pair_tail():
    assem = T.entry_spec("Assembly", "Assem5")
    assert names(assem) == ["Name", "Path", "Size", "Descriptor", "Reserved", "Reserved",
                            "Member Size", "Member Reference"]
    assert [f.presence for f in assem.fields[4:6]] == [P.RESERVED, P.RESERVED]
    assert assem.max_fields is None
    assert [assem.field_at(n).name for n in (7, 8, 9, 10, 13, 14)] == ["Member Size", "Member Reference"] * 3
    assert "ParamRef" in assem.field_at(8).alternatives
    assert "MemberKeyword" in assem.field_at(12).alternatives
    assert assem.field_at(0) is None
    assert T.entry_spec("Assembly", "ProxyAssem1").proxy_keywords == ("Module", "ModuleMemberList")


def test_repeating_tails_of_groups_rack_enum_port():
    group = T.entry_spec("Groups", "Group1")
    assert names(group) == ["Group Name String", "Number of Members", "Parameter"]
    assert group.field_at(40).name == "Parameter"
    rack = T.entry_spec("Modular", "Rack1")
    assert rack.field_at(12).name == "Legal Slot" and rack.field_at(6).presence is P.RESERVED
    assert [f.eds_type for f in rack.fields[:5]] == ["UINT", "UINT", "UINT", "USINT", "USINT"]
    enum = T.entry_spec("Params", "Enum1")
    assert [enum.field_at(n).name for n in (1, 2, 9, 10)] == ["Enum Value", "Enum String"] * 2
    assert enum.pairs_with == "Param"
    port = T.entry_spec("Port", "Port2")
    assert port.field_at(1).choices == ("ControlNet", "ControlNet_Redundant", "TCP", "DeviceNet")
    assert port.field_at(1).vendor_keywords and port.field_at(9).name == "Port Specific"
    assert port.required_count == 4
    assert T.entry_spec("Params", "Param1").field_at(25) is None


def test_connection_fields_follow_table_c22():
    conn = T.entry_spec("Connection Manager", "Connection1")
    assert len(conn.fields) == 15 and conn.sequential
    assert [f.bits for f in conn.fields[:2]] == ["C.23", "C.24"]
    assert conn.fields[2].alternatives == ("UDINT", "ParamRef", "ProxyParamRef")
    assert conn.fields[4].alternatives == ("ParamRef", "ProxyParamRef", "AssemRef", "ProxyAssemRef")
    assert [f.number for f in conn.fields if f.presence is P.CONDITIONAL] == [4, 5, 7, 8]
    assert [f.number for f in conn.fields if f.presence is P.REQUIRED] == [1, 2, 13, 14, 15]
    assert conn.fields[14].clause == "C.4.1.4.9.13"
    assert T.entry_spec("Connection Manager", "ProxyConnect1").proxy_keywords == ("Module",)


def test_modular_keywords():
    modular = [e.keyword for e in T.SECTIONS["Modular"].entries]
    assert modular == ["DefineSlotsInRack", "SlotDisplayRule", "Width", "Rack", "ExternalID", "GenericID",
                       "ExternIDExactMatch", "Query"]
    query = T.entry_spec("Modular", "Query")
    assert len(query.fields) == 4 and query.fields[1].choices == (1, 14) and query.fields[2].value_range == (1, 16)
    assert T.entry_spec("Modular", "SlotDisplayRule").fields[0].eds_type == "ParamRef"
    assert T.entry_spec("Params", "ProxyParamSizeAdder1").fields[2].name == "Default Value"


def test_every_field_is_well_formed():
    vocabulary = set(T.DATA_TYPES_BY_NAME) | set(T.FIELD_VALUE_KINDS)
    entries = T.all_entries()
    assert len(entries) == 46
    for e in entries:
        assert e.clause.startswith("C.4."), e
        assert [f.number for f in e.fields] == list(range(1, len(e.fields) + 1)), e.keyword
        repeats = [f.repeats for f in e.fields]
        assert repeats == sorted(repeats), f"{e.keyword}: repeating fields must be the tail"
        for f in e.fields:
            assert set(f.alternatives) <= vocabulary, (e.keyword, f.name, f.eds_type)
            assert not f.bits or f.bits in T.BIT_TABLES
            assert f.clause.startswith("C.4.")


# --- data types ----------------------------------------------------------------


def test_elementary_codes_run_from_c1_to_de():
    codes = sorted(T.DATA_TYPES_BY_CODE)
    assert codes == list(range(0xC1, 0xDF))
    assert [T.DATA_TYPES_BY_CODE[c].name for c in (0xC1, 0xC7, 0xCA, 0xD0, 0xD3, 0xD5, 0xD9, 0xDA, 0xDC, 0xDE)] == [
        "BOOL", "UINT", "REAL", "STRING", "DWORD", "STRING2", "STRINGN", "SHORT_STRING", "EPATH", "STRINGI"]
    # Only STRING and STRING2 codes appear in the seed (C.4.1.3.5 example).
    assert {t.name for t in T.DATA_TYPES if t.code_source.startswith("C.")} == {"STRING", "STRING2"}


@pytest.mark.parametrize(("name", "size", "lo", "hi", "hex_digits"), [
    ("USINT", 1, 0, 255, 8),
    ("UINT", 2, 0, 65535, 8),
    ("UDINT", 4, 0, 4294967295, 8),
    ("ULINT", 8, 0, 18446744073709551615, 16),
    ("SINT", 1, -128, 127, 8),
    ("INT", 2, -32768, 32767, 8),
    ("DINT", 4, -2147483648, 2147483647, 8),
    ("LINT", 8, -9223372036854775808, 9223372036854775807, 16),
    ("BYTE", 1, 0, 255, 8),
    ("LWORD", 8, 0, 18446744073709551615, 16),
])
def test_integer_ranges_follow_c4137_to_c4139(name, size, lo, hi, hex_digits):
    t = T.DATA_TYPES_BY_NAME[name]
    assert (t.size, t.minimum, t.maximum, t.hex_digits) == (size, lo, hi, hex_digits)
    assert t.in_range(lo) and t.in_range(hi) and not t.in_range(hi + 1) and not t.in_range(lo - 1)


def test_hex_literals_of_signed_types_are_twos_complement():
    sint, int_, uint = (T.DATA_TYPES_BY_NAME[n] for n in ("SINT", "INT", "UINT"))
    assert sint.from_hex(0x80) == -128 and sint.from_hex(0x7F) == 127 and sint.from_hex(0x100) is None
    assert int_.from_hex(0x8000) == -32768 and int_.from_hex(0xFE) == 254 and int_.from_hex(0xFFFF) == -1
    assert uint.from_hex(0xFFFF) == 65535 and uint.from_hex(0x10000) is None
    lint = T.DATA_TYPES_BY_NAME["LINT"]
    assert lint.from_hex(0x8000000000000000) == lint.minimum and lint.from_hex(0x7FFFFFFFFFFFFFFF) == lint.maximum


@given(st.sampled_from(["SINT", "INT", "DINT", "LINT"]), st.data())
def test_from_hex_is_a_bijection_onto_the_range(name, data):
    t = T.DATA_TYPES_BY_NAME[name]
    value = data.draw(st.integers(t.minimum, t.maximum))
    assert t.from_hex(value % (1 << (8 * t.size))) == value


def test_bit_strings_and_reals():
    assert [T.DATA_TYPES_BY_NAME[n].binary_digits for n in ("BYTE", "WORD", "DWORD", "LWORD")] == [8, 16, 32, 64]
    assert T.DATA_TYPES_BY_NAME["UINT"].binary_digits is None
    real, lreal = T.DATA_TYPES_BY_NAME["REAL"], T.DATA_TYPES_BY_NAME["LREAL"]
    assert (real.floats.integer_max, real.floats.mantissa_digits, real.floats.exponent_digits) == (16777215, 11, 4)
    # LREAL: 17, not the text's 16 (T.LREAL_SIGNIFICANT_DIGITS says why)
    assert (lreal.floats.integer_max, lreal.floats.mantissa_digits) == (9007199254740991, 17)
    assert (real.floats.decimal_digits, lreal.floats.decimal_digits) == (16, 17)
    assert 3.4028e38 < real.maximum < 3.4029e38 and lreal.maximum == pytest.approx(1.7976e308, rel=1e-4)
    assert math.isnan(T.FLOAT_SPECIAL_WORDS["QUIET-NAN"]) and T.FLOAT_SPECIAL_WORDS["-INFINITY"] == -math.inf
    assert {n for n in T.NUMERIC_PARAM_TYPES} == {
        t.name for t in T.DATA_TYPES if t.kind in ("signed", "unsigned", "real") and t.name != "STIME"}


def test_obsolete_identifiers_follow_table_c16():
    ids = {n: t.name for n, t in T.OBSOLETE_DATA_TYPE_IDS.items()}
    assert list(ids) == list(range(1, 27))
    assert ids == {
        1: "WORD", 2: "UINT", 3: "INT", 4: "BOOL", 5: "SINT", 6: "DINT", 7: "LINT", 8: "USINT", 9: "UDINT",
        10: "ULINT", 11: "REAL", 12: "LREAL", 13: "ITIME", 14: "TIME", 15: "FTIME", 16: "LTIME", 17: "DATE",
        18: "TIME_OF_DAY", 19: "DATE_AND_TIME", 20: "STRING", 21: "STRING2", 22: "STRINGN",
        23: "SHORT_STRING", 24: "BYTE", 25: "DWORD", 26: "LWORD",
    }
    # Figure C.8: "2, $ data type : 16-bit WORD" and data size 2.
    assert T.OBSOLETE_DATA_TYPE_IDS[2].size == 2


def test_min_max_rules_follow_table_c17():
    assert T.min_max_rule("WORD").presence is P.NOT_ALLOWED
    assert T.min_max_rule("STRING2") == T.MinMaxRule(P.REQUIRED, "length", T.min_max_rule("STRING").note)
    assert T.min_max_rule("EPATH").presence is P.OPTIONAL and T.min_max_rule("EPATH").meaning == "length"
    assert T.min_max_rule("DINT") is T.DEFAULT_MIN_MAX_RULE and T.DEFAULT_MIN_MAX_RULE.meaning == "value"
    assert [T.DATA_TYPES_BY_NAME[n].char_size for n in ("STRING", "STRING2", "STRINGN", "EPATH")] == [1, 2, None, 1]


# --- bit tables ------------------------------------------------------------------


@pytest.mark.parametrize("table", list(T.BIT_TABLES.values()), ids=list(T.BIT_TABLES))
def test_bit_tables_tile_their_width(table):
    covered = 0
    for f in table.fields:
        assert covered & f.mask == 0, f"{f.name} overlaps"
        covered |= f.mask
    assert covered == (1 << table.width) - 1


def test_descriptor_bits():
    # Figure C.4: Descriptor = 0x0E.
    assert T.flags_set(0x0E, T.PARAMCLASS_DESCRIPTOR_BITS) == [
        "Supports full attributes", "Non-volatile storage save command", "Params are stored in non-volatile storage"]
    # Figure C.9: "0x0004, $ descriptor : support scaling"; Figure C.15: 0x0010 read only.
    assert T.flags_set(0x0004, T.PARAM_DESCRIPTOR_BITS) == ["Supports scaling"]
    assert T.flags_set(0x0010, T.PARAM_DESCRIPTOR_BITS) == ["Read only parameter"]
    assert T.reserved_bits_set(0x01FF, T.PARAM_DESCRIPTOR_BITS) == 0
    assert T.reserved_bits_set(0x0210, T.PARAM_DESCRIPTOR_BITS) == 0x0200
    assert T.reserved_bits_set(0x0010, T.PARAMCLASS_DESCRIPTOR_BITS) == 0x0010
    assert T.reserved_bits_set(0x0003, T.ASSEM_DESCRIPTOR_BITS) == 0x0002
    decoded = T.decode_bits(0x0000, T.PARAM_DESCRIPTOR_BITS)
    assert len(decoded) == 9 and decoded[4][2] == "Parameter value can be written (set) and read (get)"


@pytest.mark.parametrize(("value", "flags"), [
    (0x04010002, ["class 1", "trigger cyclic", "exclusive-owner"]),  # Figure C.9
    (0x02010002, ["class 1", "trigger cyclic", "input-only"]),
    (0x01010002, ["class 1", "trigger cyclic", "listen-only"]),      # Figure C.15 (restored)
    (0x04030002, ["class 1", "trigger cyclic", "trigger change of state", "exclusive-owner"]),
    (0x8402000C, ["class 2", "class 3", "trigger change of state", "exclusive-owner", "client/server"]),
])
def test_trigger_and_transport_decode(value, flags):
    assert T.flags_set(value, T.TRIGGER_TRANSPORT_BITS) == flags
    assert T.reserved_bits_set(value, T.TRIGGER_TRANSPORT_BITS) == 0
    assert T.exclusive_violations(value, T.TRIGGER_TRANSPORT_BITS) == []


def test_trigger_and_transport_errors():
    role = T.TRIGGER_TRANSPORT_BITS.field("client/server")
    assert role.meanings[role.extract(0x84010002)] == "server" and role.meanings[role.extract(0x04010002)] == "client"
    assert T.reserved_bits_set(0x14080082, T.TRIGGER_TRANSPORT_BITS) == 0x10080080
    assert T.exclusive_violations(0x06010002, T.TRIGGER_TRANSPORT_BITS) == ["transport"]
    assert [f.name for f, _, m in T.decode_bits(0x00000080, T.TRIGGER_TRANSPORT_BITS) if m == "reserved"] == [
        "reserved bits 7-15"]


def test_connection_parameters_of_figure_c9():
    # "0x44244401 $ fixed, 32-bit headers, scheduled, O=>T point-to-point, T=>O multicast"
    assert T.flags_set(0x44244401, T.CONNECTION_PARAMETER_BITS) == [
        "O=>T fixed size", "O=>T real time format", "T=>O real time format",
        "O=>T POINT2POINT", "T=>O MULTICAST", "O=>T SCHEDULED", "T=>O SCHEDULED"]
    meanings = {f.name: m for f, _, m in T.decode_bits(0x44244401, T.CONNECTION_PARAMETER_BITS)}
    assert meanings["O=>T real time format"] == meanings["T=>O real time format"] == "32-bit run/idle header"
    assert meanings["O=>T bytes per slot"] == "1 byte"
    assert T.reserved_bits_set(0x44244401, T.CONNECTION_PARAMETER_BITS) == 0


def test_connection_parameters_decode():
    # Fixed both ways, O=>T run/idle header, T=>O modeless, P2P out, multicast in, scheduled.
    decoded = {f.name: (v, m) for f, v, m in T.decode_bits(0x44240405, T.CONNECTION_PARAMETER_BITS)}
    assert decoded["O=>T fixed size"][0] == decoded["T=>O fixed size"][0] == 1
    assert decoded["O=>T variable size"][0] == decoded["T=>O variable size"][0] == 0
    assert decoded["O=>T real time format"] == (4, "32-bit run/idle header")
    assert decoded["T=>O real time format"] == (0, "pure data, modeless")
    assert decoded["O=>T POINT2POINT"][0] == 1 and decoded["T=>O MULTICAST"][0] == 1
    assert decoded["O=>T LOW"][0] == 0 and decoded["T=>O SCHEDULED"][0] == 1
    # Bytes per slot for adapter rack connections (bits 4-5, 6-7).
    assert T.CONNECTION_PARAMETER_BITS.field("T=>O bytes per slot").meanings[T.CONNECTION_PARAMETER_BITS.field(
        "T=>O bytes per slot").extract(0xC0)] == "8 bytes"
    # Reserved bits 11, 15, 19, 23, 27, 31 and the reserved format value 2.
    assert T.reserved_bits_set(0x88888800, T.CONNECTION_PARAMETER_BITS) == 0x88888800
    assert [(f.name, v) for f, v in T.reserved_values_set(0x00002200, T.CONNECTION_PARAMETER_BITS)] == [
        ("O=>T real time format", 2), ("T=>O real time format", 2)]


# --- scaling (Figure C.5) --------------------------------------------------------


def test_scaling_of_figure_c9():
    # Param1: min 64 .. max 95 with offset -63 reads 1 .. 32; Param2: 160 .. 191 with -159.
    assert T.scale(64, 1, 1, 1, -63) == 1 and T.scale(95, 1, 1, 1, -63) == 32
    assert T.scale(160, 1, 1, 1, -159) == 1 and T.scale(191, 1, 1, 1, -159) == 32


def test_scaling_formula():
    # (Actual + Offset) * Mult * Base / (Div * 10 ** DecimalPrecision)
    assert T.scale(100, multiplier=3, divisor=4, base=2, offset=10) == (110 * 3 * 2) / 4
    assert T.scale(1234, precision=2) == pytest.approx(12.34)
    assert T.scale(5) == 5
    with pytest.raises(ValueError):
        T.scale(1, divisor=0)


@given(st.integers(-(1 << 31), 1 << 31), st.integers(1, 65535), st.integers(1, 65535), st.integers(1, 65535),
       st.integers(-32768, 32767), st.integers(0, 6))
def test_unscale_inverts_scale(value, mult, div, base, offset, precision):
    eng = T.scale(value, mult, div, base, offset, precision)
    assert T.unscale(eng, mult, div, base, offset, precision) == pytest.approx(value, rel=1e-9, abs=1e-6)


# --- keywords ----------------------------------------------------------------------


def test_keyword_patterns():
    assert T.is_vendor_keyword("65535_Chassis") and not T.is_vendor_keyword("065535_Chassis")
    assert not T.is_vendor_keyword("Chassis")
    assert T.split_numbered("ProxyParamSizeAdder12") == ("ProxyParamSizeAdder", 12)
    assert T.split_numbered("CfgAssembly") == ("CfgAssembly", None)
    member = re.compile(T.FIELD_VALUE_KINDS["MemberKeyword"])
    assert all(member.fullmatch(k) for k in (*T.MEMBER_REFERENCE_KEYWORDS, "ExternalID2"))
    assert not member.fullmatch("InputSlotMask2")
    assert re.fullmatch(T.FIELD_VALUE_KINDS["ParamRef"], "Param65535")
    assert not re.fullmatch(T.FIELD_VALUE_KINDS["ParamRef"], "Param0")


# --- real files ----------------------------------------------------------------------

CORPUS = Path(__file__).resolve().parents[1].parent / "shared" / "corpus" / "real"


def _corpus_connection_masks():
    found = set()
    for path in sorted(CORPUS.glob("*.eds")):
        text = re.sub(r"\$[^\n]*", "", path.read_text(encoding="latin-1"))
        for m in re.finditer(r"\b(?:Connection|ProxyConnect)\d+\s*=\s*(0x[0-9A-Fa-f]+)\s*,\s*(0x[0-9A-Fa-f]+)", text):
            found.add((int(m.group(1), 16), int(m.group(2), 16)))
    return found


@pytest.mark.skipif(not CORPUS.is_dir(), reason="../shared/corpus not present")
def test_real_connection_masks_use_only_assigned_bits():
    masks = _corpus_connection_masks()
    assert len(masks) >= 10
    for trigger, params in masks:
        assert T.reserved_bits_set(trigger, T.TRIGGER_TRANSPORT_BITS) == 0, hex(trigger)
        assert T.exclusive_violations(trigger, T.TRIGGER_TRANSPORT_BITS) == [], hex(trigger)
        assert T.reserved_bits_set(params, T.CONNECTION_PARAMETER_BITS) == 0, hex(params)
        assert any(T.TRIGGER_TRANSPORT_BITS.field(f"class {n}").extract(trigger) for n in range(7)), hex(trigger)
