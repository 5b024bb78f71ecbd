"""The rules the reader reports (EDS001-EDS017), each with its documentation.

The reader is :mod:`edsconv.eds.reader`; docs/rules.md is generated from these definitions
(``edsconv rules --format markdown``). They have a module of their own because they outgrow the reader.
"""

from __future__ import annotations

from edsconv.diagnostics import Severity, block, rule

ERROR, WARNING, INFO = Severity.ERROR, Severity.WARNING, Severity.INFO

SYNTAX_ERROR = rule(
    "EDS001", Severity.ERROR, "C.4.1.2.2", "Text that does not follow the EDS syntax",
    explanation="""
        Text that does not follow the EDS syntax: every statement is a section header
        `[Name]` or an entry `Keyword = field, field, ...;`. Reading resumes after the
        next `;` or at the next line that starts a statement.
    """,
    bad=block("""
        [File]
                Revision 1.1;           $ no '='
    """),
    good=block("""
        [File]
                Revision = 1.1;
    """),
)
MISSING_SEMICOLON = rule(
    "EDS002", Severity.ERROR, "C.4.1.2.2.8", "An entry does not end with ';'",
    fix="safe",
    explanation="""
        An entry does not end with `;`. edsconv assumes one at the end of the last
        field and reads on; other tools merge the entry with the next statement.
    """,
    bad=block("""
        [File]
                DescText = "Adapter"
        [Device]
                VendCode = 65535;
    """),
    good=block("""
        [File]
                DescText = "Adapter";
        [Device]
                VendCode = 65535;
    """),
)
BAD_ESCAPE = rule(
    "EDS003", Severity.ERROR, "C.4.1.3.3.5", "A string holds an escape sequence not in Table C.4",
    explanation=r"""
        A string holds an escape sequence that Table C.4 does not define, such as `\e`
        or `\p`. A backslash is written `\\`. Each part of a string of several
        adjacent parts is decoded on its own before the parts are joined: an escape
        never spans two parts, so `"\x4" "1"` is the undefined escape `\x4`, not `A`.
    """,
    bad=block(r"""
        [File]
                DescText = "C:\eds\files";
    """),
    good=block(r"""
        [File]
                DescText = "C:\\eds\\files";
    """),
)
UNICODE_ESCAPE_IN_ASCII = rule(
    "EDS004", Severity.ERROR, "C.4.1.3.3.5", r"A \u escape stands in an 8-bit string (valid only after L)",
    explanation=r"""
        A `\u` escape stands in an 8-bit string. `\uXXXX` is valid only in a UNICODE
        string, the one written `L"..."`.
    """,
    bad=block(r"""
        [Device]
                ProdName = "Caf\u00e9 adapter";
    """),
    good=block(r"""
        [Device]
                ProdName = L"Caf\u00e9 adapter";
    """),
)
NOT_ASCII = rule(
    "EDS005", Severity.WARNING, "C.4.1.3.2", "The file holds characters outside ASCII",
    explanation=r"""
        An EDS is ASCII; edsconv reads UTF-8, Windows-1252 and Latin-1 all the same and
        names the first line that is not ASCII, and reads UTF-16 and UTF-32 files by their
        byte order mark, but other tools may show or reject such text. Write the text in a
        UNICODE string with `\u` escapes instead.
        A warning, not an error: C.4.1.3.2 defines its "8-bit ASCII" by Row 00 of
        ISO/IEC 10646-1, which holds the Latin-1 characters too, while it lists 32 to 126
        as the valid values; 3 of the 61 real files hold such characters, and tools read
        them.
    """,
    bad=block("""
        [Device]
                VendName = "Müller GmbH";
    """),
    good=block(r"""
        [Device]
                VendName = L"M\u00fcller GmbH";
    """),
)
SECTION_NAME = rule(
    "EDS006", Severity.WARNING, "C.4.1.2.2.3", "A section name uses characters the 2003 keyword rules do not allow",
    explanation="""
        A section name uses characters or spacing the keyword rules do not allow:
        letters, digits and `_`, with single spaces between words. A warning, not an
        error: later CIP editions name object class sections this way themselves, 46 of
        the 61 real files use such names, and tools accept them; a tool that follows the
        2003 rules alone rejects them. Not reported for the names the newer tables define
        (`[TCP/IP Interface Class]`, `[EtherNet/IP Security Class]`: edsconv.cip_tables).
    """,
    bad=block("""
        [Diagnostics/Extra]
                Revision = 4;
    """),
    good=block("""
        [TCP/IP Interface Class]
                Revision = 4;
    """),
)
DUPLICATE_SECTION = rule(
    "EDS008", Severity.ERROR, "C.4.1.2.1", "A section appears more than once",
    import_blocking=True,
    clause_note="Table C.3",
    explanation="""
        A section appears more than once. C.4.1.2.1 says an EDS "shall be organised" as
        Table C.3 gives its structure, with each section once ([File] first, [Device]
        right after it, each optional section at one place); no sentence forbids a
        second one in so many words. edsconv keeps both, but tools read only one of them,
        so the other's entries are lost.
    """,
    bad=block("""
        [Device]
                VendCode = 65535;
        [Device]
                ProdCode = 1001;
    """),
    good=block("""
        [Device]
                VendCode = 65535;
                ProdCode = 1001;
    """),
)
DUPLICATE_ENTRY = rule(
    "EDS009", Severity.ERROR, "C.4.1.2.2.9", "An entry keyword appears twice in one section",
    import_blocking=True,
    explanation="An entry keyword appears twice in one section.",
    bad=block("""
        [Device]
                VendCode = 65535;
                VendCode = 1;
    """),
    good=block("""
        [Device]
                VendCode = 65535;
    """),
)
#: The rules whose messages name the line of another statement (where the first of two stands)
NAMING_A_LINE = frozenset({DUPLICATE_SECTION.code, DUPLICATE_ENTRY.code})
CANOPEN_EDS = rule(
    "EDS010", Severity.ERROR, "C.4.1.1", "The file is a CANopen EDS (CiA 306), not a CIP EDS",
    explanation="""
        The file is a CANopen EDS (CiA 306: `[FileInfo]`, `[DeviceInfo]`, object
        sections such as `[1000]`), not a CIP EDS. edsconv reads CIP EDS files only and
        stops here.
    """,
    bad=block("""
        [FileInfo]
        FileName=drive.eds
        [DeviceInfo]
        VendorName=Someone
        [1000]
        ParameterName=Device type
    """),
    good=block("""
        [File]
                DescText = "Drive";
        [Device]
                VendName = "Someone";
    """),
)
ENTRY_OUTSIDE_SECTION = rule(
    "EDS011", Severity.ERROR, "C.4.1.2.2.8", "An entry stands before the first section",
    explanation="An entry stands before the first section header: every entry belongs to a section.",
    bad=block("""
                VendCode = 65535;
        [Device]
                ProdCode = 1001;
    """),
    good=block("""
        [Device]
                VendCode = 65535;
                ProdCode = 1001;
    """),
)
MISSING_COMMA = rule(
    "EDS012", Severity.ERROR, "C.4.1.2.2.12", "Two fields are not separated by a comma",
    explanation="Two fields are not separated by a comma; here a group `{...}` follows a value.",
    bad=block("""
        [Params]
                Enum1 = 0 {1, 2};
    """),
    good=block("""
        [Params]
                Enum1 = 0, {1, 2};
    """),
)
UNTERMINATED_STRING = rule(
    "EDS013", Severity.ERROR, "C.4.1.3.3", "A string has no closing quote on its line",
    explanation="""
        A string never spans lines; a long one is written as adjacent strings, which are
        concatenated.
    """,
    bad=block("""
        [File]
                DescText = "Adapter;
    """),
    good=block("""
        [File]
                DescText = "Adapter "
                           "for 8 channels";
    """),
)
TOO_MANY_ERRORS = rule(
    "EDS014", Severity.ERROR, "C.4.1.2.2", "So many syntax errors that reading stopped",
    explanation="""
        So many syntax errors (100, a missing `;` included) that reading stopped; the rest
        of the file is not read. The file is most likely not an EDS, or badly damaged. Fix
        the first errors reported: they usually cause the others.
    """,
    bad="""
        a file of 120 lines such as

        ```
        [File]
                Revision 1.1;
                Revision 1.1;
                $ ... 118 more
        ```
    """,
    good=block("""
        [File]
                Revision = 1.1;
    """),
)
NO_SECTIONS = rule(
    "EDS015", Severity.ERROR, "C.4.1.2.2.4", "The file has no sections",
    import_blocking=True,
    explanation="The file has no sections: it is empty, or holds only comments.",
    bad=block("""
        $ generated by a tool that wrote nothing else
    """),
    good=block("""
        $ generated by a tool
        [File]
                DescText = "Adapter";
    """),
)
LONG_PREFIX_ON_CONTINUATION = rule(
    "EDS016", Severity.ERROR, "C.4.1.3.3.4", "Only the first part of a concatenated string may carry the L prefix",
    explanation="""
        In a concatenated string only the first part may carry the `L` (UNICODE) prefix;
        the whole string is UNICODE then. An error, as the text's "shall": none of the 61
        real files of the test corpus breaks it, so no tool practice argues for less.
    """,
    bad=block("""
        [File]
                DescText = L"first part "
                           L"second part";
    """),
    good=block("""
        [File]
                DescText = L"first part "
                           "second part";
    """),
)
TOO_DEEP = rule(
    "EDS017", Severity.ERROR, "C.4.1.2.14", "Braces are nested deeper than any EDS needs",
    explanation="""
        Brace groups nest deeper than 64 levels. Real files nest three deep at most; the
        entry is kept as text (and written back unchanged) but not interpreted.
    """,
    bad="`Data = {{{{ ... 65 levels ... }}}};`",
    good=block("""
        [Example]
                Entry6 = { 44, {22,33,11} };
    """),
)
