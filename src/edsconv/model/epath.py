"""CIP paths (EPATH) decoded segment by segment, for people to read (CIP Vol 1 appendix C-1).

:func:`decode_path` walks the items of a path as the model holds them (bytes,
``[ParamN]`` substitutions, SLOT keywords) and names each segment: port,
logical (class, instance, attribute, electronic key ...), network, symbolic and
data segments and elementary data types. What it cannot decode ends the walk as
one "undecoded" segment that says why; it never raises.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from edsconv import spec_tables as tables
from edsconv.model.device import Device
from edsconv.model.plain import path_text, plain
from edsconv.model.values import PathItem

#: Logical segment types by bits 2-4 of the segment byte (CIP Vol 1 C-1.4.2).
_LOGICAL_TYPES = ("class", "instance", "member", "connection point", "attribute", "special", "service ID", "reserved")
#: Network segments with one byte of data (CIP Vol 1 C-1.4.3), by segment byte.
_NETWORK_SEGMENTS = {0x41: "schedule", 0x42: "fixed tag", 0x43: "production inhibit time (ms)",
                     0x44: "fixed tag", 0x45: "production inhibit time (ms)", 0x46: "safety",
                     0x47: "production inhibit time (µs)"}
#: What the keywords that may stand in an EDS path for bytes mean (C.4.1.4.9.13).
_PATH_KEYWORD_MEANINGS = {
    "SLOT": "the slot number of the module",
    "SLOT_MINUS_ONE": "the slot number of the module minus one",
    "SYMBOL_ANSI": "an ANSI extended symbol segment (a tag name) supplied by the configuration tool",
}
#: Segment bytes of the data segments: simple data (words) and ANSI extended symbol (bytes).
_SIMPLE_DATA, _ANSI_SYMBOL = 0x80, 0x91


class _Undecodable(Exception):
    """The rest of the path cannot be decoded; the message says why."""

    def __init__(self, message: str) -> None:
        super().__init__(message)
        self.message = message


@dataclass(slots=True)
class _Segment:
    kind: str
    text: str
    value: Any = None
    extra: dict[str, Any] = field(default_factory=dict)


class _Cursor:
    """The items of a path and how far they have been read."""

    def __init__(self, items: list[PathItem]) -> None:
        self.items = items
        self.position = 0

    @property
    def done(self) -> bool:
        return self.position >= len(self.items)

    def take(self, count: int) -> list[PathItem] | None:
        """The next ``count`` items, or None (nothing taken) when fewer are left."""
        if self.position + count > len(self.items):
            return None
        taken = self.items[self.position:self.position + count]
        self.position += count
        return taken

    def need(self, count: int | None, missing: str) -> list[PathItem]:
        """The next ``count`` items; :class:`_Undecodable` with ``missing`` when they are not there."""
        taken = self.take(count) if count is not None else None
        if taken is None:
            raise _Undecodable(missing)
        return taken

    def byte(self, missing: str) -> int:
        """The next item as a byte (a length, a size)."""
        value = self.need(1, missing)[0].byte
        if value is None:
            raise _Undecodable(missing)
        return value


def decode_path(path: tuple[PathItem, ...] | str | None, device: Device | None = None) -> dict | None:
    """A CIP path segment by segment (CIP Vol 1 C-1): port, logical, network, symbolic and data
    segments, with ``[ParamN]`` substitutions and SLOT keywords where bytes stand.

    ``{"text", "segments": [{"bytes", "type", "text", ["value"], ...}], "summary"}``; with
    ``device``, a substituted parameter is named with its default.
    """
    if path is None:
        return None
    if isinstance(path, str):
        return {"text": path, "segments": [], "summary": path}
    cursor = _Cursor(list(path))
    segments: list[dict] = []
    while not cursor.done:
        start = cursor.position
        try:
            segment = _next_segment(cursor, device)
        except _Undecodable as problem:
            cursor.position = len(cursor.items)
            segment = _Segment("undecoded", problem.message)
        segments.append(_as_dict(segment, cursor.items[start:cursor.position]))
    return {"text": path_text(path), "segments": segments, "summary": ", ".join(s["text"] for s in segments)}


def _as_dict(segment: _Segment, items: list[PathItem]) -> dict:
    described = {"bytes": " ".join(str(item) for item in items), "type": segment.kind, "text": segment.text}
    if segment.value is not None:
        described["value"] = segment.value
    described.update(segment.extra)
    return described


def _next_segment(cursor: _Cursor, device: Device | None) -> _Segment:
    head = cursor.items[cursor.position]
    start = cursor.position
    cursor.position += 1
    byte = head.byte
    if byte is None:
        return _placeholder(head, device)
    segment_type = byte >> 5
    if segment_type == 0:
        return _port(byte, cursor, start, device)
    if segment_type == 1:
        return _logical(byte, cursor, device)
    if segment_type == 2:
        return _network(byte, cursor, device)
    if segment_type == 3:
        return _symbolic(byte, cursor)
    if byte in (_SIMPLE_DATA, _ANSI_SYMBOL):
        return _data(byte, cursor)
    if byte in tables.DATA_TYPES_BY_CODE:
        return _Segment("data type", f"data type {tables.DATA_TYPES_BY_CODE[byte].name}", byte)
    raise _Undecodable(f"0x{byte:02X} is not a segment type edsconv decodes")


# --- the parts of a segment -----------------------------------------------------------------------


def _item_text(item: PathItem, device: Device | None) -> str:
    """A byte in hex, a keyword, or a substitution with the name and default of its parameter."""
    if item.byte is not None:
        return f"0x{item.byte:02X}"
    if item.keyword:
        return item.keyword
    text = str(item)
    target = device.parameters.get(item.reference) if device and item.reference else None
    if target is not None:
        details = ", ".join(str(part) for part in (
            target.name and repr(target.name), target.default is not None and f"default {plain(target.default)}")
            if part)
        text += f" ({details})" if details else ""
    return text


def _number(items: list[PathItem], device: Device | None) -> tuple[Any, str]:
    """The little-endian value of ``items`` (all bytes) or, with substitutions, their spelling."""
    if len(items) == 1:
        item = items[0]
        value = item.byte if item.byte is not None else str(item)
        return value, _item_text(item, device)
    if all(item.byte is not None for item in items):
        value = int.from_bytes(bytes(item.byte for item in items if item.byte is not None), "little")
        return value, f"0x{value:0{2 * len(items)}X}"
    spelled = " ".join(str(item) for item in items)
    return spelled, spelled


def _latin1(items: list[PathItem]) -> str:
    """The characters of ``items`` when all are bytes, else their spelling."""
    if all(item.byte is not None for item in items):
        return bytes(item.byte for item in items if item.byte is not None).decode("latin-1")
    return " ".join(str(item) for item in items)


# --- segments ---------------------------------------------------------------------------------------


def _placeholder(head: PathItem, device: Device | None) -> _Segment:
    """A keyword or a ``[ParamN]`` substitution where a segment byte would stand."""
    if head.keyword:
        return _Segment("keyword", f"{head.keyword}: {_PATH_KEYWORD_MEANINGS.get(head.keyword, 'keyword')}",
                        head.keyword)
    return _Segment("substitution", f"value of {_item_text(head, device)}", str(head), {"parameter": head.reference})


def _port(byte: int, cursor: _Cursor, start: int, device: Device | None) -> _Segment:
    """Port segment (C-1.4.1): port number, extended when 15, and a one-byte or sized link address."""
    missing = "port segment: the link address is missing"
    port: Any = byte & 0x0F
    if port == 0x0F:
        port, _ = _number(cursor.need(2, "port segment: the extended port number is missing"), device)
    if not byte & 0x10:
        link_value, link_text = _number(cursor.need(1, missing), device)
        return _Segment("port", f"port {port}, link address {link_text}", port, {"link_address": link_value})
    size = cursor.take(1)
    address = cursor.need(size[0].byte if size else None, missing)
    if (cursor.position - start) % 2:
        cursor.take(1)  # pad byte
    link = _latin1(address)
    return _Segment("port", f"port {port}, link address {link}", port, {"link_address": link})


def _logical(byte: int, cursor: _Cursor, device: Device | None) -> _Segment:
    """Logical segment (C-1.4.2): a class, instance, member, attribute ... of 8, 16 or 32 bits."""
    logical = _LOGICAL_TYPES[(byte >> 2) & 7]
    width = byte & 3
    if logical == "special" and width == 0:
        return _electronic_key(cursor)
    if width == 3:
        raise _Undecodable(f"logical segment 0x{byte:02X}: reserved format")
    size = (1, 2, 4)[width]
    # padded EPATH puts a 0x00 pad byte before a 16/32-bit value; EDS files often
    # write the packed form without it ("21 04 00" is class 0x0004)
    if width and cursor.position + size < len(cursor.items) and cursor.items[cursor.position].byte == 0:
        cursor.take(1)
    data = cursor.need(size, f"{logical} segment: the value is missing")
    value, text = _number(data, device)
    if logical == "class" and isinstance(value, int) and value in tables.CIP_CLASSES:
        text += f" ({tables.CIP_CLASSES[value]})"
    references = [item.reference for item in data if item.reference]
    return _Segment(logical, f"{logical} {text}", value, {"parameter": references[0]} if references else {})


def _electronic_key(cursor: _Cursor) -> _Segment:
    """Electronic key segment (C-1.4.2, key format 4): vendor, device type, product code, revision."""
    key = cursor.take(9)
    if key is None or key[0].byte != 4 or any(item.byte is None for item in key):
        raise _Undecodable("electronic key segment: expected key format 4 and 8 bytes")
    data = bytes(item.byte for item in key[1:] if item.byte is not None)
    vendor, device_type, product = (int.from_bytes(data[i:i + 2], "little") for i in (0, 2, 4))
    major, minor = data[6] & 0x7F, data[7]
    compatibility = " (compatible)" if data[6] & 0x80 else ""
    return _Segment("electronic key", f"electronic key: vendor {vendor}, device type {device_type}, "
                    f"product code {product}, revision {major}.{minor}{compatibility}")


def _network(byte: int, cursor: _Cursor, device: Device | None) -> _Segment:
    """Network segment (C-1.4.3): one byte of data, or a word count and that many words."""
    missing = f"network segment 0x{byte:02X}: its data is missing"
    if byte in (0x46, 0x50) or byte & 0xF0 == 0x50:
        words = cursor.byte(missing)
        cursor.need(2 * words, missing)
        return _Segment("network", f"network segment 0x{byte:02X} ({words} words)")
    value, text = _number(cursor.need(1, missing), device)
    return _Segment("network", f"{_NETWORK_SEGMENTS.get(byte, f'network segment 0x{byte:02X}')} {text}", value)


def _symbolic(byte: int, cursor: _Cursor) -> _Segment:
    """Symbolic segment (C-1.4.4): a symbol of as many characters as the low five bits say."""
    size = byte & 0x1F
    symbol = cursor.take(size) if size else None
    if symbol is None or any(item.byte is None for item in symbol):
        raise _Undecodable("symbolic segment: the symbol is missing")
    name = _latin1(symbol)
    return _Segment("symbolic", f"symbol {name!r}", name)


def _data(byte: int, cursor: _Cursor) -> _Segment:
    """Data segment (C-1.4.5): simple data (a word count and words) or an ANSI extended symbol."""
    missing = "data segment: its data is missing"
    count = cursor.byte(missing)
    data = cursor.need(count * (2 if byte == _SIMPLE_DATA else 1), missing)
    if byte == _SIMPLE_DATA:
        return _Segment("data", f"simple data, {count} words")
    if count % 2:
        cursor.take(1)  # pad byte
    name = _latin1(data)
    return _Segment("symbolic", f"ANSI extended symbol {name!r}", name)
