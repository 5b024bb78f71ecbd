"""Derive XSD 1.0 renditions of the two XSD 1.1 profile schemas, for lxml (libxml2).

    python schemas/derive_xsd10.py           # (re)write schemas/xsd10/*.xsd
    python schemas/derive_xsd10.py --check   # exit 1 when a derived file is stale

``CIP_Device_Profile.xsd`` and ``ENet_CommNet_Profile.xsd`` need XSD 1.1 (see
ERRATA.md): trailing ``##any`` wildcards compete with optional elements (Unique
Particle Attribution, which XSD 1.1 resolves in favour of the element), and one
assertion. libxml2 reads only XSD 1.0, so edsconv's write path validates against
renditions made from the restored 1.1 files by the rewrites below, and never by
hand: change a 1.1 schema, run this script, and tests/test_xsd10.py checks the
renditions are current and accept and reject what the 1.1 schemas do.

Rewrites (each raises SchemaShapeError on a shape it was not written for, so
that a change to the 1.1 schemas cannot silently produce a wrong rendition):

1. A trailing ``<any namespace="##any"/>`` that competes with an optional or
   repeated element declaration before it, and a ``##any`` wildcard in a
   repeated choice of elements, become ``##other``. In XSD 1.1 (as xmlschema
   implements it) such a wildcard never takes an element that a competing
   declaration could still take, and always takes a namespace-qualified one; in
   XSD 1.0 a wildcard cannot exclude names, only namespaces. The schemas have no
   target namespace, so every declaration is unqualified and ``##other`` keeps
   exactly the namespace-qualified extension elements. A wildcard after a
   required single element has no competitor and keeps ``##any``.
   Every trailing wildcard run ``any*`` is written ``(any)*``, a repeated
   sequence of one wildcard: the same language, but libxml2 2.14 compiles
   ``a*, any*`` wrongly (it accepts ``a`` after a wildcard match);
   tests/test_xsd10.py compares lxml with xmlschema's XSD 1.0 reading of the
   same rendition to catch such differences.
2. A complex type extending a type whose content ends in a wildcard
   (``et_ProxyParamType``) gets the base's particles copied, with that wildcard
   as ``##other`` (the extension's elements follow it), then its own.
3. ``<assert test="A or B or C"/>`` over a sequence of optional particles naming
   exactly A, B and C ("at least one of them") becomes a choice of one branch
   per particle: that particle required, the ones after it optional. Repeated
   particles go into named model groups, so each element keeps one declaration.

The one deviation (rewrites 1 and 2): an element without a namespace in an
extension point whose wildcard competes with element declarations is accepted
by the 1.1 schema when no competing declaration can take it, and rejected by
the rendition. The renditions are never more permissive; see xsd10/README.md.
"""

from __future__ import annotations

import argparse
import copy
import sys
from collections.abc import Callable
from pathlib import Path

from lxml import etree

XSD = "http://www.w3.org/2001/XMLSchema"
Q = f"{{{XSD}}}"
SCHEMAS = Path(__file__).resolve().parent
OUT = SCHEMAS / "xsd10"
SOURCES = ("CIP_Device_Profile.xsd", "ENet_CommNet_Profile.xsd")
PARTICLES = {Q + "element", Q + "any", Q + "sequence", Q + "choice", Q + "group"}
NOTICE = (" DERIVED FILE, do not edit: XSD 1.0 rendition of ../{name} written by schemas/derive_xsd10.py"
          " for lxml (libxml2). The restored XSD 1.1 schema stays the reference; see xsd10/README.md ")


class SchemaShapeError(Exception):
    """The 1.1 schema has a shape the rewrites were not written for: extend the script."""


def occurs(particle: etree._Element) -> tuple[int, float]:
    maximum = particle.get("maxOccurs", "1")
    return int(particle.get("minOccurs", "1")), float("inf") if maximum == "unbounded" else int(maximum)


def is_trailing_any(element: etree._Element) -> bool:
    return (element.tag == Q + "any" and element.get("namespace") == "##any"
            and occurs(element) == (0, float("inf")) and element.get("processContents") == "lax")


def particles(group: etree._Element) -> list[etree._Element]:
    return [child for child in group if child.tag in PARTICLES]


def extended_types(root: etree._Element) -> set[str]:
    """Names of the global complex types that another type extends with further particles."""
    return {extension.get("base") for extension in root.iter(Q + "extension")
            if extension.getparent().tag == Q + "complexContent" and particles(extension)}


def rewrite_wildcard(wild: etree._Element, extended: set[str]) -> None:
    """Rewrite 1 for one ``##any`` wildcard."""
    parent = wild.getparent()
    if parent.tag == Q + "choice":
        if not all(p.tag in (Q + "element", Q + "any") for p in particles(parent)) or occurs(parent)[1] < 2:
            raise SchemaShapeError(f"line {wild.sourceline}: a wildcard in a choice of another shape")
        wild.set("namespace", "##other")
        wild.attrib.pop("minOccurs", None)
        wild.attrib.pop("maxOccurs", None)
        parent.set("minOccurs", "0")  # the wildcard made the choice emptiable; the choice now says so
        return
    siblings = particles(parent)
    if parent.tag != Q + "sequence" or siblings[-1] is not wild or not is_trailing_any(wild):
        raise SchemaShapeError(f"line {wild.sourceline}: a wildcard that does not end a sequence")
    holder = parent.getparent()
    if occurs(parent) != (1, 1) or holder.tag != Q + "complexType":
        raise SchemaShapeError(f"line {wild.sourceline}: a wildcard whose sequence is nested or repeated")
    if holder.get("name") in extended:
        return  # rewrite 2 copies this content into the extending type first; derive() comes back to it
    before = siblings[-2] if len(siblings) > 1 else None
    if before is not None and before.tag not in (Q + "element", Q + "choice", Q + "sequence"):
        raise SchemaShapeError(f"line {wild.sourceline}: a wildcard after a {before.tag}")
    competes = before is not None and not (before.tag == Q + "element" and occurs(before) == (1, 1))
    repeat_run(wild, "##other" if competes else "##any")


def repeat_run(wild: etree._Element, namespace: str) -> None:
    """Write the trailing ``any*`` as ``(any)*`` over ``namespace`` (see rewrite 1)."""
    run = etree.Element(Q + "sequence", minOccurs="0", maxOccurs="unbounded")
    etree.SubElement(run, Q + "any", namespace=namespace, processContents="lax")
    run.tail = wild.tail
    wild.getparent().replace(wild, run)


def inline_extension(root: etree._Element, complex_type: etree._Element) -> None:
    """Rewrite 2: ``complex_type`` extends a base ending in a wildcard; copy the base's particles into it."""
    extension = complex_type.find(f"{Q}complexContent/{Q}extension")
    base = root.find(f"{Q}complexType[@name='{extension.get('base')}']")
    base_sequence = base.find(Q + "sequence")
    if (len(base) != 1 or base_sequence is None or not is_trailing_any(particles(base_sequence)[-1])
            or [c.tag for c in extension if c.tag in PARTICLES] != [Q + "sequence"]):
        raise SchemaShapeError(f"line {complex_type.sourceline}: an extension of another shape")
    sequence = copy.deepcopy(base_sequence)
    repeat_run(particles(sequence)[-1], "##other")
    own = extension.find(Q + "sequence")
    for particle in particles(own):
        sequence.append(copy.deepcopy(particle))
    content = complex_type.find(Q + "complexContent")
    attributes = [copy.deepcopy(c) for c in extension if c.tag not in PARTICLES]
    complex_type.remove(content)
    complex_type.append(sequence)
    complex_type.extend(attributes)


def at_least_one_of(assertion: etree._Element) -> None:
    """Rewrite 3 for ``<assert test="A or B ..."/>`` over a sequence of optional particles."""
    complex_type = assertion.getparent()
    sequence = complex_type.find(Q + "sequence")
    names = [name.strip() for name in assertion.get("test", "").split(" or ")]
    members = particles(sequence) if sequence is not None else []
    named = [[p.get("name")] if p.tag == Q + "element" else [e.get("name") for e in particles(p)] for p in members]
    if (not members or any(occurs(p)[0] != 0 for p in members) or sorted(sum(named, [])) != sorted(names)
            or any(p.tag not in (Q + "element", Q + "choice") for p in members)):
        raise SchemaShapeError(f"line {assertion.sourceline}: an assertion other than 'at least one of'")
    schema = assertion.getroottree().getroot()
    holder = complex_type.getparent().get("name", "anonymous")
    groups = []
    for index, particle in enumerate(members):
        group = etree.Element(Q + "group", name=f"xsd10_{holder}_{index + 1}")
        body = etree.SubElement(group, Q + "sequence")
        single = copy.deepcopy(particle)
        single.attrib.pop("minOccurs", None)
        body.append(single)
        schema.append(group)
        groups.append(group.get("name"))
    choice = etree.Element(Q + "choice")
    for index in range(len(groups)):
        branch = etree.SubElement(choice, Q + "sequence")
        for later, name in enumerate(groups[index:]):
            reference = etree.SubElement(branch, Q + "group", ref=name)
            if later:
                reference.set("minOccurs", "0")
    complex_type.replace(sequence, choice)
    complex_type.remove(assertion)


def inline_fixed_reference(use: etree._Element) -> None:
    """Rewrite 4 for one ``<attribute ref=... fixed=...>`` use."""
    schema = use.getroottree().getroot()
    name = use.get("ref")
    declaration = schema.find(f"{Q}attribute[@name='{name}']")
    if schema.get("targetNamespace") or declaration is None or ":" in name or set(use.attrib) - {"ref", "fixed", "use"}:
        raise SchemaShapeError(f"line {use.sourceline}: a fixed attribute reference of another shape")
    local = copy.deepcopy(declaration)
    local.attrib.update({key: value for key, value in use.attrib.items() if key != "ref"})
    local.tail = use.tail
    use.getparent().replace(use, local)


def derive(source: Path) -> bytes:
    """The XSD 1.0 rendition of the 1.1 schema ``source``, as bytes."""
    tree = parse_beside(source)
    root = tree.getroot()
    extended = extended_types(root)
    for use in [a for a in root.iter(Q + "attribute") if a.get("ref") and a.get("fixed") is not None]:
        inline_fixed_reference(use)
    for assertion in list(root.iter(Q + "assert", Q + "assertion")):
        at_least_one_of(assertion)
    for wild in [w for w in root.iter(Q + "any") if w.get("namespace") == "##any"]:
        rewrite_wildcard(wild, extended)
    for complex_type in list(root.iter(Q + "complexType")):
        extension = complex_type.find(f"{Q}complexContent/{Q}extension")
        if extension is not None and extension.get("base") in extended and particles(extension):
            inline_extension(root, complex_type)
    for name in extended:  # the bases themselves: their trailing wildcard, left for rewrite 2, now gets rewrite 1
        base = root.find(f"{Q}complexType[@name='{name}']")
        if base is not None and base.find(Q + "sequence") is not None:
            rewrite_wildcard(particles(base.find(Q + "sequence"))[-1], set())
    return finish(tree, NOTICE.format(name=source.name))


# --- shared with derive_as_printed.py: files derived into a subdirectory of schemas/ ---------

def parse_beside(source: Path) -> etree._ElementTree:
    """``source`` parsed, its include, redefine and import locations made to work one directory down."""
    tree = etree.parse(str(source), etree.XMLParser(remove_blank_text=True))
    for location in tree.getroot().iter(Q + "include", Q + "redefine", Q + "import"):
        location.set("schemaLocation", "../" + location.get("schemaLocation"))
    return tree


def finish(tree: etree._ElementTree, notice: str) -> bytes:
    """The derived schema's bytes, with ``notice`` as its first comment."""
    tree.getroot().insert(0, etree.Comment(notice))
    etree.indent(tree, space="  ")
    return etree.tostring(tree, xml_declaration=True, encoding="UTF-8") + b"\n"


def stale(directory: Path = SCHEMAS, out: str = OUT.name, sources: tuple[str, ...] = SOURCES,
          derive_one: Callable[[Path], bytes] = derive) -> list[str]:
    """The derived files that differ from what this script writes now."""
    return [name for name in sources
            if not (directory / out / name).is_file()
            or (directory / out / name).read_bytes() != derive_one(directory / name)]


def main(description: str = __doc__, out: str = OUT.name, sources: tuple[str, ...] = SOURCES,
         derive_one: Callable[[Path], bytes] = derive, script: str = Path(__file__).name) -> int:
    parser = argparse.ArgumentParser(description=description.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="only report stale files (exit 1)")
    if parser.parse_args().check:
        names = stale(SCHEMAS, out, sources, derive_one)
        for name in names:
            print(f"schemas/{out}/{name} is stale: run python schemas/{script}", file=sys.stderr)
        return 1 if names else 0
    (SCHEMAS / out).mkdir(exist_ok=True)
    for name in sources:
        (SCHEMAS / out / name).write_bytes(derive_one(SCHEMAS / name))
        print(f"wrote {SCHEMAS / out / name}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
