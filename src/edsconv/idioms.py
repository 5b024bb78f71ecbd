"""Generator idioms that real tools accept, and how edsconv reports each (issue 10, item 4).

EDS generators (EZ-EDS above all) write things that break the letter of the 2003 text, yet the files
ship in vendor SDKs and certified product packages and the engineering tools read them. Each idiom
has a file of ours in corpus/idioms (MANIFEST.tsv there counts it in the real files); this table
holds the decision for each, with its reason, and docs/rules.md shows it (:func:`idioms_section`).
The policy is the guide's: a "shall" that real tools widely accept is a warning, not an error; what
the text allows is at most a note; an idiom with one reading is read that way.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True, slots=True)
class Idiom:
    #: the file of corpus/idioms that imitates it
    file: str
    what: str
    #: the codes ``edsconv lint`` reports on that file now
    codes: tuple[str, ...]
    #: why it is reported so
    reason: str


IDIOMS: tuple[Idiom, ...] = (
    Idiom("opaque_self_assembly.eds", "an opaque assembly written as one member naming the assembly itself with "
          "the full size (EZ-EDS)", ("EDS514",),
          "read as Size bytes of opaque data, as every tool that imports these files reads it; a note says so. "
          "Before: EDS327 (error, the assembly contains itself) and EDS326 (note, nested assembly)."),
    Idiom("port_reserved_zero.eds", "reserved PortN field 5 written 0x00", ("EDS210",),
          "stays a warning: Table C.25 leaves the field unused and tools ignore the value (8 real files)."),
    Idiom("bitstring_min_max.eds", "BYTE / WORD / DWORD parameters with a minimum and maximum", ("EDS317",),
          "stays a warning: Table C.17 says they shall not be specified, and tools ignore them (11 files, "
          "193 parameters)."),
    Idiom("descriptor_bit9.eds", "parameter descriptor bit 9 or 11 set", ("EDS314",),
          "stays a warning: Table C.15 reserves the bits; later editions assign them, so the value is not "
          "wrong, but the 2003 text cannot say what it means (19 files)."),
    Idiom("enum_without_descriptor_bit.eds", "EnumN for a parameter whose descriptor leaves bit 1 clear",
          ("EDS321",), "stays a note: no sentence forbids it; tools that follow the descriptor may not offer the "
                       "enumeration (24 files, 1861 parameters)."),
    Idiom("nested_assembly.eds", "an AssemN as a member of another", ("EDS326",),
          "stays a note: the 2003 text allows it (Table C.20); it is marked import-blocking because Rockwell's "
          "documented import checks refuse it (19 files)."),
    Idiom("homeurl_without_scheme.eds", "HomeURL without http://", ("EDS110",),
          "stays a warning: C.4.1.3.14 names RFC 1738 URLs; tools show the text as it is (14 files)."),
    Idiom("decimal_precision_non_numeric.eds", "WORD / BOOL parameters that write 0 in field 21",
          ("EDS318",), "stays a warning: Table C.18 prohibits the fields for non-numeric types; tools ignore "
                       "them (1 vendor file, 21 parameters)."),
    Idiom("modtime_before_createtime.eds", "ModTime two seconds before CreateTime on the same date",
          ("EDS215",), "stays a warning: no clause forbids it, but a modification before the creation is most "
                       "likely a slip, and one real file's ModDate is a year early (a defect); the message gives "
                       "both moments."),
    Idiom("revision_two_digit_minor.eds", "a file Revision 1.14", ("EDS115",),
          "stays a warning: C.4.1.3.13 allows one digit per part; tools read major and minor as numbers "
          "(3 files)."),
    Idiom("assembly_descriptor_bit5.eds", "assembly descriptor bit 5 set", ("EDS322",),
          "stays a warning, like EDS314: Table C.21 reserves the bit (1 file)."),
)


def idioms_section() -> str:
    """The generator idioms as a section of docs/rules.md."""
    rows = [f"| `{idiom.file}` | {idiom.what} | {', '.join(f'[{c}](#{c.lower()})' for c in idiom.codes)} | "
            f"{idiom.reason} |" for idiom in IDIOMS]
    table = "\n".join(["| file | idiom | reported as | why |", "| --- | --- | --- | --- |", *rows])
    return "\n\n".join([
        "## Generator idioms",
        "Things EDS generators write that break the letter of the 2003 text but that real tools accept. Each "
        "has a file of ours in `corpus/idioms` (its `MANIFEST.tsv` counts it in the real files); an idiom is "
        "never an error.",
        table])
