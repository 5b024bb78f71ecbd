"""Typed edsconv elements for the EDS content beyond the 2003 text (:mod:`edsconv.cip_tables`).

The entries the cip_tables define ([Capacity], the object class sections, DeviceNet [IO_Info] and
[EnumPar], and the entries later editions add to the 2003 sections: IconContents, AssemExaN, PITNS,
the common object-class entries of [Assembly] ...) are written as typed elements of the edsconv
namespace, one element per entry, named by its keyword, its fields typed by their FieldSpec:

- a one-field entry holds its value as text: ``<edsconv:MaxIOConnections>32</...>``;
- a numbered entry has ``number``: ``<edsconv:TSpec number="1" txRx="TxRx" connSize="500" .../>``;
- the other fields of a several-field entry are attributes named after the field (``connSize``);
- a repeating tail is one child per field, named after the field: ``<edsconv:AttributeID>1</...>``,
  a service ``<edsconv:Service code="16" attributes="3 5"/>`` (``all="true"`` for ``*``).

Integers are written in decimal, reals as Python writes them, references as their keyword, paths as
space-separated items, strings and keywords as their text; an empty field writes nothing. The text
of the EDS is kept where the typed value does not give it back: the reader spells each value the way
:func:`eds_spelling` does (hexadecimal for the bit-string types and service codes, quotes around
strings and paths), and a field spelt otherwise (``MaxInst = 0x01;``, a string with escapes, a value
that fits no type of its field) also gets ``<edsconv:Field index="i" kind=...>`` with its spelling,
which the reader takes. An entry whose typed element would not give back its fields exactly (a
keyword spelt by an alias) stays an opaque ``edsconv:Entry``, as every entry the tables do not define.

Sections: ``edsconv:ObjectClass section="..." classId="..."`` for the object class sections,
``edsconv:Capacity``, ``edsconv:IOInfo``, ``edsconv:EnumPar``; entries added to a 2003 section stay in
``edsconv:ExtraEntries section="..."``. docs/mapping.md lists them and says why they stand where they do.
"""

from __future__ import annotations

import functools
import re

from lxml import etree

from edsconv import cip_tables
from edsconv import spec_tables as tables
from edsconv.eds.syntax import Scalar
from edsconv.model import GenericEntry, GenericSection
from edsconv.model.cip import Service
from edsconv.model.cip_build import reading, section_table
from edsconv.model.values import PathItem
from edsconv.xml.codec import eds_scalar, eds_string, float_text, read_entry, read_field, write_entries, write_field
from edsconv.xml.common import EDSCONV, is_xml_text
from edsconv.xml.datamodel import collapse, string_value

#: The sections beyond the 2003 text that are no object class, by their element's local name.
SECTION_ELEMENTS = {"Capacity": "Capacity", "IO_Info": "IOInfo", "EnumPar": "EnumPar"}
_SECTIONS_BY_ELEMENT = {EDSCONV + local: name for name, local in SECTION_ELEMENTS.items()}
OBJECT_CLASS = EDSCONV + "ObjectClass"
#: The field types whose values an EDS writes in hexadecimal (the bit strings).
_HEX_KINDS = frozenset(name for name, data_type in tables.DATA_TYPES_BY_NAME.items() if data_type.kind == "bits")
_INTEGER = re.compile(r"[+-]?[0-9]+")
_STRING_KINDS = frozenset({"EDS_Char_Array", "Base64Icon", "EPATH"})
#: The reference kinds (``ParamRef``, ``AssemExaRef`` ...) and the keywords they name.
_REFERENCES = {kind: re.compile(pattern) for kind, pattern in {**tables.FIELD_VALUE_KINDS,
                                                                **cip_tables.CIP_VALUE_KINDS}.items()
               if kind.endswith("Ref") and pattern is not None}


def xml_name(field_name: str, first_upper: bool) -> str:
    """``"Connection overhead"`` -> ``connectionOverhead`` (``ConnectionOverhead`` for an element)."""
    words = re.findall(r"[A-Za-z0-9]+", field_name)
    name = "".join(word[:1].upper() + word[1:] for word in words)
    return name if first_upper else name[:1].lower() + name[1:]


# --- writing -----------------------------------------------------------------------------------

def section_element(section: GenericSection) -> etree._Element | None:
    """The typed element of a section beyond the 2003 text, None for one the tables do not define."""
    spec = cip_tables.section_spec(section.name)
    if spec is None:
        return None
    if section.name in SECTION_ELEMENTS:
        element = etree.Element(EDSCONV + SECTION_ELEMENTS[section.name])
    elif spec.class_id is not None or cip_tables.vendor_class_section(section.name) is not None:
        element = etree.Element(OBJECT_CLASS, section=section.name)
        class_id = cip_tables.class_id_of(section.name)
        if class_id is not None:
            element.set("classId", str(class_id))
    else:
        return None
    write_entry_list(element, section.name, section.entries, extension=False)
    return element


def write_entry_list(parent: etree._Element, section: str, entries: list[GenericEntry], extension: bool) -> None:
    """``entries`` of ``[section]`` in order: typed where the tables define them, else opaque."""
    table = section_table(section, extension)
    for generic in entries:
        typed = entry_element(table, generic) if table is not None else None
        if typed is None:
            write_entries(parent, [generic])
        else:
            parent.append(typed)


def entry_element(table: tables.SectionSpec, generic: GenericEntry) -> etree._Element | None:
    """The typed element of one entry, None when the tables do not define it or it would not give
    back its fields exactly."""
    spec = tables.find_entry(table.entries, generic.keyword)
    if spec is None or generic.keyword != _keyword(spec, tables.instance_number(generic.keyword)):
        return None
    element = etree.Element(EDSCONV + spec.keyword)
    if spec.numbered:
        element.set("number", str(tables.instance_number(generic.keyword)))
    readings = generic.readings or [reading(value, spec.field_at(index + 1))
                                    for index, value in enumerate(generic.values)]
    children: dict[int, etree._Element] = {}  # the children of the repeating tail, by field index
    for index, (value, _) in enumerate(readings):
        field_spec = spec.field_at(index + 1)
        if field_spec is not None and field_spec.repeats:
            children[index] = _write_repeated(element, field_spec, value)
        elif field_spec is not None and generic.values[index] is not None:
            _write_value(element, spec, field_spec, value)
    decoded = entry_values(element, spec)
    if decoded == generic.values:
        return element  # the usual case: the typed values give the fields back as written
    if len(decoded) != len(generic.values):
        element.set("fields", str(len(generic.values)))
        decoded = entry_values(element, spec)
    for index, (written, back) in enumerate(zip(generic.values, decoded, strict=True)):
        if written == back:
            continue
        simple = isinstance(written, Scalar) and is_xml_text(written.raw)
        if simple and (_single(spec) or index in children):
            children.get(index, element).set("spelling", written.raw)
        else:
            write_field(element, written)
            element[-1].set("index", str(index))
    return element if entry_values(element, spec) == generic.values else None


def _single(spec: tables.EntrySpec) -> bool:
    """An entry of one field, which its element holds in ``value``."""
    return len(spec.fields) == 1 and not spec.fields[0].repeats


def _keyword(spec: tables.EntrySpec, number: int) -> str:
    return f"{spec.keyword}{number}" if spec.numbered else spec.keyword


def _write_repeated(element: etree._Element, field_spec: tables.FieldSpec, value) -> etree._Element:
    """One child of a repeating tail, ``none="true"`` for an empty field or one without a typed value."""
    if isinstance(value, Service):
        service = etree.SubElement(element, EDSCONV + "Service", code=str(value.code))
        if value.all_attributes:
            service.set("all", "true")
        elif value.attributes:
            service.set("attributes", " ".join(str(a) for a in value.attributes))
        return service
    child = etree.SubElement(element, EDSCONV + xml_name(field_spec.name, True))
    text = typed_text(value)
    if text is None:
        child.set("none", "true")
    child.text = text
    return child


def _write_value(element: etree._Element, spec: tables.EntrySpec, field_spec: tables.FieldSpec, value) -> None:
    """One typed field of a single-field entry (``value``) or a several-field entry (an attribute)."""
    text = typed_text(value)
    if text is None:
        return
    elif _single(spec):
        element.set("value", text)
    elif element.get(xml_name(field_spec.name, False)) is None:
        element.set(xml_name(field_spec.name, False), text)


def typed_text(value) -> str | None:
    """The XML text of a typed field value, None when it has none (no reading, text XML cannot hold)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        return float_text(value)
    if isinstance(value, str):
        return value if is_xml_text(value) else None
    if isinstance(value, tuple) and value and all(isinstance(item, PathItem) for item in value):
        return " ".join(str(item) for item in value)
    text = getattr(value, "text", None)  # a Reference
    return text if isinstance(text, str) else None


# --- reading -----------------------------------------------------------------------------------

def entry_values(element: etree._Element, spec: tables.EntrySpec) -> list:
    """The fields of an entry element as the EDS writes them (GenericEntry.values)."""
    values: dict[int, object] = {}
    if _single(spec):
        spelling, text = element.get("spelling"), element.get("value")
        if spelling is not None:
            values[0] = eds_scalar(spelling)
        elif text is not None:
            values[0] = eds_spelling(text, spec.fields[0])
    else:
        for field_spec in spec.fields:
            text = element.get(xml_name(field_spec.name, False))
            if text is not None and not field_spec.repeats:
                values[field_spec.number - 1] = eds_spelling(text, field_spec)
    position = spec.repeating[0].number - 1 if spec.repeating else 0
    spellings = {}
    for child in element.iterchildren(etree.Element):  # comments and processing instructions skipped
        if child.tag == EDSCONV + "Field" and child.get("index") is not None:
            spellings[int(child.get("index", ""))] = read_field(child)
        elif spec.repeating and child.tag != EDSCONV + "Field":
            tail_spec = spec.field_at(position + 1)
            if child.get("spelling") is not None:
                values[position] = eds_scalar(child.get("spelling", ""))
            elif tail_spec is not None and child.get("none") != "true":
                values[position] = _repeated_value(child, tail_spec)
            position += 1
    values.update(spellings)
    count = int(element.get("fields", "0")) or (max(values) + 1 if values else 0)
    return [values.get(index) for index in range(count)]


def _repeated_value(child: etree._Element, field_spec: tables.FieldSpec):
    if child.tag == EDSCONV + "Service":
        code = Scalar(f"0x{int(child.get('code', '')):02X}")
        if child.get("all") == "true":
            return [code, Scalar("*")]
        attributes = child.get("attributes")
        return [code, *(eds_scalar(a) for a in attributes.split())] if attributes else code
    return eds_spelling(string_value(child), field_spec)


def eds_spelling(text: str, field_spec: tables.FieldSpec):
    """The EDS spelling of a typed value's text: integers in decimal (hexadecimal for the bit strings),
    strings and paths quoted, keywords, references and reals as they are."""
    hex_digits, numeric, references, string = _spelling_plan(field_spec)
    word = collapse(text)  # white space around a number, keyword or reference is no part of it
    if numeric and _INTEGER.fullmatch(word):
        return Scalar(f"0x{int(word):0{hex_digits}X}" if hex_digits else word)
    if any(pattern.fullmatch(word) for pattern in references):
        return Scalar(word)
    if string and word not in field_spec.choices:
        return eds_string((f'"{text}"',))
    return eds_scalar(word)


@functools.cache
def _spelling_plan(field_spec: tables.FieldSpec) -> tuple[int, bool, tuple[re.Pattern[str], ...], bool]:
    """How :func:`eds_spelling` spells a field's values: hexadecimal digits of its first bit-string
    type (0: decimal), whether it takes numbers, its reference patterns, whether it takes strings."""
    kinds = field_spec.alternatives
    hex_digits = next((2 * (tables.DATA_TYPES_BY_NAME[kind].size or 1) for kind in kinds if kind in _HEX_KINDS), 0)
    numeric = any(kind in tables.DATA_TYPES_BY_NAME for kind in kinds)
    references = tuple(_REFERENCES[kind] for kind in kinds if kind in _REFERENCES)
    return hex_digits, numeric, references, bool(_STRING_KINDS & set(kinds))


def read_section(element: etree._Element) -> GenericSection | None:
    """A typed section element back as a GenericSection, None for an element that is none."""
    if element.tag == OBJECT_CLASS:
        name = element.get("section", "")
    elif element.tag in _SECTIONS_BY_ELEMENT:
        name = _SECTIONS_BY_ELEMENT[element.tag]
    else:
        return None
    return GenericSection(name, read_entry_list(element, name, extension=False))


def read_entry_list(parent: etree._Element, section: str, extension: bool) -> list[GenericEntry]:
    """The entries of a section element in order: opaque ``edsconv:Entry`` and typed entry elements."""
    table = section_table(section, extension)
    entries: list[GenericEntry] = []
    for child in parent:
        if not isinstance(child.tag, str) or not child.tag.startswith(EDSCONV):
            continue
        if child.tag == EDSCONV + "Entry":
            entries.append(read_entry(child))
            continue
        local = etree.QName(child).localname
        spec = next((s for s in table.entries if s.keyword == local), None) if table is not None else None
        if spec is None:
            raise ValueError(f"{local} is no entry of [{section}]")
        number = int(child.get("number", "0")) if spec.numbered else 0
        entries.append(GenericEntry(_keyword(spec, number), entry_values(child, spec)))
    return entries


# --- placement ---------------------------------------------------------------------------------
# DeviceFunction (C.2.1.2.4, 6.3.1.4: a function of the device) holds the typed elements unless an
# extension point of the schema has the meaning of the entry: IconContents is the icon that 6.3.1.2
# counts among the device identity's attributes ("location of storage of additional information (e.g.
# icons)", beside [Device] Icon's DeviceIdentity/Icon); [Identity Class] describes the identity object
# whose revision 6.3.1.3 gives to DeviceManager. Each keeps its ``position`` among the entries of
# [Device] / the sections beyond the 2003 text, so that reading puts it back in its place.

IDENTITY_ATTRIBUTES = "DeviceIdentity/DeviceIdentity_InstanceAttributes"
_ICON = EDSCONV + "IconContents"
_IDENTITY_CLASS = "Identity Class"


def place(body: etree._Element, function: etree._Element) -> None:
    """Move the elements of ``function`` whose meaning an extension point of ``body`` fits there."""
    identity = body.find(IDENTITY_ATTRIBUTES)
    holder = function.find(f"{EDSCONV}ExtraEntries[@section='Device']")
    if identity is not None and holder is not None:
        for position, child in enumerate(list(holder)):
            if child.tag == _ICON:
                child.set("position", str(position))
                identity.append(child)
    sections = [child for child in function if child.tag in (*_SECTIONS_BY_ELEMENT, OBJECT_CLASS, EDSCONV + "Section")]
    for position, child in enumerate(sections):
        if child.tag == OBJECT_CLASS and child.get("section") == _IDENTITY_CLASS:
            manager = body.find("DeviceManager")
            if manager is None:
                manager = etree.Element("DeviceManager")
                function.addprevious(manager)
            child.set("position", str(position))
            manager.append(child)


def placed(body: etree._Element) -> tuple[list[tuple[int, GenericEntry]], list[tuple[int, GenericSection]]]:
    """The placed [Device] entries and sections with their positions, in order of position."""
    entries = [(int(element.get("position", "0")), read_entry_list(_alone(element), "Device", extension=True)[0])
               for element in body.iterfind(f"{IDENTITY_ATTRIBUTES}/{_ICON}")]
    sections = []
    for element in body.iterfind(f"DeviceManager/{OBJECT_CLASS}"):
        section = read_section(element)
        if section is not None:
            sections.append((int(element.get("position", "0")), section))
    return sorted(entries, key=lambda pair: pair[0]), sorted(sections, key=lambda pair: pair[0])


def _alone(element: etree._Element) -> etree._Element:
    """A holder of a copy of ``element``: read_entry_list reads the children of a section element."""
    holder = etree.Element("holder")
    holder.append(etree.fromstring(etree.tostring(element, with_tail=False)))
    return holder
