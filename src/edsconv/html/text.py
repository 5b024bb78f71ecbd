"""The short texts of the page's cells, labels and hover titles, from parts of the ``show`` document.

The templates escape them (Jinja2 autoescaping); these functions only choose the words.
"""

from __future__ import annotations

from edsconv.cells import cell, parameter_value, revision, value_range

__all__ = ["cell", "parameter_value", "revision", "value_range"]


def type_text(parameter: dict) -> str:
    """``UINT`` (or ``? (written)`` for a code no type has), with the size when the entry gives one."""
    data_type = parameter["data_type"]
    text = data_type["name"] or f"? ({cell(data_type['written'])})"
    return f"{text}, {parameter['size']} B" if parameter["size"] is not None else text


def bits_text(offset: int | None, bits: int | None) -> str:
    if offset is None or bits is None:
        return "?"
    return f"bit {offset}" if bits <= 1 else f"bits {offset}-{offset + bits - 1}"


def member_label(member: dict) -> str:
    """What a block of a bit map is labelled with: the name, else the keyword or value."""
    kind = member["kind"]
    if kind == "pad":
        return "pad"
    if kind == "constant":
        return f"0x{member['value']:X}"
    if kind == "path":
        return member["path"]["text"]
    return member.get("name") or member.get("keyword") or kind


def reference_text(ref: dict | None) -> str:
    """One line for a resolved reference (an RPI, a size, a format, a group or assembly member)."""
    if ref is None:
        return ""
    kind, keyword = ref.get("kind"), ref.get("keyword", "")
    bit = f" bit {ref['bit']}" if ref.get("bit") is not None else ""
    name = f" “{ref['name']}”" if ref.get("name") else ""
    if kind == "parameter":
        units = f" {ref['units']}" if ref.get("units") else ""
        return f"{keyword}{bit}{name}: default {cell(ref['default'])}{units}, range " \
               f"{value_range(ref['minimum'], ref['maximum'])}"
    if kind == "assembly":
        size = f", {ref['size']} bytes" if ref.get("size") is not None else ""
        return f"{keyword}{name}{size}"
    if kind == "undefined":
        return f"{keyword} (undefined)"
    if kind == "value":
        return cell(ref.get("written"))
    return f"{keyword}{bit}"


def member_text(member: dict) -> str:
    """A member of an assembly, as the member list says it."""
    kind = member["kind"]
    if kind == "pad":
        return "padding"
    if kind == "constant":
        return f"constant {member['value']} (0x{member['value']:X})"
    if kind == "path":
        return f"path {member['path']['text']} ({member['path']['summary']})"
    if kind == "keyword":
        return member["keyword"]
    if kind == "parameter":
        bit = f" bit {member['bit']}" if member.get("bit") is not None else ""
        return f"{member['keyword']}{bit} {member.get('name') or ''} ({member['data_type'] or '?'})".replace("  ", " ")
    return reference_text(member)


def member_title(member: dict, labelled: bool) -> str:
    """The hover text of a block: what it is and where. A parameter's name only when its block's label
    (``labelled``) does not show it whole; its type, range and help are in its row of the parameters table,
    which the block links to (and which the page's script adds to the hover)."""
    what, where = member["member"], bits_text(member["offset"], member["bits"])
    if what["kind"] != "parameter":
        return f"{member_text(what)}, {where}"
    bit = f" bit {what['bit']}" if what.get("bit") is not None else ""
    name = f" {what['name']}" if what.get("name") and not labelled else ""
    return f"{what['keyword']}{bit}{name}, {where}"


def endpoint_text(value: dict | None, unit: str = "") -> str:
    """An RPI or size of a connection: the value, or the parameter it names with its default and range."""
    if value is None:
        return ""
    if "reference" in value:
        return reference_text(value["reference"])
    return f"{cell(value['value'])}{unit}"


def path_text(path: dict | None) -> str:
    if not path:
        return ""
    summary = path.get("summary")
    return f"{path['text']} = {summary}" if summary and summary != path["text"] else path["text"]
