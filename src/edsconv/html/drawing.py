"""The geometry of the page's drawings: an assembly's bit map and the [Capacity] bar charts.

Only numbers and labels are computed here, from the :func:`~edsconv.describe.describe` document;
the templates turn them into SVG. A bit map lays the bits out in rows of 32 (64 or 128 for large
assemblies, so that a map stays under about 32 rows), bit 0 at the left of the first row; a member
is one block per row it covers, sized by its bits, labelled where the label fits.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from edsconv.html.text import member_label, member_title

#: the drawing width of one row of bits, and the margin at its left for the byte offsets
ROW_WIDTH = 768
LEFT = 64
ROW_HEIGHT = 28
#: the average width of a character of the labels (12 px sans-serif), to decide whether a label fits
CHAR_WIDTH = 6.4


#: the bits of a row a map may have; a map of many bits takes the wider rows, so that it stays short
ROW_BITS = (32, 64, 128)


def rulers(maps: Iterable[dict | None]) -> list[dict]:
    """The parts every map of ``bits`` per row shares, drawn once for the page's ``maps``: its bit numbers,
    its byte offsets and the grid of its rows, as many rows as its tallest map (each map shows its own)."""
    rows: dict[int, int] = {}
    for drawing in filter(None, maps):
        rows[drawing["row_bits"]] = max(rows.get(drawing["row_bits"], 0), drawing["rows_count"])
    result = []
    for bits in ROW_BITS:
        if bits not in rows:
            continue
        step = ROW_WIDTH // (bits // 8)
        result.append({"bits": bits, "step": step, "height": ROW_HEIGHT, "left": LEFT, "row_width": ROW_WIDTH,
                       "rows_height": rows[bits] * ROW_HEIGHT,
                       "ticks": [{"x": LEFT + byte * step + 2, "bit": byte * 8} for byte in range(bits // 8)],
                       "bytes": [{"y": row * ROW_HEIGHT + 35, "byte": row * bits // 8} for row in range(rows[bits])]})
    return result


def _row_bits(total: int) -> int:
    return next((bits for bits in ROW_BITS[:-1] if total <= bits * 32), ROW_BITS[-1])


def _number(value: float) -> float | int:
    """An integral coordinate without its ``.0``: the page is mostly numbers."""
    return int(value) if value == int(value) else round(value, 2)


def _segments(offset: int, bits: int, row_bits: int, bit_width: float) -> list[dict]:
    """The blocks of the bits ``offset`` .. ``offset + bits - 1``, one per row they cover."""
    segments = []
    while bits > 0:
        row, column = divmod(offset, row_bits)
        width = min(bits, row_bits - column)
        x, w = _number(LEFT + column * bit_width), _number(width * bit_width)
        segments.append({"x": x, "y": row * ROW_HEIGHT + 19, "w": w, "tx": _number(x + 4), "ty": row * ROW_HEIGHT + 35})
        offset, bits = offset + width, bits - width
    return segments


def _fitted(label: str, width: float) -> str:
    room = int((width - 6) // CHAR_WIDTH)
    if room >= len(label):
        return label
    return label[:room - 1] + "…" if room >= 4 else ""


def bit_map(assembly: dict) -> dict | None:
    """The drawing of ``assembly``'s members; None when no member has a known place."""
    placed = [m for m in assembly["members"] if m["offset"] is not None and m["bits"]]
    if not placed:
        return None
    end = max(m["offset"] + m["bits"] for m in placed)
    row_bits = _row_bits(end)
    bit_width = ROW_WIDTH / row_bits
    blocks = []
    for member in placed:
        what = member["member"]
        segments = _segments(member["offset"], member["bits"], row_bits, bit_width)
        label = member_label(what)
        for segment in segments:
            segment["label"] = _fitted(label, segment["w"])
        # a parameter's block is the page's usual one (no class: it is most of the page's blocks)
        blocks.append({"kind": "" if what["kind"] == "parameter" else what["kind"], "segments": segments,
                       "title": member_title(member, all(s["label"] == label for s in segments)),
                       "keyword": what.get("keyword") if what["kind"] in ("parameter", "assembly") else None,
                       "href": None})  # the view links the block when its entry is on the page
    rows = -(-end // row_bits)
    # the height ends below the last row's line: the page's grid is as tall as its tallest map
    return {"width": LEFT + ROW_WIDTH + 2, "height": rows * ROW_HEIGHT + 19, "blocks": blocks,
            "row_bits": row_bits, "bit_width": bit_width, "rows_count": rows}


# --- [Capacity] -----------------------------------------------------------------------------------------

BAR_LEFT = 200
BAR_WIDTH = 320
BAR_HEIGHT = 22


def _bars(items: list[tuple[str, Any]]) -> dict | None:
    """Horizontal bars of the numbers among ``items`` (label, value), scaled to the largest."""
    numbers = [(label, value) for label, value in items if isinstance(value, (int, float)) and value >= 0]
    if not numbers:
        return None
    largest = max(value for _, value in numbers) or 1
    bars = [{"label": label, "value": value, "y": index * BAR_HEIGHT, "w": max(1.0, BAR_WIDTH * value / largest)}
            for index, (label, value) in enumerate(numbers)]
    return {"bars": bars, "left": BAR_LEFT, "width": BAR_LEFT + BAR_WIDTH + 90, "height": len(bars) * BAR_HEIGHT}


#: the [Capacity] counts of connections, as the chart labels them
_CONNECTION_COUNTS = (("max_cip_connections", "CIP connections"), ("max_io_connections", "I/O connections"),
                      ("max_msg_connections", "messaging connections"), ("max_io_producers", "I/O producers"),
                      ("max_io_consumers", "I/O consumers"), ("max_io_produce_consume", "I/O produce+consume"),
                      ("max_io_mcast_producers", "multicast producers"),
                      ("max_io_mcast_consumers", "multicast consumers"),
                      ("max_consumers_per_mcast", "consumers per multicast"))


def capacity_charts(capacity: dict | None) -> dict:
    """Two charts of [Capacity]: its connection counts, and packets per second per TSpec."""
    if not capacity:
        return {"connections": None, "packets": None}
    return {
        "connections": _bars([(label, capacity.get(key)) for key, label in _CONNECTION_COUNTS]),
        "packets": _bars([(f"TSpec{spec['number']} {spec['direction'] or ''} {spec['connection_size'] or '?'} B",
                           spec["packets_per_second"]) for spec in capacity["traffic_specs"]]),
    }
