"""A Forward Open request built from one ConnectionN of the EDS alone (C.4.1.4.9 -> CIP Vol 1 3-5.5.2).

The entry states what the device supports (Tables C.23 and C.24 are masks); a Forward Open asks for
one choice: the lowest transport class, the first trigger (cyclic, change of state, application), a
fixed size where supported, point-to-point before multicast, scheduled before high before low
priority. The connection size on the wire is the data plus the 2-byte sequence count of classes
1-3 plus the 4-byte run/idle header where the real time format says so.
"""

from __future__ import annotations

from edsconv import spec_tables as tables
from edsconv.model import Device
from edsconv.model.device import Assembly, Connection, ConnectionEndpoint, Reference, is_integer
from edsconv.verify.client import ForwardOpen

TRIGGERS = ("cyclic", "change of state", "application")
#: Network Connection Parameters (CIP Vol 1 3-5.5.1.1): type and priority codes, fixed/variable bit
TYPES = (("POINT2POINT", 2), ("MULTICAST", 1))
PRIORITIES = (("SCHEDULED", 2), ("HIGH", 1), ("LOW", 0))
VARIABLE_BIT, PRIORITY_SHIFT, TYPE_SHIFT = 9, 10, 13
SEQUENCE_COUNT, RUN_IDLE_HEADER, RUN_IDLE_FORMAT = 2, 4, 4
SEGMENT_NAMES = {"class": "class", "instance": "instance", "attribute": "attribute", "connection point": "connection"}


def forward_open(device: Device, connection: Connection, serial: int,
                 path: list[tuple[str, int]] | None) -> tuple[ForwardOpen | None, str]:
    """The request, or None and what the entry lacks for one."""
    mask, parameters = connection.trigger_transport, connection.parameters
    if not is_integer(mask) or not is_integer(parameters):
        return None, "its trigger and transport or its connection parameters are not numbers"
    if path is None:
        return None, "its connection path is not a plain path of logical segments"
    transport = _transport(mask)
    if transport is None:
        return None, "its trigger and transport mask names no transport class or no trigger"
    ends = []
    for direction, endpoint in (("O=>T", connection.o_to_t), ("T=>O", connection.t_to_o)):
        size = _size(device, endpoint)
        if size is None or not is_integer(endpoint.rpi):
            return None, f"its {direction} size or RPI is not a number (a parameter or empty)"
        header = (SEQUENCE_COUNT if transport & 0x0F else 0) + \
            (RUN_IDLE_HEADER if _field(parameters, f"{direction} real time format") == RUN_IDLE_FORMAT else 0)
        ends.append((endpoint.rpi, _ncp(parameters, direction, size + header if size else 0)))
    (o_rpi, o_ncp), (t_rpi, t_ncp) = ends
    segments = [{SEGMENT_NAMES[kind]: value} for kind, value in path]
    return ForwardOpen(segments, transport, o_rpi, o_ncp, t_rpi, t_ncp, serial), ""


def _field(value: int, name: str) -> int:
    return tables.CONNECTION_PARAMETER_BITS.field(name).extract(value)


def _flag(table: tables.BitTable, value: int, name: str) -> bool:
    return bool(table.field(name).extract(value))


def _transport(mask: int) -> int | None:
    """The transport class / trigger byte: direction (bit 7), trigger (bits 4-6), class (bits 0-3)."""
    bits = tables.TRIGGER_TRANSPORT_BITS
    classes = [c for c in range(7) if _flag(bits, mask, f"class {c}")]
    triggers = [t for t, name in enumerate(TRIGGERS) if _flag(bits, mask, f"trigger {name}")]
    if not classes or not triggers:
        return None
    server = 0x80 if _flag(bits, mask, "client/server") else 0
    return server | triggers[0] << 4 | classes[0]


def _size(device: Device, endpoint: ConnectionEndpoint) -> int | None:
    """The data size: the entry's, else that of the assembly its format names."""
    if is_integer(endpoint.size):
        return endpoint.size
    target = endpoint.format.target if isinstance(endpoint.format, Reference) else None
    bits = device.assembly_bits(target) if isinstance(target, Assembly) else None
    return bits // 8 if bits is not None else None


def _ncp(parameters: int, direction: str, size: int) -> int:
    """The 16-bit Network Connection Parameters of a (small) Forward Open for one direction."""
    fixed, variable = (_field(parameters, f"{direction} {size_kind} size") for size_kind in ("fixed", "variable"))
    variable = not fixed and bool(variable)
    kind = next((code for name, code in TYPES if _field(parameters, f"{direction} {name}")), 0) if size else 0
    priority = next((code for name, code in PRIORITIES if _field(parameters, f"{direction} {name}")), 0)
    return kind << TYPE_SHIFT | priority << PRIORITY_SHIFT | int(variable) << VARIABLE_BIT | size
