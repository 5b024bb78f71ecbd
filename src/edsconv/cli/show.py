"""``edsconv show``: the :func:`~edsconv.describe.describe` document as tables for people, or as
JSON for programs.

The text is rendered part by part (identity, parameters, groups, assemblies, connections, ports,
modular, capacity, network, objects, devicenet, icon, other), one function each, from the same
document the JSON output prints. A part writes on a page: ``heading``, ``table`` (columns,
``add_row``), ``pairs`` (label / value rows) and ``print``. On a terminal the page is rich's
(imported only then); piped, a plain page lays the same tables out as text, column widths from
one pass over the rows, no wrapping (rich's layout was two thirds of ``show``'s time).
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import TYPE_CHECKING, Any

import click

from edsconv import analyse, cip_tables
from edsconv.cells import parameter_value as _value
from edsconv.cells import revision as _revision
from edsconv.cells import value_range as _range
from edsconv.cli.common import (
    EXIT_CLEAN,
    CannotRun,
    counts_line,
    documentation,
    emit,
    read_eds,
    split_list,
    writing,
)
from edsconv.cli.layout import Page as _Page
from edsconv.cli.layout import PlainPage, RichPage, Row, json_text
from edsconv.cli.layout import cell_text as _text
from edsconv.describe import SECTIONS, describe, select
from edsconv.diagnostics import Severity
from edsconv.eds.reader import paused_gc
from edsconv.model.cip import SINGLE_ATTRIBUTES

if TYPE_CHECKING:
    from rich.console import Console



# --- command ------------------------------------------------------------------------------------


def _section_names(ctx: click.Context, param: click.Parameter, value: tuple[str, ...]) -> tuple[str, ...]:
    names = tuple(name.lower() for name in split_list(value))
    unknown = [name for name in names if name not in SECTIONS]
    if unknown:
        raise click.BadParameter(f"{', '.join(unknown)}: choose from {', '.join(SECTIONS)}")
    return tuple(dict.fromkeys(names))


@click.command("show", epilog=documentation("show.md"))
@click.argument("file", type=click.Path(dir_okay=False, path_type=Path))
@click.option("--section", "sections", multiple=True, callback=_section_names, metavar="NAME",
              help=f"Show only these parts (repeat or comma-separate): {', '.join(SECTIONS)}.")
@click.option("--format", "output_format", type=click.Choice(["text", "json", "html"]), default="text",
              show_default=True, help="text: tables for people; json: the same content for programs; html: one "
                                      "self-contained page with drawings.")
@click.option("-o", "--output", "output", type=click.Path(dir_okay=False, path_type=Path), metavar="FILE",
              help="Write to FILE instead of standard output.")
@click.option("--icon", "icon_file", type=click.Path(dir_okay=False, path_type=Path), metavar="FILE",
              help="Also write the icon IconContents holds (decoded from base64) to FILE.")
@click.option("--force", is_flag=True, help="Overwrite an existing output or icon file (never the EDS itself).")
def show_command(file: Path, sections: tuple[str, ...], output_format: str, output: Path | None,
                 icon_file: Path | None, force: bool) -> int:
    """Show what an EDS says about a device: identity, parameters, assemblies, connections, ports, modules.

    Exit 0 whenever the file could be read, even when it has errors: their count goes to
    standard error and 'edsconv lint' lists them. Exit 2 when the file cannot be read.
    """
    eds = read_eds(file)
    device, diagnostics = analyse(eds)
    icon = device.icon_contents.data if device.icon_contents else None
    if icon_file is not None:
        _write_icon(file, icon, icon_file, force)
    with paused_gc():  # the document is many small objects and no cycles, as the model is
        document = select(describe(device), sections)
        if output_format == "html":
            from edsconv.html import show_page

            emit(show_page(document, str(file), diagnostics, eds, icon or _icon_file(file, document)), output, [file],
                 force)
        elif output_format == "json":
            emit(json_text(document), output, [file], force)
        elif output is not None:
            emit(plain_text(document, sections), output, [file], force)
        else:
            print_text(document, sections)
    if any(d.severity >= Severity.WARNING for d in diagnostics):
        click.echo(counts_line(str(file), diagnostics, notes=False) + f" (see 'edsconv lint {file}')", err=True)
    return EXIT_CLEAN


def _icon_file(file: Path, document: dict) -> bytes | None:
    """The file [Device] Icon names beside the EDS (C.4.1.4.3), when there is one of a sensible size."""
    name = (document.get("identity") or {}).get("icon")
    if not isinstance(name, str) or not name:
        return None
    path = file.parent / Path(name).name
    try:
        return path.read_bytes() if path.is_file() and path.stat().st_size <= 1 << 20 else None
    except OSError:
        return None


def _write_icon(file: Path, data: bytes | None, target: Path, force: bool) -> None:
    """The decoded IconContents to ``target``, whatever the bytes are (show says what they are)."""
    if data is None:
        raise CannotRun(f"{file}: no icon to write: IconContents is missing or not base64")
    from edsconv.atomic import write_atomically

    with writing(target):
        write_atomically(target, data, inputs=[file], force=force)


def print_text(document: dict, sections: tuple[str, ...]) -> None:
    """The tables on a terminal (rich); piped, plain text without trailing blanks."""
    if sys.stdout.isatty():
        from rich.console import Console

        render(document, Console(markup=False, highlight=False, emoji=False), sections)
        return
    click.echo(plain_text(document, sections))


# --- text of values -----------------------------------------------------------------------------


def _joined(*parts: Any) -> str:
    return " ".join(_text(part) for part in parts if part not in (None, ""))


def _reference_text(ref: dict | None) -> str:
    """One line for a resolved reference (rpi/size/format, group member, assembly member)."""
    if ref is None:
        return ""
    kind = ref.get("kind")
    keyword = ref.get("keyword", "")
    bit = f" bit {ref['bit']}" if ref.get("bit") is not None else ""
    if kind == "parameter":
        name = f" {ref['name']!r}" if ref.get("name") else ""
        units = f" {ref['units']}" if ref.get("units") else ""
        return (f"{keyword}{bit}{name}: default {_text(ref['default'])}{units}, range "
                f"{_range(ref['minimum'], ref['maximum'])}")
    if kind == "assembly":
        name = f" {ref['name']!r}" if ref.get("name") else ""
        size = f", {ref['size']} bytes" if ref.get("size") is not None else ""
        bits = f", members {ref['total_bits']} bits" if ref.get("total_bits") is not None else ""
        return f"{keyword}{name}{size}{bits}"
    if kind == "undefined":
        return f"{keyword} (undefined)"
    return f"{keyword}{bit}"


def _value_text(value: dict | None, unit: str = "") -> str:
    if value is None:
        return ""
    if "reference" in value:
        return _reference_text(value["reference"])
    return f"{_text(value['value'])}{unit}"


def _format_text(value: dict | None) -> str:
    if value is None:
        return ""
    return _text(value["written"]) if value.get("kind") == "value" else _reference_text(value)


def _member_text(member: dict) -> str:
    kind = member["kind"]
    if kind == "pad":
        return "(pad)"
    if kind == "constant":
        return f"constant {member['value']} (0x{member['value']:X})"
    if kind == "keyword":
        return member["keyword"]
    if kind == "path":
        return f"path {member['path']['text']} ({member['path']['summary']})"
    if kind == "parameter":
        name = f" {member['name']!r}" if member.get("name") else ""
        bit = f" bit {member['bit']}" if member.get("bit") is not None else ""
        return f"{member['keyword']}{bit}{name} ({member['data_type'] or '?'})"
    return _reference_text(member)


def _path_text(path: dict | None) -> str:
    if not path:
        return ""
    return f"{path['text']}\n  = {path['summary']}" if path["summary"] and path["summary"] != path["text"] else \
        path["text"]


def _title(keyword: str, name: Any) -> str:
    return f"{keyword}  {name!r}" if name else keyword


# --- the parts ----------------------------------------------------------------------------------


def _identity(page: _Page, document: dict) -> None:
    page.heading("Identity")
    page.print(page.pairs(_identity_rows(document)))
    pc = document["param_class"]
    if pc:
        page.heading("Parameter class")
        page.print(page.pairs([("Max instances", pc["max_instances"]),
                               ("Descriptor", f"{pc['descriptor']} {', '.join(pc['flags'])}"),
                               ("Config assembly", pc["cfg_assembly"])]))
    _additions(page, document)


def _identity_rows(document: dict) -> list[Row]:
    identity, file = document["identity"], document["file"]
    return [
        ("Product", identity["product_name"]),
        ("Vendor", _joined(identity["vendor_code"], identity["vendor_name"])),
        ("Product type", _joined(identity["product_type"], identity["product_type_string"])),
        ("Product code", identity["product_code"]),
        ("Revision", _revision(identity["major_revision"], identity["minor_revision"])),
        ("Catalog", identity["catalog"]),
        ("Icon", identity["icon"]),
        ("Networks", ", ".join(
            " ".join([c["classification"] or "?", *c["subclassifications"]]) for c in document["classifications"])),
        ("Description", file["description"]),
        ("File revision", file["revision"]),
        ("Created", " ".join(filter(None, (file["create_date"], file["create_time"])))),
        ("Modified", " ".join(filter(None, (file["mod_date"], file["mod_time"])))),
        ("Home URL", file["home_url"]),
    ]


def _parameters(page: _Page, document: dict) -> None:
    if not document["parameters"]:
        return
    page.heading("Parameters")
    t = page.table("Keyword", "Name", "Type", "Range", "Default", "Units", "Details")
    for column in (0, 2, 3, 4):
        t.columns[column].no_wrap = True
    for p in document["parameters"]:
        t.add_row(p["keyword"], _text(p["name"]), _type_text(p), _range(_value(p, "minimum"), _value(p, "maximum")),
                  _value(p, "default"), _text(p["units"]), "\n".join(_parameter_details(p)))
    page.print(t)


def _type_text(parameter: dict) -> str:
    data_type = parameter["data_type"]
    text = data_type["name"] or f"? ({_text(data_type['written'])})"
    if data_type["code"] is not None:
        text += f" 0x{data_type['code']:02X}"
    if parameter["size"] is not None:
        text += f", {parameter['size']} B"
    return text


def _parameter_details(p: dict) -> list[str]:
    details = []
    engineering = p.get("engineering")
    if engineering:
        details.append(f"scaled: {_range(engineering['minimum'], engineering['maximum'])}, "
                       f"default {_text(engineering['default'])}")
    details += [f"{e['value']} = {e['text']}" for e in p["enum"]]
    if p["flags"]:
        details.append("flags: " + ", ".join(p["flags"]))
    if p.get("link_path"):
        details.append(f"link path {p['link_path']['text']} ({p['link_path']['summary']})")
    if p["help"]:
        details.append(p["help"])
    return details


def _groups(page: _Page, document: dict) -> None:
    if not document["groups"]:
        return
    page.heading("Groups")
    t = page.table("Group", "Name", "Members")
    for g in document["groups"]:
        t.add_row(str(g["number"]), _text(g["name"]),
                  "\n".join(f"{m['keyword']} {m.get('name') or ''}".strip() for m in g["members"]))
    page.print(t)


def _assemblies(page: _Page, document: dict) -> None:
    for a in (*document["assemblies"], *document.get("extended_assemblies", ())):
        size = f", {a['size']} bytes" if isinstance(a["size"], int) else f", size {a['size']}" if a["size"] else ""
        path = f", path {a['path']['text']} ({a['path']['summary']})" if a["path"] else ""
        page.heading(f"{_title(a['keyword'], a['name'])}{size}{path}")
        t = page.table("Bits", "Size", "Member")
        for m in a["members"]:
            bits = m["bits"]
            t.add_row(_bit_range(m["offset"], bits), "?" if bits is None else str(bits), _member_text(m["member"]))
        if a["module_member_list"]:
            t.add_row("", "", "the members of the module (ModuleMemberList)")
        elif not a["members"]:
            t.add_row("", "", "(no members listed)")
        if a["members"]:
            t.add_row("", _text(a["total_bits"]) if a["total_bits"] is not None else "?", "total bits")
        page.print(t)


def _bit_range(offset: int | None, bits: int | None) -> str:
    if offset is None or bits is None:
        return "?"
    return f"{offset}" if bits <= 1 else f"{offset}-{offset + bits - 1}"


def _connections(page: _Page, document: dict) -> None:
    for c in document["connections"]:
        rows = _trigger_rows(c["trigger_transport"])
        parameters = c["parameters"]
        if parameters:
            rows += [("Connection parameters", parameters["value"]),
                     ("  reserved bits set", parameters.get("reserved_bits"))]
        for direction in ("O=>T", "T=>O"):
            rows += _direction_rows(c[direction], parameters, direction)
        for part in ("config1", "config2"):
            endpoint = c[part]
            if endpoint:
                rows += [(f"Config part {part[-1]}", " "),
                         ("  size", _value_text(endpoint["size"], " bytes")),
                         ("  format", _format_text(endpoint["format"]))]
        rows += [("Path", _path_text(c["path"])), ("Help", c["help"])]
        page.heading(_title(c["keyword"], c["name"]))
        page.print(page.pairs(rows))


def _trigger_rows(tt: dict | None) -> list[Row]:
    if not tt:
        return []
    rows: list[Row] = [("Trigger/transport", tt["value"])]
    if "classes" in tt:
        rows += [("  class", ", ".join(tt["class_names"]) or "none"),
                 ("  trigger", ", ".join(tt["triggers"]) or "none"),
                 ("  transport type", ", ".join(tt["transport"]) or "none"),
                 ("  role", tt["role"]),
                 ("  reserved bits set", tt["reserved_bits"])]
    return rows


def _direction_rows(endpoint: dict | None, parameters: dict | None, direction: str) -> list[Row]:
    """One direction of a connection: its RPI, size and format, and its half of the connection parameters."""
    rows: list[Row] = [(direction, "(not given)" if endpoint is None else " ")]
    if endpoint:
        rows += [("  RPI", _value_text(endpoint["rpi"], " µs")),
                 ("  size", _value_text(endpoint["size"], " bytes")),
                 ("  format", _format_text(endpoint["format"]))]
    if parameters and direction in parameters:
        d = parameters[direction]
        sizes = [s for s, on in (("fixed", d["fixed_size"]), ("variable", d["variable_size"])) if on]
        rows += [("  size type", " and ".join(sizes) or "none"),
                 ("  real-time format", d["real_time_format"]),
                 ("  connection type", ", ".join(d["connection_types"]) or "none"),
                 ("  priority", ", ".join(d["priorities"]) or "none")]
    return rows


def _ports(page: _Page, document: dict) -> None:
    if not document["ports"]:
        return
    page.heading("Ports")
    t = page.table("Port", "Type", "Name", "Port number", "Object path")
    for p in document["ports"]:
        t.add_row(str(p["number"]), _text(p["type"]), _text(p["name"]), _text(p["port_number"]),
                  _path_text(p["object_path"]))
    page.print(t)


def _modular(page: _Page, document: dict) -> None:
    m = document["modular"]
    if not m:
        return
    page.heading(f"Modular ({m['role'] or 'unknown role'})")
    page.print(page.pairs([
        ("Slots in rack", m["define_slots_in_rack"]),
        ("Slot display rule", _reference_text(m["slot_display_rule"])),
        ("Width (slots)", m["width"]),
        ("External ID", m["external_id"]),
        ("Generic ID", m["generic_id"]),
        ("ExternID exact match", m["extern_id_exact_match"]),
        ("Query", m["query"] and f"path {_path_text(m['query']['path'])}, service {m['query']['service']}, "
                                 f"ID size {_text(m['query']['id_size'])}, empty slot ID "
                                 f"{_text(m['query']['empty_slot_id'])}"),
    ]))
    if m["racks"]:
        page.heading("Racks")
        t = page.table("Rack", "Vendor", "Type", "Product", "Revision", "Legal slots")
        for r in m["racks"]:
            t.add_row(str(r["number"]), _text(r["vendor_code"]), _text(r["product_type"]),
                      _text(r["product_code"]), _revision(r["major_revision"], r["minor_revision"]),
                      ", ".join(map(str, r["legal_slots"])))
        page.print(t)


def _other(page: _Page, document: dict) -> None:
    if not (document["other_sections"] or document["extra_entries"]):
        return
    page.heading("Other sections and entries")
    t = page.table("Section", "Entries")
    for s in document["other_sections"]:
        t.add_row(f"[{s['name']}]", str(s["entries"]))
    for section, keywords in document["extra_entries"].items():
        t.add_row(f"[{section}] (not in the 2003 text)", ", ".join(keywords))
    page.print(t)


# --- content beyond the 2003 text (one function per part) --------------------------------------------


def _labels(section: str, attributes: dict[str, str]) -> list[tuple[str, str]]:
    """(attribute, label) of single entries: the label is the entry's name in cip_tables, and its keyword."""
    labels = []
    for keyword, attribute in attributes.items():
        spec = cip_tables.entry_spec(section, keyword)
        name = spec.fields[0].name if spec is not None else keyword
        labels.append((attribute, name if name == keyword else f"{name} ({keyword})"))
    return labels


def _additions(page: _Page, document: dict) -> None:
    additions = document.get("additions")
    if not additions:
        return
    page.heading("Entries later editions add to [File], [Device], [ParamClass], [Connection Manager]")
    rows = [(label, _listed(additions[attribute])) for section, attributes in SINGLE_ATTRIBUTES.items()
            if section in ("File", "Device", "ParamClass", "Connection Manager")
            for attribute, label in _labels(section, dict(attributes))]
    page.print(page.pairs(rows))


def _listed(value: Any) -> Any:
    return ", ".join(map(_text, value)) if isinstance(value, list) else value


def _capacity(page: _Page, document: dict) -> None:
    capacity = document["capacity"]
    if not capacity:
        return
    page.heading("Capacity")
    page.print(page.pairs([(label, capacity[attribute])
                           for attribute, label in _labels("Capacity", dict(SINGLE_ATTRIBUTES["Capacity"]))]))
    if capacity["traffic_specs"]:
        t = page.table("TSpec", "Direction", "Connection size (bytes)", "Packets per second")
        for spec in capacity["traffic_specs"]:
            t.add_row(str(spec["number"]), _text(spec["direction"]), _text(spec["connection_size"]),
                      _text(spec["packets_per_second"]))
        page.print(t)


def _network(page: _Page, document: dict) -> None:
    network = document["network"]
    if not network:
        return
    tcpip, link = network["tcpip_interface"], network["ethernet_link"]
    if tcpip and (tcpip["quick_connect_targets"] or tcpip["quick_connect_originators"]):
        page.heading("TCP/IP Interface: QuickConnect")
        t = page.table("Entry", "Times")
        for target in tcpip["quick_connect_targets"]:
            t.add_row(f"ENetQCT{target['number']}", f"ready for connection {_text(target['ready_for_connection_time'])}"
                      f", accumulated CIP connection {_text(target['accumulated_connection_time'])}")
        for originator in tcpip["quick_connect_originators"]:
            t.add_row(f"ENetQCO{originator['number']}", ", ".join(map(_text, originator["origination_times"])))
        page.print(t)
    if link and link["interfaces"]:
        page.heading("Ethernet Link interfaces")
        t = page.table("Instance", "Label", "Speed", "Type")
        for interface in link["interfaces"]:
            t.add_row(str(interface["instance"]), _text(interface["label"]), _text(interface["speed"]),
                      _text(interface["interface_type"]))
        page.print(t)
    for key, title, section in (("dlr", "Device Level Ring", "DLR Class"),
                                ("ingress_egress", "Ingress Egress", "Ingress Egress Class")):
        if network[key]:
            page.heading(title)
            page.print(page.pairs([(label, network[key][attribute])
                                   for attribute, label in _labels(section, dict(SINGLE_ATTRIBUTES[section]))]))


def _objects(page: _Page, document: dict) -> None:
    if not document["object_classes"]:
        return
    page.heading("Object classes")
    t = page.table("Section", "Class", "Object name", "Revision", "Instances", "Attributes and services")
    for record in document["object_classes"]:
        t.add_row(f"[{record['section']}]", _class_text(record), _text(record["name"]), _text(record["revision"]),
                  _instances_text(record), "\n".join(_services_lines(record)))
    page.print(t)


def _class_text(record: dict) -> str:
    class_id = record["class_id"]
    text = "" if class_id is None else _joined(f"0x{class_id:02X}", record["class_name"])
    if record["vendor_id"] is not None:
        text += f" (vendor {record['vendor_id']})"
    code = record["class_code"]
    if code is not None and code != class_id:
        text += f"; Object_Class_Code 0x{code:02X}"
    return text


def _instances_text(record: dict) -> str:
    parts = (("max", record["max_instance"]), ("static", record["static_instances"]),
             ("dynamic", record["max_dynamic_instances"]))
    return ", ".join(f"{label} {value}" for label, value in parts if value is not None)


def _services_lines(record: dict) -> list[str]:
    lines = [f"{label}: {', '.join(map(_text, record[key]))}" for key, label in (
        ("class_attributes", "class attributes"), ("instance_attributes", "instance attributes"),
        ("class_services", "class services"), ("instance_services", "instance services")) if record[key]]
    return lines + [f"Service_Description{d['number']}: {_text(d['code'])} {_text(d['name'])}".rstrip()
                    for d in record["service_descriptions"]]


def _devicenet(page: _Page, document: dict) -> None:
    io = document["devicenet"]
    if not io:
        return
    page.heading("DeviceNet I/O")
    t = page.table("Entry", "Connection types", "Default input", "Default output")
    t.add_row("Default", _text(io["default"]), "", "")
    for mode in io["modes"]:
        t.add_row(mode["keyword"], _text(mode["combination_mask"]), _text(mode["default_input"]),
                  _text(mode["default_output"]))
    page.print(t)
    if io["inputs"] or io["outputs"]:
        t = page.table("Data", "Name", "Size", "Connection types", "Path")
        for data in (*io["inputs"], *io["outputs"]):
            t.add_row(data["keyword"], _text(data["name"]), f"{_text(data['size'])} bytes, "
                      f"{_text(data['size_in_bits'])} bits", _text(data["connection_mask"]), _path_text(data["path"]))
        page.print(t)
    if io["enum_strings"]:
        page.heading("Enumerated parameters ([EnumPar])")
        page.print(page.pairs([(keyword, " / ".join(map(_text, strings)))
                               for keyword, strings in io["enum_strings"].items()]))


def _icon(page: _Page, document: dict) -> None:
    icon = document["icon"]
    if not icon:
        return
    page.heading("Icon (IconContents)")
    images = "; ".join(f"{i['width']}x{i['height']} {i['encoding'].upper()}"
                       + (f" {i['bits_per_pixel']}-bit" if i["bits_per_pixel"] else "") for i in icon["images"])
    page.print(page.pairs([("Format", icon["kind"].upper() if icon["kind"] in ("ico", "bmp", "png") else icon["kind"]),
                           ("Bytes", icon["bytes"]), ("Images", images), ("Problem", icon["problem"])]))


#: The parts of the text, in the order they are printed, by their ``--section`` name.
_PARTS = {"identity": _identity, "parameters": _parameters, "groups": _groups, "assemblies": _assemblies,
          "connections": _connections, "ports": _ports, "modular": _modular, "capacity": _capacity,
          "network": _network, "objects": _objects, "devicenet": _devicenet, "icon": _icon, "other": _other}


def _render(document: dict, page: _Page, sections: tuple[str, ...]) -> None:
    for name, part in _PARTS.items():
        if name in (sections or SECTIONS):
            part(page, document)


def render(document: dict, console: Console, sections: tuple[str, ...] = ()) -> None:
    """Print the :func:`~edsconv.describe.describe` document as rich tables on ``console``."""
    _render(document, RichPage(console), sections)


def plain_text(document: dict, sections: tuple[str, ...] = ()) -> str:
    """The :func:`~edsconv.describe.describe` document as plain text: the tables of :func:`render`, unwrapped."""
    page = PlainPage()
    _render(document, page, sections)
    return "\n".join(page.lines)
