"""``edsconv lsp``: a language server for EDS files, a thin adapter over the library.

:mod:`~edsconv.lsp.server` wires the handlers; each feature is a small module
that turns what the library knows (the syntax model with positions, the typed
model with resolved references, the spec tables, the rule registry, ``show``'s
descriptions, the canonical writer) into Language Server Protocol answers.
pygls and lsprotocol come with the ``lsp`` extra: ``pip install '/path/to/edsconv[lsp]'`` (a clone;
edsconv is not on PyPI).
"""
