"""Survey the EDS content that real files carry beyond ISO 15745-4:2003.

Reads every ``*.eds`` / ``*.EDS`` file of a corpus directory (default: the real
files in ``../shared/corpus/real`` beside the repository) and writes a Markdown
report of the evidence behind ``edsconv.cip_tables``:

- every section and entry keyword the 2003 tables do not define, with the files
  and entries that write it, the field counts, the notation of each field
  (hex, decimal, real, keyword, string, brace group, empty), the keywords and
  comments seen per field, and which generator wrote the files (the
  ``$ EZ-EDS Version ...`` comment, or none: hand-written or another tool);
- how each is classified by the tables: eds-pie fact, practice-only fact,
  vendor-specific (with the pattern), or unknown;
- Object_Class_Code against the class ID of its section, what IconContents
  decodes to, InterfaceLabelN against the Ethernet Link MaxInst;
- every diagnostic ``edsconv lint`` gives today, by code and generator, which
  is where generator idioms show up (docs/spec_tables.md lists them).

Run it again after the corpus or the tables change, and update the summary in
docs/spec_tables.md from its output::

    .venv/bin/python tools/survey_newer_content.py -o docs/survey_newer_content.md
"""

from __future__ import annotations

import argparse
import base64
import binascii
import re
import sys
from collections import Counter, defaultdict
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path

from edsconv import cip_tables as cip
from edsconv import spec_tables as spec
from edsconv.eds.reader import load
from edsconv.eds.syntax import EdsFile, Entry, Group, Scalar
from edsconv.lint import lint_file

DEFAULT_CORPUS = Path(__file__).resolve().parents[2] / "shared" / "corpus" / "real"
_GENERATOR = re.compile(r"EZ-EDS Version ([0-9]+\.[0-9]+)")
NO_GENERATOR = "no generator comment"
#: Field positions shown per entry in the report (AssemExaN has hundreds).
_SHOWN = 8


@dataclass
class KeywordEvidence:
    """How the real files write one entry keyword (a numbered family counts once)."""

    files: set[str] = field(default_factory=set)
    #: one keyword as written (``TSpec1`` for the family ``TSpecN``)
    sample: str = ""
    entries: int = 0
    field_counts: Counter = field(default_factory=Counter)
    #: field position -> Counter of notations
    notations: dict[int, Counter] = field(default_factory=lambda: defaultdict(Counter))
    #: field position -> Counter of bare keywords (WORD scalars)
    keywords: dict[int, Counter] = field(default_factory=lambda: defaultdict(Counter))
    #: field position -> Counter of the comments written after the field
    comments: dict[int, Counter] = field(default_factory=lambda: defaultdict(Counter))


@dataclass
class Survey:
    files: dict[str, str] = field(default_factory=dict)  # file name -> generator
    sections: dict[str, set[str]] = field(default_factory=lambda: defaultdict(set))
    keywords: dict[tuple[str, str], KeywordEvidence] = field(default_factory=lambda: defaultdict(KeywordEvidence))
    class_codes: Counter = field(default_factory=Counter)
    icons: dict[str, str] = field(default_factory=dict)
    labels: Counter = field(default_factory=Counter)
    #: (code, generator) -> [diagnostics, set of files]
    lint: dict[tuple[str, str], list] = field(default_factory=dict)


def generator(path: Path) -> str:
    """``EZ-EDS <major.minor>`` from the file's generator comment, or NO_GENERATOR."""
    match = _GENERATOR.search(path.read_bytes()[:4096].decode("latin-1"))
    return f"EZ-EDS {match.group(1)}" if match else NO_GENERATOR


def family(keyword: str) -> str:
    """``TSpec3`` -> ``TSpecN``; other keywords unchanged."""
    prefix, number = spec.split_numbered(keyword)
    return f"{prefix}N" if number is not None and not spec.is_vendor_keyword(keyword) else keyword


def beyond_2003(eds: EdsFile) -> Iterator[tuple[str, Entry | None]]:
    """(section, entry) for every entry the 2003 tables do not define, and
    (section, None) for every section they do not define."""
    for section in eds.sections:
        if section.name not in spec.SECTIONS:
            yield section.name, None
        for entry in section.entries:
            if section.name not in spec.SECTIONS or spec.entry_spec(section.name, entry.keyword) is None:
                yield section.name, entry


def notation(value) -> str:
    if value is None:
        return "empty"
    if isinstance(value, Group):
        return "group"
    if isinstance(value, Scalar):
        return value.kind.value.lower()
    return "string"


def record_entry(evidence: KeywordEvidence, name: str, entry: Entry) -> None:
    evidence.files.add(name)
    evidence.sample = evidence.sample or entry.keyword
    evidence.entries += 1
    evidence.field_counts[len(entry.fields)] += 1
    for position, item in enumerate(entry.fields, 1):
        evidence.notations[position][notation(item.value)] += 1
        if isinstance(item.value, Scalar) and notation(item.value) == "word":
            evidence.keywords[position][item.value.raw] += 1
        for comment in item.comments:
            evidence.comments[position][comment.text.strip()] += 1


def icon_kind(entry: Entry) -> str:
    """What the base64 text of IconContents decodes to."""
    value = entry.fields[0].value if entry.fields else None
    text = getattr(value, "text", None)
    if text is None:
        return "not a string"
    try:
        data = base64.b64decode(text, validate=True)
    except binascii.Error:
        return "not base64"
    if data[:4] == b"\0\0\1\0" and len(data) >= 22:
        offset = int.from_bytes(data[18:22], "little")
        return "ICO (PNG image)" if data[offset:offset + 4] == b"\x89PNG" else "ICO (BMP image)"
    return "BMP file, not ICO" if data[:2] == b"BM" else "neither ICO nor BMP"


def record_checks(survey: Survey, name: str, eds: EdsFile) -> None:
    """Object_Class_Code against the section's class ID, the icon, the link labels."""
    for section in eds.sections:
        code = section.entry("Object_Class_Code")
        if code is not None and code.fields and code.fields[0].raw:
            raw = code.fields[0].raw
            number = int(raw, 16) if raw.lower().startswith("0x") else int(raw)
            expected = cip.class_id_of(section.name)
            verdict = "no class ID in the tables" if expected is None else (
                "agrees" if expected == number else f"differs from {expected}")
            notation_ = "hex" if raw.lower().startswith("0x") else "decimal"
            survey.class_codes[(section.name, f"{raw} ({notation_})", verdict)] += 1
    device = eds.section("Device")
    icon = device.entry("IconContents") if device else None
    if icon is not None:
        survey.icons[name] = icon_kind(icon)
    link = eds.section("Ethernet Link Class")
    if link is not None and link.entry("MaxInst") is not None:
        labels = [e for e in link.entries if e.keyword.startswith("InterfaceLabel")]
        if labels:
            max_inst = int(link.entry("MaxInst").fields[0].raw, 0)
            numbers = [spec.split_numbered(e.keyword)[1] for e in labels]
            survey.labels["labels = MaxInst" if len(labels) == max_inst else "labels != MaxInst"] += 1
            survey.labels["every label N <= MaxInst" if max(numbers) <= max_inst else "a label N > MaxInst"] += 1


def record_lint(survey: Survey, path: Path, gen: str) -> None:
    for diagnostic in lint_file(str(path)).diagnostics:
        slot = survey.lint.setdefault((diagnostic.code, gen), [0, set()])
        slot[0] += 1
        slot[1].add(path.name)


def collect(corpus: Path, with_lint: bool = True) -> Survey:
    survey = Survey()
    for path in sorted(p for p in corpus.iterdir() if p.suffix in (".eds", ".EDS")):
        gen = survey.files[path.name] = generator(path)
        eds = load(path)
        for section_name, entry in beyond_2003(eds):
            if section_name not in spec.SECTIONS:
                survey.sections[section_name].add(path.name)
            if entry is not None:
                record_entry(survey.keywords[(section_name, family(entry.keyword))], path.name, entry)
        record_checks(survey, path.name, eds)
        if with_lint:
            record_lint(survey, path, gen)
    return survey


# --- classification by the tables --------------------------------------------------


def classify(section: str, keyword: str | None) -> str:
    """How edsconv.cip_tables knows a section (keyword None) or an entry keyword."""
    if keyword is not None and spec.is_vendor_keyword(keyword):
        return "vendor keyword (VendorID_keyword, C.4.1.2.2.11)"
    if keyword is None and spec.is_vendor_keyword(section):
        return "vendor section (VendorID_keyword, C.4.1.2.2.11)"
    if cip.vendor_class_section(section) is not None and keyword is None:
        return "vendor class section (Class<ID>_Vendor<VendorID>, practice)"
    target = cip.section_spec(section) if keyword is None else cip.entry_spec(section, keyword)
    if target is None or target.provenance is None:
        return "UNKNOWN"
    return "practice only" if target.provenance.practice_only else "eds-pie"


# --- report --------------------------------------------------------------------------


def _top(counter: Counter, limit: int = 4) -> str:
    return ", ".join(f"{key} ({count})" for key, count in counter.most_common(limit))


def _generators(survey: Survey, files: set[str]) -> str:
    return _top(Counter(survey.files[f] for f in files), 6)


def report_sections(survey: Survey) -> Iterator[str]:
    yield "## Sections beyond the 2003 text\n"
    yield "The 2003 sections with entries beyond it are in the next table.\n"
    yield "| section | files | tables | generators (files) |"
    yield "| --- | ---: | --- | --- |"
    for name, files in sorted(survey.sections.items(), key=lambda item: (-len(item[1]), item[0])):
        yield f"| [{name}] | {len(files)} | {classify(name, None)} | {_generators(survey, files)} |"


def report_keywords(survey: Survey) -> Iterator[str]:
    yield "\n## Entries beyond the 2003 text\n"
    yield ("Notations per field: position: notation (entries). Keywords and comments: the bare "
           "keywords and the `$` comments written at that field.\n")
    yield "| section | keyword | files | entries | tables | field counts | notations | keywords, comments |"
    yield "| --- | --- | ---: | ---: | --- | --- | --- | --- |"
    for (section, keyword), ev in sorted(survey.keywords.items(), key=lambda item: (item[0][0], -len(item[1].files))):
        notations = "; ".join(f"{pos}: {_top(c, 3)}" for pos, c in sorted(ev.notations.items())[:_SHOWN])
        words = "; ".join(f"{pos}: {_top(c, 3)}" for pos, c in sorted(ev.keywords.items())[:_SHOWN])
        comments = "; ".join(f"{pos}: {_top(c, 2)}" for pos, c in sorted(ev.comments.items())[:_SHOWN])
        extra = " / ".join(part for part in (words, comments) if part).replace("|", "\\|")
        yield (f"| [{section}] | {keyword} | {len(ev.files)} | {ev.entries} | {classify(section, ev.sample)} | "
               f"{_top(ev.field_counts, 3)} | {notations} | {extra} |")


def report_checks(survey: Survey) -> Iterator[str]:
    yield "\n## Object_Class_Code against the section's class ID\n"
    yield "| section | written | tables | files |"
    yield "| --- | --- | --- | ---: |"
    for (section, written, verdict), count in sorted(survey.class_codes.items()):
        yield f"| [{section}] | {written} | {verdict} | {count} |"
    yield "\n## IconContents decoded\n"
    for kind, count in Counter(survey.icons.values()).most_common():
        yield f"- {kind}: {count} files"
    yield "\n## InterfaceLabelN against [Ethernet Link Class] MaxInst\n"
    for verdict, count in sorted(survey.labels.items()):
        yield f"- {verdict}: {count} files"


def report_lint(survey: Survey) -> Iterator[str]:
    yield "\n## `edsconv lint` today, by code and generator\n"
    yield "| code | generator | diagnostics | files |"
    yield "| --- | --- | ---: | ---: |"
    for (code, gen), (count, files) in sorted(survey.lint.items()):
        yield f"| {code} | {gen} | {count} | {len(files)} |"
    unknown = [(s, k) for (s, k), ev in survey.keywords.items() if classify(s, ev.sample) == "UNKNOWN"]
    unknown += [(s, None) for s in survey.sections if classify(s, None) == "UNKNOWN"]
    yield "\n## Unknown to the tables\n"
    yield "\n".join(f"- [{s}] {k or '(section)'}" for s, k in sorted(unknown, key=str)) or "- none"


def report_summary(survey: Survey) -> Iterator[str]:
    """Entries and sections beyond the 2003 text by how the tables know them."""
    entries, files = Counter(), defaultdict(set)
    for (section, _), ev in survey.keywords.items():
        verdict = classify(section, ev.sample)
        entries[verdict] += ev.entries
        files[verdict] |= ev.files
    sections = Counter(classify(name, None) for name in survey.sections)
    yield "## Summary: how the tables know what the files write\n"
    yield "| tables | entries | files | distinct sections |"
    yield "| --- | ---: | ---: | ---: |"
    for verdict in sorted(set(entries) | set(sections)):
        yield f"| {verdict} | {entries[verdict]} | {len(files[verdict])} | {sections[verdict]} |"
    yield ""


def report(survey: Survey) -> str:
    gens = Counter(survey.files.values())
    head = ["# Survey of EDS content beyond ISO 15745-4:2003\n",
            f"Generated by `tools/survey_newer_content.py` over {len(survey.files)} real files.\n",
            "Generators: " + _top(gens, 20) + ".\n"]
    body = [*report_summary(survey), *report_sections(survey), *report_keywords(survey), *report_checks(survey)]
    if survey.lint:
        body += list(report_lint(survey))
    return "\n".join(head + body) + "\n"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("corpus", nargs="?", type=Path, default=DEFAULT_CORPUS)
    parser.add_argument("-o", "--output", type=Path, help="write the report here instead of stdout")
    parser.add_argument("--no-lint", action="store_true", help="skip the lint counts (faster)")
    args = parser.parse_args(argv)
    if not args.corpus.is_dir():
        print(f"no corpus at {args.corpus}", file=sys.stderr)
        return 2
    text = report(collect(args.corpus, with_lint=not args.no_lint))
    if args.output:
        args.output.write_text(text, encoding="utf-8")
    else:
        sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
