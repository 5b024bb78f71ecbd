"""The merge of C.4.1.5.3: an adapter EDS and module EDS files -> combined entries.

An adapter (the proxying device, e.g. an EtherNet/IP adapter in slot 0 of a
rack) describes what it carries for a module with ``ProxyParamN``,
``ProxyAssemN`` and ``ProxyConnectN``; the module (the proxied device, without
CIP of its own) describes its side with ``ProxiedParamN``, ``ProxiedAssemN``
and ``ProxiedConnectN``. This module combines them, on the syntax level: the
result is syntax :class:`~edsconv.eds.syntax.Entry` objects whose fields are
copies of the input fields, spelled as written.

**Which files belong together** (C.4.1.5.3.1: "when both EDS files specify a
matching Rack entry"). Both the adapter and the module are modules of a
chassis (Figures C.12 - C.14), so each lists, in its ``[Modular]`` section, a
``RackN`` entry per chassis it fits (Table C.26). A Rack entry of the adapter
and one of the module *match* when their electronic keys are equal: Vendor ID,
Product Type, Product Code and Major Revision, compared as numbers (``0xFFFF``
equals ``65535``). The Minor Revision (field 5) is not compared: C.4.1.4.3 says
changes in minor revisions "shall not be used by a configuration tool to match
a device with an EDS". The numbers N of
the two RackN keywords need not be equal, and the Legal Slot fields are not
compared (the adapter sits in slot 0, Figure C.14, the module in others,
Figures C.12 and C.13). One matching pair is enough; a module with none is not
merged (EDS401).

**How entries combine.** ProxyXN is paired with ProxiedXN of the same N. Each
field of the Proxy entry is used as written unless it is the keyword
``Module``; then the Proxied entry's field at the same position is used. In a
ProxyAssem, ``ModuleMemberList`` in place of a Member Size / Member Reference
pair (Figure C.15 writes it as the Reference with an empty Size; a lone
``ModuleMemberList`` at the Size position is read the same) stands for all the
member pairs of the ProxiedAssem. ``ProxyParamSizeAdderN`` values are added to
the combined Minimum, Maximum and Default values of ParamN, with the data type
of the combined entry. The enumeration of a combined parameter is
``ProxyEnumN`` when the adapter has one, else the module's ``ProxiedEnumN``.

**Output keywords.** C.4.1.5.3 says the combination "constitute[s] the same
field value information that exists in a single Param [Assem, Connection]
entry", so the combined entries are named ``ParamN``, ``EnumN``, ``AssemN``
and ``ConnectionN`` with the number N of the Proxy entry, and stand in
``[Params]``, ``[Assembly]`` and ``[Connection Manager]``. Each carries a
leading comment naming the entries it was made of. References inside fields
are kept as spelled: a ``ProxyParam1`` in a combined connection means the
combined Param1. The output is a view of the module as the adapter carries
it, not text to paste into the adapter: the adapter's own ``Param1`` (Figure
C.15 has one) and the combined ``Param1`` share a number.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field, replace

from edsconv import spec_tables as tables
from edsconv.checks.entity_rules import MODULE_IN_MEMBER, PROXY_CONNECT_NAME_MODULE
from edsconv.diagnostics import Diagnostic, Rule, Severity, has_errors, rule
from edsconv.eds.syntax import Comment, EdsFile, Entry, Field, Group, Scalar, Section, Value, ValueKind
from edsconv.model import MODULE, MODULE_MEMBER_LIST

_M = "C.4.1.5.3"
NO_MATCHING_RACK = rule(
    "EDS401", Severity.ERROR, "C.4.1.5.3.1",
    "An adapter and a module EDS share no matching Rack entry, so they cannot be merged",
    explanation="""
        An adapter and a module EDS share no matching Rack entry, so they cannot be
        merged: no RackN of the module has the vendor, product type, product code and
        major revision of a RackN of the adapter (or the adapter has no Rack entry at
        all). The minor revision is not compared: C.4.1.4.3 forbids matching a device
        with an EDS by it.
    """,
    bad="adapter `Rack1 = 65535, 101, 1, 1, 1,,,, 0;`, module `Rack1 = 65535, 101, 9, 1, 1,,,, 1, 2;`",
    good="module `Rack1 = 65535, 101, 1, 1, 1,,,, 1, 2;`",
)
NO_PROXIED_ENTRY = rule(
    "EDS402", Severity.ERROR, _M,
    "A Proxy entry defers a field to the module (Module, ModuleMemberList) but the module has no Proxied entry of "
    "that number, or no field at that position",
    explanation="""
        A Proxy entry defers a field to the module (`Module`, or `ModuleMemberList` in
        a ProxyAssem) but the module has no Proxied entry of that number, or no field at
        that position. The combined entry is left out.
    """,
    bad='`ProxyParam1 = 0,,,0,2,2,"a","","",Module,1,0;` and the module has no `ProxiedParam1`.',
    good='the module has `ProxiedParam1 = ,,,,,,"a","","",0;`',
)
ORPHAN_SIZE_ADDER = rule(
    "EDS404", Severity.WARNING, "C.4.1.5.3.1", "A ProxyParamSizeAdderN has no ProxyParamN to add to",
    explanation="A ProxyParamSizeAdderN has no ProxyParamN to add to; it is not used.",
    bad="`ProxyParamSizeAdder3 = 4,4,4;` without `ProxyParam3`.",
    good="`ProxyParam3` exists.",
)
SIZE_ADDER_NOT_APPLIED = rule(
    "EDS405", Severity.WARNING, "C.4.1.5.3.1",
    "A ProxyParamSizeAdder value cannot be added: no value to add to, a value that is not a number of the parameter's"
    " data type, or a sum outside its range",
    explanation="""
        A ProxyParamSizeAdder value cannot be added: the combined Minimum, Maximum or
        Default it adds to is empty, a value is not a number of the parameter's data
        type, or the sum lies outside that type's range. The value is left as it was.
    """,
    bad="""
        `ProxyParam1 = 0,,,0,0xC6,1,"a","","",0,Module,0;`, module maximum `250`, `ProxyParamSizeAdder1 = 0,10,0;` (260
        is beyond USINT)
    """,
    good="`ProxyParamSizeAdder1 = 0,4,0;`",
)
BAD_MODULE_MEMBER_LIST = rule(
    "EDS406", Severity.ERROR, "C.4.1.5.3.2",
    "ModuleMemberList does not stand in place of a whole Member Size / Member Reference pair",
    explanation="""
        `ModuleMemberList` does not stand in place of a whole Member Size / Member
        Reference pair: the other field of its pair is not empty, or it stands in
        fields 1-6 of the ProxyAssem (Table C.20; Figure C.15 prints it at field 6,
        before the two reserved fields were counted). `edsconv lint` reports it in the
        adapter's file; `edsconv merge` reports it too and leaves the entry out of the
        combination, whose member pairs would otherwise be shifted.
    """,
    bad='`ProxyAssem1 = "a",,,,,,16,ModuleMemberList;`',
    good='`ProxyAssem1 = "a",,,,,,,ModuleMemberList;`',
)


#: (section, Proxy prefix, Proxied prefix, output prefix)
FAMILIES = (
    ("Params", "ProxyParam", "ProxiedParam", "Param"),
    ("Assembly", "ProxyAssem", "ProxiedAssem", "Assem"),
    ("Connection Manager", "ProxyConnect", "ProxiedConnect", "Connection"),
)
#: 0-based positions of Minimum, Maximum and Default in a Param entry (Table C.13).
PARAM_LIMIT_POSITIONS = (9, 10, 11)
PARAM_DATA_TYPE_POSITION = 4
#: Assem fields before the member pairs: name, path, size, descriptor and two
#: reserved fields (Table C.20); member pairs start at field 7.
ASSEM_HEADER_FIELDS = 6
#: 0-based position of the connection name string (Table C.22).
CONNECTION_NAME_POSITION = 12
#: Electronic key fields of a RackN entry (Table C.26) and their types.
RACK_KEY_TYPES = ("UINT", "UINT", "UINT", "USINT", "USINT")


@dataclass(slots=True)
class ModuleMerge:
    """The combined entries of the adapter with one module."""

    module: EdsFile
    #: (adapter RackN, module RackM) keyword pairs whose electronic keys are equal
    racks: list[tuple[str, str]]
    sections: list[Section] = field(default_factory=list)

    def eds(self) -> EdsFile:
        return EdsFile(sections=self.sections)


@dataclass(slots=True)
class MergeResult:
    adapter: EdsFile
    merges: list[ModuleMerge] = field(default_factory=list)
    diagnostics: list[Diagnostic] = field(default_factory=list)

    @property
    def has_errors(self) -> bool:
        return has_errors(self.diagnostics)

    def text(self, newline: str = "\n") -> str:
        """The combined entries as EDS text, one block per merged module."""
        from edsconv.eds.writer import write

        blocks = [write(item.eds(), newline) for item in self.merges if item.sections]
        return newline.join(blocks)


# --- helpers ---------------------------------------------------------------------------


def _is_word(item: Field | None, word: str) -> bool:
    return item is not None and isinstance(item.value, Scalar) and item.value.raw == word


def _empty(item: Field | None) -> bool:
    return item is None or item.value is None


def _copy_value(value: Value | None) -> Value | None:
    if isinstance(value, Group):
        return Group([_copy_field(item) for item in value.fields])
    return value  # Scalar and String are never changed in place


def _copy_field(item: Field, comments_of: Field | None = None) -> Field:
    """A fresh field (no source position) with ``item``'s value and the comments of ``comments_of``."""
    owner = comments_of or item
    return Field(_copy_value(item.value), [Comment(c.text) for c in owner.comments])


def _numbered(eds: EdsFile) -> dict[tuple[str, int], Entry]:
    """Numbered entries of every section by (prefix, number); the first of duplicates wins."""
    found: dict[tuple[str, int], Entry] = {}
    for section in eds.sections:
        for entry in section.entries:
            prefix, number = tables.split_numbered(entry.keyword)
            if number is not None:
                found.setdefault((prefix, number), entry)
    return found


def _name(eds: EdsFile) -> str:
    return eds.path or "<string>"


class _Reporter:
    def __init__(self) -> None:
        self.diagnostics: list[Diagnostic] = []

    def __call__(self, rule_: Rule, message: str, eds: EdsFile, node: Entry | Field | None = None) -> None:
        line, column = (node.line, node.column) if node is not None else (0, 0)
        self.diagnostics.append(Diagnostic.of(rule_, message, line, column, eds.path))


# --- Rack matching ---------------------------------------------------------------------


def rack_keys(eds: EdsFile) -> dict[str, tuple[int, ...]]:
    """RackN keyword -> electronic key (vendor, product type, product code, major, minor revision).

    Rack entries whose key fields are not numbers of their types are left out.
    """
    from edsconv.model.values import ValueProblem, to_integer

    keys: dict[str, tuple[int, ...]] = {}
    for section in eds.sections:
        if section.name != "Modular":
            continue
        for entry in section.entries:
            if tables.split_numbered(entry.keyword)[0] != "Rack" or len(entry.fields) < len(RACK_KEY_TYPES):
                continue
            try:
                key = tuple(to_integer(item.value, type_name)
                            for item, type_name in zip(entry.fields, RACK_KEY_TYPES, strict=False))
            except (ValueProblem, AttributeError, KeyError, TypeError):
                continue
            keys.setdefault(entry.keyword, key)
    return keys


#: The key fields two Rack entries are matched by: all but the Minor Revision (C.4.1.4.3).
MATCHED_KEY_FIELDS = 4


def matching_racks(adapter: EdsFile, module: EdsFile) -> list[tuple[str, str]]:
    """(adapter RackN, module RackM) pairs whose electronic keys are equal but for the minor revision."""
    module_keys = rack_keys(module)
    return [(a_keyword, m_keyword) for a_keyword, a_key in rack_keys(adapter).items()
            for m_keyword, m_key in module_keys.items()
            if a_key[:MATCHED_KEY_FIELDS] == m_key[:MATCHED_KEY_FIELDS]]


# --- combining -------------------------------------------------------------------------


class _Merger:
    def __init__(self, adapter: EdsFile, module: EdsFile, report: _Reporter) -> None:
        self.adapter, self.module, self.report = adapter, module, report
        self.proxy = _numbered(adapter)
        self.proxied = _numbered(module)

    def _source_comment(self, proxy: Entry, proxied: Entry | None) -> Comment:
        parts = f" {proxy.keyword} of {_name(self.adapter)}"
        if proxied is not None:
            parts += f" + {proxied.keyword} of {_name(self.module)}"
        return Comment(parts)

    def _deferred(self, proxy: Entry, proxied: Entry | None, position: int, word: str) -> Field | None:
        """The Proxied field at ``position`` for a ``Module`` field, or None (reported)."""
        item = proxy.fields[position]
        if proxied is None:
            _, number = tables.split_numbered(proxy.keyword)
            family = tables.split_numbered(proxy.keyword)[0].replace("Proxy", "Proxied")
            self.report(NO_PROXIED_ENTRY, f"{proxy.keyword} field {position + 1} is {word}, but "
                        f"{_name(self.module)} has no {family}{number}", self.adapter, item)
            return None
        if position >= len(proxied.fields):
            self.report(NO_PROXIED_ENTRY, f"{proxy.keyword} field {position + 1} is {word}, but "
                        f"{proxied.keyword} has only {len(proxied.fields)} fields", self.adapter, item)
            return None
        return _copy_field(proxied.fields[position], comments_of=item)

    def _plain(self, proxy: Entry, proxied: Entry | None, fields: Iterable[int]) -> list[Field] | None:
        """Fields at ``positions``: as written, or from the Proxied entry where ``Module``."""
        combined: list[Field] = []
        ok = True
        for position in fields:
            item = proxy.fields[position]
            if _is_word(item, MODULE):
                deferred = self._deferred(proxy, proxied, position, MODULE)
                if deferred is None:
                    ok = False
                else:
                    combined.append(deferred)
            else:
                combined.append(_copy_field(item))
        return combined if ok else None

    def _entry(self, keyword: str, fields: list[Field], proxy: Entry, proxied: Entry | None) -> Entry:
        return Entry(keyword, fields, leading_comments=[self._source_comment(proxy, proxied)])

    def merge(self) -> list[Section]:
        sections = []
        for section_name, proxy_prefix, proxied_prefix, out_prefix in FAMILIES:
            entries: list[Entry] = []
            for (prefix, number), proxy in sorted(self.proxy.items(), key=lambda kv: kv[0][1]):
                if prefix != proxy_prefix:
                    continue
                proxied = self.proxied.get((proxied_prefix, number))
                combine = getattr(self, f"_{out_prefix.lower()}")
                fields = combine(proxy, proxied)
                if fields is None:
                    continue
                entries.append(self._entry(f"{out_prefix}{number}", fields, proxy, proxied))
                if out_prefix == "Param":
                    entries.extend(self._enum(number))
            if entries:
                sections.append(Section(section_name, entries))
        for (prefix, number), adder in self.proxy.items():
            if prefix == "ProxyParamSizeAdder" and ("ProxyParam", number) not in self.proxy:
                self.report(ORPHAN_SIZE_ADDER, f"{adder.keyword} has no ProxyParam{number}; it is not used",
                            self.adapter, adder)
        return sections

    # Params

    def _param(self, proxy: Entry, proxied: Entry | None) -> list[Field] | None:
        fields = self._plain(proxy, proxied, range(len(proxy.fields)))
        if fields is None:
            return None
        adder = self.proxy.get(("ProxyParamSizeAdder", tables.instance_number(proxy.keyword)))
        if adder is not None:
            self._add_sizes(fields, adder)
        return fields

    def _enum(self, number: int) -> list[Entry]:
        for source, family in ((self.proxy, "ProxyEnum"), (self.proxied, "ProxiedEnum")):
            enum = source.get((family, number))
            if enum is not None:
                owner = _name(self.adapter if source is self.proxy else self.module)
                return [Entry(f"Enum{number}", [_copy_field(item) for item in enum.fields],
                              leading_comments=[Comment(f" {enum.keyword} of {owner}")])]
        return []

    def _add_sizes(self, fields: list[Field], adder: Entry) -> None:
        data_type = self._param_type(fields)
        for index, position in enumerate(PARAM_LIMIT_POSITIONS):
            if index >= len(adder.fields) or _empty(adder.fields[index]):
                continue
            addend = adder.fields[index]
            what = ("minimum", "maximum", "default")[index]
            if position >= len(fields) or _empty(fields[position]):
                self.report(SIZE_ADDER_NOT_APPLIED, f"{adder.keyword}: the combined {what} is empty; "
                            f"{addend.raw} is not added", self.adapter, addend)
                continue
            target = fields[position]
            summed = self._sum(target.value, addend.value, data_type)
            if isinstance(summed, str) and summed.startswith("!"):
                self.report(SIZE_ADDER_NOT_APPLIED, f"{adder.keyword}: {what} {target.raw} + {addend.raw}: "
                            f"{summed[1:]}", self.adapter, addend)
                continue
            fields[position] = Field(Scalar(summed), target.comments)

    def _param_type(self, fields: list[Field]) -> tables.DataType | None:
        from edsconv.model.values import ValueProblem, to_integer

        if len(fields) <= PARAM_DATA_TYPE_POSITION or _empty(fields[PARAM_DATA_TYPE_POSITION]):
            return None
        try:
            code = to_integer(fields[PARAM_DATA_TYPE_POSITION].value, "USINT")
        except ValueProblem:
            return None
        return tables.DATA_TYPES_BY_CODE.get(code) or tables.OBSOLETE_DATA_TYPE_IDS.get(code)

    @staticmethod
    def _sum(value: Value | None, addend: Value | None, data_type: tables.DataType | None) -> str:
        """The spelling of ``value + addend``, or ``"!reason"``."""
        from edsconv.model.values import ValueNote, ValueProblem, convert

        if data_type is None or data_type.kind not in ("unsigned", "signed", "bits", "real", "time", "bool"):
            return "!the parameter's data type is not a number type"
        numbers = []
        for item in (value, addend):
            if item is None:
                return "!an empty field"
            try:
                numbers.append(convert(item, data_type.name))
            except ValueNote as note:
                numbers.append(note.value)
            except ValueProblem as problem:
                return f"!{problem.message}"
        total = numbers[0] + numbers[1]
        if not data_type.in_range(total):
            return f"!the sum {total} is outside the {data_type.name} range"
        if data_type.kind == "real":
            return repr(float(total))
        if isinstance(value, Scalar) and value.kind is ValueKind.HEX:
            digits = len(value.raw) - 2
            return f"0x{total & ((1 << (8 * (data_type.size or 0))) - 1):0{digits}X}"
        return str(total)

    # Assembly

    def _assem(self, proxy: Entry, proxied: Entry | None) -> list[Field] | None:
        faults = list(module_member_list_faults(proxy))
        for place, message in faults:
            self.report(BAD_MODULE_MEMBER_LIST, f"{proxy.keyword} {message}", self.adapter, place)
        if faults:
            return None
        fields = self._plain(proxy, proxied, range(min(ASSEM_HEADER_FIELDS, len(proxy.fields))))
        ok = fields is not None
        members = proxy.fields[ASSEM_HEADER_FIELDS:]
        combined: list[Field] = []
        for start in range(0, len(members), 2):
            size, reference = members[start], members[start + 1] if start + 1 < len(members) else None
            if _is_word(size, MODULE_MEMBER_LIST) or _is_word(reference, MODULE_MEMBER_LIST):
                listed = size if reference is None or _is_word(size, MODULE_MEMBER_LIST) else reference
                expanded = self._member_list(proxy, proxied, listed)
                ok = ok and expanded is not None
                combined.extend(expanded or ())
                continue
            for item in (size, reference):
                if _is_word(item, MODULE):
                    role = "Member Size" if item is size else "Member Reference"
                    self.report(MODULE_IN_MEMBER, f"{proxy.keyword}: {MODULE} is not allowed as a {role}; use "
                                f"{MODULE_MEMBER_LIST} in place of the pair", self.adapter, item)
                    ok = False
            combined.append(_copy_field(size))
            if reference is not None:
                combined.append(_copy_field(reference))
        return [*fields, *combined] if ok and fields is not None else None

    def _member_list(self, proxy: Entry, proxied: Entry | None, item: Field) -> list[Field] | None:
        if proxied is None:
            _, number = tables.split_numbered(proxy.keyword)
            self.report(NO_PROXIED_ENTRY, f"{proxy.keyword} uses {MODULE_MEMBER_LIST}, but {_name(self.module)} "
                        f"has no ProxiedAssem{number}", self.adapter, item)
            return None
        members = [_copy_field(member) for member in proxied.fields[ASSEM_HEADER_FIELDS:]]
        if len(members) % 2:
            members.append(Field(None))  # a trailing Member Size without its reference
        return members

    # Connection Manager

    def _connection(self, proxy: Entry, proxied: Entry | None) -> list[Field] | None:
        if len(proxy.fields) > CONNECTION_NAME_POSITION and _is_word(proxy.fields[CONNECTION_NAME_POSITION], MODULE):
            self.report(PROXY_CONNECT_NAME_MODULE, f"{proxy.keyword}: the connection name string shall be given by "
                        f"the adapter, not {MODULE}", self.adapter, proxy.fields[CONNECTION_NAME_POSITION])
            return None
        return self._plain(proxy, proxied, range(len(proxy.fields)))


def module_member_list_faults(entry: Entry) -> Iterator[tuple[Field, str]]:
    """(field, what is wrong) wherever a ProxyAssem's ModuleMemberList does not stand in place of a
    whole Member Size / Member Reference pair (C.4.1.5.3.2): in fields 1-6, or beside a non-empty field
    of its pair. ``edsconv lint`` and the merge both report them (EDS406)."""
    for position, item in enumerate(entry.fields[:ASSEM_HEADER_FIELDS]):
        if _is_word(item, MODULE_MEMBER_LIST):
            yield item, f"field {position + 1} is {MODULE_MEMBER_LIST}, which may stand only in place of a member " \
                        "pair (fields 7, 8 and on, Table C.20)"
    members = entry.fields[ASSEM_HEADER_FIELDS:]
    for start in range(0, len(members), 2):
        size, reference = members[start], members[start + 1] if start + 1 < len(members) else None
        position = ASSEM_HEADER_FIELDS + start
        if _is_word(size, MODULE_MEMBER_LIST) or _is_word(reference, MODULE_MEMBER_LIST):
            partner = reference if _is_word(size, MODULE_MEMBER_LIST) else size
            if partner is not None and partner.value is not None:
                yield partner, f"fields {position + 1}-{position + 2}: {MODULE_MEMBER_LIST} stands in place of the " \
                               f"whole pair; the other field shall be empty, not {partner.raw or 'a group'}"


# --- refusing what lint calls an error ---------------------------------------------------

#: combined keyword prefix -> the adapter's keyword prefix it stands for
_PROXY_OF = {out: proxy for _, proxy, _, out in FAMILIES} | {"Enum": "ProxyEnum"}


def _as_proxy(entry: Entry) -> str:
    prefix, number = tables.split_numbered(entry.keyword)
    return f"{_PROXY_OF[prefix]}{number}"


def _in_place(adapter: EdsFile, sections: list[Section]) -> EdsFile:
    """The adapter with each Proxy entry holding the fields of the entry it forms with the module's:
    the file lint would see if the adapter described the module itself. Keywords stay the adapter's,
    so references (``ProxyParam1`` in a connection) resolve as they do there."""
    combined = {_as_proxy(entry): entry for section in sections for entry in section.entries}
    rebuilt = []
    for section in adapter.sections:
        entries = [Entry(entry.keyword, combined.pop(entry.keyword).fields) if entry.keyword in combined else entry
                   for entry in section.entries]
        if section.name == "Params":
            entries += [Entry(keyword, entry.fields) for keyword, entry in combined.items()
                        if keyword.startswith("ProxyEnum")]
        rebuilt.append(Section(section.name, entries))
    return EdsFile(sections=rebuilt)


def _faults_in_combined(adapter: EdsFile, sections: list[Section]) -> dict[str, list[Diagnostic]]:
    """Adapter keyword -> the errors lint reports in the entry it forms with the module: the adapter's own
    faults in fields it gives, the module's in fields it defers (Module), and those of the pair (a size
    against its format, minimum against maximum), which neither file shows alone (C.4.1.5.3)."""
    from edsconv import analyse, parse
    from edsconv.eds.writer import write

    combined = {_as_proxy(entry) for section in sections for entry in section.entries}
    text_file = parse(write(_in_place(adapter, sections)))
    spans = [(entry.line, entry.source.position(entry.end_offset)[0] if entry.source else entry.line, entry.keyword)
             for section in text_file.sections for entry in section.entries if entry.keyword in combined]
    faults: dict[str, list[Diagnostic]] = {}
    for found in analyse(text_file)[1]:
        if found.severity is Severity.ERROR:
            for first, last, keyword in spans:
                if first <= found.line <= last:
                    faults.setdefault(keyword, []).append(found)
    return faults


def _refuse_faulty(adapter: EdsFile, module: EdsFile, sections: list[Section], report: _Reporter) -> list[Section]:
    """``sections`` without the combined entries lint reports an error in; each error reported at the
    adapter's Proxy entry, naming the module. Merge refuses what lint would refuse."""
    if not sections:
        return sections
    faults = _faults_in_combined(adapter, sections)
    proxies = _numbered(adapter)
    kept = []
    for section in sections:
        entries = [entry for entry in section.entries if _as_proxy(entry) not in faults]
        if entries:
            kept.append(Section(section.name, entries, leading_comments=section.leading_comments))
    for keyword, found in faults.items():
        prefix, number = tables.split_numbered(keyword)
        where = proxies.get((prefix, number or 0))
        for diagnostic in found:
            message = f"{diagnostic.message} (in {keyword} as combined with {_name(module)}; left out)"
            report.diagnostics.append(replace(diagnostic, message=message, path=adapter.path,
                                              line=where.line if where else 0, column=where.column if where else 0,
                                              end_line=None, end_column=None))
    return kept


def merge(adapter: EdsFile, modules: list[EdsFile]) -> MergeResult:
    """Combine the adapter's Proxy entries with those of each module whose Rack entries match.

    Modules without a matching Rack entry are not merged (EDS401). Entries
    whose combination fails are left out and reported.
    """
    report = _Reporter()
    result = MergeResult(adapter)
    if not rack_keys(adapter):
        report(NO_MATCHING_RACK, f"{_name(adapter)} has no [Modular] RackN entry with an electronic key, so no "
               "module can be matched to it", adapter)
    else:
        for module in modules:
            racks = matching_racks(adapter, module)
            if not racks:
                module_racks = ", ".join(rack_keys(module)) or "no RackN entry"
                report(NO_MATCHING_RACK, f"{_name(module)} ({module_racks}) has no Rack entry whose vendor, product "
                       f"type, product code and major revision match a Rack entry of {_name(adapter)}", module)
                continue
            sections = _refuse_faulty(adapter, module, _Merger(adapter, module, report).merge(), report)
            if sections:
                pairs = ", ".join(f"{a} = {m}" for a, m in racks)
                sections[0].leading_comments = [Comment(f" edsconv merge: {_name(adapter)} + {_name(module)} "
                                                        f"(matching racks: {pairs})")]
            result.merges.append(ModuleMerge(module, racks, sections))
    result.diagnostics = report.diagnostics
    return result


__all__ = ["FAMILIES", "MergeResult", "ModuleMerge", "matching_racks", "merge", "rack_keys"]
