"""Checks of the file's structure: sections, entries, keywords, identity (C.4.1.2, C.4.1.4, C.4.2).

Every check here is driven by :mod:`edsconv.spec_tables`: which sections and
entries are required, where they go, how many fields an entry has, which fields
are required, reserved or limited to a list of keywords. The spec's tables are
those of ISO 15745-4:2003; real files use sections, entries and keywords that
later CIP editions added, so whatever the 2003 text does not define is reported
as information and kept, never as an error.

Every EDS is checked against the common section table (Table C.3) and, unless
it is recognisably the EDS of another network, against the EtherNet/IP one
(Table C.27): edsconv targets EtherNet/IP, and the engineering tools that
import EDS files for EtherNet/IP reject a file without a [Device
Classification] naming EtherNetIP.
"""

from __future__ import annotations

import functools
import re
import sys
from collections.abc import Iterable, Iterator

from edsconv import cip_tables
from edsconv import spec_tables as tables
from edsconv.checks import Context, check, keywords, per_unit
from edsconv.checks.coherence import case_variants
from edsconv.checks.coherence_rules import FORWARD_REFERENCE_IN_SECTION, UNDEFINED_SECTION
from edsconv.checks.structure_rules import (
    FIELDS_BEYOND_2003,
    FORWARD_REFERENCE,
    ICON_NOT_ICO,
    ICON_WITHOUT_HOME_URL,
    KEYWORD_BEYOND_2003,
    KEYWORD_STARTS_WITH_DIGIT,
    MISSING_ENTRY,
    MISSING_SECTION,
    MOD_TIME_WITHOUT_DATE,
    MODIFIED_BEFORE_CREATED,
    NO_TCP_PORT,
    NOT_A_CHOICE,
    NOT_ETHERNETIP,
    NUMBERING,
    PUBLIC_CLASS_SUBCLASSIFIED,
    REQUIRED_FIELD_EMPTY,
    RESERVED_FIELD_SET,
    SECTION_PLACEMENT,
    TOO_MANY_FIELDS,
    UNKNOWN_KEYWORD,
    VENDOR_ID_LEADING_ZERO,
    VENDOR_SECTION_NOT_LAST,
)
from edsconv.diagnostics import Diagnostic, Rule
from edsconv.eds.syntax import Entry, Field, Group, Scalar, Section, String
from edsconv.limits import decimal, shown
from edsconv.model.build import iter_references
from edsconv.model.values import CONTROL_CHARACTER, NULL_TERMINATOR, string_flaw

REQUIRED, RESERVED = tables.Presence.REQUIRED, tables.Presence.RESERVED


#: A vendor-specific keyword whose vendor ID has leading zeros (``0065_Foo``, ``[0065_Foo Data]``).
_ZERO_PADDED_VENDOR_KEYWORD = re.compile(r"0[0-9]*_[A-Za-z0-9_]+(?: [A-Za-z0-9_]+)*")
#: C.4.1.5.3: a Proxied entry only supplies the fields its Proxy entry marks "Module";
#: its other fields are documentation and may be empty, so none is required.
_PROXIED_FAMILIES = frozenset(spec.keyword for spec in tables.all_entries() if spec.keyword.startswith("Proxied"))
#: Entries whose repeating tail is as long as a field of theirs says: GroupN lists Number of Members
#: parameters (Table C.19), which may be none.
_COUNTED_TAILS = frozenset({"Group"})
#: A section of DeviceNet EDS files only (CIP Vol 3: the I/O messages of a DeviceNet
#: slave); those files predate [Device Classification], which Table C.3 leaves optional.
_DEVICENET_SECTIONS = frozenset({"IO_Info"})


def _keyword_problem(keyword: str) -> tuple[Rule, str] | None:
    """The rule a keyword (section, entry or field keyword) breaks, with the reason."""
    if _ZERO_PADDED_VENDOR_KEYWORD.fullmatch(keyword):
        vendor_id = keyword.partition("_")[0]
        written = vendor_id.lstrip("0") or "0"  # as written, not int(): a vendor ID may have 5000 digits
        return VENDOR_ID_LEADING_ZERO, f"vendor ID {vendor_id} has leading zeros; write {written}_..."
    vendor_keyword = tables.VENDOR_SECTION_KEYWORD_RE if " " in keyword else tables.VENDOR_KEYWORD_RE
    if keyword[:1].isdigit() and not vendor_keyword.fullmatch(keyword):
        return KEYWORD_STARTS_WITH_DIGIT, "a public keyword never starts with a digit and a vendor-specific " \
                                          "one is VendorID_keyword"
    return None


def _network(ctx: Context) -> str | None:
    """The network whose section table applies: EtherNetIP unless the file is
    classified only under another public network or is a DeviceNet EDS without
    classification; None when it is another network's EDS."""
    public = {c.classification for c in ctx.device.classifications} & set(tables.CLASSIFICATION_KEYWORDS)
    if tables.ETHERNETIP in public:
        return tables.ETHERNETIP
    if public or (not ctx.device.classifications and any(s.name in _DEVICENET_SECTIONS for s in ctx.eds.sections)):
        return None
    return tables.ETHERNETIP


def _word(field: Field) -> str | None:
    """A scalar's spelling or a string's text; None for empty fields and brace groups."""
    value = field.value
    if isinstance(value, String):
        return value.text
    if isinstance(value, Scalar):
        return value.raw
    return None


def _sections_by_name(ctx: Context) -> dict[str, list[Section]]:
    """Every section by name, duplicates together (EDS008 reports them; their entries all count)."""
    by_name: dict[str, list[Section]] = {}
    for section in ctx.eds.sections:
        by_name.setdefault(section.name, []).append(section)
    return by_name


def _specified_entries(ctx: Context) -> Iterator[tuple[Entry, tables.EntrySpec]]:
    """Every entry that the 2003 text defines, with its spec."""
    for section in ctx.eds.sections:
        if section.name not in tables.SECTIONS:
            continue
        for entry in section.entries:
            spec = tables.entry_spec(section.name, entry.keyword)
            if spec is not None:
                yield entry, spec


# --- sections -------------------------------------------------------------------------


@check(MISSING_SECTION)
def required_sections(ctx: Context) -> Iterator[Diagnostic]:
    """Table C.3 requires [File] and [Device]; Table C.27 adds [Device Classification]."""
    if not ctx.eds.sections:
        return  # EDS015 already says the file has no sections
    present = {section.name for section in ctx.eds.sections}
    network = _network(ctx)
    for spec in tables.SECTIONS.values():
        if spec.presence_for(network) is REQUIRED and spec.name not in present:
            table = "Table C.3" if spec.presence is REQUIRED else "Table C.27 (EtherNet/IP)"
            yield ctx.at(MISSING_SECTION, f"the file has no [{spec.name}] section, which {table} requires")


@check(SECTION_PLACEMENT)
def section_placement(ctx: Context) -> Iterator[Diagnostic]:
    """[File] is the first section, [Device] the one right after it (Table C.3 placement 1, 2)."""
    order = [section.name for section in ctx.eds.sections]
    placed = sorted((s for s in tables.SECTIONS.values() if s.placement), key=lambda s: s.placement or 0)
    for previous, spec in zip([None, *placed], placed, strict=False):  # each spec after the one before
        if spec.name not in order:
            continue  # EDS201 reports it
        index = order.index(spec.name)
        section = ctx.eds.sections[index]
        if previous is None and index != 0:
            yield ctx.at(SECTION_PLACEMENT, f"[{spec.name}] shall be the first section; [{order[0]}] stands "
                                            f"before it", section)
        elif previous is not None and previous.name in order and (index == 0 or order[index - 1] != previous.name):
            yield ctx.at(SECTION_PLACEMENT, f"[{spec.name}] shall immediately follow [{previous.name}]", section)


@check(VENDOR_SECTION_NOT_LAST)
def vendor_sections_last(ctx: Context) -> Iterator[Diagnostic]:
    """Vendor-specific sections come after every section the spec defines (C.4.1.2.2.7)."""
    yield from reversed(list(_vendor_sections_misplaced(ctx)))


def _vendor_sections_misplaced(ctx: Context) -> Iterator[Diagnostic]:
    """One backward pass, last section first, remembering the nearest spec section seen: linear, where
    rescanning the sections after each vendor section was quadratic (200,000 of them took minutes)."""
    later = None
    for section in reversed(ctx.eds.sections):
        if section.name in tables.SECTIONS:
            later = section
        elif later is not None and tables.section_spec(section.name) is tables.VENDOR_SECTION:
            yield ctx.at(VENDOR_SECTION_NOT_LAST, f"vendor-specific section [{section.name}] stands before "
                                                  f"[{later.name}] (line {later.line}); vendor sections come last",
                         section)


@check(VENDOR_ID_LEADING_ZERO, KEYWORD_STARTS_WITH_DIGIT, UNDEFINED_SECTION)
def unknown_sections(ctx: Context) -> Iterator[Diagnostic]:
    variants = case_variants(section.name for section in ctx.eds.sections)  # EDS230 says what they are
    for section in ctx.eds.sections:
        problem = _keyword_problem(section.name)
        if problem is not None:
            yield ctx.at(problem[0], f"section [{section.name}]: {problem[1]}", section)
        elif cip_tables.known(section.name) is None and section.name not in variants:
            meant = keywords.closest(section.name, keywords.section_names())
            yield ctx.at(UNDEFINED_SECTION, f"[{section.name}] {_UNDEFINED}{_did_you_mean(meant and f'[{meant}]')}",
                         section)


#: What EDS222 says of a keyword no table defines.
_UNDEFINED = "is defined neither by ISO 15745-4:2003 nor by the newer CIP tables, and is not vendor-specific"


def _did_you_mean(keyword: str | None) -> str:
    return f"; did you mean {keyword}?" if keyword else ""


def _reference_places(ctx: Context) -> Iterator[tuple[Entry, int, str, Entry]]:
    """(entry, 0-based field, what it names, the entry named) of every resolved reference, those
    inside connection paths included."""
    for reference in iter_references(ctx.device):
        target_entry = getattr(reference.target, "entry", None)
        if reference.entry is not None and target_entry is not None:
            yield reference.entry, reference.field_index, str(reference), target_entry
    for connection in ctx.device.connections.values():
        if connection.entry is None or not isinstance(connection.path, tuple):
            continue
        for item in connection.path:
            target_entry = getattr(ctx.device.resolve(item.reference), "entry", None) if item.reference else None
            if target_entry is not None:
                yield connection.entry, _CONNECTION_PATH_FIELD, f"{item} in its path", target_entry


#: 0-based index of the Path field of a ConnectionN (Table C.22 field 15).
_CONNECTION_PATH_FIELD = 14


@check(FORWARD_REFERENCE, FORWARD_REFERENCE_IN_SECTION)
def forward_references(ctx: Context) -> Iterator[Diagnostic]:
    """C.4.1.2.1: sections may be in any order "provided that no forward references exist".

    Reported once per pair of sections, at the first reference that points forward:
    moving the referenced section up fixes them all. A reference forward within one
    section is a warning (EDS227): Figure C.15 makes one.
    """
    section_of = {id(entry): (index, section) for index, section in enumerate(ctx.eds.sections)
                  for entry in section.entries}
    reported: set[tuple[int, int]] = set()
    for entry, field_index, named, target_entry in _reference_places(ctx):
        source = section_of.get(id(entry))
        target = section_of.get(id(target_entry))
        if source is None or target is None or target[0] < source[0] or (source[0], target[0]) in reported:
            continue
        node = entry.fields[field_index] if field_index < len(entry.fields) else entry
        if target[0] == source[0]:
            # positions, not offsets: an incremental re-read keeps entries of an older text beside new ones
            if (target_entry.line, target_entry.column) > (entry.line, entry.column):
                reported.add((source[0], target[0]))
                yield ctx.at(FORWARD_REFERENCE_IN_SECTION, f"{entry.keyword} refers to {named}, placed later in "
                             f"[{source[1].name}] (line {target_entry.line}); C.4.1.2.1 asks for no forward "
                             "references, Figure C.15 makes this one", node)
            continue
        reported.add((source[0], target[0]))
        yield ctx.at(FORWARD_REFERENCE, f"{entry.keyword} in [{source[1].name}] refers to {named} "
                                        f"of [{target[1].name}], which comes later (line {target_entry.line}); "
                                        f"place [{target[1].name}] before [{source[1].name}]", node)


# --- entries --------------------------------------------------------------------------


@check(MISSING_ENTRY)
def required_entries(ctx: Context) -> Iterator[Diagnostic]:
    """Each present section holds the entries its table marks Required (C.6, C.8, C.10, C.4.1.4.4).

    One diagnostic per section, naming every missing entry: a truncated [Device]
    is one fault, not eight.
    """
    for name, sections in _sections_by_name(ctx).items():
        spec = tables.SECTIONS.get(name)
        if spec is None:
            continue
        present = {entry_spec for section in sections for entry in section.entries
                   if (entry_spec := tables.entry_spec(name, entry.keyword)) is not None}
        missing = [entry_spec for entry_spec in spec.entries
                   if entry_spec.presence is REQUIRED and entry_spec not in present]
        if missing:
            listed = ", ".join(f"{e.keyword}N" if e.numbered else e.keyword for e in missing)
            where = f"Table {missing[0].table}" if missing[0].table else missing[0].clause
            yield ctx.at(MISSING_ENTRY, f"[{name}] lacks the required entr{'ies' if len(missing) > 1 else 'y'} "
                                        f"{listed} ({where})", sections[0])


#: C.4.1.5.2.1: a [Modular] section describes a chassis or a module; these entries show which. A chassis
#: "shall contain a required keyword DefineSlotsInRack" (C.4.1.5.2.2), a module "the Width and Rack
#: entries" (C.4.1.5.2.3, Table C.26).
_CHASSIS_ENTRIES, _MODULE_ENTRIES = ("DefineSlotsInRack", "SlotDisplayRule"), \
    ("Width", "Rack", "ExternalID", "GenericID", "ExternIDExactMatch", "Query")
_CHASSIS_REQUIRES, _MODULE_REQUIRES = ("DefineSlotsInRack",), ("Width", "Rack")


@check(MISSING_ENTRY)
def modular_entries(ctx: Context) -> Iterator[Diagnostic]:
    """The entries a chassis or a module [Modular] section requires; an empty section describes neither."""
    sections = _sections_by_name(ctx).get("Modular")
    if not sections:
        return
    present = {spec.keyword for section in sections for entry in section.entries
               if (spec := tables.entry_spec("Modular", entry.keyword)) is not None}
    for kind, shown_by, required in (("chassis", _CHASSIS_ENTRIES, _CHASSIS_REQUIRES),
                                     ("module", _MODULE_ENTRIES, _MODULE_REQUIRES)):
        shown = [keyword for keyword in shown_by if keyword in present]
        missing = [keyword for keyword in required if keyword not in present]
        if shown and missing:
            clause = next(spec.clause for spec in tables.MODULAR_ENTRIES if spec.keyword == required[0])
            listed = ", ".join(f"{keyword}N" if keyword == "Rack" else keyword for keyword in missing)
            yield ctx.at(MISSING_ENTRY, f"[Modular] describes a {kind} ({', '.join(shown)}) but lacks the required "
                                        f"entr{'ies' if len(missing) > 1 else 'y'} {listed} ({clause})", sections[0],
                         clause=clause)


@check(VENDOR_ID_LEADING_ZERO, KEYWORD_STARTS_WITH_DIGIT, KEYWORD_BEYOND_2003, UNKNOWN_KEYWORD)
def entry_keywords(ctx: Context) -> Iterator[Diagnostic]:
    """Entry keywords: vendor IDs without leading zeros, no public keyword with a leading
    digit, keywords the 2003 text does not define in their section (kept, reported as
    information) and keywords no table defines (a warning)."""
    for section in ctx.eds.sections:
        name = sys.intern(section.name)  # one object for every analysis: the memo knows units by identity
        tabled = name in tables.SECTIONS or cip_tables.section_spec(name) is not None
        variants = case_variants(entry.keyword for entry in section.entries)  # EDS230 says what they are
        # whether a table is asked about the keyword: decided by the section, outside the memo
        yield from ctx.each(_entry_keywords, ((entry, name, tabled and entry.keyword not in variants)
                                              for entry in section.entries))


def _entry_keywords(ctx: Context, units: Iterable[tuple[Entry, str, bool]]) -> Iterator[Diagnostic]:
    for entry, section, looked_up in units:
        problem = _keyword_problem(entry.keyword)
        if problem is not None:
            yield ctx.at(problem[0], f"entry {entry.keyword}: {problem[1]}", entry)
        elif looked_up and cip_tables.known(section, entry.keyword) is None:
            if tables.entries_named(entry.keyword) or keywords.newer_entry(section, entry.keyword):
                yield ctx.at(KEYWORD_BEYOND_2003, f"{entry.keyword} {_why_undefined(section, entry.keyword)} "
                                                  "(kept)", entry)
            else:
                meant = keywords.closest(entry.keyword, *keywords.entry_keywords(section))
                yield ctx.at(UNKNOWN_KEYWORD, f"{entry.keyword} in [{section}] {_UNDEFINED}"
                                              f"{_did_you_mean(meant)}", entry, clause="C.4.1.2.2.9")


def _why_undefined(section: str, keyword: str) -> str:
    """Where the 2003 text or the newer tables define a keyword that ``[section]`` does not hold."""
    elsewhere = sorted({spec.section for spec in tables.entries_named(keyword)})
    if elsewhere:
        return f"is defined by ISO 15745-4:2003 for [{'], ['.join(elsewhere)}], not for [{section}]"
    return f"is defined by the newer CIP tables for other sections, not for [{section}]"


@check(NUMBERING)
def numbering(ctx: Context) -> Iterator[Diagnostic]:
    """ClassN, GroupN, ConnectionN, RackN: "numbers shall start at 1 ... and be incremented"."""
    for name, sections in _sections_by_name(ctx).items():
        families: dict[tables.EntrySpec, dict[int, Entry]] = {}
        for section in sections:
            for entry in section.entries:
                spec = tables.entry_spec(name, entry.keyword)
                if spec is not None and spec.sequential:
                    families.setdefault(spec, {}).setdefault(tables.instance_number(entry.keyword), entry)
        for spec, entries in families.items():
            expected = 1
            for number in sorted(entries):
                if number != expected:
                    entry = entries[number]
                    yield ctx.at(NUMBERING, f"{entry.keyword} comes where {spec.keyword}{expected} is expected: "
                                            f"{spec.keyword}N entries are numbered from 1 without gaps",
                         entry, clause=spec.clause)
                expected = number + 1


# --- fields ---------------------------------------------------------------------------


@check(REQUIRED_FIELD_EMPTY, TOO_MANY_FIELDS, FIELDS_BEYOND_2003, RESERVED_FIELD_SET)
@per_unit(_specified_entries)
def field_counts(ctx: Context, units: Iterable[tuple[Entry, tables.EntrySpec]]) -> Iterator[Diagnostic]:
    """Required fields present and not empty; no fields beyond the layout; reserved fields empty."""
    for entry, spec in units:
        missing = []
        fields = entry.fields
        for required in _required_fields(spec):
            index = required.number - 1
            if index >= len(fields):
                missing.append(f"{required.number} ({required.name})")
            elif fields[index].value is None:
                yield ctx.at(REQUIRED_FIELD_EMPTY, f"{entry.keyword} field {required.number} "
                                                   f"({required.name}) is required but empty", fields[index])
        if missing:
            yield ctx.at(REQUIRED_FIELD_EMPTY, f"{entry.keyword} lacks required field{'s' if len(missing) > 1 else ''}"
                                               f" {', '.join(missing)}", entry)
        if spec.max_fields is not None and len(entry.fields) > spec.max_fields:
            extra = entry.fields[spec.max_fields]
            if spec.max_fields == 1:
                yield ctx.at(TOO_MANY_FIELDS, f"{entry.keyword} holds one value ({spec.fields[0].name}) but has "
                                              f"{len(entry.fields)} fields", extra)
            elif len(entry.fields) > (cip_tables.known_field_count(spec) or 0):
                yield ctx.at(FIELDS_BEYOND_2003, f"{entry.keyword} has {len(entry.fields)} fields; ISO 15745-4:2003 "
                                                 f"defines {spec.max_fields} (later fields kept)", extra)
        for index, field_spec in _reserved_fields(spec, len(fields)):
            item = fields[index]
            if item.value is not None and item.raw != tables.MODULE_MEMBER_LIST_KEYWORD:  # EDS406 says what is wrong
                yield ctx.at(RESERVED_FIELD_SET, f"{entry.keyword} field {index + 1} is reserved and shall be "
                                                 f"empty (Table {field_spec.table}); {item.raw or 'its value'} "
                                                 f"is ignored", item)


@functools.lru_cache(maxsize=256)
def _required_fields(spec: tables.EntrySpec) -> tuple[tables.FieldSpec, ...]:
    """The fields of a ``spec`` entry that :func:`field_counts` requires to be present and not empty."""
    if spec.keyword in _PROXIED_FAMILIES:
        return ()
    # a required repeating tail needs its first field (a RackN one Legal Slot)
    return tuple(required for required in spec.fields if required.presence is REQUIRED and not (
        required.repeats and (spec.keyword in _COUNTED_TAILS or required is not spec.repeating[0])))


@functools.lru_cache(maxsize=1024)
def _reserved_fields(spec: tables.EntrySpec, count: int) -> tuple[tuple[int, tables.FieldSpec], ...]:
    """(0-based index, spec) of the reserved fields among the first ``count`` fields of a ``spec`` entry."""
    return tuple((index, field_spec) for index in range(count)
                 if (field_spec := spec.field_at(index + 1)) is not None and field_spec.presence is RESERVED)


#: (entry family, field number) of fields whose value a rule of their own checks, so that one fault has
#: one code: the Port Type Name (EDS333) and the Query service (EDS336).
_OWN_RULE_FIELDS = frozenset({("Port", 1), ("Query", 2)})


@functools.lru_cache(maxsize=1024)
def _choice_fields(spec: tables.EntrySpec, count: int) -> tuple[tuple[int, tables.FieldSpec, bool], ...]:
    """(0-based index, spec, is a Keyword field) of the fields among the first ``count`` of a ``spec``
    entry that :func:`field_keywords` checks: keyword fields and fields with choices."""
    found = []
    for index in range(count):
        field_spec = spec.field_at(index + 1)
        if field_spec is None or (spec.keyword, index + 1) in _OWN_RULE_FIELDS:
            continue
        is_keyword_field = "Keyword" in field_spec.alternatives
        if is_keyword_field or field_spec.choices:
            found.append((index, field_spec, is_keyword_field))
    return tuple(found)


@check(NOT_A_CHOICE, VENDOR_ID_LEADING_ZERO, KEYWORD_STARTS_WITH_DIGIT)
@per_unit(_specified_entries)
def field_keywords(ctx: Context, units: Iterable[tuple[Entry, tables.EntrySpec]]) -> Iterator[Diagnostic]:
    """Fields limited to a list of keywords or values (FieldSpec.choices)."""
    for entry, spec in units:
        fields = entry.fields
        for index, field_spec, is_keyword_field in _choice_fields(spec, len(fields)):
            item = fields[index]
            word = _word(item)
            if word is None or word in spec.proxy_keywords:
                continue
            problem = _keyword_problem(word) if is_keyword_field and isinstance(item.value, Scalar) else None
            if problem is not None:
                yield ctx.at(problem[0], f"{entry.keyword} field {index + 1}: {word}: {problem[1]}", item)
            elif field_spec.choices and not _is_choice(word, field_spec) \
                    and cip_tables.known_choice(field_spec, word) is None:
                yield _not_a_choice(ctx, entry, index, word, field_spec, item)


def _is_choice(word: str, field_spec: tables.FieldSpec) -> bool:
    if word in field_spec.choices or (field_spec.vendor_keywords and tables.is_vendor_keyword(word)):
        return True
    try:
        return (decimal(word) if word.isascii() and word.isdigit() else int(word, 0)) in field_spec.choices
    except ValueError:
        return False


def _not_a_choice(ctx: Context, entry: Entry, index: int, word: str, field_spec: tables.FieldSpec,
                  item: Field) -> Diagnostic:
    allowed = ", ".join(str(choice) for choice in field_spec.choices)
    if field_spec.vendor_keywords and isinstance(item.value, Scalar) and tables.KEYWORD_RE.fullmatch(word):
        # An open list (vendors may add keywords); the public ones later CIP editions add, such as
        # the Safety classification, are cip_tables.known_choice and not reported
        meant = keywords.closest(word, keywords.classification_keywords())
        return ctx.at(NOT_A_CHOICE, f"{entry.keyword} field {index + 1}: the {field_spec.name} {word} "
                                    f"{_UNDEFINED}{_did_you_mean(meant)}", item, clause=field_spec.clause)
    vendor = " or a VendorID_keyword" if field_spec.vendor_keywords else ""
    return ctx.at(NOT_A_CHOICE, f"{entry.keyword} field {index + 1} ({field_spec.name}) is {shown(word)}; allowed: "
                                f"{allowed}{vendor}", item)


@check(CONTROL_CHARACTER, NULL_TERMINATOR)
def string_characters(ctx: Context) -> Iterator[Diagnostic]:
    """C.4.1.3.2 and C.4.1.3.3.1: no control characters and no null terminator, in every string of the file."""
    for section in ctx.eds.sections:
        yield from ctx.each(_string_characters, section.entries)


def _string_characters(ctx: Context, entries: Iterable[Entry]) -> Iterator[Diagnostic]:
    for entry in entries:
        fields = entry.fields
        # walk_fields only for an entry with brace groups: a flat entry's fields are its walk
        for item in entry.walk_fields() if any(f.value.__class__ is Group for f in fields) else fields:
            value = item.value
            flaw = string_flaw(value) if value.__class__ is String else None
            if flaw is not None:
                yield ctx.at(flaw[0], f"{entry.keyword}: {flaw[1]}", item)


# --- classification, identity, file description ---------------------------------------


@check(NOT_ETHERNETIP, PUBLIC_CLASS_SUBCLASSIFIED)
def ethernetip_classification(ctx: Context) -> Iterator[Diagnostic]:
    """C.4.2.2.1: a ClassN = EtherNetIP, without sub-classification; C.4.1.4.4: public
    classifications are never sub-classified."""
    sections = _sections_by_name(ctx).get("Device Classification")
    if not sections:
        return  # EDS201 reports the missing section
    if _network(ctx) == tables.ETHERNETIP and not ctx.device.is_ethernetip:
        found = ", ".join(c.classification for c in ctx.device.classifications if c.classification) or "none"
        yield ctx.at(NOT_ETHERNETIP, f"no ClassN entry is EtherNetIP (classifications: {found}); an EtherNet/IP "
                                     f"EDS needs one", sections[0])
    for classification in ctx.device.classifications:
        entry = classification.entry
        if classification.classification in tables.CLASSIFICATION_KEYWORDS and entry is not None \
                and any(item.value is not None for item in entry.fields[1:]):
            yield ctx.at(PUBLIC_CLASS_SUBCLASSIFIED, f"{entry.keyword}: the public classification "
                                                     f"{classification.classification} shall not be sub-classified",
                         entry.fields[1])


@check(MOD_TIME_WITHOUT_DATE, MODIFIED_BEFORE_CREATED)
def modification_date(ctx: Context) -> Iterator[Diagnostic]:
    """Table C.7: ModDate is required when ModTime is present; it should not precede CreateDate."""
    file_section = ctx.eds.section("File")
    if file_section is None:
        return
    mod_date_entry = file_section.entry("ModDate")
    mod_time_entry = file_section.entry("ModTime")
    if mod_time_entry is not None and mod_date_entry is None:
        yield ctx.at(MOD_TIME_WITHOUT_DATE, "ModTime is present but ModDate is not; Table C.7 requires the date "
                                            "with the time", mod_time_entry)
    described = ctx.device.file
    if mod_date_entry is None or described.mod_date is None or described.create_date is None:
        return
    created = (described.create_date, described.create_time)
    modified = (described.mod_date, described.mod_time)
    same_day_earlier = created[1] is not None and modified[1] is not None and modified[1] < created[1]
    if modified[0] < created[0] or (modified[0] == created[0] and same_day_earlier):
        yield ctx.at(MODIFIED_BEFORE_CREATED, f"the last modification ({_when(modified)}) is before the creation "
                                              f"({_when(created)})", mod_date_entry)


def _when(moment: tuple) -> str:
    date, time = moment
    return f"{date.isoformat()} {time.isoformat()}" if time is not None else date.isoformat()


@check(ICON_WITHOUT_HOME_URL, ICON_NOT_ICO)
def icon(ctx: Context) -> Iterator[Diagnostic]:
    """Table C.9: the icon's location is HomeURL's folder, so Icon "shall only be present when a HomeURL
    exists"; the file "shall have the *.ICO MSWindows format"."""
    device_section = ctx.eds.section("Device")
    icon_entry = device_section.entry("Icon") if device_section is not None else None
    if icon_entry is None:
        return
    file_section = ctx.eds.section("File")
    if file_section is None or file_section.entry("HomeURL") is None:
        yield ctx.at(ICON_WITHOUT_HOME_URL, "Icon names a file relative to HomeURL, but [File] has no HomeURL",
                     icon_entry)
    name = ctx.device.identity.icon
    if isinstance(name, str) and not name.strip().lower().endswith(".ico"):
        yield ctx.at(ICON_NOT_ICO, f"Icon {shown(name)} does not end in .ico; the icon file shall have the MS Windows "
                                   "ICO format", icon_entry.fields[0] if icon_entry.fields else icon_entry)


@check(NO_TCP_PORT)
def ethernetip_port(ctx: Context) -> Iterator[Diagnostic]:
    """C.4.2.2.2: the EtherNet/IP port of a device is a PortN of type TCP."""
    port_section = ctx.eds.section("Port")
    if port_section is None or not ctx.device.is_ethernetip or not ctx.device.ports:
        return
    if any(isinstance(port.type_name, str) and port.type_name not in tables.PORT_TYPE_KEYWORDS
           and not tables.is_vendor_keyword(port.type_name) for port in ctx.device.ports):
        return  # a misspelt port type (EDS333) may be the TCP port: one fault, one code
    if not any(port.type_name == tables.ETHERNETIP_PORT_TYPE for port in ctx.device.ports):
        types = ", ".join(sorted({port.type_name for port in ctx.device.ports if port.type_name})) or "none"
        yield ctx.at(NO_TCP_PORT, f"the device is classified EtherNetIP but no PortN has the port type "
                                  f"{tables.ETHERNETIP_PORT_TYPE} (port types: {types})", port_section)
