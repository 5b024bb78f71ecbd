"""Checks of the file's structure: sections, entries, keywords, identity (C.4.1.2, C.4.1.4, C.4.2)."""
