"""The EDS content beyond ISO 15745-4:2003, as data: sections, entries and fields
that today's CIP EDS files carry ([Capacity], the object class sections,
IconContents, AssemExaN, DeviceNet [IO_Info] ...).

The records are the FieldSpec / EntrySpec / SectionSpec of
:mod:`edsconv.spec_tables`; the 2003 tables stay there. We do not hold the
current CIP specification, so each record carries a
:class:`~edsconv.spec_tables.Provenance` instead of a clause:

- ``eds_pie``: the eds-pie 1.2.0 reference (``references/*.json``, MIT; facts
  only: names, class IDs, field types) that states it, as ``file: key``;
- ``files`` / ``practice``: how many real files (shared/corpus/real, 61 files)
  write it, and how;
- ``disagreement``: where eds-pie and the files differ, both readings and which
  one the table follows.

A record without an eds-pie reference is known from practice only
(``provenance.practice_only``): a check built on it is at most a warning.
``tools/survey_newer_content.py`` recounts the evidence; docs/spec_tables.md
summarises it; tests/test_cip_tables.py holds the tables to eds-pie and to the
files.

``clause`` of these records names the source ("eds-pie meta_eds_lib.json" or
"real files"); the ``eds_type`` vocabulary is that of spec_tables plus
:data:`CIP_VALUE_KINDS`.
"""

from __future__ import annotations

import enum
import re
from collections.abc import Mapping
from types import MappingProxyType

from edsconv.limits import decimal
from edsconv.spec_tables import (
    CLASSIFICATION_ENTRIES,
    CONNECTION_ENTRIES,
    CONNECTION_FIELDS,
    SECTIONS,
    VENDOR_SECTION,
    EntrySpec,
    FieldSpec,
    Presence,
    Provenance,
    SectionSpec,
    find_entry,
    is_vendor_keyword,
)
from edsconv.spec_tables import entry_spec as entry_spec_2003
from edsconv.spec_tables import section_spec as section_spec_2003

O, R = Presence.OPTIONAL, Presence.REQUIRED  # noqa: E741 - the column letters of spec_tables
#: eds-pie 1.2.0 reference files.
META, ENIP, COMMON = "meta_eds_lib.json", "ethernetip_lib.json", "common_object_class.json"
#: ``clause`` of a record known from practice only.
PRACTICE = "real files"
#: The corpus the ``files`` counts are taken over.
CORPUS = "shared/corpus/real (61 files)"

_N = "[1-9][0-9]{0,4}"
#: Value kinds beyond spec_tables.FIELD_VALUE_KINDS: kind -> regular expression
#: of the value (None when it is not a lexical form).
CIP_VALUE_KINDS: Mapping[str, str | None] = MappingProxyType({
    #: eds-pie EDS_SERVICE: a service code, or a brace group of a service code
    #: followed by attribute IDs or ``*`` (``{0x10,3,5}``, ``{0x0E,*}``: practice).
    "ServiceSpec": None,
    #: An EDS_Char_Array whose text is the base64 of an icon file (eds-pie: STRING).
    "Base64Icon": "[A-Za-z0-9+/]*={0,2}",
    #: References eds-pie names beyond the 2003 ones (REF lists of ethernetip_lib.json).
    "AssemExaRef": f"AssemExa{_N}",
    "VariantRef": f"Variant{_N}",
    "VariantExaRef": f"VariantExa{_N}",
    "BitStringVariantRef": f"BitStringVariant{_N}",
    "ArrayRef": f"Array{_N}",
    "ConstructedParamRef": f"ConstructedParam{_N}",
    #: A value no source types: kept, not checked.
    "Untyped": None,
})


def _src(eds_pie: str = "", files: int = 0, practice: str = "", disagreement: str = "") -> Provenance:
    return Provenance(eds_pie, files, practice, disagreement)


def _clause(provenance: Provenance) -> str:
    return f"eds-pie {provenance.eds_pie.split(':')[0]}" if provenance.eds_pie else PRACTICE


def _fields(provenance: Provenance, *rows, first: int = 1) -> tuple[FieldSpec, ...]:
    """FieldSpecs numbered from ``first``; each row is (name, eds_type[, presence[,
    dict of FieldSpec keywords]]); a row's own ``provenance`` overrides the entry's."""
    out = []
    for number, row in enumerate(rows, first):
        extra = dict(row[3]) if len(row) > 3 else {}
        own = extra.pop("provenance", provenance)
        out.append(FieldSpec(number, row[0], row[1], row[2] if len(row) > 2 else O, _clause(own), "",
                             provenance=own, **extra))
    return tuple(out)


def _entry(section: str, keyword: str, description: str, provenance: Provenance, fields: tuple[FieldSpec, ...],
           numbered: bool = False, presence: Presence = O, **kw) -> EntrySpec:
    return EntrySpec(keyword, numbered, section, fields, presence, _clause(provenance), "", description,
                     provenance=provenance, **kw)


def _single(section: str, keyword: str, name: str, eds_type: str, description: str, provenance: Provenance,
            **field_kw) -> EntrySpec:
    """An entry of one field (``keyword = value;``)."""
    return _entry(section, keyword, description, provenance, _fields(provenance, (name, eds_type, O, field_kw)))


def _section(name: str, title: str, class_id: int | None, provenance: Provenance,
             entries: tuple[EntrySpec, ...], note: str = "") -> SectionSpec:
    return SectionSpec(name, title, None, O, _clause(provenance), entries, MappingProxyType({}), note=note,
                       class_id=class_id, provenance=provenance)


# --- the common object class entries (eds-pie common_object_class.json) ---------------

_COMMON = "Common Object Class"
_C = f"{COMMON}: CommonObjectClass"
_SERVICE_LIST = "ServiceSpec"
COMMON_OBJECT_ENTRIES: tuple[EntrySpec, ...] = (
    _single(_COMMON, "Revision", "Revision", "UINT", "Revision of the object class (class attribute 1)",
            _src(f"{_C}.Revision", 47, "decimal in every file")),
    _single(_COMMON, "MaxInst", "MaxInst", "UINT", "Maximum instance number of the class",
            _src(f"{_C}.MaxInst", 46, "decimal, once 0x117 ([File Class])")),
    _single(_COMMON, "Number_Of_Static_Instances", "Number of Static Instances", "UINT",
            "Instances that exist without being created",
            _src(f"{_C}.Number_Of_Static_Instances", 47, "decimal in every file",
                 "eds-pie names the field 'Maximum Instance Number'; the table names it after the entry")),
    _single(_COMMON, "Max_Number_Of_Dynamic_Instances", "Maximum Number of Dynamic Instances", "UINT",
            "Instances that can be created", _src(f"{_C}.Max_Number_Of_Dynamic_Instances", 46, "decimal")),
    _entry(_COMMON, "Class_Attributes", "Class attributes the device supports",
           _src(f"{_C}.Class_Attributes", 17, "decimal (1, 2, 3) or hex (0x01, 0x02)"),
           _fields(_src(f"{_C}.Class_Attributes"), ("Attribute ID", "UINT", O, {"repeats": True}))),
    _entry(_COMMON, "Instance_Attributes", "Instance attributes the device supports",
           _src(f"{_C}.Instance_Attributes", 18, "decimal or hex attribute IDs"),
           _fields(_src(f"{_C}.Instance_Attributes"), ("Attribute ID", "UINT", O, {"repeats": True}))),
    _entry(_COMMON, "Class_Services", "Class services the device supports",
           _src(f"{_C}.Class_Services", 18, "hex codes (0x01, 0x0E), or brace groups {0x0E,*} in 14 files"),
           _fields(_src(f"{_C}.Class_Services"), ("Service", _SERVICE_LIST, O, {"repeats": True}))),
    _entry(_COMMON, "Instance_Services", "Instance services the device supports",
           _src(f"{_C}.Instance_Services", 18,
                "hex codes, or brace groups of a service and the attribute IDs it serves ({0x10,3,5,6}) or *"),
           _fields(_src(f"{_C}.Instance_Services"), ("Service", _SERVICE_LIST, O, {"repeats": True}))),
    _single(_COMMON, "Object_Name", "Name", "EDS_Char_Array", "Name of the object class",
            _src(f"{_C}.Object_Name", 44, "the class's name + ' Object' ('TCP/IP Interface Object')")),
    _single(_COMMON, "Object_Class_Code", "Object Class Code", "UDINT",
            "CIP class ID of the object; agrees with the section's class ID",
            _src(f"{_C}.Object_Class_Code", 44,
                 "hex (0xF5) in every file but one (the hand-written eds-pie demo), which writes 6 and 245")),
    _entry(_COMMON, "Service_Description", "Description of a service", _src(f"{_C}.Service_DescriptionN"),
           _fields(_src(f"{_C}.Service_DescriptionN"),
                   ("Service Code", "USINT"), ("Name", "EDS_Char_Array"),
                   ("Service Application Path", "EPATH|Keyword", O, {"choices": ("SYMBOL_ANSI",)}),
                   ("Service Request Data", "AssemExaRef|ParamRef|ConstructedParamRef|Empty"),
                   ("Service Response Data", "AssemExaRef|ParamRef|ConstructedParamRef|Empty")),
           numbered=True,
           note="eds-pie marks the fields as repeating from field 1 in ones while naming five different "
                "fields; the table follows the five names"),
)
#: eds-pie's CommonObjectClass: the home of the shared entries, which every
#: object class section lists (the same objects, not copies).
COMMON_OBJECT_CLASS = _section(_COMMON, "Common Object Class", None, _src(f"{COMMON}: CommonObjectClass"),
                               COMMON_OBJECT_ENTRIES,
                               note="entries for all CIP and EtherNet/IP classes (eds-pie's comment)")


def _common_except(*keywords: str) -> tuple[EntrySpec, ...]:
    """The common entries, less those the 2003 text defines for the section."""
    return tuple(e for e in COMMON_OBJECT_ENTRIES if e.keyword not in keywords)


# --- [Capacity] (eds-pie meta_eds_lib.json) ---------------------------------------------

_CAP = "Capacity"
_M = f"{META}: Capacity"


def _capacity(keyword: str, name: str, eds_type: str, files: int, practice: str = "") -> EntrySpec:
    return _single(_CAP, keyword, name, eds_type, name, _src(f"{_M}.{keyword}", files, practice or "decimal"))


TXRX_KEYWORDS = ("Tx", "Rx", "TxRx")
CAPACITY_ENTRIES: tuple[EntrySpec, ...] = (
    _entry(_CAP, "TSpec", "Traffic spec: packets per second the device sustains at a connection size",
           _src(f"{_M}.TSpecN", 51, "three fields in all 91 entries: TxRx (79), Tx (6), Rx (6); decimal sizes "
                "and rates; commented 'packets per sec @ <size> bytes' in 26 files"),
           _fields(_src(f"{_M}.TSpecN"),
                   ("TxRx", "Keyword", O, {"choices": TXRX_KEYWORDS}),
                   ("ConnSize", "UINT", O, {"note": "bytes"}),
                   ("PacketsPerSecond", "UDINT")),
           numbered=True),
    _capacity("ConnOverhead", "Connection overhead", "REAL", 27,
              "written without a leading digit: .004 (26 files), .0 (1)"),
    _capacity("MaxCIPConnections", "Maximum CIP connections", "UINT", 8),
    _capacity("MaxIOConnections", "Maximum I/O connections", "UINT", 33,
              "decimal; comment 'Maximum number of Class 1 Connections' in 24 files"),
    _capacity("MaxMsgConnections", "Maximum explicit connections", "UINT", 44,
              "decimal; comment 'Maximum number of Class 3 Connections' in 24 files"),
    _capacity("MaxIOProducers", "Maximum I/O producers", "UINT", 4),
    _capacity("MaxIOConsumers", "Maximum I/O consumers", "UINT", 4),
    _capacity("MaxIOProduceConsume", "Maximum I/O producers plus consumers", "UINT", 7),
    _capacity("MaxIOMcastProducers", "Maximum I/O multicast producers", "UINT", 7),
    _capacity("MaxIOMcastConsumers", "Maximum I/O multicast consumers", "UINT", 7),
    _capacity("MaxConsumersPerMcast", "Maximum consumers per multicast connection", "UINT", 21),
)

# --- EtherNet/IP network object classes (eds-pie ethernetip_lib.json) -------------------

_TCP, _LINK, _DLR = "TCP/IP Interface Class", "Ethernet Link Class", "DLR Class"
TCPIP_ENTRIES: tuple[EntrySpec, ...] = (
    _entry(_TCP, "ENetQCT", "EtherNet/IP QuickConnect target times",
           _src(f"{ENIP}: TCP/IP Interface Class.ENetQCTN", 24,
                "two decimal fields in all 24 entries (350, 50 in 18; 4000, 500 in 6), commented "
                "'Ready for Connection Time' (22 files) and 'Accumulated CIP Connection Time' (23)",
                "eds-pie: one UINT field repeating ('Ready for Connection Time'); the files: two named "
                "fields. The table follows the files (every entry has two, 22 files name both); both "
                "readings accept what the files write"),
           _fields(_src(f"{ENIP}: TCP/IP Interface Class.ENetQCTN"),
                   ("Ready for Connection Time", "UINT"),
                   ("Accumulated CIP Connection Time", "UINT", O, {"provenance": _src(
                       f"{ENIP}: TCP/IP Interface Class.ENetQCTN (the repeated UINT)", 24,
                       "the name is the comment of 23 files")})),
           numbered=True),
    _entry(_TCP, "ENetQCO", "EtherNet/IP QuickConnect originator times",
           _src(f"{ENIP}: TCP/IP Interface Class.ENetQCON"),
           _fields(_src(f"{ENIP}: TCP/IP Interface Class.ENetQCON"),
                   ("Connection Origination Time", "UINT", O, {"repeats": True})),
           numbered=True),
)
LINK_ENTRIES: tuple[EntrySpec, ...] = (
    _entry(_LINK, "InterfaceLabel", "Label of Ethernet Link instance N (the port's marking)",
           _src(f"{ENIP}: Ethernet Link Class.InterfaceLabelN", 33,
                "one string ('XF1', 'Port 1', 'Port1', 'TP1' ...); as many labels as MaxInst in 31 of 33 "
                "files, and no label number above MaxInst in any"),
           _fields(_src(f"{ENIP}: Ethernet Link Class.InterfaceLabelN"), ("Interface Label", "EDS_Char_Array")),
           numbered=True),
    _entry(_LINK, "InterfaceSpeed", "Speed of Ethernet Link instance N",
           _src(f"{ENIP}: Ethernet Link Class.InterfaceSpeedN"),
           _fields(_src(f"{ENIP}: Ethernet Link Class.InterfaceSpeedN"), ("Interface Speed", "UDINT")),
           numbered=True),
    _entry(_LINK, "InterfaceType", "Type of Ethernet Link instance N",
           _src("", 2, "decimal 2 beside labels 'XF1', 'XF2', 'TP1', 'TP2'; 1 beside 'Internal Port' "
                "(EZ-EDS 3.11, 3.36); the type USINT is read from these values only"),
           _fields(_src("", 2), ("Interface Type", "USINT")), numbered=True),
)
DLR_ENTRIES: tuple[EntrySpec, ...] = (
    _single(_DLR, "Ring_Supervisor_Capable", "Ring Supervisor Capable", "Keyword",
            "Whether the device can be a ring supervisor",
            _src("", 8, "'No' in all 8 files (EZ-EDS 3.11 - 3.36); no source lists the allowed keywords")),
    # spelled so (sic) in the one file that writes it
    _single(_DLR, "Redunant_Gateway_Capable", "Redundant Gateway Capable", "Keyword",
            "Whether the device can be a redundant gateway",
            _src("", 1, "'No' in 1 file (EZ-EDS 3.36), keyword spelled 'Redunant'")),
)
INGRESS_EGRESS_ENTRIES: tuple[EntrySpec, ...] = (
    _entry("Ingress Egress Class", "Maintain_Existing_Connection", "Maintain existing connection",
           _src(f"{ENIP}: Ingress Egress Class.Maintain_Existing_Connection"),
           _fields(_src(f"{ENIP}: Ingress Egress Class.Maintain_Existing_Connection"),
                   ("Maintain Existing Connection", "BOOL", R)),
           presence=R),
)

# --- DeviceNet [IO_Info] and [EnumPar] (sections: eds-pie meta_eds_lib.json; entries: practice) --

_IO = "IO_Info"
#: Both files are one vendor's template (Hilscher DNS V5, EZ-EDS 3.27): weak evidence.
_IO_FILES = "2 files, one vendor's DeviceNet template (EZ-EDS 3.27)"


def _io_mode(keyword: str, mode: str) -> EntrySpec:
    provenance = _src("", 2, f"{_IO_FILES}: 0x000F/0x0007/0x000B, 1, 1 or 0, commented 'OK to Combine w/...', "
                      "'Default Input = Input1', 'Default Output = Output1' (0: 'none')")
    return _entry(_IO, keyword, f"{mode} I/O connection: combinations and default input/output", provenance,
                  _fields(provenance,
                          ("Combination mask", "WORD", O, {"note": "connection types it may combine with"}),
                          ("Default input", "UINT", O, {"note": "N of an InputN; 0: none"}),
                          ("Default output", "UINT", O, {"note": "N of an OutputN; 0: none"})))


def _io_data(keyword: str, direction: str) -> EntrySpec:
    provenance = _src("", 2, f"{_IO_FILES}: 7 fields ('10, 80, 0x000F, \"name\", 6, \"20 04 24 65 30 03\", "
                      "\"help\"'); field 5 is the byte count of the path in field 6 in all 6 entries, and "
                      "field 2 is at most 8 times field 1; names and types are read from these values")
    return _entry(_IO, keyword, f"{direction} data of DeviceNet I/O messages", provenance,
                  _fields(provenance, ("Size", "UINT", O, {"note": "bytes"}), ("Size in bits", "UINT"),
                          ("Connection mask", "WORD", O, {"note": "same form as the *Info masks"}),
                          ("Name", "EDS_Char_Array"), ("Path size", "USINT", O, {"note": "bytes of the path"}),
                          ("Path", "EPATH"), ("Help", "EDS_Char_Array")),
                  numbered=True)


IO_INFO_ENTRIES: tuple[EntrySpec, ...] = (
    _single(_IO, "Default", "Default connections", "WORD", "Connection types used by default",
            _src("", 2, f"{_IO_FILES}: 0x0001, commented 'poll as default'")),
    _io_mode("PollInfo", "Polled"),
    _io_mode("StrobeInfo", "Bit-strobed"),
    _io_mode("COSInfo", "Change-of-state"),
    _io_mode("CyclicInfo", "Cyclic"),
    _io_data("Input", "Input"),
    _io_data("Output", "Output"),
)
ENUMPAR_ENTRIES: tuple[EntrySpec, ...] = (
    _entry("EnumPar", "Param", "Enumeration strings of ParamN, one per value from its minimum",
           _src("", 1, "1 file (EZ-EDS 3.27 DeviceNet template): 2 or 3 strings per entry"),
           _fields(_src("", 1), ("Enum String", "EDS_Char_Array", O, {"repeats": True})),
           numbered=True, pairs_with="Param"),
)

# --- the sections beyond the 2003 text ------------------------------------------------------


def _eds_pie_class(name: str, class_id: int, files: int = 0, practice: str = "", entries=(),
                   title: str = "") -> SectionSpec:
    """An object class section of eds-pie's ethernetip_lib.json with the common entries."""
    provenance = _src(f"{ENIP}: {name}.class_id", files, practice)
    return _section(name, title or name, class_id, provenance, COMMON_OBJECT_ENTRIES + tuple(entries))


def _practice_class(name: str, class_id: int, files: int, practice: str) -> SectionSpec:
    """An object class section eds-pie does not list: name and class ID from the files."""
    return _section(name, name, class_id, _src("", files, practice), COMMON_OBJECT_ENTRIES)


_OBJECT_CLASS_SECTIONS: tuple[SectionSpec, ...] = (
    _eds_pie_class("Identity Class", 1, 13, "Object_Class_Code 0x01, Object_Name 'Identity Object' (12 files)"),
    _eds_pie_class("Message Router Class", 2, 1, "no Object_Class_Code in the one file"),
    _eds_pie_class("DeviceNet Class", 3),
    _eds_pie_class("Connection Class", 5),
    _eds_pie_class("Register Class", 7),
    _eds_pie_class("Discrete Input Class", 8),
    _eds_pie_class("Discrete Output Class", 9),
    _eds_pie_class("Analog Input Class", 10),
    _eds_pie_class("Analog Output Class", 11),
    _eds_pie_class("Presence Sensing Class", 14),
    _eds_pie_class("File Class", 55, 1, "Object_Class_Code 0x37 (1 file, EZ-EDS 3.31)"),
    _eds_pie_class("DLR Class", 71, 30, "Object_Class_Code 0x47 (29 files), Revision 3 (30)", DLR_ENTRIES,
                   "Device Level Ring Class"),
    _eds_pie_class("QoS Class", 72, 35, "Object_Class_Code 0x48 (35 files)", (), "Quality of Service Class"),
    _eds_pie_class("CIP Security Class", 93, 1, "Object_Class_Code 0x5D (1 file, EZ-EDS 3.31)"),
    _eds_pie_class("EtherNet/IP Security Class", 94, 1, "Object_Class_Code 0x5E (1 file, EZ-EDS 3.31)"),
    _eds_pie_class("Certificate Management Class", 95, 1, "Object_Class_Code 0x5F (1 file, EZ-EDS 3.31)"),
    _eds_pie_class("Authority Class", 96),
    _eds_pie_class("Password Authenticator Class", 97),
    _eds_pie_class("Certificate Authenticator Class", 98),
    _eds_pie_class("Ingress Egress Class", 99, 0,
                   "no file names this section; the one file with an 'Ingress Egress Object' writes it as "
                   "[Class940_Vendor1] with Object_Class_Code 0x3AC (940), see VENDOR_CLASS_SECTION",
                   INGRESS_EGRESS_ENTRIES),
    _eds_pie_class("Connection Configuration", 243, 1, "Revision 2 only (1 file, no generator comment)",
                   (), "Connection Configuration Class"),
    _eds_pie_class(_TCP, 245, 46, "Object_Class_Code 0xF5 (43 files), 245 (1); Revision 4 (43)", TCPIP_ENTRIES),
    _eds_pie_class(_LINK, 246, 44, "Object_Class_Code 0xF6 (42 files); Revision 4 (41)", LINK_ENTRIES),
    _eds_pie_class("LLDP Management Class", 265, 15, "Object_Class_Code 0x109 (15 files)"),
    _eds_pie_class("LLDP Data Table Class", 266, 6, "Object_Class_Code 0x10A (6 files)"),
    _practice_class("Time Sync Class", 0x43, 6, "Object_Class_Code 0x43, Object_Name 'Time Sync Object' "
                    "(6 files, EZ-EDS 3.29 - 3.36)"),
    _practice_class("Safety Supervisor Class", 0x39, 1, "Object_Class_Code 0x39 (1 file, EZ-EDS 3.36)"),
    _practice_class("Safety Validator Class", 0x3A, 1, "Object_Class_Code 0x3A (1 file, EZ-EDS 3.36)"),
    _practice_class("Safety Discrete Output Point Class", 0x3B, 1, "Object_Class_Code 0x3B (1 file, EZ-EDS 3.36)"),
    _practice_class("Safety Discrete Input Point Class", 0x3D, 1, "Object_Class_Code 0x3D (1 file, EZ-EDS 3.36)"),
)

#: Sections beyond the 2003 text, by the name between the brackets.
CIP_SECTIONS: Mapping[str, SectionSpec] = MappingProxyType({s.name: s for s in (
    _section(_CAP, "Capacity", None, _src(f"{META}: Capacity", 52, "after [Port] or [Connection Manager]"),
             CAPACITY_ENTRIES),
    *_OBJECT_CLASS_SECTIONS,
    _section(_IO, "I/O Characteristics", None, _src(f"{META}: IO_Info", 2, _IO_FILES), IO_INFO_ENTRIES,
             note="DeviceNet; eds-pie lists the section without entries; the entries are the files'"),
    _section("EnumPar", "Enumerated Parameters", None, _src(f"{META}: EnumPar", 1, "1 DeviceNet file"),
             ENUMPAR_ENTRIES, note="eds-pie lists the section without entries; the entry is the file's"),
)})

# --- entries beyond the 2003 text in the sections it defines -----------------------------

_ASM = f"{ENIP}: Assembly"
_X = Presence.RESERVED
_MEMBER_REFS = ("AssemRef|ParamRef|AssemExaRef|VariantRef|BitStringVariantRef|VariantExaRef|ArrayRef|"
                "ConstructedParamRef|UDINT|EPATH|Empty")
_SELECTION_REFS = "ParamRef|AssemRef|AssemExaRef|ArrayRef|ConstructedParamRef"
_PATH = ("Path", "EPATH|Keyword", O, {"choices": ("SYMBOL_ANSI",)})


def _assem_exa_fields(provenance: Provenance) -> tuple[FieldSpec, ...]:
    return _fields(provenance, ("Name", "EDS_Char_Array"), _PATH, ("Size", "UINT|ParamRef"),
                   ("Descriptor", "WORD"), ("Reserved", "Empty", _X), ("Reserved", "Empty", _X),
                   ("Member Size", "UINT", O, {"repeats": True}),
                   ("Member Reference", _MEMBER_REFS, O, {"repeats": True}))


def _variant_fields(provenance: Provenance, selector: str, selection: str) -> tuple[FieldSpec, ...]:
    return _fields(provenance, ("Name", "EDS_Char_Array"), ("Help String", "EDS_Char_Array"),
                   ("Reserved", "Empty", _X), ("Reserved", "Empty", _X), ("Reserved", "Empty", _X),
                   ("Switch selector", selector), ("First selection value", "UINT"),
                   ("First selection entry", selection), ("Second selection value", "UINT"),
                   ("Second selection entry", selection),
                   ("Subsequent selection value", "UINT", O, {"repeats": True}),
                   ("Subsequent selection entry", selection, O, {"repeats": True}))


def _bit_variant_fields(provenance: Provenance) -> tuple[FieldSpec, ...]:
    entry = f"{_SELECTION_REFS}|Empty"
    return _fields(provenance, ("Name", "EDS_Char_Array"), ("Help String", "EDS_Char_Array"),
                   ("Reserved", "Empty", _X), ("Reserved", "Empty", _X), ("Reserved", "Empty", _X),
                   ("Bit switch selector", "AssemRef|ParamRef|AssemExaRef"),
                   ("First bit selection value", "UINT"), ("First bit set selection entry", entry),
                   ("First bit reset selection entry", entry),
                   ("Subsequent bit selection value", "UINT", O, {"repeats": True}),
                   ("Subsequent bit set selection entry", entry, O, {"repeats": True}),
                   ("Subsequent bit reset selection entry", entry, O, {"repeats": True}))


def _array_fields(provenance: Provenance) -> tuple[FieldSpec, ...]:
    return _fields(provenance, ("Name", "EDS_Char_Array"), _PATH, ("Descriptor", "WORD"),
                   ("Help String", "EDS_Char_Array"), ("Reserved", "Empty", _X), ("Reserved", "Empty", _X),
                   ("Reserved", "Empty", _X), ("Array Element Size", "UINT"),
                   ("Array Element Type", "AssemRef|AssemExaRef|ParamRef|VariantRef|BitStringVariantRef|"
                    "VariantExaRef|ConstructedParamRef|Empty"),
                   ("Number of Dimensions", "USINT"),
                   ("Number of Dimension Elements", "UDINT", O, {"repeats": True}))


def _assembly_entry(keyword: str, description: str, fields_of, files: int = 0, practice: str = "",
                    note: str = "") -> EntrySpec:
    provenance = _src(f"{_ASM}.{keyword}N", files, practice)
    return _entry("Assembly", keyword, description, provenance, fields_of(provenance), numbered=True, note=note)


_RESERVED_VARIANT = "the 2003 text reserves the keyword Variant for future [Assembly] entry types (C.4.1.4.8)"
ASSEMBLY_ENTRIES: tuple[EntrySpec, ...] = (
    _assembly_entry("AssemExa", "Extended assembly: its Size may be a ParamN", _assem_exa_fields, 14,
                    "150 entries; Path empty or \"\", Size a ParamN in every file; members as AssemN's"),
    _assembly_entry("ProxyAssemExa", "Extended assembly of the proxying device", _assem_exa_fields),
    _assembly_entry("ProxiedAssemExa", "Extended assembly of the proxied device", _assem_exa_fields),
    _assembly_entry("Variant", "Selects one of several entries by the value of a selector", lambda p:
                    _variant_fields(p, "ParamRef|AssemRef", "ParamRef"), note=_RESERVED_VARIANT),
    _assembly_entry("VariantExa", "Variant that may select assemblies and arrays", lambda p:
                    _variant_fields(p, "ParamRef|AssemRef|AssemExaRef", _SELECTION_REFS)),
    _assembly_entry("BitStringVariant", "Selects entries by the bits of a selector", _bit_variant_fields),
    _assembly_entry("Array", "An array of elements of one entry", _array_fields),
)

_CM = "Connection Manager"
_SAFETY = "1 file (EZ-EDS 3.36, CIP Safety I/O module)"
CONNECTION_MANAGER_ENTRIES: tuple[EntrySpec, ...] = (
    _single(_CM, "PITNS", "PITNS", "Keyword", "Production Inhibit Time (milliseconds) network segment supported",
            _src(f"{ENIP}: Connection Manager.PITNS", 3, "Yes in 3 files"), choices=("Yes", "No")),
    _single(_CM, "PITNS_usec", "PITNS_usec", "Keyword",
            "Production Inhibit Time (microseconds) network segment supported",
            _src(f"{ENIP}: Connection Manager.PITNS_usec", 2, "No in 2 files"), choices=("Yes", "No")),
    _single(_CM, "MaxSafetyConnections", "Maximum safety connections", "UINT", "CIP Safety connections",
            _src("", 1, f"{_SAFETY}: 2")),
    _single(_CM, "MaxSafetyInputCnxns", "Maximum safety input connections", "UINT", "CIP Safety input connections",
            _src("", 1, f"{_SAFETY}: 1")),
    _single(_CM, "MaxSafetyOutputCnxns", "Maximum safety output connections", "UINT",
            "CIP Safety output connections", _src("", 1, f"{_SAFETY}: 1")),
    _entry(_CM, "DefaultSafetyConnections", "Default CIP Safety connections",
           _src("", 1, f"{_SAFETY}: 1, 2 - the numbers of its two safety ConnectionN (read from the values)"),
           _fields(_src("", 1), ("Connection", "UINT", O, {"repeats": True, "note": "N of a ConnectionN"}))),
    _single(_CM, "SafetyFormat", "Safety format", "USINT", "CIP Safety data format",
            _src("", 1, f"{_SAFETY}: 2")),
)
#: ConnectionN fields 16 and 17 of eds-pie's ConnectionN (CIP Safety), after the
#: 15 of Table C.22.
CONNECTION_SAFETY_FIELDS: tuple[FieldSpec, ...] = _fields(
    _src(f"{ENIP}: Connection Manager.ConnectionN", 1,
         f"{_SAFETY}: both safety connections write 17 fields, field 16 empty, field 17 = 1",
         "eds-pie types both fields EMPTY; the file writes 1 in field 17. The table types them Untyped (kept, "
         "not checked): no source gives their type"),
    ("Safety ASYNC", "Untyped|Empty"), ("Safety Max Consumer Number", "Untyped|Empty"),
    first=len(CONNECTION_FIELDS) + 1)

_DEVICE_ENTRIES: tuple[EntrySpec, ...] = (
    _single("Device", "IconContents", "Icon Contents", "Base64Icon",
            "The device's icon file, base64, in concatenated strings",
            _src(f"{META}: Device.IconContents", 37,
                 "base64 in 37 of 37 files, over 18 - 599 concatenated strings; decoded: ICO with BMP images "
                 "(27), ICO with a PNG image (6), a BMP file (3), neither (1)",
                 "eds-pie types it STRING; the files write base64 of an icon: the table keeps the string and "
                 "says what its text is (Base64Icon). That it is an ICO is practice, as is the Icon entry's "
                 "*.ICO of the 2003 text (C.4.1.4.3) for the file named there")),
    _single("Device", "ApplicationProfilesAssembly", "Application Profiles Assembly", "UINT",
            "Assembly of the application profiles", _src(f"{META}: Device.ApplicationProfilesAssembly")),
)
_FILE_ENTRIES: tuple[EntrySpec, ...] = (
    _single("File", "EDSFileCRC", "EDS File CRC", "UDINT", "Checksum of the EDS file",
            _src(f"{META}: File.EDSFileCRC", 1, "hex (0x798A0C2F), 1 file (EZ-EDS 3.27)")),
    _single("File", "Exclude", "Exclude", "Keyword", "Exclude", _src(f"{META}: File.Exclude"),
            choices=("NONE", "WRITE", "READ_WRITE")),
)
_PARAMCLASS_ENTRIES: tuple[EntrySpec, ...] = (
    _single("ParamClass", "SafetyCfgAssembly", "Safety configuration assembly instance", "UINT",
            "Assembly instance of the CIP Safety configuration", _src("", 1, f"{_SAFETY}: 768 (Assem768 exists)")),
)


def _extension(name: str, class_id: int | None, provenance: Provenance, entries: tuple[EntrySpec, ...]) -> SectionSpec:
    return _section(name, SECTIONS[name].title, class_id, provenance, entries,
                    note="entries beyond the 2003 text; the 2003 entries are in spec_tables.SECTIONS")


#: Sections of the 2003 text, with the entries real files add to them and their
#: class ID where the section describes an object class. Look a keyword up in
#: spec_tables first: these hold only what the 2003 text does not define.
SECTION_EXTENSIONS: Mapping[str, SectionSpec] = MappingProxyType({s.name: s for s in (
    _extension("File", None, _src(f"{META}: File", 1), _FILE_ENTRIES),
    _extension("Device", None, _src(f"{META}: Device", 37), _DEVICE_ENTRIES),
    _extension("ParamClass", 15, _src(f"{ENIP}: ParamClass.class_id", 1, f"{_SAFETY}: SafetyCfgAssembly"),
               _common_except("MaxInst") + _PARAMCLASS_ENTRIES),
    _extension("Groups", 16, _src(f"{ENIP}: Groups.class_id"), COMMON_OBJECT_ENTRIES),
    _extension("Assembly", 4, _src(f"{ENIP}: Assembly.class_id", 47,
                                   "Object_Class_Code 0x04, Object_Name 'Assembly Object' (43 files)"),
               _common_except("Revision") + ASSEMBLY_ENTRIES),
    _extension(_CM, 6, _src(f"{ENIP}: Connection Manager.class_id", 46,
                            "Object_Class_Code 0x06 (43 files), 6 (1)"),
               COMMON_OBJECT_ENTRIES + CONNECTION_MANAGER_ENTRIES),
    _extension("Port", 244, _src(f"{ENIP}: Port.class_id", 8, "Object_Class_Code 0xF4 (8 files)"),
               COMMON_OBJECT_ENTRIES),
)})

#: ClassN keywords eds-pie lists beyond the 2003 three (Safety in 1 real file).
CLASSIFICATION_KEYWORDS_NEWER = ("CompoNet", "EtherNetIP_In_Cabinet", "EtherNetIP_UDP_Only", "ModbusSL",
                                 "ModbusTCP", "Safety", "HART", "IOLink")
CLASSIFICATION_KEYWORDS_NEWER_SOURCE = _src(f"{META}: Device Classification.ClassN", 1,
                                            "the files write EtherNetIP, 1_RSNetWorx_Connectable_Module (3), and "
                                            f"Safety as Class2 beside EtherNetIP ({_SAFETY})")

# --- vendor-specific sections ----------------------------------------------------------------

#: ``[Class<class ID>_Vendor<vendor ID>]``: an object class section named by
#: its class ID and a vendor ID (practice; the 2003 form VendorID_keyword is
#: spec_tables.VENDOR_KEYWORD_RE).
VENDOR_CLASS_SECTION_RE = re.compile(r"Class([1-9][0-9]*)_Vendor([1-9][0-9]*)")
VENDOR_CLASS_SECTION = _section(
    "Class<ID>_Vendor<VendorID>", "Vendor named object class", None,
    _src("", 2, "[Class940_Vendor1] 'Ingress Egress Object' (EZ-EDS 3.31); [Class15_Vendor1] 'Parameter "
         "Object', [Class265_Vendor1] 'LLDP Management Object', [Class266_Vendor1] 'LLDP Data Table Object' "
         "(1 file, no generator comment); in 4 of 4 the number after Class is the section's "
         "Object_Class_Code, and they hold the common entries plus vendor keywords (1_Ingress_TCP_Ports)"),
    COMMON_OBJECT_ENTRIES,
    note="the class ID may be a public one (15, 265, 266) or a vendor one (940)")


def vendor_class_section(name: str) -> tuple[int, int] | None:
    """(class ID, vendor ID) of a ``[Class<ID>_Vendor<VendorID>]`` section name."""
    match = VENDOR_CLASS_SECTION_RE.fullmatch(name.strip().removeprefix("[").removesuffix("]").strip())
    return (decimal(match.group(1)), decimal(match.group(2))) if match else None


# --- lookups --------------------------------------------------------------------------------


def section_spec(name: str) -> SectionSpec | None:
    """The table of a section beyond the 2003 text, of the extension of a 2003
    section, or VENDOR_CLASS_SECTION; None for anything else."""
    name = name.strip().removeprefix("[").removesuffix("]").strip()
    found = CIP_SECTIONS.get(name) or SECTION_EXTENSIONS.get(name)
    if found is None and vendor_class_section(name) is not None:
        return VENDOR_CLASS_SECTION
    return found


def entry_spec(section: str, keyword: str) -> EntrySpec | None:
    """The spec of an entry these tables define in a section (numbered families
    resolve: ``TSpec3`` -> TSpec); None for 2003 entries and unknown keywords."""
    found = section_spec(section)
    return find_entry(found.entries, keyword) if found is not None else None


def class_id_of(section: str) -> int | None:
    """CIP class ID of the object a section describes (``[Class940_Vendor1]`` -> 940)."""
    vendor = vendor_class_section(section)
    if vendor is not None:
        return vendor[0]
    found = section_spec(section)
    return found.class_id if found is not None else None


def all_sections() -> tuple[SectionSpec, ...]:
    """Every section table here: the new sections, the extensions, the vendor class form."""
    return (*CIP_SECTIONS.values(), *SECTION_EXTENSIONS.values(), VENDOR_CLASS_SECTION)


class Known(enum.Enum):
    """Who defines a section or an entry keyword (:func:`known`)."""

    #: ISO 15745-4:2003 (edsconv.spec_tables)
    ISO_2003 = "ISO 15745-4:2003"
    #: these tables: later CIP editions, as eds-pie and the real files show them
    NEWER = "newer CIP tables"
    #: a vendor: ``VendorID_keyword`` (C.4.1.2.2.11), ``[Class<ID>_Vendor<VendorID>]``, and every
    #: keyword of a ``[VendorID_keyword]`` section
    VENDOR = "vendor-specific"


def known(section: str, keyword: str | None = None) -> Known | None:
    """Who defines ``[section]`` (``keyword`` None) or the entry ``keyword`` in it; None when
    neither the 2003 text, nor these tables, nor a vendor pattern does.

    The one answer the checks consult (EDS006, EDS219, EDS222):
    a numbered family resolves (``TSpec3``), brackets are optional. A keyword counts in its own
    section only: ``MaxInst`` is known in ``[Ethernet Link Class]``, not in ``[Capacity]``.
    """
    name = section.strip().removeprefix("[").removesuffix("]").strip()
    if keyword is None:
        if name in SECTIONS:
            return Known.ISO_2003
        if name in CIP_SECTIONS:
            return Known.NEWER
        vendor = section_spec_2003(name) is VENDOR_SECTION or vendor_class_section(name) is not None
        return Known.VENDOR if vendor else None
    if is_vendor_keyword(keyword):
        return Known.VENDOR
    if name in SECTIONS and entry_spec_2003(name, keyword) is not None:
        return Known.ISO_2003
    if entry_spec(name, keyword) is not None:
        return Known.NEWER
    return Known.VENDOR if section_spec_2003(name) is VENDOR_SECTION else None


def known_choice(field_spec: FieldSpec, word: str) -> Known | None:
    """Who defines ``word`` as the value of a keyword field: the field's own list (the 2003 text's, or
    these tables' for a field of theirs), a vendor (when the field takes VendorID_keyword), or these
    tables' additions to a 2003 list (``Safety`` for the ClassN classification); None otherwise."""
    if word in field_spec.choices:
        return Known.ISO_2003 if field_spec.provenance is None else Known.NEWER
    if field_spec.vendor_keywords and is_vendor_keyword(word):
        return Known.VENDOR
    if field_spec is CLASSIFICATION_ENTRIES[0].fields[0] and word in CLASSIFICATION_KEYWORDS_NEWER:
        return Known.NEWER
    return None


def known_field_count(spec: EntrySpec) -> int | None:
    """How many fields the 2003 text and these tables define together for a 2003 entry (ConnectionN:
    15 plus the 2 of CIP Safety); None for an entry with a repeating tail."""
    if spec.max_fields is None:
        return None
    return spec.max_fields + (len(CONNECTION_SAFETY_FIELDS) if spec is CONNECTION_ENTRIES[0] else 0)
