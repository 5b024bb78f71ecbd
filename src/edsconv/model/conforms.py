"""Does a value fit a model field's declared type? For values that come from outside (an
``edsconv:Value`` of an XML profile): a value of another type would break the code that reads
the model later (a list field holding ``true`` made ``xml2eds`` fail, found by fuzzing).

Only what the model's annotations use is understood: classes, ``X | None`` and other unions,
``list[X]``, ``tuple[X, ...]`` / ``tuple[X, Y]``, ``dict[K, V]``, ``Literal`` and ``Any``; a
dataclass value is checked field by field. Anything else is accepted.
"""

from __future__ import annotations

import dataclasses
import functools
import types
import typing
from typing import Any


def conforms(value: Any, hint: Any) -> bool:
    """``value`` has the shape ``hint`` describes: containers, dataclasses and value classes as declared;
    the scalars int, float, str and bool in place of each other (see _SCALARS)."""
    origin = typing.get_origin(hint)
    if hint is Any or isinstance(hint, typing.TypeVar):
        return True
    if origin in (typing.Union, types.UnionType):
        return any(conforms(value, arg) for arg in typing.get_args(hint))
    if origin is typing.Literal:
        return value in typing.get_args(hint)
    if origin is not None:
        return _conforms_generic(value, origin, typing.get_args(hint))
    if hint is None or hint is type(None):
        return value is None
    if not isinstance(hint, type):
        return True
    return _conforms_class(value, hint)


#: The scalar types a model field may hold in place of each other: a field declared ``int`` holds the
#: keyword ``Module`` of a ProxyParam, or a value's spelling when it has no reading (Device.erroneous).
_SCALARS = (int, float, str, bool)


def _conforms_class(value: Any, cls: type) -> bool:
    if cls in _SCALARS:
        return isinstance(value, _SCALARS)
    if not isinstance(value, cls):
        return False
    return not dataclasses.is_dataclass(value) or fields_conform(value)


def _conforms_generic(value: Any, origin: Any, args: tuple[Any, ...]) -> bool:
    if not isinstance(origin, type):
        return True
    if not _is_instance(value, origin):
        return False
    if not args:
        return True
    if origin is tuple:
        if len(args) == 2 and args[1] is Ellipsis:
            return all(conforms(item, args[0]) for item in value)
        return len(value) == len(args) and all(conforms(item, arg) for item, arg in zip(value, args, strict=True))
    if origin is dict:
        return all(conforms(k, args[0]) and conforms(v, args[1]) for k, v in value.items())
    if origin in (list, set, frozenset):
        return all(conforms(item, args[0]) for item in value)
    return True


def _is_instance(value: Any, cls: type) -> bool:
    """isinstance, without narrowing ``value`` for mypy (its items are read afterwards)."""
    return isinstance(value, cls)


def fields_conform(value: Any) -> bool:
    """Every field of the dataclass instance ``value`` fits its declared type."""
    hints = field_types(value.__class__)
    return all(conforms(getattr(value, name), hint) for name, hint in hints.items())


@functools.cache
def field_types(cls: type) -> dict[str, Any]:
    """The declared type of each init field of the dataclass ``cls``, its annotations resolved."""
    import sys

    from edsconv.model import cip, icon  # the model's own type-checking-only imports (Device.capacity ...)

    namespace = {**vars(cip), **vars(icon), **vars(sys.modules[cls.__module__])}
    try:
        hints = typing.get_type_hints(cls, globalns=namespace)
    except (NameError, TypeError):  # an annotation this module cannot resolve: that field is not checked
        hints = {}
    return {f.name: hints.get(f.name, Any) for f in dataclasses.fields(cls) if f.init}


def declared_type(root: Any, path: list[str]) -> Any:
    """The declared type of what sits at ``path`` below ``root`` (attribute names, list indexes and
    dict keys, as :func:`edsconv.xml.codec.get_path` walks them); ``Any`` where nothing declares it."""
    hint: Any = Any
    obj = root
    for segment in path:
        if dataclasses.is_dataclass(obj) and not isinstance(obj, type):
            hint = field_types(type(obj)).get(segment, Any)
            obj = getattr(obj, segment, None)
        elif isinstance(obj, list):
            hint = _item_type(hint, list, 0)
            obj = obj[int(segment)] if segment.isdigit() and int(segment) < len(obj) else None
        elif isinstance(obj, dict):
            hint = _item_type(hint, dict, 1)
            obj = obj.get(segment)
        else:
            return Any
    return hint


def _item_type(hint: Any, container: type, index: int) -> Any:
    """The item type of the ``container`` alternative of ``hint`` (``list[X] | None`` -> X)."""
    alternatives = typing.get_args(hint) if typing.get_origin(hint) in (typing.Union, types.UnionType) else (hint,)
    for alternative in alternatives:
        if typing.get_origin(alternative) is container and len(typing.get_args(alternative)) > index:
            return typing.get_args(alternative)[index]
    return Any
