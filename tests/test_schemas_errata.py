"""Every name that differs between a spec listing and our restored schema is documented in ERRATA.md.

The spec text is read in place from ``shared/`` beside the repository; the test
skips when it is absent.
"""

from __future__ import annotations

import html
import re
from collections import Counter
from pathlib import Path

import pytest

from edsconv.resources import data_dir

SEED = Path(__file__).resolve().parents[1].parent / "shared" / "seeds" / "001_4555913419fc9159.txt"

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

_TAG = re.compile(r"<xsd:(\w+)([^<>]*)>")
_NAMING_ATTRIBUTE = re.compile(r'\b(name|ref|type)\s*=\s*"([^"]*)"')


def declared_names(xsd_text: str) -> Counter[tuple[str, str, str]]:
    """(component, attribute, value) for every name=/ref=/type= of an xsd: tag, with multiplicity."""
    return Counter((tag.group(1), attribute.group(1), attribute.group(2))
                   for tag in _TAG.finditer(html.unescape(xsd_text))
                   for attribute in _NAMING_ATTRIBUTE.finditer(tag.group(2)))


def errata_section(xsd: str) -> str:
    errata = (data_dir("schemas") / "ERRATA.md").read_text(encoding="utf-8")
    sections = re.split(r"^## ", errata, flags=re.M)
    matching = [s for s in sections if s.startswith(xsd)]
    assert matching, f"ERRATA.md has no section for {xsd}"
    return matching[0] + sections[1]  # with the section of decisions shared by several schemas


def _mentions(code_span: str, name: str) -> bool:
    return re.search(rf"(?<![\w-]){re.escape(name)}(?![\w-])", code_span) is not None


@pytest.fixture(scope="module")
def seed_lines() -> list[str]:
    if not SEED.is_file():
        pytest.skip(f"spec text {SEED} not available")
    return SEED.read_text(encoding="utf-8").split("\n")


def test_listing_ranges_hold_one_schema_each(seed_lines):
    for xsd, (first, last) in LISTINGS.items():
        listing = "\n".join(seed_lines[first - 1:last])
        assert listing.count("<xsd:schema") == 1, xsd
        assert seed_lines[first - 1].startswith("```") and seed_lines[last - 1].startswith("```"), xsd


@pytest.mark.parametrize("xsd", sorted(LISTINGS))
def test_every_name_difference_is_in_errata(seed_lines, xsd):
    first, last = LISTINGS[xsd]
    printed = declared_names("\n".join(seed_lines[first - 1:last]))
    ours = declared_names((data_dir("schemas") / xsd).read_text(encoding="utf-8"))
    section = errata_section(xsd)
    spans = re.findall(r"`([^`]*)`", section)
    undocumented = sorted({value for (_, _, value) in (printed - ours) + (ours - printed)
                           if not any(_mentions(span, value) for span in spans)})
    assert undocumented == [], f"name differences in {xsd} not explained in ERRATA.md"


def test_errata_mentions_every_schema():
    errata = (data_dir("schemas") / "ERRATA.md").read_text(encoding="utf-8")
    for xsd in LISTINGS:
        assert f"## {xsd}" in errata
