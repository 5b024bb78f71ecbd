"""The typed model of EDS content beyond the 2003 text: [Capacity], the object class sections, the
network objects, DeviceNet [IO_Info], the icon, and the entries later editions add to the 2003 sections.

Plain dataclasses, built by :mod:`edsconv.model.cip_build` from the entries
:mod:`edsconv.model.build` keeps as written (``Device.extra_entries`` and ``Device.other_sections``,
which stay filled: the XML writer and ``edsconv fmt`` write those). Each record says which
:mod:`edsconv.cip_tables` entry its attributes come from; a value that does not fit its table's type is
None here (``edsconv lint`` says why, EDS501-EDS503). Every record keeps the syntax ``entry`` it was
read from (None when read otherwise), as the 2003 records do.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType

from edsconv.eds.syntax import Entry
from edsconv.model.device import Reference
from edsconv.model.values import PathItem

# --- values a field may hold beyond the 2003 kinds -------------------------------------------


@dataclass(frozen=True, slots=True)
class Service:
    """A service of Class_Services / Instance_Services (cip_tables ``ServiceSpec``): a code, or a
    brace group of the code and the attribute IDs it serves (``{0x10,3,5}``), ``*`` for all."""

    code: int
    #: the attribute IDs of a brace group; () for a bare code
    attributes: tuple[int, ...] = ()
    #: ``{0x0E,*}``: every attribute
    all_attributes: bool = False

    def __str__(self) -> str:
        if not self.attributes and not self.all_attributes:
            return f"0x{self.code:02X}"
        rest = ["*"] if self.all_attributes else [str(a) for a in self.attributes]
        return "{" + ",".join([f"0x{self.code:02X}", *rest]) + "}"


# --- [Capacity] ----------------------------------------------------------------------------


@dataclass(slots=True)
class TrafficSpec:
    """TSpecN: the packets per second the device sustains at a connection size, in a direction."""

    number: int
    #: Tx, Rx or TxRx (cip_tables.TXRX_KEYWORDS)
    direction: str | None = None
    #: bytes
    connection_size: int | None = None
    packets_per_second: int | None = None
    entry: Entry | None = field(default=None, compare=False, repr=False)


@dataclass(slots=True)
class Capacity:
    """[Capacity] (eds-pie meta_eds_lib.json): how many connections and packets the device handles."""

    traffic_specs: list[TrafficSpec] = field(default_factory=list)
    connection_overhead: float | None = None
    max_cip_connections: int | None = None
    max_io_connections: int | None = None
    max_msg_connections: int | None = None
    max_io_producers: int | None = None
    max_io_consumers: int | None = None
    max_io_produce_consume: int | None = None
    max_io_mcast_producers: int | None = None
    max_io_mcast_consumers: int | None = None
    max_consumers_per_mcast: int | None = None


# --- object classes ------------------------------------------------------------------------------


@dataclass(slots=True)
class ServiceDescription:
    """Service_DescriptionN of an object class section."""

    number: int
    code: int | None = None
    name: str | None = None
    #: an EPATH, or the keyword SYMBOL_ANSI
    path: tuple[PathItem, ...] | str | None = None
    request: Reference | None = None
    response: Reference | None = None
    entry: Entry | None = field(default=None, compare=False, repr=False)


@dataclass(slots=True)
class ObjectClass:
    """The common object-class entries of one section (cip_tables.COMMON_OBJECT_ENTRIES): an object
    class section (``[TCP/IP Interface Class]``, ``[Class940_Vendor1]``) or a 2003 section that
    describes an object class too ([Assembly], [Connection Manager], [Port], [ParamClass], [Groups])."""

    #: the section's name, without brackets
    section: str
    #: the CIP class ID the tables give the section (or its name, ``Class940_Vendor1`` -> 940)
    class_id: int | None = None
    #: the vendor of a ``[Class<ID>_Vendor<VendorID>]`` section
    vendor_id: int | None = None
    revision: int | None = None
    max_instance: int | None = None
    static_instances: int | None = None
    max_dynamic_instances: int | None = None
    class_attributes: tuple[int, ...] | None = None
    instance_attributes: tuple[int, ...] | None = None
    class_services: tuple[Service, ...] | None = None
    instance_services: tuple[Service, ...] | None = None
    name: str | None = None
    #: Object_Class_Code as written (checked against class_id, EDS505 / EDS506)
    class_code: int | None = None
    service_descriptions: list[ServiceDescription] = field(default_factory=list)


# --- the network objects --------------------------------------------------------------------


@dataclass(slots=True)
class QuickConnectTarget:
    """ENetQCTN of [TCP/IP Interface Class]: EtherNet/IP QuickConnect target times."""

    number: int
    ready_for_connection_time: int | None = None
    accumulated_connection_time: int | None = None
    entry: Entry | None = field(default=None, compare=False, repr=False)


@dataclass(slots=True)
class QuickConnectOriginator:
    """ENetQCON of [TCP/IP Interface Class]: EtherNet/IP QuickConnect originator times."""

    number: int
    origination_times: tuple[int | None, ...] = ()
    entry: Entry | None = field(default=None, compare=False, repr=False)


@dataclass(slots=True)
class TcpIpInterface:
    """The entries of [TCP/IP Interface Class] beyond the common ones."""

    quick_connect_targets: list[QuickConnectTarget] = field(default_factory=list)
    quick_connect_originators: list[QuickConnectOriginator] = field(default_factory=list)


@dataclass(slots=True)
class EthernetInterface:
    """Ethernet Link instance N: InterfaceLabelN, InterfaceSpeedN and InterfaceTypeN together."""

    instance: int
    label: str | None = None
    speed: int | None = None
    interface_type: int | None = None


@dataclass(slots=True)
class EthernetLink:
    """The entries of [Ethernet Link Class] beyond the common ones: one record per instance N."""

    interfaces: list[EthernetInterface] = field(default_factory=list)


@dataclass(slots=True)
class DeviceLevelRing:
    """The entries of [DLR Class] beyond the common ones (known from practice)."""

    ring_supervisor_capable: str | None = None
    #: Redunant_Gateway_Capable (sic)
    redundant_gateway_capable: str | None = None


@dataclass(slots=True)
class IngressEgress:
    """The entries of [Ingress Egress Class] beyond the common ones."""

    maintain_existing_connection: int | None = None


# --- DeviceNet ------------------------------------------------------------------------------


@dataclass(slots=True)
class IoMode:
    """PollInfo, StrobeInfo, COSInfo or CyclicInfo of [IO_Info]."""

    keyword: str
    #: the connection types it may be combined with (same bits as Default)
    combination_mask: int | None = None
    #: InputN / OutputN it uses by default (0 in the file: none)
    default_input: Reference | None = None
    default_output: Reference | None = None
    entry: Entry | None = field(default=None, compare=False, repr=False)


@dataclass(slots=True)
class IoData:
    """InputN or OutputN of [IO_Info]: the data of DeviceNet I/O messages."""

    keyword: str
    number: int
    #: bytes
    size: int | None = None
    size_in_bits: int | None = None
    connection_mask: int | None = None
    name: str | None = None
    #: bytes of the path
    path_size: int | None = None
    path: tuple[PathItem, ...] | None = None
    help: str | None = None
    entry: Entry | None = field(default=None, compare=False, repr=False)


@dataclass(slots=True)
class DeviceNetIo:
    """DeviceNet [IO_Info] and [EnumPar] (entries known from practice only)."""

    #: the connection types used by default
    default: int | None = None
    #: PollInfo, StrobeInfo, COSInfo, CyclicInfo by keyword, in file order
    modes: dict[str, IoMode] = field(default_factory=dict)
    inputs: dict[str, IoData] = field(default_factory=dict)
    outputs: dict[str, IoData] = field(default_factory=dict)
    #: [EnumPar] ParamN: the parameter's value strings, from its minimum on
    enum_strings: dict[str, tuple[str | None, ...]] = field(default_factory=dict)


# --- entries later editions add to the 2003 sections -------------------------------------------


@dataclass(slots=True)
class Additions:
    """The single entries real files add to [File], [Device], [ParamClass] and [Connection Manager]
    (IconContents is :class:`~edsconv.model.icon.Icon`, the object-class entries :class:`ObjectClass`)."""

    eds_file_crc: int | None = None
    exclude: str | None = None
    application_profiles_assembly: int | None = None
    #: Production Inhibit Time network segments (milliseconds, microseconds): Yes / No
    pitns: str | None = None
    pitns_usec: str | None = None
    max_safety_connections: int | None = None
    max_safety_input_connections: int | None = None
    max_safety_output_connections: int | None = None
    #: the ConnectionN that are the default safety connections
    default_safety_connections: tuple[Reference, ...] | None = None
    safety_format: int | None = None
    #: the AssemN of the CIP Safety configuration ([ParamClass] SafetyCfgAssembly)
    safety_cfg_assembly: Reference | None = None


#: The attribute of each single entry, by section and keyword (attributes of the record the section's
#: entries land in: Capacity, ObjectClass, DeviceLevelRing, IngressEgress, DeviceNetIo, Additions).
SINGLE_ATTRIBUTES: Mapping[str, Mapping[str, str]] = MappingProxyType({
    "Capacity": MappingProxyType({
        "ConnOverhead": "connection_overhead", "MaxCIPConnections": "max_cip_connections",
        "MaxIOConnections": "max_io_connections", "MaxMsgConnections": "max_msg_connections",
        "MaxIOProducers": "max_io_producers", "MaxIOConsumers": "max_io_consumers",
        "MaxIOProduceConsume": "max_io_produce_consume", "MaxIOMcastProducers": "max_io_mcast_producers",
        "MaxIOMcastConsumers": "max_io_mcast_consumers", "MaxConsumersPerMcast": "max_consumers_per_mcast"}),
    "Common Object Class": MappingProxyType({
        "Revision": "revision", "MaxInst": "max_instance", "Number_Of_Static_Instances": "static_instances",
        "Max_Number_Of_Dynamic_Instances": "max_dynamic_instances", "Class_Attributes": "class_attributes",
        "Instance_Attributes": "instance_attributes", "Class_Services": "class_services",
        "Instance_Services": "instance_services", "Object_Name": "name", "Object_Class_Code": "class_code"}),
    "DLR Class": MappingProxyType({"Ring_Supervisor_Capable": "ring_supervisor_capable",
                                   "Redunant_Gateway_Capable": "redundant_gateway_capable"}),
    "Ingress Egress Class": MappingProxyType({"Maintain_Existing_Connection": "maintain_existing_connection"}),
    "IO_Info": MappingProxyType({"Default": "default"}),
    "File": MappingProxyType({"EDSFileCRC": "eds_file_crc", "Exclude": "exclude"}),
    "Device": MappingProxyType({"ApplicationProfilesAssembly": "application_profiles_assembly"}),
    "ParamClass": MappingProxyType({"SafetyCfgAssembly": "safety_cfg_assembly"}),
    "Connection Manager": MappingProxyType({
        "PITNS": "pitns", "PITNS_usec": "pitns_usec", "MaxSafetyConnections": "max_safety_connections",
        "MaxSafetyInputCnxns": "max_safety_input_connections",
        "MaxSafetyOutputCnxns": "max_safety_output_connections",
        "DefaultSafetyConnections": "default_safety_connections", "SafetyFormat": "safety_format"}),
})
#: The Ethernet Link entry families, each an attribute of the instance N's EthernetInterface.
INTERFACE_ATTRIBUTES: Mapping[str, str] = MappingProxyType({
    "InterfaceLabel": "label", "InterfaceSpeed": "speed", "InterfaceType": "interface_type"})
