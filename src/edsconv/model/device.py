"""The semantic model of an EDS: a typed description of the device.

Built from the syntax model by :func:`edsconv.model.build.build`; the XML reader
builds the same model. Every object keeps the syntax ``entry`` it came from
(None when it was built otherwise), so positions and the original spelling
stay reachable. Values are Python values: ``int``, ``float``, ``str``,
``datetime.date``/``time``, :class:`~edsconv.model.values.Revision`, paths as tuples
of :class:`~edsconv.model.values.PathItem`, references as :class:`Reference`.
A field whose value has no reading is None (a diagnostic says why); a field
that a Proxy entry defers to its Proxied entry holds :data:`MODULE`.

The values policy: a value that breaks a notation rule of C.4.1.3 keeps its
place in the model when the text allows exactly one reading of it
(``ProdCode = 06402;`` is 6402, ``MinRev = 02;`` is 2, ``06-6-2001`` is June 6):
the diagnostic stands, and :attr:`Device.erroneous` marks the field. Where no
reading exists the field is None: a number outside its type (a BOOL default
255), a date that is no day of the calendar, a string rejected for an escape
sequence Table C.4 does not define (C.4.1.3.3.5: "reject the entire string").
"""

from __future__ import annotations

import datetime
import functools
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import TYPE_CHECKING, Any, NamedTuple, TypeGuard

from edsconv import spec_tables as tables
from edsconv.diagnostics import Diagnostic
from edsconv.eds.syntax import EdsFile, Entry, Section
from edsconv.limits import decimal
from edsconv.model.values import PathItem, Revision, StringIMember

if TYPE_CHECKING:
    from edsconv.model.cip import (
        Additions,
        Capacity,
        DeviceLevelRing,
        DeviceNetIo,
        EthernetLink,
        IngressEgress,
        ObjectClass,
        TcpIpInterface,
    )
    from edsconv.model.icon import Icon

#: The field keyword of C.4.1.5.3: "take this field from the Proxied entry".
MODULE = tables.MODULE_KEYWORD
#: C.4.1.5.3.2: "all member pairs come from the ProxiedAssem".
MODULE_MEMBER_LIST = tables.MODULE_MEMBER_LIST_KEYWORD


@dataclass(slots=True)
class Reference:
    """A keyword naming another entry (``Param3``, ``ProxyAssem2``), resolved to it."""

    keyword: str
    family: str
    number: int
    #: the Parameter / Assembly / ... it names; None when undefined
    target: Any = field(default=None, compare=False, repr=False)
    #: where it is written: the entry and the 0-based index of the field
    entry: Entry | None = field(default=None, compare=False, repr=False)
    field_index: int = field(default=0, compare=False, repr=False)
    #: the bit of the parameter a member addresses (``Param10:0`` in newer files)
    bit: int | None = None

    def __str__(self) -> str:
        return self.keyword

    @property
    def text(self) -> str:
        """The reference as written: ``Param3``, ``Param10:0``."""
        return self.keyword if self.bit is None else f"{self.keyword}:{self.bit}"

    @classmethod
    def parse(cls, text: str, entry: Entry | None = None, field_index: int = 0) -> Reference | None:
        """The reference ``text`` writes (:data:`~edsconv.spec_tables.REFERENCE_RE`); None when it is none."""
        match = tables.REFERENCE_RE.fullmatch(text)
        if match is None:
            return None
        family, number, bit = match.groups()
        return cls(f"{family}{number}", family, decimal(number), entry=entry, field_index=field_index,
                   bit=decimal(bit) if bit is not None else None)


#: The model attribute of each single-field entry of [File], [Device], [ParamClass] and
#: [Modular] (on FileDescription, Identity, ParamClass and Modular), in the order the
#: records declare them.
SINGLE_ENTRY_ATTRIBUTES: Mapping[str, Mapping[str, str]] = MappingProxyType({
    "File": MappingProxyType({
        "DescText": "description", "CreateDate": "create_date", "CreateTime": "create_time", "ModDate": "mod_date",
        "ModTime": "mod_time", "Revision": "revision", "HomeURL": "home_url"}),
    "Device": MappingProxyType({
        "VendCode": "vendor_code", "VendName": "vendor_name", "ProdType": "product_type",
        "ProdTypeStr": "product_type_string", "ProdCode": "product_code", "MajRev": "major_revision",
        "MinRev": "minor_revision", "ProdName": "product_name", "Catalog": "catalog", "Icon": "icon",
        "ExcludeFromAdapterRackConnection": "exclude_from_adapter_rack_connection"}),
    "ParamClass": MappingProxyType({"MaxInst": "max_instances", "Descriptor": "descriptor",
                                    "CfgAssembly": "cfg_assembly"}),
    "Modular": MappingProxyType({
        "DefineSlotsInRack": "define_slots_in_rack", "SlotDisplayRule": "slot_display_rule", "Width": "width",
        "ExternalID": "external_id", "GenericID": "generic_id", "ExternIDExactMatch": "extern_id_exact_match"}),
})


@dataclass(slots=True)
class FileDescription:
    """[File], Table C.6."""

    description: str | None = None
    create_date: datetime.date | None = None
    create_time: datetime.time | None = None
    mod_date: datetime.date | None = None
    mod_time: datetime.time | None = None
    revision: Revision | None = None
    home_url: str | None = None


@dataclass(slots=True)
class Identity:
    """[Device], Table C.8: the Identity object attributes that key an EDS to a product."""

    vendor_code: int | None = None
    vendor_name: str | None = None
    product_type: int | None = None
    product_type_string: str | None = None
    product_code: int | None = None
    major_revision: int | None = None
    minor_revision: int | None = None
    product_name: str | None = None
    catalog: str | None = None
    icon: str | None = None
    exclude_from_adapter_rack_connection: str | None = None


@dataclass(slots=True)
class Classification:
    """ClassN of [Device Classification] (C.4.1.4.4)."""

    number: int
    classification: str | None
    subclassifications: tuple[str, ...] = ()
    entry: Entry | None = field(default=None, compare=False, repr=False)


@dataclass(slots=True)
class ParamClass:
    """[ParamClass], Table C.10."""

    max_instances: int | None = None
    descriptor: int | None = None
    cfg_assembly: int | None = None


@dataclass(slots=True)
class Scaling:
    """Fields 13-16 of ParamN and their links 17-20 (Table C.13, Figure C.5)."""

    multiplier: int | None = None
    divisor: int | None = None
    base: int | None = None
    offset: int | None = None
    multiplier_link: int | None = None
    divisor_link: int | None = None
    base_link: int | None = None
    offset_link: int | None = None
    decimal_precision: int | None = None


@dataclass(slots=True)
class Parameter:
    """ParamN, ProxyParamN or ProxiedParamN (Table C.13, C.4.1.5.3.1)."""

    keyword: str
    family: str
    number: int
    link_path_size: int | None = None
    link_path: tuple[PathItem, ...] | None = None
    descriptor: int | None = None
    #: the resolved CIP data type; None when the code is unknown or deferred to the module
    data_type: tables.DataType | None = None
    #: the code or obsolete identifier as written (MODULE when deferred)
    data_type_code: int | str | None = None
    data_size: int | str | None = None
    name: str | None = None
    units: str | None = None
    help: str | None = None
    minimum: Any = None
    maximum: Any = None
    default: Any = None
    scaling: Scaling = field(default_factory=Scaling)
    international_name: tuple[StringIMember, ...] | None = None
    international_units: tuple[StringIMember, ...] | None = None
    international_help: tuple[StringIMember, ...] | None = None
    #: EnumN (ProxyEnumN, ProxiedEnumN): value -> text, in file order
    enum: dict[int, str] | None = None
    #: ProxyParamSizeAdderN: (minimum, maximum, default) added to a ProxyParam's values
    size_adder: tuple[Any, Any, Any] | None = None
    entry: Entry | None = field(default=None, compare=False, repr=False)

    def value_type(self, attribute: str) -> str:
        """The type its ``minimum``, ``maximum`` or ``default`` is written in (Table C.17):
        a data type name, ``UINT`` for a string's length bounds, ``EDS_Char_Array`` for
        strings and paths, or ``plain`` (kept as written) when the type has no fixed size."""
        data_type = self.data_type
        if data_type is None:
            return "plain"
        if attribute != "default" and tables.min_max_rule(data_type.name).meaning == "length":
            return "UINT"
        if data_type.kind in ("string", "epath"):
            return "EDS_Char_Array"
        if data_type.kind == "stringi" or data_type.size is None:
            return "plain"
        return data_type.name

    @property
    def enum_key_type(self) -> str:
        """The type of its EnumN values: its own integer type, LINT when it has none."""
        data_type = self.data_type
        if data_type is not None and data_type.kind in ("unsigned", "signed", "bits", "bool"):
            return data_type.name
        return "LINT"

    def descriptor_flags(self) -> list[str]:
        """The names of the Table C.15 bits set in the descriptor."""
        return list(_flags(self.descriptor or 0, tables.PARAM_DESCRIPTOR_BITS.table))

    def engineering_value(self, value: float) -> float:
        """The value shown to the user, by the scaling formula of Figure C.5.

        The decimal precision counts only when the descriptor sets bit 6,
        extended precision scaling (Figure C.5, note a).
        """
        s = self.scaling
        extended = bool((self.descriptor or 0) & 0x40)
        precision = (s.decimal_precision or 0) if extended else 0
        return tables.scale(value, s.multiplier if s.multiplier is not None else 1,
                            s.divisor if s.divisor is not None else 1, s.base if s.base is not None else 1,
                            s.offset or 0, precision)


#: The Parameter attribute each ParamN field lands in (Table C.13), in field order. Field 1 is
#: reserved (always 0) and kept nowhere: ""; ``scaling.x`` is attribute x of its Scaling.
PARAMETER_FIELD_ATTRIBUTES: tuple[str, ...] = (
    "", "link_path_size", "link_path", "descriptor", "data_type_code", "data_size", "name", "units", "help",
    "minimum", "maximum", "default",
    "scaling.multiplier", "scaling.divisor", "scaling.base", "scaling.offset", "scaling.multiplier_link",
    "scaling.divisor_link", "scaling.base_link", "scaling.offset_link", "scaling.decimal_precision",
    "international_name", "international_units", "international_help",
)


def parameter_field(parameter: Parameter, attribute: str) -> Any:
    """The value of a :data:`PARAMETER_FIELD_ATTRIBUTES` attribute of ``parameter``."""
    record, _, name = attribute.rpartition(".")
    return getattr(parameter.scaling if record else parameter, name)


def parameter_field_type(attribute: str) -> str:
    """The type the ParamN field of ``attribute`` is written in: its FieldSpec's (Table C.13), the
    data type code as a ``code``; "" for minimum, maximum and default, which have the parameter's
    own (:meth:`Parameter.value_type`)."""
    if attribute in ("minimum", "maximum", "default"):
        return ""
    if attribute == "data_type_code":
        return "code"
    return tables.PARAM_FIELDS[PARAMETER_FIELD_ATTRIBUTES.index(attribute)].alternatives[0]


@dataclass(slots=True)
class ParameterGroup:
    """GroupN of [Groups] (Table C.19)."""

    number: int
    name: str | None
    declared_members: int | None
    members: list[Reference] = field(default_factory=list)
    entry: Entry | None = field(default=None, compare=False, repr=False)


@dataclass(slots=True)
class AssemblyMember:
    """One Member Size / Member Reference pair of an AssemN (Table C.20)."""

    #: bits; None when empty (then the referenced entry gives the size)
    size: int | None
    #: a Reference (ParamN, AssemN, Proxy...), an int (UDINT constant), a path,
    #: a member keyword (ExternalID, InputSlotMask0 ...) or None for a pad
    reference: Reference | int | tuple[PathItem, ...] | str | None
    #: offset of the Member Size field in the entry (0-based), for diagnostics
    field_index: int = field(default=0, compare=False)

    @property
    def is_pad(self) -> bool:
        return self.reference is None


@dataclass(slots=True)
class Assembly:
    """AssemN, ProxyAssemN or ProxiedAssemN (Table C.20, C.4.1.5.3.2)."""

    keyword: str
    family: str
    number: int
    name: str | None = None
    path: tuple[PathItem, ...] | str | None = None
    #: bytes (an AssemExaN may give a ParamN)
    size: int | str | Reference | None = None
    descriptor: int | str | None = None
    members: list[AssemblyMember] = field(default_factory=list)
    #: True for a ProxyAssem whose members are the ProxiedAssem's (ModuleMemberList)
    module_member_list: bool = False
    entry: Entry | None = field(default=None, compare=False, repr=False)

    @property
    def opaque(self) -> bool:
        """EZ-EDS's opaque assembly: its one member names the assembly itself with a size in bits
        (``Assem1 = "Input", "20 04 24 6F 30 03", 128, 0x0000, ,, 1024, Assem1;``). Real tools read it
        as data whose layout the EDS does not give, not as an assembly that contains itself
        (checks.object_rules EDS514). The member's size need not equal the Size: where they differ
        the assembly is still opaque data, and the disagreement is EDS324's, as for any assembly."""
        if len(self.members) != 1:
            return False
        member = self.members[0]
        reference = member.reference
        return isinstance(reference, Reference) and reference.keyword == self.keyword and reference.bit is None \
            and is_integer(member.size)


@dataclass(slots=True)
class ConnectionEndpoint:
    """RPI, size and format of one direction (or config part) of a connection."""

    rpi: int | Reference | str | None = None
    size: int | Reference | str | None = None
    format: Reference | str | None = None


@dataclass(slots=True)
class Connection:
    """ConnectionN, ProxyConnectN or ProxiedConnectN (Table C.22)."""

    keyword: str
    family: str
    number: int
    trigger_transport: int | str | None = None
    parameters: int | str | None = None
    o_to_t: ConnectionEndpoint = field(default_factory=ConnectionEndpoint)
    t_to_o: ConnectionEndpoint = field(default_factory=ConnectionEndpoint)
    config1: ConnectionEndpoint = field(default_factory=ConnectionEndpoint)
    config2: ConnectionEndpoint = field(default_factory=ConnectionEndpoint)
    name: str | None = None
    help: str | None = None
    path: tuple[PathItem, ...] | str | None = None
    entry: Entry | None = field(default=None, compare=False, repr=False)

    def trigger_transport_bits(self) -> list[tuple[tables.BitField, int, str]]:
        if not isinstance(self.trigger_transport, int):
            return []
        return list(_bits(self.trigger_transport, tables.TRIGGER_TRANSPORT_BITS.table))

    def parameter_bits(self) -> list[tuple[tables.BitField, int, str]]:
        if not isinstance(self.parameters, int):
            return []
        return list(_bits(self.parameters, tables.CONNECTION_PARAMETER_BITS.table))


# The few descriptor, trigger and parameter words of a file recur on every entry: each is decoded once.
@functools.lru_cache(maxsize=1024)
def _bits(value: int, table: str) -> tuple[tuple[tables.BitField, int, str], ...]:
    """tables.decode_bits of ``value`` by the bit table named ``table`` (a key of tables.BIT_TABLES)."""
    return tuple(tables.decode_bits(value, tables.BIT_TABLES[table]))


@functools.lru_cache(maxsize=1024)
def _flags(value: int, table: str) -> tuple[str, ...]:
    """tables.flags_set of ``value`` by the bit table named ``table``."""
    return tuple(tables.flags_set(value, tables.BIT_TABLES[table]))


@dataclass(slots=True)
class Port:
    """PortN of [Port] (Table C.25)."""

    number: int
    type_name: str | None = None
    name: str | None = None
    object_path: tuple[PathItem, ...] | None = None
    port_number: int | None = None
    #: fields 7.. as written (their meaning depends on the port type)
    specific: tuple[str | None, ...] = ()
    entry: Entry | None = field(default=None, compare=False, repr=False)


@dataclass(slots=True)
class Rack:
    """RackN of a module's [Modular] section (Table C.26)."""

    number: int
    vendor_code: int | None = None
    product_type: int | None = None
    product_code: int | None = None
    major_revision: int | None = None
    minor_revision: int | None = None
    legal_slots: tuple[int, ...] = ()
    entry: Entry | None = field(default=None, compare=False, repr=False)

    @property
    def key(self) -> tuple:
        return (self.vendor_code, self.product_type, self.product_code, self.major_revision, self.minor_revision)


@dataclass(slots=True)
class Query:
    path: tuple[PathItem, ...] | None = None
    service: int | None = None
    id_size: int | None = None
    empty_slot_id: tuple[PathItem, ...] | None = None


@dataclass(slots=True)
class Modular:
    """[Modular] (C.4.1.5.2): chassis and module entries."""

    define_slots_in_rack: int | None = None
    slot_display_rule: Reference | None = None
    width: int | None = None
    racks: list[Rack] = field(default_factory=list)
    external_id: tuple[PathItem, ...] | None = None
    generic_id: tuple[PathItem, ...] | None = None
    extern_id_exact_match: str | None = None
    query: Query | None = None

    @property
    def is_chassis(self) -> bool:
        return self.define_slots_in_rack is not None

    @property
    def is_module(self) -> bool:
        return bool(self.racks) or self.width is not None


@dataclass(slots=True)
class GenericEntry:
    """An entry the 2003 text does not define, kept with its values as written.

    Values: None (an empty field), a syntax ``Scalar`` or ``String`` (their
    spelling, so that a keyword and a string with the same text stay apart),
    or a list of values for a brace group. Comments are not part of it.
    """

    keyword: str
    values: list
    entry: Entry | None = field(default=None, compare=False, repr=False)
    #: for an entry the newer CIP tables define: each field read by its type, (value, ValueProblem or
    #: None), as model.cip_build.attach read it (the checks reuse it); None otherwise
    readings: list[tuple[Any, Exception | None]] | None = field(default=None, compare=False, repr=False)


@dataclass(slots=True)
class GenericSection:
    """A section the 2003 text does not define ([Capacity], object classes, vendor sections)."""

    name: str
    entries: list[GenericEntry] = field(default_factory=list)
    section: Section | None = field(default=None, compare=False, repr=False)


@dataclass(frozen=True, slots=True)
class Unreadable:
    """Text of the EDS that the model has no reading for, kept with its exact spelling, so that
    eds2xml can convert the rest and xml2eds can write the text back (docs/mapping.md).

    A field without a reading (a BOOL default 255, a date 13-11-2008, a word where a string
    stands): ``keyword`` and the 0-based ``field``. A statement that is no entry (stray text, an
    entry whose fields lack a comma; the reader keeps it as :class:`~edsconv.eds.syntax.Unparsed`):
    ``keyword`` and ``field`` None, ``before`` the keyword of the entry it stood before (None: at
    the section's end) and the comments on its last line.
    """

    section: str
    keyword: str | None
    field: int | None
    text: str
    before: str | None = None
    comments: tuple[str, ...] = ()


class CommentNote(NamedTuple):
    """A comment of the EDS and where it stood, so that conversions can carry it.

    ``keyword`` is None for a comment of the section header; ``field`` is the
    0-based index of the top-level field it follows, None for the entry itself;
    ``leading`` is True for comment lines before the section or entry.
    """

    section: str
    keyword: str | None
    field: int | None
    text: str
    leading: bool = False


@dataclass(slots=True)
class Device:
    """Everything an EDS says about a device."""

    file: FileDescription = field(default_factory=FileDescription)
    identity: Identity = field(default_factory=Identity)
    classifications: list[Classification] = field(default_factory=list)
    param_class: ParamClass | None = None
    #: ParamN, ProxyParamN and ProxiedParamN by keyword, in file order
    parameters: dict[str, Parameter] = field(default_factory=dict)
    groups: list[ParameterGroup] = field(default_factory=list)
    #: Revision entry of [Assembly] (class attribute 1)
    assembly_revision: int | None = None
    assemblies: dict[str, Assembly] = field(default_factory=dict)
    connections: dict[str, Connection] = field(default_factory=dict)
    ports: list[Port] = field(default_factory=list)
    modular: Modular | None = None
    #: entries the 2003 text does not define, in sections it does, by section name
    extra_entries: dict[str, list[GenericEntry]] = field(default_factory=dict)
    #: sections the 2003 text does not define, in file order
    other_sections: list[GenericSection] = field(default_factory=list)
    #: fields whose value breaks a notation rule (an error) but has one reading, which the model
    #: holds: (section, entry keyword, 0-based field index) -> the code of the rule it breaks
    erroneous: dict[tuple[str, str, int], str] = field(default_factory=dict, compare=False, repr=False)
    #: text without a reading, kept as written (model.build; the XML profiles carry it in edsconv:Unreadable);
    #: in file order, which a canonical rewrite changes: edsconv.diff compares it by place, equality not
    unreadable: list[Unreadable] = field(default_factory=list, compare=False)
    # --- the same content beyond the 2003 text, typed (model.cip, built by model.cip_build.attach from
    # extra_entries and other_sections, which the writers write): derived from those, so not compared
    #: [Capacity]
    capacity: Capacity | None = field(default=None, compare=False)
    #: the common object-class entries of each section that has them, by section name
    object_classes: dict[str, ObjectClass] = field(default_factory=dict, compare=False)
    #: [TCP/IP Interface Class], [Ethernet Link Class], [DLR Class], [Ingress Egress Class] beyond the common entries
    tcpip_interface: TcpIpInterface | None = field(default=None, compare=False)
    ethernet_link: EthernetLink | None = field(default=None, compare=False)
    dlr: DeviceLevelRing | None = field(default=None, compare=False)
    ingress_egress: IngressEgress | None = field(default=None, compare=False)
    #: DeviceNet [IO_Info] and [EnumPar]
    devicenet: DeviceNetIo | None = field(default=None, compare=False)
    #: AssemExaN, ProxyAssemExaN, ProxiedAssemExaN of [Assembly], by keyword
    extended_assemblies: dict[str, Assembly] = field(default_factory=dict, compare=False)
    #: [Device] IconContents, decoded
    icon_contents: Icon | None = field(default=None, compare=False)
    #: the single entries later editions add to [File], [Device], [ParamClass], [Connection Manager]
    additions: Additions | None = field(default=None, compare=False)
    #: comments of the EDS; not part of the device's meaning (excluded from equality)
    comments: list[CommentNote] = field(default_factory=list, compare=False, repr=False)
    #: the syntax model it was built from (None when built from XML)
    eds: EdsFile | None = field(default=None, compare=False, repr=False)
    diagnostics: list[Diagnostic] = field(default_factory=list, compare=False, repr=False)

    @property
    def networks(self) -> list[str]:
        """The public networks of the ClassN entries (EtherNetIP, DeviceNet, ControlNet)."""
        return [c.classification for c in self.classifications if c.classification]

    @property
    def is_ethernetip(self) -> bool:
        return tables.ETHERNETIP in self.networks

    def resolve(self, keyword: str) -> Parameter | Assembly | Connection | GenericEntry | None:
        """The entry a reference keyword names, in any section: AssemExaN its typed Assembly, other
        newer-spec entries their generic entry."""
        found = self.parameters.get(keyword) or self.assemblies.get(keyword) or self.connections.get(keyword) \
            or self.extended_assemblies.get(keyword)
        if found is not None:
            return found
        return next((e for entries in self.extra_entries.values() for e in entries if e.keyword == keyword), None)

    # --- sizes of assembly members (C.4.1.4.8) ---------------------------------------------
    def member_bits(self, assembly: Assembly, member: AssemblyMember) -> int | None:
        """A member's size in bits: its Member Size; when that is empty, the defined size of
        what it references (C.4.1.4.8): a Param's Data Size (field 6) or an Assem's size
        (:meth:`assembly_bits`), in bytes times 8. None when unknown: a Member Size written
        but not readable, a parameter without a Data Size, any other reference, a cycle."""
        return self._member_bits(assembly, member, frozenset({assembly.keyword}))

    def assembly_bits(self, assembly: Assembly) -> int | None:
        """The size of an assembly's data block in bits. C.4.1.4.8: its Size and its members
        both specify it (and shall agree); the Size when given, else what the members add
        up to, 0 with neither. None when unknown (members from the module, a size or member
        that cannot be read, a ProxyAssem / ProxiedAssem that states neither)."""
        return self._assembly_bits(assembly, frozenset({assembly.keyword}))

    def _member_bits(self, assembly: Assembly, member: AssemblyMember, seen: frozenset[str]) -> int | None:
        if is_integer(member.size):
            return member.size
        if field_written(assembly.entry, member.field_index) or not isinstance(member.reference, Reference):
            return None
        reference = member.reference
        target = reference.target if reference.target is not None else self.resolve(reference.keyword)
        if isinstance(target, Parameter):
            return 8 * target.data_size if is_integer(target.data_size) else None
        if isinstance(target, Assembly) and target.keyword not in seen:
            return self._assembly_bits(target, seen | {target.keyword})
        return None

    def _assembly_bits(self, assembly: Assembly, seen: frozenset[str]) -> int | None:
        if is_integer(assembly.size):
            return 8 * assembly.size
        if field_written(assembly.entry, 2) or assembly.module_member_list:
            return None
        if not assembly.members and assembly.family != "Assem":
            return None  # a Proxy/Proxied assembly stating neither is described with the module (C.4.1.5.3.2)
        total = 0
        for member in assembly.members:
            bits = self._member_bits(assembly, member, seen)
            if bits is None:
                return None
            total += bits
        return total


def is_integer(value: object) -> TypeGuard[int]:
    """An int that is not a bool (a model value read as a number, not a Yes/No)."""
    return isinstance(value, int) and not isinstance(value, bool)


def field_written(entry: Entry | None, index: int) -> TypeGuard[Entry]:
    """True when field ``index`` (0-based) of the entry holds a value, converted or not."""
    return entry is not None and index < len(entry.fields) and entry.fields[index].value is not None
