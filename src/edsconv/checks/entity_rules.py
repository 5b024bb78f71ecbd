"""The rules the entity checks report (EDS301-EDS340; EDS328 and EDS341 on are the addressing rules), each
with its documentation.

The checks are in :mod:`edsconv.checks.entities`; docs/rules.md is generated from these definitions
(``edsconv rules --format markdown``). They have a module of their own because they outgrow the checks.
"""

from __future__ import annotations

from edsconv.diagnostics import TRIGGERS, Severity, block, rule

ERROR, WARNING, INFO = Severity.ERROR, Severity.WARNING, Severity.INFO

UNDEFINED_REFERENCE = rule(
    "EDS301", Severity.ERROR, "C.4.1.4.8",
    "A ParamN, ProxyParamN, AssemN or ProxyAssemN used in the file is not defined",
    import_blocking=True,
    clause_note="the clause of the field: C.4.1.4.8 assembly members, C.4.1.4.9.4 - C.4.1.4.9.10 connection "
                "fields, C.4.1.4.9.13 connection paths, C.4.1.5.2.2 SlotDisplayRule",
    explanation="""
        A reference names an entry the file does not define: an assembly member
        ("a ParamN or ProxyParamN reference from the [Params] section"), a connection
        RPI/size/format, the chassis `SlotDisplayRule`, or a `[ParamN]` / `ProxyParamN`
        inside a connection path. The diagnostic cites the clause of its field. A tool
        cannot size or show the data; Rockwell's import refuses an AssemN/ParamN used
        but not defined.

        A group member is not reported: a `GroupN` lists Parameter object instance
        numbers (Table C.19), and C.4.1.4.6 says "it is not required that ALL parameter
        object instances have a corresponding ParamN entry", so a group may list an
        instance the EDS does not describe.
        A reference in a ProxiedParam, ProxiedAssem or ProxiedConnect is not checked in
        the module's file alone: it names an entry of the pair, which may be the
        adapter's (C.4.1.5.3); `edsconv merge` checks it in the entry the pair forms.
    """,
    bad=block("""
        Assem100 = "In", "", 4,,,, 32, Param9;   $ no Param9 in [Params]
    """),
    good=block("""
        Assem100 = "In", "", 4,,,, 32, Param1;   $ Param1 is defined
    """),
    labels=TRIGGERS,
)
WRONG_PARAMETER_TYPE = rule(
    "EDS302", Severity.ERROR, "C.4.1.4.9.4",
    "A parameter named as a connection RPI, size or path value does not have the data type the field evaluates to",
    clause_note="the clause of the field: C.4.1.4.9.4, .7 RPI; C.4.1.4.9.5, .8, .10 sizes; C.4.1.4.9.13 path",
    explanation="""
        A parameter named as a connection RPI, size or path value does not have the data
        type the field evaluates to. A connection's RPI shall evaluate to a UDINT, a
        size to a UINT (C.4.1.4.9.4 - .10), a parameter inside the path to a USINT, UINT
        or UDINT (C.4.1.4.9.13). The referenced ParamN has another data type.
        A ProxiedConnect entry alone is not judged by this rule: its fields count only where
        the adapter's Proxy entry says `Module` and are documentation elsewhere (C.4.1.5.3);
        `edsconv merge` checks the entry the pair forms.
    """,
    bad=block("""
        Param2 = 0,,,0x0000,0xC6,1,"Filter","ms","",0,255,3;   $ USINT
        Connection1 = 0x04010002, 0x44640405, Param2,4,Assem100, ...
    """),
    good=block("""
        Connection1 = 0x04010002, 0x44640405, Param1,4,Assem100, ...   $ Param1 is a UDINT
    """),
    labels=TRIGGERS,
)
UNPAIRED_ENTRY = rule(
    "EDS303", Severity.ERROR, "C.4.1.4.6",
    "An EnumN, ProxyEnumN, ProxiedEnumN or ProxyParamSizeAdderN has no parameter with its number",
    explanation="""
        An EnumN, ProxyEnumN, ProxiedEnumN or ProxyParamSizeAdderN has no parameter with
        its number. `EnumN`, `ProxyEnumN`, `ProxiedEnumN` and `ProxyParamSizeAdderN`
        belong to the ParamN / ProxyParamN / ProxiedParamN of the same number
        (C.4.1.4.6, C.4.1.5.3.1); there is none.
    """,
    bad=block("""
        Enum5 = 0,"Off",1,"On";   $ no Param5
    """),
    good=block("""
        Enum2 = 0,"Off",1,"On";   $ Param2 exists
    """),
    labels=TRIGGERS,
)
GROUP_MEMBER_COUNT = rule(
    "EDS304", Severity.ERROR, "C.4.1.4.7", "A group's Number of Members differs from the members it lists",
    explanation="""
        Field 2 of a GroupN gives the number of members; fields 3 .. members + 2 list them
        (Table C.19). The count and the list differ.
    """,
    bad=block("""
        Group1 = "Setup", 2, 1;
    """),
    good=block("""
        Group1 = "Setup", 1, 1;
    """),
    labels=TRIGGERS,
)
DUPLICATE_CONNECTION_NAME = rule(
    "EDS305", Severity.ERROR, "C.4.1.4.9.11", "Two connections have the same name string",
    explanation="""
        The connection name string shall be unique among the connections of the file
        (C.4.1.4.9.11). Connection and ProxyConnect entries are compared; ProxiedConnect
        entries describe the module's side and are not.
    """,
    bad=block("""
        Connection1 = ..., "EO", "", "20 04 24 64";
        Connection2 = ..., "EO", "", "20 04 24 65";
    """),
    good=block("""
        Connection1 = ..., "EO", "", "20 04 24 64";
        Connection2 = ..., "EO 2", "", "20 04 24 65";
    """),
    labels=TRIGGERS,
)
TRIGGER_RESERVED_BITS = rule(
    "EDS306", Severity.ERROR, "C.4.1.4.9.2", "A trigger and transport mask sets reserved bits",
    explanation="""
        Bits 7-15, 19-23 and 28-30 of the trigger and transport mask are reserved (Table
        C.23) and shall be 0.
    """,
    bad=block("""
        Connection1 = 0x04010082, ...   $ bit 7
    """),
    good=block("""
        Connection1 = 0x04010002, ...
    """),
    labels=TRIGGERS,
)
TRANSPORT_NOT_ONE = rule(
    "EDS307", Severity.ERROR, "C.4.1.4.9.2", "A trigger and transport mask does not set exactly one transport type",
    explanation="""
        Only one of the transport type bits 24-27 (listen-only, input-only,
        exclusive-owner, redundant-owner) shall be set (C.4.1.4.9.2). Every connection of
        the real corpus sets exactly one, so none or several is an error.
    """,
    bad=block("""
        Connection1 = 0x05010002, ...   $ listen-only and exclusive-owner
    """),
    good=block("""
        Connection1 = 0x04010002, ...   $ exclusive-owner
    """),
    labels=TRIGGERS,
)
NO_CLASS_OR_TRIGGER = rule(
    "EDS308", Severity.ERROR, "C.4.1.4.9.2", "A trigger and transport mask sets no class or no trigger",
    explanation="""
        A connection supports at least one transport class (bits 0-6) and one trigger (bits
        16-18); a mask with none describes no usable connection.
    """,
    bad=block("""
        Connection1 = 0x04010000, ...   $ no class
    """),
    good=block("""
        Connection1 = 0x04010002, ...   $ class 1
    """),
    labels=TRIGGERS,
)
PARAMETERS_RESERVED_BITS = rule(
    "EDS309", Severity.ERROR, "C.4.1.4.9.3", "A connection parameters mask sets reserved bits",
    explanation="""
        Bits 11, 15, 19, 23, 27 and 31 of the connection parameters are reserved (Table
        C.24) and shall be 0.
    """,
    bad=block("""
        Connection1 = 0x04010002, 0x44640C05, ...   $ bit 11
    """),
    good=block("""
        Connection1 = 0x04010002, 0x44640405, ...
    """),
    labels=TRIGGERS,
)
RESERVED_REAL_TIME_FORMAT = rule(
    "EDS310", Severity.ERROR, "C.4.1.4.9.3", "A connection uses a reserved real time transfer format",
    import_blocking=True,
    explanation="""
        A real time transfer format (bits 8-10 O=>T, 12-14 T=>O) of 2, 6 or 7: reserved by
        Table C.24. Rockwell's import refuses an invalid real time format. Format 5 is
        EDS337.
    """,
    bad=block("""
        Connection1 = 0x04010002, 0x44640205, ...   $ O=>T format 2
    """),
    good=block("""
        Connection1 = 0x04010002, 0x44640405, ...   $ O=>T format 4, run/idle header
    """),
    labels=TRIGGERS,
)
SIZE_WITHOUT_FORMAT = rule(
    "EDS311", Severity.ERROR, "C.4.1.4.9.6", "A connection leaves both size and format of a direction empty",
    explanation="""
        The O=>T (T=>O) format shall not be empty when the size is empty (C.4.1.4.9.6, .9):
        nothing gives the size. Not reported for a direction whose real time format is 5
        (CIP Safety, see EDS337): safety connections take their sizes from the safety
        parameters.
        A ProxiedConnect entry alone is not judged by this rule: its fields count only where
        the adapter's Proxy entry says `Module` and are documentation elsewhere (C.4.1.5.3);
        `edsconv merge` checks the entry the pair forms.
    """,
    bad=block("""
        Connection1 = 0x04010002, 0x44640405, Param1,,, Param1,4,Assem100, ...
    """),
    good=block("""
        Connection1 = 0x04010002, 0x44640405, Param1,4,, Param1,4,Assem100, ...
    """),
    labels=TRIGGERS,
)
SIZE_FORMAT_MISMATCH = rule(
    "EDS312", Severity.WARNING, "C.4.1.4.9.5", "A connection's size differs from the size of its format assembly",
    explanation="""
        The size field and the size of the format assembly (its Size field) differ. A
        warning: the text lets the size include a run/idle header, but every real file
        gives the assembly's size.
        A ProxiedConnect entry alone is not judged by this rule: its fields count only where
        the adapter's Proxy entry says `Module` and are documentation elsewhere (C.4.1.5.3);
        `edsconv merge` checks the entry the pair forms.
    """,
    bad=block("""
        Connection1 = 0x04010002, 0x44640405, Param1,8,Assem100, ...   $ Assem100 is 4 bytes
    """),
    good=block("""
        Connection1 = 0x04010002, 0x44640405, Param1,4,Assem100, ...
    """),
    labels=TRIGGERS,
)
PROXY_CONNECT_NAME_MODULE = rule(
    "EDS313", Severity.ERROR, "C.4.1.5.3.3", "A ProxyConnect's connection name is 'Module'",
    explanation="""
        A ProxyConnect shall always give its own connection name string (field 13),
        never `Module` (C.4.1.5.3.3): the adapter gives the name itself. `edsconv lint`
        reports it in the adapter's file; `edsconv merge` reports it too and leaves the
        entry out of the combination.
    """,
    bad=block("""
        ProxyConnect2 = 0x04010002, 0x44640405, ..., Module, "", "20 04 24 64";
    """),
    good=block("""
        ProxyConnect2 = 0x04010002, 0x44640405, ..., "LO", "", "20 04 24 64";
    """),
    labels=TRIGGERS,
    aliases={"EDS407": """
        The code `edsconv merge` gave this fault before it reported the code `edsconv lint`
        gives: a ProxyConnect named `Module` is a fault of the adapter's file alone.
    """},
)
PARAM_RESERVED_BITS = rule(
    "EDS314", Severity.WARNING, "C.4.1.4.6", "A parameter descriptor sets reserved bits (Table C.15)",
    explanation="""
        Bits 9-15 of a parameter descriptor are reserved (Table C.15). A warning, not an
        error: ODVA-certified files set bit 9, which later CIP editions assign.
    """,
    bad=block("""
        Param2 = 0,,,0x0200,0xC6,1,"Filter","ms","",0,255,3;
    """),
    good=block("""
        Param2 = 0,,,0x0010,0xC6,1,"Filter","ms","",0,255,3;
    """),
    labels=TRIGGERS,
)
VALUE_ORDER = rule(
    "EDS315", Severity.ERROR, "C.4.1.4.6",
    "A parameter's minimum, maximum and default are not in order min <= default <= max",
    explanation="""
        A parameter's minimum, maximum and default are not in order min <= default <=
        max. Minimum <= default <= maximum, where an empty minimum or maximum is the
        data type's own bound (Table C.17 note b; for REAL and LREAL the bounds are
        -INFINITY and INFINITY, values C.4.1.3.10 reserves words for); for strings and
        EPATH, minimum length <= maximum length. A default of QUIET-NAN or SIGNAL-NAN
        is not a number to compare and is not reported. A default outside the data
        type's range is EDS102.
        A ProxiedParam entry alone is not judged by this rule: its fields count only where
        the adapter's Proxy entry says `Module` and are documentation elsewhere (C.4.1.5.3);
        `edsconv merge` checks the entry the pair forms.
    """,
    bad=block("""
        Param2 = 0,,,0x0000,0xC6,1,"Filter","ms","",10,5,7;
    """),
    good=block("""
        Param2 = 0,,,0x0000,0xC6,1,"Filter","ms","",5,10,7;
    """),
    labels=TRIGGERS,
)
STRING_LENGTHS_MISSING = rule(
    "EDS316", Severity.ERROR, "C.4.1.4.6",
    "A string parameter does not give its minimum and maximum length (Table C.17)",
    explanation="""
        STRING, STRING2, STRINGN and SHORT_STRING parameters shall give the minimum and
        maximum string length in fields 10 and 11 (Table C.17: required).
        A ProxiedParam entry alone is not judged by this rule: its fields count only where
        the adapter's Proxy entry says `Module` and are documentation elsewhere (C.4.1.5.3);
        `edsconv merge` checks the entry the pair forms.
    """,
    bad=block("""
        Param3 = 0,,,0x0000,0xD0,1,"Name","","",,,"abc";
    """),
    good=block("""
        Param3 = 0,,,0x0000,0xD0,1,"Name","","",0,16,"abc";
    """),
    labels=TRIGGERS,
)
BIT_STRING_MIN_MAX = rule(
    "EDS317", Severity.WARNING, "C.4.1.4.6",
    "A bit string parameter (BYTE, WORD, DWORD, LWORD) gives a minimum or maximum (Table C.17)",
    explanation="""
        A bit string parameter (BYTE, WORD, DWORD, LWORD) gives a minimum or maximum
        (Table C.17). BYTE, WORD, DWORD and LWORD have no minimum or maximum; they shall
        not be specified (Table C.17). A warning, not an error: 11 of the 61 real files
        (193 parameters, Murrelektronik's product files among them) give them, and tools
        ignore them.
        A ProxiedParam entry alone is not judged by this rule: its fields count only where
        the adapter's Proxy entry says `Module` and are documentation elsewhere (C.4.1.5.3);
        `edsconv merge` checks the entry the pair forms.
    """,
    bad=block("""
        Param3 = 0,,,0x0000,0xD2,2,"Word","","",0,0xFFFF,0;
    """),
    good=block("""
        Param3 = 0,,,0x0000,0xD2,2,"Word","","",,,0;
    """),
    labels=TRIGGERS,
)
SCALING_ON_NON_NUMERIC = rule(
    "EDS318", Severity.WARNING, "C.4.1.4.6",
    "A parameter of a non-numeric type gives scaling, link or precision fields (Table C.18)",
    explanation="""
        A parameter of a non-numeric type gives scaling, link or precision fields (Table
        C.18). Fields 13-21 (scaling, links, decimal precision) are only for SINT ...
        ULINT, REAL and LREAL; giving them for other types is prohibited (Table C.18). A
        warning, not an error: Rockwell's own EDS of the E1 Plus module
        (00010003012C0100.eds) gives them for 21 parameters, and tools ignore them.
        A ProxiedParam entry alone is not judged by this rule: its fields count only where
        the adapter's Proxy entry says `Module` and are documentation elsewhere (C.4.1.5.3);
        `edsconv merge` checks the entry the pair forms.
    """,
    bad=block("""
        Param3 = 0,,,0x0000,0xD2,2,"Word","","",,,0,1,1,1,0;
    """),
    good=block("""
        Param3 = 0,,,0x0000,0xD2,2,"Word","","",,,0,,,,;
    """),
    labels=TRIGGERS,
)
SCALING_ZERO = rule(
    "EDS319", Severity.ERROR, "C.4.1.4.6", "A parameter that supports scaling has a scaling divisor of 0",
    clause_note="Figure C.5",
    explanation="""
        The descriptor sets bit 2 (supports scaling) and the scaling divisor is 0:
        Figure C.5 divides by it, so no engineering value exists. A multiplier or base of
        0 is not reported: the formula multiplies by them, no clause forbids 0, and
        Figure C.11 itself sets the scaling bit with 0 in every scaling field. Zeros with
        bit 2 clear are how Figure C.8 writes "not used".
        A ProxiedParam entry alone is not judged by this rule: its fields count only where
        the adapter's Proxy entry says `Module` and are documentation elsewhere (C.4.1.5.3);
        `edsconv merge` checks the entry the pair forms.
    """,
    bad=block("""
        Param2 = 0,,,0x0004,0xC6,1,"Filter","ms","",0,255,3,1,0,1,0;
    """),
    good=block("""
        Param2 = 0,,,0x0004,0xC6,1,"Filter","ms","",0,255,3,1,2,1,0;
    """),
    labels=TRIGGERS,
)
DATA_SIZE_MISMATCH = rule(
    "EDS320", Severity.ERROR, "C.4.1.4.6", "A parameter's Data Size does not match its data type (Table C.14)",
    explanation="""
        The Data Size is the data type's size in bytes, or bytes per character / path
        entry: 1 for STRING, SHORT_STRING and EPATH, 2 for STRING2, any N for STRINGN
        (Table C.14).
        A ProxiedParam entry alone is not judged by this rule: its fields count only where
        the adapter's Proxy entry says `Module` and are documentation elsewhere (C.4.1.5.3);
        `edsconv merge` checks the entry the pair forms.
    """,
    bad=block("""
        Param2 = 0,,,0x0000,0xC6,2,"Filter","ms","",0,255,3;   $ USINT is 1 byte
    """),
    good=block("""
        Param2 = 0,,,0x0000,0xC6,1,"Filter","ms","",0,255,3;
    """),
    labels=TRIGGERS,
)
ENUM_WITHOUT_DESCRIPTOR_BIT = rule(
    "EDS321", Severity.INFO, "C.4.1.4.6",
    "A parameter has an EnumN but its descriptor does not set bit 1 (supports enumerated strings)",
    explanation="""
        A parameter has an EnumN but its descriptor does not set bit 1 (supports
        enumerated strings). A parameter with an EnumN whose descriptor leaves bit 1
        (supports enumerated strings, Table C.15) clear: tools that follow the
        descriptor do not offer the enumeration. Information only; very common in real files.
        A ProxiedParam entry alone is not judged by this rule: its fields count only where
        the adapter's Proxy entry says `Module` and are documentation elsewhere (C.4.1.5.3);
        `edsconv merge` checks the entry the pair forms.
    """,
    bad=block("""
        Param2 = 0,,,0x0000,0xC6,1,"Mode","","",0,1,0;
        Enum2 = 0,"Off",1,"On";
    """),
    good=block("""
        Param2 = 0,,,0x0002,0xC6,1,"Mode","","",0,1,0;
        Enum2 = 0,"Off",1,"On";
    """),
    labels=TRIGGERS,
)
ASSEMBLY_RESERVED_BITS = rule(
    "EDS322", Severity.WARNING, "C.4.1.4.8", "An assembly descriptor sets reserved bits (Table C.21)",
    explanation="""
        Bits 1-15 of an assembly descriptor are reserved (Table C.21). A warning, like
        EDS314: real files set bits later editions may assign.
    """,
    bad=block("""
        Assem100 = "In","",4,0x0002,,,32,Param1;
    """),
    good=block("""
        Assem100 = "In","",4,0x0001,,,32,Param1;
    """),
    labels=TRIGGERS,
)
EMPTY_MEMBER = rule(
    "EDS323", Severity.ERROR, "C.4.1.4.8", "An assembly member has neither a size nor a reference",
    explanation="""
        A Member Size and its Member Reference shall not both be empty (C.4.1.4.8): the
        member has no size.
    """,
    bad=block("""
        Assem100 = "In","",4,,,,32,Param1,,;
    """),
    good=block("""
        Assem100 = "In","",5,,,,32,Param1,8,;   $ an 8-bit pad
    """),
    labels=TRIGGERS,
)
ASSEMBLY_SIZE_MISMATCH = rule(
    "EDS324", Severity.ERROR, "C.4.1.4.8", "An assembly's Size differs from the total of its member sizes",
    explanation="""
        The Size field (bytes) times 8 shall equal the total of the member sizes in bits
        (C.4.1.4.8). An empty Member Size takes the referenced ParamN's Data Size or
        AssemN's Size, times 8; when a member's size cannot be known (a `Module` value, an
        undefined or newer-edition reference, a path without size) the check is skipped.
        Real files get this wrong by writing member sizes in bytes.
        A ProxiedAssem entry alone is not judged by this rule: its fields count only where
        the adapter's Proxy entry says `Module` and are documentation elsewhere (C.4.1.5.3);
        `edsconv merge` checks the entry the pair forms.
    """,
    bad=block("""
        Assem100 = "In","",4,,,,4,Param1;   $ 4 bits, not 4 bytes
    """),
    good=block("""
        Assem100 = "In","",4,,,,32,Param1;
    """),
    labels=TRIGGERS,
)
ASSEMBLY_NOT_WHOLE_BYTES = rule(
    "EDS325", Severity.ERROR, "C.4.1.4.8", "An assembly's members do not add up to a whole number of bytes",
    explanation="""
        With no Size field, the members shall still add up to a whole number of bytes
        (C.4.1.4.8).
        A ProxiedAssem entry alone is not judged by this rule: its fields count only where
        the adapter's Proxy entry says `Module` and are documentation elsewhere (C.4.1.5.3);
        `edsconv merge` checks the entry the pair forms.
    """,
    bad=block("""
        Assem101 = "Pad","",,,,,4,;
    """),
    good=block("""
        Assem101 = "Pad","",,,,,8,;
    """),
    labels=TRIGGERS,
)
NESTED_ASSEMBLY = rule(
    "EDS326", Severity.INFO, "C.4.1.4.8", "An assembly has another assembly as a member (nested AssemN)",
    import_blocking=True,
    explanation="""
        An assembly member is another AssemN or ProxyAssemN. The spec allows it (Table
        C.20; Figure C.15 does it), and vendor files made for Allen-Bradley controllers
        nest two levels deep, so this is information only; it is marked import-blocking
        because Rockwell's documented import checks list nested AssemN members among the
        problems they reject.
    """,
    bad=block("""
        Assem101 = "Outer","",4,,,,,Assem100;
    """),
    good=block("""
        Assem101 = "Outer","",4,,,,,Param1;
    """),
    labels=TRIGGERS,
)
ASSEMBLY_CYCLE = rule(
    "EDS327", Severity.ERROR, "C.4.1.4.8", "An assembly contains itself through its members",
    import_blocking=True,
    explanation="""
        An assembly reaches itself through its assembly members (directly or through
        others), so it has no finite size; no tool can import it. EZ-EDS's opaque
        assembly, whose one member names the assembly itself with a Member Size, is
        read as data of that size instead (EDS514; a Member Size that differs from the
        assembly's Size is EDS324).
    """,
    bad=block("""
        Assem100 = "In","",4,,,,32,Assem101;
        Assem101 = "Out","",4,,,,32,Assem100;
    """),
    good=block("""
        Assem101 = "Outer","",4,,,,32,Assem100;
    """),
    labels=TRIGGERS,
)
SLOT_MASK_PAIR = rule(
    "EDS329", Severity.ERROR, "C.4.1.5.3.2",
    "An assembly uses both slot mask keywords of a pair (InputSlotMask0 and InputSlotMask1 ...)",
    explanation="""
        An assembly uses both slot mask keywords of a pair (InputSlotMask0 and
        InputSlotMask1 ...). InputSlotMask0 and InputSlotMask1 shall not be used both in
        the same assembly; the same for OutputSlotMask and ConfigSlotMask (C.4.1.5.3.2).
    """,
    bad=block("""
        Assem101 = "Rack","",4,,,,16,InputSlotMask0,16,InputSlotMask1;
    """),
    good=block("""
        Assem101 = "Rack","",4,,,,16,InputSlotMask0,16,OutputSlotMask1;
    """),
    labels=TRIGGERS,
)
SLOT_MASK_WITHOUT_SIZE = rule(
    "EDS330", Severity.ERROR, "C.4.1.5.3.2", "A slot mask member has no Member Size",
    explanation="""
        The Member Size before a slot mask keyword is required (C.4.1.5.3.2): a mask has no
        defined size of its own.
    """,
    bad=block("""
        Assem101 = "Rack","",4,,,,,InputSlotMask1;
    """),
    good=block("""
        Assem101 = "Rack","",4,,,,32,InputSlotMask1;
    """),
    labels=TRIGGERS,
)
MODULE_IN_MEMBER = rule(
    "EDS331", Severity.ERROR, "C.4.1.5.3.2", "A ProxyAssem Member Reference or Member Size is 'Module'",
    explanation="""
        `Module` shall not be used for a Member Size or Member Reference of a ProxyAssem;
        `ModuleMemberList` replaces a whole member pair (C.4.1.5.3.2). `edsconv lint`
        reports a Member Reference: `Module` in a Member Size field is already EDS101
        there (not an integer). `edsconv merge` reports both and leaves the entry out
        of the combination.
    """,
    bad=block("""
        ProxyAssem1 = "Module data","",4,,,,32,Module;
    """),
    good=block("""
        ProxyAssem1 = "Module data","",4,,,,ModuleMemberList;
    """),
    labels=TRIGGERS,
    aliases={"EDS403": """
        The code `edsconv merge` gave this fault before it reported the code `edsconv lint`
        gives: `Module` in a member of a ProxyAssem is a fault of the adapter's file alone.
    """},
)
DUPLICATE_PORT_NUMBER = rule(
    "EDS332", Severity.ERROR, "C.4.1.4.10", "Two ports have the same port number",
    explanation="""
        Each PortN describes a different CIP port; two entries with the same Port Number
        describe one port twice (C.4.1.4.10).
    """,
    bad=block("""
        Port1 = TCP, "A", "20 F5 24 01", 2;
        Port2 = TCP, "B", "20 F5 24 02", 2;
    """),
    good=block("""
        Port1 = TCP, "A", "20 F5 24 01", 2;
        Port2 = TCP, "B", "20 F5 24 02", 3;
    """),
    labels=TRIGGERS,
)
UNKNOWN_PORT_TYPE = rule(
    "EDS333", Severity.ERROR, "C.4.1.4.10", "A Port Type Name is neither a spec keyword nor a vendor-specific keyword",
    explanation="""
        The Port Type Name is ControlNet, ControlNet_Redundant, TCP, DeviceNet or a
        vendor-specific keyword `<VendorID>_<name>` (C.4.1.4.10).
    """,
    bad=block("""
        Port1 = Ethernet, "A", "20 F5 24 01", 2;
    """),
    good=block("""
        Port1 = 65535_Ethernet, "A", "20 F5 24 01", 2;
    """),
    labels=TRIGGERS,
)
LEGAL_SLOT_OUT_OF_RANGE = rule(
    "EDS334", Severity.ERROR, "C.4.1.5.2.3",
    "A Rack legal slot is not a slot of the chassis the file itself describes (0 to DefineSlotsInRack - 1)",
    clause_note="DefineSlotsInRack: C.4.1.5.2.2",
    explanation="""
        The Legal Slot fields of a RackN "identify the slots into which the module may be
        placed" in the chassis the entry's key names (C.4.1.5.2.3), and a chassis has
        DefineSlotsInRack slots, 0 to DefineSlotsInRack - 1 (C.4.1.5.2.2). Checked where
        the file gives DefineSlotsInRack and a RackN whose key is the file's own device
        (vendor, type, product code, major revision: a chassis with modules of its own).
        A RackN naming another chassis is not checked: that chassis' slots are in its
        own EDS.
    """,
    bad=block("""
        DefineSlotsInRack = 4;
        Width = 1;
        Rack1 = 65535,12,1,1,1,,,,1,4;
    """),
    good=block("""
        DefineSlotsInRack = 4;
        Width = 1;
        Rack1 = 65535,12,1,1,1,,,,1,3;
    """),
    labels=TRIGGERS,
)
WIDTH_ZERO = rule(
    "EDS335", Severity.ERROR, "C.4.1.5.2.3", "A module's Width is 0",
    explanation="""
        Width is the number of slots a module consumes (C.4.1.5.2.3); a module consumes at
        least one.
    """,
    bad=block("""
        Width = 0;
    """),
    good=block("""
        Width = 1;
    """),
    labels=TRIGGERS,
)
QUERY_FIELD_VALUE = rule(
    "EDS336", Severity.ERROR, "C.4.1.5.2.4",
    "A Query entry has a service other than 1 or 14, or an ID size outside 1 to 16",
    explanation="""
        The Query service is 1 (Get_Attributes_All) or 14 (Get_Attribute_Single); the ID
        size is 1 to 16 bytes (C.4.1.5.2.4).
    """,
    bad=block("""
        Query = "20 04 24 07 30 03",3,2,"FF FF";
    """),
    good=block("""
        Query = "20 04 24 07 30 03",14,2,"FF FF";
    """),
    labels=TRIGGERS,
)
SAFETY_REAL_TIME_FORMAT = rule(
    "EDS337", Severity.WARNING, "C.4.1.4.9.3",
    "A connection uses real time format 5, reserved in the 2003 text and the CIP Safety format of later editions",
    explanation="""
        A connection uses real time format 5, reserved in the 2003 text and the CIP
        Safety format of later editions. Real time transfer format 5 is reserved in
        Table C.24; later CIP editions assign it to CIP Safety connections, and
        certified safety modules use it. A warning rather than EDS310.
    """,
    bad=block("""
        Connection1 = 0x04010002, 0x44640505, ...
    """),
    good=block("""
        Connection1 = 0x04010002, 0x44640405, ...
    """),
    labels=TRIGGERS,
)
PARAMCLASS_RESERVED_BITS = rule(
    "EDS338", Severity.ERROR, "C.4.1.4.5", "The parameter class descriptor sets bits Table C.12 does not define",
    clause_note="Table C.12",
    explanation="""
        The `Descriptor` of `[ParamClass]` sets a bit beyond 0-3: "Bits not defined in Table
        C.12 shall not be used and shall be set to zero" (C.4.1.4.5). An error, unlike the
        parameter descriptor's reserved bits (EDS314): no later edition is known to assign
        them, and no real file of the test corpus sets them.
    """,
    bad=block("""
        [ParamClass]
                Descriptor = 0x0010;
    """),
    good=block("""
        [ParamClass]
                Descriptor = 0x000E;
    """),
    labels=TRIGGERS,
)
ENUM_NOT_PAIRS = rule(
    "EDS339", Severity.ERROR, "C.4.1.4.6", "An EnumN does not consist of value / string pairs",
    explanation="""
        "Each Enum entry shall consist of pairs of integers and strings" (C.4.1.4.6); this
        one has an odd number of fields, so its last value has no string and no tool can
        show it. (EnumN with `ProxyEnumN` and `ProxiedEnumN`, C.4.1.5.3.1.) Empty fields at
        the end are not counted.
    """,
    bad='`Enum2 = 0,"Off",1,"On",2;`',
    good='`Enum2 = 0,"Off",1,"On",2,"Auto";`',
    labels=TRIGGERS,
)
MEMBER_FIELDS_ODD = rule(
    "EDS340", Severity.ERROR, "C.4.1.4.8", "An assembly's member fields are not Member Size / Member Reference pairs",
    explanation="""
        The fields from 7 on "shall be paired such that a Member Size field is paired with a
        Member Reference field making the total number of fields even" (C.4.1.4.8); this
        assembly ends with a Member Size that has no Member Reference, which tools read as
        a pad or drop. A `ModuleMemberList` alone stands for a whole pair (C.4.1.5.3.2). A
        trailing empty field is EDS323.
    """,
    bad='`Assem100 = "In","",4,,,,32,Param1,16;`',
    good='`Assem100 = "In","",6,,,,32,Param1,16,;`   $ a 16-bit pad',
    labels=TRIGGERS,
)
