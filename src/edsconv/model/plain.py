"""Values of the typed model as plain JSON data: dates ISO, paths as text, references by keyword.

What ``edsconv show --format json`` prints is made of these (:mod:`edsconv.describe`).
"""

from __future__ import annotations

import datetime
import math
from typing import Any

from edsconv.model.device import Reference
from edsconv.model.values import PathItem, Revision, StringIMember


def plain(value: Any) -> Any:
    """A model value as a JSON value: dates ISO, paths as text, references by keyword."""
    if value is None or isinstance(value, (bool, int, str)):
        return value
    if isinstance(value, float):
        return value if math.isfinite(value) else str(value)
    if isinstance(value, (datetime.date, datetime.time)):
        return value.isoformat()
    if isinstance(value, (Revision, Reference, PathItem)):
        return str(value)
    if isinstance(value, StringIMember):
        return {"language": value.language, "type": value.type_code, "charset": value.charset, "text": value.text}
    if isinstance(value, (bytes, bytearray)):
        return value.hex(" ").upper()
    if isinstance(value, tuple) and value and all(isinstance(item, PathItem) for item in value):
        return path_text(value)
    if isinstance(value, (list, tuple)):
        return [plain(item) for item in value]
    if isinstance(value, dict):
        return {str(key): plain(item) for key, item in value.items()}
    return str(value)


def path_text(path: tuple[PathItem, ...] | str | None) -> str | None:
    """A path as written in an EDS: its items separated by spaces."""
    if path is None or isinstance(path, str):
        return path
    return " ".join(str(item) for item in path)
