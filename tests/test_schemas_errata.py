"""Every difference between a spec listing and our restored schema is in ERRATA.md.

The listings and our files are compared tag by tag, in document order: every
``xsd:`` tag with all its attributes (name, ref, type, base, minOccurs,
maxOccurs, use, fixed, default, namespace, processContents, and the value of
patterns, enumerations and other facets). Layout and comments do not count.
ERRATA.md's tables say where the two may differ:

- a deliberate deviation whose Used column is only attributes is applied to the
  printed tags it selects (its Printed column: the tag and the attributes that
  select it; its Seed column: ``every`` or seed lines) before the comparison;
- every remaining difference (a run of changed, removed or added tags) must lie
  within the Seed lines of a row of its schema's table (or of a deviation row),
  and the names it changes (name=, ref=, type=, base= values) must stand in
  backticks in such a row; every row must cover a difference.

The spec text is read in place from ``shared/`` beside the repository; the test
skips when it is absent.
"""

from __future__ import annotations

import difflib
import html
import re
from dataclasses import dataclass
from pathlib import Path

import pytest

from edsconv.resources import data_dir

SEED = Path(__file__).resolve().parents[1].parent / "shared" / "seeds" / "001_4555913419fc9159.txt"
ERRATA = data_dir("schemas") / "ERRATA.md"

# Schema file -> first and last line (1-based, inclusive) of its listing in the seed text.
LISTINGS = {
    "ADS-net_Device_Profile.xsd": (812, 1024),
    "ADS-net_CommNet_Profile.xsd": (1218, 1626),
    "FL-net_Device_Profile.xsd": (1707, 1996),
    "FL-net_CommNet_Profile.xsd": (2123, 2563),
    "MasterTemplateTypes.xsd": (2669, 2744),
    "CIPDataTypes.xsd": (2750, 2918),
    "CIP_Device_Profile.xsd": (2924, 4030),
    "EDS_Device_Profile_wrapper.xsd": (4060, 4167),
    "ENet_CommNet_Profile.xsd": (4245, 5220),
    "EDS_CommNet_Profile_wrapper.xsd": (5236, 5313),
}

_TAG = re.compile(r'<(/?)xsd:(\w+)((?:\s+[\w:.-]+\s*=\s*"[^"]*")*)\s*(/?)>')
_ATTRIBUTE = re.compile(r'([\w:.-]+)\s*=\s*"([^"]*)"')
_COMMENT = re.compile(r"<!--.*?-->", re.S)
_NAMING = ("name", "ref", "type", "base")
_SEED_ITEM = re.compile(r"(\d+)(?:-(\d+))?")

#: (kind, tag, sorted attributes): "open" or "close"; a self-closing tag gives both.
Tag = tuple[str, str, tuple[tuple[str, str], ...]]


@dataclass(frozen=True)
class Located:
    tag: Tag
    line: int


def tags(text: str, first_line: int = 1) -> list[Located]:
    """The xsd: tags of a listing or schema in document order, with their line."""
    text = _COMMENT.sub(lambda comment: "\n" * comment.group(0).count("\n"), html.unescape(text))
    found = []
    for match in _TAG.finditer(text):
        line = first_line + text.count("\n", 0, match.start())
        closing, name, attributes, empty = match.groups()
        if not closing:
            found.append(Located(("open", name, tuple(sorted(_ATTRIBUTE.findall(attributes)))), line))
        if closing or empty:
            found.append(Located(("close", name, ()), line))
    return found


@dataclass(frozen=True)
class Row:
    """A row of an ERRATA.md table: the seed lines it speaks of and its backticked spans."""
    lines: frozenset[int]
    every: bool
    spans: tuple[str, ...]
    cells: tuple[str, ...]


def seed_lines(cell: str) -> frozenset[int]:
    lines: set[int] = set()
    for first, last in _SEED_ITEM.findall(cell):
        lines.update(range(int(first), int(last or first) + 1))
    return frozenset(lines)


def table_rows(section: str) -> list[Row]:
    """The rows of the tables of one ERRATA.md section whose header has a Seed column."""
    rows, seed_column = [], None
    for line in section.splitlines():
        if not line.startswith("|"):
            seed_column = None
            continue
        cells = tuple(cell.strip() for cell in line.strip().strip("|").split(" | "))
        if seed_column is None:
            seed_column = cells.index("Seed") if "Seed" in cells else -1
        elif seed_column >= 0 and not set(cells[0]) <= set("- "):
            seed = cells[seed_column]
            rows.append(Row(seed_lines(seed), seed == "every", tuple(re.findall(r"`([^`]*)`", line)), cells))
    return rows


def errata_sections() -> dict[str, str]:
    sections = re.split(r"^## ", ERRATA.read_text(encoding="utf-8"), flags=re.M)[1:]
    return {section.split("\n", 1)[0].split(" (")[0].strip(): section for section in sections}


@dataclass(frozen=True)
class Deviation:
    """A deliberate deviation that adds attributes to the printed tags it selects."""
    row: Row
    tag: str
    selector: tuple[tuple[str, str], ...]
    added: tuple[tuple[str, str], ...]

    def applies(self, located: Located) -> bool:
        kind, tag, attributes = located.tag
        return kind == "open" and tag == self.tag and set(self.selector) <= set(attributes) \
            and (self.row.every or located.line in self.row.lines)

    def apply(self, located: Located) -> Located:
        kind, tag, attributes = located.tag
        merged = dict(self.added) | dict(attributes)
        return Located((kind, tag, tuple(sorted(merged.items()))), located.line)


def deviations() -> tuple[list[Deviation], list[Row]]:
    """The deliberate deviations: those applied as attribute additions, and the located ones."""
    applied, located = [], []
    for row in table_rows(errata_sections()["Deliberate deviations"]):
        printed, used = row.cells[2], row.cells[3]
        selector = re.fullmatch(r"`<xsd:(\w+)((?:\s+[\w:.-]+=\"[^\"]*\")*)>`", printed)
        added = re.fullmatch(r"`((?:\s*[\w:.-]+=\"[^\"]*\")+)`", used)
        if selector and added:
            applied.append(Deviation(row, selector.group(1), tuple(_ATTRIBUTE.findall(selector.group(2))),
                                     tuple(_ATTRIBUTE.findall(added.group(1)))))
        elif row.lines:
            located.append(row)
    return applied, located


@dataclass(frozen=True)
class Difference:
    lines: frozenset[int]
    names: frozenset[str]


def differences(printed: list[Located], ours: list[Located]) -> list[Difference]:
    """The runs where the two tag sequences differ. A run of removed or added tags
    that could sit at several places among equal tags is put at the last one."""
    a, b = [located.tag for located in printed], [located.tag for located in ours]
    found = []
    for op, i1, i2, j1, j2 in difflib.SequenceMatcher(None, a, b, autojunk=False).get_opcodes():
        if op == "equal":
            continue
        while op == "delete" and i2 < len(a) and a[i1] == a[i2] or op == "insert" and j2 < len(b) and b[j1] == b[j2]:
            i1, i2, j1, j2 = i1 + 1, i2 + 1, j1 + 1, j2 + 1
        lines = {printed[i].line for i in range(i1, i2)} or {printed[max(i1 - 1, 0)].line}
        names = {value for tag in a[i1:i2] + b[j1:j2] for key, value in tag[2] if key in _NAMING}
        unchanged = {value for tag in a[i1:i2] for key, value in tag[2] if key in _NAMING} & \
                    {value for tag in b[j1:j2] for key, value in tag[2] if key in _NAMING}
        found.append(Difference(frozenset(lines), frozenset(names - unchanged)))
    return found


def mentioned(name: str, rows: list[Row]) -> bool:
    return any(re.search(rf"(?<![\w-]){re.escape(name)}(?![\w-])", span) for row in rows for span in row.spans)


@pytest.fixture(scope="module")
def seed_text() -> list[str]:
    if not SEED.is_file():
        pytest.skip(f"spec text {SEED} not available")
    return SEED.read_text(encoding="utf-8").split("\n")


def printed_and_ours(seed_text: list[str], xsd: str) -> tuple[list[Located], list[Located]]:
    first, last = LISTINGS[xsd]
    printed = tags("\n".join(seed_text[first - 1:last]), first)
    for deviation in deviations()[0]:
        printed = [deviation.apply(located) if deviation.applies(located) else located for located in printed]
    return printed, tags((data_dir("schemas") / xsd).read_text(encoding="utf-8"))


def test_listing_ranges_hold_one_schema_each(seed_text):
    for xsd, (first, last) in LISTINGS.items():
        listing = "\n".join(seed_text[first - 1:last])
        assert listing.count("<xsd:schema") == 1, xsd
        assert seed_text[first - 1].startswith("```") and seed_text[last - 1].startswith("```"), xsd


@pytest.mark.parametrize("xsd", sorted(LISTINGS))
def test_every_difference_is_in_errata(seed_text, xsd):
    printed, ours = printed_and_ours(seed_text, xsd)
    rows = table_rows(errata_sections()[xsd]) + deviations()[1]
    undocumented = []
    for difference in differences(printed, ours):
        covering = [row for row in rows if row.lines & difference.lines]
        if not difference.lines <= frozenset().union(*(row.lines for row in covering)):
            undocumented.append(f"seed {sorted(difference.lines)}: no ERRATA.md row gives these lines")
        undocumented += [f"seed {sorted(difference.lines)}: `{name}` not named in its row"
                         for name in sorted(difference.names) if not mentioned(name, covering)]
    assert undocumented == [], f"{xsd}: differences from the listing that ERRATA.md does not explain"


@pytest.mark.parametrize("xsd", sorted(LISTINGS))
def test_every_errata_row_speaks_of_a_difference(seed_text, xsd):
    printed, ours = printed_and_ours(seed_text, xsd)
    changed = frozenset().union(*(difference.lines for difference in differences(printed, ours)))
    first, last = LISTINGS[xsd]
    rows = table_rows(errata_sections()[xsd]) + [row for row in deviations()[1] if min(row.lines) in
                                                  range(first, last + 1)]
    stale = [row.cells[0] for row in rows if not row.lines & changed]
    assert stale == [], f"{xsd}: ERRATA.md rows at seed lines where the schema does not differ"


def test_every_applied_deviation_selects_printed_tags(seed_text):
    printed = [located for xsd, (first, last) in LISTINGS.items()
               for located in tags("\n".join(seed_text[first - 1:last]), first)]
    for deviation in deviations()[0]:
        selected = {located.line for located in printed if deviation.applies(located)}
        assert selected, f"deviation {deviation.row.cells[0]} selects no printed tag"
        assert deviation.row.every or selected == deviation.row.lines, deviation.row.cells[0]


def test_errata_has_a_section_for_every_schema_and_the_deviations():
    assert set(errata_sections()) >= {*LISTINGS, "Deliberate deviations"}
