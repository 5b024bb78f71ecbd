"""The rules ``edsconv verify`` reports (EDS601-EDS699): where the running device and its EDS disagree.

Each one compares what the device answers (List Identity, Get_Attribute_Single, Forward Open) with an
entry of the EDS, and is reported at that entry. The clause is the EDS clause of the entry: the EDS
states what the device is, and a device that answers otherwise does not match its EDS. The checks are
in :mod:`edsconv.verify.checks`; this module imports nothing of the ``device`` extra.
"""

from __future__ import annotations

from edsconv.diagnostics import TRIGGERS, Severity, block, rule

ERROR, WARNING, INFO = Severity.ERROR, Severity.WARNING, Severity.INFO
#: the clause of the rules on object class sections: their entries are eds-pie's (docs/spec_tables.md)
OBJECT_CLASSES = "eds-pie 1.2.0"

IDENTITY_MISMATCH = rule(
    "EDS601", ERROR, "C.4.1.4.2", "The device's identity differs from the [Device] section",
    clause_note="List Identity and the Identity object (class 0x01), attributes 1-4 and 7",
    explanation="""
        The vendor, device type, product code, revision or product name the device gives
        (in its List Identity reply and in the Identity object's attributes) differs from
        the `VendCode`, `ProdType`, `ProdCode`, `MajRev`/`MinRev` or `ProdName` of the EDS.
        A configuration tool matches a device to its EDS by these values: a firmware whose
        revision was raised without its EDS is refused or configured by the wrong file.
        The message names what the device answered and where.
    """,
    bad=block("""
        [Device]
                MajRev = 2;     $ the device answers revision 3.1
                MinRev = 3;
    """),
    good=block("""
        [Device]
                MajRev = 3;
                MinRev = 1;
    """),
)
OBJECT_ABSENT = rule(
    "EDS602", ERROR, OBJECT_CLASSES, "The device does not have an object class the EDS declares",
    clause_note="an object class section ([TCP/IP Interface Class], [Ethernet Link Class] ...) or [Assembly]",
    explanation="""
        The EDS has a section for an object class (its CIP class ID comes from the section's
        name), but the device answers a request for the class's Revision (class attribute 1)
        with "object does not exist" or "path destination unknown". A tool that trusts the
        EDS offers settings the device cannot take.
    """,
    bad=block("""
        [Ethernet Link Class]       $ the device has no Ethernet Link object (0xF6)
                Revision = 4;
    """),
    good="Leave out the section of an object the device does not have, or give the device the object.",
)
CLASS_ATTRIBUTE_MISMATCH = rule(
    "EDS603", ERROR, OBJECT_CLASSES, "An object class's Revision or MaxInst differs from the device's",
    clause_note="class attributes 1 (Revision) and 2 (Max Instance); [Assembly] Revision (C.4.1.4.8)",
    explanation="""
        The `Revision` or `MaxInst` of an object class section (or the `Revision` of
        [Assembly]) is not what the device answers for class attribute 1 or 2 of that class.
        The class revision says which attributes and services the object has; a different
        revision on the device means the EDS describes another object.
    """,
    bad=block("""
        [TCP/IP Interface Class]
                Revision = 4;   $ the device's class attribute 1 is 3
    """),
    good=block("""
        [TCP/IP Interface Class]
                Revision = 3;
    """),
)
ATTRIBUTE_NOT_SUPPORTED = rule(
    "EDS604", ERROR, OBJECT_CLASSES, "The device does not support an attribute the EDS lists",
    clause_note="Class_Attributes and Instance_Attributes (instance 1)",
    explanation="""
        `Class_Attributes` or `Instance_Attributes` lists an attribute the device answers
        with "attribute not supported" (general status 0x14) when it is read: at the class
        (instance 0) or at instance 1.
    """,
    bad=block("""
        [Ethernet Link Class]
                Instance_Attributes = 1, 2, 99;     $ no attribute 99
    """),
    good=block("""
        [Ethernet Link Class]
                Instance_Attributes = 1, 2;
    """),
)
OBJECT_UNDECLARED = rule(
    "EDS605", WARNING, OBJECT_CLASSES, "The device has an object class the EDS has no section for (--strict)",
    clause_note="the object classes edsconv's tables know by class ID, less Identity, Message Router and "
    "Connection Manager, which every device has",
    explanation="""
        With `--strict`, verify asks the device for the Revision of each object class the
        tables know (TCP/IP Interface, Ethernet Link, QoS, DLR, LLDP ...) that the EDS does
        not declare; one that answers is reported. An EDS need not declare every object,
        so this is a warning, and only `--strict` looks.
    """,
    bad="The device answers for its QoS object (0x48); the EDS has no [QoS Class] section.",
    good="The EDS declares [QoS Class], or the device has no QoS object.",
    labels=TRIGGERS,
)
ASSEMBLY_SIZE_MISMATCH = rule(
    "EDS606", ERROR, "C.4.1.4.8", "An assembly instance's size on the device differs from the EDS's",
    clause_note="Assembly object (class 0x04) attribute 4, else the length of attribute 3; C.4.1.4.9.5, .8 sizes",
    explanation="""
        An assembly instance a connection names (by its format or its connection path)
        holds a different number of bytes on the device than the EDS gives it (the
        AssemN's size, or what its members add up to; for an instance without an AssemN,
        the connection's size). A scanner opens the connection with the EDS's size and the
        device refuses it.
    """,
    bad=block("""
        [Assembly]
                Assem100 = "Inputs", "20 04 24 64 30 03", 8,,,;   $ the device's instance 100 holds 10 bytes
    """),
    good=block("""
        [Assembly]
                Assem100 = "Inputs", "20 04 24 64 30 03", 10,,,;
    """),
)
ASSEMBLY_ABSENT = rule(
    "EDS607", ERROR, "C.4.1.4.9.13", "The device has no assembly instance a connection names",
    explanation="""
        A connection's path names a connection point (or its format an AssemN whose path
        names an instance) that the device's Assembly object does not have.
    """,
    bad=block("""
        Connection1 = ..., "20 04 24 01 2C 97 2C 64";    $ the device has no instance 151
    """),
    good=block("""
        Connection1 = ..., "20 04 24 01 2C 96 2C 64";
    """),
)
PARAMETER_OUT_OF_RANGE = rule(
    "EDS608", ERROR, "C.4.1.4.6", "A parameter's value on the device lies outside its minimum and maximum",
    clause_note="fields 10 and 11 (minimum, maximum), read at the link path (field 3)",
    explanation="""
        The value the device holds at the parameter's link path is below the parameter's
        minimum or above its maximum (a missing bound is the data type's own). A tool shows
        the value as invalid, or refuses to download a configuration built from it.
    """,
    bad=block("""
        Param1 = 0, 6, "20 64 24 01 30 01", 0x0000, 0xC7, 2, "Speed limit", "rpm", "",
                 0, 1800, 1500, ,,,, ,,,, 0;     $ the device holds 2400
    """),
    good="The same entry, the device holding 1500.",
)
PARAMETER_WRONG_SIZE = rule(
    "EDS609", ERROR, "C.4.1.4.6", "A parameter's value on the device does not have its data type's size",
    clause_note="fields 5 and 6 (data type, data size), read at the link path (field 3)",
    explanation="""
        The attribute at the parameter's link path answers with a number of bytes other than
        the parameter's data type has (a UINT is 2 bytes): the EDS gives the attribute
        another type than the device does.
    """,
    bad=block("""
        Param1 = 0, 6, "20 64 24 01 30 01", 0x0000, 0xC7, 2, ...;  $ the device answers 4 bytes
    """),
    good=block("""
        Param1 = 0, 6, "20 64 24 01 30 01", 0x0000, 0xC8, 4, ...;  $ UDINT
    """),
)
PARAMETER_PATH_ABSENT = rule(
    "EDS610", ERROR, "C.4.1.4.6", "The device has nothing at a parameter's link path",
    clause_note="field 3 (link path)",
    explanation="""
        The device answers a read of the class, instance and attribute the parameter's link
        path names with "object does not exist", "path destination unknown" or "attribute not
        supported". A tool reading or writing the parameter fails.
    """,
    bad=block("""
        Param1 = 0, 6, "20 64 24 02 30 01", ...;    $ the device has no instance 2 of class 0x64
    """),
    good=block("""
        Param1 = 0, 6, "20 64 24 01 30 01", ...;
    """),
)
CONNECTION_REFUSED = rule(
    "EDS611", ERROR, "C.4.1.4.9", "The device refuses a connection the EDS describes (--connect)",
    clause_note="the Forward Open of CIP Vol 1 3-5.5.2, with the entry's RPIs, sizes, transport and trigger",
    explanation="""
        With `--connect`, verify sends a Forward Open for each ConnectionN with the EDS's own
        RPIs, sizes (plus the I/O header its real time format implies), transport class,
        trigger and connection path, and closes the connection again at once with a Forward
        Close. A connection the device refuses is reported with the CIP general and
        extended status in words: that is what a scanner configured from the EDS meets.
    """,
    bad="The device answers general status 0x01, extended status 0x0109 (invalid connection size).",
    good="The device accepts the Forward Open; verify closes the connection.",
    labels=TRIGGERS,
)
NOT_CHECKED = rule(
    "EDS612", INFO, "C.4.1.4.9", "Something the EDS states could not be checked against the device",
    explanation="""
        verify could not compare an entry with the device: a connection whose sizes, RPIs or
        path are parameter references or absent (so no Forward Open can be built from the
        EDS alone), a parameter whose link path is not a plain class, instance and attribute,
        or a value the device refused to give for a reason other than its absence (the CIP
        status is in the message). Nothing is wrong with the file for this.
    """,
    bad=block("""
        Connection1 = 0x04010002, 0x44640405, Param1, 4, Assem150, ...;   $ the RPI is a parameter
    """),
    good=block("""
        Connection1 = 0x04010002, 0x44640405, 10000, 4, Assem150, ...;
    """),
    labels=TRIGGERS,
)
INTERFACE_MISMATCH = rule(
    "EDS613", ERROR, OBJECT_CLASSES, "An Ethernet Link interface's label or type differs from the device's",
    clause_note="InterfaceLabelN and InterfaceTypeN against instance N's attributes 10 (Interface Label) and 7 "
    "(Interface Type)",
    explanation="""
        `InterfaceLabelN` or `InterfaceTypeN` of [Ethernet Link Class] is not what instance N
        of the device's Ethernet Link object (0xF6) answers for attribute 10 or 7, or the
        device has no instance N. Tools show the label to tell the ports apart; a label the
        device does not carry sends the cable to the wrong port.
    """,
    bad=block("""
        [Ethernet Link Class]
                InterfaceLabel1 = "Port 1";     $ the device's instance 1 is labelled "X1"
    """),
    good=block("""
        [Ethernet Link Class]
                InterfaceLabel1 = "X1";
    """),
)
