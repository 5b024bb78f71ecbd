"""What the templates draw besides the document: the drawings, the anchors of the entries, the lint
verdict with each finding linked to the entry it is about, and the marks of a comparison.

An entry shown on the page has the id ``e-KEYWORD`` (``Param3``, ``Assem100``, ``Connection1``,
``Group2``, ``Port1``; a side's prefix before it on the comparison page); each part has the id of
its ``--section`` name.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable
from typing import TYPE_CHECKING

from edsconv.diagnostics import Severity
from edsconv.html.drawing import bit_map, capacity_charts
from edsconv.html.text import bits_text, cell, endpoint_text, member_text, reference_text

if TYPE_CHECKING:
    from edsconv.diagnostics import Diagnostic
    from edsconv.eds.syntax import EdsFile

#: the part of the page each EDS section's findings link to when its entry has no anchor of its own
_SECTION_PART = {"File": "identity", "Device": "identity", "Device Classification": "identity",
                 "ParamClass": "parameters", "Params": "parameters", "EnumParams": "parameters", "Groups": "groups",
                 "Assembly": "assemblies", "Connection Manager": "connections", "Port": "ports",
                 "Capacity": "capacity", "Modular": "modular"}

#: the parts that have a heading of their own, with the document keys that make them present
_PARTS = (("identity", "Identity", ("identity",)), ("parameters", "Parameters", ("parameters",)),
          ("groups", "Groups", ("groups",)), ("assemblies", "Assemblies", ("assemblies", "extended_assemblies")),
          ("connections", "Connections", ("connections",)), ("ports", "Ports", ("ports",)),
          ("capacity", "Capacity", ("capacity",)),
          ("more", "More", ("modular", "network", "object_classes", "devicenet", "other_sections", "extra_entries")))


def _entry_ids(document: dict) -> list[str]:
    keywords = [p["keyword"] for p in document.get("parameters", ())]
    keywords += [a["keyword"] for a in (*document.get("assemblies", ()), *document.get("extended_assemblies", ()))]
    keywords += [c["keyword"] for c in document.get("connections", ())]
    keywords += [f"Group{g['number']}" for g in document.get("groups", ())]
    keywords += [f"Port{p['number']}" for p in document.get("ports", ())]
    return keywords


def _joined(*values: object) -> str:
    from edsconv.html.text import cell

    return " ".join(filter(None, map(cell, values)))


def identity_rows(document: dict) -> list[tuple[str, str, str]]:
    """(label, what a comparison calls the field(s), separated by ``|``, the text) of the identity facts."""
    from edsconv.html.text import revision

    identity, file = document.get("identity"), document.get("file")
    if not identity or not file:
        return []
    networks = ", ".join(_joined(c["classification"] or "?", *c["subclassifications"])
                         for c in document.get("classifications", ()))
    i, f = identity, file
    return [
        ("Product", "identity.product_name", _joined(i["product_name"])),
        ("Vendor", "identity.vendor_code|identity.vendor_name", _joined(i["vendor_code"], i["vendor_name"])),
        ("Product type", "identity.product_type|identity.product_type_string",
         _joined(i["product_type"], i["product_type_string"])),
        ("Product code", "identity.product_code", _joined(i["product_code"])),
        ("Revision", "identity.major_revision|identity.minor_revision",
         revision(i["major_revision"], i["minor_revision"])),
        ("Catalog", "identity.catalog", _joined(i["catalog"])),
        ("Icon file", "identity.icon", _joined(i["icon"])),
        ("Networks", "Class1|Class2|Class3|Class4", networks),
        ("Description", "file.description", _joined(f["description"])),
        ("File revision", "file.revision", _joined(f["revision"])),
        ("Created", "file.create_date|file.create_time", _joined(f["create_date"], f["create_time"])),
        ("Modified", "file.mod_date|file.mod_time", _joined(f["mod_date"], f["mod_time"])),
        ("Home URL", "file.home_url", _joined(f["home_url"])),
    ]


def _formats(connections: list[dict], maps: dict[str, dict | None]) -> list[dict]:
    """The assemblies with a drawing that are connection formats, each once: its keyword, and the words that
    name it and the connections (with their direction) that use it."""
    users: dict[str, list[str]] = {}
    names: dict[str, str] = {}
    for c in connections:
        for direction, arrow in (("O=>T", "O→T"), ("T=>O", "T→O")):
            endpoint = c[direction]
            ref = endpoint and endpoint["format"]
            if ref and ref.get("kind") == "assembly" and maps.get(ref["keyword"]):
                users.setdefault(ref["keyword"], []).append(f"{c['keyword']} {arrow}")
                names[ref["keyword"]] = f" “{ref['name']}”" if ref.get("name") else ""
    return [{"keyword": keyword, "summary": f"{keyword}{names[keyword]}: {', '.join(used)}"}
            for keyword, used in users.items()]


def _trigger_text(tt: dict | None) -> str:
    if not tt:
        return ""
    if tt.get("classes") is None:
        return cell(tt["value"])
    return "; ".join((", ".join(tt["triggers"]) or "no trigger", ", ".join(tt["class_names"]) or "no class",
                      ", ".join(tt["transport"]), tt["role"]))


def _endpoint_rows(endpoint: dict | None) -> list[tuple[str, str]] | None:
    """(label, text) of a direction's RPI, size and format; None when the connection does not use it."""
    if not endpoint:
        return None
    rows = [("RPI", endpoint_text(endpoint.get("rpi"), " µs")), ("size", endpoint_text(endpoint["size"], " bytes")),
            ("format", reference_text(endpoint["format"]))]
    return [(label, text) for label, text in rows if text]


def _connection_rows(connections: list[dict], marks: dict[str, str]) -> list[dict]:
    """The cells of the connections table, each with its mark on the comparison page."""
    rows = []
    for c in connections:
        keyword, path = c["keyword"], c["path"]
        summary = path and path.get("summary")
        rows.append({
            "keyword": keyword, "name": c["name"], "trigger": _trigger_text(c["trigger_transport"]),
            "o_to_t": _endpoint_rows(c["O=>T"]), "t_to_o": _endpoint_rows(c["T=>O"]),
            "path": path["text"] if path else "", "summary": summary if summary and summary != path["text"] else "",
            "marks": {} if not marks else {  # empty marks print no class attribute
                "row": mark(marks, keyword), "trigger": mark(marks, keyword, "trigger_transport"),
                "o_to_t": mark(marks, keyword, "O=>T RPI", "O=>T size", "O=>T format"),
                "t_to_o": mark(marks, keyword, "T=>O RPI", "T=>O size", "T=>O format"),
                "path": mark(marks, keyword, "path")},
        })
    return rows


def _member_rows(assembly: dict, prefix: str, anchors: set[str], marks: dict[str, str]) -> list[dict]:
    """The member list of an assembly: its bits, the link to the member's entry and the rest of its text."""
    rows = []
    for index, member in enumerate(assembly["members"], 1):
        what = member["member"]
        keyword = what.get("keyword") if what["kind"] in ("parameter", "assembly") else None
        href = f"{prefix}e-{keyword}" if keyword and f"{prefix}e-{keyword}" in anchors else None
        words = member_text(what)
        where = bits_text(member["offset"], member["bits"]) if member["offset"] is not None else \
            f"{cell(member['bits']) or '?'} bits"  # at an unknown place: its size, which the drawing cannot show
        rows.append({"bits": where,
                     "href": href, "keyword": keyword if href else None,
                     "rest": words[len(keyword):] if href and keyword and words.startswith(keyword) else words,
                     "mark": mark(marks, f"{assembly['keyword']} member {index}") if marks else ""})
    return rows


def device_view(document: dict, prefix: str, marks: dict[str, str]) -> dict:
    """The document with what its templates look up: entries by keyword, drawings, anchors, parts."""
    parameters = {p["keyword"]: p for p in document.get("parameters", ())}
    assemblies = {a["keyword"]: a for a in (*document.get("assemblies", ()), *document.get("extended_assemblies", ()))}
    parts = [(key, title) for key, title, keys in _PARTS if any(document.get(k) for k in keys)]
    anchors = {f"{prefix}e-{keyword}" for keyword in _entry_ids(document)} | {prefix + key for key, _ in parts}
    maps = {keyword: bit_map(assembly) for keyword, assembly in assemblies.items()}
    for drawing in filter(None, maps.values()):
        for block in drawing["blocks"]:
            block["href"] = f"{prefix}e-{block['keyword']}" if f"{prefix}e-{block['keyword']}" in anchors else None
    return {
        "doc": document, "prefix": prefix, "marks": marks, "parameters": parameters, "assemblies": assemblies,
        "maps": maps, "formats": _formats(document.get("connections", []), maps), "anchors": anchors,
        "connections": _connection_rows(document.get("connections", []), marks),
        "members": {keyword: _member_rows(a, prefix, anchors, marks) for keyword, a in assemblies.items()},
        "charts": capacity_charts(document.get("capacity")), "parts": parts, "identity": identity_rows(document),
    }


def _places(eds: EdsFile) -> tuple[list[int], list[tuple[str, str | None]]]:
    """The first line of every section and entry, in file order, and (section, keyword or None) of each."""
    lines: list[int] = []
    places: list[tuple[str, str | None]] = []
    for section in eds.sections:
        lines.append(section.line)
        places.append((section.name, None))
        for entry in section.entries:
            lines.append(entry.line)
            places.append((section.name, entry.keyword))
    return lines, places


def _target(place: tuple[str, str | None] | None, anchors: set[str]) -> tuple[str | None, str]:
    """The anchor of the entry (else the part) a finding is about, and the words of the link."""
    if place is None:
        return None, ""
    section, keyword = place
    if keyword is not None:
        if section == "EnumParams":  # EnumN lists the values of ParamN (C.4.1.4.6)
            keyword = keyword.replace("Enum", "Param", 1)
        if f"e-{keyword}" in anchors:
            return f"e-{keyword}", keyword
    part = _SECTION_PART.get(section)
    return (part if part in anchors else None), f"[{section}]"


def verdict(diagnostics: Iterable[Diagnostic], eds: EdsFile | None, anchors: set[str]) -> dict:
    """The lint verdict: counts by severity and every finding, linked to its entry where the page shows it."""
    import bisect

    lines, places = _places(eds) if eds is not None else ([], [])
    findings = []
    for d in sorted(diagnostics, key=lambda d: (d.line, d.column)):
        at = bisect.bisect_right(lines, d.line) - 1 if d.line > 0 else -1
        href, where = _target(places[at] if at >= 0 else None, anchors)
        # "Assem3: the path ..." about Assem3 says its entry once, as the link
        said = bool(where) and d.message.startswith(f"{where}: ")
        findings.append({"severity": str(d.severity), "code": d.code, "line": d.line, "column": d.column,
                         "message": d.message[len(where) + 2:] if said else d.message, "clause": d.clause,
                         "href": href, "where": where, "said": said})
    counts = Counter(f["severity"] for f in findings)
    order = [str(s) for s in sorted(Severity, reverse=True)]
    return {"findings": findings, "counts": [(name, counts[name]) for name in order if counts[name]],
            "groups": _groups(findings, order)}


def _groups(findings: list[dict], order: list[str]) -> list[dict]:
    """The findings by code (and clause), the most severe first: a code's severity and clause are said once."""
    by_code: dict[tuple[str, str | None], list[dict]] = {}
    for f in findings:
        by_code.setdefault((f["code"], f["clause"]), []).append(f)
    groups = [{"code": code, "severity": items[0]["severity"], "clause": clause, "findings": items}
              for (code, clause), items in by_code.items()]
    return sorted(groups, key=lambda g: (order.index(g["severity"]), g["code"]))


def icon_uri(data: bytes | None) -> str | None:
    """The icon as a data: URI, for an ICO, BMP or PNG file; None for other bytes (no broken image)."""
    import base64

    if not data:
        return None
    if data[:4] == b"\0\0\1\0":
        mime = "image/x-icon"
    elif data[:2] == b"BM":
        mime = "image/bmp"
    elif data[:8] == b"\x89PNG\r\n\x1a\n":
        mime = "image/png"
    else:
        return None
    return f"data:{mime};base64,{base64.b64encode(data).decode('ascii')}"


# --- the comparison page -------------------------------------------------------------------------


def mark(marks: dict[str, str], keyword: str, *fields: str) -> str:
    """The mark ("added", "removed", "changed") of an entry's field among ``fields`` (of the entry itself for
    none); ``keyword`` may name several, separated by ``|``. Empty when nothing is marked."""
    for name in keyword.split("|"):
        for key in [f"{name} {field}" for field in fields] if fields else [name]:
            if key in marks:
                return marks[key]
    return ""



def _keyword(what: str) -> str:
    """The entry a change is about: ``Param3`` of ``Param3 default``; ``identity.product_code`` whole."""
    return what.split(" ", 1)[0]


def marks(changes: list[dict], side: str) -> dict[str, str]:
    """What to mark on one side ("old" or "new"): each changed field by its ``what``, and its entry."""
    hidden = "added" if side == "old" else "removed"
    result: dict[str, str] = {}
    for change in changes:
        if change["kind"] == hidden:
            continue
        result[change["what"]] = change["kind"]
        result.setdefault(_keyword(change["what"]), "changed")
    return result


def change_rows(changes: list[dict], old_anchors: set[str], new_anchors: set[str]) -> list[dict]:
    """The changes with links to their entry on each side, where it is shown."""
    rows = []
    for change in changes:
        keyword = _keyword(change["what"])
        old, new = f"a-e-{keyword}", f"b-e-{keyword}"
        rows.append({**change, "old_href": old if old in old_anchors else None,
                     "new_href": new if new in new_anchors else None})
    return rows
