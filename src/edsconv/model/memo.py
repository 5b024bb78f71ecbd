"""What was made from one entry object, kept from one version of a text to the next.

The language server re-uses the very :class:`~edsconv.eds.syntax.Entry` objects of
the entries an edit did not touch (:mod:`edsconv.lsp.incremental`). What is made from
such an entry alone (its record, the comments it carries, the places that name
other entries in it) is then the same, and is looked up here by the object, never
made again. Whatever other entries decide is made anew on every version.

An edit that adds or removes lines moves the entries after it: the values of a
:class:`Kind` that holds line numbers are then moved with them (:meth:`EntryMemo.lines_moved`).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

#: What :meth:`EntryMemo.get` answers for what it does not hold
MISSING = object()


@dataclass(frozen=True, slots=True, eq=False)
class Kind:
    """A kind of value made from an entry (compared by identity: each is made once, where its values are
    made). ``moved(value, first_line, delta)`` is the value after the lines from ``first_line`` on
    moved ``delta`` lines; None for values that hold no line number (their nodes compute positions
    when asked)."""

    name: str
    moved: Callable[[Any, int, int], Any] | None = None


class EntryMemo:
    """Values by kind and entry object, with the context they were made in (the section's name, or
    a tuple of what else they depend on): a value made in another context is not found.
    Generational: a version keeps what it used, and the rest is let go (with the entries it
    holds alive)."""

    def __init__(self) -> None:
        #: by kind (so that moving lines visits only the kinds that hold them), then by the node's identity
        self._known: dict[Kind, dict[int, _Stored]] = {}
        self._used: dict[Kind, dict[int, _Stored]] = {}
        self._complete = True
        self.hits = self.misses = 0

    def start(self) -> None:
        """A new version: what the last one used is what is known."""
        # a version that stopped half way (superseded) used only part of what is known: keep both
        self._known = self._used if self._complete else _merged(self._known, self._used)
        self._used, self._complete = {}, False

    def finish(self) -> None:
        self._complete = True

    def get(self, kind: Kind, node: object, context: object) -> Any:
        """What was made of ``node`` in ``context`` (and keeps it for the next version), else MISSING."""
        known = self._known.get(kind)
        found = known.get(id(node)) if known is not None else None
        if found is None or found[0] is not node or found[1] != context:
            self.misses += 1
            return MISSING
        self.hits += 1
        self._used_of(kind)[id(node)] = found
        return found[2]

    def put(self, kind: Kind, node: object, context: object, value: Any) -> None:
        self._used_of(kind)[id(node)] = (node, context, value)

    def _used_of(self, kind: Kind) -> dict[int, _Stored]:
        """What this version used of ``kind``, by the node's identity."""
        used = self._used.get(kind)
        if used is None:
            used = self._used[kind] = {}
        return used

    def lines_moved(self, first_line: int, delta: int) -> None:
        """The lines of the text from ``first_line`` on moved ``delta`` lines: every value the next version
        can find (:meth:`start`) says where its entry now stands (the values are in the last text's lines,
        and now in the next's)."""
        known = self._used if self._complete else _merged(self._known, self._used)
        self._used = {kind: values if kind.moved is None else
                      {key: (node, context, kind.moved(value, first_line, delta))
                       for key, (node, context, value) in values.items()}
                      for kind, values in known.items()}
        self._known, self._complete = {}, True


#: A value with the node it was made of and the context it was made in
_Stored = tuple[object, object, Any]


def _merged(known: dict[Kind, dict[int, _Stored]],
            used: dict[Kind, dict[int, _Stored]]) -> dict[Kind, dict[int, _Stored]]:
    """What ``known`` and ``used`` hold, ``used``'s value where both hold one."""
    return {kind: {**known.get(kind, {}), **used.get(kind, {})} for kind in known.keys() | used.keys()}
