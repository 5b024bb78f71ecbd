"""The rules the checks of content beyond the 2003 text report (EDS501-EDS514), each with its documentation.

The checks are in :mod:`edsconv.checks.objects`. Their facts are those of :mod:`edsconv.cip_tables`:
each record there says whether eds-pie 1.2.0's references state it (a documented type or class ID:
its breach may be an error) or only the real files show it (at most a warning). The clause of these
rules names that source; the message names the exact record (``eds-pie meta_eds_lib.json:
Capacity.TSpecN``). docs/spec_tables.md lists the facts, docs/rules.md is generated from here.
"""

from __future__ import annotations

from edsconv.diagnostics import TRIGGERS, Severity, block, rule

ERROR, WARNING, INFO = Severity.ERROR, Severity.WARNING, Severity.INFO
#: The clause of a rule whose fact eds-pie 1.2.0's references state.
EDS_PIE = "eds-pie 1.2.0"
#: The clause of a rule whose fact only the real files show (docs/spec_tables.md, survey).
PRACTICE = "real files"

NOT_DOCUMENTED_TYPE = rule(
    "EDS501", ERROR, EDS_PIE, "An entry beyond the 2003 text does not have the fields and types eds-pie gives it",
    clause_note="the notation of each type is C.4.1.3's",
    explanation="""
        A field of an entry that later CIP editions define ([Capacity], the object class
        sections, AssemExaN, PITNS ...) is not written as the type eds-pie's references
        give it (`TSpecN` ConnSize UINT, `MaxIOConnections` UINT, `Object_Class_Code`
        UDINT, a service code USINT), a required field is empty, or the entry has more
        fields than it defines. The value is written by the notation rules of C.4.1.3
        (decimal without leading zeros, `0x` hex ...). The message names the eds-pie record.
        A number outside its type's range is EDS502; a field known only from practice
        that does not fit is EDS503.
    """,
    bad=block("""
        [Capacity]
                MaxIOConnections = "four";
    """),
    good=block("""
        [Capacity]
                MaxIOConnections = 4;
    """),
)
OUT_OF_DOCUMENTED_RANGE = rule(
    "EDS502", ERROR, EDS_PIE, "A number beyond the 2003 text lies outside the range of the type eds-pie gives it",
    clause_note="ranges of C.4.1.3.7 - C.4.1.3.10",
    explanation="""
        A number in an entry that later CIP editions define does not fit the type eds-pie's
        references give the field: a `TSpecN` connection size above 65535 (UINT), a service
        code above 0xFF (USINT), a hex number with more digits than the type has.
    """,
    bad=block("""
        [Capacity]
                TSpec1 = TxRx, 70000, 3000;
    """),
    good=block("""
        [Capacity]
                TSpec1 = TxRx, 504, 3000;
    """),
)
NOT_PRACTICE_TYPE = rule(
    "EDS503", WARNING, PRACTICE, "A field known from practice only does not fit the type the real files write",
    explanation="""
        A field that no source documents, whose type edsconv reads from how the real files
        write it (DeviceNet `[IO_Info]` entries, the CIP Safety entries of `[Connection
        Manager]`, `InterfaceTypeN`, `SafetyCfgAssembly`), holds something else. A warning
        at most: the type is inferred from practice (docs/spec_tables.md names the files).
    """,
    bad=block("""
        [Connection Manager]
                SafetyFormat = Two;
    """),
    good=block("""
        [Connection Manager]
                SafetyFormat = 2;
    """),
)
NOT_A_LISTED_KEYWORD = rule(
    "EDS504", ERROR, EDS_PIE, "A field keyword is not one of those eds-pie lists for the field",
    explanation="""
        A field that takes one of a list of keywords holds another: the direction of a
        `TSpecN` is `Tx`, `Rx` or `TxRx`; `PITNS` and `PITNS_usec` are `Yes` or `No`;
        `[File] Exclude` is `NONE`, `WRITE` or `READ_WRITE`; a service path keyword is
        `SYMBOL_ANSI`.
    """,
    bad=block("""
        [Capacity]
                TSpec1 = Both, 504, 3000;
    """),
    good=block("""
        [Capacity]
                TSpec1 = TxRx, 504, 3000;
    """),
)
CLASS_CODE_MISMATCH = rule(
    "EDS505", ERROR, EDS_PIE, "Object_Class_Code is not the class ID of the object its section describes",
    explanation="""
        An object class section's `Object_Class_Code` is not the CIP class ID eds-pie gives
        the section: `[QoS Class]` is class 0x48, `[DLR Class]` 0x47, `[TCP/IP Interface
        Class]` 0xF5, `[Assembly]` 0x04, `[Connection Manager]` 0x06, `[Port]` 0xF4. Each of
        the 296 Object_Class_Code entries of the 61 real files agrees with its section.
    """,
    bad=block("""
        [QoS Class]
                Object_Class_Code = 0x47;
    """),
    good=block("""
        [QoS Class]
                Object_Class_Code = 0x48;
    """),
)
CLASS_CODE_PRACTICE = rule(
    "EDS506", WARNING, PRACTICE,
    "Object_Class_Code is not the class ID the section's name or the real files give it",
    explanation="""
        An object class section that no source documents has an `Object_Class_Code` other
        than the one the real files write for it (`[Time Sync Class]` 0x43, the CIP Safety
        classes 0x39 - 0x3D), or a `[Class<ID>_Vendor<VendorID>]` section's code is not the
        ID in its name (`[Class940_Vendor1]`: 940 = 0x3AC, as in every real file that
        writes one). A warning: the class ID is known from practice only.
    """,
    bad=block("""
        [Class900_Vendor65535]
                Object_Class_Code = 0x385;
    """),
    good=block("""
        [Class900_Vendor65535]
                Object_Class_Code = 0x384;
    """),
)
MISSING_DOCUMENTED_ENTRY = rule(
    "EDS507", ERROR, EDS_PIE, "A section beyond the 2003 text lacks an entry eds-pie marks required",
    explanation="""
        A section that later CIP editions define lacks an entry eds-pie's references mark
        required: `Maintain_Existing_Connection` of `[Ingress Egress Class]`. Reported at
        the section.
    """,
    bad=block("""
        [Ingress Egress Class]
                Revision = 1;
    """),
    good=block("""
        [Ingress Egress Class]
                Revision = 1;
                Maintain_Existing_Connection = 1;
    """),
)
INTERFACE_BEYOND_MAX_INSTANCE = rule(
    "EDS508", WARNING, PRACTICE, "An Ethernet Link interface entry is numbered above the class's MaxInst",
    explanation="""
        `InterfaceLabelN`, `InterfaceSpeedN` or `InterfaceTypeN` of `[Ethernet Link Class]`
        describe Ethernet Link instance N, and N is above the `MaxInst` of the same section.
        No real file does it (33 files write labels, as many as MaxInst in 31); a warning,
        as the meaning of N is read from practice.
    """,
    bad=block("""
        [Ethernet Link Class]
                MaxInst = 2;
                InterfaceLabel3 = "Port 3";
    """),
    good=block("""
        [Ethernet Link Class]
                MaxInst = 3;
                InterfaceLabel3 = "Port 3";
    """),
)
ICON_NOT_BASE64 = rule(
    "EDS509", WARNING, PRACTICE, "IconContents is not base64 text",
    explanation="""
        `IconContents` of `[Device]` holds characters base64 does not use, or base64 with
        broken padding, so no tool can decode the icon. eds-pie types the entry as a
        string; every real file that writes it (37) writes the base64 of an icon file,
        which is why this is a warning.
    """,
    bad=block("""
        [Device]
                IconContents = "not an icon";
    """),
    good=block("""
        [Device]
                IconContents = "AAABAAEAEBACAAEAAQCwAAAAFgAAACgAAAAQAAAAIAAAAAEAAQAAAAAAQAAAAAAAAAAAAAAAAAAA"
                               "AAAAAAAAAAAA////AAAAAAA...";
    """),
)
ICON_NOT_ICO = rule(
    "EDS510", WARNING, PRACTICE, "IconContents does not decode to a valid ICO icon",
    explanation="""
        `IconContents` decodes, but not to an ICO file whose images lie inside it: a BMP
        or PNG file, an ICO whose directory or image runs past the end, or other data. Of
        the 37 real files that write IconContents, 33 hold a valid ICO (27 with BMP images,
        6 with a PNG image), 3 a BMP file and 1 neither. A warning, not an error: that the
        icon is an ICO is practice (and the 2003 text's `Icon = "*.ico"` for the file named
        there), eds-pie only says it is a string; a tool that expects an ICO shows no icon.
        `edsconv show --icon FILE` writes the decoded bytes out.
    """,
    bad="`IconContents` holding the base64 of a .bmp file.",
    good="the base64 of a .ico file (`edsconv show --icon` writes it back out).",
)
UNDEFINED_DOCUMENTED_REFERENCE = rule(
    "EDS511", ERROR, EDS_PIE, "An entry beyond the 2003 text refers to an entry that does not exist",
    explanation="""
        A field that eds-pie types as a reference names an entry the file does not define:
        the Size or a Member Reference of an `AssemExaN` (a ParamN, an AssemN, another
        AssemExaN), the request or response data of a `Service_DescriptionN`.
    """,
    bad=block("""
        AssemExa101 = "In", , Param9, 0x0000, ,, 16, Assem100;   $ no Param9
    """),
    good=block("""
        AssemExa101 = "In", , Param2, 0x0000, ,, 16, Assem100;   $ Param2 defined
    """),
    labels=TRIGGERS,
)
UNDEFINED_PRACTICE_REFERENCE = rule(
    "EDS512", WARNING, PRACTICE, "An entry known from practice refers to an entry that does not exist",
    explanation="""
        An entry whose fields the real files show to name other entries names one the file
        does not define: a DeviceNet `PollInfo` / `StrobeInfo` / `COSInfo` / `CyclicInfo`
        default input or output (the N of an `InputN` / `OutputN`; 0 is none), a
        `DefaultSafetyConnections` number (a ConnectionN), `SafetyCfgAssembly` (an AssemN), an
        `[EnumPar]` `ParamN` without its ParamN. A warning: what the fields name is read
        from practice.
    """,
    bad=block("""
        [IO_Info]
                PollInfo = 0x0001, 3, 1;        $ no Input3
    """),
    good=block("""
        [IO_Info]
                PollInfo = 0x0001, 1, 1;
    """),
    labels=TRIGGERS,
)
IO_SIZES_DISAGREE = rule(
    "EDS513", WARNING, PRACTICE, "A DeviceNet InputN or OutputN gives sizes that disagree",
    explanation="""
        An `InputN` or `OutputN` of DeviceNet's `[IO_Info]` gives a path size (field 5)
        other than the byte count of its path (field 6), or a size in bits (field 2) above
        eight times its size in bytes (field 1). The fields' meanings are read from the
        real files (every entry of them agrees), hence a warning.
    """,
    bad=block("""
        Input1 = 2, 12, 0x0005, "Inputs", 4, "20 04 24 64 30 03", "";
    """),
    good=block("""
        Input1 = 2, 12, 0x0005, "Inputs", 6, "20 04 24 64 30 03", "";
    """),
    labels=TRIGGERS,
)
OPAQUE_ASSEMBLY = rule(
    "EDS514", INFO, "C.4.1.4.8",
    "An assembly is opaque data: its one member is the assembly itself, with a size in bits",
    explanation="""
        EZ-EDS writes an assembly whose layout the EDS does not describe as one member that
        names the assembly itself with the assembly's full size in bits
        (`Assem1 = "Input", "20 04 24 6F 30 03", 128, 0x0000, ,, 1024, Assem1;`). Read
        literally the assembly contains itself (EDS327); every tool that imports these files
        reads it as opaque data of that size, and so does edsconv: the assembly is `Size`
        bytes of data without members, and this note says so. Issue 10 counts 33 such
        assemblies in one vendor's file (corpus/idioms/opaque_self_assembly.eds imitates
        it). The idiom is recognised whatever the member's size: where it differs from
        `Size` (one real file writes 4096 bits against 496 bytes, 19 times) the fault is
        that disagreement, reported as EDS324, not a cycle. A member naming its own
        assembly in any other way (without a Member Size, or one bit of it) is still EDS327.
    """,
    bad=block("""
        Assem1 = "Input", "20 04 24 6F 30 03", 128, 0x0000, ,, 1024, Assem1;
    """),
    good=block("""
        Assem1 = "Input", "20 04 24 6F 30 03", 128, 0x0000, ,, 1024, ;
    """),
    labels=TRIGGERS,
)
