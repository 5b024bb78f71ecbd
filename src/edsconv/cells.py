"""How a value of the ``show`` document reads in one cell: the words ``edsconv show`` prints and its HTML
page shows, in one place, so that the page says what the text says (an invalid default, an open range).
"""

from __future__ import annotations

from typing import Any


def cell(value: Any) -> str:
    """A value as a cell shows it: nothing for None, floats short, lists comma-separated."""
    if value is None:
        return ""
    if isinstance(value, float):
        return f"{value:g}"
    if isinstance(value, list):
        return ", ".join(map(cell, value))
    return str(value)


def value_range(low: Any, high: Any) -> str:
    """``low .. high``; an open end says so (``1000 .. (no max)``): a blank would read as a typo."""
    if low in (None, "") and high in (None, ""):
        return ""
    return f"{cell(low) or '(no min)'} .. {cell(high) or '(no max)'}"


def parameter_value(parameter: dict, name: str) -> str:
    """A parameter's minimum, maximum or default, or what the file writes there marked invalid when it has
    no reading (``255 (invalid)`` for a BOOL): show says what the file says."""
    written = parameter.get("invalid", {}).get(name)
    return f"{written} (invalid)" if written is not None else cell(parameter[name])


def revision(major: Any, minor: Any) -> str:
    return "" if major is None and minor is None else f"{cell(major) or '?'}.{cell(minor) or '?'}"
