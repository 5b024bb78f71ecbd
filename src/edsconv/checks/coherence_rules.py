"""The rules of issue 20 (EDS224-EDS239, EDS350-EDS369), each with its documentation: where a figure of
the text conflicts with a formula, what the classification says against what the file describes, names
and keyword values no one defines, enumerations beyond their parameter's range.

The checks are in :mod:`edsconv.checks.coherence` (and, for EDS350, in :mod:`edsconv.checks.entities`
beside EDS319); docs/rules.md is generated from these definitions (``edsconv rules --format markdown``).
"""

from __future__ import annotations

from edsconv.diagnostics import Severity, block, rule

ERROR, WARNING, INFO = Severity.ERROR, Severity.WARNING, Severity.INFO

SCALING_ALL_ZERO = rule(
    "EDS350", WARNING, "C.4.1.4.6", "A parameter supports scaling with every scaling field 0, as Figure C.11 does",
    clause_note="Figures C.5, C.11",
    explanation="""
        The descriptor sets bit 2 (supports scaling) and the multiplier, divisor, base
        and offset are all 0. Figure C.5's formula divides by the divisor, so no
        engineering value exists; but Figure C.11, the text's own example of a chassis
        EDS, writes exactly this (`0x0004` and `0,0,0,0`). Where a figure of the text
        conflicts with its formula the file is not an error: a warning that names both.
        A divisor of 0 beside any other scaling value is no figure's and stays EDS319.
        A ProxiedParam entry alone is not judged by this rule: its fields count only where
        the adapter's Proxy entry says `Module` and are documentation elsewhere (C.4.1.5.3);
        `edsconv merge` checks the entry the pair forms.
    """,
    bad=block("""
        Param1 = 0,,,0x0004,0xC6,1,"Slot Naming Convention","","",0,4,0,0,0,0,0;
    """),
    good=block("""
        Param1 = 0,,,0x0000,0xC6,1,"Slot Naming Convention","","",0,4,0,0,0,0,0;   $ bit 2 clear
    """),
)
ETHERNETIP_CONTENT_UNCLASSIFIED = rule(
    "EDS224", ERROR, "C.4.2.2.1", "The file describes an EtherNet/IP port or EtherNet/IP objects, but no ClassN is "
    "EtherNetIP",
    explanation="""
        The file is classified under another public network (DeviceNet or ControlNet)
        but describes an EtherNet/IP device: a `PortN` of type `TCP` ("an EtherNet/IP
        capable TCP port", C.4.1.4.10), or a section of an object only EtherNet/IP
        devices have (`[TCP/IP Interface Class]`, `[Ethernet Link Class]`, `[DLR Class]`,
        `[EtherNet/IP Security Class]`; names and class IDs from eds-pie 1.2.0). "For any
        EtherNet/IP compliant device, the Device Classification section of its EDS shall
        contain at least one ClassN keyword entry with its first field set to EtherNetIP"
        (C.4.2.2.1): an error. A file with no public classification at all is EDS205's.
        This is the reverse of EDS221 (classified EtherNetIP, no TCP port).
    """,
    bad=block("""
        [Device Classification]
                Class1 = DeviceNet;
        [Port]
                Port1 = TCP, "EtherNet/IP", "20 F5 24 01", 2;
    """),
    good=block("""
        [Device Classification]
                Class1 = DeviceNet;
                Class2 = EtherNetIP;
        [Port]
                Port1 = TCP, "EtherNet/IP", "20 F5 24 01", 2;
    """),
)
NETWORK_CONTENT_UNCLASSIFIED = rule(
    "EDS225", WARNING, "C.4.1.4.4", "The file describes a DeviceNet node, but [Device Classification] does not "
    "list DeviceNet",
    explanation="""
        The file has a `[Device Classification]` section that does not list `DeviceNet`,
        yet it describes the device as a DeviceNet node: an `[IO_Info]` section (the
        I/O messages of a DeviceNet slave) or a `[DeviceNet Class]` section (the
        DeviceNet object, class 3). The section "shall classify the device described by
        the EDS into one or more categories" (C.4.1.4.4). A warning, not an error: the
        2003 text requires a classification only of EtherNet/IP files (Table C.27, EDS224),
        and DeviceNet files older than the section leave it out (not reported). A
        `DeviceNet` port alone is not reported: an EtherNet/IP device with a DeviceNet
        scanner port (one real robot controller's file) is no DeviceNet node.
    """,
    bad=block("""
        [Device Classification]
                Class1 = EtherNetIP;
        [IO_Info]
                ...
    """),
    good=block("""
        [Device Classification]
                Class1 = EtherNetIP;
                Class2 = DeviceNet;
        [IO_Info]
                ...
    """),
)
CLASSIFIED_NETWORK_WITHOUT_PORT = rule(
    "EDS226", WARNING, "C.4.1.4.10", "The device is classified DeviceNet or ControlNet, but [Port] lists no port "
    "of that network",
    explanation="""
        A `ClassN` entry classifies the device under `DeviceNet` (`ControlNet`), and the
        `[Port]` section lists the device's ports, but none has the Port Type Name
        `DeviceNet` (`ControlNet` or `ControlNet_Redundant`) of C.4.1.4.10. The
        counterpart of EDS221 for the other public networks; a warning, because the
        2003 text states the port requirement for EtherNet/IP only (C.4.2.2.2) and a
        DeviceNet slave that routes nothing need not describe its port. Not reported
        when a port type is misspelt (EDS333).
    """,
    bad=block("""
        [Device Classification]
                Class1 = EtherNetIP;
                Class2 = DeviceNet;
        [Port]
                Port1 = TCP, "EtherNet/IP", "20 F5 24 01", 2;
    """),
    good=block("""
        [Device Classification]
                Class1 = EtherNetIP;
                Class2 = DeviceNet;
        [Port]
                Port1 = TCP, "EtherNet/IP", "20 F5 24 01", 2;
                Port3 = DeviceNet, "DeviceNet", "20 03 24 01", 3;
    """),
)
ENUM_CHOICE_OUT_OF_RANGE = rule(
    "EDS351", WARNING, "C.4.1.4.6", "An EnumN offers a choice outside its parameter's minimum..maximum",
    explanation="""
        An `EnumN` (`ProxyEnumN`) is "an enumeration list of parameter choices to present
        to the user" (C.4.1.4.6), and a value of the parameter lies between its Minimum and
        Maximum (Table C.13). A choice outside that range is offered but cannot be set:
        the two entries contradict each other. A warning: no sentence of the text binds
        the Enum values to the range in so many words. Checked for integer parameters
        that write both a Minimum and a Maximum; not for bit strings, whose Enum values
        name bits, nor for a ProxiedEnum alone (its parameter's range may be the
        adapter's, C.4.1.5.3).
    """,
    bad=block("""
        Param2 = 0,,,0x0002,0xC6,1,"Mode","","",0,2,0;
        Enum2 = 0,"Off", 1,"On", 3,"Test";          $ 3 is above the maximum 2
    """),
    good=block("""
        Param2 = 0,,,0x0002,0xC6,1,"Mode","","",0,3,0;
        Enum2 = 0,"Off", 1,"On", 3,"Test";
    """),
)
FORWARD_REFERENCE_IN_SECTION = rule(
    "EDS227", WARNING, "C.4.1.2.1", "An entry refers to an entry placed later in the same section",
    clause_note="Figure C.15",
    explanation="""
        An entry names an entry that comes later in its own section (an assembly member
        naming a later assembly). C.4.1.2.1 lets the optional sections stand "in any order
        provided that no forward references exist within the EDS file", which read
        literally forbids this too; but the text's own Figure C.15 (informative) does it
        (`Assem1` names `ProxyAssem1` and `ProxyAssem2`, written after it), and 18 of the
        61 real files (17 of one vendor's I/O modules, one of another's) do it in
        `[Assembly]`. Where the figure and the sentence conflict, a warning that names both:
        the sentence is about the order of sections, and a reference to a later
        section stays EDS204's error. Reported once per section, at the first such
        reference.
    """,
    bad=block("""
        [Assembly]
                Assem1 = "Outer", "", 2, , , , , Assem2;
                Assem2 = "Inner", "", 2, , , , 16, ;
    """),
    good=block("""
        [Assembly]
                Assem2 = "Inner", "", 2, , , , 16, ;
                Assem1 = "Outer", "", 2, , , , , Assem2;
    """),
)
UNDEFINED_SECTION = rule(
    "EDS228", ERROR, "C.4.1.2.2.5", "A section name that no table defines and that is not vendor-specific",
    clause_note="Table C.3, C.4.1.2.2.6",
    fix="safe",
    explanation="""
        "The valid section legal delimiters shall be those specified in Table C.3"
        (C.4.1.2.2.5), and a section keyword is public or vendor-specific (C.4.1.2.2.6,
        `[VendorID_keyword]`). The section is neither: not in Table C.3, not one of the
        sections later CIP editions define (`[Capacity]`, `[TCP/IP Interface Class]` ...,
        each with its source in `edsconv.cip_tables`: eds-pie 1.2.0's tables or the real
        files), and not vendor-specific. Tools skip it, so what it says is lost. When a
        defined name is close, the message offers it ("did you mean"). An error, as the
        text's "shall"; none of the 61 real files has such a section. Keywords are
        case-sensitive (see EDS230), so `[PARAMS]` is not `[Params]`: `lint --fix` writes
        a Table C.3 name spelt in other letter case as the table does. Until issue 20
        this was EDS222, a warning.
    """,
    bad=block("""
        [Connection Manger]                     $ did you mean [Connection Manager]?
    """),
    good=block("""
        [Connection Manager]
        [65535_Connection Notes]                $ vendor-specific
    """),
)
KEYWORD_CASE_VARIANTS = rule(
    "EDS230", ERROR, "C.4.1.2.2.9", "One keyword is written twice in one section (or two sections), differing only in "
    "letter case",
    explanation="""
        Two entry keywords of one section (or two section names) are the same letters
        in different case: `ProdName` and `Prodname`. Keywords are case-sensitive: the
        keyword characters of C.4.1.2.2.3 list upper and lower case letters as distinct
        characters, and where the text lets case vary it says so (hexadecimal digits,
        C.4.1.3.7; EPATH bytes, C.4.1.3.6), which it never says of keywords. So one of
        the two is not the keyword it looks like, and a tool that compares keywords
        without regard to case reads the same entry twice, which C.4.1.2.2.9 forbids
        ("a unique sequence of keyword characters", EDS009). An error, reported at the
        later spelling and naming both; the misspelt one is not also reported as an
        undefined keyword (EDS222, EDS228).
    """,
    bad=block("""
        [Device]
                ProdName = "Adapter";
                Prodname = "Adapter X";
    """),
    good=block("""
        [Device]
                ProdName = "Adapter";
    """),
)
