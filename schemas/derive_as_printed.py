"""Derive the as-printed variants of the schemas whose wildcards deviate from the listings.

    python schemas/derive_as_printed.py           # (re)write schemas/as_printed/*.xsd
    python schemas/derive_as_printed.py --check   # exit 1 when a derived file is stale

Two deliberate deviations of ERRATA.md change the listings' ``xsd:any`` wildcards:
``wildcard-lax`` adds ``processContents="lax"`` to every one (printed without it, that is
``strict``), and ``wildcard-bounds`` gives seven of them ``minOccurs="0"
maxOccurs="unbounded"`` (printed without bounds, that is exactly one element). The
variants written here take both back and keep every damage repair, so that ``edsconv
validate --as-printed`` shows what a document gets from the wildcards as the standard prints
them. The one deviation they keep is XSD 1.1 for the two CIP profile schemas: read as XSD
1.0, the listings are not valid schemas at all.

Never edit the variants by hand: change the restored schema, run this script;
tests/test_as_printed.py checks the variants are current and that each wildcard has the
attributes the listing prints.
"""

from __future__ import annotations

import sys
from pathlib import Path

from lxml import etree

# run as a script or loaded from its path: derive_xsd10.py beside it has the shared steps
sys.path.insert(0, str(Path(__file__).resolve().parent))
import derive_xsd10  # noqa: E402
from derive_xsd10 import Q, finish, parse_beside  # noqa: E402

OUT = "as_printed"
#: Schema -> the elements whose wildcard the listing prints without occurrence bounds (1..1),
#: ERRATA.md deviation wildcard-bounds. Every other wildcard is printed as our schemas have it.
PRINTED_SINGLE = {
    "CIP_Device_Profile.xsd": ("DeviceIdentity_InstanceAttributes", "DeviceIdentity_InstanceOperations",
                               "DeviceManager"),
    "EDS_Device_Profile_wrapper.xsd": ("DeviceIdentity", "DeviceManager", "DeviceFunction", "ApplicationProcess"),
    "ENet_CommNet_Profile.xsd": (),
    "FL-net_Device_Profile.xsd": (),
}
NOTICE = (" DERIVED FILE, do not edit: ../{name} with its wildcards as ISO 15745-4:2003 prints them (no"
          " processContents, the printed occurrence bounds), written by schemas/derive_as_printed.py;"
          " see ERRATA.md, deviations wildcard-lax and wildcard-bounds ")


class SchemaShapeError(Exception):
    """The restored schema does not have the wildcards this script expects: extend it."""


def owner(wildcard: etree._Element) -> str:
    """The name of the element declaration whose content the wildcard belongs to."""
    for ancestor in wildcard.iterancestors(Q + "element"):
        if ancestor.get("name"):
            return str(ancestor.get("name"))
    return ""


def derive(source: Path) -> bytes:
    """The as-printed variant of the restored schema ``source``, as bytes."""
    tree = parse_beside(source)
    root = tree.getroot()
    single = PRINTED_SINGLE[source.name]
    bounded: list[str] = []
    for wildcard in root.iter(Q + "any"):
        if wildcard.get("processContents") != "lax":
            raise SchemaShapeError(f"line {wildcard.sourceline}: a wildcard without processContents=\"lax\"")
        del wildcard.attrib["processContents"]
        if owner(wildcard) in single:
            if (wildcard.get("minOccurs"), wildcard.get("maxOccurs")) != ("0", "unbounded"):
                raise SchemaShapeError(f"line {wildcard.sourceline}: the wildcard of {owner(wildcard)} is not "
                                       "0..unbounded")
            del wildcard.attrib["minOccurs"], wildcard.attrib["maxOccurs"]
            bounded.append(owner(wildcard))
    if sorted(bounded) != sorted(single):
        raise SchemaShapeError(f"{source.name}: wildcards found in {bounded}, expected one in each of {single}")
    return finish(tree, NOTICE.format(name=source.name))


def stale() -> list[str]:
    """The derived files that differ from what this script writes now."""
    return derive_xsd10.stale(derive_xsd10.SCHEMAS, OUT, tuple(PRINTED_SINGLE), derive)


if __name__ == "__main__":
    sys.exit(derive_xsd10.main(__doc__, OUT, tuple(PRINTED_SINGLE), derive, Path(__file__).name))
