"""Semantic comparison of two devices: what changed between two EDS revisions.

:func:`diff` compares two :class:`~edsconv.model.Device` objects entry by entry
and field by field. What counts is the meaning, not the spelling: ``0x10`` and
``16`` are the same descriptor, entries may stand in any order, comments are
ignored. NaN equals NaN; references compare by keyword (not by what they
resolve to). Entries and sections later CIP editions define (edsconv.cip_tables:
[Capacity], the object classes, AssemExaN, IconContents ...) compare by keyword
and by the values of their fields' types, field by field (the icon by its
decoded bytes); what neither the 2003 text nor the tables define compares by
its values as written.

Each :class:`Change` says what changed (``Param3 default``, ``Assem100 member 2``,
``Connection1 O=>T RPI``, ``identity.product_code``) with the old and new value
spelled as in an EDS (:func:`edsconv.eds.from_model.render_value`).
"""

from __future__ import annotations

import dataclasses
import hashlib
import math
from collections.abc import Iterator
from dataclasses import dataclass
from typing import Any

from edsconv import cip_tables
from edsconv import spec_tables as tables
from edsconv.eds.syntax import Group, Scalar, String
from edsconv.model import (
    PARAMETER_FIELD_ATTRIBUTES,
    SINGLE_ENTRY_ATTRIBUTES,
    Assembly,
    AssemblyMember,
    Connection,
    Device,
    GenericEntry,
    GenericSection,
    Parameter,
    ParameterGroup,
    Reference,
    parameter_field_type,
)
from edsconv.model.cip_build import ASSEMBLY_FAMILIES, modelled, reading
from edsconv.model.icon import decode_icon
from edsconv.model.values import PathItem, StringIMember

#: Categories of changes, in the order the text output lists them.
CATEGORIES = ("identity", "params", "assemblies", "connections", "others")


@dataclass(frozen=True, slots=True)
class Change:
    #: "added", "removed" or "changed"
    kind: str
    #: what changed: "Param3", "Param3 default", "Assem100 member 2", "identity.product_code" ...
    what: str
    #: the old and new value as written in an EDS (None when absent)
    old: str | None = None
    new: str | None = None
    #: one of :data:`CATEGORIES`
    category: str = "others"

    def as_dict(self) -> dict:
        return {"kind": self.kind, "category": self.category, "what": self.what, "old": self.old, "new": self.new}

    def format(self) -> str:
        if self.kind == "added":
            return f"+ {self.what}" + (f": {_or_empty(self.new)}" if self.new is not None else "")
        if self.kind == "removed":
            return f"- {self.what}" + (f": {_or_empty(self.old)}" if self.old is not None else "")
        return f"~ {self.what}: {_or_empty(self.old)} -> {_or_empty(self.new)}"


#: longer values are cut in the text output (the JSON output keeps them whole)
TEXT_WIDTH = 60


def _or_empty(text: str | None) -> str:
    if text is None:
        return "(empty)"
    return text if len(text) <= TEXT_WIDTH else text[:TEXT_WIDTH - 3] + "..."


# --- comparable forms --------------------------------------------------------------------


def comparable(value: Any) -> Any:
    """A value in a form where ``==`` is the semantic equality: NaN equals NaN,
    references are their keyword (and bit), records their compared fields,
    syntax values (of generic entries) their spelling."""
    if isinstance(value, float) and math.isnan(value):
        return ("NaN",)
    if isinstance(value, Reference):
        return ("ref", value.keyword, value.bit)
    if isinstance(value, Scalar):
        return ("scalar", value.raw)
    if isinstance(value, String):
        return ("string", value.unicode, value.text)
    if isinstance(value, Group):
        return ("group", tuple(comparable(f.value) for f in value.fields))
    if isinstance(value, dict):
        return ("dict", tuple((comparable(k), comparable(v)) for k, v in value.items()))
    if isinstance(value, (list, tuple)):
        return tuple(comparable(v) for v in value)
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return (type(value).__name__, tuple(comparable(getattr(value, f.name))
                                            for f in dataclasses.fields(value) if f.compare))
    return value


def same(a: Any, b: Any) -> bool:
    return comparable(a) == comparable(b)


def display(value: Any, type_name: str = "") -> str | None:
    """A value as it would be written in an EDS: ``0x0010``, ``"Speed"``, ``Param3``."""
    from edsconv.eds.from_model import render_value

    if value is None:
        return None
    if isinstance(value, (Scalar, String, Group)):
        syntax = value
    elif isinstance(value, (list, tuple)) and any(not isinstance(v, (PathItem, StringIMember)) for v in value):
        return ", ".join(_or_empty(display(v, type_name)) for v in value)
    else:
        try:
            syntax = render_value(value, type_name)
        except TypeError:
            return str(value)
    return _syntax_text(syntax)


def _syntax_text(syntax) -> str:
    if syntax is None:
        return ""
    if isinstance(syntax, Group):
        return "{" + ", ".join(_syntax_text(f.value) for f in syntax.fields) + "}"
    return syntax.raw


# --- comparison --------------------------------------------------------------------------


class _Differ:
    def __init__(self) -> None:
        self.changes: list[Change] = []

    def value(self, what: str, old: Any, new: Any, category: str, type_name: str = "") -> None:
        if same(old, new):
            return
        if old is None:
            self.changes.append(Change("added", what, None, display(new, type_name), category))
        elif new is None:
            self.changes.append(Change("removed", what, display(old, type_name), None, category))
        else:
            self.changes.append(Change("changed", what, display(old, type_name), display(new, type_name), category))

    def attributes(self, prefix: str, old, new, attributes: dict[str, str], category: str, sep: str = ".") -> None:
        for attribute, type_name in attributes.items():
            self.value(f"{prefix}{sep}{attribute}", getattr(old, attribute) if old is not None else None,
                       getattr(new, attribute) if new is not None else None, category, type_name)

    def keyed(self, old: dict, new: dict, category: str, compare, label=lambda record: None) -> None:
        """Records by key: added, removed, and the changes of those in both."""
        for key, record in old.items():
            if key not in new:
                self.changes.append(Change("removed", key, label(record), None, category))
            elif not same(record, new[key]):
                compare(key, record, new[key])
        for key, record in new.items():
            if key not in old:
                self.changes.append(Change("added", key, None, label(record), category))


def _single_entry_types(section: str) -> dict[str, str]:
    """attribute -> the type its [File] / [Device] / [ParamClass] / [Modular] entry is written in."""
    specs = {spec.keyword: spec for spec in tables.SECTIONS[section].entries}
    return {attribute: specs[keyword].fields[0].alternatives[0]
            for keyword, attribute in SINGLE_ENTRY_ATTRIBUTES[section].items()}


_FILE = _single_entry_types("File")
_IDENTITY = _single_entry_types("Device")
_PARAM_CLASS = _single_entry_types("ParamClass")


def _parameter_field_types() -> tuple[dict[str, str], dict[str, str]]:
    """attribute -> type of the Parameter fields and of its Scaling (Table C.13), in field order."""
    parameter: dict[str, str] = {}
    scaling: dict[str, str] = {}
    for attribute in PARAMETER_FIELD_ATTRIBUTES[1:]:
        record, _, name = attribute.rpartition(".")
        (scaling if record else parameter)[name] = parameter_field_type(attribute)
    return parameter, scaling


_PARAMETER, _SCALING = _parameter_field_types()
_ASSEMBLY = {"name": "", "path": "EPATH", "size": "UINT", "descriptor": "WORD", "module_member_list": ""}
_CONNECTION = {"trigger_transport": "DWORD", "parameters": "DWORD"}
_ENDPOINTS = (("o_to_t", "O=>T"), ("t_to_o", "T=>O"), ("config1", "config #1"), ("config2", "config #2"))
_PORT = {"type_name": "Keyword", "name": "", "object_path": "EPATH", "port_number": "UINT", "specific": ""}
_MODULAR = _single_entry_types("Modular")
_RACK = {"vendor_code": "UINT", "product_type": "UINT", "product_code": "UINT", "major_revision": "USINT",
         "minor_revision": "USINT", "legal_slots": ""}
_QUERY = {"path": "EPATH", "service": "USINT", "id_size": "USINT", "empty_slot_id": "EPATH"}


def _value_type(parameter: Parameter) -> str:
    data_type = parameter.data_type
    return data_type.name if data_type is not None and data_type.size is not None else ""


def _member_text(member: AssemblyMember) -> str:
    return f"{display(member.size) or ''}, {display(member.reference) or ''}".strip()


def diff(a: Device, b: Device) -> list[Change]:
    """The semantic changes from ``a`` to ``b``; empty when they describe the same device."""
    d = _Differ()
    d.attributes("file", a.file, b.file, _FILE, "identity")
    d.attributes("identity", a.identity, b.identity, _IDENTITY, "identity")
    d.keyed({f"Class{c.number}": c for c in a.classifications}, {f"Class{c.number}": c for c in b.classifications},
            "identity", lambda key, old, new: d.value(key, (old.classification, *old.subclassifications),
                                                     (new.classification, *new.subclassifications), "identity"))
    if not same(a.param_class, b.param_class):
        d.attributes("ParamClass", a.param_class, b.param_class, _PARAM_CLASS, "params")
    d.keyed(a.parameters, b.parameters, "params", lambda key, old, new: _parameter(d, key, old, new),
            lambda p: display(p.name))
    d.keyed({f"Group{g.number}": g for g in a.groups}, {f"Group{g.number}": g for g in b.groups}, "params",
            lambda key, old, new: _group(d, key, old, new), lambda g: display(g.name))
    d.value("Assembly Revision", a.assembly_revision, b.assembly_revision, "assemblies", "UINT")
    d.keyed(a.assemblies, b.assemblies, "assemblies", lambda key, old, new: _assembly(d, key, old, new),
            lambda x: display(x.name))
    d.keyed(a.connections, b.connections, "connections", lambda key, old, new: _connection(d, key, old, new),
            lambda c: display(c.name))
    d.keyed({f"Port{p.number}": p for p in a.ports}, {f"Port{p.number}": p for p in b.ports}, "others",
            lambda key, old, new: d.attributes(key, old, new, _PORT, "others", " "), lambda p: display(p.name))
    _modular(d, a, b)
    d.keyed(a.extended_assemblies, b.extended_assemblies, "assemblies",
            lambda key, old, new: _assembly(d, key, old, new), lambda x: display(x.name))
    _generic(d, a, b)
    d.keyed(_unreadable(a), _unreadable(b), "others", lambda key, old, new: d.value(key, old, new, "others"),
            lambda text: text)
    return d.changes


def _unreadable(device: Device) -> dict[str, str]:
    """The text without a reading (Device.unreadable), by where it stands; compared as written."""
    found: dict[str, str] = {}
    for item in device.unreadable:
        if item.keyword is not None:
            where = f"[{item.section}] {item.keyword} field {(item.field or 0) + 1} (unreadable)"
        else:
            where = f"[{item.section}] text that is no entry" + (f" before {item.before}" if item.before else "")
        key, count = where, 1
        while key in found:
            count += 1
            key = f"{where} #{count}"
        found[key] = item.text
    return found


def _parameter(d: _Differ, key: str, old: Parameter, new: Parameter) -> None:
    for attribute, type_name in _PARAMETER.items():
        if attribute in ("minimum", "maximum", "default"):
            type_name = _value_type(new) or _value_type(old)
        d.value(f"{key} {attribute}", getattr(old, attribute), getattr(new, attribute), "params", type_name)
    d.attributes(f"{key} scaling", old.scaling, new.scaling, _SCALING, "params")
    d.value(f"{key} size adder", old.size_adder, new.size_adder, "params")
    if not same(old.enum, new.enum):
        old_enum, new_enum = old.enum or {}, new.enum or {}
        if old.enum is None or new.enum is None:
            d.value(f"{key} enum", _enum_text(old.enum), _enum_text(new.enum), "params")
            return
        for value in {**old_enum, **new_enum}:
            d.value(f"{key} enum {value}", old_enum.get(value), new_enum.get(value), "params")


def _group(d: _Differ, key: str, old: ParameterGroup, new: ParameterGroup) -> None:
    d.value(f"{key} name", old.name, new.name, "params")
    d.value(f"{key} members", [m.keyword for m in old.members], [m.keyword for m in new.members], "params")


def _enum_text(enum: dict | None) -> str | None:
    if enum is None:
        return None
    return ", ".join(f"{value} {display(text) or ''}".strip() for value, text in enum.items())


def _assembly(d: _Differ, key: str, old: Assembly, new: Assembly) -> None:
    d.attributes(key, old, new, _ASSEMBLY, "assemblies", " ")
    for index in range(max(len(old.members), len(new.members))):
        before = old.members[index] if index < len(old.members) else None
        after = new.members[index] if index < len(new.members) else None
        what = f"{key} member {index + 1}"
        if before is None and after is not None:
            d.changes.append(Change("added", what, None, _member_text(after), "assemblies"))
        elif after is None and before is not None:
            d.changes.append(Change("removed", what, _member_text(before), None, "assemblies"))
        elif before is not None and after is not None and not same(before, after):
            d.changes.append(Change("changed", what, _member_text(before), _member_text(after), "assemblies"))


def _connection(d: _Differ, key: str, old: Connection, new: Connection) -> None:
    d.attributes(key, old, new, _CONNECTION, "connections", " ")
    for attribute, label in _ENDPOINTS:
        before, after = getattr(old, attribute), getattr(new, attribute)
        for part, type_name in (("rpi", "UDINT"), ("size", "UINT"), ("format", "")):
            d.value(f"{key} {label} {part.upper() if part == 'rpi' else part}", getattr(before, part),
                    getattr(after, part), "connections", type_name)
    d.attributes(key, old, new, {"name": "", "help": "", "path": "EPATH"}, "connections", " ")


def _modular(d: _Differ, a: Device, b: Device) -> None:
    if same(a.modular, b.modular):
        return
    d.attributes("Modular", a.modular, b.modular, _MODULAR, "others")
    old_racks = {f"Rack{r.number}": r for r in (a.modular.racks if a.modular else [])}
    new_racks = {f"Rack{r.number}": r for r in (b.modular.racks if b.modular else [])}
    d.keyed(old_racks, new_racks, "others", lambda key, old, new: d.attributes(key, old, new, _RACK, "others", " "))
    old_query = a.modular.query if a.modular else None
    new_query = b.modular.query if b.modular else None
    if not same(old_query, new_query):
        d.attributes("Query", old_query, new_query, _QUERY, "others", " ")


def _entries_by_keyword(entries: list[GenericEntry]) -> dict[str, list]:
    """Generic entries by keyword; a repeated keyword gets ``#2``, ``#3`` ..."""
    out: dict[str, list] = {}
    for entry in entries:
        key = entry.keyword
        count = sum(1 for k in out if k == key or k.startswith(f"{key}#"))
        out[key if not count else f"{key}#{count + 1}"] = entry.values
    return out


def _generic(d: _Differ, a: Device, b: Device) -> None:
    for section in dict.fromkeys([*a.extra_entries, *b.extra_entries]):
        _entries(d, section, a.extra_entries.get(section, []), b.extra_entries.get(section, []))
    old_sections, new_sections = _sections_by_name(a.other_sections), _sections_by_name(b.other_sections)
    for name in dict.fromkeys([*old_sections, *new_sections]):
        before, after = old_sections.get(name), new_sections.get(name)
        if before is None or after is None:
            kind = "added" if before is None else "removed"
            d.changes.append(Change(kind, f"[{name}]", category="others"))
        else:
            _entries(d, name, before.entries, after.entries)


#: The category of the entries later editions add to a 2003 section; those of other sections are "others".
_SECTION_CATEGORIES = {"File": "identity", "Device": "identity", "ParamClass": "params", "Groups": "params",
                       "Assembly": "assemblies", "Connection Manager": "connections"}


def _entries(d: _Differ, section: str, before: list[GenericEntry], after: list[GenericEntry]) -> None:
    """The entries of a section that the 2003 model does not hold: those the cip_tables define by the
    values of their types (``0x1`` is ``1``), field by field; the others as written. AssemExaN are
    compared as assemblies (:func:`_newer`)."""
    old, new = _entries_by_keyword(before), _entries_by_keyword(after)
    category = _SECTION_CATEGORIES.get(section, "others")
    for keyword in dict.fromkeys([*old, *new]):
        spec = cip_tables.entry_spec(section, keyword.partition("#")[0])
        if spec is None or not modelled(section, keyword.partition("#")[0]):
            d.value(f"[{section}] {keyword}", old.get(keyword), new.get(keyword), category)
        elif spec.keyword not in ASSEMBLY_FAMILIES:
            _typed_entry(d, f"[{section}] {keyword}", spec, old.get(keyword), new.get(keyword), category)


def _typed_entry(d: _Differ, what: str, spec: tables.EntrySpec, old: list | None, new: list | None,
                 category: str) -> None:
    if old is None or new is None:
        if new is not None:
            d.changes.append(Change("added", what, None, display(_typed_values(spec, new)), category))
        elif old is not None:
            d.changes.append(Change("removed", what, display(_typed_values(spec, old)), None, category))
    elif spec.keyword == "IconContents":
        old_icon, new_icon = _icon_text(old), _icon_text(new)
        if old_icon != new_icon:
            d.changes.append(Change("changed", what, old_icon, new_icon, category))
    elif spec.repeating or len(spec.fields) == 1:
        d.value(what, _typed_values(spec, old), _typed_values(spec, new), category, spec.fields[0].alternatives[0])
    else:
        before, after = _typed_values(spec, old), _typed_values(spec, new)
        for index, field_spec in enumerate(spec.fields):
            d.value(f"{what} {field_spec.name}", _at(before, index), _at(after, index), category,
                    field_spec.alternatives[0])


def _typed_values(spec: tables.EntrySpec, values: list) -> list:
    """Each field by its FieldSpec's type (its one reading when it breaks a notation rule); a value that
    fits none stays as written (so a change still shows)."""
    out = []
    for index, value in enumerate(values):
        field_spec = spec.field_at(index + 1)
        typed, problem = reading(value, field_spec)
        as_written = field_spec is None or (problem is not None and typed is None)
        out.append(value if as_written else typed)
    return out


def _at(values: list, index: int):
    return values[index] if index < len(values) else None


def _icon_text(values: list) -> str | None:
    """An icon by what its bytes are: equal bytes are the same icon however the base64 is split."""
    text = values[0] if values else None
    if not isinstance(text, String):
        return display(text)
    icon = decode_icon(text.text)
    if icon.data is None:
        return f"{icon.kind}: {text.text}"
    return f"{icon.kind.upper()}, {len(icon.data)} bytes, sha256 {hashlib.sha256(icon.data).hexdigest()[:16]}"


def _sections_by_name(sections: list[GenericSection]) -> dict[str, GenericSection]:
    out: dict[str, GenericSection] = {}
    for section in sections:
        name = section.name
        count = sum(1 for k in out if k == name or k.startswith(f"{name}#"))
        out[name if not count else f"{name}#{count + 1}"] = section
    return out


def format_text(changes: list[Change]) -> str:
    """Changes grouped by category (identity, params, assemblies, connections, others)."""
    lines = []
    for category, group in iter_categories(changes):
        lines.append(f"{category}:")
        lines.extend(f"  {change.format()}" for change in group)
    return "\n".join(lines)


def iter_categories(changes: list[Change]) -> Iterator[tuple[str, list[Change]]]:
    """(category, changes) for each category that has changes, in :data:`CATEGORIES` order."""
    for category in CATEGORIES:
        group = [c for c in changes if c.category == category]
        if group:
            yield category, group


__all__ = ["CATEGORIES", "Change", "comparable", "diff", "display", "format_text", "iter_categories", "same"]
