"""Which keywords are defined, by the 2003 text or by the newer CIP tables, and the closest one to a word.

C.4.1.2.2.10: a public keyword is one the CIP specification defines. edsconv holds the 2003 text's
keywords (:mod:`edsconv.spec_tables`) and those later editions added that real files and eds-pie
show (:mod:`edsconv.cip_tables`); a keyword in neither, that is not vendor-specific, is unknown
(EDS222), and :func:`closest` finds what it was probably meant to be. Whether a section or keyword is
known is :func:`edsconv.cip_tables.known`'s answer; this module adds where else a keyword is defined
and the keywords a misspelling is compared with.
"""

from __future__ import annotations

import difflib
import functools
from collections.abc import Iterable

from edsconv import cip_tables
from edsconv import spec_tables as tables

#: How alike a word and a keyword must be (difflib's ratio) to be offered as "did you mean"; a word
#: that begins a keyword (``Conn`` of ``Connection``) is offered however short it is.
_LIKENESS = 0.6


def newer_entry(section: str, keyword: str) -> bool:
    """True when the newer tables define ``keyword`` in ``section``, or in any section (keywords are
    global in scope, C.4.1.2.2.8); the 2003 text's entries are looked up in spec_tables."""
    names, families = _newer_keywords()
    if keyword in names:
        return True
    family, number = tables.split_numbered(keyword)
    return number is not None and family in families


@functools.cache
def _newer_keywords() -> tuple[frozenset[str], frozenset[str]]:
    """(keywords and aliases, numbered families) of every newer section table: one lookup per
    keyword, not one per table (a file of 4,000 unknown keywords took 2 s)."""
    specs = [spec for section in cip_tables.all_sections() for spec in section.entries]
    return (frozenset(name for spec in specs if not spec.numbered for name in (spec.keyword, *spec.aliases)),
            frozenset(spec.keyword for spec in specs if spec.numbered))


@functools.cache
def section_names() -> tuple[str, ...]:
    return tuple(dict.fromkeys((*tables.SECTIONS, *cip_tables.CIP_SECTIONS)))


@functools.cache
def entry_keywords(section: str) -> tuple[tuple[str, ...], tuple[str, ...]]:
    """(keywords, numbered families) the 2003 text and the newer tables define in ``section``."""
    specs = [*tables.SECTIONS[section].entries] if section in tables.SECTIONS else []
    newer = cip_tables.section_spec(section)
    specs += newer.entries if newer is not None else ()
    return (tuple(name for spec in specs if not spec.numbered for name in (spec.keyword, *spec.aliases)),
            tuple(spec.keyword for spec in specs if spec.numbered))


def classification_keywords() -> tuple[str, ...]:
    return (*tables.CLASSIFICATION_KEYWORDS, *cip_tables.CLASSIFICATION_KEYWORDS_NEWER)


@functools.lru_cache(maxsize=4096)
def closest(word: str, keywords: tuple[str, ...], families: tuple[str, ...] = ()) -> str | None:
    """The defined keyword ``word`` most likely stands for: ``Parameter5`` -> ``Param5`` (a numbered
    family keeps the number), ``Catalogue`` -> ``Catalog``; None when none is alike enough.
    Cached: a file may repeat one unknown word thousands of times, and difflib is slow."""
    prefix, number = tables.split_numbered(word)
    if number is not None:
        family = _alike(prefix, families)
        if family is not None:
            return f"{family}{number}"
    return _alike(word, keywords)


def _alike(word: str, candidates: Iterable[str]) -> str | None:
    by_lower = {candidate.lower(): candidate for candidate in candidates}
    lowered = word.lower()
    found = difflib.get_close_matches(lowered, list(by_lower), n=1, cutoff=_LIKENESS)
    found = found or sorted((c for c in by_lower if len(lowered) > 2 and c.startswith(lowered)), key=len)[:1]
    return by_lower[found[0]] if found else None
