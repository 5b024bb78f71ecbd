"""Syntax model -> semantic model: typed values, references resolved.

Driven by :mod:`edsconv.spec_tables`: the type of every field comes from its
FieldSpec, so converting a field is one generic step; the per-section code only
says which typed attribute a field lands in. Conversion problems become
diagnostics on the field; the structural checks live in :mod:`edsconv.checks`.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Callable, Iterator
from dataclasses import dataclass, replace
from typing import Any

from edsconv import spec_tables as tables
from edsconv.diagnostics import Diagnostic, Severity, rule
from edsconv.eds.syntax import EdsFile, Entry, Field, Group, Scalar, Section, String, Value, ValueKind, plain_fields
from edsconv.limits import MAX_DIGITS, TOO_MANY_DIGITS, cut, shown
from edsconv.model import (
    MODULE,
    MODULE_MEMBER_LIST,
    SINGLE_ENTRY_ATTRIBUTES,
    Assembly,
    AssemblyMember,
    Classification,
    CommentNote,
    Connection,
    ConnectionEndpoint,
    Device,
    GenericEntry,
    GenericSection,
    Modular,
    ParamClass,
    Parameter,
    ParameterGroup,
    Port,
    Query,
    Rack,
    Reference,
    Unreadable,
)
from edsconv.model.cip_build import attach
from edsconv.model.device import PARAMETER_FIELD_ATTRIBUTES
from edsconv.model.memo import MISSING, EntryMemo, Kind
from edsconv.model.values import OUT_OF_RANGE, WRONG_KIND, ValueNote, ValueProblem, convert, converter_of, to_path

OBSOLETE_DATA_TYPE = rule(
    "EDS112", Severity.WARNING, "C.4.1.4.6", "A parameter names its data type by an obsolete Table C.16 identifier",
    explanation="""
        A parameter names its data type with an obsolete Table C.16 identifier (`2` for
        UINT) instead of the CIP code (`0xC7`). The type is understood.
    """,
    bad='`Param1 = 0,,,0x0000, 2, 2, "Speed", "", "", 0, 100, 0;`',
    good='`Param1 = 0,,,0x0000, 0xC7, 2, "Speed", "", "", 0, 100, 0;`',
)
UNKNOWN_DATA_TYPE = rule(
    "EDS113", Severity.ERROR, "C.4.1.4.6", "A parameter's data type code is not a CIP data type",
    explanation="""
        A parameter's data type code is neither a CIP data type code nor an obsolete
        identifier; its minimum, maximum and default cannot be interpreted.
    """,
    bad='`Param1 = 0,,,0x0000, 0xEE, 2, "Speed", "", "", 0, 100, 0;`',
    good='`Param1 = 0,,,0x0000, 0xC7, 2, "Speed", "", "", 0, 100, 0;`',
)

_REFERENCE_KINDS = ("ParamRef", "ProxyParamRef", "AssemRef", "ProxyAssemRef")


def _kind_pattern(kind: str) -> re.Pattern[str]:
    pattern = tables.FIELD_VALUE_KINDS[kind]
    if pattern is None:
        raise KeyError(f"{kind} has no lexical form")
    return re.compile(pattern)


_REFERENCE = {kind: _kind_pattern(kind) for kind in _REFERENCE_KINDS}
_MEMBER_KEYWORD = _kind_pattern("MemberKeyword")


@dataclass(frozen=True, slots=True)
class _Plan:
    """How to read a field of a FieldSpec type such as ``UDINT|ParamRef|ProxyParamRef``."""

    references: tuple[re.Pattern[str], ...]
    newer_assembly: bool
    member_keyword: bool
    path: bool
    #: the value type tried last (None: the field holds only references or keywords)
    data_type: str | None
    names: str
    #: a bare word may be a reference or a keyword (else only a proxy's Module words are read as words)
    words: bool
    #: kept as written (ParamDataType, Integer, PortSpecific: the data type is not known here)
    kept: bool
    #: values.convert of ``data_type``, chosen once (None: no converter, convert says so)
    converter: Callable[[Value], Any] | None


def _converter(data_type: str | None) -> Callable[[Value], Any] | None:
    try:
        return converter_of(data_type) if data_type is not None else None
    except KeyError:
        return None


@functools.cache
def _plan(type_name: str) -> _Plan:
    kinds = type_name.split("|")
    data_types = [k for k in kinds if k not in _REFERENCE and k not in ("MemberKeyword", "Empty", "EPATH")]
    names = " or ".join(kind.removesuffix("Ref") + "N" if kind in _REFERENCE else kind for kind in kinds)
    references = tuple(_REFERENCE[k] for k in kinds if k in _REFERENCE)
    data_type = data_types[0] if data_types else None
    kept = data_type in ("ParamDataType", "Integer", "PortSpecific")
    return _Plan(references, "AssemRef" in kinds, "MemberKeyword" in kinds, "EPATH" in kinds, data_type, names,
                 bool(references) or "AssemRef" in kinds or "MemberKeyword" in kinds, kept,
                 None if kept else _converter(data_type))


#: FieldSpec types whose fields are kept as written (:func:`plain`) by :meth:`ModelBuilder.fields`
_KEPT_AS_WRITTEN = frozenset({"Empty", "ParamDataType", "Integer", "PortSpecific"})


@functools.lru_cache(maxsize=1024)
def _field_types(spec: tables.EntrySpec, count: int) -> tuple[str | None, ...]:
    """The type each of the first ``count`` fields of a ``spec`` entry is read as; None: kept as written.

    Resolved once per entry family and length, not once per field (``field_at`` follows repeating tails).
    """
    types = []
    for position in range(1, count + 1):
        field_spec = spec.field_at(position)
        types.append(None if field_spec is None or field_spec.eds_type in _KEPT_AS_WRITTEN else field_spec.eds_type)
    return tuple(types)


def plain(value: Value | None):
    """A syntax value as plain data: None, a string's text, a scalar's spelling, a list."""
    if value is None:
        return None
    if isinstance(value, Group):
        return [plain(f.value) for f in value.fields]
    if isinstance(value, String):
        return value.text
    return value.raw


def as_written(value: Value | None):
    """A syntax value without positions or comments: Scalar, String, None, or a list for a group."""
    if isinstance(value, Group):
        return [as_written(f.value) for f in value.fields]
    return value


# Table C.17: these fields are read by the parameter's data type, once that is known
_TYPED_BY_DATA_TYPE = ("minimum", "maximum", "default")
#: (field index, attribute) of those fields
_TYPED_PARAMETER_FIELDS = tuple((index, attribute) for index, attribute in enumerate(PARAMETER_FIELD_ATTRIBUTES)
                                if attribute in _TYPED_BY_DATA_TYPE)
#: (field index, on the Scaling record, attribute) of the other ParamN fields (split once)
_PARAMETER_SETTERS = tuple((index, bool(attribute.partition(".")[1]), attribute.rpartition(".")[2])
                           for index, attribute in enumerate(PARAMETER_FIELD_ATTRIBUTES)
                           if attribute and attribute not in _TYPED_BY_DATA_TYPE)


def _documentation_null(entry: Entry, field: Field) -> bool:
    """A Proxied entry's null string ``""`` in a field that is not a string: the field is not described.
    A Proxied field counts only where the adapter's Proxy entry says Module, and is documentation
    elsewhere (C.4.1.5.3); Figure C.16 writes ``""`` for the sizes and formats its ProxiedConnect leaves
    to the adapter, so it is read as an empty field, not as a value of the wrong kind."""
    value = field.value
    return entry.keyword.startswith("Proxied") and isinstance(value, String) and value.parts in (('""',),)


@dataclass(slots=True)
class _Made:
    """A record made from one entry, and what making it reported."""

    record: Any
    diagnostics: list[Diagnostic]
    unreadable: list[Unreadable]
    erroneous: list[tuple[tuple[str, str, int], str]]

    def moved(self, first_line: int, delta: int) -> _Made:
        """This record's diagnostics after the lines from ``first_line`` on moved ``delta`` lines."""
        if not self.diagnostics:
            return self
        return replace(self, diagnostics=[d.moved(first_line, delta) for d in self.diagnostics])


#: The record made from an entry, and what making it reported (:meth:`ModelBuilder.record`)
RECORD = Kind("record", _Made.moved)
#: The notes made of an entry's comments (:meth:`ModelBuilder.collect_comments`)
COMMENT_NOTES = Kind("comments")


class ModelBuilder:
    def __init__(self, eds: EdsFile, memo: EntryMemo | None = None, section_of: dict[int, str] | None = None) -> None:
        self.eds = eds
        self.device = Device(eds=eds)
        self.diagnostics = self.device.diagnostics
        self.enums: list[tuple[str, Entry]] = []
        self.size_adders: list[Entry] = []
        #: the section of each entry this builder makes records of, by the entry's identity
        self.section_of = section_of if section_of is not None else \
            {id(entry): section.name for section in eds.sections for entry in section.entries}
        self.memo = memo
        #: the parameters the memo held, whose enum and size adder are those of an earlier build
        self.reused_parameters: list[Parameter] = []
        #: the erroneous values of the record being made for the memo
        self.erroneous_made: list[tuple[tuple[str, str, int], str]] | None = None

    def record(self, entry: Entry, make: Callable[[], Any]) -> Any:
        """``make()``, or the record the memo holds for this entry with what making it reported."""
        if self.memo is None:
            return make()
        section = self.section_of[id(entry)]
        made = self.memo.get(RECORD, entry, section)
        if made is MISSING:
            diagnostics, unreadable = len(self.diagnostics), len(self.device.unreadable)
            self.erroneous_made = []
            record = make()
            made = _Made(record, self.diagnostics[diagnostics:], self.device.unreadable[unreadable:],
                         self.erroneous_made)
            self.erroneous_made = None
            self.memo.put(RECORD, entry, section, made)
        else:
            self.diagnostics += made.diagnostics
            self.device.unreadable += made.unreadable
            self.device.erroneous.update(made.erroneous)
            if isinstance(made.record, Parameter):  # attach_enums_and_adders sets these anew, from other entries
                self.reused_parameters.append(made.record)
        return made.record

    # --- diagnostics and field conversion --------------------------------------------
    def report(self, rule_, message: str, node, clause: str = "") -> None:
        self.diagnostics.append(Diagnostic.of(rule_, message, node.line, node.column, self.eds.path, clause=clause))

    def value(self, entry: Entry, index: int, type_name: str, *, proxy: bool = False) -> Any:
        """Field ``index`` (0-based) of ``entry`` converted to ``type_name``; None when
        empty or without a reading (then a diagnostic says why). A value that breaks a
        rule but has one reading is returned, and marked erroneous when the rule is an
        error (:attr:`Device.erroneous`)."""
        fields = entry.fields
        if index >= len(fields):
            return None
        field = fields[index]
        if field.value is None:
            return None
        return self.converted(entry, index, field, type_name, proxy)

    def converted(self, entry: Entry, index: int, field: Field, type_name: str, proxy: bool) -> Any:
        """:meth:`value` of a field that is not empty."""
        try:
            return self.convert(field.value, type_name, proxy, entry, index)  # type: ignore[arg-type]
        except ValueProblem as problem:
            if problem.rule is WRONG_KIND and _documentation_null(entry, field):
                return None
            if not problem.reported:
                self.report(problem.rule, f"{entry.keyword} field {index + 1}: {problem.message}", field,
                            problem.clause)
            if not isinstance(problem, ValueNote):
                self.device.unreadable.append(Unreadable(self.section_of[id(entry)], entry.keyword, index,
                                                         spelling(field.value) if field.value is not None else ""))
                return None
            if problem.rule.severity is Severity.ERROR:
                key = (self.section_of[id(entry)], entry.keyword, index)
                self.device.erroneous[key] = problem.rule.code
                if self.erroneous_made is not None:
                    self.erroneous_made.append((key, problem.rule.code))
            return problem.value

    def convert(self, value: Value, type_name: str, proxy: bool, entry: Entry, index: int) -> Any:
        plan = _plan(type_name)
        if (plan.words or proxy) and isinstance(value, Scalar) and value.kind is ValueKind.WORD:
            raw = value.raw
            if proxy and raw in (MODULE, MODULE_MEMBER_LIST):
                return raw
            found = Reference.parse(raw, entry, index)
            # AssemExaN (no bit) stands where an AssemN may (see spec_tables.REFERENCE_RE)
            if found is not None and (any(pattern.fullmatch(found.keyword) for pattern in plan.references) or (
                    plan.newer_assembly and found.family == "AssemExa" and found.bit is None)):
                return found
            if plan.member_keyword and _MEMBER_KEYWORD.fullmatch(raw):
                return raw
        if plan.path and isinstance(value, String):
            return to_path(value, allow_references=True)
        if plan.data_type is None:
            raise ValueProblem(WRONG_KIND, f"expected {plan.names}, found {shown(plain(value))}")
        if plan.kept:
            return plain(value)
        if plan.converter is not None:
            return plan.converter(value)
        return convert(value, plan.data_type)

    def fields(self, entry: Entry, spec: tables.EntrySpec, *, proxy: bool = False) -> list[Any]:
        """Every field of a fixed-layout entry converted by its FieldSpec."""
        values: list[Any] = []
        fields = entry.fields
        for index, type_name in enumerate(_field_types(spec, len(fields))):
            field = fields[index]
            if type_name is None:
                values.append(plain(field.value))
            elif field.value is None:
                values.append(None)
            else:
                values.append(self.converted(entry, index, field, type_name, proxy))
        return values

    # --- sections --------------------------------------------------------------------
    def build(self) -> Device:
        for section in self.eds.sections:
            self.section(section)
        self.collect_comments()
        self.collect_unparsed()
        self.attach_enums_and_adders()
        attach(self.device)  # the typed view of the content beyond the 2003 text (model.cip)
        resolve_references(self.device)
        return self.device

    def section(self, section: Section) -> None:
        """What the entries of ``section`` make: records, attributes, entries kept as written."""
        spec = tables.SECTIONS.get(section.name)
        if spec is None:
            self.device.other_sections.append(GenericSection(
                section.name, [self.generic(e) for e in section.entries], section))
            return
        handler = getattr(self, _HANDLERS[spec.name])
        for entry in section.entries:
            entry_spec = tables.entry_spec(spec.name, entry.keyword)
            if entry_spec is None:
                self.device.extra_entries.setdefault(spec.name, []).append(self.generic(entry))
            else:
                self.check_keyword_number(entry)
                handler(entry, entry_spec)

    def check_keyword_number(self, entry: Entry) -> None:
        """EDS102 for the N of ``ParamN`` (and every numbered keyword) past the digits edsconv reads: no
        instance number has more than 10 digits, and Python refuses to convert more than 4,300."""
        family, number = tables.split_numbered(entry.keyword)
        if number == TOO_MANY_DIGITS:
            self.report(OUT_OF_RANGE, f"{cut(entry.keyword)}: the number after {family} has more than "
                        f"{MAX_DIGITS} digits, outside every instance number's range", entry)

    def collect_comments(self) -> None:
        notes = self.device.comments
        memo = self.memo
        for section in self.eds.sections:
            name = section.name
            notes.extend(CommentNote(name, None, None, c.text, True) for c in section.leading_comments)
            notes.extend(CommentNote(name, None, None, c.text) for c in section.comments)
            for entry in section.entries:
                if memo is None:
                    notes += _entry_notes(name, entry)
                    continue
                made = memo.get(COMMENT_NOTES, entry, name)
                if made is MISSING:
                    made = _entry_notes(name, entry)
                    memo.put(COMMENT_NOTES, entry, name, made)
                notes += made

    def collect_unparsed(self) -> None:
        """The statements the reader could not parse (:class:`Unreadable`, kept as written)."""
        for section in self.eds.sections:
            for index, item in section.unparsed:
                before = section.entries[index].keyword if index < len(section.entries) else None
                self.device.unreadable.append(Unreadable(section.name, None, None, item.text, before,
                                                         tuple(c.text for c in item.comments)))

    @staticmethod
    def generic(entry: Entry) -> GenericEntry:
        return GenericEntry(entry.keyword, [as_written(f.value) for f in entry.fields], entry)

    def single(self, entry: Entry, spec: tables.EntrySpec) -> Any:
        return self.value(entry, 0, spec.fields[0].eds_type)

    def single_entry(self, entry: Entry, spec: tables.EntrySpec) -> None:
        """An entry of [File], [Device] or [ParamClass]: one field into its attribute."""
        section = spec.section
        if section == "File":
            record: Any = self.device.file
        elif section == "Device":
            record = self.device.identity
        else:
            record = self.device.param_class = self.device.param_class or ParamClass()
        setattr(record, SINGLE_ENTRY_ATTRIBUTES[section][spec.keyword], self.single(entry, spec))

    def classification(self, entry: Entry, spec: tables.EntrySpec) -> None:
        values = [plain(f.value) for f in entry.fields]
        number = tables.instance_number(entry.keyword)
        self.device.classifications.append(Classification(
            number, self.value(entry, 0, "Keyword"), tuple(v for v in values[1:] if v is not None), entry))

    # --- [Params] ----------------------------------------------------------------------
    def params_entry(self, entry: Entry, spec: tables.EntrySpec) -> None:
        if not self.paired_entry(entry, spec) and entry.keyword not in self.device.parameters:
            self.device.parameters[entry.keyword] = self.record(entry, lambda: self.parameter(entry, spec))

    def paired_entry(self, entry: Entry, spec: tables.EntrySpec) -> bool:
        """Keep an entry paired with a parameter by number (EnumN, ProxyParamSizeAdderN) for
        :meth:`attach_enums_and_adders`; False for any other entry."""
        if spec.keyword in tables.ENUM_FAMILIES.values():
            self.enums.append((spec.pairs_with or "", entry))
        elif spec.keyword == "ProxyParamSizeAdder":
            self.size_adders.append(entry)
        else:
            return False
        return True

    def parameter(self, entry: Entry, spec: tables.EntrySpec) -> Parameter:
        proxy = spec.keyword == "ProxyParam"
        v = self.fields(entry, spec, proxy=proxy)
        v += [None] * (len(tables.PARAM_FIELDS) - len(v))
        parameter = Parameter(entry.keyword, spec.keyword, tables.instance_number(entry.keyword), entry=entry)
        scaling = parameter.scaling
        for index, on_scaling, name in _PARAMETER_SETTERS:
            setattr(scaling if on_scaling else parameter, name, v[index])
        parameter.data_type = self.data_type(entry, parameter.data_type_code)
        for index, attribute in _TYPED_PARAMETER_FIELDS:
            setattr(parameter, attribute, self.param_value(entry, index, parameter, attribute, proxy))
        return parameter

    def data_type(self, entry: Entry, code: Any) -> tables.DataType | None:
        if not isinstance(code, int):
            return None  # empty, Module, or a structured type given as a path
        if code in tables.DATA_TYPES_BY_CODE:
            return tables.DATA_TYPES_BY_CODE[code]
        field = entry.fields[4]
        if code in tables.OBSOLETE_DATA_TYPE_IDS:
            data_type = tables.OBSOLETE_DATA_TYPE_IDS[code]
            self.report(OBSOLETE_DATA_TYPE, f"{entry.keyword}: data type {field.raw} is the obsolete identifier of "
                        f"{data_type.name}; write 0x{data_type.code:02X}", field)
            return data_type
        self.report(UNKNOWN_DATA_TYPE, f"{entry.keyword}: data type {field.raw} is not a CIP data type code", field)
        return None

    def param_value(self, entry: Entry, index: int, parameter: Parameter, attribute: str, proxy: bool) -> Any:
        """Minimum, maximum or default: typed by the parameter's data type (Table C.17)."""
        fields = entry.fields
        if index >= len(fields) or fields[index].value is None:
            return None
        value = fields[index].value
        if proxy and isinstance(value, Scalar) and value.raw == MODULE:
            return MODULE
        type_name = parameter.value_type(attribute)
        return plain(value) if type_name == "plain" else self.value(entry, index, type_name)

    def attach_enums_and_adders(self) -> None:
        """Each parameter's enum (its first EnumN) and size adder (its last ProxyParamSizeAdderN).

        A parameter an earlier build made (the memo's) keeps the ones that build gave it until they are
        set here, never None meanwhile: the language server answers from an analysis that shares it
        while this one is made (:func:`edsconv.model.rebuild.with_entry_rebuilt`)."""
        parameters = self.device.parameters
        enums: dict[int, tuple[Parameter, dict[int, str]]] = {}
        for family, entry in self.enums:
            number = tables.instance_number(entry.keyword)
            parameter = parameters.get(f"{family}{number}")
            type_name = parameter.enum_key_type if parameter is not None else "LINT"
            enum: dict[int, str] = {}
            for index in range(0, len(entry.fields) - 1, 2):
                key = self.value(entry, index, type_name)
                text = self.value(entry, index + 1, "EDS_Char_Array")
                if key is not None:
                    enum[key] = text
            if parameter is not None:
                enums.setdefault(id(parameter), (parameter, enum))
        adders: dict[int, tuple[Parameter, tuple]] = {}
        for entry in self.size_adders:
            parameter = parameters.get(f"ProxyParam{tables.instance_number(entry.keyword)}")
            if parameter is not None:
                adders[id(parameter)] = (parameter, tuple(self.param_value(entry, i, parameter, a, False)
                                                          for i, a in enumerate(("minimum", "maximum", "default"))))
        for parameter in self.reused_parameters:
            if parameter.enum is not None and id(parameter) not in enums:
                parameter.enum = None
            if parameter.size_adder is not None and id(parameter) not in adders:
                parameter.size_adder = None
        for parameter, enum in enums.values():
            parameter.enum = enum
        for parameter, adder in adders.values():
            parameter.size_adder = adder

    # --- [Groups] ------------------------------------------------------------------------
    def group(self, entry: Entry, spec: tables.EntrySpec) -> None:
        members = []
        for index in range(2, len(entry.fields)):
            number = self.value(entry, index, "UINT")
            if number is not None:
                members.append(Reference(f"Param{number}", "Param", number, entry=entry, field_index=index))
        self.device.groups.append(ParameterGroup(
            tables.instance_number(entry.keyword), self.value(entry, 0, "EDS_Char_Array"),
            self.value(entry, 1, "UINT"), members, entry))

    # --- [Assembly] ----------------------------------------------------------------------
    def assembly_entry(self, entry: Entry, spec: tables.EntrySpec) -> None:
        if spec.keyword == ASSEMBLY_REVISION:
            self.device.assembly_revision = self.single(entry, spec)
        elif entry.keyword not in self.device.assemblies:
            self.device.assemblies[entry.keyword] = self.record(entry, lambda: self.assembly(entry, spec))

    def assembly(self, entry: Entry, spec: tables.EntrySpec) -> Assembly:
        proxy = spec.keyword == "ProxyAssem"
        assembly = Assembly(entry.keyword, spec.keyword, tables.instance_number(entry.keyword), entry=entry)
        assembly.name = self.value(entry, 0, "EDS_Char_Array", proxy=proxy)
        assembly.path = self.value(entry, 1, "EPATH", proxy=proxy)
        assembly.size = self.value(entry, 2, "UINT", proxy=proxy)
        assembly.descriptor = self.value(entry, 3, "WORD", proxy=proxy)
        member_type = spec.fields[7].eds_type
        index = 6
        while index < len(entry.fields):
            first = entry.fields[index].value
            if proxy and isinstance(first, Scalar) and first.raw == MODULE_MEMBER_LIST:
                assembly.module_member_list = True
                index += 1
                continue
            second = entry.fields[index + 1].value if index + 1 < len(entry.fields) else None
            if proxy and isinstance(second, Scalar) and second.raw == MODULE_MEMBER_LIST:
                assembly.module_member_list = True  # ",ModuleMemberList" (Figure C.15): the pair is the module's
                index += 2
                continue
            size = self.value(entry, index, "UINT")
            target = entry.fields[index + 1].value if index + 1 < len(entry.fields) else None
            if isinstance(target, String) and target.text == "":
                member_reference = None  # "" is a pad, like an empty field
            else:
                member_reference = self.value(entry, index + 1, member_type, proxy=proxy)
            assembly.members.append(AssemblyMember(size, member_reference, index))
            index += 2
        return assembly

    # --- [Connection Manager] -------------------------------------------------------------
    def connection_entry(self, entry: Entry, spec: tables.EntrySpec) -> None:
        if entry.keyword not in self.device.connections:
            self.device.connections[entry.keyword] = self.record(entry, lambda: self.connection(entry, spec))

    def connection(self, entry: Entry, spec: tables.EntrySpec) -> Connection:
        v = self.fields(entry, spec, proxy=spec.keyword == "ProxyConnect")
        v += [None] * (len(tables.CONNECTION_FIELDS) - len(v))
        return Connection(
            entry.keyword, spec.keyword, tables.instance_number(entry.keyword),
            trigger_transport=v[0], parameters=v[1],
            o_to_t=ConnectionEndpoint(*v[2:5]), t_to_o=ConnectionEndpoint(*v[5:8]),
            config1=ConnectionEndpoint(None, *v[8:10]), config2=ConnectionEndpoint(None, *v[10:12]),
            name=v[12], help=v[13], path=v[14], entry=entry)

    # --- [Port] --------------------------------------------------------------------------
    def port(self, entry: Entry, spec: tables.EntrySpec) -> None:
        v = self.fields(entry, spec)
        v += [None] * (4 - len(v))
        self.device.ports.append(Port(tables.instance_number(entry.keyword), v[0], v[1], v[2], v[3],
                                      tuple(v[6:]), entry))

    # --- [Modular] -----------------------------------------------------------------------
    def modular_entry(self, entry: Entry, spec: tables.EntrySpec) -> None:
        modular = self.device.modular = self.device.modular or Modular()
        keyword = spec.keyword
        if keyword == "Rack":
            v = self.fields(entry, spec)
            v += [None] * (8 - len(v))
            modular.racks.append(Rack(tables.instance_number(entry.keyword), v[0], v[1], v[2], v[3], v[4],
                                      tuple(s for s in v[8:] if s is not None), entry))
        elif keyword == "Query":
            v = self.fields(entry, spec)
            v += [None] * (4 - len(v))
            modular.query = Query(*v[:4])
        else:
            setattr(modular, SINGLE_ENTRY_ATTRIBUTES["Modular"][keyword], self.single(entry, spec))


def _entry_notes(section: str, entry: Entry) -> list[CommentNote]:
    """The comments of an entry and of its fields, as notes."""
    keyword = entry.keyword
    notes = [CommentNote(section, keyword, None, c.text, True) for c in entry.leading_comments]
    notes += [CommentNote(section, keyword, None, c.text) for c in entry.comments]
    fields = entry.fields
    if plain_fields(fields):
        return notes
    for index, item in enumerate(fields):
        if item.has_comments:
            notes += [CommentNote(section, keyword, index, c.text) for c in item.comments]
        if item.value.__class__ is Group:  # comments inside a group go with the group's field
            notes += [CommentNote(section, keyword, index, c.text)
                      for inner in Entry("", item.value.fields).walk_fields() for c in inner.comments]
    return notes


def iter_references(device: Device) -> Iterator[Reference]:
    """Every reference of the model: group members, assembly members, connection
    RPI/size/format fields, the chassis SlotDisplayRule."""
    for group in device.groups:
        yield from group.members
    for assembly in device.assemblies.values():
        for member in assembly.members:
            if isinstance(member.reference, Reference):
                yield member.reference
    for connection in device.connections.values():
        for endpoint in (connection.o_to_t, connection.t_to_o, connection.config1, connection.config2):
            for value in (endpoint.rpi, endpoint.size, endpoint.format):
                if isinstance(value, Reference):
                    yield value
    if device.modular is not None and isinstance(device.modular.slot_display_rule, Reference):
        yield device.modular.slot_display_rule


def spelling(value: Value) -> str:
    """A field's value as the file writes it (a group's fields joined by commas)."""
    if isinstance(value, Group):
        return "{" + ",".join("" if f.value is None else spelling(f.value) for f in value.fields) + "}"
    return value.raw


def resolve_references(device: Device) -> None:
    """Point every reference of the model at the record it names."""
    for ref in iter_references(device):
        ref.target = device.resolve(ref.keyword)


#: The builder's method that reads the entries of each 2003 section
_HANDLERS = {
    "File": "single_entry", "Device": "single_entry", "Device Classification": "classification",
    "ParamClass": "single_entry", "Params": "params_entry", "Groups": "group", "Assembly": "assembly_entry",
    "Connection Manager": "connection_entry", "Port": "port", "Modular": "modular_entry",
}
#: The entry of [Assembly] that sets the class's revision rather than making a record
ASSEMBLY_REVISION = "Revision"
#: The sections each of whose entries (the record families) makes one record of a table of the device
RECORD_TABLES = {"Params": "parameters", "Assembly": "assemblies", "Connection Manager": "connections"}


def build(eds: EdsFile, memo: EntryMemo | None = None) -> Device:
    """The semantic model of a parsed EDS; conversion problems are in ``device.diagnostics``.

    With a ``memo``, the parameters, assemblies and connections made from entries it knows are
    taken from it (:mod:`edsconv.model.memo`). A record depends on its entry's text and section
    only: what other entries decide (a parameter's enum and size adder, the targets of
    references) is set anew.
    """
    return ModelBuilder(eds, memo).build()
