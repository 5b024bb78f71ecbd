"""What ``edsconv verify`` compares without opening a connection: the identity ([Device] against List
Identity and the Identity object) and the object classes the EDS declares (their Revision, MaxInst,
instance count and listed attributes against the class and instance attributes the device answers).

Each check takes the typed model, a :class:`Probe` (the session plus the places of the EDS) and
yields diagnostics at the EDS entries that disagree with the device.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

from edsconv import cip_tables
from edsconv.checks import Context
from edsconv.diagnostics import Diagnostic, Rule
from edsconv.model import Device
from edsconv.model.cip import ObjectClass
from edsconv.verify import rules
from edsconv.verify.client import ATTRIBUTE_NOT_SUPPORTED, Reply, Session

IDENTITY_CLASS, ASSEMBLY_CLASS, ETHERNET_LINK_CLASS = 0x01, 0x04, 0xF6
#: Ethernet Link object instance attributes: 7 Interface Type (USINT), 10 Interface Label (SHORT_STRING)
INTERFACE_TYPE, INTERFACE_LABEL = 7, 10
#: objects every CIP device has (Identity, Message Router, Connection Manager): --strict does not ask for them
EVERY_DEVICE_HAS = frozenset({0x01, 0x02, 0x06})


@dataclass(slots=True)
class Probe:
    """The device being asked and the EDS being compared (for positions)."""

    session: Session
    device: Device
    context: Context

    def at(self, rule_: Rule, message: str, section: str, keyword: str | None = None,
           field: int | None = None) -> Diagnostic:
        """A diagnostic at ``[section] keyword`` (field ``field``), at the section header, or at the file's start."""
        found = self.context.eds.section(section)
        entry = found.entry(keyword) if found is not None and keyword is not None else None
        if entry is not None and field is not None and field < len(entry.fields):
            return self.context.at(rule_, message, entry.fields[field])
        return self.context.at(rule_, message, entry if entry is not None else found)

    def read(self, class_id: int, instance: int, attribute: int) -> Reply:
        return self.session.get_attribute(class_id, instance, attribute)


def number(reply: Reply) -> int:
    """A reply's data as the little-endian unsigned number CIP encodes."""
    return int.from_bytes(reply.data, "little")


def short_string(reply: Reply) -> str:
    """A SHORT_STRING: a length byte, then the characters."""
    return reply.data[1:1 + reply.data[0]].decode("latin-1") if reply.data else ""


# --- identity --------------------------------------------------------------------------------------


def identity(probe: Probe) -> Iterator[Diagnostic]:
    """VendCode, ProdType, ProdCode, MajRev, MinRev and ProdName against List Identity and the Identity object."""
    listed = probe.session.list_identity()
    revision = probe.read(IDENTITY_CLASS, 1, 4)
    read = {keyword: probe.read(IDENTITY_CLASS, 1, attribute)
            for keyword, attribute in (("VendCode", 1), ("ProdType", 2), ("ProdCode", 3), ("ProdName", 7))}
    ours = probe.device.identity
    compared = (
        ("VendCode", ours.vendor_code, listed.vendor, number(read["VendCode"]) if read["VendCode"].ok else None),
        ("ProdType", ours.product_type, listed.device_type,
         number(read["ProdType"]) if read["ProdType"].ok else None),
        ("ProdCode", ours.product_code, listed.product_code,
         number(read["ProdCode"]) if read["ProdCode"].ok else None),
        ("MajRev", ours.major_revision, listed.major_revision, revision.data[0] if revision.ok else None),
        ("MinRev", ours.minor_revision, listed.minor_revision, revision.data[1] if revision.ok else None),
        ("ProdName", ours.product_name, listed.product_name,
         short_string(read["ProdName"]) if read["ProdName"].ok else None),
    )
    for keyword, expected, in_list, in_object in compared:
        if expected is None:
            continue
        differing = [f"{_shown(value)} ({where})" for value, where in
                     ((in_list, "List Identity"), (in_object, "Identity object")) if value is not None and
                     value != expected]
        if differing:
            yield probe.at(rules.IDENTITY_MISMATCH, f"{keyword} is {_shown(expected)} but the device answers "
                           f"{' and '.join(differing)}", "Device", keyword)


def _shown(value: object) -> str:
    return f'"{value}"' if isinstance(value, str) else str(value)


# --- object classes --------------------------------------------------------------------------------


def object_classes(probe: Probe) -> Iterator[Diagnostic]:
    """Each object class section with a class ID: present, its class attributes, the attributes it lists."""
    for record in probe.device.object_classes.values():
        if record.class_id is None:
            continue
        revision = probe.read(record.class_id, 0, 1)
        if revision.absent:
            yield probe.at(rules.OBJECT_ABSENT, f"the device has no {record.section.removesuffix(' Class')} object "
                           f"(class 0x{record.class_id:02X}): {revision.words()}", record.section)
            continue
        yield from _class_attributes(probe, record, revision)
        yield from _listed_attributes(probe, record)
    if probe.device.assembly_revision is not None:
        revision = probe.read(ASSEMBLY_CLASS, 0, 1)
        yield from _compare_class_attribute(probe, "Assembly", "Revision", probe.device.assembly_revision,
                                            revision, "class attribute 1")


def _class_attributes(probe: Probe, record: ObjectClass, revision: Reply) -> Iterator[Diagnostic]:
    yield from _compare_class_attribute(probe, record.section, "Revision", record.revision, revision,
                                        "class attribute 1")
    if record.max_instance is not None:
        yield from _compare_class_attribute(probe, record.section, "MaxInst", record.max_instance,
                                            probe.read(record.class_id or 0, 0, 2), "class attribute 2")
    if record.static_instances is not None and record.max_dynamic_instances == 0:
        yield from _compare_class_attribute(probe, record.section, "Number_Of_Static_Instances",
                                            record.static_instances, probe.read(record.class_id or 0, 0, 3),
                                            "class attribute 3, with no dynamic instances")


def _compare_class_attribute(probe: Probe, section: str, keyword: str, expected: int | None, reply: Reply,
                             attribute: str) -> Iterator[Diagnostic]:
    if expected is None:
        return
    if not reply.ok:
        yield probe.at(rules.NOT_CHECKED, f"{keyword} could not be read from the device ({attribute}): "
                       f"{reply.words()}", section, keyword)
    elif number(reply) != expected:
        yield probe.at(rules.CLASS_ATTRIBUTE_MISMATCH, f"{keyword} is {expected} but the device answers "
                       f"{number(reply)} ({attribute})", section, keyword)


def _listed_attributes(probe: Probe, record: ObjectClass) -> Iterator[Diagnostic]:
    class_id = record.class_id or 0
    for keyword, instance, listed in (("Class_Attributes", 0, record.class_attributes),
                                      ("Instance_Attributes", 1, record.instance_attributes)):
        for position, attribute in enumerate(listed or ()):
            reply = probe.read(class_id, instance, attribute)
            if reply.status == ATTRIBUTE_NOT_SUPPORTED or reply.absent:
                holder = "the class" if instance == 0 else "instance 1"
                yield probe.at(rules.ATTRIBUTE_NOT_SUPPORTED, f"the device does not support attribute {attribute} "
                               f"of {holder}: {reply.words()}",
                               record.section, keyword, position)
            elif not reply.ok:
                yield probe.at(rules.NOT_CHECKED, f"attribute {attribute} could not be read: {reply.words()}",
                               record.section, keyword, position)


def ethernet_interfaces(probe: Probe) -> Iterator[Diagnostic]:
    """InterfaceLabelN and InterfaceTypeN against instance N of the Ethernet Link object."""
    link = probe.device.ethernet_link
    if link is None or probe.read(ETHERNET_LINK_CLASS, 0, 1).absent:
        return  # no object at all: EDS602 on the section says so, once
    for interface in link.interfaces:
        for keyword, attribute, expected in (("InterfaceLabel", INTERFACE_LABEL, interface.label),
                                             ("InterfaceType", INTERFACE_TYPE, interface.interface_type)):
            if expected is None:
                continue
            reply = probe.read(ETHERNET_LINK_CLASS, interface.instance, attribute)
            keyword = f"{keyword}{interface.instance}"
            if reply.absent:
                yield probe.at(rules.INTERFACE_MISMATCH, f"{keyword}: the device has no Ethernet Link instance "
                               f"{interface.instance}: {reply.words()}", "Ethernet Link Class", keyword)
                break
            found = (short_string(reply) if attribute == INTERFACE_LABEL else number(reply)) if reply.ok else None
            if found is None:
                yield probe.at(rules.NOT_CHECKED, f"{keyword} could not be read (attribute {attribute}): "
                               f"{reply.words()}", "Ethernet Link Class", keyword)
            elif found != expected:
                yield probe.at(rules.INTERFACE_MISMATCH, f"{keyword} is {_shown(expected)} but the device's "
                               f"instance {interface.instance} answers {_shown(found)} (attribute {attribute})",
                               "Ethernet Link Class", keyword)


def undeclared_objects(probe: Probe) -> Iterator[Diagnostic]:
    """--strict: the object classes the tables know that the device has and the EDS does not declare."""
    declared = {record.class_id for record in probe.device.object_classes.values()}
    for spec in cip_tables.CIP_SECTIONS.values():
        if spec.class_id is None or spec.class_id in declared | EVERY_DEVICE_HAS:
            continue
        if probe.read(spec.class_id, 0, 1).ok:
            name = spec.name.removesuffix(" Class")
            yield probe.at(rules.OBJECT_UNDECLARED, f"the device has a {name} object (class 0x{spec.class_id:02X}) "
                           f"but the EDS has no [{spec.name}] section", "")
