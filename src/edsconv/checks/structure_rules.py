"""The rules the file-structure checks report (EDS201-EDS221), each with its documentation.

The checks are in :mod:`edsconv.checks.structure`; docs/rules.md is generated from these definitions
(``edsconv rules --format markdown``). They have a module of their own because they outgrow the checks.
"""

from __future__ import annotations

from edsconv.diagnostics import Severity, block, rule

ERROR, WARNING, INFO = Severity.ERROR, Severity.WARNING, Severity.INFO

MISSING_SECTION = rule(
    "EDS201", ERROR, "C.4.1.2.1", "A required section ([File], [Device], [Device Classification]) is missing",
    import_blocking=True,
    clause_note="Tables C.3, C.27",
    explanation="""
        A required section is missing: `[File]` and `[Device]` (Table C.3) and, in an
        EtherNet/IP EDS, `[Device Classification]` (Table C.27). Reported at the file
        start; not reported for a file without any section (EDS015 says that).
    """,
    bad=block("""
        [File]
                DescText = "Adapter"; CreateDate = 01-02-2020; CreateTime = 10:00:00; Revision = 1.0;
        [Device Classification]
                Class1 = EtherNetIP;            $ no [Device]
    """),
    good="the same file with its `[Device]` section.",
)
SECTION_PLACEMENT = rule(
    "EDS202", ERROR, "C.4.1.2.1", "[File] is not the first section, or [Device] does not immediately follow it",
    clause_note="Table C.3 placement",
    explanation="`[File]` shall be the first section and `[Device]` shall immediately follow it.",
    bad=block("""
        [File]
                ...
        [Device Classification]
                Class1 = EtherNetIP;
        [Device]                                $ not right after [File]
                ...
    """),
    good="`[File]`, `[Device]`, then `[Device Classification]` and the other sections.",
)
VENDOR_SECTION_NOT_LAST = rule(
    "EDS203", ERROR, "C.4.1.2.2.7", "A vendor-specific section stands before a section the spec defines",
    explanation="""
        A vendor-specific section (`[VendorID_keyword]`) stands before a section the
        spec defines; vendor sections come last.
    """,
    bad=block("""
        [65535_Extra]
                65535_Note = 1;
        [Params]
                Param1 = ...;
    """),
    good="`[Params]` first, `[65535_Extra]` after it.",
)
FORWARD_REFERENCE = rule(
    "EDS204", ERROR, "C.4.1.2.1", "An entry refers to an entry of a section placed later",
    explanation="""
        Optional sections may be in any order "provided that no forward references
        exist": an entry names an entry of a section that comes later in the file
        (a connection naming an assembly or parameter in a field or inside its path, an
        assembly member naming a parameter, a group naming a parameter). The message
        gives both lines. Reported once per pair of sections: moving the referenced
        section up fixes them all. An error, as the text's "shall": the one real file of
        61 that breaks it is a hand-written library demo, so no tool practice argues
        for less. A reference to a later entry of the same section is EDS227, a
        warning: the text's own Figure C.15 makes one.
    """,
    bad=block("""
        [Connection Manager]
                Connection1 = 0x04010002, 0x44640405, , 2, Assem2, , 2, Assem1, , , , ,
                              "Owner", "", "20 04 24 01 2C 02 2C 01";
        [Assembly]
                Assem1 = "In", "", 2, 0x0000, , , 16, ;
                Assem2 = "Out", "", 2, 0x0000, , , 16, ;
    """),
    good="`[Assembly]` before `[Connection Manager]`.",
)
NOT_ETHERNETIP = rule(
    "EDS205", ERROR, "C.4.2.2.1", "No ClassN entry classifies the device as EtherNetIP",
    import_blocking=True,
    explanation="""
        No `ClassN` entry of `[Device Classification]` is `EtherNetIP`. An EtherNet/IP
        EDS needs one. A file classified only under DeviceNet or ControlNet is the EDS
        of that network and is not reported.
    """,
    bad=block("""
        [Device Classification]
                Class1 = 65535_Tool;
    """),
    good=block("""
        [Device Classification]
                Class1 = EtherNetIP;
                Class2 = 65535_Tool;
    """),
)
MISSING_ENTRY = rule(
    "EDS206", ERROR, "C.4.1.4", "A section lacks an entry the spec requires",
    clause_note="Tables C.6, C.8, C.10; C.4.1.4.4; C.4.1.5.2.2, C.4.1.5.2.3",
    explanation="""
        A section lacks an entry its table marks Required: `DescText`, `CreateDate`,
        `CreateTime`, `Revision` in `[File]`; `VendCode`, `VendName`, `ProdType`,
        `ProdTypeStr`, `ProdCode`, `MajRev`, `MinRev`, `ProdName` in `[Device]`; the
        three entries of `[ParamClass]`; a `ClassN` in `[Device Classification]`.
        A `[Modular]` section that describes a chassis (it has `DefineSlotsInRack` or
        `SlotDisplayRule`) requires `DefineSlotsInRack` (C.4.1.5.2.2); one that describes
        a module (`Width`, `RackN`, `ExternalID`, `GenericID`, `ExternIDExactMatch` or
        `Query`) requires `Width` and a `RackN` (C.4.1.5.2.3): `edsconv merge` matches
        files by their Rack entries. One diagnostic per section (per kind for
        `[Modular]`), at its header, names every missing entry and cites its clause.
    """,
    bad=block("""
        [File]
                DescText = "Adapter";
                CreateDate = 01-02-2020;
                Revision = 1.0;                 $ no CreateTime
    """),
    good="the same section with `CreateTime = 10:00:00;`.",
)
REQUIRED_FIELD_EMPTY = rule(
    "EDS207", ERROR, "C.4.1.2.2.12", "A required field is empty or missing",
    fix="safe",
    import_blocking=True,
    explanation="""
        A field the entry's table marks Required is empty, or the entry ends before it.
        Every entry with a layout in the spec is checked (ParamN field 1, 4-9, 12;
        ConnectionN fields 1, 2, 13-15; PortN fields 1 and 4; a RackN's first Legal
        Slot, field 9, since a module fits at least one slot; the first value of an
        EnumN ...). A GroupN may list no parameter: its Number of Members says how many. A string that is
        empty by meaning is written `""`, not left out. ProxiedParamN, ProxiedAssemN and
        ProxiedConnectN are exempt: they only supply the fields their Proxy entry marks
        `Module` (C.4.1.5.3).
    """,
    bad=block("""
        [Port]
                Port1 = TCP, "EtherNet/IP", "20 F5 24 01", ;      $ Port Number empty
    """),
    good=block("""
        [Port]
                Port1 = TCP, "EtherNet/IP", "20 F5 24 01", 1;
    """),
)
TOO_MANY_FIELDS = rule(
    "EDS208", ERROR, "C.4.1.2.2.12", "A single-value entry has more than one field",
    explanation="""
        An entry that holds one value (the entries of `[File]`, `[Device]`,
        `[ParamClass]` and the single-value `[Assembly]`/`[Modular]` entries) has more
        than one field.
    """,
    bad=block("""
        [File]
                DescText = "Test", "adapter";
    """),
    good=block("""
        [File]
                DescText = "Test adapter";
    """),
)
FIELDS_BEYOND_2003 = rule(
    "EDS209", INFO, "C.4.1.2.2.12", "An entry has more fields than ISO 15745-4:2003 defines for it (kept)",
    explanation="""
        An entry with a fixed layout of several fields has more fields than
        ISO 15745-4:2003 and the newer CIP tables define (those add the two CIP Safety
        fields of a ConnectionN, which makes 17); edsconv keeps them and does not
        interpret them.
    """,
    bad=block("""
        Connection1 = 0x04010002, 0x44640405, , 2, Assem2, , 2, Assem1, , , , ,
                      "Owner", "", "20 04 24 01 2C 02 2C 01", , 1, 7;
    """),
    good="the 15 fields of Table C.22, or 17 with the CIP Safety fields.",
    labels=("Bad (for the 2003 text)", "Good"),
)
RESERVED_FIELD_SET = rule(
    "EDS210", WARNING, "C.4.1.2.2.12", "A reserved field is not empty",
    clause_note="Tables C.20, C.25, C.26",
    explanation="""
        A reserved field is not empty: fields 5 and 6 of `AssemN` and `PortN`, fields
        6-8 of `RackN`. Tools ignore the value. In an `AssemN` it often means the
        member pairs start two fields too early (a `ModuleMemberList` there is EDS406). A
        warning, not an error: Table C.20 and
        C.26 say "shall be empty" (Table C.25 only "Not Used"), but 8 of the 61 real files
        write 0 in a PortN's field 5 (OpENer-based files and the ifm AL1322), and tools
        ignore it.
    """,
    bad=block("""
                Port1 = TCP, "EtherNet/IP", "20 F5 24 01", 1, 0x00;
    """),
    good=block("""
                Port1 = TCP, "EtherNet/IP", "20 F5 24 01", 1;
    """),
)
NOT_A_CHOICE = rule(
    "EDS211", ERROR, "C.4.1.2.2.13", "A field holds a value outside the keywords its entry allows",
    explanation="""
        A field limited to a list of keywords or values holds another one:
        `ExternIDExactMatch` is `Yes` or `No`, `ExcludeFromAdapterRackConnection` is
        `"Yes"` or `"No"`, ParamN field 1 is `0`. The open keyword list of the first
        field of `ClassN`, which vendors and later editions extend, gets EDS219 or
        EDS222 instead; the Port Type Name and the Query service have rules of their
        own (EDS333, EDS336), so that one fault has one code.
    """,
    bad=block("""
        [Modular]
                ExternIDExactMatch = Maybe;
    """),
    good=block("""
        [Modular]
                ExternIDExactMatch = No;
    """),
)
PUBLIC_CLASS_SUBCLASSIFIED = rule(
    "EDS212", ERROR, "C.4.1.4.4", "A public classification (EtherNetIP, DeviceNet, ControlNet) is sub-classified",
    clause_note="and C.4.2.2.1",
    explanation="""
        A public classification (`EtherNetIP`, `DeviceNet`, `ControlNet`) has
        sub-classification fields; their sub-classification is reserved. Vendor
        classifications may be sub-classified.
    """,
    bad=block("""
                Class1 = EtherNetIP, Adapter;
    """),
    good=block("""
                Class1 = EtherNetIP;
                Class2 = 65535_Tool, Adapter;
    """),
)
NUMBERING = rule(
    "EDS213", ERROR, "C.4.1.4.4",
    "ClassN, GroupN, ConnectionN or RackN entries are not numbered 1, 2, 3 ... without gaps",
    clause_note="and C.4.1.4.7, C.4.1.4.9, C.4.1.5.2.3",
    explanation="""
        `ClassN`, `GroupN`, `ConnectionN` and `RackN` entries are numbered from 1 and
        incremented by one; a number is missing or the first is not 1. Reported at the
        entry after the gap, with the clause of its family (C.4.1.4.4 ClassN, C.4.1.4.7
        GroupN, C.4.1.4.9.1 ConnectionN, C.4.1.5.2.3 RackN). `ProxyConnect`/`ProxiedConnect`
        numbers are free. An error, as the text's "shall": none of the 61 real files of
        the test corpus breaks it.
    """,
    bad=block("""
                Class1 = EtherNetIP;
                Class3 = 65535_Tool;
    """),
    good=block("""
                Class1 = EtherNetIP;
                Class2 = 65535_Tool;
    """),
)
MOD_TIME_WITHOUT_DATE = rule(
    "EDS214", ERROR, "C.4.1.4.2", "ModTime is present without ModDate",
    clause_note="Table C.7",
    explanation="""
        `ModTime` is present but `ModDate` is not; Table C.7 requires the date when the
        time is given.
    """,
    bad=block("""
                ModTime = 11:00:00;
    """),
    good=block("""
                ModDate = 01-03-2020;
                ModTime = 11:00:00;
    """),
)
MODIFIED_BEFORE_CREATED = rule(
    "EDS215", WARNING, "C.4.1.4.2", "The last modification is dated before the creation",
    explanation="""
        The last modification (`ModDate`, with `ModTime` when both times are given) is
        before the creation (`CreateDate`, `CreateTime`). No clause forbids it in so many
        words, so a warning: it is most likely a slip in one of the dates.
    """,
    bad=block("""
                CreateDate = 01-02-2020;
                CreateTime = 10:00:00;
                ModDate = 01-01-2020;
    """),
    good="`ModDate = 01-02-2020;` or later.",
)
ICON_WITHOUT_HOME_URL = rule(
    "EDS216", ERROR, "C.4.1.4.3", "Icon is present without a HomeURL in [File]",
    clause_note="Table C.9",
    explanation="""
        `Icon` names a file relative to the folder of `HomeURL`, and "shall only be
        present when a HomeURL keyword exists"; `[File]` has no `HomeURL`. An error, as
        the text's "shall": of the 47 real files with an `Icon`, one lacks `HomeURL`, and
        that one was rewritten by a library, not by a vendor's tool.
    """,
    bad=block("""
        [Device]
                Icon = "adapter.ico";           $ and no HomeURL in [File]
    """),
    good='`HomeURL = "http://www.example.com/eds/adapter.eds";` in `[File]`.',
)
VENDOR_ID_LEADING_ZERO = rule(
    "EDS217", ERROR, "C.4.1.2.2.11", "A vendor-specific keyword writes its vendor ID with leading zeros",
    explanation="""
        A vendor-specific keyword (section, entry or field keyword) writes its vendor ID
        with leading zeros; the ID is decimal without leading zeros.
    """,
    bad=block("""
        [0065_Extra]
                0065_Note = 1;
    """),
    good=block("""
        [65_Extra]
                65_Note = 1;
    """),
)
KEYWORD_STARTS_WITH_DIGIT = rule(
    "EDS218", ERROR, "C.4.1.2.2.10", "A keyword starts with a digit but is not VendorID_keyword",
    explanation="""
        A keyword starts with a digit but is not `VendorID_keyword`; public keywords
        never begin with a digit.
    """,
    bad=block("""
                1Note = 1;
    """),
    good=block("""
                1_Note = 1;
    """),
)
KEYWORD_BEYOND_2003 = rule(
    "EDS219", INFO, "C.4.1.2.2.9", "A keyword defined for other sections than the one it stands in (kept)",
    explanation="""
        An entry keyword that neither ISO 15745-4:2003 nor the tables of later CIP editions
        (edsconv.cip_tables) define for its section, but that one of them defines for
        another: `MaxInst` in `[Params]` (the 2003 text's is in `[ParamClass]`; keywords
        are global in scope, C.4.1.2.2.8), `MaxInst` in `[Capacity]` (the newer tables'
        is an object-class entry). edsconv keeps the entry as it is. What the tables
        define in its section (`IconContents` in `[Device]`, `AssemExaN` in `[Assembly]`,
        the object-class entries) is not reported; a keyword no table defines is EDS222.
    """,
    bad=block("""
        [Params]
                MaxInst = 4;
    """),
    good="`MaxInst = 4;` in `[ParamClass]`, and vendor-specific keywords (`65535_MaxInst`).",
    labels=("Example", "Not reported"),
)
NO_TCP_PORT = rule(
    "EDS221", ERROR, "C.4.2.2.2", "The [Port] section of an EtherNet/IP device has no TCP port",
    explanation="""
        The device is classified `EtherNetIP` and has a `[Port]` section, but no `PortN`
        has the port type `TCP`: "the PortN entry corresponding to an EtherNet/IP
        compliant port shall" have the Port Type Name `TCP` (C.4.2.2.2), and every CIP
        routable port has an entry (C.4.1.4.10). An error, as the text's "shall": none of
        the 61 real files breaks it. Not reported when a port type is misspelt (EDS333):
        that port may be the TCP one.
    """,
    bad=block("""
        [Port]
                Port1 = DeviceNet, "DeviceNet", "20 03 24 01", 2;
    """),
    good=block("""
        [Port]
                Port1 = TCP, "EtherNet/IP", "20 F5 24 01", 1;
                Port2 = DeviceNet, "DeviceNet", "20 03 24 01", 2;
    """),
)
UNKNOWN_KEYWORD = rule(
    "EDS222", WARNING, "C.4.1.2.2.10",
    "An entry keyword that neither ISO 15745-4:2003 nor the newer CIP tables define, and that is not vendor-specific",
    clause_note="C.4.1.2.2.9",
    explanation="""
        An entry keyword that no table edsconv holds defines, and that is not
        vendor-specific (`VendorID_keyword`): not the 2003 text's (the entry tables)
        and not one that later CIP editions added (`IconContents`, `AssemExa` ...;
        `edsconv.cip_tables`). A public keyword "shall always be defined within the CIP
        specification" (C.4.1.2.2.10), so this is most likely a misspelling: tools ignore
        the entry, and what it says is lost. When a defined keyword is close, the message
        offers it ("did you mean"). Keywords are case-sensitive (EDS230): `catalog` is
        not `Catalog`.

        A warning, not an error: later CIP editions define entry keywords edsconv's tables
        may not hold yet. Keywords the tables hold beyond the 2003 text are not reported
        (the EDS5xx rules check them); one they define for another section is EDS219
        (information). A section name no table defines is EDS228 and a field keyword
        outside its list (a classification, `Profibus`) EDS211, both errors since issue
        20; the Port Type Name has its own rule (EDS333).
    """,
    bad=block("""
        [Device]
                Catalogue = "PRB-1";            $ did you mean Catalog?
        [Params]
                Parameter1 = ...;               $ did you mean Param1?
    """),
    good=block("""
        [Device]
                Catalog = "PRB-1";
                65535_Catalogue = "PRB-1";      $ vendor-specific
    """),
    aliases={"EDS220": """
        EDS220 was "a section not defined by ISO 15745-4:2003" (information) until issue 10
        phase 2: the sections later CIP editions define are now modelled and checked
        (EDS5xx), and a section no table defines was EDS222 (EDS228 since issue 20), so
        configurations that name EDS220 keep working. Selecting or ignoring EDS220 acts
        on all of EDS222.
    """},
)
ICON_NOT_ICO = rule(
    "EDS223", WARNING, "C.4.1.4.3", "The Icon file name does not end in .ico",
    clause_note="Table C.9",
    explanation="""
        The icon file "shall have the *.ICO MSWindows format" (Table C.9); the name in
        `Icon` does not end in `.ico` (in any case). A warning, not an error: the text
        constrains the file's format, which the EDS does not hold, and a name is only a
        strong sign of it. (All 47 real files with an `Icon` name an `.ico` file.)
    """,
    bad='`Icon = "adapter.png";`',
    good='`Icon = "adapter.ico";`',
)
