"""edsconv: parse, check and convert CIP Electronic Data Sheets (ISO 15745-4 Annex C.4)."""

from edsconv.reader import load, parse
from edsconv.syntax import Comment, EdsFile, Entry, Field, Group, Scalar, Section, String, ValueKind

__all__ = ["Comment", "EdsFile", "Entry", "Field", "Group", "Scalar", "Section", "String", "ValueKind", "load", "parse"]
