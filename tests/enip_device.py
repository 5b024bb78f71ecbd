"""An EtherNet/IP device on 127.0.0.1 for edsconv verify's tests: cpppo's server (its Identity,
TCP/IP Interface, Message Router and Connection Manager objects), configured by a JSON file as the
device an EDS describes, with the Assembly instances and other objects the configuration names.

    python tests/enip_device.py CONFIG.json

binds an unprivileged port the system chooses on 127.0.0.1 (TCP only: List Identity is asked over
TCP) and prints ``Network TCP Server address = ('127.0.0.1', PORT)`` once it listens. The
configuration (tests/test_verify.py writes it):

    {"identity": {"Vendor Number": 1, ...},        cpppo's [Identity] settings
     "classes": {"245": 4},                         class Revision (class attribute 1) of cpppo's objects
     "assemblies": {"100": [8, 2], "150": [4, 6]},  instance -> [data bytes, I/O header bytes]
     "objects": {"246": {"revision": 4, "instances": {"1": {"1": ["UDINT", 100]}}}}}

Where cpppo's server differs from what a CIP device answers, this script makes it answer as one
(docs/verify.md lists it): a request to an object that does not exist gets general status 0x05
(cpppo ends the session), an attribute that does not exist 0x14 (cpppo: 0x08), class attribute 1 of
the TCP/IP Interface object is readable (cpppo puts the class Revision where the object belongs),
and a Forward Open is refused with status 0x01 and the Connection Manager's extended status when
it names a connection point that is not an Assembly instance (0x0315) or a size that is not the
instance's data plus its I/O header (0x0109); cpppo accepts every Forward Open.
"""

from __future__ import annotations

import json
import sys

from cpppo.server.enip import device, logix, parser
from cpppo.server.enip import main as enip_main

TYPES = {name: getattr(parser, name) for name in ("USINT", "UINT", "UDINT", "INT", "DINT", "REAL", "SSTRING")}
PATH_DESTINATION_UNKNOWN, ATTRIBUTE_NOT_SUPPORTED, CONNECTION_FAILURE = 0x05, 0x14, 0x01
INVALID_SEGMENT, INVALID_CONNECTION_SIZE = 0x0315, 0x0109
#: connection point -> (data bytes, I/O header bytes), from the configuration
ASSEMBLIES: dict[int, tuple[int, int]] = {}


class Assembly(device.Object):
    """The Assembly object (class 4): attribute 3 the data, attribute 4 its size in bytes."""

    class_id = 0x04

    def __init__(self, name: str | None = None, size: int = 0, **kwds: object) -> None:
        super().__init__(name=name, **kwds)
        if self.instance_id:
            self.attribute["3"] = device.Attribute("Data", parser.USINT, default=[0] * size)
            self.attribute["4"] = device.Attribute("Size", parser.UINT, default=size)


class ConnectionManager(device.Connection_Manager):
    def request(self, data, addr=None):  # type: ignore[no-untyped-def]
        """A request to an object that does not exist: general status 0x05, not a session ended."""
        request = data.get("request.input") if data else None
        try:
            return super().request(data, addr=addr)
        except Exception:
            if request is None:
                raise
            data.request.input = bytearray([request[0] | 0x80, 0, PATH_DESTINATION_UNKNOWN, 0])
            return True

    def forward_open(self, data, addr):  # type: ignore[no-untyped-def]
        points = [s["connection"] for s in data.forward_open.connection_path.segment if "connection" in s]
        sizes = (data.forward_open.O_T.NCP & 0x1FF, data.forward_open.T_O.NCP & 0x1FF)
        for point, size in zip(points[-2:], sizes[-len(points[-2:]):], strict=True):
            if point not in ASSEMBLIES:
                refuse(data, INVALID_SEGMENT)
            if sum(ASSEMBLIES[point]) != size:
                refuse(data, INVALID_CONNECTION_SIZE)
        super().forward_open(data, addr)


def refuse(data, extended: int) -> None:  # type: ignore[no-untyped-def]
    data.status = CONNECTION_FAILURE
    data.status_ext = {"size": 1, "data": [extended]}
    raise ValueError(f"Forward Open refused: 0x{extended:04X}")


def answer_unknown_attributes_as_a_device() -> None:
    """Get_Attribute_Single of an attribute the object lacks: 0x14 (cpppo answers 0x08)."""
    original = device.Object.request

    def request(self, data, addr=None):  # type: ignore[no-untyped-def]
        proceed = original(self, data, addr=addr)
        segment = data.get("path.segment", [{}])[-1]
        if data.get("service") == self.GA_SNG_RPY and data.status == 0x08 \
                and str(segment.get("attribute")) not in self.attribute:
            data.status = ATTRIBUTE_NOT_SUPPORTED
            data.input = bytearray(self.produce(data))
        return proceed

    device.Object.request = request


class TCPIP(device.TCPIP):
    def __init__(self, name: str | None = None, **kwds: object) -> None:
        super().__init__(name=name, **kwds)
        if self.instance_id == 0:
            self.attribute["0"] = self  # where lookup() and the router expect the object


def set_class_revision(class_id: int, revision: int) -> None:
    device.lookup(class_id, 0).attribute["1"] = device.Attribute("Revision", parser.UINT, default=revision)


def add_object(class_id: int, spec: dict) -> None:
    """A plain object of ``class_id`` with the given instances and attributes (type name, value)."""
    cls = type(f"Class_{class_id}", (device.Object,), {"class_id": class_id})
    for instance, attributes in spec.get("instances", {}).items():
        obj = cls(instance_id=int(instance))
        for number, (type_name, value) in attributes.items():
            obj.attribute[number] = device.Attribute(f"Attribute {number}", TYPES[type_name], default=value)
    set_class_revision(class_id, spec.get("revision", 1))


def configure(config: dict) -> None:
    device.Object.config_loader.read_dict({"Identity": {k: str(v) for k, v in config["identity"].items()}})
    logix.setup(tcpip_class=TCPIP, connection_manager_class=ConnectionManager)
    answer_unknown_attributes_as_a_device()
    for instance, (size, header) in config.get("assemblies", {}).items():
        Assembly(instance_id=int(instance), size=size)
        ASSEMBLIES[int(instance)] = (size, header)
    for class_id, spec in config.get("objects", {}).items():
        add_object(int(class_id), spec)
    for class_id, revision in config.get("classes", {}).items():
        set_class_revision(int(class_id), revision)


def main() -> int:
    with open(sys.argv[1], encoding="utf-8") as file:
        configure(json.load(file))
    return enip_main.main(argv=["--no-config", "--address", "127.0.0.1:0", "--address-output", "--no-udp"])


if __name__ == "__main__":
    sys.exit(main())
