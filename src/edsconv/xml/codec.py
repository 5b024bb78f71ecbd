"""The edsconv extension elements of a device profile: a reflective codec.

A device profile carries what its schema elements cannot inside ``DeviceFunction``
(whose content C.2.1.2.4 leaves open), in the namespace ``urn:x-edsconv:eds-extensions:1``:

- ``edsconv:ExtraEntries`` / ``edsconv:Section``: entries and sections the 2003 text does
  not define, as ``edsconv:Entry`` / ``edsconv:Field`` (:func:`write_entries`, :func:`read_entries`);
- ``edsconv:Comments``: the comments of the EDS (:func:`write_comment`, :func:`read_comment`);
- ``edsconv:Value``: any model value at a model path (``parameters.Param1.default``).

The values are written by reflection over the model's dataclasses, so a new model field
needs no code here: :func:`encode` writes a value as ``kind`` plus text or child values,
:func:`decode` reads it back, :func:`differences` lists the model paths where two models
differ (the writer stores exactly those) and :func:`get_path` / :func:`set_path` read and
write the model at a path. Text XML 1.0 cannot carry is stored as a JSON string
(``escaped="json"``). docs/mapping.md lists the elements.
"""

from __future__ import annotations

import dataclasses
import datetime
import json
import math

from lxml import etree

from edsconv import spec_tables as tables
from edsconv.eds.lexicon import lexicon
from edsconv.eds.syntax import Scalar, String
from edsconv.model import (
    Assembly,
    AssemblyMember,
    Classification,
    CommentNote,
    FileDescription,
    GenericEntry,
    Identity,
    Modular,
    ParamClass,
    Parameter,
    ParameterGroup,
    Query,
    Rack,
    Reference,
    Scaling,
    Unreadable,
)
from edsconv.model.conforms import conforms, declared_type
from edsconv.model.values import PathItem, Revision, StringIMember, path_items
from edsconv.xml.common import EDSCONV, is_xml_text, xml_text
from edsconv.xml.datamodel import string_value


def float_text(value: float) -> str:
    if math.isnan(value):
        return "NaN"
    if math.isinf(value):
        return "INF" if value > 0 else "-INF"
    return repr(value)


# --- text, generic entries and comments -----------------------------------------------------

def reference(text: str) -> Reference:
    """The reference ``text`` writes; ValueError when it is none."""
    found = Reference.parse(text.strip())
    if found is None:
        raise ValueError(text)
    return found


def set_text(element, text: str) -> None:
    """Text of an edsconv element; text XML cannot carry is stored as a JSON string."""
    if not is_xml_text(text):
        element.set("escaped", "json")
        element.text = json.dumps(text, ensure_ascii=True)
    else:
        element.text = text


def get_text(element) -> str:
    text = string_value(element)
    return json.loads(text) if element.get("escaped") == "json" else text


def write_comment(parent, note: CommentNote) -> None:
    """One ``edsconv:Comment``: an element each, so that no text node grows with the file."""
    attributes = {"section": note.section, "keyword": note.keyword,
                  "field": None if note.field is None else str(note.field), "leading": "true" if note.leading else None}
    element = etree.SubElement(parent, EDSCONV + "Comment",
                               {key: xml_text(value) for key, value in attributes.items() if value is not None})
    set_text(element, note.text)


def write_unreadable(parent, item: Unreadable) -> None:
    """One ``edsconv:Unreadable``: where the text stood (``field`` numbered from 1, as the diagnostics
    number it), its exact spelling in ``edsconv:Text``, a statement's comments in ``edsconv:Comment``."""
    attributes = {"section": item.section, "keyword": item.keyword, "before": item.before,
                  "field": None if item.field is None else str(item.field + 1)}
    element = etree.SubElement(parent, EDSCONV + "Unreadable",
                               {key: xml_text(value) for key, value in attributes.items() if value is not None})
    set_text(etree.SubElement(element, EDSCONV + "Text"), item.text)
    for comment in item.comments:
        set_text(etree.SubElement(element, EDSCONV + "Comment"), comment)


def read_unreadable(element) -> Unreadable:
    number = element.get("field")
    field = None if number is None else int(number) - 1
    if field is not None and field < 0:
        raise ValueError(f"an unreadable field numbered {number}")
    if (field is None) != (element.get("keyword") is None):
        raise ValueError("an unreadable field names its keyword and field, a statement neither")
    texts = [get_text(child) for child in element if child.tag == EDSCONV + "Text"]
    if len(texts) != 1:
        raise ValueError("an Unreadable holds one Text")
    return Unreadable(element.get("section", ""), element.get("keyword"), field, texts[0], element.get("before"),
                      tuple(get_text(child) for child in element if child.tag == EDSCONV + "Comment"))


def write_entries(parent, entries: list[GenericEntry]) -> None:
    for entry in entries:
        element = etree.SubElement(parent, EDSCONV + "Entry", keyword=entry.keyword)
        for value in entry.values:
            write_field(element, value)


def write_field(parent, value) -> None:
    element = etree.SubElement(parent, EDSCONV + "Field")
    if value is None:
        element.set("kind", "empty")
    elif isinstance(value, list):
        element.set("kind", "group")
        for item in value:
            write_field(element, item)
    elif isinstance(value, String):
        element.set("kind", "string")
        if len(value.parts) == 1:  # the usual case: the part as text, quotes included
            set_text(element, value.parts[0])
        else:
            for part in value.parts:
                set_text(etree.SubElement(element, EDSCONV + "Part"), part)
    else:
        element.set("kind", "scalar")
        set_text(element, value.raw)


def read_field(element):
    kind = element.get("kind")
    if kind == "empty":
        return None
    if kind == "group":
        return [read_field(child) for child in element if child.tag == EDSCONV + "Field"]
    if kind == "string":
        parts = tuple(get_text(part) for part in element if part.tag == EDSCONV + "Part")
        return eds_string(parts or (get_text(element),))
    if kind == "scalar":
        return eds_scalar(get_text(element))
    raise ValueError(f"unknown field kind {kind!r}")


def eds_string(parts: tuple[str, ...]) -> String:
    """``parts`` as an EDS string's parts, each spelled ``"..."`` or ``L"..."``; ValueError otherwise (a part
    XML text made without its quotes would not read back as the string it was)."""
    for part in parts:
        match = lexicon().string_piece.fullmatch(part)
        if match is None or match.group(1) is None:
            raise ValueError(f"{part[:40]!r} is not a quoted EDS string")
    return String(parts)


def eds_scalar(text: str) -> Scalar:
    """``text`` as an EDS scalar; ValueError when no EDS scalar is spelled so (an empty text, ``a;b``):
    written into an EDS it would not read back as the one field it was."""
    scalar = Scalar(text)
    scalar.kind  # noqa: B018 - raises ValueError for a text that is no scalar
    return scalar


def read_entry(entry) -> GenericEntry:
    """One ``edsconv:Entry``."""
    return GenericEntry(entry.get("keyword", ""), [read_field(f) for f in entry if f.tag == EDSCONV + "Field"])


def read_entries(parent) -> list[GenericEntry]:
    return [read_entry(entry) for entry in parent if entry.tag == EDSCONV + "Entry"]


def read_comment(element) -> CommentNote:
    field = None if element.get("field") is None else int(element.get("field"))
    if field is not None and field < 0:
        raise ValueError(f"a comment on field {field}")
    return CommentNote(element.get("section", ""), element.get("keyword"), field, get_text(element),
                       element.get("leading") == "true")


# --- typed values (edsconv:Value) ------------------------------------------------------------

_CLASSES = {cls.__name__: cls for cls in (
    FileDescription, Identity, Classification, ParamClass, Scaling, Parameter, ParameterGroup, AssemblyMember,
    Assembly, Rack, Query, Modular, Reference, StringIMember, PathItem)}


def _compared_fields(value) -> list[str]:
    return [f.name for f in dataclasses.fields(value) if f.compare and f.init]


def encode(element, value) -> None:
    """Write a model value into ``element`` as ``kind`` plus text or child Values."""
    def child(item, **attributes):
        encode(etree.SubElement(element, EDSCONV + "Value", **attributes), item)

    if value is None:
        element.set("kind", "none")
    elif isinstance(value, bool):
        element.set("kind", "bool")
        element.text = "true" if value else "false"
    elif isinstance(value, int):
        element.set("kind", "int")
        element.text = str(value)
    elif isinstance(value, float):
        element.set("kind", "float")
        element.text = float_text(value)
    elif isinstance(value, str):
        element.set("kind", "str")
        set_text(element, value)
    elif isinstance(value, datetime.time):
        element.set("kind", "time")
        element.text = value.isoformat()
    elif isinstance(value, datetime.date):
        element.set("kind", "date")
        element.text = value.isoformat()
    elif isinstance(value, Revision):
        element.set("kind", "revision")
        element.text = str(value)
    elif isinstance(value, tables.DataType):
        element.set("kind", "datatype")
        element.text = value.name
    elif isinstance(value, Reference):
        element.set("kind", "ref")
        element.text = value.text
    elif isinstance(value, tuple) and value and all(isinstance(item, PathItem) for item in value):
        element.set("kind", "path")
        element.text = " ".join(str(item) for item in value)
    elif isinstance(value, (list, tuple)):
        element.set("kind", type(value).__name__)
        for item in value:
            child(item)
    elif isinstance(value, dict):
        element.set("kind", "dict")
        for key, item in value.items():
            entry = etree.SubElement(element, EDSCONV + "Item")
            encode(etree.SubElement(entry, EDSCONV + "Value"), key)
            encode(etree.SubElement(entry, EDSCONV + "Value"), item)
    elif type(value).__name__ in _CLASSES:
        element.set("kind", "object")
        element.set("class", type(value).__name__)
        for name in _compared_fields(value):
            child(getattr(value, name), name=name)
    else:
        raise TypeError(f"cannot store a {type(value).__name__} in an edsconv:Value")


def decode(element):
    kind = element.get("kind")
    # the text of a scalar, comments and processing instructions skipped; containers have none
    text = "" if kind in ("list", "tuple", "dict", "object") else string_value(element)
    values = [child for child in element if child.tag == EDSCONV + "Value"]
    match kind:
        case "none":
            return None
        case "bool":
            return text == "true"
        case "int":
            return int(text)
        case "float":
            return float(text)
        case "str":
            return get_text(element)
        case "time":
            return datetime.time.fromisoformat(text)
        case "date":
            return datetime.date.fromisoformat(text)
        case "revision":
            major, minor = text.split(".")
            return Revision(int(major), int(minor))
        case "datatype":
            return tables.DATA_TYPES_BY_NAME[text]
        case "ref":
            return reference(text)
        case "path":
            return path_items(text)
        case "list":
            return [decode(child) for child in values]
        case "tuple":
            return tuple(decode(child) for child in values)
        case "dict":
            return {decode(item[0]): decode(item[1]) for item in element if item.tag == EDSCONV + "Item"}
        case "object":
            cls = _CLASSES[element.get("class")]
            return cls(**{child.get("name"): decode(child) for child in values})
    raise ValueError(f"unknown value kind {kind!r}")


def same(a, b) -> bool:
    """Equal and of the same types, all the way down (1 is not 1.0 nor True; NaN is NaN)."""
    if type(a) is not type(b):
        return False
    if isinstance(a, float):
        return a == b or (math.isnan(a) and math.isnan(b))
    if isinstance(a, (list, tuple)):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b, strict=True))
    if isinstance(a, dict):
        return list(a) == list(b) and all(same(a[k], b[k]) and type(k) is type(k2)
                                          for k, k2 in zip(a, b, strict=True))
    if dataclasses.is_dataclass(a) and not isinstance(a, tables.DataType):
        return all(same(getattr(a, name), getattr(b, name)) for name in _compared_fields(a))
    return a == b


_LEAF_CLASSES = (Reference, PathItem, StringIMember, Revision, tables.DataType)


def differences(a, b, path: list[str]) -> list[list[str]]:
    """The model paths where ``a`` (the model) and ``b`` (read back) differ."""
    if type(a) is not type(b):
        return [path]
    if dataclasses.is_dataclass(a) and not isinstance(a, _LEAF_CLASSES):
        return [p for name in _compared_fields(a)
                for p in differences(getattr(a, name), getattr(b, name), path + [name])]
    if isinstance(a, list):
        if len(a) != len(b):
            return [path]
        return [p for index, (x, y) in enumerate(zip(a, b, strict=True))
                for p in differences(x, y, path + [str(index)])]
    if isinstance(a, dict) and all(isinstance(key, str) for key in a):
        if any(key not in a for key in b):
            return [path]
        return [p for key in a for p in (differences(a[key], b[key], path + [key]) if key in b else [path + [key]])]
    return [] if same(a, b) else [path]


def get_path(obj, path: list[str]):
    for segment in path:
        obj = obj[int(segment)] if isinstance(obj, list) else obj[segment] if isinstance(obj, dict) \
            else getattr(obj, segment)
    return obj


def set_path(obj, path: list[str], value) -> None:
    """Set the model value at ``path``; a value of another type than the model declares there is a
    TypeError (it would break whatever reads the model later)."""
    if not conforms(value, declared_type(obj, path)):
        raise TypeError(f"a {type(value).__name__} does not fit the model there")
    parent = get_path(obj, path[:-1])
    last = path[-1]
    if isinstance(parent, list):
        parent[int(last)] = value
    elif isinstance(parent, dict):
        parent[last] = value
    elif dataclasses.is_dataclass(parent) and last in _compared_fields(parent):
        setattr(parent, last, value)
    else:
        raise KeyError(last)
