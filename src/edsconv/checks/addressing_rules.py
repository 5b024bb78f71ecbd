"""The rules the addressing checks report: paths, instance numbers, ports, racks and slots.

The checks are in :mod:`edsconv.checks.addressing`; docs/rules.md is generated from these definitions
(``edsconv rules --format markdown``).
"""

from __future__ import annotations

from edsconv.diagnostics import TRIGGERS, Severity, rule

ERROR, WARNING = Severity.ERROR, Severity.WARNING

PACKED_CONNECTION_PATH = rule(
    "EDS328", ERROR, "C.4.1.4.9.13", "A connection path is not written in the padded EPATH notation",
    explanation="""
        A connection path (ConnectionN field 15) "shall be entered as a CIP Path (EPATH),
        using the padded path notation" (C.4.1.4.9.13): a 16- or 32-bit logical segment
        (segment byte 0x21, 0x25, 0x2D, 0x31 ... with value format 1 or 2) is followed by
        a 0x00 pad byte and then its value, so that every segment is a whole number of
        16-bit words. Here the value follows the segment byte directly (the packed
        notation). Port, network and data segments are walked over; the walk stops where
        a keyword or a `[ParamN]` stands for a segment byte.

        Assembly member paths are not held to it: C.4.1.4.8 asks only that they consist
        of logical or data segments (EDS341), not the padded notation (EDS349 says where a
        tool refuses a packed one).
    """,
    bad='`Connection1 = ..., "20 04 25 97 00 2C 96 2C 64";` (a 16-bit instance, packed)',
    good='`Connection1 = ..., "20 04 25 00 97 00 2C 96 2C 64";`',
    labels=TRIGGERS,
)
NON_LOGICAL_SEGMENT = rule(
    "EDS341", ERROR, "C.4.1.4.8",
    "An assembly path is not a logical path, or a member path holds segments other than logical or data segments",
    explanation="""
        The Path field (field 2) of an AssemN "shall be a string that specifies a logical
        path", and a Member Reference path "shall consist of either Logical Segments
        (path to an object within the device) or Data Segments" (C.4.1.4.8). The path
        holds a segment of another type: a port segment (0x01 - 0x1F), a network segment
        (0x40 - 0x5F), a symbolic segment (0x60 - 0x7F), a data segment in an assembly
        path. A keyword or `[ParamN]` inside a logical segment (`"20 7D 24 SLOT 30 0A"`,
        Figure C.15) is a value, not a segment.
    """,
    bad='`Assem100 = "In", "01 00 20 04 24 64 30 03", 2, ...;` (a port segment first)',
    good='`Assem100 = "In", "20 04 24 64 30 03", 2, ...;`',
    labels=TRIGGERS,
)
PARAM_INSTANCE_MISMATCH = rule(
    "EDS342", ERROR, "C.4.1.4.6", "A ParamN's own link path addresses another instance of the Parameter object",
    explanation="""
        The N of `ParamN` "shall be equal to the parameter object instance" when that
        instance exists in the device and the EDS describes it (C.4.1.4.6). The link path
        (field 3) of this entry addresses the Parameter object (class 0x0F) at another
        instance: the entry describes that instance under the wrong number. Only a link
        path that names class 0x0F and an instance as numbers is checked; a path to
        another object says nothing of the Parameter instance.
    """,
    bad='`Param2 = 0, 6, "20 0F 24 03 30 01", ...;`',
    good='`Param2 = 0, 6, "20 0F 24 02 30 01", ...;`',
    labels=TRIGGERS,
)
ASSEM_INSTANCE_MISMATCH = rule(
    "EDS343", WARNING, "C.4.1.4.8", "An AssemN's own path addresses another instance of the Assembly object",
    explanation="""
        "If a particular instance of the Assembly object is addressable from the link,
        there shall be a one-for-one pairing between the Assem number in the EDS file and
        the Assembly instance number in the device" (C.4.1.4.8). The Path field of this
        entry addresses the Assembly object (class 0x04) at another instance than N.
        Only a path that names class 0x04 and an instance as numbers is checked.

        A warning, not an error: 2 of the 61 real files of the test corpus, both written
        with ODVA's EZ-EDS (3.9 and 3.27) for commercial products, number their AssemN
        apart from the instances their paths address (Assem1 at instance 150), so tools
        accept it. The connection paths name the instance; the AssemN number only names
        the entry.
    """,
    bad='`Assem100 = "In", "20 04 24 65 30 03", 2, ...;` (instance 101)',
    good='`Assem100 = "In", "20 04 24 64 30 03", 2, ...;`',
    labels=TRIGGERS,
)
LINK_SIZE_WITHOUT_PATH = rule(
    "EDS344", ERROR, "C.4.1.4.6", "A ParamN gives a Link Path Size but no Link Path",
    clause_note="Table C.14",
    explanation="""
        An empty Link Path (field 3) says the parameter "is not directly addressable from
        the network", and then the Link Path Size (field 2) "shall be empty" (Table
        C.14). This entry gives a size without a path. A Link Path `""` is not empty: it
        addresses the data attribute of Parameter instance N.
    """,
    bad='`Param1 = 0, 6, , 0x0000, 0xC7, 2, "Speed", "", "", 0, 100, 0;`',
    good='`Param1 = 0, , , 0x0000, 0xC7, 2, "Speed", "", "", 0, 100, 0;`',
    labels=TRIGGERS,
)
PORT_TYPE_VENDOR_ID = rule(
    "EDS345", ERROR, "C.4.1.4.10", "A vendor-specific Port Type Name carries another vendor's ID",
    explanation="""
        A vendor-specific Port Type Name is "a vendor-specific field keyword beginning
        with the device's Vendor ID and an underscore" (C.4.1.4.10); this one begins
        with another vendor ID than the `VendCode` of `[Device]`.
    """,
    bad='`VendCode = 65535;` and `Port2 = 1234_Chassis, "Chassis", "20 9A 24 01", 1;`',
    good='`Port2 = 65535_Chassis, "Chassis", "20 9A 24 01", 1;`',
    labels=TRIGGERS,
)
PORT_1_NOT_BACKPLANE = rule(
    "EDS346", WARNING, "C.4.1.4.10", "Port number 1 is given to a network port, not to the backplane",
    explanation="""
        "The port number 1 shall correspond to the backplane port" (C.4.1.4.10), and a
        device whose backplane cannot route has no port 1. A port of a network type
        (TCP, ControlNet, ControlNet_Redundant, DeviceNet) has port number 1. A
        warning, not an error: 7 of the 17 real files with a TCP port number it 1,
        files written with ODVA's EZ-EDS (3.27, 3.38) among them, so tools accept it.
        A vendor-specific port type may be the backplane and is not reported.
    """,
    bad='`Port1 = TCP, "EtherNet/IP", "20 F5 24 01", 1;`',
    good='`Port1 = TCP, "EtherNet/IP", "20 F5 24 01", 2;`',
    labels=TRIGGERS,
)
DUPLICATE_RACK = rule(
    "EDS347", ERROR, "C.4.1.5.2.3", "Two RackN entries name the same chassis",
    explanation="""
        "The EDS for the module shall contain one Rack entry for each chassis into which
        the module may be placed" (C.4.1.5.2.3): two RackN entries have the same
        electronic key (vendor, product type, product code, major and minor revision).
        List all the legal slots of a chassis in one entry.
    """,
    bad="`Rack1 = 65535, 101, 1, 1, 1,,,, 1, 2;` and `Rack2 = 65535, 101, 1, 1, 1,,,, 3;`",
    good="`Rack1 = 65535, 101, 1, 1, 1,,,, 1, 2, 3;`",
    labels=TRIGGERS,
)
QUERY_NOT_SLOT_0 = rule(
    "EDS348", ERROR, "C.4.1.5.2.4", "A module with a Query entry cannot be placed in slot 0",
    explanation="""
        "A query shall only be addressed to a module in slot 0" (C.4.1.5.2.4): the Query
        entry belongs to a module with a link connection in slot 0 (Figure C.14), but no
        RackN of this module lists slot 0 among its legal slots.
    """,
    bad="`Rack1 = 65535, 101, 1, 1, 1,,,, 1, 2;` and a `Query` entry",
    good="`Rack1 = 65535, 101, 1, 1, 1,,,, 0;` and a `Query` entry",
    labels=TRIGGERS,
)
PACKED_MEMBER_PATH = rule(
    "EDS349", Severity.INFO, "C.4.1.4.8", "An assembly member path is written packed (no pad bytes)",
    import_blocking=True,
    explanation="""
        A Member Reference path has a 16- or 32-bit logical segment whose value follows the
        segment byte without the 0x00 pad byte (the packed notation). The text allows it:
        C.4.1.4.8 asks of a member path only logical or data segments, and the padded
        notation of C.4.1.4.9.13 is the connection path's (EDS328). Information only; it
        is marked import-blocking because Rockwell's documented import checks refuse packed
        EPATH members ("packed" read as the CIP term for the pad-less encoding).
    """,
    bad='`Assem101 = "Path","",4,,,,32,"20 04 25 64 00 30 03";`',
    good='`Assem101 = "Path","",4,,,,32,"20 04 25 00 64 00 30 03";`',
    labels=TRIGGERS,
)
