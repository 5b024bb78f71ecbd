"""What was made from one entry object, kept from one version of a text to the next.

The language server re-uses the very :class:`~edsconv.eds.syntax.Entry` objects of
the entries an edit did not touch (:mod:`edsconv.lsp.incremental`). What is made from
such an entry alone (its record, the comments it carries, the places that name
other entries in it) is then the same, and is looked up here by the object, never
made again. Whatever other entries decide is made anew on every version.
"""

from __future__ import annotations

from typing import Any

#: What :meth:`EntryMemo.get` answers for what it does not hold
MISSING = object()


class EntryMemo:
    """Values by kind and entry object, with the context they were made in (the section's name, or
    a tuple of what else they depend on): a value made in another context is not found.
    Generational: a version keeps what it used, and the rest is let go (with the entries it
    holds alive)."""

    def __init__(self) -> None:
        self._known: dict[tuple[str, int], tuple[object, object, Any]] = {}
        self._used: dict[tuple[str, int], tuple[object, object, Any]] = {}
        self._complete = True
        self.hits = self.misses = 0

    def start(self) -> None:
        """A new version: what the last one used is what is known."""
        # a version that stopped half way (superseded) used only part of what is known: keep both
        self._known = self._used if self._complete else {**self._known, **self._used}
        self._used, self._complete = {}, False

    def finish(self) -> None:
        self._complete = True

    def get(self, kind: str, node: object, context: object) -> Any:
        """What was made of ``node`` in ``context`` (and keeps it for the next version), else MISSING."""
        key = (kind, id(node))
        found = self._known.get(key)
        if found is None or found[0] is not node or found[1] != context:
            self.misses += 1
            return MISSING
        self.hits += 1
        self._used[key] = found
        return found[2]

    def put(self, kind: str, node: object, context: object, value: Any) -> None:
        self._used[(kind, id(node))] = (node, context, value)
