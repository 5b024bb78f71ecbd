"""edsconv.cip_tables: the tables beyond the 2003 text, held to their sources.

- against eds-pie 1.2.0's references/*.json (skipped when eds-pie is not installed):
  every reference a record cites exists, class IDs, field types, repetition;
- against the real files (skipped without ../shared): every section and keyword
  they write beyond the 2003 text is known or vendor-specific, the file counts
  recorded as evidence are right, every value they write fits the table's type;
- against our own files in corpus/cip (MANIFEST.tsv): the clean files fit the
  tables, each fault file breaks them in exactly the one place it names;
- corpus/idioms (MANIFEST.tsv): each file draws the code edsconv.idioms decided
  for its generator idiom, and the evidence counted for it is what the real files give.
"""

from __future__ import annotations

import base64
import binascii
import csv
import functools
import json
import re
from collections import defaultdict
from pathlib import Path

import pytest

from conftest import REPO, SHARED_REAL, needs_real_corpus
from edsconv import cip_tables as cip
from edsconv import spec_tables as spec
from edsconv.diagnostics import Severity, load_rules
from edsconv.eds.reader import load
from edsconv.eds.syntax import EdsFile, Entry, Group, Scalar, String
from edsconv.idioms import IDIOMS
from edsconv.lint import lint_file
from edsconv.model import values

CIP_CORPUS = REPO / "corpus" / "cip"
IDIOMS_DIR = REPO / "corpus" / "idioms"
REAL_FILES = sorted(p for p in SHARED_REAL.glob("*") if p.suffix in (".eds", ".EDS")) if SHARED_REAL.is_dir() else []


@functools.cache
def real(path: Path) -> EdsFile:
    """A real file, read once for all the tests here."""
    return load(path)


def all_entries() -> list[spec.EntrySpec]:
    seen: dict[int, spec.EntrySpec] = {}
    for section in cip.all_sections():
        for entry in section.entries:
            seen.setdefault(id(entry), entry)
    return list(seen.values())


# --- the tables themselves ---------------------------------------------------------------


def test_every_record_has_a_source_and_a_practice_only_fact_has_files():
    records = [*cip.all_sections(), *all_entries(),
               *(f for e in all_entries() for f in e.fields), *cip.CONNECTION_SAFETY_FIELDS]
    for record in records:
        source = record.provenance
        assert source is not None, record
        assert record.clause == (f"eds-pie {source.eds_pie.split(':')[0]}" if source.eds_pie else cip.PRACTICE)
        if source.practice_only and record is not cip.VENDOR_CLASS_SECTION:
            assert source.files > 0, f"{record} is known from practice only, yet no real file shows it"


def test_every_field_type_is_a_data_type_or_a_known_kind():
    known = {*spec.DATA_TYPES_BY_NAME, *spec.FIELD_VALUE_KINDS, *cip.CIP_VALUE_KINDS}
    for entry in all_entries():
        for field_spec in (*entry.fields, *cip.CONNECTION_SAFETY_FIELDS):
            assert set(field_spec.alternatives) <= known, (entry.keyword, field_spec.name)


def test_common_entries_are_shared_not_copied():
    common = {e.keyword: e for e in cip.COMMON_OBJECT_ENTRIES}
    sample = {e.keyword: e.keyword + ("1" if e.numbered else "") for e in cip.COMMON_OBJECT_ENTRIES}
    class_sections = [s for s in cip.all_sections() if s.class_id is not None or s is cip.VENDOR_CLASS_SECTION]
    assert len(class_sections) >= 30
    for section in class_sections:
        defined_2003 = ({e.keyword for e in spec.SECTIONS[section.name].entries}
                        if section.name in spec.SECTIONS else set())
        for keyword, entry in common.items():
            if keyword in defined_2003:
                assert section.entry(sample[keyword]) is None
            else:
                assert section.entry(sample[keyword]) is entry, (section.name, keyword)
    # nowhere else an entry of the same keyword: one object per fact
    for entry in all_entries():
        if entry.keyword in common:
            assert entry is common[entry.keyword]


def test_extensions_add_only_what_the_2003_text_does_not_define():
    for name, extension in cip.SECTION_EXTENSIONS.items():
        for entry in extension.entries:
            sample = entry.keyword + ("1" if entry.numbered else "")
            assert spec.entry_spec(name, sample) is None, (name, entry.keyword)
    assert not set(cip.CIP_SECTIONS) & set(spec.SECTIONS)


def test_lookups():
    tspec = cip.entry_spec("[Capacity]", "TSpec12")
    assert tspec.keyword == "TSpec" and tspec.fields[0].choices == ("Tx", "Rx", "TxRx")
    assert [f.eds_type for f in tspec.fields] == ["Keyword", "UINT", "UDINT"]
    assert cip.entry_spec("TCP/IP Interface Class", "ENetQCT1").field_at(2).name == "Accumulated CIP Connection Time"
    assert cip.entry_spec("Assembly", "AssemExa3").field_at(9).name == "Member Size"
    assert cip.entry_spec("Assembly", "Assem3") is None  # a 2003 entry: spec_tables has it
    assert cip.entry_spec("Capacity", "TSpec") is None  # a family needs its number
    assert cip.class_id_of("TCP/IP Interface Class") == 0xF5 == spec.TCPIP_INTERFACE_CLASS
    assert cip.class_id_of("[Class940_Vendor1]") == 940
    assert cip.vendor_class_section("Class15_Vendor1") == (15, 1)
    assert cip.vendor_class_section("1_Class15") is None
    assert cip.section_spec("Class940_Vendor1") is cip.VENDOR_CLASS_SECTION
    assert cip.section_spec("Params") is None and cip.class_id_of("Params") is None
    assert cip.entry_spec("Ingress Egress Class", "Maintain_Existing_Connection").presence is spec.Presence.REQUIRED
    assert cip.CIP_SECTIONS["Time Sync Class"].provenance.practice_only
    assert not cip.CIP_SECTIONS["QoS Class"].provenance.practice_only


# --- against eds-pie ---------------------------------------------------------------------


def _eds_pie() -> dict[str, dict]:
    eds_pie = pytest.importorskip("eds_pie")
    folder = Path(eds_pie.__file__).parent / "references"
    return {name: json.loads((folder / name).read_text())["sections"] for name in (cip.META, cip.ENIP, cip.COMMON)}


def _cited(key: str, references: dict[str, dict]):
    """The eds-pie JSON node a provenance key (``file: Section.Entry`` ...) names."""
    file_name, path = key.split(": ", 1)
    path = path.split(" (")[0]
    section, _, rest = path.partition(".")
    node = references[file_name][section]
    if rest in ("", "class_id"):
        return node.get(rest, node) if rest else node
    return node["entries"][rest]


def test_every_eds_pie_reference_exists():
    references = _eds_pie()
    records = [*cip.all_sections(), cip.COMMON_OBJECT_CLASS, *all_entries(),
               *(f for e in all_entries() for f in e.fields), *cip.CONNECTION_SAFETY_FIELDS]
    keys = {r.provenance.eds_pie for r in records if r.provenance.eds_pie}
    keys.add(cip.CLASSIFICATION_KEYWORDS_NEWER_SOURCE.eds_pie)
    for key in keys:
        assert _cited(key, references) is not None, key


def test_class_ids_match_eds_pie():
    references = _eds_pie()
    for name, section in references[cip.ENIP].items():
        ours = cip.section_spec(name)
        assert ours is not None, name
        assert ours.class_id == section["class_id"], name


#: eds-pie data type -> the eds_type alternatives that stand for it here.
EDS_PIE_TYPES = {"STRING": {"EDS_Char_Array", "Base64Icon"}, "KEYWORD": {"Keyword"}, "EMPTY": {"Empty"},
                 "EDS_SERVICE": {"ServiceSpec"}}
EDS_PIE_REFS = {"AssemN": "AssemRef", "ParamN": "ParamRef", "ProxyAssemN": "ProxyAssemRef",
                "ProxyParamN": "ProxyParamRef", "AssemExaN": "AssemExaRef", "VariantN": "VariantRef",
                "VariantExaN": "VariantExaRef", "BitStringVariantN": "BitStringVariantRef", "ArrayN": "ArrayRef",
                "ConstructedParamN": "ConstructedParamRef"}


def _eds_pie_alternatives(data_types: dict) -> list[set[str]]:
    """For each eds-pie data type (and each REF), the alternatives that may stand for it."""
    out: list[set[str]] = []
    for name, detail in data_types.items():
        if name == "REF":
            out += [{EDS_PIE_REFS[ref]} for ref in detail]
        else:
            out.append(EDS_PIE_TYPES.get(name, {name}))
    return out


def _modelled_eds_pie_entries():
    """(section, eds-pie key, eds-pie entry, our spec) for every eds-pie entry beyond 2003."""
    references = _eds_pie()
    for file_name in (cip.META, cip.ENIP, cip.COMMON):
        for section_name, section in references[file_name].items():
            for key, entry in section["entries"].items():
                keyword = key[:-1] + "1" if key.endswith("N") else key
                home = cip.COMMON_OBJECT_CLASS.name if section_name == "CommonObjectClass" else section_name
                if home in spec.SECTIONS and spec.entry_spec(home, keyword) is not None:
                    continue  # a 2003 entry
                ours = (cip.COMMON_OBJECT_CLASS.entry(keyword) if home == cip.COMMON_OBJECT_CLASS.name
                        else cip.entry_spec(home, keyword))
                yield section_name, key, entry, ours


def test_field_types_match_eds_pie():
    checked = 0
    for section_name, key, entry, ours in _modelled_eds_pie_entries():
        assert ours is not None, (section_name, key)
        for position, eds_pie_field in enumerate(entry["fields"], 1):
            field_spec = ours.field_at(position)
            assert field_spec is not None, (key, position)
            for wanted in _eds_pie_alternatives(eds_pie_field["data_types"]):
                assert wanted & set(field_spec.alternatives), (key, position, wanted, field_spec.eds_type)
            if "KEYWORD" in eds_pie_field["data_types"]:
                assert set(eds_pie_field["data_types"]["KEYWORD"]) == set(field_spec.choices), key
            checked += 1
    assert checked > 60


def test_repetition_and_presence_match_eds_pie_or_the_disagreement_is_recorded():
    for _section_name, key, entry, ours in _modelled_eds_pie_entries():
        assert (ours.presence is spec.Presence.REQUIRED) == entry["required"], key
        marker = entry["enumerated_fields"]
        repeats_from = min((f.number for f in ours.fields if f.repeats), default=None)
        eds_pie_from = marker["first_enum_field"] if marker else None
        if repeats_from != eds_pie_from:
            why = ours.provenance.disagreement + ours.note
            assert "repeat" in why, f"{key}: eds-pie repeats from {eds_pie_from}, the table from {repeats_from}"


def test_newer_classification_keywords_are_eds_pies():
    references = _eds_pie()
    listed = references[cip.META]["Device Classification"]["entries"]["ClassN"]["fields"][0]["data_types"]["KEYWORD"]
    assert set(cip.CLASSIFICATION_KEYWORDS_NEWER) == set(listed) - set(spec.CLASSIFICATION_KEYWORDS)


# --- a value against a field of the tables ------------------------------------------------

_REGEX_KINDS = {k: v for k, v in {**spec.FIELD_VALUE_KINDS, **cip.CIP_VALUE_KINDS}.items() if v}


def _service_ok(value) -> bool:
    if isinstance(value, Group):
        first, *rest = value.fields
        return _type_ok("USINT", first.value) and all(
            (isinstance(f.value, Scalar) and f.value.raw == "*") or _type_ok("UINT", f.value) for f in rest)
    return _type_ok("USINT", value)


def _type_ok(type_name: str, value) -> bool:
    try:
        values.convert(value, type_name)
    except (ValueError, KeyError, TypeError, AttributeError):
        return False
    return True


def alternative_ok(kind: str, field_spec: spec.FieldSpec, value) -> bool:
    """Whether a field value is of one alternative of a field's eds_type."""
    if value is None or kind == "Empty":
        return value is None and kind == "Empty"
    if kind == "Untyped":
        return True
    if kind == "ServiceSpec":
        return _service_ok(value)
    if kind == "Keyword":
        return isinstance(value, Scalar) and re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", value.raw) is not None and (
            not field_spec.choices or value.raw in field_spec.choices)
    if kind == "Base64Icon":
        return isinstance(value, String) and re.fullmatch(_REGEX_KINDS[kind], value.text) is not None
    if kind in _REGEX_KINDS:
        return isinstance(value, Scalar) and re.fullmatch(_REGEX_KINDS[kind], value.raw) is not None
    return _type_ok(kind, value)


def field_problems(entry: Entry, entry_spec: spec.EntrySpec) -> list[str]:
    """Fields of an entry that fit none of their table's alternatives, or are too many."""
    problems = []
    for position, item in enumerate(entry.fields, 1):
        field_spec = entry_spec.field_at(position)
        if field_spec is None:
            problems.append(f"{entry.keyword} field {position}: beyond the {len(entry_spec.fields)} fields")
        elif item.value is None:
            if field_spec.presence is spec.Presence.REQUIRED:
                problems.append(f"{entry.keyword} field {position} ({field_spec.name}) is required")
        elif not any(alternative_ok(kind, field_spec, item.value) for kind in field_spec.alternatives):
            problems.append(f"{entry.keyword} field {position} ({field_spec.name}): {item.raw!r} is not "
                            f"{field_spec.eds_type}")
    return problems


def newer_entries(eds: EdsFile):
    """(section name, entry, spec of these tables or None) for every entry beyond the 2003 text."""
    for section in eds.sections:
        for entry in section.entries:
            if section.name in spec.SECTIONS and spec.entry_spec(section.name, entry.keyword) is not None:
                continue
            yield section.name, entry, cip.entry_spec(section.name, entry.keyword)


def _known(section: str, keyword: str) -> bool:
    return (cip.entry_spec(section, keyword) is not None or spec.is_vendor_keyword(keyword))


def test_alternative_ok_tells_good_from_bad():
    tspec = cip.entry_spec("Capacity", "TSpec1")
    good = load_text("[Capacity]\nTSpec1 = TxRx, 504, 3000;\n").sections[0].entries[0]
    bad = load_text("[Capacity]\nTSpec1 = Both, 70000, 3000, 1;\n").sections[0].entries[0]
    assert field_problems(good, tspec) == []
    assert len(field_problems(bad, tspec)) == 3
    services = cip.COMMON_OBJECT_CLASS.entry("Instance_Services")
    entry = load_text("[QoS Class]\nInstance_Services = {0x10,*}, {0x0E,3,4}, 0x01;\n").sections[0].entries[0]
    assert field_problems(entry, services) == []
    entry = load_text("[QoS Class]\nInstance_Services = {0x100,*}, Get;\n").sections[0].entries[0]
    assert len(field_problems(entry, services)) == 2


def load_text(text: str) -> EdsFile:
    from edsconv.eds.reader import parse

    return parse(text)


# --- against the real files --------------------------------------------------------------


@needs_real_corpus
def test_real_files_write_nothing_unknown():
    unknown = set()
    for path in REAL_FILES:
        eds = real(path)
        for section in eds.sections:
            if section.name not in spec.SECTIONS and cip.section_spec(section.name) is None \
                    and not spec.is_vendor_keyword(section.name):
                unknown.add((section.name, None))
        for section, entry, found in newer_entries(eds):
            if found is None and not spec.is_vendor_keyword(entry.keyword):
                unknown.add((section, entry.keyword))
    assert unknown == set()


def _real_counts() -> tuple[dict[int, set[str]], dict[int, set[str]]]:
    """Files per spec object (entries and sections of these tables)."""
    entries: dict[int, set[str]] = defaultdict(set)
    sections: dict[int, set[str]] = defaultdict(set)
    for path in REAL_FILES:
        eds = real(path)
        for section in eds.sections:
            if section.name not in spec.SECTIONS and cip.section_spec(section.name) is not None:
                sections[id(cip.section_spec(section.name))].add(path.name)
        for section, _entry, found in newer_entries(eds):
            if found is not None:
                entries[id(found)].add(path.name)
                if section in cip.SECTION_EXTENSIONS:
                    sections[id(cip.SECTION_EXTENSIONS[section])].add(path.name)
    return entries, sections


@needs_real_corpus
def test_recorded_file_counts_are_the_real_files():
    entries, sections = _real_counts()
    wrong = []
    for section in cip.all_sections():
        if len(sections[id(section)]) != section.provenance.files:
            wrong.append((section.name, section.provenance.files, len(sections[id(section)])))
    for entry in all_entries():
        if len(entries[id(entry)]) != entry.provenance.files:
            wrong.append((entry.keyword, entry.provenance.files, len(entries[id(entry)])))
    assert wrong == []


@needs_real_corpus
def test_real_values_fit_the_tables():
    problems = []
    for path in REAL_FILES:
        for section, entry, found in newer_entries(real(path)):
            if found is not None:
                problems += [f"{path.name}: [{section}] {p}" for p in field_problems(entry, found)]
    assert problems == []


@needs_real_corpus
def test_real_object_class_codes_agree_with_the_tables():
    seen = 0
    for path in REAL_FILES:
        for section in real(path).sections:
            code = section.entry("Object_Class_Code")
            if code is not None:
                assert values.convert(code.fields[0].value, "UDINT") == cip.class_id_of(section.name), path.name
                seen += 1
    assert seen == 296


@needs_real_corpus
def test_real_icon_contents_are_base64():
    icons = 0
    for path in REAL_FILES:
        device = real(path).section("Device")
        entry = device.entry("IconContents") if device else None
        if entry is not None:
            base64.b64decode(entry.fields[0].value.text, validate=True)
            icons += 1
    assert icons == cip.entry_spec("Device", "IconContents").provenance.files


# --- our own files: corpus/cip ------------------------------------------------------------


def ico_problem(text: str) -> str | None:
    """Why an IconContents text is not the base64 of an ICO whose images lie inside it."""
    try:
        data = base64.b64decode(text, validate=True)
    except binascii.Error:
        return "not base64"
    if len(data) < 6 or data[:4] != b"\0\0\1\0" or int.from_bytes(data[4:6], "little") == 0:
        return "no ICO header"
    for index in range(int.from_bytes(data[4:6], "little")):
        entry = data[6 + 16 * index:22 + 16 * index]
        size, offset = int.from_bytes(entry[8:12], "little"), int.from_bytes(entry[12:16], "little")
        if len(entry) < 16 or offset + size > len(data):
            return "an image lies beyond the end"
    return None


def _found_fields(eds: EdsFile):
    for section, entry, found in newer_entries(eds):
        if found is not None and field_problems(entry, found):
            yield section, entry.keyword


def _found_class_codes(eds: EdsFile):
    for section in eds.sections:
        code, expected = section.entry("Object_Class_Code"), cip.class_id_of(section.name)
        if code is not None and expected is not None and values.convert(code.fields[0].value, "UDINT") != expected:
            yield section.name, code.keyword


def _found_duplicates(eds: EdsFile):
    for section in eds.sections:
        keywords = [e.keyword for e in section.entries]
        yield from {(section.name, k) for k in keywords if keywords.count(k) > 1}


def _found_label_instances(eds: EdsFile):
    link = eds.section("Ethernet Link Class")
    if link is not None and link.entry("MaxInst") is not None:
        max_inst = values.convert(link.entry("MaxInst").fields[0].value, "UINT")
        for entry in link.entries:
            prefix, number = spec.split_numbered(entry.keyword)
            if prefix == "InterfaceLabel" and number > max_inst:
                yield link.name, entry.keyword


def _found_icons(eds: EdsFile):
    device = eds.section("Device")
    icon = device.entry("IconContents") if device else None
    if icon is not None and ico_problem(icon.fields[0].value.text):
        yield "Device", "IconContents"


def _found_required(eds: EdsFile):
    for section in eds.sections:
        table = cip.section_spec(section.name)
        for entry_spec in table.entries if table else ():
            if entry_spec.presence is spec.Presence.REQUIRED and section.entry(entry_spec.keyword) is None:
                yield section.name, entry_spec.keyword


def _defined(eds: EdsFile) -> set[str]:
    return {entry.keyword for section in eds.sections for entry in section.entries}


def _found_references(eds: EdsFile):
    """AssemExaN members naming no entry; [IO_Info] defaults naming no InputN / OutputN (0: none);
    DefaultSafetyConnections naming no ConnectionN."""
    defined = _defined(eds)
    for section in eds.sections:
        for entry in section.entries:
            words = [f.value.raw for f in entry.fields if isinstance(f.value, Scalar)]
            if entry.keyword.startswith("AssemExa") and any(
                    re.fullmatch(r"(Param|Assem|AssemExa)[0-9]+", w) and w not in defined for w in words):
                yield section.name, entry.keyword
            defaults = zip(("Input", "Output"), words[1:3], strict=False)
            if section.name == "IO_Info" and entry.keyword.endswith("Info") and any(
                    w != "0" and f"{kind}{w}" not in defined for kind, w in defaults):
                yield section.name, entry.keyword
            if entry.keyword == "DefaultSafetyConnections" and any(f"Connection{w}" not in defined for w in words):
                yield section.name, entry.keyword


def _found_io_sizes(eds: EdsFile):
    """[IO_Info] InputN / OutputN whose path size (field 5) is not the byte count of its path (field 6)."""
    io = eds.section("IO_Info")
    for entry in io.entries if io else ():
        if re.fullmatch(r"(Input|Output)[0-9]+", entry.keyword) and \
                int(entry.fields[4].value.raw) != len(entry.fields[5].value.text.split()):
            yield io.name, entry.keyword


DETECTORS = {"field": _found_fields, "class-code": _found_class_codes, "duplicate": _found_duplicates,
             "label-instance": _found_label_instances, "icon": _found_icons, "required-entry": _found_required,
             "reference": _found_references, "io-sizes": _found_io_sizes}


def manifest() -> list[dict[str, str]]:
    with (CIP_CORPUS / "MANIFEST.tsv").open(newline="") as handle:
        return list(csv.DictReader(handle, delimiter="\t"))


def test_manifest_lists_every_file_and_each_family_has_a_clean_file():
    rows = manifest()
    assert sorted(r["file"] for r in rows) == sorted(p.name for p in CIP_CORPUS.glob("*.eds"))
    families = {r["file"].split("_")[0] for r in rows}
    clean = {r["file"].split("_")[0] for r in rows if r["kind"] == "clean"}
    assert families == clean


@pytest.mark.parametrize("row", manifest(), ids=lambda row: row["file"])
def test_cip_file_has_exactly_its_fault(row):
    eds = load(CIP_CORPUS / row["file"])
    syntax_errors = {d.code for d in eds.diagnostics if d.severity is Severity.ERROR}
    assert syntax_errors == ({"EDS009"} if row["kind"] == "duplicate" else set()), row["file"]
    found = {kind: set(detect(eds)) for kind, detect in DETECTORS.items()}
    everything = set().union(*found.values())
    if row["kind"] == "clean":
        assert everything == set()
    else:
        target = (row["section"], row["entry"])
        assert target in found[row["kind"]]
        assert everything == {target}


@pytest.mark.parametrize("row", [r for r in manifest() if r["kind"] != "clean"], ids=lambda row: row["file"])
def test_fault_severity_follows_the_source(row):
    """An error only where a documented fact (eds-pie, the 2003 text) is broken; the code's rule has
    the manifest's severity."""
    assert str(load_rules().rules[row["code"]].severity) == row["severity"]
    if row["kind"] == "class-code":
        table = cip.section_spec(row["section"])
    elif row["kind"] == "duplicate":
        assert (row["basis"], row["code"], row["severity"]) == ("2003 text", "EDS009", "error")
        return
    else:
        table = cip.entry_spec(row["section"], row["entry"])
    practice = table.provenance.practice_only or row["kind"] in ("icon", "label-instance", "io-sizes")
    assert row["basis"] == ("practice" if practice else "eds-pie")
    assert row["severity"] == ("warning" if practice else "error")


@pytest.mark.parametrize("row", manifest(), ids=lambda row: row["file"])
def test_cip_file_draws_its_code_and_no_other_error(row):
    """lint gives a fault file its manifest code (EDS5xx, or EDS009) once and a clean file none; the
    files have no other error."""
    report = lint_file(str(CIP_CORPUS / row["file"]))
    newer = [d for d in report.diagnostics if d.code.startswith("EDS5") or d.code == "EDS009"]
    assert [d.code for d in newer] == ([] if row["kind"] == "clean" else [row["code"]])
    assert {d.code for d in report.diagnostics if d.severity is Severity.ERROR} <= {row["code"]}


# --- generator idioms: corpus/idioms -------------------------------------------------------

#: Notes about content beyond the 2003 text, which every file may draw.
_NEWER_CONTENT_NOTES = {"EDS006", "EDS219", "EDS220"}


def idioms() -> list[dict[str, str]]:
    with (IDIOMS_DIR / "MANIFEST.tsv").open(newline="") as handle:
        return list(csv.DictReader(handle, delimiter="\t"))


def test_idiom_manifest_lists_every_file():
    assert sorted(r["file"] for r in idioms()) == sorted(p.name for p in IDIOMS_DIR.glob("*.eds"))


def test_every_idiom_has_a_decision():
    assert [idiom.file for idiom in IDIOMS] == [row["file"] for row in idioms()]


@pytest.mark.parametrize("row", idioms(), ids=lambda row: row["file"])
def test_idiom_file_draws_the_decided_code_and_no_error(row):
    """Each file reproduces the idiom: lint gives exactly the codes edsconv.idioms decided, none an
    error (in phase 1 it gave codes_phase1)."""
    decided = next(idiom for idiom in IDIOMS if idiom.file == row["file"])
    report = lint_file(str(IDIOMS_DIR / row["file"]))
    assert {d.code for d in report.diagnostics} - _NEWER_CONTENT_NOTES == set(decided.codes)
    assert all(d.severity is not Severity.ERROR for d in report.diagnostics)


@functools.cache
def _real_lint() -> list:
    return [d for path in REAL_FILES for d in lint_file(str(path)).diagnostics]


@needs_real_corpus
@pytest.mark.parametrize("row", idioms(), ids=lambda row: row["file"])
def test_idiom_evidence_is_the_real_files(row):
    code = max(row["codes_phase1"].split(","))
    pattern = re.compile(row["message_regex"]) if row["message_regex"] else None
    hits = [d for d in _real_lint() if d.code == code and (pattern is None or pattern.search(d.message))]
    assert (len(hits), len({d.path for d in hits})) == (int(row["real_diagnostics"]), int(row["real_files"]))
